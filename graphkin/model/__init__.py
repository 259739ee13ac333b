"""The mechanism as data: links, joints, the driver and loads (frozen dataclasses)."""

from .driver import Driver
from .joints import GearMesh, Joint, Prismatic, Revolute
from .link import FRAME, Link
from .loads import SENSES, Active, Load, PointForce, Table, Torque
from .mechanism import Mechanism

__all__ = [
    "FRAME", "Active", "Driver", "GearMesh", "Joint", "Link", "Load", "Mechanism",
    "PointForce", "Prismatic", "Revolute", "SENSES", "Table", "Torque",
]
