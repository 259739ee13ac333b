"""Loads that are not constant (issue 13, item 4): tables against the input, senses that follow the motion.

- :class:`graphkin.model.Table`: the straight line between rows, a turn's
  wrap for a crank, jumps, and a clear message for a table that cannot be one;
- problem files: ``table`` inline, ``csv`` beside the file, ``direction``,
  ``sense``; every mistake one line naming the field;
- physics on random linkages of every family whose loads were made tabulated
  and motion-following (hypothesis): every link balances, power balances with
  the new loads' power, and the graphical route equals the analytical one;
- over a cycle: a resistance that opposes the slider's motion does the work
  |F| × the distance travelled, so the average driving torque is that work
  over 2π, to the accuracy of the trapezoidal rule *with* samples either side
  of every reversal (without them the error would be first order).
"""

from __future__ import annotations

import dataclasses
import json
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from graphkin.cli import main
from graphkin.errors import GraphkinError, ModelError
from graphkin.model import SENSES, PointForce, SpringForce, Table
from graphkin.problem import load_problem, parse_problem
from tests.physics import (
    RTOL,
    SETTINGS,
    _solve,
    balance,
    close,
    frictionless,
    graphical_equals_analytical,
    load_value,
    power_terms,
    table_value,
)
from tests.strategies import families

R, L = 0.05, 0.2  # crank and rod of the slider-crank below [m]

SLIDER_CRANK = """
title = "In-line slider-crank"

[frame]
points = { A0 = ["0 mm", "0 mm"] }

[[links]]
number = 2
points = { A0 = ["0 mm", "0 mm"], A = ["50 mm", "0 mm"] }
mass = "1 kg"
k = "20 mm"

[[links]]
number = 3
points = { A = ["0 mm", "0 mm"], B = ["200 mm", "0 mm"] }
mass = "1.5 kg"
G = ["60 mm", "0 mm"]
k = "60 mm"

[[links]]
number = 4
points = { B = ["0 mm", "0 mm"] }
mass = "0.8 kg"

[[joints]]
type = "revolute"
links = [1, 2]
point = "A0"

[[joints]]
type = "revolute"
links = [2, 3]
point = "A"

[[joints]]
type = "revolute"
links = [3, 4]
point = "B"

[[joints]]
type = "prismatic"
slider = 4
guide = 1
point = "B"
through = "A0"
direction = "0 deg"

[driver]
link = 2
theta = { start = "0 deg", stop = "360 deg", step = "10 deg" }
omega = "3000 rpm"
"""

GAS = """
[[loads]]
type = "force"
name = "Fg"
link = 4
point = "B"
direction = "180 deg"
table = \"\"\"
angle [deg], force [N]
0, 8000
30, 5000
90, 1500
180, 0
360, 0
\"\"\"
"""

RESIST = """
[[loads]]
type = "force"
name = "Fr"
link = 4
point = "B"
force = ["-500 N", "0 N"]
sense = "{sense}"
"""


def _problem(extra: str, **fmt):
    return parse_problem(SLIDER_CRANK + extra.format(**fmt) if fmt else SLIDER_CRANK + extra, file="p.toml")


# -- the table itself ----------------------------------------------------------------------------------------
def test_table_is_the_straight_line_between_rows_and_wraps_a_turn():
    t = Table(np.radians([0, 30, 90, 180]), [8000, 5000, 1500, 0])
    q = np.radians([0, 15, 60, 135, 270, 360, 375, -345])
    expected = [8000, 6500, 3250, 750, 4000, 8000, 6500, 6500]   # 180° → 360°: 0 back up to the first row
    np.testing.assert_allclose(t(q), expected, rtol=1e-12)
    np.testing.assert_allclose(t(q), table_value(t, q), rtol=1e-12)


def test_a_repeated_input_is_a_jump():
    t = Table(np.radians([0, 90, 90, 180, 360]), [0, 100, 300, 300, 0])
    assert t.jumps() == [pytest.approx(math.pi / 2)]
    before, at, after = t(np.radians([90 - 1e-7, 90, 90 + 1e-7]))
    assert before == pytest.approx(100, rel=1e-6) and at == 300 and after == pytest.approx(300)


def test_a_full_turn_table_whose_ends_differ_jumps_at_its_start():
    t = Table(np.radians([0, 360]), [0, 100])
    assert t.jumps() == [0.0]


@pytest.mark.parametrize("q, value, periodic, words", [
    ([0, 1], [1], True, "one per row"),
    ([0], [1], True, "at least two rows"),
    ([0, 2, 1], [1, 2, 3], True, "row 3 is below row 2"),
    ([0, 1, 1, 1], [1, 2, 3, 4], True, "three rows"),
    ([0, 7], [1, 2], True, "one turn"),
    ([0, float("nan")], [1, 2], True, "finite"),
])
def test_a_table_that_cannot_be_one_says_why(q, value, periodic, words):
    with pytest.raises(ModelError, match=words):
        Table(q, value, periodic)


