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
import weakref
from dataclasses import replace

import numpy as np

from graphkin.kinematics import solve_kinematics
from graphkin.kinematics.plan import plan_of
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
class _Shape:
    """What the guard reads of a mechanism at every position, made once per mechanism (its plan's cache)."""

    def __init__(self, mech):
        self.size = mechanism_size(mech)
        self.frame = mech.frame
        self.moving = tuple(mech.moving)
        self.points = plan_of(mech).points  # (link, name): the point in its link's own frame [m], complex
        self.G = {link.number: complex(*link.G) for link in mech.links}
        self.bodies = {n: [self.points[n, name] for name in mech.link(n).points] + [self.G[n]] for n in self.moving}


def _shape(mech) -> _Shape:
    compiled = plan_of(mech).compiled
    shape = compiled.get("guard")
    if shape is None:
        shape = compiled["guard"] = _Shape(mech)
    return shape


class _Truth:
    """The analytical motion of position ``i``: any point's velocity and acceleration as a point of any link.

    ``motion[link]`` is ``(O, e, v_O, a_O, iω, iα − ω²)``: the link's origin and direction [m, unit complex], its
    origin's velocity and acceleration, and the factors that carry them to a point r = P − O away (v = v_O + iω r,
    a = a_O + (iα − ω²) r).
    """

    def __init__(self, kin, i: int):
        shape = self.shape = _shape(kin.mechanism)
        self.frame, self.size = shape.frame, shape.size
        self.w = {shape.frame: 0.0}
        self.al = {shape.frame: 0.0}
        motion = self.motion = {shape.frame: (0j, 1 + 0j, 0j, 0j, 0j, 0j)}
        # The scales: the fastest named point or centre of mass, or a link's ω (α) over the mechanism's size.
        v_top, a_top = 0.0, 0.0
        for n in shape.moving:
            # .item(i): Python numbers straight from the arrays, without a numpy scalar in between.
            w, al = float(kin.omega[n].item(i)), float(kin.alpha[n].item(i))
            e, v_O, a_O = complex(kin.e[n].item(i)), complex(kin.v_O[n].item(i)), complex(kin.a_O[n].item(i))
            iw, turn = 1j * w, 1j * al - w * w
            self.w[n], self.al[n] = w, al
            motion[n] = (complex(kin.O[n].item(i)), e, v_O, a_O, iw, turn)
            v_top = max([v_top, abs(w) * self.size] + [abs(v_O + iw * e * p) for p in shape.bodies[n]])
            a_top = max([a_top, abs(al) * self.size] + [abs(a_O + turn * e * p) for p in shape.bodies[n]])
        self.v_scale, self.a_scale = v_top, a_top

    def v(self, link: int, P: complex) -> complex:
        """Velocity [m/s] of the point at ``P`` [m] moving with ``link``."""
        O, _, v_O, _, iw, _ = self.motion[link]
        return v_O + iw * (P - O)

    def a(self, link: int, P: complex) -> complex:
        """Acceleration [m/s²] of the point at ``P`` [m] moving with ``link``."""
        O, _, _, a_O, _, turn = self.motion[link]
        return a_O + turn * (P - O)


_LAST: list = []
"""The last few truths made, ``(weakref to the kinematics, i, truth)``: the polygons and the instant centres of one
position (``solve --json --motion-polygons``, a handout) share theirs."""


def _truth(kin, i: int) -> _Truth:
    for ref, at, truth in _LAST:
        if at == i and ref() is kin:
            return truth
    truth = _Truth(kin, i)
    _LAST[:] = [(weakref.ref(kin), i, truth)] + _LAST[:3]
    return truth


