"""A design as the answer (graphkin.exercises.designs): the key is the study's choice for the student's own data,
graded to one step of the grid, with its slips and whether a wrong design meets the limits; a [design] table at
fault is named by its field."""

from __future__ import annotations

import json

import numpy as np
import pytest

import graphkin as gk
from graphkin import exercises
from graphkin.errors import ProblemFileError
from graphkin.exercises.grading import grade_question
from graphkin.exercises.keys import Keys, keys_text, make_keys

NAME = "counterweight_design"


def _grade(student, answer):
    return exercises.grade(NAME, student, {"B": answer})["questions"][0]


def _study_of(student):
    """The student's engine studied over the exercise's grid, by gk.study directly."""
    v = exercises.variant(NAME, student)
    data = dict(v.exercise.base)
    data["driver"] = dict(data["driver"], omega=next(g.value for g in v.data if g.symbol == "N"))
    data["links"] = [dict(link) for link in data["links"]]
    data["links"][2]["mass"] = next(g.value for g in v.data if g.symbol == "m_R")
    return gk.study(data, {"links[0].mass": list(v.exercise.design.values)}, n=360)


def test_the_key_is_the_lightest_design_of_the_grid_that_meets_the_limit():
    s = _study_of("s002")
    peaks = np.array([d.shaking_force_peak for d in s.designs])
    grid = np.array(exercises.load(NAME).design.si)
    key = exercises.key(NAME, "s002")["questions"][0]["answer"]["si"]
    assert key == grid[np.flatnonzero(peaks <= 1500)[0]]
    assert peaks[grid == key][0] <= 1500 < peaks[grid < key].min()


def test_the_slack_is_one_step_of_the_grid_and_the_sheet_says_so():
    v = exercises.variant(NAME, "s001")
    q = v.exercise.questions[0]
    e = v.expected(q)
    assert e.slack == pytest.approx(0.01, abs=1e-12)
    assert v.sheet()["questions"][0]["within"] == "one step of the grid (0.01 kg)"
    key = e.value
    assert _grade("s001", f"{key + 0.01:.2f} kg")["verdict"] == "correct"
    assert _grade("s001", f"{(key - 0.01) * 1000:.0f} g")["verdict"] == "correct"
    assert _grade("s001", f"{key + 0.025:.3f} kg")["verdict"] == "wrong"


def test_the_slips_of_a_design_are_named_and_earn_their_share():
    v = exercises.variant(NAME, "s003")
    q = v.exercise.questions[0]
    best_balanced = v.slip_value(q, "best_for_limit")
    assert best_balanced > v.expected(q).value + 0.05
    r = _grade("s003", f"{best_balanced:.2f} kg")
    assert (r["slip"], r["score"]) == ("best_for_limit", 0.25)
    assert "best for the limit" in r["feedback"]
    r = _grade("s003", "0 kg")  # no counterweight: the cheapest design with the limit left out
    assert (r["slip"], r["score"]) == ("unconstrained", 0.25)
    assert "does not meet the peak shaking force ≤ 1500 N" in r["feedback"]


def test_a_wrong_design_is_told_whether_it_meets_the_limit_where_the_feedback_says_how_far_off():
    v = exercises.variant(NAME, "s001")
    q = v.exercise.questions[0]
    key = v.expected(q).value
    s = _study_of("s001")
    grid = np.array(v.exercise.design.si)
    peaks = np.array([d.shaking_force_peak for d in s.designs])
    lighter, heavier = key - 0.05, key + 0.05
    assert peaks[np.isclose(grid, lighter)][0] > 1500 >= peaks[np.isclose(grid, heavier)][0]
    low, high = (grade_question(v, q, f"{x:.2f} kg", feedback="distance") for x in (lighter, heavier))
    assert "that design does not meet the peak shaking force ≤ 1500 N (yours is" in low["feedback"]
    assert "that design meets the peak shaking force ≤ 1500 N, but it is not the one of least counterweight B that " \
           "does (yours is" in high["feedback"]
    assert low["score"] == high["score"] == 0.0
    # By default ("parts") it is not said: "meets" and "does not meet" part at the key, so a search would bisect on it.
    for x in (lighter, heavier):
        r = grade_question(v, q, f"{x:.2f} kg")
        assert "that design" not in r["feedback"] and f"{key:.2f}" not in r["feedback"]


