"""The closed-form position, velocity and acceleration of each group, vectorised: the textbook's steps.

Plane vectors are complex numbers here (x + iy), as in the textbooks' loop
equations: a point of a link is O + e^{iθ} p, ω × r is iωr.

Positions are solved in closed form for each dyad type; the assembly branch
σ = ±1 picks one of the two solutions and stays the same over a cycle, so the
branch is continuous. Its meaning, with J1, J2, J3 the dyad's joints in the
order of :class:`~graphkin.kinematics.structure.Dyad`:

- RRR: σ = +1 puts J2 to the left of the directed line J1 → J3, J1 being the
  outer pin on the link located later (the crank pin A of a four-bar);
- RRP: σ = +1 puts J2 on the far side (along the guide direction u) of the
  foot of the perpendicular from J1 to the guide;
- RPR: σ = +1 points the guide direction u from the pin of the guide link
  towards the pin of the slider link;
- PRP, RPP: one solution, σ is not used.

Velocities and accelerations come from one loop equation written for every
dyad type: going from J1 to J3 through links j and k,

    v3(b) − v1(a) = ṡ1 u1 + ω_j i(X2 − X1) + ṡ2 u2 + ω_k i(X3 − X2) − ṡ3 u3,

where X1, X2, X3 are the joint points (pin, or slider point) and the ṡ terms
appear only for prismatic joints (a prismatic joint also ties the angular
velocities of the links it joins). Exactly two unknowns remain for every
dyad type, solved by Cramer's rule; accelerations use the same two columns
with centripetal and Coriolis terms on the right.

These are the steps a textbook writes, one function each, on a :class:`State`
that holds what the groups before have located: :func:`positions` (closed form
per dyad type), :func:`loop` and :func:`rates` (the loop equation solved by
Cramer's rule, :func:`solve_columns`), :func:`locate_driver` and :func:`gear`.
:mod:`graphkin.kinematics.solver` runs them (with a compiled form of the
crank and the RRR dyad), and the handouts write them out with the numbers
in (:mod:`graphkin.handout.loops`).
"""


from __future__ import annotations

from types import MappingProxyType
from typing import NamedTuple

import numpy as np

from graphkin.geometry import zcross as cross
from graphkin.geometry import zdot as dot
from graphkin.kinematics.plan import Plan, plan_of
from graphkin.kinematics.structure import DriverGroup, Dyad, GearGroup
from graphkin.model import Mechanism, Prismatic, Revolute

DEAD_POINT = 1e-7
"""Relative size of the velocity determinant below which a position is a dead point.

At an exact toggle the assembled position itself carries rounding of about
√ε ≈ 1e-8 (a square root of a difference near zero), so the determinant
there is of that size rather than zero: the threshold sits above it."""


def solve_columns(A, B, rhs):
    """Real z1, z2 with A z1 + B z2 = rhs for complex A, B, rhs (Cramer); inf/nan where A ∥ B."""
    with np.errstate(divide="ignore", invalid="ignore"):
        det = cross(A, B)
        return cross(rhs, B) / det, cross(A, rhs) / det


