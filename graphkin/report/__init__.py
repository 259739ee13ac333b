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
"""

from graphkin.report.cycle import DISK_THICKNESS, STEEL, cycle_data, cycle_links, format_cycle
from graphkin.report.flywheel import flywheel_data, format_flywheel
from graphkin.report.polygons import graphical_kinematics_data, kinematic_constructions
from graphkin.report.solution import constructions, cross_check, format_solution, solution
from graphkin.report.study import format_study, study_data

__all__ = ["DISK_THICKNESS", "STEEL", "constructions", "cross_check", "cycle_data", "cycle_links", "flywheel_data",
           "format_cycle", "format_flywheel", "format_solution", "format_study", "graphical_kinematics_data",
           "kinematic_constructions", "solution", "study_data"]
