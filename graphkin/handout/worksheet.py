"""A worksheet a student can work: the position and every given stated, the mechanism at a stated scale with
room to draw the lines of action, the free bodies with their known loads, a box per force polygon that holds
it at the stated scale, what to find, and room for the answers.

Two worksheets of a problem: the one that gives each link's motion and inertia loads and asks for the forces
(:func:`worksheet`, issue 24), and the one that starts from the input motion (:func:`worksheet`,
``from_motion=True``): the positions, the input's ω and α (or a driving slider's v and a), the mass properties
and the external loads are given; the velocity and acceleration polygons, each link's ω, α, a_G and inertia
loads, then the force polygons are the student's to construct, and no number they construct is printed.

The scales are :func:`graphkin.graphical.paper.sheet_scales`'s, the ones the grader allows a reading error at
(:data:`graphkin.graphical.paper.READING` on paper), so the sheet and the grading agree.
"""

from __future__ import annotations

import math

from graphkin.exercises.exercise import MOTION_KINDS
from graphkin.exercises.quantities import equilibrium_steps
from graphkin.graphical.paper import POLYGON_ROOM, READING, force_text, length_text, sheet_reach, sheet_scales
from graphkin.handout import maths as M
from graphkin.handout import motion as polygons
from graphkin.handout import scaled
from graphkin.handout.compact import polygon_equation, worked_steps
from graphkin.handout.document import Doc, Subject
from graphkin.handout.sections import loads

BOX = (POLYGON_ROOM[0] + 14.0, POLYGON_ROOM[1] + 16.0)
"""A polygon's box [mm]: the room every polygon fits at the sheet's force scale, and a margin for its labels.
All boxes are the same size: a box as large as its own polygon would tell the answer's size."""


def motion_only(s: Subject) -> bool:
    """Whether the sheet is an exercise on the velocity and acceleration polygons alone: the motion is then the
    student's to find, not given, and there are no force polygons to draw."""
    v = s.variant
    return v is not None and bool(v.exercise.questions) and all(q.kind in MOTION_KINDS for q in v.exercise.questions)


def givens(doc: Doc, s: Subject, entry: dict, *, from_motion: bool = False):
    """Everything the position gives: each link's motion and inertia loads (``from_motion``: the positions and the
    input's motion only), and the loads acting here."""
    doc.heading(2, "Given at this position")
    if from_motion:
        doc.table(["link", "θ [°]"], [[f"link {link}", M.n(M.fmt_fixed(math.degrees(d["theta"])))]
                                      for link, d in entry["links"].items()], "lr",
                  caption="Each link's angle here; the input's motion is in the data above")
    elif s.static or motion_only(s):
        # The polygons' exercise asks for ω, α and a_G: only the positions are given.
        doc.table(["link", "θ [°]"], [[f"link {link}", M.n(M.fmt_fixed(math.degrees(d["theta"])))]
                                      for link, d in entry["links"].items()], "lr")
    else:
        rows = []
        for link, d in entry["links"].items():
            a, F, T, h = d["a_G"], d["inertia_force"], d["inertia_torque"], d["h"]
            massless = s.mech.link(int(link)).mass == 0
            rows.append([f"link {link}", M.n(M.fmt_fixed(math.degrees(d["theta"]))), M.n(d["omega"]), M.n(d["alpha"]),
                         M.polar(M.size_of(a), M.angle_of(a), ""),
                         "—" if massless else M.polar(M.size_of(F), M.angle_of(F), "N"),
                         "—" if massless else M.qty(T, "N·m"),
                         "—" if h is None else M.qty(h * 1e3, "mm")])
        doc.table(["link", "θ [°]", "ω [rad/s]", "α [rad/s²]", (M.sym("a", "G"), " [m/s²]"),
                   ("inertia force ", M.row(M.op("−"), M.i("m"), M.sym("a", "G"))),
                   ("inertia torque ", M.row(M.op("−"), M.sym("I", "G"), M.i("α"))), ("offset ", M.i("h"))],
                  rows, "lrrrrrrr", caption="The inertia force and torque of a link combine into one force of the "
                  "same size on a line offset from G by h = |T|/|F|, to the side that reproduces the torque's sense")
    loads(doc, s, entry, always=True)


