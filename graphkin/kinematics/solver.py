"""The kinematic solver: every group's step, compiled once per mechanism, run over a batch of positions.

The equations are those of :mod:`graphkin.kinematics.groups`, group by group in
the order :func:`graphkin.kinematics.decompose` gives. The revolute crank and
the RRR dyad (the four-bar's groups) also have a compiled form here: the same
equations with fewer array operations and every constant (points as complex
numbers, bar lengths, the branch, messages) worked out once per mechanism by
:mod:`graphkin.kinematics.plan`; the other groups run the general code.
:func:`solve_kinematics` runs the steps :data:`CHUNK` positions at a time.

A constant may also be an array with one value per position: a batch of designs of one linkage laid end to end,
each design's points repeated over its positions (:func:`plan_with`, used by
:mod:`graphkin.analytical.designs`). The steps then do the same arithmetic, position by position; only a test of
a constant against 0, which saves work for one design, is never made of such an array.
"""
from __future__ import annotations

import copy
from collections.abc import Mapping

import numpy as np

from graphkin.errors import ModelError
from graphkin.kinematics.groups import DEAD_POINT, State, gear, locate_driver, positions, rates
from graphkin.kinematics.plan import Plan, plan_of
from graphkin.kinematics.state import Kinematics
from graphkin.kinematics.structure import DriverGroup, Dyad, GearGroup
from graphkin.model import Mechanism, Revolute
from graphkin.ranges import MAX_POSITIONS, RANGES, as_array

# -- the compiled steps ----------------------------------------------------------------------------------
# Each group becomes one function of the state, with everything that does not depend on the input
# positions (points as complex numbers, bar lengths, the branch, messages) worked out once, when the
# mechanism's plan is compiled. The revolute crank and the RRR dyad, the four-bar's groups, have their own
# lean form; the other groups run the general code above.


def is_zero(x) -> bool:
    """Whether a constant is the number 0 (an array of a batch of designs' values never is: see the module)."""
    return not isinstance(x, np.ndarray) and x == 0


def rows(x, y) -> np.ndarray:
    """Two constants as the rows of a (2, 1) array, or of a (2, n) array if either has one value per position."""
    if np.ndim(x) or np.ndim(y):
        return np.stack(np.broadcast_arrays(x, y))
    return np.array([[x], [y]])


def _crank_step(plan: Plan, g: DriverGroup):
    link, name = g.link, g.joint.point
    X, p = plan.points[plan.frame, name], plan.points[link, name]

    def step(st):
        q, w, al = st.q, st.q_dot, st.q_ddot
        e = np.exp(1j * q) if st.e_q is None else st.e_q
        st.e[link] = e
        st.theta[link], st.omega[link], st.alpha[link] = q, w, al
        st.pivots[link] = (X, p)
        if is_zero(p):  # the link's origin on the pivot: it does not move
            O = st.O[link] = np.full(st.n, X)
            st.v_O[link] = st.a_O[link] = st.zero
            st.finite.add(id(O))
            return
        r = e * -p
        st.O[link] = X + r
        st.v_O[link] = st.spin(w) * r
        st.a_O[link] = st.turn(w, al) * r

    return step


def _driver_step(plan: Plan, g: DriverGroup):
    if isinstance(g.joint, Revolute):
        return _crank_step(plan, g)

    def step(st):
        locate_driver(st, g, st.q, st.q_dot, st.q_ddot)

    return step


def _point_motion(st, link, p):
    """Position, velocity and acceleration of the point p (local, complex) of a located moving link.

    For a link turning about a fixed pivot (the crank) they come from the pivot and the input rates,
    and are finite for finite inputs: they are marked so, and the validity check skips them.
    """
    w = st.omega[link]
    pivot = st.pivots.get(link)
    if pivot is not None:
        X, p0 = pivot
        r = st.e[link] * (p - p0)
        motion = (r if is_zero(X) else X + r), st.spin(w) * r, st.turn(w, st.alpha[link]) * r
        st.finite.update(map(id, motion))
        return motion
    r = st.e[link] * p
    return st.O[link] + r, st.v_O[link] + 1j * w * r, st.a_O[link] + (1j * st.alpha[link] - w * w) * r


