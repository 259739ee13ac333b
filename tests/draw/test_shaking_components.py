"""draw_shaking_components: the shaking force's x and y components against the crank angle (lesson 12)."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from graphkin import catalog, draw
from graphkin.cycle import sweep


def test_the_curves_are_the_cycle_s_shaking_force_components():
    cycle = sweep(catalog.load("engine_balancing"), 72)
    d = draw.draw_shaking_components(cycle)
    S = cycle.shaking_force()
    for name, column in (("S_x", 0), ("S_y", 1)):
        x, y = d.curves[name].get_data()
        np.testing.assert_array_equal(y, S[:, column])
        np.testing.assert_allclose(x, np.degrees(cycle.q))
    assert [t.get_text() for t in d.ax.get_legend().get_texts()] == ["$S_x$ (along x)", "$S_y$ (along y)"]


def test_it_draws_on_the_axes_it_is_given():
    ax = Figure().add_subplot()
    d = draw.draw_shaking_components(sweep(catalog.load("engine_balancing"), 36), ax=ax)
    assert d.ax is ax and len(ax.lines) >= 2
