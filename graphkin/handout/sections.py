"""The sections that state the problem and its motion: the exercise, the given data, the questions, the sign
convention, the mechanism, the kinematics of every link (as the loop equations), the inertia loads and the
external loads."""

from __future__ import annotations

import math
import re

import numpy as np

from graphkin.exercises.variants import pretty
from graphkin.graphical.paper import FIGURE_WIDTH, length_scale, mechanism_size
from graphkin.handout import maths as M
from graphkin.handout import scaled
from graphkin.handout.document import Doc, Subject
from graphkin.handout.figures import Picture
from graphkin.handout.loops import groups
from graphkin.model import Prismatic, Revolute
from graphkin.notation import num, unit_text


# -- sections ----------------------------------------------------------------------------------
def statement(doc: Doc, s: Subject, version: str, *, full: bool = False, at=(), from_motion: bool = False):
    """What is asked: the exercise's statement with the student's values, the problem's notes (the full key,
    for the teacher: they say how the catalog read the book), or the question in one sentence (``from_motion``:
    by construction from the input motion)."""
    v = s.variant
    if v is not None and v.exercise.intro:
        doc.heading(1, "The exercise")
        for para in _paragraphs(v.sheet()["intro"]):
            doc.text(*M.prose(para))
        return
    doc.heading(1, "The problem")
    if full and s.problem.notes:
        for para in _paragraphs(s.problem.notes):
            doc.text(para)
        return
    how = ("a static force analysis: no inertia loads" if s.static else "inertia included (d'Alembert)")
    what = f"the driving {'torque' if s.crank else 'force'} {s.mech.driver.symbol}"
    if from_motion:
        where = " and ".join(s.where(i) for i in at)
        doc.text(*M.prose(f"At {where}, starting from the input motion, construct the velocity and acceleration "
                          "polygons, read off each link's ω, α and a_G, find its inertia loads, then find every "
                          f"joint force and {what} graphically."))
        return
    if s.whole_cycle:
        where = (f" Over the whole cycle, worked out in full at {s.where(at[0])}, where {what} is largest in size."
                 if at else "")
        doc.text(*M.prose(f"Find every joint force and {what}, {how}, both analytically and graphically.{where}"))
    else:
        where = " and ".join(s.where(i) for i in at)
        doc.text(*M.prose(f"At {where}, find every joint force and {what}, {how}, both analytically and graphically."))


def notation(doc: Doc, s: Subject):
    """The sign convention in one paragraph (the full key draws it)."""
    sliding = any(isinstance(j, Prismatic) for j in s.mech.joints)
    doc.text("Notation: ", M.sym("F", "ij"), " is the force of link i on link j, ",
             M.row(M.sym("F", "ji"), M.op("="), M.op("−"), M.sym("F", "ij")),
             *(["; at a sliding pair it is written ", M.sym("G", "ij"), " (across the guide, but for friction)"]
               if sliding else []),
             f". Link {s.mech.frame} is the frame. x to the right, y up; angles, ω, α and torques are positive "
             "counter-clockwise; a force in polar form is its magnitude ∠ its direction from +x." + _units_note(s))


def _units_note(s: Subject) -> str:
    """What ``--units`` changed: the answers' units, and that the working stays in SI."""
    u = s.units
    if u.is_si:
        return ""
    return (f" Answers are in {u.name} units ({u.symbol('force')}, {u.symbol('torque')}, {u.symbol('length')}); "
            "the working (inertia loads, equations, polygons) is in SI, N and mm, as it is solved.")


def _paragraphs(text: str) -> list[str]:
    return [" ".join(p.split()) for p in text.strip().split("\n\n") if p.strip()]


_LONG = re.compile(r"(?<![\w.])(-?)(\d+\.\d+|\d+)(?:[eE]([-+]?\d+))?(?![\w.])")


def _tidy(text: str) -> str:
    """Numbers of a file's value as a handout prints them: 4 significant figures at most (``35342.917353`` →
    ``35340``), a power of ten written out (``5.3466667e-5`` → ``5.347×10⁻⁵``) and a true minus."""

    def one(m):
        sign, digits, power = m[1], m[2], m[3]
        significant = len(digits.replace(".", "").lstrip("0"))
        if power is None and significant <= 4:
            return (M.MINUS if sign else "") + digits
        text = num(float(m[0]), 4, power=True)
        return re.sub(r"\^([−-]?\d+)", lambda e: e[1].translate(_SUPERSCRIPT), text)

    return _LONG.sub(one, text).replace("-", M.MINUS) if _LONG.search(text) else text


