"""Hypothesis strategies: random, assemblable planar linkages with random loads.

Every strategy draws a :class:`Case` -- ``(mechanism, q, q_dot, q_ddot)`` --
where ``q`` holds one to four input positions (crank angle [rad] or slider
position [m]) at which the linkage assembles with a margin from dead points,
and ``q_dot``, ``q_ddot`` hold a different input rate for each position (so a
solver that mixed positions up would be caught).

Geometry is *constructed* to assemble (Grashof crank-rockers, couplers longer
than the crank's reach from the guide, dyads hung on a point whose path is
known, ...), so ``assume`` rejects almost nothing. On top of that, positions are
chosen from a sweep of the input where every dyad keeps a transmission margin
(:func:`margin` ≥ :data:`MARGIN`), so that the force equations are
well-conditioned and 1e-9 relative tolerances are meaningful.

Everything else is random too: the overall size (3 cm to 5 m links), where
each link's own frame sits (a pin is rarely at a link's origin and a bar is
rarely along its x-axis), masses (zero allowed), centres of mass, moments of
inertia, external point forces and torques (sometimes acting over part of the
cycle only), gravity, the input's rates (either sense: clockwise input too),
the assembly branch σ = ±1, Coulomb friction at sliders, which gear of a mesh
is listed first, and the numbering of the links (the frame 1 or 0; the moving
links, half the time, in a random order).

Families (keys of :data:`families`):

``fourbar``                 Grashof crank-rocker, open or crossed (RRR dyad)
``slider_crank``            offset slider-crank, guide at any angle (RRP)
``double_slider``           two sliders on non-parallel guides, slider-driven
``inverted_slider_crank``   block on the crank pin slides on a rocker, a turning guide (RPR)
``scotch_yoke``             block on the crank pin in a slotted yoke (RPP)
``watt2``                   Watt II: two four-bars in series sharing the rocker
``stephenson3``             Stephenson III: RRR dyad from a coupler point to the frame
``quick_return``            crank-shaper: RPR (a turning guide), then RRP from the rocker to a ram
``gear_pair``               two gears pivoted on the frame, load torque on the driven one
``epicyclic``               a planet on the driving arm, meshing with a fixed sun or annulus (and a sun on the arm's axis)
``annulus``                 an annulus found from its pinion: on the frame, about a driving arm's axis, or on the arm
``compound_planet``         a planet of two gears on the driving arm, meshing with a fixed gear and a turning one
``driven_arm``              a planet on an arm that is not the driver: a gear turned by a pinion, or a four-bar's rocker
``piston_driven``           a slider-crank driven by its slider (RRR), the crank half the time a planet's arm

Graphkin also accepts, and no family draws: a PRP dyad (tests/handout has one). It does not accept an arm found
from two meshes of its planet (the sun driving, the annulus held, the arm the output: Khurmi's trains are solved
with the arm as the driver and the sun's torque as a load), so no family draws that.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from typing import Mapping, NamedTuple

import numpy as np
from hypothesis import assume
from hypothesis import strategies as st

from graphkin.kinematics import Dyad, decompose, solve_kinematics
from graphkin.model import (
    FRAME,
    Active,
    Driver,
    GearMesh,
    Link,
    Mechanism,
    PointForce,
    Prismatic,
    Revolute,
    SpringForce,
    Torque,
    spring,
)

TWO_PI = 2.0 * math.pi

MARGIN = 0.2
"""Least sine of the transmission angle of every dyad at a drawn position
(friction included: the tilted reaction direction is used)."""

GRID = 720
"""Number of input positions swept to find where the linkage is well conditioned."""


class Case(NamedTuple):
    """A drawn example: unpacks as ``mechanism, q, q_dot, q_ddot``.

    Its repr is the Python that rebuilds it, which is what hypothesis prints for a failing (shrunk) example:
    paste it into a test after ``from tests.strategies import *`` (which brings ``np``, ``Case`` and the classes
    of :mod:`graphkin.model`).
    """

    mechanism: Mechanism
    q: np.ndarray
    q_dot: np.ndarray
    q_ddot: np.ndarray

    def __repr__(self):
        m = self.mechanism
        lines = ["Case(", "    mechanism=Mechanism("]
        for name in ("links", "joints", "loads"):
            lines += [f"        {name}=[", *(f"            {_code(x)}," for x in getattr(m, name)), "        ],"]
        lines += [f"        {f.name}={_code(getattr(m, f.name))}," for f in dataclasses.fields(m)
                  if f.name not in ("links", "joints", "loads") and not _default(m, f)]
        lines.append("    ),")
        lines += [f"    {name}={_code(getattr(self, name))}," for name in ("q", "q_dot", "q_ddot")]
        return "\n".join([*lines, ")"])

    def _repr_pretty_(self, p, cycle):
        """What hypothesis's printer calls: the same Python as the repr."""
        p.text(repr(self))


def _default(obj, f) -> bool:
    """Whether field ``f`` of dataclass ``obj`` holds its default (the rebuilding code leaves it out)."""
    default = f.default if f.default_factory is dataclasses.MISSING else f.default_factory()
    value = getattr(obj, f.name)
    if default is dataclasses.MISSING or isinstance(value, np.ndarray):
        return False
    value = dict(value) if isinstance(value, Mapping) else value
    return type(value) is type(default) and value == default


