"""The sections that solve: the matrix [A]{x} = {b} and its solution, the graphical route step by step with
its sub-problems, the table of both routes, the blank worksheet's room to draw, and a whole cycle."""

from __future__ import annotations

import math

import numpy as np

from graphkin.cycle import sweep
from graphkin.graphical.construction import STEP_TITLES
from graphkin.graphical.paper import FIGURE_WIDTH, force_text, length_text
from graphkin.handout import equilibrium as E
from graphkin.handout import maths as M
from graphkin.handout import scaled
from graphkin.handout.compact import polygon_equation
from graphkin.handout.document import Doc, Subject
from graphkin.notation import unless_rounding
from graphkin.report import cycle_data


def matrix(doc: Doc, s: Subject, entry: dict, i: int):
    system = E.system(s)
    A, b = system.A[i], system.b[i]
    A, b = E.clean(A, np.abs(A).max()), E.clean(b, np.abs(b).max())
    x = system.solve()[i]
    x = E.clean(x, np.abs(x).max(), 1e-9)
    doc.heading(2, "Equilibrium equations: the matrix method")
    F_ext, M_ext = M.sym("F", "ext"), M.sym("M", "ext")
    moved = (M.row(M.op("−"), M.op("Σ"), F_ext, M.op(","), M.op("−"), M.op("Σ"), M_ext) if s.static else
             M.row(M.i("m"), M.sym("a", "G"), M.op("−"), M.op("Σ"), F_ext, M.op(","), M.SP, M.sym("I", "G"),
                   M.i("α"), M.op("−"), M.op("Σ"), M_ext))
    doc.text(f"Three equations per moving link (ΣFx = 0, ΣFy = 0, ΣM about G = 0), links "
             f"{', '.join(map(str, s.mech.moving))} in turn; one column per unknown. Force columns in N, "
             "moment rows in N·m (lever arms in m); {b} holds the known loads moved across (", moved,
             "; static: no inertia terms)." if s.static else ").")
    doc.text("The unknowns: ", *E.definitions(s, system.unknowns))
    cells = [[M.n(v) for v in r] for r in A]
    unknowns = [E.unknown(u) for u in system.unknowns]
    # Each row named by the equation it is (link 3: ΣFx), to the left of the matrix.
    labels = M.mat([[_equation_name(e)] for e in system.equations], "")
    doc.equation(M.row(labels, M.mat(cells), M.column(unknowns), M.op("="), M.column([M.n(v) for v in b])),
                 small=True)
    doc.text("Solved:")
    rows = []
    for u, value in zip(system.unknowns, x):
        rows.append([E.unknown(u), M.qty(value, E.unit_of(u))])
    doc.table(["unknown", "value"], rows, "lr")


def _equation_name(equation: str) -> list:
    """A row's name as the matrix prints it beside the row: ``"link 3: ΣM_G"`` → link 3 ΣM_G, G a subscript."""
    link, _, what = equation.partition(": ")
    base, _, subscript = what.partition("_")
    if not subscript:
        return M.row(M.t(f"{link} {base}"))
    return M.row(M.t(f"{link} "), M.op(base[:1]), M.sym(base[1:], subscript)) if base[:1] == "Σ" else \
        M.row(M.t(f"{link} "), M.sym(base, subscript))


def forces(doc: Doc, s: Subject, entry: dict):
    doc.heading(2, "Joint forces")
    r = s.result
    rows = []
    for a, b in r.forces:
        name, back = r.name_of(a, b), r.name_of(b, a)
        F = entry["forces"][name]
        rows.append([M.name(name), s.pair(F), s.polar(F), M.row(M.name(back), M.op("="), M.op("−"), M.name(name))])
    doc.table(["force", "x, y", "polar", ""], rows, "lrrl")
    d = entry["driver"]
    if s.crank:
        sense = " (CCW)" if d["value"] > 0 else " (CW)" if d["value"] < 0 else ""
        doc.text("The driving torque: ", M.row(M.name(d["name"]), M.op("="), s.qty(d["value"], "torque")), sense + ".")
    else:
        doc.text("The driving force: ", M.row(M.name(d["name"]), M.op("="), s.polar(d["vector"])),
                 ", that is ", s.qty(d["value"], "force"), " along the guide.")
    L = s.units.symbol("length")
    for pname, p in entry["prismatic"].items():
        where = ("—" if p["offset"] is None else
                 f"{M.fmt(s.units.show(p['offset'], 'length'))} {L} from {p['slider_point']} along the guide")
        doc.text(f"Sliding pair {pname}: normal force ", s.qty(p["normal"], "force"), ", friction ",
                 s.qty(p["friction"], "force"), f"; its line acts {where}.")


