"""The key as a textbook prints a solution, both ways: the motion; the analytical route (the inertia loads, then
each link's equilibrium equations with the numbers in, group by group, :mod:`graphkin.handout.equilibrium`); the
graphical route (the free bodies, the lines of action, the force polygons and every step of the construction,
numbered as an exercise's feedback names them); and the answers, after the work that finds them.

Every drawing is printed at the scales it states (:mod:`graphkin.handout.scaled`): the free bodies at one force
scale, the polygons at one force scale. The kinematics loop by loop, the matrix [A]{x} = {b} and every step of
the construction with its own figure are the full walk-through's (``detail="full"``,
:mod:`graphkin.handout.sections` and :mod:`graphkin.handout.solution`).
"""

from __future__ import annotations

import numpy as np

from graphkin.exercises.exercise import MOTION_KINDS
from graphkin.exercises.quantities import equilibrium_steps
from graphkin.graphical.paper import length_text, sheet_reach, sheet_scales
from graphkin.handout import book, equilibrium, scaled
from graphkin.handout import maths as M
from graphkin.handout import motion as polygons
from graphkin.handout.document import Doc, Subject
from graphkin.handout.sections import link_table, loads


def solution(doc: Doc, s: Subject, entry: dict, c, i: int):
    """A position's compact solution (its heading is the caller's): the motion, the analytical route step by step,
    the graphical route step by step, and the answers after the work that finds them."""
    motion(doc, s, entry)
    polygons.key(doc, s, i, steps=_motion_asked(s), explain=False)
    loads(doc, s, entry)
    drawn = c is not None and c.valid
    bodies = []
    equilibrium.analytical(doc, s, entry, i, inertia=None if s.static else lambda: inertia(doc, s, entry),
                           free_bodies=(lambda: bodies.append(free_bodies(doc, s, c, i))) if drawn else None)
    book.asked(doc, s, entry, i)
    if not drawn:
        doc.text(f"The construction cannot be drawn here: {c.reason if c is not None else 'no solution'}.")
    else:
        graphical(doc, s, entry, c, i, bodies[0] if bodies else None)
    answers(doc, s, entry, c)


def _motion_asked(s: Subject) -> bool:
    """Whether an exercise asks for what the velocity and acceleration polygons find: its key numbers their
    steps, which the feedback names."""
    return s.variant is not None and any(q.kind in MOTION_KINDS for q in s.variant.exercise.questions)


def motion(doc: Doc, s: Subject, entry: dict):
    doc.text("Each link's position θ, from the position loops:" if s.static else
             "The motion: each link's θ, ω and α, and the acceleration of its centre of mass, from the position, "
             "velocity and acceleration loops:")
    link_table(doc, entry, s.static)


