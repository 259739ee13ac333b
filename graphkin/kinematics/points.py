"""Position, velocity and acceleration of any point of a link, from a known point of the same link.

A rigid body's points move together: with ω and α of the link and a point A
whose motion is known,

    v_P = v_A + ω × r_AP,        a_P = a_A + α × r_AP − ω² r_AP,

where r_AP = r_P − r_A (ω × r is ``i ω r`` for plane vectors written as
complex numbers). :func:`point_motion` takes the link's centre of mass G as
the known point and uses the values the force analysis uses: a ``[given.N]``
ω, α, v_G, a_G or point position where the problem gives one, the derived
value elsewhere. Without given values this is the link frame's own
rigid-body motion (:meth:`graphkin.kinematics.Kinematics.velocity`) to
rounding.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from graphkin.geometry import as_xy, as_z

__all__ = ["PointMotion", "link_points", "point_motion", "rigid_body"]


@dataclass(frozen=True)
class PointMotion:
    """The motion of one point over n positions.

    Attributes
    ----------
    position : ndarray, shape (n, 2)
        [m]
    velocity : ndarray, shape (n, 2)
        [m/s]
    acceleration : ndarray, shape (n, 2)
        [m/s²]
    """

    position: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray


def rigid_body(r_A, v_A, a_A, omega, alpha, r_P) -> tuple[np.ndarray, np.ndarray]:
    """Velocity and acceleration of a point P of a rigid body from a point A of the same body.

    Parameters
    ----------
    r_A, v_A, a_A : array_like, shape (n, 2)
        Position [m], velocity [m/s] and acceleration [m/s²] of A.
    omega, alpha : array_like, shape (n,)
        Angular velocity [rad/s] and acceleration [rad/s²] of the body, CCW positive.
    r_P : array_like, shape (n, 2)
        Position of P [m].

    Returns
    -------
    v_P, a_P : ndarray, shape (n, 2)
        ``v_A + ω × r_AP`` and ``a_A + α × r_AP − ω² r_AP``.

    Examples
    --------
    >>> v, a = rigid_body([[0, 0]], [[0, 0]], [[0, 0]], [2.0], [0.0], [[0.5, 0]])
    >>> v.tolist(), a.tolist()
    ([[0.0, 1.0]], [[-2.0, 0.0]])
    """
    r = as_z(r_P) - as_z(r_A)
    w, al = np.asarray(omega, dtype=float), np.asarray(alpha, dtype=float)
    # At a dead point ω and α are infinite: nan there, by design (the position is not valid), not a warning.
    with np.errstate(invalid="ignore", over="ignore"):
        return as_xy(as_z(v_A) + 1j * w * r), as_xy(as_z(a_A) + (1j * al - w**2) * r)


def point_motion(kin, link: int, point) -> PointMotion:
    """Position, velocity and acceleration of a point of ``link`` over every position of ``kin``.

    Parameters
    ----------
    kin : graphkin.kinematics.Kinematics
    link : int
        A moving link.
    point : str or (float, float)
        A named point of the link, or local coordinates [m].

    Returns
    -------
    PointMotion
        Found from G's motion and the link's ω and α (given or derived, as the
        force analysis uses them); see the module's docstring.
    """
    G = kin.G(link)
    P = kin.position(link, point)
    v, a = rigid_body(G, kin.v_G(link), kin.a_G(link), kin.w(link), kin.al(link), P)
    return PointMotion(P, v, a)


def link_points(kin, link: int) -> dict[str, PointMotion]:
    """Every named point of ``link``, by name, as :class:`PointMotion`."""
    return {name: point_motion(kin, link, name) for name in kin.mechanism.link(link).points}
