r"""A small representation of the handout's mathematics, and its three writers.

An equation is plain data: nested lists whose first item names the node.

=====================  =====================================================
``["i", "F"]``         an identifier (a symbol, italic): ``F``, ``θ``
``["n", "−25.98"]``    a number, already formatted (U+2212 for minus)
``["t", "N·m"]``       upright text: a unit, a word, a point's name
``["o", "="]``         an operator or punctuation: ``= + − · × ∠ ° , ;``
``["sub", b, s]``      b with subscript s
``["sup", b, s]``      b with superscript s
``["subsup", b, s, p]``  b with subscript s and superscript p over it (F′₂₃)
``["frac", a, b]``     a over b
``["vec", a]``         a with an arrow over it (a vector)
``["abs", a]``         the absolute value: a between bars
``["sqrt", a]``        the square root of a
``["paren", a]``       (a), the parentheses as tall as a
``["mat", rows, d]``   a matrix, rows of cells, delimiter ``"["``, ``"("``, ``"{"`` or ``""`` (none)
``["row", *items]``    items one after the other
``["sp"]``             a thin space
=====================  =====================================================

The handout builds these with the helpers below and never writes typst or
LaTeX itself; :func:`to_typst` (the PDF), :func:`to_latex` (Markdown, and
MathML for HTML through ``latex2mathml``) and :func:`to_text` (alternative
text) each turn one node into their own notation, so the three documents
show the same mathematics.

Examples
--------
>>> eq = row(sym("F", "23"), op("="), polar(27.06, -73.78, "N"))
>>> to_text(eq)
'F23 = 27.06 N ∠ −73.78°'
>>> to_typst(eq)
'attach(F, b: "23") = 27.06 thin "N" thin ∠ thin class("unary", −)73.78 degree'
"""

from __future__ import annotations

import math
import re

from graphkin import notation
from graphkin.notation import MINUS
from graphkin.notation import fixed as fmt_fixed


# -- numbers ------------------------------------------------------------------
def fmt(x: float, digits: int = 4) -> str:
    """A number with ``digits`` significant digits, as the handout prints it (:func:`graphkin.notation.num`).

    A true minus, ``"0"`` for zero (never ``"−0"``) and ``—`` for nan. Rounding
    noise (1e-17 where a lever arm is zero) is the caller's to clear: only the
    caller knows the scale.

    Examples
    --------
    >>> fmt(25.97834), fmt(-0.865942), fmt(7580.38), fmt(-0.0), fmt(123456.0), fmt(9.99996)
    ('25.98', '−0.8659', '7580', '0', '123500', '10')
    """
    return notation.num(x, digits, nonfinite="—", power=True)


def angle_of(v) -> float:
    """Direction of a plane vector [deg] in (−180°, 180°], as :func:`graphkin.notation.polar`."""
    return notation.polar(v)[1]


def size_of(v) -> float:
    return math.hypot(float(v[0]), float(v[1]))


# -- nodes ----------------------------------------------------------------------
def i(name: str) -> list:
    return ["i", name]


_POWER = re.compile(r"([−-]?[0-9.]+)×10\^([−-]?[0-9]+)")


def n(value: float | str, digits: int = 4) -> list:
    """A number node; a float is formatted with :func:`fmt`. A power of ten is set as one: 5.347 × 10⁻⁵."""
    return ["n", value if isinstance(value, str) else fmt(value, digits)]


def t(text: str) -> list:
    return ["t", text]


def op(symbol: str) -> list:
    return ["o", symbol]


def sub(base, subscript) -> list:
    return ["sub", _node(base), _node(subscript, text=True)]


def sup(base, superscript) -> list:
    return ["sup", _node(base), _node(superscript, text=True)]


def subsup(base, subscript, superscript) -> list:
    """``base`` with a subscript and a superscript over it: F′₂₃ (a sub-problem's force)."""
    return ["subsup", _node(base), _node(subscript, text=True), _node(superscript, text=True)]


def frac(a, b) -> list:
    return ["frac", _node(a), _node(b)]


def vec(a) -> list:
    return ["vec", _node(a)]


