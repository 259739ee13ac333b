"""Values as problem files write them (``"500 mm"``, a vector, a list, a range table) converted to SI floats."""

from __future__ import annotations

import math
import numbers
import re
from typing import Any, NamedTuple

import numpy as np

from graphkin.errors import ProblemFileError
from graphkin.ranges import MAX_POSITIONS
from graphkin.units.checks import check_unit, parse_unit
from graphkin.units.dimensions import (
    SI_UNITS,
    article,
    check_dimension,
    dimension_label,
    example_of,
    shown_number,
    type_name,
)
from graphkin.units.registries import known_factors, learn, registry

# A number, then (optionally) a unit expression.
_NUMBER_RE = re.compile(
    r"""^\s*(?P<number>
            [+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?
          | [+-]?(?:nan|inf(?:inity)?)(?![A-Za-z])
        )\s*(?P<unit>.*?)\s*$""",
    re.VERBOSE | re.IGNORECASE,
)


# Cap on the length of a range table, to catch a mistyped step; also the most positions a sweep solves at once.
_MAX_RANGE_POINTS = MAX_POSITIONS


# Relative tolerance for "stop lands on the grid" and "stop is a full turn".
_GRID_RTOL = 1e-9


# Strings already converted, (text, dimension) -> SI value: exercise variants
# re-read the same file hundreds of times, and pint takes ~50 µs a value.
# Only successes are kept, so every error still names its own file and field.
_CONVERTED: dict[tuple[str, str], float] = {}


_MAX_CONVERTED = 10_000


# Polar components smaller than this times the magnitude are set to 0.0, so
# that {magnitude = "5 N", angle = "90 deg"} gives exactly (0.0, 5.0).
POLAR_ZERO_RTOL = 1e-13


def _finite(x: float, raw: str, file: str, field: str) -> float:
    if not math.isfinite(x):
        raise ProblemFileError(
            file, field, f"{raw} is not a finite number (nan and inf are not allowed)"
        )
    return x


def _scalar_si(value: Any, dimension: str, file: str, field: str) -> float:
    """Convert one scalar value (string, number or pint Quantity) to SI."""
    if value is None or isinstance(value, (bool, np.bool_)):
        raise ProblemFileError(
            file,
            field,
            f"expected a value such as {example_of(dimension)}, "
            f"got {value!r}"
            + ("" if value is None else f" (a {type_name(value)})"),
        )
    if isinstance(value, (dict, list, tuple, set, bytes, np.ndarray)):
        raise ProblemFileError(
            file,
            field,
            f"expected a single value such as {example_of(dimension)}, "
            f"got a {type_name(value)}",
        )

    if isinstance(value, numbers.Real):
        x = float(value)
        if dimension == "dimensionless":
            return _finite(x, repr(x), file, field)
        text = shown_number(value)
        if dimension == "angle":
            raise ProblemFileError(
                file,
                field,
                f"units are missing: {text} could be degrees or radians; write it "
                f'as "{text} deg" or "{text} rad"',
            )
        raise ProblemFileError(
            file,
            field,
            f"units are missing: {article(dimension_label(dimension))} {dimension_label(dimension)} "
            f"needs units; write it as {example_of(dimension, text)}",
        )

    if not isinstance(value, str):
        if hasattr(value, "magnitude") and hasattr(value, "units"):
            return _quantity_si(value, dimension, file, field)
        raise ProblemFileError(
            file,
            field,
            f"expected a string such as {example_of(dimension)}, "
            f"got a {type_name(value)}",
        )

    known = _CONVERTED.get((value, dimension))
    if known is not None:
        return known
    raw = value.strip()
    match = _NUMBER_RE.match(value)
    if not raw or match is None or re.search(r"\d,\d", value):
        hint = ""
        if re.search(r"\d,\d", value):
            hint = " (use a decimal point, not a comma, and no thousands separator)"
        raise ProblemFileError(
            file,
            field,
            f'could not read "{value}": expected a number followed by units, '
            f"e.g. {example_of(dimension)}{hint}",
        )
    number_text, unit_text = match["number"], match["unit"]
    x = _finite(float(number_text), f'"{raw}"', file, field)

    if not unit_text:
        if dimension == "dimensionless":
            return x
        if dimension == "angle":
            raise ProblemFileError(
                file,
                field,
                f'units are missing: "{raw}" could be degrees or radians; write it '
                f'as "{number_text} deg" or "{number_text} rad"',
            )
        raise ProblemFileError(
            file,
            field,
            f'units are missing: "{raw}" has no units; write it as '
            f"{example_of(dimension, number_text)}",
        )

    factors = known_factors()
    factor = factors.get((unit_text, dimension))
    if factor is not None:
        si = _finite_si(x * factor, raw, file, field)
    else:
        unit = parse_unit(unit_text, raw, file, field)
        check_unit(unit, raw, dimension, file, field)
        ureg = registry()
        si = _finite_si(float(ureg.Quantity(x, unit).m_as(SI_UNITS[dimension] or "dimensionless")), raw, file, field)
        learn(ureg, unit, unit_text, dimension, x, si)
    if len(_CONVERTED) >= _MAX_CONVERTED:
        _CONVERTED.clear()
    _CONVERTED[(value, dimension)] = si
    return si


