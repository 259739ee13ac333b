"""Position, velocity and acceleration of every link, vectorised over input positions."""

from graphkin.kinematics.solver import solve_kinematics
from graphkin.kinematics.state import Kinematics
from graphkin.kinematics.structure import DriverGroup, Dyad, GearGroup, decompose

__all__ = ["Dyad", "DriverGroup", "GearGroup", "Kinematics", "decompose", "solve_kinematics"]