def _rrr_step(plan: Plan, d: Dyad, sigma: int, index: int):
    """The RRR dyad in closed form, positions to accelerations, with the loop kept for the force analysis.

    The loop, ``st.loops[index]``: ``(X1, X2, X3, R, size, a1, a3, E, W, AL)``, the joints' points, the
    arms r12 and r23 (rows of R), |det|, the accelerations of the outer pins (None on the frame), and
    e^{iθ}, ω and α of links j and k as rows. The Kinematics keep the first seven.
    """
    P, frame = plan.points, plan.frame
    a, b, j, k = d.a, d.b, d.j, d.k
    if a == frame and b == frame:  # both ends on the frame: a rigid triangle, rare; the general code
        return None
    pa, pb = P[a, d.J1.point], P[b, d.J3.point]
    pj1, pk3 = P[j, d.J1.point], P[k, d.J3.point]
    dj = P[j, d.J2.point] - pj1
    dk = pk3 - P[k, d.J2.point]
    Lj, Lk = abs(dj), abs(dk)
    Lj2 = Lj**2
    half_c = (Lj**2 - Lk**2) / 2
    # Rows 0 and 1 of the (2, n) arrays below are links j and k: their arms r12, r23, e^{iθ}, ω, α.
    to_e = rows(dj.conjugate() / abs(dj) ** 2, dk.conjugate() / abs(dk) ** 2)
    # Cramer's determinants: w_j = (rhs · r23) / det, w_k = (r12 · rhs) / (−det), det = r12 × r23 = −σ |det|.
    signs = np.array([[-1.0], [1.0]]) * sigma
    # |A| |B| of the general test (the arms' lengths, to rounding): below this |det| is a dead point.
    dead = DEAD_POINT * Lj * Lk
    reach = f"{d.label} cannot be assembled ({d.J1.point}{d.J3.point} out of reach)"
    toggle = f"{d.label} is at a dead point"
    together = (f"{d.label} has no definite position: its outer pins {d.J1.point} and {d.J3.point} coincide, "
                f"so it may turn about them")

    def step(st):
        if a == frame:
            X1, v1, a1 = pa, None, None
        else:
            X1, v1, a1 = _point_motion(st, a, pa)
        if b == frame:
            X3, v3, a3 = pb, None, None
        else:
            X3, v3, a3 = _point_motion(st, b, pb)
        # J2 is at X1 + D z with D = X3 − X1, z = t + iσ h/|D|, t = l/|D| = 1/2 + (Lj² − Lk²)/(2|D|²) and
        # (h/|D|)² = Lj²/|D|² − t²: one square root. Then r12 = D z, r23 = D − r12, and the determinant
        # r12 × r23 = r12 × D = −σ |D|² h/|D| comes without a cross product or cancellation.
        D = X3 - X1
        dd2 = D.real * D.real
        dd2 += D.imag * D.imag
        at_one = dd2 == 0  # the outer pins coincide: no direction to build the dyad on
        if at_one.any():
            # Equal arms fold onto each other and may turn about the pins; unequal arms cannot reach each other.
            equal = abs(Lj - Lk) <= 1e-12 * np.maximum(Lj, Lk)
            if np.ndim(equal):  # a batch of designs: each design's own reason
                st.fail(together, at_one & equal)
                st.fail(reach, at_one & ~equal)
            else:
                st.fail(together if equal else reach, at_one)
        t = half_c / dd2
        t += 0.5
        h2 = Lj2 / dd2
        h2 -= t * t
        short = h2 < 0
        if short.any():
            st.fail(reach, short)
        s = np.sqrt(h2)
        R = np.empty((2, st.n), complex)
        z = R[1]  # t + iσ s, made of its parts in the row r23 takes next (the same numbers as t + branch · s)
        z.real = t
        np.multiply(s, sigma, out=z.imag)
        r12 = np.multiply(D, z, out=R[0])
        np.subtract(D, r12, out=R[1])  # r23
        Rx = R[::-1]  # r23, r12: the other arm of each row, for the dot products
        X2 = X1 + r12
        st.e[j], st.e[k] = E = R * to_e
        # Each link's origin from its outer pin: no arithmetic when that pin is the link's origin.
        rj = None if is_zero(pj1) else E[0] * -pj1
        rk = None if is_zero(pk3) else E[1] * -pk3
        st.O[j] = _at(st, X1, rj)
        st.O[k] = _at(st, X3, rk)

        # Rates: v3 − v1 = ω_j i r12 + ω_k i r23, both rows at once (x · y = Re(x̄ y)).
        size = dd2 * s  # |det|; false below where there is no position (nan)
        near = size <= dead
        if near.any():
            st.fail(toggle, near)
        dets = size * signs
        rhs = v3 if v1 is None else (-v1 if v3 is None else v3 - v1)
        W = (np.conj(rhs) * Rx).real / dets
        # Accelerations: the same columns; the centripetal terms ω² r are known now.
        W2 = W * W
        P = W2 * R
        rhs = np.add(P[0], P[1], out=P[0])
        if a1 is not None:
            rhs -= a1
        if a3 is not None:
            rhs += a3
        AL = (np.conj(rhs) * Rx).real / dets
        (st.omega[j], st.omega[k]), (st.alpha[j], st.alpha[k]) = W, AL

        # Link j from J1, link k from J3.
        for link, r, v, acc, w, w2, al in ((j, rj, v1, a1, W[0], W2[0], AL[0]), (k, rk, v3, a3, W[1], W2[1], AL[1])):
            if r is None:  # the origin is the pin: it moves with the located link
                st.v_O[link] = st.zero if v is None else v
                st.a_O[link] = st.zero if acc is None else acc
                continue
            vO = 1j * w * r
            aO = (1j * al - w2) * r
            if v is not None:
                vO += v
                aO += acc
            st.v_O[link], st.a_O[link] = vO, aO
        st.loops[index] = (X1, X2, X3, R, size, a1, a3, E, W, AL)

    return step


