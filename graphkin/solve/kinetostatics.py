"""Analytical kinetostatics, solved group by group in closed form.

The three equilibrium equations of each moving link (d'Alembert: inertia
force −m a_G and torque −I_G α included as loads) form [A]{x} = {b}; see
:mod:`graphkin.solve.matrix` for that matrix, which the lessons display and the
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
"""

from __future__ import annotations

import itertools

import numpy as np

from ..errors import GraphkinError
from ..kinematics import Dyad, DriverGroup, GearGroup, Kinematics, solve_kinematics
from ..kinematics.dyads import solve_columns
from ..geometry import as_xy
from ..geometry import zcross as cross
from ..geometry import zdot as dot
from ..model import Mechanism, Prismatic, Revolute
from .loads import _known
from .result import ForceAnalysis


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
    rk = mesh.radii[mesh.links.index(g.k)]
    Ck = kin.z(g.b, g.pivot.point)
    Cj = kin.z(g.b, g.j_pivot.point)
    e = (Cj - Ck) / np.abs(Cj - Ck)
    P = Ck + rk * e
    t = 1j * e
    # The tooth force's tangential part balances k's moment about its centre;
    # its radial part, |W_t| tan φ, pushes k away from j.
    W_t = -(M[g.k] - cross(Ck, L[g.k])) / rk
    W = W_t * t - np.abs(W_t) * np.tan(mesh.pressure_angle) * e
    F = -L[g.k] - W
    return [_Reactions(mesh, g.k, W, P), _Reactions(g.pivot, g.k, F, Ck)]


def _friction_joints(d: Dyad):
    return [i for i, J in enumerate(d.joints) if isinstance(J, Prismatic) and J.mu > 0]


def solve_forces(kin: Kinematics) -> ForceAnalysis:
    """Joint forces and driving effort for known kinematics (all positions at once).

    Parameters
    ----------
    kin : Kinematics
        From :func:`graphkin.kinematics.solve_kinematics`, possibly with given values.

    Returns
    -------
    ForceAnalysis
    """
    if not isinstance(kin, Kinematics):
        raise GraphkinError(f"solve_forces takes the Kinematics of a mechanism (solve_kinematics(...) or "
                            f"problem.kinematics()), got {type(kin).__name__}")
    mech = kin.mechanism
    n = kin.n
    L, M = {}, {}
    for link in mech.moving:
        L[link], M[link] = _known(kin, link)
    forces, normal, couple = {}, {}, {}
    failures: dict[str, np.ndarray] = {}
    effort = None

    def apply(reactions):
        for r in reactions:
            i, j = r.joint.links
            other = i if r.on == j else j
            key = (min(i, j), max(i, j))
            sign = 1.0 if r.on == key[1] else -1.0
            forces[key] = as_xy(sign * r.F)
            if r.N is not None:
                normal[key] = sign * r.N
                couple[key] = sign * r.C
            if other != mech.frame:
                # On the other link the reaction acts at that link's own pin (the same point, unless an angle is given).
                X = kin.z(other, r.joint.point) if isinstance(r.joint, Revolute) else r.X
                L[other] = L[other] - r.F
                M[other] = M[other] - cross(X, r.F) - (r.C if r.C is not None else 0.0)

    # Invalid positions carry nan through the arithmetic, by design.
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for g in reversed(kin.groups):
            if isinstance(g, DriverGroup):
                reactions, effort = _driver(kin, g, L, M)
            elif isinstance(g, GearGroup):
                reactions = _gear(kin, g, L, M)
            else:
                reactions = _solve_dyad_with_friction(kin, g, L, M, failures)
            apply(reactions)

    valid = kin.valid & np.isfinite(effort)
    for F in forces.values():
        valid &= np.isfinite(F[:, 0]) & np.isfinite(F[:, 1])
    for where in failures.values():
        valid &= ~where
    dead = kin.valid & ~valid & ~np.logical_or.reduce([w for w in failures.values()] or [np.zeros(n, bool)])
    if dead.any():
        failures["the force equations are singular (dead point)"] = dead
    return ForceAnalysis(kin, forces, normal, couple, effort, valid, failures)


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
    """
    from dataclasses import replace

    kin = solve_kinematics(mech, q, q_dot, q_ddot)
    return solve_forces(replace(kin, static=True) if static else kin)
