"""Closed-form position, velocity and acceleration of each group, vectorised.

Positions are solved in closed form for each dyad type; the assembly branch
σ = ±1 picks one of the two solutions and stays the same over a cycle, so the
branch is continuous. Its meaning, with J1, J2, J3 the dyad's joints in the
order of :class:`~graphkin.kinematics.structure.Dyad`:

- RRR: σ = +1 puts J2 to the left of the directed line J1 → J3;
- RRP: σ = +1 puts J2 on the far side (along the guide direction u) of the
  foot of the perpendicular from J1 to the guide;
- RPR: σ = +1 points the guide direction u from the pin of the guide link
  towards the pin of the slider link;
- PRP, RPP: one solution, σ is not used.

Velocities and accelerations come from one loop equation written for every
dyad type: going from J1 to J3 through links j and k,

    v3(b) − v1(a) = ṡ1 u1 + ω_j k×(X2 − X1) + ṡ2 u2 + ω_k k×(X3 − X2) − ṡ3 u3,

where X1, X2, X3 are the joint points (pin, or slider point) and the ṡ terms
appear only for prismatic joints (a prismatic joint also ties the angular
velocities of the links it joins). Exactly two unknowns remain for every
dyad type, solved by Cramer's rule; accelerations use the same two columns
with centripetal and Coriolis terms on the right.
"""

from __future__ import annotations

import numpy as np

from ..geometry import angle_of, cross, dot, norm, perp, rotate, solve2, unit
from ..model import FRAME, Mechanism, Prismatic, Revolute
from .structure import Dyad, DriverGroup, GearGroup, decompose
from .state import Kinematics

DEAD_POINT = 1e-9
"""Relative size of the velocity determinant below which a position is a dead point."""


class _State:
    """Mutable scratch space filled group by group, then frozen into Kinematics."""

    def __init__(self, mech: Mechanism, n: int):
        self.mech = mech
        self.n = n
        z, z2 = np.zeros(n), np.zeros((n, 2))
        self.theta, self.omega, self.alpha = {FRAME: z}, {FRAME: z}, {FRAME: z}
        self.O, self.v_O, self.a_O = {FRAME: z2}, {FRAME: z2}, {FRAME: z2}
        self.failures: dict[str, np.ndarray] = {}

    def local(self, link, name):
        return rotate(np.asarray(self.mech.link(link).point(name)), self.theta[link])

    def pos(self, link, name):
        return self.O[link] + self.local(link, name)

    def vel_at(self, link, X):
        return self.v_O[link] + self.omega[link][:, None] * perp(X - self.O[link])

    def acc_at(self, link, X):
        r = X - self.O[link]
        return self.a_O[link] + self.alpha[link][:, None] * perp(r) - (self.omega[link] ** 2)[:, None] * r

    def place(self, link, theta, X, name):
        """Set link's angle and origin from the global position X of its point ``name``."""
        self.theta[link] = theta
        self.O[link] = X - rotate(np.asarray(self.mech.link(link).point(name)), theta)

    def fail(self, why, where):
        where = np.asarray(where, dtype=bool)
        if where.any():
            self.failures[why] = self.failures.get(why, np.zeros(self.n, bool)) | where


def _across(joint: Prismatic, link: int, theta_other):
    """Angle of ``link`` from the angle of the other link of a prismatic joint."""
    offset = joint.direction - joint.slider_direction
    return theta_other + offset if link == joint.slider else theta_other - offset


def _own_point(joint, link):
    """The point of ``link`` that takes part in a joint (pin, slider point or guide point)."""
    if isinstance(joint, Prismatic):
        return joint.point if link == joint.slider else joint.through
    return joint.point


def _line(st: _State, joint: Prismatic, link: int, theta, ref: str):
    """Line (Y, u) on which point ``ref`` of ``link`` must lie, given link's angle.

    The prismatic condition cross(u, X_slider − X_through) = 0 with the other
    link located becomes: X_ref lies on the line through Y along u.
    """
    other = joint.guide if link == joint.slider else joint.slider
    u = unit((theta if link == joint.guide else st.theta[joint.guide]) + joint.direction)
    Z = st.pos(other, _own_point(joint, other))
    lk = st.mech.link(link)
    w = rotate(np.subtract(lk.point(_own_point(joint, link)), lk.point(ref)), theta)
    return Z - w, u


