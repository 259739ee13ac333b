"""Reading a student's typed answer: plain text in, SI numbers out.

A student types an answer as they would write it on paper; :func:`read_answer`
reads it *as data* (regular expressions and pint's unit parser, never
``eval``) into a :class:`Reading` holding SI numbers. The question supplies
the dimension it expects and its unit, which is assumed when a student writes
a bare number.

Accepted formats (for a force question in ``N``, a torque in ``N*m``, an
angle in ``deg``, a length in ``mm``):

=======================  ==============================================
form                     examples
=======================  ==============================================
scalar                   ``1.29 kN``, ``1290 N``, ``+1290N``,
                         ``1.29e3 N``, ``1.29 × 10³ N``
bare number              ``1290`` (read in the question's unit)
product units            ``108.9 N*m``, ``108.9 N·m``, ``108.9 N m``
                         (a space multiplies), ``108900 N*mm``,
                         ``0.1089 kN*m``, ``0.534 kg·m²``
sense of rotation        ``108.9 N·m CCW``, ``108.9 N*m cw``,
                         ``108.9 N·m clockwise`` (see below)
polar vector             ``27.06 N ∠ -73.78°``, ``27.06 N at -73.78 deg``,
                         ``27.06 N @ -1.2877 rad``, ``27.06 ∠ -73.78``
                         (a bare magnitude is in the question's unit, a
                         bare direction in degrees)
cartesian vector         ``(7.56, -25.98) N``, ``(7.56 N, -25.98 N)``,
                         ``(7.56, -25.98)`` (bare), ``[7.56, -25.98] N``
angle                    ``-73.78°``, ``-73.78 deg``, ``-1.2877 rad``,
                         ``286.22°``, ``-73.78`` (bare)
energy, inertia, ratio   ``237.2 J``, ``0.2372 kJ``, ``0.534 kg*m^2``,
                         ``1.41``
=======================  ==============================================

Before reading, the text is normalised: surrounding whitespace and one
trailing period are dropped; ``·``, ``⋅``, ``∙`` and ``×`` become ``*``;
superscript powers (``²``, ``³``, ``⁻¹``) become ``^2``, ``^3``, ``^-1``;
the Unicode minus and dashes (``−``, ``–``, ``‐``) become ``-``; ``°`` (and
``º``, ``˚``) becomes `` deg``; no-break and thin spaces become spaces.
``µ`` and ``μ`` both mean micro.

Rules:

* **Sense words.** ``CCW``, ``counterclockwise``, ``counter-clockwise``,
  ``anticlockwise``, ``anti-clockwise`` (sense +1) and ``CW``, ``clockwise``
  (sense -1), in any case, optionally in brackets, may end a scalar answer.
  ``CW`` makes the number negative: ``"108.9 N·m CW"`` is −108.9 N·m. A
  negative number with a sense word (``"-108.9 N·m CW"``) is refused: it
  could mean either sense. A sense word after a
  vector is refused.
* **Units.** A unit of the question's dimension is converted to SI. A unit
  of another dimension is *not* an error: the reading has ``value`` (or
  ``vector``) ``None`` and names the dimension written, so that the grader
  can say what was given. Energy and power units (J, kJ, W*s, ...) are
  energy, not torque, although pint finds J = N*m; for an energy question,
  N*m is read as energy. Torque units as people write them are read:
  ``N-m``, ``N.m``, ``Nm``, ``kNm``, ``Nmm``, ``N m``, ``lbf*in``.
* **Refused** (:class:`Unreadable`, whose message is one sentence saying how
  to write the answer): empty text; anything but a string or a real number
  (``None``, ``True``, lists, ...); more than :data:`MAX_CHARS` characters;
  a decimal comma where the exercise reads none (``decimal_comma=False``),
  and an ambiguous one (``"1,352"``) either way (``"0,799"`` is not: no
  thousands separator follows a 0); unknown units (named); two
  numbers where one is expected; anything that is not a number first (``"__import__('os')"``);
  ``nan``, ``inf`` and numbers too large for a float, in the text or once in
  SI; a power of a power (``"m^2^3"``, ``"9**9**9"``) and powers of three
  digits or more; an angle (a direction, or a polar vector's) of more than
  :data:`MAX_TURNS` turns either way, whose float has lost the direction it
  stands for; a polar direction whose unit is not an angle; a vector
  with other than two components, or whose components carry different
  units.

pint is imported lazily, by :func:`graphkin.registry`, on the first
answer that names a unit: importing this module does not load it. Parsed
units are cached, so reading an answer takes a few microseconds once its unit
has been seen.

Examples
--------
>>> r = read_answer("108.9 N·m CW", dimension="torque", unit="N*m")
>>> r.value, r.sense, r.unit
(-108.9, -1, 'N*m')
>>> read_answer("1.29 kN", dimension="force", unit="N").value
1290.0
>>> r = read_answer("237.2 J", dimension="torque", unit="N*m")
>>> r.value is None, r.dimension
(True, 'energy')
>>> read_answer("12,5 N", dimension="force", unit="N").value  # a decimal comma, where the exercise reads one
12.5
>>> try:
...     read_answer("12,5 N", dimension="force", unit="N", decimal_comma=False)
... except Unreadable as exc:
...     print(exc)
Could not read "12,5 N": write a number and a unit, such as "27.06 N" (use a decimal point).
"""

