"""Joints (kinematic pairs) between two links.

A revolute joint is named by a point that both links carry; a prismatic joint
by the slider's point that runs on the guide line; a gear mesh by the two
pitch circles. Joint forces follow the sign convention of the README:
``F_ij`` is the force of link i on link j.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.errors import ModelError
from graphkin.ranges import check, finite


def _pair(links, what, at=("links",)):
    try:
        i, j = links
    except (TypeError, ValueError):
        raise ModelError(f"{what} must join two links, got {links!r}", at=at) from None
    for n in (i, j):
        # int("3") or int(2.7) would quietly make a link number of a string or a fraction.
        if isinstance(n, (bool, np.bool_)) or not isinstance(n, (int, np.integer)):
            raise ModelError(f"{what} must join two links given by number, e.g. (2, 3), got {links!r}", at=at)
    if i == j:
        raise ModelError(f"{what} joins link {i} to itself", at=at)
    return int(i), int(j)


def _name(value, what, at=()) -> str:
    """A point's name: a non-empty string."""
    if not isinstance(value, str) or not value:
        raise ModelError(f"{what} must be the name of a point, e.g. 'A', got {value!r}", at=at)
    return value


@dataclass(frozen=True)
class Revolute:
    """A pin joint between ``links`` at the point named ``point`` on both links.

    Its reaction is a force through the pin centre, two unknowns (x, y).
    """

    links: tuple[int, int]
    point: str

    def __post_init__(self):
        _name(self.point, "revolute joint: point", ("point",))
        object.__setattr__(self, "links", _pair(self.links, f"revolute joint at {self.point}"))

    @property
    def label(self) -> str:
        return f"revolute {self.links[0]}–{self.links[1]} at {self.point}"

    force_letter = "F"


@dataclass(frozen=True)
class Prismatic:
    """A slider: ``slider`` translates along a line fixed in ``guide``.

    Parameters
    ----------
    guide, slider : int
        Link that carries the guide line, link that slides on it.
    point : str
        The slider's point that lies on the guide line (the block's pin).
    through : str
        A point of the guide link that the guide line passes through.
    direction : float
        Direction of the guide line in the guide link's frame [rad].
    slider_direction : float
        Direction of the same line in the slider's frame [rad] (0 for a block
        whose x-axis runs along the guide). Fixes the slider's orientation:
        θ_slider = θ_guide + direction − slider_direction.
    mu : float
        Coulomb friction coefficient μ ≥ 0. The friction force, μ|N|, opposes
        the slider's motion relative to the guide.

    Notes
    -----
    The reaction ``G_ij`` (guide force) has a normal component N and, with
    friction, a tangential one; its line is located by the couple C that the
    pair also transmits (offset e = C/N along the guide from ``point``).
    """

    guide: int
    slider: int
    point: str
    through: str
    direction: float = 0.0
    slider_direction: float = 0.0
    mu: float = 0.0

    def __post_init__(self):
        _name(self.point, "prismatic joint: point", ("point",))
        _name(self.through, f"prismatic joint at {self.point}: through", ("through",))
        _pair((self.guide, self.slider), f"prismatic joint at {self.point}", ("slider",))
        for name in ("direction", "slider_direction"):
            what = f"prismatic joint at {self.point}: {name}"
            object.__setattr__(self, name, check(finite(getattr(self, name), what, "rad"), "angle", what))
        mu = finite(self.mu, f"prismatic joint at {self.point}: friction coefficient mu")
        if mu < 0:
            raise ModelError(f"prismatic joint at {self.point}: friction coefficient mu must be ≥ 0, got {mu:g}")
        object.__setattr__(self, "mu", check(mu, "friction", f"prismatic joint at {self.point}: friction coefficient mu"))

    @property
    def links(self) -> tuple[int, int]:
        return (self.guide, self.slider)

    @property
    def label(self) -> str:
        return f"prismatic {self.guide}–{self.slider} at {self.point}"

    force_letter = "G"


