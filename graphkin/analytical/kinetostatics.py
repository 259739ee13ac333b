"""Analytical kinetostatics, solved group by group in closed form.

The three equilibrium equations of each moving link (d'Alembert: inertia
force −m a_G and torque −I_G α included as loads) form [A]{x} = {b}; see
:mod:`graphkin.analytical.matrix` for that matrix, which the lessons display and the
tests use as a cross-check. Solving it position by position is slow, so this
module uses its structure instead: the groups of the kinematic decomposition
are solved in reverse order (last dyad first), each in closed form with at
most one 2×2 system, all positions at once. Reactions found in one group are
loads on the links of the groups before it.

Coulomb friction at a prismatic pair makes the friction force μ|N| depend on
the sign of the normal force N. Each group is solved for every sign
assumption of its friction pairs, and at each position the assumption that
the solution confirms is kept (a position where none does is self-locking
and reported invalid).

The revolute crank and the RRR dyad have compiled steps (built once per
mechanism, :mod:`graphkin.kinematics.plan`) that reuse the loop the kinematic
pass solved; the other groups run the general code. A large batch is solved
:data:`~graphkin.kinematics.solver.CHUNK` positions at a time.
"""

from __future__ import annotations

import itertools
from dataclasses import replace

import numpy as np

from graphkin.analytical.loads import _external_fast, _inertia_fast, _known, cross, load_specs, springs_without_a_line
from graphkin.analytical.meshes import contact, power_flow
from graphkin.analytical.result import ForceAnalysis
from graphkin.errors import GraphkinError
from graphkin.geometry import zdot as dot
from graphkin.kinematics import DriverGroup, Dyad, GearGroup, Kinematics
from graphkin.kinematics.groups import solve_columns
from graphkin.kinematics.plan import Plan, plan_of
from graphkin.kinematics.solver import CHUNK, deferred_kinematics, prepare, rows, run
from graphkin.model import Mechanism, Prismatic, Revolute


class _Reactions:
    """A joint's reaction on one link: force F at point X and couple C (prismatic)."""

    __slots__ = ("joint", "on", "F", "X", "C", "N")

    def __init__(self, joint, on, F, X, C=None, N=None):
        self.joint, self.on, self.F, self.X, self.C, self.N = joint, on, F, X, C, N


def _w(kin: Kinematics, joint: Prismatic, on: int, sigma_N):
    """Direction w of the reaction on ``on`` per unit normal force: F = N w.

    w = n − μ σ_N sgn(ṡ) u, with u the guide direction, n = k × u, sgn(ṡ)
    the sense of the velocity of ``on`` relative to the other link
    (:meth:`Kinematics.slide_sense`, 0 where it is still) and σ_N the sign of N.
    """
    u = kin.z_guide(joint)
    w = 1j * u
    if joint.mu:
        w = w - joint.mu * sigma_N * kin.slide_sense(joint, on) * u
    return w


def _point(kin: Kinematics, joint, link: int):
    if isinstance(joint, Prismatic):
        return kin.z(joint.slider, joint.point)
    return kin.z(link, joint.point)