def worksheet(doc: Doc, s: Subject, entry: dict, c, i: int, *, find=True, from_motion=False):
    """A position's worksheet (its heading is the caller's); ``from_motion``: the one that starts from the input
    motion (the module's docstring)."""
    givens(doc, s, entry, from_motion=from_motion)
    if c is None or not c.valid:
        return
    scales = sheet_scales(c)
    k = scales.length
    doc.heading(2, "The mechanism")
    doc.figure([scaled.mechanism(s, c, i, k, room=True, key="sheet-mechanism")],
               f"The mechanism at {s.where(i)}, with room around it to draw the lines of action and find where they "
               f"meet. Scale {length_text(k)}: measure a length and multiply it by {M.fmt(k)}.")
    if not motion_only(s):
        where_to_draw(doc, s, c, k, offsets=not from_motion)
    if motion_only(s):
        polygons.boxes(doc, s, i)
        if find:
            answer_room(doc, s)
        return
    if from_motion:
        polygons.boxes(doc, s, i)
        motion_room(doc, s, entry)
    links = list(s.mech.moving)
    if from_motion:
        caption = ("The free bodies with the external loads only. Draw each inertia resultant from your table, on its "
                   "line at h from G: here, or on the mechanism's drawing, which has room for a line far from its "
                   "link. The joint forces are yours to find. ")
    else:
        caption = ("The free bodies with the loads known before the construction ("
                   + ("" if s.static else "the inertia resultant on its line, ") + "external loads); the joint forces "
                   "are yours to find. ")
    # At the scales that hold every force the free bodies carry once the student has drawn the inertia resultants.
    scaled.free_body_figures(doc, s, c, i, links, caption.rstrip(), unknowns=False, inertia=not from_motion)
    X = scales.polygon
    doc.heading(2, "Force polygons")
    doc.text(f"Draw each polygon tip to tail at {force_text(X)}, each in its box (it fits at that scale), and "
             f"measure the sides you find: a reading to ±{READING:g} mm is ±{M.fmt(READING * X)} N.")
    sums = [scaled.resultant_step(c, st) for st in c.steps if st.kind == "resultant" and not getattr(st, "sub", "")]
    steps = [st for st in sums if st is not None] + worked_steps(c)
    steps, aside, limit = scaled.set_aside(steps)
    if aside:
        doc.text(*scaled.set_aside_text(aside, limit, X, polygon_equation))
    for n, st in enumerate(steps, start=1):
        label = f"Polygon {n}" + (f", link {st.link}" if st.link is not None else "") + \
            (f" (sub-problem {st.sub})" if getattr(st, "sub", "") else "") + f", at {force_text(X)}: "
        doc.space(BOX[1], label, polygon_equation(st), width=BOX[0])
    if asks_analytical(s, from_motion):
        analytical_room(doc, s)
    if find:
        answer_room(doc, s, both=asks_analytical(s, from_motion))


def asks_analytical(s: Subject, from_motion: bool = False) -> bool:
    """Whether the sheet asks for the analytical route too: a problem's does ("both analytically and graphically"),
    unless it starts from the input motion (graphically only); an exercise's where its text asks for it."""
    if s.variant is not None:
        return "analytic" in s.variant.sheet()["intro"].lower()
    return not from_motion


def analytical_room(doc: Doc, s: Subject):
    """Room for the analytical route, numbered as the key numbers it: each group's equilibrium equations, a link's
    ΣFx = 0, ΣFy = 0 and ΣM_G = 0 each, from the last group located to the driver."""
    loads = "its external loads" + ("" if s.static else " and its inertia loads (given above)")
    doc.heading(2, "The analytical part")
    doc.text(f"Each moving link is in equilibrium under the joint forces, {loads}: write ΣFx = 0, ΣFy = 0 and ΣM "
             "about its centre of mass G = 0 for each link, group by group as numbered (step 1, the inertia loads, "
             "is given above), and solve each group for its unknowns.")
    for n, g in equilibrium_steps(s.mech):
        links = ", ".join(str(link) for link in g.links)
        doc.space(ANALYTICAL_ROOM * len(g.links) + 12.0, f"Step {n}. The equilibrium of {g.label} "
                  f"(link{'s' if len(g.links) > 1 else ''} {links}):")


