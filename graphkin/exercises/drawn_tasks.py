"""Drawn questions: what the student is asked to draw, and the drawings the grader compares theirs with.

A drawn question (``find = "drawing"``, ``docs/exercises.md``) asks for one step of the graphical solution at
the variant's position, drawn on the mechanism or in a polygon at the worksheet's printed scale:

- ``"inertia-line"``: a link's inertia resultant's line of action (anchored at the foot of the perpendicular
  from G), slips ``wrong_side`` (the offset mirrored about G), ``through_G`` (the line through G along F) and
  ``scale_factor`` (h laid off at ×10 or ÷10, a unit read wrongly);
- ``"two-force-line"``: a two-force member's line (through its pins), slip ``wrong_member`` (the line through
  the pins of a neighbour that is not two-force);
- ``"concurrency"``: a three-force member's point of concurrency, slips ``through_G`` (the resultant's line
  taken through G, the inertia couple left out) and ``wrong_member``;
- ``"force-polygon"``: a link's polygon, its known vectors given tip to tail from the pole, closed by the
  student; slips ``wrong_order`` (the two unknowns' directions taken in the other order), ``sense_reversed``
  (one unknown drawn with its sense reversed) and ``scale_factor`` (the unknowns drawn ×10 or ÷10);
- ``"velocity-step"`` / ``"acceleration-step"``: the step of a polygon that finds a point's image from two
  known ones; slips ``sense_reversed``, ``coriolis_reversed`` and ``normal_outward`` (that component reversed,
  the step closed again) and ``scale_factor`` (the components whose size the student works out, laid off ×10
  or ÷10, the step closed again).

Everything is read off the construction (:mod:`graphkin.graphical.construction`) and the polygons
(:mod:`graphkin.graphical.motion`) the variant already holds; nothing is solved again. The data made here
(:func:`keyed`) are plain JSON: the task (``docs/json.md``, "Drawn answers"), the targets (the right drawing
first, then each slip's), the tolerance and the words; keys carry them, so grading needs neither a re-solve
nor the course secret.

Tolerance
---------
:data:`TIMES` times the drawing's stated precision (:data:`graphkin.exercises.precision.LENGTH` and
:data:`~graphkin.exercises.precision.ANGLE`) at the drawing's stated scale. A drawn element is the sum of a
few drawn operations (a direction carried with set squares, an offset or a side laid off, a point placed where
two lines meet): up to four, each within ±LENGTH and ±ANGLE. Their sum, each error uniform within its bound,
is held at :data:`~graphkin.exercises.precision.HELD` by :data:`~graphkin.exercises.precision.COVERAGE`·√4 ≈
2.6 bounds; :data:`TIMES` = 3 rounds that up (1.5 mm and 1.5° on paper, about the width of a pencil line and
of a click on the screen), and it stays well inside the gap to every slip it names (a slip closer to the
right drawing than this cannot be told apart, and is not named).
"""

from __future__ import annotations

import math

import numpy as np

from graphkin.errors import GraphkinError
from graphkin.exercises.drawn_grading import match
from graphkin.exercises.precision import ANGLE, LENGTH
from graphkin.graphical.paper import (
    MECHANISM_ROOM,
    POLYGON_ROOM,
    length_scale,
    length_text,
    motion_scales,
    sheet_scales,
)
from graphkin.model import GearMesh, Prismatic
from graphkin.notation import num

__all__ = ["DRAW_KINDS", "SPACE_OF", "TIMES", "Undefined", "keyed", "right_drawing", "task_of", "within_words"]

TIMES = 3.0
"""How many times the drawing's stated precision a drawn element may be off and still be right (see the module)."""

DRAW_KINDS = ("inertia-line", "two-force-line", "concurrency", "force-polygon", "velocity-step", "acceleration-step")
"""What a drawn question may ask for (its ``draw``)."""

SPACE_OF = {"inertia-line": "mechanism", "two-force-line": "mechanism", "concurrency": "mechanism",
            "force-polygon": "force", "velocity-step": "velocity", "acceleration-step": "acceleration"}
"""The space each kind is drawn in."""

