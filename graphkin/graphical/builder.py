"""The graphical construction, group by group: the steps a person draws, with the forces they find.

For one position, the groups of the kinematic decomposition are taken in
reverse order, as in the analytical solver, but each is solved the way it is
drawn:

1. each loaded link's known loads are combined into one resultant R — for
   inertia alone, −m a_G on a line offset from G by h = |T|/|F|;
2. in a dyad with one link loaded, the unloaded link is a two-force member,
   which fixes the line of the force it passes on (along its two pins;
   through its pin, normal to its guide; or through its pin, normal to a slot
   in the loaded link);
3. the loaded link is then a three-force member: its resultant, that line and
   the reaction at its other joint meet in one point, found with shapely; the
   force polygon closes tip to tail (a guide reaction has a known direction
   instead, so the polygon alone gives both sizes); reactions found are loads
   on the links of the groups before;
4. the driver: the crank's pivot force and the resultant on the crank form a
   couple T = F·d, or the slider's polygon gives the driving force.

When a dyad has both links loaded, the steps are a superposition as books
write it (docs/graphical.md): one sub-problem per loaded link, with every
other link unloaded, each announced, solved through to its own driving
effort and read off; then the sum of every joint force and the driver with
the summed reactions. The whole problem is solved first, unshown, for the
side of each guide's friction and each tooth's flank, which the
sub-problems keep so that they add up; a sub-problem that loads both links
of a dyad again is split once more into parts.

Magnitudes are read off exactly: a force along a known line is found from
moments about the other joint (the polygon's closing side, computed rather
than measured), so the construction agrees with the matrix solution to
rounding. Friction at a guide tilts its reaction by atan μ against the
sliding; the sense of the tilt depends on the side the normal force pushes,
so the construction assumes a side, checks it, and redoes the polygon if the
assumption was wrong.
"""

from __future__ import annotations

import cmath
import itertools
import math
import struct

import numpy as np
import shapely

from graphkin.analytical.loads import applied_at
from graphkin.analytical.meshes import contact
from graphkin.geometry import zcross as cross
from graphkin.geometry import zdot as dot
from graphkin.graphical.captions import Later, and_list, number, polar, sense
from graphkin.graphical.construction import Arrow, Line, Step
from graphkin.kinematics import DriverGroup, Dyad, GearGroup, Kinematics
from graphkin.model import PointForce, Prismatic, Revolute, Torque
from graphkin.notation import PICOMETRE, largest, unless_rounding

CLOSE = 1e-9
"""Relative tolerance of the closure check of a polygon."""


def xy(z) -> tuple[float, float]:
    if type(z) is complex:  # most are: its parts are floats already
        return (z.real, z.imag)
    return (float(z.real), float(z.imag))


class _Load:
    """A set of loads reduced to the origin: force F (complex) and moment M0 about the origin."""

    def __init__(self, F=0j, M0=0.0):
        self.F, self.M0 = complex(F), float(M0)

    def add(self, F, at=None, couple=0.0):
        self.F += F
        self.M0 += (cross(at, F) if at is not None else 0.0) + couple

    def about(self, X) -> float:
        """Moment about point X."""
        return self.M0 - cross(X, self.F)

    def point(self):
        """The point of the resultant's line nearest the origin (None for a pure couple)."""
        if self.F == 0:
            return None
        # F/|F|² written as 1/conj(F): |F|² underflows to 0 for a force of 1e-170 N, the quotient does not.
        # Plain complex numbers: a force so small beside its moment that its line lies beyond any float gives
        # inf quietly, and is then a pure couple.
        P = complex(-1j * float(self.M0)) / complex(self.F).conjugate()
        return P if cmath.isfinite(P) else None


_LINES = struct.Struct("8d")


def _meet(p, u, q, w, reach):
    """Intersection of two lines with shapely, or None when they are parallel.

    The segments are drawn long enough (``reach``) to meet wherever the lines do.
    """
    den = cross(u, w)
    if abs(den) <= 1e-12 * abs(u) * abs(w):
        return None
    t = cross(q - p, w) / den
    s = cross(q - p, u) / den
    L = 2 * max(abs(t), abs(s), reach)
    # Both segments in one call: shapely's array form skips the per-geometry constructor.
    a, b = shapely.linestrings([[xy(p - L * u), xy(p + L * u)], [xy(q - L * w), xy(q + L * w)]])
    hit = shapely.intersection(a, b)
    if hit.is_empty or hit.geom_type != "Point":
        return p + t * u
    return complex(hit.x, hit.y)