def _dyad(kin: Kinematics, d: Dyad, L, M, sig) -> list[_Reactions]:
    """Reactions at J1 (on j), J2 (of j on k) and J3 (on k) of one dyad.

    Each link's moments are taken at its own points: X2 is the middle pin on
    k and X2j the same pin on j. They coincide unless the problem gives a
    link's angle (:meth:`Kinematics.with_given`), as a drawing read to the
    degree does.
    """
    X1, X2, X3 = _point(kin, d.J1, d.j), _point(kin, d.J2, d.k), _point(kin, d.J3, d.k)
    X2j = _point(kin, d.J2, d.j)
    Lj, Mj, Lk, Mk = L[d.j], M[d.j], L[d.k], M[d.k]
    S = -(Lj + Lk)
    t = d.type
    C1 = C2 = C3 = N1 = N2 = N3 = None
    if t == "RRR":
        # Moments of j and of k about the middle pin, and the dyad's force sum.
        r1, r3 = X1 - X2j, X3 - X2
        b1 = -(Mj - cross(X2j, Lj))
        b3 = cross(r3, S) + Mk - cross(X2, Lk)
        # cross(r1, F1) = b1 and cross(r3, F1) = b3, by Cramer's rule.
        with np.errstate(divide="ignore", invalid="ignore"):
            F1 = (b1 * r3 - b3 * r1) / cross(r1, r3)
        F3 = S - F1
        F2 = F1 + Lj
    elif t == "RRP":
        w3 = _w(kin, d.J3, d.k, sig[2])
        r1 = X1 - X2j
        with np.errstate(divide="ignore", invalid="ignore"):
            N3 = (cross(r1, S) + Mj - cross(X2j, Lj)) / cross(r1, w3)
        F3 = N3 * w3
        F1 = S - F3
        F2 = F1 + Lj
        C3 = -(Mk + cross(X2, F2) + cross(X3, F3))
    elif t == "RPR":
        w2 = _w(kin, d.J2, d.k, sig[1])
        with np.errstate(divide="ignore", invalid="ignore"):
            N2 = (cross(X1, Lj) + cross(X3, Lk) - Mj - Mk) / cross(X1 - X3, w2)
        F2 = N2 * w2
        F1 = F2 - Lj
        F3 = -F2 - Lk
        C2 = -(cross(X2, F2) + cross(X3, F3) + Mk)
    elif t == "RPP":
        w2, w3 = _w(kin, d.J2, d.k, sig[1]), _w(kin, d.J3, d.k, sig[2])
        N2, N3 = solve_columns(w2, w3, -Lk)
        F2, F3 = N2 * w2, N3 * w3
        F1 = F2 - Lj
        C2 = cross(X1, F1) - cross(X2, F2) + Mj
        C3 = -(cross(X2, F2) + C2 + cross(X3, F3) + Mk)
    else:  # PRP
        w1, w3 = _w(kin, d.J1, d.j, sig[0]), _w(kin, d.J3, d.k, sig[2])
        N1, N3 = solve_columns(w1, w3, S)
        F1, F3 = N1 * w1, N3 * w3
        F2 = F1 + Lj
        C1 = cross(X2j, F2) - cross(X1, F1) - Mj
        C3 = -(cross(X2, F2) + cross(X3, F3) + Mk)
    return [
        _Reactions(d.J1, d.j, F1, X1, C1, N1),
        _Reactions(d.J2, d.k, F2, X2, C2, N2),
        _Reactions(d.J3, d.k, F3, X3, C3, N3),
    ]


def _driver(kin: Kinematics, g: DriverGroup, L, M):
    link, J = g.link, g.joint
    if isinstance(J, Revolute):
        X = kin.z(link, J.point)
        F = -L[link]
        T = -(M[link] + cross(X, F))
        return [_Reactions(J, link, F, X)], T
    u = kin.z_guide(J)
    X = kin.z(link, J.point)
    N = -dot(L[link], 1j * u)
    # N is known before friction enters, so its sign needs no assumption.
    w = _w(kin, J, link, np.sign(N))
    P = -dot(L[link], u) - N * dot(w, u)
    G = N * w
    C = -(M[link] + cross(X, G + P * u))
    return [_Reactions(J, link, G, X, C, N)], P


def _gear(kin: Kinematics, g: GearGroup, L, M):
    mesh = g.mesh
    Ck = kin.z(g.b, g.ck)
    Cj = kin.z(g.b, g.cj)
    # The tooth force's moment on k balances k's other loads about its centre; its tangential part is that over
    # the arm, and its radial part, |W_t| tan φ, separates the teeth.
    T = -(M[g.k] - cross(Ck, L[g.k]))
    X, t, r, rho = contact(mesh, g.k, Ck, Cj, power_flow(kin, g, T))
    W_t = T / rho
    W = W_t * t + np.abs(W_t) * np.tan(mesh.pressure_angle) * r
    F = -L[g.k] - W
    return [_Reactions(mesh, g.k, W, X), _Reactions(g.pivot, g.k, F, Ck)]


