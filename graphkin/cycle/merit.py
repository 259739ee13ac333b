"""The figures of merit of one design of a study, read off its cycle (:class:`Design`, :func:`merit`).

A designer judges a choice by what it costs over the whole cycle (Norton, *Design of Machinery*, ch. 11): the peak
and RMS driving torque, the flywheel it needs, the peak force at each joint, the shaking force and moment on the
frame, the smallest transmission angle. A design that cannot be assembled somewhere on its cycle has none of them
(nan): a peak over part of a cycle would look better than the design is. :func:`merit` reads them off one
:class:`~graphkin.cycle.Cycle`; :func:`batch_merits` off a batch of designs solved together (what
:func:`graphkin.cycle.study` does), array by array, each design's to rounding.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import SimpleNamespace
from typing import Mapping

import numpy as np

from graphkin.analytical.designs import Batch, solve_designs
from graphkin.cycle.sweep import Cycle
from graphkin.cycle.turn import TURN, closing_step, steps, weights
from graphkin.errors import GraphkinError
from graphkin.geometry import zcross
from graphkin.model import Prismatic, Revolute
from graphkin.model.names import force_name
from graphkin.notation import position_text

__all__ = ["Design", "Shared", "batch_merits", "failed", "merit", "unbuilt"]

@dataclass(frozen=True)
class Design:
    """One design of a study and its figures of merit over the cycle (SI units; nan where not defined).

    Attributes
    ----------
    values : tuple
        The value of each varied field, in the order of :attr:`Study.fields`, as given (problem-file values).
    torque_peak : float
        Largest |T1j| over the cycle [N·m] (a slider driver: |F1j| [N]).
    torque_rms : float
        Root mean square of the driving effort, √(mean T²) by the cycle's trapezoidal rule
        (:meth:`Cycle.mean`) [N·m] (or [N]).
    joint_peaks : dict of str to float
        Largest |F| at each joint over the cycle [N], by the force's name (``"F12"``, ``"F23"``, ...).
    I_s : float
        The flywheel's system inertia for the study's C_s [kg·m²] (:meth:`Cycle.flywheel`); nan where none can
        be sized, and :attr:`no_flywheel` says why.
    shaking_force_peak : float
        Largest |Σ F_j1| on the frame [N] (:meth:`Cycle.shaking_force`).
    shaking_moment_peak : float
        Largest |M| of the mechanism on the frame about the origin [N·m] (:meth:`Cycle.shaking_moment`).
    transmission_angle_min : float
        Smallest transmission angle μ over the cycle [rad] (folded to [0, π/2]); nan for a linkage that is not
        a crank-driven four-bar of revolutes.
    failure : str or None
        Where and why the design cannot be assembled over the whole cycle (its first such position); None if it
        can.
    failed_at : float
        That position, θ [rad] or s [m]; nan if the design assembles everywhere.
    no_flywheel : str or None
        Why no flywheel can be sized (:meth:`Cycle.why_no_flywheel`); None if one can.
    """

    values: tuple
    torque_peak: float
    torque_rms: float
    joint_peaks: Mapping[str, float]
    I_s: float
    shaking_force_peak: float
    shaking_moment_peak: float
    transmission_angle_min: float
    failure: str | None = None
    failed_at: float = math.nan
    no_flywheel: str | None = None

    @property
    def ok(self) -> bool:
        """True if the design assembles at every position of its cycle."""
        return self.failure is None




def unbuilt(values: tuple, why: str) -> Design:
    """A design whose values, together, make no mechanism (each alone does): marked, its figures nan."""
    nan = math.nan
    return Design(values, nan, nan, {}, nan, nan, nan, nan, why, nan, "the design cannot be built")


def failed(values: tuple, names: list, count: int, q: np.ndarray, i: int, crank: bool, reason: str) -> Design:
    """A design that has no solution at ``count`` of the positions ``q``, the first ``q[i]``, for ``reason``."""
    nan = math.nan
    return Design(values, nan, nan, dict.fromkeys(names, nan), nan, nan, nan, nan,
                  f"no solution at {count} of the {len(q)} positions, the first at {position_text(q[i], crank)}: "
                  f"{reason}", float(q[i]), "the design cannot be assembled over the whole cycle")


def merit(cycle: Cycle, values: tuple, Cs: float) -> Design:
    """The figures of merit of one design's cycle (see :class:`Design`).

    Parameters
    ----------
    cycle : Cycle
        The design swept over its cycle.
    values : tuple
        The design's values of the varied fields.
    Cs : float
        Coefficient of speed fluctuation for the flywheel.
    """
    names = [cycle.analysis.name_of(i, j) for (i, j) in cycle.analysis.forces]
    bad = np.flatnonzero(~cycle.valid)
    if len(bad):
        i = int(bad[0])
        return failed(values, names, len(bad), cycle.q, i, cycle.problem.mechanism.driver.crank,
                       cycle.analysis.reason(i))
    T = cycle.torque
    peaks = cycle.peaks().forces
    why = cycle.why_no_flywheel()
    try:
        mu = float(np.min(cycle.transmission_angle()))
    except GraphkinError:  # not a crank-driven four-bar: μ is not defined (the joint-force index is)
        mu = math.nan
    return Design(
        values=values,
        torque_peak=float(np.max(np.abs(T))),
        torque_rms=math.sqrt(cycle.mean(T * T)),
        joint_peaks={name: peaks[name].value for name in names},
        I_s=math.nan if why else cycle.flywheel(Cs).I_s,
        shaking_force_peak=float(np.max(np.hypot(*cycle.shaking_force().T))),
        shaking_moment_peak=float(np.max(np.abs(cycle.shaking_moment()))),
        transmission_angle_min=mu,
        no_flywheel=why,
    )


def _means(q: np.ndarray, f: np.ndarray, w: np.ndarray | None = None) -> np.ndarray:
    """:meth:`Cycle.mean` of each row of ``f`` (designs, positions), by the same rule (``w``: the periodic
    trapezoid weights of ``q``, if worked out already)."""
    if w is not None:
        return np.sum(w * f, axis=1) / TURN
    gap = closing_step(q)
    if gap is not None:
        return np.sum(weights(q, gap) * f, axis=1) / TURN
    if len(q) < 2 or q[-1] == q[0]:
        return f[:, 0] if len(q) == 1 else np.full(len(f), math.nan)
    return np.sum(0.5 * (f[:, 1:] + f[:, :-1]) * np.diff(q), axis=1) / (q[-1] - q[0])


def _four_bar(mech) -> tuple | None:
    """The pins (link, point) of a crank-driven four-bar's transmission angle: A and B on the coupler, B0 on the
    frame (:meth:`Cycle.transmission_angle`); None for another linkage."""
    if not (len(mech.links) == 4 and len(mech.joints) == 4 and mech.driver.crank
            and all(isinstance(j, Revolute) for j in mech.joints)):
        return None
    crank = mech.driver.link
    coupler = [j for j in mech.moving if j != crank and any(set(J.links) == {crank, j} for J in mech.joints)]
    if len(coupler) != 1:
        return None
    (coupler,) = coupler
    (rocker,) = [j for j in mech.moving if j not in (crank, coupler)]
    return ((coupler, mech.joint_between(crank, coupler).point), (coupler, mech.joint_between(coupler, rocker).point),
            (mech.frame, mech.joint_between(mech.frame, rocker).point))


def _frame_pins(mech, forces) -> list:
    """Each joint with the frame, in the order of ``forces`` (pairs of links): (joint, moving link, the point its
    force acts at)."""
    out = []
    for i, j in forces:
        if mech.frame in (i, j):
            joint = mech.joint_between(i, j)
            at = (joint.slider, joint.point) if isinstance(joint, Prismatic) else (mech.frame, joint.point)
            out.append((joint, j if i == mech.frame else i, at))
    return out


def _shaking(b: Batch, mech, pins) -> tuple[np.ndarray, np.ndarray]:
    """The shaking force (complex) and moment of each design at each position, as :class:`Cycle` sums them."""
    k, N = b.effort.shape
    groups = (k // b.per, b.per, N)  # a point's row is its group's (Batch.points)
    S = M = None
    for joint, j, at in pins:  # in place: arrays of every design-position of the batch
        F = b.forces[(mech.frame, j)]
        # zcross(at, F) as one complex product, each design's row of F with its group's of the point
        moment = (np.conjugate(b.points[at])[:, None, :] * F.reshape(groups)).imag.reshape(k, N)
        if S is None:  # −F, not 0 − F: the two differ in the sign of a 0 only, and only |S| and |M| are read
            S, M = -F, -moment
        else:
            S -= F
            M -= moment
        if isinstance(joint, Prismatic):
            M -= b.couple[(mech.frame, j)]
    if S is None:
        S, M = np.zeros(b.effort.shape, complex), np.zeros(b.effort.shape)
    if mech.driver.crank:
        M -= b.effort
        return S, M
    # A slider driver's actuator pushes along the frame's guide: F1j = effort u, at the slider's point.
    joint = mech.joint_between(mech.frame, mech.driver.link)
    F = b.effort * np.exp(1j * joint.direction)
    at = np.repeat(b.points[joint.slider, joint.point], b.per, axis=0)
    return S - F, M + zcross(at, -F)


def _energy_swings(theta: np.ndarray, T: np.ndarray, h: np.ndarray | None = None) -> np.ndarray:
    """The energy swing E [J] of :func:`graphkin.cycle.flywheel.size_flywheel` for each row of ``T`` (designs, one
    closed turn ``theta``), driven at its mean, by the same steps row by row; rows with nan give nan.

    The pulses' areas, accumulated from the first crossing of T with its mean, are the energies at the crossings
    less that at the first (the last accumulated sum, the whole turn's, is U at the turn's end); so E is the larger
    of their largest and U's end less the smaller of their smallest and U's end (0 without a crossing). The first
    crossing is the first by index, or the last interval's where it lies past the turn's end (it is then one turn
    back, first of all). Rows with a crossing past the turn's end elsewhere (a turn whose last angle repeats the
    first), or angles that decrease, take :func:`_energy_swings_sorted`. ``h``: the turn's steps
    (:func:`graphkin.cycle.turn.steps`), if worked out already.
    """
    k, n = T.shape
    if h is None:
        h = steps(theta, closing_step(theta))
    half = 0.5 * h  # 0.5 (a + b) h is (a + b) (0.5 h) to the bit: a product by 0.5 is exact
    T_next = np.empty_like(T)  # np.roll(T, -1, axis=1)
    T_next[:, :-1] = T[:, 1:]
    T_next[:, -1] = T[:, 0]
    step = T + T_next
    step *= half
    T_avg = np.sum(step, axis=1) / TURN
    D = T - T_avg[:, None]
    D_next = np.subtract(T_next, T_avg[:, None], out=T_next)  # D rolled
    step = np.add(D, D_next, out=step)
    step *= half
    U = np.cumsum(step, axis=1)  # U[:, i] the energy at sample i + 1; at sample 0 it is 0
    U_end = U[:, -1].copy()
    up = D >= 0
    cross = D_next >= 0  # up rolled
    cross ^= up
    r, c = np.nonzero(cross)
    d, d_next, hc = D[r, c], D_next[r, c], h[c]
    frac = d / (d - d_next)
    at = theta[c] + frac * hc
    wrap = at >= theta[0] + TURN * (1 - 1e-12)
    # The energy at each crossing: U at the interval's start plus the trapezoid up to it.
    V = d * frac
    V *= 0.5 * hc
    inner = c > 0
    V[inner] += U[r[inner], c[inner] - 1]
    past = wrap & (c == n - 1)  # the last interval's crossing past the turn's end: one turn back
    V[past] -= U_end[r[past]]
    E = np.zeros(k)
    if len(r):
        starts = np.flatnonzero(np.concatenate(([True], r[1:] != r[:-1])))  # each design's first crossing
        ends = np.append(starts[1:], len(r)) - 1  # and its last (the last interval's, if it has one)
        V0 = V[np.where(past[ends], ends, starts)]
        top = np.maximum.reduceat(V, starts) - V0
        low = np.minimum.reduceat(V, starts) - V0
        mine = r[starts]
        end = U_end[mine]
        E[mine] = np.maximum(np.maximum(top, end), 0.0) - np.minimum(np.minimum(low, end), 0.0)
    odd = np.zeros(k, bool)
    odd[r[wrap & (c < n - 1)]] = True
    if not np.all(np.diff(theta) > 0):
        odd[:] = True
    if odd.any():
        E[odd] = _energy_swings_sorted(theta, T[odd])
    # A row's mean is finite where all of its T is (a sum of finite numbers that overflows aside: checked alone).
    finite = np.isfinite(T_avg)
    if not finite.all():
        finite = np.isfinite(T).all(axis=1)
    return np.where(finite, E, np.nan)


def _energy_swings_sorted(theta: np.ndarray, T: np.ndarray) -> np.ndarray:
    """:func:`_energy_swings` with the crossings sorted by angle and their pulses' areas summed, for any closed turn.

    With m crossings of T and its mean in a row, the pulses' areas are padded with zeros to the row's length:
    their running sum then stays at its last value, which changes neither its largest nor its smallest value.
    """
    k, n = T.shape
    h = steps(theta, closing_step(theta))
    T_avg = np.sum(0.5 * (T + np.roll(T, -1, axis=1)) * h, axis=1) / TURN
    D = T - T_avg[:, None]
    D_next = np.roll(D, -1, axis=1)
    U = np.concatenate([np.zeros((k, 1)), np.cumsum(0.5 * (D + D_next) * h, axis=1)], axis=1)
    cross = (D >= 0) != (D_next >= 0)
    frac = D / (D - D_next)
    at = theta + frac * h
    U_c = U[:, :-1] + 0.5 * D * frac * h
    wrap = at >= theta[0] + TURN * (1 - 1e-12)
    at = np.where(wrap, at - TURN, at)
    U_c = np.where(wrap, U_c - U[:, -1:], U_c)
    # Each row's crossings in order of angle (the others after them), then the areas between them.
    order = np.argsort(np.where(cross, at, np.inf), axis=1, kind="stable")
    U_c = np.take_along_axis(np.where(cross, U_c, np.nan), order, axis=1)
    m = cross.sum(axis=1)
    rows = np.arange(k)
    ends = np.append(U_c[:, 1:], np.full((k, 1), np.nan), axis=1)
    ends[rows[m > 0], m[m > 0] - 1] = U_c[m > 0, 0] + U[m > 0, -1]
    areas = np.where(np.arange(n) < m[:, None], ends - U_c, 0.0)
    accumulated = np.cumsum(areas, axis=1)
    E = np.maximum(accumulated.max(axis=1, initial=0.0), 0.0) - np.minimum(accumulated.min(axis=1, initial=0.0), 0.0)
    return np.where(np.isfinite(T).all(axis=1), E, np.nan)


class Shared:
    """What every batch of a study's designs of one shape and positions shares for its figures of merit: worked
    out for the first batch (:func:`batch_merits`) and kept for the others.

    Parameters
    ----------
    shape : Problem
        One of the designs (their links, joints, loads, analysis).
    q : ndarray
        Their positions [rad or m].
    Cs : float
        Coefficient of speed fluctuation for the flywheels.
    """

    def __init__(self, shape, q: np.ndarray, Cs: float):
        mech = shape.mechanism
        self.shape, self.q, self.Cs = shape, q, Cs
        self.four = _four_bar(mech)
        self.points = [at for _, _, at in _frame_pins(mech, [j.links for j in mech.joints])] + list(self.four or ())
        gap = closing_step(q)
        self.closed = gap is not None
        self.h = steps(q, gap) if self.closed else None
        self.w = weights(q, gap) if self.closed else None
        self.pins = self.names = None  # from the first batch's forces, in their order
        self.whys: dict = {}  # each speed's words for a flywheel its designs cannot have, and Cs ω²

    def why(self, w: float, valid: np.ndarray) -> tuple:
        """The words of a design's own cycle for a flywheel it cannot have, and Cs ω² (None with words): for a valid
        design of a crank they follow from its speed (and, at rest, whether its analysis is static, which a batch
        shares)."""
        if w not in self.whys:
            q_dot = np.full(len(self.q), w)
            why = Cycle.why_no_flywheel(SimpleNamespace(problem=self.shape, closed=self.closed, valid=valid,
                                                        q_dot=q_dot))
            self.whys[w] = why, None if why else self.Cs * float(np.mean(q_dot)) ** 2
        return self.whys[w]


def batch_merits(shape, members, q: np.ndarray, Cs: float, shared: Shared | None = None, per: int | None = None) -> dict:
    """The figures of merit of designs that share a batch (:func:`merit`'s, each design's to rounding), by index.

    ``shape`` is one of the designs' problems (their links, joints, loads, analysis); ``members`` is either a list
    of ``(index, values, numbers, q_dot, q_ddot)``, one per design, or those as five columns
    ``(indices, values, numbers, q_dot, q_ddot)``, the numbers a dict of columns
    (:func:`graphkin.analytical.designs.solve_designs`). ``shared``: what the study's batches share
    (:class:`Shared`), if it has been worked out; ``per``: how many designs in a row share their points and rates
    (:func:`graphkin.analytical.designs.solve_designs`), if known.
    """
    if isinstance(members, list):
        indices, values, numbers, q_dot, q_ddot = ([m[k] for m in members] for k in range(5))
    else:
        indices, values, numbers, q_dot, q_ddot = members
    shared = Shared(shape, q, Cs) if shared is None else shared
    mech = shape.mechanism
    four = shared.four
    b = solve_designs(mech, numbers, q, q_dot, q_ddot, static=shape.static, points=shared.points, per=per)
    if shared.pins is None:
        shared.pins = _frame_pins(mech, b.forces)  # in the order a Cycle sums them
        shared.names = [force_name(mech, i, j) for (i, j) in b.forces]
    pins, names = shared.pins, shared.names
    T = b.effort
    with np.errstate(all="ignore"):  # a design that fails carries nan; its figures are not read
        # Reductions over each design's positions.
        peak, square = np.max(np.abs(T), axis=1), _means(q, T * T, shared.w)
        joints = [_peak_size(F) for F in b.forces.values()]
        S, M = _shaking(b, mech, pins)
        shaking_force, shaking_moment = _peak_size(S), np.max(np.abs(M), axis=1)
        if four is not None:
            # μ folded to [0, π/2] grows with |u × v| / |u · v|: its least is μ at the position of the least ratio.
            # One row per group of designs that share their kinematics (Batch.points), then each design's.
            A, B, B0 = (b.points[at] for at in four)
            u, v = A - B, B0 - B
            uv = np.conjugate(u) * v  # u · v + i u × v, one complex product
            size, along = np.abs(uv.imag), uv.real
            at = np.argmin(size / np.abs(along), axis=1)
            rows = np.arange(len(at))
            mu = np.arctan2(size[rows, at], along[rows, at])
            mu_min = np.repeat(np.minimum(mu, np.pi - mu), b.per).tolist()
        # T not crossing its mean: 0/0, x/0, not read
        swing = _energy_swings(q, T, shared.h).tolist() if shared.closed else None
    valid = b.valid.all(axis=1)
    ok = valid.tolist()
    peak, square, shaking_force, shaking_moment = (x.tolist() for x in (peak, square, shaking_force, shaking_moment))
    joints = [x.tolist() for x in joints]
    w_all = q_dot.tolist() if isinstance(q_dot, np.ndarray) else list(q_dot)
    out = {}
    nan = math.nan
    for d, (index, vals, w) in enumerate(zip(indices, values, w_all)):
        if not ok[d]:
            bad = np.flatnonzero(~b.valid[d])
            out[index] = failed(vals, names, len(bad), q, int(bad[0]), mech.driver.crank, b.reason(d, int(bad[0])))
            continue
        why, per = shared.whys[w] if w in shared.whys else shared.why(w, b.valid[d])
        out[index] = Design(
            values=vals, torque_peak=peak[d], torque_rms=math.sqrt(square[d]),
            joint_peaks={name: x[d] for name, x in zip(names, joints)},
            I_s=nan if why else swing[d] / per,
            shaking_force_peak=shaking_force[d], shaking_moment_peak=shaking_moment[d],
            transmission_angle_min=mu_min[d] if four is not None else nan, no_flywheel=why)
    return out


def _peak_size(F: np.ndarray) -> np.ndarray:
    """The largest |F| of each row of complex ``F`` (designs, positions): np.abs of a complex array is
    np.hypot of its parts, a third of the time of np.hypot on the strided parts."""
    return np.max(np.abs(F), axis=1)
