"""Plane-vector helpers, in two forms.

Results and the public API use arrays whose last axis is (x, y). The solvers
work with complex numbers x + iy, as the textbooks' loop equations do
(r e^{iθ}): a rotation is one multiplication and k × r is i r. Angles in
radians, counter-clockwise positive (see the sign convention in the README).
"""

from __future__ import annotations

import numpy as np


def cross(a, b):
    """z-component of the cross product a × b of (..., 2) arrays.

    Parameters
    ----------
    a, b : array_like, shape (..., 2)
        Plane vectors (x, y).

    Returns
    -------
    ndarray, shape (...)
        a_x b_y − a_y b_x.

    Examples
    --------
    >>> float(cross([1.0, 0.0], [0.0, 2.0]))
    2.0
    """
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def dot(a, b):
    """Scalar product of (..., 2) arrays over the last axis."""
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1]


def perp(v):
    """v rotated by +90° (k × v), the direction of ω × r.

    Examples
    --------
    >>> perp([1.0, 0.0]).tolist()
    [-0.0, 1.0]
    """
    v = np.asarray(v, dtype=float)
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


def zcross(a, b):
    """z-component of a × b for complex plane vectors (Im(ā b)).

    Examples
    --------
    >>> float(zcross(1 + 0j, 2j))
    2.0
    """
    return a.real * b.imag - a.imag * b.real


def zdot(a, b):
    """Scalar product of complex plane vectors (Re(ā b))."""
    return a.real * b.real + a.imag * b.imag


def as_xy(z) -> np.ndarray:
    """Complex array, shape (n,), as a float array of shape (n, 2)."""
    z = np.asarray(z, dtype=complex)
    return np.stack([z.real, z.imag], axis=-1)


def as_z(v) -> np.ndarray:
    """Float array of shape (..., 2) as complex x + iy."""
    v = np.asarray(v, dtype=float)
    return v[..., 0] + 1j * v[..., 1]
