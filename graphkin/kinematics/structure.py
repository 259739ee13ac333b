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
    """Gear k pivoted on carrier b, driven through ``mesh`` by located gear j (also pivoted on b)."""

    k: int
    j: int
    b: int
    mesh: GearMesh
    pivot: Revolute
    j_pivot: Revolute

    @property
    def links(self) -> tuple[int, ...]:
        return (self.k,)

    @property
    def joints(self) -> tuple[Joint, ...]:
        return (self.pivot, self.mesh)

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
                b = (set(pivot.links) - {k}).pop()
                if isinstance(pivot, Revolute) and b in known and id(pivot) not in used:
                    try:
                        j_pivot = mech.joint_between(j, b)
                    except ModelError:
                        j_pivot = None
                    if not isinstance(j_pivot, Revolute):
                        raise ModelError(f"{mesh.label}: both gears must be pivoted on one link; gear {j} is not "
                                         f"pivoted on link {b}", at=("joints", _index(mech, mesh), "links"))
                    _check_centre_distance(mech, mesh, k, j, b, pivot, j_pivot)
                    return GearGroup(k, j, b, mesh, pivot, j_pivot)
    return None


def _check_centre_distance(mech, mesh, k, j, b, pivot, j_pivot):
    carrier = mech.link(b)
    (xk, yk), (xj, yj) = carrier.point(pivot.point), carrier.point(j_pivot.point)
    d = math.hypot(xk - xj, yk - yj)
    r = sum(mesh.radii)
    if abs(d - r) > 1e-9 * max(d, r):
        raise ModelError(f"{mesh.label}: pitch radii {mesh.radii[0] * 1e3:.6g} mm + {mesh.radii[1] * 1e3:.6g} mm do not "
                         f"add up to the centre distance {d * 1e3:.6g} mm between {pivot.point} and {j_pivot.point}",
                         at=("joints", _index(mech, mesh), "radii"))


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
