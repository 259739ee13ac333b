"""Tables of values against an angle (a torque curve), written inline in a TOML file or in a CSV file beside it.

A table is CSV text whose first line names each column with its units in
brackets, one row per line after it::

    angle [deg], torque [N*m]
    0,    0
    15,   2800
    30,   2090

The same text may be the value of a ``table`` field (a TOML multi-line
string) or the content of a ``.csv`` file named by a ``csv`` field, read
relative to the TOML file. Blank lines and lines starting with ``#`` are
skipped. Every error names the file, the field and the line.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np

from graphkin.errors import ProblemFileError
from graphkin.units import to_si

_HEADER = re.compile(r"^\s*(?P<name>[A-Za-z_][\w ]*?)\s*\[(?P<unit>[^\]]+)\]\s*$")


def parse_table(text: str, columns: dict[str, str], *, file: str, field: str, shown: str | None = None) -> dict:
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

    lines = [(k + 1, line) for k, line in enumerate(text.splitlines()) if line.strip() and not line.lstrip().startswith("#")]
    names = list(columns)
    example = ", ".join(f"{n} [{_UNIT_HINT.get(columns[n], 'unit')}]" for n in names)
    if not lines:
        raise fail(None, f"is empty: write a header line ({example}) and one row per line")
    head_no, head = lines[0]
    cells = [c.strip() for c in head.split(",")]
    if len(cells) != len(names):
        raise fail(head_no, f"the header must name {len(names)} columns with their units, e.g. '{example}', got {head!r}")
    scale = []
    for cell, name in zip(cells, names):
        m = _HEADER.match(cell)
        if not m or m["name"].strip().lower() != name:
            raise fail(head_no, f"the header's column {cell!r} must be {name} with its units in brackets, e.g. '{example}'")
        scale.append(to_si(f"1 {m['unit'].strip()}", columns[name], field=f"{field} ({where}header, {name})", file=file))
    rows = []
    for no, line in lines[1:]:
        cells = [c.strip() for c in line.split(",")]
        if len(cells) != len(names):
            raise fail(no, f"has {len(cells)} cells, the header {len(names)}: {line.strip()!r}")
        row = []
        for cell, name in zip(cells, names):
            try:
                x = float(cell)
            except ValueError:
                raise fail(no, f"{name} {cell!r} is not a number (units go in the header)") from None
            if not math.isfinite(x):
                raise fail(no, f"{name} {cell!r} is not a finite number")
            row.append(x)
        rows.append(row)
    if len(rows) < 2:
        raise fail(None, f"has {len(rows)} row{'s' * (len(rows) != 1)}: a curve needs at least two")
    data = np.array(rows, dtype=float)
    return {name: data[:, k] * s for k, (name, s) in enumerate(zip(names, scale))}


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
