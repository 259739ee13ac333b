"""``graphkin study``: the JSON and the table equal the study API's numbers; a bad --vary is one line, exit 2."""

import importlib
import json
import math

import numpy as np
import pytest

from graphkin.cli import main
from graphkin.cli.study import vary_values
from graphkin.cycle import study
from graphkin.report import study_data

VARY = ["--vary", "links[0].points.A[0]=60..240 mm:4", "--vary", "links[1].mass=2..4 kg:2"]


def run(capsys, *argv):
    code = main(["study", *argv])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture(scope="module")
def expected():
    mm = np.linspace(60, 240, 4).tolist()
    return study("strip_cutter", {"links[0].points.A[0]": [f"{x!r} mm" for x in mm],
                                  "links[1].mass": ["2.0 kg", "4.0 kg"]}, n=36, Cs=0.02)


def test_json_is_the_study_data(capsys, expected):
    code, out, err = run(capsys, "strip_cutter", *VARY, "--n", "36", "--cs", "0.02", "--json")
    assert code == 0 and err == ""
    got = json.loads(out)
    assert got == json.loads(json.dumps(study_data(expected)).replace("NaN", "null"))
    assert got["vectorised"] is True and got["why_not_vectorised"] is None
    assert [d["ok"] for d in got["designs"]].count(False) > 0  # a 240 mm crank cannot turn
    failed = next(d for d in got["designs"] if not d["ok"])
    assert failed["torque_peak"] is None and "cannot be assembled" in failed["failure"]


def test_the_table_shows_each_design(capsys, expected):
    code, out, err = run(capsys, "strip_cutter", *VARY, "--n", "36", "--cs", "0.02")
    assert code == 0 and err == ""
    table = out.split("\n\n")[1].splitlines()[1:]  # after the title, before the failures: a row per design
    rows = [line.split() for line in table]
    assert len(rows) == len(expected.designs)
    for row, d in zip(rows, expected.designs):
        if d.ok:  # columns: #, the two values (number and unit each), T_peak, T_rms, I_s
            assert math.isclose(float(row[5]), d.torque_peak, rel_tol=1e-5)
            assert math.isclose(float(row[7]), d.I_s, rel_tol=1e-5)
        else:
            assert row[5] == "—"
    assert "cannot be assembled over the whole cycle" in out


@pytest.mark.parametrize(("vary", "words"), [
    ("links[9].mass=1..2 kg:3", "the problem has no links[9]"),
    ("links[1].mass=1..2 m:3", "expected a mass"),
    ("links[1].mas=1..2 kg:3", "unknown field"),
    ("links[1].mass=1..x kg:3", "write it FIELD=FROM..TO UNIT:N"),
    ("links[1].mass=1.2.3..4 kg:3", "is not a range of two numbers"),
    ("links[1].mass=1..2 kg:0", "N = 0"),
    ("links[1].mass=1..2 kg:1", "N = 1 value cannot span"),
    ("links[1].mass=2..2 kg:3", "would all be equal"),
    ("links[1].mass 2 kg", "write it FIELD=FROM..TO UNIT:N"),
])
def test_a_bad_vary_is_one_line_naming_it(capsys, vary, words):
    code, out, err = run(capsys, "strip_cutter", "--vary", "links[0].mass=3..4 kg:2", "--vary", vary, "--n", "36")
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith(f"graphkin: error: --vary {vary!r}: ") and words in err


def test_a_field_varied_twice_is_named(capsys):
    code, _, err = run(capsys, "strip_cutter", "--vary", "links[1].mass=1..2 kg:2", "--vary",
                       "links[1].mass=3..4 kg:2")
    assert code == 2 and "--vary 'links[1].mass=3..4 kg:2': links[1].mass is varied twice" in err


def test_values_are_equally_spaced_in_the_unit_given():
    assert vary_values("links[1].mass = 2..3 kg:3") == ("links[1].mass", ["2.0 kg", "2.5 kg", "3.0 kg"])
    assert vary_values("driver.omega=600..900 rpm:1" .replace("900", "600"))[1] == ["600.0 rpm"]


def test_a_slider_drivers_effort_is_a_force(capsys):
    code, out, _ = run(capsys, "double_slider", "--vary", "links[1].mass=4..6 kg:3", "--json")
    got = json.loads(out)
    assert code == 0 and got["driver"] == "slider" and got["units"]["torque"] == "N"
    efforts = [d["torque_peak"] for d in got["designs"]]
    assert efforts == sorted(efforts) and efforts[0] < efforts[-1]  # a heavier rod takes a larger push
    code, out, _ = run(capsys, "double_slider", "--vary", "links[1].mass=4..6 kg:3")
    assert "F_peak [N]" in out and "T_peak" not in out


