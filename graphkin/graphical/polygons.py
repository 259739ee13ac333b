"""Velocity and acceleration polygons from the input motion, group by group (:func:`construct_kinematics`).

The construction a course draws, as vector geometry on one position: it reads the mechanism's *positions*
from the kinematics and the input's ω2, α2 (or v, a of a driving slider), and nothing else of the motion.

- The driver: a crank's pin velocity ω2 × O2A (⊥ O2A, in the sense of ω2), its acceleration the normal
  ω2² AO2 (towards O2) plus the tangential α2 × O2A; a driving slider's v and a along its guide.
- A dyad: one point X (the tracer) is reached from both sides. From a pin P of the same link, the relative
  velocity v_XP is perpendicular to PX; across a sliding pair, the relative velocity is along the guide.
  Each side is a line through a known image point; the two lines meet at x. In the acceleration polygon
  each side adds what it knows in size and direction first (the normal component ω² PX from X towards P,
  or the Coriolis component 2ω v_rel, v_rel turned 90° in the sense of the guide's ω) and leaves open the
  tangential component (⊥ PX) or the sliding one (along the guide).
- A gear pivoted on a located carrier: its pitch point has the velocity of the meshing gear's pitch point
  (rolling); the contact points' accelerations differ only along the line of centres.
- Images: once a link has one image point and its ω (α), every other point and G follow from the image,
  the link's shape turned 90° in the sense of ω and scaled by |ω| (the acceleration image: turned by
  atan2(α, −ω²) and scaled by √(ω⁴ + α²)).

ω and α of a link are read off the polygon as a relative vector over the length it turns about, with the
sense the vector gives (ω3 = v_BA / AB). The test compares every value with the analytical solver's.
"""

from __future__ import annotations

import cmath
import math

import numpy as np

from graphkin.analytical.meshes import pitch as pitch_point
from graphkin.errors import GraphkinError
from graphkin.geometry import zcross as cross
from graphkin.graphical.captions import Later, number
from graphkin.graphical.construction import nice_scale
from graphkin.graphical.guard import derived, kept, motion_disagreement
from graphkin.graphical.guard import plan as kept_plan
from graphkin.graphical.motion import MotionConstruction, MotionStep, PolygonLine, Vector
from graphkin.graphical.motion_captions import (
    A,
    V,
    acceleration_image,
    driver_sliding,
    driver_sliding_acceleration,
    driver_turning,
    driver_turning_acceleration,
    gear_rolling,
    gear_rolling_acceleration,
    rate,
    sense,
    vector,
    velocity_image,
)
from graphkin.kinematics import DriverGroup, Dyad, GearGroup, Kinematics
from graphkin.kinematics.groups import DEAD_POINT
from graphkin.kinematics.plan import plan_of
from graphkin.model import Prismatic, Revolute


class Degenerate(Exception):
    """A polygon that cannot be drawn at this position (two parallel lines, a zero arm); the message says why."""


class _Motion:
    """A link's motion as the polygons know it: a point X, its velocity v and acceleration a, ω and α.

    The image rule gives every other point (:meth:`vel`, :meth:`acc`); α is None until the acceleration
    polygon reaches the link.
    """

    __slots__ = ("X", "v", "a", "w", "al", "n")

    def __init__(self, X, v, w, a=None, al=None, normal=True):
        self.X, self.v, self.w, self.a, self.al = X, v, w, a, al
        self.n = 1.0 if normal else 0.0  # 0: the normal component left out (a student's slip, for a grader)

    def vel(self, P):
        return self.v + 1j * self.w * (P - self.X)

    def acc(self, P):
        return self.a + (1j * self.al - self.n * self.w * self.w) * (P - self.X)