def _friction_joints(d: Dyad):
    return [i for i, J in enumerate(d.joints) if isinstance(J, Prismatic) and J.mu > 0]


def _solve_dyad_with_friction(kin, d, L, M, failures):
    fj = _friction_joints(d)
    if not fj:
        return _dyad(kin, d, L, M, (1.0, 1.0, 1.0))
    n = kin.n
    chosen = None
    found = np.zeros(n, bool)
    for signs in itertools.product((1.0, -1.0), repeat=len(fj)):
        sig = [1.0, 1.0, 1.0]
        for i, s in zip(fj, signs):
            sig[i] = s
        trial = _dyad(kin, d, L, M, sig)
        ok = np.ones(n, bool)
        for i in fj:
            ok &= trial[i].N * sig[i] >= 0
        take = ok & ~found
        if chosen is None:
            chosen = trial
        else:
            for c, t in zip(chosen, trial):
                c.F = np.where(take, t.F, c.F)
                if c.C is not None:
                    c.C = np.where(take, t.C, c.C)
                    c.N = np.where(take, t.N, c.N)
        if chosen is trial:
            chosen = [_Reactions(r.joint, r.on, r.F.copy(), r.X, None if r.C is None else r.C.copy(),
                                 None if r.N is None else r.N.copy()) for r in trial]
        found |= ok
    stuck = ~found & kin.valid
    if stuck.any():
        failures[f"{d.label}: friction locks it (no consistent direction of the normal force)"] = stuck
        for r in chosen:
            r.F = np.where(stuck, np.nan, r.F)
    return chosen


# -- the compiled force analysis ---------------------------------------------------------------------------
# Without values given in place of the derived ones (Kinematics.with_given), the revolute crank and the RRR
# dyad -- the four-bar's groups -- are solved by compiled steps that take their links' inertia loads into
# account themselves, as moments about the dyad's middle pin or the crank's pivot, from the arms and rates of
# the kinematic pass (or from the Kinematics, worked out once). Loads from elsewhere (external loads, weight,
# the reactions of groups solved before) arrive in L (force) and M (moment about the origin); a link with none
# has no entry, and costs nothing. Each link's m, I_G and G come from the plan's load specs (load_specs), which a
# batch of designs (graphkin.analytical.designs) fills with one value per position where its designs differ.


def _add(d, key, x):
    """d[key] += x, an absent entry being 0."""
    d[key] = x if key not in d else d[key] + x


def _sub(d, key, x):
    """d[key] −= x, an absent entry being 0."""
    d[key] = -x if key not in d else d[key] - x