from __future__ import annotations

import functools
import math
import numbers
import re
from dataclasses import dataclass
from typing import Any

from graphkin.errors import GraphkinError
from graphkin.units import checks
from graphkin.units.convert import POLAR_ZERO_RTOL
from graphkin.units.dimensions import ANGLE_POWER, DIMENSIONS, SI_UNITS
from graphkin.units.registries import registry

__all__ = ["MAX_CHARS", "MAX_TURNS", "Reading", "Unreadable", "read_answer"]

#: The longest answer read, in characters (after stripping surrounding
#: whitespace); a longer one is refused before any parsing.
MAX_CHARS = 200

#: The most turns an angle may have either way (a direction, or a direction of a polar vector): beyond, its float
#: has lost the direction it stands for, and it is refused.
MAX_TURNS = 1_000_000

# A flywheel question asks for an energy; J, kJ and N*m are all right for it
# (for a torque question J is not), so energy is told from torque here.
_ENERGY = "energy"
_ENERGY_DIMENSIONALITY = DIMENSIONS["torque"]  # [mass]*[length]**2/[time]**2
_POWER_DIMENSIONALITY = "[mass] * [length] ** 2 / [time] ** 3"
# (graphkin.units may know energy too; the set does not mind.)
_QUESTION_DIMENSIONS = frozenset(DIMENSIONS) | {_ENERGY}

# Number shown in "such as ..." hints, with the question's unit.
_EXAMPLE_NUMBER = "27.06"
_EXAMPLE_VECTOR = "(7.56, -25.98)"
_EXAMPLE_DIRECTION = "-73.78 deg"
# How much of the student's text a message quotes.
_SHOWN_CHARS = 40
# Parsed units kept; bounded because student text is arbitrary.
_UNIT_CACHE_SIZE = 4096

# --- normalisation --------------------------------------------------------

_TRANSLATE = str.maketrans(
    {
        "·": "*",  # middle dot
        "⋅": "*",  # dot operator
        "∙": "*",  # bullet operator
        "×": "*",
        "−": "-",  # minus sign
        "–": "-",  # en dash
        "‐": "-",  # hyphen
        "‑": "-",  # non-breaking hyphen
        "°": " deg",
        "º": " deg",  # masculine ordinal, typed for a degree on many keyboards
        "˚": " deg",  # ring above
        "\u00a0": " ",  # no-break space (pasted from books and web pages)
        "\u2009": " ",  # thin space
        "\u202f": " ",  # narrow no-break space
    }
)
_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻", "0123456789+-")
_SUPERSCRIPT_RE = re.compile(r"[⁺⁻]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+")
_SPACES_RE = re.compile(r"\s+")

# --- the parts of an answer -----------------------------------------------

