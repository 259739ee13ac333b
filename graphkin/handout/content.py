"""The worked solution as data: one structure that every renderer (PDF, HTML, Markdown) reads.

:func:`build` returns a dictionary::

    {"title": str, "subtitle": str, "source": str, "version": "key" | "sheet" | "blank",
     "problem": str, "student": str | None,
     "worked": [{"index": int, "q": float, "label": "θ12 = 342°"}],   the positions worked out
     "blocks": [block, ...]}

in the order a textbook solution goes: title and source; the given data
(the file's own units); the sign convention; for each worked position the
mechanism, the kinematics of every link, the inertia loads, the matrix
[A]{x} = {b} and its solution, the graphical route step by step and the
table of both routes; for a whole cycle the torque curve, the flywheel's
energy table (Norton Table 11-1) and the joint-force index.

A block is a dict with a ``"kind"``:

=============  ==================================================================
``heading``    ``level`` (1–3), ``text``
``text``       ``runs``: a paragraph; ``keep``: on the same page as the next block
               (it introduces a figure or ends with a colon)
``list``       ``items``: each a list of runs; ``ordered``
``table``      ``header`` and ``rows``: cells, each a list of runs; ``align``
               (one of ``l c r`` per column); ``caption`` (str or None)
``equation``   ``lines``: math nodes, one displayed line each; ``small``
``figure``     ``pictures`` (:class:`graphkin.handout.figures.Picture`, side by
               side), ``caption`` (starts ``"Figure k."``), ``label``
``space``      ``height`` [mm] of empty room to draw in by hand, ``label`` and ``math``
               (the equation of what to draw there, or None)
``pagebreak``  a new page (PDF only)
=============  ==================================================================

A *run* is a str (plain text) or a math node (a list, see
:mod:`graphkin.handout.maths`). Every number is formatted here, once, with
:func:`graphkin.handout.maths.fmt`: the three renderers print the same digits.
The numbers come from :func:`graphkin.report.solution` (the data of
``graphkin solve --json``) and :func:`graphkin.report.cycle_data` (``graphkin
cycle --json``); nothing is solved twice.
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np

from graphkin import catalog, exercises
from graphkin.analytical.matrix import assemble
from graphkin.cycle import sweep
from graphkin.errors import GraphkinError
from graphkin.exercises.exercise import set_field
from graphkin.exercises.variants import Variant, pretty
from graphkin.graphical import construct_forces
from graphkin.handout import maths as M
from graphkin.handout.figures import Picture
from graphkin.handout.loops import groups
from graphkin.model import Revolute
from graphkin.notation import input_text
from graphkin.report import cycle_data, solution
from graphkin.units import to_si

VERSIONS = ("key", "sheet", "blank")

DEFAULT_CS = 0.05
"""Coefficient of speed fluctuation for a whole cycle's flywheel when none is given (Norton: 0.01–0.05)."""

BLANK_SPACE = 75.0
"""Height of the empty room left for each force polygon in the blank version [mm]."""


def _runs(x) -> list:
    """A cell or list item as runs: a str or a math node is one run, a tuple holds several."""
    return list(x) if isinstance(x, tuple) else [x]


