"""``--units`` on the commands that print a report: text in the chosen units, JSON converted field by field."""

from __future__ import annotations

import json
import math

import pytest

from graphkin.cli import main
from graphkin.units.systems import unit_system

US = unit_system("US")


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    assert code == 0, err
    return out


def test_json_stays_si_without_units(capsys):
    plain = json.loads(run(capsys, "solve", "engine_inch_bevan", "--json"))
    assert plain["units"]["force"] == "N" and "system" not in plain["units"]


@pytest.mark.parametrize("name", ["engine_double_acting_khurmi", "double_slider", "epicyclic_khurmi"])
def test_solve_json_in_us_is_si_json_converted_field_by_field(capsys, name):
    si = json.loads(run(capsys, "solve", name, "--json"))
    us = json.loads(run(capsys, "solve", name, "--json", "--units", "US"))
    assert us["units"]["system"] == "US"
    for a, b in zip(si["positions"], us["positions"]):
        assert a["valid"] == b["valid"]
        if not a["valid"]:
            continue
        for force in a["forces"]:
            for x, y in zip(a["forces"][force], b["forces"][force]):
                assert US.si(y, "force") == pytest.approx(x, rel=1e-14, abs=1e-300)
        kind = "torque" if si["driver"]["kind"] == "crank" else "force"
        assert US.si(b["driver"]["value"], kind) == pytest.approx(a["driver"]["value"], rel=1e-14)
        for link, s in a["links"].items():
            t = b["links"][link]
            assert t["theta"] == pytest.approx(math.degrees(s["theta"]), rel=1e-14, abs=1e-12)
            assert US.si(t["omega"], "angular_velocity") == pytest.approx(s["omega"], rel=1e-14, abs=1e-300)
            assert [US.si(c, "length") for c in t["G"]] == pytest.approx(s["G"], rel=1e-14, abs=1e-300)
        assert b["graphical"]["forces"].keys() == a["graphical"]["forces"].keys()
        # What the table does not list keeps its SI value, and says so.
        assert b["graphical"]["steps"] == a["graphical"]["steps"]
    assert us["units"]["positions[].graphical.steps"].startswith("SI")


def test_solve_units_si_states_every_fields_unit(capsys):
    data = json.loads(run(capsys, "solve", "double_slider", "--json", "--units", "SI"))
    assert data["units"]["positions[].forces.*"] == "N"
    assert data["units"]["positions[].input.value"] == "mm"  # a slider's position, as the text prints it
    assert data["units"]["positions[].links.*.theta"] == "deg"


def test_solve_text_in_us(capsys):
    out = run(capsys, "solve", "engine_double_acting_khurmi", "--units", "US")
    assert " lbf ∠ " in out and " lbf·ft" in out and "rpm" in out
    assert " N ∠ " not in out.split("Graphical route")[0]  # the answers; the construction's captions stay in SI
    assert "(the construction is drawn in N and mm: its steps and its scale are in SI)" in out


def test_cycle_in_us(capsys):
    si = json.loads(run(capsys, "cycle", "slider_crank_dynamic_makdin", "--n", "36", "--cs", "0.05", "--json"))
    us = json.loads(run(capsys, "cycle", "slider_crank_dynamic_makdin", "--n", "36", "--cs", "0.05", "--json",
                        "--units", "US"))
    assert us["units"]["effort.values"] == "lbf*ft" and us["units"]["power.values"] == "hp"
    assert US.si(us["effort"]["max"]["value"], "torque") == pytest.approx(si["effort"]["max"]["value"], rel=1e-14)
    assert us["effort"]["max"]["at"] == pytest.approx(math.degrees(si["effort"]["max"]["at"]), rel=1e-14)
    assert US.si(us["flywheel"]["I_s"], "moment_of_inertia") == pytest.approx(si["flywheel"]["I_s"], rel=1e-14)
    text = run(capsys, "cycle", "slider_crank_dynamic_makdin", "--n", "36", "--cs", "0.05", "--units", "US")
    peak = US.show(si["effort"]["max"]["value"], "torque")
    assert f"peak     {peak:.6g} lbf·ft at θ12 = " in text
    assert "ft·lbf (largest energy swing)" in text and " lb·ft² (system inertia" in text


def test_flywheel_in_us(capsys):
    si = json.loads(run(capsys, "flywheel", "three_cylinder", "--json"))
    us = json.loads(run(capsys, "flywheel", "three_cylinder", "--json", "--units", "US"))
    assert us["omega_avg"] == pytest.approx(si["omega_avg"] * 30 / math.pi, rel=1e-14)  # rpm
    assert US.si(us["E"], "energy") == pytest.approx(si["E"], rel=1e-14)
    assert us["units"]["table[].area"] == "ft*lbf"
    text = run(capsys, "flywheel", "three_cylinder", "--units", "US")
    assert f"E = largest accumulated − smallest (0 included) = {US.show(si['E'], 'energy'):.6g} ft·lbf" in text


def test_handout_in_us_shows_lbf(capsys, tmp_path):
    path = tmp_path / "bevan.md"
    assert main(["handout", "engine_inch_bevan", "--units", "US", "-o", str(path)]) == 0
    text = path.read_text(encoding="utf-8")
    answers = text.split("Answers")[-1]
    assert answers.count(r"\text{lbf}") >= 8 and r"\text{lbf·ft}" in answers
    assert r"\text{N}" not in answers
    assert "Answers are in US units (lbf, lbf·ft, in)" in text
    si = tmp_path / "bevan_si.md"
    assert main(["handout", "engine_inch_bevan", "-o", str(si)]) == 0
    assert r"\text{lbf}" not in si.read_text(encoding="utf-8")