def _code(value) -> str:
    """Python source for a value of a case: dataclasses by their fields, floats exactly (repr round-trips)."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        args = (f"{f.name}={_code(getattr(value, f.name))}" for f in dataclasses.fields(value)
                if f.init and not _default(value, f))
        return f"{type(value).__name__}({', '.join(args)})"
    if isinstance(value, np.ndarray):
        return f"np.array({_code(value.tolist())})"
    if isinstance(value, Mapping):
        return "{" + ", ".join(f"{_code(k)}: {_code(v)}" for k, v in value.items()) + "}"
    if isinstance(value, tuple):
        return "(" + ", ".join(map(_code, value)) + (",)" if len(value) == 1 else ")")
    if isinstance(value, list):
        return "[" + ", ".join(map(_code, value)) + "]"
    if isinstance(value, (bool, np.bool_)):
        return repr(bool(value))
    if isinstance(value, (int, np.integer)):
        return repr(int(value))
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    return repr(value)


# --------------------------------------------------------------------------
# small geometry helpers (plain numpy, independent of graphkin)
# --------------------------------------------------------------------------
def _rot(v, a):
    c, s = math.cos(a), math.sin(a)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])


def _u(a):
    return np.array([math.cos(a), math.sin(a)])


def _n(a):
    return np.array([-math.sin(a), math.cos(a)])


def _t(p):
    return (float(p[0]), float(p[1]))


@functools.lru_cache(maxsize=4096)  # ranges drawn from earlier draws make new keys: bounded
def _floats(lo, hi):
    """Floats in [lo, hi]; magnitudes below 1e-6 of the range are flushed to 0.

    Values like 1e-250 that hypothesis likes to try are not physical and only
    test floating-point underflow (products of two of them vanish). One strategy per range, made once: hypothesis
    checks a new strategy on its first draw, and the families draw thousands of these.
    """
    tiny = 1e-6 * max(abs(lo), abs(hi))
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False).map(lambda x: 0.0 if abs(x) < tiny else x)


_angles = _floats(-math.pi, math.pi)


def _signed(draw, lo, hi):
    """A number with magnitude in [lo, hi] and a random sign."""
    return draw(_floats(lo, hi)) * draw(st.sampled_from((-1.0, 1.0)))


# --------------------------------------------------------------------------
# links with random frames and mass properties
# --------------------------------------------------------------------------
def _mass(draw, pts, scale):
    """(mass, G, I_G) in the same coordinates as ``pts``: G near the pins."""
    mass = draw(st.one_of(st.just(0.0), _floats(0.05, 20.0)))
    centre = np.mean(np.array(list(pts.values())), axis=0)
    G = centre + np.array([draw(_floats(-0.6, 0.6)), draw(_floats(-0.6, 0.6))]) * scale
    k = draw(st.one_of(st.just(0.0), _floats(0.0, 1.0))) * scale
    return mass, G, mass * k * k


def _link(draw, number, natural, scale, name=""):
    """A moving link from points given in a design ("natural") frame.

    The link's own frame is a random rigid transform of the design frame,
    and a load point ``P<number>`` is added somewhere near the link.
    """
    pts = {k: np.asarray(v, dtype=float) for k, v in natural.items()}
    centre = np.mean(np.array(list(pts.values())), axis=0)
    pts[f"P{number}"] = centre + np.array([draw(_floats(-1, 1)), draw(_floats(-1, 1))]) * scale
    mass, G, I_G = _mass(draw, pts, scale)
    beta = draw(_angles)
    shift = np.array([draw(_floats(-1, 1)), draw(_floats(-1, 1))]) * scale

    def local(p):
        return _t(_rot(np.asarray(p) - shift, -beta))

    return Link(number, {k: local(v) for k, v in pts.items()}, mass=mass, G=local(G), I_G=I_G, name=name)


def _local_link(draw, number, pts, scale, name=""):
    """A moving link whose points are already in its own frame (sliders, blocks)."""
    pts = {k: np.asarray(v, dtype=float) for k, v in pts.items()}
    centre = np.mean(np.array(list(pts.values())), axis=0)
    pts[f"P{number}"] = centre + np.array([draw(_floats(-1, 1)), draw(_floats(-1, 1))]) * scale
    mass, G, I_G = _mass(draw, pts, scale)
    return Link(number, {k: _t(v) for k, v in pts.items()}, mass=mass, G=_t(G), I_G=I_G, name=name)


def _point(draw, scale, r=1.0):
    return np.array([draw(_floats(-r, r)), draw(_floats(-r, r))]) * scale


def _mu(draw, friction, hi=0.35):
    """Friction coefficient: random (None), forced positive (True) or zero (False)."""
    if friction is False:
        return 0.0
    if friction is True:
        return draw(_floats(0.05, hi))
    return draw(st.one_of(st.just(0.0), _floats(0.05, hi)))


# --------------------------------------------------------------------------
# loads, gravity, rates
# --------------------------------------------------------------------------
def _loads(draw, moving, scale, periodic, q_range, links=()):
    loads = []
    for i in range(draw(st.integers(0, 3))):
        link = draw(st.sampled_from(moving))
        if links and draw(st.integers(0, 3)) == 0:  # a linear spring from P{link} to a point of another link
            own = next(lk for lk in links if lk.number == link).points
            # Not to a pin this link shares (the load point may shrink onto it: a spring of no length has no line).
            ends = [(lk, p) for lk in links if lk.number != link for p in sorted(lk.points) if p not in own]
            if not ends:
                continue
            other, anchor = draw(st.sampled_from(ends))
            rate = draw(_floats(0.0, 2000.0)) / scale
            free = draw(st.one_of(st.just(0.0), _floats(0.05, 2.0))) * scale  # graphkin refuses L0 below 1 µm
            loads += spring((link, other.number), (f"P{link}", anchor), rate, free, frame=FRAME, name=f"S{i}")
            continue
        active = None
        if draw(st.integers(0, 3)) == 0:  # sometimes over part of the cycle only
            lo, hi = q_range
            a = draw(_floats(lo, hi))
            b = draw(_floats(lo, hi))
            active = Active(a, b) if periodic else Active(min(a, b), max(a, b), periodic=False)
        if draw(st.booleans()):
            f = (draw(_floats(-500, 500)), draw(_floats(-500, 500)))
            loads.append(PointForce(link, f"P{link}", f, active=active, name=f"F{i}"))
        else:
            loads.append(Torque(link, draw(_floats(-200, 200)) * scale, active=active, name=f"T{i}"))
    return loads


def _gravity(draw):
    return draw(st.one_of(st.just(0.0), st.just(9.81), _floats(0.0, 20.0)))


def _length_scale(mech: Mechanism) -> float:
    """Largest distance between two points of one link: the mechanism's size."""
    size = 0.0
    for link in mech.links:
        P = np.array(list(link.points.values()) or [(0.0, 0.0)])
        size = max(size, float(np.max(np.hypot(*(P[:, None, :] - P[None, :, :]).transpose(2, 0, 1)))))
    return size


length_scale = _length_scale


# --------------------------------------------------------------------------
# conditioning of a position: transmission margin of every dyad
# --------------------------------------------------------------------------
def _joint_point(kin, joint, link):
    if isinstance(joint, Prismatic):
        return kin.position(joint.slider, joint.point)
    return kin.position(link, joint.point)


