"""Analytical kinetostatics: joint forces and the driving effort."""

from graphkin.analytical.kinetostatics import solve, solve_forces
from graphkin.analytical.loads import Inertia, applied, applied_at, external_loads, inertia, known_loads
from graphkin.analytical.result import ForceAnalysis

__all__ = ["ForceAnalysis", "Inertia", "applied", "applied_at", "external_loads", "inertia", "known_loads", "solve",
           "solve_forces"]
