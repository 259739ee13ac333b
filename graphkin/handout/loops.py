"""The kinematics as a textbook writes it: each group's closed-form equations with the numbers substituted.

The solver (:mod:`graphkin.kinematics.groups`) locates the links group by
group — the driver, then each dyad or gear pair in the order
:func:`graphkin.kinematics.decompose` gives — in closed form: a triangle for
an RRR dyad, a line and a circle for an RRP dyad, an arcsine for an RPR
dyad, two lines for the others. Velocities and accelerations come from one
loop equation per dyad, J1 → J2 → J3 through links j and k, with exactly
two unknowns left, solved by Cramer's rule.

:func:`groups` writes those same steps, group by group, as equations with
the numbers in them. The numbers are the solver's: each group starts from
the state the solver reached before it (the located links' positions,
velocities and accelerations, read from the
:class:`~graphkin.kinematics.Kinematics`), and every step uses the
solver's own helpers (``_line``, ``_across``, ``_joint_points``, ``_bar``,
``_meet``, ``solve_columns``), so what is printed as a result is what the
solver found (``tests/handout/test_handout.py`` checks it to the printed digits).

Every result is an equation line that starts with the result's symbol and
ends with its value (``ω3 = … = −4.364 rad/s``); two results on one line are
separated by a semicolon.
"""

from __future__ import annotations

import math

import numpy as np

from graphkin.geometry import zcross as cross
from graphkin.geometry import zdot as dot
from graphkin.handout import maths as M
from graphkin.kinematics import groups as solver
from graphkin.kinematics.solver import branches
from graphkin.kinematics.structure import DriverGroup, Dyad, GearGroup
from graphkin.model import Prismatic, Revolute

SIGMA = {
    "RRR": "σ = +1 puts {J2} to the left of the line {J1} → {J3}",
    "RRP": "σ = +1 puts {J2} on the far side, along u, of the foot of the perpendicular from {J1} to the guide",
    "RPR": "σ = +1 points the guide's direction u from the pin of the guide link to the pin of the slider",
}
"""What the assembly branch σ means for each dyad type (as in :mod:`graphkin.kinematics.groups`)."""


# -- the solver's state before a group ------------------------------------------------------------------
_FIELDS = ("e", "O", "v_O", "a_O", "theta", "omega", "alpha")


def _state(kin, i: int):
    """The solver's scratch state for position ``i`` with only the frame located, for its own helpers.

    It carries the solver's branches (:meth:`~graphkin.kinematics.groups.State.turned`), so that a gear's angle is
    written from the angles it was found from.
    """
    st = solver.State(kin.mechanism, 1)
    st.q, st.branches = kin.q[i:i + 1], branches(kin.mechanism)
    return st


def _locate(st, kin, i: int, links, fields=_FIELDS):
    """Copy what the solver found for ``links`` at position ``i`` into ``st``: the next group starts from it."""
    for name in fields:
        for link in links:
            getattr(st, name)[link] = np.asarray(getattr(kin, name)[link][i:i + 1])


def _z(x) -> complex:
    return complex(np.asarray(x).reshape(-1)[0])


def _f(x) -> float:
    return float(np.asarray(x).reshape(-1)[0])


# -- small pieces of notation ---------------------------------------------------------------------------------
def _deg(rad: float) -> list:
    return M.row(M.n(M.fmt_fixed(math.degrees(rad))), M.op("°"))


def _mm(z: complex) -> list:
    return M.pair((z.real * 1e3, z.imag * 1e3), "mm")


def _vec(z: complex, unit: str = "") -> list:
    return M.pair((z.real, z.imag), unit)


def _in_mm(x: float) -> list:
    """A length [m] as a bare number of millimetres."""
    return M.n(x * 1e3)


def _len(z: complex) -> list:
    return M.qty(abs(z) * 1e3, "mm")


def _r(a: str, b: str = "") -> list:
    """r_A (a point's position) or r_AB (from A to B)."""
    return M.sym("r", a + b)


def _kx(x) -> list:
    return M.row(M.i("k"), M.op("×"), x)


def _sq(x) -> list:
    """x²; a negative number in parentheses, (−200)², as it is squared."""
    if x[0] == "n" and x[1].startswith(M.MINUS):
        x = M.paren(x)
    return M.sup(x, "2")


def _joint_text(J) -> str:
    if isinstance(J, Prismatic):
        return f"slider {J.slider} on the guide of link {J.guide} at {J.point}"
    return f"pin {J.point} ({'–'.join(map(str, J.links))})"


def _w(link: int) -> list:
    return M.sym("ω", str(link))


def _al(link: int) -> list:
    return M.sym("α", str(link))


def _th(link: int) -> list:
    return M.sym("θ", str(link))