def _finite_si(x: float, raw: str, file: str, field: str) -> float:
    if not math.isfinite(x):
        raise ProblemFileError(
            file, field, f'"{raw}" is too large: it overflows when converted to SI'
        )
    return x


def _quantity_si(q: Any, dimension: str, file: str, field: str) -> float:
    """Convert a pint Quantity (from any registry) to SI."""
    ureg = registry()
    raw = str(q)
    try:
        unit = ureg.parse_units(str(q.units))
        magnitude = float(q.magnitude)
    except Exception:
        raise ProblemFileError(
            file, field, f"could not use the quantity {raw!r}"
        ) from None
    _finite(magnitude, raw, file, field)
    check_unit(unit, raw, dimension, file, field)
    si = ureg.Quantity(magnitude, unit).m_as(SI_UNITS[dimension] or "dimensionless")
    return _finite_si(float(si), raw, file, field)


def to_si(value: Any, dimension: str, *, field: str, file: str = "<input>") -> float:
    """Convert one value from a problem file to a float in SI units.

    Parameters
    ----------
    value : str, int, float or pint.Quantity
        A number followed by units, e.g. ``"500 mm"``, ``"900 rpm"``,
        ``"865 N*mm"``. A bare number (``0.3`` or ``"0.3"``) is accepted only
        for ``dimension="dimensionless"``.
    dimension : str
        A key of :data:`DIMENSIONS`, e.g. ``"length"``, ``"torque"``.
    field : str
        Dotted path of the field, e.g. ``"links[2].mass"``; used in messages.
    file : str, optional
        Path or catalog name of the problem file; used in messages.

    Returns
    -------
    float
        The value in the SI unit of :data:`SI_UNITS` (m, rad, kg, s, N, N*m,
        rad/s, ...).

    Raises
    ------
    graphkin.errors.ProblemFileError
        If the value has no units (where some are needed), the wrong
        dimension, an unknown or ambiguous unit, is not finite, or is not a
        scalar. The message names ``file`` and ``field``.
    ValueError
        If ``dimension`` is not a key of :data:`DIMENSIONS` (a programming
        error, not a problem-file error).

    Examples
    --------
    >>> to_si("500 mm", "length", field="crank.length")
    0.5
    >>> round(to_si("900 rpm", "angular_velocity", field="crank.speed"), 4)
    94.2478
    >>> to_si("865 N*mm", "torque", field="load")
    0.865
    """
    check_dimension(dimension)
    return _scalar_si(value, dimension, file, field)


class Written(NamedTuple):
    """How a problem file writes a value: its unit, that unit's size in SI, and the value's rounding in SI."""

    unit: str
    size: float
    rounding: float


def written(value: Any, dimension: str, *, field: str, file: str = "<input>") -> Written:
    """The unit a value is written in, the unit's size in SI, and the value's rounding as written.

    A book's number is rounded to the digits it prints: ``"862.5 rpm"`` stands for anything from 862.45 to
    862.55 rpm. The rounding is half a unit in the last digit written (``"1500 rpm"``: 0.5 rpm; ``"1.5e3 rpm"``:
    50 rpm), in SI. A value given as a number or a pint quantity has no written digits: its unit is the SI one
    and its rounding 0.

    Parameters
    ----------
    value : str, int, float or pint.Quantity
        As :func:`to_si` takes it (and checked as it checks it).
    dimension : str
        A key of :data:`DIMENSIONS`.
    field, file : str
        For messages, as :func:`to_si`.

    Returns
    -------
    Written
        ``unit`` (the text after the number), ``size`` (one of that unit in SI) and ``rounding`` (SI).

    Examples
    --------
    >>> w = written("862.5 rpm", "angular_velocity", field="speed")
    >>> w.unit, round(w.size, 6), round(w.rounding / w.size, 6)
    ('rpm', 0.10472, 0.05)
    """
    to_si(value, dimension, field=field, file=file)
    match = _NUMBER_RE.match(value) if isinstance(value, str) else None
    if match is None or not match["unit"]:
        return Written(SI_UNITS[dimension], 1.0, 0.0)
    mantissa, _, exponent = match["number"].lower().partition("e")
    last = 10.0 ** (int(exponent or 0) - len(mantissa.partition(".")[2]))
    size = to_si(f"1 {match['unit']}", dimension, field=field, file=file)
    return Written(match["unit"], size, 0.5 * last * size)