class _Doc:
    """Collects the blocks in order and numbers the figures."""

    def __init__(self):
        self.blocks: list[dict] = []
        self.figures = 0

    def heading(self, level: int, text: str):
        self.blocks.append({"kind": "heading", "level": level, "text": text})

    def text(self, *runs):
        # A paragraph that ends with a colon introduces what follows: a page break between them would orphan it.
        last = runs[-1] if runs else ""
        self.blocks.append({"kind": "text", "runs": list(runs),
                            "keep": isinstance(last, str) and last.rstrip().endswith(":")})

    def items(self, items, ordered=False):
        self.blocks.append({"kind": "list", "items": [_runs(r) for r in items], "ordered": ordered})

    def table(self, header, rows, align=None, caption=None):
        self.blocks.append({"kind": "table", "header": [_runs(h) for h in header],
                            "rows": [[_runs(c) for c in r] for r in rows],
                            "align": align or "l" * len(header), "caption": caption})

    def equation(self, *lines, small=False):
        self.blocks.append({"kind": "equation", "lines": list(lines), "small": small})

    def figure(self, pictures, caption: str) -> str:
        """Add a figure; returns its name (``"Figure 3"``) for the text to refer to."""
        self.figures += 1
        label = f"Figure {self.figures}"
        # A section that opens with a figure keeps its heading and any paragraphs before the figure on the
        # figure's page: a heading alone at the foot of a page, its figure overleaf, is what a reader trips on.
        lead = []
        for b in reversed(self.blocks):
            if b["kind"] != "text":
                break
            lead.append(b)
        if len(lead) < len(self.blocks) and self.blocks[-1 - len(lead)]["kind"] == "heading":
            for b in lead:
                b["keep"] = True
        self.blocks.append({"kind": "figure", "pictures": list(pictures), "caption": f"{label}. {caption}",
                            "label": label})
        return label

    def space(self, height: float, label: str, math=None):
        self.blocks.append({"kind": "space", "height": height, "label": label, "math": math})

    def pagebreak(self):
        self.blocks.append({"kind": "pagebreak"})


# -- what the handout is about ---------------------------------------------------------
class _Subject:
    """A problem (or a student's variant of an exercise) with everything solved once."""

    def __init__(self, problem, raw: dict, *, variant=None, at=None, Cs=None):
        self.problem = problem
        self.raw = raw
        self.variant = variant
        self.mech = problem.mechanism
        self.crank = self.mech.driver.crank
        self.static = bool(getattr(problem, "static", False))
        self.result = problem.solve(at)
        self.n = self.result.n
        self.whole_cycle = at is None and self.n > 1
        ex = variant.exercise if variant is not None else None
        self.Cs = Cs if Cs is not None else (variant.Cs if variant is not None and variant.Cs else DEFAULT_CS)
        self.cycle_positions = ex.positions if ex is not None else None
        self._pictures: dict[str, Picture] = {}

    def construction(self, i: int):
        """The graphical construction at position ``i`` (None where the linkage has no solution), built once."""
        key = f"construction-{i}"
        if key not in self.__dict__:
            self.__dict__[key] = construct_forces(self.result.kinematics, i) if self.result.valid[i] else None
        return self.__dict__[key]

    def data(self) -> dict:
        """:func:`graphkin.report.solution` of the worked positions, graphical route included (made once)."""
        if "_data" not in self.__dict__:
            graphical = [None] * self.n
            for i in self.worked():
                graphical[i] = self.construction(i)
            self._data = solution(self.problem, self.result, graphical)
        return self._data

    def picture(self, key: str, draw, width: float = 1.0, alt: str = "", height: float = 80.0) -> Picture:
        """The picture named ``key``, made once: a student's sheet and key share their drawings."""
        if key not in self._pictures:
            self._pictures[key] = Picture(key, draw, width, alt, height)
        return self._pictures[key]

    def worked(self) -> list[int]:
        """The positions worked out in full: each one given, or over a cycle the design case.

        Over a whole cycle the position of the largest |driving torque| (or
        force) among the file's own positions is worked out: the one a
        designer sizes the parts for.
        """
        r = self.result
        if not self.whole_cycle:
            return list(range(self.n))
        effort = np.where(r.valid, np.abs(r.effort), -np.inf)
        return [int(np.argmax(effort))] if np.isfinite(effort).any() else [0]

    def where(self, i: int) -> str:
        """``θ12 = 342°`` or ``s = 200 mm``: the input at position ``i``."""
        q = float(self.result.kinematics.q[i])
        d = self.mech.driver
        return input_text(q, d.crank, d.input_symbol)


def _read_raw(name: str) -> dict:
    """A problem file's data as written (units and all), for the table of given data."""
    path = catalog.path(name) if name in catalog.names() else Path(name)
    try:
        return tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError):  # already read once by load(): cannot fail here but for a race
        return {}


