"""One guard for everything graphical: each value a construction yields, checked against the analytical route.

A construction is other arithmetic on the same positions: resultants and concurrency points, polygons closed tip
to tail, Kennedy's lines. It agrees with the analytical route (the matrix solution, the closed-form kinematics) to
rounding, about 1e-13 on textbook problems and at most about 1e-10 on random linkages near their transmission
limits; a wrong term in either route (a pitch point on the wrong side of an internal mesh, a sign, a reaction not
passed on) is a difference of order one. Whatever differs by more than :data:`AGREEMENT` of the position's scale
is not a number anyone may see: the construction is returned not valid, its reason naming the quantity and both
values, and every reader (the report and its JSON, the figures, the handouts, the exercises' keys, the widgets)
already refuses an invalid construction.

What is compared, position by position:

- **Force polygons** (:func:`check_forces`): every joint force and the driving effort, against the
  :class:`~graphkin.analytical.ForceAnalysis`; the scale is the largest joint force (a torque is divided by the
  mechanism's size to be measured as a force).
- **Velocity and acceleration polygons** (:func:`motion_disagreement`): ω and α of every link (times the
  mechanism's size, to be measured as a speed), the velocity and acceleration of every named point and centre of
  mass, every image point of both polygons (each is a point of a link, so its value follows from the link's
  motion) and every Coriolis component 2 ω v_rel, against the kinematics; the scale is the largest speed (or
  acceleration) of the position. Every other vector of a polygon (a relative velocity, a normal or tangential
  component) joins two image points, so it is right when they are.
- **Instant centres** (:func:`centres_disagreement`): each centre found must be a point with no velocity of one
  link relative to the other (the relative velocity there, against the largest speed), each centre at infinity a
  direction across which the two links only translate; the ω and velocities the centres give are compared as the
  polygons' are.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from graphkin.kinematics import solve_kinematics
from graphkin.notation import largest, num, polar_text

AGREEMENT = 1e-9
"""How far a graphical value may differ from the analytical one, relative to the largest value of its kind at the
position, before the position's construction is not valid (issue 35). The routes differ by rounding, ~1e-13 on
textbook problems and at most ~1e-10 on the property tests' random linkages; any wrong term is O(1)."""


def is_disagreement(reason: str) -> bool:
    """Whether a construction is not valid because this guard found it disagreeing with the analytical route (a
    fault in graphkin's arithmetic, to be reported, rather than a position the linkage cannot take)."""
    return "analytical route disagree: " in reason or "analytical routes disagree: " in reason


def mechanism_size(mech) -> float:
    """The mechanism's size [m]: the largest distance between two points of one link (1 m for a point-sized one)."""
    size = 0.0
    for link in mech.links:
        pts = [complex(*p) for p in link.points.values()]
        size = max([size] + [abs(a - b) for a in pts for b in pts])
    return size or 1.0


# -- forces ---------------------------------------------------------------------------------------------------
def forces_disagreement(result, c, i: int, size: float | None = None) -> str:
    """Why the force construction ``c`` of position ``i`` disagrees with the analytical ``result`` ('' if not).

    Every difference is measured as a force: a joint force's as it is, the driving torque's divided by the
    mechanism's size (``size`` [m], :func:`mechanism_size` when not given); the largest, against
    :data:`AGREEMENT` of the largest force (or effort) at the position.
    """
    if not c.valid:
        return f"the graphical route cannot close ({c.reason}) where the analytical one finds a solution"
    size = mechanism_size(result.mechanism) if size is None else size
    scale = largest(result.force(a, b)[i] for a, b in result.forces)
    worst, what = 0.0, ""
    for a, b in result.forces:
        A, G = result.force(a, b)[i], c.force(a, b)
        gap = float(np.hypot(*(G - A)))
        if not gap <= worst:  # nan counts as the worst
            worst, what = gap, (f"{result.name_of(a, b)} is {polar_text(G, scale=scale)} graphically, "
                                f"{polar_text(A, scale=scale)} analytically")
    crank = result.mechanism.driver.crank
    arm = size if crank else 1.0  # a torque [N·m] per metre of the mechanism is a force
    effort = float(result.effort[i])
    gap = abs(c.effort - effort) / arm
    if not gap <= worst:
        unit = "N·m" if crank else "N"
        worst, what = gap, (f"{result.driver_name} is {num(c.effort, 6, minus='-')} {unit} graphically, "
                            f"{num(effort, 6, minus='-')} {unit} analytically")
    if worst <= AGREEMENT * max(scale, abs(effort) / arm):
        return ""
    return f"the graphical and analytical routes disagree: {what}"


