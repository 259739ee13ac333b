"""The kinematic state of every link over a batch of input positions.

Inside, plane vectors are complex numbers x + iy, as in the textbooks' loop
equations (r e^{iθ}): a rotation is one multiplication by e^{iθ}, and
ω × r is iωr. Methods return ordinary arrays of shape (n, 2).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import Mapping

import numpy as np

from graphkin.geometry import as_xy, as_z
from graphkin.geometry import zdot as dot
from graphkin.model import Mechanism, Prismatic, Revolute

STILL = 1e-9
"""Relative sliding speed below which a sliding pair counts as still (no Coulomb friction)."""


@dataclass(frozen=True)
class Kinematics:
    """Position, velocity and acceleration of every link, for n input positions.

    Each link is described by the motion of its frame: angle ``theta``,
    angular velocity ``omega`` and acceleration ``alpha`` (CCW positive), and
    the position, velocity and acceleration of the frame's origin. Points of
    the link follow from rigid-body kinematics (:meth:`position`,
    :meth:`velocity`, :meth:`acceleration`).

    Attributes
    ----------
    mechanism : Mechanism
    q, q_dot, q_ddot : ndarray, shape (n,)
        Input coordinate and its rates: θ [rad], ω [rad/s], α [rad/s²] of a
        crank, or s [m], v [m/s], a [m/s²] of a slider.
    theta, omega, alpha : dict of int to ndarray, shape (n,)
    e : dict of int to complex ndarray, shape (n,)
        e^{iθ} of each link.
    O, v_O, a_O : dict of int to complex ndarray, shape (n,)
        Position [m], velocity [m/s] and acceleration [m/s²] of each link
        frame's origin, as x + iy.
    valid : ndarray of bool, shape (n,)
        False where the linkage cannot be assembled or is at a dead point.
    failures : dict of str to ndarray of bool
        For each group that failed somewhere, where and why (key is the reason).
    groups : tuple
        The driver and Assur groups in solution order
        (:func:`graphkin.kinematics.decompose`).
    given : dict
        Values supplied by a problem instead of derived, keyed
        ``(link, "omega" | "alpha" | "a_G" | "v_G" | "theta")`` and
        ``(link, "at", point)`` (a point's global position [m], shape (n, 2));
        used by the force analysis. Set them with :meth:`with_given`, which
        also places a link whose angle θ is given.
    static : bool
        True for a static force analysis: the solvers leave out every inertia
        load (−m a_G, −I_G α); the motion still gives the sense of sliding for
        Coulomb friction.
    loops : dict of int to tuple
        For each RRR dyad (by its index in ``groups``), the loop the kinematic
        pass solved: the joints' points, the arms, the size of the
        determinant. The force analysis reuses them, so that it gives the same
        numbers to the last digit whether it is called on these kinematics or
        through :func:`graphkin.analytical.solve`. Empty once values are given
        (:meth:`with_given`).
    points : dict of (int, str) to complex or complex ndarray, shape (n,), optional
        Each named point in its link's frame [m], in place of the mechanism's: a batch of designs of one
        linkage (:mod:`graphkin.analytical.designs`) gives one value per position where its designs differ.
        None (the default): the mechanism's own.
    """

    mechanism: Mechanism
    q: np.ndarray
    q_dot: np.ndarray
    q_ddot: np.ndarray
    theta: Mapping[int, np.ndarray]
    omega: Mapping[int, np.ndarray]
    alpha: Mapping[int, np.ndarray]
    e: Mapping[int, np.ndarray]
    O: Mapping[int, np.ndarray]
    v_O: Mapping[int, np.ndarray]
    a_O: Mapping[int, np.ndarray]
    valid: np.ndarray
    failures: Mapping[str, np.ndarray] = field(default_factory=dict)
    groups: tuple = ()
    given: Mapping[tuple, np.ndarray] = field(default_factory=dict)
    static: bool = False
    loops: Mapping[int, tuple] = field(default_factory=dict, repr=False, compare=False)
    points: Mapping[tuple, complex | np.ndarray] | None = field(default=None, repr=False, compare=False)

    @property
    def n(self) -> int:
        return len(self.q)

    def with_given(self, given: Mapping[tuple, np.ndarray]) -> "Kinematics":
        """These kinematics with values measured off a drawing (or read from polygons) in place of the derived ones.

        Parameters
        ----------
        given : mapping
            ``(link, "omega")`` [rad/s], ``(link, "alpha")`` [rad/s²], ``(link, "theta")`` [rad], each shape (n,);
            ``(link, "a_G")`` [m/s²], ``(link, "v_G")`` [m/s], ``(link, "at", point)`` [m], each shape (n, 2).

        Returns
        -------
        Kinematics
            A link with a given angle θ is turned, as a rigid body, about its
            anchor: the pin that joins it to a link located before it (for a
            coupler AB driven at A, the pin A; for a rocker B0B, the pivot
            B0), or its origin if it has no such pin. Its other points move
            with it, so the pin it shares with the next link may sit slightly
            apart on the two links, as on a drawing whose angles are read to the
            degree: each link's equilibrium uses its own points. A point given
            by its position (``"at"``) sits there on that link only.
        """
        from dataclasses import replace

        theta, e, O = dict(self.theta), dict(self.e), dict(self.O)
        v_O, a_O = dict(self.v_O), dict(self.a_O)
        for key, value in given.items():
            if key[1] != "theta":
                continue
            link = key[0]
            anchor = self.anchor(link)
            p = self._p(link, anchor) if anchor is not None else 0j
            X = self.z(link, anchor) if anchor is not None else self.O[link]
            v_X = self.z_velocity(link, (p.real, p.imag))
            a_X = self.z_acceleration(link, (p.real, p.imag))
            w = np.asarray(given.get((link, "omega"), self.omega[link]), dtype=float)
            al = np.asarray(given.get((link, "alpha"), self.alpha[link]), dtype=float)
            theta[link] = np.asarray(value, dtype=float)
            e[link] = np.exp(1j * theta[link])
            O[link] = X - e[link] * p
            r = O[link] - X
            v_O[link] = v_X + 1j * w * r
            a_O[link] = a_X + (1j * al - w**2) * r
        out = replace(self, theta=theta, e=e, O=O, v_O=v_O, a_O=a_O, given=dict(given), loops={})
        # The motion the input derives, which the given values stand in for (graphkin.graphical constructs from it).
        object.__setattr__(out, "_derived", self.derived if self.given else self)
        return out

    @property
    def derived(self) -> Kinematics | None:
        """The kinematics whose derived values :meth:`with_given` replaced by given ones: the motion the input
        produces, the same positions and mechanism (these kinematics themselves where nothing is given). None where
        it is not known: kinematics with given values made otherwise than by :meth:`with_given` (a copy by
        ``dataclasses.replace`` keeps only the fields)."""
        return self.__dict__.get("_derived", None if self.given else self)

    def anchor(self, link: int) -> str | None:
        """The pin link ``link`` is turned about when its angle is given: its revolute joint to a link located before it."""
        located = {self.mechanism.frame}
        for g in self.groups:
            if link in g.links:
                for joint in g.joints:
                    if isinstance(joint, Revolute) and link in joint.links and (set(joint.links) - {link}) <= located:
                        return joint.point
                return None
            located |= set(g.links)
        return None

    # -- complex forms, used by the solvers -------------------------------
    def _p(self, link: int, point) -> complex:
        if isinstance(point, str):
            if self.points is not None and (link, point) in self.points:
                return self.points[link, point]
            point = self.mechanism.link(link).point(point)
        return complex(point[0], point[1])

    def z(self, link: int, point) -> np.ndarray:
        """Position of a point of ``link`` as complex x + iy [m], shape (n,) (a given position if there is one)."""
        if isinstance(point, str) and (link, "at", point) in self.given:
            return as_z(self.given[(link, "at", point)])
        return self.O[link] + self.e[link] * self._p(link, point)

    # At a dead point ω and α are infinite and a position that cannot be assembled is nan: their
    # products are nan there, by design (``valid`` says so), not a floating-point warning.
    def z_velocity(self, link: int, point) -> np.ndarray:
        with np.errstate(invalid="ignore", over="ignore"):
            return self.v_O[link] + 1j * self.omega[link] * (self.e[link] * self._p(link, point))

    def z_acceleration(self, link: int, point) -> np.ndarray:
        r = self.e[link] * self._p(link, point)
        with np.errstate(invalid="ignore", over="ignore"):
            return self.a_O[link] + (1j * self.alpha[link] - self.omega[link] ** 2) * r

    def z_G(self, link: int) -> np.ndarray:
        return self.z(link, self.mechanism.link(link).G)

    def z_a_G(self, link: int) -> np.ndarray:
        if (link, "a_G") in self.given:
            return as_z(self.given[(link, "a_G")])
        return self.z_acceleration(link, self.mechanism.link(link).G)

    # -- points -----------------------------------------------------------
    def position(self, link: int, point) -> np.ndarray:
        """Global position [m] of a point of ``link`` (a name or local (x, y)), shape (n, 2)."""
        return as_xy(self.z(link, point))

    def velocity(self, link: int, point) -> np.ndarray:
        """Velocity [m/s] of a point of ``link``, shape (n, 2)."""
        return as_xy(self.z_velocity(link, point))

    def acceleration(self, link: int, point) -> np.ndarray:
        """Acceleration [m/s²] of a point of ``link``, shape (n, 2)."""
        return as_xy(self.z_acceleration(link, point))

    # -- centres of mass --------------------------------------------------
    def G(self, link: int) -> np.ndarray:
        """Position of the centre of mass G [m], shape (n, 2)."""
        return as_xy(self.z_G(link))

    def v_G(self, link: int) -> np.ndarray:
        """Velocity of G [m/s], shape (n, 2) (a given value if the problem supplied one)."""
        return self.given.get((link, "v_G"), self.velocity(link, self.mechanism.link(link).G))

    def a_G(self, link: int) -> np.ndarray:
        """Acceleration of G [m/s²], shape (n, 2) (a given value if the problem supplied one)."""
        return as_xy(self.z_a_G(link))

    def w(self, link: int) -> np.ndarray:
        """Angular velocity ω [rad/s] (given or derived)."""
        return self.given.get((link, "omega"), self.omega[link])

    def al(self, link: int) -> np.ndarray:
        """Angular acceleration α [rad/s²] (given or derived)."""
        return self.given.get((link, "alpha"), self.alpha[link])

    # -- sliders ----------------------------------------------------------
    def z_guide(self, joint: Prismatic) -> np.ndarray:
        """Unit vector u along a prismatic joint's guide, complex, shape (n,)."""
        return self.e[joint.guide] * np.exp(1j * joint.direction)

    def guide_direction(self, joint: Prismatic) -> np.ndarray:
        """Global unit vector u along a prismatic joint's guide, shape (n, 2)."""
        return as_xy(self.z_guide(joint))

    def slide_rate(self, joint: Prismatic, on: int) -> np.ndarray:
        """Velocity [m/s] of link ``on`` relative to the other link of ``joint``, along u.

        Its sign decides the direction of Coulomb friction on ``on``.
        """
        other = joint.guide if on == joint.slider else joint.slider
        X = self.z(joint.slider, joint.point)
        v_on = self.v_O[on] + 1j * self.w(on) * (X - self.O[on])
        v_other = self.v_O[other] + 1j * self.w(other) * (X - self.O[other])
        return dot(v_on - v_other, self.z_guide(joint))

    def sliding(self, joint: Prismatic) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The slider's motion relative to its guide link, at the slider's point P: the textbook's decomposition

        a_P(slider) = a_P(guide) + a_c + a_r u,    a_c = 2 ω_g × v_r u,

        where P(guide) is the guide link's point coinciding with P, u the guide's direction (turning with the
        guide link, :meth:`z_guide`) and ω_g the guide's angular velocity (the slider's too: the pair keeps them
        turning together). All from the derived motion, not values a problem gives (:meth:`with_given`).

        Returns
        -------
        v_r : ndarray, shape (n,)
            Sliding velocity [m/s] along u: (v_P(slider) − v_P(guide)) · u.
        a_r : ndarray, shape (n,)
            Sliding acceleration [m/s²] along u, the rate of v_r as the guide link sees it:
            (a_P(slider) − a_P(guide)) · u (a_c is perpendicular to u).
        a_c : complex ndarray, shape (n,)
            Coriolis component [m/s²] as x + iy: v_r u turned 90° in the sense of ω_g, of size 2 |ω_g v_r|.
        """
        g, p = joint.guide, self._p(joint.slider, joint.point)
        u = self.z_guide(joint)
        w = self.omega[g]
        r = self.O[joint.slider] + self.e[joint.slider] * p - self.O[g]  # P from the guide link's origin
        with np.errstate(invalid="ignore", over="ignore"):
            v_r = dot(self.z_velocity(joint.slider, joint.point) - (self.v_O[g] + 1j * w * r), u)
            a_r = dot(self.z_acceleration(joint.slider, joint.point) - (self.a_O[g] + (1j * self.alpha[g] - w * w) * r),
                      u)
            return v_r, a_r, 2j * w * v_r * u

    def slide_sense(self, joint: Prismatic, on: int) -> np.ndarray:
        """Sense of :meth:`slide_rate`: +1, −1, or 0 where the pair is still, shape (n,).

        "Still" means a rate below ``STILL`` times the mechanism's velocity
        scale (the speed of its fastest named point at that position), so a
        dead centre whose slide rate is rounding (1e-17 m/s) gives no
        friction rather than full friction of a random sense.
        """
        rate = self.slide_rate(joint, on)
        return np.where(np.abs(rate) > STILL * self.speed_scale, np.sign(rate), 0.0)

    @cached_property
    def speed_scale(self) -> np.ndarray:
        """Largest speed of any named point of any moving link [m/s], shape (n,).

        Computed once: every sliding pair's friction asks for it, several times per
        construction. (A frozen dataclass still takes a cached property: it writes
        the instance's ``__dict__``, and :func:`dataclasses.replace` makes a new one.)
        """
        scale = np.zeros(self.n)
        for link in self.mechanism.moving:
            for name in self.mechanism.link(link).points:
                scale = np.maximum(scale, np.abs(self.z_velocity(link, name)))
        return scale

    def reason(self, i: int) -> str:
        """Why position ``i`` is invalid ('' if it is valid)."""
        why = "; ".join(why for why, where in self.failures.items() if where[i])
        return why or ("" if self.valid[i] else "the motion is not finite there (no group says why)")