def _slide(on: int, other: int, what: str = "v") -> list:
    """v_4/1: the speed of link ``on`` relative to ``other`` along their guide (a: the acceleration).

    Two links slide on each other at one pair at most, so the links name it.
    """
    return M.sym(what, f"{on}/{other}")


def _u(J: Prismatic) -> list:
    return M.sym("u", J.point)


def _angle_line(link: int, X_from: complex, X_to: complex, d_local: complex, name_from: str, name_to: str,
                value: float) -> list:
    """θ of a link from two of its located points: θ = ∠(r_to − r_from) − β, β that direction in the link's frame.

    Of the two senses, the one whose β is smaller is written (∠(r_B − r_B0)
    rather than ∠(r_B0 − r_B) − 180° for a rocker drawn from B0 to B).
    """
    if abs(math.atan2(-d_local.imag, -d_local.real)) < abs(math.atan2(d_local.imag, d_local.real)) - 1e-12:
        X_from, X_to, name_from, name_to, d_local = X_to, X_from, name_to, name_from, -d_local
    beta = math.atan2(d_local.imag, d_local.real)
    items = [_th(link), M.op("="), M.op("∠"), M.paren(_r(name_to), M.op("−"), _r(name_from))]
    if abs(beta) > 1e-12:
        items += [M.op("−"), _deg(beta)]
        items += [M.op("="), _deg(math.atan2((X_to - X_from).imag, (X_to - X_from).real)), M.op("−"), _deg(beta)]
    items += [M.op("="), _deg(value)]
    return M.row(*items)


def _tied_angle(J: Prismatic, link: int, other: int, value: float) -> list:
    """θ of a link that keeps its angle to the other link of a sliding pair: θ_slider = θ_guide + δ − δ_s."""
    delta = J.direction - J.slider_direction
    sign = "+" if link == J.slider else "−"
    items = [_th(link), M.op("="), _th(other)]
    if abs(delta) > 1e-12:
        items += [M.op("+" if (delta > 0) == (sign == "+") else "−"), _deg(abs(delta))]
    return M.row(*items, M.op("="), _deg(value))


# -- the groups ---------------------------------------------------------------------------------------------
def groups(doc, kin, i: int, rates: bool = True) -> None:
    """Write each group's position, velocity and acceleration equations at position ``i``, in solution order.

    Parameters
    ----------
    doc
        Collects the blocks: ``heading(level, text)``, ``text(*runs)``,
        ``equation(*lines)`` (:class:`graphkin.handout.document.Doc`).
    kin : graphkin.kinematics.Kinematics
        The solver's result; its ``groups`` give the order.
    i : int
        The position, where the linkage is assembled (``kin.valid[i]``).
    rates : bool
        False for a static analysis: positions only (no velocity or
        acceleration enters a static force analysis).
    """
    mech = kin.mechanism
    st = _state(kin, i)
    for g in kin.groups:
        if isinstance(g, DriverGroup):
            _driver(doc, kin, i, g, rates)
        elif isinstance(g, GearGroup):
            _gear(doc, st, g, rates)
        else:
            _dyad(doc, st, kin, i, g, mech.assembly.get(g.key, 1), rates)
        _locate(st, kin, i, g.links)
        for link in g.links if rates else ():
            given = [q for q in ("omega", "alpha") if (link, q) in kin.given]
            if given:
                names = " and ".join("ω" if q == "omega" else "α" for q in given)
                doc.text(f"The problem gives link {link}'s {names} at this position: the inertia loads below use "
                         "the given value.")


def _driver(doc, kin, i: int, g: DriverGroup, rates: bool = True):
    link = g.link
    doc.heading(3, f"Link {link}: the driver")
    q, qd, qdd = float(kin.q[i]), float(kin.q_dot[i]), float(kin.q_ddot[i])
    what = "its angle and rates are" if rates else "its angle is"
    if isinstance(g.joint, Revolute):
        doc.text(f"The crank turns about {g.joint.point}; {what} the input:")
        line = [_th(link), M.op("="), _deg(q)]
        if rates:
            line += [M.op(";"), M.SP, _w(link), M.op("="), M.qty(qd, "rad/s"), M.op(";"), M.SP, _al(link), M.op("="),
                     M.qty(qdd, "rad/s²")]
        doc.equation(M.row(*line))
        return
    J = g.joint
    what = "and its rates are" if rates else "is"
    doc.text(f"Slider {link} moves along the guide of link {J.guide} through {J.through}: its position s from "
             f"{J.through} {what} the input, and it keeps its angle to the guide:")
    s = M.i("s")
    line = [s, M.op("="), M.qty(q * 1e3, "mm")]
    if rates:
        line += [M.op(";"), M.SP, M.sym("v", str(link)), M.op("="), M.qty(qd, "m/s"), M.op(";"), M.SP,
                 M.sym("a", str(link)), M.op("="), M.qty(qdd, "m/s²")]
    lines = [M.row(*line), _tied_angle(J, link, J.guide if link == J.slider else J.slider, float(kin.theta[link][i]))]
    if rates:
        lines.append(M.row(_w(link), M.op("="), M.qty(float(kin.omega[link][i]), "rad/s"), M.op(";"), M.SP,
                           _al(link), M.op("="), M.qty(float(kin.alpha[link][i]), "rad/s²")))
    doc.equation(*lines)


