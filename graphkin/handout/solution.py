"""The sections that solve: the matrix [A]{x} = {b} and its solution, the graphical route step by step with
its sub-problems, the table of both routes, the blank worksheet's room to draw, and a whole cycle."""

from __future__ import annotations

import math

import numpy as np

from graphkin.analytical.matrix import assemble
from graphkin.cycle import sweep
from graphkin.handout import maths as M
from graphkin.handout.document import Doc, Subject
from graphkin.report import cycle_data

BLANK_SPACE = 75.0
"""Height of the empty room left for each force polygon in the blank version [mm]."""


def _clean(x, scale, rel=1e-12):
    """Values below ``rel`` × ``scale`` set to 0: rounding noise (1e-17 where a lever arm is zero) would hide
    the matrix's structure, as in :meth:`graphkin.analytical.matrix.System.format`."""
    x = np.array(x, dtype=float)
    x[np.abs(x) < rel * max(scale, 1e-300)] = 0.0
    return x + 0.0


def _unknown(name: str) -> list:
    """``"F12x"`` → F₁₂ₓ, ``"N14"`` → N₁₄, ``"T12"`` → T₁₂."""
    return M.sym(name[0], name[1:]) if len(name) > 1 else M.i(name)


def matrix(doc: Doc, s: Subject, entry: dict, i: int):
    system = _system(s)
    A, b = system.A[i], system.b[i]
    A, b = _clean(A, np.abs(A).max()), _clean(b, np.abs(b).max())
    x = system.solve()[i]
    x = _clean(x, np.abs(x).max(), 1e-9)
    doc.heading(2, "Equilibrium equations: the matrix method")
    doc.text(f"Three equations per moving link (ΣFx = 0, ΣFy = 0, ΣM about G = 0), links "
             f"{', '.join(map(str, s.mech.moving))} in turn; one column per unknown. Force columns in N, "
             "moment rows in N·m (lever arms in m); {b} holds the known loads moved across "
             + ("(−ΣF_ext, −ΣM_ext; static: no inertia terms)." if s.static else "(m a_G − ΣF_ext, I_G α − ΣM_ext)."))
    cells = [[M.n(v) for v in r] for r in A]
    unknowns = [_unknown(u) for u in system.unknowns]
    doc.equation(M.row(M.mat(cells), M.column(unknowns), M.op("="), M.column([M.n(v) for v in b])), small=True)
    doc.text("Solved:")
    rows = []
    for u, value in zip(system.unknowns, x):
        unit = "N·m" if u[0] in "CT" else "N"  # couples of sliding pairs and the crank's torque
        rows.append([_unknown(u), M.qty(value, unit)])
    doc.table(["unknown", "value"], rows, "lr")


def _system(s: Subject):
    if not hasattr(s, "_system"):
        s._system = assemble(s.result)
    return s._system


def forces(doc: Doc, s: Subject, entry: dict):
    doc.heading(2, "Joint forces")
    r = s.result
    rows = []
    for a, b in r.forces:
        name, back = r.name_of(a, b), r.name_of(b, a)
        F = entry["forces"][name]
        rows.append([M.name(name), M.pair(F, "N"), M.polar(M.size_of(F), M.angle_of(F), "N"),
                     M.row(M.name(back), M.op("="), M.op("−"), M.name(name))])
    doc.table(["force", "x, y", "polar", ""], rows, "lrrl")
    d = entry["driver"]
    if s.crank:
        sense = " (CCW)" if d["value"] > 0 else " (CW)" if d["value"] < 0 else ""
        doc.text("The driving torque: ", M.row(M.name(d["name"]), M.op("="), M.qty(d["value"], "N·m")), sense + ".")
    else:
        doc.text("The driving force: ", M.row(M.name(d["name"]), M.op("="),
                                             M.polar(M.size_of(d["vector"]), M.angle_of(d["vector"]), "N")),
                 ", that is ", M.qty(d["value"], "N"), " along the guide.")
    for pname, p in entry["prismatic"].items():
        where = "—" if p["offset"] is None else f"{M.fmt(p['offset'] * 1e3)} mm from {p['slider_point']} along the guide"
        doc.text(f"Sliding pair {pname}: normal force ", M.qty(p["normal"], "N"), ", friction ",
                 M.qty(p["friction"], "N"), f"; its line acts {where}.")


