"""Answers in a handed-in notebook are read as data: literals only, never run, whatever else the notebook holds."""

from __future__ import annotations

import os

import pytest

from graphkin.errors import GraphkinError
from graphkin.exercises.notebooks import NotData, answer_variables, kernel_cells, notebook_answers, read_cells

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


def test_only_code_cells_count():
    _, answers = notebook_answers(nb('F23 = "1 N"', kind="markdown"), NAMES)
    assert answers["F23"] is None


NESTED = [
    ('if True:\n    F23 = "12 N"', "an assignment inside an `if` block"),
    ('try:\n    F23 = "12 N"\nexcept Exception:\n    pass', "an assignment inside a `try` block"),
    ('import contextlib\nwith contextlib.nullcontext():\n    F23 = "12 N"', "an assignment inside a `with` block"),
    ('for _ in range(1):\n    F23 = "12 N"', "an assignment inside a loop"),
    ('while True:\n    F23 = "12 N"\n    break', "an assignment inside a loop"),
    ('def answer():\n    global F23\n    F23 = "12 N"\nanswer()', "an assignment inside a function"),
    ('class A:\n    F23 = "12 N"', "an assignment inside a class"),
    ('match 1:\n    case 1:\n        F23 = "12 N"', "an assignment inside a `match` block"),
    ('print(F23 := "12 N")', "an assignment inside an expression"),
    ('x = (F23 := "12 N")', "an assignment inside an expression"),
    ("from math import pi as F23", "an import"),
    ('F23 = "12 N"\ndel F23', "a `del` statement"),
    ('try:\n    pass\nexcept ValueError as F23:\n    pass', "an assignment inside a `try` block"),
    ('[*F23] = ["12 N"]', "an unpacking"),
]


@pytest.mark.parametrize("source, reason", NESTED)
def test_an_answer_given_its_value_other_than_by_a_plain_assignment_is_not_data(source, reason):
    """Whether code inside an if, a try or a function runs is not known from the file: the answer it would give is
    not read, and says why (issue 34: the grader used to call it missing, while the check called it readable)."""
    _, answers = notebook_answers(nb('F23 = "1 N"', source), NAMES)
    assert answers["F23"] == NotData(reason)


def test_a_later_plain_assignment_wins_over_a_nested_one_and_a_declaration_is_none():
    _, answers = notebook_answers(nb('if True:\n    F23 = "1 N"', 'F23 = "12 N"', "T12: str"), NAMES)
    assert answers["F23"] == "12 N" and answers["T12"] is None


@pytest.mark.parametrize("typed, read", [("231006", "231006"), ('"231006"', "231006"), ("True", True),
                                         ("-5", -5), ("...", None)])
def test_an_id_typed_as_a_whole_number_is_read_as_its_digits(typed, read):
    assert read_cells([f"STUDENT = {typed}"], {})[0] == read


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


def test_outside_ipython_no_cell_was_run_in_a_kernel():
    assert kernel_cells() is None


def test_the_module_runs_nothing(tmp_path, monkeypatch):
    """A notebook whose every cell would write a file, run or not: nothing is written."""
    monkeypatch.chdir(tmp_path)
    cells = [f"open('pwned{i}', 'w')\nF23 = open('pwned{i}b', 'w')" for i in range(5)]
    notebook_answers(nb(*cells), NAMES)
    assert os.listdir(tmp_path) == []
