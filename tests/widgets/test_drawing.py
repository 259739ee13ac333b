"""``gk.draw_answer``: a drawn question in a notebook widget (issue 38). The kernel side: the task sent to the
browser is the exercise's (without its targets), a drawing from the browser becomes the answer line, Check grades it
with the exercise's grader and sends the feedback back. The browser side is tested in Chromium
(tests/e2e/test_drawing_widget.py)."""

from __future__ import annotations

import ast
import json

import pytest

import graphkin as gk
from graphkin import exercises
from graphkin.errors import GraphkinError
from graphkin.exercises.drawn_grading import grade_drawing
from graphkin.exercises.drawn_tasks import task_of
from graphkin.scene.page import DRAW_MODULES, module
from graphkin.widgets.drawing import MIME, DrawingBox

EXERCISE, STUDENT = "draw_strip_cutter", "s007"


@pytest.fixture(scope="module")
def variant():
    return exercises.variant(exercises.load(EXERCISE), STUDENT, "")


def drawing_of(task, elements) -> str:
    return json.dumps({"drawing": 1, "question": task["question"], "space": task["space"], "unit": task["unit"],
                       "elements": elements})


def test_the_widget_sends_the_task_and_grades_what_is_drawn_as_the_grader_does(variant):
    box = gk.draw_answer(EXERCISE, "I3", STUDENT)
    assert box.widget._esm == module(DRAW_MODULES)
    task = json.loads(box.widget.task)
    assert task == json.loads(json.dumps(task_of(variant, "I3"))) and task["check"] is None
    assert box.line == "I3 = ''"
    targets = task_of(variant, "I3", practice=True)["check"]["targets"]
    for target in targets:
        text = drawing_of(task, target["elements"])
        box.widget.drawing = text  # as the browser sends it
        assert ast.literal_eval(box.line.split(" = ", 1)[1]) == text and box.widget.line == box.line
        box.widget.asked += 1  # the Check button
        sent = json.loads(box.widget.feedback)
        graded = grade_drawing(variant, "I3", text)
        assert sent["verdict"] == graded["verdict"] and sent["slip"] == graded["slip"]
        assert sent["verdict"] in ("correct", "slip") and sent["fault"] == graded["fault"]
    box.widget.drawing = drawing_of(task, [])
    assert box.widget.feedback == ""  # a grading is of the drawing it graded


def test_the_answer_output_follows_the_drawing(variant):
    task = {k: v for k, v in task_of(variant, "R3i").items()}
    box = DrawingBox(task, lambda text: {"verdict": "missing"}, drawing={"drawing": 1, "elements": []},
                     variable="answer_R3i")
    assert box._bundle()["text/plain"] == "answer_R3i = '{\"drawing\": 1, \"elements\": []}'"
    assert box._bundle()[MIME] == {"drawing": 1, "elements": []}


def test_a_graded_task_never_carries_its_targets_and_a_question_must_be_drawn(variant):
    with pytest.raises(GraphkinError, match="must not carry its targets"):
        DrawingBox(task_of(variant, "R3i", practice=True), lambda text: {})
    with pytest.raises(GraphkinError, match="no question 'nope'"):
        gk.draw_answer(EXERCISE, "nope", STUDENT)
    with pytest.raises(GraphkinError, match="student's id"):
        gk.draw_answer(EXERCISE, "R3i", " ")


def test_the_answer_line_pasted_into_a_cell_is_what_the_notebook_reader_reads_and_grades_alike(variant):
    from graphkin.exercises.grading import grade_question
    from graphkin.exercises.notebooks import answer_variables, read_cells

    box = gk.draw_answer(EXERCISE, "polygon3", STUDENT)
    task = json.loads(box.widget.task)
    (target, *_) = task_of(variant, "polygon3", practice=True)["check"]["targets"]
    box.widget.drawing = drawing_of(task, target["elements"])
    box.widget.asked += 1
    variables = answer_variables([q.id for q in variant.exercise.questions])
    _, answers = read_cells([f"STUDENT = {STUDENT!r}", box.line], variables)
    assert answers["polygon3"] == box.text
    graded = grade_question(variant, variant.exercise.question("polygon3"), answers["polygon3"])
    assert graded["verdict"] == box.report["verdict"] == "correct"


def test_a_saved_notebook_s_drawing_output_is_read_as_its_answer_and_a_later_typed_line_decides(variant, tmp_path):
    """The notebook as JupyterLab saves it: the box's output (display_data with the drawing's MIME type) under the
    cell that drew it. The reader finds the drawing there, in a hand-in file too, as data; a line the student typed
    in a later cell decides instead, as any later assignment does."""
    from graphkin.exercises.handins import read_handin
    from graphkin.exercises.notebooks import answer_variables, notebook_answers

    box = gk.draw_answer(EXERCISE, "I3", STUDENT)
    task = json.loads(box.widget.task)
    right, *slips = task_of(variant, "I3", practice=True)["check"]["targets"]
    box.widget.drawing = drawing_of(task, right["elements"])
    output = {"output_type": "display_data", "metadata": {}, "data": box._bundle()}
    assert MIME in output["data"]
    cells = [{"cell_type": "code", "source": f"STUDENT = {STUDENT!r}", "outputs": []},
             {"cell_type": "code", "source": 'gk.draw_answer("draw_strip_cutter", "I3", STUDENT)', "outputs": [output]}]
    variables = answer_variables([q.id for q in variant.exercise.questions])
    claimed, answers = notebook_answers({"cells": cells}, variables)
    assert claimed == STUDENT and json.loads(answers["I3"]) == json.loads(box.text)
    path = tmp_path / "hw.ipynb"
    path.write_text(json.dumps({"cells": cells, "metadata": {}, "nbformat": 4, "nbformat_minor": 5}))
    handin = read_handin(path, variables)
    assert handin.answers["I3"] == answers["I3"]
    assert variant.grade({"I3": handin.answers["I3"]})["questions"][2]["verdict"] == "correct"
    # A drawing typed later (here a slip's) is the answer instead.
    typed = drawing_of(task, slips[0]["elements"]) if slips else box.text
    cells.append({"cell_type": "code", "source": f"I3 = {typed!r}", "outputs": []})
    assert notebook_answers({"cells": cells}, variables)[1]["I3"] == typed