def absval(a) -> list:
    return ["abs", _node(a)]


def sqrt(a) -> list:
    return ["sqrt", _node(a)]


def paren(*items) -> list:
    return ["paren", row(*items)]


def mat(rows, delim: str = "[") -> list:
    return ["mat", [[_node(c) for c in r] for r in rows], delim]


def row(*items) -> list:
    return ["row", *(_node(x) for x in items)]


SP = ["sp"]


def _node(x, text=False):
    if isinstance(x, list):
        return x
    if isinstance(x, (int, float)):
        return n(x)
    return t(x) if text else i(x)


def sym(letter: str, subscript: str | None = None) -> list:
    """A symbol with an upright subscript: ``sym("F", "23")`` is F₂₃, ``sym("a", "G3")`` is a_G3."""
    return i(letter) if not subscript else sub(i(letter), t(subscript))


_NAME = re.compile(r"^([A-Za-z])_?([0-9][0-9A-Za-z,]*|[A-Z][0-9A-Za-z]*|c[0-9]+)([′″‴⁗]|⁽[⁰¹²³⁴⁵⁶⁷⁸⁹]+⁾)?$")
_PLAIN_DIGITS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁽⁾", "0123456789()")
_SUPERSCRIPT_DIGITS = str.maketrans("0123456789()", "⁰¹²³⁴⁵⁶⁷⁸⁹⁽⁾")


def name(text: str) -> list:
    """A force, torque or point name as a symbol: ``"F23"`` → F₂₃, ``"R3i"`` → R₃ᵢ, ``"T12"`` → T₁₂.

    Names that do not look like a letter and a subscript are kept upright.
    """
    if text[:1] in "−-" and len(text) > 1:
        return row(op("−"), name(text[1:]))  # a reversed force in a polygon: −F23
    base, paren, rest = text.partition(" (")
    if paren and base:
        return row(name(base), SP, t("(" + rest))  # a load named for print: Fc3 (cutting)
    m = _NAME.match(text)
    if not m:
        return t(text)
    # A superposition's part carries its mark as a superscript over the subscript, snug to the letter: F′₂₃,
    # F⁗₂₃, F⁽⁵⁾₂₃ (the fifth and later marks spelled as superscript numbers).
    if m[3]:
        return subsup(i(m[1]), t(m[2]), t(m[3].translate(_PLAIN_DIGITS)))
    return sym(m[1], m[2])


def prose(text: str) -> tuple:
    """Words written for a terminal as the handout sets them: each symbol with its subscript
    (:func:`graphkin.notation.symbols_in`).

    Returns
    -------
    tuple
        Runs for :meth:`graphkin.handout.document.Doc.text` or a table cell: text and math nodes.

    Examples
    --------
    >>> [to_text(r) if isinstance(r, list) else r for r in prose("F_ij is of link i on j; F3i = −m3 a_G3 at G3")]
    ['Fij', ' is of link i on j; ', 'F3i', ' = −', 'm3', ' ', 'aG3', ' at G3']
    """
    out = [part if isinstance(part, str) else subsup(i(part[0]), t(part[1]), t(part[2])) if part[2] else
           sym(part[0], part[1]) for part in notation.symbols_in(text)]
    return tuple(r for r in out if r != "") or ("",)


def qty(value: float | str, unit: str, digits: int = 4) -> list:
    """A number and its unit: 25.98 N."""
    return row(n(value, digits), SP, t(unit)) if unit else n(value, digits)


def polar(size: float, angle: float, unit: str, digits: int = 4) -> list:
    """The books' polar form: 27.06 N ∠ −73.78°."""
    return row(qty(size, unit, digits), op("∠"), n(fmt_fixed(angle)), op("°"))


def pair(v, unit: str = "", digits: int = 4) -> list:
    """A vector by components: (7.559, −25.98) N.

    A component below 10⁻⁹ of the other is rounding noise (−2e-16 where
    the exact value is 0) and is printed as 0.
    """
    x, y = (float(c) for c in v)
    tiny = 1e-9 * max(abs(x), abs(y))
    x, y = (0.0 if abs(x) <= tiny else x), (0.0 if abs(y) <= tiny else y)
    inside = paren(n(x, digits), op(","), n(y, digits))
    return row(inside, SP, t(unit)) if unit else inside


