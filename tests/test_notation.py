"""Numbers in text for people (graphkin.notation): no exponent where none is needed, rounding residues as 0."""

from __future__ import annotations

import math
import re

import pytest
from hypothesis import given
from hypothesis import strategies as st

from graphkin import catalog, report
from graphkin.notation import num


@pytest.mark.parametrize("x, text", [
    (50640.7, "50640"), (-22851.3, "−22850"), (1972.4, "1972"), (27.0625, "27.06"), (0.01234, "0.01234"),
    (0.0, "0"), (2.5e-5, "2.5e−05"), (3.2e7, "32000000"), (3.2e9, "3.2e+09"),
])
def test_four_significant_figures_without_an_exponent_from_1e_minus_4_to_1e9(x, text):
    assert num(x) == text


def test_the_minus_sign_and_the_residue_floor():
    assert num(-0.5, minus="-") == "-0.5"
    assert num(3.2e-12, zero=1e-9) == "0" and num(-1e-9, zero=1e-9) == "0" and num(2e-9, zero=1e-9) == "2e−09"


@given(st.floats(min_value=1e-4, max_value=9.99e8) | st.floats(min_value=-9.99e8, max_value=-1e-4))
def test_the_digits_read_back_as_the_value_to_four_figures(x):
    text = num(x, minus="-")
    assert "e" not in text
    assert float(text) == pytest.approx(x, rel=5.01e-4)


def _text_at(name, degrees):
    p = catalog.load(name)
    r = p.solve(at=[math.radians(degrees)])
    return report.format_solution(p, r, report.constructions(r))


def test_a_dead_centre_reads_as_zero_not_as_rounding():
    """Khurmi & Gupta's engine at θ = 180° (inner dead centre): no guide force and no driving torque, exactly."""
    text = _text_at("engine_gas_force", 180)
    assert not re.search(r"\de[-+]\d", text.split("rel. diff")[0]), text  # no exponent before the last table
    assert re.search(r"G14 += \( +0\.0000, +0\.0000\) N = 0 N ", text)
    assert "normal 0 N, friction 0 N, line acts —" in text
    assert re.search(r"Driver: T12 = 0\.0000 N·m\n", text)  # no sense (CW or CCW of a residue), no trailing space
    assert "acts through O (its arm d = 0), so the driving torque is T12 = 0 N·m" in text
    # The data (what --json writes) keeps what the solver computed, rounding and all.
    p = catalog.load("engine_gas_force")
    r = p.solve(at=[math.pi])
    data = report.solution(p, r, report.constructions(r))["positions"][0]
    assert data["forces"]["G14"] == pytest.approx(list(r["G14"][0]), abs=0, rel=0)
    assert data["driver"]["value"] == r.effort[0]


def test_large_forces_are_written_in_digits():
    """The engine's rod thrust at 60° from IDC (Khurmi & Gupta Ex. 15.7: 50.62 kN printed; graphkin's 50.641 kN and
    its components are checked against the book in tests/books/test_khurmi_engine.py) reads 50640 N."""
    text = _text_at("engine_gas_force", 60)
    assert "e+0" not in text.split("rel. diff")[0]
    assert re.search(r"F23 += \( *49440\.0331, +-10964\.1372\) N = 50640 N ∠ -12\.50°", text), text


def test_an_inertia_torque_of_rounding_is_zero_and_its_force_acts_through_g():
    """The shaper's crank and slotted lever at 90°: α = 0 but for rounding (T_i ~ 1e-21 N·m)."""
    text = _text_at("shaper_six_bar", 90)
    assert re.search(r"link 2: F_i = 0\.7018 N ∠ 90\.00° +T_i = 0 N·m +h = 0 mm", text), text
    assert "its inertia force F2i = −m2·a_G2 = 0.7018 N ∠ " in text
    readings = next(line for line in text.splitlines() if "Sub-problem II gives" in line)
    assert "G23″ = 0 N" in readings and not re.search(r"\de-\d", readings), readings  # 6.4e-21 N was printed


def test_a_sub_problem_whose_loads_reach_the_crank_only_as_rounding_reads_zero():
    """The shaper at 90°: sub-problem III (the lever's own loads) leaves the crank nothing but 3.7e-17 N."""
    text = _text_at("shaper_six_bar", 90)
    lines = [line for line in text.splitlines() if "sub-problem III" in line and "link 1" in line or
             "The crank in sub-problem III" in line]
    assert any("R1‴ = 0 N." in line for line in lines), lines
    assert any("R1‴ is rounding, so F01‴ = 0 and T01‴ = 0 N·m" in line for line in lines), lines
    assert not any(re.search(r"\de-\d", line) for line in lines), lines
    # What was computed stays in the construction, and the sub-problems still add up to the whole.
    p = catalog.load("shaper_six_bar")
    c = report.constructions(p.solve(at=[math.pi / 2]))[0]
    third = next(sp for sp in c.subproblems if sp.label == "III")
    assert abs(third.effort) < 1e-15
    assert sum(sp.effort for sp in c.subproblems) == pytest.approx(c.effort, rel=1e-12)
    # Nor is a line drawn for R1‴ or F01‴: its direction would be the rounding's (it was drawn straight down).
    drawn = [ln.name for s in c.steps if s.sub == "III" for ln in s.lines]
    assert "R1‴" not in drawn and "F01‴" not in drawn, drawn
    assert "R1″" in [ln.name for s in c.steps if s.sub == "II" for ln in s.lines]  # one that is there is drawn