class State:
    """Scratch space filled group by group, then frozen into Kinematics."""

    given = MappingProxyType({})  # read by the force analysis, like Kinematics.given: the state has none
    static = False

    def __init__(self, mech: Mechanism, n: int, plan: Plan | None = None):
        self.mech = self.mechanism = mech
        self.n = n
        self.points = (plan or plan_of(mech)).points
        self.zero = np.zeros(n, complex)
        frame = mech.frame
        self.still = still = np.zeros(n)
        self.ones = np.ones(n, complex)
        self.e = {frame: self.ones}
        self.O, self.v_O, self.a_O = {frame: self.zero}, {frame: self.zero}, {frame: self.zero}
        self.theta, self.omega, self.alpha = {frame: still}, {frame: still}, {frame: still}
        self.failures: dict[str, np.ndarray] = {}
        # What a dyad's force analysis can reuse from its kinematics: joint points, arms, determinant.
        self.loops: dict = {}
        # Links turning about a fixed pivot: link -> (pivot, its local point); arrays known to be finite (ids).
        self.pivots: dict = {}
        self.finite = {id(self.zero)}
        self.w0 = self.al0 = None
        # e^{iq} of a crank's input angles when the caller has it (a batch of designs: one turn's, repeated).
        self.e_q = None
        # Links placed by a dyad whose angle a gear is turned by: link -> (m, c) of :meth:`turned`.
        self.branches: dict = {}

    def spin(self, w):
        """iω as a number when the input speed is the same at every position, else as an array."""
        return 1j * (w if self.w0 is None else self.w0)

    def turn(self, w, al):
        """iα − ω² (the factor of r in a rigid body's acceleration), a number when the input rates are constant."""
        if self.w0 is None or self.al0 is None:
            return 1j * al - w * w
        return 1j * self.al0 - self.w0 * self.w0

    def p(self, link, name) -> complex:
        try:
            return self.points[link, name]
        except KeyError:
            x, y = self.mech.link(link).point(name)  # the model's own message when the point is not there
            return complex(x, y)

    def pos(self, link, name):
        if link == self.mech.frame:
            return np.full(self.n, self.p(link, name))
        return self.O[link] + self.e[link] * self.p(link, name)

    def vel_at(self, link, X):
        if link == self.mech.frame:
            return self.zero
        return self.v_O[link] + 1j * self.omega[link] * (X - self.O[link])

    def acc_at(self, link, X):
        if link == self.mech.frame:
            return self.zero
        return self.a_O[link] + (1j * self.alpha[link] - self.omega[link] ** 2) * (X - self.O[link])

    def place(self, link, e, X, name):
        """Set link's e^{iθ} and origin from the position X of its point ``name``."""
        self.e[link] = e
        self.O[link] = X - e * self.p(link, name)

    def angle(self, link):
        if link not in self.theta:
            self.theta[link] = np.angle(self.e[link])
        return self.theta[link]

    def turned(self, link):
        """θ of ``link`` on a branch continuous over the driver's travel: what a gear's angle is taken from.

        A dyad gives a link's angle as np.angle gives it, in (−π, π]; a planet on an arm that swings across ±π
        would jump there by (1 − ρ) turns. With ``branches[link] = (m, c)``, the link turning m times per turn
        of the crank and the rest of its angle θ − m q ranging about c by less than half a turn either way,
        θ = m q + c + wrap(θ − m q − c) is continuous. Links without a branch keep their angle.
        """
        theta = self.angle(link)
        branch = self.branches.get(link)
        if branch is None:
            return theta
        m, c = branch
        base = m * self.q + c if m else c
        return base + (np.remainder(theta - base + np.pi, 2 * np.pi) - np.pi)

    def fail(self, why, where):
        if where.any():
            self.failures[why] = self.failures.get(why, np.zeros(self.n, bool)) | where


def across(joint: Prismatic, link: int, e_other):
    """e^{iθ} of ``link`` from that of the other link of a prismatic joint."""
    turn = np.exp(1j * (joint.direction - joint.slider_direction))
    return e_other * turn if link == joint.slider else e_other / turn


def own_point(joint, link):
    """The point of ``link`` that takes part in a joint (pin, slider point or guide point)."""
    if isinstance(joint, Prismatic):
        return joint.point if link == joint.slider else joint.through
    return joint.point


def line(st: State, joint: Prismatic, link: int, e_link, ref: str):
    """Line (Y, u) on which point ``ref`` of ``link`` must lie, given link's e^{iθ}.

    The prismatic condition cross(u, X_slider − X_through) = 0 with the other
    link located becomes: X_ref lies on the line through Y along u.
    """
    other = joint.guide if link == joint.slider else joint.slider
    u = (e_link if link == joint.guide else st.e[joint.guide]) * np.exp(1j * joint.direction)
    Z = st.pos(other, own_point(joint, other))
    return Z - e_link * (st.p(link, own_point(joint, link)) - st.p(link, ref)), u


def bar(st, link, X_from, X_to, p_from, p_to):
    """e^{iθ} of a link from the positions of two of its points (|X_to − X_from| = |p_to − p_from|)."""
    d = st.p(link, p_to) - st.p(link, p_from)
    return (X_to - X_from) * (d.conjugate() / abs(d) ** 2)