_SUPERSCRIPT = str.maketrans("0123456789−-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁻")


def _pretty(value) -> str:
    """A value of the problem file as written, in a book's notation (``"7.6 deg"`` → ``7.6°``)."""
    if isinstance(value, str):
        return _tidy(pretty(value))
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, (int, float)):
        return _tidy(f"{value:g}")
    if isinstance(value, list):
        if len(value) == 2 and all(isinstance(x, str) for x in value):
            return f"({_pretty(value[0])}, {_pretty(value[1])})"
        return ", ".join(_pretty(x) for x in value)
    if isinstance(value, dict):
        if {"r", "angle"} <= value.keys():
            return f"{_pretty(value['r'])} ∠ {_pretty(value['angle'])}"
        if {"magnitude", "angle"} <= value.keys():
            return f"{_pretty(value['magnitude'])} ∠ {_pretty(value['angle'])}"
        if {"start", "stop"} <= value.keys():
            step = f" in steps of {_pretty(value['step'])}" if "step" in value else ""
            return f"from {_pretty(value['start'])} to {_pretty(value['stop'])}{step}"
        if {"from", "to"} <= value.keys():
            return f"from {_pretty(value['from'])} to {_pretty(value['to'])}"
        return ", ".join(f"{_SYMBOL.get(k, k)} = {_pretty(x)}" for k, x in value.items())
    return str(value)


_SYMBOL = {"mass": "m", "theta": "θ", "omega": "ω", "alpha": "α", "s": "s", "v": "v", "a": "a", "mu": "μ", "a_G": "aG",
           "v_G": "vG", "I_G": "IG",
           "r": "r", "radius": "r", "width": "w", "height": "h", "thickness": "t", "length": "L", "density": "ρ"}
"""A file's keys as the symbols a book writes."""


def _driver_text(s: Subject, d: dict, i: int | None) -> str:
    """The driver's data with a book's symbols: ``θ12 = 140°; ω12 = 900 rpm; α12 = 0 rad/s²``.

    At a worked position (not over a whole cycle) the input is stated at that position: a file that lists
    0°–358° worked out at 140° is worked out at 140°.
    """
    drv = s.mech.driver
    ij = f"{drv.frame}{drv.link}"
    names = ({"theta": f"θ{ij}", "omega": f"ω{ij}", "alpha": f"α{ij}"} if drv.crank else
             {"s": "s", "v": "v", "a": "a"})
    parts = []
    for key, value in d.items():
        if key in ("type", "link"):
            continue
        if key in ("theta", "s") and i is not None and not s.whole_cycle:
            parts.append(s.where(i))
            continue
        if key == "travel" and i is not None and not s.whole_cycle:
            # The piston's travel as the book gives it, and the crank angle it puts the crank at.
            one = not isinstance(value, (list, dict))
            parts.append((f"piston travel = {_pretty(value)}, so " if one else "") + s.where(i))
            continue
        parts.append(f"{names.get(key, key)} = {_pretty(value)}" if not isinstance(value, dict) or
                     {"start", "stop"} > value.keys() else f"{names.get(key, key)} {_pretty(value)}")
    return "; ".join(parts)


def _joined(parts) -> str | tuple:
    """Parts of a cell joined by ``"; "``: text, or runs where a part is a symbol and its value (I_G, subscripted)."""
    if all(isinstance(p, str) for p in parts):
        return "; ".join(parts)
    out: list = []
    for k, p in enumerate(parts):
        out += (["; "] if k else []) + (list(p) if isinstance(p, tuple) else [p])
    return tuple(out)