class Builder:
    """Builds the construction of one position: the whole problem, or one sub-problem of a superposition.

    A sub-problem's builder shares the list of steps and warnings of the
    presentation, marks its forces (``F23′``), says which sub-problem it is
    in (``scope``), and takes the side of each guide's friction and the flank
    of each tooth force from the whole problem (``fixed``) instead of
    finding them, so that the sub-problems add up.
    """

    def __init__(self, kin: Kinematics, i: int, *, sub: str = "", mark: str = "", scope: str = "",
                 fixed: dict | None = None, steps: list | None = None, warnings: list | None = None,
                 like: "Builder | None" = None):
        self.kin, self.i = kin, i
        self.mech = kin.mechanism
        self.steps: list[Step] = [] if steps is None else steps
        self.warnings: list[str] = [] if warnings is None else warnings
        self.forces, self.normal, self.couple = {}, {}, {}
        self.effort = math.nan
        self.rname: dict[int, str] = {}
        self.driver_vector = None
        self.sub, self.mark, self.scope = sub, mark, scope
        self.fixed = fixed
        # The side each friction guide's reaction tilts to, the sense of a slider driver's normal force, the flank
        # of each tooth force, by id of the joint: what the sub-problems must share with the whole problem.
        self.sides: dict[int, float] = {}
        # Every joint, in the order its force is found, with the link the force's name puts it on (F23: on 3).
        self.order: dict[int, tuple] = {}
        # Reactions passed on to the links of the groups still to solve: link -> [(name unmarked, name, F, X, couple)].
        self.passed: dict[int, list] = {}
        self.superposed: list[str] = []  # the dyads found with both links loaded
        self.contacts: dict[tuple, tuple] = {}  # where each mesh's tooth force acts: (lo, hi) -> (x, y) [m]
        # Positions of points, guide directions and slide senses are the same in every sub-problem: ``like`` (another
        # builder of this position) shares them.
        self._z: dict = like._z if like is not None else {}
        self._u: dict = like._u if like is not None else {}
        # Each link's own loads, and the step that states them, are the same for the whole problem and the
        # superposition's presentation: found once (by link, for builders of the whole problem only).
        self._own: dict = like._own if like is not None else {}
        self._applied: dict = like._applied if like is not None else {}
        self._names: dict = like._names if like is not None else {}
        self._motion: dict = like._motion if like is not None else {}
        self._meets: dict = like._meets if like is not None else {}
        if like is not None:
            self.reach = like.reach
        else:
            pts = [self.z(link, p) for link in self.mech.moving for p in self.mech.link(link).points]
            # Each pair once: |a − b| and |b − a| are the same number.
            self.reach = max((abs(a - b) for k, a in enumerate(pts) for b in pts[k + 1:]), default=0.0) or 1.0

    def rounding(self, F: complex, M: float = 0.0) -> bool:
        """Whether a force ``F`` [N] and a moment ``M`` [N·m] are rounding beside the largest force found so far in
        this (sub-)problem (times a metre, for the moment): what the captions then say is 0."""
        scale = largest(self.forces.values())
        return unless_rounding(abs(F), scale) == 0 and unless_rounding(M, scale) == 0

    def step(self, kind, caption, link=None, lines=(), points=None, polygon=(), values=None) -> Step:
        return Step(kind, caption, link, tuple(lines), points or {}, tuple(polygon), values or {}, self.sub)

    def add(self, *args, **kwargs) -> Step:
        self.steps.append(self.step(*args, **kwargs))
        return self.steps[-1]

    def lead(self, text: str) -> str:
        """``"In sub-problem I, link 4 …"`` in a sub-problem, ``"Link 4 …"`` in the whole problem."""
        return _lead(self.scope, text)

    def within(self) -> str:
        """``" in sub-problem I"`` or ``""``."""
        return f" in {self.scope}" if self.scope else ""

    # -- geometry at this position -----------------------------------------
    def z(self, link, point) -> complex:
        """Position of a point of ``link`` (a name or local (x, y)) at this position [m]."""
        key = (link, point) if type(point) is str else (link, tuple(point))
        z = self._z.get(key)
        if z is None:
            z = self._z[key] = complex(self.kin.z(link, point)[self.i])
        return z

    def meet(self, p: complex, u: complex, q: complex, w: complex):
        """Where the lines through p along u and through q along w meet (:func:`_meet`), or None.

        A sub-problem often draws the very lines the whole problem drew (a dyad's part with the same load):
        each pair of lines is intersected once per position, keyed by the bits of its numbers (−0.0 is not 0.0).
        """
        key = _LINES.pack(p.real, p.imag, u.real, u.imag, q.real, q.imag, w.real, w.imag)
        if key not in self._meets:
            self._meets[key] = _meet(p, u, q, w, self.reach)
        return self._meets[key]

    def motion(self, link):
        """Acceleration of G [m/s²] (complex) and α [rad/s²] of ``link`` at this position, as numpy scalars."""
        found = self._motion.get(link)
        if found is None:
            found = self._motion[link] = (self.kin.z_a_G(link)[self.i], self.kin.al(link)[self.i])
        return found

    def applied(self, load):
        """What an external load applies at this position: complex force [N] or torque [N·m], 0 where it does not act."""
        key = id(load)
        if key not in self._applied:
            self._applied[key] = applied_at(self.kin, load, self.i)
        return self._applied[key]

    def joint_point(self, joint, link):
        return self.z(joint.slider, joint.point) if isinstance(joint, Prismatic) else self.z(link, joint.point)

    def u(self, joint: Prismatic) -> complex:
        """Unit vector along the guide of ``joint`` at this position."""
        key = id(joint)
        if key not in self._u:
            self._u[key] = complex(self.kin.z_guide(joint)[self.i])
        return self._u[key]

    def slide_sense(self, joint: Prismatic, on: int):
        """Sense of the sliding of ``on`` along the guide of ``joint`` (+1, −1, or 0 where it is still)."""
        key = (id(joint), on)
        if key not in self._u:
            # Kept a numpy scalar: the friction tilt is then computed exactly as before it was cached.
            self._u[key] = self.kin.slide_sense(joint, on)[self.i]
        return self._u[key]

    def w(self, joint: Prismatic, on: int, sigma: float):
        """Direction of the guide reaction on ``on`` per unit normal force (friction tilt included)."""
        u = self.u(joint)
        w = 1j * u
        if joint.mu:
            w -= joint.mu * sigma * self.slide_sense(joint, on) * u
        return w

    def base_name(self, i, j):
        name = self._names.get((i, j))
        if name is None:
            letter = self.mech.joint_between(i, j).force_letter
            name = self._names[i, j] = f"{letter}{i}{j}" if i < 10 and j < 10 else f"{letter}{i},{j}"
        return name

    def name(self, i, j):
        return self.base_name(i, j) + self.mark

    # -- loads ---------------------------------------------------------------
    def own_loads(self, link) -> _Load:
        """Inertia, weight and external loads of a link, with a step explaining its resultant."""
        if self.sub or link not in self._own:
            found = self._own_loads(link)
            if not self.sub:
                self._own[link] = found
        else:
            found = self._own[link]
        F, M0, self.rname[link], step = found
        if step is not None:
            self.steps.append(step)
        return _Load(F, M0)

    def _own_loads(self, link) -> tuple[complex, float, str, Step | None]:
        """A link's own loads reduced to the origin (F, M0), the name of their resultant, and the step stating them."""
        kin, body = self.kin, self.mech.link(link)
        load = _Load()
        G = self.z(link, body.G)
        # A static analysis has no inertia loads: the links carry their weights and external loads only.
        a_G, alpha = self.motion(link) if (body.mass or body.I_G) and not kin.static else (0j, 0.0)
        Fi = complex(-body.mass * a_G) if body.mass and not kin.static else 0j
        Ti = float(-body.I_G * alpha) if body.I_G and not kin.static else 0.0
        load.add(Fi, G, Ti)
        parts = []
        lines = []
        values = {}
        if Fi or Ti:
            values[f"F{link}i"], values[f"T{link}i"] = xy(Fi), Ti
            if Fi:
                h = abs(Ti) / abs(Fi)
                values["h"] = h
                # The offset side makes the moment of F about G equal T.
                P = G - 1j * Ti / Fi.conjugate()  # Ti Fi/|Fi|², without squaring a small |Fi| to 0
                lines.append(Line(f"R{link}i", xy(P), xy(Fi / abs(Fi)), "resultant"))
                # An offset under a picometre is rounding (α = 0 but for it): the force acts through G.
                parts.append(Later(_inertia_offset, link, Fi, Ti, h) if h > PICOMETRE else
                             Later(_inertia_through_G, link, Fi))
            else:
                parts.append(Later(lambda link, Ti: f"its inertia torque T{link}i = {number(Ti)} N·m is a pure couple",
                                   link, Ti))
        if self.mech.gravity and body.mass:
            W = -1j * body.mass * self.mech.gravity
            load.add(W, G)
            parts.append(Later(lambda link, W: f"its weight {number(abs(W))} N acts at G{link}", link, W))

        for ld in self.mech.loads:
            if ld.link != link:
                continue
            value = self.applied(ld)
            if not value:  # not acting here (outside its window, a table's zero, or at rest on its working stroke)
                continue
            if isinstance(ld, PointForce):
                F = complex(value)
                load.add(F, self.z(link, ld.point))
                parts.append(Later(lambda name, F, at: f"the external force {name} = {number(abs(F))} N acts at {at}",
                                   ld.name or "P", F, ld.point))
            elif isinstance(ld, Torque):
                load.add(0j, None, value)
                parts.append(Later(lambda name, T: f"the external torque {name} = {number(T)} N·m acts on it",
                                   ld.name or "T", value))
        only_inertia = len(parts) == 1 and bool(Fi or Ti)
        rname = f"R{link}i" if only_inertia else f"R{link}"
        if len(parts) > 1 and load.F and load.point() is not None:
            lines.append(Line(f"R{link}", xy(load.point()), xy(load.F / abs(load.F)), "resultant"))
            values[f"R{link}"] = xy(load.F)
            parts.append(Later(lambda link, F: f"together they make one resultant R{link} = {number(abs(F))} N",
                               link, load.F))
        step = self.step("resultant", Later(_own_text, link, tuple(parts)), link, lines, values=values) if parts else None
        return load.F, load.M0, rname, step

    def combine(self, link, load: _Load, extra: list):
        """Add reactions (name, force, point, couple) from groups solved before; one resultant R for the link."""
        own, own_name = bool(load.F or load.M0), self.rname.get(link, f"R{link}")
        for _, F, X, C in extra:
            load.add(F, X, C)
        if extra:
            R = self.rname[link] = f"R{link}{self.mark}"
            names = tuple(n for n, _, _, _ in extra)
            P = load.point()
            nothing = P is not None and self.rounding(load.F)
            # A resultant that is rounding has no line: its direction would be the rounding's.
            lines = (Line(R, xy(P), xy(load.F / abs(load.F)), "resultant"),) if P is not None and not nothing else ()
            # The own loads' name only when it differs from the new one (a crank's weight alone is R2 too).
            mine = (f" ({own_name})" if own_name != R else "") if own else None
            self.add("resultant", Later(_combined_text, self.scope, link, R, names, mine, nothing, P is not None, load.F,
                                        load.M0), link, lines, values={R: xy(load.F)})
        return load

    # -- dyads -----------------------------------------------------------------
    def m_line(self, d: Dyad, L: int, sigma):
        """Line (point, direction) of the force the unloaded partner of L passes to L, or None (couple only)."""
        if L == d.j:
            M, JM = d.k, d.J3
        else:
            M, JM = d.j, d.J1
        J2 = d.J2
        if isinstance(J2, Revolute) and isinstance(JM, Revolute):
            X2, XM = self.z(M, J2.point), self.z(M, JM.point)
            text = f"along {JM.point}{J2.point}, the line through its two pins"
            return X2, (XM - X2) / abs(XM - X2), M, text
        if isinstance(J2, Revolute):
            X2 = self.z(M, J2.point)
            w = self.w(JM, M, sigma[id(JM)])
            text = f"through {J2.point}, along the reaction of its guide (normal to the guide" + (
                ", tilted by the friction angle)" if JM.mu else ")")
            return X2, w / abs(w), M, text
        if isinstance(JM, Revolute):
            XM = self.z(M, JM.point)
            w = self.w(J2, d.k, sigma[id(J2)])
            return XM, w / abs(w), M, f"through its pin {JM.point}, normal to the sliding pair at {J2.point}"
        return None, None, M, "as a couple only (two guides cannot balance a force)"

    def sub_construction(self, d: Dyad, L: int, R: _Load, sigma):
        """Forces on L (and through J2) when only L is loaded. Returns {joint id: force on the dyad link}."""
        JL = d.J1 if L == d.j else d.J3
        RL = self.rname[L]
        M_point, M_dir, M, how = self.m_line(d, L, sigma)
        # On L the passed force acts at L's own middle pin (the same point unless a link's angle is given).
        on_L = self.z(L, d.J2.point) if M_point is not None and isinstance(d.J2, Revolute) else M_point
        nM, nL = self.name(M, L), self.name(_other(JL, L), L)
        steps = []
        steps.append(self.step("two-force", self.lead(f"link {M} carries no load, so it is a two-force member: {nM} acts "
                                                      f"{how}."), M,
                               (Line(nM, xy(M_point), xy(M_dir)),) if M_point is not None else ()))
        Rp = R.point()
        lines = []
        if Rp is not None:
            lines.append(Line(RL, xy(Rp), xy(R.F / abs(R.F)), "resultant"))
        if M_point is None:
            # The partner passes a couple only: the outer pin force balances R alone.
            XL = self.z(L, JL.point)
            F_out = -R.F
            steps.append(self.step("polygon", self.lead(f"{nL} = −{RL} acts at {JL.point}; the couple they form is taken by "
                                                        "the sliding pairs."),
                                   L, lines, polygon=(Arrow(RL, xy(R.F), True), Arrow(nL, xy(F_out), False, xy(XL))),
                                   values={nL: xy(F_out)}))
            self.steps.extend(steps)
            return {id(d.J1): 0j, id(d.J3): 0j, id(JL): F_out, id(d.J2): 0j}
        if isinstance(JL, Revolute):
            XL = self.z(L, JL.point)
            arm = cross(on_L - XL, M_dir)
            if abs(arm) <= 1e-12 * self.reach:
                raise DeadPoint(f"the line of {nM} passes through {JL.point}, so link {L} cannot be balanced (dead point)")
            a = -R.about(XL) / arm
            F_M = a * M_dir
            F_out = -R.F - F_M
            points = {}
            if Rp is None:
                text = f"{RL} is a pure couple, so {nM} and {nL} form the opposite couple: {nL} is parallel to {nM}"
            else:
                I = self.meet(Rp, R.F / abs(R.F), on_L, M_dir)
                if abs(R.about(XL)) <= 1e-12 * abs(R.F) * self.reach:
                    text = (f"{RL} already passes through {JL.point}, so the three lines cannot meet elsewhere: "
                            f"{nM} is zero and {nL} = −{RL}")
                elif I is None:
                    text = (f"{RL} is parallel to {nM}: they meet at infinity, so {nL} is parallel to both; "
                            f"moments about {JL.point} give its size")
                else:
                    points[f"I{L}"] = xy(I)
                    text = (f"link {L} is a three-force member: {RL}, {nM} and {nL} meet in one point I{L} "
                            f"(where {RL} crosses the line of {nM}); {nL} passes through {JL.point} and I{L}")
                    if F_out != 0 and abs(cross(I - XL, F_out)) > 1e-7 * abs(I - XL) * abs(F_out):
                        self.warnings.append(f"{nL} misses the concurrency point I{L}")
                lines.append(Line(nL, xy(XL), xy(F_out / abs(F_out)) if F_out else (1.0, 0.0), "found"))
            lines.append(Line(nM, xy(on_L), xy(M_dir)))
            steps.append(self.step("three-force", self.lead(text) + ".", L, lines, points))
        else:
            wL = self.w(JL, L, sigma[id(JL)])
            a, b = _decompose(-R.F, M_dir, wL)
            F_M, F_out = a * M_dir, b * wL
            points = {}
            if Rp is not None:
                I = self.meet(Rp, R.F / abs(R.F), on_L, M_dir)
                if I is not None:
                    points[f"I{L}"] = xy(I)
                    lines.append(Line(nL, xy(I), xy(wL / abs(wL)), "found"))
            lines.append(Line(nM, xy(on_L), xy(M_dir)))
            steps.append(self.step("three-force", self.lead(
                f"the guide force {nL} has a known direction (normal to the guide"
                + (", tilted by the friction angle" if JL.mu else "") + f"), so the polygon of {RL}, {nM} and {nL} "
                f"gives both sizes; its line passes through the point where {RL} crosses {nM}."), L, lines, points))
        poly = (Arrow(RL, xy(R.F), True), Arrow(nM, xy(F_M), False), Arrow(nL, xy(F_out), False))
        steps.append(self.step("polygon", f"Force polygon of link {L}{self.within()}: {RL} + {nM} + {nL} = 0, tip to tail.",
                               L, polygon=poly, values={nM: xy(F_M), nL: xy(F_out)}))
        self._check(steps[-1])
        self.steps.extend(steps)
        # The unloaded partner M passes F_M straight on: its outer joint pushes on it with F_M too.
        return {id(JL): F_out, id(d.J2): F_M if L == d.k else -F_M, id(d.J1 if L == d.k else d.J3): F_M}

    def dyad(self, d: Dyad, R: dict):
        friction = [J for J in d.joints if isinstance(J, Prismatic) and J.mu > 0]
        if self.fixed is not None:
            # A sub-problem: the sides are the whole problem's, right or not for these loads alone.
            sigma = {id(J): 1.0 for J in d.joints if isinstance(J, Prismatic)}
            sigma.update({id(J): self.fixed[id(J)] for J in friction})
            return self._superpose(d, R, sigma)
        mark = len(self.steps)
        for signs in itertools.product((1.0, -1.0), repeat=len(friction)):
            del self.steps[mark:]
            sigma = {id(J): 1.0 for J in d.joints if isinstance(J, Prismatic)}
            sigma.update(zip(map(id, friction), signs))
            F = self._superpose(d, R, sigma)
            if F is None:
                return None
            bad = [J for J in friction if F["N"][id(J)] * sigma[id(J)] < 0]
            if not bad:
                self.sides.update({id(J): sigma[id(J)] for J in friction})
                if friction:
                    self.steps.insert(mark, self.step("note", "Friction: the guide reaction is tilted by atan μ against the "
                                                      "sliding; its sense depends on the side the normal force pushes. "
                                                      "The side assumed below is confirmed by the result.", d.j))
                return F
        raise DeadPoint(f"friction locks the {d.label}: no side of the normal force is consistent")

    def _parts(self, d: Dyad, loaded: list, R: dict, sigma) -> list:
        """Both links of the dyad loaded: one part per link, the other unloaded, each announced, then added."""
        sub, mark, scope = self.sub, self.mark, self.scope
        letters = "abcdefgh"[: len(loaded)]
        self.add("note", self.lead(
            f"links {d.j} and {d.k} both carry loads ({and_list([self.rname[L] for L in loaded])}), so neither is a "
            f"two-force member: the dyad is split once more, " + ", ".join(
                f"part ({x}) with only the loads on link {L}" for x, L in zip(letters, loaded))
            + ", and the parts are added."), d.j)
        parts = []
        for x, L in zip(letters, loaded):
            self.sub = f"{sub}.{x}" if sub else x
            self.mark = mark + x
            self.scope = f"part ({x}) of {scope}" if scope else f"part ({x})"
            other = d.k if L == d.j else d.j
            self.add("sub-problem", f"{self.scope[0].upper()}{self.scope[1:]}: only the loads on link {L} "
                     f"({self.rname[L]}); link {other} is unloaded. Its forces are marked {self.mark}.", L)
            parts.append((x, self.sub_construction(d, L, R[L], sigma)))
        self.sub, self.mark, self.scope = sub, mark, scope
        return parts

    def _superpose(self, d: Dyad, R: dict, sigma):
        loaded = [L for L in (d.j, d.k) if abs(R[L].F) > 0 or R[L].M0 != 0]
        total = {id(J): 0j for J in d.joints}
        joints = ((d.J1, d.j), (d.J2, d.k), (d.J3, d.k))
        for J, on in joints:
            self.order.setdefault(id(J), (J, on))
        if not loaded:
            self.add("note", self.lead(f"links {d.j} and {d.k} carry no load, so their joint forces are zero."), d.j)
        if len(loaded) > 1:
            self.superposed.append(d.label)
            parts = self._parts(d, loaded, R, sigma)
            for _, part in parts:
                for key, F in part.items():
                    total[key] += F
            for J, on in joints:
                other = _other(J, on)
                n = self.name(other, on)
                arrows = [Arrow(f"{n}{x}", xy(p[id(J)]), True) for x, p in parts]
                # The closing side runs back to the start: it is −(the sum).
                self.add("superpose", Later(lambda scope, n, arrows, F: _lead(
                    scope, f"{n} is the sum of its parts: {n} = " + " + ".join(a.name for a in arrows) + f" = {polar(F)}."),
                    self.scope, n, arrows, total[id(J)]),
                         on, polygon=tuple(arrows) + (Arrow(f"−{n}", xy(-total[id(J)]), False),),
                         values={n: xy(total[id(J)])})
        elif loaded:
            for key, F in self.sub_construction(d, loaded[0], R[loaded[0]], sigma).items():
                total[key] += F
        X = {id(J): self.joint_point(J, on) for J, on in joints}
        F1, F2, F3 = total[id(d.J1)], total[id(d.J2)], total[id(d.J3)]
        # Couples of sliding pairs (where their lines act) from each link's moment balance.
        Mj = R[d.j].M0 + cross(X[id(d.J1)], F1) - cross(self.joint_point(d.J2, d.j), F2)
        Mk = R[d.k].M0 + cross(X[id(d.J2)], F2) + cross(X[id(d.J3)], F3)
        C = {id(J): 0.0 for J in d.joints}
        P1, P2, P3 = (isinstance(J, Prismatic) for J in d.joints)
        if P2 and P3:
            C[id(d.J2)] = Mj if not P1 else 0.0
            C[id(d.J3)] = -(Mk + C[id(d.J2)])
        elif P2:
            C[id(d.J2)] = Mj
        else:
            if P1:
                C[id(d.J1)] = -Mj
            if P3:
                C[id(d.J3)] = -Mk
        residual = abs(Mj - C[id(d.J2)] + C[id(d.J1)]) + abs(Mk + C[id(d.J2)] + C[id(d.J3)])
        scale = max(abs(R[d.j].F) + abs(R[d.k].F), 1e-300) * self.reach + abs(R[d.j].M0) + abs(R[d.k].M0)
        if residual > 1e-8 * scale:
            self.warnings.append(f"{d.label}: the moments do not balance (residual {residual:.3g} N·m)")
        N = {}
        for J, on, F in ((d.J1, d.j, F1), (d.J2, d.k, F2), (d.J3, d.k, F3)):
            self.store(J, on, F, C[id(J)])
            if isinstance(J, Prismatic):
                N[id(J)] = dot(F, 1j * self.u(J))
        return {"F": total, "N": N}

    def store(self, joint, on, F, C=0.0):
        lo, hi = sorted(joint.links)
        sign = 1.0 if on == hi else -1.0
        self.forces[(lo, hi)] = xy(sign * F)
        if isinstance(joint, Prismatic):
            self.normal[(lo, hi)] = float(dot(sign * F, 1j * self.u(joint)))
            self.couple[(lo, hi)] = float(sign * C)

    # -- gears and the driver ----------------------------------------------------
    def gear(self, g: GearGroup, R: _Load):
        mesh = g.mesh
        Ck, Cj = self.z(g.b, g.ck), self.z(g.b, g.cj)
        self.order.setdefault(id(mesh), (mesh, g.k))
        self.order.setdefault(id(g.pivot), (g.pivot, g.k))
        if R.F == 0 and R.M0 == 0:
            P = contact(mesh, g.k, Ck, Cj)[0]
            self.add("note", self.lead(f"gear {g.k} carries no load, so its tooth and pivot forces are zero."), g.k)
            self.store(g.mesh, g.k, 0j)
            self.store(g.pivot, g.k, 0j)
            self.contacts[tuple(sorted(mesh.links))] = xy(P)
            return {id(g.mesh): (0j, P), id(g.pivot): (0j, Ck)}
        # The flank the tooth force presses on follows the tangential load; a sub-problem keeps the whole problem's,
        # and with it the way the power flows through the mesh (which gear loses to the efficiency).
        flank = float(np.sign(-R.about(Ck))) if self.fixed is None else self.fixed.get(id(mesh), 0.0)
        self.sides[id(mesh)] = flank
        flow = 0.0
        if mesh.efficiency < 1:  # the power into gear k, relative to the carrier: which side loses
            flow = flank * float(np.sign(self.kin.omega[g.k][self.i] - self.kin.omega[g.b][self.i]))
        P, t, r, rho = contact(mesh, g.k, Ck, Cj, flow)
        self.contacts[tuple(sorted(mesh.links))] = xy(P)
        d = t + flank * math.tan(mesh.pressure_angle) * r
        d /= abs(d)
        nW, nF = self.name(g.j, g.k), self.name(g.support, g.k)
        Rk = self.rname[g.k]
        # Each mesh's pitch point its own name, as the drawing of the mechanism labels it: P34, not a second "P".
        pitch = "P" + "".join(str(n) for n in sorted(mesh.links))
        if flow:
            where = Later(lambda scope, nW, angle, k, eta, rho, rk, driven, pitch: _lead(
                scope, f"the tooth force {nW} lies on a line inclined {number(math.degrees(angle))}° to the common "
                f"tangent, on the flank that opposes the load on gear {k}; with the mesh efficiency η = {number(eta)} "
                f"it crosses the line of centres at {pitch}′, {number(rho * 1e3)} mm from gear {k}'s centre instead of "
                f"the pitch radius {number(rk * 1e3)} mm, so that the driven gear {driven} receives η times the ideal "
                f"torque (relative to the carrier)."), self.scope, nW, mesh.pressure_angle, g.k, mesh.efficiency,
                rho, mesh.radius(g.k), g.k if flow > 0 else g.j, pitch)
            self.add("line", where, g.k, (Line(nW, xy(P), xy(d)),), {f"{pitch}′": xy(P)})
        else:
            self.add("line", Later(lambda scope, nW, angle, k, pitch: _lead(
                scope, f"the tooth force {nW} lies on the pressure line through the pitch point {pitch}, inclined "
                f"{number(math.degrees(angle))}° to the common tangent, on the flank that opposes the load on gear "
                f"{k}."), self.scope, nW, mesh.pressure_angle, g.k, pitch), g.k, (Line(nW, xy(P), xy(d)),),
                {pitch: xy(P)})
        arm = cross(P - Ck, d)
        F_W = (-R.about(Ck) / arm) * d
        F_piv = -R.F - F_W
        points = {}
        Rp = R.point()
        if Rp is not None:
            I = self.meet(Rp, R.F / abs(R.F), P, d)
            if I is not None:
                points[f"I{g.k}"] = xy(I)
        pivot_line = (Line(nF, xy(Ck), xy(F_piv / abs(F_piv)) if F_piv else (1.0, 0.0), "found"),)
        # A gear loaded by a couple alone (its own weight and inertia force
        # nil, e.g. an input torque) is no three-force member: the tooth and
        # pivot forces are then the opposite couple, equal and opposite.
        if abs(R.F) <= 1e-9 * abs(F_W):
            self.add("couple", Later(lambda k, M0, within, nW, nF, at: f"Gear {k} carries only a couple ({number(M0)} N·m)"
                                     f"{within}: {nW} and the pivot force {nF} form the opposite couple, so {nF} = −{nW}, "
                                     f"through the centre {at}.", g.k, R.M0, self.within(), nW, nF, g.pivot.point),
                     g.k, pivot_line, points)
            poly = (Arrow(nW, xy(F_W), False), Arrow(nF, xy(F_piv), False))
            caption = f"Force polygon of gear {g.k}{self.within()}: {nW} + {nF} = 0."
        else:
            self.add("three-force", f"Gear {g.k} is a three-force member{self.within()}: {Rk}, {nW} and the pivot force "
                     f"{nF} meet in one point; {nF} passes through the centre {g.pivot.point}.", g.k, pivot_line, points)
            poly = (Arrow(Rk, xy(R.F), True), Arrow(nW, xy(F_W), False), Arrow(nF, xy(F_piv), False))
            caption = f"Force polygon of gear {g.k}{self.within()}: {Rk} + {nW} + {nF} = 0."
        self._check(self.add("polygon", caption, g.k, polygon=poly, values={nW: xy(F_W), nF: xy(F_piv)}))
        self.store(g.mesh, g.k, F_W)
        self.store(g.pivot, g.k, F_piv)
        return {id(g.mesh): (F_W, P), id(g.pivot): (F_piv, Ck)}

    def driver(self, g: DriverGroup, R: _Load, total: str = ""):
        """The input link's equilibrium; ``total`` is added to the caption (the sum of the sub-problems' efforts)."""
        link, J = g.link, g.joint
        name = self.name(self.mech.frame, link)
        drive = self.mech.driver.symbol + self.mark
        Rd = self.rname[link]
        self.order.setdefault(id(J), (J, link))
        what = "crank" if isinstance(J, Revolute) else "slider"
        if R.F == 0 and R.M0 == 0:
            self.add("driver", f"The {what}{self.within()} carries no load: {name} = 0 and {drive} = 0.", link,
                     values={name: (0.0, 0.0), drive: 0.0 if what == "crank" else (0.0, 0.0)})
            self.store(J, link, 0j)
            self.effort = 0.0
            self.driver_vector = None if what == "crank" else (0.0, 0.0)
            return
        if isinstance(J, Revolute):
            X = self.z(link, J.point)
            F = -R.F
            T = float(-R.about(X))
            # Plain floats: a resultant tiny beside its moment (a pure couple in all but rounding) gives an arm
            # too long for a float, which is said in words rather than as a numpy overflow.
            d = abs(T) / abs(complex(R.F)) if R.F else 0.0
            dn = "d" + self.mark
            nothing = self.rounding(R.F, R.M0)
            self.add("driver", Later(_crank_text, self.within(), name, Rd, J.point, drive, dn, nothing, d, T, total), link,
                     () if nothing else (Line(name, xy(X), xy(F / abs(F)) if F else (1.0, 0.0), "found"),),
                     values={name: xy(F), drive: T, **({"d": d} if math.isfinite(d) else {})},
                     polygon=(Arrow(Rd, xy(R.F), True), Arrow(name, xy(F), False, xy(X))))
            self.store(J, link, F)
            self.effort = float(T)
            self.driver_vector = None
            return
        u = self.u(J)
        X = self.z(link, J.point)
        N = -dot(R.F, 1j * u)
        # The side of the guide's friction follows the normal force; a sub-problem keeps the whole problem's.
        side = float(np.sign(N)) if self.fixed is None else self.fixed.get(id(J), 0.0)
        self.sides[id(J)] = side
        w = self.w(J, link, side)
        b, P = _decompose(-R.F, w, u)
        G, Fd = b * w, P * u
        C = -(R.M0 + cross(X, G + Fd))
        self._check(self.add(
            "driver",
            Later(lambda within, drive, name, mu, Rd, total: f"The slider{within}: the driving force {drive} acts along "
                  f"the guide and the guide force {name} normal to it" + (" (tilted by the friction angle)" if mu else "")
                  + f"; the polygon {Rd} + {name} + {drive} = 0 gives both" + (f"; {total}." if total else "."),
                  self.within(), drive, name, J.mu, Rd, total),
            link, (Line(drive, xy(X), xy(u), "found"),),
            polygon=(Arrow(Rd, xy(R.F), True), Arrow(name, xy(G), False), Arrow(drive, xy(Fd), False, xy(X))),
            values={name: xy(G), drive: xy(Fd)}))
        self.store(J, link, G, C)
        self.effort = float(P)
        self.driver_vector = xy(Fd)

    def _check(self, step: Step):
        if step.closure() > CLOSE:
            self.warnings.append(f"{step.caption.split(':')[0]}: the polygon fails to close by {step.closure():.2g} "
                                 "of its largest side")
        return step

    # -- the groups in turn ------------------------------------------------------
    def run(self, own) -> None:
        """Solve the groups from the last located back to the driver; ``own(link)`` gives a link's own loads."""
        mech = self.mech
        R: dict[int, _Load] = {}
        self.passed = {link: [] for link in mech.moving}

        def R_of(link):
            if link not in R:
                R[link] = self.combine(link, own(link), [p[1:] for p in self.passed[link]])
            return R[link]

        def pass_on(other, base, F, X, C=0.0):
            # A group with no load passes nothing: "also carries F54′ = 0" would say nothing.
            if other != mech.frame and (F != 0 or C != 0):
                self.passed[other].append((base, base + self.mark, F, X, C))

        for g in reversed(self.kin.groups):
            if isinstance(g, DriverGroup):
                self.driver(g, R_of(g.link))
            elif isinstance(g, GearGroup):
                found = self.gear(g, R_of(g.k))
                F_W, P = found[id(g.mesh)]
                pass_on(g.j, self.base_name(g.k, g.j), -F_W, P)
                # The pivot's reaction loads the link gear k turns on: the arm of an epicyclic train.
                F_piv, C = found[id(g.pivot)]
                pass_on(g.support, self.base_name(g.k, g.support), -F_piv, C)
            else:
                self.dyad(g, {g.j: R_of(g.j), g.k: R_of(g.k)})
                for J, on in ((g.J1, g.j), (g.J3, g.k)):
                    other = _other(J, on)
                    lo, hi = sorted(J.links)
                    s = 1.0 if other == hi else -1.0
                    pass_on(other, self.base_name(on, other), s * complex(*self.forces[(lo, hi)]),
                            self.joint_point(J, other), s * self.couple.get((lo, hi), 0.0))

    def on(self, joint, link) -> complex:
        """The force this builder found at ``joint`` on ``link``, complex [N]."""
        lo, hi = sorted(joint.links)
        F = complex(*self.forces[(lo, hi)])
        return F if link == hi else -F