def check_forces(result, c, i: int):
    """The force construction ``c`` of position ``i``, or a copy not valid where it disagrees with ``result``.

    Parameters
    ----------
    result : graphkin.analytical.ForceAnalysis
        The analytical solution the construction was built beside (the same kinematics).
    c : graphkin.graphical.Construction or None
        :func:`graphkin.graphical.construct_forces` at position ``i`` (None passes through).
    i : int
        The position's index in ``result``.

    Returns
    -------
    Construction or None
        ``c`` itself where both routes agree (or where the analytical route has no solution, whose reason the
        construction already gives); else a copy whose ``valid`` is False and whose ``reason`` names the force
        and both values.
    """
    if c is None or not c.valid or not result.valid[i]:
        return c
    why = forces_disagreement(result, c, i)
    return replace(c, valid=False, reason=why) if why else c


# -- motion -----------------------------------------------------------------------------------------------------
class _Truth:
    """The analytical motion of position ``i``: any point's velocity and acceleration as a point of any link."""

    def __init__(self, kin, i: int):
        mech = kin.mechanism
        self.frame = mech.frame
        self.size = mechanism_size(mech)
        self.w = {n: float(kin.omega[n][i]) for n in mech.moving}
        self.al = {n: float(kin.alpha[n][i]) for n in mech.moving}
        self.O = {n: complex(kin.O[n][i]) for n in mech.moving}
        self.v_O = {n: complex(kin.v_O[n][i]) for n in mech.moving}
        self.a_O = {n: complex(kin.a_O[n][i]) for n in mech.moving}
        self.w[self.frame] = self.al[self.frame] = 0.0
        self.O[self.frame] = self.v_O[self.frame] = self.a_O[self.frame] = 0j
        self.e = {n: complex(kin.e[n][i]) for n in mech.moving}
        self.e[self.frame] = 1 + 0j
        # The scales: the fastest named point or centre of mass, or a link's ω over the mechanism's size.
        speeds, accels = [0.0], [0.0]
        for n in mech.moving:
            body = mech.link(n)
            for p in list(body.points.values()) + [body.G]:
                P = self.at(n, p)
                speeds.append(abs(self.v(n, P)))
                accels.append(abs(self.a(n, P)))
            speeds.append(abs(self.w[n]) * self.size)
            accels.append(abs(self.al[n]) * self.size)
        self.v_scale, self.a_scale = max(speeds), max(accels)

    def at(self, link: int, p) -> complex:
        """Where the point ``p`` (x, y) [m] of ``link``'s own frame is [m]."""
        return self.O[link] + self.e[link] * complex(*p)

    def v(self, link: int, P: complex) -> complex:
        """Velocity [m/s] of the point at ``P`` [m] moving with ``link``."""
        return self.v_O[link] + 1j * self.w[link] * (P - self.O[link])

    def a(self, link: int, P: complex) -> complex:
        """Acceleration [m/s²] of the point at ``P`` [m] moving with ``link``."""
        return self.a_O[link] + (1j * self.al[link] - self.w[link] ** 2) * (P - self.O[link])


