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
>>> from graphkin.graphical import construct_forces
>>> from graphkin import draw
>>> p = catalog.load("double_slider")
>>> c = construct_forces(p.kinematics(), 0)
>>> fig = draw.draw_solution(c, p.solve())
>>> draw.save(fig, "double_slider.svg")  # doctest: +SKIP
"""

from __future__ import annotations

import importlib
from pathlib import Path

from graphkin.draw import style
from graphkin.draw.axes import Drawn
from graphkin.draw.convention import draw_sign_convention
from graphkin.draw.fbd import draw_free_body, loads_on
from graphkin.draw.given import draw_given
from graphkin.draw.labels import measuring_renderer
from graphkin.draw.mechanism import draw_mechanism
from graphkin.draw.polygon import draw_force_polygon
from graphkin.draw.solution import comparison_rows, draw_solution
from graphkin.files import interrupts_deferred, replacing

FORMATS = ("png", "svg", "pdf")

_LATER = {
    **dict.fromkeys(("draw_cycle", "draw_energy", "draw_joint_force_index", "draw_polar_forces", "draw_positions", "draw_shaking",
                     "draw_torque_curve"), "cycle"),
    "draw_shaking_components": "shaking",
    "draw_transmission_angle": "transmission",
    "draw_study": "study",
    "draw_positions": "positions",
    **dict.fromkeys(("draw_grades", "what_went_wrong"), "grades"),
    "draw_free_bodies": "paper",
    **dict.fromkeys(("draw_step_grid", "draw_steps"), "steps"),
    **dict.fromkeys(("draw_motion_polygon", "draw_motion_polygons", "draw_motion_steps"), "motion"),
    **dict.fromkeys(("Animation", "animate"), "animation"),
}
"""Drawings imported when first asked for: the cycle plots bring graphkin.cycle and matplotlib's tickers
(~20 ms that ``graphkin solve --figure`` does not need); the animation its writers."""


def __getattr__(name):
    module = _LATER.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f".{module}", __name__), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted({*globals(), *_LATER})


def save(fig, path, *, dpi=None, **kwargs) -> Path:
    """Save a figure as PNG, SVG or PDF, chosen by the file's suffix.

    The figure is cropped to what is drawn (``bbox_inches="tight"``, with a
    0.08 in margin) on a white background. The file is written whole or not
    at all (:func:`graphkin.files.replacing`).

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

    Notes
    -----
    matplotlib's ``bbox_inches="tight"`` draws the whole figure once to find
    its extent and then again to save it. Here the extent is measured
    without drawing (``Figure.get_tightbbox`` at the saving resolution,
    which lays out the same texts and applies the same aspect ratios), so
    a figure without a layout engine is drawn once, with the same pixels.
    A PNG is compressed at zlib level :data:`PNG_LEVEL` (Pillow, through
    matplotlib): a line drawing is mostly runs of one colour, which a light
    level finds nearly as well as the default, in less time.
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
    dpi = dpi or style.STYLE.dpi
    kwargs.setdefault("facecolor", "white")
    # A layout engine must draw to place the axes, and matplotlib's own "tight" then costs nothing more;
    # SVG and PDF measure text with their own renderers, so they keep matplotlib's way too; and any
    # other savefig option goes to matplotlib whole.
    own = (fmt == "png" and kwargs.get("bbox_inches", "tight") == "tight" and fig.get_layout_engine() is None
           and set(kwargs) <= _OWN_PNG)
    if own:
        kwargs["bbox_inches"] = _tight_box(fig, dpi, kwargs.pop("pad_inches", 0.08))
    kwargs.setdefault("bbox_inches", "tight")
    kwargs.setdefault("pad_inches", 0.08)
    if fmt in ("svg", "pdf"):
        # No creation date: the same figure gives the same file.
        kwargs.setdefault("metadata", {"Date": None} if fmt == "svg" else {"CreationDate": None})
    if fmt == "png":
        kwargs.setdefault("pil_kwargs", {"compress_level": PNG_LEVEL})
    # Ctrl-C waits for matplotlib to finish drawing (a few tenths of a second at most), then discards the file:
    # raised inside matplotlib's C++ transforms it would come out as a TypeError (files.interrupts_deferred).
    with replacing(path, "figure") as tmp, interrupts_deferred():
        fig.savefig(tmp, format=fmt, dpi=dpi, **kwargs)
    return path


# savefig arguments for which :func:`save` measures the tight box itself; with any other, matplotlib does.
_OWN_PNG = {"bbox_inches", "pad_inches", "facecolor"}
PNG_LEVEL = 3
"""zlib level of :func:`save`'s PNGs: the double slider's solution at 200 dpi is ~445 kB at level 3 against
~350 kB at Pillow's default 6, in four fifths of the time."""


def _tight_box(fig, dpi: float, pad: float):
    """The figure's drawn extent in inches, plus ``pad``, measured at ``dpi`` as ``savefig`` would."""
    from matplotlib.backends.backend_agg import RendererAgg

    old = fig.dpi
    fig.dpi = dpi  # text extents depend on the resolution: measure at the one the file is drawn at
    try:
        box = fig.get_tightbbox(RendererAgg(1, 1, dpi))
    finally:
        fig.dpi = old
    return box.padded(pad)


__all__ = [
    "animate", "Animation", "comparison_rows", "draw_cycle", "draw_energy", "draw_force_polygon", "draw_free_bodies",
    "draw_free_body", "draw_given", "draw_grades", "draw_joint_force_index", "draw_mechanism", "draw_motion_polygon",
    "draw_motion_polygons", "draw_motion_steps", "draw_polar_forces", "draw_positions", "draw_shaking",
    "draw_shaking_components", "draw_sign_convention", "draw_solution", "draw_step_grid", "draw_steps",
    "draw_study", "draw_torque_curve", "draw_transmission_angle", "Drawn", "FORMATS", "loads_on", "measuring_renderer",
    "save", "style", "what_went_wrong",
]
