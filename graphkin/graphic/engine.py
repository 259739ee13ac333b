"""The graphical route: resultants, two- and three-force members, force polygons.

For one position, the groups of the kinematic decomposition are taken in
reverse order, as in the analytical solver, but each is solved the way it is
drawn:

1. each loaded link's known loads are combined into one resultant R — for
   inertia alone, −m a_G on a line offset from G by h = |T|/|F|;
2. in a dyad with both links loaded, the loads are superposed: one
   sub-construction per loaded link, the other link unloaded;
3. the unloaded link is a two-force member, which fixes the line of the force
   it passes on (along its two pins; through its pin, normal to its guide; or
   through its pin, normal to a slot in the loaded link);
4. the loaded link is then a three-force member: its resultant, that line and
   the reaction at its other joint meet in one point, found with shapely; the
   force polygon closes tip to tail (a guide reaction has a known direction
   instead, so the polygon alone gives both sizes);
5. the sub-results are added (a polygon of the sum); reactions found are
   loads on the links of the groups before;
6. the driver: the crank's pivot force and the resultant on the crank form a
   couple T = F·d, or the slider's polygon gives the driving force.

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

import numpy as np
import shapely

from ..errors import GraphkinError
from ..kinematics import Dyad, DriverGroup, GearGroup, Kinematics
from ..geometry import zcross as cross
from ..geometry import zdot as dot
from ..model import Prismatic, Revolute
from .construction import Arrow, Construction, Line, Step, nice_scale

CLOSE = 1e-9
"""Relative tolerance of the closure check of a polygon."""


def _xy(z) -> tuple[float, float]:
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
    a = shapely.LineString([_xy(p - L * u), _xy(p + L * u)])
    b = shapely.LineString([_xy(q - L * w), _xy(q + L * w)])
    hit = shapely.intersection(a, b)
    if hit.is_empty or hit.geom_type != "Point":
        return p + t * u
    return complex(hit.x, hit.y)


class _Builder:
    """Builds the construction of one position."""

    def __init__(self, kin: Kinematics, i: int):
        self.kin, self.i = kin, i
        self.mech = kin.mechanism
        self.steps: list[Step] = []
        self.warnings: list[str] = []
        self.forces, self.normal, self.couple = {}, {}, {}
        self.effort = math.nan
        self.rname: dict[int, str] = {}
        self.driver_vector = None
        pts = [self.z(link, p) for link in self.mech.moving for p in self.mech.link(link).points]
        self.reach = max((abs(a - b) for a in pts for b in pts), default=1.0) or 1.0

    # -- geometry at this position -----------------------------------------
    def z(self, link, point):
        return complex(self.kin.z(link, point)[self.i])

    def joint_point(self, joint, link):
        return self.z(joint.slider, joint.point) if isinstance(joint, Prismatic) else self.z(link, joint.point)

    def w(self, joint: Prismatic, on: int, sigma: float):
        """Direction of the guide reaction on ``on`` per unit normal force (friction tilt included)."""
        u = complex(self.kin.z_guide(joint)[self.i])
        w = 1j * u
        if joint.mu:
            w -= joint.mu * sigma * self.kin.slide_sense(joint, on)[self.i] * u
        return w

    def name(self, i, j):
        letter = self.mech.joint_between(i, j).force_letter
        return f"{letter}{i}{j}" if i < 10 and j < 10 else f"{letter}{i},{j}"

    # -- loads ---------------------------------------------------------------
    def own_loads(self, link) -> _Load:
        """Inertia, weight and external loads of a link, with a step explaining its resultant."""
        kin, i, body = self.kin, self.i, self.mech.link(link)
        load = _Load()
        G = complex(kin.z_G(link)[i])
        # A static analysis has no inertia loads: the links carry their weights and external loads only.
        Fi = complex(-body.mass * kin.z_a_G(link)[i]) if body.mass and not kin.static else 0j
        Ti = float(-body.I_G * kin.al(link)[i]) if body.I_G and not kin.static else 0.0
        load.add(Fi, G, Ti)
        parts = []
        lines = []
        values = {}
        if Fi or Ti:
            values[f"F{link}i"], values[f"T{link}i"] = _xy(Fi), Ti
            if Fi:
                h = abs(Ti) / abs(Fi)
                values["h"] = h
                # The offset side makes the moment of F about G equal T.
                P = G - 1j * Ti / Fi.conjugate()  # Ti Fi/|Fi|², without squaring a small |Fi| to 0
                lines.append(Line(f"R{link}i", _xy(P), _xy(Fi / abs(Fi)), "resultant"))
                sense = "clockwise" if Ti < 0 else "counter-clockwise"
                parts.append(
                    f"its inertia force F{link}i = −m a_G = {abs(Fi):.4g} N and inertia torque T{link}i = −I_G α = "
                    f"{Ti:.4g} N·m combine into one force R{link}i of the same size and direction, whose line is offset "
                    f"from G{link} by h = |T|/|F| = {h * 1e3:.4g} mm to the side that turns link {link} {sense}"
                    if Ti else f"its inertia force F{link}i = −m a_G = {abs(Fi):.4g} N acts through G{link}")
            else:
                parts.append(f"its inertia torque T{link}i = {Ti:.4g} N·m is a pure couple")
        if self.mech.gravity and body.mass:
            W = -1j * body.mass * self.mech.gravity
            load.add(W, G)
            parts.append(f"its weight {abs(W):.4g} N acts at G{link}")
        from ..model import PointForce, Torque

        for ld in self.mech.loads:
            if ld.link != link or (ld.active is not None and not ld.active.mask(kin.q[i : i + 1])[0]):
                continue
            if isinstance(ld, PointForce):
                F = complex(*ld.force)
                load.add(F, self.z(link, ld.point))
                parts.append(f"the external force {ld.name or 'P'} = {abs(F):.4g} N acts at {ld.point}")
            elif isinstance(ld, Torque):
                load.add(0j, None, ld.torque)
                parts.append(f"the external torque {ld.name or 'T'} = {ld.torque:.4g} N·m acts on it")
        only_inertia = len(parts) == 1 and bool(Fi or Ti)
        self.rname[link] = f"R{link}i" if only_inertia else f"R{link}"
        if len(parts) > 1 and load.F and load.point() is not None:
            lines.append(Line(f"R{link}", _xy(load.point()), _xy(load.F / abs(load.F)), "resultant"))
            values[f"R{link}"] = _xy(load.F)
            parts.append(f"together they make one resultant R{link} = {abs(load.F):.4g} N")
        if parts:
            caption = f"Link {link}: " + "; ".join(parts) + "."
            self.steps.append(Step("resultant", caption, link, tuple(lines), values=values))
        return load

    def combine(self, link, load: _Load, extra: list):
        """Add reactions (name, force, point, couple) from groups solved before; one resultant R for the link."""
        for _, F, X, C in extra:
            load.add(F, X, C)
        if extra:
            self.rname[link] = f"R{link}"
            names = ", ".join(n for n, _, _, _ in extra)
            P = load.point()
            lines = (Line(f"R{link}", _xy(P), _xy(load.F / abs(load.F)), "resultant"),) if P is not None else ()
            self.steps.append(Step(
                "resultant",
                f"Link {link} also carries {names}, found before; with its own loads they add up to one resultant "
                f"R{link} = {abs(load.F):.4g} N" + ("." if P is not None else f" (a pure couple of {load.M0:.4g} N·m)."),
                link, lines, values={f"R{link}": _xy(load.F)}))
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
            w = self.w(JM, M, sigma[JM])
            text = f"through {J2.point}, along the reaction of its guide (normal to the guide" + (
                ", tilted by the friction angle)" if JM.mu else ")")
            return X2, w / abs(w), M, text
        if isinstance(JM, Revolute):
            XM = self.z(M, JM.point)
            w = self.w(J2, d.k, sigma[J2])
            return XM, w / abs(w), M, f"through its pin {JM.point}, normal to the sliding pair at {J2.point}"
        return None, None, M, "as a couple only (two guides cannot balance a force)"

    def sub_construction(self, d: Dyad, L: int, R: _Load, sigma):
        """Forces on L (and through J2) when only L is loaded. Returns {joint id: force on the dyad link}."""
        JL = d.J1 if L == d.j else d.J3
        RL = self.rname[L]
        M_point, M_dir, M, how = self.m_line(d, L, sigma)
        # On L the passed force acts at L's own middle pin (the same point unless a link's angle is given).
        on_L = self.z(L, d.J2.point) if M_point is not None and isinstance(d.J2, Revolute) else M_point
        nM, nL = self.name(M, L), self.name((set(JL.links) - {L}).pop(), L)
        steps = []
        steps.append(Step("two-force", f"Link {M} carries no load of its own here, so it is a two-force member: "
                          f"{nM} acts {how}.", M,
                          (Line(nM, _xy(M_point), _xy(M_dir)),) if M_point is not None else ()))
        Rp = R.point()
        lines = []
        if Rp is not None:
            lines.append(Line(RL, _xy(Rp), _xy(R.F / abs(R.F)), "resultant"))
        if M_point is None:
            # The partner passes a couple only: the outer pin force balances R alone.
            XL = self.z(L, JL.point)
            F_out = -R.F
            steps.append(Step("polygon", f"{nL} = −{RL} acts at {JL.point}; the couple they form is taken by the sliding pairs.",
                              L, tuple(lines), polygon=(Arrow(RL, _xy(R.F), True), Arrow(nL, _xy(F_out), False, _xy(XL))),
                              values={nL: _xy(F_out)}))
            self.steps.extend(steps)
            return {id(d.J1): 0j, id(d.J3): 0j, id(JL): F_out, id(d.J2): 0j}
        if isinstance(JL, Revolute):
            XL = self.z(L, JL.point)
            arm = cross(on_L - XL, M_dir)
            if abs(arm) <= 1e-12 * self.reach:
                raise _DeadPoint(f"the line of {nM} passes through {JL.point}, so link {L} cannot be balanced (dead point)")
            a = -R.about(XL) / arm
            F_M = a * M_dir
            F_out = -R.F - F_M
            points = {}
            if Rp is None:
                text = (f"{RL} is a pure couple, so {nM} and {nL} form the opposite couple: {nL} is parallel to {nM}")
            else:
                I = _meet(Rp, R.F / abs(R.F), on_L, M_dir, self.reach)
                if abs(R.about(XL)) <= 1e-12 * abs(R.F) * self.reach:
                    text = (f"{RL} already passes through {JL.point}, so the three lines cannot meet elsewhere: "
                            f"{nM} is zero and {nL} = −{RL}")
                elif I is None:
                    text = (f"{RL} is parallel to {nM}: they meet at infinity, so {nL} is parallel to both; "
                            f"moments about {JL.point} give its size")
                else:
                    points[f"I{L}"] = _xy(I)
                    text = (f"Link {L} is a three-force member: {RL}, {nM} and {nL} meet in one point I{L} "
                            f"(where {RL} crosses the line of {nM}); {nL} passes through {JL.point} and I{L}")
                    if F_out != 0 and abs(cross(I - XL, F_out)) > 1e-7 * abs(I - XL) * abs(F_out):
                        self.warnings.append(f"{nL} misses the concurrency point I{L}")
                lines.append(Line(nL, _xy(XL), _xy(F_out / abs(F_out)) if F_out else (1.0, 0.0), "found"))
            lines.append(Line(nM, _xy(on_L), _xy(M_dir)))
            steps.append(Step("three-force", text + ".", L, tuple(lines), points))
        else:
            wL = self.w(JL, L, sigma[JL])
            a, b = _decompose(-R.F, M_dir, wL)
            F_M, F_out = a * M_dir, b * wL
            points = {}
            if Rp is not None:
                I = _meet(Rp, R.F / abs(R.F), on_L, M_dir, self.reach)
                if I is not None:
                    points[f"I{L}"] = _xy(I)
                    lines.append(Line(nL, _xy(I), _xy(wL / abs(wL)), "found"))
            lines.append(Line(nM, _xy(on_L), _xy(M_dir)))
            steps.append(Step("three-force",
                              f"The guide force {nL} has a known direction (normal to the guide"
                              + (", tilted by the friction angle" if JL.mu else "") + f"), so the polygon of {RL}, {nM} and {nL} "
                              f"gives both sizes; its line passes through the point where {RL} crosses {nM}.",
                              L, tuple(lines), points))
        poly = (Arrow(RL, _xy(R.F), True), Arrow(nM, _xy(F_M), False), Arrow(nL, _xy(F_out), False))
        steps.append(Step("polygon", f"Force polygon of link {L}: {RL} + {nM} + {nL} = 0, tip to tail.", L,
                          polygon=poly, values={nM: _xy(F_M), nL: _xy(F_out)}))
        self._check(steps[-1])
        self.steps.extend(steps)
        # The unloaded partner M passes F_M straight on: its outer joint pushes on it with F_M too.
        return {id(JL): F_out, id(d.J2): F_M if L == d.k else -F_M, id(d.J1 if L == d.k else d.J3): F_M}

    def dyad(self, d: Dyad, R: dict):
        friction = [J for J in d.joints if isinstance(J, Prismatic) and J.mu > 0]
        mark = len(self.steps)
        for signs in itertools.product((1.0, -1.0), repeat=len(friction)):
            del self.steps[mark:]
            sigma = {J: 1.0 for J in d.joints if isinstance(J, Prismatic)}
            sigma.update(zip(friction, signs))
            F = self._superpose(d, R, sigma)
            if F is None:
                return None
            bad = [J for J in friction if F["N"][id(J)] * sigma[J] < 0]
            if not bad:
                if friction:
                    self.steps.insert(mark, Step("note", "Friction: the guide reaction is tilted by atan μ against the "
                                                 "sliding; its sense depends on the side the normal force pushes. "
                                                 "The side assumed below is confirmed by the result.", d.j))
                return F
        raise _DeadPoint(f"friction locks the {d.label}: no side of the normal force is consistent")

    def _superpose(self, d: Dyad, R: dict, sigma):
        loaded = [L for L in (d.j, d.k) if abs(R[L].F) > 0 or R[L].M0 != 0]
        total = {id(J): 0j for J in d.joints}
        subs = []
        for L in loaded:
            part = self.sub_construction(d, L, R[L], sigma)
            subs.append((L, part))
            for key, F in part.items():
                total[key] += F
        if len(subs) > 1:
            for J, on in ((d.J1, d.j), (d.J2, d.k), (d.J3, d.k)):
                other = (set(J.links) - {on}).pop()
                n = self.name(other, on)
                arrows = [Arrow(f"{n} ({L} loaded)", _xy(p[id(J)]), True) for L, p in subs]
                # The closing side runs back to the start: it is −(the sum).
                self.steps.append(Step("superpose", f"Superposition: {n} is the sum of its parts from each loaded link.",
                                       on, polygon=tuple(arrows) + (Arrow(f"−{n}", _xy(-total[id(J)]), False),),
                                       values={n: _xy(total[id(J)])}))
        X = {id(J): self.joint_point(J, on) for J, on in ((d.J1, d.j), (d.J2, d.k), (d.J3, d.k))}
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
                N[id(J)] = dot(F, 1j * complex(self.kin.z_guide(J)[self.i]))
        return {"F": total, "N": N}

    def store(self, joint, on, F, C=0.0):
        lo, hi = sorted(joint.links)
        sign = 1.0 if on == hi else -1.0
        self.forces[(lo, hi)] = _xy(sign * F)
        if isinstance(joint, Prismatic):
            u = complex(self.kin.z_guide(joint)[self.i])
            self.normal[(lo, hi)] = float(dot(sign * F, 1j * u))
            self.couple[(lo, hi)] = float(sign * C)

    # -- gears and the driver ----------------------------------------------------
    def gear(self, g: GearGroup, R: _Load):
        mesh = g.mesh
        rk = mesh.radii[mesh.links.index(g.k)]
        Ck, Cj = self.z(g.b, g.pivot.point), self.z(g.b, g.j_pivot.point)
        e = (Cj - Ck) / abs(Cj - Ck)
        P = Ck + rk * e
        W_t = -R.about(Ck) / rk
        d = 1j * e - np.sign(W_t) * math.tan(mesh.pressure_angle) * e
        d /= abs(d)
        nW, nF = self.name(g.j, g.k), self.name(g.b, g.k)
        Rk = self.rname[g.k]
        self.steps.append(Step("line",
                               f"The tooth force {nW} lies on the pressure line through the pitch point P, inclined "
                               f"{math.degrees(mesh.pressure_angle):.4g}° to the common tangent, on the flank that "
                               f"opposes the load on gear {g.k}.", g.k, (Line(nW, _xy(P), _xy(d)),), {"P": _xy(P)}))
        arm = cross(P - Ck, d)
        F_W = (-R.about(Ck) / arm) * d
        F_piv = -R.F - F_W
        points = {}
        Rp = R.point()
        if Rp is not None:
            I = _meet(Rp, R.F / abs(R.F), P, d, self.reach)
            if I is not None:
                points[f"I{g.k}"] = _xy(I)
        pivot_line = (Line(nF, _xy(Ck), _xy(F_piv / abs(F_piv)) if F_piv else (1.0, 0.0), "found"),)
        # A gear loaded by a couple alone (its own weight and inertia force
        # nil, e.g. an input torque) is no three-force member: the tooth and
        # pivot forces are then the opposite couple, equal and opposite.
        if abs(R.F) <= 1e-9 * abs(F_W):
            self.steps.append(Step("couple", f"Gear {g.k} carries only a couple ({R.M0:.4g} N·m): {nW} and the pivot "
                                   f"force {nF} form the opposite couple, so {nF} = −{nW}, through the centre "
                                   f"{g.pivot.point}.", g.k, pivot_line, points))
            poly = (Arrow(nW, _xy(F_W), False), Arrow(nF, _xy(F_piv), False))
            caption = f"Force polygon of gear {g.k}: {nW} + {nF} = 0."
        else:
            self.steps.append(Step("three-force", f"Gear {g.k} is a three-force member: {Rk}, {nW} and the pivot force "
                                   f"{nF} meet in one point; {nF} passes through the centre {g.pivot.point}.", g.k,
                                   pivot_line, points))
            poly = (Arrow(Rk, _xy(R.F), True), Arrow(nW, _xy(F_W), False), Arrow(nF, _xy(F_piv), False))
            caption = f"Force polygon of gear {g.k}: {Rk} + {nW} + {nF} = 0."
        self.steps.append(Step("polygon", caption, g.k, polygon=poly, values={nW: _xy(F_W), nF: _xy(F_piv)}))
        self._check(self.steps[-1])
        self.store(g.mesh, g.k, F_W)
        self.store(g.pivot, g.k, F_piv)
        return {id(g.mesh): (F_W, P), id(g.pivot): (F_piv, Ck)}

    def driver(self, g: DriverGroup, R: _Load):
        link, J = g.link, g.joint
        name = self.name(self.mech.frame, link)
        Rd = self.rname[link]
        if isinstance(J, Revolute):
            X = self.z(link, J.point)
            F = -R.F
            T = float(-R.about(X))
            # Plain floats: a resultant tiny beside its moment (a pure couple in all but rounding) gives an arm
            # too long for a float, which is said in words rather than as a numpy overflow.
            d = abs(T) / abs(complex(R.F)) if R.F else 0.0
            sense = "CCW" if T > 0 else "CW"
            arm = (f"with {Rd} it forms a couple of arm d = {d * 1e3:.4g} mm, which the driving torque balances: "
                   f"{self.mech.driver.symbol} = ±|{Rd}|·d = {T:.4g} N·m ({sense})." if math.isfinite(d * 1e3) else
                   f"{Rd} is so small beside its moment about {J.point} that the loads are a pure couple, which the "
                   f"driving torque balances: {self.mech.driver.symbol} = {T:.4g} N·m ({sense}).")
            self.steps.append(Step(
                "driver",
                f"The crank: the pivot force {name} = −{Rd} acts at {J.point}; {arm}", link,
                (Line(name, _xy(X), _xy(F / abs(F)) if F else (1.0, 0.0), "found"),),
                values={name: _xy(F), self.mech.driver.symbol: T, **({"d": d} if math.isfinite(d) else {})},
                polygon=(Arrow(Rd, _xy(R.F), True), Arrow(name, _xy(F), False, _xy(X)))))
            self.store(J, link, F)
            self.effort = float(T)
            self.driver_vector = None
            return
        u = complex(self.kin.z_guide(J)[self.i])
        X = self.z(link, J.point)
        N = -dot(R.F, 1j * u)
        w = self.w(J, link, np.sign(N))
        b, P = _decompose(-R.F, w, u)
        G, Fd = b * w, P * u
        C = -(R.M0 + cross(X, G + Fd))
        drive = self.mech.driver.symbol
        self.steps.append(Step(
            "driver",
            f"The slider: the driving force {drive} acts along the guide and the guide force {name} normal to it"
            + (" (tilted by the friction angle)" if J.mu else "") + f"; the polygon {Rd} + {name} + {drive} = 0 gives both.",
            link, (Line(drive, _xy(X), _xy(u), "found"),),
            polygon=(Arrow(Rd, _xy(R.F), True), Arrow(name, _xy(G), False), Arrow(drive, _xy(Fd), False, _xy(X))),
            values={name: _xy(G), drive: _xy(Fd)}))
        self._check(self.steps[-1])
        self.store(J, link, G, C)
        self.effort = float(P)
        self.driver_vector = _xy(Fd)

    def _check(self, step: Step):
        if step.closure() > CLOSE:
            self.warnings.append(f"{step.caption.split(':')[0]}: the polygon fails to close by {step.closure():.2g} of its largest side")


class _DeadPoint(Exception):
    pass


def _decompose(v, a, b):
    """Real x, y with v = x a + y b (a, b complex directions)."""
    det = cross(a, b)
    return cross(v, b) / det, cross(a, v) / det


def construct_forces(kin: Kinematics, index: int = 0) -> Construction:
    """The graphical solution of position ``index``, step by step.

    Parameters
    ----------
    kin : Kinematics
    index : int
        Which of the kinematics' positions to construct.

    Returns
    -------
    Construction
        Not ``valid`` (with the reason) where the position cannot be assembled,
        is a dead point, or friction locks it.
    """
    if not isinstance(kin, Kinematics):
        raise GraphkinError(f"construct_forces takes the Kinematics of a problem (problem.kinematics()), "
                            f"got {type(kin).__name__}")
    if isinstance(index, (bool, np.bool_)) or not isinstance(index, (int, np.integer)) or not -kin.n <= index < kin.n:
        raise GraphkinError(f"construct_forces: index must be a whole number from 0 to {kin.n - 1} (one of the "
                            f"{kin.n} positions), got {index!r}")
    index = int(index) % kin.n
    mech = kin.mechanism
    q = float(kin.q[index])
    if not kin.valid[index]:
        return Construction(mech, index, q, valid=False, reason=kin.reason(index))
    b = _Builder(kin, index)
    own = {link: None for link in mech.moving}
    passed: dict[int, list] = {link: [] for link in mech.moving}

    def R_of(link):
        if own[link] is None:
            own[link] = b.combine(link, b.own_loads(link), passed[link])
        return own[link]

    try:
        for g in reversed(kin.groups):
            if isinstance(g, DriverGroup):
                b.driver(g, R_of(g.link))
            elif isinstance(g, GearGroup):
                out = b.gear(g, R_of(g.k))
                F_W, P = out[id(g.mesh)]
                if g.j != mech.frame:
                    passed[g.j].append((b.name(g.k, g.j), -F_W, P, 0.0))
            else:
                b.dyad(g, {g.j: R_of(g.j), g.k: R_of(g.k)})
                for J, on in ((g.J1, g.j), (g.J3, g.k)):
                    other = (set(J.links) - {on}).pop()
                    if other != mech.frame:
                        lo, hi = sorted(J.links)
                        s = 1.0 if other == hi else -1.0
                        passed[other].append((b.name(on, other), s * complex(*b.forces[(lo, hi)]),
                                              b.joint_point(J, other), s * b.couple.get((lo, hi), 0.0)))
    except _DeadPoint as exc:
        return Construction(mech, index, q, tuple(b.steps), valid=False, reason=str(exc))
    largest = max([abs(complex(*F)) for F in b.forces.values()] + [0.0])
    return Construction(mech, index, q, tuple(b.steps), b.forces, b.normal, b.couple, b.effort,
                        nice_scale(largest), True, "", tuple(b.warnings), driver_vector=b.driver_vector,
                        **_geometry(kin, index))


def _geometry(kin: Kinematics, i: int) -> dict:
    """Plain-data geometry of position i, for drawing and handouts."""
    from ..model import GearMesh, PointForce, Torque
    from ..solve.loads import inertia

    mech = kin.mechanism
    points = {link.number: {name: _xy(complex(kin.z(link.number, name)[i])) for name in link.points} for link in mech.links}
    G = {link: _xy(complex(kin.z_G(link)[i])) for link in mech.moving}
    inert, external = {}, {}
    for link in mech.moving:
        body = mech.link(link)
        if (body.mass or body.I_G) and not kin.static:
            inn = inertia(kin, link)
            h = float(inn.h[i])
            inert[link] = {"F": tuple(map(float, inn.F[i])), "T": float(inn.T[i]), "h": None if math.isnan(h) else h,
                           "line_point": None if math.isnan(h) else tuple(map(float, inn.line_point[i]))}
        arrows = []
        if mech.gravity and body.mass:
            arrows.append(Arrow(f"W{link}", (0.0, -body.mass * mech.gravity), True, G[link]))
        for ld in mech.loads:
            if isinstance(ld, PointForce) and ld.link == link and (ld.active is None or ld.active.mask(kin.q[i:i + 1])[0]):
                arrows.append(Arrow(ld.name or f"P{link}", ld.force, True, points[link][ld.point]))
        external[link] = arrows
    torques = {link: [(ld.name or f"T{link}", ld.torque) for ld in mech.loads
                      if isinstance(ld, Torque) and ld.link == link and (ld.active is None or ld.active.mask(kin.q[i:i + 1])[0])]
               for link in mech.moving}
    guides = {tuple(sorted(j.links)): _xy(complex(kin.z_guide(j)[i])) for j in mech.joints if isinstance(j, Prismatic)}
    angles = {link.number: float(kin.theta[link.number][i]) for link in mech.links}
    pitch = {}
    for joint in mech.joints:
        if isinstance(joint, GearMesh):
            (a, b), (ca, cb) = joint.links, joint.centers
            A, B = complex(kin.z(a, ca)[i]), complex(kin.z(b, cb)[i])
            pitch[tuple(sorted(joint.links))] = _xy(A + joint.radii[0] * (B - A) / abs(B - A))
    return {"points": points, "G": G, "inertia": inert, "external": external, "pitch_points": pitch,
            "torques": torques, "guides": guides, "angles": angles}

