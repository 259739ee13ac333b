"""How a scene's forces change with the input speed: which problems a page may rescale exactly, and why.

At a constant input speed ω (a slider's v) and with no load that depends on it, the kinetostatic system is linear in
its loads, and every inertia load is −m a_G or −I_G α of a motion whose accelerations are ω² times those at unit
speed (the positions, and so the system's matrix, do not change with ω). So every joint force and the driving effort
are

    F(ω) = F_rest + ω² F_ω²,

F_rest from the external loads and weights alone, F_ω² from the inertia loads at ω = 1. Two solves give both parts
exactly, and a page rescales the speed by this arithmetic on the scene's numbers (each inertia resultant by
(ω/ω₀)², its line unmoved). A load whose sense follows the motion keeps its sense for every speed of the same sense,
so the parts are found from two speeds of the file's sense and hold for that sense only (at ω = 0 such a load
vanishes).

Where that does not hold the scene carries the forces at a few presolved speeds (:data:`PRESOLVED`), or, where the
problem is fixed to its own speed, none: :func:`linearity` says which, and why.
"""

from __future__ import annotations

import numpy as np

from graphkin.model import GearMesh, Prismatic

PRESOLVED = (0.5, 1.0, 1.5, 2.0)
"""The speeds a page offers where the forces are not linear in ω², as fractions of the file's own."""


def linearity(problem) -> tuple[str, str]:
    """How the problem's forces depend on its input speed, and why.

    Parameters
    ----------
    problem : graphkin.Problem

    Returns
    -------
    kind : {"superpose", "presolved", "static", "fixed"}
        ``"superpose"``: F(ω) = F_rest + ω² F_ω² holds exactly, for every speed of the file's sense;
        ``"presolved"``: it does not, and the scene holds the forces at :data:`PRESOLVED` speeds;
        ``"static"``: a static analysis, no force depends on the speed;
        ``"fixed"``: the problem holds at its own speed only.
    reason : str
        One sentence a page states beside its speed box.
    """
    mech = problem.mechanism
    symbol = "ω" if mech.driver.crank else "v"
    if problem.static:
        return "static", "a static analysis: no inertia loads, so no force depends on the speed"
    if problem.given:
        return "fixed", "the file gives kinematic values ([given]) that hold at its own speed only"
    if len(set(problem.q_dot)) > 1 or len(set(problem.q_ddot)) > 1:
        return "fixed", "the input's rate varies over the positions the file gives"
    if problem.q_dot[0] == 0:
        return "fixed", f"the input is at rest ({symbol} = 0): no speed of a sense to scale"
    for joint in mech.joints:
        i, j = sorted(joint.links)
        if isinstance(joint, Prismatic) and joint.mu:
            return "presolved", (f"Coulomb friction at the sliding pair of links {i} and {j} (μ = {joint.mu:g}): its "
                                 "size μ|N| is not linear in the loads")
        if isinstance(joint, GearMesh) and joint.efficiency < 1:
            return "presolved", (f"the mesh of gears {i} and {j} loses power (η = {joint.efficiency:g}): the loss "
                                 "follows the power's direction, which is not linear in the loads")
    if problem.q_ddot[0] != 0:
        return "presolved", ("the input accelerates: the joint forces are linear in the square of its speed, but each "
                             "inertia resultant's line moves with it")
    sense = any(getattr(load, "sense", "fixed") != "fixed" for load in mech.loads)
    return "superpose", ("constant input speed and no load that depends on it: every inertia load is "
                         f"{symbol}² times its value at unit speed" +
                         (", and a load whose sense follows the motion keeps it at every speed of this sense"
                          if sense else ""))


def parts(F_a, F_b, rate_a: float, rate_b: float) -> tuple[np.ndarray, np.ndarray]:
    """F_rest and F_ω² from the forces at two speeds of the same sense: F = F_rest + ω² F_ω².

    Parameters
    ----------
    F_a, F_b : array_like
        The same quantity (joint forces [N], an effort [N·m or N]) at the input rates ``rate_a`` and ``rate_b``.
    rate_a, rate_b : float
        The two rates [rad/s or m/s], of the same sense and different sizes.

    Returns
    -------
    F_rest : ndarray
        The part the external loads and weights give (in the unit of F).
    F_omega2 : ndarray
        The part per unit rate squared (in the unit of F per (rad/s)² or (m/s)²).
    """
    F_a, F_b = np.asarray(F_a, float), np.asarray(F_b, float)
    F_omega2 = (F_b - F_a) / (rate_b**2 - rate_a**2)
    return F_a - rate_a**2 * F_omega2, F_omega2
