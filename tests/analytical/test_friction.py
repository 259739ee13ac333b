"""Coulomb friction at a sliding pair where the slider stands still, and the Problem helpers that vary it.

The offset slider-crank of the catalog (crank 60 mm, rod 200 mm, guide 20 mm above O2, μ = 0.2)
has its dead centres where crank and rod are in line: θ = asin(e/(l + r)) and π + asin(e/(l − r)).
There the slider's velocity is zero, and rounding leaves ~1e-17 m/s of either sign; friction must
not switch on at full strength in a random sense because of it.
"""

import math

import numpy as np
import pytest

from graphkin import catalog
from graphkin.errors import GraphkinError
from graphkin.graphical import construct_forces
from graphkin.model import Prismatic

PROBLEM = catalog.load("slider_crank_friction")
_mech = PROBLEM.mechanism
r = _mech.link(2).points["A"][0]  # crank O2A, along link 2's x-axis [m]
l = _mech.link(3).points["B"][0]  # rod AB [m]
e = _mech.link(1).points["E"][1]  # the guide's line passes through E, this far above O2 [m]
DEAD_CENTRES = np.array([math.asin(e / (l + r)), math.pi + math.asin(e / (l - r))])


@pytest.fixture(scope="module")
def problem():
    return PROBLEM


def test_the_slider_is_still_at_the_dead_centres(problem):
    kin = problem.kinematics(at=DEAD_CENTRES)
    guide = next(j for j in problem.mechanism.joints if isinstance(j, Prismatic))
    rate = kin.slide_rate(guide, guide.slider)
    assert np.all(np.abs(rate) < 1e-12)
    np.testing.assert_array_equal(kin.slide_sense(guide, guide.slider), [0.0, 0.0])
    # A hundredth of a degree away the slider moves, and friction has a sense again.
    near = problem.kinematics(at=DEAD_CENTRES + np.radians(0.01))
    assert np.all(np.abs(near.slide_sense(guide, guide.slider)) == 1.0)


def test_no_friction_at_a_dead_centre_both_routes(problem):
    """At a dead centre the solution with μ = 0.2 is the frictionless one, analytically and graphically."""
    with_mu = problem.solve(at=DEAD_CENTRES)
    without = problem.with_friction(0.0).solve(at=DEAD_CENTRES)
    np.testing.assert_allclose(with_mu.effort, without.effort, rtol=1e-12, atol=1e-12)
    for key, F in without.forces.items():
        np.testing.assert_allclose(with_mu.forces[key], F, rtol=1e-12, atol=1e-9)
    for i in range(2):
        c = construct_forces(with_mu.kinematics, i)
        assert c.valid and c.effort == pytest.approx(with_mu.effort[i], rel=1e-9)


def test_with_friction_and_at_speed(problem):
    assert problem.with_friction(0.35).mechanism.joints[-1].mu == 0.35
    assert problem.mechanism.joints[-1].mu == 0.2  # the original is left as it was
    fast = problem.at_speed(2 * float(problem.q_dot[0]))
    assert np.all(fast.q_dot == 2 * problem.q_dot[0]) and np.all(fast.q_ddot == problem.q_ddot[0])
    # Inertia forces grow with ω², so at θ = 90° the driving torque changes.
    assert fast.solve(at=[math.pi / 2]).effort[0] != pytest.approx(problem.solve(at=[math.pi / 2]).effort[0])
    with pytest.raises(GraphkinError, match="mu"):
        problem.with_friction(-0.1)
    with pytest.raises(GraphkinError, match="q_dot"):
        problem.at_speed("fast")
    with pytest.raises(GraphkinError, match="no sliding pair"):
        catalog.load("gearset").with_friction(0.1)


def test_at_speed_refuses_given_kinematics_and_renames(problem):
    """Given ω/α/a_G hold at the file's speed only: at another speed they would be silently wrong."""
    import dataclasses

    given = dataclasses.replace(problem, given={(3, "omega"): 1.0})
    with pytest.raises(GraphkinError, match="given"):
        given.at_speed(10.0)
    assert "driven at 1200 rpm" in problem.at_speed(1200 * math.pi / 30).title
