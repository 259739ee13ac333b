"""Pure numpy helpers for plane vectors.

Vectors are arrays whose last axis has length 2 (x, y); leading axes broadcast,
so the same call serves one position or a whole cycle. Angles in radians,
counter-clockwise positive (see the sign convention in the README).
"""

from __future__ import annotations

import numpy as np


def cross(a, b):
    """z-component of the cross product a × b.

    Parameters
    ----------
    a, b : array_like, shape (..., 2)

    Returns
    -------
    ndarray, shape (...)

    Examples
    --------
    >>> float(cross([1.0, 0.0], [0.0, 2.0]))
    2.0
    """
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def perp(v):
    """v rotated by +90° (k × v), the direction of ω × r.

    Examples
    --------
    >>> perp([1.0, 0.0]).tolist()
    [-0.0, 1.0]
    """
    v = np.asarray(v, dtype=float)
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


def dot(a, b):
    """Scalar product over the last axis."""
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1]


def norm(v):
    """Length of v over the last axis."""
    v = np.asarray(v, dtype=float)
    return np.hypot(v[..., 0], v[..., 1])


def unit(angle):
    """Unit vector at ``angle`` [rad] from +x, shape ``angle.shape + (2,)``."""
    angle = np.asarray(angle, dtype=float)
    return np.stack([np.cos(angle), np.sin(angle)], axis=-1)


def angle_of(v):
    """Direction of v [rad] in (−π, π]."""
    v = np.asarray(v, dtype=float)
    return np.arctan2(v[..., 1], v[..., 0])


def rotate(v, angle):
    """Rotate vectors v by ``angle`` [rad] (broadcast over leading axes)."""
    v = np.asarray(v, dtype=float)
    c = np.cos(angle)
    s = np.sin(angle)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)


def solve2(a11, a12, a21, a22, b1, b2):
    """Solve the 2×2 systems [[a11, a12], [a21, a22]] x = b elementwise (Cramer).

    A zero determinant (dead point, parallel lines) gives ``inf``/``nan`` in
    the result rather than an exception, so a whole cycle is solved at once
    and bad positions are masked afterwards.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        det = a11 * a22 - a12 * a21
        return (b1 * a22 - a12 * b2) / det, (a11 * b2 - b1 * a21) / det


def intersect_lines(p, u, q, w):
    """Intersection of the line through p along u with the line through q along w.

    Returns ``nan`` where the lines are parallel.

    Examples
    --------
    >>> intersect_lines([0, 0], [1, 0], [2, -1], [0, 1]).tolist()
    [2.0, 0.0]
    """
    p, u, q, w = (np.asarray(x, dtype=float) for x in (p, u, q, w))
    with np.errstate(divide="ignore", invalid="ignore"):
        den = cross(u, w)
        t = np.where(den == 0.0, np.nan, cross(q - p, w) / den)
    return p + t[..., None] * u