def _gear(doc, st, g: GearGroup, rates: bool = True):
    rj, rk = g.mesh.radius(g.j), g.mesh.radius(g.k)
    rho = rj / rk
    b, j, k = g.b, g.j, g.k
    # Relative to the carrier the pair turns as gears on fixed axes (Willis): opposite ways when external, the same
    # way when one is an annulus.
    sign, op = (1.0, "+") if g.mesh.internal else (-1.0, "−")
    doc.heading(3, f"Gear {k}: meshing with gear {j}" + (f" on carrier {b}" if b in st.mech.moving else ""))
    doc.text(f"Gear {k} turns about {g.ck}, a point of link {b}; relative to link {b} it turns "
             f"{'the same way as' if g.mesh.internal else 'the other way from'} gear {j}, by the ratio of the pitch "
             f"radii ρ = r{j}/r{k}:")
    theta_k = _f(st.turned(b)) + sign * rho * (_f(st.turned(j)) - _f(st.turned(b)))
    w_k = _f(st.omega[b]) + sign * rho * (_f(st.omega[j]) - _f(st.omega[b]))
    a_k = _f(st.alpha[b]) + sign * rho * (_f(st.alpha[j]) - _f(st.alpha[b]))
    lines = [M.row(M.i("ρ"), M.op("="), M.frac(M.qty(rj * 1e3, "mm"), M.qty(rk * 1e3, "mm")), M.op("="), M.n(rho))]
    for sym, values, result, unit in (
            (_th, (st.turned(b), st.turned(j)), theta_k, "°"),
            (_w, (st.omega[b], st.omega[j]), w_k, "rad/s"),
            (_al, (st.alpha[b], st.alpha[j]), a_k, "rad/s²"))[:3 if rates else 1]:
        vb, vj = (_f(v) for v in values)
        show = _deg if unit == "°" else M.n
        tail = _deg(result) if unit == "°" else M.qty(result, unit)
        lines.append(M.row(sym(k), M.op("="), sym(b), M.op(op), M.i("ρ"), M.paren(sym(j), M.op("−"), sym(b)),
                           M.op("="), show(vb), M.op(op), M.n(rho), M.paren(show(vj), M.op("−"), show(vb)),
                           M.op("="), tail))
    doc.equation(*lines)


# -- dyads ------------------------------------------------------------------------------------------------
def _dyad(doc, st, kin, i: int, d: Dyad, sigma: int, rates: bool = True):
    doc.heading(3, f"Links {d.j} and {d.k}: {'an' if d.type[0] == 'R' else 'a'} {d.type} dyad")
    doc.text(f"Links {d.j} and {d.k} are joined to each other by the {_joint_text(d.J2)}; the "
             f"{_joint_text(d.J1)} joins link {d.j} to link {d.a}, the {_joint_text(d.J3)} joins link {d.k} "
             f"to link {d.b}, both located already.")
    _POSITION[d.type](doc, st, d, sigma)
    _locate(st, kin, i, d.links, ("e", "O", "theta"))
    if rates:
        _rates(doc, st, kin, i, d)