def graphical(doc: Doc, s: Subject, entry: dict, c, i: int):
    """The graphical route step by step, every figure at the scales it states."""
    g = entry.get("graphical", {})
    doc.heading(2, "The graphical route")
    if c is None or not c.valid:
        doc.text(f"The construction cannot be drawn here: {g.get('reason') or (c.reason if c else '')}.")
        return
    links = list(s.mech.moving)
    doc.text("The free bodies first, every force on each link"
             + ("" if s.static else ", with the inertia resultant on its offset line") + ":")
    scaled.free_body_figures(doc, s, c, i, links, "Free bodies of every moving link, with every force found.")
    drawn = [st for st in c.steps if st.kind not in _TEXT_ONLY and st.kind != "sub-problem"]
    sums = [scaled.resultant_step(c, st) for st in drawn if st.kind == "resultant"]
    X = scaled.polygon_scale(drawn + [st for st in sums if st is not None], _POLYGON_ROOM)
    k = scaled.step_scale(c, [st for st in drawn if _draws_geometry(st, s.mech.driver.link)], X, _STEP_ROOM)
    doc.text(f"Each step below is drawn on the mechanism at {length_text(k)}, its polygon at {force_text(X)}.")
    for n, step in enumerate(c.steps, start=1):
        sub = getattr(step, "sub", "")
        if step.kind == "sub-problem":
            # A book announces each sub-problem before its steps: a heading of its own.
            doc.heading(3, f"Sub-problem {sub}: only the loads on link {step.link}")
            doc.text(f"Step {n}. ", *M.prose(step.caption))
            continue
        if step.kind in _TEXT_ONLY:
            doc.text(f"Step {n}. ", *M.prose(step.caption))
            continue
        where = f"link {step.link}: " if step.link is not None else ""
        title = STEP_TITLES.get(step.kind, step.kind)
        doc.heading(3, f"Step {n}. {where}{title}" + (f" (sub-problem {sub})" if sub else ""))
        geometry = _draws_geometry(step, s.mech.driver.link)
        if step.kind == "resultant":
            total = scaled.resultant_step(c, step)
            if total is not None:
                # The resultant the later steps use, drawn as the sum it is (R3 = R3i + Fc3).
                doc.figure([scaled.step(s, c, i, n, step, k, X, extra=total)],
                           f"{step.caption} {scaled.statement(k, X)}")
                continue
        if geometry:
            doc.figure([scaled.step(s, c, i, n, step, k, X)],
                       f"{step.caption} {scaled.statement(k, X if step.polygon else None)}")
        elif step.polygon:
            doc.figure([scaled.polygons(s, f"polygon-{i}-{n}", [step], X, c.driver_name, [""])],
                       f"{step.caption} {scaled.statement(None, X)}")
        else:
            doc.text(*M.prose(step.caption))
        if step.polygon:
            doc.equation(polygon_equation(step))
    _subproblems(doc, s, entry)
    _both_routes(doc, s, entry)


_STEP_ROOM = (FIGURE_WIDTH, 90.0)
"""Room for the mechanism's panel of a step's figure [mm] (its polygon beside it, or under it if it must)."""
_POLYGON_ROOM = (58.0, 80.0)


_TEXT_ONLY = {"note", "readings"}
"""Steps that say something and draw nothing new: a paragraph each, no figure."""


def _draws_geometry(step, driver: int) -> bool:
    """Whether a step's lines of action are worth a mechanism figure of their own.

    A polygon's lines were drawn at the step that found them (the two- or
    three-force member before it), a sum of sub-problems adds vectors
    already drawn, and a sub-problem's crank is the whole problem's crank
    with another load: their polygons alone say what is new.
    """
    if step.kind in ("polygon", "superpose"):
        return False
    if getattr(step, "sub", "") and step.link == driver and step.kind in ("resultant", "driver"):
        return False
    return True