def _at(st, X, r):
    """X + r as an array of n points (r None for 0); a point fixed in the frame is marked finite."""
    if r is not None:
        return X + r
    if np.ndim(X):
        return X
    X = np.full(st.n, X)
    st.finite.add(id(X))
    return X


def _dyad_step(d: Dyad, sigma: int):
    def step(st):
        positions(st, d, sigma)
        rates(st, d)

    return step


def _gear_step(g: GearGroup):
    def step(st):
        gear(st, g)

    return step


def _steps(plan: Plan, mech: Mechanism) -> list:
    """The plan's kinematic steps, one per group (compiled on first use)."""
    steps = plan.compiled.get("kinematics")
    if steps is None:
        steps = []
        for index, g in enumerate(plan.groups):
            if isinstance(g, DriverGroup):
                steps.append(_driver_step(plan, g))
            elif isinstance(g, GearGroup):
                steps.append(_gear_step(g))
            else:
                sigma = mech.assembly.get(g.key, 1)
                steps.append((g.type == "RRR" and _rrr_step(plan, g, sigma, index)) or _dyad_step(g, sigma))
        # The branches first, the steps last: another thread that finds the steps finds their branches too.
        plan.compiled["branches"] = _branches(plan, mech, steps)
        plan.compiled["kinematics"] = steps
    return steps


def plan_with(plan: Plan, points: Mapping) -> Plan:
    """A copy of ``plan`` with other values of its points and nothing compiled yet: a batch of designs' plan.

    Parameters
    ----------
    plan : Plan
        The plan of one design (its groups, links and frame are every design's).
    points : dict of (int, str) to complex or complex ndarray, shape (n,)
        Each point in its link's frame [m]: a number where every design has it there, else one value per
        position of the batch. The copy is not cached (:func:`graphkin.kinematics.plan.plan_of` never returns it).
    """
    batch = copy.copy(plan)
    batch.points, batch.compiled = points, {}
    return batch


def branches(mech: Mechanism) -> dict:
    """The branch (m, c) of each link placed by a dyad that a gear turns with (:func:`_branches`), by link."""
    plan = plan_of(mech)
    _steps(plan, mech)
    return plan.compiled["branches"]


SAMPLE = 721
"""Positions over a turn of the crank (half a degree apart) from which :func:`_branches` finds each arm's branch."""