def test_keys_carry_the_design_and_grade_as_live(tmp_path):
    ex = exercises.load(NAME)
    keys = Keys(json.loads(keys_text(make_keys(ex, ["s001", "s002"], "term"))))
    for s in ("s001", "s002"):
        v = exercises.variant(ex, s, "term")
        key = v.expected(ex.questions[0]).value
        for answer in (f"{key:.2f} kg", "0 kg", f"{key - 0.05:.2f} kg", f"{key + 0.05:.2f} kg"):
            assert keys.grade(s, {"B": answer}) == exercises.grade(ex, s, {"B": answer}, "term", classmates=["s001", "s002"])


STRIP = """
title = "Choosing the strip cutter's speed"
problem = "strip_cutter"
positions = 90
[vary.m3]
field = "links[1].mass"
values = ["1 kg", "2 kg"]
[design]
field = "driver.omega"
label = "crank speed"
from = "600 rpm"
to = "1200 rpm"
step = "50 rpm"
minimise = "I_s"
require = ["torque_peak <= 350 N*m"]
[flywheel]
Cs = 0.05
[[questions]]
id = "N"
find = "design"
ask = "N, the crank speed of least flywheel within 350 N·m"
"""


def test_a_design_that_minimises_a_figure_of_merit_is_the_studys_best(tmp_path):
    (tmp_path / "speed.toml").write_text(STRIP, encoding="utf-8")
    ex = exercises.load_exercise(tmp_path / "speed.toml")
    assert ex.questions[0].kind == "design_angular_velocity" and ex.questions[0].unit == "rpm"
    for student in ("a", "b", "c"):
        v = exercises.variant(ex, student)
        mass = v.data[0].value
        s = gk.study("strip_cutter", {"links[1].mass": [mass], "driver.omega": list(ex.design.values)}, n=90, Cs=0.05)
        best = s.designs[s.best("I_s", ["torque_peak <= 350 N*m"]).index]
        rpm = float(best.values[1].split()[0])
        assert v.expected(ex.questions[0]).value == pytest.approx(rpm * np.pi / 30, rel=1e-12)
        assert v.key()["questions"][0]["answer"]["text"] == f"{rpm:g} rpm"


@pytest.mark.parametrize("change, field", [
    (('require = ["torque_peak <= 350 N*m"]', 'require = ["torque_peek <= 350 N*m"]'), "design.require[0]"),
    (('require = ["torque_peak <= 350 N*m"]', 'require = ["torque_peak <= 350 N"]'), "design.require[0]"),
    (('require = ["torque_peak <= 350 N*m"]', "require = []"), "design.require"),
    (('minimise = "I_s"', 'minimise = "cost"'), "design.minimise"),
    (('field = "driver.omega"', 'field = "driver.omegaa"'), "design"),
    (('field = "driver.omega"', 'field = "drive.omega"'), "design.field"),
    (('label = "crank speed"', 'label = "crank speed"\ncolour = "red"'), "design.colour"),
    (('find = "design"', 'find = "T12"'), "design"),
    (('from = "600 rpm"', 'from = "600 kg"'), "design"),
])
def test_a_design_table_at_fault_is_named(tmp_path, change, field):
    (tmp_path / "bad.toml").write_text(STRIP.replace(*change), encoding="utf-8")
    with pytest.raises(ProblemFileError) as info:
        exercises.load_exercise(tmp_path / "bad.toml")
    assert info.value.field == field, str(info.value)


def test_a_design_question_needs_a_design_table(tmp_path):
    bad = STRIP.split("[design]")[0] + STRIP.split("Cs = 0.05")[1]
    (tmp_path / "bad.toml").write_text(bad.replace("[vary.m3]", "[flywheel]\nCs = 0.05\n[vary.m3]"), encoding="utf-8")
    with pytest.raises(ProblemFileError, match="'design' names nothing this problem has"):
        exercises.load_exercise(tmp_path / "bad.toml")
