"""Text as the figures write it: subscripted names, numbers with a true minus, polar form, the input, a halo."""

from __future__ import annotations

import math
import re

from .axes import MM

_NAME = re.compile(r"^([−-]?)([A-Za-z])([a-z]?\d+(?:,\d+)?[a-z]?)([′″‴⁗]|⁽[⁰¹²³⁴⁵⁶⁷⁸⁹]+⁾)?$")
SUBSCRIPTS = dict(zip("0123456789aehijklmnoprstuvx,", "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ,"))
"""Characters that Unicode has a subscript for, and that subscript."""
_UNSUB = {v: k for k, v in SUBSCRIPTS.items() if k != ","}


def subscript(text: str) -> str:
    """Every character of ``text`` as a subscript where Unicode has one: ``12`` → ``₁₂``."""
    return "".join(SUBSCRIPTS.get(ch, ch) for ch in text)


def sub(name: str) -> str:
    """A force or point name with its subscript typeset: ``F23`` → ``F₂₃``, ``R3i`` → ``R₃ᵢ``, ``A0`` → ``A₀``.

    Unicode subscripts rather than mathtext: as legible, and text is laid
    out some twenty times faster. A subscript with a letter Unicode has no
    subscript for (``Fc3``: there is no subscript c) is set in upright
    mathtext instead, ``$\\mathregular{F_{c3}}$``. A leading minus (``−F23``,
    or ``-F23``) stays in front, as a true minus: ``−F₂₃``; a sub-problem's
    mark stays behind: ``F23″`` → ``F₂₃″``. Names that are
    not a letter and a numeric subscript (``FP``, ``O``) are returned as
    they are; anything after the first space is kept as plain text
    (``Fc3 (cutting)`` → F_c3 and `` (cutting)``).
    """
    head, sep, rest = name.partition(" ")
    m = _NAME.match(head)
    if not m:
        return name
    sign, letter, index, mark = m.groups()
    sign = "−" if sign else ""
    mark = mark or ""
    if all(ch in SUBSCRIPTS for ch in index):
        return sign + letter + subscript(index) + mark + sep + rest
    # Only the name goes into mathtext, so a note after it keeps the text font and plain characters.
    return sign + rf"$\mathregular{{{letter}_{{{index}}}}}$" + mark + sep + rest


def plain(text: str) -> str:
    """Text with subscripts and mathtext markup undone: ``F₂₃ = 27 N`` → ``F23 = 27 N``.

    ``$\\mathregular{F_{c3}}$ (cutting)`` → ``Fc3 (cutting)`` too (see :func:`sub`).
    """
    text = "".join(_UNSUB.get(ch, ch) for ch in text)
    return re.sub(r"\\mathregular|[${}]|_(?=\{)", "", text)


def num(x: float, digits: int = 4) -> str:
    """A number with ``digits`` significant figures and a true minus sign."""
    if x == 0 or not math.isfinite(x):
        return "0" if x == 0 else str(x)
    text = f"{x:.{digits}g}"
    if "e" in text and 1e-4 <= abs(x) < 1e7:
        # 22850 rather than 2.285e+04: the same digits, read at a glance.
        places = max(0, digits - 1 - math.floor(math.log10(abs(x))))
        text = f"{round(x, digits - 1 - math.floor(math.log10(abs(x)))):.{places}f}"
    return text.replace("-", "−")


def polar_text(v, unit: str = "N", digits: int = 4) -> str:
    """``27.06 N ∠ −73.78°`` (the README's polar form)."""
    from ..report import polar

    size, angle = polar(v)
    if size == 0:
        return f"0 {unit}"
    return f"{num(size, digits)} {unit} ∠ {angle:.2f}°".replace("-", "−")


def input_text(construction) -> str:
    """``θ₁₂ = 30°`` for a crank, ``s = 200 mm`` for a slider driver."""
    d = construction.mechanism.driver
    if d.kind == "crank":
        return f"θ{subscript(f'{d.frame}{d.link}')} = {num(math.degrees(construction.q), 6)}°"
    return f"s = {num(construction.q * MM, 6)} mm"


def halo(width: float = 2.6):
    """A white outline behind text, so a label stays legible where a line runs under it."""
    from matplotlib.patheffects import withStroke

    return withStroke(linewidth=width, foreground="white")
