"""Numbers as a person reads them: significant figures without an exponent where none is needed, and rounding
residues shown as the zero they are.

A solution at a dead centre or a symmetric position has values that are zero
in exact arithmetic and 1e-12 N or 1e-14 mm after floating-point rounding;
printed as they are ("3.284e-12 N", "d = 2.755e-14 mm") they read as if they
meant something. Text for people (the report, the construction's captions,
the drawings) prints such a value as 0; the data (JSON, arrays) keeps it.

Examples
--------
>>> num(50640.7)
'50640'
>>> num(-0.01234, minus="-")
'-0.01234'
>>> num(3.2e-12, zero=1e-9)
'0'
"""

from __future__ import annotations

import math

RESIDUE = 1e-12
"""A value this small beside its scale (the largest force at the position, for a force) is rounding: shown as 0."""

PICOMETRE = 1e-12
"""A length [m] below which a distance in a linkage is rounding: no drawing or machine tells it from 0."""


def largest(forces) -> float:
    """The largest size of ``forces`` ((x, y) pairs [N]), 0 for none: what a force among them is rounding beside."""
    return max((math.hypot(*F) for F in forces), default=0.0)


def unless_rounding(x: float, scale: float) -> float:
    """``x``, or 0 where it is rounding beside ``scale`` (:data:`RESIDUE` of it).

    A driving torque [N·m] is measured against the largest force times a
    metre, so ``scale`` is the largest force [N] for a force and a torque alike.
    """
    return 0.0 if abs(x) <= RESIDUE * abs(scale) else x + 0.0


def num(x: float, digits: int = 4, *, minus: str = "−", zero: float = 0.0) -> str:
    """``x`` with ``digits`` significant figures, without an exponent from 1e-4 to 1e7.

    Parameters
    ----------
    x : float
    digits : int
        Significant figures.
    minus : str
        The minus sign: a true minus (drawings, handouts) or ``"-"`` (plain text).
    zero : float
        Values not larger than this in size are rounding residues: ``"0"``.

    Returns
    -------
    str
        ``22850`` rather than ``2.285e+04``; ``2.5e-05`` below 1e-4.
    """
    if x == 0 or abs(x) <= zero:
        return "0"
    if not math.isfinite(x):
        return str(x)
    text = f"{x:.{digits}g}"
    if "e" in text and 1e-4 <= abs(x) < 1e7:
        # 22850 rather than 2.285e+04: the same digits, read at a glance.
        places = max(0, digits - 1 - math.floor(math.log10(abs(x))))
        text = f"{round(x, digits - 1 - math.floor(math.log10(abs(x)))):.{places}f}"
    return text.replace("-", minus)
