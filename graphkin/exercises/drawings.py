"""A drawn answer read as data: the lines, points and vectors a student drew, in the space of the question.

A drawing (format ``docs/json.md``, "Drawn answers") is JSON: ``{"drawing": 1, "question": ..., "space": ...,
"unit": ..., "elements": [...]}``, each element a ``"line"`` (two distinct points it passes through), a
``"point"`` or a ``"vector"`` (from, to), coordinates in the question's space and SI units. It comes as text (a
notebook's answer variable, a Gradescope JSON hand-in's value) or as the dict already parsed. It is read with
``json.loads`` only, never evaluated: only objects, lists, strings and finite numbers; at most
:data:`MAX_ELEMENTS` elements and :data:`MAX_CHARS` characters; each coordinate within :data:`REACH` times the
size of the question's view of its middle (:func:`reach`). Anything else is :class:`Unreadable`, with one
sentence naming the field at fault.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass

__all__ = ["KINDS", "MAX_CHARS", "MAX_COORDINATE", "MAX_ELEMENTS", "REACH", "SPACES", "VERSION", "Drawing", "Element",
           "Unreadable", "printable", "reach", "read_drawing"]

VERSION = 1
"""The ``drawing`` field this version writes and reads."""

MAX_ELEMENTS = 64
"""The most elements a drawing may hold."""

MAX_CHARS = 20_000
"""The longest a drawing's text may be."""

REACH = 1000
"""How far a drawn coordinate may lie from the middle of the question's view, in sizes of the view (its larger
side). A slip's drawing lies within a few sizes (a length laid off ×10 is the farthest); a coordinate beyond a
thousand is on no page, and one near ±1e308 would overflow the grader's arithmetic (a difference or a square is
infinite) and come out a plain "wrong"."""

MAX_COORDINATE = 1e15
"""The bound of a coordinate when no view is given [the space's unit]: its square still a finite float."""

SPACES = {"mechanism": "m", "force": "N", "velocity": "m/s", "acceleration": "m/s^2"}
"""Each space a question is drawn in, and its unit (SI)."""

KINDS = ("line", "point", "vector")
"""The kinds of element a student draws."""

_FIELDS = {"drawing", "question", "space", "unit", "elements"}
_ELEMENT = {"line": ("through",), "point": ("at",), "vector": ("from", "to")}


class Unreadable(ValueError):
    """A drawing that cannot be read; its message is one sentence naming the field."""


@dataclass(frozen=True)
class Element:
    """One drawn element.

    Attributes
    ----------
    kind : str
        ``"line"``, ``"point"`` or ``"vector"``.
    name : str
        The name it is labelled by (``""`` when none).
    points : tuple of (float, float)
        A line's two points, a point's one, a vector's from and to [the space's unit].
    """

    kind: str
    name: str
    points: tuple

    def data(self) -> dict:
        """The element as the drawing's JSON writes it."""
        p = [list(x) for x in self.points]
        if self.kind == "line":
            return {"kind": "line", "name": self.name, "through": p}
        if self.kind == "point":
            return {"kind": "point", "name": self.name, "at": p[0]}
        return {"kind": "vector", "name": self.name, "from": p[0], "to": p[1]}


@dataclass(frozen=True)
class Drawing:
    """A drawn answer read.

    Attributes
    ----------
    question : str
    space : str
        A key of :data:`SPACES`.
    unit : str
    elements : tuple of Element
    """

    question: str
    space: str
    unit: str
    elements: tuple

    def data(self) -> dict:
        """The drawing as JSON data (the format it was read from)."""
        return {"drawing": VERSION, "question": self.question, "space": self.space, "unit": self.unit,
                "elements": [e.data() for e in self.elements]}


def _refuse_constant(name: str):
    raise Unreadable(f"the drawing holds {name}, which is not a finite number")


def _number(x, field: str) -> float:
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        raise Unreadable(f"{field} must be a number, got {_short(x)}")
    x = float(x)
    if not math.isfinite(x):
        raise Unreadable(f"{field} must be a finite number, got {x!r}")
    return x


def reach(view, unit: str) -> tuple:
    """The range each drawn coordinate must lie in: ``((xlo, xhi), (ylo, yhi), words)`` [the space's unit].

    Parameters
    ----------
    view : sequence of 4 floats or None
        The task's view ``[xmin, ymin, xmax, ymax]``; None: ±:data:`MAX_COORDINATE` for both.
    unit : str
        The space's unit, for the words.
    """
    if view is None:
        m = MAX_COORDINATE
        return (-m, m), (-m, m), f"within ±{m:g} {unit}"
    x0, y0, x1, y1 = (float(v) for v in view)
    size = max(x1 - x0, y1 - y0, 1e-12)
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    xs, ys = (cx - REACH * size, cx + REACH * size), (cy - REACH * size, cy + REACH * size)
    words = (f"within {REACH} times the view's size ({size:.4g} {unit}) of its middle: x from {xs[0]:.4g} to "
             f"{xs[1]:.4g}, y from {ys[0]:.4g} to {ys[1]:.4g} {unit}")
    return xs, ys, words


def _pair(p, field: str, box, what: str) -> tuple[float, float]:
    """A point [x, y] of the element ``what`` (its kind and name, for the message), each coordinate in ``box``
    (``(x range, y range, their words, unit)``, :func:`reach`)."""
    if not isinstance(p, list) or len(p) != 2:
        raise Unreadable(f"{field} must be a point [x, y], got {_short(p)}")
    xy = _number(p[0], f"{field}[0]"), _number(p[1], f"{field}[1]")
    for i, (v, (lo, hi)) in enumerate(zip(xy, box[:2])):
        if not lo <= v <= hi:
            raise Unreadable(f"{field}[{i}] of the {what} is {v:.4g} {box[3]}, out of the drawing's range: a "
                             f"coordinate must lie {box[2]}")
    return xy


