"""The check in a student's notebook and the grader agree (issue 34): what the check calls readable is what the
grader reads, and what the grader refuses the check refuses with the same sentence.

The check runs in the student's kernel, a real IPython shell here, after the student's cells; the grader reads the
same cells from the notebook file. Both go through one reader (:func:`graphkin.exercises.notebooks.read_cells`) and
one decision (:func:`graphkin.exercises.grading.read_given`).
"""

from __future__ import annotations

import pytest

from graphkin import exercises
from graphkin.exercises.grading import grade_question
from graphkin.exercises.notebooks import notebook_answers
from graphkin.exercises.platforms import nbgrader, otter, runtime

NAME = "strip_cutter_cut"
KEY = {q["id"]: q["answer"]["text"] for q in exercises.key(NAME, "s001")["questions"]}

CELLS = [
    [f"F23 = {KEY['F23']!r}"],
    ['F23 = "1,352 N"'],
    ["F23 = ..."],
    ["x = 1"],
    ['F23 = f"{12} N"'],
    ['F23 = "12 N"', "F23 += ' more'"],
    ['if True:\n    F23 = "12 N"'],
    ['F23 = "1 N"', 'try:\n    F23 = "12 N"\nexcept Exception:\n    pass'],
    ['import contextlib\nwith contextlib.nullcontext():\n    F23 = "12 N"'],
    ['for _ in range(1):\n    F23 = "12 N"'],
    ['def answer():\n    global F23\n    F23 = "12 N"\nanswer()'],
    ['print(F23 := "12 N")'],
    ['F23 = "1 N"', "del F23"],
    ['%time F23 = "12 N"'],
    ['F23 = "12 N"\n%time x = 1'],
    ['F23 = "12 N"', 'if False:\n    F23 = "13 N"'],
    ['if True:\n    F23 = "13 N"', 'F23 = "12 N"'],
]


def graded(cells: list[str]) -> dict:
    """The grader's verdict on F23 for a notebook of these code cells."""
    nb = {"cells": [{"cell_type": "code", "source": c, "metadata": {}} for c in cells]}
    _, answers = notebook_answers(nb, {"F23": "F23"})
    v = exercises.variant(NAME, "s001")
    return grade_question(v, v.exercise.question("F23"), answers["F23"])


@pytest.mark.parametrize("cells", CELLS, ids=lambda c: " | ".join(c)[:40])
def test_the_check_refuses_what_the_grader_refuses_with_its_sentence_and_only_that(cells, kernel):
    for cell in cells:
        kernel.run_cell(cell, store_history=True)
    value = kernel.user_ns.get("F23")  # what the exported check cells pass: the kernel's value, and the variable
    check = runtime.readable_problem(exercises.load(NAME), "F23", value, "F23")
    r = graded(cells)
    refused = r["verdict"] in ("missing", "unreadable")
    assert (check is not None) == refused, (check, r)
    if refused:
        assert check == r["feedback"]


def test_the_exported_checks_say_the_graders_sentence(kernel, tmp_path, capsys):
    """otter's public test and nbgrader's visible test both give the grader's own sentence."""
    file = exercises.path(NAME)
    kernel.run_cell('if True:\n    F23 = "12 N"', store_history=True)
    sentence = graded(['if True:\n    F23 = "12 N"'])["feedback"]
    assert "on a line of its own" in sentence and "inside an `if` block" in sentence
    with pytest.raises(AssertionError) as info:
        otter.readable(file, "F23", kernel.user_ns["F23"], "F23")
    assert str(info.value) == sentence
    with pytest.raises(AssertionError) as info:
        nbgrader.check_answer(file, "F23", kernel.user_ns["F23"], "F23")
    assert str(info.value) == sentence
    kernel.run_cell(f"F23 = {KEY['F23']!r}", store_history=True)
    nbgrader.check_answer(file, "F23", kernel.user_ns["F23"], "F23")
    assert "F23: your answer can be read" in capsys.readouterr().out


def test_an_id_typed_as_a_number_is_read_in_a_notebook_and_an_answers_file():
    from graphkin.exercises.notebooks import read_cells
    from graphkin.exercises.platforms import gradescope

    claimed, _ = read_cells(["STUDENT = 231006"], {})
    assert claimed == "231006" and runtime.identity_error(claimed, "231006") is None
    # answers.toml: student = 231006 is a TOML integer.
    student, _ = gradescope.whom_to_grade([{"sid": "231006", "email": "", "name": "A"}], 231006, ["231006"])
    assert student == "231006" and runtime.identity_error(231006, student) is None
    assert runtime.sheet_text(exercises.load(NAME), 231006) == runtime.sheet_text(exercises.load(NAME), "231006")