def _gear_text(j: dict) -> str:
    """A gear mesh in words: ``gear 2 (pitch radius 100 mm, centre O2) meshes with gear 3 (pitch radius 40 mm,
    centre O3); pressure angle φ = 20°``."""
    links, centres, radii = j.get("links", []), j.get("centers", []), j.get("radii", [])
    gears = []
    for k, link in enumerate(links):
        about = [f"pitch radius {_pretty(radii[k])}" if k < len(radii) else "",
                 f"centre {centres[k]}" if k < len(centres) else ""]
        about = ", ".join(x for x in about if x)
        gears.append(f"gear {link}" + (f" ({about})" if about else ""))
    text = " meshes with ".join(gears)
    if "pressure_angle" in j:
        text += f"; pressure angle φ = {_pretty(j['pressure_angle'])}"
    if "efficiency" in j:
        text += f"; mesh efficiency η = {_pretty(j['efficiency'])}"
    return text


def _given_rows(s: Subject, raw: dict, frame_number: int, i: int | None = None) -> list[list]:
    """The problem file's data, one row per frame, link, joint, driver and load, in the file's units."""
    rows = []
    if raw.get("gravity") is not None:
        rows.append(["gravity", f"g = {_pretty(raw['gravity'])}, along −y"])
    frame = raw.get("frame", {})
    if frame.get("points"):
        rows.append([f"frame (link {frame_number})", "; ".join(f"{k} = {_pretty(p)}" for k, p in frame["points"].items())])
    for link in raw.get("links", []):
        parts = [f"{k} = {_pretty(p)}" for k, p in link.get("points", {}).items()]
        for key, label in (("mass", "m"), ("G", "G"), ("I_G", M.sym("I", "G")), ("k", "k")):
            if key in link:
                parts.append((label, f" = {_pretty(link[key])}") if not isinstance(label, str) else
                             f"{label} = {_pretty(link[key])}")
        if "shape" in link:
            shape = dict(link["shape"])
            kind = shape.pop("type", "shape")
            parts.append(f"{kind} " + _pretty(shape) if shape else kind)
        name = f"link {link.get('number', '?')}" + (f" ({link['name']})" if link.get("name") else "")
        rows.append([name, _joined(parts)])
    pins = [f"links {'–'.join(map(str, j.get('links', [])))} at {j.get('point', '?')}" for j in raw.get("joints", [])
            if j.get("type", "joint") == "revolute"]
    if pins:
        # One row for every pin: a pin says no more than which links it joins and where.
        rows.append([f"revolute joint{'s' if len(pins) > 1 else ''}", "; ".join(pins)])
    for j in raw.get("joints", []):
        kind = j.get("type", "joint")
        if kind == "revolute":
            continue
        if kind == "prismatic":
            text = (f"slider {j.get('slider')} on guide {j.get('guide')} at {j.get('point')}, guide through "
                    f"{j.get('through')} at {_pretty(j.get('direction', '0 deg'))}")
            if "mu" in j:
                text += f", μ = {_pretty(j['mu'])}"
        elif kind == "gear":
            text = _gear_text(j)
        else:
            text = "; ".join(f"{_SYMBOL.get(k, k)} = {_pretty(x)}" for k, x in j.items() if k != "type")
        rows.append([f"{kind} joint", text])
    d = raw.get("driver", {})
    if d:
        kind = f" ({d['type']})" if d.get("type") else ""
        rows.append([f"driver, link {d.get('link', '?')}{kind}", _driver_text(s, d, i)])
    for ld in raw.get("loads", []):
        where = f"on link {ld.get('link')}" + (f" at {ld['point']}" if "point" in ld else "")
        value = _pretty(ld.get("force", ld.get("torque", "")))
        if "table" in ld or "csv" in ld:
            rows = [r for r in str(ld.get("table", "")).strip().splitlines()[1:] if r.strip() and r.strip()[0] != "#"]
            value = (f"from the table in {ld['csv']}" if "csv" in ld else f"from a table of {len(rows)} rows")
            if "direction" in ld:
                value += f", along {_pretty(ld['direction'])}"
        when = f", {_pretty(ld['active'])}" if "active" in ld else ""
        if ld.get("sense", "fixed") != "fixed":
            when += f", sense: {ld['sense']}"
        rows.append([f"{ld.get('type', 'load')} {ld.get('name', '')}".strip(), f"{value} {where}{when}"])
    for link, values in raw.get("given", {}).items():
        rows.append([f"given, link {link}", "; ".join(f"{_SYMBOL.get(k, k)} = {_pretty(x)}" for k, x in values.items())])
    return rows