def _positions(st: _State, d: Dyad, sigma: int):
    m = st.mech
    lj, lk = m.link(d.j), m.link(d.k)
    t = d.type
    if t == "RRR":
        X1 = st.pos(d.a, d.J1.point)
        X3 = st.pos(d.b, d.J3.point)
        Lj = norm(np.subtract(lj.point(d.J2.point), lj.point(d.J1.point)))
        Lk = norm(np.subtract(lk.point(d.J3.point), lk.point(d.J2.point)))
        D = X3 - X1
        dd = norm(D)
        with np.errstate(divide="ignore", invalid="ignore"):
            l = (Lj**2 - Lk**2 + dd**2) / (2 * dd)
            h2 = Lj**2 - l**2
            st.fail(f"{d.label} cannot be assembled ({d.J1.point}{d.J3.point} out of reach)", ~(h2 >= 0))
            e = D / dd[:, None]
            X2 = X1 + l[:, None] * e + (sigma * np.sqrt(np.where(h2 >= 0, h2, np.nan)))[:, None] * perp(e)
        st.place(d.j, angle_of(X2 - X1) - angle_of(np.subtract(lj.point(d.J2.point), lj.point(d.J1.point))), X2, d.J2.point)
        st.place(d.k, angle_of(X3 - X2) - angle_of(np.subtract(lk.point(d.J3.point), lk.point(d.J2.point))), X2, d.J2.point)
    elif t == "RRP":
        theta_k = _across(d.J3, d.k, st.theta[d.b])
        Y, u = _line(st, d.J3, d.k, theta_k, d.J2.point)
        X1 = st.pos(d.a, d.J1.point)
        Lj = norm(np.subtract(lj.point(d.J2.point), lj.point(d.J1.point)))
        t0 = dot(X1 - Y, u)
        e = cross(u, X1 - Y)
        h2 = Lj**2 - e**2
        st.fail(f"{d.label} cannot be assembled ({d.J1.point} out of reach of the guide)", ~(h2 >= 0))
        with np.errstate(invalid="ignore"):
            X2 = Y + (t0 + sigma * np.sqrt(np.where(h2 >= 0, h2, np.nan)))[:, None] * u
        st.place(d.j, angle_of(X2 - X1) - angle_of(np.subtract(lj.point(d.J2.point), lj.point(d.J1.point))), X2, d.J2.point)
        st.place(d.k, theta_k, X2, d.J2.point)
    elif t == "RPR":
        P = d.J2
        X1 = st.pos(d.a, d.J1.point)
        X3 = st.pos(d.b, d.J3.point)
        pin = {d.j: (X1, d.J1.point), d.k: (X3, d.J3.point)}
        (Xs, ps), (Xg, pg) = pin[P.slider], pin[P.guide]
        ls, lg = m.link(P.slider), m.link(P.guide)
        # cross(u, Xs − Xg) = e with u the guide direction: e is fixed by the
        # links' shapes, so the guide angle follows from one arcsine.
        a_s = rotate(np.subtract(ls.point(P.point), ls.point(ps)), -P.slider_direction)
        a_g = rotate(np.subtract(lg.point(P.through), lg.point(pg)), -P.direction)
        e = -(a_s[1] - a_g[1])
        D = Xs - Xg
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = e / norm(D)
        st.fail(f"{d.label} cannot be assembled (the guide cannot reach {P.point})", ~(np.abs(ratio) <= 1))
        with np.errstate(invalid="ignore"):
            asin = np.arcsin(np.where(np.abs(ratio) <= 1, ratio, np.nan))
        phi = angle_of(D) - asin if sigma > 0 else angle_of(D) - np.pi + asin
        theta = {P.guide: phi - P.direction, P.slider: phi - P.slider_direction}
        st.place(d.j, theta[d.j], X1, d.J1.point)
        st.place(d.k, theta[d.k], X3, d.J3.point)
    elif t == "RPP":
        theta_k = _across(d.J3, d.k, st.theta[d.b])
        theta_j = _across(d.J2, d.j, theta_k)
        st.place(d.j, theta_j, st.pos(d.a, d.J1.point), d.J1.point)
        ref = _own_point(d.J3, d.k)
        Y2, u2 = _line(st, d.J2, d.k, theta_k, ref)
        Y3, u3 = _line(st, d.J3, d.k, theta_k, ref)
        X = _meet(st, d, Y2, u2, Y3, u3)
        st.place(d.k, theta_k, X, ref)
    elif t == "PRP":
        theta_j = _across(d.J1, d.j, st.theta[d.a])
        theta_k = _across(d.J3, d.k, st.theta[d.b])
        Y1, u1 = _line(st, d.J1, d.j, theta_j, d.J2.point)
        Y3, u3 = _line(st, d.J3, d.k, theta_k, d.J2.point)
        X2 = _meet(st, d, Y1, u1, Y3, u3)
        st.place(d.j, theta_j, X2, d.J2.point)
        st.place(d.k, theta_k, X2, d.J2.point)
    else:  # pragma: no cover - decompose() only yields the types above
        raise AssertionError(t)


