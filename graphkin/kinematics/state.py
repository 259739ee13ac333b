"""The kinematic state of every link over a batch of input positions."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping

import numpy as np

from ..geometry import dot, perp, rotate, unit
from ..model import Mechanism, Prismatic


@dataclass(frozen=True)
class Kinematics:
    """Position, velocity and acceleration of every link, for n input positions.

    Each link is described by the motion of its frame: angle ``theta``, angular
    velocity ``omega`` and acceleration ``alpha`` (CCW positive), and the
    position, velocity and acceleration of the frame's origin ``O``. Points of
    the link follow from rigid-body kinematics (:meth:`position`,
    :meth:`velocity`, :meth:`acceleration`).

    Attributes
    ----------
    mechanism : Mechanism
    q, q_dot, q_ddot : ndarray, shape (n,)
        Input coordinate and its rates: θ [rad], ω [rad/s], α [rad/s²] of a
        crank, or s [m], v [m/s], a [m/s²] of a slider.
    theta, omega, alpha : dict of int to ndarray, shape (n,)
    O, v_O, a_O : dict of int to ndarray, shape (n, 2)
    valid : ndarray of bool, shape (n,)
        False where the linkage cannot be assembled or is at a dead point.
    failures : dict of str to ndarray of bool
        For each group that failed somewhere, where and why (key is the reason).
    given : dict
        Values supplied by a problem instead of derived (``{(3, "a_G"): ...}``),
        used as they are by the force analysis.
    """

    mechanism: Mechanism
    q: np.ndarray
    q_dot: np.ndarray
    q_ddot: np.ndarray
    theta: Mapping[int, np.ndarray]
    omega: Mapping[int, np.ndarray]
    alpha: Mapping[int, np.ndarray]
    O: Mapping[int, np.ndarray]
    v_O: Mapping[int, np.ndarray]
    a_O: Mapping[int, np.ndarray]
    valid: np.ndarray
    failures: Mapping[str, np.ndarray] = field(default_factory=dict)
    given: Mapping[tuple[int, str], np.ndarray] = field(default_factory=dict)

    @property
    def n(self) -> int:
        return len(self.q)

    # -- points -----------------------------------------------------------
    def _local(self, link: int, point) -> np.ndarray:
        if isinstance(point, str):
            point = self.mechanism.link(link).point(point)
        return rotate(np.asarray(point, dtype=float), self.theta[link])

    def position(self, link: int, point) -> np.ndarray:
        """Global position [m] of a point of ``link`` (a name or local (x, y)), shape (n, 2)."""
        return self.O[link] + self._local(link, point)

    def velocity(self, link: int, point) -> np.ndarray:
        """Velocity [m/s] of a point of ``link``, shape (n, 2)."""
        return self.v_O[link] + self.omega[link][:, None] * perp(self._local(link, point))

    def acceleration(self, link: int, point) -> np.ndarray:
        """Acceleration [m/s²] of a point of ``link``, shape (n, 2)."""
        r = self._local(link, point)
        return self.a_O[link] + self.alpha[link][:, None] * perp(r) - (self.omega[link] ** 2)[:, None] * r

    # -- centres of mass --------------------------------------------------
    def G(self, link: int) -> np.ndarray:
        """Position of the centre of mass G [m], shape (n, 2)."""
        return self.position(link, self.mechanism.link(link).G)

    def v_G(self, link: int) -> np.ndarray:
        """Velocity of G [m/s], shape (n, 2)."""
        return self.given.get((link, "v_G"), self.velocity(link, self.mechanism.link(link).G))

    def a_G(self, link: int) -> np.ndarray:
        """Acceleration of G [m/s²], shape (n, 2) (a given value if the problem supplied one)."""
        return self.given.get((link, "a_G"), self.acceleration(link, self.mechanism.link(link).G))

    def w(self, link: int) -> np.ndarray:
        """Angular velocity ω [rad/s] (given or derived)."""
        return self.given.get((link, "omega"), self.omega[link])

    def al(self, link: int) -> np.ndarray:
        """Angular acceleration α [rad/s²] (given or derived)."""
        return self.given.get((link, "alpha"), self.alpha[link])

    # -- sliders ----------------------------------------------------------
    def guide_direction(self, joint: Prismatic) -> np.ndarray:
        """Global unit vector u along a prismatic joint's guide, shape (n, 2)."""
        return unit(self.theta[joint.guide] + joint.direction)

    def slide_rate(self, joint: Prismatic, on: int) -> np.ndarray:
        """Velocity [m/s] of link ``on`` relative to the other link of ``joint``, along u.

        Its sign decides the direction of Coulomb friction on ``on``.
        """
        other = joint.guide if on == joint.slider else joint.slider
        X = self.position(joint.slider, joint.point)
        v_on = self.v_O[on] + self.w(on)[:, None] * perp(X - self.O[on])
        v_other = self.v_O[other] + self.w(other)[:, None] * perp(X - self.O[other])
        return dot(v_on - v_other, self.guide_direction(joint))

    def reason(self, i: int) -> str:
        """Why position ``i`` is invalid ('' if it is valid)."""
        return "; ".join(why for why, where in self.failures.items() if where[i])