def _meet(Q1, d1, Q2, d2, what: str):
    """Where the lines Q1 + t d1 and Q2 + s d2 meet (d1, d2 unit); Degenerate where they are parallel.

    Parallel lines in a polygon are a dead point (a transmission angle of 0 or 180°): the threshold is the
    kinematic solver's.
    """
    den = cross(d1, d2)
    if not abs(den) > DEAD_POINT:
        raise Degenerate(f"{what}: the two lines of the polygon are parallel (a dead point), so they do not meet")
    return Q1 + cross(Q2 - Q1, d2) / den * d1


class _Side:
    """One way of reaching the tracer X of a dyad: turning with link L about its pin P, or sliding on link m.

    Attributes
    ----------
    turn : bool
        True: X is a point of link L, which turns about its pin P (known from ``base``).
        False: X on link L slides along a guide relative to the coincident point of link m.
    L, m, base : int
        The link X is on, the link it slides on (sliding only), the located link whose motion gives the
        known point (P, or X on m).
    P, P_name : complex, str
        The pin (turning only).
    joint : Prismatic or None
    """

    __slots__ = ("turn", "L", "m", "base", "P", "P_name", "joint")

    def __init__(self, turn, L, base, *, P=None, P_name="", m=None, joint=None):
        self.turn, self.L, self.base, self.P, self.P_name, self.m, self.joint = turn, L, base, P, P_name, m, joint


class _Fixed:
    """What the polygons of a mechanism share at every position, worked out once (kept in its plan).

    Attributes
    ----------
    points : dict of (int, str) to complex
        Each named point in its link's own frame [m].
    twice : set of str
        Names carried by two moving links that are not pinned together there: two points, written with
        the link (B3, B4).
    images : dict of int to list
        Per moving link, the image points: ``(key, symbol, image label, local point)``, key ``(link, name)``
        for a named point and ``(link, None)`` for G.
    size : float
        The mechanism's size [m], for what counts as rounding in a caption.
    """

    def __init__(self, mech):
        plan = plan_of(mech)
        self.points = plan.points
        carriers: dict[str, set] = {}
        for n in mech.moving:
            for name in mech.link(n).points:
                carriers.setdefault(name, set()).add(n)
        pinned = {(j.point, l) for j in mech.joints if isinstance(j, Revolute) for l in j.links}
        self.twice = {name for name, ls in carriers.items() if len(ls) > 1 and not all((name, l) in pinned for l in ls)}
        self.images = {}
        for n in mech.moving:
            body = mech.link(n)
            rows = []
            for name in body.points:
                s = f"{name}{n}" if name in self.twice else name
                rows.append(((n, name), s, s.lower(), self.points[n, name]))
            rows.append(((n, None), f"G{n}", f"g{n}", complex(*body.G)))
            self.images[n] = rows
        self.size = sum(max(abs(complex(*p)) for p in link.points.values()) for link in mech.links) or 1.0


def _fixed(kin: Kinematics) -> _Fixed:
    """The polygons' :class:`_Fixed` of the kinematics' mechanism (kept in its plan, and found once per kinematics:
    :func:`graphkin.graphical.guard.kept`)."""
    mech = kin.mechanism
    compiled = kept_plan(kin).compiled
    fixed = compiled.get("polygons")
    if fixed is None:
        fixed = compiled["polygons"] = _Fixed(mech)
    return fixed


