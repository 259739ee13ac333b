"""The ranges of values graphkin accepts, one per kind of quantity (SI).

Each range is wide enough for any machine a course of mechanisms meets (a
watch's gear to a forging press) and narrow enough that no product the
solvers form (m·ω²·r, |F|², F·r, ...) overflows or underflows a float. A
value outside is almost always a slip — the wrong unit, a missing minus in
an exponent — so it is refused with a message that names the field and the
range, rather than solved into nonsense or a numpy warning.

The problem-file reader (:mod:`graphkin.problem`) checks every value it reads
against these ranges and names the field; the model's constructors and
:func:`graphkin.kinematics.solve_kinematics` check the same ranges for
mechanisms built in Python. ``docs/problem-files.md`` lists them ("Ranges").
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.errors import ModelError

TURNS = 1000
"""Largest input angle or direction, in turns either way (a sweep over a few turns fits easily)."""


@dataclass(frozen=True)
class Range:
    """Values a quantity may take: 0 (if allowed) or a magnitude from ``low`` to ``high`` [SI].

    Attributes
    ----------
    what : str
        The quantity in words, plural ("masses").
    high : float
        Largest magnitude [SI].
    low : float
        Smallest magnitude other than zero [SI]; 0 for no lower bound.
    zero : bool
        Whether exactly 0 is allowed.
    signed : bool
        Whether negative values are allowed (their magnitude is checked).
    text : str
        The range as a student reads it, with units.
    """

    what: str
    high: float
    low: float = 0.0
    zero: bool = True
    signed: bool = True
    text: str = ""

    def complaint(self, x: float) -> str | None:
        """Why ``x`` is outside the range (a phrase), or None if it is inside."""
        if not math.isfinite(x):
            return "is not a finite number"
        if x < 0 and not self.signed:
            return "must not be negative"
        size = abs(x)
        if size == 0:
            return None if self.zero else "must not be zero"
        if size > self.high:
            return "is too large"
        if size < self.low:
            return "is too small"
        return None


RANGES: dict[str, Range] = {
    # A coordinate may be 0 or as small as rounding makes it (a polar point at 90°); only its size is capped.
    "coordinate": Range("coordinates and positions", 1e3, text="within ±1 km"),
    "length": Range("lengths", 1e3, 1e-6, zero=False, signed=False, text="from 1 µm to 1 km"),
    "length0": Range("lengths", 1e3, 1e-6, signed=False, text="of 0, or from 1 µm to 1 km"),
    "angle": Range("angles", TURNS * 2 * math.pi, text=f"within ±{TURNS} turns (±{TURNS * 360:,}°)"),
    "mass": Range("masses", 1e6, 1e-9, signed=False, text="of 0, or from 1 µg (1e-9 kg) to 1000 t (1e6 kg)"),
    "moment_of_inertia": Range("moments of inertia", 1e12, signed=False, text="from 0 to 1e12 kg·m²"),
    "density": Range("densities", 1e5, 1e-1, zero=False, signed=False, text="from 0.1 to 100,000 kg/m³"),
    # Speeds are squared (ω² r, v²/r): a nonzero one below these would square to nothing a float can hold.
    "angular_velocity": Range("angular velocities", 1e6 * math.pi / 30, 1e-6,
                              text="of 0, or from 1e-6 rad/s (a turn in 73 days) to 1,000,000 rpm either way"),
    "angular_acceleration": Range("angular accelerations", 1e10, text="within ±1e10 rad/s²"),
    "velocity": Range("velocities", 1e4, 1e-9, text="of 0, or from 1 nm/s to 10 km/s either way"),
    "acceleration": Range("accelerations", 1e10, text="within ±1e10 m/s²"),
    "force": Range("forces", 1e10, text="within ±1e10 N (10 GN)"),
    "torque": Range("torques", 1e10, text="within ±1e10 N·m"),
    "pressure": Range("pressures", 1e10, text="within ±1e10 Pa (10 GPa)"),
    "power": Range("powers", 1e10, text="within ±1e10 W (10 GW)"),
    "stiffness": Range("spring rates", 1e12, signed=False, text="from 0 to 1e12 N/m"),
    "friction": Range("friction coefficients", 10.0, signed=False, text="from 0 to 10"),
}
"""The ranges by kind. ``length`` is a size that must not be zero (a radius, a
thickness, the distance between two pins), ``length0`` one that may be (a hole,
a radius of gyration), ``coordinate`` a signed position (a point's x or y, a
slider's s)."""


def complaint(x, kind: str) -> str | None:
    """A sentence's end saying why ``x`` is outside the range of ``kind``, or None if it is inside.

    Parameters
    ----------
    x : float
        The value [SI].
    kind : str
        A key of :data:`RANGES`.

    Returns
    -------
    str or None
        E.g. ``"is too large: graphkin accepts masses of 0, or from 1 µg ...;
        check the number and its units"``.
    """
    r = RANGES[kind]
    why = r.complaint(float(x))
    if why is None:
        return None
    return f"{why}: graphkin accepts {r.what} {r.text}; check the number and its units"


def check(x, kind: str, what: str) -> float:
    """``x`` as a float if it is inside the range of ``kind``; a ModelError naming ``what`` if not.

    Parameters
    ----------
    x : float
        The value [SI].
    kind : str
        A key of :data:`RANGES`.
    what : str
        What the value is, to start the message ("link 3 mass").

    Raises
    ------
    ModelError
        ``"link 3 mass 1e-200 kg is too small: graphkin accepts masses of ..."``.
    """
    x = float(x)
    why = complaint(x, kind)
    if why is not None:
        unit = f" {_SI[kind]}" if _SI[kind] else ""
        raise ModelError(f"{what} = {x:.6g}{unit} {why}")
    return x


def check_array(x: np.ndarray, kind: str, what: str) -> np.ndarray:
    """Every element of ``x`` inside the range of ``kind``; a ModelError naming the first that is not."""
    x = np.asarray(x, dtype=float)
    r = RANGES[kind]
    size = np.abs(x)
    with np.errstate(invalid="ignore"):
        bad = ~np.isfinite(x) | (size > r.high) | ((size < r.low) & (size > 0))
        if not r.zero:
            bad |= size == 0
        if not r.signed:
            bad |= x < 0
    if bad.any():
        # Only the first offender is named: one line is enough to act on.
        i = int(np.argmax(bad.ravel()))
        check(x.ravel()[i], kind, f"{what}[{i}]" if x.size > 1 else what)
    return x


_SI = {"coordinate": "m", "length": "m", "length0": "m", "angle": "rad", "mass": "kg", "moment_of_inertia": "kg·m²",
       "density": "kg/m³", "angular_velocity": "rad/s", "angular_acceleration": "rad/s²", "velocity": "m/s",
       "acceleration": "m/s²", "force": "N", "torque": "N·m", "friction": ""}


MAX_POSITIONS = 1_000_000
"""Most input positions solved at once (a 0.00036° grid over a turn); more is surely a slip, and costs gigabytes."""


def as_array(value, what: str, kind: str, *, n: int | None = None) -> np.ndarray:
    """``value`` as a 1-D float array [SI], each element inside the range of ``kind``.

    Parameters
    ----------
    value : float or array_like, shape (m,)
        One number or a 1-D sequence of numbers.
    what : str
        Its name in messages ("at", "q_dot").
    kind : str
        A key of :data:`RANGES`.
    n : int, optional
        The number of positions: then ``value`` must be one number (repeated
        n times) or exactly n numbers.

    Returns
    -------
    ndarray, shape (m,) or (n,)

    Raises
    ------
    ModelError
        One plain sentence: not numbers, not one or a 1-D list, empty, too
        many, the wrong length, not finite or outside the range.
    """
    unit = f" [{_SI[kind]}]" if _SI[kind] else ""
    if isinstance(value, (str, bytes)) or value is None:
        raise ModelError(f"{what} must be a number or a list of numbers{unit}, got {value!r:.60}")
    try:
        x = np.asarray(value)
    except (ValueError, TypeError):
        raise ModelError(f"{what} must be a number or a flat list of numbers{unit}; it holds lists of "
                         "different lengths") from None
    if x.dtype == bool or not (np.issubdtype(x.dtype, np.number) and not np.issubdtype(x.dtype, np.complexfloating)):
        raise ModelError(f"{what} must be a number or a list of numbers{unit}, got {value!r:.60}")
    if x.ndim > 1:
        raise ModelError(f"{what} must be one number or a 1-D list of them{unit}, got an array of shape {x.shape}; "
                         "pass one row or column (e.g. .ravel())")
    x = np.atleast_1d(x.astype(float))
    if x.size == 0:
        raise ModelError(f"{what} is empty: give at least one value{unit}")
    if x.size > MAX_POSITIONS:
        raise ModelError(f"{what} has {x.size:,} values; graphkin solves at most {MAX_POSITIONS:,} positions at once")
    if n is not None and x.size not in (1, n):
        raise ModelError(f"{what} has {x.size} values for {n} positions: give one value, or one per position")
    check_array(x, kind, what)
    return np.broadcast_to(x, (n,)).copy() if n is not None else x


def ndim(value) -> int:
    """Number of array dimensions of ``value``; -1 for a ragged nest of lists that is no array at all."""
    if type(value) in (float, int):  # the common case, without numpy's dispatch
        return 0
    try:
        return np.ndim(value)
    except (ValueError, TypeError):
        return -1


def finite(value, what: str, unit: str = "") -> float:
    """``value`` as a finite float, or a one-line ModelError naming ``what`` (and its unit)."""
    unit = f" [{unit}]" if unit else ""
    # bool is an int subclass; a student who passes True meant something else.
    # A string ("5 kg") belongs in a problem file, where units are read; an array is many numbers, not one.
    if isinstance(value, (bool, np.bool_, str, bytes)) or ndim(value) != 0:
        raise ModelError(f"{what} must be a number{unit}, got {value!r}")
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ModelError(f"{what} must be a number{unit}, got {value!r}") from None
    if not math.isfinite(x):
        raise ModelError(f"{what} must be finite{unit}, got {value!r}")
    return x


def point(value, what: str, kind: str = "coordinate") -> tuple[float, float]:
    """A pair (x, y) of finite floats inside the range of ``kind`` (:mod:`graphkin.ranges`)."""
    unit = {"coordinate": "in metres", "force": "in newtons"}[kind]
    # A string unpacks into two characters and an array into rows: neither is a pair of numbers.
    if isinstance(value, (str, bytes)) or ndim(value) != 1:
        raise ModelError(f"{what} must be a pair (x, y) {unit}, got {value!r}")
    try:
        x, y = value
    except (TypeError, ValueError):
        raise ModelError(f"{what} must be a pair (x, y) {unit}, got {value!r}") from None
    return (check(finite(x, what + ".x"), kind, what + ".x"), check(finite(y, what + ".y"), kind, what + ".y"))
