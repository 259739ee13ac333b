"""Hand-written drawn tasks in docs/json.md's "Drawn answers" format, for the practice page and the drawing's browser
tests: a line (an inertia resultant's line of action, offset h from G3), a point (a three-force member's point of
concurrency) and two vectors (a force polygon closed tip to tail). Each carries its ``check``: the right construction
and the slips, as the grader's targets would.

The numbers are the construction's own: the right line is F3i's direction through G3 + h n (n the unit normal on the
side that gives the torque), the concurrency point the intersection of the two known lines, the polygon's vectors
close F3i + F43 + F23 = 0.
"""

from __future__ import annotations

import math

G3 = (0.15, 0.05)
F3I = (-0.06, -0.02)  # the inertia force's arrow as drawn at G3 (m of the drawing's space)
H = 0.03  # the offset of R3i's line from G3 [m]


def unit(v):
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n)


def line_task(practice: bool = True) -> dict:
    """Draw R3i's line of action: F3i's direction at the offset h from G3 on the side n (a 'wrong_side' slip on -n,
    'through_G' through G3 itself)."""
    d = unit(F3I)
    n = (-d[1], d[0])
    angle = math.atan2(d[1], d[0])
    anchor = (G3[0] + H * n[0], G3[1] + H * n[1])
    other = (G3[0] - H * n[0], G3[1] - H * n[1])

    def line(p):
        return [{"kind": "line", "name": "R3i", "through": [list(p), [p[0] + 0.1 * d[0], p[1] + 0.1 * d[1]]]}]

    return {"task": 1, "question": "line3", "kind": "inertia-line", "space": "mechanism", "unit": "m",
            "ask": "Draw the line of action of R3i, the resultant of −m3 a_G3 and −I_G3 α3",
            "scale": {"si_per_mm": 0.002, "text": "1 mm = 2 mm"}, "view": [-0.05, -0.05, 0.35, 0.2],
            "shown": {"segments": [{"name": "AB", "from": [0.0, 0.0], "to": [0.3, 0.1]}],
                      "points": [{"name": "A", "at": [0.0, 0.0]}, {"name": "B", "at": [0.3, 0.1]},
                                 {"name": "G3", "at": list(G3)}],
                      "vectors": [{"name": "F3i", "from": list(G3), "to": [G3[0] + F3I[0], G3[1] + F3I[1]]}],
                      "lines": []},
            "snap": {"points": [{"name": "A", "at": [0.0, 0.0]}, {"name": "G3", "at": list(G3)},
                                {"name": "B", "at": [0.3, 0.1]}],
                     "angles": [{"name": "∥ F3i", "angle": angle}]},
            "draw": [{"kind": "line", "name": "R3i"}],
            "check": {"targets": [{"slip": None, "elements": line(anchor)},
                                  {"slip": "wrong_side", "elements": line(other)},
                                  {"slip": "through_G", "elements": line(G3)}],
                      "tolerance": {"length": 0.002, "angle": math.radians(2)},
                      "words": {"wrong_side": "The offset is on the wrong side: R3i's moment about G3 must have the "
                                              "sense of −I_G3 α3.",
                                "through_G": "R3i passes through G3 only when α3 = 0: offset it by h = I_G3 α3 / R3i."}}
            if practice else None}


P = (0.10, 0.05)  # a snap point 10 mm left and 5 mm above the concurrency point at the 1 mm = 2 mm scale
I3 = (P[0] + 0.02, P[1] - 0.01)


def point_task() -> dict:
    """Place I3, where the two known lines of action meet (a slip 'at_G': at the snap point P)."""
    return {"task": 1, "question": "point3", "kind": "concurrency", "space": "mechanism", "unit": "m",
            "ask": "Place the point of concurrency I3 of the three forces on link 3",
            "scale": {"si_per_mm": 0.002, "text": "1 mm = 2 mm"}, "view": [0.0, -0.05, 0.25, 0.12],
            "shown": {"segments": [], "points": [{"name": "P", "at": list(P)}], "vectors": [],
                      "lines": [{"name": "F23", "through": list(I3), "angle": math.radians(30)},
                                {"name": "F43", "through": list(I3), "angle": math.radians(120)}]},
            "snap": {"points": [{"name": "P", "at": list(P)}], "angles": []},
            "draw": [{"kind": "point", "name": "I3"}],
            "check": {"targets": [{"slip": None, "elements": [{"kind": "point", "name": "I3", "at": list(I3)}]},
                                  {"slip": "at_G", "elements": [{"kind": "point", "name": "I3", "at": list(P)}]}],
                      "tolerance": {"length": 0.002, "angle": math.radians(2)},
                      "words": {"at_G": "I3 is where the lines of action meet, not a point of the link."}}}


TIP = (120.0, 40.0)
CORNER = (120.0, 0.0)


