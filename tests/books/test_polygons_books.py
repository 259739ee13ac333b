"""The velocity and acceleration polygons reproduce two textbook examples' printed kinematics.

- Söylemez, *Mechanisms*, §6.4, the double-slider example (seed 000_6a5b8db2377b79fc.txt; catalog
  ``double_slider``): slider 2 driven at 2 m/s, rod AB = 500 mm, x = 200 mm. Printed: ω13 = 4.364 rad/s CCW,
  α13 = 8.312 rad/s² CCW, ẏ = −872.872 mm/s, ÿ = −10.390 m/s², a_G3 = 5.194 m/s² ∠ 270°. The book rounds to
  four or five digits: 0.2 % as in ``test_soylemez_double_slider.py``. A PRP dyad: two sliding sides, and the
  driver in pure translation.
- Marghitu & Dupac, *Advanced Dynamics*, Example 6.1 (the MATLAB program ``E6_1.m``, see
  ``test_marghitu_sixbar.py``; catalog ``shaper_six_bar``): the R-RTR-RRT shaper, frame numbered 0. Printed
  ω3 = 6.46, α3 = 30.4, ω4 = 3.93, α4 = −82.5 (three figures), v_C, a_C, v_E, a_E and a_C2 = a_B to 3 decimals.
  An RPR dyad (the block slides on the turning lever: a Coriolis component) and an RRP dyad. Tolerance: half a
  unit of the printed last digit.
"""

from __future__ import annotations

import numpy as np
import pytest

from graphkin import catalog
from graphkin.graphical import construct_kinematics
from graphkin.notation import polar

REL = 2e-3
HALF = 0.0005


@pytest.fixture(scope="module")
def double_slider():
    return construct_kinematics(catalog.load("double_slider").kinematics(), 0)


@pytest.fixture(scope="module")
def shaper():
    return construct_kinematics(catalog.load("shaper_six_bar").kinematics(), 0)


def test_soylemez_double_slider_polygons(double_slider):
    c = double_slider
    assert c.valid
    assert c.omega[3] == pytest.approx(4.364, rel=REL)
    assert c.alpha[3] == pytest.approx(8.312, rel=REL)
    assert c.v(4, "B")[1] * 1e3 == pytest.approx(-872.872, rel=REL)
    assert c.a(4, "B")[1] == pytest.approx(-10.390, rel=REL)
    size, angle = polar(c.a_G[3])
    assert size == pytest.approx(5.194, rel=REL)
    assert angle == pytest.approx(-90.0, abs=1e-9)


def test_soylemez_double_slider_driver_translates(double_slider):
    """Link 2 slides on the frame: its velocity image is one point, every point at 2 m/s along +x."""
    image = next(s for s in double_slider.steps if s.kind == "image" and s.links == (2,) and s.polygon == "velocity")
    assert "translates" in image.caption
    for v in image.points.values():
        assert v == pytest.approx((2.0, 0.0), abs=1e-12)


def test_marghitu_shaper_polygons(shaper):
    c = shaper
    assert c.valid
    for value, printed, half in ((c.omega[3], 6.46, 0.005), (c.alpha[3], 30.4, 0.05), (c.omega[4], 3.93, 0.005),
                                 (c.alpha[4], -82.5, 0.05)):
        assert abs(value - printed) <= half
    assert np.all(np.abs(np.subtract(c.v(3, "C"), (-4.374, 1.143))) <= HALF)
    assert np.all(np.abs(np.subtract(c.a(3, "C"), (-27.947, -22.882))) <= HALF)
    assert np.all(np.abs(np.subtract(c.v(5, "E"), (-4.660, 0.0))) <= HALF)
    assert np.all(np.abs(np.subtract(c.a(5, "E"), (-17.464, 0.0))) <= HALF)
    assert np.all(np.abs(np.subtract(c.a_G[2], (-62.034, -62.034))) <= HALF)


def test_marghitu_shaper_coriolis_is_2_omega_v_turned_with_omega(shaper):
    """The Coriolis vector of the acceleration polygon is 2 ω v_rel, v_rel (from the velocity polygon) turned 90°
    in the sense of the guide's ω (the slot is in lever 3, which turns CCW)."""
    c = shaper
    v_rel = next(v for v in c.vectors("velocity") if v.name.startswith("v_B3B2") and v.known == "direction")
    a_c = next(v for v in c.vectors("acceleration") if v.name.startswith("a^c_"))
    w = c.omega[2]
    expected = 2 * w * complex(*v_rel.vector) * 1j
    assert a_c.vector == pytest.approx((expected.real, expected.imag), rel=1e-12, abs=1e-12 * abs(expected))
    step = next(s for s in c.steps if s.polygon == "acceleration" and s.kind == "dyad" and "RPR" in s.caption)
    assert "turned 90° CCW (the sense of ω3)" in step.caption
