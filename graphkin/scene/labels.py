"""Names as structured text: a symbol, its subscript, a sub-problem's mark and a unit, for a drawing to typeset."""

from __future__ import annotations

MARKS = "′″‴⁗⁽⁾⁰¹²³⁴⁵⁶⁷⁸⁹"
"""What the marks a sub-problem's forces carry are written with (F23′ in sub-problem I, F23″ in II, F23⁽⁵⁾ in V)."""


def label(name: str, unit: str = "") -> dict:
    """A quantity's name as structured text: ``"F23′"`` → symbol F, subscript 23, mark ′ (and its unit).

    Examples
    --------
    >>> label("G14", "N")
    {'symbol': 'G', 'sub': '14', 'mark': '', 'unit': 'N'}
    >>> label("−F23″")
    {'symbol': '−F', 'sub': '23', 'mark': '″', 'unit': ''}
    >>> label("F45⁽⁵⁾")["mark"]
    '⁽⁵⁾'

    """
    sign = "−" if name.startswith("−") else ""
    core = name.lstrip("−")
    bare = core.rstrip(MARKS)
    return {"symbol": sign + bare[:1], "sub": bare[1:], "mark": core[len(bare):], "unit": unit}
