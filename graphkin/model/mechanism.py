"""The mechanism: links, joints, the driver, loads and the assembly branch."""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

from ..errors import ModelError
from .driver import Driver
from .joints import GearMesh, Joint, Prismatic, Revolute
from .link import FRAME, Link
from .loads import Load, PointForce, standard_gravity


@dataclass(frozen=True)
class Mechanism:
    """A planar linkage with one degree of freedom, as data.

    Parameters
    ----------
    links : sequence of Link
        All links, the frame (number 1) included.
    joints : sequence of Revolute, Prismatic or GearMesh
    driver : Driver
    loads : sequence of PointForce or Torque
        External loads (inertia loads are added by the solver).
    gravity : float
        g [m/s²] acting along −y on every link's centre of mass; 0 to neglect.
    assembly : mapping of str to {+1, −1}
        Assembly branch σ of each dyad, keyed by the name of its middle joint
        point (see :mod:`graphkin.kinematics.dyads`); +1 where not given.
    title, source : str
        What the problem is and where it comes from (book, example).
    """

    links: tuple[Link, ...]
    joints: tuple[Joint, ...]
    driver: Driver
    loads: tuple[Load, ...] = ()
    gravity: float = 0.0
    assembly: Mapping[str, int] = field(default_factory=dict)
    title: str = ""
    source: str = ""

    def __post_init__(self):
        object.__setattr__(self, "links", tuple(self.links))
        object.__setattr__(self, "joints", tuple(self.joints))
        object.__setattr__(self, "loads", tuple(self.loads))
        object.__setattr__(self, "gravity", standard_gravity(self.gravity))
        object.__setattr__(self, "assembly", MappingProxyType(dict(self.assembly)))
        self._check()

    # -- look-ups ---------------------------------------------------------
    def link(self, number: int) -> Link:
        """The link with this number; a clear error naming the known ones if absent."""
        for link in self.links:
            if link.number == number:
                return link
        have = ", ".join(str(l.number) for l in self.links)
        raise ModelError(f"unknown link {number!r} (the mechanism has links {have})")

    @property
    def moving(self) -> tuple[int, ...]:
        """Numbers of the moving links, in ascending order."""
        return tuple(sorted(l.number for l in self.links if l.number != FRAME))

    def joints_of(self, number: int) -> tuple[Joint, ...]:
        return tuple(j for j in self.joints if number in j.links)

    def joint_between(self, i: int, j: int) -> Joint:
        for joint in self.joints:
            if set(joint.links) == {i, j}:
                return joint
        raise ModelError(f"no joint between links {i} and {j}")

    # -- validation -------------------------------------------------------
    def _check(self):
        numbers = [l.number for l in self.links]
        for n in set(numbers):
            if numbers.count(n) > 1:
                raise ModelError(f"link {n} is defined {numbers.count(n)} times")
        if FRAME not in numbers:
            raise ModelError("the mechanism needs a frame: link 1")
        for joint in self.joints:
            for n in joint.links:
                if n not in numbers:
                    known = ", ".join(map(str, sorted(numbers)))
                    raise ModelError(f"{joint.label} names unknown link {n} (links are {known})")
            if isinstance(joint, Revolute):
                for n in joint.links:
                    self.link(n).point(joint.point)
            elif isinstance(joint, Prismatic):
                self.link(joint.slider).point(joint.point)
                self.link(joint.guide).point(joint.through)
            elif isinstance(joint, GearMesh):
                for n, c in zip(joint.links, joint.centers):
                    self.link(n).point(c)
        pairs = [frozenset(j.links) for j in self.joints]
        for p in set(pairs):
            if pairs.count(p) > 1:
                i, j = sorted(p)
                raise ModelError(f"links {i} and {j} are joined {pairs.count(p)} times; one joint per pair")
        for link in self.links:
            pins = [j.point for j in self.joints_of(link.number) if isinstance(j, Revolute)]
            for a, b in itertools.combinations(sorted(set(pins)), 2):
                (xa, ya), (xb, yb) = link.point(a), link.point(b)
                if math.hypot(xb - xa, yb - ya) <= 1e-12:
                    raise ModelError(f"{link.label}: pins {a} and {b} coincide (zero length)")
        self._check_driver()
        for load in self.loads:
            if load.link == FRAME or load.link not in numbers:
                raise ModelError(f"load {load.name or ''} names link {load.link}, which is not a moving link".replace("  ", " "))
            if isinstance(load, PointForce):
                self.link(load.link).point(load.point)
        for key, sigma in self.assembly.items():
            if sigma not in (1, -1):
                raise ModelError(f"assembly branch for {key!r} must be +1 or -1, got {sigma!r}")
        lower = sum(1 for j in self.joints if not isinstance(j, GearMesh))
        higher = len(self.joints) - lower
        dof = 3 * (len(self.links) - 1) - 2 * lower - higher
        if dof != 1:
            raise ModelError(
                f"the mechanism has {dof} degrees of freedom (Gruebler: 3·({len(self.links)}−1) − 2·{lower} − {higher});"
                " graphkin needs exactly one, driven by the driver"
            )

    def _check_driver(self):
        d = self.driver
        if d.link == FRAME:
            raise ModelError("the driver cannot be the frame (link 1)")
        self.link(d.link)
        try:
            joint = self.joint_between(FRAME, d.link)
        except ModelError:
            raise ModelError(f"driver link {d.link} must be joined to the frame (link 1)") from None
        wanted = Revolute if d.kind == "crank" else Prismatic
        if not isinstance(joint, wanted):
            raise ModelError(f"a {d.kind} driver needs a {wanted.__name__.lower()} joint to the frame; link {d.link} has a {joint.label}")
        if isinstance(joint, Prismatic) and joint.guide != FRAME:
            raise ModelError(f"slider driver {d.link}: the guide must be the frame (link 1)")
