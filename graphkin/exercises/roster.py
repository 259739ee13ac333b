"""Class files: a roster of student ids, and a class's answers, as CSV with a ``student`` column.

Every id is normalised as the variants normalise it (:func:`graphkin.exercises.variants.check_student`:
Unicode NFC, runs of white space as one space, none at either end), so ``"s001 "`` and ``"s001"`` are one
student, and a file naming a student twice is refused. Every error names the file and the line.
"""

from __future__ import annotations

import csv
import io

from graphkin.errors import GraphkinError
from graphkin.exercises.variants import check_student
from graphkin.files import read_text

MAX_ROSTER = 100_000
"""The most rows a class file may have."""


def read_class_csv(path, what: str) -> list[dict]:
    """The rows of a class CSV (a roster, or answers) with a ``student`` column, ids normalised.

    Parameters
    ----------
    path : str or Path
        The CSV file (``-`` reads standard input).
    what : str
        What the file is ("roster", "answers"), to start the message of an error.

    Returns
    -------
    list of dict
        One dict per row, column name -> text, with the id under ``"student"`` and the row's line in the
        file under ``"#line"`` (a name no question id can have).

    Raises
    ------
    GraphkinError
        Naming the file and the line: a file that cannot be read or is not CSV (a NUL byte, a broken
        quote), no ``student`` column, more than :data:`MAX_ROSTER` rows, an empty or unusable id, or a
        student named twice.
    """
    text = read_text(path, what)
    nul = text.find("\x00")  # (read_text refuses a file with NUL bytes; standard input is checked here)
    if nul >= 0:
        raise GraphkinError(f"{what} {path}: line {text.count(chr(10), 0, nul) + 1}: a NUL byte; the file is not "
                            "plain text (save it as CSV, UTF-8)")
    # A field may be as long as the file: one 1 MB answer is that answer's problem (the reader refuses it with
    # a sentence), not the whole class file's (csv refuses fields over 128 kB by default).
    csv.field_size_limit(max(csv.field_size_limit(), min(len(text) + 1, 2**31 - 1)))
    # strict: a broken quote is an error at its line, not a field that runs to the end of the file.
    reader = csv.DictReader(io.StringIO(text), strict=True)
    rows = []
    try:
        for row in reader:
            row["#line"] = reader.line_num
            rows.append(row)
            if len(rows) > MAX_ROSTER:
                raise GraphkinError(f"{what} {path}: more than {MAX_ROSTER} rows")
    except csv.Error as exc:
        raise GraphkinError(f"{what} {path}: line {reader.line_num}: not readable as CSV ({exc})") from None
    fields = [(f or "").strip().lower() for f in reader.fieldnames or []]
    if "student" not in fields:
        raise GraphkinError(f"{what} {path}: needs a header row with a 'student' column "
                            f"(found: {', '.join(reader.fieldnames or []) or 'no header'})")
    key = (reader.fieldnames or [])[fields.index("student")]
    seen: dict[str, int] = {}
    for row in rows:
        n = row["#line"]
        raw = row.pop(key) or ""
        if not raw.strip():
            raise GraphkinError(f"{what} {path}: line {n}: the student id is empty")
        try:
            student = check_student(raw)
        except GraphkinError as exc:
            raise GraphkinError(f"{what} {path}: line {n}: {exc}") from None
        if student in seen:
            raise GraphkinError(f"{what} {path}: line {n}: student {student!r} is already on line {seen[student]}")
        seen[student] = n
        row["student"] = student
    return rows


_FORMULA = ("=", "+", "-", "@", "\t", "\r")


def spreadsheet_text(value):
    """A cell of a class table as a spreadsheet must show it: text that begins as a formula does (``=``, ``+``,
    ``-``, ``@``, a tab or a carriage return; a student's id or answer may) with a leading apostrophe, which
    spreadsheets read as "this is text"; anything else as it is.

    >>> spreadsheet_text("=1+1"), spreadsheet_text("s1"), spreadsheet_text(-2.5)
    ("'=1+1", 's1', -2.5)
    """
    return "'" + value if isinstance(value, str) and value.startswith(_FORMULA) else value


def spreadsheet_rows(rows) -> list[dict]:
    """Rows of a class table with every cell :func:`spreadsheet_text`."""
    return [{k: spreadsheet_text(v) for k, v in row.items()} for row in rows]


def read_roster(path) -> list[str]:
    """The student ids of a roster, in its order: a CSV with a ``student`` column, any others ignored.

    Parameters
    ----------
    path : str or Path
        The CSV file, as a platform exports a class list (``-`` reads standard input).

    Returns
    -------
    list of str
        The ids, normalised as :func:`read_class_csv` does (stray spaces removed).

    Raises
    ------
    GraphkinError
        If the file cannot be read or is not such a roster (the message names the file and the problem).
    """
    return [row["student"] for row in read_class_csv(path, "roster")]