def _subproblems(doc: Doc, s: Subject, entry: dict):
    """The superposition at a glance: each sub-problem's joint forces and driving effort, and their sum."""
    g = entry.get("graphical") or {}
    subs = g.get("subproblems") or []
    if not subs:
        return
    r = s.result
    names = [r.name_of(a, b) for a, b in r.forces]
    header = ["force"] + [(f"sub-problem {sp['label']}", "\n", f"(link {sp['link']})") for sp in subs] + ["sum"]
    rows = []
    for name in names:
        rows.append([M.name(name)] + [_stacked(sp["forces"][name]) for sp in subs] + [_stacked(g["forces"][name])])
    unit = "N·m" if s.crank else "N"
    d = g["driver"]
    rows.append([M.name(d["name"])] + [M.qty(sp["driver"]["value"], unit) for sp in subs] + [M.qty(d["value"], unit)])
    doc.table(header, rows, "l" + "r" * (len(subs) + 1),
              caption="Superposition: each sub-problem's forces and driving effort, and their sum", small=len(subs) > 2)


def _stacked(F) -> tuple:
    """A force in a narrow cell: its magnitude over its direction (a table of many columns stays in the page)."""
    return (M.qty(M.size_of(F), "N"), "\n", M.row(M.op("∠"), M.n(M.fmt_fixed(M.angle_of(F))), M.op("°")))


def _reldiff(d: float):
    if not math.isfinite(d):
        return "—"
    return M.n(0.0) if d == 0 else M.n(d, 2)


def _both_routes(doc: Doc, s: Subject, entry: dict):
    g = entry["graphical"]
    doc.heading(2, "Both routes")
    rows = []
    for name, rel in g["relative_difference"].items():
        if name == g["driver"]["name"]:
            kind = "torque" if s.crank else "force"
            rows.append([M.name(name), s.qty(entry["driver"]["value"], kind), s.qty(g["driver"]["value"], kind),
                         _reldiff(rel)])
        else:
            A, G = entry["forces"][name], g["forces"][name]
            rows.append([M.name(name), s.polar(A), s.polar(G), _reldiff(rel)])
    doc.table(["force", "analytical", "graphical", "relative difference"], rows, "lrrr",
              caption="The graphical magnitudes are read off exactly (the closing side computed, not measured), "
                      "so the two routes agree to rounding.")
    for w in g["warnings"]:
        doc.text(f"Warning: {w}")


# -- a whole cycle ------------------------------------------------------------------------------------
_PLOT = (160.0, 90.0)
"""Printed size of the torque curve [mm]: drawn at it, so its labels print at their own sizes."""
_SMALL_PLOT = (130.0, 72.0)
"""Printed size of the energy and joint-force index plots [mm]."""


