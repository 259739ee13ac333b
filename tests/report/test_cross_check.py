"""No solve reports valid while its two routes disagree (issue 25).

The case that started it: a planet gear on a driven arm meshing with a fixed sun. The analytical route found the
arm's torque; the graphical route passed the tooth force on to the sun (the frame) but never the planet's pivot
force on to the arm, and so reported F12 = 0 and T12 = 0 with ``valid: true``. The pivot force now loads the arm
in the graphical route, and :func:`graphkin.report.cross_check` marks any position where the routes differ.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from graphkin import report
from graphkin.analytical import solve, solve_forces
from graphkin.graphical import construct_forces
from graphkin.kinematics import solve_kinematics
from graphkin.model import Driver, GearMesh, Link, Mechanism, Revolute, Torque
from tests.physics import SETTINGS
from tests.strategies import families


def planet_on_a_driven_arm():
    """Arm 2 about O (150 mm), planet 3 (r = 50 mm) at its end meshing with a fixed sun (the frame, r = 100 mm);
    a torque of −100 N·m on the planet (a load on its shaft)."""
    links = [Link(1, {"O": (0.0, 0.0)}), Link(2, {"O": (0.0, 0.0), "C": (0.15, 0.0)}), Link(3, {"C": (0.0, 0.0)})]
    joints = [Revolute((1, 2), "O"), Revolute((2, 3), "C"), GearMesh((1, 3), ("O", "C"), (0.10, 0.05))]
    return Mechanism(links, joints, Driver(2), [Torque(3, -100.0)])


def test_the_planets_pivot_force_loads_the_arm_in_the_graphical_route():
    r = solve(planet_on_a_driven_arm(), np.radians([0.0, 37.0, 250.0]), 10.0, static=True)
    # By hand: the planet's moment about C, −100 + 0.05 W_t = 0, W_t = 2000 N; it acts on the arm at C, 150 mm out,
    # a moment of 2000 × 0.15 = 300 N·m, which the driving torque balances: T12 = +300 N·m (the planet's −100 N·m
    # becomes −300 N·m at the arm through the sun's ratio 1 + 100/50).
    np.testing.assert_allclose(r.effort, 300.0, rtol=1e-14)
    for i in range(r.n):
        c = construct_forces(r.kinematics, i)
        assert c.valid and not c.warnings
        assert c.effort == pytest.approx(300.0, rel=1e-13)
        for key in r.forces:
            np.testing.assert_allclose(c.force(*key), r.force(*key)[i], rtol=0, atol=1e-12 * 2200)
    graphical = report.constructions(r)
    assert report.cross_check(r, graphical) is r


def test_a_route_that_disagrees_makes_the_position_not_valid():
    """The graphical route as it was before the fix (F12 = 0, T12 = 0): the position is not valid, and the reason
    names the force that differs, with both values."""
    r = solve(planet_on_a_driven_arm(), [0.3, 1.0], 10.0, static=True)
    graphical = report.constructions(r)
    old = dataclasses.replace(graphical[0], effort=0.0, forces={**graphical[0].forces, (1, 2): (0.0, 0.0)})
    checked = report.cross_check(r, [old, graphical[1]])
    assert checked.valid.tolist() == [False, True]
    assert checked.reason(0).startswith("the graphical and analytical routes disagree: F12 is 0 N graphically, 2")
    data = report.solution(_Named(), r, [old, graphical[1]])
    assert [p["valid"] for p in data["positions"]] == [False, True]
    assert "disagree" in data["positions"][0]["reason"]


def test_a_construction_that_cannot_close_where_the_analytical_route_can_is_not_valid():
    r = solve(planet_on_a_driven_arm(), [0.3], 10.0, static=True)
    c = dataclasses.replace(report.constructions(r)[0], valid=False, reason="friction locks it")
    checked = report.cross_check(r, [c])
    assert not checked.valid[0]
    assert "the graphical route cannot close (friction locks it)" in checked.reason(0)


class _Named:
    name, title, source = "planet", "", ""


@pytest.mark.parametrize("family", sorted(families))
@SETTINGS
@given(data=st.data())
def test_the_guard_passes_agreeing_routes_and_stops_any_that_differ(family, data):
    """On random linkages of every family (gears and epicyclic trains included) the routes agree, so the guard
    changes nothing; a disagreement of 1e-5 of the largest force (or effort) in any one joint force is caught and
    named."""
    mech, q, q_dot, q_ddot = data.draw(families[family])
    r = solve_forces(solve_kinematics(mech, q, q_dot, q_ddot))
    graphical = report.constructions(r)
    assert report.cross_check(r, graphical) is r, [report.cross_check(r, graphical).reason(i) for i in range(r.n)]
    i = data.draw(st.integers(0, r.n - 1))
    key = data.draw(st.sampled_from(sorted(r.forces)))
    # The guard measures a difference against the largest force at the position, or the driving effort as a force
    # (a torque over the mechanism's size) where that is larger: the nudge is 1e-5 of the same.
    size = max(math.dist(p, q) for link in mech.links for p in link.points.values() for q in link.points.values())
    arm = (size or 1.0) if mech.driver.crank else 1.0
    scale = max([np.hypot(*r.force(*k)[i]) for k in r.forces] + [abs(r.effort[i]) / arm])
    if not scale > 0:
        return
    turn = data.draw(st.floats(0.0, 2 * math.pi))
    nudge = 1e-5 * scale * np.array([math.cos(turn), math.sin(turn)])
    c = graphical[i]
    wrong = dataclasses.replace(c, forces={**c.forces, key: tuple(np.asarray(c.forces[key]) + nudge)})
    checked = report.cross_check(r, [wrong if k == i else g for k, g in enumerate(graphical)])
    assert checked.valid.tolist() == [k != i for k in range(r.n)]
    assert f"{r.name_of(*key)} is" in checked.reason(i), checked.reason(i)