_UNIT = {"mechanism": "m", "force": "N", "velocity": "m/s", "acceleration": "m/s^2"}
_SHOWN_UNIT = {"mechanism": ("mm", 1e3), "force": ("N", 1.0), "velocity": ("m/s", 1.0), "acceleration": ("m/s²", 1.0)}

WORDS = {
    None: "your construction matches the right one",
    "wrong_side": "the line is offset by h to the wrong side of G: the resultant's moment about G must turn the way "
                  "the inertia torque does",
    "through_G": "the inertia resultant is taken through G: offset it by h = |T|/|F| so that its moment about G is "
                 "the inertia torque",
    "scale_factor": "a length is laid off at the wrong factor (×10 or ÷10): check the unit of the value and the "
                    "drawing's scale",
    "wrong_member": "the line follows a member that carries more than two forces: only a member loaded at its two "
                    "pins alone has its force along the line through them",
    "wrong_order": "the two unknown directions are taken in the other order: the polygon closes the other way round, "
                   "and each force must lie along its own line of action",
    "sense_reversed": "a vector is drawn with its sense reversed: the forces (or components) follow tip to tail",
    "coriolis_reversed": "the Coriolis component 2ωv is reversed: turn the sliding velocity 90° in the sense of ω",
    "normal_outward": "a normal component ω²r is drawn away from the centre: it always points towards the centre "
                      "of the relative motion",
}
"""The words of each verdict of a drawn question, by slip (None: right)."""


class Undefined(Exception):
    """The question has no drawing at this variant's position (then the draw is not handed out)."""


# -- small geometry ---------------------------------------------------------------------------------------------
def _p(x) -> list[float]:
    return [float(x[0]), float(x[1])]


def _line(name, anchor, direction, reach) -> dict:
    a = np.asarray(anchor, float)
    return {"kind": "line", "name": name, "through": [_p(a), _p(a + reach * np.asarray(direction, float))]}


def _point(name, at) -> dict:
    return {"kind": "point", "name": name, "at": _p(at)}


def _vector(name, tail, tip) -> dict:
    return {"kind": "vector", "name": name, "from": _p(tail), "to": _p(tip)}


def _unit(v) -> np.ndarray:
    v = np.asarray(v, float)
    n = math.hypot(*v)
    return v / n if n > 0 else v


def _foot(point, direction, G) -> np.ndarray:
    """The foot of the perpendicular from G to the line through ``point`` along ``direction``."""
    p, d, g = (np.asarray(x, float) for x in (point, direction, G))
    d = _unit(d)
    return p + float(np.dot(g - p, d)) * d


def _meet(p1, d1, p2, d2):
    """Where two lines meet (None when they are parallel)."""
    p1, d1, p2, d2 = (np.asarray(x, float) for x in (p1, d1, p2, d2))
    det = d1[0] * -d2[1] + d2[0] * d1[1]
    if abs(det) < 1e-12 * max(1.0, math.hypot(*d1) * math.hypot(*d2)):
        return None
    r = p2 - p1
    s = (r[0] * -d2[1] + d2[0] * r[1]) / det
    return p1 + s * d1


def _mm_point(p) -> str:
    return f"({num(p[0] * 1e3, 4)}, {num(p[1] * 1e3, 4)}) mm"


def _angle(d) -> float:
    return float(math.atan2(d[1], d[0]))


# -- what the question is about ---------------------------------------------------------------------------------
def _refuse_invalid(solved, q, what, c) -> None:
    if not c.valid:
        raise GraphkinError(f"exercise {solved.exercise.id}, question {q.id}: no drawing is keyed at "
                            f"{solved.problem.name}: the {what} is not valid ({c.reason})")


def _step(steps, kind, link, q, what):
    found = [s for s in steps if s.kind == kind and s.link == link]
    if not found:
        raise Undefined(f"question {q.id}: the construction has no {what} of link {link} at this position")
    return next((s for s in found if not s.sub), found[0])


def _numbered(steps, step, words: str, of: str = "of the construction") -> str:
    """The step to revisit, as every hint names it: ``"step 7 of the construction: ..."``."""
    n = next(i for i, s in enumerate(steps, 1) if s is step)
    return f"step {n} {of}: {words}"


