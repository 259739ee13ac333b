"""Grading a drawn answer: the student's drawing matched against the right drawing and each slip's.

The rule (``docs/json.md``, "Drawn answers"; the practice page runs the same in the browser): an element matches
a target element of the same kind and index when

- point: |p − q| ≤ L;
- line: the angle between the lines, modulo π, ≤ the angle tolerance, and the distance from the target's first
  ``through`` point (its anchor) to the drawn line ≤ L;
- vector: |from − from_t| ≤ L and |to − to_t| ≤ L.

A drawing matches a target when it has as many elements and each matches. The verdict is the first target matched
(the right drawing first: ``"correct"``; a slip's: ``"slip"`` with its name and the share of the points the
exercise's ``partial`` gives it); none: ``"wrong"``, with ``fault``, the indices of the drawing's elements that do
not match the right drawing. Plain Python floats only: a few microseconds per drawing.
"""

from __future__ import annotations

import math

from graphkin.exercises.drawings import Drawing, Unreadable, printable, read_drawing
from graphkin.exercises.notebooks import NotData

__all__ = ["element_matches", "faults", "grade_drawing", "grade_drawn", "match"]


def _xy(e):
    """An element's points as a tuple of (x, y) (a drawn :class:`~graphkin.exercises.drawings.Element` or data)."""
    if isinstance(e, dict):
        kind = e["kind"]
        if kind == "line":
            return kind, tuple(tuple(p) for p in e["through"])
        if kind == "point":
            return kind, (tuple(e["at"]),)
        return kind, (tuple(e["from"]), tuple(e["to"]))
    return e.kind, e.points


def element_matches(drawn, target, tolerance: dict) -> bool:
    """Whether one drawn element matches one target element (see the module for the rule)."""
    kind, p = _xy(drawn)
    tkind, t = _xy(target)
    if kind != tkind:
        return False
    L = tolerance["length"]
    if kind == "point":
        return math.dist(p[0], t[0]) <= L
    if kind == "vector":
        return math.dist(p[0], t[0]) <= L and math.dist(p[1], t[1]) <= L
    dx, dy = p[1][0] - p[0][0], p[1][1] - p[0][1]
    tx, ty = t[1][0] - t[0][0], t[1][1] - t[0][1]
    n, m = math.hypot(dx, dy), math.hypot(tx, ty)
    if not (n > 0 and m > 0):
        return False
    # The angle between the two lines, modulo π.
    off = abs(math.atan2(dx * ty - dy * tx, dx * tx + dy * ty))
    if min(off, math.pi - off) > tolerance["angle"]:
        return False
    # The distance from the target's anchor to the drawn line.
    ax, ay = t[0][0] - p[0][0], t[0][1] - p[0][1]
    return abs(ax * dy - ay * dx) / n <= L


def faults(elements, target_elements, tolerance: dict) -> list[int]:
    """The indices of the drawn elements that do not match the target's element of the same index (every element
    beyond the target's count is at fault)."""
    return [i for i, e in enumerate(elements)
            if i >= len(target_elements) or not element_matches(e, target_elements[i], tolerance)]


def match(elements, targets, tolerance: dict) -> int | None:
    """The index of the first target the drawing's ``elements`` match, or None.

    ``targets`` is a list of targets (``{"slip", "elements"}``) or the elements of one target."""
    if targets and isinstance(targets[0], dict) and "elements" in targets[0]:
        for i, t in enumerate(targets):
            if match(elements, t["elements"], tolerance) is not None:
                return i
        return None
    if len(elements) != len(targets):
        return None
    return 0 if all(element_matches(e, t, tolerance) for e, t in zip(elements, targets)) else None


def _mm(L: float, scale: dict) -> str:
    return f"{L / scale['si_per_mm']:.2g} mm"


