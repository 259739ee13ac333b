"""Grading in a Python process of its own: answers read as data go in, reports come out.

The notebook platforms run a student's notebook to grade it, in a kernel where the student's code can
replace any function the tests call. graphkin's otter plugin and nbgrader preprocessor read the answers
from the notebook file as data instead (:mod:`graphkin.exercises.notebooks`) and hand them to
:func:`grade_submissions`, which grades them in a new interpreter:

- started with ``python -I`` (isolated: no user site-packages, no ``PYTHON*`` variables, not even the
  current folder on ``sys.path``), in an empty temporary folder, with an environment of a few
  variables (``PATH``, ``HOME``, ``LANG``, the cache folder) and nothing else, so no secret and no
  setting of the grading machine reaches it;
- importing graphkin from the copy that travelled with the export when one is named (``vendor``),
  else the very copy the calling process runs (the grader and the platform's hook are one version),
  before any of the student's files could be;
- holding the precomputed keys (:mod:`graphkin.exercises.keys`), never the course secret;
- reading one JSON request on standard input and writing one JSON answer on standard output.

Nothing of the student's is code to it: the answers are JSON strings, numbers, markers and the text of
the notebook's other literals, read back with :func:`ast.literal_eval` (the notebook reader's own). The reports
it returns are those of :meth:`graphkin.exercises.keys.Keys.grade`, so a teacher who grades the
collected answers again on their own machine (``graphkin exercise grade ... --answers *.ipynb``) gets
the same scores.
"""

from __future__ import annotations

import ast
import contextlib
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.exercises.grading import echo, grade_variant
from graphkin.exercises.handins import REFUSALS
from graphkin.exercises.keys import Keys
from graphkin.exercises.notebooks import NotData
from graphkin.exercises.platforms import runtime

# The folder holding the graphkin package this module belongs to.
_HOME = Path(__file__).resolve().parents[3]

TIMEOUT = 300
"""Seconds the grading process may take for one request before it is stopped."""

# The variables a grading process keeps: where programs and the home folder are, the text encoding, and
# graphkin's cache folder. Nothing else of the grader's environment (a secret, a token) goes through.
_KEEP = ("PATH", "HOME", "TMPDIR", "LANG", "LC_ALL", "GRAPHKIN_CACHE_DIR")

_BOOT = ("import sys\n"
         "if sys.argv[1]:\n"
         "    sys.path.insert(0, sys.argv[1])\n"
         "from graphkin.exercises.platforms.isolated import main\n"
         "sys.exit(main())\n")

# What a student may have assigned besides text and numbers that cannot be carried as its text (a nan inside a
# list, say), rebuilt empty on the other side: the reader refuses each with a sentence naming its type.
_TYPES = {"list": list, "tuple": tuple, "dict": dict, "set": set, "frozenset": frozenset, "bytes": bytes,
          "complex": complex, "ellipsis": lambda: None}


def encode(value):
    """An answer as JSON data for the grading process: text and numbers as they are; any other literal a notebook
    holds (a list, a dict, a tuple: a drawing's object, say) as its Python text, which the process reads back with
    :func:`ast.literal_eval`, the notebook reader's own (literals only, nothing called); anything else a marker."""
    if value is None or isinstance(value, (str, bool, float)):
        return value
    if isinstance(value, int):
        return value if value.bit_length() <= 1000 else {"huge": value < 0}
    if isinstance(value, NotData):
        return {"not_data": value.reason}
    try:
        text = repr(value)  # a literal's own text: the notebook's literals are of Python's own types
        if ast.literal_eval(text) == value:  # the very value back (not a nan, nor a number too long to write)
            return {"literal": text, "type": type(value).__name__}
    except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
        pass
    return {"type": type(value).__name__}


def decode(data):
    """:func:`encode` undone."""
    if not isinstance(data, dict):
        return data
    if isinstance(data.get("literal"), str):
        try:
            return ast.literal_eval(data["literal"])
        except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
            pass
    if "not_data" in data:
        return NotData(str(data["not_data"]))
    if "huge" in data:
        return -(10**400) if data["huge"] else 10**400
    return _TYPES.get(data.get("type"), object)()


_NO_CLAIM = object()


def submission(student: str, answers: dict, claimed=_NO_CLAIM, *, refused: str | None = None) -> dict:
    """One submission for :func:`grade_submissions`: whom to grade, their answers and, to be checked against
    ``student``, the id the notebook carries (None when it carries none); or, with ``refused``, why the
    hand-in is not graded (:data:`graphkin.exercises.handins.REFUSALS`)."""
    out = {"student": student, "answers": {k: encode(v) for k, v in answers.items()}}
    if claimed is not _NO_CLAIM:
        out["claimed"] = encode(claimed)
    if refused:
        out["refused"] = refused
    return out