def _sub_words(step) -> str:
    return f" (sub-problem {step.sub}: link {step.link}'s own loads alone)" if step.sub else ""


def _pins(c, link) -> list:
    """The revolute pins of ``link`` at this position, each (name, (x, y))."""
    out = []
    for J in c.mechanism.joints_of(link):
        if isinstance(J, (Prismatic, GearMesh)):
            continue
        out.append((J.point, c.points[link][J.point]))
    return out


def _mechanism_shown(c, extra_points=()) -> tuple[dict, list]:
    segments, points, seen = [], [], set()
    for link, pts in c.points.items():
        names = list(pts)
        if link != c.mechanism.frame:
            for i, a in enumerate(names):
                for b in names[i + 1:]:
                    if math.dist(pts[a], pts[b]) > 0:
                        segments.append({"name": f"{a}{b}", "from": _p(pts[a]), "to": _p(pts[b])})
        for n in names:
            if n not in seen:
                seen.add(n)
                points.append({"name": n, "at": _p(pts[n])})
    points += [{"name": n, "at": _p(at)} for n, at in extra_points]
    return {"segments": segments, "points": points, "vectors": [], "lines": []}, points


def _view(points, margin=0.15) -> list[float]:
    P = np.asarray(points, float).reshape(-1, 2)
    lo, hi = P.min(axis=0), P.max(axis=0)
    size = max(float(np.max(hi - lo)), 1e-9)
    pad = margin * size
    return [float(lo[0] - pad), float(lo[1] - pad), float(hi[0] + pad), float(hi[1] + pad)]


def _with_slips(view, targets, fits) -> list[float]:
    """The view grown to hold what each slip's drawing is anchored at (a line's anchor, a point, a vector's ends),
    where the box still ``fits`` the page at its scale, so that a student can make the slip the grader names (the
    offset on the other side of G, the polygon closed in the other order). A slip of scale (ten times too long or
    short) is left out, and so is a slip that would not fit: a drawing that runs off the box tells the student by
    itself that something is wrong, and the grader still names the slip."""
    for t in targets[1:]:
        if t["slip"] == "scale_factor":
            continue
        points = [e["through"][0] if e["kind"] == "line" else e.get("at") for e in t["elements"]
                  if e["kind"] != "vector"]
        points += [p for e in t["elements"] if e["kind"] == "vector" for p in (e["from"], e["to"])]
        P = np.asarray(points, float)
        lo, hi = P.min(axis=0), P.max(axis=0)
        if lo[0] >= view[0] and lo[1] >= view[1] and hi[0] <= view[2] and hi[1] <= view[3]:
            continue
        pad = 0.05 * max(view[2] - view[0], view[3] - view[1])
        grown = [float(min(view[0], lo[0] - pad)), float(min(view[1], lo[1] - pad)),
                 float(max(view[2], hi[0] + pad)), float(max(view[3], hi[1] + pad))]
        if fits(grown):
            view = grown
    return view


def _elements_points(elements) -> list:
    out = []
    for e in elements:
        out += e.get("through", []) + ([e["at"]] if "at" in e else []) + \
            ([e["from"], e["to"]] if "from" in e else [])
    return out


