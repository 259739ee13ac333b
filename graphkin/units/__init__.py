"""The units boundary: problem-file strings in, SI floats out.

Problem files (TOML) write every dimensional value as a string with units,
e.g. ``"500 mm"``, ``"900 rpm"``, ``"7.6 deg"``, ``"-2000 N"``,
``"0.10417 kg*m^2"``, ``"865 N*mm"``. The rest of graphkin works in SI with
plain floats:

=====================  ==========  =====================================
dimension              SI unit     accepted, for example
=====================  ==========  =====================================
length                 m           mm, cm, m, in
angle                  rad         deg, rad, rev, turn
mass                   kg          g, kg, lb
time                   s           ms, s, min
velocity               m/s         m/s, mm/s, km/h
acceleration           m/s^2       m/s^2, mm/s^2
angular_velocity       rad/s       rpm, rad/s, deg/s, rev/min
angular_acceleration   rad/s^2     rad/s^2, deg/s^2, rpm/s
force                  N           N, kN
torque                 N*m         N*m, N*mm, kN*m
moment_of_inertia      kg*m^2      kg*m^2, kg*mm^2
energy                 J           J, kJ, N*m (exercise answers)
density                kg/m^3      kg/m^3, g/cm^3
dimensionless          (none)      0.3, "0.3", "30 percent"
=====================  ==========  =====================================

This module is the only place graphkin uses pint, and it imports pint lazily
inside functions: ``import graphkin.units`` does not load pint. The factor
pint converts each unit by is kept on disk once pint has found it
(:data:`_FACTORS`, in graphkin's cache folder), so reading a problem file in
units met before does not import pint at all; a new unit, and every check
that fails, goes through pint.

Rules (every violation raises :class:`graphkin.errors.ProblemFileError`
naming the file and the field):

* A string is a number followed by units (``"500 mm"``, ``"500mm"``); only
  ``"dimensionless"`` accepts a bare number (``0.3`` or ``"0.3"``).
  ``"angle"`` accepts no bare number either: ``7.6`` could be degrees or
  radians.
* Angular quantities must name an angle unit: ``"5 Hz"`` or ``"5 1/s"`` is
  rejected for an angular velocity (revolutions or radians per second?), and
  an angle unit is rejected where no angle is expected (``"5 deg"`` for a
  friction coefficient).
* ``"Nm"``, ``"kNm"``, ``"Nmm"`` are rejected (pint would read ``Nm`` as a
  nanometre-like unit): write ``"N*m"``, ``"kN*m"``, ``"N*mm"``.
* Energy and power units (J, kJ, cal, Wh, W*s, ...) are rejected for a
  torque, although pint finds them dimensionally equal: torque is written in
  N*m.
* ``nan`` and ``inf`` are rejected, and so are values that overflow when
  converted to SI.
* Booleans, ``None``, tables and lists are rejected where a scalar is
  expected; the message names the Python type.

Offset units (degC, degF) are not supported.
"""

from __future__ import annotations

import functools
import json
import math
import numbers
import os
import re
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from graphkin.errors import ProblemFileError

if TYPE_CHECKING:  # pragma: no cover
    import pint

__all__ = [
    "DIMENSIONS",
    "SI_UNITS",
    "registry",
    "to_si",
    "to_si_vector",
    "to_si_array",
    "format_si",
]

#: Our dimension names -> pint dimensionality strings (parseable by
#: ``registry().get_dimensionality``). "angle" and "dimensionless" share the
#: empty dimensionality ``[]``; they are told apart by the angle unit (see
#: :data:`_ANGLE_POWER`).
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
    "dimensionless": "",
}

# Power of the radian in the root units each dimension requires (pint treats
# the radian as dimensionless, so this is how angles are told from ratios and
# rad/s from Hz).
_ANGLE_POWER: dict[str, int] = {
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
    "dimensionless": ("0.3", ""),
}

