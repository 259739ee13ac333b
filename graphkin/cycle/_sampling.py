"""Where a sweep samples the input, and the extremes read off it (used by the cycle and the joint-force index).

Kept apart from :mod:`graphkin.cycle.sweep` so that the joint-force index
(:mod:`graphkin.cycle.index`) and the cycle both import it, one way, and
neither imports the other's importer.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from graphkin.cycle.turn import TURN, closing_step
from graphkin.errors import GraphkinError
from graphkin.ranges import MAX_POSITIONS

if TYPE_CHECKING:
    from graphkin.problem import Problem


def positions(problem: "Problem", n: int | None = None) -> np.ndarray | None:
    """The input positions a sweep uses: None for the problem's own, else n crank angles over one turn.

    Parameters
    ----------
    problem : Problem
    n : int, optional
        Number of equally spaced crank angles θ = 2πk/n [rad], k = 0 … n−1.
        Only for a crank driver: a slider has no natural "one turn", so a
        slider-driven problem is swept at its own positions.

    Raises
    ------
    GraphkinError
        If n is given for a slider driver, or is not a whole number ≥ 2.
    """
    if n is None:
        return None
    if not problem.mechanism.driver.crank:
        raise GraphkinError(
            f"{problem.name}: the driver is a slider, so there is no turn to divide into n positions;"
            " sweep it at the problem's own positions (n=None)"
        )

    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 2 <= n <= MAX_POSITIONS:
        raise GraphkinError(f"n must be a whole number of positions from 2 to {MAX_POSITIONS:,} (the limit of a "
                            f"problem file's ranges: 1° steps need 360, 0.01° steps 36,000), got {n!r}")
    return np.linspace(0.0, TURN, int(n), endpoint=False)


SWITCH = 1e-9
"""Half-width of the pair of samples put either side of a switching angle [rad] (or of a slider's span)."""


def switching_angles(problem: "Problem") -> list[float]:
    """Where a load jumps: it switches on or off, its table jumps, or its sense follows a reversal of the motion.

    Input units (rad or m), ascending, no repeats.
    """
    ends = set()
    for load in problem.mechanism.loads:
        if load.active is not None:
            ends |= {load.active.start, load.active.stop}
        if load.table is not None:
            ends |= set(load.table.jumps())
        if load.sense != "fixed" or getattr(load, "back", None) is not None:
            # A stroke table with a return column switches at the dead centres, where the piston reverses.
            ends |= set(reversals(problem, load))
    return sorted(ends)


REVERSAL_GRID = 720
"""Positions over the cycle at which a motion-following load's sense is first looked at, before bisection."""


def reversals(problem: "Problem", load) -> list[float]:
    """Where the motion a load follows reverses: its point's velocity along the load's line (a torque: its link's ω).

    Sign changes are found on :data:`REVERSAL_GRID` positions over a turn
    (a slider: over the problem's span) and each is bisected to the last
    bit (60 halvings, all at once) with the problem's own input speed.
    """
    mech = problem.mechanism
    crank = mech.driver.crank
    if crank:
        q = np.linspace(0.0, TURN, REVERSAL_GRID + 1)
    else:
        lo, hi = float(np.min(problem.q)), float(np.max(problem.q))
        if hi <= lo:
            return []
        q = np.linspace(lo, hi, REVERSAL_GRID + 1)

    def rate(at):
        kin = problem.kinematics(at)
        if hasattr(load, "point"):
            v = kin.z_velocity(load.link, load.point)
            u = complex(*load.force)
            # At a dead point a velocity is infinite, and along a line it does not move on (0 · ∞) not a number.
            with np.errstate(invalid="ignore"):
                r = v.real * u.real + v.imag * u.imag
        else:
            r = kin.w(load.link)
        # Where the linkage does not assemble, or stands at a dead point, there is no motion to follow.
        return np.where(kin.valid, r, np.nan)

    r = rate(q)
    sign = np.sign(r)
    k = np.flatnonzero((sign[:-1] * sign[1:] < 0) & np.isfinite(r[:-1]) & np.isfinite(r[1:]))
    zero = [float(q[j]) for j in np.flatnonzero(sign == 0)]
    if not k.size:
        return sorted({x % TURN if crank else x for x in zero})
    a, b, ra = q[k].copy(), q[k + 1].copy(), r[k].copy()
    for _ in range(60):
        m = 0.5 * (a + b)
        rm = rate(m)
        left = np.sign(rm) == np.sign(ra)
        a, ra = np.where(left, m, a), np.where(left, rm, ra)
        b = np.where(left, b, m)
    roots = 0.5 * (a + b)
    return sorted({float(x % TURN) if crank else float(x) for x in list(roots) + zero})


def switching_samples(problem: "Problem", q: np.ndarray) -> np.ndarray:
    """``q`` with two more samples, just before and just after, each place a load switches on or off.

    A load that acts over part of the cycle (the strip cutter's cutting force
    for 124° < θ < 156°) makes the driving effort jump there. Sampled on a
    plain grid, the jump falls inside a step and the trapezoidal rule errs by
    up to half a step times the jump, an error only first order in the step.
    With samples at b ∓ δ (δ = :data:`SWITCH`) the curve is smooth between
    samples again and the rule is second order; a plot draws the jump as a
    vertical line where it belongs.

    Only ascending positions are refined (others are returned unchanged);
    :func:`sweep` refines a problem's own positions only when its input
    rates are constant and it gives no kinematic values per position.
    """
    q = np.asarray(q, dtype=float)
    ends = switching_angles(problem)
    if not ends or len(q) < 2 or not np.all(np.diff(q) > 0):
        return q
    crank = problem.mechanism.driver.crank
    delta = SWITCH if crank else SWITCH * (q[-1] - q[0])
    end = q[0] + TURN if crank and closing_step(q) is not None else q[-1]
    extra = []
    for b in ends:
        for c in (b - delta, b + delta):
            if crank:
                c = q[0] + (c - q[0]) % TURN
            if q[0] < c < end:
                extra.append(c)
    return np.unique(np.concatenate([q, extra]))


def check_problem(problem, what: str) -> None:
    """A plain error if ``problem`` is not a :class:`graphkin.problem.Problem` (by its parts, to keep layers apart)."""
    if not all(hasattr(problem, name) for name in ("mechanism", "q", "solve", "kinematics")):
        raise GraphkinError(f"{what} takes a Problem (graphkin.catalog.load(name) or graphkin.problem.load_problem"
                            f"(path)), got {type(problem).__name__}")


def sweep_positions(problem: "Problem", n: int | None = None) -> np.ndarray | None:
    """The positions :func:`sweep` solves at: :func:`positions` with :func:`switching_samples` added (None: the problem's own)."""
    q = positions(problem, n)
    if q is None and len(set(problem.q_dot)) == 1 and len(set(problem.q_ddot)) == 1 and not problem.given:
        q = problem.q
    return None if q is None else switching_samples(problem, q)


@dataclass(frozen=True)
class Peak:
    """An extreme value over the cycle and where it occurs.

    Attributes
    ----------
    value : float
        The extreme value (its unit is that of the quantity: N, N·m, ...).
    at : float
        Input position where it occurs: θ [rad] or s [m]; nan if no position is valid.
    index : int
        Index of that position in the sweep; −1 if no position is valid.
    """

    value: float
    at: float
    index: int


def peak_of(values, q, *, lowest: bool = False) -> Peak:
    """Largest (or lowest) finite value of ``values`` (n,) and the position ``q`` where it occurs."""
    values = np.asarray(values, dtype=float)
    finite = np.isfinite(values)
    if not finite.any():
        return Peak(float("nan"), float("nan"), -1)
    masked = np.where(finite, values, np.inf if lowest else -np.inf)
    i = int(np.argmin(masked) if lowest else np.argmax(masked))
    return Peak(float(values[i]), float(q[i]), i)