# -- each kind ----------------------------------------------------------------------------------------------------
def _inertia_line(solved, q, c, si_mm):
    k = q.link
    inn = c.inertia.get(k)
    if inn is None or not math.hypot(*inn["F"]) > 0 or inn.get("h") is None:
        raise Undefined(f"link {k}'s inertia force is zero, so its resultant has no line of action")
    step = _step(c.steps, "resultant", k, q, "inertia resultant")
    line = next((ln for ln in step.lines if ln.name == f"R{k}i"), None)
    if line is None:
        raise Undefined(f"link {k} has no single inertia resultant at this position (no inertia force)")
    G = np.asarray(c.G[k], float)
    u = _unit(line.direction)
    foot = _foot(line.point, u, G)
    reach = 40 * si_mm
    F, T = inn["F"], inn["T"]
    name = f"R{k}i"
    right = [_line(name, foot, u, reach)]
    off = foot - G
    slips = [("wrong_side", [_line(name, G - off, u, reach)]), ("through_G", [_line(name, G, u, reach)])]
    slips += [("scale_factor", [_line(name, G + f * off, u, reach)]) for f in (10.0, 0.1)]
    shown, snap_points = _mechanism_shown(c, [(f"G{k}", G)])
    shown["vectors"] = [_vector(f"F{k}i", G, G + 20 * si_mm * u)]
    Fsize = math.hypot(*F)
    ask = (f"Draw the line of action of {name}, the single resultant of F{k}i = −m{k} a_G{k} (|F{k}i| = "
           f"{num(Fsize, 4)} N, drawn at G{k} to show its direction) and T{k}i = −I_G{k} α{k} = {num(abs(T), 4)} N·m "
           f"{'CCW' if T > 0 else 'CW'}")
    snap = {"points": snap_points, "angles": [{"name": f"∥ F{k}i", "angle": _angle(u)},
                                              {"name": f"⊥ F{k}i", "angle": _angle((-u[1], u[0]))}]}
    text = (f"{_mm_point(foot)}: the foot of the perpendicular from G{k} to the line of {name}, parallel to F{k}i "
            f"and offset h = {num(math.hypot(*off) * 1e3, 4)} mm from G{k}")
    hint = _numbered(c.steps, step, f"link {k}'s inertia force −m a_G and torque −I_G α combined into one resultant "
                                    f"offset by h = |T|/|F| from G{k}")
    view = _view([p["at"] for p in snap_points] + [_p(foot)])
    return ask, shown, snap, [{"kind": "line", "name": name}], right, slips, view, text, hint


def _wrong_member_line(c, three, known_link, q):
    """The line through the pins of the three-force member's other neighbour (a member that is not two-force),
    or None where there is none."""
    k = three.link
    for J in c.mechanism.joints_of(k):
        other = (set(J.links) - {k}).pop()
        if other in (known_link, c.mechanism.frame) or isinstance(J, (Prismatic, GearMesh)):
            continue
        pins = _pins(c, other)
        if len(pins) == 2 and math.dist(pins[0][1], pins[1][1]) > 0:
            return pins
    return None


def _two_force_line(solved, q, c, si_mm):
    m = q.link
    step = _step(c.steps, "two-force", m, q, "two-force step")
    line = step.lines[0]
    u = _unit(line.direction)
    reach = 40 * si_mm
    right = [_line(line.name, line.point, u, reach)]
    slips = []
    three = next((s for s in c.steps if s.kind == "three-force" and s.sub == step.sub
                  and any(ln.name == line.name for ln in s.lines)), None)
    if three is not None:
        pins = _wrong_member_line(c, three, m, q)
        if pins is not None:
            a, b = (np.asarray(p, float) for _, p in pins)
            slips.append(("wrong_member", [_line(line.name, a, _unit(b - a), reach)]))
    shown, snap_points = _mechanism_shown(c)
    ask = f"Draw the line of action of {line.name}: link {m} carries two forces only{_sub_words(step)}"
    pins = _pins(c, m)
    text = (f"{' and '.join(_mm_point(p) for _, p in pins)}: the line of {line.name} through "
            f"{' and '.join(n for n, _ in pins)}, the pins of link {m}")
    hint = _numbered(c.steps, step, f"link {m} as a two-force member: its two forces share the line through its pins")
    view = _view([p["at"] for p in snap_points])
    return ask, shown, {"points": snap_points, "angles": []}, [{"kind": "line", "name": line.name}], right, slips, \
        view, text, hint