def test_a_slider_table_is_not_extended_beyond_its_rows():
    t = Table([0.0, 0.1], [0.0, 10.0], periodic=False)
    assert t(0.05) == pytest.approx(5.0)
    with pytest.raises(ModelError, match="outside its rows"):
        t([0.05, 0.2])


# -- problem files -------------------------------------------------------------------------------------------
def test_inline_table_and_csv_beside_the_file_are_the_same(tmp_path):
    (tmp_path / "gas.csv").write_text("angle [deg], force [kN]\n0, 8\n30, 5\n90, 1.5\n180, 0\n360, 0\n",
                                      encoding="utf-8")
    extra = GAS.split("table =")[0] + 'csv = "gas.csv"\n'
    (tmp_path / "p.toml").write_text(SLIDER_CRANK + extra, encoding="utf-8")
    from_csv = load_problem(tmp_path / "p.toml").solve()
    inline = _problem(GAS).solve()
    np.testing.assert_array_equal(from_csv.effort, inline.effort)
    load = load_problem(tmp_path / "p.toml").mechanism.loads[0]
    assert load.table is not None and load.force == pytest.approx((-1.0, 0.0))


@pytest.mark.parametrize("extra, field, words", [
    (GAS.replace('direction = "180 deg"', 'force = ["-1 N", "0 N"]'), "loads[0].force", "direction"),
    (RESIST.replace('sense = "{sense}"', 'direction = "0 deg"'), "loads[0].direction", "table"),
    (GAS.replace('direction = "180 deg"\n', ""), "loads[0].direction", "is missing"),
    (GAS.replace("table =", 'csv = "x.csv"\ntable ='), "loads[0].csv", "not both"),
    (GAS.replace("angle [deg]", "angle [N]"), "loads[0].table", "angle"),
    (GAS.replace("30, 5000", "30, five"), "loads[0].table", "line 3"),
    (GAS.replace("90, 1500", "20, 1500"), "loads[0].table", "ascend"),
    (RESIST.replace("{sense}", "against"), "loads[0].sense", "opposes motion"),
    (GAS.replace('table = """', 'table = 5\nX = """').split("X =")[0], "loads[0].table", "CSV text"),
])
def test_a_mistake_in_a_load_names_its_field(tmp_path, capsys, extra, field, words):
    path = tmp_path / "p.toml"
    path.write_text(SLIDER_CRANK + extra, encoding="utf-8")
    assert main(["solve", str(path)]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and err.startswith("graphkin: error: "), err
    assert field in err and words in err, err


def test_a_csv_table_needs_a_file(tmp_path, capsys):
    with pytest.raises(GraphkinError, match="loads\\[0\\].csv.*folder"):
        parse_problem(SLIDER_CRANK + GAS.split("table =")[0] + 'csv = "gas.csv"\n', file="p.toml")
    path = tmp_path / "p.toml"
    path.write_text(SLIDER_CRANK + GAS.split("table =")[0] + 'csv = "gas.csv"\n', encoding="utf-8")
    assert main(["solve", str(path)]) == 2
    assert "no such file" in capsys.readouterr().err


def test_a_motion_sense_needs_the_motion():
    text = (SLIDER_CRANK + RESIST.format(sense="opposes motion")).replace('omega = "3000 rpm"', "")
    text = text.replace('title = ', 'analysis = "static"\ntitle = ', 1)
    with pytest.raises(GraphkinError, match="loads\\[0\\].sense.*driver.omega"):
        parse_problem(text, file="p.toml")


# -- what the loads apply, reported ----------------------------------------------------------------------------
def test_the_gas_force_follows_its_table_in_json_and_text(capsys):
    p = _problem(GAS)
    r = p.solve(at=np.radians([15.0, 200.0]))
    from graphkin.report import format_solution, solution

    data = solution(p, r)
    (at15,), (at200,) = (e["loads"] for e in data["positions"])
    assert at15["name"] == "Fg" and at15["force"] == pytest.approx([-6500.0, 0.0]) and at15["acting"]
    assert at200["force"] == [0.0, 0.0] and not at200["acting"]
    text = format_solution(p, r)
    assert "Fg    on link 4 at B: 6500 N ∠ 180.00°" in text and "0 N (not acting here)" in text


def test_a_resistance_opposes_the_slider_on_both_strokes():
    p = _problem(RESIST, sense="opposes motion")
    kin = p.kinematics(np.radians([90.0, 270.0]))
    from graphkin.analytical import applied

    F = applied(kin, p.mechanism.loads[0])
    v = kin.velocity(4, "B")[:, 0]
    assert np.sign(v).tolist() == [-1.0, 1.0]             # the slider comes back at 90°, goes out at 270°
    assert F.real.tolist() == [500.0, -500.0] and not F.imag.any()


# -- physics on random linkages ----------------------------------------------------------------------------------
@st.composite
def varying(draw, family):
    """A case of ``family`` whose loads are made tabulated and/or motion-following."""
    case = draw(families[family])
    mech = case.mechanism
    crank = mech.driver.kind == "crank"
    q = np.asarray(case.q, dtype=float)
    loads = []
    for load in mech.loads:
        if isinstance(load, SpringForce):  # a spring's force follows its length: no table, no sense
            loads.append(load)
            continue
        size = abs(complex(*load.force)) if isinstance(load, PointForce) else abs(load.torque)
        table = None
        if draw(st.booleans()):
            rows = draw(st.integers(2, 6))
            if crank:
                x = np.sort(draw(st.lists(st.floats(0.0, 6.28), min_size=rows, max_size=rows, unique=True)))
            else:
                lo, hi = float(q.min()), float(q.max())
                x = np.linspace(lo - 0.01 - abs(lo) * 0.1, hi + 0.01 + abs(hi) * 0.1, rows)
            x = np.maximum.accumulate(x)
            y = draw(st.lists(st.floats(-2.0, 2.0, allow_subnormal=False), min_size=rows, max_size=rows))
            y = [v if abs(v) > 1e-6 else 0.0 for v in y]  # graphkin refuses loads below its range (1 µN)
            table = Table(x, np.asarray(y) * (size or 1.0), periodic=crank)
        sense = draw(st.sampled_from(SENSES))
        if isinstance(load, PointForce):
            force = load.force if any(load.force) else (1.0, 0.0)
            loads.append(dataclasses.replace(load, force=force, table=table, sense=sense))
        else:
            loads.append(dataclasses.replace(load, torque=1.0 if table is not None else load.torque,
                                             table=table, sense=sense))
    return case._replace(mechanism=dataclasses.replace(mech, loads=tuple(loads)))


FAMILIES_WITH_LOADS = sorted(families)


@pytest.mark.parametrize("family", FAMILIES_WITH_LOADS)
@SETTINGS
@given(data=st.data())
def test_every_link_balances_with_varying_loads(family, data):
    case = data.draw(varying(family))
    kin, r = _solve(case)
    for link in kin.mechanism.moving:
        F, M = balance(kin, r, link)
        scale = 1.0 + max(np.abs(r.force(*k)).max() for k in r.forces)
        for ld in kin.mechanism.loads:
            scale += np.abs(load_value(kin, ld)).max()
        ok, excess = close(F, 0.0, RTOL * scale)
        assert ok, f"link {link} force residual {excess:.3g} N beyond tolerance"


@pytest.mark.parametrize("family", FAMILIES_WITH_LOADS)
@SETTINGS
@given(data=st.data())
def test_power_balances_with_varying_loads(family, data):
    """Input + the varying loads' power (a table's value times the velocity; a resistance's always ≤ 0) = dT/dt."""
    case = data.draw(varying(family))
    mech = frictionless(case.mechanism)
    kin, r = _solve(case, mech)
    P, dT, scale = power_terms(kin, r)
    ok, excess = close(P, dT, RTOL * scale)
    assert ok, f"power balance off by {excess:.3g} W beyond tolerance"
    for ld in mech.loads:
        if ld.sense != "fixed":
            value = load_value(kin, ld)
            p = (np.sum(value * kin.velocity(ld.link, ld.point), axis=-1) if isinstance(ld, PointForce)
                 else value * kin.omega[ld.link])
            assert (p <= 1e-12 * (1 + np.abs(p).max())).all(), "a motion-following load did positive work"


@pytest.mark.parametrize("family", FAMILIES_WITH_LOADS)
@SETTINGS
@given(data=st.data())
def test_graphical_equals_analytical_with_varying_loads(family, data):
    graphical_equals_analytical(data.draw(varying(family)))


# -- over a cycle -------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("sense, strokes", [("opposes motion", 2), ("working stroke", 1)])
def test_a_resistance_does_its_work_over_the_cycle(sense, strokes):
    """500 N against the slider over 2r = 100 mm per stroke: W = 500 N × 0.1 m × strokes, T_avg = W / 2π."""
    from graphkin.cycle import sweep

    p = _problem(RESIST, sense=sense)
    cycle = sweep(p, 360)
    # Both dead centres of an in-line slider-crank (0° and 180°) are where the resistance reverses.
    extra = np.setdiff1d(cycle.q, np.linspace(0, 2 * math.pi, 360, endpoint=False))
    assert len(extra) == 4  # 0° + δ; 180° ∓ δ; 0° − δ, at the end of the turn
    work = 500.0 * 2 * R * strokes
    # Over a whole turn the inertia torques average to zero exactly (kinetic energy is periodic), so the only
    # error is the trapezoidal rule's, second order in the 1° step where the samples straddle each reversal.
    assert cycle.average == pytest.approx(work / (2 * math.pi), rel=2e-4)


def test_cycle_json_carries_the_reversals(capsys, tmp_path):
    path = tmp_path / "p.toml"
    path.write_text(SLIDER_CRANK + RESIST.format(sense="opposes motion"), encoding="utf-8")
    assert main(["cycle", str(path), "--n", "36", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["n"] == 36 + 4
