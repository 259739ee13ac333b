"""The symbols of an exercise's statement: ``{θ12}`` is the student's value, ``{{`` and ``}}`` a brace.

Examples
--------
>>> fill_symbols("At θ12 = {θ12}, [A]{{x}} = {{b}}", {"θ12": "132°"})
'At θ12 = 132°, [A]{x} = {b}'
>>> symbol_problem("a force of {Fp}", ["Fc", "θ12"])
'{Fp} is not a symbol of [vary] (did you mean {Fc}?); the symbols are {Fc}, {θ12}, and {{ and }} write a brace'
"""

from __future__ import annotations

import difflib
import re

# In a statement, {symbol} is the student's value, {{ and }} a brace; anything else in braces is a slip.
_BRACES = re.compile(r"\{\{|\}\}|\{([^{}]*)\}|[{}]")


def symbol_problem(text: str, symbols) -> str | None:
    """What is wrong with the braces of a statement (a sentence naming it), or None.

    Every ``{name}`` must be one of ``symbols``; a lone brace is written ``{{`` or ``}}``.
    """
    symbols = list(symbols)
    for m in _BRACES.finditer(text):
        if m[0] in ("{{", "}}") or m[1] in symbols:
            continue
        known = ", ".join(f"{{{s}}}" for s in symbols) or "none: the exercise varies nothing"
        if m[1] is None:
            return (f"has a lone {m[0]!r} (at character {m.start() + 1}); write {m[0] * 2} for a brace "
                    f"(the symbols are {known})")
        close = difflib.get_close_matches(m[1], symbols, n=1, cutoff=0.5)
        hint = f" (did you mean {{{close[0]}}}?)" if close else ""
        return f"{{{m[1]}}} is not a symbol of [vary]{hint}; the symbols are {known}, and {{{{ and }}}} write a brace"
    return None


def fill_symbols(text: str, values: dict) -> str:
    """A statement with each ``{symbol}`` replaced by its value and ``{{``, ``}}`` by a brace."""
    def one(m: re.Match) -> str:
        if m[0] in ("{{", "}}"):
            return m[0][0]
        return values.get(m[1], m[0]) if m[1] is not None else m[0]

    return _BRACES.sub(one, text)


__all__ = ["fill_symbols", "symbol_problem"]
