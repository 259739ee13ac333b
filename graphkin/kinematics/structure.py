"""Split a mechanism into its driver and Assur groups (dyads, gear pairs).

A class-II linkage is the driver plus a sequence of dyads, each dyad being
two links j, k joined to each other (joint J2) and to links already located
(J1: a–j, J3: k–b). Each joint is revolute (R) or prismatic (P), which gives
the dyad types RRR, RRP, RPR, PRP, RPP (and their mirror images PRR, PPR,
which are stored reversed; a symmetric dyad is stored with J1 on the link
located later, so that its branch does not depend on link numbers). A gear that is pivoted on a located carrier and
meshes with a located gear forms a group of its own.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from graphkin.errors import ModelError
from graphkin.model import GearMesh, Joint, Mechanism, Prismatic, Revolute


def kind(joint: Joint) -> str:
    """``"R"`` or ``"P"`` for a lower pair."""
    return "P" if isinstance(joint, Prismatic) else "R"


def joint_point(joint: Joint) -> str:
    """The point naming a joint: the pin, or the slider's point."""
    return joint.point


@dataclass(frozen=True)
class DriverGroup:
    """The input link and its joint to the frame."""

    link: int
    joint: Joint

    @property
    def links(self) -> tuple[int, ...]:
        return (self.link,)

    @property
    def joints(self) -> tuple[Joint, ...]:
        return (self.joint,)

    @property
    def label(self) -> str:
        return f"driver {self.link}"


@dataclass(frozen=True)
class Dyad:
    """Links j, k with joints J1 (a–j), J2 (j–k), J3 (k–b); a, b already located."""

    j: int
    k: int
    a: int
    b: int
    J1: Joint
    J2: Joint
    J3: Joint

    @property
    def type(self) -> str:
        return kind(self.J1) + kind(self.J2) + kind(self.J3)

    @property
    def key(self) -> str:
        """Key of the assembly branch σ in ``Mechanism.assembly``: J2's point."""
        return joint_point(self.J2)

    @property
    def links(self) -> tuple[int, ...]:
        return (self.j, self.k)

    @property
    def joints(self) -> tuple[Joint, ...]:
        return (self.J1, self.J2, self.J3)

    @property
    def label(self) -> str:
        return f"{self.type} dyad {self.j}–{self.k}"

    def reversed(self) -> "Dyad":
        return Dyad(self.k, self.j, self.b, self.a, self.J3, self.J2, self.J1)


@dataclass(frozen=True)
class GearGroup:
    """Gear k, located by its mesh with gear j (located) and its pivot; both centres are fixed in carrier b.

    The carrier b is located before k. It is the link both gears are
    pivoted on (the frame of a gear pair, the arm of an epicyclic train), or
    the arm of an epicyclic train when one gear is pivoted on the arm and the
    other on the link the arm turns about, at the arm's axis (a planet on an
    arm meshing with a sun or annulus on the frame). Relative to b the gears
    turn as a fixed-axis pair: ω_k − ω_b = ∓ (r_j / r_k)(ω_j − ω_b), minus for
    an external mesh, plus for an internal one.

    Attributes
    ----------
    k, j, b : int
        The gear located here, the gear it meshes with, the carrier.
    mesh : GearMesh
    pivot : Revolute
        Gear k's pin: to the carrier, or to the link the carrier turns about.
    j_pivot : Revolute
        Gear j's pin (to the carrier, or to the link it turns on).
    ck, cj : str
        The points of the carrier at the centres of k and of j.
    """

    k: int
    j: int
    b: int
    mesh: GearMesh
    pivot: Revolute
    j_pivot: Revolute
    ck: str = ""
    cj: str = ""

    def __post_init__(self):
        if not self.ck:
            object.__setattr__(self, "ck", self.pivot.point)
        if not self.cj:
            object.__setattr__(self, "cj", self.j_pivot.point)

    @property
    def links(self) -> tuple[int, ...]:
        return (self.k,)

    @property
    def joints(self) -> tuple[Joint, ...]:
        return (self.pivot, self.mesh)

    @property
    def support(self) -> int:
        """The link gear k is pivoted on (its pin's other link): the carrier, or the link the carrier turns about."""
        return (set(self.pivot.links) - {self.k}).pop()

    @property
    def sign(self) -> float:
        """−1 for an external mesh (relative to the carrier the gears turn opposite ways), +1 for an internal one."""
        return 1.0 if self.mesh.internal else -1.0

    @property
    def label(self) -> str:
        return f"gear {self.k} (meshing with {self.j})"