def grade_submissions(keys_file, submissions: list[dict], *, vendor=None, python: str | None = None,
                      timeout: float = TIMEOUT) -> list[dict]:
    """Grade submissions (each from :func:`submission`) in a fresh, isolated Python process.

    Parameters
    ----------
    keys_file : str or Path
        The keys (:func:`graphkin.exercises.keys.make_keys`) as a JSON file.
    submissions : list of dict
    vendor : str or Path, optional
        A folder holding the ``graphkin`` package to import (the copy the export carries); by default
        the folder of the graphkin this process imported.
    python : str, optional
        The interpreter (default: this one).
    timeout : float
        Seconds before the process is stopped.

    Returns
    -------
    list of dict
        One report per submission (:func:`grade_one`).

    Raises
    ------
    GraphkinError
        The process failed or timed out (its last lines of stderr in the message, for the teacher).
    """
    request = json.dumps({"keys": os.fspath(os.path.abspath(keys_file)), "submissions": submissions})
    env = {k: os.environ[k] for k in _KEEP if k in os.environ}
    env.setdefault("PATH", os.defpath)
    env.setdefault("LANG", "C.UTF-8")
    with tempfile.TemporaryDirectory(prefix="graphkin-grade-") as cwd:
        try:
            done = subprocess.run([python or sys.executable, "-I", "-c", _BOOT, os.fspath(vendor or _HOME)],
                                  input=request, capture_output=True, text=True, encoding="utf-8", env=env, cwd=cwd,
                                  timeout=timeout)
        except subprocess.TimeoutExpired:
            raise GraphkinError(f"the grading process took more than {timeout:g} s and was stopped") from None
    if done.returncode != 0:
        tail = "\n".join(done.stderr.strip().splitlines()[-8:])
        raise GraphkinError(f"the grading process failed (exit code {done.returncode}):\n{tail}")
    return json.loads(done.stdout)["reports"]


def refused(exercise, student: str, reason: str) -> dict:
    """A report for a submission that is not graded: every question 0 points with ``reason``."""
    questions = [{"id": q.id, "verdict": "refused", "slip": None, "score": 0.0, "max": q.points, "feedback": reason,
                  "answer": ""} for q in exercise.questions]
    return {"exercise": exercise.id, "student": echo(student, 100), "score": 0.0,
            "max": sum(q.points for q in exercise.questions), "questions": questions, "ignored": [],
            "refused": reason}


def grade_one(keys: Keys, student, answers: dict, claimed=_NO_CLAIM, *, reveal=None, feedback=None) -> dict:
    """A submission's report: graded as ``student`` with the keys, or refused with a sentence.

    It is refused when ``student`` is not on the roster or, when ``claimed`` is given (the id the notebook
    carries, None if it carries none), when that is not ``student``.
    """
    ex = keys.exercise
    if claimed is not _NO_CLAIM:
        if not isinstance(claimed, str) or not claimed.strip():
            by = f"; it was handed in by {echo(str(student), 100)!r}" if str(student).strip() else ""
            return refused(ex, str(student), "This notebook carries no student id (type yours in the STUDENT cell, "
                                             f"in quotes, as your teacher gave it){by}.")
        wrong = runtime.identity_error(claimed, student)
        if wrong:
            return refused(ex, str(student), wrong[0].upper() + wrong[1:] + ".")
    try:
        variant = keys.variant(student)
    except GraphkinError as exc:
        text = str(exc)
        return refused(ex, str(student), text[0].upper() + text[1:] + ".")
    report = grade_variant(variant, answers, reveal=reveal, classmates=keys.classmates(), feedback=feedback)
    report["data"] = [g["shown"] for g in variant.sheet()["data"]]
    return report


def main() -> int:
    """The grading process: one JSON request on stdin, ``{"reports": [...]}`` on stdout."""
    request = json.loads(sys.stdin.read())
    out = sys.stdout
    with contextlib.redirect_stdout(sys.stderr):  # whatever else prints goes to the log, not into the answer
        keys = Keys(request["keys"])
        reports = []
        for sub in request["submissions"]:
            if sub.get("refused"):
                reports.append(refused(keys.exercise, sub["student"], REFUSALS[sub["refused"]]))
                continue
            answers = {str(k): decode(v) for k, v in sub["answers"].items()}
            claimed = decode(sub["claimed"]) if "claimed" in sub else _NO_CLAIM
            reports.append(grade_one(keys, sub["student"], answers, claimed))
    json.dump({"reports": reports}, out, ensure_ascii=False, allow_nan=False)
    out.flush()
    return 0


__all__ = ["TIMEOUT", "decode", "encode", "grade_one", "grade_submissions", "main", "refused", "submission"]