class _Ledger:
    """Every comparison of a construction with the analytical route, of speeds (``"v"``) or accelerations (``"a"``).

    Each is measured against the largest value of its kind at the position: the named points', the links' ω (α)
    times the mechanism's size, and every analytical value compared (a pitch point that is no named point may be
    the only thing that moves).
    """

    def __init__(self, truth: _Truth):
        self.scale = {"v": truth.v_scale, "a": truth.a_scale}
        self.items: list[tuple[str, float, object]] = []

    def see(self, kind: str, gap: float, what, size: float = 0.0):
        """A difference ``gap`` of ``kind``; ``what(scale)`` says it; ``size``: the analytical value's magnitude."""
        self.items.append((kind, gap, what))
        if size > self.scale[kind]:
            self.scale[kind] = size

    def reason(self, route: str) -> str:
        worst, what = 0.0, None
        for kind, gap, say in self.items:
            scale = self.scale[kind]
            ratio = gap / scale if scale > 0 else (0.0 if gap == 0 else math.inf)
            if not ratio <= worst:  # nan counts as the worst
                worst, what = ratio, (say, scale)
        if worst <= AGREEMENT:
            return ""
        say, scale = what
        return f"the {route} and the analytical route disagree: {say(scale)}"


def _vec(z: complex, unit: str, scale: float) -> str:
    return polar_text((z.real, z.imag), unit, scale=scale, minus="-")


def _rate(x: float, unit: str) -> str:
    return f"{num(x, 6, minus='-')} {unit}"


def _where(truth: _Truth, mech, link: int, point) -> complex:
    """Where a link's named point is [m] (``point`` None: its centre of mass), placed as the polygons place it."""
    body = mech.link(link)
    return truth.at(link, body.G if point is None else body.point(point))


_UNIT = {"v": "m/s", "a": "m/s²"}


def _compare(ledger: _Ledger, kind: str, z, t: complex, name: str):
    """A vector ``z`` of the construction against the analytical ``t``, both [m/s] or [m/s²]."""
    z = complex(*z)
    unit = _UNIT[kind]
    ledger.see(kind, abs(z - t), lambda scale: f"{name} is {_vec(z, unit, scale)} graphically, "
               f"{_vec(t, unit, scale)} analytically", abs(t))


def _motion_values(ledger: _Ledger, truth: _Truth, mech, omega: dict, velocity: dict, v_G: dict, alpha=None,
                   acceleration=None, a_G=None):
    """Compare a construction's ω (α) of each link and the velocity (acceleration) of each named point and G."""
    size = truth.size
    for kind, table, true, symbol, unit in (("v", omega, truth.w, "ω", "rad/s"),
                                            ("a", alpha or {}, truth.al, "α", "rad/s²")):
        for link, x in table.items():
            t = true[link]
            ledger.see(kind, abs(x - t) * size, lambda scale, link=link, x=x, t=t, symbol=symbol, unit=unit:
                       f"{symbol}{link} is {_rate(x, unit)} graphically, {_rate(t, unit)} analytically")
    for kind, table, rule in (("v", velocity, truth.v), ("a", acceleration or {}, truth.a)):
        for (link, point), value in table.items():
            _compare(ledger, kind, value, rule(link, _where(truth, mech, link, point)), f"{kind}_{point} of link {link}")
    for kind, table, rule in (("v", v_G, truth.v), ("a", a_G or {}, truth.a)):
        for link, value in table.items():
            _compare(ledger, kind, value, rule(link, _where(truth, mech, link, None)), f"{kind}_G{link}")