def _rrr(plan: Plan, mech: Mechanism, d: Dyad):
    """The RRR dyad's reactions F1 (a on j), F2 (j on k), F3 (b on k), in closed form, inertia included."""
    P, frame = plan.points, plan.frame
    a, b, j, k = d.a, d.b, d.j, d.k
    pa, pb, pk2 = P[a, d.J1.point], P[b, d.J3.point], P[k, d.J2.point]
    specs = load_specs(plan, mech)
    (mj, Ij, Gj), (mk, Ik, Gk) = specs[j][:3], specs[k][:3]
    # Rows j and k: G from the outer pin (J1 on j, J3 on k) in the link's frame, −m, I_G. Groups of designs
    # (graphkin.analytical.designs): the positions have three axes, a row of numbers is (2, 1, 1, 1), and each link
    # takes its own −m and I_G, so that the arrays of a link no design changes keep the kinematics' shape (g, 1, N).
    axes = plan.compiled.get("axes", 1)
    G_out, minus_m, I_G = (x if x.ndim > axes else x.reshape((2,) + (1,) * axes) for x in (
        rows(Gj - P[j, d.J1.point], Gk - P[k, d.J3.point]),
        rows(-mj, -mk).astype(complex),  # −m a_G as one complex product (NumPy's, with the mass made complex)
        rows(Ij, Ik)))
    minus_j, minus_k, I_j, I_k = (np.asarray(x, t).reshape(np.shape(x) or (1,) * axes)
                                  for x, t in ((-mj, complex), (-mk, complex), (Ij, float), (Ik, float)))
    heavy = any(map(np.any, (mj, mk, Ij, Ik)))
    sigma = mech.assembly.get(d.key, 1)  # det = r12 × r23 = −σ |det|; the force equations' is −det
    sign1 = 1.0 if j > a else -1.0  # stored as the force of the lower-numbered link on the higher
    sign2 = 1.0 if k > j else -1.0
    sign3 = 1.0 if k > b else -1.0
    keys = ((min(a, j), max(a, j)), (min(j, k), max(j, k)), (min(b, k), max(b, k)))

    def from_kinematics(kin):
        """The loop (see :func:`graphkin.kinematics.solver._rrr_step`) from kinematics that do not have it."""
        X1 = pa if a == frame else kin.O[a] + kin.e[a] * pa
        X3 = pb if b == frame else kin.O[b] + kin.e[b] * pb
        X2 = kin.O[k] + kin.e[k] * pk2
        R = np.stack([X2 - X1, X3 - X2])
        a1 = None if a == frame else _acceleration(kin, a, pa)
        a3 = None if b == frame else _acceleration(kin, b, pb)
        return X1, X2, X3, R, cross(R[0], R[1]) * -sigma, a1, a3  # "size" σ·(−det), the kinematic pass's |det|

    def forces(kin, L, M, out, loop):
        X1, X2, X3, R, size, a1, a3, *rows = from_kinematics(kin) if loop is None else loop
        E, W, AL = rows or (np.stack([kin.e[j], kin.e[k]]), np.stack([kin.omega[j], kin.omega[k]]),
                            np.stack([kin.alpha[j], kin.alpha[k]]))
        r12, r23 = R
        if heavy and not kin.static:
            # a_G = a(outer pin) + (iα − ω²) ρ with ρ from the pin to G; F = −m a_G.
            rho = E * G_out
            A = np.empty(rho.shape, complex)  # iα − ω², made of its parts (no product with 1j, no real − complex)
            np.multiply(W, W, out=A.real)
            np.negative(A.real, out=A.real)
            A.imag = AL
            A *= rho
            if a1 is not None:
                A[0] += a1
            if a3 is not None:
                A[1] += a3
            # Moments about the middle pin: G − X2 = ρ − r12 on j, ρ + r23 on k.
            rho[0] -= r12
            rho[1] += r23
            if axes > 1:  # not in place: I_G may vary where m does not
                Fj, Fk = A[0] * minus_j, A[1] * minus_k
                Mj, Mk = cross(rho[0], Fj) - AL[0] * I_j, cross(rho[1], Fk) - AL[1] * I_k
            else:
                F = A * minus_m
                Mg = cross(rho, F)
                Mg -= AL * I_G
                Fj, Fk, Mj, Mk = F[0], F[1], Mg[0], Mg[1]
        else:
            Fj = Fk = Mj = Mk = 0.0
        # Loads from elsewhere: moments about the origin shifted to the middle pin.
        if j in L:
            Fj = Fj + L[j]
            Mj = Mj - cross(X2, L[j])
        if j in M:
            Mj = Mj + M[j]
        if k in L:
            Fk = Fk + L[k]
            Mk = Mk - cross(X2, L[k])
        if k in M:
            Mk = Mk + M[k]
        # Moments of j and of k about the middle pin and the dyad's force sum, by Cramer's rule:
        # cross(r12, F1) = Mj and cross(r23, F1) = Mk + cross(r23, S), S = −(Fj + Fk) = F1 + F3.
        T = Fj + Fk
        ndet = size if sigma > 0 else -size
        b3 = Mk - cross(r23, T)
        F1 = r12 * (b3 / ndet)  # real quotients: a complex one by a real divisor costs ten times as much
        F1 = np.subtract(F1, r23 * (Mj / ndet), out=None if axes > 1 else F1)  # in groups Mj may be the wider
        F3 = -(T + F1)
        F2 = F1 + Fj
        for key, sign, F in zip(keys, (sign1, sign2, sign3), (F1, F2, F3)):
            out[key] = F if sign > 0 else -F
        if a != frame:
            _sub(L, a, F1)
            _add(M, a, cross(F1, X1))
        if b != frame:
            _sub(L, b, F3)
            _add(M, b, cross(F3, X3))

    return forces


