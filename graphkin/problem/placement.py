"""A slider placed by another link's angle: the slider positions s at which the link stands at θ (``driver.place``).

θ(s) is found where the linkage stands, on its assembly branch, in three steps, each narrowed to the last bit:

1. the stretches of s where the linkage can be assembled, from a grid over the slider's reach, each end the last
   s that still assembles (a dead centre of a slider-crank: the crank and the rod in line);
2. the extremes of θ(s) inside each stretch (dθ/ds = 0, where the rod of a slider-crank leans most), which cut
   it into pieces on which θ(s) only rises or only falls;
3. the s of each piece at which θ(s) passes the wanted angle.

A sampled θ(s) alone would miss what lies between the last sample that assembles and the stretch's end: near a
dead centre s changes as the square of the crank's angle, so one step of the grid there spans degrees. At the
end itself rounding leaves the angle known only to about √ε; the dead centre's angle lies between the link's
angles on the two branches there, and a wanted angle in that gap is placed at the end.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from graphkin.kinematics import decompose, solve_kinematics
from graphkin.kinematics.structure import Dyad

GRID = 4001
"""Slider positions at which the linkage is first solved, over four times its size either way."""

SECTIONS = 128
"""Parts each bracket is cut into at every step of :func:`_narrow` (7 bits a step: a solve costs the same for one
position or a hundred)."""

STEPS = 200
"""Steps of :func:`_narrow` at most: floats crowd near 0, where a bracket may span 10³⁰⁰ of them."""

ANGLE = 4 * np.finfo(float).eps * math.pi
"""The rounding of an angle [rad]: a few ulps of π. At an extreme of θ(s) the curve is flat, and its top is only
known to that, so a target that much beyond a sample's angle is still taken there."""


@dataclass(frozen=True)
class Stretch:
    """A stretch of slider positions where the linkage stands, and the angles the placed link takes on it.

    Attributes
    ----------
    s : (float, float)
        Its first and last slider position [m].
    theta : (float, float)
        The smallest and largest angle of the link on it [rad], unwrapped: the smallest in (−π, π].
    rounding : float
        How well the angles at its ends are known [rad]: at a dead centre, the gap between the link's angles on
        the two branches there (:func:`_toggle`); 0 at an end of the grid.
    """

    s: tuple[float, float]
    theta: tuple[float, float]
    rounding: float = 0.0

    @property
    def every_angle(self) -> bool:
        """Whether the link turns a whole turn or more on this stretch."""
        return self.theta[1] - self.theta[0] >= 2 * math.pi


@dataclass(frozen=True)
class Placement:
    """Where a link stands at an angle: the slider positions [m], ascending, and the link's reach (its stretches)."""

    s: tuple[float, ...]
    reach: tuple[Stretch, ...]


def _wrap(x):
    """An angle [rad] in [−π, π)."""
    return (np.asarray(x) + math.pi) % (2 * math.pi) - math.pi


class _Motion:
    """θ of one link against the slider's position s, on the mechanism's branch."""

    def __init__(self, mech, link):
        self.mech, self.link = mech, link

    def __call__(self, s):
        """θ [rad] and dθ/ds [rad/m] at positions s [m] (any shape); θ nan where the linkage does not stand."""
        s = np.asarray(s, dtype=float)
        if not s.size:
            return s.copy(), s.copy()
        kin = solve_kinematics(self.mech, s.ravel(), 1.0, 0.0)
        stands = np.logical_and.reduce([np.isfinite(kin.theta[k]) for k in self.mech.moving])
        return (np.where(stands, kin.theta[self.link], np.nan).reshape(s.shape),
                kin.omega[self.link].reshape(s.shape))


