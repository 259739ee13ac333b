"""The graphical route as data: velocity and acceleration polygons, instant centres, resultants, force polygons.

Uses shapely for the geometry and never matplotlib; :mod:`graphkin.draw`
draws what this builds.

The velocity and acceleration polygons and the instant centres are loaded when first named (PEP 562): ``graphkin
solve`` without ``--motion-polygons`` never uses them, and issue 26 asks it be no slower for them.
"""

import importlib

from graphkin.graphical.build import construct_forces
from graphkin.graphical.construction import Arrow, Construction, Line, Step, SubProblem, nice_scale

_LATER = {"InstantCentres": "centres", "instant_centres": "centres", "MotionConstruction": "motion",
          "MotionStep": "motion", "PolygonLine": "motion", "Vector": "motion", "construct_kinematics": "polygons",
          "kinematics_from_polygons": "readings"}

__all__ = ["Arrow", "Construction", "InstantCentres", "Line", "MotionConstruction", "MotionStep", "PolygonLine",
           "Step", "SubProblem", "Vector", "construct_forces", "construct_kinematics", "instant_centres",
           "kinematics_from_polygons", "nice_scale"]


def __getattr__(name: str):
    module = _LATER.get(name)
    if module is None:
        raise AttributeError(f"module 'graphkin.graphical' has no attribute {name!r}")
    value = getattr(importlib.import_module(f"graphkin.graphical.{module}"), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(_LATER))