def _position_rrr(doc, st, d: Dyad, sigma: int):
    P1, P2, P3 = d.J1.point, d.J2.point, d.J3.point
    X1, X3 = _z(st.pos(d.a, P1)), _z(st.pos(d.b, P3))
    Lj = abs(st.p(d.j, P2) - st.p(d.j, P1))
    Lk = abs(st.p(d.k, P3) - st.p(d.k, P2))
    D = X3 - X1
    dd = abs(D)
    # The triangle J1 J2 J3 as the solver solves it (groups.positions): l along J1 → J3, h across it.
    l = (Lj ** 2 - Lk ** 2 + dd ** 2) / (2 * dd)
    h = math.sqrt(max(Lj ** 2 - l ** 2, 0.0))
    X2 = X1 + (l + 1j * sigma * h) * (D / dd)
    mm = _in_mm
    d_ = M.i("d")
    Lj_, Lk_ = M.sym("L", P1 + P2), M.sym("L", P2 + P3)
    doc.text(f"{P2} is where the circle of radius {P1}{P2} about {P1} meets the circle of radius {P2}{P3} about "
             f"{P3}: the triangle {P1}{P2}{P3} with base d = |{P1}{P3}|, l along the base and h across it "
             f"({SIGMA['RRR'].format(J1=P1, J2=P2, J3=P3)}; here σ = {sigma:+d}). Lengths in mm:")
    doc.equation(
        M.row(_r(P1), M.op("="), _mm(X1), M.op(";"), M.SP, _r(P3), M.op("="), _mm(X3)),
        M.row(_r(P1, P3), M.op("="), _r(P3), M.op("−"), _r(P1), M.op("="), _mm(D), M.op(";"), M.SP, d_, M.op("="),
              M.absval(_r(P1, P3)), M.op("="), _len(D)),
        M.row(M.i("l"), M.op("="),
              M.frac(M.row(_sq(Lj_), M.op("−"), _sq(Lk_), M.op("+"), _sq(d_)), M.row(M.n("2"), d_)),
              M.op("="), M.frac(M.row(_sq(mm(Lj)), M.op("−"), _sq(mm(Lk)), M.op("+"), _sq(mm(dd))),
                                M.row(M.n("2"), M.op("·"), mm(dd))), M.op("="), M.qty(l * 1e3, "mm")),
        M.row(M.i("h"), M.op("="), M.i("σ"), M.sqrt(M.row(_sq(Lj_), M.op("−"), _sq(M.i("l")))), M.op("="),
              M.op("+" if sigma > 0 else "−"), M.sqrt(M.row(_sq(mm(Lj)), M.op("−"), _sq(mm(l)))), M.op("="),
              M.qty(sigma * h * 1e3, "mm")),
        M.row(_r(P2), M.op("="), _r(P1), M.op("+"), M.frac(M.row(M.i("l"), M.SP, _r(P1, P3), M.op("+"), M.i("h"), M.SP,
                                                             _kx(_r(P1, P3))), d_), M.op("="), _mm(X2)),
    )
    e_j = _z(solver.bar(st, d.j, X1, X2, P1, P2))
    e_k = _z(solver.bar(st, d.k, X2, X3, P2, P3))
    doc.equation(
        _angle_line(d.j, X1, X2, st.p(d.j, P2) - st.p(d.j, P1), P1, P2, float(np.angle(e_j))),
        _angle_line(d.k, X2, X3, st.p(d.k, P3) - st.p(d.k, P2), P2, P3, float(np.angle(e_k))),
    )


def _line_of(st, J: Prismatic, link: int, e_link: complex, ref: str):
    """The solver's line (Y, u) on which point ``ref`` of ``link`` lies, and a name for Y."""
    Y, u = solver.line(st, J, link, np.asarray([e_link]), ref)
    own = solver.own_point(J, link)
    other = J.guide if link == J.slider else J.slider
    # Y is the other link's point of the pair when ref is this link's own point of it (a pin on the slider).
    name = solver.own_point(J, other) if st.p(link, own) == st.p(link, ref) else f"Y{J.point}"
    return _z(Y), _z(u), name


def _position_rrp(doc, st, d: Dyad, sigma: int):
    P1, P2 = d.J1.point, d.J2.point
    J3 = d.J3
    e_k = _z(solver.across(J3, d.k, st.e[d.b]))
    Y, u, Yname = _line_of(st, J3, d.k, e_k, P2)
    X1 = _z(st.pos(d.a, P1))
    Lj = abs(st.p(d.j, P2) - st.p(d.j, P1))
    e = cross(u, X1 - Y)
    along = _clean(dot(X1 - Y, u), Lj)
    h = math.sqrt(max(Lj ** 2 - e ** 2, 0.0))
    X2 = Y + (along + sigma * h) * u
    mm = _in_mm
    u_, e_ = _u(J3), M.i("e")
    Lj_ = M.sym("L", P1 + P2)
    doc.text(f"Link {d.k} keeps its angle to link {d.b}, so the guide's direction u is known; {P2} lies on the "
             f"line through {Yname} along u, at {P1}{P2} from {P1}: e is {P1}'s distance from that line "
             f"({SIGMA['RRP'].format(J1=P1, J2=P2)}; here σ = {sigma:+d}). Lengths in mm:")
    doc.equation(
        _tied_angle(J3, d.k, d.b, float(np.angle(e_k))),
        M.row(u_, M.op("="), _vec(u), M.op(";"), M.SP, _r(Yname), M.op("="), _mm(Y), M.op(";"), M.SP, _r(P1),
              M.op("="), _mm(X1)),
        M.row(e_, M.op("="), u_, M.op("×"), M.paren(_r(P1), M.op("−"), _r(Yname)), M.op("="), M.qty(e * 1e3, "mm")),
        M.row(_r(P2), M.op("="), _r(Yname), M.op("+"), M.paren(M.paren(_r(P1), M.op("−"), _r(Yname)), M.op("·"), u_,
                                                               M.op("+"), M.i("σ"),
                                                               M.sqrt(M.row(_sq(Lj_), M.op("−"), _sq(e_)))), u_),
        M.row(M.op("="), _r(Yname), M.op("+"), M.paren(mm(along), M.op("+" if sigma > 0 else "−"),
                                                       M.sqrt(M.row(_sq(mm(Lj)), M.op("−"), _sq(mm(e))))), u_,
              M.op("="), _mm(X2)),
    )
    e_j = _z(solver.bar(st, d.j, X1, X2, P1, P2))
    doc.equation(_angle_line(d.j, X1, X2, st.p(d.j, P2) - st.p(d.j, P1), P1, P2, float(np.angle(e_j))))


