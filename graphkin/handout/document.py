"""A handout as it is built: the blocks in order (:class:`Doc`), and what it is about (:class:`Subject`).

:func:`subject` reads a problem or a student's exercise once, solves it, and
keeps the data (``graphkin solve --json``'s, :func:`graphkin.report.solution`)
and the constructions that every section writes from.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np

from graphkin import catalog, exercises
from graphkin.errors import GraphkinError
from graphkin.exercises.exercise import CYCLE_KINDS
from graphkin.exercises.variants import Variant
from graphkin.graphical import construct_forces, construct_kinematics
from graphkin.graphical.guard import check_forces
from graphkin.handout import maths as M
from graphkin.handout.figures import Picture
from graphkin.notation import input_text, typeset
from graphkin.problem.fields import set_field
from graphkin.report import solution
from graphkin.units import to_si
from graphkin.units.systems import SI, UnitSystem

DEFAULT_CS = 0.05
"""Coefficient of speed fluctuation for a whole cycle's flywheel when none is given (Norton: 0.01–0.05)."""


def runs(x) -> list:
    """A cell or list item as runs: a str or a math node is one run, a tuple holds several. A number's sign in
    the text is a true minus (captions are written for terminals too, with a hyphen-minus)."""
    return [typeset(r) if isinstance(r, str) else r for r in (x if isinstance(x, tuple) else (x,))]


class Doc:
    """Collects the blocks in order and numbers the figures."""

    def __init__(self):
        self.blocks: list[dict] = []
        self.figures = 0

    def heading(self, level: int, text: str):
        self.blocks.append({"kind": "heading", "level": level, "text": typeset(text)})

    def text(self, *parts):
        # A paragraph that ends with a colon introduces what follows: a page break between them would orphan it.
        last = parts[-1] if parts else ""
        self.blocks.append({"kind": "text", "runs": runs(parts),
                            "keep": isinstance(last, str) and last.rstrip().endswith(":")})

    def items(self, items, ordered=False, small=False):
        """A list; ``small``: in a smaller type (a long list of steps beside the figures that draw them)."""
        self.blocks.append({"kind": "list", "items": [runs(r) for r in items], "ordered": ordered, "small": small})

    def table(self, header, rows, align=None, caption=None, boxed=False, tall=False, small=False, wide=False):
        """``boxed``: framed, as a book boxes its answers; ``tall``: rows tall enough to write an answer in;
        ``small``: a smaller type, for a table of many columns; ``wide``: the text's width, the columns after the
        first sharing it (cells wide enough to write a value ∠ its direction in)."""
        self.blocks.append({"kind": "table", "header": [runs(h) for h in header],
                            "rows": [[runs(c) for c in r] for r in rows],
                            "align": align or "l" * len(header), "caption": typeset(caption) if caption else caption,
                            "boxed": boxed, "tall": tall, "wide": wide,
                            "small": small})

    def equation(self, *lines, small=False, stacked=False):
        """Displayed maths, a line each; ``small``: in a smaller type (a wide matrix); ``stacked``: a set of
        equations read one after another (each link's ΣF = 0 and ΣM = 0), set close together from the left."""
        self.blocks.append({"kind": "equation", "lines": list(lines), "small": small, "stacked": stacked})

    def figure(self, pictures, caption: str, *, inline: bool = False) -> str:
        """Add a figure; returns its name (``"Figure 3"``) for the text to refer to. ``inline``: where it stands in
        the text, never floated to a page's top or foot (a key's last polygons, which its answers follow)."""
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
        # The caption as text (alternative text, tests) and as runs, each symbol with its subscript (a_G3, F23).
        self.blocks.append({"kind": "figure", "pictures": list(pictures), "inline": inline,
                            "caption": f"{label}. {typeset(caption)}", "label": label,
                            "runs": runs((f"{label}. ", *M.prose(caption)))})
        return label

    def space(self, height: float, label: str, math=None, width: float | None = None):
        """Room to draw in by hand, ``height`` [mm] tall and ``width`` [mm] wide (None: the text width)."""
        self.blocks.append({"kind": "space", "height": height, "label": label, "math": math, "width": width})

    def pagebreak(self):
        self.blocks.append({"kind": "pagebreak"})

    def flush(self):
        """Every drawing named so far placed before what follows (a key's answers after the polygons that find
        them, though the polygons float)."""
        self.blocks.append({"kind": "flush"})


