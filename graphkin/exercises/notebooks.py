"""Answers in a handed-in notebook, read as data: the notebook's JSON is parsed, its code never run.

A student answers in a notebook by assigning text to a variable (``F23 = "3226 N ∠ −114.32°"``). The
graders of the notebook platforms (otter-grader, nbgrader) run the notebook to read those values,
which lets whatever else the notebook holds run too: code that replaces the grader, reads the course's
files or waits for ever. Here the notebook is read as a file instead. Each code cell is parsed with
:mod:`ast`; the last statement that gives an answer's variable a value decides the answer. When it is
an assignment on a line of its own (``F23 = ...``, at the top level of the cell), its right-hand side is
read with :func:`ast.literal_eval`, which accepts literals only (text, numbers, ``...``) and never calls
anything. An answer that is not a literal (a call, a name, an f-string), or that is assigned inside an
``if``, ``try``, ``with``, a loop or a function (which may or may not run), is :class:`NotData`: it is
graded unreadable with a sentence saying to type the answer as text, on a line of its own.

:func:`read_cells` is the one reader: the grader reads a handed-in notebook's code cells with it
(:func:`notebook_answers`), and a notebook's own check reads the notebook's file as saved with it, top to bottom
as the grader does (:func:`kernel_notebook`), else the cells run so far in its kernel (:func:`kernel_cells`), so
that what the check calls readable is what the grader reads, and the reverse.

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
>>> read_cells(['if True:\\n    F23 = "12 N"', "STUDENT = 231006"], {"F23": "F23"})
('231006', {'F23': NotData(reason='an assignment inside an `if` block')})
"""

from __future__ import annotations

import ast
import keyword
import re
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

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

# `NAME = value` or `NAME: type = value` on one line, for a cell that does not parse as a whole; the value is
# stripped after the match (a lazy value before `\s*$` would take time quadratic in a run of spaces).
_LINE = re.compile(r"^([A-Za-z_]\w*)\s*(?::[^=]*)?=(?!=)(.+)$")

# Where a statement that is not a plain assignment gives a variable its value, in words.
_WHERE = {ast.If: "an assignment inside an `if` block", ast.Try: "an assignment inside a `try` block",
          ast.With: "an assignment inside a `with` block", ast.AsyncWith: "an assignment inside a `with` block",
          ast.For: "an assignment inside a loop", ast.AsyncFor: "an assignment inside a loop",
          ast.While: "an assignment inside a loop", ast.FunctionDef: "an assignment inside a function",
          ast.AsyncFunctionDef: "an assignment inside a function", ast.ClassDef: "an assignment inside a class",
          ast.Match: "an assignment inside a `match` block", ast.Import: "an import",
          ast.ImportFrom: "an import", ast.Delete: "a `del` statement"}
if hasattr(ast, "TryStar"):  # Python 3.11: try ... except*
    _WHERE[ast.TryStar] = "an assignment inside a `try` block"

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