# A number, then (optionally) a unit expression.
_NUMBER_RE = re.compile(
    r"""^\s*(?P<number>
            [+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?
          | [+-]?(?:nan|inf(?:inity)?)(?![A-Za-z])
        )\s*(?P<unit>.*?)\s*$""",
    re.VERBOSE | re.IGNORECASE,
)
# Torque units glued together, e.g. Nm, kNm, Nmm: pint reads "Nm" as another unit.
_GLUED_TORQUE_RE = re.compile(r"^(?P<prefix>da|[kMmcd])?N(?P<length>m|mm|cm)$")
# A power of a power (m^2^3, 9**9**9): refused, it can take forever to evaluate.
_POWER_CHAIN_RE = re.compile(r"(?:\^|\*\*)[^*/^]*(?:\^|\*\*)")
_MAX_UNIT_CHARS = 60
# Cap on the length of a range table, to catch a mistyped step; also the most positions a sweep solves at once.
from graphkin.files import write_text
from graphkin.ranges import MAX_POSITIONS  # noqa: E402  (one limit for files, --n and the Python API)

_MAX_RANGE_POINTS = MAX_POSITIONS
# Relative tolerance for "stop lands on the grid" and "stop is a full turn".
_GRID_RTOL = 1e-9
# Strings already converted, (text, dimension) -> SI value: exercise variants
# re-read the same file hundreds of times, and pint takes ~50 µs a value.
# Only successes are kept, so every error still names its own file and field.
_CONVERTED: dict[tuple[str, str], float] = {}
_MAX_CONVERTED = 10_000
# SI factor of each unit pint has converted, (unit text, dimension) -> factor, exactly the one pint
# multiplies by (pint converts a float x as x * factor: PlainRegistry._convert). Learned from pint on a
# unit's first use and kept on disk (:func:`_factors_path`), so that the next command reads a file written
# in units it has met before without importing pint (~0.2 s of its start), with the same numbers. A unit
# not met before, and every error message, goes through pint.
_FACTORS: dict[tuple[str, str], float] | None = None
# Polar components smaller than this times the magnitude are set to 0.0, so
# that {magnitude = "5 N", angle = "90 deg"} gives exactly (0.0, 5.0).
_POLAR_ZERO_RTOL = 1e-13


@functools.cache
def registry() -> pint.UnitRegistry:
    """Return graphkin's one shared pint unit registry.

    The registry is created on first call (this is where pint is imported)
    and cached. Products of units print in the order written
    (``N·m``, not ``m·N``), and ``rev`` is defined as an alias of ``turn``.

    pint's parsed definitions are kept on disk (:func:`cache_folder`), which
    builds the registry in ~20 ms instead of ~130 ms from the second process
    on; without a usable cache folder it is built from pint's text files,
    with the same units and the same numbers.

    Returns
    -------
    pint.UnitRegistry
        The shared registry; use it for every quantity that must interact
        with graphkin's.
    """
    import pint

    ureg = _cached_registry(pint, cache_folder())
    ureg.formatter.default_sort_func = None
    ureg.define("@alias turn = rev")
    return ureg


def _pint_stamp() -> str | None:
    """pint's version and definition files as a short tag, found without importing pint (None: no pint)."""
    import importlib.util
    import zlib

    spec = importlib.util.find_spec("pint")
    if spec is None or not spec.origin:
        return None
    here = Path(spec.origin).parent
    times = [str(p.stat().st_mtime_ns) for p in sorted(here.glob("*.txt"))] + [str(Path(spec.origin).stat().st_mtime_ns)]
    return f"{zlib.crc32(' '.join(times).encode()):08x}"


def _factors_path() -> Path | None:
    """The file the learned unit factors are kept in (None: no cache folder)."""
    root = cache_folder()
    return None if root is None else root / "unit-factors.json"


def _known_factors() -> dict[tuple[str, str], float]:
    """The unit factors pint has given before, read once per process from :func:`_factors_path`.

    A missing, unreadable or damaged file, or one written by another pint,
    is an empty table: every unit then goes through pint once more.
    """
    global _FACTORS
    if _FACTORS is None:
        _FACTORS = {}
        try:
            path = _factors_path()
            data = json.loads(path.read_text(encoding="utf-8")) if path is not None else {}
            if data.get("pint") == _pint_stamp():
                for unit, dimension, factor in data["factors"]:
                    if isinstance(unit, str) and dimension in DIMENSIONS and type(factor) is float \
                            and math.isfinite(factor) and factor > 0:
                        _FACTORS[(unit, dimension)] = factor
        except Exception:  # no cache yet, or a damaged one: pint answers, and the file is written again
            _FACTORS = {}
    return _FACTORS


