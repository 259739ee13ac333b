"""``graphkin study FILE`` with the file's ``[study]`` table, ``--units``, ``--optimize`` and ``-o design.toml``.

The command's numbers must be the study API's: the JSON in SI equal to ``study_data``, in other units equal to it
times each unit's factor; the design it writes must be a problem file whose own sweep gives the study's figures
for that design to 1e-12 relative.
"""

import csv
import io
import json
import math
import sys

import pytest

from graphkin.cli import main
from graphkin.cycle import study, sweep
from graphkin.cycle.merit import merit
from graphkin.optional import available
from graphkin.problem import load_problem
from graphkin.report import study_data

REL = 1e-12
LBF = 4.4482216152605  # N in one pound-force
LBF_FT = LBF * 0.3048  # N·m in one pound-force foot


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture(scope="module")
def table_study():
    return study("strip_cutter_study", n=36)


def test_the_files_table_is_used_without_vary(capsys, table_study):
    code, out, err = run(capsys, "study", "strip_cutter_study", "--n", "36", "--json")
    assert code == 0
    got = json.loads(out)
    want = study_data(table_study, table_study.best("torque_peak", ["transmission_angle_min >= 30 deg"]))
    if available("scipy"):  # the table asks for the optimum too: the rest is the same
        assert got.pop("optimum")["objective"] == "torque_peak"
    assert got == json.loads(json.dumps(want).replace("NaN", "null"))
    assert got["fields"] == ["links[0].points.A[0]", "links[1].mass"] and len(got["designs"]) == 28


def test_flags_override_the_table(capsys):
    code, out, _ = run(capsys, "study", "strip_cutter_study", "--vary", "links[1].mass=2 kg, 3 kg", "--n", "36",
                       "--cs", "0.1", "--best", "I_s", "--require", "torque_peak <= 1 MN*m", "--json")
    assert code == 0
    got = json.loads(out)
    assert got["fields"] == ["links[1].mass"] and got["grid"] == [["2 kg", "3 kg"]] and got["Cs"] == 0.1
    assert got["best"]["minimise"] == "I_s" and got["best"]["require"] == ["torque_peak <= 1 MN*m"]
    assert "optimum" not in got or got["optimum"]["require"] == ["torque_peak <= 1 MN*m"]


def test_units_us_converts_the_json_the_table_and_the_csv(capsys, tmp_path):
    args = ["study", "strip_cutter", "--vary", "links[1].mass=2..4 kg:3", "--n", "36", "--best", "torque_peak"]
    _, si, _ = run(capsys, *args, "--json")
    _, us, _ = run(capsys, *args, "--json", "--units", "US")
    si, us = json.loads(si), json.loads(us)
    assert us["units"]["system"] == "US" and us["units"]["designs[].torque_peak"] == "lbf*ft"
    assert us["units"]["designs[].joint_peaks.*"] == "lbf" and us["units"]["designs[].I_s"] == "lb*ft^2"
    for a, b in zip(si["designs"], us["designs"]):
        assert math.isclose(b["torque_peak"], a["torque_peak"] / LBF_FT, rel_tol=1e-9)
        assert math.isclose(b["shaking_force_peak"], a["shaking_force_peak"] / LBF, rel_tol=1e-9)
        assert math.isclose(b["transmission_angle_min"], math.degrees(a["transmission_angle_min"]), rel_tol=1e-9)
        assert all(math.isclose(b["joint_peaks"][j], a["joint_peaks"][j] / LBF, rel_tol=1e-9) for j in a["joint_peaks"])
        assert b["values"] == a["values"]  # the varied fields stay as the file writes them
    code, out, _ = run(capsys, *args, "--units", "US", "--csv", str(tmp_path / "s.csv"))
    assert code == 0 and "T_peak [lbf·ft]" in out and "|F23| peak [lbf]" in out
    assert "least torque_peak = " in out and out.rstrip().endswith("lbf·ft")
    rows = list(csv.reader(io.StringIO((tmp_path / "s.csv").read_text(encoding="utf-8"))))
    head = rows[0]
    assert "torque_peak [lbf*ft]" in head and "F23_peak [lbf]" in head and "failed_at [deg]" in head
    k = head.index("torque_peak [lbf*ft]")
    assert [float(r[k]) for r in rows[1:]] == pytest.approx([d["torque_peak"] for d in us["designs"]], rel=1e-15)


def test_units_si_is_the_default_table(capsys):
    args = ["study", "strip_cutter", "--vary", "links[1].mass=2..4 kg:3", "--n", "36"]
    _, plain, _ = run(capsys, *args)
    _, si, _ = run(capsys, *args, "--units", "SI")
    assert si == plain


