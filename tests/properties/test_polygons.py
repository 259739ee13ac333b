"""The velocity and acceleration polygons, and the instant centres, equal the analytical kinematics (hypothesis).

On random mechanisms of every family the core supports: each dyad type (sliders on turning guides, so
Coriolis components, included), a slider driver, external and internal gears (an annulus found from its pinion,
on the frame or on an arm), compound planets, planets on driven arms, input turning either way, random link
numbering with the frame 1 or 0. A failure names the quantity, the position and both values, and hypothesis prints
the shrunk case as code (``tests.strategies.Case``).
"""

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.physics import SETTINGS, forces_from_polygons_equal_analytical, polygons_equal_analytical
from tests.strategies import families


@SETTINGS
@pytest.mark.parametrize("family", sorted(families))
@given(data=st.data())
def test_polygons_equal_analytical(family, data):
    assert polygons_equal_analytical(data.draw(families[family])) > 0


@SETTINGS
@pytest.mark.parametrize("family", sorted(families))
@given(data=st.data())
def test_forces_from_the_polygons_equal_analytical(family, data):
    assert forces_from_polygons_equal_analytical(data.draw(families[family])) > 0