def motion_disagreement(kin, i: int, c, where: dict, coriolis: dict) -> str:
    """Why the velocity and acceleration polygons ``c`` of position ``i`` disagree with ``kin`` ('' if they agree).

    Parameters
    ----------
    kin : graphkin.kinematics.Kinematics
        The analytical kinematics (its derived motion: values a problem gives off its drawing are not the route).
    i : int
        The position's index.
    c : graphkin.graphical.MotionConstruction
        The polygons built from the input motion.
    where : dict of str to (int, complex)
        Each image point of both polygons, by its name (``"b"``, ``"g3′"``): the link it is a point of and where
        that point is [m]. The pole (``"o"``, ``"o′"``) is the frame's.
    coriolis : dict of str to (int, int, int, complex)
        Each Coriolis vector by its name: the guide's link m, the sliding link k, the link b whose point the
        relative velocity is measured from, and the point X [m]; it must equal 2 ω_m × (v_X on k − v_X on b).

    Returns
    -------
    str
        '' where every value agrees to :data:`AGREEMENT` of its scale; else the reason, naming the worst quantity
        and both values.
    """
    truth = _Truth(kin, i)
    ledger = _Ledger(truth)
    _motion_values(ledger, truth, kin.mechanism, c.omega, c.velocity, c.v_G, c.alpha, c.acceleration, c.a_G)
    for kind, polygon, rule in (("v", "velocity", truth.v), ("a", "acceleration", truth.a)):
        for name, value in c.images[polygon].items():
            if name.rstrip("′") == "o":  # the pole: the frame's image
                link, P = truth.frame, 0j
            elif name in where:
                link, P = where[name]
            else:  # an image a construction added without saying whose point it is cannot be checked: not shown
                ledger.see(kind, math.inf, lambda scale, name=name, polygon=polygon:
                           f"the {polygon} polygon's image {name} is no point of a link the check knows")
                continue
            _compare(ledger, kind, value, rule(link, P), f"the {polygon} image {name}")
    for vector in c.vectors("acceleration"):
        if vector.name in coriolis:
            m, k, b, X = coriolis[vector.name]
            _compare(ledger, "a", vector.vector, 2j * truth.w[m] * (truth.v(k, X) - truth.v(b, X)), vector.name)
    return ledger.reason("velocity and acceleration polygons")


def centres_disagreement(kin, i: int, ic) -> str:
    """Why the instant centres ``ic`` of position ``i`` disagree with ``kin`` ('' if they agree).

    A centre I_ab found at P must be where links a and b have the same velocity: the relative velocity
    v_b(P) − v_a(P) [m/s] is compared with the position's largest speed. A centre at infinity in the direction u
    must leave a and b only translating relative to each other (ω_a = ω_b), and across u (the relative velocity
    perpendicular to u). The ω and the velocities the centres give are compared as the polygons' are.
    """
    truth = _Truth(kin, i)
    ledger = _Ledger(truth)
    for (a, b), P in ic.centres.items():  # keyed by the links' own numbers, the frame's included
        z = complex(*P)
        gap = abs(truth.v(b, z) - truth.v(a, z))
        ledger.see("v", gap, lambda scale, a=a, b=b, z=z, gap=gap: f"I{a}{b} at ({num(z.real * 1e3, 6, minus='-')}, "
                   f"{num(z.imag * 1e3, 6, minus='-')}) mm moves at {num(gap, 6)} m/s relative to link {a} as a point "
                   f"of link {b} (an instant centre has no relative velocity)")
    for (a, b), u in ic.at_infinity.items():
        dw = truth.w[b] - truth.w[a]
        ledger.see("v", abs(dw) * truth.size, lambda scale, a=a, b=b, dw=dw: f"I{a}{b} is at infinity graphically, "
                   f"but links {a} and {b} turn relative to each other at {_rate(dw, 'rad/s')} analytically")
        d = truth.v(b, 0j) - truth.v(a, 0j)  # where ω_a = ω_b, the same at every point
        along = abs(d.real * u[0] + d.imag * u[1])
        ledger.see("v", along, lambda scale, a=a, b=b, along=along: f"I{a}{b} is at infinity across the sliding "
                   f"graphically, but links {a} and {b} move {num(along, 6)} m/s apart along it analytically")
    _motion_values(ledger, truth, kin.mechanism, ic.omega, ic.velocity, ic.v_G)
    return ledger.reason("instant centres")


def derived(kin, i: int):
    """The kinematics the motion constructions draw and are checked against at position ``i``: ``(kin, i)``.

    A problem may give values measured off its book's drawing (a link's angle θ, α, a_G: ``[given]``); the force
    route uses them, but they are not a motion the input produces (an angle read to the degree leaves a pin slightly
    apart on its two links), so no analytical route shares them. The polygons and instant centres are constructed
    from the input motion alone: from the position's own kinematics, solved again without the given values.
    """
    if not kin.given:
        return kin, i
    return solve_kinematics(kin.mechanism, kin.q[i:i + 1], kin.q_dot[i:i + 1], kin.q_ddot[i:i + 1]), 0