def _learn(ureg, unit, unit_text: str, dimension: str, x: float, si: float) -> None:
    """Keep pint's factor for ``unit_text`` (in memory, and on disk where it can be written).

    Only a factor that reproduces pint's own result for this value is kept
    (a multiplicative unit: pint converts x as x * factor); the file is
    written whole or not at all, and a folder that cannot be written is
    skipped without a word.
    """
    factor = float(ureg.Quantity(1.0, unit).m_as(SI_UNITS[dimension] or "dimensionless"))
    if not (math.isfinite(factor) and factor > 0 and x * factor == si):
        return
    factors = _known_factors()
    if factors.get((unit_text, dimension)) == factor:
        return
    factors[(unit_text, dimension)] = factor
    try:
        path = _factors_path()
        if path is not None:
            path.parent.mkdir(parents=True, exist_ok=True)
            write_text(path, json.dumps({"pint": _pint_stamp(),
                                         "factors": sorted([u, d, f] for (u, d), f in factors.items())}))
    except Exception:  # a read-only home costs the time the cache would save, no more
        pass


def cache_folder() -> Path | None:
    """The folder for graphkin's caches, or None if caching is switched off.

    ``$GRAPHKIN_CACHE_DIR`` if set (an empty value switches the cache off),
    else the user cache folder of the platform (``~/.cache/graphkin`` on
    Linux, through platformdirs, which pint depends on). The folder need not
    exist or be writable: a cache that cannot be read or written is skipped.

    Returns
    -------
    pathlib.Path or None
    """
    env = os.environ.get("GRAPHKIN_CACHE_DIR")
    if env is not None:
        return Path(env).expanduser() if env.strip() else None
    try:
        import platformdirs

        return Path(platformdirs.user_cache_path("graphkin", appauthor=False))
    except Exception:  # no platformdirs, or no home folder to put a cache in: no cache
        return None


# The file naming a complete set of pint cache files: pint reads its cache
# only when this lists files that are all there, so it never finds a missing
# file and writes one itself (pint writes in place, where a second process
# could read half a file).
_PINT_MARKER = "complete.json"


def _cached_registry(pint: Any, root: Path | None) -> pint.UnitRegistry:
    """A pint registry, read from the disk cache under ``root`` when it can be.

    Parameters
    ----------
    pint : module
        The pint module (imported by the caller).
    root : pathlib.Path or None
        graphkin's cache folder (:func:`cache_folder`); None for no cache.

    Returns
    -------
    pint.UnitRegistry
        Built without its own disk cache (pint's ``_diskcache`` is None or
        points at the complete cache folder).

    Notes
    -----
    The cache of one pint version lives in ``root/pint-VERSION``. A missing,
    incomplete or unreadable cache is built again in a temporary folder
    beside it and each file moved into place with :func:`os.replace`, the
    list of files last; a reader sees the old files or the new ones, never
    half a file. If nothing can be written there (a read-only home), the
    registry is built from pint's text files, as without a cache.
    """
    if root is None:
        return pint.UnitRegistry()
    folder = root / f"pint-{pint.__version__}-{_definitions_stamp(pint)}"
    try:
        names = json.loads((folder / _PINT_MARKER).read_text(encoding="utf-8"))
        if names and all(isinstance(n, str) and (folder / n).is_file() for n in names):
            return pint.UnitRegistry(cache_folder=folder)
    except Exception:  # no cache yet, or a damaged one (pickle, json, a partial file): build it again
        pass
    try:
        return _publish_registry(pint, folder)
    except Exception:  # a cache folder that cannot be written costs the time the cache would save, no more
        return pint.UnitRegistry()


def _definitions_stamp(pint: Any) -> str:
    """A short tag of pint's definition files' modification times.

    pint takes a cache file older than its source for stale and rewrites it
    in place; a reinstalled pint gets a new folder instead.
    """
    import zlib

    here = Path(pint.__file__).parent
    times = [str(p.stat().st_mtime_ns) for p in sorted(here.glob("*.txt"))]
    return f"{zlib.crc32(' '.join(times).encode()):08x}"


