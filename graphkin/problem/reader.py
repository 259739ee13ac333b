"""Reading a TOML file's fields into SI values with messages that name the file and the field."""

from __future__ import annotations

import difflib
import math
from pathlib import Path

from graphkin.errors import ProblemFileError
from graphkin.problem.tables import DECIMALS
from graphkin.ranges import complaint
from graphkin.units import to_si, to_si_array, to_si_vector


class FieldReader:
    """Reads the fields of one TOML file into SI values, every error naming the file and the field.

    Problem, exercise and flywheel files are read with it: unknown fields get a
    "did you mean" hint, values go through :func:`graphkin.units.to_si` and are
    checked against graphkin's ranges (:mod:`graphkin.ranges`).

    Parameters
    ----------
    file : str
        The file's name as messages show it.
    """

    base: str | Path | None = None
    """The file's path, where a CSV named in it is read from (None for text with no file)."""

    def __init__(self, file: str):
        self.file = file

    def fail(self, where: str, message: str):
        return ProblemFileError(self.file, where, message)

    def table(self, value, where, allowed) -> dict:
        if not isinstance(value, dict):
            raise self.fail(where, f"must be a table, got {type(value).__name__}")
        for key in value:
            if key not in allowed:
                close = difflib.get_close_matches(key, sorted(allowed), n=1)
                hint = f" (did you mean {close[0]!r}?)" if close else f" (allowed: {', '.join(sorted(allowed))})"
                raise self.fail(f"{where}.{key}" if where else key, f"unknown field{hint}")
        return value

    def need(self, t: dict, key: str, where: str):
        if key not in t:
            raise self.fail(f"{where}.{key}" if where else key, "is missing")
        return t[key]

    def si(self, value, dimension, where, kind="auto"):
        """``value`` in SI, inside the range of ``kind`` (:mod:`graphkin.ranges`).

        ``kind="auto"`` takes the dimension's range (:data:`KIND`); None
        checks none (the caller checks the sign first, with its own message).
        """
        x = to_si(value, dimension, field=where, file=self.file)
        self.ranged(x, value, KIND.get(dimension) if kind == "auto" else kind, where)
        return x

    def ranged(self, x, raw, kind, where):
        """Refuse a value outside the range graphkin accepts for ``kind``, naming the field and showing it as written."""
        if kind is None:
            return
        why = complaint(x, kind)
        if why is not None:
            raise self.fail(where, f"{shown(raw)} {why}")

    def vec(self, value, dimension, where):
        x, y = to_si_vector(value, dimension, field=where, file=self.file)
        kind = KIND.get(dimension)
        if isinstance(value, dict):
            self.ranged(math.hypot(x, y), value.get("magnitude"), kind, f"{where}.magnitude")
        else:
            for i, c in enumerate((x, y)):
                self.ranged(c, value[i], kind, f"{where}[{i}]")
        return (x, y)

    def array(self, value, dimension, where):
        if isinstance(value, dict):
            # A range is linear: its ends bound every value in it. They are checked first, so that a start of
            # "1e9 deg" is named as such rather than as a step that gives too many points.
            for end in ("start", "stop"):
                if end in value:
                    self.si(value[end], dimension, f"{where}.{end}")
        q = to_si_array(value, dimension, field=where, file=self.file)
        kind = KIND.get(dimension)
        if isinstance(value, list):
            for i, (x, raw) in enumerate(zip(q, value)):
                self.ranged(x, raw, kind, f"{where}[{i}]")
        elif not isinstance(value, dict):
            self.ranged(q[0], value, kind, where)
        return q

    def decimal(self, t: dict, where: str) -> str:
        """A table's declared decimal separator, ``t["decimal"]``: ``"."`` (the default) or ``","``.

        Only a table (``table`` or ``csv``) has numbers to read with it.
        """
        if "decimal" not in t:
            return "."
        if "table" not in t and "csv" not in t:
            raise self.fail(f"{where}.decimal", "is the decimal separator of a table: give it beside table or csv")
        value = t["decimal"]
        if value not in DECIMALS:
            raise self.fail(f"{where}.decimal", f'must be "." or "," (the decimal separator of the table\'s numbers), '
                            f"got {value!r}")
        return value

    def whole(self, value, where) -> int:
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.fail(where, f"must be a whole number, got {value!r}")
        return value

    def text(self, value, where) -> str:
        if not isinstance(value, str):
            raise self.fail(where, f"must be a string, got {value!r}")
        return value

    def point(self, value, where):
        """A point: ["x mm", "y mm"] or {r = "467 mm", angle = "7.6 deg"} (polar about the link origin)."""
        if isinstance(value, dict) and set(value) <= {"r", "angle"} and "r" in value:
            r = self.si(value["r"], "length", f"{where}.r")
            a = self.si(self.need(value, "angle", where), "angle", f"{where}.angle")
            return (r * math.cos(a), r * math.sin(a))
        if isinstance(value, dict):
            raise self.fail(where, 'a point is ["x mm", "y mm"] or {r = "…mm", angle = "…deg"}')
        return self.vec(value, "length", where)


KIND = {"length": "coordinate", "angle": "angle", "mass": "mass", "moment_of_inertia": "moment_of_inertia",
         "density": "density", "angular_velocity": "angular_velocity", "angular_acceleration": "angular_acceleration",
         "velocity": "velocity", "acceleration": "acceleration", "force": "force", "torque": "torque",
        "pressure": "pressure", "power": "power", "stiffness": "stiffness"}
"""The range (:data:`graphkin.ranges.RANGES`) a value of each dimension is checked against, unless the
field says more (a radius is a ``length``, which must not be zero; a friction coefficient is ``friction``)."""


def shown(raw) -> str:
    """A value as the file wrote it, for a message: ``"1e-200 kg"`` (quoted when it is text)."""
    return f'"{raw}"' if isinstance(raw, str) else repr(raw)
