"""A whole cycle of a mechanism in one vectorised solve, and what a designer reads off it.

The driving torque against crank angle, its average and power, the peak of
every joint force and where it occurs, the polar data of each joint force
(Söylemez §6.4.1, the strip cutter), the shaking force and moment on the
frame, and the transmission angle of a four-bar.

Signs follow the README's convention: ``F_ij`` is the force of link i on
link j, CCW positive, SI units throughout.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING, Mapping

import numpy as np

from graphkin.analytical import ForceAnalysis
from graphkin.analytical.meshes import pitch
from graphkin.cycle._sampling import (
    SWITCH,
    Peak,
    check_problem,
    peak_of,
    positions,
    sweep_positions,
    switching_angles,
    switching_samples,
)
from graphkin.cycle.flywheel import size_flywheel
from graphkin.cycle.index import JointForceIndex, index_at
from graphkin.cycle.turn import TURN, closing_step, weights
from graphkin.errors import GraphkinError, GraphkinWarning
from graphkin.geometry import as_xy, cross
from graphkin.model import GearMesh, Prismatic, Revolute
from graphkin.notation import position_text

if TYPE_CHECKING:
    from graphkin.cycle.flywheel import Flywheel
    from graphkin.problem import Problem

__all__ = ["SWITCH", "Cycle", "Peak", "Peaks", "check_problem", "peak_of", "positions", "sweep", "sweep_positions",
           "switching_angles", "switching_samples"]


def sweep(problem: "Problem", n: int | None = None, *, at=None) -> "Cycle":
    """Solve a problem over a whole cycle in one vectorised call.

    Parameters
    ----------
    problem : Problem
        The mechanism, its input motion and loads.
    n : int, optional
        If given (crank drivers only), solve at n equally spaced crank angles
        θ = 2πk/n [rad] at the problem's constant ω and α; otherwise at the
        problem's own positions. Either way, a load that acts over part of
        the cycle adds two samples either side of each angle where it
        switches (:func:`switching_samples`), so the cycle has n + 4 positions
        for one such load.
    at : array_like, optional
        Solve at exactly these input positions instead (SI: rad or m), e.g.
        another cycle's ``q`` to compare two machines sample by sample.

    Returns
    -------
    Cycle
        The force analysis at every position, with the cycle's peaks, averages, flywheel and polar data.

    Examples
    --------
    >>> from graphkin import catalog
    >>> c = sweep(catalog.load("strip_cutter"))
    >>> c.n, c.closed   # 180 positions of the book, 2 more either side of 124° and of 156°
    (184, True)
    """
    check_problem(problem, "sweep")
    if at is not None:
        if n is not None:
            raise GraphkinError("give either n (equally spaced crank angles) or at (the positions), not both")
        return Cycle(problem, problem.solve(at=at))
    if problem.given and n is not None:
        # A book's measured values hold at its own position only: a cycle is the motion the input produces.
        warnings.warn(GraphkinWarning(
            f"{problem.name}: its [given] values hold at {position_text(float(problem.q[0]), problem.mechanism.driver.crank)}"
            " only; the cycle is solved with the motion its input produces"), stacklevel=2)
        problem = problem.without_given()
    return Cycle(problem, problem.solve(at=sweep_positions(problem, n)))


@dataclass(frozen=True)
class Peaks:
    """Peak joint forces and the extremes of the driving effort over a cycle.

    Attributes
    ----------
    forces : dict of str to Peak
        For each joint force (``"F12"``, ``"F23"``, ``"G14"``, ...): its peak
        magnitude |F| [N] and where it occurs.
    effort_max, effort_min : Peak
        Largest and smallest driving torque T1j [N·m] (or slider force F1j [N]).
    """

    forces: Mapping[str, Peak]
    effort_max: Peak
    effort_min: Peak


@dataclass(frozen=True)
class Cycle:
    """A force analysis over a cycle, with the quantities a designer reads off it.

    Attributes
    ----------
    problem : Problem
    analysis : ForceAnalysis
        The vectorised solution at every position of the sweep.
    """

    problem: "Problem"
    analysis: ForceAnalysis

    # -- the sweep --------------------------------------------------------
    @property
    def n(self) -> int:
        return self.analysis.n

    @property
    def q(self) -> np.ndarray:
        """Input positions, shape (n,): crank angle θ [rad] or slider position s [m]."""
        return self.analysis.kinematics.q

    @property
    def q_dot(self) -> np.ndarray:
        """Input rate, shape (n,): ω [rad/s] of a crank or v [m/s] of a slider."""
        return self.analysis.kinematics.q_dot

    @property
    def valid(self) -> np.ndarray:
        return self.analysis.valid

    @property
    def closed(self) -> bool:
        """True if the positions are one full turn of a crank (the last step closes the turn)."""
        return self.problem.mechanism.driver.crank and closing_step(self.q) is not None

    # -- the driving effort -------------------------------------------------
    @property
    def torque(self) -> np.ndarray:
        """Driving torque T1j [N·m], shape (n,) (for a slider driver: its force F1j [N] along the guide)."""
        return self.analysis.effort

    @property
    def average(self) -> float:
        """Mean driving effort over the cycle [N·m] (or [N]).

        Over a closed turn: the periodic trapezoidal rule, (1/2π) ∮ T dθ, the
        closing interval from the last angle back to the first included. Over
        positions that are not a closed turn (a slider, a partial sweep): the
        trapezoidal mean over the range swept, ∫ T dq / (q_last − q_first).
        nan if any position is invalid.
        """
        return self._mean(self.torque)

    def mean(self, values) -> float:
        """Mean of any quantity sampled at this cycle's positions, by the same rule as :attr:`average`.

        Use it rather than ``values.mean()``: the positions are not equally
        spaced where a load switches on or off, so a plain mean over-weights
        the two samples crowded at each switching angle.

        Examples
        --------
        >>> from graphkin import catalog
        >>> c = sweep(catalog.load("strip_cutter"))
        >>> round(c.mean(c.power), 1), round(float(c.power.mean()), 1)   # W: the trapezoid, and a biased plain mean
        (755.5, 828.0)
        """
        values = np.asarray(values, dtype=float)
        if values.shape != (self.n,):
            raise GraphkinError(f"mean: expected one value per position, shape ({self.n},), got {values.shape}")
        return self._mean(values)

    def _mean(self, f: np.ndarray) -> float:
        """Periodic trapezoid over a closed turn, else the trapezoid over the range swept."""
        q = self.q
        gap = closing_step(q) if self.closed else None
        if gap is not None:
            return float(np.sum(weights(q, gap) * f) / TURN)
        if self.n < 2 or q[-1] == q[0]:
            return float(f[0]) if self.n == 1 else float("nan")
        return float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(q)) / (q[-1] - q[0]))

    @property
    def power(self) -> np.ndarray:
        """Input power P = T1j·ω (crank) or F1j·v (slider) [W], shape (n,)."""
        return self.torque * self.q_dot

    # -- joint forces ---------------------------------------------------------
    def peaks(self) -> Peaks:
        """Peak magnitude of every joint force, and the effort's maximum and minimum, with their positions."""
        r = self.analysis
        forces = {r.name_of(i, j): peak_of(np.hypot(F[:, 0], F[:, 1]), self.q) for (i, j), F in r.forces.items()}
        return Peaks(forces, peak_of(self.torque, self.q), peak_of(self.torque, self.q, lowest=True))

    def polar(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """A joint force in polar form over the cycle, for a polar plot.

        Parameters
        ----------
        name : str
            ``"F23"`` (force of 2 on 3), ``"F32"`` (its reaction), ``"G14"``, ...

        Returns
        -------
        magnitude : ndarray, shape (n,)
            |F| [N].
        angle : ndarray, shape (n,)
            Direction of F from +x [rad], CCW positive, in (−π, π].
        """
        F = self.analysis[name]
        if F.ndim != 2:
            raise GraphkinError(f"{name} is a torque: it has no direction to plot")
        return np.hypot(F[:, 0], F[:, 1]), np.arctan2(F[:, 1], F[:, 0])

    # -- the frame --------------------------------------------------------------
    def _frame_joints(self):
        r = self.analysis
        mech = self.problem.mechanism
        for (i, j), F in r.forces.items():
            if i == mech.frame:
                yield mech.joint_between(i, j), j, F

    def _driver_point(self) -> np.ndarray:
        mech = self.problem.mechanism
        joint = mech.joint_between(mech.frame, mech.driver.link)
        return self.analysis.kinematics.position(joint.slider, joint.point)

    def shaking_force(self) -> np.ndarray:
        """Resultant force of the mechanism on the frame [N], shape (n, 2).

        The sum over the frame's joints of the force of each moving link on
        the frame, Σ F_j1, plus the reaction −F1j of a slider driver's
        actuator. Summing every moving link's equilibrium (d'Alembert) shows
        it equals −Σ m_i a_Gi + Σ (external forces and weights on the moving
        links): with no external loads it is the inertia forces' resultant.
        """
        S = np.zeros((self.n, 2))
        for _, _, F in self._frame_joints():
            S = S - F
        if not self.problem.mechanism.driver.crank:
            S = S - self.analysis.driver_force()
        return S

    def shaking_moment(self) -> np.ndarray:
        """Moment of the mechanism on the frame about the global origin [N·m], shape (n,), CCW positive.

        The moments of the forces F_j1 at the frame's joints, the couples a
        prismatic pair with the frame transmits, and the driver's reaction:
        −T12 for a crank, −F12 at the slider's point for a slider. It equals
        Σ (r_Gi × (−m_i a_Gi) − I_Gi α_i) plus the moment of the external
        loads on the moving links, all about the origin.
        """
        r = self.analysis
        kin = r.kinematics
        M = np.zeros(self.n)
        for joint, j, F in self._frame_joints():
            if isinstance(joint, Revolute):
                X = kin.position(kin.mechanism.frame, joint.point)
                M = M + cross(X, -F)
            elif isinstance(joint, Prismatic):
                X = kin.position(joint.slider, joint.point)
                M = M + cross(X, -F) - r.couple[(kin.mechanism.frame, j)]
            elif isinstance(joint, GearMesh):  # a held sun or annulus: the tooth force acts at the pitch point
                frame = kin.mechanism.frame
                C_j = kin.z(j, joint.centers[joint.links.index(j)])
                C_frame = kin.z(frame, joint.centers[joint.links.index(frame)])
                X = as_xy(pitch(joint, j, C_j, C_frame)[0])
                M = M + cross(X, -F)
        if self.problem.mechanism.driver.crank:
            M = M - self.torque
        else:
            M = M + cross(self._driver_point(), -r.driver_force())
        return M

    # -- four-bars ----------------------------------------------------------------
    def transmission_angle(self) -> np.ndarray:
        """Transmission angle μ of a crank-driven four-bar [rad], shape (n,), folded to [0, π/2].

        μ is the angle between the coupler (pins A and B) and the rocker
        (pins B0 and B) at B; an angle μ and its supplement π − μ transmit
        force equally well, so μ is reported as min(μ, π − μ).

        Raises
        ------
        GraphkinError
            If the mechanism is not a four-bar of revolute joints driven by a crank.
        """
        mech = self.problem.mechanism
        ok = (len(mech.links) == 4 and len(mech.joints) == 4 and mech.driver.crank
              and all(isinstance(j, Revolute) for j in mech.joints))
        crank = mech.driver.link
        coupler = [j for j in mech.moving if j != crank and any(set(J.links) == {crank, j} for J in mech.joints)]
        if not ok or len(coupler) != 1:
            raise GraphkinError(
                f"{self.problem.name}: the transmission angle is defined for a crank-driven four-bar of four revolute"
                " joints; for other linkages use the joint-force index (graphkin.cycle.joint_force_index)"
            )
        coupler = coupler[0]
        (rocker,) = [j for j in mech.moving if j not in (crank, coupler)]
        kin = self.analysis.kinematics
        A = mech.joint_between(crank, coupler).point
        B = mech.joint_between(coupler, rocker).point
        B0 = mech.joint_between(mech.frame, rocker).point
        PB = kin.position(coupler, B)
        u, v = kin.position(coupler, A) - PB, kin.position(mech.frame, B0) - PB
        mu = np.arctan2(np.abs(cross(u, v)), np.sum(u * v, axis=-1))
        return np.minimum(mu, np.pi - mu)

    # -- flywheel ------------------------------------------------------------------
    def joint_force_index(self, limit: float = 2.0) -> "JointForceIndex":
        """Joint-force index at this cycle's positions (:func:`graphkin.cycle.joint_force_index`)."""
        own = len(self.q) == len(self.problem.q) and np.array_equal(self.q, self.problem.q)
        return index_at(self.problem, None if own else self.q, limit)

    def flywheel(self, Cs: float) -> "Flywheel":
        """Size a flywheel for this cycle's torque (:func:`graphkin.cycle.size_flywheel`).

        Parameters
        ----------
        Cs : float
            Coefficient of speed fluctuation (ω_max − ω_min)/ω_avg, e.g. 0.05.
        """
        why = self.why_no_flywheel()
        if why:
            raise GraphkinError(f"{self.problem.name}: {why}")
        return size_flywheel(self.q, self.torque, omega_avg=float(np.mean(self.q_dot)), Cs=Cs)

    def why_no_flywheel(self) -> str | None:
        """Why no flywheel can be sized for this cycle, in words a student can act on; None if one can.

        A flywheel stores and returns the energy of the torque's swings over
        one whole turn (Norton §11.11), so it needs a crank swept over one
        full turn, a torque at every position of it, and a constant speed.
        """
        if not self.problem.mechanism.driver.crank:
            return "no flywheel can be sized: the driver is a slider, and a flywheel evens out a crank's turn"
        if not self.closed:
            return ("no flywheel can be sized from these positions: they are not one full turn of the crank; "
                    "sweep it over a whole turn (--n N, or sweep(problem, n=...))")
        bad = np.flatnonzero(~self.valid)
        if len(bad):
            i = int(bad[0])
            return (f"no flywheel can be sized: it evens out the torque over a whole turn, but the linkage has no "
                    f"solution at {len(bad)} of the {self.n} positions, the first at "
                    f"{position_text(self.q[i], True)} ({self.analysis.reason(i)}); choose dimensions that let the "
                    "crank turn fully")
        omega = float(np.mean(self.q_dot))
        if not np.allclose(self.q_dot, omega):
            return "no flywheel can be sized: the crank's speed varies over the turn, and sizing assumes a constant ω"
        if omega == 0:
            # A static analysis (or a linkage at rest) has no speed to store energy at.
            return ("no flywheel can be sized: the crank does not turn (ω = 0: "
                    + ("a static analysis" if self.problem.analysis == "static" else "no driver.omega")
                    + "), and a flywheel's size follows from its mean speed; give driver.omega, e.g. \"300 rpm\"")
        if omega < 0:
            return (f"no flywheel can be sized: sizing needs the crank turning counter-clockwise (ω > 0), "
                    f"and here ω = {omega:.6g} rad/s")
        return None
