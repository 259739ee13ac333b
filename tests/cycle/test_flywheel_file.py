"""Flywheels from a turning-moment diagram alone (issue 13, item 5): ``size_flywheel`` with a driving and a
resisting torque, both directions (I from C_s, C_s from I), the extremes of speed and acceleration, the energy
table, the flywheel file format, ``graphkin flywheel`` and its bad input."""

from __future__ import annotations

import json
import math
import os

import numpy as np
import pytest

from graphkin.cli import main
from graphkin.cycle import size_flywheel
from graphkin.cycle.flywheel_file import load_flywheel, parse_flywheel
from graphkin.errors import GraphkinError

TURN = 2 * math.pi


# -- size_flywheel ------------------------------------------------------------------------------------------------


def test_a_varying_resistance_is_not_the_mean():
    """Engine T_d = T0 + A sin θ against a load T_r = T0 − A sin θ: the net torque swings by 2A, so E = 4A.

    Passed alone (the resistance taken as its mean) the engine torque gives E = 2A, half the right swing:
    the silent error of issue 13. With the resisting curve given, E is right.
    """
    theta = np.linspace(0, TURN, 3600, endpoint=False)
    T0, A = 50.0, 20.0
    engine, load = T0 + A * np.sin(theta), T0 - A * np.sin(theta)
    alone = size_flywheel(theta, driving=engine, omega_avg=100.0, Cs=0.02)
    both = size_flywheel(theta, driving=engine, resisting=load, omega_avg=100.0, Cs=0.02)
    assert alone.E == pytest.approx(2 * A, rel=1e-6)
    assert both.E == pytest.approx(4 * A, rel=1e-6)
    assert both.I_s == pytest.approx(4 * A / (0.02 * 100.0**2), rel=1e-6)
    np.testing.assert_allclose(both.resisting, load)
    np.testing.assert_allclose(both.driving, engine)


def test_both_directions_agree():
    """I from C_s, then C_s from that I: the same C_s; and ω swings by exactly C_s ω_avg."""
    theta = np.linspace(0, TURN, 720, endpoint=False)
    T = 100 + 60 * np.sin(2 * theta) + 25 * np.cos(3 * theta)
    f = size_flywheel(theta, driving=T, omega_avg=150.0, Cs=0.03)
    g = size_flywheel(theta, driving=T, omega_avg=150.0, I=f.I_s)
    assert g.Cs == pytest.approx(0.03, rel=1e-12) and g.E == pytest.approx(f.E, rel=1e-12)
    w = g.speed()
    assert w.max() - w.min() == pytest.approx(0.03 * 150.0, rel=1e-3)
    sp = g.speed_extremes()
    assert sp.omega_max == pytest.approx(150.0 * 1.015) and sp.omega_min == pytest.approx(150.0 * 0.985)


def test_where_the_speed_and_the_acceleration_peak():
    """T_d = T0 + A sin θ against a constant T0: the shaft gains energy from 0 to π, so it is slowest at 0 and
    fastest at π; α = A sin θ / I is largest at 90° and smallest at 270°."""
    theta = np.radians(np.arange(0.0, 360.0, 1.0))
    T0, A = 10.0, 5.0
    f = size_flywheel(theta, driving=T0 + A * np.sin(theta), resisting=T0, omega_avg=100.0, Cs=0.05)
    sp = f.speed_extremes()
    assert math.degrees(sp.at_max) == pytest.approx(180.0, abs=1e-9)
    assert math.degrees(sp.at_min) == pytest.approx(0.0, abs=1e-9)
    hi, lo = f.acceleration_extremes()
    assert math.degrees(hi.at) == pytest.approx(90.0) and math.degrees(lo.at) == pytest.approx(270.0)
    assert hi.value == pytest.approx(A / f.I_s, rel=1e-12) and lo.value == pytest.approx(-A / f.I_s, rel=1e-12)
    # The legacy form (a machine's demand, driven at its mean) puts the extremes the other way round.
    m = size_flywheel(theta, T0 + A * np.sin(theta), omega_avg=100.0, Cs=0.05)
    assert math.degrees(m.speed_extremes().at_min) == pytest.approx(180.0, abs=1e-9)