def _acceleration(kin, link, p):
    """Acceleration of the point p (local, complex) of a moving link."""
    w = kin.omega[link]
    return kin.a_O[link] + (1j * kin.alpha[link] - w * w) * (kin.e[link] * p)


def _crank(plan: Plan, mech: Mechanism, g: DriverGroup):
    """The crank's pivot force (frame on crank) and the driving torque, its inertia included."""
    link, name = g.link, g.joint.point
    X = plan.points[plan.frame, name]
    p0 = plan.points[link, name]
    m, I_G, G = load_specs(plan, mech)[link][:3]
    G = G - p0  # G from the pivot, in the crank's frame
    key = (min(plan.frame, link), max(plan.frame, link))
    # Tests of the constants made once (np.any: one value per design-position in a batch of designs).
    swings, spins, off = bool(np.any(m) and np.any(G)), bool(np.any(I_G)), bool(np.any(X))

    def forces(kin, L, M, out, loop):
        F, T = L.get(link, 0.0), M.get(link, 0.0)  # loads from elsewhere; T about the origin
        if not kin.static:
            if swings:
                w, al = kin.omega[link], kin.alpha[link]
                rho = kin.e[link] * G
                Fi = (1j * al - w * w) * rho * -m
                F = F + Fi
                T = T + cross(X + rho, Fi)
            if spins:
                al0 = getattr(kin, "al0", None)  # the solver's state knows a constant input acceleration
                T = T - (kin.alpha[link] if al0 is None else al0) * I_G
        # The pivot's force balances the rest; the driving torque balances the moments about the origin.
        F = -F
        out[key] = F if link > plan.frame else -F
        return -(T + cross(X, F)) if off else -T

    return forces


def _program(plan: Plan, mech: Mechanism) -> list:
    """Per group, in reverse order: a compiled force step, or None for the general code."""
    steps = plan.compiled.get("forces")
    if steps is None:
        steps = []
        for g in reversed(plan.groups):
            if isinstance(g, DriverGroup) and isinstance(g.joint, Revolute):
                steps.append(_crank(plan, mech, g))
            elif isinstance(g, Dyad) and g.type == "RRR":
                steps.append(_rrr(plan, mech, g))
            else:
                steps.append(None)
        plan.compiled["forces"] = steps
        # A load that follows a table or the motion reads the Kinematics (a point's velocity, a link's ω).
        plan.compiled["general"] = None in steps or any(load.varies for load in mech.loads)
    return steps


def _apply(kin, mech, reactions, L, M, forces, normal, couple):
    """Store a group's reactions and pass them on, as loads, to the links located before it."""
    for r in reactions:
        i, j = r.joint.links
        other = i if r.on == j else j
        key = (min(i, j), max(i, j))
        sign = 1.0 if r.on == key[1] else -1.0
        forces[key] = sign * r.F
        if r.N is not None:
            normal[key] = sign * r.N
            couple[key] = sign * r.C
        if other != mech.frame:
            # On the other link the reaction acts at that link's own pin (the same point, unless an angle is given).
            X = kin.z(other, r.joint.point) if isinstance(r.joint, Revolute) else r.X
            _sub(L, other, r.F)
            _sub(M, other, cross(X, r.F) + (r.C if r.C is not None else 0.0))


