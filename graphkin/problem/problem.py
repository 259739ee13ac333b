"""A problem: a mechanism with its input motion (and kinematic values a book gives), ready to solve."""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any, Mapping

import numpy as np

from graphkin.analytical import solve_forces
from graphkin.errors import GraphkinError
from graphkin.kinematics import solve_kinematics
from graphkin.model import Mechanism, Prismatic
from graphkin.notation import position_text
from graphkin.problem.unknown import Unknown
from graphkin.ranges import as_array, check, finite


@dataclass(frozen=True)
class Forward:
    """A forward step where a book asks one: the crank shaft's angular acceleration from its torque excess.

    At each position the shaft's rotating parts (a flywheel, the crank) of moment of inertia ``I`` about the
    crank's axis take the excess of the torque the mechanism turns the shaft with over the load taken off it:
    I α = T_driving − T_resisting. T_driving = −T12 is the turning moment of the mechanism's loads (gas force,
    inertia of the other links) at the given motion — what the frame would have to supply to keep it; the
    resisting torque, of size ``T_resisting``, opposes the crank's rotation. All CCW positive.

    Attributes
    ----------
    I : float
        Moment of inertia of the parts on the crank shaft about its axis [kg·m²], > 0.
    T_resisting : float
        Size of the resisting torque [N·m], ≥ 0 (a power P taken off at speed ω: P/|ω|).
    """

    I: float
    T_resisting: float

    def step(self, T12, omega) -> dict:
        """T_driving, T_resisting and α at each position (CCW positive).

        Parameters
        ----------
        T12 : array_like, shape (n,)
            The driving effort found at the given motion [N·m].
        omega : array_like, shape (n,)
            The crank's angular velocity [rad/s]: the resisting torque opposes it.

        Returns
        -------
        dict of str to ndarray, shape (n,)
            ``{"T_driving": N·m, "T_resisting": N·m, "alpha": rad/s²}``.
        """
        T_driving = -np.asarray(T12, dtype=float)
        T_resisting = -np.sign(np.asarray(omega, dtype=float)) * self.T_resisting
        return {"T_driving": T_driving, "T_resisting": T_resisting, "alpha": (T_driving + T_resisting) / self.I}


