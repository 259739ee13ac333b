"""One turn of a crank sampled at a set of angles: the periodic trapezoidal rule."""

from __future__ import annotations

import math

import numpy as np

TURN = 2 * math.pi
"""One turn of the crank [rad]."""


def closing_step(theta, period: float = TURN) -> float | None:
    """Step from the last angle back round to the first [rad], or None if ``theta`` is not one cycle.

    ``theta`` is one cycle when it is strictly monotonic, spans less than
    ``period`` (one turn, 2π, unless said: a four-stroke engine's cycle is
    4π), and the gap left to close the cycle is no wider than its widest
    step (0 when the last angle repeats the first one cycle on, e.g. 0°…360°).

    Examples
    --------
    >>> bool(np.isclose(closing_step(np.radians(np.arange(0, 360, 2.0))), np.radians(2)))
    True
    >>> closing_step(np.radians([0.0, 90.0])) is None
    True
    """
    theta = np.asarray(theta, dtype=float)
    if theta.ndim != 1 or len(theta) < 2 or not np.all(np.isfinite(theta)):
        return None
    d = np.abs(np.diff(theta))
    if not (np.all(np.diff(theta) > 0) or np.all(np.diff(theta) < 0)):
        return None
    gap = period - abs(theta[-1] - theta[0])
    tol = 1e-9 * period
    if gap < -tol or gap > d.max() * (1 + 1e-9) + tol:
        return None
    return max(gap, 0.0)


def steps(theta, gap: float) -> np.ndarray:
    """Widths [rad] of the n intervals of a closed turn: sample k to k+1, the last one closing the turn."""
    return np.append(np.abs(np.diff(np.asarray(theta, dtype=float))), gap)


def weights(theta, gap: float) -> np.ndarray:
    """Periodic trapezoid weights w_k [rad]: ∮ f dθ ≈ Σ w_k f_k, with Σ w_k = 2π."""
    h = steps(theta, gap)
    return 0.5 * (h + np.roll(h, 1))