def inertia(doc: Doc, s: Subject, entry: dict):
    """Each link's inertia force and torque with the numbers in (the offset h of their resultant is the
    construction's: its step that draws the resultant gives it)."""
    lines, still = [], []
    for link, d in entry["links"].items():
        body = s.mech.link(int(link))
        if body.mass == 0:
            still.append(link)
            continue
        F, T = d["inertia_force"], d["inertia_torque"]
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
    if lines:
        doc.text("Each link's inertia force ", M.row(M.op("−"), M.i("m"), M.sym("a", "G")), ", at G, and inertia torque ",
                 M.row(M.op("−"), M.sym("I", "G"), M.i("α")), ":")
        doc.equation(*lines, stacked=True)
    # A massless link needs no word: the mass properties say so. One that moves without accelerating does.
    still = [link for link in still if s.mech.link(int(link)).mass > 0]
    if still:
        doc.text(f"Link{'s' if len(still) > 1 else ''} {', '.join(still)}: no inertia loads here (",
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


def free_bodies(doc: Doc, s: Subject, c, i: int) -> str:
    """The free bodies, which both routes start from: the analytical one writes their equations, the graphical one
    draws their lines of action and polygons. Returns the figure's label."""
    return scaled.free_body_figures(doc, s, c, i, list(s.mech.moving), "Every force on each moving link" + (
        "" if s.static else ", the inertia resultant on its offset line") + ".")


def graphical(doc: Doc, s: Subject, entry: dict, c, i: int, bodies: str | None = None):
    """The graphical route from the free bodies (``bodies``, their figure's label): the lines of action, the
    force polygons, and every step of the construction numbered as the feedback names them, with what it finds."""
    doc.heading(2, "The graphical construction")
    first, at = doc.figures + 1, len(doc.blocks)
    # How each resultant's line is found, then each three-force member's lines, each as far as the page holds it.
    found = scaled.merged([p for p in (scaled.resultant_panel(c, st) for st in c.steps if st.kind == "resultant")
                           if p is not None], 2)
    concurrent = [scaled.drawable(c, st) for st in c.steps if st.kind in ("three-force", "line", "couple") and st.lines]
    k = None
    if found or concurrent:
        panels = found + concurrent
        k = scaled.construction_scale(c, panels)
        titles = _construction_titles(panels) if len(panels) > 1 else None
        doc.figure([scaled.constructions(s, c, i, panels, k, titles)],
                   ("How each resultant's line is found: the lines of its parts meet at K, which it passes through. "
                    if found else "") + "The lines of action of each three-force member, and where they meet. "
                   + scaled.statement(k))
    steps = worked_steps(c)
    sums = [scaled.resultant_step(c, st) for st in c.steps if st.kind == "resultant" and not getattr(st, "sub", "")]
    drawn = [st for st in sums if st is not None] + steps
    drawn, aside, limit = scaled.set_aside(drawn)
    if drawn:
        X = scaled.polygon_scale(drawn)
        if aside:
            doc.text(*scaled.set_aside_text(aside, limit, X, polygon_equation))
        # As many figures as it takes for each to fit a page (the shaper's thirteen polygons take two).
        groups = scaled.polygon_groups(drawn, X, [_polygon_title(st) for st in drawn])
        for n, group in enumerate(groups):
            titles = [_polygon_title(st) for st in group]
            key = f"polygons-{i}" + (f"-{n + 1}" if n else "")
            # The last polygons stand in the text, just before the answers they find (a float would go below them).
            doc.figure([scaled.polygons(s, key, group, X, c.driver_name, titles)],
                       ("The force polygons, tip to tail, each closing on its link's equilibrium. " if not n
                        else "The force polygons, continued. ") + scaled.statement(None, X), inline=n == len(groups) - 1)
    # The steps in words before the figures that draw them (which float to the tops and feet of pages).
    items = []
    for n, st in enumerate(c.steps, 1):
        found = _result(st) if st.polygon else []
        items.append((f"Step {n}. ", *M.prose(st.caption), *([" ⇒ ", M.row(*found)] if found else [])))
    figures = f"Figure {first}" if doc.figures == first else f"Figures {first}–{doc.figures}"
    figures = f"{bodies}'s free bodies, then {figures}" if bodies else figures
    blocks, doc.blocks[at:] = doc.blocks[at:], []
    doc.text(f"The construction, step by step ({figures} draw it):")
    doc.items(items, small=True)
    detours = sheet_reach(c).detours
    if detours:
        k = k or sheet_scales(c).length
        doc.text(f"Drawn another way, where a point lies off the page (lengths on the drawing at {length_text(k)}):")
        doc.items([scaled.detour_text(d, k, True) for d in detours], small=True)
    doc.blocks += blocks


def _construction_title(step) -> str:
    sub = getattr(step, "sub", "")
    if step.kind == "resultant":
        return step.caption
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


def answers(doc: Doc, s: Subject, entry: dict, c=None):
    """The answers, after every drawing that finds them (the polygons float), with the steps that give them."""
    r = s.result
    cells = []
    for a, b in r.forces:
        name = r.name_of(a, b)
        F = entry["forces"][name]
        cells.append([M.name(name), s.pair(F), s.polar(F)])
    d = entry["driver"]
    if s.crank:
        sense = " CCW" if d["value"] > 0 else " CW" if d["value"] < 0 else ""
        cells.append([M.name(d["name"]), "", (s.qty(d["value"], "torque"), sense)])
    else:
        cells.append([M.name(d["name"]), s.pair(d["vector"]), (s.qty(d["value"], "force"), " along the guide")])
    # Two answers a row: half the height of a table of one a row.
    half = (len(cells) + 1) // 2
    rows = [cells[k] + (cells[k + half] if k + half < len(cells) else ["", "", ""]) for k in range(half)]
    doc.flush()
    doc.heading(2, "Answers")
    last = equilibrium_steps(s.mech)[-1][0]
    how = f"the analytical solution's steps 2–{last} solve for them" if last > 2 else \
        "the analytical solution's step 2 solves for them"
    if c is not None and c.valid:
        how += f"; the construction's steps 1–{len(c.steps)} draw them, to the same digits"
    doc.table(["", "x, y", "polar"] * 2, rows, "lrrlrr", caption=f"Both routes give these: {how}.", boxed=True)
