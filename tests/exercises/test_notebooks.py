"""Answers in a handed-in notebook are read as data: literals only, never run, whatever else the notebook holds."""

from __future__ import annotations

import os

import pytest

from graphkin.errors import GraphkinError
from graphkin.exercises.notebooks import NotData, answer_variables, notebook_answers, typed_in_kernel

NAMES = {"F23": "F23", "T12": "T12", "peak.at": "answer_peak_at"}


def nb(*sources, kind="code"):
    return {"cells": [{"cell_type": kind, "source": s, "metadata": {}} for s in sources]}


def test_literals_are_read_and_the_last_assignment_wins():
    claimed, answers = notebook_answers(nb('STUDENT = "s001"', 'F23 = "1 N"', 'F23 = "12.5 N ∠ 30°"',
                                           "answer_peak_at = 12.5", "T12 = ..."), NAMES)
    assert claimed == "s001"
    assert answers == {"F23": "12.5 N ∠ 30°", "T12": None, "peak.at": 12.5}


def test_sources_as_lists_annotations_and_implicit_concatenation():
    claimed, answers = notebook_answers(nb(['STUDENT: str = "s0"\n', '"01"\n'], ['F23 = ("12 "\n', '"N")']), NAMES)
    assert claimed == "s0" and answers["F23"] == "12 N"


@pytest.mark.parametrize("source, reason", [
    ('F23 = open("keys.json").read()', "a call"),
    ("F23 = answer", "a variable"),
    ('F23 = f"{x} N"', "an f-string"),
    ('F23 = "1" + " N"', "a calculation"),
    ("F23 = os.environ['GRAPHKIN_SECRET']", "an index"),
    ("F23 = __import__('os').getenv('HOME')", "a call"),
    ("F23 = lambda: '1 N'", "a function"),
    ('F23 = "1 N" if True else "2 N"', "an expression"),
    ("F23, T12 = '1 N', '2 N*m'", "an unpacking"),
    ('F23 = "1"\nF23 += " N"', "a calculation"),
])
def test_anything_but_a_literal_is_not_data_and_never_runs(source, reason, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    _, answers = notebook_answers(nb(source + "\nopen('ran', 'w')"), NAMES)
    assert answers["F23"] == NotData(reason)
    assert not (tmp_path / "ran").exists()


def test_a_cell_that_does_not_parse_still_gives_its_answer_lines():
    # nbgrader's stub left in place, and a stray character below it.
    _, answers = notebook_answers(nb('F23 = "1 N"\n# YOUR CODE HERE\nraise NotImplementedError()\n§'), NAMES)
    assert answers["F23"] == "1 N"
    _, answers = notebook_answers(nb('F23 = open("x"\n§'), NAMES)
    assert isinstance(answers["F23"], NotData)


def test_only_code_cells_and_only_top_level_assignments_count():
    _, answers = notebook_answers(nb('F23 = "1 N"', kind="markdown"), NAMES)
    assert answers["F23"] is None
    _, answers = notebook_answers(nb('if True:\n    F23 = "1 N"', 'def f():\n    T12 = "2 N*m"'), NAMES)
    assert answers == {"F23": None, "T12": None, "peak.at": None}


@pytest.mark.parametrize("source", [
    "F23 = " + "1" * 5000,                  # more digits than Python converts: a SyntaxError when parsed
    "F23 = " + "[" * 100_000 + "]" * 100_000,  # too deep for the parser
    "F23 = '" + "x" * 1_000_000 + "'",      # a 1 MB answer
    "F23 = float('nan')",
    "F23 = b'12 N'",
    "F23 = 1e999",
])
def test_hostile_literals_never_raise(source):
    _, answers = notebook_answers(nb(source, 'T12 = "5 N*m"'), NAMES)
    assert answers["T12"] == "5 N*m"


def test_answer_variables_avoid_the_notebooks_own_names():
    assert answer_variables(["F23", "peak.at", "runtime", "_x", "lambda", "graphkin"]) == {
        "F23": "F23", "peak.at": "answer_peak_at", "runtime": "answer_runtime", "_x": "answer__x",
        "lambda": "answer_lambda", "graphkin": "answer_graphkin"}
    with pytest.raises(GraphkinError, match="same notebook variable answer_peak_at"):
        answer_variables(["peak.at", "answer_peak_at"])


def test_outside_ipython_nothing_is_typed_in_a_kernel():
    assert typed_in_kernel("F23") is None


def test_the_module_runs_nothing(tmp_path, monkeypatch):
    """A notebook whose every cell would write a file, run or not: nothing is written."""
    monkeypatch.chdir(tmp_path)
    cells = [f"open('pwned{i}', 'w')\nF23 = open('pwned{i}b', 'w')" for i in range(5)]
    notebook_answers(nb(*cells), NAMES)
    assert os.listdir(tmp_path) == []
