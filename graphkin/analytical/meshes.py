"""A gear mesh's geometry for the force analysis: the pitch point, and where the tooth force acts with a mesh
efficiency (:func:`contact`), which both routes and the matrix method use.

Sign convention as everywhere (:func:`graphkin.draw.draw_sign_convention`); points as complex numbers x + iy [m].
"""

from __future__ import annotations

import numpy as np

from graphkin.kinematics import GearGroup, Kinematics


def pitch(mesh, k, Ck, Cj):
    """The pitch point of a mesh, and the unit vectors of gear k's tooth force there, from the centres of k and j.

    Returns ``(P, t, r)``: the pitch point [m], the tangent t along which a positive tangential force turns k
    counter-clockwise about Ck, and the radial direction r of the separating part of the tooth force on k. With
    e the unit vector from k's centre to j's: external, P = Ck + r_k e and r = −e (each gear is pushed away from
    the other); internal, the pitch point lies beyond the pinion's centre on the annulus's side (P = Ck + r_k e
    for the annulus, Ck − r_k e for the pinion) and r = +e (the pinion is pushed towards the annulus's centre,
    the annulus away from it).
    """
    rk = mesh.radius(k)
    e = (Cj - Ck) / np.abs(Cj - Ck)
    out = -1.0 if mesh.internal and k != mesh.ring else 1.0  # which way from Ck the pitch point lies, along e
    return Ck + out * rk * e, out * 1j * e, e if mesh.internal else -e


def contact(mesh, k, Ck, Cj, flow=0.0):
    """Where the tooth force on gear k acts: ``(X, t, r, rho)``, X on the line of centres and rho its distance from
    k's centre, the arm of k's moment (t and r as :func:`pitch` gives them).

    Without loss (``mesh.efficiency`` 1, or no power through the mesh, ``flow`` 0) X is the pitch point and rho the
    pitch radius r_k. A mesh efficiency η is a loss of power where the teeth slide: relative to the carrier (the
    link both centres are on, the frame for gears on fixed axes), the driven gear receives η times the power the
    driving gear gives. The tooth force is one force, equal and opposite on the two gears, so it is its line that
    moves: it crosses the line of centres at X, which divides it so that the arms are in the ratio
    ρ_k / ρ_j = f r_k / r_j, with f = η when the power flows into k (``flow`` > 0: k is driven, its torque is η
    times the ideal) and 1/η when it flows out of k (``flow`` < 0: k drives, the other gear's torque is η times
    the ideal). The arms add up to the centre distance a (external), or differ by it (internal: X beyond the
    pinion, on the annulus's side, as the pitch point is). The line keeps the pressure angle's direction.

    Parameters
    ----------
    mesh : GearMesh
    k : int
        The gear the force acts on.
    Ck, Cj : complex or complex ndarray, shape (n,)
        The centres of k and of the other gear [m].
    flow : float or ndarray, shape (n,)
        The sign of the power into k relative to the carrier: sign(W_t (ω_k − ω_carrier)), W_t the tooth force's
        moment on k.
    """
    P, t, r = pitch(mesh, k, Ck, Cj)
    eta = mesh.efficiency
    rk = mesh.radius(k)
    if eta == 1:
        return P, t, r, rk
    rj = mesh.radius(mesh.links[0] if mesh.links[1] == k else mesh.links[1])
    f = np.where(np.asarray(flow) > 0, eta, np.where(np.asarray(flow) < 0, 1 / eta, 1.0))
    a = mesh.centre_distance
    if not mesh.internal:
        rho = a * f * rk / (rj + f * rk)
    elif k == mesh.ring:
        rho = a * f * rk / (f * rk - rj)
    else:
        rho = a * f * rk / (rj - f * rk)
    if np.ndim(rho) == 0:
        rho = float(rho)
    return Ck + (P - Ck) * (rho / rk), t, r, rho


def power_flow(kin: Kinematics, g: GearGroup, W_t):
    """The sign of the power into gear g.k through its mesh, relative to the carrier g.b: +1, −1, or 0 (no loss to
    apply: an efficiency of 1, no moment, or no relative turning). ``W_t``: the tooth force's moment on k."""
    if g.mesh.efficiency == 1:
        return 0.0
    return np.sign(W_t) * np.sign(kin.omega[g.k] - kin.omega[g.b])
