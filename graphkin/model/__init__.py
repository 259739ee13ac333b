"""The mechanism as data: links, joints, the driver and loads (frozen dataclasses)."""

from graphkin.model.driver import Driver
from graphkin.model.joints import GearMesh, Joint, Prismatic, Revolute
from graphkin.model.link import FRAME, Link
from graphkin.model.loads import SENSES, Active, Load, PointForce, SpringForce, StrokeForce, Table, Torque, spring
from graphkin.model.mechanism import Mechanism

__all__ = [
    "FRAME", "Active", "Driver", "GearMesh", "Joint", "Link", "Load", "Mechanism",
    "PointForce", "Prismatic", "Revolute", "SENSES", "SpringForce", "StrokeForce", "Table", "Torque", "spring",
]
