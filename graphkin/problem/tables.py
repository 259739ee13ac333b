"""Tables of values against an angle (a torque curve), written inline in a TOML file or in a CSV file beside it.

A table is CSV text whose first line names each column with its units in
brackets, one row per line after it::

    angle [deg], torque [N*m]
    0,    0
    15,   2800
    30,   2090

The same text may be the value of a ``table`` field (a TOML multi-line
string) or the content of a ``.csv`` file named by a ``csv`` field, read
relative to the TOML file. It is read with Python's :mod:`csv`: the
delimiter is found from the text (a comma, a semicolon or a tab: a
spreadsheet in a language that writes 2800,5 exports ``angle [deg];torque
[N*m]``), fields may be quoted, and a delimiter at the end of a line is
allowed. A decimal comma is read where the file says so (``decimal = ","``
beside ``csv`` or ``table``); the delimiter is then a semicolon or a tab.
Blank lines and lines starting with ``#`` are skipped. Every error names the
file, the field and the line.
"""

from __future__ import annotations

import csv
import math
import re
from pathlib import Path

import numpy as np

from graphkin.errors import ModelError, ProblemFileError
from graphkin.model import Table
from graphkin.units import to_si

_HEADER = re.compile(r"^\s*(?P<name>[A-Za-z_][\w ]*?)\s*\[(?P<unit>[^\]]+)\]\s*$")

DELIMITERS = ",;\t"
"""The delimiters a table's columns may be separated by."""

DECIMALS = (".", ",")
"""The decimal separators a table may declare (``decimal`` in the TOML file; a point by default)."""


def _delimiter(lines: list[str], decimal: str) -> str:
    """The delimiter of a table's lines: the one csv.Sniffer finds among :data:`DELIMITERS` (a comma when
    the lines give no sign, e.g. a single column), never the decimal separator."""
    allowed = DELIMITERS.replace(decimal, "")
    try:
        found = csv.Sniffer().sniff("\n".join(lines[:20]), delimiters=allowed).delimiter
    except csv.Error:
        found = None
    if found and found in allowed:
        return found
    for d in allowed:  # a table of one row the sniffer cannot judge: the first delimiter the header uses
        if d in lines[0]:
            return d
    return allowed[0]


def parse_table(text: str, columns: dict[str, str], *, file: str, field: str, shown: str | None = None,
                decimal: str = ".") -> dict:
    """Read a table with a header of named columns and units, into SI arrays.

    Parameters
    ----------
    text : str
        The CSV text (header line first).
    columns : dict of str to str
        The columns wanted, name → dimension (:data:`graphkin.units.DIMENSIONS`),
        e.g. ``{"angle": "angle", "torque": "torque"}``, in the order they
        must appear.
    file, field : str
        Where the table is, for messages (the TOML file and ``driving.table``).
    shown : str, optional
        The CSV file's name, put before line numbers in messages.
    decimal : {".", ","}
        The decimal separator of the numbers (a comma: the delimiter is then a
        semicolon or a tab).

    Returns
    -------
    dict of str to ndarray, shape (n,)
        Each column in SI units.

    Raises
    ------
    ProblemFileError
        A missing or misspelt header, a unit of the wrong dimension, a row
        with the wrong number of cells, a cell that is not a finite number,
        or fewer than two rows.
    """
    where = f"{shown} " if shown else ""

    def fail(line: int | None, message: str):
        at = f"{where}line {line}: " if line is not None else where
        return ProblemFileError(file, field, at + message)

    numbered = [(k + 1, line) for k, line in enumerate(text.splitlines())
                if line.strip() and not line.lstrip().startswith("#")]
    names = list(columns)
    example = ", ".join(f"{n} [{_UNIT_HINT.get(columns[n], 'unit')}]" for n in names)
    if not numbered:
        raise fail(None, f"is empty: write a header line ({example}) and one row per line")
    delimiter = _delimiter([line for _, line in numbered], decimal)
    try:
        rows = list(csv.reader([line for _, line in numbered], delimiter=delimiter, skipinitialspace=True))
    except csv.Error as exc:
        raise fail(None, f"is not readable CSV ({exc})") from None
    for cells in rows:
        while len(cells) > len(names) and not cells[-1].strip():
            cells.pop()  # a delimiter at the end of the line
    (head_no, head), cells = numbered[0], [c.strip() for c in rows[0]]
    if len(cells) != len(names):
        raise fail(head_no, f"the header must name {len(names)} columns with their units, e.g. '{example}', got {head!r}")
    scale = []
    for cell, name in zip(cells, names):
        m = _HEADER.match(cell)
        if not m or m["name"].strip().lower() != name:
            raise fail(head_no, f"the header's column {cell!r} must be {name} with its units in brackets, e.g. '{example}'")
        scale.append(to_si(f"1 {m['unit'].strip()}", columns[name], field=f"{field} ({where}header, {name})", file=file))
    values = []
    for (no, line), cells in zip(numbered[1:], rows[1:]):
        if len(cells) != len(names):
            raise fail(no, f"has {len(cells)} cells, the header {len(names)}: {line.strip()!r}")
        row = []
        for cell, name in zip((c.strip() for c in cells), names):
            row.append(_number(cell, decimal, lambda message, no=no: fail(no, message), name))
        values.append(row)
    if len(values) < 2:
        raise fail(None, f"has {len(values)} row{'s' * (len(values) != 1)}: a curve needs at least two")
    data = np.array(values, dtype=float)
    return {name: data[:, k] * s for k, (name, s) in enumerate(zip(names, scale))}


