"""What the exported notebooks, tests and server code call on the platform.

Kept small and stable: a platform's hidden test or ``server.py`` says
``from graphkin.exercises.platforms import runtime`` and calls one of these
with the exercise file that travelled with the export, the student's id and
the course secret. Nothing here evaluates what a student typed: an answer is
text (or a number) handed to the same reader ``graphkin exercise grade`` uses.
"""

from __future__ import annotations

import json
from functools import lru_cache
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.exercises import load_exercise
from graphkin.exercises.exercise import Exercise
from graphkin.exercises.feedback import Refusal, read_given
from graphkin.exercises.grading import echo, grade_variant
from graphkin.exercises.grading import grade_question as _grade_one
from graphkin.exercises.handins import read_handin
from graphkin.exercises.notebooks import NotData, kernel_cells, kernel_notebook, read_cells
from graphkin.exercises.sheets import format_sheet
from graphkin.exercises.variants import check_student, make_variant


@lru_cache(maxsize=16)
def _load(path: str):
    p = Path(path)
    return load_exercise(p, name=p.stem)


def exercise(path_or_exercise):
    """The exercise of an export (read once per process), from its file or as given."""
    if isinstance(path_or_exercise, Exercise):
        return path_or_exercise
    return _load(str(Path(path_or_exercise).resolve()))


def variant(path_or_exercise, student: str, secret: str = ""):
    """The student's variant (:class:`graphkin.exercises.Variant`)."""
    return make_variant(exercise(path_or_exercise), student, secret)


def answer_value(value):
    """What a notebook variable holds, as the grader reads it: text or a number; unanswered is ``None``.

    ``...`` (the placeholder the notebook platforms leave in a student's
    copy) and ``None`` are unanswered; anything else goes to the reader as
    it is, which refuses what is not text or a number with a sentence.
    """
    return None if value is None or value is Ellipsis else value


def sheet(path_or_exercise, student: str, sheets=None, secret: str = "") -> dict:
    """The student's sheet: from the roster's sheets (a JSON file or dict) when given, else drawn from the id.

    A student notebook passes the sheets that travelled with the export, so
    it never needs the course secret; an id that is not on the roster is an
    error that says so.
    """
    student = check_student(student)
    if sheets is None:
        return variant(path_or_exercise, student, secret).sheet()
    if not isinstance(sheets, dict):
        sheets = json.loads(Path(sheets).read_text(encoding="utf-8"))
    if student not in sheets:
        raise GraphkinError(f"student id {student!r} is not on this assignment's roster: check the id you typed "
                            "(as your teacher gave it), or ask your teacher to add you")
    return sheets[student]


def sheet_text(path_or_exercise, student: str, sheets=None, secret: str = "") -> str:
    """The student's sheet as text (data and questions), for a notebook cell to print."""
    return format_sheet(sheet(path_or_exercise, student, sheets, secret))


def grade(path_or_exercise, student: str, answers: dict, secret: str = "", *, reveal=None) -> dict:
    """Grade a student's answers (question id → value): the report of ``graphkin exercise grade --json``."""
    answers = {k: answer_value(v) for k, v in dict(answers).items()}
    return grade_variant(variant(path_or_exercise, student, secret), answers, reveal=reveal)


def grade_question(path_or_exercise, student: str, qid: str, answer, secret: str = "", *, reveal=None) -> dict:
    """Grade one answer: ``{"id", "verdict", "slip", "score", "max", "feedback", "answer"[, "expected"]}``."""
    v = variant(path_or_exercise, student, secret)
    q = v.exercise.question(qid)
    reveal = v.exercise.reveal if reveal is None else bool(reveal)
    return _grade_one(v, q, answer_value(answer), reveal=reveal)