def _resultant_through_G(c, k, R_line):
    """The line of link k's resultant load with the inertia torque left out (its inertia force through G)."""
    inn = c.inertia.get(k)
    if inn is None or not abs(inn["T"]) > 0:
        return None
    G = np.asarray(c.G[k], float)
    Fx, Fy = inn["F"]
    Rx, Ry = Fx, Fy
    M = sum(T for _, T in c.torques.get(k, []))
    for a in c.external.get(k, []):
        if a.at is None:
            continue
        r = np.asarray(a.at, float) - G
        Rx, Ry = Rx + a.vector[0], Ry + a.vector[1]
        M += r[0] * a.vector[1] - r[1] * a.vector[0]
    R2 = Rx * Rx + Ry * Ry
    if not R2 > 0:
        return None
    return G + M / R2 * np.array([Ry, -Rx]), _unit((Rx, Ry))


def _concurrency(solved, q, c, si_mm):
    k = q.link
    step = _step(c.steps, "three-force", k, q, "three-force step")
    name = f"I{k}"
    if name not in step.points:
        raise Undefined(f"link {k} has no point of concurrency at this position")
    I = np.asarray(step.points[name], float)
    R = next((ln for ln in step.lines if ln.role == "resultant"), None)
    known = next((ln for ln in step.lines if ln.role == "known direction"), None)
    right = [_point(name, I)]
    slips = []
    if R is not None and known is not None:
        moved = _resultant_through_G(c, k, R)
        if moved is not None:
            X = _meet(moved[0], moved[1], known.point, known.direction)
            if X is not None:
                slips.append(("through_G", [_point(name, X)]))
        two = next((s for s in c.steps if s.kind == "two-force" and s.sub == step.sub
                    and any(ln.name == known.name for ln in s.lines)), None)
        pins = _wrong_member_line(c, step, two.link if two is not None else None, q)
        if pins is not None:
            a, b = (np.asarray(p, float) for _, p in pins)
            X = _meet(R.point, R.direction, a, b - a)
            if X is not None:
                slips.append(("wrong_member", [_point(name, X)]))
    shown, snap_points = _mechanism_shown(c, [(f"G{k}", c.G[k])] if k in c.G else [])
    shown["lines"] = [{"name": ln.name, "through": _p(ln.point), "angle": _angle(ln.direction)}
                      for ln in step.lines if ln.role != "found"]
    ask = (f"Place {name}, the point where the lines of action of the three forces on link {k} meet: the lines "
           f"{' and '.join(ln.name for ln in step.lines if ln.role != 'found')} are drawn{_sub_words(step)}")
    text = f"{_mm_point(I)}: {name}"
    hint = _numbered(c.steps, step, f"link {k} as a three-force member and its point of concurrency")
    view = _view([p["at"] for p in snap_points] + [_p(I)])
    return ask, shown, {"points": snap_points, "angles": []}, [{"kind": "point", "name": name}], right, slips, view, \
        text, hint


def _force_polygon(solved, q, c, si_mm):
    k = q.link
    step = _step(c.steps, "polygon", k, q, "force polygon")
    knowns = [a for a in step.polygon if a.known]
    unknowns = [a for a in step.polygon if not a.known]
    tip = np.zeros(2)
    shown_vectors = []
    snap_points = [{"name": "o", "at": [0.0, 0.0]}]
    for a in knowns:
        nxt = tip + np.asarray(a.vector, float)
        shown_vectors.append(_vector(a.name, tip, nxt))
        tip = nxt
        snap_points.append({"name": f"tip of {a.name}", "at": _p(tip)})
    start = tip.copy()

    def chain(vectors, names):
        out, t = [], start.copy()
        for v, n in zip(vectors, names):
            out.append(_vector(n, t, t + v))
            t = t + v
        return out

    vecs = [np.asarray(a.vector, float) for a in unknowns]
    names = [a.name for a in unknowns]
    right = chain(vecs, names)
    slips = []
    if len(unknowns) == 2:
        u1, u2 = (_unit(v) for v in vecs)
        X = _meet(start, u2, np.zeros(2), u1)
        if X is not None:
            slips.append(("wrong_order", [_vector(names[0], start, X), _vector(names[1], X, np.zeros(2))]))
    for i in range(len(right)):
        flipped = [dict(e) for e in right]
        flipped[i] = _vector(names[i], right[i]["to"], right[i]["from"])
        slips.append(("sense_reversed", flipped))
    slips += [("scale_factor", chain([f * v for v in vecs], names)) for f in (10.0, 0.1)]
    angles = [{"name": f"∥ {n}", "angle": _angle(v)} for n, v in zip(names, vecs)]
    shown = {"segments": [], "points": [{"name": "o", "at": [0.0, 0.0]}], "vectors": shown_vectors, "lines": []}
    ask = (f"Close the force polygon of link {k}{_sub_words(step)}: its known forces are drawn tip to tail from the "
           f"pole o; draw {' and '.join(names)} along their lines of action so that the polygon closes")
    text = "; ".join(f"{num(math.hypot(*v), 4)} N ∠ {num(math.degrees(_angle(v)), 4)}° ({n})"
                     for n, v in zip(names, vecs))
    hint = _numbered(c.steps, step, f"the force polygon of link {k}, closed tip to tail")
    view = _view([p["at"] for p in snap_points] + _elements_points(right), margin=0.2)
    return ask, shown, {"points": snap_points, "angles": angles}, [{"kind": "vector", "name": n} for n in names], \
        right, slips, view, text, hint


