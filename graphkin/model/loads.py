"""External loads: point forces and torques on links, and gravity.

A load may act only over a range of the input coordinate, like the cutting
force of the strip cutter (Söylemez §6.4.1: 2000 N for 124° < θ12 < 156°).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import ModelError
from .link import _finite, _point
from .ranges import check


EDGE = 1e-12
"""Relative distance from an end of an :class:`Active` interval within which a position counts as on the end."""


@dataclass(frozen=True)
class Active:
    """The open interval ``start < q < stop`` of the input where a load acts.

    For a crank the interval is in radians and taken modulo one turn, so
    ``Active(radians(350), radians(10))`` acts across 0°.
    """

    start: float
    stop: float
    periodic: bool = True

    def __post_init__(self):
        kind, unit = ("angle", "rad") if self.periodic else ("coordinate", "m")
        for name in ("start", "stop"):
            what = f"active window: {name}"
            object.__setattr__(self, name, check(_finite(getattr(self, name), what, unit), kind, what))

    @property
    def width(self) -> float:
        """Width of the window [rad or m] (modulo one turn for a crank)."""
        return (self.stop - self.start) % (2 * math.pi) if self.periodic else self.stop - self.start

    def mask(self, q):
        """Boolean array: where the load acts, for input positions ``q``.

        The interval is open: a position within rounding (:data:`EDGE`,
        relative) of ``start`` or ``stop`` is outside, so 124° computed two
        ways gives the same answer.
        """
        q = np.asarray(q, dtype=float)
        if not self.periodic:
            tol = EDGE * max(abs(self.start), abs(self.stop), 1.0)
            return (q > self.start + tol) & (q < self.stop - tol)
        turn = 2 * math.pi
        tol = EDGE * turn
        width = (self.stop - self.start) % turn
        d = (q - self.start) % turn
        return (d > tol) & (d < width - tol)


@dataclass(frozen=True)
class PointForce:
    """A force of fixed global direction on a link.

    Parameters
    ----------
    link : int
        Link it acts on.
    point : str
        Point of the link where it acts.
    force : (float, float)
        Force vector (Fx, Fy) [N] in global axes.
    active : Active or None
        Where it acts; None for always.
    name : str
        Label for reports, e.g. ``"F13"``.
    """

    link: int
    point: str
    force: tuple[float, float]
    active: Active | None = None
    name: str = ""

    def __post_init__(self):
        object.__setattr__(self, "force", _point(self.force, f"force on link {self.link} at {self.point}", "force"))


@dataclass(frozen=True)
class Torque:
    """A couple T [N·m] on a link, CCW positive."""

    link: int
    torque: float
    active: Active | None = None
    name: str = ""

    def __post_init__(self):
        what = f"torque on link {self.link}"
        object.__setattr__(self, "torque", check(_finite(self.torque, what, "N·m"), "torque", what))


Load = PointForce | Torque


def standard_gravity(g: float) -> float:
    """Validate a gravitational acceleration g [m/s²] (acts along −y)."""
    g = check(_finite(g, "gravity", "m/s²"), "acceleration", "gravity")
    if g < 0:
        raise ModelError(f"gravity must be ≥ 0 m/s² (it acts along −y), got {g:g}")
    return g