def own_data(doc: Doc, s: Subject):
    """A student's own values."""
    v = s.variant
    if v is not None and v.data:
        doc.table(["your data", "value"], [[M.prose(f"{g.label} {g.symbol}".strip() if g.label else g.symbol),
                                             g.shown.split(" = ", 1)[1]] for g in v.data], "lr",
                  caption="Your own values (the rest of the data is the same for everyone)")


def given(doc: Doc, s: Subject, i: int | None = None, own: bool = True):
    doc.heading(1, "Given" if own else "The data")
    if own:
        own_data(doc, s)
    rows = [[M.prose(c) if isinstance(c, str) else c for c in row] for row in _given_rows(s, s.raw, s.mech.frame, i)]
    if rows:
        doc.table(["item", "data"], rows, "ll", caption="Points in each link's own frame; angles from +x, "
                  "counter-clockwise positive")
    if s.static:
        doc.text("A static analysis: the links' masses play no part (no inertia loads), so none are needed.")
        return
    moving = [s.mech.link(k) for k in s.mech.moving]
    heavy = [b for b in moving if b.mass > 0 or b.I_G > 0]
    rows = [[f"link {b.number}", M.qty(b.mass, "kg"), M.qty(b.I_G, "kg·m²"),
             M.pair(np.asarray(b.G) * 1e3, "mm")] for b in heavy]
    light = [str(b.number) for b in moving if b not in heavy]
    massless = (f"; link{'s' if len(light) > 1 else ''} {', '.join(light)} massless") if light else ""
    if rows:
        doc.table(["link", ("mass ", M.i("m")), ("inertia about G, ", M.sym("I", "G")), "G in the link's frame"],
                  rows, "lrrr", caption="Mass properties used (the file's shapes and radii of gyration worked out: "
                                        f"the inertia about G is m k², or the shape's){massless}")


def questions(doc: Doc, s: Subject, answers: bool):
    """The questions: with the answers and hints (a key), or with room for the student's answers (a sheet).

    The tolerance is stated as every sheet states it (:func:`graphkin.exercises.quantities.within`): a graphical
    question's says both what the exercise allows and what a ruler reads at the worksheet's printed scale.
    """
    v = s.variant
    sheet = v.key() if answers else v.sheet()
    doc.heading(1, "Questions" if not answers else "Questions and answers")
    rows = []
    for data in sheet["questions"]:
        unit = unit_text(data["unit"]) or "no unit"
        row = [data["id"], M.prose(data["ask"]), f"{unit}, within {data['within']}, {data['points']:g} pt"]
        row += [data["answer"]["text"]] if answers else [""]
        rows.append(row)
    header = ["id", "question", "unit, tolerance, points", "answer" if answers else "your answer"]
    doc.table(header, rows, "llll", tall=not answers, boxed=not answers)
    if answers:
        doc.items([M.prose(f"{q['id']}: {q['answer']['hint']}") for q in sheet["questions"] if q["answer"].get("hint")])


_CONVENTION: list[Picture] = []


def _convention_picture() -> Picture:
    """The sign convention's drawing: the same in every handout, so drawn once per process (a class's batch)."""
    if not _CONVENTION:
        from graphkin import draw

        # Printed at its own size (about 100 mm wide), so its labels print at theirs.
        _CONVENTION.append(Picture("convention", lambda: draw.draw_sign_convention(), 0.5,
                                   "x right, y up; angles, ω, α and torques positive counter-clockwise", 60,
                                   natural=True))
    return _CONVENTION[0]


def convention(doc: Doc, s: Subject):
    doc.heading(1, "Sign convention")
    label = doc.figure([_convention_picture()], "The sign convention used throughout.")
    items = [
        ("Global x to the right, y up; angles, ω, α and torques are positive counter-clockwise (", label, ")."),
        (M.sym("F", "ij"), " is the force of link i on link j, and ",
         M.row(M.sym("F", "ji"), M.op("="), M.op("−"), M.sym("F", "ij")),
         f". Link {s.mech.frame} is the frame. A sliding pair's reaction is written ", M.sym("G", "ij"), "."),
        ("Inertia force ", M.row(M.op("−"), M.i("m"), M.sym("a", "G")), " at G, inertia torque ",
         M.row(M.op("−"), M.sym("I", "G"), M.i("α")), "; their single resultant is offset from G by ",
         M.row(M.i("h"), M.op("="), M.frac(M.absval(M.i("T")), M.absval(M.i("F")))),
         " to the side that reproduces the torque's sense."),
        ("Forces in polar form, as the books print them: magnitude ∠ direction in degrees from +x, "
         "counter-clockwise positive.",),
    ]
    if s.static:
        del items[2]  # no inertia loads in a static analysis
    if not s.units.is_si:
        items.append((_units_note(s).strip(),))
    doc.items(items)


