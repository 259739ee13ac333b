"""A failing property prints its shrunk example as Python that rebuilds it (issue 35, item 2).

Hypothesis prints what a test drew by its repr: a :class:`tests.strategies.Case` prints the mechanism's links,
joints, loads, driver, gravity, assembly and frame, and q, q̇, q̈, as code a developer pastes into a test.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.strategies import families

PASTE = "from tests.strategies import *"
"""What the printed code needs before it (tests.strategies brings np, Case and graphkin.model's classes)."""


@settings(max_examples=5, deadline=None)
@pytest.mark.parametrize("family", sorted(families))
@given(data=st.data())
def test_a_printed_case_rebuilds_the_case(family, data):
    case = data.draw(families[family])
    names = {}
    exec(PASTE, names)
    again = eval(repr(case), names)
    assert again.mechanism == case.mechanism
    for name in ("q", "q_dot", "q_ddot"):
        np.testing.assert_array_equal(getattr(again, name), getattr(case, name))