class _Ledger:
    """Every comparison of a construction with the analytical route, of speeds (kind 0) or accelerations (kind 1).

    Each difference is measured against the largest value of its kind at the position: the named points', the
    links' ω (α) times the mechanism's size, and every analytical value compared (a pitch point that is no named
    point may be the only thing that moves). Only the worst is put in words. Plain Python: a position has a few
    dozen values, where numpy's arrays cost more to make than the arithmetic.
    """

    __slots__ = ("scale", "items")

    def __init__(self, truth: _Truth):
        self.scale = [truth.v_scale, truth.a_scale]
        self.items: list[tuple] = []  # (kind, gap, z, t, say): the words made for the worst only

    def see(self, kind: int, z: complex, t: complex, *say):
        """The construction's value ``z`` against the analytical ``t`` [m/s or m/s²]; ``say``: a function and its
        first arguments, to put the difference in words."""
        size = abs(t)
        if size > self.scale[kind]:
            self.scale[kind] = size
        self.items.append((kind, abs(z - t), z, t, say))

    def reason(self, route: str) -> str:
        worst, found = 0.0, None
        for item in self.items:
            kind, gap = item[0], item[1]
            scale = self.scale[kind]
            ratio = gap / scale if scale > 0 else (0.0 if gap == 0 else math.inf)
            if not ratio <= worst:  # nan counts as the worst
                worst, found = ratio, item
        if worst <= AGREEMENT:
            return ""
        kind, _, z, t, (say, *args) = found
        return f"the {route} and the analytical route disagree: {say(*args, z, t, self.scale[kind])}"


_UNIT = ("m/s", "m/s²")


def _vec(z: complex, unit: str, scale: float) -> str:
    return polar_text((z.real, z.imag), unit, scale=scale, minus="-")


def _rate(x: float, unit: str) -> str:
    return f"{num(x, 6, minus='-')} {unit}"


def _vectors(name: str, kind: int, z: complex, t: complex, scale: float) -> str:
    unit = _UNIT[kind]
    return f"{name} is {_vec(z, unit, scale)} graphically, {_vec(t, unit, scale)} analytically"


def _point(kind: int, link: int, point: str | None, z: complex, t: complex, scale: float) -> str:
    name = f"{'va'[kind]}_G{link}" if point is None else f"{'va'[kind]}_{point} of link {link}"
    return _vectors(name, kind, z, t, scale)


def _rates(symbol: str, link: int, unit: str, size: float, z: complex, t: complex, scale: float) -> str:
    return f"{symbol}{link} is {_rate(z.real / size, unit)} graphically, {_rate(t.real / size, unit)} analytically"


def _motion_values(ledger: _Ledger, truth: _Truth, omega: dict, velocity: dict, v_G: dict, alpha=None,
                   acceleration=None, a_G=None):
    """Compare a construction's ω (α) of each link and the velocity (acceleration) of each named point and G."""
    size, motion, shape = truth.size, truth.motion, truth.shape
    see = ledger.see
    # ω and α times the mechanism's size: measured as the speed (acceleration) they give its farthest point.
    for kind, table, true, symbol, unit in ((0, omega, truth.w, "ω", "rad/s"), (1, alpha or {}, truth.al, "α", "rad/s²")):
        for link, x in table.items():
            see(kind, complex(x * size), complex(true[link] * size), _rates, symbol, link, unit, size)
    # A point r = e p from its link's origin (p in the link's own frame): v = v_O + iω r, a = a_O + (iα − ω²) r.
    points, G = shape.points, shape.G
    for (link, point), (x, y) in velocity.items():
        _, e, v_O, _, iw, _ = motion[link]
        see(0, complex(x, y), v_O + iw * e * points[link, point], _point, 0, link, point)
    for (link, point), (x, y) in (acceleration or {}).items():
        _, e, _, a_O, _, turn = motion[link]
        see(1, complex(x, y), a_O + turn * e * points[link, point], _point, 1, link, point)
    for link, (x, y) in v_G.items():
        _, e, v_O, _, iw, _ = motion[link]
        see(0, complex(x, y), v_O + iw * e * G[link], _point, 0, link, None)
    for link, (x, y) in (a_G or {}).items():
        _, e, _, a_O, _, turn = motion[link]
        see(1, complex(x, y), a_O + turn * e * G[link], _point, 1, link, None)