def _branches(plan: Plan, mech: Mechanism, steps: list) -> dict:
    """For each link placed by a dyad that a gear turns with (its carrier, or its mate): its branch (m, c).

    m is the turns it makes per turn of the crank (0 when a slider drives), c the middle of the range of the rest
    of its angle, θ − m q, over a cycle sampled every half degree (over the slider's reach, four times the
    mechanism's size either way, for a slider). :meth:`State.turned` takes the link's angle within half a turn of
    m q + c, so that a planet carried by a rocker that swings across ±180° turns on without a jump.
    """
    dyads = {link for g in plan.groups if isinstance(g, Dyad) for link in g.links}
    links = sorted({x for g in plan.groups if isinstance(g, GearGroup) for x in (g.b, g.j) if x in dyads})
    if not links:
        return {}
    crank = isinstance(plan.groups[0], DriverGroup) and isinstance(plan.groups[0].joint, Revolute)
    if crank:
        q = np.linspace(0.0, 2 * np.pi, SAMPLE)
    else:
        size = max([abs(complex(*p1) - complex(*p0)) for k in mech.links for p0 in k.points.values()
                    for p1 in k.points.values()] + [1e-3])
        q = np.linspace(-4 * size, 4 * size, 8 * SAMPLE)
    with np.errstate(all="ignore"):
        # The sample runs on np.angle's branch (none found yet).
        st, valid = run(plan, mech, q, np.ones_like(q), np.zeros_like(q), compiled=(steps, {}))
    out = {}
    for link in links:
        theta = np.unwrap(st.angle(link)[valid])
        if not theta.size:
            continue
        m = round((theta[-1] - theta[0]) / (2 * np.pi)) if crank and valid.all() else 0
        rest = theta - m * q[valid]
        out[link] = (m, float(rest.min() + rest.max()) / 2)
    return out


# -- running them ------------------------------------------------------------------------------------------
CHUNK = 8192
"""Positions solved together. A larger batch is solved this many positions at a time, into its result's
arrays: the temporaries of one chunk (64 kB to 256 kB each) stay in the processor's cache and the allocator
hands the same memory back for the next chunk, so the time per position does not grow with n and the
memory a solve needs beyond its result is that of one chunk (a few MB)."""

_FIELDS = ("theta", "omega", "alpha", "e", "O", "v_O", "a_O")


def run(plan: Plan, mech: Mechanism, q, q_dot, q_ddot, rates=(None, None), *, angles: bool = True,
        compiled=None, e_q=None):
    """Every step over one batch of positions: the filled state and where it is valid.

    ``rates`` are the input speed and acceleration as numbers when they are the same at every position
    (:func:`constant`), else None. ``compiled``: the steps and branches to run, while they are being compiled.
    ``e_q``: e^{iq} of a crank's input angles, if the caller has it (else worked out here).
    """
    if compiled is None:
        steps = _steps(plan, mech)
        compiled = steps, plan.compiled["branches"]
    steps, branches = compiled
    st = State(mech, len(q), plan)
    st.q, st.q_dot, st.q_ddot = q, q_dot, q_ddot
    st.branches = branches
    st.e_q = e_q
    # Constant input rates (the usual case) make the crank's factors numbers instead of arrays.
    st.w0, st.al0 = rates
    for step in steps:
        step(st)
    if angles:
        for link in plan.moving:
            st.angle(link)
    return st, _valid(st, plan)


def _valid(st: State, plan: Plan) -> np.ndarray:
    """Where every link's motion is finite and no group failed.

    The driver's motion is finite for finite inputs, which are checked on the way in, and so is every
    array a step marked finite (a point of the crank, a point fixed in the frame). The sum of the others
    is non-finite wherever one of them is; where it is not finite (an invalid position, or, in theory, an
    overflow of the sum) each quantity is checked on its own.
    """
    known = st.finite
    driver = st.mech.driver.link
    real, cplx, seen = [], [], set()
    for link in plan.moving:
        if link == driver:
            continue
        for x, to in ((st.omega[link], real), (st.alpha[link], real), (st.O[link], cplx), (st.v_O[link], cplx),
                      (st.a_O[link], cplx)):
            if id(x) not in known and id(x) not in seen:
                seen.add(id(x))
                to.append(x)
    valid = None
    for xs in (real, cplx):
        if xs:
            total = xs[0] + xs[1] if len(xs) > 1 else xs[0]
            for x in xs[2:]:
                total += x
            ok = np.isfinite(total)
            valid = ok if valid is None else valid & ok
    if valid is None:
        valid = np.ones(st.n, bool)
    elif not valid.all():
        valid = np.ones(st.n, bool)
        for x in real + cplx:
            valid &= np.isfinite(x)
    for where in st.failures.values():
        valid &= ~where
    return valid