Group = DriverGroup | Dyad | GearGroup


def decompose(mech: Mechanism) -> tuple[Group, ...]:
    """Order the mechanism's links into groups that can be located one by one.

    Parameters
    ----------
    mech : Mechanism
        The linkage.

    Returns
    -------
    tuple of DriverGroup, Dyad or GearGroup
        The driver first, then each group whose outer joints are on links located before it.

    Raises
    ------
    ModelError
        If some links cannot be located by dyads or gear pairs (not class II).
    """
    driver_joint = mech.joint_between(mech.frame, mech.driver.link)
    groups: list[Group] = [DriverGroup(mech.driver.link, driver_joint)]
    known = {mech.frame, mech.driver.link}
    located = [mech.frame, mech.driver.link]
    used = {id(driver_joint)}

    def joints_to_known(n):
        return [jt for jt in mech.joints_of(n) if id(jt) not in used and (set(jt.links) - {n}) <= known]

    while len(known) < len(mech.links):
        unknown = [n for n in mech.moving if n not in known]
        group = _next_gear(mech, unknown, known, used) or _next_dyad(mech, unknown, known, used, joints_to_known, located)
        if group is None:
            raise ModelError(
                f"links {', '.join(map(str, unknown))} cannot be located dyad by dyad from the driver; "
                "graphkin solves linkages built from a driver plus dyads (RRR, RRP, RPR, PRP, RPP) and gear pairs"
            )
        groups.append(group)
        known.update(group.links)
        located.extend(group.links)
        used.update(id(jt) for jt in group.joints)
    return tuple(groups)


def _next_gear(mech, unknown, known, used):
    for mesh in mech.joints:
        if not isinstance(mesh, GearMesh) or id(mesh) in used:
            continue
        for k, j in (mesh.links, mesh.links[::-1]):
            if k not in unknown or j not in known:
                continue
            for pivot in mech.joints_of(k):
                s = (set(pivot.links) - {k}).pop()
                if isinstance(pivot, Revolute) and s in known and id(pivot) not in used:
                    found = _carrier(mech, mesh, k, j, s, pivot, known)
                    if found is None:
                        raise ModelError(f"{mesh.label}: the gear centres must stay a fixed distance apart: gear {j} must be "
                                         f"pivoted on link {s}, as gear {k} is, or one of them on an arm that turns about "
                                         f"the other's centre (an epicyclic train); gear {j} is neither",
                                         at=("joints", _index(mech, mesh), "links"))
                    b, ck, cj, j_pivot = found
                    _check_centres(mech, mesh, k, j, pivot, j_pivot)
                    _check_centre_distance(mech, mesh, b, ck, cj)
                    return GearGroup(k, j, b, mesh, pivot, j_pivot, ck, cj)
    return None


def _revolute(mech, i, j):
    """The revolute joint between links i and j, or None."""
    try:
        joint = mech.joint_between(i, j)
    except ModelError:
        return None
    return joint if isinstance(joint, Revolute) else None


def _same_place(link, p, q) -> bool:
    """Whether points p and q of one link coincide (the same name, or the same coordinates to rounding)."""
    if p == q:
        return True
    (xp, yp), (xq, yq) = link.point(p), link.point(q)
    return math.hypot(xp - xq, yp - yq) <= 1e-9 * max(math.hypot(xp, yp), math.hypot(xq, yq), 1e-3)