def _pass(kin, plan: Plan, kin_valid, loops):
    """Every joint force (complex), normal and couple, the effort, where it is valid and why not, for one batch.

    ``kin`` is a Kinematics, or (inside :func:`solve`, when every group has a compiled step) the kinematic
    pass's own state, which has the same per-link fields; ``loops`` is what that pass kept for the RRR dyads
    (:attr:`Kinematics.loops`), by group index.
    """
    mech = kin.mechanism
    n = kin.n
    L, M = {}, {}
    forces, normal, couple = {}, {}, {}
    failures: dict[str, np.ndarray] = {}
    effort = None
    steps = _program(plan, mech)
    if kin.given:  # values read off a drawing: the general code, point by point
        loops = {}
        for link in plan.moving:
            L[link], M[link] = _known(kin, link)
        steps = [None] * len(steps)
    else:
        specs = load_specs(plan, mech)
        for link in plan.moving:
            _external_fast(kin, link, specs[link], L, M)
    last = len(plan.groups) - 1
    for index, (g, step) in enumerate(zip(reversed(plan.groups), steps)):
        if step is not None:
            done = step(kin, L, M, forces, loops.get(last - index))
            if isinstance(g, DriverGroup):
                effort = done
            continue
        if not kin.given:
            for link in g.links:
                _inertia_fast(kin, link, specs[link], L, M)
                if link not in L:
                    L[link] = np.zeros(n, complex)
                if link not in M:
                    M[link] = np.zeros(n)
        if isinstance(g, DriverGroup):
            reactions, effort = _driver(kin, g, L, M)
        elif isinstance(g, GearGroup):
            reactions = _gear(kin, g, L, M)
        else:
            reactions = _solve_dyad_with_friction(kin, g, L, M, failures)
        _apply(kin, mech, reactions, L, M, forces, normal, couple)

    effort = _full(effort, n, float)
    for key, F in forces.items():
        forces[key] = _full(F, n, complex)
    # One sum is non-finite wherever a force or the effort is (where it is not finite, or in theory
    # overflows, each is checked on its own).
    total = effort
    for F in forces.values():
        if total is effort:
            total = effort + F
        else:
            total += F
    ok = np.isfinite(total)
    if failures or not ok.all():
        valid = np.isfinite(effort)
        for F in forces.values():
            valid &= np.isfinite(F)
        valid &= kin_valid
        for why, where in springs_without_a_line(kin, mech, kin_valid).items():
            failures[why] = where
        for where in failures.values():
            valid &= ~where
        dead = kin_valid & ~valid & ~np.logical_or.reduce([w for w in failures.values()] or [np.zeros(n, bool)])
        if dead.any():
            failures["the force equations are singular (dead point)"] = dead
    else:
        valid = kin_valid.copy()
    return forces, normal, couple, effort, valid, failures


def _full(x, n, dtype):
    """x as an array of shape (n,) (or of shape ``n``, a tuple: groups of designs, graphkin.analytical.designs): a
    constant (a link with no load at all), or an array of fewer axes, repeated."""
    if type(x) is np.ndarray and x.shape == (n if type(n) is tuple else (n,)):
        return x
    x = np.asarray(x)
    return np.full(n, x, dtype=np.result_type(x, dtype))


class _Merged:
    """The results of a force analysis done CHUNK positions at a time, put together."""

    def __init__(self, n):
        self.n = n
        self.parts = None

    def add(self, s, t, part):
        forces, normal, couple, effort, valid, failures = part
        n = self.n
        if self.parts is None:
            def alloc(d, dtype):
                return {key: np.empty(n, dtype) for key in d}
            self.parts = (alloc(forces, complex), alloc(normal, float), alloc(couple, float), np.empty(n),
                          np.empty(n, bool), {})
        out = self.parts
        for dst, src in zip(out[:3], (forces, normal, couple)):
            for key, x in src.items():
                dst[key][s:t] = x
        out[3][s:t] = effort
        out[4][s:t] = valid
        for why, where in failures.items():
            out[5].setdefault(why, np.zeros(n, bool))[s:t] = where


_XY = np.dtype((np.float64, (2,)))
"""A complex number seen as its (x, y): a complex array of shape (n,) is the same memory as an (n, 2) array."""


def _result(kin: Kinematics, parts) -> ForceAnalysis:
    forces, normal, couple, effort, valid, failures = parts
    return ForceAnalysis(kin, {key: F.view(_XY) for key, F in forces.items()}, normal, couple, effort, valid, failures)