# A sense word ends the answer, optionally in brackets; it may not be glued
# to a unit ("N*mCW"). Which group matched gives the sense.
_SENSE_RE = re.compile(
    r"""\ ?(?P<open>\()?(?<![^\W\d_])
        (?:(?P<ccw>counter[-\ ]?clockwise|anti[-\ ]?clockwise|ccw)|(?P<cw>clockwise|cw))
        (?(open)\))$""",
    re.IGNORECASE | re.VERBOSE,
)
# "∠", "@" or the word "at" between a magnitude and a direction.
_POLAR_RE = re.compile(r" ?(?:∠|@|(?<![^\W\d_])at(?![^\W\d_])) ?", re.IGNORECASE)
_VECTOR_RE = re.compile(
    r"^(?:\((?P<a>[^()\[\]]*)\)|\[(?P<b>[^()\[\]]*)\]) ?(?P<unit>.*)$", re.DOTALL
)
# A number, optionally times a power of ten ("1.29 × 10³"), then the rest.
# ASCII digits only: float() would also take other scripts' digits.
_NUMBER_RE = re.compile(
    r"""(?P<number>[+-]?\ ?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)
        (?:\ ?[*x]\ ?10\ ?(?:\^|\*\*)\ ?(?P<exp10>[+-]?[0-9]+))?
        \ ?(?P<rest>.*)""",
    re.VERBOSE | re.DOTALL,
)
_NOT_FINITE_RE = re.compile(r"[+-]? ?(?:nan|inf(?:inity)?)(?![^\W\d_])", re.IGNORECASE)
_DECIMAL_COMMA_RE = re.compile(r"\d,\d")
# A number written with commas: "1,29", "1,352", "12,345,678", "12,352.5".
_COMMA_NUMBER_RE = re.compile(r"(?<![\w.,])\d+(?:,\d+)+(?:\.\d+)?(?:[eE][+-]?\d+)?(?![\w,])")
# Thousands separated by commas: a first group of one to three digits that does not start with 0 ("0,799" and
# "1234,567" are decimal commas), then groups of three.
_THOUSANDS_RE = re.compile(r"[1-9]\d{0,2}(?:,\d{3})+(?:\.\d+)?")
# Spaces around operators go; a space left between two units multiplies.
_OPERATOR_SPACES_RE = re.compile(r" ?([*/^()]) ?")
_EXPONENT_RE = re.compile(r"(?:\^|\*\*)[+-]?\d+(?:\.\d+)?")
# A number inside the unit text (after its powers are removed): "12 5 N".
_STRAY_NUMBER_RE = re.compile(r"(?:^|[*/()+-])\.?\d")
_LETTERS_RE = re.compile(r"[^\W\d_]+")
# Units joined by "-" or "." ("N-m", "N.m", "ft-lbf"), as many books print them: a product.
_JOINED_UNITS_RE = re.compile(r"(?<=[^\W\d_])[-.](?=[^\W\d_])")
_WORD_RE = re.compile(r"[^\W\d_]+")
# What may reach pint: unit names with integer powers of one or two digits,
# "*", "/", brackets and "%", optionally after "1/". Possessive quantifiers
# keep the match linear on any text.
_POWER = r"(?:\^|\*\*)[+-]?\d{1,2}"
_UNIT_TEXT_RE = re.compile(
    rf"(?:1/)?(?:[^\W\d]\w*+(?:{_POWER})?+|\)(?:{_POWER})?+|[(*/%])++"
)


class Unreadable(GraphkinError):
    """An answer that cannot be read.

    ``str(exc)`` is one plain sentence telling the student how to write the
    answer, with an example in the question's unit, e.g. ``Could not read
    "12,5 N": write a number and a unit, such as "27.06 N" (use a decimal
    point).`` It is a :class:`ValueError` (through
    :class:`graphkin.errors.GraphkinError`).
    """


@dataclass(frozen=True, slots=True)
class Reading:
    """A student's answer, read.

    Attributes
    ----------
    text : str
        The answer as typed, stripped of surrounding whitespace.
    form : str
        ``"scalar"``, ``"polar"`` (magnitude and direction) or ``"vector"``
        (two components).
    number : float or None
        Scalar: the number as written, with the sense applied, not
        converted (``"1.29 kN"`` gives 1.29). Polar: the magnitude as
        written. Vector: ``None``.
    value : float or None
        Scalar: the value in the SI unit of the question's dimension;
        ``None`` if the unit written has another dimension.
    vector : tuple of float or None
        Polar and vector: ``(x, y)`` in SI; ``None`` if the unit written has
        another dimension, and for a scalar.
    angle : float or None
        Polar: the direction as written, in rad (``286.22°`` is not wrapped
        to ``-73.78°``); ``None`` otherwise.
    unit : str
        The unit as written, normalised (``"N·m"`` and ``"N m"`` give
        ``"N*m"``); ``""`` for a bare number.
    dimension : str or None
        The dimension of the unit written: a key of
        :data:`graphkin.DIMENSIONS` (angle powers respected, so
        ``rad/s`` is ``"angular_velocity"`` and ``Hz`` is not), ``"energy"``
        for J, kJ, W*s, ... (and for N*m when the question asks for an
        energy), ``"power"`` for W, N*m/s, ..., else pint's dimensionality,
        e.g. ``"[length] / [mass]"``. ``None`` for a bare number.
    sense : int or None
        +1 for a counterclockwise word, -1 for a clockwise one, ``None`` if
        there is no such word.
    bare : bool
        True when no unit was written (the question's unit was assumed).
    """

    text: str
    form: str
    number: float | None
    value: float | None
    vector: tuple[float, float] | None
    angle: float | None
    unit: str
    dimension: str | None
    sense: int | None
    bare: bool


