"""graphkin: kinetostatics of planar machinery, analytically and graphically, for teaching.

The public names, each loaded when first used (PEP 562), so ``import graphkin``
loads nothing but this file; matplotlib, ipywidgets and pint are loaded by the
parts that draw, show widgets and read units::

    import graphkin as gk

    p = gk.load("strip_cutter")                 # a catalog problem (or a TOML file)
    r = p.solve()                               # the matrix method: every joint force, the driving torque
    c = gk.construct_forces(r.kinematics, 0)    # the graphical route at the first position
    gk.draw.draw_solution(c, r)                 # both routes side by side (loads matplotlib)
    cycle = gk.sweep(p, 360)                    # a whole turn: torque curve, flywheel, joint-force index

=====================  ==================================================================
problems               :func:`load`, :func:`load_problem`, :func:`parse_problem`,
                       :func:`build_problem`, :class:`Problem`, :mod:`catalog`
the mechanism          :class:`Mechanism`, :class:`Link`, :class:`Revolute`,
                       :class:`Prismatic`, :class:`GearMesh`, :class:`Driver`,
                       :class:`PointForce`, :class:`Torque`, :class:`Table`, :mod:`mass`
kinematics             :func:`solve_kinematics`, :class:`Kinematics`, :func:`decompose`
the analytical route   :func:`solve_forces`, :class:`ForceAnalysis`, :func:`assemble`,
                       :func:`solve_matrix`, :func:`inertia`,
                       :func:`effort_by_virtual_work`, :func:`load_powers`
the graphical route    :func:`construct_forces`, :class:`Construction`,
                       :func:`construct_kinematics`, :class:`MotionConstruction`
                       (velocity and acceleration polygons), :func:`instant_centres`,
                       :class:`InstantCentres`, :func:`kinematics_from_polygons`
whole cycles           :func:`sweep`, :class:`Cycle`, :func:`size_flywheel`, :func:`study`, :class:`Study`,
                       :func:`joint_force_index`, :func:`static_problem`, :func:`load_flywheel`
reports (plain data)   :mod:`report`, :func:`solution`, :func:`format_solution`,
                       :func:`cycle_data`, :func:`format_cycle`, :func:`study_data`, :func:`format_study`
printed notation       :func:`polar`, :func:`polar_text`, :func:`cross`
drawings               :mod:`draw` (matplotlib)
teaching               :mod:`exercises`, :mod:`handout`, :func:`explore`, :func:`exercise`
in the browser         :mod:`scene` (``gk.scene.scene(problem)``: a cycle as data a web page draws)
errors                 :class:`GraphkinError`, :class:`ModelError`,
                       :class:`ProblemFileError`, :class:`GraphkinWarning`
=====================  ==================================================================
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

__version__ = "0.1.0"

_LAZY = {
    # problems
    "load": ("graphkin.catalog", "load"),
    "load_problem": ("graphkin.problem", "load_problem"),
    "parse_problem": ("graphkin.problem", "parse_problem"),
    "build_problem": ("graphkin.problem", "build_problem"),
    "Problem": ("graphkin.problem", "Problem"),
    "catalog": ("graphkin.catalog", None),
    # the mechanism
    "Mechanism": ("graphkin.model", "Mechanism"),
    "Link": ("graphkin.model", "Link"),
    "Revolute": ("graphkin.model", "Revolute"),
    "Prismatic": ("graphkin.model", "Prismatic"),
    "GearMesh": ("graphkin.model", "GearMesh"),
    "Driver": ("graphkin.model", "Driver"),
    "PointForce": ("graphkin.model", "PointForce"),
    "Torque": ("graphkin.model", "Torque"),
    "Table": ("graphkin.model", "Table"),
    "mass": ("graphkin.model.mass", None),
    # kinematics
    "solve_kinematics": ("graphkin.kinematics", "solve_kinematics"),
    "Kinematics": ("graphkin.kinematics", "Kinematics"),
    "decompose": ("graphkin.kinematics", "decompose"),
    # the analytical route
    "solve_forces": ("graphkin.analytical", "solve_forces"),
    "ForceAnalysis": ("graphkin.analytical", "ForceAnalysis"),
    "inertia": ("graphkin.analytical", "inertia"),
    "assemble": ("graphkin.analytical.matrix", "assemble"),
    "solve_matrix": ("graphkin.analytical.matrix", "solve_matrix"),
    "effort_by_virtual_work": ("graphkin.analytical.virtual_work", "effort_by_virtual_work"),
    "load_powers": ("graphkin.analytical.virtual_work", "load_powers"),
    # the graphical route
    "construct_forces": ("graphkin.graphical", "construct_forces"),
    "Construction": ("graphkin.graphical", "Construction"),
    "construct_kinematics": ("graphkin.graphical", "construct_kinematics"),
    "MotionConstruction": ("graphkin.graphical", "MotionConstruction"),
    "instant_centres": ("graphkin.graphical", "instant_centres"),
    "InstantCentres": ("graphkin.graphical", "InstantCentres"),
    "kinematics_from_polygons": ("graphkin.graphical", "kinematics_from_polygons"),
    # whole cycles
    "sweep": ("graphkin.cycle", "sweep"),
    "study": ("graphkin.cycle", "study"),
    "Study": ("graphkin.cycle", "Study"),
    "Cycle": ("graphkin.cycle", "Cycle"),
    "size_flywheel": ("graphkin.cycle", "size_flywheel"),
    "joint_force_index": ("graphkin.cycle", "joint_force_index"),
    "static_problem": ("graphkin.cycle", "static_problem"),
    "load_flywheel": ("graphkin.cycle.flywheel_file", "load_flywheel"),
    # reports
    "report": ("graphkin.report", None),
    "solution": ("graphkin.report", "solution"),
    "format_solution": ("graphkin.report", "format_solution"),
    "cycle_data": ("graphkin.report", "cycle_data"),
    "format_cycle": ("graphkin.report", "format_cycle"),
    "study_data": ("graphkin.report", "study_data"),
    "format_study": ("graphkin.report", "format_study"),
    # printed notation
    "polar": ("graphkin.notation", "polar"),
    "polar_text": ("graphkin.notation", "polar_text"),
    "cross": ("graphkin.geometry", "cross"),
    # drawings, teaching
    "draw": ("graphkin.draw", None),
    "exercises": ("graphkin.exercises", None),
    "handout": ("graphkin.handout", None),
    "explore": ("graphkin.widgets", "explore"),
    "scene": ("graphkin.scene", None),
    "exercise": ("graphkin.widgets", "exercise"),
    "draw_answer": ("graphkin.widgets", "draw_answer"),
    # errors
    "GraphkinError": ("graphkin.errors", "GraphkinError"),
    "ModelError": ("graphkin.errors", "ModelError"),
    "ProblemFileError": ("graphkin.errors", "ProblemFileError"),
    "GraphkinWarning": ("graphkin.errors", "GraphkinWarning"),
}
"""Each public name: the module it lives in, and its name there (None: the module itself)."""

__all__ = ["__version__", *sorted(_LAZY)]


def __getattr__(name: str):
    """Load a public name when it is first used (PEP 562)."""
    try:
        module, attr = _LAZY[name]
    except KeyError:
        raise AttributeError(f"module 'graphkin' has no attribute {name!r}") from None
    value = importlib.import_module(module)
    if attr is not None:
        value = getattr(value, attr)
    globals()[name] = value  # the next use finds it at once
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *_LAZY})


if TYPE_CHECKING:  # pragma: no cover - for type checkers and editors; at run time each name loads lazily
    from graphkin import catalog, draw, exercises, handout, report, scene
    from graphkin.analytical import ForceAnalysis, inertia, solve_forces
    from graphkin.analytical.matrix import assemble, solve_matrix
    from graphkin.analytical.virtual_work import effort_by_virtual_work, load_powers
    from graphkin.catalog import load
    from graphkin.cycle import Cycle, Study, joint_force_index, size_flywheel, static_problem, study, sweep
    from graphkin.cycle.flywheel_file import load_flywheel
    from graphkin.errors import GraphkinError, GraphkinWarning, ModelError, ProblemFileError
    from graphkin.geometry import cross
    from graphkin.graphical import (
        Construction,
        InstantCentres,
        MotionConstruction,
        construct_forces,
        construct_kinematics,
        instant_centres,
        kinematics_from_polygons,
    )
    from graphkin.kinematics import Kinematics, decompose, solve_kinematics
    from graphkin.model import Driver, GearMesh, Link, Mechanism, PointForce, Prismatic, Revolute, Table, Torque, mass
    from graphkin.notation import polar, polar_text
    from graphkin.problem import Problem, build_problem, load_problem, parse_problem
    from graphkin.report import cycle_data, format_cycle, format_solution, format_study, solution, study_data
    from graphkin.widgets import draw_answer, exercise, explore