def _slice(kin: Kinematics, s: int, t: int) -> Kinematics:
    def cut(d):
        return {key: x[s:t] for key, x in d.items()}

    loops = {index: tuple(x[..., s:t] if isinstance(x, np.ndarray) else x for x in loop)
             for index, loop in kin.loops.items()}
    return Kinematics(kin.mechanism, kin.q[s:t], kin.q_dot[s:t], kin.q_ddot[s:t], cut(kin.theta), cut(kin.omega),
                      cut(kin.alpha), cut(kin.e), cut(kin.O), cut(kin.v_O), cut(kin.a_O), kin.valid[s:t], {},
                      kin.groups, cut(kin.given), kin.static, loops)


def solve_forces(kin: Kinematics) -> ForceAnalysis:
    """Joint forces and driving effort for known kinematics (all positions at once).

    Parameters
    ----------
    kin : Kinematics
        From :func:`graphkin.kinematics.solve_kinematics`, possibly with given values.

    Returns
    -------
    ForceAnalysis
        Every joint force and the driving effort at every position (nan where a position is not valid).
    """
    if not isinstance(kin, Kinematics):
        raise GraphkinError(f"solve_forces takes the Kinematics of a mechanism (solve_kinematics(...) or "
                            f"problem.kinematics()), got {type(kin).__name__}")
    plan = plan_of(kin.mechanism)
    n = kin.n
    if kin.loops and kin.groups != plan.groups:  # kinematics of another mechanism's structure: no reuse
        kin = replace(kin, loops={})
    # Invalid positions carry nan through the arithmetic, by design.
    with np.errstate(all="ignore"):
        if n <= CHUNK:
            return _result(kin, _pass(kin, plan, kin.valid, kin.loops))
        merged = _Merged(n)
        for s in range(0, n, CHUNK):
            t = min(n, s + CHUNK)
            part = _slice(kin, s, t)
            merged.add(s, t, _pass(part, plan, part.valid, part.loops))
    return _result(kin, merged.parts)


def solve(mech: Mechanism, q, q_dot=0.0, q_ddot=0.0, *, static: bool = False) -> ForceAnalysis:
    """Kinematics and kinetostatics in one call.

    Parameters
    ----------
    mech : Mechanism
    q, q_dot, q_ddot : array_like
        Input coordinate and rates (see :func:`graphkin.kinematics.solve_kinematics`).
    static : bool, optional
        A static force analysis: no inertia loads (the rates then only give
        the sense of sliding for friction).

    Returns
    -------
    ForceAnalysis
        Its ``kinematics`` are worked out again, the same, when first read: the result keeps only the
        forces, the effort and where they are valid (about 100 bytes a position).
    """
    plan, q, q_dot, q_ddot, rates = prepare(mech, q, q_dot, q_ddot)
    n = len(q)
    _program(plan, mech)
    general = plan.compiled["general"]
    merged = _Merged(n) if n > CHUNK else None
    kin_valid = np.empty(n, bool) if merged else None
    kin_failures: dict[str, np.ndarray] = {}
    with np.errstate(all="ignore"):
        for s in range(0, n, CHUNK):
            t = min(n, s + CHUNK)
            st, valid = run(plan, mech, q[s:t], q_dot[s:t], q_ddot[s:t], rates, angles=False)
            st.static = static
            # The state has the per-link fields the compiled steps read; the general code wants Kinematics.
            kin = Kinematics(mech, st.q, st.q_dot, st.q_ddot, st.theta, st.omega, st.alpha, st.e, st.O, st.v_O,
                             st.a_O, valid, st.failures, plan.groups, static=static) if general else st
            part = _pass(kin, plan, valid, st.loops)
            if merged is None:
                kin_valid, kin_failures, parts = valid, st.failures, part
            else:
                merged.add(s, t, part)
                kin_valid[s:t] = valid
                for why, where in st.failures.items():
                    kin_failures.setdefault(why, np.zeros(n, bool))[s:t] = where
    if merged is not None:
        parts = merged.parts
    return _result(deferred_kinematics(plan, mech, q, q_dot, q_ddot, rates, kin_valid, kin_failures,
                                       static=static), parts)