def _image_name(vector_name: str, polygon: str) -> str:
    return vector_name[2:].lower() + ("′" if polygon == "acceleration" else "")


def _chains(drawn):
    """The drawn vectors of a step as chains, each from a known image to the found one (lists of indices)."""
    def same(a, b):
        return math.dist(a, b) <= 1e-9 * max(1.0, math.hypot(*a), math.hypot(*b))

    starts = [i for i, v in enumerate(drawn) if not any(same(v.tail, w.tip) for w in drawn)]
    chains = []
    for i in starts:
        chain = [i]
        while True:
            nxt = next((j for j, w in enumerate(drawn) if j not in chain and same(w.tail, drawn[chain[-1]].tip)), None)
            if nxt is None:
                break
            chain.append(nxt)
        chains.append(chain)
    return chains


def _closed_again(drawn, chains, change):
    """The step's drawn vectors with the known-size ones changed by ``change(index, vector)`` and each chain's last
    vector (its size unknown) carried to where the two chains' lines now meet; None where that cannot be done."""
    if len(chains) != 2 or any(drawn[ch[-1]].known != "direction" for ch in chains):
        return None
    ends = []
    for ch in chains:
        t = np.asarray(drawn[ch[0]].tail, float)
        for i in ch[:-1]:
            t = t + change(i, np.asarray(drawn[i].vector, float))
        ends.append(t)
    d = [np.asarray(drawn[ch[-1]].vector, float) for ch in chains]
    X = _meet(ends[0], d[0], ends[1], d[1])
    if X is None:
        return None
    out = [None] * len(drawn)
    for ch, end in zip(chains, ends):
        t = np.asarray(drawn[ch[0]].tail, float)
        for i in ch[:-1]:
            nxt = t + change(i, np.asarray(drawn[i].vector, float))
            out[i] = _vector(drawn[i].name, t, nxt)
            t = nxt
        out[ch[-1]] = _vector(drawn[ch[-1]].name, end, X)
    return out