# -- what the handout is about ---------------------------------------------------------
class Subject:
    """A problem (or a student's variant of an exercise) with everything solved once."""

    def __init__(self, problem, raw: dict, *, variant=None, at=None, Cs=None, units: UnitSystem | None = None):
        self.problem = problem
        self.units = SI if units is None else units  # the answers' units; the working stays in SI
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

    def qty(self, x: float, kind: str) -> list:
        """An answer ``x`` (SI) of ``kind`` in the handout's units: ``6117 lbf·ft``."""
        u = self.units
        return M.qty(u.show(x, kind), u.symbol(kind))

    def polar(self, v, kind: str = "force") -> list:
        """A vector answer (SI) in the handout's units, in polar form: ``8313 lbf ∠ −7.39°``."""
        k = self.units.scales[kind]
        return M.polar(k * M.size_of(v), M.angle_of(v), self.units.symbol(kind))

    def pair(self, v, kind: str = "force") -> list:
        """A vector answer (SI) in the handout's units, by components."""
        k = self.units.scales[kind]
        return M.pair([k * float(v[0]), k * float(v[1])], self.units.symbol(kind))

    def construction(self, i: int):
        """The graphical construction at position ``i`` (None where the linkage has no solution), built once."""
        key = f"construction-{i}"
        if key not in self.__dict__:
            # Checked against the analytical route before it is drawn or written (graphical/guard.py).
            self.__dict__[key] = (check_forces(self.result, construct_forces(self.result.kinematics, i), i)
                                  if self.result.valid[i] else None)
        return self.__dict__[key]

    def motion(self, i: int):
        """The velocity and acceleration polygons at position ``i`` (None where the linkage has no solution), built
        once (:func:`graphkin.graphical.construct_kinematics`)."""
        key = f"motion-{i}"
        if key not in self.__dict__:
            self.__dict__[key] = construct_kinematics(self.result.kinematics, i) if self.result.valid[i] else None
        return self.__dict__[key]

    def data(self) -> dict:
        """:func:`graphkin.report.solution` of the worked positions, graphical route included (made once)."""
        if "_data" not in self.__dict__:
            graphical = [None] * self.n
            for i in self.worked():
                graphical[i] = self.construction(i)
            self._data = solution(self.problem, self.result, graphical)
        return self._data

    def picture(self, key: str, draw, width: float = 1.0, alt: str = "", height: float = 80.0,
                natural=False) -> Picture:
        """The picture named ``key``, made once: a student's sheet and key share their drawings."""
        if key not in self._pictures:
            self._pictures[key] = Picture(key, draw, width, alt, height, natural)
        return self._pictures[key]

    def worked(self) -> list[int]:
        """The positions worked out in full: each one given, or over a cycle the design case.

        Over a whole cycle the position of the largest |driving torque| (or
        force) among the file's own positions is worked out: the one a
        designer sizes the parts for. An exercise's key works out what its
        questions ask: its position (the first of the problem's), or none
        when every question is about the whole cycle.
        """
        r = self.result
        v = self.variant
        if v is not None:
            return [] if all(q.kind in CYCLE_KINDS for q in v.exercise.questions) else [0]
        if not self.whole_cycle:
            return list(range(self.n))
        effort = np.where(r.valid, np.abs(r.effort), -np.inf)
        return [int(np.argmax(effort))] if np.isfinite(effort).any() else [0]

    @property
    def cycle_asked(self) -> bool:
        """Whether the handout works out the whole cycle: a problem given over one, an exercise that asks about it."""
        if not (self.whole_cycle and self.crank):
            return False
        return self.variant is None or self.variant.exercise.cycle

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


def subject(source, *, student=None, secret="", at=None, Cs=None, units: UnitSystem | None = None):
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
        return Subject(v.problem, raw, variant=v, Cs=Cs, units=units)
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
    return Subject(problem, _read_raw(source), at=at, Cs=Cs, units=units)


def _is_exercise(path) -> bool:
    try:
        return "questions" in tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError, UnicodeDecodeError):
        return False
