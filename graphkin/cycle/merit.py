"""The figures of merit of one design of a study, read off its cycle (:class:`Design`, :func:`merit`).

A designer judges a choice by what it costs over the whole cycle (Norton, *Design of Machinery*, ch. 11): the peak
and RMS driving torque, the flywheel it needs, the peak force at each joint, the shaking force and moment on the
frame, the smallest transmission angle. A design that cannot be assembled somewhere on its cycle has none of them
(nan): a peak over part of a cycle would look better than the design is. :func:`graphkin.cycle.study` reads the same
figures off a batch of designs at once; :func:`merit` reads them off one :class:`~graphkin.cycle.Cycle`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping

import numpy as np

from graphkin.cycle.sweep import Cycle
from graphkin.errors import GraphkinError
from graphkin.notation import position_text

__all__ = ["Design", "failed", "merit", "unbuilt"]

@dataclass(frozen=True)
class Design:
    """One design of a study and its figures of merit over the cycle (SI units; nan where not defined).

    Attributes
    ----------
    values : tuple
        The value of each varied field, in the order of :attr:`Study.fields`, as given (problem-file values).
    torque_peak : float
        Largest |T1j| over the cycle [N·m] (a slider driver: |F1j| [N]).
    torque_rms : float
        Root mean square of the driving effort, √(mean T²) by the cycle's trapezoidal rule
        (:meth:`Cycle.mean`) [N·m] (or [N]).
    joint_peaks : dict of str to float
        Largest |F| at each joint over the cycle [N], by the force's name (``"F12"``, ``"F23"``, ...).
    I_s : float
        The flywheel's system inertia for the study's C_s [kg·m²] (:meth:`Cycle.flywheel`); nan where none can
        be sized, and :attr:`no_flywheel` says why.
    shaking_force_peak : float
        Largest |Σ F_j1| on the frame [N] (:meth:`Cycle.shaking_force`).
    shaking_moment_peak : float
        Largest |M| of the mechanism on the frame about the origin [N·m] (:meth:`Cycle.shaking_moment`).
    transmission_angle_min : float
        Smallest transmission angle μ over the cycle [rad] (folded to [0, π/2]); nan for a linkage that is not
        a crank-driven four-bar of revolutes.
    failure : str or None
        Where and why the design cannot be assembled over the whole cycle (its first such position); None if it
        can.
    failed_at : float
        That position, θ [rad] or s [m]; nan if the design assembles everywhere.
    no_flywheel : str or None
        Why no flywheel can be sized (:meth:`Cycle.why_no_flywheel`); None if one can.
    """

    values: tuple
    torque_peak: float
    torque_rms: float
    joint_peaks: Mapping[str, float]
    I_s: float
    shaking_force_peak: float
    shaking_moment_peak: float
    transmission_angle_min: float
    failure: str | None = None
    failed_at: float = math.nan
    no_flywheel: str | None = None

    @property
    def ok(self) -> bool:
        """True if the design assembles at every position of its cycle."""
        return self.failure is None




def unbuilt(values: tuple, why: str) -> Design:
    """A design whose values, together, make no mechanism (each alone does): marked, its figures nan."""
    nan = math.nan
    return Design(values, nan, nan, {}, nan, nan, nan, nan, why, nan, "the design cannot be built")


def failed(values: tuple, names: list, count: int, q: np.ndarray, i: int, crank: bool, reason: str) -> Design:
    """A design that has no solution at ``count`` of the positions ``q``, the first ``q[i]``, for ``reason``."""
    nan = math.nan
    return Design(values, nan, nan, dict.fromkeys(names, nan), nan, nan, nan, nan,
                  f"no solution at {count} of the {len(q)} positions, the first at {position_text(q[i], crank)}: "
                  f"{reason}", float(q[i]), "the design cannot be assembled over the whole cycle")


def merit(cycle: Cycle, values: tuple, Cs: float) -> Design:
    """The figures of merit of one design's cycle (see :class:`Design`).

    Parameters
    ----------
    cycle : Cycle
        The design swept over its cycle.
    values : tuple
        The design's values of the varied fields.
    Cs : float
        Coefficient of speed fluctuation for the flywheel.
    """
    names = [cycle.analysis.name_of(i, j) for (i, j) in cycle.analysis.forces]
    bad = np.flatnonzero(~cycle.valid)
    if len(bad):
        i = int(bad[0])
        return failed(values, names, len(bad), cycle.q, i, cycle.problem.mechanism.driver.crank,
                       cycle.analysis.reason(i))
    T = cycle.torque
    peaks = cycle.peaks().forces
    why = cycle.why_no_flywheel()
    try:
        mu = float(np.min(cycle.transmission_angle()))
    except GraphkinError:  # not a crank-driven four-bar: μ is not defined (the joint-force index is)
        mu = math.nan
    return Design(
        values=values,
        torque_peak=float(np.max(np.abs(T))),
        torque_rms=math.sqrt(cycle.mean(T * T)),
        joint_peaks={name: peaks[name].value for name in names},
        I_s=math.nan if why else cycle.flywheel(Cs).I_s,
        shaking_force_peak=float(np.max(np.hypot(*cycle.shaking_force().T))),
        shaking_moment_peak=float(np.max(np.abs(cycle.shaking_moment()))),
        transmission_angle_min=mu,
        no_flywheel=why,
    )