def subject(source, *, student=None, secret="", at=None, Cs=None):
    """Resolve what a handout is about: a problem (name or file) or, with ``student``, an exercise variant."""
    if isinstance(source, Variant) or student is not None:
        if at is not None:
            raise GraphkinError("--at: an exercise's position is part of the student's data; leave --at out")
        v = source if isinstance(source, Variant) else exercises.variant(source, student, secret)
        raw = dict(v.exercise.base)
        for g in v.data:
            for f in g.field:
                if f != "flywheel.Cs":
                    set_field(raw, f, g.value, copy=True)
        return _Subject(v.problem, raw, variant=v, Cs=Cs)
    try:
        problem = catalog.load(source)
    except GraphkinError:
        if source in exercises.names() or str(source).endswith(".toml") and _is_exercise(source):
            raise GraphkinError(f"{source} is an exercise: give the student's id with --student ID "
                                "(or a class with --roster FILE.csv)") from None
        raise
    if isinstance(at, str):
        dim = "angle" if problem.mechanism.driver.crank else "length"
        at = np.array([to_si(part.strip(), dim, field="--at", file="command line") for part in at.split(",")])
    elif at is not None:
        at = np.atleast_1d(np.asarray(at, dtype=float))
    return _Subject(problem, _read_raw(source), at=at, Cs=Cs)


def _is_exercise(path) -> bool:
    try:
        return "questions" in tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError, UnicodeDecodeError):
        return False


# -- the document ---------------------------------------------------------------------------
def build(source, *, student=None, secret="", at=None, version=None, Cs=None) -> dict:
    """The worked solution (or a student's sheet) as data, ready for any renderer.

    Parameters
    ----------
    source : str or graphkin.exercises.Variant
        A catalog problem or a problem file; with ``student``, a catalog
        exercise or an exercise file; or a variant already made.
    student : str, optional
        The student's id: the handout is their variant of the exercise.
    secret : str
        The course secret the variants are drawn with.
    at : str or array_like, optional
        Input positions to work out (``"124 deg,140 deg"``, or SI values [rad or m]);
        by default the problem's own (over a whole cycle: the position of
        the largest driving effort, and the cycle itself).
    version : {"key", "sheet", "blank"}, optional
        ``"key"``: everything (the default for a problem); ``"sheet"``: the
        data and the questions, no answers (the default for an exercise; for
        a problem, the same as ``"blank"``); ``"blank"``: the sheet with the
        free bodies drawn to the force scale and room to draw the polygons.
    Cs : float, optional
        Coefficient of speed fluctuation for the flywheel of a whole cycle
        (default: the exercise's, else :data:`DEFAULT_CS`).

    Returns
    -------
    dict
        See the module's docstring.
    """
    s = source if isinstance(source, _Subject) else subject(source, student=student, secret=secret, at=at, Cs=Cs)
    version = version or ("sheet" if s.variant is not None else "key")
    if version not in VERSIONS:
        raise GraphkinError(f"version must be one of {', '.join(VERSIONS)}, got {version!r}")
    if version == "sheet" and s.variant is None:
        version = "blank"  # a problem has no questions: its sheet is the blank worksheet
    return _build(s, version)