def _inertia_offset(link, Fi, Ti, h) -> str:
    sense = "clockwise" if Ti < 0 else "counter-clockwise"
    return (f"its inertia force F{link}i = −m{link}·a_G{link} = {polar(Fi)} and inertia torque T{link}i = "
            f"−I_G{link}·α{link} = {number(Ti)} N·m combine into one force R{link}i of the same size and direction, "
            f"whose line is offset from G{link} by h = |T|/|F| = {number(h * 1e3)} mm to the side that turns link "
            f"{link} {sense}")


def _inertia_through_G(link, Fi) -> str:
    return f"its inertia force F{link}i = −m{link}·a_G{link} = {polar(Fi)} acts through G{link}"


def _combined_text(scope, link, R, names, mine, nothing, line, F, M0) -> str:
    """What :meth:`Builder.combine` says: the reactions ``names`` found before, added to the own loads (named
    ``mine``; None for none) into one resultant ``R`` (nothing: rounding; ``line``: not a pure couple)."""
    res = (f"{R} = 0 N" if nothing else f"{R} = {number(abs(F))} N" if line else f"{R}, a pure couple of {number(M0)} N·m")
    if mine is not None:
        text = (f"link {link} also carries {and_list(names)}, found before; with its own loads{mine} they add up "
                f"to one resultant {res}.")
    elif len(names) == 1:
        text = f"link {link} carries only {names[0]}, found before, so its resultant is {names[0]} itself: {res}."
    else:
        text = f"link {link} carries only {and_list(names)}, found before; they add up to one resultant {res}."
    return _lead(scope, text)