def _position_rpr(doc, st, d: Dyad, sigma: int):
    P = d.J2
    X1, X3 = _z(st.pos(d.a, d.J1.point)), _z(st.pos(d.b, d.J3.point))
    pin = {d.j: (X1, d.J1.point), d.k: (X3, d.J3.point)}
    (Xs, ps), (Xg, pg) = pin[P.slider], pin[P.guide]
    # As the solver: the guide line passes at a fixed offset c from the slider's pin, set by the links' shapes.
    a_s = (st.p(P.slider, P.point) - st.p(P.slider, ps)) * np.exp(-1j * P.slider_direction)
    a_g = (st.p(P.guide, P.through) - st.p(P.guide, pg)) * np.exp(-1j * P.direction)
    c = a_g.imag - a_s.imag
    D = Xs - Xg
    r = abs(D)
    ratio = c / r
    cos = math.sqrt(max(1 - ratio ** 2, 0.0))
    u = D / r * (cos - 1j * ratio) if sigma > 0 else -D / r * (cos + 1j * ratio)
    beta = math.asin(ratio)
    u_ = _u(P)
    doc.text(f"Link {P.slider} slides on the guide of link {P.guide}; the guide line passes at a fixed distance c "
             f"from {ps} (set by the links' shapes), so its direction u follows from the line {pg}{ps} and one "
             f"arcsine ({SIGMA['RPR']}; here σ = {sigma:+d}). Lengths in mm:")
    doc.equation(
        M.row(_r(pg), M.op("="), _mm(Xg), M.op(";"), M.SP, _r(ps), M.op("="), _mm(Xs), M.op(";"), M.SP, M.i("c"),
              M.op("="), M.qty(c * 1e3, "mm")),
        M.row(_r(pg, ps), M.op("="), _mm(D), M.op(";"), M.SP, M.i("β"), M.op("="), M.t("arcsin"),
              M.paren(M.frac(M.i("c"), M.absval(_r(pg, ps)))), M.op("="), M.t("arcsin"),
              M.paren(M.frac(M.n(c * 1e3), M.n(r * 1e3))), M.op("="), _deg(beta)),
        M.row(M.op("∠"), u_, M.op("="), M.op("∠"), _r(pg, ps), *([M.op("+"), _deg(math.pi)] if sigma < 0 else []),
              M.op("−" if sigma > 0 else "+"), M.i("β"), M.op("="), _deg(math.atan2(u.imag, u.real))),
    )
    e = {P.guide: u * np.exp(-1j * P.direction), P.slider: u * np.exp(-1j * P.slider_direction)}
    lines = []
    for link, delta in ((P.guide, P.direction), (P.slider, P.slider_direction)):
        items = [_th(link), M.op("="), M.op("∠"), u_]
        if abs(delta) > 1e-12:
            items += [M.op("−"), _deg(delta)]
        lines.append(M.row(*items, M.op("="), _deg(float(np.angle(e[link])))))
    doc.equation(*lines)


