"""Drawn answers (issue 38): the right construction is correct, each slip is named, a drawing off by more than the
tolerance is wrong with the element at fault marked, and every platform's reader hands the drawing to the grader.

The targets are the construction's own geometry (graphkin.graphical), so the right drawing here is made from the
targets and moved within the tolerance; a slip's drawing is the slip's target, which each kind makes from the same
construction by the slip's own rule (tested against the geometry in test_drawn_tasks.py)."""

import copy
import json
import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphkin import exercises
from graphkin.exercises.drawn_grading import grade_drawing
from graphkin.exercises.drawn_tasks import right_drawing, task_of
from graphkin.exercises.keys import Keys, make_keys
from graphkin.exercises.notebooks import answer_variables, read_cells
from graphkin.exercises.platforms.gradescope import read_answers

DRAWN = ["draw_strip_cutter", "draw_shaper_polygons"]
CASES = [(name, q.id) for name in DRAWN for q in exercises.load(name).questions]


def drawing_of(v, qid, elements):
    task = task_of(v, qid)
    return {"drawing": 1, "question": qid, "space": task["space"], "unit": task["unit"], "elements": elements}


def moved(element, by, turn=0.0):
    """An element moved by ``by`` (x, y) and, a line, turned by ``turn`` [rad] about its first point."""
    e = copy.deepcopy(element)
    for key in ("through", "at", "from", "to"):
        if key not in e:
            continue
        pts = e[key] if key == "through" else [e[key]]
        for p in pts:
            p[0] += by[0]
            p[1] += by[1]
    if turn and e["kind"] == "line":
        (x1, y1), (x2, y2) = e["through"]
        c, s = math.cos(turn), math.sin(turn)
        e["through"][1] = [x1 + c * (x2 - x1) - s * (y2 - y1), y1 + s * (x2 - x1) + c * (y2 - y1)]
    return e


@pytest.mark.parametrize("name, qid", CASES)
def test_the_right_drawing_and_one_within_the_tolerance_are_correct_each_slip_is_named(name, qid):
    v = exercises.variant(name, "s001")
    check = task_of(v, qid, practice=True)["check"]
    targets, tol = check["targets"], check["tolerance"]
    L = tol["length"]
    right = targets[0]["elements"]
    r = grade_drawing(v, qid, drawing_of(v, qid, right))
    assert (r["verdict"], r["score"], r["fault"]) == ("correct", 1.0, [])
    # Every element moved by 0.6 L (a line also turned by 0.6 of the angle): still within the tolerance.
    near = [moved(e, (0.6 * L / math.sqrt(2), 0.6 * L / math.sqrt(2)), 0.6 * tol["angle"]) for e in right]
    assert grade_drawing(v, qid, json.dumps(drawing_of(v, qid, near)))["verdict"] == "correct"
    partial = v.exercise.partial
    for n, t in enumerate(targets[1:], 1):
        r = grade_drawing(v, qid, drawing_of(v, qid, t["elements"]))
        first = next(i for i, u in enumerate(targets) if u["elements"] == t["elements"] or i == n)
        if first == n:  # an earlier slip's drawing may be the same (the two senses of one vector)
            assert (r["verdict"], r["slip"]) == ("slip", t["slip"]), (qid, t["slip"], r)
            assert r["score"] == pytest.approx(partial[t["slip"]])
            assert r["fault"] and all(0 <= i < len(right) for i in r["fault"])
    assert {t["slip"] for t in targets[1:]} <= set(check["words"])


@pytest.mark.parametrize("name, qid", CASES)
def test_an_element_beyond_the_tolerance_is_wrong_and_marked(name, qid):
    v = exercises.variant(name, "s001")
    check = task_of(v, qid, practice=True)["check"]
    right, L = check["targets"][0]["elements"], check["tolerance"]["length"]
    for i in range(len(right)):
        off = list(right)
        # Moved across by 4 L (a vector: its tip only), beyond the tolerance; a slip is never that near.
        e = off[i]
        if e["kind"] == "vector":
            dx, dy = e["to"][0] - e["from"][0], e["to"][1] - e["from"][1]
            n = math.hypot(dx, dy)
            e = copy.deepcopy(e)
            e["to"] = [e["to"][0] - 4 * L * dy / n, e["to"][1] + 4 * L * dx / n]
        elif e["kind"] == "line":
            (x1, y1), (x2, y2) = e["through"]
            n = math.hypot(x2 - x1, y2 - y1)
            e = moved(e, (-4 * L * (y2 - y1) / n, 4 * L * (x2 - x1) / n))
        else:
            e = moved(e, (4 * L, 0.0))
        off[i] = e
        r = grade_drawing(v, qid, drawing_of(v, qid, off), reveal=True)
        assert (r["verdict"], r["fault"], r["score"]) == ("wrong", [i], 0.0), (qid, i, r)
        assert r["right"] == right and "revisit step" in r["feedback"]
    # Too few elements: wrong, each missing one not marked (there is nothing to mark), the count said.
    r = grade_drawing(v, qid, drawing_of(v, qid, right[:-1]) if len(right) > 1 else drawing_of(v, qid, []))
    assert r["verdict"] == "wrong" and f"asks for {len(right)} element" in r["feedback"]
    assert grade_drawing(v, qid, drawing_of(v, qid, right))["right"] is None  # revealed only when asked


