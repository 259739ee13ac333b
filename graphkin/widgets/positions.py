"""Where the explorer moves a slider-driven problem whose file gives one position: where its linkage assembles.

A crank turns 0–360°, and the scene samples the turn. A slider-driven problem is drawn at its own positions
(:func:`graphkin.scene.scene`); a file that gives one (``double_slider``) would be a still picture, so the explorer
moves the slider over the span where the linkage assembles (:func:`assembling_span`), or over the range asked for, at
its own speed.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from graphkin.errors import GraphkinError


def _link_size(link) -> float:
    pts = np.array(list(link.points.values()), float).reshape(-1, 2)
    if len(pts) < 2:
        return 0.0
    return float(np.max(np.hypot(*(pts[:, None, :] - pts[None, :, :]).transpose(2, 0, 1))))


def assembling_span(problem, q0: float, n: int) -> tuple[float, float]:
    """Where a slider-driven linkage assembles around q0 [m], with one step of margin (its dead ends included).

    Searched over q0 ± twice the total length of the moving links.

    Parameters
    ----------
    problem : graphkin.Problem
        At a constant input speed.
    q0 : float
        The file's position [m].
    n : int
        The search takes ``4 n + 1`` positions.

    Returns
    -------
    (float, float)
        The span [m].
    """
    L = 2.0 * (sum(_link_size(link) for link in problem.mechanism.links if link.number != 1) or 0.5)
    q = np.linspace(q0 - L, q0 + L, 4 * n + 1)
    try:
        ok = np.flatnonzero(problem.kinematics(q).valid)
    except GraphkinError:
        ok = np.zeros(0, int)
    if not len(ok):
        return q0 - L / 2, q0 + L / 2
    step = q[1] - q[0]
    return float(q[ok[0]] - step), float(q[ok[-1]] + step)


def spread(problem, n: int, limits=None):
    """The problem the explorer draws: a slider driver whose file gives one position moved over a span.

    Parameters
    ----------
    problem : graphkin.Problem
    n : int
        Positions over the span.
    limits : (float, float), optional
        The span [mm]; by default where the linkage assembles (:func:`assembling_span`). Only for a slider driver.

    Returns
    -------
    graphkin.Problem
        ``problem`` itself for a crank, or for a slider driver whose file gives a range of positions; else the same
        problem at ``n`` positions, at its own speed, a book's measured values (``[given]``, which hold at its own
        position only) dropped.
    """
    crank = problem.mechanism.driver.crank
    if limits is not None and crank:
        raise GraphkinError("explore: limits are a slider driver's range [mm]; a crank turns 0–360°")
    q = np.asarray(problem.q, float)
    if crank or (limits is None and float(np.ptp(q)) > 1e-9):
        return problem
    moving = problem.without_given()
    if limits is None:
        lo, hi = assembling_span(moving.at_speed(float(moving.q_dot[0])), float(q[0]), n)
    else:
        try:
            lo, hi = (float(x) * 1e-3 for x in limits)
        except (TypeError, ValueError):
            raise GraphkinError(f"explore: limits must be (low, high) [mm], got {limits!r}") from None
        if not (np.isfinite(lo) and np.isfinite(hi) and hi > lo):
            raise GraphkinError(f"explore: limits must be (low, high) with high > low [mm], got {limits!r}")
    return replace(moving, q=np.linspace(lo, hi, n), q_dot=np.full(n, moving.q_dot[0]),
                   q_ddot=np.full(n, moving.q_ddot[0]))
