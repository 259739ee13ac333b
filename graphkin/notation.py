"""Every printed form, once: numbers, the minus sign, rounding residues, the polar form and the input position.

Text for people (reports, captions, handouts, drawings, exercise feedback)
is written here; the data (JSON, result objects) keeps what was computed.

* **Numbers** (:func:`num`): significant figures, without an exponent
  where a book would print none (``50640 N``, not ``5.064e+04 N``).
* **The minus sign**: a true minus ``−`` (U+2212) in what is typeset
  (drawings, handouts, exercise sheets), a hyphen-minus ``-`` in plain
  text a program or a terminal reads (the command line's reports).
* **Rounding residues**: a solution at a dead centre or a symmetric
  position has values that are zero in exact arithmetic and 1e-12 N or
  1e-14 mm after floating-point rounding; printed as they are
  ("3.284e-12 N", "d = 2.755e-14 mm") they read as if they meant
  something, so text shows them as 0 (:func:`unless_rounding`).
* **The polar form** as the books print it (:func:`polar`,
  :func:`polar_text`): ``27.06 N ∠ −73.78°``, degrees from +x, CCW positive.
* **The input position**: to the digits a report prints
  (:func:`input_text`, ``θ12 = 62°``) or to as many as name the very
  position (:func:`position_text`, for messages about a position that fails).

Examples
--------
>>> num(50640.7)
'50640'
>>> num(-0.01234, minus="-")
'-0.01234'
>>> num(3.2e-12, zero=1e-9)
'0'
>>> polar_text([7.5586, -25.9783], minus="-")
'27.06 N ∠ -73.78°'
"""

from __future__ import annotations

import math
import re

MINUS = "\u2212"
"""The true minus sign, for text that is typeset."""

RESIDUE = 1e-12
"""A value this small beside its scale (the largest force at the position, for a force) is rounding: shown as 0."""

PICOMETRE = 1e-12
"""A length [m] below which a distance in a linkage is rounding: no drawing or machine tells it from 0."""

PLAIN_FROM, PLAIN_TO = 1e-4, 1e9
"""Numbers of this size [from, to) are printed without a power of ten (7580 N, 123500 N, 0.0001234 m)."""


def largest(forces) -> float:
    """The largest size of ``forces`` ((x, y) pairs [N]), 0 for none: what a force among them is rounding beside."""
    return max((math.hypot(*F) for F in forces), default=0.0)


def unless_rounding(x: float, scale: float) -> float:
    """``x``, or 0 where it is rounding beside ``scale`` (:data:`RESIDUE` of it).

    A driving torque [N·m] is measured against the largest force times a
    metre, so ``scale`` is the largest force [N] for a force and a torque alike.
    """
    return 0.0 if abs(x) <= RESIDUE * abs(scale) else x + 0.0


def num(x: float, digits: int = 4, *, minus: str = MINUS, zero: float = 0.0, nonfinite: str | None = None,
        power: bool = False) -> str:
    """``x`` with ``digits`` significant figures, without an exponent from 1e-4 to 1e9.

    Parameters
    ----------
    x : float
    digits : int
        Significant figures.
    minus : str
        The minus sign: a true minus (drawings, handouts) or ``"-"`` (plain text).
    zero : float
        Values not larger than this in size are rounding residues: ``"0"``.
    nonfinite : str, optional
        What to print for nan or ±inf (default: Python's ``nan``, ``inf``).
    power : bool or "superscript"
        Write a power of ten as ``1.5×10^−5`` instead of ``1.5e−05`` (for
        text a student reads as an answer), or with ``"superscript"`` as
        ``1.5×10⁻⁵`` (for a drawing's labels, as a book prints it).

    Returns
    -------
    str
        ``22850`` rather than ``2.285e+04``; ``2.5e-05`` below 1e-4.

    Examples
    --------
    >>> num(25.97834), num(-0.865942), num(7580.38), num(-0.0), num(123456.0), num(9.99996)
    ('25.98', '−0.8659', '7580', '0', '123500', '10')
    >>> num(1.5e-5, power=True), num(-5.871e-5, power="superscript"), num(float("nan"), nonfinite="—")
    ('1.5×10^−5', '−5.871×10⁻⁵', '—')
    """
    x = float(x)
    if x == 0 or abs(x) <= zero:
        return "0"
    if not math.isfinite(x):
        return str(x) if nonfinite is None else nonfinite
    text = f"{x:.{digits}g}"
    if "e" in text:
        if PLAIN_FROM <= abs(x) < PLAIN_TO:
            # 22850 rather than 2.285e+04: the same digits, read at a glance.
            places = digits - 1 - math.floor(math.log10(abs(x)))
            text = f"{round(x, places):.{max(places, 0)}f}"
        elif power:
            mantissa, exponent = text.split("e")
            exponent = str(int(exponent))
            # "superscript": as a drawing or a typeset page prints it (5.871×10⁻⁵); True: as one types it.
            text = f"{mantissa}×10" + (exponent.translate(_SUPERSCRIPT) if power == "superscript" else f"^{exponent}")
    return text.replace("-", minus)