class _Polygons:
    """Builds both polygons of one position, group by group; the velocity pass first, then the acceleration."""

    def __init__(self, kin: Kinematics, i: int, slip: str | None = None):
        self.kin, self.i, self.slip = kin, i, slip
        self.mech = mech = kin.mechanism
        self.frame = mech.frame
        self.fixed = kept(kin, "polygons", _fixed)
        self.motion = {self.frame: _Motion(0j, 0j, 0.0, 0j, 0.0)}
        self.steps: list[MotionStep] = []
        self.v_img = {"o": (0.0, 0.0)}
        self.a_img = {"o′": (0.0, 0.0)}
        self.velocity, self.acceleration = {}, {}
        # Whose point each image is, and what each Coriolis component is of, for the guard (graphical/guard.py).
        self.where: dict[str, tuple[int, complex, tuple | None]] = {}
        self.coriolis: dict[str, tuple[int, int, int, complex]] = {}
        self._O = {n: kin.O[n].item(i) for n in mech.moving}  # .item: a Python complex, no numpy scalar made
        self._e = {n: kin.e[n].item(i) for n in mech.moving}
        # What a residue of rounding is beside, in the captions: the input's speed over the mechanism's size.
        size = self.fixed.size
        w, al = abs(float(kin.q_dot[i])), abs(float(kin.q_ddot[i]))
        self.v_ref = w * size if mech.driver.crank else w
        self.a_ref = (w * w + al) * size if mech.driver.crank else al + w * w / size

    # -- positions and names --------------------------------------------------------------------------------
    def pos(self, link: int, name: str) -> complex:
        p = self.fixed.points[link, name]
        if link == self.frame:
            return p
        return self._O[link] + self._e[link] * p

    def sym(self, link: int, name: str) -> str:
        return f"{name}{link}" if name in self.fixed.twice else name

    def text(self, z, unit: str) -> str:
        """A vector of a polygon in a caption, its rounding residue written as 0."""
        return vector(z, unit, self.v_ref if unit == V else self.a_ref)

    # -- recording ------------------------------------------------------------------------------------------
    def step(self, polygon, kind, caption, links, vectors=(), lines=(), points=None, values=None):
        n = len(self.steps)
        vecs = tuple([Vector(name, (t.real, t.imag), (h.real, h.imag), known, n) for name, t, h, known in vectors])
        pts = {k: (z.real, z.imag) for k, z in points.items()} if points else {}
        (self.v_img if polygon == "velocity" else self.a_img).update(pts)
        self.steps.append(MotionStep(polygon, kind, caption, tuple(links), vecs,
                                     tuple([PolygonLine(name, (Q.real, Q.imag), (d.real, d.imag)) for name, Q, d in lines]), pts,
                                     values or {}))

    # -- the driver -----------------------------------------------------------------------------------------
    def driver_velocity(self, g: DriverGroup):
        kin, i, link, J = self.kin, self.i, g.link, g.joint
        w2 = float(kin.q_dot[i])
        if isinstance(J, Revolute):
            O2 = self.pos(self.frame, J.point)
            self.motion[link] = _Motion(O2, 0j, w2)
            caption = Later(driver_turning, link, J.point, w2)
            self.step("velocity", "driver", caption, (link,), values={f"omega{link}": w2})
        else:
            u = cmath.exp(1j * J.direction)
            v = w2 * u
            X = self.pos(link, J.point)
            self.motion[link] = _Motion(X, v, 0.0)
            s = self.sym(link, J.point)
            self.where[s.lower()] = self.where[f"{s.lower()}′"] = (link, X, (link, J.point))
            caption = Later(driver_sliding, link, s, w2, v, self.v_ref)
            self.step("velocity", "driver", caption, (link,), [(f"v_{s}", 0j, v, "size and direction")],
                      points={s.lower(): v}, values={f"omega{link}": 0.0})
        self.image_velocity(link)

    def driver_acceleration(self, g: DriverGroup):
        kin, i, link, J = self.kin, self.i, g.link, g.joint
        al2 = float(kin.q_ddot[i])
        m = self.motion[link]
        if isinstance(J, Revolute):
            m.a, m.al = 0j, al2
            caption = Later(driver_turning_acceleration, link, J.point, al2)
            self.step("acceleration", "driver", caption, (link,), values={f"alpha{link}": al2})
        else:
            m.a, m.al = al2 * cmath.exp(1j * J.direction), 0.0
            s = self.sym(link, J.point)
            caption = Later(driver_sliding_acceleration, link, s, al2, m.a, self.a_ref)
            self.step("acceleration", "driver", caption, (link,), [(f"a_{s}", 0j, m.a, "size and direction")],
                      points={f"{s.lower()}′": m.a}, values={f"alpha{link}": 0.0})
        self.image_acceleration(link)

    # -- images ---------------------------------------------------------------------------------------------
    def image_velocity(self, link: int):
        m = self.motion[link]
        O, e = (0j, 1 + 0j) if link == self.frame else (self._O[link], self._e[link])
        vectors, found, listed = [], {}, []
        for key, s, label, p in self.fixed.images[link]:
            P = O + e * p
            v = m.vel(P)
            found[label] = v
            self.where[label] = (link, P, key)
            vectors.append((f"v_{s}", 0j, v, "found"))
            if label not in self.v_img:  # a point a step before has found is not read off again
                listed.append((s, v))
            self.velocity[key] = v
        # Written when first read (most polygons are made to be checked): the values as they are now.
        caption = Later(velocity_image, link, m.w, m.v, listed, self.v_ref)
        self.step("velocity", "image", caption, (link,), vectors, points=found)

    def image_acceleration(self, link: int):
        m = self.motion[link]
        O, e = (0j, 1 + 0j) if link == self.frame else (self._O[link], self._e[link])
        vectors, found, listed = [], {}, []
        for key, s, label, p in self.fixed.images[link]:
            P = O + e * p
            a = m.acc(P)
            label += "′"
            found[label] = a
            self.where[label] = (link, P, key)
            vectors.append((f"a_{s}", 0j, a, "found"))
            if label not in self.a_img:
                listed.append((s, a))
            self.acceleration[key] = a
        caption = Later(acceleration_image, link, m.w, m.al, m.a, listed, self.a_ref)
        self.step("acceleration", "image", caption, (link,), vectors, points=found)

    # -- dyads ----------------------------------------------------------------------------------------------
    def sides(self, d: Dyad):
        """The tracer X (its position, symbol and point name) and the two sides of the dyad that reach it.

        X is the pin J2 where there is one; in an RPR or RPP dyad it is the point of link k that coincides
        with the pin J1 (A4, on a rocker under the block 3 pinned at A), as the books take it.
        """
        t, J1, J2, J3 = d.type, d.J1, d.J2, d.J3
        if t in ("RRR", "RRP", "PRP"):
            X, x, name = self.pos(d.j, J2.point), self.sym(d.k, J2.point), J2.point
        else:
            X, x, name = self.pos(d.j, J1.point), f"{J1.point}{d.k}", J1.point
        if t in ("RRR", "RRP"):
            first = _Side(True, d.j, d.a, P=self.pos(d.j, J1.point), P_name=self.sym(d.j, J1.point))
        elif t == "PRP":
            first = _Side(False, d.j, d.a, m=d.a, joint=J1)
        else:
            first = _Side(False, d.k, d.a, m=d.j, joint=J2)
        if t[2] == "R":
            second = _Side(True, d.k, d.b, P=self.pos(d.k, J3.point), P_name=self.sym(d.k, J3.point))
        else:
            second = _Side(False, d.k, d.b, m=d.b, joint=J3)
        return X, x, name, (first, second)

    def dyad_velocity(self, d: Dyad):
        X, x, name, sides = self.sides(d)
        lines, vectors, phrases = [], [], []
        for s in sides:
            if s.turn:
                arm = X - s.P
                if abs(arm) == 0:
                    raise Degenerate(f"{d.label}: {x} lies on the pin {s.P_name}, so v_{x}{s.P_name} has no direction")
                Q, direction = self.motion[s.base].vel(s.P), 1j * arm / abs(arm)
                rel = f"v_{x}{s.P_name}"
                phrases.append(f"v_{x} = v_{s.P_name} + {rel}, {rel} ⊥ {s.P_name}{x}")
                vectors.append((f"v_{s.P_name}", 0j, Q, "size and direction"))
            else:
                k = f"{name}{s.m}"
                Q, direction = self.motion[s.base].vel(X), self.guide(s.joint)
                rel = f"v_{x}{k}"
                phrases.append(f"v_{x} = v_{k} + {rel}, {rel} along the guide of {s.joint.guide} "
                               f"(∠ {number(math.degrees(cmath.phase(direction)))}°)")
                vectors.append((f"v_{k}", 0j, Q, "size and direction"))
            lines.append((rel, Q, direction))
        v_X = _meet(lines[0][1], lines[0][2], lines[1][1], lines[1][2], d.label)
        vectors += [(name, Q, v_X, "direction") for name, Q, _ in lines]
        vectors.append((f"v_{x}", 0j, v_X, "found"))

        # ω of each link: from a side that turns about a pin, or tied to the link it slides on.
        w = {}
        for s, (_, Q, _) in zip(sides, lines):
            if s.turn:
                arm = X - s.P
                w[s.L] = cross(arm, v_X - Q) / (abs(arm) ** 2)
        self.tie(d, w, "w")
        values = {f"omega{d.j}": w[d.j], f"omega{d.k}": w[d.k], f"v_{x}": abs(v_X)}
        read = "; ".join(self.omega_phrase(s, x, w) for s in sides if s.turn)
        caption = (f"{d.label}: {' and '.join(phrases)}. The two lines meet at {x.lower()}: "
                   f"v_{x} = {self.text(v_X, V)}." + (f" {read}." if read else "")
                   + self.tied_phrase(d, sides, w))
        self.where[x.lower()] = self.where[f"{x.lower()}′"] = (d.k, X, None)
        self.step("velocity", "dyad", caption, (d.j, d.k), vectors, lines, {x.lower(): v_X}, values)

        on_j = d.type in ("RRR", "RRP", "PRP")
        normal = self.slip != "no_normal"
        self.motion[d.j] = (_Motion(X, v_X, w[d.j], normal=normal) if on_j else
                            _Motion(self.pos(d.j, d.J1.point), self.motion[d.a].vel(self.pos(d.j, d.J1.point)), w[d.j],
                                    normal=normal))
        self.motion[d.k] = _Motion(X, v_X, w[d.k], normal=normal)
        self.image_velocity(d.j)
        self.image_velocity(d.k)

    def omega_phrase(self, s, x, w):
        return f"ω{s.L} = v_{x}{s.P_name} / {s.P_name}{x} = {rate(w[s.L], 'rad/s')}"

    def tied_phrase(self, d, sides, w) -> str:
        turned = {s.L for s in sides if s.turn}
        tied = [link for link in (d.j, d.k) if link not in turned]
        if not tied:
            return ""
        return " " + " ".join(f"Link {link} slides without turning on its neighbour: ω{link} = {rate(w[link], 'rad/s')}."
                              for link in tied)

    def tie(self, d: Dyad, w: dict, field: str):
        """Fill ω (``"w"``) or α (``"al"``) of a dyad's links that a sliding pair ties to a neighbour."""
        def of(link):
            return w[link] if link in w else getattr(self.motion[link], field)

        if d.j not in w and isinstance(d.J1, Prismatic):
            w[d.j] = of(d.a)
        if d.k not in w and isinstance(d.J3, Prismatic):
            w[d.k] = of(d.b)
        if d.j not in w:
            w[d.j] = w[d.k]
        if d.k not in w:
            w[d.k] = w[d.j]

    def guide(self, joint: Prismatic) -> complex:
        """Unit direction of a guide at this position (fixed in the guide link)."""
        e = 1 + 0j if joint.guide == self.frame else self._e[joint.guide]
        return e * cmath.exp(1j * joint.direction)

    def dyad_acceleration(self, d: Dyad):
        X, x, name, sides = self.sides(d)
        mj, mk = self.motion[d.j], self.motion[d.k]
        v_X = mk.vel(X)
        lines, vectors, phrases, values = [], [], [], {}
        for s in sides:
            w = self.motion[s.L].w
            if s.turn:
                arm = X - s.P
                Q0 = self.motion[s.base].acc(s.P)
                normal = -w * w * arm if self.slip != "no_normal" else 0j
                direction = 1j * arm / abs(arm)
                n_name, t_name = f"a^n_{x}{s.P_name}", f"a^t_{x}{s.P_name}"
                phrases.append(f"a_{x} = a_{s.P_name} + {n_name} + {t_name}: {n_name} = ω{s.L}² {s.P_name}{x} = "
                               f"{number(abs(normal))} m/s² from {x} towards {s.P_name} (known), {t_name} ⊥ {s.P_name}{x}")
                vectors += [(f"a_{s.P_name}", 0j, Q0, "size and direction"), (n_name, Q0, Q0 + normal, "size and direction")]
                values[n_name] = abs(normal)
                lines.append((t_name, Q0 + normal, direction))
            else:
                k = f"{name}{s.m}"
                wm = self.motion[s.m].w
                Q0 = self.motion[s.base].acc(X)
                v_rel = v_X - self.motion[s.base].vel(X)
                coriolis = (2j if self.slip != "coriolis_reversed" else -2j) * wm * v_rel
                direction = self.guide(s.joint)
                c_name, r_name = f"a^c_{x}{k}", f"a^r_{x}{k}"
                self.coriolis[c_name] = (s.m, d.k, s.base, X)
                # The two links of a sliding pair turn together: the guide's ω is the one the books name.
                g = s.joint.guide
                if wm == 0 or v_rel == 0:
                    why = f"ω{g} = 0" if wm == 0 else f"v_{x}{k} = 0"
                    rule = f"{c_name} = 0 ({why})"
                else:
                    rule = (f"{c_name} = 2 ω{g} v_{x}{k} = {number(abs(coriolis))} m/s², v_{x}{k} turned 90° "
                            f"{sense(wm)} (the sense of ω{g})")
                phrases.append(f"a_{x} = a_{k} + {c_name} + {r_name}: {rule}; {r_name} along the guide")
                vectors += [(f"a_{k}", 0j, Q0, "size and direction"), (c_name, Q0, Q0 + coriolis, "size and direction")]
                values[c_name] = abs(coriolis)
                lines.append((r_name, Q0 + coriolis, direction))
        a_X = _meet(lines[0][1], lines[0][2], lines[1][1], lines[1][2], d.label)
        vectors += [(name, Q, a_X, "direction") for name, Q, _ in lines]
        vectors.append((f"a_{x}", 0j, a_X, "found"))

        al, read = {}, []
        for n, s in enumerate(sides):
            if s.turn:
                arm = X - s.P
                tangential = a_X - lines[n][1]
                al[s.L] = cross(arm, tangential) / (abs(arm) ** 2)
                values[lines[n][0]] = abs(tangential)
                read.append(f"α{s.L} = {lines[n][0]} / {s.P_name}{x} = {rate(al[s.L], 'rad/s²')}")
        self.tie(d, al, "al")
        for link in (d.j, d.k):
            if not any(s.turn and s.L == link for s in sides):
                read.append(f"α{link} = {rate(al[link], 'rad/s²')} (tied by its sliding pair)")
        values.update({f"alpha{d.j}": al[d.j], f"alpha{d.k}": al[d.k], f"a_{x}": abs(a_X)})
        caption = (f"{d.label}: {' and '.join(phrases)}. The two lines meet at {x.lower()}′: "
                   f"a_{x} = {self.text(a_X, A)}. {'; '.join(read)}.")
        self.step("acceleration", "dyad", caption, (d.j, d.k), vectors, lines, {f"{x.lower()}′": a_X}, values)

        on_j = d.type in ("RRR", "RRP", "PRP")
        if on_j:
            mj.X, mj.v, mj.a = X, v_X, a_X
        else:
            P = self.pos(d.j, d.J1.point)
            mj.X, mj.v, mj.a = P, self.motion[d.a].vel(P), self.motion[d.a].acc(P)
        mj.al = al[d.j]
        mk.X, mk.v, mk.a, mk.al = X, v_X, a_X, al[d.k]
        self.image_acceleration(d.j)
        self.image_acceleration(d.k)

    # -- gears ----------------------------------------------------------------------------------------------
    def pitch(self, g: GearGroup):
        # The force route's pitch point: beyond the pinion's centre, on the annulus's side, for an internal mesh.
        Cj, Ck = self.pos(g.j, g.j_pivot.point), self.pos(g.k, g.pivot.point)
        return complex(pitch_point(g.mesh, g.k, Ck, Cj)[0]), Ck

    def gear_velocity(self, g: GearGroup):
        P, Ck = self.pitch(g)
        c = self.sym(g.k, g.pivot.point)
        v_P = self.motion[g.j].vel(P)
        v_C = self.motion[g.b].vel(Ck)
        arm = P - Ck
        w = cross(arm, v_P - v_C) / abs(arm) ** 2
        p = f"P{g.j}{g.k}"
        self.where[p.lower()] = (g.j, P, None)  # the pitch point of gear j: gear k's has its velocity (rolling)
        self.where[f"{p.lower()}′"] = (g.k, P, None)  # the acceleration polygon finds gear k's (gear_acceleration)
        caption = Later(gear_rolling, g.j, g.k, p, c, v_P, w, self.v_ref)
        self.step("velocity", "gear", caption, (g.k,),
                  [(f"v_{c}", 0j, v_C, "size and direction"), (f"v_{p}", 0j, v_P, "size and direction"),
                   (f"v_{p}{c}", v_C, v_P, "found")], points={p.lower(): v_P}, values={f"omega{g.k}": w})
        self.motion[g.k] = _Motion(Ck, v_C, w, normal=self.slip != "no_normal")
        self.image_velocity(g.k)

    def gear_acceleration(self, g: GearGroup):
        P, Ck = self.pitch(g)
        c = self.sym(g.k, g.pivot.point)
        m = self.motion[g.k]
        arm = P - Ck
        a_C = self.motion[g.b].acc(Ck)
        a_Pj = self.motion[g.j].acc(P)
        normal = -m.w * m.w * arm if self.slip != "no_normal" else 0j
        p = f"P{g.j}{g.k}"
        t_name = f"a^t_{p}{c}"
        lines = [(t_name, a_C + normal, 1j * arm / abs(arm)), (f"a_{p}{g.k}{g.j}", a_Pj, arm / abs(arm))]
        a_P = _meet(*lines[0][1:], *lines[1][1:], g.label)
        al = cross(arm, a_P - a_C - normal) / abs(arm) ** 2
        caption = Later(gear_rolling_acceleration, g.j, g.k, p, c, t_name, abs(normal), al)
        self.step("acceleration", "gear", caption, (g.k,),
                  [(f"a_{c}", 0j, a_C, "size and direction"), (f"a^n_{p}{c}", a_C, a_C + normal, "size and direction"),
                   (t_name, a_C + normal, a_P, "direction"), (f"a_{p}", 0j, a_P, "found")], lines,
                  {f"{p.lower()}′": a_P}, {f"alpha{g.k}": al, t_name: abs(a_P - a_C - normal)})
        m.a, m.al = a_C, al
        self.image_acceleration(g.k)

    # -- running it -----------------------------------------------------------------------------------------
    def run(self):
        groups = self.kin.groups
        for g in groups:
            if isinstance(g, DriverGroup):
                self.driver_velocity(g)
            elif isinstance(g, GearGroup):
                self.gear_velocity(g)
            else:
                self.dyad_velocity(g)
        for g in groups:
            if isinstance(g, DriverGroup):
                self.driver_acceleration(g)
            elif isinstance(g, GearGroup):
                self.gear_acceleration(g)
            else:
                self.dyad_acceleration(g)


