"""What a lesson's explorer (``gk.explore``, drawn by the browser) shows at a position, read from its scene as the
browser reads it (docs/json.md, "scene"), with the scene's own rounding as the tolerance.

The scene rounds each value to ``precision`` (10⁻⁹) of its kind's scale: forces of the largest force of the cycle,
torques of that force times the mechanism's size. Two units of it either way are the tolerances below.
"""

from __future__ import annotations

import json

import numpy as np


def scene_of(ex) -> dict:
    """The scene as the browser has it: the widget's JSON, read back."""
    return json.loads(ex.widget.scene)


def force_tol(s: dict) -> float:
    """Two units of rounding of a force [N]."""
    return 2 * s["precision"] * max(float(np.nanmax(np.abs(np.array(f["analytical"], float)))) for f in s["forces"])


def torque_tol(s: dict) -> float:
    """Two units of rounding of a torque [N·m] (or of a slider's force [N], rounded as a force)."""
    return force_tol(s) * (s["size"] if s["input"]["name"] == "theta" else 1.0)


def force(s: dict, name: str, i: int, route: str = "analytical") -> np.ndarray:
    """The joint force ``name`` (F23: of 2 on 3, as the scene holds it) at position ``i`` [N]."""
    (f,) = [f for f in s["forces"] if f["name"] == name]
    return np.array(f[route][2 * i:2 * i + 2], float)


def effort(s: dict, i: int, route: str = "analytical") -> float:
    """The driving torque (or force) at position ``i``."""
    return float(s["effort"][route][i])


def superposed_effort(s: dict, omega: float) -> np.ndarray:
    """The driving torque at input speed ω [rad/s] as the browser's speed box computes it: rest + ω² · omega2."""
    parts = s["speed"]["superpose"]["effort"]
    return np.array(parts["rest"], float) + omega**2 * np.array(parts["omega2"], float)