def test_a_crossing_at_zero_is_reported_at_zero():
    """The crossing on the step that closes the turn, landing on θ = 0 itself, is 0°, not 360° (issue 13)."""
    theta = np.radians(np.arange(0.0, 360.0, 2.0))
    f = size_flywheel(theta, 10 + 5 * np.sin(theta), omega_avg=100.0, Cs=0.05)
    assert f.crossings[0] == 0.0 and np.all(f.crossings < TURN)
    rows = f.table()
    assert rows[0].start == 0.0 and rows[-1].end == pytest.approx(TURN)
    assert sum(r.area for r in rows) == pytest.approx(0.0, abs=1e-9)


def test_period_of_a_four_stroke_cycle():
    """One cylinder of a four-stroke engine repeats every 720°: sized over 4π, its energy swing is that of
    the whole cycle."""
    theta = np.linspace(0, 2 * TURN, 1440, endpoint=False)
    T = 40 + 100 * np.sin(theta / 2)
    f = size_flywheel(theta, driving=T, omega_avg=200.0, Cs=0.01, period=2 * TURN)
    assert f.T_avg == pytest.approx(40.0, rel=1e-9)
    assert f.E == pytest.approx(2 * 100 * 2, rel=1e-5)  # ∫ 100 sin(θ/2) dθ over 0…2π = 400
    with pytest.raises(GraphkinError, match="720"):
        size_flywheel(theta[:700], T[:700], omega_avg=200.0, Cs=0.01, period=2 * TURN)


@pytest.mark.parametrize("kwargs, match", [
    ({"driving": "mean", "resisting": "mean"}, "both"),
    ({"driving": "average"}, "mean"),
    ({"driving": np.ones(10)}, "same length"),
    ({"driving": 50 + np.sin(np.linspace(0, TURN, 360, endpoint=False)), "resisting": 60.0}, "steady state"),
    ({"T": np.ones(360), "driving": np.ones(360)}, "not both"),
    ({"driving": np.ones(360), "I": 1.0}, "exactly one"),
    ({"driving": np.ones(360), "Cs": None}, "exactly one"),
    ({"driving": np.r_[np.ones(359), np.nan]}, "not finite"),
])
def test_size_flywheel_refuses(kwargs, match):
    theta = np.linspace(0, TURN, 360, endpoint=False)
    args = {"omega_avg": 100.0, "Cs": 0.05, **kwargs}  # Cs=None with no I: neither is given
    with pytest.raises(GraphkinError, match=match):
        size_flywheel(theta, **args)


def test_a_given_inertia_too_small_to_keep_the_shaft_turning():
    theta = np.linspace(0, TURN, 360, endpoint=False)
    with pytest.raises(GraphkinError, match="too small"):
        size_flywheel(theta, driving=100 + 90 * np.sin(theta), omega_avg=1.0, I=1e-3)


# -- flywheel files -----------------------------------------------------------------------------------------------

ONE_CYLINDER = """# one cylinder of a four-stroke engine (numbers ours, a test shape)
angle [deg], torque [N*m]
0, 0
30, 300
60, 200
90, 120
120, 60
150, 20
180, 0
210, -60
240, -40
270, -20
300, -10
330, -5
360, 0
390, -20
420, -40
450, -60
480, -40
510, -10
540, 0
570, 10
600, 30
630, 20
660, 10
690, 5
720, 0
"""

ENGINE = """title = "Four-cylinder four-stroke engine (a test shape)"
[flywheel]
omega_avg = "3000 rpm"
Cs = 0.01
period = "720 deg"
[driving]
csv = "cylinder.csv"
cylinders = 4
"""


@pytest.fixture
def engine(tmp_path):
    (tmp_path / "cylinder.csv").write_text(ONE_CYLINDER, encoding="utf-8")
    path = tmp_path / "engine.toml"
    path.write_text(ENGINE, encoding="utf-8")
    return path