def _bound(node: ast.AST):
    """Every name a statement gives a value to (or deletes), at any depth: targets, loop variables, ``as``
    names, imports, functions and classes, ``:=``."""
    for sub in ast.walk(node):
        if isinstance(sub, ast.Name) and isinstance(sub.ctx, (ast.Store, ast.Del)):
            yield sub.id
        elif isinstance(sub, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            yield sub.name
        elif isinstance(sub, ast.alias):
            yield (sub.asname or sub.name).split(".")[0]
        elif isinstance(sub, ast.ExceptHandler) and sub.name:
            yield sub.name
        elif isinstance(sub, (ast.MatchAs, ast.MatchStar)) and sub.name:
            yield sub.name
        elif isinstance(sub, ast.MatchMapping) and sub.rest:
            yield sub.rest


def _cell_assignments(source: str) -> dict:
    """Every statement of a cell that gives a variable a value, in order: name → the value read (the last one
    wins); a value given any other way than by a plain assignment at the top level is :class:`NotData`."""
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
                    expr = ast.parse(m[2].strip(), mode="eval").body
                except (SyntaxError, ValueError, MemoryError, RecursionError):
                    found[m[1]] = NotData("not valid Python")
                    continue
                found[m[1]] = _value(expr)
        return found
    for node in tree.body:
        if isinstance(node, (ast.Assign, ast.AnnAssign)) and node.value is not None:
            # A name given a value by ":=" inside the right-hand side, before the assignment itself.
            for sub in ast.walk(node.value):
                if isinstance(sub, ast.NamedExpr) and isinstance(sub.target, ast.Name):
                    found[sub.target.id] = NotData("an assignment inside an expression")
        if isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    found[target.id] = _value(node.value)
                elif isinstance(target, (ast.Tuple, ast.List, ast.Starred)):
                    for name in _bound(target):
                        found[name] = NotData("an unpacking")
        elif isinstance(node, ast.AnnAssign):  # without a value (F23: str) it gives none
            if isinstance(node.target, ast.Name) and node.value is not None:
                found[node.target.id] = _value(node.value)
        elif isinstance(node, ast.AugAssign):
            if isinstance(node.target, ast.Name):
                found[node.target.id] = NotData("a calculation")
        else:
            # Inside an if, a loop, a function ...: the grader cannot know whether it runs, and never runs it.
            where = NotData(_WHERE.get(type(node), "an assignment inside an expression"))
            for name in _bound(node):
                found[name] = where
    return found


def _source(cell) -> str:
    source = cell.get("source", "") if isinstance(cell, Mapping) else ""
    if isinstance(source, list):
        return "".join(s for s in source if isinstance(s, str))
    return source if isinstance(source, str) else ""


def read_cells(sources, variables: Mapping[str, str], student_variable: str = STUDENT_VARIABLE):
    """The id and the answers that code cells hold, read as data: the one reader of answers in a notebook.

    Parameters
    ----------
    sources : iterable of str
        The code cells' sources, in order (a notebook's, or the cells run in a kernel).
    variables : mapping of str to str
        Question id → the variable its answer is typed into.
    student_variable : str
        The variable holding the student's id.

    Returns
    -------
    claimed : object
        What ``student_variable`` holds: text (an id typed as a whole number, ``231006``, is read as its
        digits), ``...`` if left blank, :class:`NotData`, or None if it is never assigned.
    answers : dict
        Question id → text or number as typed, ``None`` when the variable is never assigned or holds
        ``...`` (unanswered), or :class:`NotData`.
    """
    seen: dict = {}
    for source in sources:
        if isinstance(source, str):
            seen.update(_cell_assignments(source))

    def get(name):
        value = seen.get(name)
        return None if value is Ellipsis else value

    claimed = get(student_variable)
    if isinstance(claimed, int) and not isinstance(claimed, bool) and claimed >= 0 and claimed.bit_length() < 300:
        claimed = str(claimed)  # a student number typed without quotes is still that number
    return claimed, {qid: get(var) for qid, var in variables.items()}


DRAWING_MIME = "application/vnd.graphkin.drawing+json"
"""The MIME type of a drawn answer's output (:mod:`graphkin.widgets.drawing`): its ``text/plain`` is the answer
line, ``variable = '<the drawing as JSON>'``."""


def _drawn_lines(cell) -> list[str]:
    """The answer lines a code cell's drawn-answer outputs hold (the ``text/plain`` of each output that carries
    :data:`DRAWING_MIME`), in order: read as the cell's own lines are, as data."""
    outputs = cell.get("outputs") if isinstance(cell, Mapping) else None
    lines = []
    for out in outputs if isinstance(outputs, list) else []:
        data = out.get("data") if isinstance(out, Mapping) else None
        if isinstance(data, Mapping) and DRAWING_MIME in data:
            lines.append(_source({"source": data.get("text/plain", "")}))
    return lines


def code_sources(notebook) -> list[str]:
    """The text of a notebook's code cells, in order: all that :func:`notebook_answers` reads.

    A drawn answer's box (``gk.draw_answer``) keeps the drawing in an output under itself, which JupyterLab saves
    with the notebook: its answer line is read after its cell's text, as a line the student typed there would be
    (a later assignment of the same variable, typed or drawn, decides, as for any answer).
    """
    cells = notebook.get("cells", []) if isinstance(notebook, Mapping) else []
    sources = []
    for c in cells if isinstance(cells, list) else []:
        if isinstance(c, Mapping) and c.get("cell_type") == "code":
            sources += [_source(c), *_drawn_lines(c)]
    return sources


def notebook_answers(notebook, variables: Mapping[str, str], student_variable: str = STUDENT_VARIABLE):
    """The id and the answers a notebook holds, read as data (:func:`read_cells` of its code cells).

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
    claimed, answers
        As :func:`read_cells` gives them.
    """
    return read_cells(code_sources(notebook), variables, student_variable)


def _shell():
    """This process's IPython shell; None outside IPython (or where IPython is not installed)."""
    try:
        from IPython import get_ipython
    except ImportError:
        return None
    return get_ipython()


def kernel_cells() -> list[str] | None:
    """The cells run so far in this IPython kernel, as they were typed, in the order they ran; None outside
    IPython.

    A notebook's own check reads them with :func:`read_cells` where the kernel does not know its notebook's file
    (:func:`kernel_notebook`), and to tell a student when the cells as run give another answer than the file the
    grader reads.
    """
    shell = _shell()
    if shell is None:
        return None
    # The raw input (magics as typed, as the notebook file holds them), else IPython's transformed copy.
    history = getattr(getattr(shell, "history_manager", None), "input_hist_raw", None)
    if not isinstance(history, list):
        history = shell.user_ns.get("In", [])
    return [s for s in history if isinstance(s, str)] if isinstance(history, list) else []


def kernel_notebook() -> Path | None:
    """The notebook file this IPython kernel runs, as saved; None when it is not known (outside IPython, a console).

    The cells run in a kernel are in the order they ran; the grader reads the file handed in, top to bottom. A
    notebook's own check reads this file too, so that a cell rerun out of order cannot make it say "readable" of
    an answer the grader reads otherwise. Jupyter (jupyter_server 2: JupyterLab 4, Notebook 7) starts a notebook's
    kernel with its path, which ipykernel keeps as ``__session__``; VS Code sets ``__vsc_ipynb_file__``. A path
    relative to the server's root is looked for in the kernel's folder, which is the notebook's.
    """
    shell = _shell()
    if shell is None:
        return None
    for name in ("__vsc_ipynb_file__", "__session__"):
        value = shell.user_ns.get(name)
        if not isinstance(value, str) or not value.lower().endswith(".ipynb"):
            continue
        p = Path(value)
        for candidate in (p, Path.cwd() / p, Path.cwd() / p.name):
            if candidate.is_file():
                return candidate
    return None


__all__ = ["MAX_CELL_CHARS", "MAX_NOTEBOOK_BYTES", "NotData", "RESERVED", "STUDENT_VARIABLE", "answer_variables",
           "code_sources", "kernel_cells", "kernel_notebook", "notebook_answers", "read_cells"]
