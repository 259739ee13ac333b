"""The key as a textbook prints a solution: the motion, the inertia loads, the free bodies, the lines of action,
the force polygons and their equations with the numbers in, and the answers in a box.

Every drawing is printed at the scales it states (:mod:`graphkin.handout.scaled`): the free bodies at one force
scale, the polygons at one force scale. The kinematics loop by loop, the matrix [A]{x} = {b} and every step of
the construction with its own figure are the full walk-through's (``detail="full"``,
:mod:`graphkin.handout.sections` and :mod:`graphkin.handout.solution`).
"""

from __future__ import annotations

import numpy as np

from graphkin.handout import maths as M
from graphkin.handout import motion as polygons
from graphkin.handout import scaled
from graphkin.handout.document import Doc, Subject
from graphkin.handout.sections import link_table, loads
from graphkin.model import Revolute


def solution(doc: Doc, s: Subject, entry: dict, c, i: int):
    """A position's compact solution (its heading is the caller's)."""
    motion(doc, s, entry)
    polygons.key(doc, s, i)
    if not s.static:
        inertia(doc, s, entry)
    loads(doc, s, entry)
    if c is None or not c.valid:
        doc.text(f"The construction cannot be drawn here: {c.reason if c is not None else 'no solution'}.")
    else:
        graphical(doc, s, entry, c, i)
    crank_pin(doc, s, entry, i)
    answers(doc, s, entry)


def motion(doc: Doc, s: Subject, entry: dict):
    doc.heading(2, "Position" if s.static else "Motion")
    if not s.static:
        doc.text("Each link's angle, angular velocity and angular acceleration, and the acceleration of its centre of "
                 "mass, from the position, velocity and acceleration loops:")
    link_table(doc, entry, s.static)


def inertia(doc: Doc, s: Subject, entry: dict):
    doc.heading(2, "Inertia loads")
    lines, still = [], []
    for link, d in entry["links"].items():
        body = s.mech.link(int(link))
        if body.mass == 0:
            still.append(link)
            continue
        F, T, h = d["inertia_force"], d["inertia_torque"], d["h"]
        if not any(F) and not T:
            still.append(link)
            continue
        Fi, Ti = M.sym("F", f"{link}i"), M.sym("T", f"{link}i")
        lines.append(M.row(Fi, M.op("="), M.op("−"), M.sym("m", link), M.sym("a", f"G{link}"), M.op("="),
                           M.op("−"), M.paren(M.qty(body.mass, "kg")), M.paren(M.polar(M.size_of(d["a_G"]),
                                                                                     M.angle_of(d["a_G"]), "m/s²")),
                           M.op("="), M.polar(M.size_of(F), M.angle_of(F), "N")))
        lines.append(M.row(Ti, M.op("="), M.op("−"), M.sym("I", f"G{link}"), M.sym("α", link), M.op("="), M.op("−"),
                           M.paren(M.qty(body.I_G, "kg·m²")), M.paren(M.qty(d["alpha"], "rad/s²")), M.op("="),
                           M.qty(T, "N·m"), M.t(" (CCW)" if T > 0 else " (CW)" if T < 0 else "")))
        if h is not None:
            lines.append(M.row(M.sym("h", link), M.op("="), M.frac(M.absval(Ti), M.absval(Fi)), M.op("="),
                               M.frac(M.qty(abs(T), "N·m"), M.qty(M.size_of(F), "N")), M.op("="),
                               M.qty(h * 1e3, "mm")))
    if lines:
        doc.text("d'Alembert: on each link the inertia force ", M.row(M.op("−"), M.i("m"), M.sym("a", "G")),
                 " at G and the inertia torque ", M.row(M.op("−"), M.sym("I", "G"), M.i("α")), " combine into one "
                 "force of the same size, on a line offset from G by ",
                 M.row(M.i("h"), M.op("="), M.frac(M.absval(M.i("T")), M.absval(M.i("F")))),
                 " to the side that reproduces the torque's sense:")
        doc.equation(*lines)
    if still:
        doc.text(f"Link{'s' if len(still) > 1 else ''} {', '.join(still)}: no inertia loads here (massless, or ",
                 M.row(M.sym("a", "G"), M.op("="), M.n(0)), " and ", M.row(M.i("α"), M.op("="), M.n(0)), ").")


def worked_steps(c):
    """The steps a compact key draws a polygon for: each link's polygon, each sum of a superposition and the
    whole problem's input link. A sub-problem's input link is the whole problem's with another load, and
    the whole problem's polygon of it gives the effort."""
    out = []
    for step in c.steps:
        if not step.polygon:
            continue
        if step.kind == "driver" and getattr(step, "sub", ""):
            continue
        out.append(step)
    return out


