"""What the graphical route reads instead of working it out again (behaviour, not speed).

:attr:`Kinematics.derived <graphkin.kinematics.Kinematics.derived>`: the motion the input produces, which
:meth:`~graphkin.kinematics.Kinematics.with_given` keeps beside the book's given values. :func:`plan_solved
<graphkin.kinematics.plan.plan_solved>`: the plan a mechanism's kinematics were solved with, found by their
decomposition. Timings: benchmarks/README.md, "The guard's cost".
"""

import dataclasses
import math
from types import MappingProxyType

import numpy as np

from graphkin import catalog
from graphkin.kinematics import decompose, solve_kinematics
from graphkin.kinematics.plan import kept_plan, plan_of, plan_solved
from graphkin.model import Driver, Link, Mechanism, Revolute

THETA = np.linspace(0.0, 2 * math.pi, 13)


def fourbar(a3=0.235):
    links = [
        Link(1, {"A0": (0.0, 0.0), "B0": (0.5, 0.0)}),
        Link(2, {"A0": (0.0, 0.0), "A": (0.085, 0.0)}, mass=3.0, I_G=0.03),
        Link(3, {"A": (0.0, 0.0), "B": (a3, 0.0)}, mass=2.0, I_G=0.14),
        Link(4, {"B0": (0.0, 0.0), "B": (0.55, 0.0)}, mass=5.1, I_G=0.92),
    ]
    joints = [Revolute((1, 2), "A0"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), Revolute((1, 4), "B0")]
    return Mechanism(links, joints, Driver(2), (), assembly={"B": 1})


def test_kinematics_with_nothing_given_are_their_own_derived_motion():
    kin = solve_kinematics(fourbar(), THETA, 94.0, 3.0)
    assert kin.given == {} and kin.derived is kin
    copy = dataclasses.replace(kin, static=True)  # nothing given: a copy is its own derived motion too
    assert copy.derived is copy


def test_with_given_keeps_the_motion_the_input_derives():
    kin = solve_kinematics(fourbar(), THETA, 94.0, 3.0)
    omega3, alpha4 = kin.omega[3].copy(), kin.alpha[4].copy()
    given = kin.with_given({(3, "omega"): omega3 * 1.01, (4, "alpha"): alpha4 - 2.0})
    assert given.derived is kin
    np.testing.assert_array_equal(given.w(3), omega3 * 1.01)  # the given values stand in ...
    np.testing.assert_array_equal(given.al(4), alpha4 - 2.0)
    np.testing.assert_array_equal(given.derived.w(3), omega3)  # ... for the derived, which are kept as they were
    np.testing.assert_array_equal(given.derived.al(4), alpha4)
    assert given.derived.given == {}
    # Given again: still the motion the input derives, not the kinematics the first values were put in.
    again = given.with_given({(3, "omega"): omega3 * 1.02})
    assert again.derived is kin
    np.testing.assert_array_equal(again.w(3), omega3 * 1.02)
    np.testing.assert_array_equal(again.derived.w(3), omega3)


def test_a_given_angle_turns_the_link_but_not_the_derived_motion():
    kin = solve_kinematics(fourbar(), THETA, 94.0, 3.0)
    theta3, e3 = kin.theta[3].copy(), kin.e[3].copy()
    turned = kin.with_given({(3, "theta"): theta3 + 0.01})
    assert turned.derived is kin
    np.testing.assert_allclose(turned.e[3], e3 * np.exp(0.01j), rtol=0, atol=1e-15)
    np.testing.assert_array_equal(turned.derived.theta[3], theta3)
    np.testing.assert_array_equal(turned.derived.e[3], e3)


def test_a_copy_by_replace_of_given_kinematics_does_not_know_their_derived_motion():
    kin = solve_kinematics(fourbar(), THETA, 94.0, 3.0)
    given = kin.with_given({(3, "omega"): kin.omega[3] * 1.01})
    assert dataclasses.replace(given, static=True).derived is None  # only the fields are copied


def test_a_problem_with_given_values_keeps_the_motion_its_input_derives():
    problem = catalog.load("fourbar_dynamic_makdin")
    kin = problem.kinematics()
    assert kin.given and kin.derived is not None and kin.derived.given == {}
    own = solve_kinematics(problem.mechanism, problem.q, problem.q_dot, problem.q_ddot)
    for link in own.omega:
        np.testing.assert_array_equal(kin.derived.omega[link], own.omega[link])
        np.testing.assert_array_equal(kin.derived.alpha[link], own.alpha[link])
        np.testing.assert_array_equal(kin.derived.w(link), own.w(link))
    assert any(not np.array_equal(kin.w(link), own.w(link)) or not np.array_equal(kin.al(link), own.al(link))
               for link in own.omega)  # the book's values, where the derived motion has its own


def test_plan_solved_is_the_plan_the_kinematics_were_solved_with():
    mech = fourbar()
    kin = solve_kinematics(mech, THETA, 94.0, 3.0)
    plan = plan_of(mech)
    assert plan_solved(mech, kin.groups) is plan and plan.groups is kin.groups


def test_plan_solved_describes_the_mechanism_as_solved_after_a_change_in_place():
    mech = fourbar()
    kin = solve_kinematics(mech, THETA, 94.0, 3.0)
    solved = plan_of(mech)
    coupler = mech.links[2]
    object.__setattr__(coupler, "points", MappingProxyType({**coupler.points, "B": (0.25, 0.0)}))
    # The kinematics describe the coupler as it was: so does the plan they were solved with ...
    assert plan_solved(mech, kin.groups) is solved
    assert solved.points[3, "B"] == complex(0.235, 0.0)
    # ... while the mechanism's own plan is made again for it as it is now.
    now = plan_of(mech)
    assert now is not solved and now.points[3, "B"] == complex(0.25, 0.0)
    # That plan is the one kept now: kinematics solved before the change are answered with the current plan.
    assert plan_solved(mech, kin.groups) is now


def test_plan_solved_of_other_groups_or_another_mechanism_is_that_mechanisms_plan():
    mech = fourbar()
    kin = solve_kinematics(mech, THETA, 94.0, 3.0)
    plan = plan_of(mech)
    assert plan_solved(mech, decompose(mech)) is plan  # equal groups, not the plan's own: checked, and current
    assert plan_solved(mech, ()) is plan
    other = fourbar(a3=0.25)  # the same links and joints, another mechanism: never answered with mech's plan
    assert kept_plan(other) is None
    mine = plan_solved(other, kin.groups)
    assert mine is not plan and kept_plan(other) is mine and mine.points[3, "B"] == complex(0.25, 0.0)
