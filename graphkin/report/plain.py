"""Plain data for JSON: numbers that are not finite become None (``null``), peaks become small dicts."""

from __future__ import annotations

import math

import numpy as np


def floats(a) -> list:
    """An array as a JSON list, nan and ±inf as None."""
    a = np.asarray(a, dtype=float).ravel()
    # tolist() gives the same Python floats as float(x) one by one, ~20x faster for a cycle's 3600 values.
    out = a.tolist()
    bad = ~np.isfinite(a)
    if bad.any():
        for i in np.flatnonzero(bad).tolist():
            out[i] = None
    return out


def number(x) -> float | None:
    """A number for JSON, None where it is not finite."""
    x = float(x)
    return x if math.isfinite(x) else None


def peak(p) -> dict:
    """A peak (:class:`graphkin.cycle.Peak`) as ``{"value", "at", "index"}``."""
    return {"value": number(p.value), "at": number(p.at), "index": int(p.index)}