def _image(polygon: str, name: str, kind: int, z: complex, t: complex, scale: float) -> str:
    return _vectors(f"the {polygon} image {name}", kind, z, t, scale)


def _unknown_image(name: str, polygon: str, z, t, scale) -> str:
    return f"the {polygon} polygon's image {name} is no point of a link the check knows"


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
    truth = _truth(kin, i)
    ledger = _Ledger(truth)
    _motion_values(ledger, truth, c.omega, c.velocity, c.v_G, c.alpha, c.acceleration, c.a_G)
    see, motion = ledger.see, truth.motion
    for kind, polygon in ((0, "velocity"), (1, "acceleration")):
        for name, (x, y) in c.images[polygon].items():
            if name in where:
                link, P = where[name]
                O, _, v_O, a_O, iw, turn = motion[link]
                see(kind, complex(x, y), a_O + turn * (P - O) if kind else v_O + iw * (P - O), _image, polygon, name,
                    kind)
            elif name not in ("o", "o′"):  # the pole is the frame's image: 0
                # An image a construction added without saying whose point it is cannot be checked: not shown.
                see(kind, complex(math.inf), 0j, _unknown_image, name, polygon)
            else:
                see(kind, complex(x, y), 0j, _image, polygon, name, kind)
    for vector in c.vectors("acceleration") if coriolis else ():
        if vector.name in coriolis:
            m, k, b, X = coriolis[vector.name]
            ledger.see(1, complex(*vector.vector), 2j * truth.w[m] * (truth.v(k, X) - truth.v(b, X)), _vectors,
                       vector.name, 1)
    return ledger.reason("velocity and acceleration polygons")


def centres_disagreement(kin, i: int, ic) -> str:
    """Why the instant centres ``ic`` of position ``i`` disagree with ``kin`` ('' if they agree).

    A centre I_ab found at P must be where links a and b have the same velocity: the relative velocity
    v_b(P) − v_a(P) [m/s] is compared with the position's largest speed. A centre at infinity in the direction u
    must leave a and b only translating relative to each other (ω_a = ω_b), and across u (the relative velocity
    perpendicular to u). The ω and the velocities the centres give are compared as the polygons' are.
    """
    truth = _truth(kin, i)
    ledger = _Ledger(truth)
    for (a, b), (x, y) in ic.centres.items():  # keyed by the links' own numbers, the frame's included
        P = complex(x, y)
        ledger.see(0, truth.v(b, P) - truth.v(a, P), 0j, _moving_centre, a, b, P)
    for (a, b), u in ic.at_infinity.items():
        dw = truth.w[b] - truth.w[a]
        ledger.see(0, complex(dw * truth.size), 0j, _turning_apart, a, b, truth.size)
        d = truth.v(b, 0j) - truth.v(a, 0j)  # where ω_a = ω_b, the same at every point
        ledger.see(0, complex(d.real * u[0] + d.imag * u[1]), 0j, _sliding_apart, a, b)
    _motion_values(ledger, truth, ic.omega, ic.velocity, ic.v_G)
    return ledger.reason("instant centres")


def _moving_centre(a: int, b: int, P: complex, z, t, scale) -> str:
    return (f"I{a}{b} at ({num(P.real * 1e3, 6, minus='-')}, {num(P.imag * 1e3, 6, minus='-')}) mm moves at "
            f"{num(abs(z), 6)} m/s relative to link {a} as a point of link {b} (an instant centre has no relative "
            "velocity)")


def _turning_apart(a: int, b: int, size: float, z, t, scale) -> str:
    return (f"I{a}{b} is at infinity graphically, but links {a} and {b} turn relative to each other at "
            f"{_rate(z.real / size, 'rad/s')} analytically")


def _sliding_apart(a: int, b: int, z, t, scale) -> str:
    return (f"I{a}{b} is at infinity across the sliding graphically, but links {a} and {b} move "
            f"{num(abs(z), 6)} m/s apart along it analytically")


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