# ---------------------------------------------------------------------------
# units (cached; the only place pint is used)


@dataclass(frozen=True, slots=True)
class _Unit:
    """What a unit text means: its kind and its factor to SI."""

    kind: str  # a DIMENSIONS key, "energy", "power", or pint's dimensionality text
    factor: float | None  # to the SI unit of ``kind``; None when kind is not ours


@dataclass(frozen=True, slots=True)
class _BadUnit:
    """A unit text pint could not read, and the names it did not know."""

    unknown: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class _Question:
    dimension: str
    unit: str  # as given, for hints
    factor: float  # question unit -> SI


@functools.lru_cache(maxsize=_UNIT_CACHE_SIZE)
def _unit(text: str) -> _Unit | _BadUnit:
    """Parse a normalised unit text with pint; failures are cached too.

    Parameters
    ----------
    text : str
        A unit text that passed :data:`_UNIT_TEXT_RE` (or ``""``).

    Returns
    -------
    _Unit or _BadUnit
    """
    ureg = registry()
    try:
        unit = ureg.parse_units(text)
        kind = _kind(ureg, unit)
        factor = None
        si = _si_unit(kind)
        if si is not None:
            factor = float(ureg.Quantity(1.0, unit).m_as(si))
    except Exception as exc:  # pint raises many types (UndefinedUnitError, TypeError, ...)
        names = getattr(exc, "unit_names", None) or ()
        if isinstance(names, str):
            names = (names,)
        return _BadUnit(tuple(str(n) for n in names))
    if factor is not None and not (math.isfinite(factor) and factor > 0.0):
        return _BadUnit(())  # e.g. a power overflowing the SI factor; not a unit to grade
    return _Unit(kind, factor)


def _si_unit(kind: str) -> str | None:
    si = {_ENERGY: "J", "power": "W"}.get(kind) or SI_UNITS.get(kind)
    if si is None:
        return None
    return si or "dimensionless"


def _kind(ureg: Any, unit: Any) -> str:
    """Name what a unit measures, telling energy from torque and angles from ratios."""
    dim = unit.dimensionality
    power = checks.angle_power(unit)
    if power == 0 and dim == ureg.get_dimensionality(_ENERGY_DIMENSIONALITY):
        # pint finds J == N*m; the unit names tell energy from a moment.
        names = (name for name, _ in checks.unit_items(unit))
        if any(checks.is_energy_or_power(ureg, name) for name in names):
            return _ENERGY
        return "torque"
    if power == 0 and dim == ureg.get_dimensionality(_POWER_DIMENSIONALITY):
        return "power"
    for name, dimensionality in DIMENSIONS.items():
        if (
            ureg.get_dimensionality(dimensionality) == dim
            and ANGLE_POWER.get(name, 0) == power
        ):
            return name
    text = "" if not dim else str(dim)
    if power:
        angle = "[angle]" if power == 1 else f"[angle] ** {power:g}"
        text = f"{text} * {angle}" if text else angle
    return text or "dimensionless"


def _written_kind(u: _Unit, question: str) -> str:
    """The kind reported for a unit; N*m for an energy question is energy."""
    if question == _ENERGY and u.kind == "torque":
        return _ENERGY
    return u.kind


@functools.lru_cache(maxsize=256)
def _question(dimension: str, unit: str) -> _Question:
    """Check and cache the question's dimension and unit (a programming error raises)."""
    if dimension not in _QUESTION_DIMENSIONS:
        known = ", ".join(sorted(_QUESTION_DIMENSIONS))
        raise ValueError(f"unknown dimension {dimension!r}; known: {known}")
    if unit:
        text = _unit_text(_normalise(unit))
        parsed = _unit(text) if _UNIT_TEXT_RE.fullmatch(text) else None
    else:
        parsed = _unit("")
    if not isinstance(parsed, _Unit) or _written_kind(parsed, dimension) != dimension:
        raise ValueError(f"{unit!r} is not a unit of {dimension}")
    return _Question(dimension, unit, parsed.factor)


# ---------------------------------------------------------------------------
# text helpers


def _normalise(text: str) -> str:
    """Typographic variants to plain ASCII operators; one space between words."""
    text = text.translate(_TRANSLATE)
    text = _SUPERSCRIPT_RE.sub(_superscript, text)
    text = _SPACES_RE.sub(" ", text).strip()
    if text.endswith("."):
        text = text[:-1].rstrip()
    return text


