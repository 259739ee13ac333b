"""Full-cycle results: the driving torque curve, joint-force peaks and polar data, shaking
force and moment, transmission angle, flywheel sizing, the joint-force index, and design studies over a grid of designs.

Compute only (numpy): the drawing layer plots these results.

A design study (:mod:`graphkin.cycle.studies`, with its figures of merit, limits and optimum) is loaded when first
named (PEP 562): ``graphkin solve`` reads a cycle's peaks and never a study, and issue 35 asks it not pay for their
import. The sweep is imported at once: its module and its function share the name ``sweep``, and the function
must be what ``graphkin.cycle.sweep`` names once the module has been imported.
"""

import importlib

from graphkin.cycle.flywheel import Disk, Flywheel, Pulse, Rim, size_flywheel
from graphkin.cycle.index import JointForceIndex, joint_force_index, static_problem
from graphkin.cycle.sweep import Cycle, Peak, Peaks, sweep

_LATER = {"Design": "studies", "Study": "studies", "study": "studies"}

__all__ = [
    "Cycle", "Design", "Disk", "Flywheel", "JointForceIndex", "Peak", "Peaks", "Pulse", "Rim", "Study",
    "joint_force_index", "size_flywheel", "static_problem", "study", "sweep",
]


def __getattr__(name: str):
    module = _LATER.get(name)
    if module is None:
        raise AttributeError(f"module 'graphkin.cycle' has no attribute {name!r}")
    value = getattr(importlib.import_module(f"graphkin.cycle.{module}"), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(_LATER))
