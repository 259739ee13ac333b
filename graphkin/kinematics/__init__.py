"""Position, velocity and acceleration of every link, vectorised over input positions."""

from .dyads import solve_kinematics
from .state import Kinematics
from .structure import Dyad, DriverGroup, GearGroup, decompose

__all__ = ["Dyad", "DriverGroup", "GearGroup", "Kinematics", "decompose", "solve_kinematics"]