def test_the_best_design_written_solves_to_the_studys_numbers(capsys, tmp_path, table_study):
    path = tmp_path / "design.toml"
    code, _, err = run(capsys, "study", "strip_cutter", "--vary", "links[0].points.A[0]=60..120 mm:7",
                       "--vary", "links[1].mass=1..4 kg:4", "--n", "36", "--best", "torque_peak",
                       "--require", "transmission_angle_min >= 30 deg", "-o", str(path))
    assert code == 0 and f"design written to {path}" in err
    index = table_study.best("torque_peak", ["transmission_angle_min >= 30 deg"]).index
    d = table_study.designs[index]
    assert "[study]" not in path.read_text(encoding="utf-8")
    assert math.isclose(merit(sweep(load_problem(path), 36), d.values, 0.05).torque_peak, d.torque_peak,
                        rel_tol=REL, abs_tol=0)
    back = merit(sweep(load_problem(path), 36), d.values, 0.05)
    assert all(math.isclose(back.joint_peaks[j], d.joint_peaks[j], rel_tol=REL, abs_tol=0) for j in d.joint_peaks)
    assert math.isclose(back.I_s, d.I_s, rel_tol=REL, abs_tol=0)
    # The written design is an ordinary problem file for the other commands.
    code, out, _ = run(capsys, "solve", str(path), "--at", "30 deg", "--json")
    assert code == 0 and json.loads(out)["positions"][0]["driver"]["value"] is not None
    code, out, _ = run(capsys, "cycle", str(path), "--n", "36", "--json")
    assert code == 0 and math.isclose(max(abs(x) for x in json.loads(out)["effort"]["values"]), d.torque_peak,
                                      rel_tol=1e-9)


@pytest.mark.skipif(not available("scipy"), reason="scipy (the study extra) is not installed")
def test_the_optimum_is_printed_and_written(capsys, tmp_path):
    path = tmp_path / "optimum.toml"
    code, out, err = run(capsys, "study", "strip_cutter_study", "--n", "36", "--json", "-o", str(path))
    assert code == 0 and f"design written to {path}" in err
    o = json.loads(out)["optimum"]
    grid = json.loads(out)["designs"][o["start"]]["torque_peak"]
    assert o["design"]["torque_peak"] <= grid and isinstance(o["converged"], bool) and o["message"]
    back = merit(sweep(load_problem(path), 36), tuple(o["values"]), 0.05)
    assert math.isclose(back.torque_peak, o["design"]["torque_peak"], rel_tol=REL, abs_tol=0)
    assert math.isclose(back.transmission_angle_min, o["design"]["transmission_angle_min"], rel_tol=REL, abs_tol=0)
    code, out, _ = run(capsys, "study", "strip_cutter_study", "--n", "36", "--optimize", "maximise I_s",
                       "--require", "torque_peak <= 300 N*m")
    assert code == 0 and "optimum (scipy SLSQP" in out and "greatest I_s = " in out


@pytest.mark.parametrize(("args", "words"), [
    (["strip_cutter"], "give the fields to vary"),
    (["strip_cutter", "--vary", "links[1].mass=1..2 kg:2", "-o", "d.toml"], "-o d.toml: writes the chosen design"),
    (["strip_cutter", "--vary", "links[1].mass=1..2 kg:2", "--best", "I_s", "-o", "d.txt"], "ends in .toml"),
    (["strip_cutter", "--vary", "links[1].mass=1..2 kg:2", "--units", "furlongs"], "--units 'furlongs'"),
    (["strip_cutter", "--vary", "links[1].mass=1..2 kg:2", "--require", "I_s <= 1 kg*m^2"],
     "a limit goes with --best FIGURE"),
    (["strip_cutter", "--vary", "links[1].mass=1..2 kg:2", "--optimize", "minimise torque"],
     "--optimize 'minimise torque': no such figure of merit"),
    (["strip_cutter", "--vary", "links[1].mass=heavy", "--n", "36"], "write it FIELD=FROM..TO UNIT:N"),
])
def test_a_bad_option_is_one_line(capsys, tmp_path, monkeypatch, args, words):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, "study", *args)
    assert code == 2 and out == "" and err.count("\n") == 1 and words in err
    assert not any(tmp_path.iterdir())  # nothing written


def test_without_scipy_the_files_optimize_is_skipped_with_a_note(capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "scipy", None)
    monkeypatch.setitem(sys.modules, "scipy.optimize", None)
    code, out, err = run(capsys, "study", "strip_cutter_study", "--n", "36", "--json")
    assert code == 0 and "optimum" not in json.loads(out)
    assert "pip install 'graphkin[study]'" in err
    code, out, err = run(capsys, "study", "strip_cutter_study", "--n", "36", "--optimize", "torque_peak")
    assert code == 2 and out == "" and "needs scipy, which is not installed: pip install 'graphkin[study]'" in err