def _result(step) -> list:
    """What a polygon finds, as ``F43 = 7.559 N ∠ 180°, …``."""
    items = []
    for a in step.polygon:
        if a.known:
            continue
        name = a.name[1:] if a.name[:1] in "−-" else a.name
        v = -np.asarray(a.vector, float) if a.name[:1] in "−-" else np.asarray(a.vector, float)
        if items:
            items += [M.op(","), M.SP]
        items += [M.name(name), M.op("="), M.polar(M.size_of(v), M.angle_of(v), "N")]
    return items


def graphical(doc: Doc, s: Subject, entry: dict, c, i: int):
    links = list(s.mech.moving)
    k_fb, X_fb = scaled.free_body_scales(c, links)
    doc.heading(2, "Free bodies")
    doc.figure([scaled.free_bodies(s, c, i, links, k_fb, X_fb)],
                       "Every force on each moving link" + ("" if s.static else
                                                            ", the inertia resultant on its offset line") + ". "
                       + scaled.statement(k_fb, X_fb))
    concurrent = [st for st in c.steps if st.kind in ("three-force", "line", "couple") and st.lines]
    if concurrent:
        k = scaled.construction_scale(c, concurrent)
        doc.heading(2, "Lines of action")
        titles = _construction_titles(concurrent) if len(concurrent) > 1 else None
        doc.figure([scaled.constructions(s, c, i, concurrent, k, titles)],
                   "The lines of action of each three-force member, and where they meet. " + scaled.statement(k))
        for st in concurrent:
            # A caption that names its sub-problem and link ("In sub-problem I, link 3 is …") needs no title.
            named = not titles or f"link {st.link}" in st.caption[:40].lower()
            doc.text(*M.prose(st.caption if named else f"{titles[concurrent.index(st)]}: {st.caption}"))
    steps = worked_steps(c)
    sums = [scaled.resultant_step(c, st) for st in c.steps if st.kind == "resultant" and not getattr(st, "sub", "")]
    sums = [st for st in sums if st is not None]
    drawn = sums + steps
    if not drawn:
        return
    X = scaled.polygon_scale(drawn)
    doc.heading(2, "Force polygons")
    for st in sums:
        R = -np.asarray(st.polygon[-1].vector, float)
        name = st.polygon[-1].name[1:]
        doc.equation(M.row(M.vec(M.name(name)), M.op("="),
                           *[x for k, a in enumerate(st.polygon[:-1]) for x in ([M.op("+")] if k else []) +
                             [M.vec(M.name(a.name))]],
                           M.op("="), M.polar(M.size_of(R), M.angle_of(R), "N")))
    labels = []
    # As many figures as it takes for each to fit a page (the shaper's thirteen polygons take two).
    for n, group in enumerate(scaled.polygon_groups(drawn, X, [_polygon_title(st) for st in drawn])):
        titles = [_polygon_title(st) for st in group]
        key = f"polygons-{i}" + (f"-{n + 1}" if n else "")
        labels.append(doc.figure([scaled.polygons(s, key, group, X, c.driver_name, titles)],
                                 ("The force polygons, tip to tail, each closing on its link's equilibrium. " if not n
                                  else "The force polygons, continued. ") + scaled.statement(None, X)))
    label = labels[0] if len(labels) == 1 else f"Figures {labels[0].split()[-1]}–{labels[-1].split()[-1]}"
    doc.text(f"{label}, polygon by polygon:")
    lines = []
    for st in steps:
        line = [polygon_equation(st)]
        found = _result(st)
        if found:
            line += [M.SP, M.op("⇒"), M.SP, *found]
        lines.append(M.row(*line))
    doc.equation(*lines)
    d = next((st for st in c.steps if st.kind == "driver" and not getattr(st, "sub", "")), None)
    if d is not None and s.crank and "d" in d.values:
        R = next(a for a in d.polygon if a.known)
        T = c.effort
        doc.equation(M.row(M.name(c.driver_name), M.op("="), M.op("±"), M.absval(M.name(R.name)), M.i("d"),
                           M.op("="), M.qty(M.size_of(R.vector), "N"), M.op("·"), M.qty(d.values["d"] * 1e3, "mm"),
                           M.op("="), M.qty(T, "N·m"), M.t(" (CCW)" if T > 0 else " (CW)" if T < 0 else "")))
        doc.text(f"The pivot force and {R.name} form a couple of arm d; the driving torque balances it, "
                 "in the opposite sense.")


def _construction_title(step) -> str:
    sub = getattr(step, "sub", "")
    return (f"Sub-problem {sub}, link {step.link}" if sub else f"Link {step.link}")


_DRAWS = {"three-force": "three forces meet", "line": "line of", "couple": "couple, line of"}
"""What a panel of the lines of action draws, where its link alone does not tell two panels apart."""