def _kinematics(plan: Plan, mech: Mechanism, q, q_dot, q_ddot, rates=(None, None)) -> Kinematics:
    """Kinematics over all positions, CHUNK at a time."""
    n = len(q)
    with np.errstate(all="ignore"):  # unassemblable positions and dead points propagate as nan, by design
        if n <= CHUNK:
            st, valid = run(plan, mech, q, q_dot, q_ddot, rates)
            return Kinematics(mech, q, q_dot, q_ddot, st.theta, st.omega, st.alpha, st.e, st.O, st.v_O, st.a_O,
                              valid, st.failures, plan.groups, loops=_kept(st.loops))
        out = {name: {} for name in _FIELDS}
        valid, failures = np.empty(n, bool), {}
        # The inputs, and the state's constant arrays at full length, are shared by the result, not copied.
        whole = {"zero": np.zeros(n, complex), "still": np.zeros(n), "ones": np.ones(n, complex)}
        shared = {id(x) for x in (q, q_dot, q_ddot, *whole.values())}
        loops = {}
        for s in range(0, n, CHUNK):
            t = min(n, s + CHUNK)
            st, valid[s:t] = run(plan, mech, q[s:t], q_dot[s:t], q_ddot[s:t], rates)
            same = {id(st.q): q, id(st.q_dot): q_dot, id(st.q_ddot): q_ddot,
                    **{id(getattr(st, name)): x for name, x in whole.items()}}
            for name in _FIELDS:
                to = out[name]
                for link, x in getattr(st, name).items():
                    full = same.get(id(x))
                    if full is not None and to.get(link, full) is full:
                        to[link] = full
                        continue
                    if link not in to:
                        to[link] = np.empty(n, x.dtype)
                    elif id(to[link]) in shared:  # shared by the chunks before, not by this one: its own copy
                        to[link] = np.array(to[link], dtype=np.result_type(to[link], x))
                    to[link][s:t] = x
            # A loop's arrays that are also a link's field (an outer pin at the link's origin) stay shared.
            fields = {id(x): (name, link) for name in ("O", "a_O") for link, x in getattr(st, name).items()}
            for index, loop in _kept(st.loops).items():
                merged = loops.setdefault(index, [None] * len(loop))
                for m, x in enumerate(loop):
                    if not isinstance(x, np.ndarray):
                        merged[m] = x  # a point of the frame, or None
                    elif id(x) in fields:
                        name, link = fields[id(x)]
                        merged[m] = out[name][link]
                    else:
                        if merged[m] is None:
                            merged[m] = np.empty(x.shape[:-1] + (n,), x.dtype)
                        merged[m][..., s:t] = x
            for why, where in st.failures.items():
                failures.setdefault(why, np.zeros(n, bool))[s:t] = where
    return Kinematics(mech, q, q_dot, q_ddot, *(out[name] for name in _FIELDS), valid, failures, plan.groups,
                      loops={index: tuple(loop) for index, loop in loops.items()})


def _kept(loops: dict) -> dict:
    """What a Kinematics keeps of the kinematic pass's loops (the rows of e, ω, α it has already)."""
    return {index: loop[:7] for index, loop in loops.items()}


class _Deferred:
    """Kinematics to be worked out again when first asked for (see :func:`deferred_kinematics`)."""

    __slots__ = ("plan", "args", "kin")

    def __init__(self, plan, *args):
        self.plan, self.args, self.kin = plan, args, None

    def get(self, name: str):
        if self.kin is None:
            self.kin = _kinematics(self.plan, *self.args)
        return getattr(self.kin, name)


class _DeferredLinks(Mapping):
    """One per-link field (θ, ω, ...) of deferred kinematics: a read-only mapping, filled on first use."""

    __slots__ = ("_source", "_name")

    def __init__(self, source: _Deferred, name: str):
        self._source, self._name = source, name

    def __getitem__(self, link):
        return self._source.get(self._name)[link]

    def __iter__(self):
        return iter(self._source.get(self._name))

    def __len__(self):
        return len(self._source.get(self._name))

    def __repr__(self):
        return f"<{self._name} of every link, worked out when first read>"