def mechanism(doc: Doc, s: Subject, c, i: int):
    k = length_scale(mechanism_size(c), (FIGURE_WIDTH, 90.0))
    label = doc.figure([scaled.mechanism(s, c, i, k)],
                       f"The mechanism at {s.where(i)}, with its centres of mass. {scaled.statement(k)}")
    doc.text(f"{label} shows the linkage at {s.where(i)}.")


def _pick_point(s: Subject, link: int) -> str:
    """The point the acceleration of G is taken from: a frame pivot if the link has one, else a shared pin."""
    joints = [j for j in s.mech.joints_of(link) if isinstance(j, Revolute)]
    joints.sort(key=lambda j: (s.mech.frame not in j.links, min(set(j.links) - {link})))
    if joints:
        return joints[0].point
    return next(iter(s.mech.link(link).points))


def kinematics(doc: Doc, s: Subject, entry: dict, i: int):
    kin = s.result.kinematics
    doc.heading(2, "Position of every link" if s.static else "Kinematics")
    what = "position equations" if s.static else "position, velocity and acceleration equations"
    doc.text("The solver locates the links group by group, in closed form: the driver first, then each dyad "
             f"(two links joined to each other and to links already located) or gear pair. Each group's {what}, "
             "with the numbers:")
    groups(doc, kin, i, rates=not s.static)
    doc.text("Every link at once (θ of a link is the angle of its own x-axis, the axis its points are given in):")
    link_table(doc, entry, s.static)
    if s.static:
        return
    doc.text("Each centre of mass from a point P of the same link whose acceleration is known "
             "(relative acceleration: tangential α k × r and normal −ω² r):")
    for link, d in entry["links"].items():
        link = int(link)
        if s.mech.link(link).mass == 0:
            continue
        P = _pick_point(s, link)
        aP = kin.acceleration(link, P)[i]
        r = kin.G(link)[i] - kin.position(link, P)[i]
        w, al = d["omega"], d["alpha"]
        G = f"G{link}"
        aG = M.sym("a", G)
        if math.hypot(*r) < 1e-12:
            doc.equation(M.row(aG, M.op("="), M.sym("a", P), M.op("="), M.pair(aP, "m/s²")))
            continue
        lines = [
            M.row(aG, M.op("="), M.sym("a", P), M.op("+"), M.sym("α", str(link)), M.i("k"), M.op("×"),
                  M.sym("r", f"{P}{G}"), M.op("−"), M.sup(M.sym("ω", str(link)), "2"), M.sym("r", f"{P}{G}")),
            M.row(M.op("="), M.pair(aP), M.op("+"), M.paren(M.n(al)), M.pair((-r[1], r[0])), M.op("−"),
                  M.sup(M.paren(M.n(w)), "2"), M.pair(r)),
            M.row(M.op("="), M.pair(d["a_G"], "m/s²"), M.op("="),
                  M.polar(M.size_of(d["a_G"]), M.angle_of(d["a_G"]), "m/s²")),
        ]
        doc.equation(*lines)
    doc.text("with ", M.sym("r", "PG"), " in m, the vector from P to G, and ", M.row(M.i("k"), M.op("×"), M.i("r")),
             " the vector r turned 90° counter-clockwise.")