@dataclass(frozen=True)
class Problem:
    """A mechanism with its input motion, as read from a problem file.

    Attributes
    ----------
    name : str
        Catalog name or file path.
    mechanism : Mechanism
    q, q_dot, q_ddot : ndarray, shape (n,)
        Input positions and rates, SI.
    given : dict
        Kinematic values the problem gives instead of deriving them, keyed
        ``(link, "omega" | "alpha" | "a_G" | "v_G" | "theta")`` and
        ``(link, "at", point)`` for a point's position [m] (see
        :class:`graphkin.kinematics.Kinematics`).
    title, source, notes : str
    cite : str
        The source in one line for students (a handout's title block); empty: the first clause of ``source``
        (:func:`graphkin.notation.citation`).
    analysis : {"dynamic", "static"}
        ``"static"`` leaves every inertia load out (masses are then needed
        only for weights, and the input rates only give the sense of motion
        for friction); ``"dynamic"`` (the default) includes them.
    forward : Forward or None
        The forward step the book asks for (the file's ``[forward]``).
    unknown : Unknown or None
        The link whose effort the book asks for instead of the driver's (the file's ``[unknown]``,
        :mod:`graphkin.problem.unknown`).
    """

    name: str
    mechanism: Mechanism
    q: np.ndarray
    q_dot: np.ndarray
    q_ddot: np.ndarray
    given: Mapping[tuple[int, str], Any] = field(default_factory=dict)
    title: str = ""
    source: str = ""
    notes: str = ""
    analysis: str = "dynamic"
    cite: str = ""
    forward: Forward | None = None
    unknown: Unknown | None = None

    @property
    def static(self) -> bool:
        """True for a static force analysis (no inertia loads)."""
        return self.analysis == "static"

    @property
    def input_name(self) -> str:
        """``"theta"`` for a crank, ``"s"`` for a slider."""
        return "theta" if self.mechanism.driver.crank else "s"

    def at_speed(self, q_dot: float, q_ddot: float | None = None) -> "Problem":
        """The same problem driven at a constant input rate (its title says so).

        Parameters
        ----------
        q_dot : float
            ω [rad/s] of a crank or v [m/s] of a slider, at every position.
        q_ddot : float, optional
            α [rad/s²] or a [m/s²]; by default the problem's own (first) value.

        Examples
        --------
        >>> from graphkin import catalog
        >>> fast = catalog.load("slider_crank_friction").at_speed(200.0)
        >>> float(fast.q_dot[0])
        200.0
        """
        crank = self.mechanism.driver.crank
        rate = {"q_dot": finite(q_dot, f"{self.name}: q_dot", "rad/s" if crank else "m/s"),
                "q_ddot": finite(self.q_ddot[0] if q_ddot is None else q_ddot, f"{self.name}: q_ddot",
                                  "rad/s²" if crank else "m/s²")}
        check(rate["q_dot"], "angular_velocity" if crank else "velocity", f"{self.name}: q_dot")
        check(rate["q_ddot"], "angular_acceleration" if crank else "acceleration", f"{self.name}: q_ddot")
        if self.given:
            # Given ω, α, a_G or v_G belong to the file's speed; at another speed they would be silently wrong.
            raise GraphkinError(f"{self.name}: it gives kinematic values ([given] in the file) that hold at its own"
                                " speed only; remove them to let graphkin derive the motion at another speed")
        m = len(self.q)
        speed = f"{rate['q_dot'] * 30 / np.pi:.4g} rpm" if crank else f"{rate['q_dot']:.4g} m/s"
        title = f"{self.title} (driven at {speed})" if self.title else ""
        return replace(self, q_dot=np.full(m, rate["q_dot"]), q_ddot=np.full(m, rate["q_ddot"]), title=title)

    def without_given(self) -> "Problem":
        """The same problem with its motion derived from the input at every position: the ``[given]`` values dropped.

        A book's measured ω, α, a_G or θ hold at its own position only; a whole cycle (an explorer, a scene) is
        drawn from the motion the input produces.

        Examples
        --------
        >>> from graphkin import catalog
        >>> p = catalog.load("slider_crank_dynamic_makdin")
        >>> bool(p.given), bool(p.without_given().given)
        (True, False)
        """
        return replace(self, given={})

    def with_friction(self, mu: float) -> "Problem":
        """The same problem with Coulomb coefficient μ (≥ 0) at every sliding pair; 0 removes friction.

        Examples
        --------
        >>> from graphkin import catalog
        >>> p = catalog.load("slider_crank_friction")
        >>> round(float(p.with_friction(0.0).solve(at=[0.5]).effort[0]), 4) != round(float(p.solve(at=[0.5]).effort[0]), 4)
        True
        """
        joints = tuple(replace(j, mu=mu) if isinstance(j, Prismatic) else j for j in self.mechanism.joints)
        if not any(isinstance(j, Prismatic) for j in joints):
            raise GraphkinError(f"{self.name}: it has no sliding pair to put friction on")
        return replace(self, mechanism=replace(self.mechanism, joints=joints))

    def kinematics(self, at=None):
        """Kinematics at the file's positions, or at ``at``.

        Parameters
        ----------
        at : float or array_like, shape (n,), optional
            Input positions θ [rad] or s [m], instead of the file's.

        Returns
        -------
        graphkin.kinematics.Kinematics

        Raises
        ------
        GraphkinError
            If ``at`` is not one number or a 1-D list of finite numbers within
            graphkin's ranges, or the file's rates vary with position.
        """
        q, q_dot, q_ddot = self.q, self.q_dot, self.q_ddot
        if at is not None:
            crank = self.mechanism.driver.crank
            at = as_array(at, f"{self.name}: at", "angle" if crank else "coordinate")
            if len(set(self.q_dot)) > 1 or len(set(self.q_ddot)) > 1:
                raise GraphkinError(f"{self.name}: its input rates vary with position, so it can only be solved at its "
                                    "own positions")
            if self.given and np.any(at != self.q[0]):
                # A book's ω, α, a_G or v_G hold at its own position: at any other they would be silently wrong.
                elsewhere = position_text(float(at[np.flatnonzero(at != self.q[0])[0]]), crank)
                raise GraphkinError(f"{self.name}: it gives kinematic values ([given] in the file) that hold at its own "
                                    f"position only ({position_text(float(self.q[0]), crank)}), not at {elsewhere}; "
                                    "remove them to let graphkin derive the motion at every position")
            q, q_dot, q_ddot = at, np.full(len(at), self.q_dot[0]), np.full(len(at), self.q_ddot[0])
        kin = solve_kinematics(self.mechanism, q, q_dot, q_ddot)
        if self.given:
            n = len(q)
            given = {key: np.broadcast_to(np.asarray(v, dtype=float), (n, 2) if key[1] in ("a_G", "v_G", "at") else (n,))
                     for key, v in self.given.items()}
            kin = kin.with_given(given)
        if self.static:
            kin = replace(kin, static=True)
        return kin

    def solve(self, at=None):
        """Force analysis (:class:`graphkin.analytical.ForceAnalysis`) at the file's positions or at ``at``.

        Parameters
        ----------
        at : float or array_like, shape (n,), optional
            Input positions θ [rad] or s [m] (see :meth:`kinematics`).
        """
        kin = self.kinematics(at)
        if self.unknown is not None:
            return self.unknown.solve(kin, solve_forces)
        return solve_forces(kin)
