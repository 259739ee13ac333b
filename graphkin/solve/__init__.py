"""Analytical kinetostatics: joint forces and the driving effort."""

from graphkin.solve.kinetostatics import solve, solve_forces
from graphkin.solve.loads import Inertia, applied, applied_at, external_loads, inertia, known_loads
from graphkin.solve.result import ForceAnalysis

__all__ = ["ForceAnalysis", "Inertia", "applied", "applied_at", "external_loads", "inertia", "known_loads", "solve", "solve_forces"]