def test_multi_cylinder_engine_is_the_sum_of_shifted_cylinders(engine):
    p = load_flywheel(engine)
    rows = np.loadtxt(engine.with_name("cylinder.csv"), delimiter=",", comments="#", skiprows=2)
    a, T = np.radians(rows[:-1, 0]), rows[:-1, 1]
    expected = sum(np.interp(p.theta - k * math.pi, a, T, period=2 * TURN) for k in range(4))
    np.testing.assert_allclose(p.driving, expected, atol=1e-9)
    f = p.size()
    # Four firings per cycle, all alike: the energy table repeats every 180°.
    assert len(f.crossings) % 4 == 0
    np.testing.assert_allclose(f.areas[: len(f.areas) // 4], f.areas[len(f.areas) // 4: len(f.areas) // 2], rtol=1e-9)
    assert f.T_avg == pytest.approx(4 * np.trapezoid(np.r_[T, T[0]], np.r_[a, 4 * math.pi]) / (4 * math.pi), rel=1e-12)
    # An inline table gives the same as the CSV beside the file.
    inline = ENGINE.replace('csv = "cylinder.csv"', f'table = """\n{ONE_CYLINDER}"""')
    q = parse_flywheel(inline, file="inline.toml")
    assert q.size().E == pytest.approx(f.E, rel=1e-12)


def test_cli_reports_the_table_and_the_extremes(engine, capsys):
    assert main(["flywheel", str(engine)]) == 0
    out = capsys.readouterr().out
    for text in ("Energy table", "Table 11-1", "I_s = E / (C_s ω_avg²)", "ω_max", "ω_min", "α = (T_d − T_r)/I_s",
                 "4 cylinders fired 180° apart"):
        assert text in out, text
    assert main(["flywheel", str(engine), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    f = load_flywheel(engine).size()
    assert data["E"] == pytest.approx(f.E) and data["I_s"] == pytest.approx(f.I_s)
    assert data["given"] == "Cs" and len(data["table"]) == len(f.crossings)
    assert all(0 <= row["from"] < data["period"] for row in data["table"])


def test_a_given_inertia_finds_the_fluctuation(engine, capsys):
    f = load_flywheel(engine).size()
    engine.write_text(ENGINE.replace("Cs = 0.01", f'I = "{f.I_s!r} kg*m^2"'), encoding="utf-8")
    g = load_flywheel(engine).size()
    assert g.Cs == pytest.approx(0.01, rel=1e-12)
    assert main(["flywheel", str(engine)]) == 0
    assert "C_s = E / (I_s ω_avg²) = 0.01" in capsys.readouterr().out


def test_resisting_curve_of_its_own(tmp_path):
    """A resisting table with its own angles: both curves are sampled at every angle of either."""
    text = """[flywheel]
omega_avg = "100 rad/s"
Cs = 0.05
[driving]
table = \"\"\"
angle [deg], torque [N*m]
0, 10
90, 30
180, 10
270, -10
\"\"\"
[resisting]
table = \"\"\"
angle [rad], torque [N*m]
0, 5
3.14159265358979, 15
\"\"\"
"""
    p = parse_flywheel(text, file="r.toml")
    assert len(p.theta) == 4  # 0°, 90°, 180°, 270°: the second table's 0 and π (180°) are among them
    f = p.size()
    assert f.T_avg == pytest.approx(10.0)


# -- bad input: one line, exit 2, the field named --------------------------------------------------------------

P = pytest.param
BAD = [
    P('omega_avg = "3000 rpm"\n', "", ["flywheel.omega_avg", "missing"], id="omega-missing"),
    P('omega_avg = "3000 rpm"', 'omega_avg = "3000"', ["flywheel.omega_avg", "units"], id="omega-no-unit"),
    P('omega_avg = "3000 rpm"', 'omega_avg = "-3000 rpm"', ["flywheel.omega_avg", "> 0"], id="omega-negative"),
    P("Cs = 0.01\n", "", ["flywheel.Cs", "exactly one"], id="neither-cs-nor-i"),
    P("Cs = 0.01\n", 'Cs = 0.01\nI = "1 kg*m^2"\n', ["flywheel.I", "not both"], id="both-cs-and-i"),
    P("Cs = 0.01", "Cs = 2.5", ["flywheel.Cs", "between 0 and 2"], id="cs-too-large"),
    P("Cs = 0.01", 'I = "-1 kg*m^2"', ["flywheel.I"], id="inertia-negative"),
    P("Cs = 0.01", 'I = "1 kg"', ["flywheel.I", "moment of inertia"], id="inertia-wrong-unit"),
    P('period = "720 deg"', 'period = "540 deg"', ["flywheel.period", "720 deg"], id="period-odd"),
    P('period = "720 deg"\n', "", ["driving.csv", "more than one cycle"], id="period-too-short-for-table"),
    P('csv = "cylinder.csv"', 'csv = "nowhere.csv"', ["driving.csv", "no such file"], id="csv-missing"),
    P('csv = "cylinder.csv"', 'csv = "cylinder.txt"', ["driving.csv", ".csv"], id="csv-not-csv"),
    P('csv = "cylinder.csv"', 'csv = "cylinder.csv"\ntorque = "mean"', ["driving", "only one"], id="two-sources"),
    P("cylinders = 4", "cylinders = 0", ["driving.cylinders", "1 to 24"], id="cylinders-zero"),
    P("cylinders = 4", 'cylinders = "4"', ["driving.cylinders", "whole number"], id="cylinders-text"),
    P("cylinders = 4", 'phase = "180 deg"', ["driving.phase", "cylinders"], id="phase-without-cylinders"),
    P('csv = "cylinder.csv"\ncylinders = 4', 'torque = "80 N*m"\ncylinders = 4', ["driving.cylinders", "curve"],
      id="cylinders-on-a-constant"),
    P('csv = "cylinder.csv"\ncylinders = 4', 'torque = "mean"', ["driving", "vary"], id="both-mean"),
    P("cylinders = 4\n", 'cylinders = 4\n\n[resisting]\ntorque = "120 N*m"\n', ["steady state"],
      id="resisting-mean-differs"),
    P("cylinders = 4\n", 'cylinders = 4\n\n[resisting]\ntorque = "120 Nm"\n', ["resisting.torque", "N*m"],
      id="resisting-glued-unit"),
    P("[driving]", "[drivng]", ["drivng", "driving"], id="unknown-table"),
    P("Cs = 0.01", "Cs = 0.01\nomega = 3", ["flywheel.omega", "omega_avg"], id="unknown-field"),
]
CSV_BAD = [
    P("angle [deg], torque [N*m]", "angle, torque", ["driving.csv", "cylinder.csv line 2", "units in brackets"],
      id="csv-header-no-units"),
    P("angle [deg], torque [N*m]", "angle [deg], force [N]", ["driving.csv", "torque"], id="csv-header-wrong-column"),
    P("angle [deg], torque [N*m]", "angle [deg], torque [N]", ["driving.csv", "torque"], id="csv-header-wrong-unit"),
    P("30, 300", "30, 3OO", ["driving.csv", "line 4", "'3OO' is not a number"], id="csv-cell-not-number"),
    P("30, 300", "30, 300, 1", ["driving.csv", "line 4", "3 cells"], id="csv-row-too-long"),
    P("60, 200", "20, 200", ["driving.csv", "increase", "row 3"], id="csv-angles-not-increasing"),
    P("720, 0", "720, 5", ["driving.csv", "720°", "differs"], id="csv-last-row-not-periodic"),
    P("30, 300", "30, inf", ["driving.csv", "finite"], id="csv-infinite"),
    P("30, 300", "30, 1e12", ["driving.csv", "too large"], id="csv-torque-out-of-range"),
]


def _fly(tmp_path, toml=ENGINE, csv=ONE_CYLINDER):
    (tmp_path / "cylinder.csv").write_text(csv, encoding="utf-8")
    path = tmp_path / "engine.toml"
    path.write_text(toml, encoding="utf-8")
    return path


def _one_line(capsys, path, *named):
    before = sorted(os.listdir(path.parent))
    code = main(["flywheel", str(path)])
    out, err = capsys.readouterr()
    assert code == 2 and out == ""
    assert err.startswith("graphkin: error: ") and err.count("\n") == 1 and "Traceback" not in err, err
    for text in (str(path), *named):
        assert text in err, f"{text!r} not in {err!r}"
    assert sorted(os.listdir(path.parent)) == before


@pytest.mark.parametrize("old, new, named", BAD)
def test_bad_flywheel_file(tmp_path, capsys, old, new, named):
    assert old in ENGINE
    _one_line(capsys, _fly(tmp_path, ENGINE.replace(old, new, 1)), *named)


@pytest.mark.parametrize("old, new, named", CSV_BAD)
def test_bad_flywheel_table(tmp_path, capsys, old, new, named):
    assert old in ONE_CYLINDER
    _one_line(capsys, _fly(tmp_path, csv=ONE_CYLINDER.replace(old, new, 1)), *named)


def test_bad_inline_table_names_the_field(tmp_path, capsys):
    toml = ENGINE.replace('csv = "cylinder.csv"', 'table = """\nangle [deg], torque [N*m]\n0, 1\n"""')
    _one_line(capsys, _fly(tmp_path, toml), "driving.table", "1 row", "at least two")


def test_not_a_file(tmp_path, capsys):
    code = main(["flywheel", str(tmp_path / "none.toml")])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "none.toml" in err
