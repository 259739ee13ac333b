"""The force polygons equal the analytical route on random mechanisms of every family the core supports (hypothesis).

The families and what a failure prints: tests/properties/test_polygons.py.
"""

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.physics import graphical_equals_analytical
from tests.strategies import families, friction_families

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@SETTINGS
@pytest.mark.parametrize("family", sorted(families))
@given(data=st.data())
def test_graphical_equals_analytical(family, data):
    graphical_equals_analytical(data.draw(families[family]))


@SETTINGS
@pytest.mark.parametrize("family", sorted(friction_families))
@given(data=st.data())
def test_graphical_equals_analytical_with_friction(family, data):
    graphical_equals_analytical(data.draw(friction_families[family]))
