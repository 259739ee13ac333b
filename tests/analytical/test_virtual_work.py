"""The driving effort from virtual work (one power balance) against the matrix method.

The power balance is independent of the matrix method: it reads only the kinematics (velocities of the load
points and the centres of mass) and the loads, never a joint force. So agreement to round-off on random
linkages of every family (tests/strategies.py), on the catalog's problems and over whole cycles checks both.
Tolerance: 1e-9 relative to the largest effort, as in tests/properties/test_equilibrium.py (an error of the
method — a missing load, a sign — is O(1)).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from graphkin import catalog
from graphkin.analytical import solve_forces
from graphkin.analytical.virtual_work import effort_by_virtual_work, load_powers
from graphkin.cycle import sweep
from graphkin.errors import GraphkinError
from graphkin.kinematics import solve_kinematics
from tests.physics import RTOL, SETTINGS, frictionless, power_terms
from tests.strategies import families

FAMILIES = sorted(families)
# Problems that write a book's rounded link angles as [given] positions are solved at the book's geometry,
# which is not a position of the linkage (see effort_by_virtual_work's Notes); friction needs joint forces.
BOOK_GEOMETRY = {"fourbar_dynamic_makdin", "fourbar_two_loads_makdin", "slider_crank_dynamic_makdin"}
WITH_FRICTION = {"slider_crank_friction"}


@pytest.mark.parametrize("family", FAMILIES)
@SETTINGS
@given(data=st.data())
def test_virtual_work_equals_matrix_method_on_random_linkages(family, data):
    case = data.draw(families[family])
    mech = frictionless(case.mechanism)
    kin = solve_kinematics(mech, case.q, case.q_dot, case.q_ddot)
    r = solve_forces(kin)
    by_power = effort_by_virtual_work(kin)
    ok = kin.valid & (np.asarray(kin.q_dot) != 0)
    # The size of every power in the balance, term by term (tests/physics.py): a sum can vanish by orthogonality.
    _, _, scale = power_terms(kin, r)
    tolerance = RTOL * scale[ok] / np.abs(kin.q_dot[ok])
    assert np.all(np.abs(by_power[ok] - r.effort[ok]) <= tolerance), (by_power[ok], r.effort[ok], tolerance)


@pytest.mark.parametrize("name", sorted(set(catalog.names()) - BOOK_GEOMETRY - WITH_FRICTION))
def test_virtual_work_equals_matrix_method_on_the_catalog(name):
    problem = catalog.load(name)
    effort = problem.solve().effort
    np.testing.assert_allclose(effort_by_virtual_work(problem.kinematics()), effort, rtol=0,
                               atol=1e-9 * np.abs(effort).max())


@pytest.mark.parametrize("name", ["strip_cutter", "engine_gas_force", "shaper_six_bar"])
def test_virtual_work_over_a_cycle(name):
    cycle = sweep(catalog.load(name), 360)
    by_power = effort_by_virtual_work(cycle.analysis.kinematics)
    np.testing.assert_allclose(by_power, cycle.torque, rtol=0, atol=1e-9 * np.abs(cycle.torque).max())


def test_static_problem_uses_a_virtual_motion():
    # Khurmi & Gupta Ex. 15.10 (static): T = F_P · r (sin θ + sin 2θ / (2 sqrt(n² − sin² θ))), the book's
    # turning moment from the piston effort, is −T12.
    problem = catalog.load("engine_static_khurmi")
    kin = problem.kinematics()
    assert kin.static and not np.any(kin.q_dot)
    theta, r, n = np.radians(30), 0.3, 4.5
    F_P = 35342.917353 - 6480 - 600
    T = F_P * r * (np.sin(theta) + np.sin(2 * theta) / (2 * np.sqrt(n**2 - np.sin(theta) ** 2)))
    assert effort_by_virtual_work(kin)[0] == pytest.approx(-T, rel=1e-12)
    assert set(load_powers(kin)) == {"FL (gas)", "FI (inertia of the reciprocating parts)", "RF (friction)"}


def test_inertia_and_weight_powers_are_named_per_link():
    powers = load_powers(catalog.load("diesel_vertical_khurmi").kinematics())
    assert {"weight of link 4", "inertia of link 4"} <= set(powers)


def test_friction_is_refused_with_the_reason():
    with pytest.raises(GraphkinError, match="friction.*normal force"):
        effort_by_virtual_work(catalog.load("slider_crank_friction").kinematics())
