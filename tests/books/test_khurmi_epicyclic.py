"""Khurmi & Gupta, *Theory of Machines*, 14th ed., Example 13.20 (p. 465): an epicyclic train, the sun driven with
100 N·m, the annulus held, the arm the output (catalog problem ``epicyclic_khurmi``).

Printed (FOSSEE Python Textbook Companion, ch13, Example 13.20): T_E = 64 teeth, and the torque necessary to keep
the internal gear stationary = 400 N·m. The book's method is a torque balance on the whole train, T_S + T_C + T_E
= 0, with the arm's torque from the speed ratio, T_C = −T_S N_S/N_C = −500 N·m (the power in equals the power out).

graphkin finds the same torques from the tooth forces, gear by gear (the planet's tooth forces on the sun and the
annulus, its pivot force on the arm), in both routes. The book gives no module: the file takes 5 mm, and the
torques do not depend on it (tested at 3 mm too). No deviation: the printed values are exact here.
"""

from __future__ import annotations

import numpy as np
import pytest

from graphkin import catalog
from graphkin.problem import parse_problem
from graphkin.report import constructions, cross_check

T_S, RATIO, T_HOLD = 100.0, 5.0, 400.0  # N·m, N_S/N_C, N·m (printed)


def test_the_teeth_the_book_derives_fit_the_file():
    mech = catalog.load("epicyclic_khurmi").mechanism
    ring, sun = mech.joints[3], mech.joints[4]
    assert ring.radius(1) / sun.radius(4) == pytest.approx(RATIO - 1)  # T_E = T_S (N_S/N_C − 1): 64 = 16 × 4
    assert ring.radius(1) - ring.radius(3) == pytest.approx(sun.radius(4) + sun.radius(3))


@pytest.mark.parametrize("module_mm", [5.0, 3.0])
def test_the_arm_and_the_holding_torque(module_mm):
    text = catalog.path("epicyclic_khurmi").read_text(encoding="utf-8")
    k = module_mm / 5.0
    for old, new in (('radii = ["160 mm", "60 mm"]', f'radii = ["{160 * k} mm", "{60 * k} mm"]'),
                     ('radii = ["40 mm", "60 mm"]', f'radii = ["{40 * k} mm", "{60 * k} mm"]'),
                     ('C = ["100 mm", "0 mm"]', f'C = ["{100 * k} mm", "0 mm"]')):
        assert old in text
        text = text.replace(old, new)
    r = parse_problem(text).solve(np.radians([30.0, 100.0, 250.0]))
    np.testing.assert_allclose(r.effort, -T_S * RATIO, rtol=1e-13)  # the output taken off the arm
    for i in range(r.n):
        kin = r.kinematics
        C = kin.position(3, "C")[i]
        P = C + 60e-3 * k * C / np.hypot(*C)
        F31 = r.force(3, 1)[i]
        assert -(P[0] * F31[1] - P[1] * F31[0]) == pytest.approx(T_HOLD, rel=1e-13)
    assert cross_check(r, constructions(r)).valid.all()