def readable_problem(path_or_exercise, qid: str, answer, variable: str | None = None) -> str | None:
    """Why an answer would be graded missing or unreadable (the grader's sentence), or None when it is read.

    What a notebook's own check cell tells a student: it needs neither the key nor the secret. With
    ``variable``, in a kernel, the answer is what the grader reads, never the value the kernel holds: from the
    notebook file as saved, read as the grader reads a hand-in (:func:`graphkin.exercises.handins.read_handin`,
    the cells top to bottom), when the kernel knows its file (:func:`graphkin.exercises.notebooks.kernel_notebook`),
    else from the cells run so far, in the order they ran (:func:`graphkin.exercises.notebooks.read_cells`, the
    grader's own reader). Where the saved file and the cells as run give different answers (a cell rerun out of
    order, or edits not saved yet), the sentence says both and how to make them agree; where no cell run assigns
    the variable, the saved file decides alone. Readability is the
    grader's own decision (:func:`graphkin.exercises.grading.read_given`).
    """
    ex = exercise(path_or_exercise)
    q = ex.question(qid)
    cells = kernel_cells() if variable else None
    if cells is None:
        return _refusal(ex, q, answer_value(answer))
    ran = read_cells(cells, {qid: variable})[1][qid]
    saved = _saved_notebook(qid, variable)
    if saved is None:
        return _refusal(ex, q, ran)
    if saved.refused:
        return saved.reason  # the grader refuses the notebook as saved whole, with this sentence
    given = saved.answers[qid]
    refused = _refusal(ex, q, given)
    # No cell run assigns it: nothing to disagree with (a drawing kept in its box's output is in the file only).
    if ran is None or given == ran:
        return refused
    differs = (f"The notebook as saved, which the grader reads from top to bottom, gives {variable} = "
               f"{_shown(given)}, but the cells as you ran them give {_shown(ran)}: save the notebook, then run it "
               "from the top (Kernel, then Restart Kernel and Run All Cells) and check again before you hand it in.")
    return differs + (f" As saved: {refused}" if refused else "")


def _refusal(ex, q, given) -> str | None:
    refused = read_given(q, given, decimal_comma=ex.decimal_comma)
    return refused.sentence if isinstance(refused, Refusal) else None


def _saved_notebook(qid: str, variable: str):
    """The kernel's notebook file as saved, read as the grader reads a hand-in; None when the file is not known."""
    path = kernel_notebook()
    if path is None:
        return None
    try:
        return read_handin(path, {qid: variable})
    except GraphkinError:  # gone between finding and reading it: the cells as run are all there is
        return None


def _shown(value) -> str:
    """An answer as the check's sentence quotes it (one line)."""
    if value is None:
        return "no answer"
    if isinstance(value, NotData):
        return echo(value)
    return repr(echo(value, 60)) if isinstance(value, str) else echo(value, 60)


def feedback_line(result: dict) -> str:
    """One question's result as the line a student reads: verdict, points and the feedback sentence."""
    slip = f" ({result['slip'].replace('_', ' ')})" if result.get("slip") else ""
    line = f"{result['id']}: {result['verdict']}{slip}, {result['score']:g} / {result['max']:g} — {result['feedback']}"
    if "expected" in result and result["verdict"] != "correct":
        line += f" (expected: {result['expected']})"
    return line


def summary(report: dict) -> str:
    """A graded notebook's opening lines: whom it was graded as, the score, the student's data.

    Parameters
    ----------
    report : dict
        A report of :func:`graphkin.exercises.platforms.isolated.grade_one` (points, no unit).
    """
    lines = [f"Graded as student {report['student']!r}: {report['score']:g} / {report['max']:g} points."]
    if report.get("refused"):
        lines.append(f"Not graded: {report['refused']}")
    if report.get("data"):
        lines.append("Your data: " + ", ".join(report["data"]) + ".")
    return "\n".join(lines)


def identity_error(claimed, graded_as) -> str | None:
    """Why a submission must not be graded under ``graded_as`` when it carries ``claimed``; None when they agree.

    The notebook carries the student's id as a field the student fills in;
    the platform knows whom it grades. A submission that carries another
    student's id (a friend's variant, a friend's answers) scores nothing.
    """
    try:
        claimed = check_student(claimed)
    except GraphkinError:
        return f"this submission carries no usable student id ({claimed!r}); it is graded as {graded_as!r}"
    if claimed != check_student(graded_as):
        return (f"this submission carries the student id {claimed!r} but was handed in by {graded_as!r}: "
                "each student answers their own variant")
    return None


__all__ = ["answer_value", "exercise", "feedback_line", "grade", "grade_question", "identity_error",
           "readable_problem", "sheet", "sheet_text", "summary", "variant"]
