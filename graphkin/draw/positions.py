"""The mechanism at a few chosen positions, side by side at one scale (lesson 03: the blades during the cut)."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from graphkin.draw import style as _style
from graphkin.draw.axes import MM
from graphkin.draw.mechanism import draw_mechanism
from graphkin.draw.text import input_text, subscript
from graphkin.errors import GraphkinError
from graphkin.graphical import construct_forces
from graphkin.notation import fixed


def draw_positions(problem, at, *, between=None, cell=(4.4, 3.8), **style) -> Figure:
    """The mechanism at each of the positions ``at``, one panel each, left to right, all at one scale.

    Each panel is :func:`graphkin.draw.draw_mechanism` at one input position, titled with that position;
    every panel shows the same stretch of the plane, so a link that moves between two panels moves by
    as much on the page. A book draws a mechanism so at the positions where something happens: the
    strip cutter's blades at the start, middle and end of the cut.

    Parameters
    ----------
    problem : Problem
        A problem whose kinematics graphkin computes (not one of measured ``[given]`` kinematics).
    at : array_like, shape (n,)
        The input positions: crank angles [rad] for a crank, slider positions [m] for a slider.
    between : tuple of two (int, str), optional
        Two points, each ``(link, name)``, e.g. ``((3, "C"), (4, "C"))``: each panel's title also gives
        the vector from the second to the first [mm], ``C₃ − C₄ = (x, y) mm``.
    cell : tuple of float
        Width and height of one panel [in].
    **style
        Overrides of :class:`graphkin.draw.style.Style` fields.

    Returns
    -------
    Figure
        One axes per position, in the order of ``at``; each axes' title names its position.

    Raises
    ------
    GraphkinError
        If ``at`` is empty, or the problem has no kinematics of its own to compute.
    """
    at = np.atleast_1d(np.asarray(at, float))
    if at.ndim != 1 or at.size == 0:
        raise GraphkinError("draw_positions: 'at' must be one or more input positions")
    if not hasattr(problem, "kinematics") or getattr(problem, "mechanism", None) is None:
        raise GraphkinError("draw_positions: the problem has no mechanism whose positions graphkin computes")
    s = _style.resolve(**style)
    kin = problem.kinematics(at=at)
    fig = Figure(figsize=(cell[0] * at.size, cell[1]), dpi=100)
    axes = np.atleast_1d(fig.subplots(1, at.size))
    for n, ax in enumerate(axes):
        c = construct_forces(kin, n)
        draw_mechanism(c, ax=ax, bar=n == 0, **style)
        title = input_text(c)
        if between is not None and kin.valid[n]:
            (i, p), (j, r) = between
            gap = (kin.position(i, p)[n] - kin.position(j, r)[n]) * MM
            title += (f":  {p}{subscript(str(i))} − {r}{subscript(str(j))} = "
                      f"({fixed(gap[0], 1)}, {fixed(gap[1], 1)}) mm")
        ax.set_title(title, fontsize=s.title_size)
    _one_view(axes)
    fig.subplots_adjust(left=0.01, right=0.99, bottom=0.02, top=0.9, wspace=0.05)
    return fig


def _one_view(axes) -> None:
    """Give every panel the limits that hold them all, so that one mm of the plane is as long in each."""
    box = np.array([[*ax.get_xlim(), *ax.get_ylim()] for ax in axes])
    x0, x1, y0, y1 = box[:, 0].min(), box[:, 1].max(), box[:, 2].min(), box[:, 3].max()
    # A margin of 6 % a side: a point's label (B₀ at the right) stays inside its panel, not cut at the figure's edge.
    dx, dy = 0.06 * (x1 - x0), 0.06 * (y1 - y0)
    for ax in axes:
        ax.set_xlim(x0 - dx, x1 + dx)
        ax.set_ylim(y0 - dy, y1 + dy)