def to_si_vector(
    value: Any, dimension: str, *, field: str, file: str = "<input>"
) -> tuple[float, float]:
    """Convert a planar vector from a problem file to SI components.

    Parameters
    ----------
    value : list or dict
        Either two components, ``["3 N", "-4 N"]`` (x, then y), or polar
        form, ``{magnitude = "5 N", angle = "30 deg"}``, the angle measured
        counter-clockwise from +x. A negative magnitude points the other way.
    dimension : str
        A key of :data:`DIMENSIONS` for the components / magnitude.
    field : str
        Dotted path of the field; components are reported as ``field[0]``,
        ``field[1]``, ``field.magnitude``, ``field.angle``.
    file : str, optional
        Path or catalog name of the problem file; used in messages.

    Returns
    -------
    tuple of float
        ``(x, y)`` in SI. In polar form, a component smaller than ``1e-13``
        times the magnitude is returned as exactly ``0.0`` (so ``90 deg``
        gives ``x == 0.0``).

    Raises
    ------
    graphkin.errors.ProblemFileError
        If the value is neither form, or a component fails :func:`to_si`.
    ValueError
        If ``dimension`` is unknown.

    Examples
    --------
    >>> to_si_vector(["3 N", "-4 N"], "force", field="load")
    (3.0, -4.0)
    >>> to_si_vector({"magnitude": "2 N", "angle": "90 deg"}, "force", field="load")
    (0.0, 2.0)
    """
    check_dimension(dimension)
    example = (
        f"[{example_of(dimension, '3')}, {example_of(dimension, '-4')}] or "
        f"{{magnitude = {example_of(dimension, '5')}, angle = \"30 deg\"}}"
    )
    if isinstance(value, (list, tuple)):
        if len(value) != 2:
            raise ProblemFileError(
                file,
                field,
                f"a planar vector has 2 components, got {len(value)}; "
                f"write it as {example}",
            )
        x = _scalar_si(value[0], dimension, file, f"{field}[0]")
        y = _scalar_si(value[1], dimension, file, f"{field}[1]")
        return (x, y)
    if isinstance(value, dict):
        keys = set(value)
        if keys != {"magnitude", "angle"}:
            missing = sorted({"magnitude", "angle"} - keys)
            extra = sorted(keys - {"magnitude", "angle"}, key=str)
            parts = []
            if missing:
                parts.append("missing " + ", ".join(missing))
            if extra:
                parts.append("unknown key " + ", ".join(map(str, extra)))
            raise ProblemFileError(
                file,
                field,
                f"a vector in polar form has the keys magnitude and angle "
                f"({'; '.join(parts)}); write it as {example}",
            )
        r = _scalar_si(value["magnitude"], dimension, file, f"{field}.magnitude")
        a = _scalar_si(value["angle"], "angle", file, f"{field}.angle")
        x, y = r * math.cos(a), r * math.sin(a)
        small = POLAR_ZERO_RTOL * abs(r)
        if abs(x) <= small:
            x = 0.0
        if abs(y) <= small:
            y = 0.0
        return (x, y)
    raise ProblemFileError(
        file,
        field,
        f"expected a vector, written as {example}, got a {type_name(value)}",
    )