def _sqrt(st, h2, why):
    # nan comes from a group that failed before, which has said why already.
    st.fail(why, h2 < 0)
    return np.sqrt(np.where(h2 >= 0, h2, np.nan))


def positions(st: State, d: Dyad, sigma: int):
    t = d.type
    if t == "RRR":
        X1, X3 = st.pos(d.a, d.J1.point), st.pos(d.b, d.J3.point)
        Lj = abs(st.p(d.j, d.J2.point) - st.p(d.j, d.J1.point))
        Lk = abs(st.p(d.k, d.J3.point) - st.p(d.k, d.J2.point))
        D = X3 - X1
        dd = np.abs(D)
        with np.errstate(divide="ignore", invalid="ignore"):
            l = (Lj**2 - Lk**2 + dd**2) / (2 * dd)
            h = _sqrt(st, Lj**2 - l**2, f"{d.label} cannot be assembled ({d.J1.point}{d.J3.point} out of reach)")
            X2 = X1 + (l + 1j * sigma * h) * (D / dd)
        st.place(d.j, bar(st, d.j, X1, X2, d.J1.point, d.J2.point), X2, d.J2.point)
        st.place(d.k, bar(st, d.k, X2, X3, d.J2.point, d.J3.point), X2, d.J2.point)
    elif t == "RRP":
        e_k = across(d.J3, d.k, st.e[d.b])
        Y, u = line(st, d.J3, d.k, e_k, d.J2.point)
        X1 = st.pos(d.a, d.J1.point)
        Lj = abs(st.p(d.j, d.J2.point) - st.p(d.j, d.J1.point))
        h = _sqrt(st, Lj**2 - cross(u, X1 - Y) ** 2, f"{d.label} cannot be assembled ({d.J1.point} out of reach of the guide)")
        X2 = Y + (dot(X1 - Y, u) + sigma * h) * u
        st.place(d.j, bar(st, d.j, X1, X2, d.J1.point, d.J2.point), X2, d.J2.point)
        st.place(d.k, e_k, X2, d.J2.point)
    elif t == "RPR":
        P = d.J2
        X1, X3 = st.pos(d.a, d.J1.point), st.pos(d.b, d.J3.point)
        pin = {d.j: (X1, d.J1.point), d.k: (X3, d.J3.point)}
        (Xs, ps), (Xg, pg) = pin[P.slider], pin[P.guide]
        # cross(u, Xs − Xg) = c with u the guide direction: c is fixed by the
        # links' shapes, so the guide angle follows from one arcsine.
        a_s = (st.p(P.slider, P.point) - st.p(P.slider, ps)) * np.exp(-1j * P.slider_direction)
        a_g = (st.p(P.guide, P.through) - st.p(P.guide, pg)) * np.exp(-1j * P.direction)
        c = a_g.imag - a_s.imag
        D = Xs - Xg
        r = np.abs(D)
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = c / r
            cos = _sqrt(st, 1 - ratio**2, f"{d.label} cannot be assembled (the guide cannot reach {P.point})")
            u = D / r * (cos - 1j * ratio) if sigma > 0 else -D / r * (cos + 1j * ratio)
        e = {P.guide: u * np.exp(-1j * P.direction), P.slider: u * np.exp(-1j * P.slider_direction)}
        st.place(d.j, e[d.j], X1, d.J1.point)
        st.place(d.k, e[d.k], X3, d.J3.point)
    elif t == "RPP":
        e_k = across(d.J3, d.k, st.e[d.b])
        st.place(d.j, across(d.J2, d.j, e_k), st.pos(d.a, d.J1.point), d.J1.point)
        ref = own_point(d.J3, d.k)
        X = meet(st, d, *line(st, d.J2, d.k, e_k, ref), *line(st, d.J3, d.k, e_k, ref))
        st.place(d.k, e_k, X, ref)
    elif t == "PRP":
        e_j = across(d.J1, d.j, st.e[d.a])
        e_k = across(d.J3, d.k, st.e[d.b])
        X2 = meet(st, d, *line(st, d.J1, d.j, e_j, d.J2.point), *line(st, d.J3, d.k, e_k, d.J2.point))
        st.place(d.j, e_j, X2, d.J2.point)
        st.place(d.k, e_k, X2, d.J2.point)
    else:  # pragma: no cover - decompose() only yields the types above
        raise AssertionError(t)