def _publish_registry(pint: Any, folder: Path) -> pint.UnitRegistry:
    """Build pint's disk cache in a temporary folder, move it into ``folder``, and read it back."""
    import shutil
    import tempfile

    folder.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(dir=folder.parent, prefix=f".{folder.name}."))
    try:
        pint.UnitRegistry(cache_folder=tmp)
        names = sorted(p.name for p in tmp.iterdir())
        for name in names:
            os.replace(tmp / name, folder / name)
        write_text(folder / _PINT_MARKER, json.dumps(names))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return pint.UnitRegistry(cache_folder=folder)


# ---------------------------------------------------------------------------
# helpers


def _check_dimension(dimension: str) -> None:
    if dimension not in DIMENSIONS:
        known = ", ".join(sorted(DIMENSIONS))
        raise ValueError(f"unknown dimension {dimension!r}; known: {known}")


def _label(dimension: str) -> str:
    return dimension.replace("_", " ")


def _article(word: str) -> str:
    return "an" if word[:1] in "aeiou" else "a"


def _number_text(x: float) -> str:
    """A short text for a number given by the user, for use in hints."""
    if isinstance(x, numbers.Integral):
        return str(int(x))
    return f"{float(x):g}"


def _example(dimension: str, number: str | None = None) -> str:
    """A value written the right way, e.g. '"500 mm"' (with the quotes)."""
    typical, unit = _EXAMPLES[dimension]
    number = typical if number is None else number
    return f'"{number} {unit}"' if unit else number


def _type_name(value: Any) -> str:
    if value is None:
        return "None"
    return type(value).__name__


def _angle_power(unit: pint.Unit) -> float:
    ureg = registry()
    _, root = ureg.get_root_units(unit)
    return dict(_unit_items(root)).get("radian", 0)


def _unit_items(unit: pint.Unit) -> tuple[tuple[str, float], ...]:
    """The (unit name, exponent) pairs of a unit, e.g. (("newton", 1), ("meter", 1))."""
    return registry().Quantity(1, unit).to_tuple()[1]


def _describe(unit: pint.Unit) -> str:
    """Name the dimension of a unit: one of ours if it matches, else pint's."""
    ureg = registry()
    dim = unit.dimensionality
    power = _angle_power(unit)
    for name, text in DIMENSIONS.items():
        if (
            ureg.get_dimensionality(text) == dim
            and _ANGLE_POWER.get(name, 0) == power
        ):
            return f"{_article(name)} {_label(name)}"
    if power:
        return f"{dim} with an angle unit to the power {power:g}"
    if dim == ureg.get_dimensionality("1 / [time]"):
        return "a frequency (1 / [time]) with no angle unit"
    return str(dim)


def _is_energy_or_power(ureg: pint.UnitRegistry, name: str) -> bool:
    dim = ureg.get_dimensionality(name)
    energy = ureg.get_dimensionality("[mass] * [length] ** 2 / [time] ** 2")
    power = ureg.get_dimensionality("[mass] * [length] ** 2 / [time] ** 3")
    return dim == energy or dim == power


def _parse_unit(text: str, raw: str, file: str, field: str) -> pint.Unit:
    """Parse the unit part of a value string, with hints for common slips."""
    ureg = registry()

    def fail(message: str) -> ProblemFileError:
        return ProblemFileError(file, field, message)

    for token in re.findall(r"[^\W\d_]+", text):
        m = _GLUED_TORQUE_RE.match(token)
        if m:
            fixed = f"{m['prefix'] or ''}N*{m['length']}"
            raise fail(
                f'"{raw}": "{token}" would not be read as newton-metres (pint reads '
                f'"Nm" as another unit); write "{fixed}"'
            )
    if len(text) > _MAX_UNIT_CHARS or _POWER_CHAIN_RE.search(text):
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