def _crank_text(within, name, Rd, at, drive, dn, nothing, d, T, total) -> str:
    """What :meth:`Builder.driver` says of a crank: the pivot force ``name`` and the driving torque ``drive`` = ``T``,
    with the arm ``dn`` = ``d`` of the couple they form (``nothing``: the resultant ``Rd`` is rounding)."""
    arm = (f"{Rd} is rounding, so {name} = 0 and {drive} = 0 N·m" if nothing else
           f"{Rd} acts through {at} (its arm {dn} = 0), so the driving torque is {drive} = 0 N·m"
           if d <= PICOMETRE else  # a dead centre: what is left of the arm is rounding
           f"with {Rd} it forms a couple of arm {dn} = {number(d * 1e3)} mm, which the driving torque balances: "
           f"{drive} = ±|{Rd}|·{dn} = {number(T)} N·m{sense(T)}" if math.isfinite(d * 1e3) else
           f"{Rd} is so small beside its moment about {at} that the loads are a pure couple, which the "
           f"driving torque balances: {drive} = {number(T)} N·m{sense(T)}")
    return f"The crank{within}: the pivot force {name} = −{Rd} acts at {at}; {arm}" + (f"; {total}." if total else ".")


def _lead(scope: str, text: str) -> str:
    """``"In sub-problem I, link 4 …"`` in a sub-problem (``scope``), ``"Link 4 …"`` in the whole problem."""
    return f"In {scope}, {text}" if scope else text[0].upper() + text[1:]


def _own_text(link, parts) -> str:
    return f"Link {link}: " + "; ".join(map(str, parts)) + "."


def _other(joint, link: int) -> int:
    """The link ``joint`` joins to ``link``."""
    a, b = joint.links
    return b if a == link else a


def _decompose(v, a, b):
    """Real x, y with v = x a + y b (a, b complex directions)."""
    det = cross(a, b)
    return cross(v, b) / det, cross(a, v) / det


class DeadPoint(Exception):
    pass