def to_si_array(
    value: Any, dimension: str, *, field: str, file: str = "<input>"
) -> np.ndarray:
    """Convert a value, a list of values or a range table to an SI array.

    Parameters
    ----------
    value : str, list or dict
        One of

        * a single value, ``"30 deg"`` -> shape ``(1,)``;
        * a list of values, ``["0 deg", "90 deg"]`` -> shape ``(n,)``;
        * a range table with a step,
          ``{start = "0 deg", stop = "360 deg", step = "2 deg"}``;
        * a range table with a count,
          ``{start = "0 deg", stop = "180 deg", num = 181}``.
    dimension : str
        A key of :data:`DIMENSIONS`.
    field : str
        Dotted path of the field; elements are reported as ``field[i]``,
        ``field.start``, ``field.stop``, ``field.step``, ``field.num``.
    file : str, optional
        Path or catalog name of the problem file; used in messages.

    Returns
    -------
    numpy.ndarray
        1-D float array in SI.

    Raises
    ------
    graphkin.errors.ProblemFileError
        If the value is malformed, an element fails :func:`to_si`, a range
        is empty or would have more than 1,000,000 points.
    ValueError
        If ``dimension`` is unknown.

    Notes
    -----
    The rule for ``stop`` in a range table:

    * **Full turn of an angle**: if ``dimension == "angle"`` and
      ``stop - start`` is exactly one turn (+360 deg or -360 deg, to a
      relative 1e-9), ``stop`` is *excluded*, because it is the same
      position as ``start`` and a cycle must not hold it twice. So
      ``{start = "0 deg", stop = "360 deg", step = "2 deg"}`` gives 180
      points, 0 to 358 deg, and ``num = 180`` gives the same 180 points
      (``numpy.linspace(..., endpoint=False)``). Two or more turns are not a
      full turn: their ``stop`` follows the next rule.
    * **Otherwise, with step**: the points are ``start + k*step``, and
      ``stop`` is *included* if it lands on that grid (to a relative 1e-9;
      the last point is then exactly ``stop``); if it does not, the range
      ends at the last grid point before ``stop``.
      ``{start = "0 s", stop = "1 s", step = "0.25 s"}`` gives 5 points.
    * **Otherwise, with num**: ``num`` evenly spaced points, both ends
      included (``numpy.linspace``). ``num`` is an integer >= 2.

    ``step`` may be negative to go down (it must point from ``start``
    towards ``stop``); ``start`` must differ from ``stop``; give exactly
    one of ``step`` and ``num``.

    Examples
    --------
    >>> to_si_array("2 m", "length", field="x")
    array([2.])
    >>> to_si_array(["1 mm", "2 mm"], "length", field="x")
    array([0.001, 0.002])
    >>> len(to_si_array({"start": "0 deg", "stop": "360 deg", "step": "2 deg"},
    ...                 "angle", field="sweep"))
    180
    """
    check_dimension(dimension)
    if isinstance(value, (list, tuple)):
        if len(value) == 0:
            raise ProblemFileError(file, field, "the list is empty; give at least one value")
        out = [_scalar_si(v, dimension, file, f"{field}[{i}]") for i, v in enumerate(value)]
        return np.asarray(out, dtype=float)
    if isinstance(value, dict):
        return _range_si(value, dimension, file, field)
    return np.asarray([_scalar_si(value, dimension, file, field)], dtype=float)


def _range_si(table: dict, dimension: str, file: str, field: str) -> np.ndarray:
    example = (
        f"{{start = {example_of(dimension, '0')}, stop = {example_of(dimension, '360')}, "
        f"step = {example_of(dimension, '2')}}}"
        if dimension == "angle"
        else f"{{start = {example_of(dimension, '0')}, stop = {example_of(dimension, '10')}, "
        f"step = {example_of(dimension, '1')}}}"
    )
    allowed = {"start", "stop", "step", "num"}
    extra = sorted((k for k in table if k not in allowed), key=str)
    if extra:
        raise ProblemFileError(
            file,
            field,
            f"unknown key {', '.join(map(str, extra))} in a range table; "
            f"the keys are start, stop and step or num, e.g. {example}",
        )
    missing = [k for k in ("start", "stop") if k not in table]
    if missing:
        raise ProblemFileError(
            file, field, f"a range table needs {' and '.join(missing)}, e.g. {example}"
        )
    if ("step" in table) == ("num" in table):
        raise ProblemFileError(
            file, field, f"a range table needs exactly one of step and num, e.g. {example}"
        )
    start = _scalar_si(table["start"], dimension, file, f"{field}.start")
    stop = _scalar_si(table["stop"], dimension, file, f"{field}.stop")
    span = stop - start
    if span == 0.0:
        raise ProblemFileError(
            file,
            field,
            "start and stop are equal; for a single value write just the value",
        )
    full_turn = dimension == "angle" and math.isclose(
        abs(span), 2 * math.pi, rel_tol=_GRID_RTOL
    )

    if "num" in table:
        num = table["num"]
        if (
            isinstance(num, bool)
            or not isinstance(num, numbers.Integral)
            or num < 2
        ):
            raise ProblemFileError(
                file,
                f"{field}.num",
                f"num is the number of points, an integer >= 2; got {num!r}",
            )
        num = int(num)
        if num > _MAX_RANGE_POINTS:
            raise ProblemFileError(
                file,
                f"{field}.num",
                f"{num} points is too many (at most {_MAX_RANGE_POINTS:,})",
            )
        return np.linspace(start, stop, num, endpoint=not full_turn)

    step = _scalar_si(table["step"], dimension, file, f"{field}.step")
    if step == 0.0 or (step > 0) != (span > 0):
        raise ProblemFileError(
            file,
            f"{field}.step",
            f"the step must be nonzero and go from start towards stop; got "
            f"{table['step']!r} from {table['start']!r} to {table['stop']!r}",
        )
    n = span / step
    k = round(n)
    on_grid = abs(n - k) <= _GRID_RTOL * max(1.0, abs(n))
    count = (k if full_turn else k + 1) if on_grid else math.floor(n) + 1
    if count > _MAX_RANGE_POINTS:
        raise ProblemFileError(
            file,
            f"{field}.step",
            f"this step gives {count:,} points, too many (at most "
            f"{_MAX_RANGE_POINTS:,}); is the step mistyped?",
        )
    out = start + np.arange(count, dtype=float) * step
    if on_grid and not full_turn:
        out[-1] = stop
    return out
