"""The graphical route as data: resultants, two- and three-force members, force polygons.

Uses shapely for the geometry and never matplotlib; :mod:`graphkin.draw`
draws what this builds.
"""

from graphkin.graphical.build import construct_forces
from graphkin.graphical.construction import Arrow, Construction, Line, Step, SubProblem, nice_scale

__all__ = ["Arrow", "Construction", "Line", "Step", "SubProblem", "construct_forces", "nice_scale"]