def meet(st, d, Y1, u1, Y2, u2):
    """Point on both lines (Y1, u1) and (Y2, u2); nan where they are parallel."""
    with np.errstate(divide="ignore", invalid="ignore"):
        t = cross(Y2 - Y1, u2) / cross(u1, u2)
    known = np.isfinite(Y2 - Y1) & np.isfinite(u1) & np.isfinite(u2)  # else a group before has failed
    st.fail(f"{d.label}: its two guides are parallel", known & ~np.isfinite(t))
    return Y1 + t * u1


def joint_points(st: State, d: Dyad):
    return [st.pos(J.slider, J.point) if isinstance(J, Prismatic) else st.pos(link, J.point)
            for J, link in ((d.J1, d.j), (d.J2, d.k), (d.J3, d.k))]


class Loop(NamedTuple):
    """The loop J1 → J2 → J3 of a dyad's rate equations, set up once for the solver and the handouts.

    Attributes
    ----------
    X1, X2, X3 : ndarray of complex
        The joints' points [m].
    r12, r23 : ndarray of complex
        The arms J1 → J2 (on link j) and J2 → J3 (on link k) [m].
    u : dict of int to ndarray of complex
        The guide's unit direction at each sliding joint (1, 2 or 3).
    known_w : dict of str to int
        ``"j"``/``"k"`` → the located link whose angular velocity that side shares (a sliding pair).
    col : dict of str to ndarray of complex
        The column ``i r`` of each side's angular velocity.
    names : list of str
        The two unknowns: ``"j"``, ``"k"``, ``"w"`` (both links as one), ``"s1"``… (sliding speeds).
    A, B : ndarray of complex
        Their columns in ``A x + B y = rhs``.
    """

    X1: np.ndarray
    X2: np.ndarray
    X3: np.ndarray
    r12: np.ndarray
    r23: np.ndarray
    u: dict
    known_w: dict
    col: dict
    names: list
    A: np.ndarray
    B: np.ndarray


def loop(st: State, d: Dyad) -> Loop:
    """The dyad's loop: its arms, guides, the angular velocities a sliding pair ties, the two unknowns' columns."""
    X1, X2, X3 = joint_points(st, d)
    r12, r23 = X2 - X1, X3 - X2
    u = {i: st.e[J.guide] * np.exp(1j * J.direction) for i, J in ((1, d.J1), (2, d.J2), (3, d.J3)) if isinstance(J, Prismatic)}

    # Which angular velocities are tied to a located link, and which are free.
    known_w = {}
    if 1 in u:
        known_w["j"] = d.a
    if 3 in u:
        known_w["k"] = d.b
    if 2 in u and "j" in known_w:
        known_w["k"] = d.a
    if 2 in u and "k" in known_w:
        known_w["j"] = known_w["k"]
    col = {"j": 1j * r12, "k": 1j * r23}
    columns, names = [], []
    if 2 in u and not known_w:
        columns.append(col["j"] + col["k"]), names.append("w")
    else:
        for side in ("j", "k"):
            if side not in known_w:
                columns.append(col[side]), names.append(side)
    for i in (1, 2, 3):
        if i in u:
            columns.append(-u[i] if i == 3 else u[i]), names.append(f"s{i}")
    return Loop(X1, X2, X3, r12, r23, u, known_w, col, names, *columns)