def fixed(x: float, places: int = 2, *, minus: str = MINUS) -> str:
    """``x`` with a fixed number of decimals (an angle: ``−73.78``), never ``−0.00``; ``—`` for nan.

    Examples
    --------
    >>> fixed(-73.7812), fixed(-0.001), fixed(12.0, 1, minus="-")
    ('−73.78', '0.00', '12.0')
    """
    x = float(x)
    if not math.isfinite(x):
        return "—"
    text = f"{x:.{places}f}"
    if float(text) == 0:
        text = text.lstrip("-")
    return text.replace("-", minus)


def polar(v) -> tuple[float, float]:
    """Magnitude and angle [deg] in (−180°, 180°] of a plane vector, as the books print it.

    Parameters
    ----------
    v : (float, float)
        The vector's components.

    Returns
    -------
    size, angle : float
        Its magnitude, and its direction [deg] from +x, CCW positive; rounding noise in a component
        (1e-12 of the size) is taken as 0, so that 180° never prints as −180°.

    Examples
    --------
    >>> polar([-7.555, -1e-16])
    (7.555, 180.0)
    """
    x, y = (float(c) for c in v)
    size = math.hypot(x, y)
    # Rounding noise must not turn 180° into −180°.
    tiny = 1e-12 * size
    x, y = (0.0 if abs(x) <= tiny else x), (0.0 if abs(y) <= tiny else y)
    angle = math.degrees(math.atan2(y, x))
    return size, (180.0 if angle == -180.0 else angle)


def polar_text(v, unit: str = "N", digits: int = 4, *, scale: float = 0.0, minus: str = MINUS) -> str:
    """A vector as the books print it: ``27.06 N ∠ −73.78°``; ``0 N`` if it is rounding beside ``scale``.

    Parameters
    ----------
    v : (float, float)
        The vector's components, in ``unit``.
    unit : str
        Its unit as printed ("" for none).
    digits : int
        Significant figures of the magnitude (the angle has two decimals).
    scale : float
        What the vector may be rounding beside (:data:`RESIDUE` of it): the
        largest force at the position, for a force. 0 prints any vector that is
        not exactly zero.
    minus : str
        The minus sign (:data:`MINUS`, or ``"-"`` for plain text).

    Returns
    -------
    str
        Magnitude, unit and angle, e.g. ``27.06 N ∠ −73.78°``.

    Examples
    --------
    >>> polar_text([0.0, 0.0]), polar_text([3e-15, 0.0], scale=100.0), polar_text([-1.0, -1.0], "m/s²")
    ('0 N', '0 N', '1.414 m/s² ∠ −135.00°')
    """
    size, angle = polar(v)
    unit = f" {unit}" if unit else ""
    if size == 0 or unless_rounding(size, scale) == 0:
        return f"0{unit}"
    return f"{num(size, digits, minus=minus)}{unit} ∠ {fixed(angle, minus=minus)}°"