def _carrier(mech, mesh, k, j, s, pivot, known):
    """The carrier of a mesh whose new gear k is pivoted on located link s: ``(b, ck, cj, j_pivot)``, or None.

    Three arrangements keep the centre distance fixed: j pivoted on s too (a gear pair on the frame, two gears on
    one arm); j pivoted on a link c about which s turns, at j's centre (a planet k on arm s, meshing with a sun or
    annulus j on the frame); j pivoted on an arm c that turns about s at k's centre (a sun or annulus k on the
    frame s, meshing with a planet j on arm c).
    """
    j_pivot = _revolute(mech, j, s)
    if j_pivot is not None:
        return s, pivot.point, j_pivot.point, j_pivot
    for c in known:
        j_pivot = _revolute(mech, j, c)
        if j_pivot is None or c == k:
            continue
        arm = _revolute(mech, s, c)
        if arm is not None and _same_place(mech.link(c), arm.point, j_pivot.point):
            return s, pivot.point, arm.point, j_pivot
        arm = _revolute(mech, c, s)
        if arm is not None and _same_place(mech.link(s), arm.point, pivot.point):
            return c, arm.point, j_pivot.point, j_pivot
    return None


def _check_centres(mech, mesh, k, j, pivot, j_pivot):
    """The mesh's centre of each gear must be where the gear is pivoted."""
    for gear, joint in ((k, pivot), (j, j_pivot)):
        centre = mesh.centers[mesh.links.index(gear)]
        if not _same_place(mech.link(gear), centre, joint.point):
            raise ModelError(f"{mesh.label}: the centre {centre} of gear {gear} is not at its pivot {joint.point}",
                             at=("joints", _index(mech, mesh), "centers"))


def _check_centre_distance(mech, mesh, b, ck, cj):
    carrier = mech.link(b)
    (xk, yk), (xj, yj) = carrier.point(ck), carrier.point(cj)
    d = math.hypot(xk - xj, yk - yj)
    r = mesh.centre_distance
    if abs(d - r) > 1e-9 * max(d, r):
        how = "less" if mesh.internal else "+"
        first, second = (max(mesh.radii), min(mesh.radii)) if mesh.internal else mesh.radii
        raise ModelError(f"{mesh.label}: pitch radii {first * 1e3:.6g} mm {how} {second * 1e3:.6g} mm do not "
                         f"{'leave' if mesh.internal else 'add up to'} the centre distance {d * 1e3:.6g} mm between "
                         f"{ck} and {cj}", at=("joints", _index(mech, mesh), "radii"))


def _index(mech, joint) -> int:
    """Position of ``joint`` in the mechanism's joints (by identity: two equal joints are two joints)."""
    return next(k for k, j in enumerate(mech.joints) if j is joint)


def _next_dyad(mech, unknown, known, used, joints_to_known, located):
    for j in unknown:
        for J2 in mech.joints_of(j):
            if id(J2) in used or isinstance(J2, GearMesh):
                continue
            k = (set(J2.links) - {j}).pop()
            if k not in unknown:
                continue
            J1s, J3s = joints_to_known(j), joints_to_known(k)
            if len(J1s) != 1 or len(J3s) != 1:
                continue
            J1, J3 = J1s[0], J3s[0]
            if isinstance(J1, GearMesh) or isinstance(J3, GearMesh):
                continue
            a = (set(J1.links) - {j}).pop()
            b = (set(J3.links) - {k}).pop()
            dyad = Dyad(j, k, a, b, J1, J2, J3)
            if dyad.type == "PPP":
                raise ModelError(f"links {j} and {k} form a PPP group, which cannot be located (it is free to translate)")
            if dyad.type in ("PRR", "PPR"):
                dyad = dyad.reversed()
            elif dyad.type[0] == dyad.type[2] and _later_first(dyad, located) is False:
                dyad = dyad.reversed()
            return dyad
    return None


def _later_first(d: Dyad, located: list[int]) -> bool:
    """Whether a symmetric dyad (RRR, RPR, PRP) already has J1 on the link located later.

    The assembly branch σ is defined looking from J1 to J3, so J1 must not
    depend on how the links are numbered: J1 is the joint on the link located
    later (nearer the driver; for a four-bar, the crank pin A rather than the
    frame pivot B0); on one link, the alphabetically first point.
    """
    ia, ib = located.index(d.a), located.index(d.b)
    if ia != ib:
        return ia > ib
    return d.J1.point <= d.J3.point