def _construction_titles(steps) -> list[str]:
    """A title for each panel of the lines of action, each its own: ``Link 3``, or where two panels are of one
    link (a gear's tooth force and its couple) what each draws: ``Link 3: line of F23``."""
    plain = [_construction_title(st) for st in steps]
    return [t if plain.count(t) == 1 else
            f"{t}: {_DRAWS[st.kind]}" + ("" if st.kind == "three-force" else " " + ", ".join(ln.name for ln in st.lines))
            for t, st in zip(plain, steps)]


def _polygon_title(step) -> str:
    """A polygon's title over its drawing, as plain names (the drawing subscripts them)."""
    if step.kind == "superpose":
        total = step.polygon[-1].name.lstrip("−-")
        return f"{total} = " + " + ".join(a.name for a in step.polygon[:-1])
    if step.kind == "polygon" and step.caption.startswith("R") and step.link is not None and not step.sub \
            and step.polygon[-1].name.startswith("−R"):
        return step.caption  # a resultant's sum: "R3 = R3i + Fc3"
    head = f"Link {step.link}" + (f" ({step.sub})" if getattr(step, "sub", "") else "")
    out = ""
    for k, a in enumerate(step.polygon):
        neg = a.name[:1] in "−-"
        out += (" − " if neg else " + " if k else "") + (a.name[1:] if neg else a.name)
    return f"{head}: " + out.strip() + " = 0"


def polygon_equation(step) -> list:
    """A polygon's vector equation: ``R3 + F43′ + F23′ = 0``; a reversed force is subtracted (``− F23``)."""
    items = []
    for k, a in enumerate(step.polygon):
        neg = a.name[:1] in "−-"
        if neg:
            items.append(M.op("−"))
        elif k:
            items.append(M.op("+"))
        items.append(M.vec(M.name(a.name[1:] if neg else a.name)))
    return M.row(*items, M.op("="), M.n("0"))


def crank_pin(doc: Doc, s: Subject, entry: dict, i: int):
    """The force of the coupler (or connecting rod) on the crank pin, along the crank and across it.

    Books on engines ask for these: the thrust on the crank-shaft bearing F_B (along the crank, towards
    the shaft) and the tangential force F_T that turns the crank, T = r F_T (Khurmi and Gupta, §15.10).
    """
    d = s.mech.driver
    if not d.crank:
        return
    pivot = s.mech.joint_between(s.mech.frame, d.link)
    pins = [j for j in s.mech.joints_of(d.link) if isinstance(j, Revolute) and s.mech.frame not in j.links]
    if pivot is None or len(pins) != 1:
        return
    pin = pins[0]
    other = (set(pin.links) - {d.link}).pop()
    kin = s.result.kinematics
    O = kin.position(d.link, pivot.point)[i]
    P = kin.position(d.link, pin.point)[i]
    r = float(np.hypot(*(P - O)))
    if r <= 0:
        return
    u = (P - O) / r
    name = s.result.name_of(other, d.link)
    F = np.asarray(entry["forces"][name], float)
    F_B = float(-F @ u)
    F_T = float(F @ np.array([-u[1], u[0]]))
    doc.heading(2, "At the crank pin")
    doc.text(f"The force {name} of link {other} on the crank, resolved along the crank {pivot.point}{pin.point} "
             f"(unit vector u) and across it (k × u, the sense of positive θ):")
    doc.equation(
        M.row(M.sym("F", "B"), M.op("="), M.op("−"), M.vec(M.name(name)), M.op("·"), M.i("u"), M.op("="),
              s.qty(F_B, "force"), M.t(" (towards the shaft: a thrust on its bearing)" if F_B > 0 else
                                   " (away from the shaft: a pull on its bearing)" if F_B < 0 else "")),
        M.row(M.sym("F", "T"), M.op("="), M.vec(M.name(name)), M.op("·"), M.paren(M.i("k"), M.op("×"), M.i("u")),
              M.op("="), s.qty(F_T, "force"), M.op(";"), M.SP, M.i("T"), M.op("="), M.i("r"), M.sym("F", "T"),
              M.op("="), M.paren(s.qty(r, "length")), M.paren(s.qty(F_T, "force")), M.op("="),
              s.qty(r * F_T, "torque")))


def answers(doc: Doc, s: Subject, entry: dict):
    r = s.result
    rows = []
    for a, b in r.forces:
        name = r.name_of(a, b)
        F = entry["forces"][name]
        rows.append([M.name(name), s.pair(F), s.polar(F)])
    d = entry["driver"]
    if s.crank:
        sense = " CCW" if d["value"] > 0 else " CW" if d["value"] < 0 else ""
        rows.append([M.name(d["name"]), "", (s.qty(d["value"], "torque"), sense)])
    else:
        rows.append([M.name(d["name"]), s.pair(d["vector"]), (s.qty(d["value"], "force"), " along the guide")])
    doc.heading(2, "Answers")
    doc.table(["", "x, y", "polar"], rows, "lrr", caption="Both routes give these: the graphical one reads "
              "the polygons, the analytical one solves the equilibrium equations of every link.", boxed=True)