ANALYTICAL_ROOM = 24.0
"""Room for one link's three equations with the numbers in, and what they give [mm]."""


def where_to_draw(doc: Doc, s: Subject, c, k: float, *, offsets=True):
    """Where the lines of action go on the sheet's drawing at 1:k: each inertia resultant's offset from G on the
    paper, and each step drawn another way because a point of it lies off the drawing (:mod:`graphkin.graphical.reach`).
    ``offsets=False``: the inertia resultants are the student's to find, and so are their offsets."""
    r = sheet_reach(c)
    items = []
    if offsets:
        for link, d in c.inertia.items():
            if d.get("h") and math.hypot(*d["F"]) > 0:
                h = float(d["h"]) * 1e3
                line = f"R{link}i"
                drawn = any(m.what == f"{line}'s line" for m in r.marks)
                instead = next((x.name for x in r.detours if x.kind == "offset" and line in x.parts), None)
                tail = (".",) if drawn else (": not needed, ", M.name(instead), "'s line is drawn directly (below).") \
                    if instead else (", beyond the drawing: the steps that use it are drawn another way (below).",)
                items.append((M.name(line), f"'s line: {scaled.mm(h / k)} from G{link} on the drawing "
                              f"(h = {scaled.mm(h)})", *tail))
    for d in r.detours:
        items.append(scaled.detour_text(d, k, offsets))
    if items:
        doc.text("Where the lines go on this drawing" + (" (a point of the construction that lies off the page is "
                 "reached another way, as said):" if r.detours else ":"))
        doc.items(items, small=True)


def motion_room(doc: Doc, s: Subject, entry: dict):
    """A table with an empty cell for each link's ω, α, a_G and inertia loads, read off the student's polygons; a
    driving crank's ω and α are given, and stated in its row."""
    d = s.mech.driver
    rows = []
    for link in s.mech.moving:
        massless = s.mech.link(link).mass == 0
        given = entry["links"][str(link)] if d.crank and link == d.link else None
        rows.append([f"link {link}", M.n(given["omega"]) if given else "", M.n(given["alpha"]) if given else "", "",
                     *(["—"] * 3 if massless else ["", "", ""])])
    doc.heading(2, "Read off your polygons")
    doc.table(["link", "ω [rad/s]", "α [rad/s²]", (M.sym("a", "G"), " [m/s²] ∠"),
               (M.row(M.op("−"), M.i("m"), M.sym("a", "G")), " [N] ∠"),
               (M.row(M.op("−"), M.sym("I", "G"), M.i("α")), " [N·m]"), (M.i("h"), " [mm]")],
              rows, "lllllll", boxed=True, tall=True, wide=True,
              caption="A link's ω is a relative velocity over the length it turns about, its α the tangential "
                      "acceleration over that length (positive counter-clockwise); the acceleration of G runs from o′ "
                      "to its image g′. Then the inertia force is −m times it, the inertia torque −α times the moment "
                      "of inertia about G, and h = |T|/|F|, to the side that reproduces the torque's sense")


def answer_room(doc: Doc, s: Subject, both: bool = False):
    """What to find, with an empty cell for each answer (``both``: the sheet asks for the analytical route too)."""
    r = s.result
    rows = [[M.name(r.name_of(a, b)), "", ""] for a, b in r.forces]
    d = s.mech.driver
    rows.append([M.name(d.symbol), "", "(CCW or CW)" if d.crank else "(along the guide)"])
    doc.heading(2, "Answers")
    doc.table(["find", "magnitude", "direction [°] or sense"], rows, "lll",
              caption="Every joint force (magnitude and direction) and the driving "
                      + ("torque" if d.crank else "force") + ", read off your polygons"
                      + (" and found again by your equations: the two routes agree" if both else ""),
              boxed=True, tall=True)