@pytest.mark.parametrize("mutate, words", [
    (lambda d: d | {"drawing": 2}, "drawing must be 1"),
    (lambda d: d | {"question": "other"}, "answers another question"),
    (lambda d: d | {"space": "velocity"}, "drawn in the mechanism space"),
    (lambda d: d | {"elements": [{"kind": "circle"}]}, "elements[0].kind must be one of"),
    (lambda d: d | {"elements": [{"kind": "point", "name": "I3", "at": [1, float("nan")]}]}, "at[1] must be a finite number"),
    (lambda d: json.dumps(d).replace("]}]", ", 1e999]}]").replace("[", "[", 1), "must be"),
    (lambda d: '{"drawing": NaN}', "not a finite number"),
    (lambda d: d | {"elements": [{"kind": "point", "at": [0, 0]}] * 65}, "at most 64"),
    (lambda d: d | {"elements": [{"kind": "line", "through": [[1, 2], [1, 2]]}]}, "two distinct points"),
    (lambda d: json.dumps(d) + " " * 20_000, "at most 20000"),
    (lambda d: "__import__('os')", "not JSON"),
])
def test_an_unreadable_drawing_is_refused_with_a_sentence_naming_the_field(mutate, words):
    v = exercises.variant("draw_strip_cutter", "s001")
    d = drawing_of(v, "I3", task_of(v, "I3", practice=True)["check"]["targets"][0]["elements"])
    r = grade_drawing(v, "I3", mutate(d))
    assert r["verdict"] == "unreadable" and words in r["feedback"] and r["score"] == 0
    assert r["feedback"].count(". ") == 0  # one sentence


def test_keys_grade_drawings_as_the_live_variant_does_and_carry_the_task():
    ex = exercises.load("draw_strip_cutter")
    keys = Keys(json.loads(json.dumps(make_keys(ex, ["s1", "s2"]))))
    for s in ("s1", "s2"):
        live, keyed = exercises.variant(ex, s), keys.variant(s)
        for q in ex.questions:
            assert task_of(keyed, q.id, practice=True) == json.loads(json.dumps(task_of(live, q.id, practice=True)))
            for t in task_of(live, q.id, practice=True)["check"]["targets"]:
                d = drawing_of(live, q.id, t["elements"])
                assert grade_drawing(keyed, q.id, d) == json.loads(json.dumps(grade_drawing(live, q.id, d)))
    assert task_of(live, "I3")["check"] is None


def test_a_gradescope_json_hand_in_and_a_notebook_variable_hold_the_drawing(tmp_path):
    ex = exercises.load("draw_strip_cutter")
    v = exercises.variant(ex, "s1")
    right = {q.id: right_drawing(v.drawn(q)) for q in ex.questions}
    # Gradescope: an answers.json holding each drawing as an object, or as its text.
    path = tmp_path / "answers.json"
    path.write_text(json.dumps({"R3i": right["R3i"], "F43": json.dumps(right["F43"]), "I3": right["I3"]}))
    answers = read_answers(path)
    report = Keys(make_keys(ex, ["s1"])).grade("s1", answers)
    assert [q["verdict"] for q in report["questions"]] == ["correct", "correct", "correct", "missing"]
    # A notebook: the answer variable holds the drawing's JSON text (a string literal, read as data, never run).
    variables = answer_variables([q.id for q in ex.questions])
    cell = f"{variables['polygon3']} = {json.dumps(json.dumps(right['polygon3']))}\n"
    _, read = read_cells([cell], variables)
    assert exercises.grade(ex, "s1", read)["questions"][3]["verdict"] == "correct"
    _, read = read_cells([f"{variables['polygon3']} = json.dumps(right)\n"], variables)  # code: never run
    r = exercises.grade(ex, "s1", read)["questions"][3]
    assert r["verdict"] == "unreadable" and "a call" in r["feedback"]


@settings(max_examples=4, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(student=st.text("abcdefghij0123456789", min_size=1, max_size=8))
def test_the_right_drawing_is_correct_for_any_student(student):
    v = exercises.variant("draw_strip_cutter", student)
    answers = {q.id: json.dumps(right_drawing(v.drawn(q))) for q in v.exercise.questions}
    assert v.grade(answers)["score"] == len(v.exercise.questions)