def test_csv_is_a_row_per_design_with_units(capsys, expected, tmp_path):
    import csv

    out_file = tmp_path / "study.csv"
    code, out, err = run(capsys, "strip_cutter", *VARY, "--n", "36", "--cs", "0.02", "--csv", str(out_file))
    assert code == 0 and f"table written to {out_file}" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["study.csv"]  # no temporary file left beside it
    rows = list(csv.reader(out_file.read_text(encoding="utf-8").splitlines()))
    head = rows[0]
    assert head[:4] == ["design", "links[0].points.A[0] [mm]", "links[1].mass [kg]", "ok"]
    assert {"torque_peak [N*m]", "I_s [kg*m^2]", "transmission_angle_min [deg]", "F23_peak [N]",
            "failed_at [rad]", "failure"} <= set(head)
    assert len(rows) == 1 + len(expected.designs)
    col = {h: i for i, h in enumerate(head)}
    mm = np.linspace(60, 240, 4)
    for k, (row, d) in enumerate(zip(rows[1:], expected.designs)):
        assert float(row[col["links[0].points.A[0] [mm]"]]) == mm[k // 2]
        assert row[col["ok"]] == str(d.ok)
        if d.ok:
            assert float(row[col["torque_peak [N*m]"]]) == d.torque_peak
            assert float(row[col["transmission_angle_min [deg]"]]) == math.degrees(d.transmission_angle_min)
            assert float(row[col["F23_peak [N]"]]) == d.joint_peaks["F23"]
            assert row[col["failure"]] == row[col["failed_at [rad]"]] == ""
        else:
            assert row[col["torque_peak [N*m]"]] == ""
            assert float(row[col["failed_at [rad]"]]) == d.failed_at and row[col["failure"]] == d.failure


def test_study_rows_are_the_csv(expected):
    from graphkin.report.study import study_csv, study_rows

    data = study_data(expected)
    rows = study_rows(data)
    assert study_csv(data).count("\n") == len(rows) == 1 + len(expected.designs)
    assert [r[0] for r in rows[1:]] == list(range(1, len(expected.designs) + 1))


@pytest.mark.parametrize(("flag", "where", "words"), [
    ("--csv", "{dir}", "is a folder, not a file"),
    ("--csv", "{file}/t.csv", "is a file, not a folder"),
    ("--figure", "{dir}/f.gif", "must end in .png, .svg or .pdf"),
    ("--figure", "{file}/f.png", "is a file, not a folder"),
])
def test_a_bad_destination_is_refused_before_the_solve(capsys, tmp_path, monkeypatch, flag, where, words):
    module = importlib.import_module("graphkin.cycle.studies")

    def no_solve(*a, **k):
        raise AssertionError("solved before the destination was checked")

    monkeypatch.setattr(module, "study", no_solve)
    (tmp_path / "a.txt").write_text("x")
    dest = where.format(dir=tmp_path, file=tmp_path / "a.txt")
    code, out, err = run(capsys, "strip_cutter", *VARY, flag, dest)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert err.startswith(f"graphkin: error: {flag} ") and words in err


def test_best_under_limits_is_printed_marked_and_in_json(capsys, expected):
    limit = "transmission_angle_min >= 45 deg"
    choice = expected.best("torque_rms", [limit])
    assert choice.index is not None
    code, out, _ = run(capsys, "strip_cutter", *VARY, "--n", "36", "--cs", "0.02", "--best", "torque_rms",
                       "--require", limit, "--json")
    assert code == 0
    assert json.loads(out)["best"] == {"minimise": "torque_rms", "require": [limit], "index": choice.index,
                                       "why": None}
    code, out, _ = run(capsys, "strip_cutter", *VARY, "--n", "36", "--cs", "0.02", "--best", "torque_rms",
                       "--require", limit)
    marked = [line.split()[0] for line in out.split("\n\n")[1].splitlines()[1:] if line.split()[0].endswith("*")]
    assert marked == [f"{choice.index + 1}*"]
    d = expected.designs[choice.index]
    assert f"best (*): design {choice.index + 1} " in out and f"least torque_rms = {d.torque_rms:.6g} N·m" in out


@pytest.mark.parametrize(("args", "words"), [
    (["--best", "peak_torque"], "--best 'peak_torque': no such figure of merit; the study has torque_peak"),
    (["--best", "torque_peak", "--require", "mu>40 deg"], "--require 'mu>40 deg': 'mu': no such figure of merit"),
    (["--best", "torque_peak", "--require", "I_s < 2 kg"], "--require 'I_s < 2 kg': expected a moment of inertia"),
    (["--require", "I_s < 2 kg*m^2"], "--require 'I_s < 2 kg*m^2': a limit goes with --best FIGURE"),
    (["--merit", "I_s"], "--merit I_s: goes with --figure FILE"),
])
def test_a_bad_best_or_limit_is_one_line_naming_it(capsys, args, words):
    code, out, err = run(capsys, "strip_cutter", *VARY, "--n", "36", *args)
    assert code == 2 and out == "" and err.count("\n") == 1 and words in err


def test_a_figure_is_written(capsys, tmp_path):
    path = tmp_path / "study.svg"
    code, _, err = run(capsys, "strip_cutter", *VARY, "--n", "36", "--best", "torque_peak", "--figure", str(path))
    assert code == 0 and f"figure written to {path}" in err
    assert path.read_text(encoding="utf-8").lstrip().startswith("<?xml")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["study.svg"]


def test_a_bad_limit_is_told_before_the_grid_is_solved(capsys, monkeypatch):
    module = importlib.import_module("graphkin.cycle.studies")
    solved = []

    def counted(problem, vary, **kw):
        solved.append(math.prod(len(v) for v in vary.values()))
        return study(problem, vary, **kw)

    monkeypatch.setattr(module, "study", counted)
    code, _, err = run(capsys, "strip_cutter", *VARY, "--n", "36", "--best", "torque_peak",
                       "--require", "F23_peak < 2 kg")
    assert code == 2 and "--require 'F23_peak < 2 kg': expected a force" in err
    assert solved == [1]  # one design, not the grid of eight
    code, _, _ = run(capsys, "strip_cutter", *VARY, "--n", "36", "--best", "torque_peak", "--require", "F23_peak < 2 MN")
    assert code == 0 and solved == [1, 1, 8]


def test_a_merit_no_design_has_is_refused_and_nothing_written(capsys, tmp_path):
    table, figure = tmp_path / "t.csv", tmp_path / "f.png"
    code, out, err = run(capsys, "double_slider", "--vary", "links[1].mass=4..6 kg:3", "--csv", str(table),
                         "--figure", str(figure), "--merit", "transmission_angle_min")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "merit 'transmission_angle_min': not defined for any design of double_slider" in err
    assert list(tmp_path.iterdir()) == []