def printable(text: str) -> str:
    """Text of the student's as a message quotes it: each character that does not print (a line break, a
    direction override) as U+FFFD, so that it can write no line and turn no sentence of the feedback around."""
    return "".join(c if c.isprintable() else "\N{REPLACEMENT CHARACTER}" for c in text)


def _short(x) -> str:
    try:
        text = json.dumps(x, ensure_ascii=False)
    except (TypeError, ValueError):
        text = type(x).__name__
    return printable(text if len(text) <= 40 else text[:39] + "…")


def _element(e, i: int, box) -> Element:
    where = f"elements[{i}]"
    if not isinstance(e, dict):
        raise Unreadable(f"{where} must be an object {{\"kind\": ..., ...}}, got {_short(e)}")
    kind = e.get("kind")
    if kind not in _ELEMENT:
        raise Unreadable(f"{where}.kind must be one of {', '.join(KINDS)}, got {_short(kind)}")
    extra = set(e) - {"kind", "name", *_ELEMENT[kind]}
    if extra:
        raise Unreadable(f"{where} has a field a {kind} does not: {sorted(extra)[0]!r}")
    name = e.get("name", "")
    if not isinstance(name, str) or len(name) > 40:
        raise Unreadable(f"{where}.name must be a short text, got {_short(name)}")
    what = f"{kind} {printable(name)!r}" if name else kind
    for key in _ELEMENT[kind]:
        if key not in e:
            raise Unreadable(f"{where}.{key} is missing")
    if kind == "line":
        through = e["through"]
        if not isinstance(through, list) or len(through) != 2:
            raise Unreadable(f"{where}.through must be two points [[x1, y1], [x2, y2]], got {_short(through)}")
        p = (_pair(through[0], f"{where}.through[0]", box, what), _pair(through[1], f"{where}.through[1]", box, what))
        if p[0] == p[1]:
            raise Unreadable(f"{where}.through: a line needs two distinct points, got the same point twice")
        return Element(kind, name, p)
    if kind == "point":
        return Element(kind, name, (_pair(e["at"], f"{where}.at", box, what),))
    return Element(kind, name, (_pair(e["from"], f"{where}.from", box, what), _pair(e["to"], f"{where}.to", box, what)))


def read_drawing(source, *, question: str | None = None, space: str | None = None, view=None) -> Drawing:
    """Read a drawing (JSON text or the dict already parsed), checked against the question it answers.

    Parameters
    ----------
    source : str or dict
    question : str, optional
        The question's id: a drawing of another question is refused.
    space : str, optional
        The space the question is drawn in: a drawing in another space is refused.
    view : sequence of 4 floats, optional
        The task's view ``[xmin, ymin, xmax, ymax]`` [the space's unit]: a coordinate farther than :data:`REACH`
        view sizes from its middle is refused (:func:`reach`); without it, one beyond ±:data:`MAX_COORDINATE`.

    Raises
    ------
    Unreadable
        One sentence naming the field at fault.
    """
    if isinstance(source, str):
        if len(source) > MAX_CHARS:
            raise Unreadable(f"the drawing is {len(source)} characters long; at most {MAX_CHARS} are read")
        try:
            data = json.loads(source, parse_constant=_refuse_constant)
        except Unreadable:
            raise
        except (ValueError, RecursionError):
            raise Unreadable("the drawing is not JSON text (it should be the text the drawing page gives)") from None
    elif isinstance(source, dict):
        data = source
    else:
        raise Unreadable(f"a drawing must be JSON text or an object, got {type(source).__name__}")
    if not isinstance(data, dict):
        raise Unreadable("the drawing must be a JSON object {\"drawing\": 1, ...}")
    extra = set(data) - _FIELDS
    if extra:
        raise Unreadable(f"the drawing has a field it should not: {sorted(map(str, extra))[0]!r}")
    if data.get("drawing") != VERSION or isinstance(data.get("drawing"), bool):
        raise Unreadable(f"drawing must be {VERSION} (the format's version), got {_short(data.get('drawing'))}")
    q = data.get("question")
    if not isinstance(q, str):
        raise Unreadable(f"question must be the question's id, got {_short(q)}")
    if question is not None and q != question:
        raise Unreadable(f"question is {_short(q)}: this drawing answers another question than {question!r}")
    sp = data.get("space")
    if sp not in SPACES:
        raise Unreadable(f"space must be one of {', '.join(SPACES)}, got {_short(sp)}")
    if space is not None and sp != space:
        raise Unreadable(f"space is {sp!r}, but this question is drawn in the {space} space")
    unit = data.get("unit", SPACES[sp])
    if unit != SPACES[sp]:
        raise Unreadable(f"unit must be {SPACES[sp]!r} in the {sp} space, got {_short(unit)}")
    elements = data.get("elements")
    if not isinstance(elements, list):
        raise Unreadable(f"elements must be a list, got {_short(elements)}")
    if len(elements) > MAX_ELEMENTS:
        raise Unreadable(f"elements holds {len(elements)} elements; at most {MAX_ELEMENTS} are read")
    xs, ys, words = reach(view, unit)
    box = (xs, ys, words, unit)
    return Drawing(q, sp, unit, tuple(_element(e, i, box) for i, e in enumerate(elements)))
