"""The graphical route as data: velocity and acceleration polygons, instant centres, resultants, force polygons.

Uses shapely for the geometry and never matplotlib; :mod:`graphkin.draw`
draws what this builds.
"""

from graphkin.graphical.build import construct_forces
from graphkin.graphical.centres import InstantCentres, instant_centres
from graphkin.graphical.construction import Arrow, Construction, Line, Step, SubProblem, nice_scale
from graphkin.graphical.motion import MotionConstruction, MotionStep, PolygonLine, Vector
from graphkin.graphical.polygons import construct_kinematics
from graphkin.graphical.readings import kinematics_from_polygons

__all__ = ["Arrow", "Construction", "InstantCentres", "Line", "MotionConstruction", "MotionStep", "PolygonLine",
           "Step", "SubProblem", "Vector", "construct_forces", "construct_kinematics", "instant_centres",
           "kinematics_from_polygons", "nice_scale"]
