"""Links: rigid bodies with named points and mass properties."""

from __future__ import annotations

from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

from graphkin.errors import ModelError
from graphkin.ranges import check, finite, point

FRAME = 1
"""Link number of the frame (ground) unless a mechanism says otherwise: many books number it 1, others 0
(:attr:`graphkin.model.Mechanism.frame`)."""

FRAME_NUMBERS = (0, 1)
"""The numbers a frame may carry: 1 (Norton, Söylemez) or 0 (books that write F01, M01)."""


@dataclass(frozen=True)
class Link:
    """A rigid link with named points in its own frame.

    The link frame is attached to the link; ``theta`` of the link (from the
    kinematics) is the angle of this frame's x-axis from the global x-axis.
    By convention the first two points of a bar are placed on its x-axis,
    so ``theta`` is the angle of the bar as the books draw it (θ13 for AB).

    Parameters
    ----------
    number : int
        Link number, ≥ 0; the frame is 1 (or 0, see :attr:`Mechanism.frame`).
    points : mapping of str to (float, float)
        Named points in the link frame [m], e.g. ``{"A": (0, 0), "B": (0.5, 0)}``.
    mass : float
        Mass m [kg], ≥ 0 (0 for a massless link).
    G : (float, float)
        Centre of mass in the link frame [m].
    I_G : float
        Moment of inertia about G, normal to the plane [kg·m²], ≥ 0.
    name : str
        A label for reports ("crank", "coupler").
    """

    number: int
    points: Mapping[str, tuple[float, float]] = field(default_factory=dict)
    mass: float = 0.0
    G: tuple[float, float] = (0.0, 0.0)
    I_G: float = 0.0
    name: str = ""

    def __post_init__(self):
        if isinstance(self.number, bool) or not isinstance(self.number, int) or self.number < 0:
            raise ModelError(f"link number must be a whole number ≥ 0, got {self.number!r}")
        label = f"link {self.number}"
        if not isinstance(self.points, Mapping):
            raise ModelError(f"{label} points must map names to (x, y) in metres, e.g. {{'A': (0, 0)}}, "
                             f"got {self.points!r}")
        points = {str(k): point(v, f"{label} point {k}") for k, v in dict(self.points).items()}
        object.__setattr__(self, "points", MappingProxyType(points))
        mass = finite(self.mass, f"{label} mass")
        if mass < 0:
            raise ModelError(f"{label} mass must be ≥ 0 kg, got {mass:g} kg")
        check(mass, "mass", f"{label} mass")
        I_G = finite(self.I_G, f"{label} I_G")
        if I_G < 0:
            raise ModelError(f"{label} I_G must be ≥ 0 kg·m², got {I_G:g} kg·m²")
        check(I_G, "moment_of_inertia", f"{label} I_G")
        object.__setattr__(self, "mass", mass)
        object.__setattr__(self, "I_G", I_G)
        object.__setattr__(self, "G", point(self.G, f"{label} G"))

    @property
    def label(self) -> str:
        """``"link 3 (coupler)"`` or ``"link 3"``."""
        return f"link {self.number} ({self.name})" if self.name else f"link {self.number}"

    def point(self, name: str) -> tuple[float, float]:
        """Local coordinates of point ``name`` [m]; a clear error if it is not on the link."""
        try:
            return self.points[name]
        except KeyError:
            have = ", ".join(sorted(self.points)) or "none"
            raise ModelError(f"{self.label} has no point {name!r} (it has: {have})") from None

    @classmethod
    def from_radius_of_gyration(cls, number, points, mass, G, k, name=""):
        """Build a link from its radius of gyration k [m]: I_G = m k²."""
        k = finite(k, f"link {number} radius of gyration")
        if k < 0:
            raise ModelError(f"link {number} radius of gyration must be ≥ 0, got {k:g} m")
        check(k, "length0", f"link {number} radius of gyration")
        return cls(number, points, mass, G, mass * k * k, name)