def rates(st: State, d: Dyad):
    """ω, α of j and k, and the velocity and acceleration of their origins."""
    X1, X2, X3, r12, r23, u, known_w, col, names, A, B = loop(st, d)

    def pick(side, z, known):
        if side in known_w:
            return known[known_w[side]]
        return z["w"] if "w" in z else z[side]

    v1a, v3b = st.vel_at(d.a, X1), st.vel_at(d.b, X3)
    rhs = v3b - v1a
    for side, link in known_w.items():
        rhs = rhs - st.omega[link] * col[side]
    size = np.abs(cross(A, B))
    # Only where the dyad has a position: one that cannot be assembled is not also "at a dead point".
    st.fail(f"{d.label} is at a dead point", np.isfinite(size) & ~(size > DEAD_POINT * np.abs(A) * np.abs(B)))
    zv = dict(zip(names, solve_columns(A, B, rhs)))
    w_j, w_k = pick("j", zv, st.omega), pick("k", zv, st.omega)

    # Accelerations: same columns; centripetal and Coriolis terms are known now.
    a1a, a3b = st.acc_at(d.a, X1), st.acc_at(d.b, X3)
    rhs = a3b - a1a + w_j**2 * r12 + w_k**2 * r23
    coriolis = {}
    if 1 in u:
        coriolis[1] = 2j * st.omega[d.a] * zv["s1"] * u[1]
        rhs = rhs - coriolis[1]
    if 2 in u:
        rhs = rhs - 2j * w_j * zv["s2"] * u[2]
    if 3 in u:
        coriolis[3] = 2j * st.omega[d.b] * zv["s3"] * u[3]
        rhs = rhs + coriolis[3]
    for side, link in known_w.items():
        rhs = rhs - st.alpha[link] * col[side]
    za = dict(zip(names, solve_columns(A, B, rhs)))
    al_j, al_k = pick("j", za, st.alpha), pick("k", za, st.alpha)

    # Link j from J1, link k from J3.
    v1j, a1j, v3k, a3k = v1a, a1a, v3b, a3b
    if 1 in u:
        v1j = v1a + zv["s1"] * u[1]
        a1j = a1a + za["s1"] * u[1] + coriolis[1]
    if 3 in u:
        v3k = v3b + zv["s3"] * u[3]
        a3k = a3b + za["s3"] * u[3] + coriolis[3]
    for link, X, v, a, w, al in ((d.j, X1, v1j, a1j, w_j, al_j), (d.k, X3, v3k, a3k, w_k, al_k)):
        r = st.O[link] - X
        w = np.broadcast_to(w, (st.n,)).astype(float)
        al = np.broadcast_to(al, (st.n,)).astype(float)
        st.omega[link], st.alpha[link] = w, al
        st.v_O[link] = v + 1j * w * r
        st.a_O[link] = a + (1j * al - w**2) * r


def locate_driver(st: State, g: DriverGroup, q, q_dot, q_ddot):
    link, J = g.link, g.joint
    if isinstance(J, Revolute):
        X = st.pos(st.mech.frame, J.point)
        st.place(link, np.exp(1j * q), X, J.point)
        st.theta[link], st.omega[link], st.alpha[link] = q, q_dot, q_ddot
        r = st.O[link] - X
        st.v_O[link] = 1j * q_dot * r
        st.a_O[link] = (1j * q_ddot - q_dot**2) * r
    else:
        u = np.exp(1j * J.direction)
        st.place(link, np.full(st.n, np.exp(1j * (J.direction - J.slider_direction))),
                 st.pos(st.mech.frame, J.through) + q * u, J.point)
        st.omega[link] = st.alpha[link] = np.zeros(st.n)
        st.v_O[link] = q_dot * u
        st.a_O[link] = q_ddot * u


def gear(st: State, g: GearGroup):
    """Gear k from its mesh with gear j: relative to the carrier b, ω_k − ω_b = ∓ρ (ω_j − ω_b), ρ = r_j / r_k.

    Minus for an external mesh (the gears turn opposite ways relative to the carrier), plus for an internal one;
    the same for the angles and the accelerations.
    """
    rj, rk = g.mesh.radius(g.j), g.mesh.radius(g.k)
    rho = g.sign * rj / rk
    b, j, k = g.b, g.j, g.k
    st.theta[k] = st.turned(b) + rho * (st.turned(j) - st.turned(b))
    X = st.pos(b, g.ck)
    st.place(k, np.exp(1j * st.theta[k]), X, g.pivot.point)
    st.omega[k] = st.omega[b] + rho * (st.omega[j] - st.omega[b])
    st.alpha[k] = st.alpha[b] + rho * (st.alpha[j] - st.alpha[b])
    r = st.O[k] - X
    st.v_O[k] = st.vel_at(b, X) + 1j * st.omega[k] * r
    st.a_O[k] = st.acc_at(b, X) + (1j * st.alpha[k] - st.omega[k] ** 2) * r
