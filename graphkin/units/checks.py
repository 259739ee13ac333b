"""Which units a value may carry: the dimension, the power of the angle unit, and the slips refused with a hint."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from graphkin.errors import ProblemFileError
from graphkin.units.dimensions import ANGLE_POWER, DIMENSIONS, article, dimension_label, example_of
from graphkin.units.registries import registry

if TYPE_CHECKING:  # pragma: no cover
    import pint

# Torque units glued together, e.g. Nm, kNm, Nmm: pint reads "Nm" as another unit.
GLUED_TORQUE = re.compile(r"^(?P<prefix>da|[kMmcd])?N(?P<length>m|mm|cm)$")


# A power of a power (m^2^3, 9**9**9): refused, it can take forever to evaluate.
POWER_CHAIN = re.compile(r"(?:\^|\*\*)[^*/^]*(?:\^|\*\*)")


MAX_UNIT_CHARS = 60


def angle_power(unit: pint.Unit) -> float:
    ureg = registry()
    _, root = ureg.get_root_units(unit)
    return dict(unit_items(root)).get("radian", 0)


def unit_items(unit: pint.Unit) -> tuple[tuple[str, float], ...]:
    """The (unit name, exponent) pairs of a unit, e.g. (("newton", 1), ("meter", 1))."""
    return registry().Quantity(1, unit).to_tuple()[1]


def describe(unit: pint.Unit) -> str:
    """Name the dimension of a unit: one of ours if it matches, else pint's."""
    ureg = registry()
    dim = unit.dimensionality
    power = angle_power(unit)
    for name, text in DIMENSIONS.items():
        if (
            ureg.get_dimensionality(text) == dim
            and ANGLE_POWER.get(name, 0) == power
        ):
            return f"{article(name)} {dimension_label(name)}"
    if power:
        return f"{dim} with an angle unit to the power {power:g}"
    if dim == ureg.get_dimensionality("1 / [time]"):
        return "a frequency (1 / [time]) with no angle unit"
    return str(dim)


def is_energy_or_power(ureg: pint.UnitRegistry, name: str) -> bool:
    dim = ureg.get_dimensionality(name)
    energy = ureg.get_dimensionality("[mass] * [length] ** 2 / [time] ** 2")
    power = ureg.get_dimensionality("[mass] * [length] ** 2 / [time] ** 3")
    return dim == energy or dim == power


def parse_unit(text: str, raw: str, file: str, field: str) -> pint.Unit:
    """Parse the unit part of a value string, with hints for common slips."""
    ureg = registry()

    def fail(message: str) -> ProblemFileError:
        return ProblemFileError(file, field, message)

    for token in re.findall(r"[^\W\d_]+", text):
        m = GLUED_TORQUE.match(token)
        if m:
            fixed = f"{m['prefix'] or ''}N*{m['length']}"
            raise fail(
                f'"{raw}": "{token}" would not be read as newton-metres (pint reads '
                f'"Nm" as another unit); write "{fixed}"'
            )
    if len(text) > MAX_UNIT_CHARS or POWER_CHAIN.search(text):
        raise fail(f'could not read the units of "{raw}"')
    try:
        unit = ureg.parse_units(text)
    except Exception as exc:  # pint raises many types (TokenError, TypeError, ...)
        names = getattr(exc, "unit_names", None)
        if names:
            unknown = ", ".join(f'"{n}"' for n in names)
            raise fail(f'unknown unit {unknown} in "{raw}"') from None
        hint = ""
        if re.search(r"[^\W\d_]\s*-\s*[^\W\d_]", text):
            hint = '; multiply units with "*", e.g. "N*m"'
        raise fail(f'could not read the units of "{raw}"{hint}') from None
    return unit


def check_unit(unit: pint.Unit, raw: str, dimension: str, file: str, field: str) -> None:
    """Check that ``unit`` has the dimension (and angle power) asked for."""
    ureg = registry()
    expected = ureg.get_dimensionality(DIMENSIONS[dimension])
    label = dimension_label(dimension)
    what = f"{article(label)} {label}"
    if dimension == "dimensionless":
        what = "a dimensionless number"
    if unit.dimensionality != expected:
        raise ProblemFileError(
            file,
            field,
            f'expected {what} ({DIMENSIONS[dimension]}, e.g. '
            f'{example_of(dimension)}), got "{raw}", which is {describe(unit)}',
        )
    power = angle_power(unit)
    want = ANGLE_POWER.get(dimension, 0)
    if power != want:
        if want and power == 0:
            if dimension == "angle":
                detail = "it has no angle unit; write it in deg or rad"
            else:
                detail = (
                    "it has no angle unit, so revolutions and radians cannot be "
                    f"told apart (is 1 Hz 1 rev/s or 1 rad/s?); write it as e.g. "
                    f"{example_of(dimension, '5')} or \"5 rad/s\""
                    if dimension == "angular_velocity"
                    else "it has no angle unit; write it in rad/s^2 or deg/s^2"
                )
        elif power and want == 0:
            detail = f"it has an angle unit, which {what} has not"
        else:
            detail = f"its angle unit has the power {power:g}"
        raise ProblemFileError(
            file, field, f'expected {what}, got "{raw}": {detail}'
        )
    if dimension == "torque":
        for name, _ in unit_items(unit):
            if is_energy_or_power(ureg, name):
                symbol = format(ureg.Unit(name), "~")
                raise ProblemFileError(
                    file,
                    field,
                    f'"{raw}": {symbol} is a unit of energy or power; torque is '
                    f"written in N*m (J is energy), e.g. \"50 N*m\"",
                )