def input_text(q: float, crank: bool, symbol: str = "", digits: int = 6, *, minus: str = MINUS) -> str:
    """An input position as a report prints it: ``θ12 = 62°`` for a crank, ``s = 200 mm`` for a slider.

    Parameters
    ----------
    q : float
        θ [rad] for a crank, s [m] for a slider; nan prints ``—``.
    crank : bool
        Whether the driver is a crank.
    symbol : str, optional
        The name to print (default ``θ`` or ``s``).
    digits : int
        Significant figures.
    minus : str
        The minus sign.

    Examples
    --------
    >>> import math
    >>> input_text(math.radians(62.0), True, "θ12"), input_text(-0.12, False, minus="-")
    ('θ12 = 62°', 's = -120 mm')
    """
    name = symbol or ("θ" if crank else "s")
    if not math.isfinite(q):
        return "—"
    shown, unit = (math.degrees(q), "°") if crank else (q * 1e3, " mm")
    return f"{name} = {num(shown, digits, minus=minus)}{unit}"


def position_text(q: float, crank: bool, symbol: str = "") -> str:
    """An input position for a message: ``θ = 89.99999999999°`` or ``s = 499.999999999999 mm``.

    With as many digits as it takes to name this very position (up to 17),
    never fewer than the 6 a report prints: near a dead point the position
    that fails may differ from the dead point itself only in the 13th digit,
    and "θ = 90°" would name the wrong one. 124° read from a file, which is
    124.00000000000001° after the trip through radians, still prints "124°".

    Parameters
    ----------
    q : float
        The position, θ [rad] for a crank, s [m] for a slider.
    crank : bool
        Whether the driver is a crank.
    symbol : str, optional
        The name to print (default ``θ`` or ``s``).

    Examples
    --------
    >>> import math
    >>> position_text(math.radians(124.0), True)
    'θ = 124°'
    >>> position_text(0.499999999999999, False)
    's = 499.999999999999 mm'
    """
    q = float(q)
    name = symbol or ("θ" if crank else "s")
    if not math.isfinite(q):
        return f"{name} = {q}"
    shown, unit = (math.degrees(q), "°") if crank else (q * 1e3, " mm")
    for digits in range(6, 18):
        text = f"{shown:.{digits}g}"
        # Converted back as the units boundary converts "124 deg" and "200 mm", the text gives q exactly.
        back = math.radians(float(text)) if crank else float(text) * 1e-3
        if back == q:
            break
    return f"{name} = {text}{unit}"


_UNIT_SIGNS = str.maketrans({"*": "·"})


def unit_text(unit: str) -> str:
    """A unit as a book prints it, from its pint spelling: a raised dot between units, powers raised.

    The one home of a unit as printed: sheets, keys, handouts and the platforms' pages all show units so.

    Examples
    --------
    >>> unit_text("N*m"), unit_text("m/s^2"), unit_text("kg*m^2"), unit_text("mm^3")
    ('N·m', 'm/s²', 'kg·m²', 'mm³')
    """
    return unit.translate(_UNIT_SIGNS).replace("^2", "²").replace("^3", "³")


def citation(source: str) -> str:
    """A source as one line for students: the book and the example, without the catalog's provenance.

    The catalog's ``source`` cites the book and then says how graphkin read it (``…; data and answers as in
    the FOSSEE companion``): that is for the teacher. A student's sheet cites the book: the text up to the
    first ``;`` or full stop.

    Examples
    --------
    >>> citation("Khurmi & Gupta, Theory of Machines, Example 15.10 (p. 536); data as in the FOSSEE companion")
    'Khurmi & Gupta, Theory of Machines, Example 15.10 (p. 536)'
    >>> citation("Söylemez, Mechanisms, §6.4, double-slider example. The numbers are the book's.")
    'Söylemez, Mechanisms, §6.4, double-slider example'
    """
    text = " ".join(str(source).split())
    for stop in ("; ", ". "):
        # A full stop ends the sentence only where a capital follows (not "p. 536", "Ex. 6.1").
        at = text.find(stop) if stop == "; " else next((m.start() for m in re.finditer(r"\.\s+(?=[A-Z])", text)
                                                        if not re.search(r"\b(?:p|pp|Ex|ch|No|vol|ed)$",
                                                                         text[:m.start()])), -1)
        if at > 0:
            text = text[:at]
    return text.strip().rstrip(".,;:")


_SIGN = re.compile(r"(?<![\w.)\]])-(?=\.?\d)")


