"""Drawings of the graphical route: mechanism, free bodies, force polygons, steps, the side-by-side solution.

The only part of graphkin that imports matplotlib, and only its object API
(:class:`matplotlib.figure.Figure`), so it works headless and never touches
pyplot's global state. Every ``draw_*`` function that draws on one axes
takes ``ax=None`` (a new figure when omitted) and ``**style`` overrides of
:class:`graphkin.draw.style.Style`, and returns a :class:`Drawn` — the list
of artists it made, with the force arrows and labels by name. Functions
that need several axes return a Figure.

Examples
--------
>>> from graphkin import catalog
>>> from graphkin.graphic import construct_forces
>>> from graphkin import draw
>>> p = catalog.load("double_slider")
>>> c = construct_forces(p.kinematics(), 0)
>>> fig = draw.draw_solution(c, p.solve())
>>> draw.save(fig, "double_slider.svg")  # doctest: +SKIP
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from ..files import file_mode
from . import style
from .axes import Drawn
from .convention import draw_sign_convention
from .cycle import draw_cycle, draw_energy, draw_joint_force_index, draw_polar_forces, draw_shaking, draw_torque_curve
from .fbd import draw_free_body, loads_on
from .given import draw_given
from .labels import measuring_renderer
from .mechanism import draw_mechanism
from .polygon import draw_force_polygon
from .solution import comparison_rows, draw_solution
from .steps import draw_step_grid, draw_steps

FORMATS = ("png", "svg", "pdf")


def save(fig, path, *, dpi=None, **kwargs) -> Path:
    """Save a figure as PNG, SVG or PDF, chosen by the file's suffix.

    Parameters
    ----------
    fig : Figure, Axes or Drawn
        What to save (an axes or a :class:`Drawn` saves its whole figure).
    path : str or Path
        Ends in ``.png``, ``.svg`` or ``.pdf``.
    dpi : int, optional
        Resolution of a PNG (``style.STYLE.dpi`` by default).
    **kwargs
        Passed on to :meth:`matplotlib.figure.Figure.savefig`.

    Returns
    -------
    Path
    """
    path = Path(path)
    fmt = path.suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise ValueError(f"cannot save {path.name!r}: the suffix must be one of .png, .svg, .pdf")
    if isinstance(fig, Drawn):
        fig = fig.ax.figure
    elif not hasattr(fig, "savefig"):
        fig = fig.figure
    if hasattr(fig, "get_figure"):
        fig = fig.get_figure(root=True)
    kwargs.setdefault("bbox_inches", "tight")
    kwargs.setdefault("pad_inches", 0.08)
    kwargs.setdefault("facecolor", "white")
    if fmt in ("svg", "pdf"):
        # No creation date: the same figure gives the same file.
        kwargs.setdefault("metadata", {"Date": None} if fmt == "svg" else {"CreationDate": None})
    # A temporary file in the same folder, then a rename: a reader never sees half a figure, and an
    # interrupted or failed save leaves the old file (or none).
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    os.close(fd)
    try:
        fig.savefig(tmp, format=fmt, dpi=dpi or style.STYLE.dpi, **kwargs)
        # mkstemp's file is owner-only: the figure gets the permissions a plain open() would give it.
        os.chmod(tmp, file_mode())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise
    return path


__all__ = [
    "Drawn", "FORMATS", "comparison_rows", "draw_cycle", "draw_energy", "draw_force_polygon", "draw_free_body",
    "draw_given", "draw_joint_force_index", "draw_mechanism", "draw_polar_forces", "draw_shaking", "draw_sign_convention",
    "draw_solution", "draw_step_grid", "draw_steps", "draw_torque_curve", "loads_on", "measuring_renderer", "save",
    "style",
]
