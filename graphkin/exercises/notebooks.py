"""Answers in a handed-in notebook, read as data: the notebook's JSON is parsed, its code never run.

A student answers in a notebook by assigning text to a variable (``F23 = "3226 N ∠ −114.32°"``). The
graders of the notebook platforms (otter-grader, nbgrader) run the notebook to read those values,
which lets whatever else the notebook holds run too: code that replaces the grader, reads the course's
files or waits for ever. Here the notebook is read as a file instead. Each code cell is parsed with
:mod:`ast`; the last top-level assignment to an answer's variable gives the answer, and its right-hand
side is read with :func:`ast.literal_eval`, which accepts literals only (text, numbers, ``...``) and
never calls anything. An answer that is not a literal (a call, a name, an f-string) is
:class:`NotData`: it is graded unreadable with a sentence saying to type the answer as text.

Examples
--------
>>> nb = {"cells": [{"cell_type": "code", "source": 'STUDENT = "s001"'},
...                 {"cell_type": "code", "source": ['F23 = "12 N"\\n', 'raise NotImplementedError()']},
...                 {"cell_type": "code", "source": 'T12 = open("secret").read()'}]}
>>> claimed, answers = notebook_answers(nb, {"F23": "F23", "T12": "T12", "F14": "F14"})
>>> claimed, answers["F23"], answers["F14"]
('s001', '12 N', None)
>>> answers["T12"].reason
'a call'
"""

from __future__ import annotations

import ast
import keyword
import re
from collections.abc import Mapping
from dataclasses import dataclass

from graphkin.errors import GraphkinError

MAX_NOTEBOOK_BYTES = 50_000_000
"""The largest notebook file read (a notebook of answers is a few kB; outputs with images reach MB)."""

MAX_CELL_CHARS = 2_000_000
"""A code cell longer than this is not parsed (an answer in it is read as not typed)."""

STUDENT_VARIABLE = "STUDENT"
"""The variable a student types their id into, in the notebooks graphkin exports."""

RESERVED = frozenset({STUDENT_VARIABLE, "grader", "otter", "runtime", "sys", "graphkin", "check_answer", "graded_as",
                      "course_secret"})
"""Names the exported notebooks use themselves: no answer is typed into one of them."""

# `NAME = value` or `NAME: type = value` on one line, for a cell that does not parse as a whole.
_LINE = re.compile(r"^([A-Za-z_]\w*)\s*(?::[^=]*)?=(?!=)\s*(.+?)\s*$")

_WHAT = {ast.Call: "a call", ast.Name: "a variable", ast.JoinedStr: "an f-string", ast.Attribute: "an attribute",
         ast.Subscript: "an index", ast.BinOp: "a calculation", ast.BoolOp: "an expression",
         ast.Compare: "a comparison", ast.IfExp: "an expression", ast.Lambda: "a function",
         ast.ListComp: "a comprehension", ast.GeneratorExp: "a comprehension"}


@dataclass(frozen=True)
class NotData:
    """An answer variable assigned something other than a literal: it is not read (and never run).

    Attributes
    ----------
    reason : str
        What was assigned, in words (``"a call"``, ``"a variable"``, ``"an f-string"``, ...).
    """

    reason: str


def answer_variables(question_ids) -> dict[str, str]:
    """Question id → the notebook variable its answer is typed into, as the notebook exports name them.

    The id itself when it is a Python name the notebook does not use already (``F23``); else ``answer_``
    and the id with ``.`` as ``_`` (``peak.at`` → ``answer_peak_at``, ``runtime`` → ``answer_runtime``).

    Raises
    ------
    GraphkinError
        Two ids that would share a variable.

    Examples
    --------
    >>> answer_variables(["F23", "peak.at", "STUDENT", "lambda"])
    {'F23': 'F23', 'peak.at': 'answer_peak_at', 'STUDENT': 'answer_STUDENT', 'lambda': 'answer_lambda'}
    """
    names = {}
    for qid in question_ids:
        ok = qid.isidentifier() and not keyword.iskeyword(qid) and qid not in RESERVED and not qid.startswith("_")
        names[qid] = qid if ok else "answer_" + qid.replace(".", "_")
    clash = sorted({v for v in names.values() if list(names.values()).count(v) > 1})
    if clash:
        raise GraphkinError(f"question ids give the same notebook variable {', '.join(clash)}; rename one of them "
                            "in the exercise file")
    return names


