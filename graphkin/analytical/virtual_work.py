"""The driving effort from virtual work: one power balance in place of the joint forces.

With d'Alembert's inertia loads added, a mechanism is in equilibrium, and the
powers of all the loads on it add up to zero at every instant. In a
frictionless mechanism the joint forces take no power (the two links at a pin
or a gear's pitch point move together there, and a guide's normal force is
across the sliding), so one equation gives the driving effort::

    T12 ω2 + Σ_loads F·v_P + Σ_torques T ω + Σ_links (F_i·v_G + T_i ω) = 0

with F_i = −m a_G and T_i = −I_G α (a crank driver; a slider driver's force F12
takes the place of T12 and its speed v of ω2). Signs as everywhere in graphkin
(see :func:`graphkin.draw.draw_sign_convention`).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from graphkin.analytical.loads import applied, inertia
from graphkin.errors import GraphkinError
from graphkin.kinematics import Kinematics, solve_kinematics
from graphkin.model import GearMesh, PointForce, Prismatic


def load_powers(kin: Kinematics) -> dict[str, np.ndarray]:
    """The power of every known load at each position: external loads, weights and inertia loads.

    Parameters
    ----------
    kin : graphkin.kinematics.Kinematics
        The motion. A static analysis (``kin.static``) has no inertia loads and
        may stand still: its powers are those of a virtual motion at a unit
        input rate (ω = 1 rad/s, or v = 1 m/s for a slider driver).

    Returns
    -------
    dict of str to ndarray, shape (n,)
        Power [W] of each load, by name: the external loads by their names
        (``"load k"`` for an unnamed one, k counting from 1), ``"weight of link j"``
        and ``"inertia of link j"`` (the force −m a_G at G and the torque −I_G α
        together). Positive where the load drives the mechanism.

    Examples
    --------
    >>> from graphkin import catalog
    >>> p = catalog.load("engine_gas_force")
    >>> {name: round(float(P[0])) for name, P in load_powers(p.kinematics()).items()}
    {'FL (net gas load)': 527281, 'inertia of link 4': -147946}
    """
    kin = _moving(kin)
    mech = kin.mechanism
    powers: dict[str, np.ndarray] = {}
    for k, load in enumerate(mech.loads, start=1):
        value = applied(kin, load)
        if isinstance(load, PointForce):
            v = kin.z_velocity(load.link, load.point)
            P = value.real * v.real + value.imag * v.imag
        else:
            P = value * kin.omega[load.link]
        name = load.name or f"load {k}"
        powers[name] = powers.get(name, 0.0) + P
    for link in mech.moving:
        body = mech.link(link)
        if mech.gravity and body.mass:
            powers[f"weight of link {link}"] = -body.mass * mech.gravity * kin.v_G(link)[:, 1]
        if not kin.static and (body.mass or body.I_G):
            i = inertia(kin, link)
            P = np.sum(np.nan_to_num(i.F) * kin.v_G(link), axis=1) + i.T * kin.omega[link]
            powers[f"inertia of link {link}"] = P
    return powers


def effort_by_virtual_work(kin: Kinematics) -> np.ndarray:
    """The driving torque T12 (or force F12) from the power balance, without the joint forces.

    Parameters
    ----------
    kin : graphkin.kinematics.Kinematics
        The motion, as for :func:`load_powers`.

    Returns
    -------
    ndarray, shape (n,)
        T12 [N·m] of a crank driver or F12 [N] of a slider driver, signed as
        :attr:`graphkin.analytical.ForceAnalysis.effort`: −Σ P / q̇. nan where
        the input stands still (q̇ = 0 in a dynamic analysis) or the linkage
        cannot be assembled.

    Raises
    ------
    GraphkinError
        If a sliding pair has friction, or a gear mesh an efficiency below 1:
        the power they lose needs a joint force, which is what virtual work
        leaves out.

    Notes
    -----
    The velocities are the linkage's own. A problem that writes a book's rounded link angles as
    ``[given]`` positions is solved by the matrix method at the book's geometry, which is not exactly a
    position of the linkage; there the two efforts differ by the book's rounding (about 1 % for
    Mak & Din's four-bar).

    Examples
    --------
    >>> from graphkin import catalog
    >>> p = catalog.load("engine_gas_force")
    >>> round(float(effort_by_virtual_work(p.kinematics())[0]), 1), round(float(p.solve().effort[0]), 1)
    (-14489.5, -14489.5)
    """
    for joint in kin.mechanism.joints:
        if isinstance(joint, Prismatic) and joint.mu:
            raise GraphkinError(f"virtual work: the slider {joint.slider} on {joint.guide} has friction "
                                f"(mu = {joint.mu:g}); its power needs the normal force, so solve the joint forces")
        if isinstance(joint, GearMesh) and joint.efficiency < 1:
            raise GraphkinError(f"virtual work: the {joint.label} has an efficiency of {joint.efficiency:g}; the "
                                "power it loses needs its tooth force, so solve the joint forces")
    moving = _moving(kin)
    total = sum(load_powers(moving).values(), np.zeros(moving.n))
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(moving.q_dot != 0, -total / moving.q_dot, np.nan)


def _moving(kin: Kinematics) -> Kinematics:
    """The motion itself, or a static analysis at a unit input rate (its virtual motion)."""
    if not kin.static or np.all(kin.q_dot != 0):
        return kin
    return replace(solve_kinematics(kin.mechanism, kin.q, 1.0, 0.0), static=True)
