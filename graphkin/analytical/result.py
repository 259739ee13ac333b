"""The result of a force analysis: every joint force, both orders answered."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping

import numpy as np

from graphkin.analytical.loads import Inertia, inertia
from graphkin.errors import GraphkinError
from graphkin.kinematics import Kinematics
from graphkin.model import GearMesh, Prismatic
from graphkin.model.names import force_name, parse_force_name


@dataclass(frozen=True)
class ForceAnalysis:
    """Joint forces and the driving effort over n positions.

    Joint forces follow the README's sign convention: ``force(i, j)`` is the
    force of link i on link j [N], shape (n, 2), and ``force(j, i)`` is its
    negative. By name: ``result["F23"]`` (revolute or gear mesh),
    ``result["G14"]`` (a prismatic pair's guide reaction, normal force plus
    friction), and the driver's ``"T12"`` [N·m] or ``"F12"`` [N, along the
    guide, shape (n, 2)]. Names with links above 9 use ``"F10,11"``.

    Attributes
    ----------
    kinematics : Kinematics
        The motion the forces were found from. From :func:`graphkin.analytical.solve`, its per-link arrays
        are worked out again, to the same digits, the first time one is read, rather than kept.
    forces : dict of (int, int) to ndarray, shape (n, 2)
        Force of the lower-numbered link on the higher, per joint.
    normal, couple : dict of (int, int) to ndarray, shape (n,)
        For prismatic pairs: the normal component N [N] of that force along
        k × u (u the guide direction) and the couple C [N·m] it transmits.
    effort : ndarray, shape (n,)
        Driving torque T1j [N·m, CCW] of a crank, or driving force F1j [N,
        along the guide direction] of a slider.
    valid : ndarray of bool, shape (n,)
    failures : dict of str to ndarray of bool
        Reasons for invalid positions, beyond the kinematic ones.
    """

    kinematics: Kinematics
    forces: Mapping[tuple[int, int], np.ndarray]
    normal: Mapping[tuple[int, int], np.ndarray]
    couple: Mapping[tuple[int, int], np.ndarray]
    effort: np.ndarray
    valid: np.ndarray
    failures: Mapping[str, np.ndarray] = field(default_factory=dict)

    @property
    def mechanism(self):
        return self.kinematics.mechanism

    @property
    def n(self) -> int:
        return len(self.effort)

    @property
    def driver_name(self) -> str:
        """``"T12"`` for a crank, ``"F12"`` for a slider driver."""
        return self.mechanism.driver.symbol

    def force(self, i: int, j: int) -> np.ndarray:
        """Force of link i on link j [N], shape (n, 2)."""
        key = (min(i, j), max(i, j))
        if key not in self.forces:
            known = ", ".join(f"{a}–{b}" for a, b in self.forces)
            raise GraphkinError(f"links {i} and {j} share no joint (joints: {known})")
        F = self.forces[key]
        return F if i < j else -F

    def driver_force(self) -> np.ndarray:
        """The driving effort as a vector: F1j along the guide (slider) [N], shape (n, 2)."""
        if self.mechanism.driver.crank:
            raise GraphkinError(f"the driver is a crank: its effort is the torque {self.driver_name}")
        joint = self.mechanism.joint_between(self.mechanism.frame, self.mechanism.driver.link)
        return self.effort[:, None] * self.kinematics.guide_direction(joint)

    def offset(self, i: int, j: int) -> np.ndarray:
        """Where a prismatic reaction's line acts: distance e [m] along the guide from the slider point."""
        key = (min(i, j), max(i, j))
        with np.errstate(divide="ignore", invalid="ignore"):
            return self.couple[key] / self.normal[key]

    def names(self) -> list[str]:
        """Every joint force's name in stored order (``F12``, ``F23``, ``G14``, ...) and the driver's."""
        out = [self.name_of(i, j) for i, j in self.forces]
        return out + [self.driver_name]

    def name_of(self, i: int, j: int) -> str:
        """The name of the force of link ``i`` on link ``j`` (:func:`graphkin.model.names.force_name`)."""
        return force_name(self.mechanism, i, j)

    def __getitem__(self, name: str) -> np.ndarray:
        if name == self.driver_name:
            return self.effort if name[0] == "T" else self.driver_force()
        return self.force(*parse_force_name(self.mechanism, name))

    def inertia(self, link: int) -> Inertia:
        """The link's inertia force, torque and h (see :func:`graphkin.analytical.loads.inertia`)."""
        return inertia(self.kinematics, link)

    def reason(self, i: int) -> str:
        """Why position ``i`` has no solution ('' if it has one)."""
        parts = [self.kinematics.reason(i)] + [why for why, where in self.failures.items() if where[i]]
        return "; ".join(p for p in parts if p)

    def joint_kind(self, i: int, j: int) -> str:
        joint = self.mechanism.joint_between(i, j)
        return "prismatic" if isinstance(joint, Prismatic) else "gear" if isinstance(joint, GearMesh) else "revolute"