def grade_drawn(variant, q, answer, *, reveal: bool = False) -> dict:
    """Grade one drawn answer (JSON text or the dict) to question ``q``; never raises on the answer.

    Returns
    -------
    dict
        The grader's verdict (``{"id", "verdict", "slip", "score", "max", "feedback", "answer"[, "expected"]}``)
        with the drawing's feedback fields: ``fault`` (indices of the student's elements at fault) and ``right``
        (the right drawing's elements with ``reveal``, else None).
    """
    d = variant.drawn(q)
    task, tolerance = d["task"], d["tolerance"]
    right = d["targets"][0]["elements"]
    out = {"id": q.id, "verdict": "", "slip": None, "score": 0.0, "max": q.points, "feedback": "", "answer": "",
           "fault": [], "right": right if reveal else None}
    if reveal:
        out["expected"] = d["text"]
    if answer is None or (isinstance(answer, str) and not answer.strip()):
        return out | {"verdict": "missing", "feedback": "No drawing was handed in for this question."}
    if isinstance(answer, NotData):  # a notebook's variable given by code, not a literal: not read, never run
        return out | {"verdict": "unreadable", "answer": f"({answer.reason}, not text)",
                      "feedback": f"The drawing could not be read: the variable holds {answer.reason}, not the "
                                  "drawing's text (paste the text the drawing gives, between quotes)."}
    try:
        drawing = answer if isinstance(answer, Drawing) else \
            read_drawing(answer, question=q.id, space=task["space"], view=task["view"])
    except Unreadable as exc:
        return out | {"verdict": "unreadable", "feedback": f"The drawing could not be read: {exc}."}
    n = len(drawing.elements)
    out["answer"] = f"a drawing of {n} element{'s' if n != 1 else ''}"
    within = f"±{_mm(tolerance['length'], task['scale'])} and ±{math.degrees(tolerance['angle']):.2g}°"
    found = match(drawing.elements, d["targets"], tolerance)
    if found == 0:
        return out | {"verdict": "correct", "score": q.points,
                      "feedback": f"Correct: {d['words']['right']} (each element within {within} on the drawing)."}
    if found is not None:
        slip = d["targets"][found]["slip"]
        share = variant.exercise.partial.get(slip, 0.0)
        fault = faults(drawing.elements, right, tolerance)
        return out | {"verdict": "slip", "slip": slip, "score": q.points * share, "fault": fault,
                      "feedback": f"Not quite: {d['words'][slip]}."}
    fault = faults(drawing.elements, right, tolerance)
    want = len(task["draw"])
    if n != want:
        msg = (f"The task asks for {want} element{'s' if want != 1 else ''} "
               f"({', '.join(e['kind'] + ' ' + e['name'] for e in task['draw'])}); the drawing has {n}.")
    else:
        names = ", ".join(f"{drawing.elements[i].kind} {printable(drawing.elements[i].name) or i + 1}".strip()
                          for i in fault)
        msg = (f"Not where the construction puts it: {names} (each element must lie within {within} on the drawing); "
               f"revisit {d['hint']}.")
    return out | {"verdict": "wrong", "fault": fault, "feedback": msg}


def grade_drawing(variant, question_id: str, drawing, *, reveal: bool | None = None) -> dict:
    """Grade a student's drawing of question ``question_id`` (JSON text or the dict), as the grader does.

    Parameters
    ----------
    variant : graphkin.exercises.Variant or graphkin.exercises.keys.KeyedVariant
    question_id : str
    drawing : str or dict
    reveal : bool, optional
        Show the right drawing (``right``) and its numbers (``expected``); default the exercise's ``reveal``.

    Returns
    -------
    dict
        ``{"id", "verdict", "slip", "score", "max", "feedback", "answer", "fault", "right"[, "expected"]}``.
    """
    q = variant.exercise.question(question_id)
    reveal = variant.exercise.reveal if reveal is None else bool(reveal)
    return grade_drawn(variant, q, drawing, reveal=reveal)