def _build(s: _Subject, version: str) -> dict:
    doc = _Doc()
    v = s.variant
    title = (v.exercise.title if v is not None else s.problem.title) or s.problem.name
    source = (v.exercise.source if v is not None else s.problem.source) or ""
    what = {"key": "worked solution", "sheet": "exercise sheet", "blank": "worksheet"}[version]
    who = f"student {v.student}" if v is not None else ""
    worked = s.worked()
    out = {"title": title, "subtitle": ", ".join(x for x in (what.capitalize(), who) if x), "source": source,
           "version": version, "problem": v.exercise.id if v is not None else s.problem.name,
           "student": v.student if v is not None else None,
           "worked": [{"index": i, "q": float(s.result.kinematics.q[i]), "label": s.where(i)} for i in worked],
           "blocks": doc.blocks}
    key = version == "key"
    data = s.data()
    _statement(doc, s, version)
    _given(doc, s)
    if v is not None:
        _questions(doc, s, answers=key)
    _convention(doc, s)
    for i in worked:
        entry = data["positions"][i]
        c = s.construction(i)
        doc.heading(1, f"{'Solution' if key else 'The position'} at {s.where(i)}"
                    if len(worked) > 1 or s.whole_cycle else ("Solution" if key else "The position"))
        if not entry["valid"]:
            doc.text(f"The linkage has no solution here: {entry['reason']}.")
            continue
        drawn = version == "blank" or (v is not None and v.exercise.draw)
        if key or not drawn:  # the blank's figure of the free bodies shows the mechanism too
            _mechanism(doc, s, c, i)
        if key:
            _kinematics(doc, s, entry, i)
            if not s.static:
                _inertia(doc, s, entry, c, i)
            _loads(doc, s, entry)
            _matrix(doc, s, entry, i)
            _forces(doc, s, entry)
            _graphical(doc, s, entry, c)
        else:
            _blank(doc, s, c, drawn=drawn)
    if s.whole_cycle and s.crank and key:
        _cycle(doc, s)
    elif s.whole_cycle and not key:
        doc.heading(1, "Over the whole cycle")
        doc.text(f"Solve every position of the file ({len(s.problem.q)} positions) and plot the driving "
                 f"{'torque' if s.crank else 'force'} against the input; read off its extremes and mean.")
    return out


# -- sections ----------------------------------------------------------------------------------
def _statement(doc: _Doc, s: _Subject, version: str):
    v = s.variant
    if v is not None and v.exercise.intro:
        doc.heading(1, "The exercise")
        for para in _paragraphs(v.sheet()["intro"]):
            doc.text(para)
    elif s.problem.notes and version == "key":
        # The notes of a catalog file say what is asked (and sometimes the book's answers: key only).
        doc.heading(1, "The problem")
        for para in _paragraphs(s.problem.notes):
            doc.text(para)
    else:
        doc.heading(1, "The problem")
        how = ("a static force analysis: no inertia loads" if s.static else "inertia included (d'Alembert)")
        doc.text(f"Find every joint force and the driving {'torque' if s.crank else 'force'} "
                 f"{s.mech.driver.symbol}, {how}, both analytically and graphically.")


def _paragraphs(text: str) -> list[str]:
    return [" ".join(p.split()) for p in text.strip().split("\n\n") if p.strip()]


def _pretty(value) -> str:
    """A value of the problem file as written, in a book's notation (``"7.6 deg"`` → ``7.6°``)."""
    if isinstance(value, str):
        return pretty(value)
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, (int, float)):
        return f"{value:g}"
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
            return f"{_pretty(value['start'])} to {_pretty(value['stop'])}{step}"
        if {"from", "to"} <= value.keys():
            return f"from {_pretty(value['from'])} to {_pretty(value['to'])}"
        return ", ".join(f"{k} = {_pretty(x)}" for k, x in value.items())
    return str(value)