def _value(node: ast.expr):
    """The literal ``node`` stands for, or :class:`NotData` saying what it is instead."""
    try:
        return ast.literal_eval(node)
    except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
        return NotData(_WHAT.get(type(node), "an expression"))


def _cell_assignments(source: str) -> dict:
    """Every top-level assignment in a cell, in order: name → the value read (the last one wins)."""
    found: dict = {}
    if len(source) > MAX_CELL_CHARS:
        return found
    try:
        tree = ast.parse(source)
    except (SyntaxError, ValueError, MemoryError, RecursionError):
        # A cell with a slip elsewhere (a stray character under the answer) still has its answer lines.
        for line in source.splitlines():
            m = _LINE.match(line)
            if m:
                try:
                    expr = ast.parse(m[2], mode="eval").body
                except (SyntaxError, ValueError, MemoryError, RecursionError):
                    found[m[1]] = NotData("not valid Python")
                    continue
                found[m[1]] = _value(expr)
        return found
    for node in tree.body:
        if isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    found[target.id] = _value(node.value)
                elif isinstance(target, (ast.Tuple, ast.List)):
                    for element in target.elts:
                        if isinstance(element, ast.Name):
                            found[element.id] = NotData("an unpacking")
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name) and node.value is not None:
            found[node.target.id] = _value(node.value)
        elif isinstance(node, ast.AugAssign) and isinstance(node.target, ast.Name):
            found[node.target.id] = NotData("a calculation")
    return found


def _source(cell) -> str:
    source = cell.get("source", "") if isinstance(cell, Mapping) else ""
    if isinstance(source, list):
        return "".join(s for s in source if isinstance(s, str))
    return source if isinstance(source, str) else ""


_UNSEEN = object()


def typed_in_kernel(variable: str):
    """What the latest cell run in this IPython kernel assigned to ``variable``, read as the grader reads it.

    A notebook's own check cell calls it, so that a student learns before handing in that an answer typed
    as a calculation (``F23 = f"{x} N"``) will not be read. Returns :class:`NotData`, the literal, or
    None when no cell run so far assigns it (or outside IPython).
    """
    try:
        from IPython import get_ipython
    except ImportError:
        return None
    shell = get_ipython()
    history = shell.user_ns.get("In", []) if shell is not None else []
    for source in reversed(history if isinstance(history, list) else []):
        if isinstance(source, str) and variable in source:
            value = _cell_assignments(source).get(variable, _UNSEEN)
            if value is not _UNSEEN:
                return value
    return None


def code_sources(notebook) -> list[str]:
    """The text of a notebook's code cells, in order: all that :func:`notebook_answers` reads."""
    cells = notebook.get("cells", []) if isinstance(notebook, Mapping) else []
    return [_source(c) for c in (cells if isinstance(cells, list) else [])
            if isinstance(c, Mapping) and c.get("cell_type") == "code"]


def notebook_answers(notebook, variables: Mapping[str, str], student_variable: str = STUDENT_VARIABLE):
    """The id and the answers a notebook holds, read as data.

    Parameters
    ----------
    notebook : mapping
        The notebook's JSON (``{"cells": [...]}``; nbformat's node is one).
    variables : mapping of str to str
        Question id → the variable its answer is typed into.
    student_variable : str
        The variable holding the student's id.

    Returns
    -------
    claimed : object
        What ``student_variable`` holds (text, ``...`` if left blank, :class:`NotData`, or None if
        it is never assigned).
    answers : dict
        Question id → text or number as typed, ``None`` when the variable is never assigned or holds
        ``...`` (unanswered), or :class:`NotData`.
    """
    seen: dict = {}
    for source in code_sources(notebook):
        seen.update(_cell_assignments(source))

    def get(name):
        value = seen.get(name)
        return None if value is Ellipsis else value

    return get(student_variable), {qid: get(var) for qid, var in variables.items()}


__all__ = ["MAX_CELL_CHARS", "MAX_NOTEBOOK_BYTES", "NotData", "RESERVED", "STUDENT_VARIABLE", "answer_variables",
           "code_sources", "notebook_answers", "typed_in_kernel"]