def inertia(doc: Doc, s: Subject, entry: dict, c, i: int):
    doc.heading(2, "Inertia loads")
    doc.text("d'Alembert: each moving link is in equilibrium under its loads, the joint forces, and its inertia "
             "force and torque.")
    for link, d in entry["links"].items():
        body = s.mech.link(int(link))
        if body.mass == 0:
            doc.text(f"Link {link} is massless: no inertia loads.")
            continue
        a, F, T, h = d["a_G"], d["inertia_force"], d["inertia_torque"], d["h"]
        Fi, Ti = M.sym("F", f"{link}i"), M.sym("T", f"{link}i")
        lines = [
            M.row(Fi, M.op("="), M.op("−"), M.sym("m", link), M.sym("a", f"G{link}"), M.op("="), M.op("−"),
                  M.paren(M.qty(body.mass, "kg")), M.pair(a, "m/s²"), M.op("="), M.pair(F, "N"), M.op("="),
                  M.polar(M.size_of(F), M.angle_of(F), "N")),
            M.row(Ti, M.op("="), M.op("−"), M.sym("I", f"G{link}"), M.sym("α", link), M.op("="), M.op("−"),
                  M.paren(M.qty(body.I_G, "kg·m²")), M.paren(M.qty(d["alpha"], "rad/s²")), M.op("="),
                  M.qty(T, "N·m"), M.t(" (CCW)" if T > 0 else " (CW)" if T < 0 else "")),
        ]
        if h is not None:
            lines.append(M.row(M.sym("h", link), M.op("="), M.frac(M.absval(Ti), M.absval(Fi)), M.op("="),
                               M.frac(M.qty(abs(T), "N·m"), M.qty(M.size_of(F), "N")), M.op("="),
                               M.qty(h * 1e3, "mm")))
        doc.equation(*lines)
        inert = c.inertia.get(int(link)) if c is not None and c.valid else None
        if h is None:
            doc.text(f"The inertia force of link {link} is zero: its inertia torque acts alone, as a couple.")
        elif inert and inert.get("line_point") is not None:
            G = np.asarray(c.G[int(link)])
            e = np.asarray(F) / M.size_of(F)
            off = np.asarray(inert["line_point"]) - G
            off = off - np.dot(off, e) * e
            if np.hypot(*off) <= 1e-12:
                doc.text(f"The resultant R{link}i passes through G{link} (no inertia torque).")
            else:
                side = "left" if e[0] * off[1] - e[1] * off[0] > 0 else "right"
                sense = "counter-clockwise" if T > 0 else "clockwise"
                doc.text(f"The single resultant R{link}i = F{link}i acts on a line parallel to it at h{link} = ",
                         M.qty(h * 1e3, "mm"), f" to the {side} of G{link} (looking along the force; from G{link} "
                         f"towards ", M.n(M.fmt_fixed(M.angle_of(off))), "°), where its moment about "
                         f"G{link} is {sense}, as T{link}i is.")


def loads(doc: Doc, s: Subject, entry: dict, always: bool = False):
    """The external loads at this position, when any of them changes with the position (a table, a sense), or
    ``always`` (a worksheet states every load it is worked with)."""
    if not entry["loads"] or not (always or any(ld.varies for ld in s.mech.loads)):
        return  # the given data already says what they are
    doc.heading(2, "External loads here")
    rows = []
    for ld in entry["loads"]:
        name = M.name(ld["name"]) if ld["name"] else ("P" if "force" in ld else "T")
        if "force" in ld:
            value = s.polar(ld["force"]) if ld["acting"] else s.qty(0.0, "force")
            rows.append([name, f"link {ld['link']} at {ld['point']}", value])
        else:
            rows.append([name, f"link {ld['link']}", s.qty(ld["torque"], "torque")])
    doc.table(["load", "on", "value at this position"], rows, "llr",
              caption="Each load at its value here: read off its table, and with the sense the motion gives it")


def link_table(doc: Doc, entry: dict, static: bool):
    """Every link's θ, and (not static) ω, α and a_G in components and in polar form, from a position's JSON entry."""
    if static:
        doc.table(["link", "θ [°]"], [[f"link {link}", M.n(M.fmt_fixed(math.degrees(d["theta"])))]
                                      for link, d in entry["links"].items()], "lr")
        return
    rows = []
    for link, d in entry["links"].items():
        a = d["a_G"]
        rows.append([f"link {link}", M.n(M.fmt_fixed(math.degrees(d["theta"]))), M.n(d["omega"]), M.n(d["alpha"]),
                     M.pair(a), M.polar(M.size_of(a), M.angle_of(a), "")])
    doc.table(["link", "θ [°]", "ω [rad/s]", "α [rad/s²]", (M.sym("a", "G"), " [m/s²]"),
               (M.sym("a", "G"), " polar")], rows, "lrrrrr")
