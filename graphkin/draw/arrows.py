"""Force arrows and couple arrows, and the plane-vector helpers they need."""

from __future__ import annotations

import math

import numpy as np
from matplotlib.patches import ArrowStyle, FancyArrowPatch
from matplotlib.path import Path

from graphkin.draw.axes import put


def unit(v):
    """``v`` scaled to length 1 (``(1, 0)`` for a zero vector)."""
    v = np.asarray(v, dtype=float)
    n = float(np.hypot(*v))
    return v / n if n else np.array([1.0, 0.0])


def perp(v):
    """``v`` turned 90° counter-clockwise."""
    return np.array([-v[1], v[0]], dtype=float)


def arrow(ax, tail, tip, *, color, lw, s, hollow=False, zorder=4.0, gid=None, alpha=None, pt_per_unit=None):
    """A force arrow from ``tail`` to ``tip`` (data coordinates); its head's point is at ``tip``.

    With ``pt_per_unit`` (points per data unit), the head of a short arrow is
    shrunk to at most half the arrow's length, so it never outgrows it.
    """
    head = s.head * (0.95 if hollow else 1.0)
    if pt_per_unit:
        length_pt = float(np.hypot(*(np.asarray(tip, float) - np.asarray(tail, float)))) * pt_per_unit
        head = min(head, max(length_pt * 0.5 / 0.75, 2.0))
    a = FancyArrowPatch(
        tuple(map(float, tail)), tuple(map(float, tip)),
        arrowstyle=ArrowStyle("-|>", head_length=0.75, head_width=0.3),
        mutation_scale=head, shrinkA=0, shrinkB=0, lw=lw,
        edgecolor=color, facecolor="white" if hollow else color,
        capstyle="butt", joinstyle="miter", zorder=zorder, alpha=alpha)
    if gid:
        a.set_gid(gid)
    return put(ax, a, [tail, tip])


def arc_points(centre, radius, a0, a1, n=48):
    """``n`` points of the arc of ``radius`` around ``centre`` from angle ``a0`` to ``a1`` [rad]."""
    t = np.linspace(a0, a1, n)
    return np.column_stack([centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)])


def moment_arrow(ax, centre, radius, ccw: bool, *, color, lw, s, start=-0.75 * math.pi, span=1.5 * math.pi, zorder=4.0,
                 gid=None):
    """A curved arrow of a couple around ``centre``: counter-clockwise when ``ccw``.

    Returns (patch, polyline of the arc, the point at the arc's middle).
    """
    a0, a1 = (start, start + span) if ccw else (start + span, start)
    pts = arc_points(centre, radius, a0, a1)
    a = FancyArrowPatch(path=Path(pts), arrowstyle=ArrowStyle("-|>", head_length=0.75, head_width=0.3),
                        mutation_scale=s.head, shrinkA=0, shrinkB=0, lw=lw, edgecolor=color, facecolor=color,
                        capstyle="butt", joinstyle="miter", zorder=zorder)
    if gid:
        a.set_gid(gid)
    put(ax, a, pts)
    mid = pts[len(pts) // 2]
    return a, pts, mid
