"""The shaking force on the frame as its x and y components against the input (lesson 12's balancing)."""

from __future__ import annotations

from graphkin.draw import style as _style
from graphkin.draw.axes import Drawn, line
from graphkin.draw.cycle import _drawn, _input_axis, _is_crank, _rect_axes, _theta, _x


def draw_shaking_components(cycle, *, ax=None, **style) -> Drawn:
    """The shaking force on the frame as its x and y components against the input.

    For an engine whose line of stroke is the x axis these are the unbalanced
    force along the stroke and across it: what a counterweight trades one for
    the other (lesson 12). :func:`draw_shaking` draws the same force in polar form.

    Parameters
    ----------
    cycle : Cycle
    ax : Axes, optional
        Where to draw; a new figure if None.

    Returns
    -------
    Drawn
        ``curves``: ``"S_x"`` and ``"S_y"`` (input, component [N]).
    """
    s = _style.resolve(**style)
    ax = _rect_axes(ax)
    d = _drawn(ax)
    crank = _is_crank(cycle.problem.mechanism)
    S = cycle.shaking_force()
    x = _x(cycle.q, crank)
    d.curves["S_x"] = d.add(line(ax, x, S[:, 0], color=s.unknown, lw=1.6, label="$S_x$ (along x)"))
    d.curves["S_y"] = d.add(line(ax, x, S[:, 1], color=s.known, lw=1.6, ls="--", label="$S_y$ (along y)"))
    ax.axhline(0.0, color=s.ink, lw=0.6)
    _input_axis(ax, crank, _theta(cycle.problem.mechanism))
    ax.set_ylabel("shaking force component [N]")
    ax.set_title("Shaking force on the frame: its x and y components", fontsize=s.title_size)
    ax.legend(loc="best", fontsize=s.label_size)
    return d