def deferred_kinematics(plan: Plan, mech: Mechanism, q, q_dot, q_ddot, rates, valid, failures, *,
                        static=False) -> Kinematics:
    """Kinematics whose per-link arrays are recomputed (identically) the first time one is read.

    The force analysis needs the motion of every link, but its result need not keep it (for a four-bar,
    about 300 bytes a position). ``valid`` and ``failures`` come from the pass already made.
    """
    source = _Deferred(plan, mech, q, q_dot, q_ddot, rates)
    fields = (_DeferredLinks(source, name) for name in _FIELDS)
    return Kinematics(mech, q, q_dot, q_ddot, *fields, valid, failures, plan.groups, static=static,
                      loops=_DeferredLinks(source, "loops"))


# -- inputs ------------------------------------------------------------------------------------------------
def _checked(value, what: str, kind: str, n: int | None = None):
    """:func:`graphkin.ranges.as_array`, with a short way for a float array or a plain number.

    Anything else, or anything out of range, goes through ``as_array``, which accepts the same values and
    gives the same messages. Returns the array and, for a plain number, that number (else None).
    """
    r = RANGES[kind]
    if type(value) is np.ndarray and value.dtype == np.float64 and value.ndim == 1 and 0 < value.size <= MAX_POSITIONS \
            and (n is None or value.size == n):
        if value.size == 1:
            # One position (an exercise's draw, a position of a report): the range's own test of the one number.
            if r.complaint(float(value[0])) is None:
                return value.copy(), None
        elif r.zero and r.signed and not r.low and -r.high <= np.minimum.reduce(value) \
                and np.maximum.reduce(value) <= r.high:  # false for nan
            return value.copy(), None
    elif type(value) in (float, int, np.float64) and abs(value) <= r.high:
        x = float(value)
        if r.complaint(x) is None:
            return np.full(1 if n is None else n, x), x
    return as_array(value, what, kind, n=n), None


def constant(x: np.ndarray, number):
    """``number``, or the value of every element of ``x`` if they are all the same, else None."""
    if number is None and np.minimum.reduce(x) == np.maximum.reduce(x):
        return float(x[0])
    return number


def prepare(mech, q, q_dot=0.0, q_ddot=0.0, *, caller: str = "solve_kinematics"):
    """The mechanism's plan and the checked inputs: ``(plan, q, q_dot, q_ddot, rates)``.

    ``q``, ``q_dot``, ``q_ddot`` have shape (n,); ``rates`` is ``(ω, α)`` (or (v, a)), each a number when
    it is the same at every position, else None.
    """
    if not isinstance(mech, Mechanism):
        raise ModelError(f"{caller} takes a Mechanism first, got {type(mech).__name__}")
    crank = mech.driver.crank
    q, _ = _checked(q, "q (the input positions)", "angle" if crank else "coordinate")
    n = len(q)
    q_dot, w0 = _checked(q_dot, "q_dot", "angular_velocity" if crank else "velocity", n)
    q_ddot, al0 = _checked(q_ddot, "q_ddot", "angular_acceleration" if crank else "acceleration", n)
    return plan_of(mech), q, q_dot, q_ddot, (constant(q_dot, w0), constant(q_ddot, al0))


def solve_kinematics(mech: Mechanism, q, q_dot=0.0, q_ddot=0.0) -> Kinematics:
    """Kinematics of every link for a batch of input positions, in one call.

    Parameters
    ----------
    mech : Mechanism
        The linkage.
    q : array_like, shape (n,) or scalar
        Input coordinate: crank angle θ [rad] or slider position s [m].
    q_dot, q_ddot : float or array_like, shape (n,)
        Input rates: ω [rad/s] and α [rad/s²], or v [m/s] and a [m/s²]; one
        value for every position, or one per position.

    Returns
    -------
    Kinematics
        Positions that cannot be assembled, or are dead points, hold nan and
        are False in ``valid``; ``reason(i)`` says why.

    Raises
    ------
    ModelError
        If the inputs are not numbers, not 1-D, of different lengths, not
        finite or outside graphkin's ranges (:mod:`graphkin.ranges`).
    """
    plan, q, q_dot, q_ddot, rates = prepare(mech, q, q_dot, q_ddot)
    return _kinematics(plan, mech, q, q_dot, q_ddot, rates)
