"""Wentzell, *Machine Design*, Example 12.1 (p. 254): a spur pinion in inch-pound units, 5 hp at 1725 rpm (catalog
problem ``spur_pair_wentzell``, written in inches and horsepower).

Printed (FOSSEE Python Textbook Companion, Machine Design by T. H. Wentzell, Chapter 12, Example 12.1): pitch
diameter 2.50 in, transmitted force 146.09 lb, separating force 53.17 lb, maximum (resultant) force 155.46 lb. The
book's method: d = N/P_d, T = 63000 hp/n [lb·in], W_t = T/(d/2), W_r = W_t tan φ, W = W_t / cos φ.

The one deviation: the book's 63000 is 63 025 rounded (1 hp = 6600 lbf·in/s, 6600 × 60/2π). The method with
63000 gives every printed digit (tested); with 63 025 it is graphkin to 1e-9 (tested); so the printed values lie
exactly 63000/63 025 − 1 = −0.04 % from graphkin's, tested as that ratio and nothing looser.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin import catalog
from graphkin.report import constructions, cross_check

LBF, INCH = 4.4482216152605, 0.0254  # N, m (exact by definition)
HP, N_RPM, TEETH, P_D, PHI = 5.0, 1725.0, 20, 8.0, math.radians(20.0)
PRINTED = {"d": 2.50, "W_t": 146.09, "W_r": 53.17, "W": 155.46}
HALF_UNIT = {"d": 0.005, "W_t": 0.005, "W_r": 0.005, "W": 0.005}


def method(constant):
    d = TEETH / P_D
    W_t = constant * HP / N_RPM / (d / 2)
    return {"d": d, "W_t": W_t, "W_r": W_t * math.tan(PHI), "W": W_t / math.cos(PHI)}


EXACT = 6600 * 60 / (2 * math.pi)  # lb·in per hp and rpm


@pytest.fixture(scope="module")
def solved():
    r = catalog.load("spur_pair_wentzell").solve()
    W = -r.force(2, 3)[0]  # the gear's tooth force on the pinion, N
    O2, O3 = r.kinematics.position(2, "O2")[0], r.kinematics.position(3, "O3")[0]
    e = (O3 - O2) / np.hypot(*(O3 - O2))
    W_r = abs(float(W @ e))
    W_t = abs(float(W[0] * -e[1] + W[1] * e[0]))
    return r, {"W_t": W_t / LBF, "W_r": W_r / LBF, "W": float(np.hypot(*W)) / LBF}


def test_the_books_method_gives_every_printed_digit():
    got = method(63000.0)
    for key, printed in PRINTED.items():
        assert abs(got[key] - printed) <= HALF_UNIT[key], key


def test_graphkin_is_the_method_with_the_exact_horsepower(solved):
    r, got = solved
    want = method(EXACT)
    for key in ("W_t", "W_r", "W"):
        assert got[key] == pytest.approx(want[key], rel=1e-9), key
    assert r.effort[0] == pytest.approx(EXACT * HP / N_RPM * LBF * INCH, rel=1e-9)  # T = 63 025 hp/n lb·in
    assert cross_check(r, constructions(r)).valid.all()


def test_the_printed_forces_lie_63000_over_63025_from_graphkins(solved):
    _, got = solved
    for key in ("W_t", "W_r", "W"):
        assert PRINTED[key] / got[key] == pytest.approx(63000.0 / EXACT, abs=HALF_UNIT[key] / PRINTED[key]), key


def test_reported_in_us_units_the_tooth_force_is_in_lb(capsys):
    """``graphkin solve spur_pair_wentzell --units US``: the gear's tooth force on the pinion in lbf, the book's
    unit; the printed 155.46 lb lies 63000/63 025 from it, as above. With a units file giving torques in lbf·in
    (Wentzell's unit), the pinion's torque is 63 025 hp/n lb·in."""
    import json

    from graphkin.cli import main

    assert main(["solve", "spur_pair_wentzell", "--units", "US", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["units"]["positions[].forces.*"] == "lbf"
    F32 = data["positions"][0]["forces"]["F32"]
    W = math.hypot(*F32)
    assert W == pytest.approx(method(EXACT)["W"], rel=1e-9)
    assert PRINTED["W"] / W == pytest.approx(63000.0 / EXACT, abs=HALF_UNIT["W"] / PRINTED["W"])
    assert main(["solve", "spur_pair_wentzell", "--units", "US"]) == 0
    assert f"{W:.4g} lbf ∠" in capsys.readouterr().out


def test_in_lb_in_from_a_units_file(capsys, tmp_path):
    import json

    from graphkin.cli import main

    units = tmp_path / "wentzell.toml"
    units.write_text('base = "US"\ntorque = "lbf*in"\n', encoding="utf-8")
    assert main(["solve", "spur_pair_wentzell", "--units", str(units), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["units"]["positions[].driver.value"] == "lbf*in"
    assert data["positions"][0]["driver"]["value"] == pytest.approx(EXACT * HP / N_RPM, rel=1e-9)
    assert data["positions"][0]["input"]["rate"] == pytest.approx(N_RPM, rel=1e-12)  # rpm