def _position_meet(doc, st, d: Dyad, sigma: int):
    """RPP and PRP: the links' angles follow from the guides; a point lies on two lines at once."""
    if d.type == "RPP":
        e_k = _z(solver.across(d.J3, d.k, st.e[d.b]))
        e_j = _z(solver.across(d.J2, d.j, np.asarray([e_k])))
        # As the solver: link j is placed on its pin first, for the line of the pair J2 to be known.
        st.place(d.j, np.asarray([e_j]), st.pos(d.a, d.J1.point), d.J1.point)
        ref = solver.own_point(d.J3, d.k)
        (Y1, u1, n1), (Y2, u2, n2) = _line_of(st, d.J2, d.k, e_k, ref), _line_of(st, d.J3, d.k, e_k, ref)
        angles = [_tied_angle(d.J3, d.k, d.b, float(np.angle(e_k))), _tied_angle(d.J2, d.j, d.k, float(np.angle(e_j)))]
        J_1, J_2 = d.J2, d.J3
    else:  # PRP
        e_j = _z(solver.across(d.J1, d.j, st.e[d.a]))
        e_k = _z(solver.across(d.J3, d.k, st.e[d.b]))
        ref = d.J2.point
        (Y1, u1, n1), (Y2, u2, n2) = _line_of(st, d.J1, d.j, e_j, ref), _line_of(st, d.J3, d.k, e_k, ref)
        angles = [_tied_angle(d.J1, d.j, d.a, float(np.angle(e_j))), _tied_angle(d.J3, d.k, d.b, float(np.angle(e_k)))]
        J_1, J_2 = d.J1, d.J3
    X = _z(solver.meet(st, d, *(np.asarray([x]) for x in (Y1, u1, Y2, u2))))
    t = cross(Y2 - Y1, u2) / cross(u1, u2)
    u1_, u2_ = _u(J_1), _u(J_2)
    doc.text(f"Each link keeps its angle to the link it slides on, so both guides' directions are known; {ref} lies "
             f"on both guide lines, through {n1} along {J_1.point}'s guide and through {n2} along {J_2.point}'s. "
             "Lengths in mm:")
    doc.equation(
        *angles,
        M.row(_r(n1), M.op("="), _mm(Y1), M.op(";"), M.SP, u1_, M.op("="), _vec(u1), M.op(";"), M.SP, _r(n2),
              M.op("="), _mm(Y2), M.op(";"), M.SP, u2_, M.op("="), _vec(u2)),
        M.row(M.i("t"), M.op("="), M.frac(M.row(M.paren(_r(n2), M.op("−"), _r(n1)), M.op("×"), u2_),
                                          M.row(u1_, M.op("×"), u2_)), M.op("="), M.qty(t * 1e3, "mm")),
        M.row(_r(ref), M.op("="), _r(n1), M.op("+"), M.i("t"), u1_, M.op("="), _mm(X)),
    )


_POSITION = {"RRR": _position_rrr, "RRP": _position_rrp, "RPR": _position_rpr, "RPP": _position_meet,
             "PRP": _position_meet}


