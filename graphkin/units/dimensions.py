"""The dimensions a problem file's values have, their SI units, and how messages name them and show examples."""

from __future__ import annotations

import numbers
from typing import Any

#: Our dimension names -> pint dimensionality strings (parseable by
#: ``registry().get_dimensionality``). "angle" and "dimensionless" share the
#: empty dimensionality ``[]``; they are told apart by the angle unit (see
#: :data:`ANGLE_POWER`).
DIMENSIONS: dict[str, str] = {
    "length": "[length]",
    "angle": "[]",
    "mass": "[mass]",
    "time": "[time]",
    "velocity": "[length] / [time]",
    "acceleration": "[length] / [time] ** 2",
    "angular_velocity": "1 / [time]",
    "angular_acceleration": "1 / [time] ** 2",
    "force": "[mass] * [length] / [time] ** 2",
    "torque": "[mass] * [length] ** 2 / [time] ** 2",
    "moment_of_inertia": "[mass] * [length] ** 2",
    "energy": "[mass] * [length] ** 2 / [time] ** 2",
    "density": "[mass] / [length] ** 3",
    "pressure": "[mass] / [length] / [time] ** 2",
    "power": "[mass] * [length] ** 2 / [time] ** 3",
    "stiffness": "[mass] / [time] ** 2",
    "dimensionless": "[]",
}


#: The SI unit graphkin's core uses for each dimension (pint spelling).
SI_UNITS: dict[str, str] = {
    "length": "m",
    "angle": "rad",
    "mass": "kg",
    "time": "s",
    "velocity": "m/s",
    "acceleration": "m/s^2",
    "angular_velocity": "rad/s",
    "angular_acceleration": "rad/s^2",
    "force": "N",
    "torque": "N*m",
    "moment_of_inertia": "kg*m^2",
    "energy": "J",
    "density": "kg/m^3",
    "pressure": "Pa",
    "power": "W",
    "stiffness": "N/m",
    "dimensionless": "",
}


# Power of the radian in the root units each dimension requires (pint treats
# the radian as dimensionless, so this is how angles are told from ratios and
# rad/s from Hz).
ANGLE_POWER: dict[str, int] = {
    "angle": 1,
    "angular_velocity": 1,
    "angular_acceleration": 1,
}


# The unit and a typical number shown in "write it as ..." hints.
_EXAMPLES: dict[str, tuple[str, str]] = {
    "length": ("500", "mm"),
    "angle": ("30", "deg"),
    "mass": ("5", "kg"),
    "time": ("2", "s"),
    "velocity": ("2", "m/s"),
    "acceleration": ("9.81", "m/s^2"),
    "angular_velocity": ("900", "rpm"),
    "angular_acceleration": ("8.3", "rad/s^2"),
    "force": ("2000", "N"),
    "torque": ("50", "N*m"),
    "moment_of_inertia": ("0.1", "kg*m^2"),
    "energy": ("240", "J"),
    "density": ("7850", "kg/m^3"),
    "pressure": ("0.35", "MPa"),
    "power": ("20", "kW"),
    "stiffness": ("5", "N/mm"),
    "dimensionless": ("0.3", ""),
}


def check_dimension(dimension: str) -> None:
    if dimension not in DIMENSIONS:
        known = ", ".join(sorted(DIMENSIONS))
        raise ValueError(f"unknown dimension {dimension!r}; known: {known}")


def dimension_label(dimension: str) -> str:
    return dimension.replace("_", " ")


def article(word: str) -> str:
    return "an" if word[:1] in "aeiou" else "a"


def shown_number(x: float) -> str:
    """A short text for a number given by the user, for use in hints."""
    if isinstance(x, numbers.Integral):
        return str(int(x))
    return f"{float(x):g}"


def example_of(dimension: str, number: str | None = None) -> str:
    """A value written the right way, e.g. '"500 mm"' (with the quotes)."""
    typical, unit = _EXAMPLES[dimension]
    number = typical if number is None else number
    return f'"{number} {unit}"' if unit else number


def type_name(value: Any) -> str:
    if value is None:
        return "None"
    return type(value).__name__