def _superscript(m: re.Match) -> str:
    return "^" + m[0].translate(_SUPERSCRIPTS)


def _unit_text(rest: str) -> str:
    """Normalise the unit part: no spaces around operators; a space, "-" or "." between units multiplies.

    ``N m``, ``N-m``, ``N.m`` and ``N*m`` are one unit; so are ``ft-lbf`` and ``in·lbf``. ``Nm``, ``kNm``
    and ``Nmm`` (which pint would read as nanometres, or not at all) are newton-metres.
    """
    text = _OPERATOR_SPACES_RE.sub(r"\1", rest.strip()).replace(" ", "*")
    text = _JOINED_UNITS_RE.sub("*", text)
    return _WORD_RE.sub(_unglue, text)


def _unglue(m: re.Match) -> str:
    glued = checks.GLUED_TORQUE.match(m[0])
    return f"{glued['prefix'] or ''}N*{glued['length']}" if glued else m[0]


def _shown(text: str) -> str:
    """The student's text for a message: printable, on one line, short."""
    text = "".join(
        c if c.isprintable() else "\N{REPLACEMENT CHARACTER}"
        for c in text[: _SHOWN_CHARS + 1]
    )
    if len(text) > _SHOWN_CHARS:
        text = text[: _SHOWN_CHARS - 1] + "…"
    return text


class _Context:
    """The answer being read, the question, and whether a decimal comma is read; for messages."""

    __slots__ = ("raw", "q", "comma")

    def __init__(self, raw: str, q: _Question, comma: bool = True):
        self.raw = raw
        self.q = q
        self.comma = comma

    def example(self, number: str = _EXAMPLE_NUMBER, unit: str | None = None) -> str:
        unit = self.q.unit if unit is None else unit
        return f'"{number} {unit}"' if unit else f'"{number}"'

    def polar_example(self) -> str:
        magnitude = f"{_EXAMPLE_NUMBER} {self.q.unit}".strip()
        return f'"{magnitude} @ {_EXAMPLE_DIRECTION}"'

    def vector_example(self) -> str:
        unit = f" {self.q.unit}" if self.q.unit else ""
        return f'"{_EXAMPLE_VECTOR}{unit}"'

    def fail(self, advice: str) -> Unreadable:
        return Unreadable(f'Could not read "{_shown(self.raw)}": {advice}.')

    def sense_advice(self) -> str:
        example = self.example(unit=f"{self.q.unit} CCW".strip())
        return f"CW and CCW go after a single number, such as {example}"

    def scalar_advice(self) -> str:
        if not self.q.unit:  # a dimensionless question
            return f"write a number, such as {self.example()}"
        return f"write a number and a unit, such as {self.example()}"


# ---------------------------------------------------------------------------
# reading


def _number(part: str, ctx: _Context, what: str) -> tuple[float, str]:
    """Read ``number [unit]`` from the start of ``part``.

    Returns
    -------
    number : float
        The number, finite.
    rest : str
        What follows the number (the unit text, not yet normalised).
    """
    m = _NUMBER_RE.match(part)
    if m is None:
        if _NOT_FINITE_RE.match(part):
            raise ctx.fail(f"nan and inf are not numbers to grade; {what}")
        raise ctx.fail(what)
    digits = m["number"].replace(" ", "")
    if m["exp10"] is not None:
        mantissa, _, exponent = digits.lower().partition("e")
        digits = f"{mantissa}e{int(exponent or 0) + int(m['exp10'])}"
    x = float(digits)
    if not math.isfinite(x):
        raise ctx.fail(f"the number is too large; {what}")
    return x, m["rest"]


def _check_unit_text(text: str, ctx: _Context, what: str) -> None:
    """Refuse, with a hint, unit texts pint would misread or should not see."""
    if len(text) > checks.MAX_UNIT_CHARS:
        raise ctx.fail(f"the unit is too long; {what}")
    if checks.POWER_CHAIN.search(text):
        raise ctx.fail('write one power per unit, such as "kg*m^2"')
    bare = text[2:] if text.startswith("1/") else text
    if _STRAY_NUMBER_RE.search(_EXPONENT_RE.sub("", bare)):
        raise ctx.fail(ctx.scalar_advice().replace("a number", "one number", 1))
    if not _UNIT_TEXT_RE.fullmatch(text):
        raise ctx.fail(f"could not read the unit; {what}")


