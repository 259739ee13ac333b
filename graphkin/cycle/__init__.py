"""Full-cycle results: the driving torque curve, joint-force peaks and polar data, shaking
force and moment, transmission angle, flywheel sizing, the joint-force index, and design studies over a grid of designs.

Compute only (numpy): the drawing layer plots these results.
"""

from graphkin.cycle.flywheel import Disk, Flywheel, Pulse, Rim, size_flywheel
from graphkin.cycle.index import JointForceIndex, joint_force_index, static_problem
from graphkin.cycle.study import Design, Study, study
from graphkin.cycle.sweep import Cycle, Peak, Peaks, sweep

__all__ = [
    "Cycle", "Design", "Disk", "Flywheel", "JointForceIndex", "Peak", "Peaks", "Pulse", "Rim", "Study",
    "joint_force_index", "size_flywheel", "static_problem", "study", "sweep",
]
