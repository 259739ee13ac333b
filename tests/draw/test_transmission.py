"""draw_transmission_angle: μ over the strip cutter's cycle, its least value marked (lesson 03)."""

from __future__ import annotations

import numpy as np
import pytest
from matplotlib.figure import Figure

from graphkin import catalog, draw
from graphkin.cycle import sweep
from graphkin.errors import GraphkinError


def test_the_curve_is_the_cycle_s_transmission_angle_and_its_least_value_is_marked():
    cycle = sweep(catalog.load("strip_cutter"), 72)
    d = draw.draw_transmission_angle(cycle)
    x, y = d.curves["mu"].get_data()
    mu = np.degrees(cycle.transmission_angle())
    np.testing.assert_array_equal(y, mu)
    np.testing.assert_allclose(x, np.degrees(cycle.q))
    (px,), (py,) = d.curves["least"].get_data()
    assert py == mu.min() and px == x[np.argmin(mu)]
    assert d.labels["least"].get_text() == f"least μ = {mu.min():.1f}°"


def test_it_draws_on_the_axes_it_is_given():
    ax = Figure().add_subplot()
    d = draw.draw_transmission_angle(sweep(catalog.load("strip_cutter"), 36), ax=ax)
    assert d.ax is ax and len(ax.lines) >= 2


def test_a_mechanism_without_a_transmission_angle_is_told_so():
    with pytest.raises(GraphkinError, match="four-bar"):
        draw.draw_transmission_angle(sweep(catalog.load("slider_crank_friction"), 12))
