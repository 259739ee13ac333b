"""Position, velocity and acceleration of every link, vectorised over input positions."""

from .dyads import solve_kinematics
from .state import Kinematics, position_text
from .structure import Dyad, DriverGroup, GearGroup, decompose

__all__ = ["Dyad", "DriverGroup", "GearGroup", "Kinematics", "decompose", "position_text", "solve_kinematics"]