def _motion_step(solved, q, mc, si_mm):
    polygon = q.space
    letter = "v" if polygon == "velocity" else "a"
    want = f"{letter}_{q.point}"
    step = next((s for s in mc.steps if s.polygon == polygon and s.kind == "dyad"
                 and any(v.name == want and v.known == "found" for v in s.vectors)), None)
    if step is None:
        found = sorted({v.name for s in mc.steps if s.polygon == polygon and s.kind == "dyad" for v in s.vectors
                        if v.known == "found"})
        raise GraphkinError(f"exercise {solved.exercise.id}, question {q.id}: point = {q.point!r}: no step of the "
                            f"{polygon} polygon finds {want} (steps find: {', '.join(found) or 'none'})")
    absolute = [v for v in step.vectors if v.known == "size and direction" and v.name.startswith(f"{letter}_")
                and math.hypot(*v.tail) == 0]
    drawn = [v for v in step.vectors if v not in absolute and v.known != "found"]
    pole = "o" if polygon == "velocity" else "o′"
    snap_points = [{"name": pole, "at": [0.0, 0.0]}]
    shown_vectors = []
    for v in absolute:
        snap_points.append({"name": _image_name(v.name, polygon), "at": _p(v.tip)})
        if math.hypot(*v.vector) > 0:
            shown_vectors.append(_vector(v.name, v.tail, v.tip))
    right = [_vector(v.name, v.tail, v.tip) for v in drawn]
    chains = _chains(drawn)
    slips = []
    for i in range(len(right)):
        flipped = list(right)
        flipped[i] = _vector(drawn[i].name, drawn[i].tip, drawn[i].tail)
        slips.append(("sense_reversed", flipped))
    fixed = [i for i, v in enumerate(drawn) if v.known == "size and direction"]
    for i in fixed:
        slip = "coriolis_reversed" if drawn[i].name.startswith("a^c") else \
            "normal_outward" if drawn[i].name.startswith("a^n") else None
        if slip is not None:
            made = _closed_again(drawn, chains, lambda j, v, i=i: -v if j == i else v)
            if made is not None:
                slips.append((slip, made))
    if fixed:
        for f in (10.0, 0.1):
            made = _closed_again(drawn, chains, lambda j, v, f=f: f * v if j in fixed else v)
            if made is not None:
                slips.append(("scale_factor", made))
    angles = [{"name": f"∥ {v.name}", "angle": _angle(v.vector)} for v in drawn if math.hypot(*v.vector) > 0]
    shown = {"segments": [], "points": snap_points, "vectors": shown_vectors, "lines": []}
    image = _image_name(want, polygon)
    what = "velocity" if polygon == "velocity" else "acceleration"
    ask = (f"Find {image}, the image of {q.point} in the {what} polygon: from the known images drawn, draw "
           f"{', '.join(v.name for v in drawn)} tip to tail, each along its known direction, to where they meet")
    unit = _SHOWN_UNIT[polygon][0]
    text = "; ".join(f"{num(math.hypot(*v.vector), 4)} {unit} ∠ {num(math.degrees(_angle(v.vector)), 4)}° ({v.name})"
                     for v in drawn)
    hint = _numbered(mc.steps, step, f"the {what} polygon's dyad that finds {image}", "of the construction of the polygons")
    view = _view([p["at"] for p in snap_points] + _elements_points(right), margin=0.2)
    return ask, shown, {"points": snap_points, "angles": angles}, [{"kind": "vector", "name": v.name} for v in drawn], \
        right, slips, view, text, hint


_MAKERS = {"inertia-line": _inertia_line, "two-force-line": _two_force_line, "concurrency": _concurrency,
           "force-polygon": _force_polygon, "velocity-step": _motion_step, "acceleration-step": _motion_step}


def _scale(solved, q):
    """The drawing's stated scale: (SI per mm of drawing, its text)."""
    space = q.space
    if space == "mechanism":
        k = sheet_scales(solved.construction).length
        return k * 1e-3, f"1 mm = {num(k, 4)} mm ({length_text(k)})"
    if space == "force":
        X = sheet_scales(solved.construction).polygon
        return X, f"1 mm = {num(X, 4)} N"
    Xv, Xa = motion_scales(solved.motion, POLYGON_ROOM)
    return (Xv, f"1 mm = {num(Xv, 4)} m/s") if space == "velocity" else (Xa, f"1 mm = {num(Xa, 4)} m/s²")