def _given_rows(raw: dict, frame_number: int) -> list[list[str]]:
    """The problem file's data, one row per frame, link, joint, driver and load, in the file's units."""
    rows = []
    if raw.get("gravity") is not None:
        rows.append(["gravity", _pretty(raw["gravity"])])
    frame = raw.get("frame", {})
    if frame.get("points"):
        rows.append([f"frame (link {frame_number})", "; ".join(f"{k} = {_pretty(p)}" for k, p in frame["points"].items())])
    for link in raw.get("links", []):
        parts = [f"{k} = {_pretty(p)}" for k, p in link.get("points", {}).items()]
        for key, label in (("mass", "m"), ("G", "G"), ("I_G", "I_G"), ("k", "k")):
            if key in link:
                parts.append(f"{label} = {_pretty(link[key])}")
        if "shape" in link:
            shape = dict(link["shape"])
            kind = shape.pop("type", "shape")
            parts.append(f"{kind} " + _pretty(shape) if shape else kind)
        name = f"link {link.get('number', '?')}" + (f" ({link['name']})" if link.get("name") else "")
        rows.append([name, "; ".join(parts)])
    for j in raw.get("joints", []):
        kind = j.get("type", "joint")
        if kind == "revolute":
            text = f"links {'–'.join(map(str, j.get('links', [])))} at {j.get('point', '?')}"
        elif kind == "prismatic":
            text = (f"slider {j.get('slider')} on guide {j.get('guide')} at {j.get('point')}, guide through "
                    f"{j.get('through')} at {_pretty(j.get('direction', '0 deg'))}")
            if "mu" in j:
                text += f", μ = {_pretty(j['mu'])}"
        else:
            text = "; ".join(f"{k} = {_pretty(x)}" for k, x in j.items() if k != "type")
        rows.append([f"{kind} joint", text])
    d = raw.get("driver", {})
    if d:
        text = "; ".join(f"{k} = {_pretty(x)}" for k, x in d.items() if k not in ("type", "link"))
        kind = f" ({d['type']})" if d.get("type") else ""
        rows.append([f"driver, link {d.get('link', '?')}{kind}", text])
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
        rows.append([f"given, link {link}", "; ".join(f"{k} = {_pretty(x)}" for k, x in values.items())])
    return rows


def _given(doc: _Doc, s: _Subject):
    doc.heading(1, "Given")
    v = s.variant
    if v is not None and v.data:
        doc.table(["your data", "value"], [[f"{g.label} {g.symbol}".strip() if g.label else g.symbol,
                                             g.shown.split(" = ", 1)[1]] for g in v.data], "lr",
                  caption="Your own values (the rest of the data below is the same for everyone)")
    rows = _given_rows(s.raw, s.mech.frame)
    if rows:
        doc.table(["item", "data (units as in the problem file)"], rows, "ll")
    if s.static:
        doc.text("A static analysis: the links' masses play no part (no inertia loads), so none are needed.")
        return
    moving = [s.mech.link(k) for k in s.mech.moving]
    rows = [[f"link {b.number}", M.qty(b.mass, "kg"), M.qty(b.I_G, "kg·m²"),
             M.pair(np.asarray(b.G) * 1e3, "mm")] for b in moving]
    doc.table(["link", ("mass ", M.i("m")), ("inertia about G, ", M.sym("I", "G")), "G in the link's frame"], rows,
              "lrrr", caption="Mass properties used (the file's shapes and radii of gyration worked out: "
                              "I_G = m k², or from the shape)")


def _questions(doc: _Doc, s: _Subject, answers: bool):
    v = s.variant
    sheet = v.key() if answers else v.sheet()
    doc.heading(1, "Questions" if not answers else "Questions and answers")
    rows = []
    for q in sheet["questions"]:
        unit = q["unit"].replace("*", "·").replace("^2", "²") or "no unit"
        tol = f"{100 * q['tolerance']:g} %"
        if q["form"] == "direction":
            tol = "the step of the sweep" if q["part"] == "at" else f"{math.degrees(math.atan(q['tolerance'])):.2g}°"
        row = [q["id"], q["ask"], f"{unit}, within {tol}, {q['points']:g} pt"]
        if answers:
            a = q["answer"]
            row += [a["text"]]
        rows.append(row)
    header = ["id", "question", "unit, tolerance, points"] + (["answer"] if answers else [])
    doc.table(header, rows, "llll" if answers else "lll")
    if answers:
        doc.items([f"{q['id']}: {q['answer']['hint']}" for q in sheet["questions"] if q["answer"].get("hint")])


_CONVENTION: list[Picture] = []


def _convention_picture() -> Picture:
    """The sign convention's drawing: the same in every handout, so drawn once per process (a class's batch)."""
    if not _CONVENTION:
        from graphkin import draw

        _CONVENTION.append(Picture("convention", lambda: draw.draw_sign_convention(), 0.5,
                                   "x right, y up; angles, ω, α and torques positive counter-clockwise", 60))
    return _CONVENTION[0]