SLIPS = ("no_normal", "coriolis_reversed")
"""The slips a construction can be made with, as a student makes them (for a grader to name): the normal component
of each relative acceleration left out, or the Coriolis component drawn in the reversed sense."""


def construct_kinematics(kin: Kinematics, index: int = 0, *, slip: str | None = None) -> MotionConstruction:
    """The velocity and acceleration polygons of position ``index``, step by step, from the input motion.

    Parameters
    ----------
    kin : Kinematics
        The mechanism's motion (``problem.kinematics()``); the polygons read only its positions and the
        input's rates, and construct the rest.
    index : int
        Which of the kinematics' positions to construct.
    slip : {None, "no_normal", "coriolis_reversed"}
        Construct the acceleration polygon as a student who made this slip would (:data:`SLIPS`), for a grader
        to recognise the answers it gives; None (the default) constructs it right.

    Returns
    -------
    MotionConstruction
        Not ``valid`` (with the reason) where the position cannot be assembled, the polygon's lines are
        parallel (a dead point), or a value it yields differs from the analytical kinematics
        (:mod:`graphkin.graphical.guard`; a construction made with a ``slip`` is not compared).
    """
    if not isinstance(kin, Kinematics):
        raise GraphkinError(f"construct_kinematics takes the Kinematics of a problem (problem.kinematics()), "
                            f"got {type(kin).__name__}")
    if isinstance(index, (bool, np.bool_)) or not isinstance(index, (int, np.integer)) or not -kin.n <= index < kin.n:
        raise GraphkinError(f"construct_kinematics: index must be a whole number from 0 to {kin.n - 1} (one of the "
                            f"{kin.n} positions), got {index!r}")
    if slip is not None and slip not in SLIPS:
        raise GraphkinError(f"construct_kinematics: slip must be None or one of {', '.join(SLIPS)}, got {slip!r}")
    index = int(index) % kin.n
    mech = kin.mechanism
    q = float(kin.q[index])
    if not kin.valid[index]:
        return MotionConstruction(mech, index, q, valid=False, reason=kin.reason(index))
    own, at = derived(kin, index)  # the input motion's own kinematics: a problem's given values left out
    b = _Polygons(own, at, slip)
    if kin.given:
        # Values a problem gives (measured off its drawing) are what the force route uses; the polygons are the
        # construction from the input motion, so say which of the two the reader is looking at.
        named = sorted({f"{k[1]} of link {k[0]}" for k in kin.given if k[1] != "at"})
        b.step("velocity", "note", f"The problem gives {', '.join(named) or 'point positions'} instead of deriving "
               "them; these polygons are constructed from the input motion alone (the linkage placed by it) and "
               "may differ from those values.", ())
    try:
        b.run()
    except Degenerate as exc:
        b.step("velocity" if not any(s.polygon == "acceleration" for s in b.steps) else "acceleration", "note",
               f"{exc}.", ())
        return MotionConstruction(mech, index, q, tuple(b.steps), valid=False, reason=str(exc))
    velocity = {key: (z.real, z.imag) for key, z in b.velocity.items() if key[1] is not None}
    acceleration = {key: (z.real, z.imag) for key, z in b.acceleration.items() if key[1] is not None}
    v_G = {link: (z.real, z.imag) for (link, name), z in b.velocity.items() if name is None}
    a_G = {link: (z.real, z.imag) for (link, name), z in b.acceleration.items() if name is None}
    omega = {link: float(m.w) for link, m in b.motion.items()}
    alpha = {link: float(m.al) for link, m in b.motion.items()}
    top_v = max([math.hypot(*v) for v in b.v_img.values()] + [0.0])
    top_a = max([math.hypot(*a) for a in b.a_img.values()] + [0.0])
    c = MotionConstruction(mech, index, q, tuple(b.steps), omega, alpha, velocity, acceleration, v_G, a_G,
                           {"velocity": dict(b.v_img), "acceleration": dict(b.a_img)},
                           nice_scale(top_v), nice_scale(top_a))
    if slip is None:
        # Checked against the analytical kinematics before anyone sees it: a disagreement is a reason, not a number.
        why = motion_disagreement(own, at, c, b.where, b.coriolis)
        if why:
            b.step("acceleration", "note", f"{why}.", ())
            return MotionConstruction(mech, index, q, tuple(b.steps), valid=False, reason=why, disagreement=True)
    return c
