"""An epicyclic train drawn (issue 25): the annulus on the frame with its teeth pointing in, the planet meshing
inside it clear of its teeth, turning with the arm."""

from __future__ import annotations

import numpy as np
import pytest

from graphkin import draw
from graphkin.analytical import solve
from graphkin.draw.geometry import PINION_TEETH
from graphkin.graphical import construct_forces
from tests.kinematics.test_epicyclic import train

MM = 1e3


def _annulus(d):
    from matplotlib.patches import PathPatch

    return [p for p in d.ax.patches if isinstance(p, PathPatch)]


@pytest.mark.parametrize("theta", [0.0, 0.7, 2.9])
def test_the_annulus_is_drawn_around_the_planet_and_they_mesh(theta):
    shapely = pytest.importorskip("shapely")
    from matplotlib.patches import Polygon

    mech = train(ring=True, sun=False)
    c = construct_forces(solve(mech, [theta], 10.0).kinematics, 0)
    d = draw.draw_mechanism(c, labels=False)
    (ring,) = _annulus(d)
    verts = ring.get_path().vertices
    radii = np.hypot(*verts.T)
    module = 2 * 60 / PINION_TEETH  # the planet, the train's smallest gear, has PINION_TEETH teeth
    assert radii.max() == pytest.approx(150 + 3.5 * module, rel=1e-9)  # the rim, 3.5 modules out
    assert radii.min() < 150 < np.percentile(radii, 90)  # the teeth reach in past the pitch circle
    planet = max((p.get_xy()[:-1] for p in d.ax.patches if isinstance(p, Polygon) and len(p.get_xy()) > 40),
                 key=lambda v: np.ptp(v[:, 0]))
    inner = shapely.Polygon(verts[97:-1])  # the annulus's toothed inside: the planet's teeth stay in its gaps
    assert shapely.Polygon(planet).difference(inner).area < 1e-6 * shapely.Polygon(planet).area
    C = np.asarray(c.points[3]["C"]) * MM
    assert np.hypot(*(planet.mean(axis=0) - C)) < 1.0  # drawn about its centre on the arm


def test_the_solution_figure_of_a_train_is_drawn():
    mech = train(ring=True, sun=True)
    c = construct_forces(solve(mech, [0.5], 10.0).kinematics, 0)
    r = solve(mech, [0.5], 10.0)
    fig = draw.draw_solution(c, r)
    # The annulus (on the frame) is drawn once, in the mechanism's panel, with the sun and the planet inside it.
    rings = [p for ax in fig.axes for p in ax.patches if type(p).__name__ == "PathPatch"]
    assert len(rings) == 1
    assert np.hypot(*rings[0].get_path().vertices.T).max() < 200
