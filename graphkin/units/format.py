"""SI values written in a chosen unit, for reports."""

from __future__ import annotations

import math
import numbers

from graphkin.errors import ProblemFileError
from graphkin.units.checks import check_unit
from graphkin.units.dimensions import SI_UNITS, check_dimension
from graphkin.units.registries import registry


def format_si(
    value: float, dimension: str, unit: str | None = None, digits: int = 4
) -> str:
    """Format an SI value for a report, in a chosen unit.

    Parameters
    ----------
    value : float
        The value in SI (the unit of :data:`SI_UNITS` for ``dimension``).
        ``nan`` is formatted as ``"nan"`` followed by the unit.
    dimension : str
        A key of :data:`DIMENSIONS`.
    unit : str, optional
        The unit to show, in pint spelling (``"N*mm"``, ``"deg"``,
        ``"rpm"``); default the SI unit.
    digits : int, optional
        Significant digits (``%g`` style: trailing zeros dropped, exponent
        notation for very large or small values).

    Returns
    -------
    str
        e.g. ``"865 N·mm"``; products print with ``·``, powers as
        superscripts (``"kg·m²"``); a dimensionless value has no unit.

    Raises
    ------
    ValueError
        If ``dimension`` is unknown, ``unit`` is not a unit of that
        dimension, or ``digits < 1``.

    Examples
    --------
    >>> format_si(0.865, "torque", "N*mm")
    '865 N·mm'
    >>> format_si(94.2477796, "angular_velocity", "rpm")
    '900 rpm'
    """
    check_dimension(dimension)
    if isinstance(digits, bool) or not isinstance(digits, numbers.Integral) or digits < 1:
        raise ValueError(f"digits must be an integer >= 1, got {digits!r}")
    ureg = registry()
    si_text = SI_UNITS[dimension]
    unit_text = si_text if unit is None else unit
    try:
        target = ureg.parse_units(unit_text)
        check_unit(target, unit_text, dimension, "<format_si>", "unit")
    except ProblemFileError as exc:
        raise ValueError(f"format_si: {exc.message}") from None
    except Exception:
        raise ValueError(f"format_si: unknown unit {unit_text!r}") from None
    x = float(value)
    if math.isfinite(x):
        x = ureg.Quantity(x, si_text or "dimensionless").m_as(target)
    number = f"{x:.{int(digits)}g}"
    if number == "-0":
        number = "0"
    symbol = format(target, "~P")
    return f"{number} {symbol}" if symbol else number