def _rates(doc, st, kin, i: int, d: Dyad):
    """The loop J1 → J3 for velocities and accelerations, as the solver writes it (groups.rates)."""
    # The solver's own loop (its arms, guides, tied angular velocities and unknowns), at this position.
    L = solver.loop(st, d)
    X1, X2, X3, r12, r23, A, B = (_z(x) for x in (L.X1, L.X2, L.X3, L.r12, L.r23, L.A, L.B))
    u = {n: _z(x) for n, x in L.u.items()}
    col = {side: _z(x) for side, x in L.col.items()}
    known_w, names = L.known_w, L.names
    J = {1: d.J1, 2: d.J2, 3: d.J3}
    scale = max(abs(r12), abs(r23))
    link_of = {"j": d.j, "k": d.k}
    # Who slides on whom at each sliding pair of the loop: J1 carries j over a, J2 k over j, J3 k over b.
    rel = {1: (d.j, d.a), 2: (d.k, d.j), 3: (d.k, d.b)}
    P = {1: d.J1.point, 2: d.J2.point, 3: d.J3.point}

    def unknown(name, what):
        if name == "w":
            return (_w if what == "v" else _al)(d.j)
        if name in ("j", "k"):
            return (_w if what == "v" else _al)(link_of[name])
        n = int(name[1])
        return _slide(*rel[n], what=what)

    def point(n, link):
        """A loop end's name: A for a pin, B1 for link 1's point under a slider at B (B0,1 after a digit)."""
        if isinstance(J[n], Revolute):
            return P[n]
        return f"{P[n]},{link}" if P[n][-1].isdigit() else f"{P[n]}{link}"

    ends = (point(1, d.a), point(3, d.b))
    if known_w:
        doc.text("A sliding pair keeps the angle between its links; "
                 + " and ".join(f"link {link_of[side]} turns with link {link}" for side, link in known_w.items()) + ":")
        doc.equation(*(M.row(_w(link_of[side]), M.op("="), _w(link), M.op("="), M.qty(_f(st.omega[link]), "rad/s"),
                             M.op(";"), M.SP, _al(link_of[side]), M.op("="), _al(link), M.op("="),
                             M.qty(_f(st.alpha[link]), "rad/s²")) for side, link in known_w.items()))
    elif "w" in names:
        doc.text(f"The block and its guide turn together: ω{d.k} = ω{d.j} and α{d.k} = α{d.j}, one unknown each.")

    # Velocities.
    v1a, v3b = _z(st.vel_at(d.a, np.asarray([X1]))), _z(st.vel_at(d.b, np.asarray([X3])))
    rhs = v3b - v1a
    for side, link in known_w.items():
        rhs = rhs - _f(st.omega[link]) * col[side]
    zv = dict(zip(names, (_f(z) for z in solver.solve_columns(np.asarray([A]), np.asarray([B]), np.asarray([rhs])))))
    path = [P[1]] + [P[n] for n in (2, 3) if P[n] != P[n - 1]]
    doc.text(f"Velocities: the loop {' → '.join(path)} through links {d.j} and {d.k} "
             "(k × r is r turned 90° counter-clockwise; lengths in m):")
    # The arms of the loop: r12 on link j, r23 on link k; one arm r13 when the two links turn as one (RPR).
    if "w" in names:
        arms = [(d.j, _r(P[1], P[3]), r12 + r23)]
    else:
        arms = [(link, _r(P[a], P[b]), r) for link, a, b, r in ((d.j, 1, 2, r12), (d.k, 2, 3, r23))]
    arms = [(link, sym, r) for link, sym, r in arms if abs(r) > 1e-12 * scale]

    def loop(what):
        """The loop's right-hand side: slides along the guides and turns of the arms, in the loop's order."""
        rate = _w if what == "v" else _al
        terms = [(M.op("+"), unknown("s1", what), _u(J[1]))] if 1 in u else []
        terms += [(M.op("+"), rate(link), _kx(sym)) for link, sym, r in arms if link == d.j]
        terms += [(M.op("+"), unknown("s2", what), _u(J[2]))] if 2 in u else []
        terms += [(M.op("+"), rate(link), _kx(sym)) for link, sym, r in arms if link != d.j]
        terms += [(M.op("−"), unknown("s3", what), _u(J[3]))] if 3 in u else []
        return _terms(terms)

    lines = [M.row(M.sym("v", ends[1]), M.op("−"), M.sym("v", ends[0]), M.op("="), *loop("v")),
             *_knowns([(M.sym("v", ends[0]), v1a, "m/s"), (M.sym("v", ends[1]), v3b, "m/s")]
                     + [(sym, r, "m") for _, sym, r in arms] + [(_u(J[n]), u[n], "") for n in sorted(u)]
                     + _tied_terms(_w, known_w, st.omega, col, link_of, P, "m/s")),
             _system(A, B, [unknown(x, "v") for x in names], rhs)]
    lines += _solution(A, B, rhs, [unknown(x, "v") for x in names], [_unit(x, "v") for x in names])
    if "w" in names:
        lines.append(M.row(_w(d.k), M.op("="), _w(d.j), M.op("="), M.qty(zv["w"], "rad/s")))
    doc.equation(*lines)
    _locate(st, kin, i, d.links, ("omega", "v_O"))
    w_j, w_k = _f(st.omega[d.j]), _f(st.omega[d.k])

    # Accelerations: the same two columns; the normal (ω² r) and Coriolis (2ω v k × u) terms are known now.
    a1a, a3b = _z(st.acc_at(d.a, np.asarray([X1]))), _z(st.acc_at(d.b, np.asarray([X3])))
    rhs = a3b - a1a + w_j ** 2 * r12 + w_k ** 2 * r23
    known = [(M.sym("a", ends[0]), a1a, "m/s²"), (M.sym("a", ends[1]), a3b, "m/s²")]
    omega = {d.j: w_j, d.k: w_k}
    if "w" in names:
        normal = [(M.row(_sq(_w(d.j)), sym), w_j ** 2 * r12 + w_k ** 2 * r23) for _, sym, _ in arms]
    else:
        normal = [(M.row(_sq(_w(link)), sym), omega[link] ** 2 * r) for link, sym, r in arms]
    coriolis = []
    turning = {1: d.a, 2: d.j, 3: d.b}  # the link whose rotation turns each guide, as in the solver
    for n, sign in ((1, -1), (2, -1), (3, +1)):
        # A guide on the frame does not turn: no Coriolis term to write.
        if n in u and turning[n] in st.mech.moving:
            value = 2j * _f(st.omega[turning[n]]) * zv[f"s{n}"] * u[n]
            rhs = rhs + sign * value
            coriolis.append((sign, M.row(M.n("2"), _w(turning[n]), unknown(f"s{n}", "v"), _kx(_u(J[n]))), value))
    for side, link in known_w.items():
        rhs = rhs - _f(st.alpha[link]) * col[side]
    left = [M.sym("a", ends[1]), M.op("−"), M.sym("a", ends[0])]
    for sym, _ in normal:
        left += [M.op("+"), sym]
    for sign, sym, _ in coriolis:
        left += [M.op("+" if sign > 0 else "−"), sym]
    doc.text("Accelerations: the same loop differentiated once more; the normal terms ω² r and the Coriolis terms "
             "2ω v k × u are known now and go to the left:")
    lines = [M.row(*left, M.op("="), *loop("a")),
             *_knowns(known + [(sym, value, "m/s²") for sym, value in normal]
                     + [(sym, value, "m/s²") for _, sym, value in coriolis]
                     + _tied_terms(_al, known_w, st.alpha, col, link_of, P, "m/s²")),
             _system(A, B, [unknown(x, "a") for x in names], rhs)]
    lines += _solution(A, B, rhs, [unknown(x, "a") for x in names], [_unit(x, "a") for x in names])
    if "w" in names:
        za = dict(zip(names, (_f(z) for z in solver.solve_columns(*(np.asarray([x]) for x in (A, B, rhs))))))
        lines.append(M.row(_al(d.k), M.op("="), _al(d.j), M.op("="), M.qty(za["w"], "rad/s²")))
    doc.equation(*lines)
    _locate(st, kin, i, d.links, ("alpha", "a_O"))


