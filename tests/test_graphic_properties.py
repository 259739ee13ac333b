"""Graphical = analytical on random mechanisms of every family the core supports (hypothesis)."""

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphkin.analytical import solve_forces
from graphkin.graphical import construct_forces
from graphkin.kinematics import solve_kinematics
from tests.strategies import families, friction_families

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def check(case):
    mech, q, q_dot, q_ddot = case
    r = solve_forces(solve_kinematics(mech, q, q_dot, q_ddot))
    checked = 0
    for i in np.flatnonzero(r.valid):
        c = construct_forces(r.kinematics, int(i))
        assert c.valid, c.reason
        assert not c.warnings, c.warnings
        scale = max(np.abs(r.force(*k)[i]).max() for k in r.forces)
        if scale == 0:
            continue
        for key in r.forces:
            np.testing.assert_allclose(c.force(*key), r.force(*key)[i], rtol=0, atol=1e-9 * scale)
        for key in r.normal:
            assert c.normal[key] == pytest.approx(r.normal[key][i], rel=0, abs=1e-9 * scale)
        lever = max(np.abs(r.couple[k][i]) for k in r.couple) if r.couple else 0.0
        for key in r.couple:
            assert c.couple[key] == pytest.approx(r.couple[key][i], rel=0, abs=1e-9 * max(lever, scale * 1e-3))
        effort_scale = max(abs(r.effort[i]), scale * 1e-3)
        assert c.effort == pytest.approx(r.effort[i], rel=0, abs=1e-9 * effort_scale * 10)
        for step in c.steps:
            assert step.closure() < 1e-9
        checked += 1
    return checked


@SETTINGS
@pytest.mark.parametrize("family", sorted(families))
@given(data=st.data())
def test_graphical_equals_analytical(family, data):
    check(data.draw(families[family]))


@SETTINGS
@pytest.mark.parametrize("family", sorted(friction_families))
@given(data=st.data())
def test_graphical_equals_analytical_with_friction(family, data):
    check(data.draw(friction_families[family]))
