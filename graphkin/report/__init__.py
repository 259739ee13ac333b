"""Everything a command prints or writes as ``--json``: plain data in SI units, and the text made from it.

Each report is a pair: ``X_data(...)`` (or :func:`solution`) returns plain
data (dicts, lists, str, float; a number that is not finite is None), which
handouts, exercise platforms and widgets read too, and ``format_X(...)``
writes it as textbook text. :func:`graphkin.files.json_text` writes the
data as JSON (schema: ``docs/json.md``).

==============================  ==================================  ======================
command                         data                                text
==============================  ==================================  ======================
``graphkin solve``              :func:`solution`                    :func:`format_solution`
``graphkin cycle``              :func:`cycle_data`                  :func:`format_cycle`
``graphkin flywheel``           :func:`flywheel_data`               :func:`format_flywheel`
``graphkin study``              :func:`study_data`                  :func:`format_study`
==============================  ==================================  ======================

With ``--units``, :mod:`graphkin.report.in_units` converts the data into the chosen units and states each
field's unit, and each ``format_X`` takes the same :class:`graphkin.units.systems.UnitSystem`.

The reports of a cycle, a flywheel and a study are loaded when first named (PEP 562): ``graphkin solve`` needs
none of them, nor the cycle's engine they read (issue 35, "Keep"). The solution's are imported at once: its module
and its function share the name ``solution``, and the function must be what ``graphkin.report.solution`` names
once the module has been imported.
"""

import importlib

from graphkin.report.polygons import graphical_kinematics_data, kinematic_constructions
from graphkin.report.solution import constructions, cross_check, format_solution, solution

_LATER = {"DISK_THICKNESS": "cycle", "STEEL": "cycle", "cycle_data": "cycle", "cycle_links": "cycle",
          "format_cycle": "cycle", "flywheel_data": "flywheel", "format_flywheel": "flywheel", "format_study": "study",
          "study_data": "study"}

__all__ = ["DISK_THICKNESS", "STEEL", "constructions", "cross_check", "cycle_data", "cycle_links", "flywheel_data",
           "format_cycle", "format_flywheel", "format_solution", "format_study", "graphical_kinematics_data",
           "kinematic_constructions", "solution", "study_data"]


def __getattr__(name: str):
    module = _LATER.get(name)
    if module is None:
        raise AttributeError(f"module 'graphkin.report' has no attribute {name!r}")
    value = getattr(importlib.import_module(f"graphkin.report.{module}"), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(_LATER))