def _convention(doc: _Doc, s: _Subject):
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
    doc.items(items)


def _mechanism(doc: _Doc, s: _Subject, c, i: int):
    from graphkin import draw

    label = doc.figure([s.picture(f"mechanism-{i}", lambda: draw.draw_mechanism(c), 0.7,
                                f"the mechanism at {s.where(i)}", 75)],
                       f"The mechanism at {s.where(i)}, drawn to scale, with its centres of mass.")
    doc.text(f"{label} shows the linkage at {s.where(i)}.")


def _pick_point(s: _Subject, link: int) -> str:
    """The point the acceleration of G is taken from: a frame pivot if the link has one, else a shared pin."""
    joints = [j for j in s.mech.joints_of(link) if isinstance(j, Revolute)]
    joints.sort(key=lambda j: (s.mech.frame not in j.links, min(set(j.links) - {link})))
    if joints:
        return joints[0].point
    return next(iter(s.mech.link(link).points))


def _kinematics(doc: _Doc, s: _Subject, entry: dict, i: int):
    kin = s.result.kinematics
    doc.heading(2, "Position of every link" if s.static else "Kinematics")
    what = "position equations" if s.static else "position, velocity and acceleration equations"
    doc.text("The solver locates the links group by group, in closed form: the driver first, then each dyad "
             f"(two links joined to each other and to links already located) or gear pair. Each group's {what}, "
             "with the numbers:")
    groups(doc, kin, i, rates=not s.static)
    doc.text("Every link at once (θ of a link is the angle of its own x-axis, the axis its points are given in):")
    if s.static:
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


def _inertia(doc: _Doc, s: _Subject, entry: dict, c, i: int):
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


def _loads(doc: _Doc, s: _Subject, entry: dict):
    """The external loads at this position, when any of them changes with the position (a table, a sense)."""
    if not any(ld.varies for ld in s.mech.loads):
        return  # the given data already says what they are
    doc.heading(2, "External loads here")
    rows = []
    for ld in entry["loads"]:
        name = M.name(ld["name"]) if ld["name"] else ("P" if "force" in ld else "T")
        if "force" in ld:
            value = (M.polar(M.size_of(ld["force"]), M.angle_of(ld["force"]), "N") if ld["acting"]
                     else M.qty(0.0, "N"))
            rows.append([name, f"link {ld['link']} at {ld['point']}", value])
        else:
            rows.append([name, f"link {ld['link']}", M.qty(ld["torque"], "N·m")])
    doc.table(["load", "on", "value at this position"], rows, "llr",
              caption="Each load at its value here: read off its table, and with the sense the motion gives it")


def _clean(x, scale, rel=1e-12):
    """Values below ``rel`` × ``scale`` set to 0: rounding noise (1e-17 where a lever arm is zero) would hide
    the matrix's structure, as in :meth:`graphkin.analytical.matrix.System.format`."""
    x = np.array(x, dtype=float)
    x[np.abs(x) < rel * max(scale, 1e-300)] = 0.0
    return x + 0.0


def _unknown(name: str) -> list:
    """``"F12x"`` → F₁₂ₓ, ``"N14"`` → N₁₄, ``"T12"`` → T₁₂."""
    return M.sym(name[0], name[1:]) if len(name) > 1 else M.i(name)


def _matrix(doc: _Doc, s: _Subject, entry: dict, i: int):
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


def _system(s: _Subject):
    if not hasattr(s, "_system"):
        s._system = assemble(s.result)
    return s._system


def _forces(doc: _Doc, s: _Subject, entry: dict):
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


def _graphical(doc: _Doc, s: _Subject, entry: dict, c):
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


def _subproblems(doc: _Doc, s: _Subject, entry: dict):
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


def _both_routes(doc: _Doc, s: _Subject, entry: dict):
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


def _blank(doc: _Doc, s: _Subject, c, drawn: bool):
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
def _cycle(doc: _Doc, s: _Subject):
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
    where = lambda p: "—" if p["at"] is None else f"{theta} = {M.fmt(deg(p['at']), 5)}°"
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
