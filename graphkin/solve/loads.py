"""Known loads on each link: d'Alembert inertia, gravity and external loads."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..geometry import cross
from ..kinematics import Kinematics
from ..model import PointForce, Torque


@dataclass(frozen=True)
class Inertia:
    """d'Alembert inertia loads of one link over n positions.

    Attributes
    ----------
    F : ndarray, shape (n, 2)
        Inertia force −m a_G [N], acting at G.
    T : ndarray, shape (n,)
        Inertia torque −I_G α [N·m], CCW positive.
    h : ndarray, shape (n,)
        Offset |T|/|F| [m] of the single equivalent resultant from G (nan where F = 0).
    line_point : ndarray, shape (n, 2)
        A point of the resultant's line: G shifted by h to the side that
        reproduces the torque's sense (moment of F about G equals T).
    """

    F: np.ndarray
    T: np.ndarray
    h: np.ndarray
    line_point: np.ndarray


def inertia(kin: Kinematics, link: int) -> Inertia:
    """Inertia force and torque of a link and their single equivalent resultant."""
    body = kin.mechanism.link(link)
    F = -body.mass * kin.a_G(link)
    T = -body.I_G * kin.al(link)
    F2 = np.sum(F * F, axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        h = np.where(F2 > 0, np.abs(T) / np.sqrt(F2), np.nan)
        # r × F = T with r ⟂ F gives r = (F × T k)/|F|² = T·(F_y, −F_x)/|F|².
        shift = np.where(F2[:, None] > 0, T[:, None] * np.stack([F[:, 1], -F[:, 0]], -1) / F2[:, None], np.nan)
    return Inertia(F, T, h, kin.G(link) + shift)


def external_loads(kin: Kinematics, link: int):
    """Resultant of the external loads on a link and its moment about the origin.

    Returns
    -------
    F : ndarray, shape (n, 2)
        Sum of external forces and weight [N].
    M : ndarray, shape (n,)
        Their moment about the global origin plus applied torques [N·m].
    """
    mech = kin.mechanism
    n = kin.n
    F = np.zeros((n, 2))
    M = np.zeros(n)
    body = mech.link(link)
    if mech.gravity and body.mass:
        W = np.broadcast_to([0.0, -body.mass * mech.gravity], (n, 2))
        F = F + W
        M = M + cross(kin.G(link), W)
    for load in mech.loads:
        if load.link != link:
            continue
        on = np.ones(n) if load.active is None else load.active.mask(kin.q).astype(float)
        if isinstance(load, PointForce):
            f = on[:, None] * np.asarray(load.force)
            F = F + f
            M = M + cross(kin.position(link, load.point), f)
        elif isinstance(load, Torque):
            M = M + on * load.torque
    return F, M


def known_loads(kin: Kinematics, link: int):
    """External loads plus inertia loads: force (n, 2) and moment about the origin (n,)."""
    F, M = external_loads(kin, link)
    i = inertia(kin, link)
    return F + i.F, M + cross(kin.G(link), i.F) + i.T
