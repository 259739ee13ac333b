"""Joints (kinematic pairs) between two links.

A revolute joint is named by a point that both links carry; a prismatic joint
by the slider's point that runs on the guide line; a gear mesh by the two
pitch circles. Joint forces follow the sign convention of the README:
``F_ij`` is the force of link i on link j.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import ModelError
from .link import _finite


def _pair(links, what):
    try:
        i, j = links
    except (TypeError, ValueError):
        raise ModelError(f"{what} must join two links, got {links!r}") from None
    if i == j:
        raise ModelError(f"{what} joins link {i} to itself")
    return int(i), int(j)


@dataclass(frozen=True)
class Revolute:
    """A pin joint between ``links`` at the point named ``point`` on both links.

    Its reaction is a force through the pin centre, two unknowns (x, y).
    """

    links: tuple[int, int]
    point: str

    def __post_init__(self):
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
        _pair((self.guide, self.slider), f"prismatic joint at {self.point}")
        for name in ("direction", "slider_direction"):
            object.__setattr__(self, name, _finite(getattr(self, name), f"prismatic joint at {self.point}: {name}"))
        mu = _finite(self.mu, f"prismatic joint at {self.point}: friction coefficient mu")
        if mu < 0:
            raise ModelError(f"prismatic joint at {self.point}: friction coefficient mu must be ≥ 0, got {mu:g}")
        object.__setattr__(self, "mu", mu)

    @property
    def links(self) -> tuple[int, int]:
        return (self.guide, self.slider)

    @property
    def label(self) -> str:
        return f"prismatic {self.guide}–{self.slider} at {self.point}"

    force_letter = "G"


@dataclass(frozen=True)
class GearMesh:
    """Two external spur gears in mesh.

    Parameters
    ----------
    links : (int, int)
        The two gear links. Each must be pivoted (revolute) on one common
        carrier link, usually the frame.
    centers : (str, str)
        Names of the gear centres (their pivot points) on each gear link.
    radii : (float, float)
        Pitch radii [m]; their sum must equal the centre distance.
    pressure_angle : float
        Pressure angle φ [rad], 0 ≤ φ < 45°. The tooth force lies on the
        pressure line, inclined by φ to the common tangent at the pitch point.
    """

    links: tuple[int, int]
    centers: tuple[str, str]
    radii: tuple[float, float]
    pressure_angle: float = math.radians(20.0)

    def __post_init__(self):
        object.__setattr__(self, "links", _pair(self.links, "gear mesh"))
        r = tuple(_finite(x, "gear mesh pitch radius") for x in self.radii)
        if len(r) != 2 or min(r) <= 0:
            raise ModelError(f"gear mesh {self.links[0]}–{self.links[1]}: pitch radii must be two positive lengths, got {self.radii!r}")
        object.__setattr__(self, "radii", r)
        phi = _finite(self.pressure_angle, "gear mesh pressure angle")
        if not 0 <= phi < math.radians(45):
            raise ModelError(f"gear mesh {self.links[0]}–{self.links[1]}: pressure angle must be in [0°, 45°), got {math.degrees(phi):g}°")
        object.__setattr__(self, "pressure_angle", phi)
        object.__setattr__(self, "centers", tuple(str(c) for c in self.centers))

    @property
    def label(self) -> str:
        return f"gear mesh {self.links[0]}–{self.links[1]}"

    force_letter = "F"


Joint = Revolute | Prismatic | GearMesh
