"""Every command's ``--json`` is JSON a strict parser takes: no NaN or Infinity (a number that is not finite is null).

Python's own ``json.loads`` accepts ``NaN`` and ``Infinity``, which JSON does not have; the parser here
refuses them, as a browser's ``JSON.parse`` or a grading platform would.
"""

from __future__ import annotations

import json

import pytest

from graphkin.cli import main


def _strict(text: str):
    def refuse(name):
        raise ValueError(f"{name} is not JSON")

    return json.loads(text, parse_constant=refuse)


def _json_of(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    assert code in (0, 2), err
    return _strict(out)


@pytest.mark.parametrize("argv", [
    ["solve", "double_slider", "--json"],
    ["solve", "strip_cutter", "--at", "0 deg,140 deg", "--json"],  # the cutting force off, then on
    ["solve", "engine_static_khurmi", "--json"],
    ["cycle", "strip_cutter", "--n", "36", "--cs", "0.05", "--json"],
    ["cycle", "double_slider", "--json"],  # a slider: no flywheel, no transmission angle (null)
    ["flywheel", "three_cylinder", "--json"],
    ["exercise", "make", "inertia_resultant", "--student", "s1", "--json"],
    ["exercise", "key", "torque_curve", "--student", "s1", "--json"],
])
def test_every_command_writes_strict_json(capsys, argv):
    data = _json_of(capsys, *argv)
    assert data


def test_a_value_that_is_not_finite_is_null_not_nan(capsys):
    """The joint-force index is undefined (nan) where no load acts: null in the JSON."""
    data = _json_of(capsys, "cycle", "strip_cutter", "--n", "36", "--json")
    values = data["joint_force_index"]["values"]
    assert None in values and all(v is None or isinstance(v, float) for v in values)


def test_a_grade_report_is_strict_json(capsys, tmp_path):
    answers = tmp_path / "answers.json"
    answers.write_text(json.dumps({"F23": "nan N", "T12": "inf N*m"}), encoding="utf-8")
    data = _json_of(capsys, "exercise", "grade", "double_slider_forces", "--student", "s1", "--answers",
                    str(answers), "--json")
    assert {q["id"] for q in data["questions"]} >= {"F23"}


@pytest.mark.parametrize("problem", ["strip_cutter", "double_slider", "shaper_six_bar", "gearset"])
def test_solve_json_with_motion_polygons_carries_the_polygons_of_every_position(capsys, problem):
    data = _json_of(capsys, "solve", problem, "--json", "--motion-polygons")
    for entry in data["positions"]:
        g = entry["graphical_kinematics"]
        assert g["valid"] == entry["valid"]
        if not g["valid"]:
            assert g["reason"]
            continue
        for kind, difference in g["relative_difference"].items():
            assert difference <= 1e-9, kind
        for polygon in ("velocity", "acceleration"):
            vectors = g[f"{polygon}_polygon"]["vectors"]
            assert vectors
            for v in vectors:
                assert g["steps"][v["step"]]["polygon"] == polygon
                assert v["components"] == pytest.approx([v["tip"][0] - v["tail"][0], v["tip"][1] - v["tail"][1]])
        assert g["points"].keys() == entry["links"].keys()
        for link, points in g["points"].items():
            for name, motion in points.items():
                exact = entry["links"][link]["points"][name]
                scale = max(abs(x) for p in entry["links"].values() for q in p["points"].values() for x in q["velocity"])
                assert motion["velocity"] == pytest.approx(exact["velocity"], rel=0, abs=1e-9 * scale)
        assert not g["instant_centres"]["missing"]
        assert all(s["caption"] for s in g["steps"])


def test_solve_json_leaves_the_polygons_to_motion_polygons(capsys):
    """Building every position's polygons made `solve --json` a quarter slower and nearly twice as large (issue
    26's "no slower than today", benchmarks/README.md): without --motion-polygons there are none, and the rest of
    each position is as it was."""
    plain = _json_of(capsys, "solve", "strip_cutter", "--json", "--at", "140 deg")
    full = _json_of(capsys, "solve", "strip_cutter", "--json", "--at", "140 deg", "--motion-polygons")
    assert "graphical_kinematics" not in plain["positions"][0]
    assert full["positions"][0].pop("graphical_kinematics")["valid"]
    assert full == plain


def test_solve_json_with_motion_polygons_carries_every_step_in_full(capsys):
    data = _json_of(capsys, "solve", "shaper_six_bar", "--json", "--motion-polygons")
    g = data["positions"][0]["graphical_kinematics"]
    assert all(s["caption"] for s in g["steps"])
    assert any("Coriolis" in s["caption"] or "a^c_" in s["caption"] for s in g["steps"])
    assert g["instant_centres"]["steps"]