def _meet(st, d, Y1, u1, Y2, u2):
    """Point on both lines (Y1, u1) and (Y2, u2); nan where they are parallel."""
    x, y = solve2(-u1[:, 1], u1[:, 0], -u2[:, 1], u2[:, 0], cross(u1, Y1), cross(u2, Y2))
    st.fail(f"{d.label}: its two guides are parallel", ~np.isfinite(x))
    return np.stack([x, y], axis=-1)


def _joint_points(st: _State, d: Dyad):
    X = []
    for J, link in ((d.J1, d.j), (d.J2, d.k), (d.J3, d.k)):
        X.append(st.pos(J.slider, J.point) if isinstance(J, Prismatic) else st.pos(link, J.point))
    return X


def _rates(st: _State, d: Dyad):
    """ω, α of j and k, and the link origins' velocity and acceleration."""
    X1, X2, X3 = _joint_points(st, d)
    r12, r23 = X2 - X1, X3 - X2
    P1, P2, P3 = (isinstance(J, Prismatic) for J in (d.J1, d.J2, d.J3))
    u = {i: unit(st.theta[J.guide] + J.direction) for i, J in ((1, d.J1), (2, d.J2), (3, d.J3)) if isinstance(J, Prismatic)}

    # Which angular velocities are tied to a located link, and which are free.
    known_w = {}
    if P1:
        known_w["j"] = d.a
    if P3:
        known_w["k"] = d.b
    if P2 and "j" in known_w:
        known_w["k"] = d.a
    if P2 and "k" in known_w:
        known_w["j"] = known_w["k"]
    col = {"j": perp(r12), "k": perp(r23)}
    columns, names = [], []
    if P2 and not known_w:
        columns.append(col["j"] + col["k"]); names.append("w")
    else:
        for s in ("j", "k"):
            if s not in known_w:
                columns.append(col[s]); names.append(s)
    for i, sign in ((1, 1.0), (2, 1.0), (3, -1.0)):
        if i in u:
            columns.append(sign * u[i]); names.append(f"s{i}")
    assert len(columns) == 2, d.type
    A, B = columns

    def omega_of(side, z):
        if side in known_w:
            return st.omega[known_w[side]]
        return z["w"] if "w" in z else z[side]

    def alpha_of(side, z):
        if side in known_w:
            return st.alpha[known_w[side]]
        return z["w"] if "w" in z else z[side]

    v1a, v3b = st.vel_at(d.a, X1), st.vel_at(d.b, X3)
    rhs = v3b - v1a
    for side, link in known_w.items():
        rhs = rhs - st.omega[link][:, None] * col[side]
    detv = cross(A, B)
    scale = norm(A) * norm(B)
    st.fail(f"{d.label} is at a dead point", ~(np.abs(detv) > DEAD_POINT * scale))
    z1, z2 = solve2(A[:, 0], B[:, 0], A[:, 1], B[:, 1], rhs[:, 0], rhs[:, 1])
    zv = dict(zip(names, (z1, z2)))
    w_j, w_k = omega_of("j", zv), omega_of("k", zv)
    sd = {i: zv.get(f"s{i}", 0.0) for i in (1, 2, 3)}

    # Accelerations: same columns; centripetal and Coriolis terms are known now.
    a1a, a3b = st.acc_at(d.a, X1), st.acc_at(d.b, X3)
    rhs = a3b - a1a + (w_j**2)[:, None] * r12 + (w_k**2)[:, None] * r23
    if 1 in u:
        rhs = rhs - (2 * st.omega[d.a] * sd[1])[:, None] * perp(u[1])
    if 2 in u:
        rhs = rhs - (2 * w_j * sd[2])[:, None] * perp(u[2])
    if 3 in u:
        rhs = rhs + (2 * st.omega[d.b] * sd[3])[:, None] * perp(u[3])
    for side, link in known_w.items():
        rhs = rhs - st.alpha[link][:, None] * col[side]
    y1, y2 = solve2(A[:, 0], B[:, 0], A[:, 1], B[:, 1], rhs[:, 0], rhs[:, 1])
    za = dict(zip(names, (y1, y2)))
    al_j, al_k = alpha_of("j", za), alpha_of("k", za)
    sdd = {i: za.get(f"s{i}", 0.0) for i in (1, 2, 3)}

    # Link j from J1, link k from J3.
    v1j, a1j = v1a, a1a
    if 1 in u:
        v1j = v1a + sd[1][:, None] * u[1]
        a1j = a1a + sdd[1][:, None] * u[1] + (2 * st.omega[d.a] * sd[1])[:, None] * perp(u[1])
    v3k, a3k = v3b, a3b
    if 3 in u:
        v3k = v3b + sd[3][:, None] * u[3]
        a3k = a3b + sdd[3][:, None] * u[3] + (2 * st.omega[d.b] * sd[3])[:, None] * perp(u[3])
    for link, X, v, a, w, al in ((d.j, X1, v1j, a1j, w_j, al_j), (d.k, X3, v3k, a3k, w_k, al_k)):
        r = st.O[link] - X
        st.omega[link] = np.broadcast_to(w, (st.n,)).astype(float)
        st.alpha[link] = np.broadcast_to(al, (st.n,)).astype(float)
        st.v_O[link] = v + st.omega[link][:, None] * perp(r)
        st.a_O[link] = a + st.alpha[link][:, None] * perp(r) - (st.omega[link] ** 2)[:, None] * r


