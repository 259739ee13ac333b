"""Precomputed keys grade exactly as the live variants do, and carry no secret."""

from __future__ import annotations

import json
import math

import pytest

from graphkin import catalog, exercises
from graphkin.errors import GraphkinError
from graphkin.exercises.keys import Keys, keys_text, make_keys
from graphkin.exercises.quantities import format_value, value_of

SECRET = "keys-test-secret-91c"
STUDENTS = ["s001", "s002", "s003", "s004"]


def answer_sets(v):
    """Right answers, each re-solved slip, sign slips, a power of ten, and plain wrong ones, as typed text."""
    ex = v.exercise
    sets = [{q.id: v.expected(q).text for q in ex.questions}]
    for slip in ("rpm_as_rad_s", "no_inertia_torque", "no_inertia_force"):
        row = {}
        for q in ex.questions:
            x = v.slip_value(q, slip)
            if x is not None:
                e = v.expected(q)
                row[q.id] = format_value(e.form, x, q.unit, _dim(q), torque=False)
        sets.append(row)
    sets.append({q.id: ("−" + t[1:] if not t.startswith("−") else t[1:]) for q, t in
                 ((q, v.expected(q).text) for q in ex.questions)})
    sets.append({q.id: "1" for q in ex.questions})
    sets.append({q.id: "1,352" for q in ex.questions})
    return sets


def _dim(q):
    from graphkin.exercises.exercise import dimension_of

    return dimension_of(q.kind, q.part)


@pytest.mark.parametrize("name", exercises.names())
def test_keys_grade_as_the_live_variants_do(name):
    ex = exercises.load(name)
    keys = Keys(json.loads(keys_text(make_keys(ex, STUDENTS, SECRET))))  # through JSON, as on a platform
    assert keys.roster == STUDENTS
    for s in STUDENTS:
        v = exercises.variant(ex, s, SECRET)
        assert keys.variant(s).sheet() == v.sheet()
        for answers in answer_sets(v):
            live = exercises.grade(ex, s, answers, SECRET, classmates=STUDENTS)
            assert keys.grade(s, answers) == live, (s, answers)


def test_a_teachers_own_exercise_and_problem_file(tmp_path):
    problem = tmp_path / "my_link.toml"
    problem.write_text(catalog.path("single_link").read_text(encoding="utf-8"), encoding="utf-8")
    text = exercises.path("single_link").read_text(encoding="utf-8").replace('problem = "single_link"',
                                                                            'problem = "my_link.toml"')
    (tmp_path / "mine.toml").write_text(text, encoding="utf-8")
    ex = exercises.load_exercise(tmp_path / "mine.toml")
    data = make_keys(ex, STUDENTS, SECRET)
    assert data["exercise"]["problem_text"] == problem.read_text(encoding="utf-8")
    keys = Keys(data)
    for s in STUDENTS:
        v = exercises.variant(ex, s, SECRET)
        for answers in answer_sets(v):
            assert keys.grade(s, answers) == exercises.grade(ex, s, answers, SECRET, classmates=STUDENTS)


def test_keys_hold_no_secret_and_refuse_a_student_off_the_roster(tmp_path):
    ex = exercises.load("strip_cutter_cut")
    text = keys_text(make_keys(ex, STUDENTS, SECRET))
    assert SECRET not in text
    (tmp_path / "k.json").write_text(text, encoding="utf-8")
    keys = Keys(tmp_path / "k.json")
    with pytest.raises(GraphkinError, match="'s999' is not on this assignment's roster"):
        keys.variant("s999")
    # Ids are normalised as the variants normalise them.
    assert keys.variant(" s001 ").student == "s001"
    for x in _numbers(json.loads(text)):
        assert math.isfinite(x)


def test_keys_without_a_roster_need_no_secret_and_refuse_one():
    ex = exercises.load("single_link")
    with pytest.raises(GraphkinError, match="would need the course secret"):
        make_keys(ex, None, SECRET)
    keys = Keys(make_keys(ex, None, ""))
    assert keys.roster is None and keys.classmates() is None
    answers = {"T12": "1 N*m"}
    assert keys.grade("anyone", answers) == exercises.grade(ex, "anyone", answers)


def test_keys_of_another_format_are_refused(tmp_path):
    with pytest.raises(GraphkinError, match="not graphkin keys"):
        Keys({"format": "something else"})
    (tmp_path / "bad.json").write_text("{", encoding="utf-8")
    with pytest.raises(GraphkinError, match="bad.json: not JSON"):
        Keys(tmp_path / "bad.json")
    with pytest.raises(GraphkinError, match="cannot be read"):
        Keys(tmp_path / "absent.json")


def test_a_classmates_answer_is_named_and_earns_nothing():
    ex = exercises.load("strip_cutter_cut")
    keys = Keys(make_keys(ex, STUDENTS, SECRET))
    theirs = {q["id"]: q["answer"]["text"] for q in exercises.key(ex, "s002", SECRET)["questions"]}
    report = keys.grade("s001", theirs)
    assert report["score"] == 0
    for q in report["questions"]:
        assert (q["verdict"], q["slip"], q["other"]) == ("wrong", "other_data", "s002")
        assert "another student's data" in q["feedback"] and "s002" not in q["feedback"]


def _numbers(node):
    if isinstance(node, float):
        yield node
    elif isinstance(node, dict):
        for v in node.values():
            yield from _numbers(v)
    elif isinstance(node, list):
        for v in node:
            yield from _numbers(v)


def test_value_of_is_what_the_keys_carry():
    ex = exercises.load("double_slider_forces")
    data = make_keys(ex, ["s001"], SECRET)
    v = exercises.variant(ex, "s001", SECRET)
    for q in ex.questions:
        stored = data["students"]["s001"]["questions"][q.id]["value"]
        value = value_of(v.solved, q)
        assert stored == ([value.real, value.imag] if isinstance(value, complex) else value)


def test_keys_file_is_plain_json_text():
    text = keys_text(make_keys(exercises.load("single_link"), ["a"], ""))
    assert text.endswith("\n") and "NaN" not in text and "Infinity" not in text
    assert json.loads(text)["format"] == "graphkin-keys-1"
