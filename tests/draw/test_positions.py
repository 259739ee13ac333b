"""draw_positions: the strip cutter at the start, middle and end of the cut, side by side (lesson 03)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from matplotlib.colors import to_rgb
from matplotlib.patches import Polygon

from graphkin import catalog, draw
from graphkin.draw import style
from graphkin.errors import GraphkinError

CUT = np.radians([124.0, 140.0, 156.0])


@pytest.fixture(scope="module")
def cutter():
    p = catalog.load("strip_cutter")
    return p, draw.draw_positions(p, CUT, between=((3, "C"), (4, "C")))


def _plates(ax):
    """The plates drawn: a ternary link is a polygon filled with the style's plate colour."""
    fill = to_rgb(style.STYLE.plate_fill)
    return [a for a in ax.patches if isinstance(a, Polygon) and a.get_facecolor()[:3] == pytest.approx(fill)]


def test_one_panel_per_position_titled_with_its_angle_and_the_blades_gap(cutter):
    p, fig = cutter
    kin = p.kinematics(at=CUT)
    assert len(fig.axes) == 3
    for n, ax in enumerate(fig.axes):
        gap = (kin.position(3, "C")[n] - kin.position(4, "C")[n]) * 1e3
        assert ax.get_title().startswith(f"θ₁₂ = {round(math.degrees(CUT[n]))}°:  C₃ − C₄ = (")
        assert ax.get_title().replace("−", "-").endswith(f"({gap[0]:.1f}, {gap[1]:.1f}) mm")


def test_each_panel_draws_the_two_plates_with_the_blades_where_the_kinematics_puts_them(cutter):
    p, fig = cutter
    kin = p.kinematics(at=CUT)
    for n, ax in enumerate(fig.axes):
        plates = _plates(ax)
        assert len(plates) == 2  # the coupler 3 and the rocker 4 are plates; the crank 2 is a bar
        corners = [np.asarray(poly.get_xy(), float) for poly in plates]
        for link in (3, 4):
            tip = kin.position(link, "C")[n] * 1e3  # the blade tip [mm]
            assert any(np.isclose(c, tip, rtol=0, atol=1e-9).all(axis=1).any() for c in corners), (n, link)
        crank = kin.position(2, "A")[n] * 1e3
        assert any(np.allclose(line.get_xydata(), [kin.position(2, "A0")[n] * 1e3, crank]) for line in ax.lines)


def test_every_panel_shows_the_same_stretch_of_the_plane(cutter):
    _, fig = cutter
    assert len({(ax.get_xlim(), ax.get_ylim()) for ax in fig.axes}) == 1


def test_no_positions_is_told_so():
    with pytest.raises(GraphkinError, match="'at'"):
        draw.draw_positions(catalog.load("strip_cutter"), [])