def polygon_task() -> dict:
    """Close the polygon F3i + F43 + F23 = 0 tip to tail from the known F3i (the slip 'reversed': both senses
    reversed, drawn from the pole out)."""
    def vectors(a, b, c):
        return [{"kind": "vector", "name": "F43", "from": list(a), "to": list(b)},
                {"kind": "vector", "name": "F23", "from": list(b), "to": list(c)}]

    return {"task": 1, "question": "polygon3", "kind": "force-polygon", "space": "force", "unit": "N",
            "ask": "Close the force polygon of link 3: F43 (vertical), then F23 (horizontal), tip to tail",
            "scale": {"si_per_mm": 2.0, "text": "1 mm = 2 N"}, "view": [-30.0, -30.0, 170.0, 70.0],
            "shown": {"segments": [], "points": [{"name": "o", "at": [0.0, 0.0]}],
                      "vectors": [{"name": "F3i", "from": [0.0, 0.0], "to": list(TIP)}], "lines": []},
            "snap": {"points": [{"name": "o", "at": [0.0, 0.0]}, {"name": "tip of F3i", "at": list(TIP)}],
                     "angles": [{"name": "∥ F43", "angle": math.pi / 2}, {"name": "∥ F23", "angle": 0.0}]},
            "draw": [{"kind": "vector", "name": "F43"}, {"kind": "vector", "name": "F23"}],
            "check": {"targets": [{"slip": None, "elements": vectors(TIP, CORNER, (0.0, 0.0))},
                                  {"slip": "reversed", "elements": vectors(CORNER, TIP, (0.0, 0.0))[:1]
                                   + [{"kind": "vector", "name": "F23", "from": [0.0, 0.0], "to": list(CORNER)}]}],
                      "tolerance": {"length": 2.0, "angle": math.radians(2)},
                      "words": {"reversed": "Each force's sense is reversed: tip to tail, each starts where the "
                                            "last one ends."}}}


def tasks() -> list[dict]:
    """The three tasks of the practice page's browser test."""
    return [line_task(), point_task(), polygon_task()]


def fixture_grade(task: dict):
    """A stand-in for the exercise's grader, for the widget's browser test: the spec's matching rule against the
    task's targets (the verdict, the words, the fault), the right construction revealed. The real grader is
    :func:`graphkin.exercises.grading.grade_question`."""
    import json

    check = task["check"]
    tol = check["tolerance"]

    def near(e, t):
        if e["kind"] != t["kind"]:
            return False
        if e["kind"] == "point":
            return math.dist(e["at"], t["at"]) <= tol["length"]
        if e["kind"] == "vector":
            return math.dist(e["from"], t["from"]) <= tol["length"] and math.dist(e["to"], t["to"]) <= tol["length"]
        (a, b), (p, q) = e["through"], t["through"]
        gap = abs(math.atan2(b[1] - a[1], b[0] - a[0]) - math.atan2(q[1] - p[1], q[0] - p[0])) % math.pi
        off = abs((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) / math.dist(a, b)
        return min(gap, math.pi - gap) <= tol["angle"] and off <= tol["length"]

    def grade(text: str) -> dict:
        elements = json.loads(text)["elements"] if text else []
        right = check["targets"][0]["elements"]
        for t in check["targets"]:
            if len(elements) == len(t["elements"]) and all(map(near, elements, t["elements"])):
                slip = t["slip"]
                return {"verdict": "slip" if slip else "correct", "slip": slip, "score": 0.5 if slip else 1,
                        "max": 1, "feedback": check["words"].get(slip, "Right."), "fault": [], "right": right}
        fault = [k for k, e in enumerate(elements) if k >= len(right) or not near(e, right[k])]
        return {"verdict": "wrong", "slip": None, "score": 0, "max": 1, "feedback": "Not the construction.",
                "fault": fault, "right": right}

    return grade


# -- where a browser test clicks to draw a target --------------------------------------------------------------
def inside(task, p, inset=3.0):
    """Whether p lies in the task's view, ``inset`` mm of drawing in from its edges."""
    m = inset * task["scale"]["si_per_mm"]
    x0, y0, x1, y1 = task["view"]
    return x0 + m < p[0] < x1 - m and y0 + m < p[1] < y1 - m


def on_line(task, a, b):
    """Two points of the line through a and b to click: inside the view and clear of the snap points (the anchor a
    itself may lie outside the view: a line is matched by its direction and its distance from a); None when the line
    misses the view."""
    s = task["scale"]["si_per_mm"]
    u = (b[0] - a[0]) / math.dist(a, b), (b[1] - a[1]) / math.dist(a, b)
    reach = math.dist(task["view"][:2], task["view"][2:])
    line = [(a[0] + t * u[0], a[1] + t * u[1]) for t in (reach * (k / 200 - 1) + 0 for k in range(401))]
    line += [(a[0] + t * u[0], a[1] + t * u[1]) for t in
             (math.hypot(a[0] - task["view"][0], a[1] - task["view"][1]) * (k / 200 - 1) for k in range(401))]
    ok = [q for q in line if inside(task, q) and all(math.dist(q, p["at"]) > 3 * s for p in task["snap"]["points"])]
    if not ok:
        return None
    first = ok[len(ok) // 3]
    far = max(ok, key=lambda q: math.dist(q, first))
    if math.dist(first, far) < 10 * s:
        return None
    mid = (first[0] + (far[0] - first[0]) / 2, first[1] + (far[1] - first[1]) / 2)
    return first, min(ok, key=lambda q: math.dist(q, mid))


def reachable(task, target):
    """Whether every element of ``target`` can be drawn in the task's view, each vector at least 3 mm long."""
    for e in target["elements"]:
        if e["kind"] == "line" and on_line(task, *e["through"]) is None:
            return False
        if e["kind"] == "point" and not inside(task, e["at"], 0):
            return False
        if e["kind"] == "vector" and not (inside(task, e["from"], 0) and inside(task, e["to"], 0)):
            return False
        # A vector shorter than the snap radius either way cannot be drawn apart from the points it starts at.
        if e["kind"] == "vector" and math.dist(e["from"], e["to"]) < 3 * task["scale"]["si_per_mm"]:
            return False
    return True
