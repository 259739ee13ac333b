"""One class table from the ``results.json`` files a platform wrote: ``otter run`` (one per notebook) or
Gradescope's autograder (one per submission).

Each file holds graphkin's summary line, ``Graded as student 's001': 2.5 / 3 points.``, and one test per
question (otter names it after the question id; the Gradescope export ``"<id>: <question>"``). The table
has a row per file: the student, the score, the maximum, each question's points, and the file.
"""

from __future__ import annotations

import ast
import html
import json
import re
from pathlib import Path

from graphkin.errors import GraphkinError

_GRADED = re.compile(r"Graded as student ('(?:[^'\\]|\\.)*'|\"(?:[^\"\\]|\\.)*\")")
_REFUSED = re.compile(r"^Not graded: (.*)$", re.MULTILINE)


def find_results(paths) -> list[Path]:
    """The ``results.json`` files named, or found in the folders named (recursively), in path order."""
    found = []
    for p in map(Path, paths):
        if p.is_dir():
            found += sorted(p.rglob("results.json"))
        elif p.is_file():
            found.append(p)
        else:
            raise GraphkinError(f"{p}: no such file or folder")
    if not found:
        raise GraphkinError(f"no results.json in {', '.join(map(str, paths))}")
    return found


def student_of(results: dict) -> str | None:
    """The student a results file was graded as, from graphkin's summary line (None if it has none)."""
    m = _GRADED.search(results.get("output") or "")
    if m is None:
        return None
    try:
        return html.unescape(ast.literal_eval(m[1]))  # otter's output is escaped (the plugin escapes it)
    except (ValueError, SyntaxError):
        return None


def refusal_of(results: dict) -> str | None:
    """Why a results file's submission was not graded, from graphkin's summary (None when it was graded)."""
    m = _REFUSED.search(results.get("output") or "")
    return html.unescape(m[1]) if m else None


def row_of(results: dict, file: str) -> dict:
    """A class-table row for one results file (a hand-in that could not be read has no student: its file names it)."""
    tests = [t for t in results.get("tests", []) if isinstance(t, dict) and "score" in t and "max_score" in t]
    student = student_of(results)
    row = {"student": student or "", "score": results.get("score", sum(t["score"] for t in tests)),
           "max": sum(t["max_score"] for t in tests)}
    for t in tests:
        row[str(t.get("name", "")).split(":")[0]] = t["score"]
    refused = refusal_of(results)
    if refused:
        row["refused"] = refused
    if student is None:
        row["error"] = "no graphkin summary in this file (not graded by graphkin's plugin or autograder)"
    row["file"] = file
    return row


def class_table(files) -> list[dict]:
    """A row per results file, sorted by student (see :func:`row_of`).

    Raises
    ------
    GraphkinError
        A file that cannot be read as JSON, naming it.
    """
    rows = []
    for f in files:
        try:
            results = json.loads(Path(f).read_text(encoding="utf-8"))
        except (OSError, ValueError) as exc:
            raise GraphkinError(f"{f}: not a results.json ({exc})") from None
        rows.append(row_of(results if isinstance(results, dict) else {}, str(f)))
    return sorted(rows, key=lambda r: (r["student"] == "", r["student"], r["file"]))


def repeated(rows: list[dict]) -> dict[str, list[str]]:
    """Students graded in more than one results file (student → the files): under ``otter run`` the id typed
    in a notebook decides whom it is graded as, so two files for one student need a look."""
    files: dict[str, list[str]] = {}
    for r in rows:
        if r["student"]:
            files.setdefault(r["student"], []).append(r["file"])
    return {s: f for s, f in files.items() if len(f) > 1}


__all__ = ["class_table", "find_results", "refusal_of", "repeated", "row_of", "student_of"]