def _polygon_equation(step) -> list:
    items = []
    for k, a in enumerate(step.polygon):
        if k:
            items.append(M.op("+"))
        items.append(M.vec(M.name(a.name)))
    return M.row(*items, M.op("="), M.n("0"))


def graphical(doc: Doc, s: Subject, entry: dict, c):
    from graphkin import draw
    from graphkin.draw.steps import KIND_TITLE, draw_step_geometry

    g = entry.get("graphical", {})
    doc.heading(2, "The graphical route")
    if c is None or not c.valid:
        doc.text(f"The construction cannot be drawn here: {g.get('reason') or (c.reason if c else '')}.")
        return
    scale = c.force_scale
    doc.text("Force polygons are drawn to the scale 1 mm = ", M.qty(scale, "N"), ". The free bodies first, "
             "every force on each link" + ("" if s.static else ", with the inertia resultant on its offset line")
             + ":")
    pics = [s.picture(f"fbd-{link}", lambda link=link: draw.draw_free_body(c, link), 1 / 3,
                    f"free body of link {link}", 70) for link in s.mech.moving]
    for k in range(0, len(pics), 3):
        part = pics[k:k + 3]
        links = s.mech.moving[k:k + 3]
        doc.figure(part, "Free bodies of " + ", ".join(f"link {n}" for n in links) + ", with every force found.")
    for k, step in enumerate(c.steps, start=1):
        sub = getattr(step, "sub", "")
        if step.kind == "sub-problem":
            # A book announces each sub-problem before its steps: a heading of its own.
            doc.heading(3, f"Sub-problem {sub}: only the loads on link {step.link}")
            doc.text(f"Step {k}. {step.caption}")
            continue
        if step.kind in _TEXT_ONLY:
            doc.text(f"Step {k}. {step.caption}")
            continue
        where = f"link {step.link}: " if step.link is not None else ""
        title = KIND_TITLE.get(step.kind, step.kind)
        doc.heading(3, f"Step {k}. {where}{title}" + (f" (sub-problem {sub})" if sub else ""))
        pics = []
        if _draws_geometry(step, s.mech.driver.link):
            def geometry(step=step):
                # The step places the mechanism's labels with its own: placing them alone first is work lost.
                d = draw.draw_mechanism(c, faint=True, emphasis=step.link, place=False)
                draw_step_geometry(c, step, ax=d.ax)
                return d

            pics.append(s.picture(f"step-{k}", geometry, 0.58 if step.polygon else 0.7,
                                  f"step {k}: the lines of action", 75))
        if step.polygon:
            pics.append(s.picture(f"polygon-{k}", lambda step=step: draw.draw_force_polygon(
                step, scale=scale, title=False, driver_name=c.driver_name), 0.4 if pics else 0.5,
                f"step {k}: the force polygon", 75))
        if pics:
            doc.figure(pics, step.caption)
        else:
            doc.text(step.caption)
        if step.polygon:
            doc.equation(_polygon_equation(step))
    _subproblems(doc, s, entry)
    _both_routes(doc, s, entry)


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
    header = ["force"] + [f"sub-problem {sp['label']} (link {sp['link']})" for sp in subs] + ["sum"]
    rows = []
    for name in names:
        rows.append([M.name(name)] + [M.polar(M.size_of(sp["forces"][name]), M.angle_of(sp["forces"][name]), "N")
                                      for sp in subs]
                    + [M.polar(M.size_of(g["forces"][name]), M.angle_of(g["forces"][name]), "N")])
    unit = "N·m" if s.crank else "N"
    d = g["driver"]
    rows.append([M.name(d["name"])] + [M.qty(sp["driver"]["value"], unit) for sp in subs] + [M.qty(d["value"], unit)])
    doc.table(header, rows, "l" + "r" * (len(subs) + 1),
              caption="Superposition: each sub-problem's forces and driving effort, and their sum")


def _reldiff(d: float) -> str:
    if not math.isfinite(d):
        return "—"
    return "0" if d == 0 else f"{d:.1e}".replace("-", M.MINUS)


