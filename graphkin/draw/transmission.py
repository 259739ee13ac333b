"""The transmission angle of a crank-driven four-bar over its cycle, with the rule of thumb's band (lesson 03)."""

from __future__ import annotations

import numpy as np

from graphkin.draw import style as _style
from graphkin.draw.axes import Drawn, line
from graphkin.draw.cycle import _drawn, _input_axis, _rect_axes, _theta, _x

RULE = 40.0
"""The rule of thumb's least transmission angle [deg]: μ within 90° ± 50°."""


def draw_transmission_angle(cycle, *, ax=None, **style) -> Drawn:
    """The transmission angle μ against the crank angle, the band μ < 40° shaded.

    μ is :meth:`graphkin.cycle.Cycle.transmission_angle`, folded to [0°, 90°]
    (an angle and its supplement transmit force alike); below 40° the coupler
    turns the rocker poorly and the pin forces grow.

    Parameters
    ----------
    cycle : Cycle
        A sweep of a crank-driven four-bar of revolute joints.
    ax : Axes, optional
        Where to draw; a new figure if None.

    Returns
    -------
    Drawn
        ``curves``: ``"mu"`` (input [deg], μ [deg]) and ``"least"`` (the point of least μ); ``labels``:
        ``"least"``, its annotation.

    Raises
    ------
    GraphkinError
        If the mechanism is not such a four-bar (the message says why).
    """
    mu = np.degrees(cycle.transmission_angle())
    s = _style.resolve(**style)
    ax = _rect_axes(ax)
    d = _drawn(ax)
    x = _x(cycle.q, True)
    d.curves["mu"] = d.add(line(ax, x, mu, color=s.unknown, lw=1.6, label="μ"))
    worst = int(np.nanargmin(mu))
    d.curves["least"] = d.add(ax.plot([x[worst]], [mu[worst]], "o", color=s.unknown, ms=5)[0])
    d.labels["least"] = d.add(ax.annotate(f"least μ = {mu[worst]:.1f}°", (x[worst], mu[worst]),
                                          textcoords="offset points", xytext=(8, 8), fontsize=s.label_size,
                                          color=s.ink))
    ax.axhspan(0.0, RULE, color=s.unknown, alpha=0.08, lw=0)
    ax.axhline(RULE, color=s.ink, lw=0.6, ls=":")
    ax.set_ylim(0.0, 90.0)
    _input_axis(ax, True, _theta(cycle.problem.mechanism))
    ax.set_ylabel("transmission angle μ [deg]")
    ax.set_title(f"Transmission angle over the cycle (below {RULE:g}° shaded)", fontsize=s.title_size)
    return d