def _parse_unit(text: str, ctx: _Context, what: str) -> _Unit:
    """The meaning of a normalised, non-empty unit text, or a hint."""
    _check_unit_text(text, ctx, what)
    u = _unit(text)
    if isinstance(u, _BadUnit):
        if u.unknown:
            names = ", ".join(f'"{_shown(n)}"' for n in u.unknown)
            hint = ""
            if any(n[-1:].isdigit() for n in u.unknown):
                hint = ' (write a power with "^", such as "m^2")'
            plural = "are not units" if len(u.unknown) > 1 else "is not a unit"
            raise ctx.fail(f"{names} {plural}{hint}; {what}")
        raise ctx.fail(f"could not read the unit; {what}")
    return u


def _finite(x: float, ctx: _Context) -> float:
    if not math.isfinite(x):
        raise ctx.fail(f"the number is too large; write a finite number, such as {ctx.example()}")
    return x


def _turns(a: float, ctx: _Context) -> float:
    """A direction [rad] of at most :data:`MAX_TURNS` turns either way; a larger one, whose float has lost the
    direction it stands for ("1e20°" is 280°, but 1.745e18 rad ± 256 rad), is refused."""
    if abs(a) > 2 * math.pi * MAX_TURNS:
        raise ctx.fail(f"the angle is more than {MAX_TURNS:,} turns, too large to read as a direction; write it "
                       "between -360° and 360°, such as \"-73.78°\"")
    return a


def _quantity(part: str, ctx: _Context, what: str) -> tuple[float, str, _Unit | None]:
    """Read ``number [unit]``: the number, the normalised unit text, its meaning."""
    x, rest = _number(part, ctx, what)
    text = _unit_text(rest)
    if not text:
        return x, "", None
    try:
        return x, text, _parse_unit(text, ctx, what)
    except Unreadable:
        _trailing_words(rest, ctx)
        raise


def _trailing_words(rest: str, ctx: _Context) -> None:
    """Refuse, naming them, words after a unit that reads ("12 N approx", "251 N*m CCW about A0")."""
    words = rest.split()
    for k in range(len(words) - 1, 0, -1):
        head = _unit_text(" ".join(words[:k]))
        if not _UNIT_TEXT_RE.fullmatch(head) or checks.POWER_CHAIN.search(head) or \
                len(head) > checks.MAX_UNIT_CHARS or not isinstance(_unit(head), _Unit):
            continue
        tail = words[k:]
        sense = _SENSE_RE.search(" " + tail[0])
        if sense is not None and len(tail) > 1:
            tail = tail[1:]
        if not tail[0][:1].isalpha():
            return  # a second number ("1290 N 1.29 kN"): the reader's own sentence says to write one
        shown = _shown(" ".join(tail))
        example = ctx.example(unit=f"{ctx.q.unit} CCW".strip()) if sense is not None else ctx.example()
        raise ctx.fail(f'"{shown}" after the unit is not part of an answer: write only the value, such as {example}')


def _to_si(x: float, u: _Unit | None, ctx: _Context) -> float | None:
    """``x`` in SI if its unit (None: the question's) has the question's dimension."""
    if u is None:
        return _finite(x * ctx.q.factor, ctx)
    if _written_kind(u, ctx.q.dimension) != ctx.q.dimension:
        return None
    return _finite(x * u.factor, ctx)


def _read_scalar(body: str, sense: int | None, ctx: _Context) -> Reading:
    what = ctx.scalar_advice()
    x, text, u = _quantity(body, ctx, what)
    if sense is not None:
        if x < 0:
            # "−108.9 N·m CW" could mean CW or its negative, CCW: refused rather than guessed.
            example = ctx.example(unit=f"{ctx.q.unit} CW".strip())
            raise ctx.fail(f"give a signed number or the size with CW/CCW, not both, such as {example}")
        x = sense * x
    value = _to_si(x, u, ctx)
    if value is not None and ctx.q.dimension == "angle":
        value = _turns(value, ctx)
    return Reading(
        text=ctx.raw,
        form="scalar",
        number=x,
        value=value,
        vector=None,
        angle=None,
        unit=text,
        dimension=None if u is None else _written_kind(u, ctx.q.dimension),
        sense=sense,
        bare=u is None,
    )