def typeset_minus(text: str) -> str:
    """Text written for a terminal made fit to typeset: each hyphen-minus that is a number's sign becomes a
    true minus (``T12 = -57.84 N·m``, ``∠ -124.29°``, ``(-57.84)``); hyphens in words stay (``two-force``).

    Examples
    --------
    >>> typeset_minus("T3i = -379.4 N·m; F23 = 1972 N ∠ -124.29°; 166.8 + (-57.84); a two-force member")
    'T3i = −379.4 N·m; F23 = 1972 N ∠ −124.29°; 166.8 + (−57.84); a two-force member'
    """
    return _SIGN.sub(MINUS, text)


_POWER = re.compile(r"(?<![\w.])(\d+(?:\.\d+)?)[eE]([-+−]?)0*(\d+)(?![\w.])")
_SUPERSCRIPT = str.maketrans("0123456789−-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁻")


def typeset(text: str) -> str:
    """Text written for a terminal made fit to typeset: a number's sign a true minus (:func:`typeset_minus`),
    and a power of ten written out as a book prints it (``6.007e-5`` → ``6.007×10⁻⁵``, ``1e-6`` → ``10⁻⁶``).

    Examples
    --------
    >>> typeset("T2i = -5.871e-05 N·m; I = 6.007e-5 kg·m²; 1e-6 m³; E6_1.m; 2e3 N")
    'T2i = −5.871×10⁻⁵ N·m; I = 6.007×10⁻⁵ kg·m²; 10⁻⁶ m³; E6_1.m; 2×10³ N'
    """

    def power(m):
        sign = MINUS if m[2] in ("-", MINUS) else ""
        exponent = (sign + m[3]).translate(_SUPERSCRIPT)
        return f"10{exponent}" if m[1] in ("1", "1.0") else f"{m[1]}×10{exponent}"

    return typeset_minus(_POWER.sub(power, text))


_SYMBOL = re.compile(r"(?<![\w.])(?:([A-Za-zα-ω])\^([a-z])_([A-Za-z0-9]+)|([A-Za-zα-ω])_([A-Za-z0-9]+)"
                     r"|([FRT])(c?[0-9]{1,2}i?)|(G)([0-9]{2})|([mαωθ])([0-9]{1,2}))([′″‴]?)(?![A-Za-z0-9_′″‴])")


def symbols_in(text: str) -> list:
    """Plain text cut at its symbols, for a writer that sets a subscript as one (a handout, a web page).

    ``F_ij``, ``a_G3``, ``I_G``, ``ω_avg`` (an underscore marks the subscript) and the names the exercises
    write without one (``F23``, ``R3i``, ``Fc3``, ``T12``, the guide's ``G12``, ``m3``, ``α3``, ``θ12``) are
    symbols, with a sub-problem's mark (``F43′``) or a component's superscript (``a^n_BA``, the normal component:
    ``("a", "BA", "n")``); everything else stays text. A point's name (``G3``, ``A0``)
    stays upright, as drawings print points.

    Returns
    -------
    list
        Strings (text) and ``(letter, subscript, mark)`` triples (symbols; ``mark`` is ``""``, ``′`` or ``″``…),
        in order; no empty strings.

    Examples
    --------
    >>> symbols_in("F_ij is of link i on j; F3i = −m3 a_G3 at G3")
    [('F', 'ij', ''), ' is of link i on j; ', ('F', '3i', ''), ' = −', ('m', '3', ''), ' ', ('a', 'G3', ''), ' at G3']
    >>> symbols_in("F43′ and Fc3")
    [('F', '43', '′'), ' and ', ('F', 'c3', '')]
    >>> symbols_in("a^n_BA = ω3² AB")
    [('a', 'BA', 'n'), ' = ', ('ω', '3', ''), '² AB']
    """
    out: list = []
    last = 0
    for m in _SYMBOL.finditer(text):
        # A component's superscript (a^n_BA: normal, tangential, Coriolis) is set where a mark would be.
        symbol = (m[1], m[3], m[2]) if m[1] else next((m[k], m[k + 1], m[12]) for k in (4, 6, 8, 10) if m[k])
        out += [text[last:m.start()], symbol]
        last = m.end()
    out.append(text[last:])
    return [part for part in out if part != ""]
