"""The mechanism: links, joints, the driver, loads and the assembly branch."""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field, replace
from functools import cached_property
from types import MappingProxyType
from typing import Mapping

from graphkin.errors import ModelError
from graphkin.model.driver import Driver
from graphkin.model.joints import GearMesh, Joint, Prismatic, Revolute
from graphkin.model.link import FRAME, FRAME_NUMBERS, Link
from graphkin.model.loads import Load, PointForce, SpringForce, Torque, standard_gravity
from graphkin.ranges import complaint


@dataclass(frozen=True)
class Mechanism:
    """A planar linkage with one degree of freedom, as data.

    Parameters
    ----------
    links : sequence of Link
        All links, the frame (number 1) included.
    joints : sequence of Revolute, Prismatic or GearMesh
        The joints between them: pins, sliding pairs and gear meshes.
    driver : Driver
        The input link and whether it is a crank or a slider.
    loads : sequence of PointForce or Torque
        External loads (inertia loads are added by the solver).
    gravity : float
        g [m/s²] acting along −y on every link's centre of mass; 0 to neglect.
    assembly : mapping of str to {+1, −1}
        Assembly branch σ of each dyad, keyed by the name of its middle joint
        point (see :mod:`graphkin.kinematics.groups`); +1 where not given.
    title, source : str
        What the problem is and where it comes from (book, example).
    frame : int
        The frame's link number: 1 (the default, Norton and Söylemez) or 0
        (books that write F01, T01). Every name follows the numbers as given:
        with the frame 0 and the crank 1, the driving torque is ``T01`` and the
        crank's pivot force ``F01``.
    """

    links: tuple[Link, ...]
    joints: tuple[Joint, ...]
    driver: Driver
    loads: tuple[Load, ...] = ()
    gravity: float = 0.0
    assembly: Mapping[str, int] = field(default_factory=dict)
    title: str = ""
    source: str = ""
    frame: int = FRAME

    def __post_init__(self):
        for name in ("links", "joints", "loads"):
            value = getattr(self, name)
            # A single Link (or a string) where a list of them belongs would otherwise fail deep inside.
            if isinstance(value, (str, bytes, Mapping)) or not hasattr(value, "__iter__"):
                raise ModelError(f"{name} must be a list, got a single {type(value).__name__}", at=(name,))
            object.__setattr__(self, name, tuple(value))
        object.__setattr__(self, "gravity", standard_gravity(self.gravity))
        if not isinstance(self.assembly, Mapping):
            raise ModelError(f"assembly must map joint points to +1 or -1, e.g. {{'B': 1}}, got {self.assembly!r}",
                             at=("assembly",))
        object.__setattr__(self, "assembly", MappingProxyType(dict(self.assembly)))
        if isinstance(self.frame, bool) or self.frame not in FRAME_NUMBERS:
            raise ModelError(f"the frame's number must be 1 or 0, got {self.frame!r}", at=("frame", "number"))
        object.__setattr__(self, "frame", int(self.frame))
        self._check()
        if self.driver.frame != self.frame:
            object.__setattr__(self, "driver", replace(self.driver, frame=self.frame))

    # -- look-ups ---------------------------------------------------------
    def link(self, number: int) -> Link:
        """The link with this number; a clear error naming the known ones if absent."""
        for link in self.links:
            if link.number == number:
                return link
        have = ", ".join(str(l.number) for l in self.links)
        raise ModelError(f"unknown link {number!r} (the mechanism has links {have})")

    @cached_property
    def moving(self) -> tuple[int, ...]:
        """Numbers of the moving links, in ascending order (found once: the solvers ask for it per load)."""
        return tuple(sorted(l.number for l in self.links if l.number != self.frame))

    def joints_of(self, number: int) -> tuple[Joint, ...]:
        return tuple(j for j in self.joints if number in j.links)

    def joint_between(self, i: int, j: int) -> Joint:
        joint = self._pairs.get(frozenset((i, j)))
        if joint is None:
            raise ModelError(f"no joint between links {i} and {j}")
        return joint

    @cached_property
    def _pairs(self) -> dict:
        """Each pair of links (a frozenset) → the first joint between them (a construction asks thousands of times)."""
        pairs: dict = {}
        for joint in self.joints:
            pairs.setdefault(frozenset(joint.links), joint)
        return pairs

    # -- validation -------------------------------------------------------
    def _check(self):
        # Each error carries where it lies (``at``), so a problem file's reader can name the field.
        self._check_types()
        numbers = [l.number for l in self.links]
        for k, n in enumerate(numbers):
            if n in numbers[:k]:
                raise ModelError(f"link {n} is defined twice; give each link its own number", at=("links", k, "number"))
        if self.frame not in numbers:
            raise ModelError(f"the mechanism needs a frame: link {self.frame}")
        for k, n in enumerate(numbers):
            if n < self.frame:
                raise ModelError(f"link {n}: with the frame numbered {self.frame}, the moving links are numbered from "
                                 f"{self.frame + 1} up", at=("links", k, "number"))
        known = ", ".join(map(str, sorted(numbers)))
        for k, joint in enumerate(self.joints):
            fields = ("guide", "slider") if isinstance(joint, Prismatic) else ("links[0]", "links[1]")
            for n, name in zip(joint.links, fields):
                if n not in numbers:
                    raise ModelError(f"{joint.label} names unknown link {n} (links are {known})", at=("joints", k, name))
            if isinstance(joint, Revolute):
                needs = [(n, joint.point, "point") for n in joint.links]
            elif isinstance(joint, Prismatic):
                needs = [(joint.slider, joint.point, "point"), (joint.guide, joint.through, "through")]
            else:
                needs = [(n, c, f"centers[{m}]") for m, (n, c) in enumerate(zip(joint.links, joint.centers))]
            for n, name, where in needs:
                try:
                    self.link(n).point(name)
                except ModelError as exc:
                    raise ModelError(f"{joint.label}: {exc}", at=("joints", k, where)) from None
        pairs = [frozenset(j.links) for j in self.joints]
        for k, p in enumerate(pairs):
            if p in pairs[:k]:
                i, j = sorted(p)
                raise ModelError(f"links {i} and {j} are joined twice; one joint per pair",
                                 at=("joints", k, "slider" if isinstance(self.joints[k], Prismatic) else "links"))
        for k, link in enumerate(self.links):
            pins = [j.point for j in self.joints_of(link.number) if isinstance(j, Revolute)]
            for a, b in itertools.combinations(sorted(set(pins)), 2):
                (xa, ya), (xb, yb) = link.point(a), link.point(b)
                d = math.hypot(xb - xa, yb - ya)
                if d <= 1e-12:
                    raise ModelError(f"{link.label}: pins {a} and {b} coincide (zero length)", at=("links", k, "points"))
                # Shorter than the smallest length graphkin accepts: surely a unit slip (µm for mm), and the
                # solvers' products of such lengths would lose every digit.
                why = complaint(d, "length")
                if why:
                    raise ModelError(f"{link.label}: the distance {d:.3g} m between pins {a} and {b} {why}",
                                     at=("links", k, "points"))
        self._check_driver()
        for k, load in enumerate(self.loads):
            if load.link == self.frame or load.link not in numbers:
                raise ModelError(f"load {load.name or ''} names link {load.link}, which is not a moving link "
                                 f"(moving links are {', '.join(map(str, self.moving))})".replace("  ", " "),
                                 at=("loads", k, "link"))
            if isinstance(load, PointForce):
                try:
                    self.link(load.link).point(load.point)
                except ModelError as exc:
                    raise ModelError(f"load {load.name + ': ' if load.name else ''}{exc}", at=("loads", k, "point")) from None
            if isinstance(load, SpringForce):
                if load.anchor_link not in numbers:
                    raise ModelError(f"{load.name or 'spring'}: its other end names unknown link {load.anchor_link} "
                                     f"(links are {known})", at=("loads", k, "links"))
                try:
                    self.link(load.anchor_link).point(load.anchor_point)
                except ModelError as exc:
                    raise ModelError(f"{load.name or 'spring'}: {exc}", at=("loads", k, "points")) from None
        for key, sigma in self.assembly.items():
            if isinstance(sigma, bool) or sigma not in (1, -1):
                raise ModelError(f"assembly branch for {key!r} must be +1 or -1, got {sigma!r}", at=("assembly", key))
        lower = sum(1 for j in self.joints if not isinstance(j, GearMesh))
        higher = len(self.joints) - lower
        dof = 3 * (len(self.links) - 1) - 2 * lower - higher
        if dof != 1:
            raise ModelError(
                f"the mechanism has {dof} degrees of freedom (Gruebler: 3·({len(self.links)}−1) − 2·{lower} − {higher});"
                " graphkin needs exactly one, driven by the driver", at=("joints",)
            )

    def _check_types(self):
        """Plain messages for parts of the wrong kind (a dict for a Link, a tuple for a joint, ...)."""
        for what, items, kinds, names in (
            ("links", self.links, (Link,), "Link"),
            ("joints", self.joints, (Revolute, Prismatic, GearMesh), "Revolute, Prismatic or GearMesh"),
            ("loads", self.loads, (PointForce, Torque), "PointForce or Torque"),
        ):
            for k, item in enumerate(items):
                if not isinstance(item, kinds):
                    raise ModelError(f"{what}[{k}] must be a {names}, got a {type(item).__name__}",
                                     at=(what, k))
        if not isinstance(self.driver, Driver):
            raise ModelError(f"driver must be a Driver, e.g. Driver(2, 'crank'), got {self.driver!r}", at=("driver",))

    def _check_driver(self):
        d = self.driver
        at = ("driver", "link")
        if d.link == self.frame:
            raise ModelError(f"the driver cannot be the frame (link {self.frame})", at=at)
        try:
            self.link(d.link)
            joint = self.joint_between(self.frame, d.link)
        except ModelError as exc:
            if d.link not in [l.number for l in self.links]:
                raise ModelError(f"driver: {exc}", at=at) from None
            raise ModelError(f"driver link {d.link} must be joined to the frame (link {self.frame})", at=at) from None
        wanted = Revolute if d.crank else Prismatic
        if not isinstance(joint, wanted):
            raise ModelError(f"a {d.kind} driver needs a {wanted.__name__.lower()} joint to the frame; "
                             f"link {d.link} has a {joint.label}", at=("driver", "type"))
        if isinstance(joint, Prismatic) and joint.guide != self.frame:
            raise ModelError(f"slider driver {d.link}: the guide must be the frame (link {self.frame})", at=at)
