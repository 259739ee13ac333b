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

from graphkin.errors import ModelError, ProblemFileError
from graphkin.model import Table
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


def load_table(rd, t, where, kind, driver_kind):
    """A load's ``table`` (CSV text inline) or ``csv`` (a file beside the problem file), as a :class:`Table`."""
    given = [k for k in ("table", "csv") if k in t]
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
    cols = parse_table(text, columns, file=rd.file, field=field, shown=shown)
    try:
        return Table(cols[x], cols[kind], periodic=driver_kind == "crank", source=shown or "")
    except ModelError as exc:
        raise rd.fail(field, str(exc).split(": ", 1)[-1]) from None