def _number(cell: str, decimal: str, fail, name: str) -> float:
    """A cell's number, with the table's decimal separator; a clear message where it is not one."""
    text = cell.replace(",", ".") if decimal == "," else cell
    try:
        x = float(text)
    except ValueError:
        hint = (' (it has a decimal comma: write decimal = "," beside the table in the TOML file)'
                if decimal == "." and re.fullmatch(r"[+-]?\d+,\d+", cell) else "")
        raise fail(f"{name} {cell!r} is not a number (units go in the header){hint}") from None
    if not math.isfinite(x):
        raise fail(f"{name} {cell!r} is not a finite number")
    return x


_UNIT_HINT = {"angle": "deg", "torque": "N*m", "force": "N", "length": "mm"}


def read_csv_beside(name, base: str | Path, *, file: str, field: str) -> tuple[str, str]:
    """The text of the CSV file ``name``, relative to the folder of ``base`` (the TOML file); and the name to show.

    Raises
    ------
    ProblemFileError
        If ``name`` is not a file name ending in ``.csv``, or the file cannot be read as UTF-8 text.
    """
    if not isinstance(name, str) or not name.strip():
        raise ProblemFileError(file, field, f"must be the name of a CSV file beside the problem file, got {name!r}")
    if not name.lower().endswith(".csv"):
        raise ProblemFileError(file, field, f"{name!r}: the file must end in .csv")
    path = Path(name)
    if not path.is_absolute():
        path = Path(base).parent / path
    try:
        return path.read_text(encoding="utf-8-sig"), name
    except FileNotFoundError:
        raise ProblemFileError(file, field, f"{name!r}: no such file (looked for {path})") from None
    except IsADirectoryError:
        raise ProblemFileError(file, field, f"{name!r} is a folder, not a CSV file") from None
    except UnicodeDecodeError:
        raise ProblemFileError(file, field, f"{name!r} is not UTF-8 text") from None
    except OSError as exc:
        raise ProblemFileError(file, field, f"{name!r} cannot be read ({exc.strerror or exc})") from None


def load_table(rd, t, where, kind, driver_kind):
    """A load's ``table`` (CSV text inline) or ``csv`` (a file beside the problem file), as a :class:`Table`."""
    given = [k for k in ("table", "csv") if k in t]
    decimal = rd.decimal(t, where)
    if not given:
        return None
    if len(given) == 2:
        raise rd.fail(f"{where}.csv", "give the table inline (table) or in a file (csv), not both")
    field = f"{where}.{given[0]}"
    x = "angle" if driver_kind == "crank" else "position"
    columns = {x: "angle" if driver_kind == "crank" else "length", kind: kind}
    if given[0] == "table":
        if not isinstance(t["table"], str):
            unit = "deg" if x == "angle" else "mm"
            raise rd.fail(field, f"must be CSV text in a TOML multi-line string: a header line such as "
                          f"'{x} [{unit}], {kind} [{ {'force': 'N', 'pressure': 'MPa'}.get(kind, 'N*m')}]' and one row per line; "
                          f"got {t['table']!r:.40}")
        text, shown = t["table"], None
    else:
        if rd.base is None:
            raise rd.fail(field, "a CSV table is read from the problem file's folder: load the problem from its file "
                          "(load_problem), or give the table inline with table = \"\"\"…\"\"\"")
        text, shown = read_csv_beside(t["csv"], rd.base, file=rd.file, field=field)
    cols = parse_table(text, columns, file=rd.file, field=field, shown=shown, decimal=decimal)
    try:
        return Table(cols[x], cols[kind], periodic=driver_kind == "crank", source=shown or "")
    except ModelError as exc:
        raise rd.fail(field, str(exc).split(": ", 1)[-1]) from None
