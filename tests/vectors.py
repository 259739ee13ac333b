"""Plane-vector helpers for the tests, written out so that the tests do not lean on
graphkin's own geometry module. Vectors are arrays of shape (..., 2)."""

import numpy as np


def cross(a, b):
    """z-component of a × b."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def dot(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1]


def perp(v):
    """k × v (v turned +90°)."""
    v = np.asarray(v, float)
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)
