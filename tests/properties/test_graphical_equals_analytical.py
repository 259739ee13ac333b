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


def test_a_load_the_driver_alone_balances_leaves_joint_forces_of_rounding_noise():
    """A case hypothesis found (check-lowest, hypothesis 6.100): a double slider at rest whose only load, a spring on
    the driven slider (0.95 N), is balanced by the driving force alone. Every joint force is rounding noise (5e-17 N,
    a couple of 3e-18 N·m) in the matrix route and exactly 0 in the polygons: they agree to 1e-9 of the load, as the
    comparison now judges them, not to 1e-9 of the noise itself."""
    import numpy as np

    from graphkin.model.driver import Driver
    from graphkin.model.joints import Prismatic, Revolute
    from graphkin.model.link import Link
    from graphkin.model.loads import SpringForce
    from graphkin.model.mechanism import Mechanism

    mech = Mechanism(
        links=[Link(number=1, points={"S2": (0.0, 0.0), "S4": (0.0, 0.0)}),
               Link(number=2, points={"A": (0.0, 0.0), "Q2": (0.0, 0.0), "P2": (0.0, 0.0)}, name="slider"),
               Link(number=3, points={"A": (0.0, 0.0), "B": (0.055918896663253385, 0.0),
                                      "P3": (0.027959448331626693, 0.0)}, G=(0.027959448331626693, 0.0)),
               Link(number=4, points={"B": (0.0, 0.0), "Q4": (0.0, 0.0), "P4": (0.0, 0.0)}, name="slider")],
        joints=[Prismatic(guide=1, slider=2, point="Q2", through="S2", direction=1.0), Revolute(links=(2, 3), point="A"),
                Revolute(links=(3, 4), point="B"), Prismatic(guide=1, slider=4, point="Q4", through="S4")],
        loads=[SpringForce(link=2, point="P2", force=(0.0, 0.0), name="S0", anchor_point="S2",
                           rate=17.883042400175633)],
        driver=Driver(link=2, kind="slider"), assembly={"B": 1}, title="double slider")
    zero = np.array([0.0])
    assert graphical_equals_analytical((mech, np.array([-0.05316299449209827]), zero, zero)) == 1