def cycle(doc: Doc, s: Subject):
    from graphkin import draw
    from graphkin.draw import paper

    cycle = sweep(s.problem, s.cycle_positions)
    Cs = s.Cs if cycle.closed and not s.static else None  # a static analysis has no speed to keep steady
    data = cycle_data(cycle, Cs)
    deg = math.degrees
    doc.heading(1, "Over the whole cycle")
    e = data["effort"]
    doc.text(f"The same solution at every one of the {data['n']} positions (a load that switches on or off is "
             "sampled just before and just after its switching angle).")
    f = cycle.flywheel(Cs) if Cs is not None else None
    label = doc.figure([s.picture("torque-curve", lambda: paper.plotted(
        lambda ax: draw.draw_torque_curve(cycle, flywheel=f, ax=ax), *_PLOT), alt="the driving torque over the cycle",
        natural=True)],
                       "The driving torque over one turn with its average" +
                       (", and its pulses above and below the average with their energies." if f is not None else "."))
    theta = f"θ{s.mech.driver.frame}{s.mech.driver.link}"

    def where(p):
        return "—" if p["at"] is None else f"{theta} = {M.fmt(deg(p['at']), 5)}°"

    doc.table(["", "value", "at"], [
        ["peak", s.qty(e["max"]["value"], "torque"), where(e["max"])],
        ["lowest", s.qty(e["min"]["value"], "torque"), where(e["min"])],
        ["average", s.qty(e["average"], "torque"), ""],
    ], "lrl", caption=f"Driving torque {e['name']} ({label})")
    rows = [[M.name(k), s.qty(v["peak"]["value"], "force"), where(v["peak"])] for k, v in data["forces"].items()]
    doc.table(["joint force", "peak", "at"], rows, "lrl", caption="Peak joint forces over the cycle")
    # An exercise's key answers what its questions ask: the flywheel and the joint-force index only if asked.
    asked = {q.kind for q in s.variant.exercise.questions} if s.variant is not None else None
    fw = data["flywheel"] if asked is None or asked & {"flywheel_E", "flywheel_I"} else None
    if fw is not None:
        doc.heading(2, "Flywheel")
        doc.text("Norton §11.11: the energy of each pulse of ", M.row(M.i("T"), M.op("−"), M.sym("T", "avg")),
                 " between its crossings of the average, accumulated from the first crossing; E is the largest "
                 "swing of the accumulated energy.")
        ends = fw["crossings"][1:] + fw["crossings"][:1]
        # The pulses add up to zero over a turn: the last accumulated energy is 0 but for rounding (5.7e−14 J).
        swing = max([abs(x) for x in fw["areas"]] + [0.0])
        rows = [[str(k + 1), M.n(M.fmt_fixed(deg(a) % 360, 1)), M.n(M.fmt_fixed(deg(b) % 360, 1)), M.n(area),
                 M.n(unless_rounding(acc, swing))]
                for k, (a, b, area, acc) in enumerate(zip(fw["crossings"], ends, fw["areas"], fw["accumulated"]))]
        doc.table(["pulse", "from θ [°]", "to θ [°]", "ΔE [J]", "accumulated [J]"], rows, "lrrrr",
                  caption="The energy table (after Norton Table 11-1)")
        d = fw["disk"]
        doc.equation(
            M.row(M.sym("T", "avg"), M.op("="), M.qty(fw["T_avg"], "N·m"), M.op(","), M.SP, M.i("E"), M.op("="),
                  M.qty(fw["E"], "J")),
            M.row(M.sym("I", "s"), M.op("="), M.frac(M.i("E"), M.row(M.sym("C", "s"), M.sup(M.sym("ω", "avg"), "2"))),
                  M.op("="), M.frac(M.qty(fw["E"], "J"), M.row(M.n(fw["Cs"]), M.op("·"),
                                                              M.sup(M.paren(M.qty(fw["omega_avg"], "rad/s")), "2"))),
                  M.op("="), M.qty(fw["I_s"], "kg·m²")))
        doc.text(f"A solid steel disk ({d['thickness'] * 1e3:g} mm thick, ρ = {d['density']:g} kg/m³, an assumption) "
                 "of that inertia has radius ", M.qty(d["radius"] * 1e3, "mm"), " and mass ", M.qty(d["mass"], "kg"), ".")
        doc.figure([s.picture("energy", lambda: paper.plotted(lambda ax: draw.draw_energy(f, ax=ax), *_SMALL_PLOT),
                              alt="the flywheel's energy over the cycle", natural=True)],
                   "The energy taken from the shaft over the cycle (the torque less its average, integrated over the "
                   "crank angle): its largest swing is E.")
    jfi = data["joint_force_index"]
    if asked is not None and "jfi_peak" not in asked:
        return
    doc.heading(2, "Joint-force index")
    if not jfi["defined"]:
        doc.text(f"Not defined here: {jfi['reason']}")
    else:
        u = f" {jfi['units']}" if jfi["units"] else ""
        over = "over" if (jfi["peak"]["value"] or 0) > jfi["limit"] else "within"
        doc.text("Holte and Chase (Norton §11.12): the largest static joint force over the external load, at each "
                 "position. Peak ", M.n(jfi["peak"]["value"]), f"{u} at {where(jfi['peak'])} "
                 f"(limit {jfi['limit']:g}: {over}).")
        index = cycle.joint_force_index()
        doc.figure([s.picture("jfi", lambda: paper.plotted(lambda ax: draw.draw_joint_force_index(index, ax=ax),
                                                           *_SMALL_PLOT), alt="the joint-force index", natural=True)],
                   "The joint-force index over the cycle, with its limit.")