def _driver(st: _State, g: DriverGroup, q, q_dot, q_ddot):
    link = g.link
    J = g.joint
    if isinstance(J, Revolute):
        X = st.pos(FRAME, J.point)
        st.place(link, q, X, J.point)
        st.omega[link], st.alpha[link] = q_dot, q_ddot
        r = st.O[link] - X
        st.v_O[link] = q_dot[:, None] * perp(r)
        st.a_O[link] = q_ddot[:, None] * perp(r) - (q_dot**2)[:, None] * r
    else:
        theta = np.full(st.n, J.direction - J.slider_direction)
        u = unit(np.full(st.n, J.direction))
        X = st.pos(FRAME, J.through) + q[:, None] * u
        st.place(link, theta, X, J.point)
        st.omega[link] = st.alpha[link] = np.zeros(st.n)
        st.v_O[link] = q_dot[:, None] * u
        st.a_O[link] = q_ddot[:, None] * u


def _gear(st: _State, g: GearGroup):
    (rj, rk) = g.mesh.radii if g.mesh.links[0] == g.j else g.mesh.radii[::-1]
    rho = rj / rk
    b, j, k = g.b, g.j, g.k
    # External mesh: relative to the carrier, the gears turn in opposite senses.
    theta = st.theta[b] - rho * (st.theta[j] - st.theta[b])
    X = st.pos(b, g.pivot.point)
    st.place(k, theta, X, g.pivot.point)
    st.omega[k] = st.omega[b] - rho * (st.omega[j] - st.omega[b])
    st.alpha[k] = st.alpha[b] - rho * (st.alpha[j] - st.alpha[b])
    r = st.O[k] - X
    st.v_O[k] = st.vel_at(b, X) + st.omega[k][:, None] * perp(r)
    st.a_O[k] = st.acc_at(b, X) + st.alpha[k][:, None] * perp(r) - (st.omega[k] ** 2)[:, None] * r


def solve_kinematics(mech: Mechanism, q, q_dot=0.0, q_ddot=0.0) -> Kinematics:
    """Kinematics of every link for a batch of input positions, in one call.

    Parameters
    ----------
    mech : Mechanism
    q : array_like, shape (n,) or scalar
        Input coordinate: crank angle θ [rad] or slider position s [m].
    q_dot, q_ddot : array_like, broadcast to q
        Input rates: ω [rad/s] and α [rad/s²], or v [m/s] and a [m/s²].

    Returns
    -------
    Kinematics
        Positions that cannot be assembled, or are dead points, hold nan and
        are False in ``valid``; ``reason(i)`` says why.
    """
    q = np.atleast_1d(np.asarray(q, dtype=float))
    q_dot = np.broadcast_to(np.asarray(q_dot, dtype=float), q.shape).astype(float)
    q_ddot = np.broadcast_to(np.asarray(q_ddot, dtype=float), q.shape).astype(float)
    st = _State(mech, len(q))
    for g in decompose(mech):
        if isinstance(g, DriverGroup):
            _driver(st, g, q, q_dot, q_ddot)
        elif isinstance(g, GearGroup):
            _gear(st, g)
        else:
            _positions(st, g, mech.assembly.get(g.key, 1))
            _rates(st, g)
    valid = np.ones(len(q), bool)
    for store in (st.theta, st.omega, st.alpha):
        for v in store.values():
            valid &= np.isfinite(v)
    for store in (st.O, st.v_O, st.a_O):
        for v in store.values():
            valid &= np.isfinite(v).all(axis=-1)
    for where in st.failures.values():
        valid &= ~where
    return Kinematics(mech, q, q_dot, q_ddot, st.theta, st.omega, st.alpha, st.O, st.v_O, st.a_O, valid, st.failures)