def column(items) -> list:
    return mat([[x] for x in items], "{")


# -- writers ------------------------------------------------------------------------
# An escaped comma is a comma even inside a function's arguments (frac, attach), where a bare one would
# separate them.
_TYPST_OPS = {"·": "dot", "×": "times", "°": "degree", ",": "\\,", ";": "\\;", "(": "\\(", ")": "\\)",
              "/": "\\/", "∠": "thin ∠ thin", "Σ": "Σ"}


_TYPST_PRIMES = {"′": "prime", "″": "prime.double", "‴": "prime.triple", "⁗": "prime.quad"}


def _typst_text(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def to_typst(node) -> str:
    """The node as typst math (the content between ``$ ... $``)."""
    kind = node[0]
    if kind == "i":
        s = node[1]
        return s if len(s) == 1 else f"italic({_typst_text(s)})"
    if kind == "n":
        text = node[1]
        power = _POWER.fullmatch(text)
        if power:
            return f"{to_typst(['n', power[1]])} times 10^({to_typst(['n', power[2]])})"
        if not re.fullmatch(r"[−-]?[0-9.]+", text):
            return _typst_text(text)
        # A leading minus is the number's sign, not a subtraction: unary, so "∠ −73.78" is not spaced as "∠ − 73.78".
        return f'class("unary", −){text[1:]}' if text[0] in "−-" else text
    if kind == "t":
        return _typst_text(node[1])
    if kind == "o":
        return _TYPST_OPS.get(node[1], node[1] if node[1] in "=+−<>≈∠→⇒±" else _typst_text(node[1]))
    if kind == "sub":
        return f"attach({to_typst(node[1])}, b: {to_typst(node[2])})"
    if kind == "sup":
        return f"attach({to_typst(node[1])}, t: {to_typst(node[2])})"
    if kind == "subsup":
        # Typst's own primes sit snug to the letter; the character ′ set as a superscript would float above it.
        mark = _TYPST_PRIMES.get(node[3][1], to_typst(node[3])) if node[3][0] == "t" else to_typst(node[3])
        return f"attach({to_typst(node[1])}, b: {to_typst(node[2])}, t: {mark})"
    if kind == "frac":
        return f"frac({to_typst(node[1])}, {to_typst(node[2])})"
    if kind == "vec":
        return f"arrow({to_typst(node[1])})"
    if kind == "abs":
        return f"abs({to_typst(node[1])})"
    if kind == "sqrt":
        return f"sqrt({to_typst(node[1])})"
    if kind == "paren":
        return f"lr(( {to_typst(node[1])} ))"
    if kind == "mat":
        delim = {"[": '"["', "(": '"("', "{": '"{"', "": "#none"}[node[2]]
        body = "; ".join(", ".join(to_typst(c) for c in r) for r in node[1])
        return f"mat(delim: {delim}, {body})"
    if kind == "row":
        return " ".join(to_typst(x) for x in node[1:]) or '""'
    if kind == "sp":
        return "thin"
    raise ValueError(f"unknown math node {kind!r}")


_ADVANCES = {
    0.2: "⁽⁾", 0.3: "l.,:;!|'[]·", 0.35: "i ′⁰⁴⁵⁶⁷⁸⁹₀₁₂₃₄₅₆₇₈₉-_", 0.4: 't()²³°¹"ι', 0.45: "cjI",
    0.5: "012345689efgorsz{}/–*\\?δθο", 0.55: "7akqvy″εζηνξρτυ", 0.6: "bdhnpuxJ~^βγκλπσ", 0.65: "SαμχωΓ",
    0.7: "FLPZφψΛ", 0.75: "wACETUVY‴ΞΦ", 0.8: "BGOQR−+=<>≈±∠×&@ΘΣΨΩ", 0.85: "DHKNX%#ΔΠ", 0.9: "m", 0.95: "⁗",
    1.0: "M→⇒—", 1.05: "W",
}
"""Each character's advance in the handout's maths [em], the larger of italic and upright, rounded up to 0.05 em:
measured in typst's New Computer Modern Math (``tests/handout/test_typesetting.py`` measures them again)."""
_ADVANCE = {ch: w for w, chars in _ADVANCES.items() for ch in chars}
_GLYPH = 1.1
"""Width allowed any other Latin or Greek letter, sign or punctuation [em]: the widest measured is 1.05 em."""
_SCRIPT = 0.75
"""A script's share of its width at full size (typst sets it at 70 %)."""
_OTHER = 2.0
"""Width allowed a character outside Latin, Greek, punctuation, super- and subscripts, arrows and operators [em]."""
_NARROW = re.compile(r"[\x20-\x7e\u00a0-\u024f\u0370-\u03ff\u2010-\u2044\u2070-\u209f\u2190-\u22ff]")


def _chars(s: str) -> float:
    return sum(_ADVANCE.get(ch) or (_GLYPH if _NARROW.match(ch) else _OTHER) for ch in s)


def width_bound(node) -> float:
    """More than the node can be wide, typeset in a block equation [em of its font size].

    Each character at the widest a glyph is, each operator with the widest spaces math puts around one, each
    script at full size, every delimiter and gap generous. A line whose bound fits the page needs no measuring.

    Examples
    --------
    >>> width_bound(row(sym("F", "23"), op("="), polar(27.06, -73.78, "N"))) < 40
    True
    """
    kind = node[0]
    if kind in ("i", "n", "t"):
        return _chars(node[1]) + (_GLYPH + 1.0 if kind == "n" and _POWER.fullmatch(node[1]) else 0.0)
    if kind == "o":
        # A sign's glyph and a relation's spaces either side (5/18 em each); ∠ has thin spaces (1/6 em each) too.
        return _chars(node[1]) + (1.0 if "∠" in node[1] else 0.6)
    if kind in ("sub", "sup"):
        # A script is set at 70 %.
        return width_bound(node[1]) + _SCRIPT * width_bound(node[2]) + 0.3
    if kind == "subsup":
        return width_bound(node[1]) + _SCRIPT * max(width_bound(node[2]), width_bound(node[3])) + 0.3
    if kind == "frac":
        return max(width_bound(node[1]), width_bound(node[2])) + 0.5
    if kind == "vec":
        return max(width_bound(node[1]), _GLYPH) + 0.5
    if kind in ("abs", "sqrt"):
        return width_bound(node[1]) + 1.5
    if kind == "paren":
        return width_bound(node[1]) + 2.0
    if kind == "mat":
        rows = node[1]
        cols = max((len(r) for r in rows), default=0)
        widths = [max((width_bound(r[k]) for r in rows if k < len(r)), default=0.0) for k in range(cols)]
        return sum(widths) + 1.0 * cols + 6.0
    if kind == "row":
        return sum(width_bound(x) for x in node[1:])
    if kind == "sp":
        return 0.25
    raise ValueError(f"unknown math node {kind!r}")


_GREEK = {"α": r"\alpha", "β": r"\beta", "γ": r"\gamma", "θ": r"\theta", "ω": r"\omega", "μ": r"\mu", "ρ": r"\rho",
          "σ": r"\sigma", "Σ": r"\Sigma", "Δ": r"\Delta", "τ": r"\tau", "φ": r"\varphi"}
_LATEX_OPS = {"·": r"\cdot", "×": r"\times", "∠": r"\;\angle\;", "°": r"^{\circ}", "−": "-", ",": r",\ ", ";": ";",
              "≈": r"\approx", "→": r"\rightarrow", "⇒": r"\Rightarrow", "±": r"\pm"}


def _latex_text(s: str) -> str:
    s = re.sub(r"([{}_%#&$^~\\])", lambda m: "\\" + m[1] if m[1] not in "\\^~" else
               {"\\": r"\backslash ", "^": r"\^{}", "~": r"\~{}"}[m[1]], s)
    return r"\text{" + s + "}"


def _latex_mark(node) -> str:
    """A sub-problem's mark as LaTeX: primes as \\prime (′ is no character LaTeX maths has), others as text."""
    text = node[1] if node[0] == "t" else ""
    primes = {"′": 1, "″": 2, "‴": 3, "⁗": 4}
    if text in primes:
        return r"\prime" * primes[text]
    return to_latex(node)


def to_latex(node) -> str:
    """The node as LaTeX math (for Markdown's ``$…$``, and MathML through ``latex2mathml``)."""
    kind = node[0]
    if kind == "i":
        return "".join(_GREEK.get(ch, ch) for ch in node[1]) if len(node[1]) == 1 else r"\mathit{" + node[1] + "}"
    if kind == "n":
        power = _POWER.fullmatch(node[1])
        if power:
            return rf"{to_latex(['n', power[1]])} \times 10^{{{to_latex(['n', power[2]])}}}"
        text = node[1].replace(MINUS, "-")
        if not re.fullmatch(r"-?[0-9.]+", text):
            return _latex_text(node[1])
        return "{" + text + "}" if text.startswith("-") else text  # braced: a sign, not a subtraction
    if kind == "t":
        return _latex_text(node[1])
    if kind == "o":
        return _LATEX_OPS.get(node[1], _GREEK.get(node[1], node[1]))
    if kind == "sub":
        return f"{{{to_latex(node[1])}}}_{{{to_latex(node[2])}}}"
    if kind == "sup":
        return f"{{{to_latex(node[1])}}}^{{{to_latex(node[2])}}}"
    if kind == "subsup":
        return f"{{{to_latex(node[1])}}}_{{{to_latex(node[2])}}}^{{{_latex_mark(node[3])}}}"
    if kind == "frac":
        return rf"\frac{{{to_latex(node[1])}}}{{{to_latex(node[2])}}}"
    if kind == "vec":
        return rf"\vec{{{to_latex(node[1])}}}"
    if kind == "abs":
        return rf"\left|{to_latex(node[1])}\right|"
    if kind == "sqrt":
        return rf"\sqrt{{{to_latex(node[1])}}}"
    if kind == "paren":
        return rf"\left({to_latex(node[1])}\right)"
    if kind == "mat":
        # \left … \right rather than bmatrix: latex2mathml then marks the brackets as stretchy fences,
        # which browsers' MathML draws as tall as the matrix.
        left, right = {"[": (r"\left[", r"\right]"), "(": (r"\left(", r"\right)"), "{": (r"\left\{", r"\right\}"),
                       "": ("", "")}[node[2]]
        body = r" \\ ".join(" & ".join(to_latex(c) for c in r) for r in node[1])
        return rf"{left}\begin{{matrix}} {body} \end{{matrix}}{right}"
    if kind == "row":
        return " ".join(to_latex(x) for x in node[1:])
    if kind == "sp":
        return r"\,"
    raise ValueError(f"unknown math node {kind!r}")


def to_text(node) -> str:
    """The node as plain text (alternative text, search, tests)."""
    kind = node[0]
    if kind in ("i", "n", "t"):
        return node[1]
    if kind == "o":
        return {",": ", ", "°": "°"}.get(node[1], f" {node[1]} ")
    if kind in ("sub", "sup"):
        return to_text(node[1]) + ("" if kind == "sub" else "^") + to_text(node[2])
    if kind == "subsup":
        return to_text(node[1]) + to_text(node[2]) + to_text(node[3]).translate(_SUPERSCRIPT_DIGITS)
    if kind == "frac":
        return f"({to_text(node[1])})/({to_text(node[2])})"
    if kind == "vec":
        return to_text(node[1])
    if kind == "abs":
        return f"|{to_text(node[1])}|"
    if kind == "sqrt":
        return f"√({to_text(node[1])})"
    if kind == "paren":
        return f"({to_text(node[1])})"
    if kind == "mat":
        return "[" + "; ".join(", ".join(to_text(c) for c in r) for r in node[1]) + "]"
    if kind == "row":
        return re.sub(r" {2,}", " ", "".join(to_text(x) for x in node[1:])).strip()
    if kind == "sp":
        return " "
    raise ValueError(f"unknown math node {kind!r}")
