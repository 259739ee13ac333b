"""Class files: a roster of student ids, and a class's answers, as CSV with a ``student`` column."""

from __future__ import annotations

import csv
import io

from graphkin.errors import GraphkinError
from graphkin.files import read_text

MAX_ROSTER = 100_000
"""The most rows a class file may have."""


def read_class_csv(path, what: str) -> list[dict]:
    """The rows of a class CSV (a roster, or answers) with a ``student`` column, ids trimmed.

    Parameters
    ----------
    path : str or Path
        The CSV file (``-`` reads standard input).
    what : str
        What the file is ("roster", "answers"), to start the message of an error.

    Returns
    -------
    list of dict
        One dict per row, column name -> text, with the id under ``"student"``.

    Raises
    ------
    GraphkinError
        A file that cannot be read, is not CSV, has no ``student`` column or
        more than :data:`MAX_ROSTER` rows, or a row with an empty id.
    """
    text = read_text(path, what)
    try:
        reader = csv.DictReader(io.StringIO(text))
        rows = []
        for row in reader:
            rows.append(row)
            if len(rows) > MAX_ROSTER:
                raise GraphkinError(f"{what} {path}: more than {MAX_ROSTER} rows")
    except csv.Error as exc:
        raise GraphkinError(f"{what} {path}: not a readable CSV ({exc})") from None
    fields = [f.strip().lower() for f in reader.fieldnames or []]
    if "student" not in fields:
        raise GraphkinError(f"{what} {path}: needs a header row with a 'student' column "
                            f"(found: {', '.join(reader.fieldnames or []) or 'no header'})")
    key = (reader.fieldnames or [])[fields.index("student")]
    for n, row in enumerate(rows, start=2):
        if not (row.get(key) or "").strip():
            raise GraphkinError(f"{what} {path}: line {n}: the student id is empty")
        row["student"] = row.pop(key).strip()
    return rows


def read_roster(path) -> list[str]:
    """The student ids of a roster: a CSV with a ``student`` column (see :func:`read_class_csv`)."""
    return [row["student"] for row in read_class_csv(path, "roster")]