def _narrow(a, b, on_a_side):
    """Narrow the brackets [a, b] (arrays; a on one side, b on the other) down to adjacent floats.

    ``on_a_side(m)`` takes positions of shape (brackets, k) and says, for each, whether it lies on a's side.
    Each step cuts every bracket into :data:`SECTIONS` parts and keeps the one where the side changes. Returns the
    last a and b.
    """
    a, b = np.array(a, dtype=float), np.array(b, dtype=float)
    cuts = np.arange(1, SECTIONS) / SECTIONS
    for _ in range(STEPS):
        if not (np.nextafter(a, b) != b).any():
            break
        m = a[:, None] + (b - a)[:, None] * cuts
        # The cuts on a's side before the first on b's: the side changes after the last of them.
        j = np.argmin(np.c_[on_a_side(m), np.zeros(a.size, bool)], axis=1)
        rows = np.arange(a.size)
        a, b = np.where(j > 0, m[rows, j - 1], a), np.where(j < cuts.size, m[rows, np.minimum(j, cuts.size - 1)], b)
    return a, b


def placements(mech, link: int, target: float) -> Placement:
    """The slider positions at which ``link`` stands at ``target``, on the mechanism's assembly branch.

    Parameters
    ----------
    mech : Mechanism
        Driven by a slider.
    link : int
        The moving link whose angle places the slider.
    target : float
        Its angle [rad] (taken modulo a turn).

    Returns
    -------
    Placement
        Every slider position [m] where it stands there, the ends of a stretch (dead centres) included, and the
        angles it reaches on each stretch where the linkage stands. A stretch narrower than a step of the grid
        (a 500th of the mechanism's size) is not seen.
    """
    motion = _Motion(mech, link)
    size = max([math.hypot(x1 - x0, y1 - y0) for k in mech.links for (x0, y0) in k.points.values()
                for (x1, y1) in k.points.values()] + [1e-3])
    stretches = _stretches(motion, np.linspace(-4 * size, 4 * size, GRID))
    if not stretches:
        return Placement((), ())
    reach, brackets = [], []
    for s, theta, tol in stretches:
        turn = 2 * math.pi * math.ceil((theta.min() - math.pi) / (2 * math.pi))
        reach.append(Stretch((float(s[0]), float(s[-1])), (float(theta.min() - turn), float(theta.max() - turn)),
                             max(tol)))
        brackets.append(_brackets(s, theta, target, tol))
    roots = sorted(_roots(motion, *(np.concatenate(column) for column in zip(*brackets))))
    return Placement(tuple(x for j, x in enumerate(roots) if j == 0 or x - roots[j - 1] > 1e-9 * size), tuple(reach))


def _stretches(motion, grid) -> list:
    """Each stretch of ``grid`` where the linkage stands: its samples s in order (its ends, the grid between,
    the extremes of θ), θ there unwrapped, and how far [rad] beyond the angle at each end a target may lie
    (:func:`_toggle`; 0 at an end of the grid)."""
    theta, omega = motion(grid)
    stands = np.isfinite(theta)
    # 1. Its ends: the last position that still assembles, next to one that does not.
    k = np.flatnonzero(stands[:-1] != stands[1:])
    ends, _ = _narrow(np.where(stands[k], grid[k], grid[k + 1]), np.where(stands[k], grid[k + 1], grid[k]),
                      lambda m: np.isfinite(motion(m)[0]))
    end = dict(zip(k.tolist(), ends.tolist()))
    slack = dict(zip(ends.tolist(), _toggle(motion, ends).tolist()))
    # 2. The extremes of θ(s): dθ/ds changes sign between two samples (both finite: neither at a dead point).
    rises = np.sign(omega)
    k = np.flatnonzero(stands[:-1] & stands[1:] & np.isfinite(omega[:-1]) & np.isfinite(omega[1:])
                       & (rises[:-1] * rises[1:] < 0))
    extremes, _ = _narrow(grid[k], grid[k + 1], lambda m, r=rises[k, None]: np.sign(motion(m)[1]) == r)
    out = []
    at = np.flatnonzero(stands)
    for run in np.split(at, np.flatnonzero(np.diff(at) > 1) + 1) if at.size else []:
        i0, i1 = int(run[0]), int(run[-1])
        lo, hi = end.get(i0 - 1, grid[0]), end.get(i1, grid[-1])
        inner = extremes[(extremes > grid[i0]) & (extremes < grid[i1])]
        out.append((np.unique(np.concatenate([[lo], grid[i0:i1 + 1], inner, [hi]])), (slack.get(lo, 0.0),
                    slack.get(hi, 0.0))))
    if not out:
        return []
    theta = np.split(motion(np.concatenate([s for s, _ in out]))[0], np.cumsum([s.size for s, _ in out])[:-1])
    return [(s, np.unwrap(th), tol) for (s, tol), th in zip(out, theta)]