def _tied_terms(rate, known_w, values, col, link_of, P, unit) -> list:
    """The loop's terms whose rate a sliding pair ties to a located link: known, so on the right-hand side's list."""
    arm = {"j": (1, 2), "k": (2, 3)}
    out = []
    for side, link in known_w.items():
        if abs(col[side]) > 0:
            a, b = arm[side]
            out.append((M.row(rate(link_of[side]), _kx(_r(P[a], P[b]))), _f(values[link]) * col[side], unit))
    return out


def _unit(name: str, what: str) -> str:
    if name[0] == "s":
        return "m/s" if what == "v" else "m/s²"
    return "rad/s" if what == "v" else "rad/s²"


def _terms(terms) -> list:
    out = []
    for k, (sign, *parts) in enumerate(terms):
        if k or sign[1] != "+":
            out.append(sign)
        out.extend(parts)
    return out


KNOWNS_PER_LINE = 3
"""Known vectors written on one line of a loop's list (more would not fit the page's width)."""


def _knowns(items) -> list:
    """``v_A = (2, 0) m/s; r_AB = (…) m; …``: the known vectors of a loop with their numbers, a few a line."""
    lines = []
    for start in range(0, len(items), KNOWNS_PER_LINE):
        out = []
        for k, (sym, z, unit) in enumerate(items[start:start + KNOWNS_PER_LINE]):
            if k:
                out += [M.op(";"), M.SP]
            out += [sym, M.op("="), _vec(z, unit)]
        lines.append(M.row(*out))
    return lines


def _system(A: complex, B: complex, unknowns, rhs: complex) -> list:
    """The loop's two components as a matrix equation [A B]{z} = {c}, with numbers."""
    scale = max(abs(A), abs(B), 1e-300)
    cells = [[_clean(A.real, scale), _clean(B.real, scale)], [_clean(A.imag, scale), _clean(B.imag, scale)]]
    c = max(abs(rhs), 1e-300)
    return M.row(M.mat([[M.n(x) for x in r] for r in cells]), M.column(unknowns), M.op("="),
                 M.column([M.n(_clean(rhs.real, c)), M.n(_clean(rhs.imag, c))]))


def _clean(x: float, scale: float) -> float:
    """Rounding noise (1e-17 where a component is exactly zero) printed as 0."""
    return 0.0 if abs(x) < 1e-12 * scale else x


def _solution(A: complex, B: complex, rhs: complex, unknowns, units) -> list:
    """Cramer's rule, as the solver solves it (``solve_columns``): the determinant and each unknown."""
    det = cross(A, B)
    z = [_f(x) for x in solver.solve_columns(np.asarray([A]), np.asarray([B]), np.asarray([rhs]))]
    nums = (cross(rhs, B), cross(A, rhs))
    scale = abs(A) * abs(B)
    row = [M.i("Δ"), M.op("="), M.n(_clean(det, scale))]
    for sym, num, value, unit in zip(unknowns, nums, z, units):
        num = _clean(num, abs(rhs) * max(abs(A), abs(B)))
        numerator = M.n(num)
        if num == 0:
            value = 0.0  # its numerator is rounding, and so is what it gives (1e-17 m/s² where a slide stops)
        row += [M.op(";"), M.SP, sym, M.op("="), M.frac(numerator, M.i("Δ")), M.op("="),
                M.qty(value, unit)]
    return [M.row(*row)]
