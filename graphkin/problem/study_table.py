"""A problem file's ``[study]`` table: the designs a study of it tries, in the words of ``graphkin study --vary``.

::

    [study]
    vary = { "links[0].points.A[0]" = "60..120 mm:7", "links[1].mass" = ["1 kg", "2 kg", "4 kg"] }
    n = 360                                         # crank angles per design (default: the file's positions)
    Cs = 0.05                                       # the flywheels' coefficient of speed fluctuation
    best = "torque_peak"                            # the figure of merit the best design has least of
    require = ["transmission_angle_min >= 40 deg"]  # limits the best design (and the optimum) must meet
    optimize = "minimise torque_peak"               # scipy.optimize between the grid's values (``study`` extra)

Each entry of ``vary`` is a field of the file by its path (:mod:`graphkin.problem.fields`) and its values: a range
``"FROM..TO UNIT:N"`` (N equally spaced values), a list of values as the file writes them (``"2 kg"``, or a point
``["80 mm", "0 mm"]``), or a list written on one line, ``"2 kg, 3 kg, 5 kg"``. ``graphkin study FILE`` and
``gk.study(FILE)`` use the table when no ``--vary`` (``vary=``) is given. The file is still a problem file: a
solve, a handout or an explorer of it ignores the table, once it has checked that every entry reads.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from graphkin.errors import GraphkinError
from graphkin.problem.fields import missing

__all__ = ["FORM", "MAX_DESIGNS", "StudyTable", "parse_values", "read_study"]

MAX_DESIGNS = 100_000
"""The most designs one study solves (the product of the numbers of values of its fields)."""

KEYS = ("vary", "n", "Cs", "best", "require", "optimize")
"""The fields of a ``[study]`` table."""

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_RANGE = re.compile(r"\s*(?P<a>[-+]?[\d.]+(?:[eE][-+]?\d+)?)\s*\.\.\s*(?P<b>[-+]?[\d.]+(?:[eE][-+]?\d+)?)"
                    r"\s+(?P<unit>\S(?:.*\S)?)\s*:\s*(?P<n>\d+)\s*")
"""``FROM..TO UNIT:N``: two numbers, the unit they are in, and how many equally spaced values from one to the other."""
_VALUE = re.compile(rf"\s*{_NUMBER}\s*(?:[^\s,\d.+-][^,]*)?")
"""One value of a list written on one line: a number and its unit (``2 kg``)."""

FORM = 'FROM..TO UNIT:N (e.g. "2..4 kg:11") or a list V1, V2, ... (e.g. "2 kg, 3 kg, 5 kg")'
"""How the values of a varied field are written, for messages."""


@dataclass(frozen=True)
class StudyTable:
    """A ``[study]`` table as read: each varied field's values as the file writes them, and what to choose by.

    Attributes
    ----------
    vary : dict of str to tuple
        Each field's path and its values (problem-file values with units), in the table's order.
    n : int or None
        Crank angles per design (None: the problem's own positions).
    Cs : float or None
        The coefficient of speed fluctuation the flywheels are sized for (None: the study's default).
    best : str or None
        The figure of merit the best design has least of.
    require : tuple of str
        Limits ``"FIGURE OP VALUE UNIT"`` the best design and the optimum must meet.
    optimize : str or None
        ``"minimise FIGURE"`` or ``"maximise FIGURE"``: the optimum between the grid's values.
    """

    vary: dict
    n: int | None = None
    Cs: float | None = None
    best: str | None = None
    require: tuple = ()
    optimize: str | None = None


def parse_values(text: str) -> list[str] | None:
    """The values of one varied field written as text: ``"FROM..TO UNIT:N"`` or ``"2 kg, 3 kg, 5 kg"``.

    Returns
    -------
    list of str or None
        The values as a problem file writes them (``"62.5 mm"``; a range's as ``f"{x!r} {unit}"``); None if the
        text is neither form (:data:`FORM`).

    Raises
    ------
    GraphkinError
        A range whose ends are not numbers, or whose N (1 to :data:`MAX_DESIGNS`) and ends disagree.
    """
    import numpy as np

    if not isinstance(text, str):
        return None
    m = _RANGE.fullmatch(text)
    if m is None:
        parts = text.split(",") if ".." not in text else []
        return [p.strip() for p in parts] if parts and all(_VALUE.fullmatch(p) for p in parts) else None
    try:
        a, b = float(m["a"]), float(m["b"])
    except ValueError:
        raise GraphkinError(f"{m['a']}..{m['b']} is not a range of two numbers") from None
    n = int(m["n"])
    why = None
    if not 1 <= n <= MAX_DESIGNS:
        why = f"N = {n}: give from 1 to {MAX_DESIGNS:,} values"
    elif n == 1 and a != b:
        why = f"N = 1 value cannot span {m['a']}..{m['b']}; give N ≥ 2"
    elif n > 1 and a == b:
        why = f"{n} values from {m['a']} to {m['b']} would all be equal; give N = 1 or two different ends"
    if why:
        raise GraphkinError(why)
    return [f"{x!r} {m['unit']}" for x in np.linspace(a, b, n).tolist()]


def read_study(rd, value: Any, data: dict) -> StudyTable:
    """The ``[study]`` table of problem data ``data``, every entry checked; a fault names its field.

    Parameters
    ----------
    rd : graphkin.problem.FieldReader
        The file's reader (its messages name the file).
    value : Any
        ``data["study"]``.
    data : dict
        The whole file's data: each varied field must be one of its fields.

    Raises
    ------
    graphkin.errors.ProblemFileError
        Naming the field: ``study.vary.links[1].mass``, ``study.n``, ...
    """
    t = rd.table(value, "study", set(KEYS))
    vary = rd.need(t, "vary", "study")
    if not isinstance(vary, dict):
        raise rd.fail("study.vary", f'must be a table of fields and their values, got {vary!r:.60}')
    if not vary:
        raise rd.fail("study.vary", 'name one or more fields and their values, e.g. vary = { "links[1].mass" = '
                      '"1..4 kg:7" }')
    out, count = {}, 1
    for field, values in vary.items():
        where = f"study.vary.{field}"
        try:
            gap = missing(data, field)
        except KeyError:
            raise rd.fail(where, "is not a field path (tables and keys joined by dots, list items by [index], "
                          "e.g. links[1].mass)") from None
        if gap is not None:
            raise rd.fail(where, f"the problem has no {gap}")
        if isinstance(values, str):
            try:
                values = parse_values(values)
            except GraphkinError as exc:
                raise rd.fail(where, f"{values!r}: {exc}") from None
            if values is None:
                raise rd.fail(where, f"write its values {FORM}, got {vary[field]!r}")
        elif not isinstance(values, list) or not values:
            raise rd.fail(where, f'give a range "FROM..TO UNIT:N" or a list of one or more values, got {values!r:.60}')
        out[field] = tuple(values)
        count *= len(values)
    if count > MAX_DESIGNS:
        raise rd.fail("study.vary", f"{count:,} designs is more than {MAX_DESIGNS:,}; take fewer values")
    n = t.get("n")
    if n is not None and (rd.whole(n, "study.n") < 2):
        raise rd.fail("study.n", f"give at least 2 crank angles, got {n!r}")
    Cs = t.get("Cs")
    if Cs is not None and (isinstance(Cs, bool) or not isinstance(Cs, (int, float)) or not 0 < Cs < 2):
        raise rd.fail("study.Cs", f"the coefficient of speed fluctuation is a number above 0 and below 2, got {Cs!r}")
    best = rd.text(t["best"], "study.best") if "best" in t else None
    optimize = rd.text(t["optimize"], "study.optimize") if "optimize" in t else None
    require = t.get("require", [])
    if isinstance(require, str):
        require = [require]
    if not isinstance(require, list) or not all(isinstance(r, str) for r in require):
        raise rd.fail("study.require", f'give a list of limits, e.g. ["transmission_angle_min >= 40 deg"], got '
                      f"{require!r:.60}")
    if require and best is None and optimize is None:
        raise rd.fail("study.require", "a limit goes with best or optimize (the figure it chooses by)")
    return StudyTable(out, n, None if Cs is None else float(Cs), best, tuple(require), optimize)