def keyed(solved, q) -> dict:
    """A drawn question's task, targets, tolerance and words for a solved draw, as JSON data.

    Parameters
    ----------
    solved : graphkin.exercises.variants.Solved
    q : Question
        A drawn question (``q.kind == "drawing"``).

    Returns
    -------
    dict
        ``{"task": {...}, "targets": [{"slip": None, "elements": [...]}, ...], "tolerance": {"length", "angle"},
        "words": {slip: text}, "text": the right drawing in words and numbers, "hint": the step to revisit}``.
        The task's ``check`` is None (:func:`task_of` fills it for a practice page).

    Raises
    ------
    Undefined
        Where the question has no drawing at this position (a zero inertia force, no point of concurrency).
    GraphkinError
        Where the construction or the polygons are not valid (naming the question and the position), or the
        question names a step the polygons do not have.
    """
    space = q.space
    if space in ("mechanism", "force"):
        c = solved.construction
        _refuse_invalid(solved, q, "graphical construction", c)
        source = c
    else:
        mc = solved.motion
        _refuse_invalid(solved, q, f"{space} polygon", mc)
        source = mc
    si_mm, scale_text = _scale(solved, q)
    while True:
        ask, shown, snap, draw, right, slips, view, text, hint = _MAKERS[q.draw](solved, q, source, si_mm)
        # On the mechanism, a box wider than the page (an inertia resultant's line far from its link) is drawn at
        # the standard scale that fits it, as a student would choose a smaller scale on paper.
        k = length_scale((1e3 * (view[2] - view[0]), 1e3 * (view[3] - view[1])), MECHANISM_ROOM)
        if q.space != "mechanism" or k <= 1e3 * si_mm * (1 + 1e-9):
            break
        si_mm, scale_text = k * 1e-3, f"1 mm = {num(k, 4)} mm ({length_text(k)})"
    tolerance = {"length": TIMES * LENGTH * si_mm, "angle": math.radians(TIMES * ANGLE)}
    targets = [{"slip": None, "elements": right}]
    for slip, elements in slips:
        # A slip that leaves the drawing within the tolerance of the right one cannot be told from it.
        if match(elements, right, tolerance) is None:
            targets.append({"slip": slip, "elements": elements})
    room = MECHANISM_ROOM if q.space == "mechanism" else (math.inf, math.inf)
    view = _with_slips(view, targets, lambda v: (v[2] - v[0]) / si_mm <= room[0] and (v[3] - v[1]) / si_mm <= room[1])
    words = {str(t["slip"]) if t["slip"] else "right": WORDS[t["slip"]] for t in targets}
    task = {"task": 1, "question": q.id, "kind": q.draw, "space": space, "unit": _UNIT[space], "ask": ask,
            "scale": {"si_per_mm": si_mm, "text": scale_text}, "view": view, "shown": shown, "snap": snap,
            "draw": draw, "check": None}
    return {"task": task, "targets": targets, "tolerance": tolerance, "words": words, "text": text, "hint": hint}


def within_words(q, solved=None) -> str:
    """A drawn question's tolerance as the sheet states it: ``"±1.5 mm and ±1.5° for each element drawn, at the
    drawing's scale 1 mm = 10 mm (1:10)"`` (``solved``: the student's solved draw, for the scale)."""
    text = f"±{TIMES * LENGTH:g} mm and ±{TIMES * ANGLE:g}° for each element drawn"
    try:
        return text if solved is None else f"{text}, at the drawing's scale {solved.drawn(q)['task']['scale']['text']}"
    except (Undefined, GraphkinError):
        return text


def task_of(variant, question_id: str, *, practice: bool = False) -> dict:
    """The task of a drawn question for a student's variant (``docs/json.md``, "Drawn answers").

    Parameters
    ----------
    variant : graphkin.exercises.Variant or graphkin.exercises.keys.KeyedVariant
    question_id : str
    practice : bool
        Fill ``check`` with the grader's targets, tolerance and words, for a practice page that says which the
        drawing matches (no grade recorded). Never for a graded task: the targets are the answer.

    Raises
    ------
    GraphkinError
        A question the exercise does not have, or one that is not drawn.
    """
    q = variant.exercise.question(question_id)
    if q.kind != "drawing":
        raise GraphkinError(f"{variant.exercise.id}: question {question_id!r} is not drawn (find = {q.find!r})")
    d = variant.drawn(q)
    task = dict(d["task"])
    task["check"] = ({"targets": d["targets"], "tolerance": d["tolerance"], "words": d["words"]} if practice
                     else None)
    return task


def right_drawing(drawn: dict) -> dict:
    """The right drawing of a drawn question (its :func:`keyed` data), as a student's drawing holds it."""
    task = drawn["task"]
    return {"drawing": 1, "question": task["question"], "space": task["space"], "unit": task["unit"],
            "elements": drawn["targets"][0]["elements"]}