def _check_unit(unit: pint.Unit, raw: str, dimension: str, file: str, field: str) -> None:
    """Check that ``unit`` has the dimension (and angle power) asked for."""
    ureg = registry()
    expected = ureg.get_dimensionality(DIMENSIONS[dimension])
    label = _label(dimension)
    what = f"{_article(label)} {label}"
    if dimension == "dimensionless":
        what = "a dimensionless number"
    if unit.dimensionality != expected:
        raise ProblemFileError(
            file,
            field,
            f'expected {what} ({DIMENSIONS[dimension]}, e.g. '
            f'{_example(dimension)}), got "{raw}", which is {_describe(unit)}',
        )
    power = _angle_power(unit)
    want = _ANGLE_POWER.get(dimension, 0)
    if power != want:
        if want and power == 0:
            if dimension == "angle":
                detail = "it has no angle unit; write it in deg or rad"
            else:
                detail = (
                    "it has no angle unit, so revolutions and radians cannot be "
                    f"told apart (is 1 Hz 1 rev/s or 1 rad/s?); write it as e.g. "
                    f"{_example(dimension, '5')} or \"5 rad/s\""
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
        for name, _ in _unit_items(unit):
            if _is_energy_or_power(ureg, name):
                symbol = format(ureg.Unit(name), "~")
                raise ProblemFileError(
                    file,
                    field,
                    f'"{raw}": {symbol} is a unit of energy or power; torque is '
                    f"written in N*m (J is energy), e.g. \"50 N*m\"",
                )


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
            f"expected a value such as {_example(dimension)}, "
            f"got {value!r}"
            + ("" if value is None else f" (a {_type_name(value)})"),
        )
    if isinstance(value, (dict, list, tuple, set, bytes, np.ndarray)):
        raise ProblemFileError(
            file,
            field,
            f"expected a single value such as {_example(dimension)}, "
            f"got a {_type_name(value)}",
        )

    if isinstance(value, numbers.Real):
        x = float(value)
        if dimension == "dimensionless":
            return _finite(x, repr(x), file, field)
        text = _number_text(value)
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
            f"units are missing: {_article(_label(dimension))} {_label(dimension)} "
            f"needs units; write it as {_example(dimension, text)}",
        )

    if not isinstance(value, str):
        if hasattr(value, "magnitude") and hasattr(value, "units"):
            return _quantity_si(value, dimension, file, field)
        raise ProblemFileError(
            file,
            field,
            f"expected a string such as {_example(dimension)}, "
            f"got a {_type_name(value)}",
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
            f"e.g. {_example(dimension)}{hint}",
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
            f"{_example(dimension, number_text)}",
        )

    factors = _known_factors()
    factor = factors.get((unit_text, dimension))
    if factor is not None:
        si = _finite_si(x * factor, raw, file, field)
    else:
        unit = _parse_unit(unit_text, raw, file, field)
        _check_unit(unit, raw, dimension, file, field)
        ureg = registry()
        si = _finite_si(float(ureg.Quantity(x, unit).m_as(SI_UNITS[dimension] or "dimensionless")), raw, file, field)
        _learn(ureg, unit, unit_text, dimension, x, si)
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
    _check_unit(unit, raw, dimension, file, field)
    si = ureg.Quantity(magnitude, unit).m_as(SI_UNITS[dimension] or "dimensionless")
    return _finite_si(float(si), raw, file, field)


# ---------------------------------------------------------------------------
# public API


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
    _check_dimension(dimension)
    return _scalar_si(value, dimension, file, field)


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
    _check_dimension(dimension)
    example = (
        f"[{_example(dimension, '3')}, {_example(dimension, '-4')}] or "
        f"{{magnitude = {_example(dimension, '5')}, angle = \"30 deg\"}}"
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
        small = _POLAR_ZERO_RTOL * abs(r)
        if abs(x) <= small:
            x = 0.0
        if abs(y) <= small:
            y = 0.0
        return (x, y)
    raise ProblemFileError(
        file,
        field,
        f"expected a vector, written as {example}, got a {_type_name(value)}",
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
    _check_dimension(dimension)
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
        f"{{start = {_example(dimension, '0')}, stop = {_example(dimension, '360')}, "
        f"step = {_example(dimension, '2')}}}"
        if dimension == "angle"
        else f"{{start = {_example(dimension, '0')}, stop = {_example(dimension, '10')}, "
        f"step = {_example(dimension, '1')}}}"
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
    _check_dimension(dimension)
    if isinstance(digits, bool) or not isinstance(digits, numbers.Integral) or digits < 1:
        raise ValueError(f"digits must be an integer >= 1, got {digits!r}")
    ureg = registry()
    si_text = SI_UNITS[dimension]
    unit_text = si_text if unit is None else unit
    try:
        target = ureg.parse_units(unit_text)
        _check_unit(target, unit_text, dimension, "<format_si>", "unit")
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