def _read_polar(magnitude: str, direction: str, ctx: _Context) -> Reading:
    what = f"write a magnitude and a direction, such as {ctx.polar_example()}"
    r, text, u = _quantity(magnitude, ctx, what)
    a, _, a_unit = _quantity(direction, ctx, what)
    if a_unit is None:
        a = math.radians(a)  # a bare direction is in degrees, as the books print it
    elif a_unit.kind != "angle":
        raise ctx.fail(
            f"the direction must be an angle, in deg or rad, such as {ctx.polar_example()}"
        )
    else:
        a = _finite(a * a_unit.factor, ctx)
    a = _turns(a, ctx)
    r_si = _to_si(r, u, ctx)
    vector = None if r_si is None else _polar_xy(r_si, a)
    return Reading(
        text=ctx.raw,
        form="polar",
        number=r,
        value=None,
        vector=vector,
        angle=a,
        unit=text,
        dimension=None if u is None else _written_kind(u, ctx.q.dimension),
        sense=None,
        bare=u is None,
    )


def _polar_xy(r: float, a: float) -> tuple[float, float]:
    """Components of a polar vector; roundoff-sized ones are exactly 0.0 (90° gives x == 0.0)."""
    x, y = r * math.cos(a), r * math.sin(a)
    small = POLAR_ZERO_RTOL * abs(r)
    return (0.0 if abs(x) <= small else x, 0.0 if abs(y) <= small else y)


def _commas(text: str, ctx: _Context) -> str:
    """Decimal commas as points ("1,29" → "1.29") where the exercise reads them; other commas in a
    number (a thousands separator, or a decimal comma the exercise does not read) refused with a sentence."""
    def fix(m: re.Match) -> str:
        number, exponent = re.fullmatch(r"([^eE]*)(.*)", m[0]).groups()
        plain = number.replace(",", "")
        if _THOUSANDS_RE.fullmatch(number) and (number.count(",") > 1 or "." in number) and not exponent:
            raise ctx.fail(f'write {plain} without a thousands separator')
        if number.count(",") > 1 or "." in number:
            return m[0]  # a list of numbers, not one: the caller says how to write a vector
        whole, frac = number.split(",")
        if _THOUSANDS_RE.fullmatch(number) and not exponent:
            if ctx.comma:
                raise ctx.fail(f'"{number}" could be {whole}.{frac} or {plain}: write {whole}.{frac} (a decimal '
                               f'point) or {plain} (no separator)')
            raise ctx.fail(f"write {plain} without a thousands separator, or {whole}.{frac} with a decimal point")
        if not ctx.comma:
            raise ctx.fail(f"{ctx.scalar_advice()} (use a decimal point)")
        return f"{whole}.{frac}{exponent}"

    return _COMMA_NUMBER_RE.sub(fix, text)


def _components(body: str, ctx: _Context, what: str) -> list[str]:
    """The two components of a bracketed vector: split at ";", else at its one comma, else (decimal
    commas) at its one ", "."""
    body = body.strip()
    if ";" in body:
        parts = [_commas(p.strip(), ctx) for p in body.split(";")]
    else:
        parts = [p.strip() for p in body.split(",")]
        if len(parts) != 2 and ctx.comma and len(body.split(", ")) == 2:
            parts = [_commas(p.strip(), ctx) for p in body.split(", ")]
    if len(parts) != 2:
        if _DECIMAL_COMMA_RE.search(body):
            what += (' (with decimal commas, put ";" between the components, such as "(7,56; -25,98)")'
                     if ctx.comma else " (use a decimal point)")
        raise ctx.fail(f"a planar vector has two components; {what}")
    return parts


def _read_vector(body: str, outer: str, ctx: _Context) -> Reading:
    what = f"write two components in brackets, such as {ctx.vector_example()}"
    parts = _components(body, ctx, what)
    (x, x_text, x_unit), (y, y_text, y_unit) = (_quantity(p, ctx, what) for p in parts)
    outer_text = _unit_text(outer)
    if x_text != y_text:
        raise ctx.fail(f"write both components in one unit, such as {ctx.vector_example()}")
    if outer_text and x_text:
        raise ctx.fail(f"write the unit once, such as {ctx.vector_example()}")
    text = outer_text or x_text
    u = x_unit if x_text else (_parse_unit(outer_text, ctx, what) if outer_text else None)
    x_si, y_si = _to_si(x, u, ctx), _to_si(y, u, ctx)
    return Reading(
        text=ctx.raw,
        form="vector",
        number=None,
        value=None,
        vector=None if x_si is None else (x_si, y_si),
        angle=None,
        unit=text,
        dimension=None if u is None else _written_kind(u, ctx.q.dimension),
        sense=None,
        bare=u is None,
    )


def _split_sense(text: str) -> tuple[str, int | None]:
    """Take a sense word off the end of the text."""
    m = _SENSE_RE.search(text)
    if m is None:
        return text, None
    sense = 1 if m["ccw"] else -1
    return text[: m.start()].rstrip(), sense