def _both_routes(doc: Doc, s: Subject, entry: dict):
    g = entry["graphical"]
    doc.heading(2, "Both routes")
    rows = []
    for name, rel in g["relative_difference"].items():
        if name == g["driver"]["name"]:
            unit = "N·m" if s.crank else "N"
            rows.append([M.name(name), M.qty(entry["driver"]["value"], unit), M.qty(g["driver"]["value"], unit),
                         _reldiff(rel)])
        else:
            A, G = entry["forces"][name], g["forces"][name]
            rows.append([M.name(name), M.polar(M.size_of(A), M.angle_of(A), "N"),
                         M.polar(M.size_of(G), M.angle_of(G), "N"), _reldiff(rel)])
    doc.table(["force", "analytical", "graphical", "relative difference"], rows, "lrrr",
              caption="The graphical magnitudes are read off exactly (the closing side computed, not measured), "
                      "so the two routes agree to rounding.")
    for w in g["warnings"]:
        doc.text(f"Warning: {w}")


def blank(doc: Doc, s: Subject, c, drawn: bool):
    from graphkin import draw

    if c is None or not c.valid:
        return
    scale = c.force_scale
    if drawn:
        doc.heading(2, "Free bodies")
        label = doc.figure([s.picture("given", lambda: draw.draw_given(c), 1.0,
                                    "the mechanism and the free bodies with their known loads", 85)],
                           "The free bodies to scale with the known loads ("
                           + ("" if s.static else "the inertia resultant on its offset line, ")
                           + "external loads) and the force scale; the joint forces are yours to find.")
        doc.text("Draw the polygons at 1 mm = ", M.qty(scale, "N"), f" ({label}); step by step:")
        for k, step in enumerate(c.steps, start=1):
            if step.polygon:
                doc.space(BLANK_SPACE, f"Step {k}. Force polygon of link {step.link}: ", _polygon_equation(step))


# -- a whole cycle ------------------------------------------------------------------------------------
def cycle(doc: Doc, s: Subject):
    from graphkin import draw

    cycle = sweep(s.problem, s.cycle_positions)
    Cs = s.Cs if cycle.closed and not s.static else None  # a static analysis has no speed to keep steady
    data = cycle_data(cycle, Cs)
    deg = math.degrees
    doc.heading(1, "Over the whole cycle")
    e = data["effort"]
    doc.text(f"The same solution at every one of the {data['n']} positions (a load that switches on or off is "
             "sampled just before and just after its switching angle).")
    f = cycle.flywheel(Cs) if Cs is not None else None
    label = doc.figure([s.picture("torque-curve", lambda: draw.draw_torque_curve(cycle, flywheel=f), 0.85,
                                "the driving torque over the cycle", 85)],
                       "The driving torque over one turn with its average" +
                       (" and the pulses of T − T_avg with their energies." if f is not None else "."))
    theta = f"θ{s.mech.driver.frame}{s.mech.driver.link}"

    def where(p):
        return "—" if p["at"] is None else f"{theta} = {M.fmt(deg(p['at']), 5)}°"

    doc.table(["", "value", "at"], [
        ["peak", M.qty(e["max"]["value"], "N·m"), where(e["max"])],
        ["lowest", M.qty(e["min"]["value"], "N·m"), where(e["min"])],
        ["average", M.qty(e["average"], "N·m"), ""],
    ], "lrl", caption=f"Driving torque {e['name']} ({label})")
    rows = [[M.name(k), M.qty(v["peak"]["value"], "N"), where(v["peak"])] for k, v in data["forces"].items()]
    doc.table(["joint force", "peak", "at"], rows, "lrl", caption="Peak joint forces over the cycle")
    fw = data["flywheel"]
    if fw is not None:
        doc.heading(2, "Flywheel")
        doc.text("Norton §11.11: the energy of each pulse of T − T_avg between its crossings of the average, "
                 "accumulated from the first crossing; E is the largest swing of the accumulated energy.")
        ends = fw["crossings"][1:] + fw["crossings"][:1]
        rows = [[str(k + 1), M.n(M.fmt_fixed(deg(a) % 360, 1)), M.n(M.fmt_fixed(deg(b) % 360, 1)), M.n(area),
                 M.n(acc)] for k, (a, b, area, acc) in enumerate(zip(fw["crossings"], ends, fw["areas"],
                                                                      fw["accumulated"]))]
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
        doc.figure([s.picture("energy", lambda: draw.draw_energy(f), 0.7, "the flywheel's energy over the cycle", 70)],
                   "The energy ∫(T − T_avg) dθ over the cycle: its largest swing is E.")
    jfi = data["joint_force_index"]
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
        doc.figure([s.picture("jfi", lambda: draw.draw_joint_force_index(index), 0.7, "the joint-force index", 70)],
                   "The joint-force index over the cycle, with its limit.")