def _sin(a, b):
    """|sin| of the angle between vectors a and b (rows)."""
    den = np.hypot(a[:, 0], a[:, 1]) * np.hypot(b[:, 0], b[:, 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.abs(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]) / den


def _reaction_dirs(kin, joint):
    """Possible directions of a prismatic reaction: the normal, tilted by ±atan μ."""
    u = kin.guide_direction(joint)
    n = np.stack([-u[:, 1], u[:, 0]], -1)
    if not joint.mu:
        return [n]
    return [n + s * joint.mu * u for s in (1.0, -1.0)]


def margin(kin) -> np.ndarray:
    """Least |sin| of a transmission angle over all dyads, per position.

    RRR: between the two links; RRP: between link j and the (friction-tilted)
    guide reaction; RPR: between the line of the two pins and that reaction;
    RPP/PRP: between the two guide reactions. Zero at a dead point (or where a
    friction pair would self-lock), 1 at the best transmission.
    """
    mech = kin.mechanism
    out = np.ones(kin.n)
    for g in decompose(mech):
        if not isinstance(g, Dyad):
            continue
        X1 = _joint_point(kin, g.J1, g.j)
        X2 = _joint_point(kin, g.J2, g.k)
        X3 = _joint_point(kin, g.J3, g.k)
        t = g.type
        if t == "RRR":
            m = _sin(X2 - X1, X3 - X2)
        elif t == "RRP":
            m = np.min([_sin(X1 - X2, w) for w in _reaction_dirs(kin, g.J3)], axis=0)
        elif t == "RPR":
            m = np.min([_sin(X1 - X3, w) for w in _reaction_dirs(kin, g.J2)], axis=0)
        else:
            Ja, Jb = (g.J2, g.J3) if t == "RPP" else (g.J1, g.J3)
            m = np.min([_sin(a, b) for a in _reaction_dirs(kin, Ja) for b in _reaction_dirs(kin, Jb)], axis=0)
        out = np.minimum(out, np.where(np.isfinite(m), m, 0.0))
    return out


# --------------------------------------------------------------------------
# picking positions and rates
# --------------------------------------------------------------------------
def _rates(draw, n, slider, scale):
    if slider:
        v = st.one_of(st.just(0.0), _floats(-3.0, 3.0).map(lambda x: x * scale))
        a = _floats(-50.0, 50.0).map(lambda x: x * scale)
    else:
        v = st.one_of(st.just(0.0), _floats(-30.0, 30.0))
        a = _floats(-300.0, 300.0)
    q_dot = np.array([draw(v) for _ in range(n)])
    q_ddot = np.array([draw(a) for _ in range(n)])
    return q_dot, q_ddot


def _case(draw, mech, q_range, periodic, scale):
    """Draw 1–4 well-conditioned positions from a sweep of the input, and rates."""
    lo, hi = q_range
    grid = np.linspace(lo, hi, GRID, endpoint=not periodic)
    step = grid[1] - grid[0]
    kin = solve_kinematics(mech, grid)
    good = np.flatnonzero(kin.valid & (margin(kin) >= MARGIN))
    assume(len(good) > 0)
    n = draw(st.integers(1, 4))
    q = np.array([grid[draw(st.sampled_from(good))] + draw(_floats(-0.4, 0.4)) * step for _ in range(n)])
    if not periodic:
        q = np.clip(q, lo, hi)
    q_dot, q_ddot = _rates(draw, n, mech.driver.kind == "slider", scale)
    kin = solve_kinematics(mech, q)
    assume(kin.valid.all() and (margin(kin) >= 0.9 * MARGIN).all())
    for load in mech.loads:
        # A spring of some free length whose ends meet has no line: graphkin marks the position not valid (tested
        # in tests/bad_input); a random mechanism whose load point lands on the anchor is not the case to draw.
        if isinstance(load, SpringForce) and load.free_length and load.rate:
            gap = kin.z(load.anchor_link, load.anchor_point) - kin.z(load.link, load.point)
            assume(bool(np.all(np.abs(gap) > 1e-9 * scale)))
    return Case(mech, q, q_dot, q_ddot)


def _numbering(draw, moving):
    """A numbering of the links as books give it: the frame 1 or 0, the moving links from the next number up, in
    order or (half the time) in a random order.

    So every name follows the frame's number (``T12`` or ``T01``), the driver need not be the first moving link,
    and which link of a pair has the lower number (the sign convention of ``F_ij``, ``N``, ``C``) varies.
    """
    frame = draw(st.sampled_from((FRAME, 0)))
    numbers = list(range(frame + 1, frame + 9))
    if draw(st.booleans()):
        numbers = draw(st.permutations(numbers))
    return {FRAME: frame, **dict(zip(moving, numbers))}


def _relabel(mech: Mechanism, m) -> Mechanism:
    """The same mechanism with link n renumbered m[n] (the frame, link 1, too)."""
    links = [dataclasses.replace(l, number=m[l.number], points=dict(l.points)) for l in mech.links]
    joints = []
    for j in mech.joints:
        if isinstance(j, Prismatic):
            joints.append(dataclasses.replace(j, guide=m[j.guide], slider=m[j.slider]))
        else:
            joints.append(dataclasses.replace(j, links=tuple(m[i] for i in j.links)))
    loads = [dataclasses.replace(load, link=m[load.link], **({"anchor_link": m[load.anchor_link]}
                                                            if isinstance(load, SpringForce) else {}))
             for load in mech.loads]
    driver = Driver(m[mech.driver.link], mech.driver.kind)
    return Mechanism(links, joints, driver, loads, mech.gravity, dict(mech.assembly), mech.title, frame=m[FRAME])


def _finish(draw, links, joints, driver, assembly, q_range, periodic, scale, title, loads=(), numbering=None):
    moving = [l.number for l in links if l.number != FRAME]
    numbering = numbering or _numbering(draw, sorted(moving))
    mech = Mechanism(
        links,
        joints,
        driver,
        loads=[*_loads(draw, moving, scale, periodic, q_range, links), *loads],
        gravity=_gravity(draw),
        assembly=assembly,
        title=title,
    )
    return _case(draw, _relabel(mech, numbering), q_range, periodic, scale)


_scales = _floats(-1.5, 0.7).map(lambda e: 10.0**e)  # 3 cm ... 5 m
_sigma = st.sampled_from((1, -1))


# --------------------------------------------------------------------------
# building blocks
# --------------------------------------------------------------------------
def _grashof_lengths(draw):
    """Crank a2, coupler a3, rocker a4, frame a1 (unit scale) of a crank-rocker.

    The frame, coupler and rocker make a triangle with slack ≥ 0.3·min(a3, a4)
    and the crank is at most 0.8 of min(shortest, slack): Grashof with margin,
    so every crank angle assembles with transmission angle away from 0, 180°.
    """
    a3 = draw(_floats(0.5, 1.5))
    a4 = draw(_floats(0.5, 1.5))
    m = min(a3, a4)
    a1 = draw(_floats(abs(a3 - a4) + 0.3 * m, a3 + a4 - 0.3 * m))
    slack = a1 + a3 + a4 - 2 * max(a1, a3, a4)
    a2 = draw(_floats(0.15, 0.8)) * min(a1, a3, a4, slack)
    return a1, a2, a3, a4


def _fourbar_parts(draw, scale, coupler_extra=None, rocker_extra=None):
    """Frame points, links 2, 3, 4 and joints of a Grashof crank-rocker.

    ``coupler_extra`` / ``rocker_extra``: extra named points in the design
    frame of the coupler (A at 0, B on +x) or rocker (O4 at 0, B on +x).
    """
    a1, a2, a3, a4 = (x * scale for x in _grashof_lengths(draw))
    O2 = _point(draw, scale)
    O4 = O2 + a1 * _u(draw(_angles))
    crank = _link(draw, 2, {"O2": (0, 0), "A": (a2, 0)}, scale, "crank")
    coupler = _link(draw, 3, {"A": (0, 0), "B": (a3, 0), **(coupler_extra or {})}, scale, "coupler")
    rocker = _link(draw, 4, {"O4": (0, 0), "B": (a4, 0), **(rocker_extra or {})}, scale, "rocker")
    frame = {"O2": _t(O2), "O4": _t(O4)}
    joints = [Revolute((1, 2), "O2"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), Revolute((4, 1), "O4")]
    return frame, [crank, coupler, rocker], joints


def _extra_point(draw, scale):
    """A point for a ternary link, polar about the design origin, ≥ 17° off the bar (+x)."""
    return _t(draw(_floats(0.4, 1.5)) * scale * _u(_signed(draw, 0.3, math.pi)))


def _path(mech, link, point, periodic_range=(0.0, TWO_PI), n=360):
    """Path of a point over a full crank turn (the sub-linkage must assemble everywhere)."""
    kin = solve_kinematics(mech, np.linspace(*periodic_range, n, endpoint=False))
    assume(kin.valid.all())
    return kin.position(link, point)


def _hang_rrr(draw, path, scale):
    """Frame pivot and the two lengths of an RRR dyad driven by a point on ``path``.

    The pivot is put outside the path's bounding circle; the lengths make the
    triangle (|C − O|, a, b) non-degenerate for every C on the path.
    """
    centre = path.mean(axis=0)
    radius = float(np.max(np.hypot(*(path - centre).T)))
    O = centre + (radius + draw(_floats(0.3, 1.5)) * scale) * _u(draw(_angles))
    d = np.hypot(*(path - O).T)
    dmin, dmax = float(d.min()), float(d.max())
    S = dmax * (1 + draw(_floats(0.15, 0.6)))
    D = dmin * (1 - draw(_floats(0.15, 0.6)))
    a, b = (S + D) / 2, (S - D) / 2
    if draw(st.booleans()):
        a, b = b, a
    return O, a, b


def _slider(draw, number, guide_angle, line_point, scale, friction, through="S", guide=FRAME):
    """A slider on a frame guide whose pin named ``D`` runs on (line_point, guide_angle).

    The slider's point on the guide is offset from its pin, and its frame is
    rotated by a random ``slider_direction``; the frame's guide point is
    placed so that the pin's line is the one asked for.
    Returns (link, prismatic joint, frame point).
    """
    pin = _point(draw, scale, 0.5)
    q_pt = pin + (np.zeros(2) if draw(st.booleans()) else _point(draw, scale, 0.5))
    sd = draw(_angles)
    theta = guide_angle - sd
    S = line_point + _rot(q_pt - pin, theta) + draw(_floats(-1, 1)) * scale * _u(guide_angle)
    name = f"Q{number}"
    link = _local_link(draw, number, {"D": pin, name: q_pt}, scale, "slider")
    joint = Prismatic(guide, number, name, through, guide_angle, sd, mu=_mu(draw, friction))
    return link, joint, S


def _rename(link: Link, old: str, new: str) -> Link:
    pts = {(new if k == old else k): v for k, v in link.points.items()}
    return Link(link.number, pts, link.mass, link.G, link.I_G, link.name)


# --------------------------------------------------------------------------
# the families
# --------------------------------------------------------------------------
@st.composite
def fourbar(draw, friction=None):
    scale = draw(_scales)
    frame, moving, joints = _fourbar_parts(draw, scale, coupler_extra={"C": _extra_point(draw, scale)})
    links = [Link(1, frame), *moving]
    return _finish(draw, links, joints, Driver(2), {"B": draw(_sigma)}, (0.0, TWO_PI), True, scale, "four-bar")


@st.composite
def slider_crank(draw, friction=None):
    """Offset slider-crank: crank r, coupler l ≥ 1.4 (r + |e|), guide at any angle."""
    scale = draw(_scales)
    r = draw(_floats(0.2, 1.0)) * scale
    e = r * draw(_floats(-0.8, 0.8))
    l = (r + abs(e)) * draw(_floats(1.4, 3.0))
    O2 = _point(draw, scale)
    phi = draw(_angles)
    crank = _link(draw, 2, {"O2": (0, 0), "A": (r, 0)}, scale, "crank")
    coupler = _link(draw, 3, {"A": (0, 0), "B": (l, 0)}, scale, "coupler")
    slider, guide, S = _slider(draw, 4, phi, O2 + e * _n(phi), scale, friction)
    slider = _rename(slider, "D", "B")
    links = [Link(1, {"O2": _t(O2), "S": _t(S)}), crank, coupler, slider]
    joints = [Revolute((1, 2), "O2"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), guide]
    return _finish(draw, links, joints, Driver(2), {"B": draw(_sigma)}, (0.0, TWO_PI), True, scale, "slider-crank")


@st.composite
def double_slider(draw, friction=None):
    """Sliders 2 and 4 on non-parallel frame guides, joined by coupler 3; 2 drives."""
    scale = draw(_scales)
    L = draw(_floats(0.3, 1.5)) * scale
    phi1 = draw(_angles)
    delta = _signed(draw, 0.3, math.pi - 0.3)
    phi2 = phi1 + delta
    C = _point(draw, scale)
    s_max = 0.8 * L / abs(math.sin(delta))
    # Slider 2: its pin A runs on the line through C along phi1.
    s2, g2, S2 = _slider(draw, 2, phi1, C, scale, friction, through="S2")
    s4, g4, S4 = _slider(draw, 4, phi2, C, scale, friction, through="S4")
    s2, s4 = _rename(s2, "D", "A"), _rename(s4, "D", "B")
    # q is the slider point's position from S2; the pin A is at C + (q − t) u1.
    A_loc, Q_loc = np.array(s2.point("A")), np.array(s2.point(g2.point))
    w2 = _rot(Q_loc - A_loc, phi1 - g2.slider_direction)
    t = float(np.dot(S2 - C - w2, _u(phi1)))  # S2 = C + w2 + t u1
    q_range = (-t - s_max, -t + s_max)
    coupler = _link(draw, 3, {"A": (0, 0), "B": (L, 0)}, scale, "coupler")
    links = [Link(1, {"S2": _t(S2), "S4": _t(S4)}), s2, coupler, s4]
    joints = [g2, Revolute((2, 3), "A"), Revolute((3, 4), "B"), g4]
    return _finish(draw, links, joints, Driver(2, "slider"), {"B": draw(_sigma)}, q_range, False, scale, "double slider")


def _rpr(draw, crank_r, pivot_dist, scale, friction, extra_rocker=None):
    """Crank 2, block 3 on the crank pin A, rocker 4 pivoted at O4: an RPR dyad.

    Which of block and rocker carries the guide is random; the guide line
    (with the slider point's offset) passes at a distance |e| ≤ 0.5 |d − r|
    from the line of the pins, so |A − O4| ≥ |d − r| > |e| everywhere.
    """
    O2 = _point(draw, scale)
    O4 = O2 + pivot_dist * _u(draw(_angles))
    crank = _link(draw, 2, {"O2": (0, 0), "A": (crank_r, 0)}, scale, "crank")
    e = draw(_floats(-0.5, 0.5)) * abs(pivot_dist - crank_r)
    block_guides = draw(st.booleans())
    (gn, gpin), (sn, spin) = ((3, "A"), (4, "O4")) if block_guides else ((4, "O4"), (3, "A"))
    g_pin, s_pin = _point(draw, scale, 0.5), _point(draw, scale, 0.5)
    direction, sd = draw(_angles), draw(_angles)
    a_g = _point(draw, scale, 0.7)
    a_s = np.array([draw(_floats(-0.7, 0.7)) * scale, a_g[1] - e])
    through = g_pin + _rot(a_g, direction)
    spoint = s_pin + _rot(a_s, sd)
    pts = {gn: {gpin: g_pin, f"T{gn}": through}, sn: {spin: s_pin, f"Q{sn}": spoint}}
    if extra_rocker:
        o4 = pts[4]["O4"]
        phi = draw(_angles)
        pts[4]["C"] = o4 + _rot(np.array(extra_rocker), phi)
    block = _local_link(draw, 3, pts[3], scale, "block")
    rocker = _local_link(draw, 4, pts[4], scale, "rocker")
    guide = Prismatic(gn, sn, f"Q{sn}", f"T{gn}", direction, sd, mu=_mu(draw, friction, 0.3))
    joints = [Revolute((1, 2), "O2"), Revolute((2, 3), "A"), guide, Revolute((4, 1), "O4")]
    return {"O2": _t(O2), "O4": _t(O4)}, [crank, block, rocker], joints, {guide.point: draw(_sigma)}


@st.composite
def inverted_slider_crank(draw, friction=None):
    """Crank with a block sliding on a rocker: oscillating (d > r) or Whitworth (d < r)."""
    scale = draw(_scales)
    r = draw(_floats(0.3, 1.0)) * scale
    d = r * draw(st.one_of(_floats(0.2, 0.7), _floats(1.4, 3.0)))
    frame, moving, joints, assembly = _rpr(draw, r, d, scale, friction)
    links = [Link(1, frame), *moving]
    return _finish(draw, links, joints, Driver(2), assembly, (0.0, TWO_PI), True, scale, "inverted slider-crank")


@st.composite
def scotch_yoke(draw, friction=None):
    """Crank 2, block 3 on its pin, yoke 4 sliding on the frame; the slot is on 4 or 3."""
    scale = draw(_scales)
    r = draw(_floats(0.2, 1.0)) * scale
    O2 = _point(draw, scale)
    phi = draw(_angles)
    crank = _link(draw, 2, {"O2": (0, 0), "A": (r, 0)}, scale, "crank")
    sd4 = draw(_angles)
    delta = _signed(draw, math.pi / 6, 5 * math.pi / 6)  # slot at ≥ 30° to the frame guide
    mu_hi = 0.15
    block_pts = {"A": _point(draw, scale, 0.5)}
    yoke_pts = {"Q4": _point(draw, scale, 0.5)}
    if draw(st.booleans()):  # slot in the yoke, the block slides in it
        block_pts["Q3"] = block_pts["A"] + (np.zeros(2) if draw(st.booleans()) else _point(draw, scale, 0.3))
        yoke_pts["T4"] = _point(draw, scale)
        slot = Prismatic(4, 3, "Q3", "T4", sd4 + delta, draw(_angles), mu=_mu(draw, friction, mu_hi))
    else:  # the block carries the guide, the yoke slides on it
        block_pts["T3"] = _point(draw, scale, 0.5)
        yoke_pts["R4"] = _point(draw, scale)
        slot = Prismatic(3, 4, "R4", "T3", draw(_angles), sd4 + delta, mu=_mu(draw, friction, mu_hi))
    block = _local_link(draw, 3, block_pts, scale, "block")
    yoke = _local_link(draw, 4, yoke_pts, scale, "yoke")
    guide = Prismatic(1, 4, "Q4", "S", phi, sd4, mu=_mu(draw, friction, mu_hi))
    links = [Link(1, {"O2": _t(O2), "S": _t(_point(draw, scale))}), crank, block, yoke]
    joints = [Revolute((1, 2), "O2"), Revolute((2, 3), "A"), slot, guide]
    return _finish(draw, links, joints, Driver(2), {}, (0.0, TWO_PI), True, scale, "Scotch yoke")


def _six_bar(draw, scale, on, frame, moving, joints, assembly, title):
    """Hang an RRR dyad 5–6 from point C of link ``on`` to a frame pivot O6."""
    links = [Link(1, frame), *moving]
    # The links get their final numbers before the path of C is traced, so
    # that the path is computed on exactly the linkage that will be finished
    # (σ of an RRR dyad once depended on link numbers; see
    # test_assembly_branch_does_not_depend_on_link_numbering).
    numbering = _numbering(draw, [2, 3, 4, 5, 6])
    sub = _relabel(Mechanism(links, joints, Driver(2), assembly=assembly), numbering)
    path = _path(sub, numbering[on], "C")
    O6, a5, a6 = _hang_rrr(draw, path, scale)
    l5 = _link(draw, 5, {"C": (0, 0), "D": (a5, 0)}, scale, "coupler 2")
    l6 = _link(draw, 6, {"O6": (0, 0), "D": (a6, 0)}, scale, "rocker 2")
    links = [Link(1, {**frame, "O6": _t(O6)}), *moving, l5, l6]
    joints = [*joints, Revolute((on, 5), "C"), Revolute((5, 6), "D"), Revolute((6, 1), "O6")]
    assembly = {**assembly, "D": draw(_sigma)}
    return _finish(draw, links, joints, Driver(2), assembly, (0.0, TWO_PI), True, scale, title, numbering=numbering)


@st.composite
def watt2(draw, friction=None):
    """Watt II: four-bar 1-2-3-4, then four-bar 1-4-5-6 driven by the rocker 4."""
    scale = draw(_scales)
    frame, moving, joints = _fourbar_parts(draw, scale, rocker_extra={"C": _extra_point(draw, scale)})
    return _six_bar(draw, scale, 4, frame, moving, joints, {"B": draw(_sigma)}, "Watt II")


@st.composite
def stephenson3(draw, friction=None):
    """Stephenson III: four-bar 1-2-3-4, then dyad 5-6 from coupler point C to the frame."""
    scale = draw(_scales)
    frame, moving, joints = _fourbar_parts(draw, scale, coupler_extra={"C": _extra_point(draw, scale)})
    return _six_bar(draw, scale, 3, frame, moving, joints, {"B": draw(_sigma)}, "Stephenson III")


@st.composite
def quick_return(draw, friction=None):
    """Crank-shaper: crank 2, block 3 sliding on rocker 4 (RPR), link 5 from the
    rocker's point C to the ram 6 sliding on a frame guide (RRP)."""
    scale = draw(_scales)
    r = draw(_floats(0.3, 1.0)) * scale
    d = r * draw(_floats(1.4, 3.0))
    frame, moving, joints, assembly = _rpr(draw, r, d, scale, friction, extra_rocker=(draw(_floats(0.8, 2.0)) * d, 0.0))
    sub = Mechanism([Link(1, frame), *moving], joints, Driver(2), assembly=assembly)
    path = _path(sub, 4, "C")
    phi = draw(_angles)
    centre = path.mean(axis=0)
    off = (path - centre) @ _n(phi)
    e0 = draw(_floats(float(off.min()), float(off.max())))
    h = float(np.max(np.abs(off - e0)))
    L = max(h, 0.05 * scale) / draw(_floats(0.3, 0.7))
    l5 = _link(draw, 5, {"C": (0, 0), "D": (L, 0)}, scale, "connecting rod")
    ram, guide, S = _slider(draw, 6, phi, centre + e0 * _n(phi), scale, friction)
    links = [Link(1, {**frame, "S": _t(S)}), *moving, l5, ram]
    joints = [*joints, Revolute((4, 5), "C"), Revolute((5, 6), "D"), guide]
    assembly = {**assembly, "D": draw(_sigma)}
    return _finish(draw, links, joints, Driver(2), assembly, (0.0, TWO_PI), True, scale, "quick return")


@st.composite
def gear_pair(draw, friction=None):
    """Gear 2 (driver) meshing with gear 3, both pivoted on the frame; load torque on 3."""
    scale = draw(_scales)
    r2 = draw(_floats(0.2, 1.0)) * scale
    r3 = draw(_floats(0.2, 1.0)) * scale
    O2 = _point(draw, scale)
    O3 = O2 + (r2 + r3) * _u(draw(_angles))
    g2 = _link(draw, 2, {"O2": (0, 0)}, scale, "pinion")
    g3 = _link(draw, 3, {"O3": (0, 0)}, scale, "gear")
    phi = draw(st.one_of(st.just(0.0), st.just(math.radians(20)), _floats(0.0, math.radians(30))))
    if draw(st.booleans()):
        mesh = GearMesh((2, 3), ("O2", "O3"), (r2, r3), phi)
    else:
        mesh = GearMesh((3, 2), ("O3", "O2"), (r3, r2), phi)
    links = [Link(1, {"O2": _t(O2), "O3": _t(O3)}), g2, g3]
    joints = [Revolute((1, 2), "O2"), Revolute((1, 3), "O3"), mesh]
    load = Torque(3, draw(_floats(-200, 200)) * scale, name="load")
    return _finish(draw, links, joints, Driver(2), {}, (0.0, TWO_PI), True, scale, "gear pair", loads=[load])


@st.composite
def epicyclic(draw, friction=None):
    """An epicyclic train driven by its arm 2 about O: planet 3 on the arm meshes with a fixed sun or annulus
    (the frame, external or internal mesh), and half the time also with a sun 4 turning about O (located from the
    planet), loaded by a torque."""
    scale = draw(_scales)
    internal = draw(st.booleans())
    rp = draw(_floats(0.1, 0.5)) * scale
    rf = rp * draw(_floats(1.6, 4.0)) if internal else draw(_floats(0.1, 0.8)) * scale
    arm = rf - rp if internal else rf + rp  # the centre distance: the arm's length
    O = _point(draw, scale)
    a_dir = draw(_angles)
    points = {"O": (0.0, 0.0), "C": _t(arm * _u(a_dir))}
    arm_link = _link(draw, 2, points, scale, "arm")
    # The planet's own frame: its centre anywhere, as a pin elsewhere on a link would be.
    planet = _local_link(draw, 3, {"C": _point(draw, scale, 0.3)}, scale, "planet")
    frame = Link(1, {"O": _t(O)})
    if internal:
        fixed = GearMesh((1, 3), ("O", "C"), (rf, rp), _pressure_angle(draw), internal=True)
    else:
        fixed = GearMesh((3, 1), ("C", "O"), (rp, rf), _pressure_angle(draw))
    links = [frame, arm_link, planet]
    joints = [Revolute((1, 2), "O"), Revolute((2, 3), "C"), fixed]
    loads = []
    if internal and draw(st.booleans()):
        rs = rf - 2 * rp  # a sun inside the annulus, meshing with the same planet
        assume(rs > 0.05 * rf)
        sun = _local_link(draw, 4, {"O": _point(draw, scale, 0.3)}, scale, "sun")
        links.append(sun)
        joints += [Revolute((1, 4), "O"), GearMesh((4, 3), ("O", "C"), (rs, rp), _pressure_angle(draw))]
        loads.append(Torque(4, draw(_floats(-200, 200)) * scale, name="sun load"))
    else:
        loads.append(Torque(3, draw(_floats(-200, 200)) * scale, name="planet load"))
    return _finish(draw, links, joints, Driver(2), {}, (0.0, TWO_PI), True, scale, "epicyclic train", loads=loads)


def _pressure_angle(draw):
    return draw(st.one_of(st.just(0.0), st.just(math.radians(20)), _floats(0.0, math.radians(30))))


def _mesh(draw, gears, centres, radii, internal=False):
    """A mesh of ``gears`` (pivoted at ``centres``, of pitch ``radii``), the two listed in a random order: which gear
    comes first must not matter."""
    if draw(st.booleans()):
        gears, centres, radii = gears[::-1], centres[::-1], radii[::-1]
    return GearMesh(tuple(gears), tuple(centres), tuple(radii), _pressure_angle(draw), internal=internal)


def _gear(draw, number, centre, scale, name):
    """A gear: a link whose pivot ``centre`` sits anywhere in its own frame, as a pin elsewhere on a link would."""
    return _local_link(draw, number, {centre: _point(draw, scale, 0.3)}, scale, name)


def _planet_train(draw, scale, arm, pivot, a, planet, output=True, fixed=None, out=None, compound=False):
    """A planet ``planet`` pinned at C of link ``arm``, ``a`` [m] from the arm's ``pivot`` on the frame.

    The planet meshes with a sun or an annulus (``fixed``, random if None) fixed to the frame about the pivot; with
    ``output``, also with a gear turning about the pivot (``out``: a sun or an annulus), found from the planet: of
    the other kind than the fixed one, or of either kind with a ``compound`` planet, which carries a second gear of
    its own radius for that mesh. Returns (links, joints, loads): the planet and output gear, their pins and meshes,
    and a load torque on the last gear.
    """
    fixed = fixed or draw(st.sampled_from(("sun", "annulus")))
    r1 = draw(_floats(0.15, 0.7)) * a
    links = [_gear(draw, planet, "C", scale, "compound planet" if compound else "planet")]
    ring = fixed == "annulus"
    joints = [Revolute((arm, planet), "C"),
              _mesh(draw, (planet, FRAME), ("C", pivot), (r1, a + r1 if ring else a - r1), ring)]
    last = planet
    if output:
        r2 = draw(_floats(0.15, 0.7)) * a if compound else r1
        if out is None:
            out = draw(st.sampled_from(("sun", "annulus"))) if compound else "sun" if ring else "annulus"
        ring = out == "annulus"
        last = planet + 1
        links.append(_gear(draw, last, pivot, scale, out))
        joints += [Revolute((FRAME, last), pivot),
                   _mesh(draw, (last, planet), (pivot, "C"), (a + r2 if ring else a - r2, r2), ring)]
    return links, joints, [Torque(last, draw(_floats(-200, 200)) * scale, name="output load")]


@st.composite
def annulus(draw, friction=None):
    """An annulus (internal gear) found from the pinion inside it, as issue 35 met it, loaded by a torque.

    Where it turns: on the frame, about a pinion 2 also on the frame (the pinion drives, or half the time the
    annulus); about the frame pivot O of a driving arm 2 whose planet 3 meshes with a sun fixed about O; or
    pivoted on that arm itself at D, beside the planet (which meshes with a fixed sun or annulus).
    """
    scale = draw(_scales)
    where = draw(st.sampled_from(("frame", "arm's axis", "arm")))
    O = _point(draw, scale)
    if where == "frame":
        r = draw(_floats(0.1, 0.5)) * scale
        R = r * draw(_floats(1.3, 4.0))
        links = [Link(1, {"O2": _t(O), "O3": _t(O + (R - r) * _u(draw(_angles)))}),
                 _gear(draw, 2, "O2", scale, "pinion"), _gear(draw, 3, "O3", scale, "annulus")]
        joints = [Revolute((1, 2), "O2"), Revolute((1, 3), "O3"), _mesh(draw, (2, 3), ("O2", "O3"), (r, R), True)]
        driver = draw(st.sampled_from((2, 3)))
        loads = [Torque(5 - driver, draw(_floats(-200, 200)) * scale, name="load")]
        return _finish(draw, links, joints, Driver(driver), {}, (0.0, TWO_PI), True, scale, "internal gear pair",
                       loads=loads)
    a = draw(_floats(0.3, 1.0)) * scale
    if where == "arm's axis":
        arm = _link(draw, 2, {"O": (0, 0), "C": (a, 0)}, scale, "arm")
        gears, joints, loads = _planet_train(draw, scale, 2, "O", a, 3, fixed="sun", out="annulus")
    else:
        gears, joints, _ = _planet_train(draw, scale, 2, "O", a, 3, output=False)
        rp = joints[1].radius(3)
        R = rp * draw(_floats(1.3, 4.0))
        D = np.array([a, 0.0]) + (R - rp) * _u(draw(_angles))
        assume(np.hypot(*D) > 0.1 * a)  # D away from the arm's pivot O
        arm = _link(draw, 2, {"O": (0, 0), "C": (a, 0), "D": _t(D)}, scale, "arm")
        gears.append(_gear(draw, 4, "D", scale, "annulus"))
        joints += [Revolute((2, 4), "D"), _mesh(draw, (3, 4), ("C", "D"), (rp, R), True)]
        loads = [Torque(4, draw(_floats(-200, 200)) * scale, name="annulus load")]
    links = [Link(1, {"O": _t(O)}), arm, *gears]
    return _finish(draw, links, [Revolute((1, 2), "O"), *joints], Driver(2), {}, (0.0, TWO_PI), True, scale,
                   "annulus on an arm", loads=loads)


@st.composite
def compound_planet(draw, friction=None):
    """Arm 2 drives about O; planet 3 on it carries two gears of their own radii, one meshing with a sun or annulus
    fixed about O, the other with a sun or annulus 4 turning about O (found from the planet), loaded by a torque."""
    scale = draw(_scales)
    a = draw(_floats(0.3, 1.0)) * scale
    arm = _link(draw, 2, {"O": (0, 0), "C": (a, 0)}, scale, "arm")
    gears, joints, loads = _planet_train(draw, scale, 2, "O", a, 3, compound=True)
    links = [Link(1, {"O": _t(_point(draw, scale))}), arm, *gears]
    return _finish(draw, links, [Revolute((1, 2), "O"), *joints], Driver(2), {}, (0.0, TWO_PI), True, scale,
                   "compound planet", loads=loads)


def toggle_fourbar(theta=(0.0,)):
    """A triple rocker, frame 1.0, crank 0.4, coupler 0.6, rocker 0.6 (m), as a Problem at the crank angles
    ``theta`` [rad]: coupler and rocker fold into line (|AB0| = 1.2) at cos θ = (1 + 0.16 − 1.44)/0.8 = −0.35,
    a toggle the crank cannot pass."""
    from graphkin.problem import Problem

    links = [
        Link(1, {"A0": (0, 0), "B0": (1.0, 0)}),
        Link(2, {"A0": (0, 0), "A": (0.4, 0)}, mass=1.0, I_G=0.01),
        Link(3, {"A": (0, 0), "B": (0.6, 0)}, mass=1.0, G=(0.3, 0), I_G=0.03),
        Link(4, {"B0": (0, 0), "B": (0.6, 0), "P": (0.3, 0)}, mass=1.0, G=(0.3, 0), I_G=0.03),
    ]
    joints = [Revolute((1, 2), "A0"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), Revolute((1, 4), "B0")]
    mech = Mechanism(links, joints, Driver(2), [PointForce(4, "P", (0.0, -100.0))])
    n = len(theta)
    return Problem("toggle four-bar", mech, np.asarray(theta, dtype=float), np.full(n, 10.0), np.zeros(n))


def planet_on_a_rocker() -> Mechanism:
    """A crank-rocker whose rocker 4 swings across 180° carries a planet 5 meshing with a sun fixed at the rocker's
    pivot: the shrunk case the family ``driven_arm`` found, where the planet's angle jumped by 1.6 turns as the
    rocker's crossed ±180° (issue 35)."""
    return Mechanism(
        [Link(1, {"O2": (0.0, 0.0), "O4": (-0.9899924966004454, 0.1411200080598672)}),
         Link(2, {"O2": (0.0, 0.0), "A": (0.5, 0.0)}),
         Link(3, {"A": (0.0, 0.0), "B": (1.0, 0.0)}),
         Link(4, {"O4": (0.0, 0.0), "B": (-0.4161468365471424, 0.9092974268256817),
                  "C": (0.5403023058681397, 0.8414709848078965)}),
         Link(5, {"C": (0.0, 0.0)})],
        [Revolute((1, 2), "O2"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), Revolute((4, 1), "O4"),
         Revolute((4, 5), "C"), GearMesh((5, 1), ("C", "O4"), (0.625, 0.375), 0.0)],
        Driver(2), assembly={"B": 1})


@st.composite
def driven_arm(draw, friction=None):
    """A planet on an arm that is not the driver: the arm a gear 3 turned by a driving pinion 2 (outside it, or
    inside it: the arm an annulus), or the rocker 4 of a crank-rocker. The planet meshes with a sun or annulus fixed
    about the arm's pivot, and half the time with a gear of the other kind turning about it."""
    scale = draw(_scales)
    if draw(st.booleans()):
        r2 = draw(_floats(0.1, 0.5)) * scale
        internal = draw(st.booleans())
        R3 = r2 * draw(_floats(1.3, 3.0)) if internal else draw(_floats(0.2, 1.0)) * scale
        O = _point(draw, scale)
        O2 = O + (R3 - r2 if internal else R3 + r2) * _u(draw(_angles))
        a = draw(_floats(0.3, 1.0)) * scale
        frame = {"O2": _t(O2), "O": _t(O)}
        moving = [_gear(draw, 2, "O2", scale, "pinion"), _link(draw, 3, {"O": (0, 0), "C": (a, 0)}, scale, "arm")]
        joints = [Revolute((1, 2), "O2"), Revolute((1, 3), "O"), _mesh(draw, (2, 3), ("O2", "O"), (r2, R3), internal)]
        arm, pivot, assembly = 3, "O", {}
    else:
        C = _extra_point(draw, scale)
        a = math.hypot(*C)
        frame, moving, joints = _fourbar_parts(draw, scale, rocker_extra={"C": C})
        arm, pivot, assembly = 4, "O4", {"B": draw(_sigma)}
    gears, more, loads = _planet_train(draw, scale, arm, pivot, a, arm + 1, output=draw(st.booleans()))
    links = [Link(1, frame), *moving, *gears]
    return _finish(draw, links, [*joints, *more], Driver(2), assembly, (0.0, TWO_PI), True, scale,
                   "planet on a driven arm", loads=loads)


@st.composite
def piston_driven(draw, friction=None):
    """An offset slider-crank driven by its slider 4 (an engine's piston), the crank 2 and rod 3 found as an RRR
    dyad, over the stroke on one side of the crank's pivot, away from the dead centres; half the time the crank is
    also the arm of a planet meshing with a sun or annulus fixed about the crank's pivot (and perhaps a gear turning
    about it)."""
    scale = draw(_scales)
    r = draw(_floats(0.2, 1.0)) * scale
    e = r * draw(_floats(-0.8, 0.8))
    l = (r + abs(e)) * draw(_floats(1.4, 3.0))
    O2 = _point(draw, scale)
    phi = draw(_angles)
    C = _extra_point(draw, scale) if draw(st.booleans()) else None
    crank = _link(draw, 2, {"O2": (0, 0), "A": (r, 0), **({"C": C} if C else {})}, scale, "crank")
    coupler = _link(draw, 3, {"A": (0, 0), "B": (l, 0)}, scale, "connecting rod")
    F = O2 + e * _n(phi)  # the foot of the perpendicular from O2 to the line of the piston's pin B
    piston, guide, S = _slider(draw, 4, phi, F, scale, friction)
    piston = _rename(piston, "D", "B")
    # q is the slider point's place from S along the guide; the pin B is then at F + (q + t) u.
    w = _rot(np.subtract(piston.point(guide.point), piston.point("B")), phi - guide.slider_direction)
    t = float(np.dot(S - F - w, _u(phi)))
    # The stroke on one side, crank and rod at 30° to 150° (|F B|² = r² + l² − 2 r l cos γ − e²): near a dead centre
    # the crank's angle goes as the root of the piston's travel, and its rates grow without bound.
    near, far = (math.sqrt(r * r + l * l - 2 * r * l * c - e * e) for c in (math.cos(math.pi / 6), -math.cos(math.pi / 6)))
    q_range = draw(st.sampled_from(((near - t, far - t), (-far - t, -near - t))))
    links = [Link(1, {"O2": _t(O2), "S": _t(S)}), crank, coupler, piston]
    joints = [Revolute((1, 2), "O2"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), guide]
    loads = []
    if C:
        gears, more, loads = _planet_train(draw, scale, 2, "O2", math.hypot(*C), 5, output=draw(st.booleans()))
        links, joints = [*links, *gears], [*joints, *more]
    return _finish(draw, links, joints, Driver(4, "slider"), {"A": draw(_sigma)}, q_range, False, scale,
                   "piston-driven slider-crank", loads=loads)


_builders = {
    "fourbar": fourbar,
    "slider_crank": slider_crank,
    "double_slider": double_slider,
    "inverted_slider_crank": inverted_slider_crank,
    "scotch_yoke": scotch_yoke,
    "watt2": watt2,
    "stephenson3": stephenson3,
    "quick_return": quick_return,
    "gear_pair": gear_pair,
    "epicyclic": epicyclic,
    "annulus": annulus,
    "compound_planet": compound_planet,
    "driven_arm": driven_arm,
    "piston_driven": piston_driven,
}

families = {name: build() for name, build in _builders.items()}
"""Family name -> strategy of :class:`Case` (friction at sliders drawn at random)."""

friction_families = {
    name: _builders[name](friction=True)
    for name in ("slider_crank", "double_slider", "inverted_slider_crank", "scotch_yoke", "quick_return",
                 "piston_driven")
}
"""The families with sliders, every slider with Coulomb friction μ > 0."""

frictionless_families = {name: build(friction=False) for name, build in _builders.items()}
"""Every family with friction-free sliders."""

crank_families = [name for name in families if name not in ("double_slider", "piston_driven")]
"""Families driven by a fully rotating crank (the others by a slider)."""

gear_families = ["gear_pair", "epicyclic", "annulus", "compound_planet", "driven_arm"]
"""Families with gears in every mechanism (a gear's period is not one turn of the input)."""

cases = st.one_of(*families.values())
"""Any family."""
