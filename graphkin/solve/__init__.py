"""Analytical kinetostatics: joint forces and the driving effort."""

from .kinetostatics import solve, solve_forces
from .loads import Inertia, applied, applied_at, external_loads, inertia, known_loads
from .result import ForceAnalysis

__all__ = ["ForceAnalysis", "Inertia", "applied", "applied_at", "external_loads", "inertia", "known_loads", "solve", "solve_forces"]