def _read_number(value: Any, q: _Question) -> Reading:
    """A real number given instead of text: a bare number in the question's unit."""
    advice = _Context("", q).scalar_advice()
    try:
        x = float(value)
    except (OverflowError, ValueError, TypeError):
        # str() of a huge int can itself fail, so the number is not quoted.
        raise Unreadable(f"Could not read the number given: it is too large; {advice}.") from None
    ctx = _Context(str(value), q)
    if not math.isfinite(x):
        raise ctx.fail(f"nan and inf are not numbers to grade; {advice}")
    value = _finite(x * q.factor, ctx)
    if q.dimension == "angle":
        value = _turns(value, ctx)
    return Reading(
        text=ctx.raw,
        form="scalar",
        number=x,
        value=value,
        vector=None,
        angle=None,
        unit="",
        dimension=None,
        sense=None,
        bare=True,
    )


def read_answer(text: Any, *, dimension: str, unit: str, decimal_comma: bool = True) -> Reading:
    """Read a student's typed answer into SI numbers.

    Parameters
    ----------
    text : str, int or float
        The answer as typed, e.g. ``"108.9 N·m CCW"``, ``"27.06 N ∠ -73.78°"``,
        ``"(7.56, -25.98) N"`` (formats: see the module docstring). A real
        number is read as a bare number.
    dimension : str
        The question's dimension: a key of :data:`graphkin.DIMENSIONS`
        or ``"energy"``.
    unit : str
        The question's unit in pint spelling (``"N"``, ``"N*m"``, ``"deg"``,
        ``"kg*m^2"``, ``""`` for a dimensionless number): used for a bare
        number and in the messages' examples.
    decimal_comma : bool
        Whether a decimal comma is read (``"1,29 kN"``; the exercise's
        ``decimal_comma``). Either way a comma that could separate
        thousands (``"1,352"``) is refused with a sentence.

    Returns
    -------
    Reading
        The answer read; ``value`` (scalar) or ``vector`` (polar, vector) is
        ``None`` if the unit written is not of ``dimension``.

    Raises
    ------
    Unreadable
        If the answer cannot be read; the message is one sentence saying how
        to write it.
    ValueError
        If ``dimension`` is unknown or ``unit`` is not a unit of it (a
        programming error, not the student's).

    Examples
    --------
    >>> r = read_answer("27.06 N ∠ -73.78°", dimension="force", unit="N")
    >>> r.form, round(r.vector[0], 2), round(r.vector[1], 2)
    ('polar', 7.56, -25.98)
    >>> round(read_answer("-73.78", dimension="angle", unit="deg").value, 6)
    -1.287704
    """
    if not isinstance(dimension, str) or not isinstance(unit, str):
        raise ValueError(
            f"the question's dimension and unit must be strings, got {dimension!r}, {unit!r}"
        )
    q = _question(dimension, unit)
    if isinstance(text, bool) or not isinstance(text, (str, numbers.Real)):
        kind = "None" if text is None else type(text).__name__
        advice = _Context("", q).scalar_advice()
        raise Unreadable(f"Could not read an answer of type {kind}: {advice}.")
    if not isinstance(text, str):
        return _read_number(text, q)
    raw = text.strip()
    ctx = _Context(raw, q, decimal_comma)
    if not raw:
        raise Unreadable(f"The answer is empty: {ctx.scalar_advice()}.")
    if len(raw) > MAX_CHARS:
        raise Unreadable(
            f"The answer is too long ({len(raw)} characters, at most {MAX_CHARS}): "
            f"write a number and a unit, such as {ctx.example()}."
        )
    body, sense = _split_sense(_normalise(raw))
    vector = _VECTOR_RE.match(body)
    if vector is not None:
        if sense is not None:
            raise ctx.fail(ctx.sense_advice())
        body = vector["a"] if vector["a"] is not None else vector["b"]
        return _read_vector(body, vector["unit"], ctx)
    body = _commas(body, ctx)
    if "," in body:
        raise ctx.fail(f"write a vector in brackets, such as {ctx.vector_example()}")
    parts = _POLAR_RE.split(body)
    if len(parts) == 1:
        return _read_scalar(body, sense, ctx)
    if sense is not None:
        raise ctx.fail(ctx.sense_advice())
    if len(parts) > 2:
        raise ctx.fail(f"write a magnitude and one direction, such as {ctx.polar_example()}")
    return _read_polar(parts[0], parts[1], ctx)