@dataclass(frozen=True)
class GearMesh:
    """Two spur gears in mesh: external (two pinions), or internal (a pinion inside an annulus).

    Parameters
    ----------
    links : (int, int)
        The two gear links. Their centres stay a fixed distance apart: both
        gears are pivoted on one carrier link (the frame, or the arm of an
        epicyclic train), or one is pivoted on a link that turns about the
        other's centre (a planet on an arm that turns about the sun's axis).
    centers : (str, str)
        Names of the gear centres (their pivot points) on each gear link.
    radii : (float, float)
        Pitch radii [m]; their sum (internal: their difference) must equal the
        centre distance.
    pressure_angle : float
        Pressure angle φ [rad], 0 ≤ φ < 45°. The tooth force lies on the
        pressure line, inclined by φ to the common tangent at the pitch point.
    internal : bool
        True for an annulus (ring gear) with teeth inside, meshing with a
        pinion inside it: the gear with the larger pitch radius is the
        annulus. Relative to a carrier that holds both centres, the two then
        turn the same way (external gears turn opposite ways).
    efficiency : float
        Mesh efficiency η, 0 < η ≤ 1 (default 1, no loss): the power the
        driven gear receives is η times what the driving gear gives, both
        measured relative to the carrier. An internal mesh needs η above the
        ratio of the pinion's pitch radius to the annulus's (below it no
        tooth force can turn the two that way). See
        :func:`graphkin.analytical.meshes.contact`.
    """

    links: tuple[int, int]
    centers: tuple[str, str]
    radii: tuple[float, float]
    pressure_angle: float = math.radians(20.0)
    internal: bool = False
    efficiency: float = 1.0

    def __post_init__(self):
        object.__setattr__(self, "links", _pair(self.links, "gear mesh"))
        label = f"gear mesh {self.links[0]}–{self.links[1]}"
        if isinstance(self.radii, (str, bytes)) or not hasattr(self.radii, "__len__") or len(self.radii) != 2:
            raise ModelError(f"{label}: pitch radii must be two positive lengths [m], got {self.radii!r}")
        r = tuple(finite(x, f"{label}: pitch radius", "m") for x in self.radii)
        if min(r) <= 0:
            raise ModelError(f"{label}: pitch radii must be two positive lengths, got {self.radii!r}")
        object.__setattr__(self, "radii", tuple(check(x, "length", f"{label}: pitch radius") for x in r))
        if isinstance(self.centers, (str, bytes)) or not hasattr(self.centers, "__len__") or len(self.centers) != 2:
            raise ModelError(f"{label}: centers must name the two gear centres, e.g. ('O2', 'O3'), got {self.centers!r}")
        for c in self.centers:
            _name(c, f"{label}: centre")
        phi = finite(self.pressure_angle, "gear mesh pressure angle")
        if not 0 <= phi < math.radians(45):
            raise ModelError(f"gear mesh {self.links[0]}–{self.links[1]}: pressure angle must be in [0°, 45°), "
                             f"got {math.degrees(phi):.12g}°", at=("pressure_angle",))
        object.__setattr__(self, "pressure_angle", phi)
        object.__setattr__(self, "centers", tuple(self.centers))
        if not isinstance(self.internal, (bool, np.bool_)):
            raise ModelError(f"{label}: internal must be True (an annulus and a pinion) or False, got {self.internal!r}",
                             at=("internal",))
        object.__setattr__(self, "internal", bool(self.internal))
        if self.internal and abs(r[0] - r[1]) <= 1e-9 * max(r):
            raise ModelError(f"{label}: an internal mesh needs an annulus larger than its pinion, got equal pitch radii "
                             f"{r[0] * 1e3:.6g} mm", at=("radii",))
        eta = finite(self.efficiency, f"{label}: efficiency")
        if not 0 < eta <= 1:
            raise ModelError(f"{label}: efficiency must be above 0 and at most 1 (the fraction of the power the driving "
                             f"gear gives that the driven one receives), got {eta:g}", at=("efficiency",))
        if self.internal and eta <= min(r) / max(r):
            raise ModelError(f"{label}: an internal mesh's efficiency must be above the pinion's pitch radius over the "
                             f"annulus's ({min(r) / max(r):.6g}): below it the tooth force's line, which divides the "
                             f"line of centres in the ratio of the torques, would have to lie outside both gears, "
                             f"got {eta:g}", at=("efficiency",))
        object.__setattr__(self, "efficiency", float(eta))

    @property
    def label(self) -> str:
        return f"{'internal ' if self.internal else ''}gear mesh {self.links[0]}–{self.links[1]}"

    @property
    def ring(self) -> int | None:
        """The annulus of an internal mesh (the gear of the larger pitch radius), None for an external mesh."""
        if not self.internal:
            return None
        return self.links[0] if self.radii[0] > self.radii[1] else self.links[1]

    def radius(self, link: int) -> float:
        """Pitch radius [m] of gear ``link``."""
        return self.radii[self.links.index(link)]

    @property
    def centre_distance(self) -> float:
        """Distance between the gear centres [m]: r₁ + r₂, or the annulus's less the pinion's."""
        return abs(self.radii[0] - self.radii[1]) if self.internal else self.radii[0] + self.radii[1]

    force_letter = "F"


Joint = Revolute | Prismatic | GearMesh