def _toggle(motion, ends) -> np.ndarray:
    """At each end of assembly, how far [rad] the link's angle there may lie from the dead centre's.

    Rounding stops the assembly a hair before the dead centre, where the dyad that toggles has its two branches
    a square root apart (√ε of its size): the dead centre lies between them, so the link's angle there lies
    between its angles on the two branches. The dyad that toggles is the one whose other branch moves the
    linkage's points least at the end (any other moves one by about a link's length). With no dyad: 0.
    """
    if not ends.size:
        return ends.copy()
    mech = motion.mech
    here = solve_kinematics(mech, ends, 1.0, 0.0)
    gap, least = np.zeros(ends.size), np.full(ends.size, np.inf)
    for key in sorted({g.key for g in decompose(mech) if isinstance(g, Dyad)}):
        there = solve_kinematics(replace(mech, assembly={**mech.assembly, key: -mech.assembly.get(key, 1)}), ends,
                                 1.0, 0.0)
        moved = np.max([np.abs(there.z(k, p) - here.z(k, p)) for k in mech.moving for p in mech.link(k).points],
                       axis=0)
        closer = moved < least
        least = np.where(closer, moved, least)
        gap = np.where(closer, np.abs(_wrap(there.theta[motion.link] - here.theta[motion.link])), gap)
    return gap


def _brackets(s, theta, target, tol):
    """Each pair of neighbouring samples of a stretch whose angles take in a turn of ``target``: (s, s′, θ, θ′, t).

    Between two samples θ only rises or only falls (the extremes are samples). Each sample takes a target up to
    :data:`ANGLE` beyond the angle it reaches; the stretch's first and last, up to ``tol`` [rad] if that is more.
    """
    if s.size == 1:  # a stretch of one position: a pair of it with itself
        s, theta = np.r_[s, s], np.r_[theta, theta]
    a, b = theta[:-1], theta[1:]
    beyond_a, beyond_b = np.full(a.size, ANGLE), np.full(b.size, ANGLE)
    beyond_a[0], beyond_b[-1] = max(tol[0], ANGLE), max(tol[1], ANGLE)
    sense = np.where(b < a, -1.0, 1.0)
    low, high = np.minimum(a - sense * beyond_a, b + sense * beyond_b), np.maximum(a - sense * beyond_a,
                                                                                 b + sense * beyond_b)
    first = np.ceil((low - target) / (2 * math.pi))
    count = np.maximum(np.floor((high - target) / (2 * math.pi)) - first + 1, 0).astype(int)
    pair = np.repeat(np.arange(a.size), count)
    turns = first[pair] + np.arange(pair.size) - np.repeat(np.cumsum(count) - count, count)
    return s[pair], s[pair + 1], a[pair], b[pair], target + 2 * math.pi * turns


def _roots(motion, sa, sb, ta, tb, t) -> list[float]:
    """Where θ(s) = t between each pair (sa, sb) of angles (ta, tb): narrowed to adjacent floats, the nearer one
    taken; a t beyond both angles (by the slack of an end) is placed at the nearer end."""
    if not sa.size:
        return []
    side = np.sign(ta - t)
    x, y = _narrow(sa, sb, lambda m: np.sign(_wrap(motion(m)[0] - t[:, None])) == side[:, None])
    root = np.where(np.abs(_wrap(motion(x)[0] - t)) <= np.abs(_wrap(motion(y)[0] - t)), x, y)
    nearer = np.where(np.abs(t - ta) <= np.abs(t - tb), sa, sb)
    root = np.where((t - ta) * (t - tb) > 0, nearer, root)
    return np.where(ta == t, sa, np.where(tb == t, sb, root)).tolist()
