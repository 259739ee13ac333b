"""Variants: each student's own data, drawn from a stable hash, and the answers they imply.

A variant is fixed by (exercise id, student id, course secret): the values are
picked with SHA-256 and integer arithmetic only, so the same student gets the
same data on every machine and every Python or numpy version. The answers are
computed from the data **as the student sees them**: the value strings shown
("135 deg") are the strings the problem is solved with.

A draw that does not assemble, sits near a dead point, or whose graphical
construction fails is never handed out: the next draw (``attempt`` + 1) is
taken instead.
"""

from __future__ import annotations

import hashlib
import json
import math
import re
import unicodedata
from collections import OrderedDict
from dataclasses import dataclass, field, replace
from functools import cached_property, lru_cache

import numpy as np

from graphkin.cycle import sweep
from graphkin.errors import GraphkinError
from graphkin.exercises import designs, drawn_tasks
from graphkin.exercises.exercise import CYCLE_KINDS, MOTION_KINDS, Exercise, Question
from graphkin.exercises.grading import grade_variant
from graphkin.exercises.quantities import _span, expected, message_words, question_data, undefined, value_of, within
from graphkin.exercises.symbols import fill_symbols
from graphkin.graphical import construct_forces, construct_kinematics
from graphkin.graphical.guard import check_forces
from graphkin.graphical.polygons import SLIPS as POLYGON_SLIPS
from graphkin.notation import input_text, unit_text
from graphkin.problem import build_problem
from graphkin.problem.fields import set_field
from graphkin.units import to_si

MAX_ATTEMPTS = 64
"""Draws tried per student before the exercise is declared unusable."""

MAX_STUDENT_CHARS = 100

_SEED_TAG = "graphkin-variant-v1"


def check_student(student) -> str:
    """The student id as used in the seed (stripped), or a clear error.

    An id typed as a whole number (``STUDENT = 231006`` in a notebook, ``student = 231006`` in an answers
    file) is its digits: the same student as ``"231006"``.
    """
    if isinstance(student, int) and not isinstance(student, bool) and 0 <= student < 10**MAX_STUDENT_CHARS:
        student = str(student)
    if not isinstance(student, str) or not student.strip():
        raise GraphkinError(f"student id must be a non-empty text, got {student!r}")
    # The same id typed on any keyboard or pasted from a spreadsheet gives the same data: Unicode NFC
    # (é composed or not) and any run of white space (no-break spaces too) as one space.
    student = " ".join(unicodedata.normalize("NFC", student).split())
    if len(student) > MAX_STUDENT_CHARS or not student.isprintable():
        raise GraphkinError(f"student id must be printable text of at most {MAX_STUDENT_CHARS} characters")
    return student


def draw_index(secret: str, exercise: str, student: str, attempt: int, symbol: str, count: int) -> int:
    """Index in ``range(count)`` for one varied value: SHA-256 of the seed fields, reduced mod ``count``.

    Examples
    --------
    >>> draw_index("", "double_slider_forces", "s001", 0, "x", 21)
    4
    """
    text = "\x1f".join((_SEED_TAG, secret, exercise, student, str(attempt), symbol))
    digest = hashlib.sha256(text.encode("utf-8")).digest()
    return int.from_bytes(digest[:8], "big") % count


@lru_cache(maxsize=4096)
def pretty(value: str) -> str:
    """A value string as a book prints it: ``"135 deg"`` → ``"135°"``, ``"8.3 rad/s^2"`` → ``"8.3 rad/s²"``.

    Kept for each string (a class's sheets show the same few dozen values again and again)."""
    m = re.match(r"^(\S+)\s+deg$", value)
    if m:
        return f"{m[1]}°"
    return unit_text(value)


@dataclass(frozen=True)
class Given:
    """One value of a student's data: ``θ12 = 135°``."""

    symbol: str
    label: str
    field: tuple[str, ...]
    value: str

    @property
    def shown(self) -> str:
        return f"{self.symbol} = {pretty(self.value)}"


class Solved:
    """A problem's results at the exercise's position or over its cycle, computed when first asked for."""

    def __init__(self, problem, exercise: Exercise, Cs: float | None, slip: str | None = None, data: dict | None = None):
        self.problem = problem
        self.data = data
        """The problem file's data the problem was built from (a design's study varies it)."""
        self.exercise = exercise
        self.Cs = Cs
        self.answers: dict = {}
        """Each question's :class:`~graphkin.exercises.quantities.Expected`, by question id, once computed."""
        self.texts: dict = {}
        """The sheet's texts for these values (the statement and each question filled in, each tolerance), once
        written: every student who drew them gets the same."""
        # A slip in reading the polygons ("no_normal", "coriolis_reversed", "image_misplaced"): the motion
        # quantities are those a student who made it reads off.
        self.slip = slip
        self.drawings: dict = {}
        """Each drawn question's task, targets and words (:func:`graphkin.exercises.drawn_tasks.keyed`), by question
        id, once made."""

    def drawn(self, q: Question) -> dict:
        """A drawn question's task, targets and words on this draw (:func:`graphkin.exercises.drawn_tasks.keyed`)."""
        if q.id not in self.drawings:
            self.drawings[q.id] = drawn_tasks.keyed(self, q)
        return self.drawings[q.id]

    @cached_property
    def result(self):
        return self.problem.solve()

    @cached_property
    def construction(self):
        # Checked against the analytical route: a value that disagrees is never keyed (graphical/guard.py).
        return check_forces(self.result, construct_forces(self.result.kinematics, 0), 0)

    @cached_property
    def span(self) -> float:
        """The mechanism's size at the position: the largest distance between two points of the construction [m]
        (asked for by the draw's check and by every question's tolerance floor)."""
        return _span(self.construction)

    @cached_property
    def motion(self):
        """The velocity and acceleration polygons at the exercise's position (as the slip draws them)."""
        slip = self.slip if self.slip in POLYGON_SLIPS else None
        return construct_kinematics(self.result.kinematics, 0, slip=slip)

    @cached_property
    def cycle(self):
        return sweep(self.problem, self.exercise.positions)

    @cached_property
    def flywheel(self):
        return self.cycle.flywheel(self.Cs)

    @cached_property
    def jfi(self):
        return self.cycle.joint_force_index()

    @cached_property
    def design(self) -> designs.Chosen:
        """The key and the keyed slips of the exercise's design question (:func:`graphkin.exercises.designs.choose`)."""
        return designs.choose(self.exercise.design, self.data, n=self.exercise.positions, Cs=self.Cs)


@dataclass(frozen=True)
class Variant:
    """One student's exercise: their data, and (for the key and the grader) the solved problem.

    Attributes
    ----------
    exercise : Exercise
    student : str
    attempt : int
        Which draw this is (0 unless earlier draws were unusable).
    data : tuple of Given
    problem : graphkin.problem.Problem
        The base problem with the student's values.
    Cs : float or None
    """

    exercise: Exercise
    student: str
    attempt: int
    data: tuple[Given, ...]
    problem: object
    Cs: float | None
    solved: Solved = field(repr=False, compare=False)
    _memo: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def construction(self):
        """The graphical construction of the student's position (:class:`graphkin.graphical.Construction`)."""
        return self.solved.construction

    def altered(self, slip: str) -> Solved | None:
        """The same variant solved as a student who made ``slip`` would (None if it cannot apply)."""
        if ("slip", slip) not in self._memo:
            self._memo["slip", slip] = _altered(self, slip)
        return self._memo["slip", slip]

    def expected(self, q: Question):
        """The answer to question ``q`` (:class:`graphkin.exercises.quantities.Expected`), computed once."""
        # On the solved draw, not the variant: classmates who drew the same values share it.
        answers = self.solved.answers
        if q.id not in answers:
            answers[q.id] = expected(self, q)
        return answers[q.id]

    def slip_value(self, q: Question, slip: str):
        """The answer to ``q`` of a student who made ``slip`` (a re-solved one: ``rpm_as_rad_s``,
        ``no_inertia_torque``, ``no_inertia_force``); None where the slip does not apply or does not solve."""
        if ("slip value", q.id, slip) not in self._memo:
            value = None
            solved = self.altered(slip)
            if solved is not None:
                try:
                    value = value_of(solved, q)
                except Exception:  # the altered problem may not solve (e.g. a dead point at the wrong speed)
                    value = None
                if isinstance(value, float) and not math.isfinite(value):
                    value = None
            self._memo["slip value", q.id, slip] = value
        return self._memo["slip value", q.id, slip]

    def drawn(self, q: Question) -> dict:
        """A drawn question's task, targets, tolerance and words (:func:`graphkin.exercises.drawn_tasks.keyed`)."""
        return self.solved.drawn(q)

    def words(self, q: Question) -> dict:
        """The words of ``q``'s grading messages (:func:`graphkin.exercises.quantities.message_words`)."""
        if ("words", q.id) not in self._memo:
            self._memo["words", q.id] = message_words(self.solved, q, self.expected(q))
        return self._memo["words", q.id]

    def sheet(self) -> dict:
        """The student's exercise as plain data: the statement, their data and the questions; no answers."""
        texts = self.solved.texts
        if not texts:
            # On the solved draw, not the variant: classmates who drew the same values share them. A graphical
            # question's tolerance reads the worksheet's scales off the construction.
            texts["intro"] = _fill(self.exercise.intro, self.data)
            for q in self.exercise.questions:
                texts["ask", q.id], texts["within", q.id] = _fill(q.ask, self.data), within(q, self.solved)
        return {"exercise": self.exercise.id, "title": self.exercise.title, "source": self.exercise.source,
                "student": self.student, "intro": texts["intro"], "draw": self.exercise.draw,
                "data": [{"symbol": g.symbol, "label": g.label, "value": g.value, "shown": g.shown}
                         for g in self.data],
                "questions": [{**question_data(q), "ask": texts["ask", q.id], "within": texts["within", q.id]}
                              for q in self.exercise.questions]}

    def key(self) -> dict:
        """The sheet with every answer: its value in SI and as the book prints it, and the tolerance."""
        out = self.sheet()
        out["attempt"] = self.attempt
        for q, entry in zip(self.exercise.questions, out["questions"]):
            e = self.expected(q)
            entry["answer"] = {"text": e.text, "si": e.si_data(), "unit_si": e.si_unit, "hint": e.hint}
            if q.kind == "drawing":  # the right drawing itself, as a student's answer holds it
                entry["answer"]["drawing"] = json.dumps(drawn_tasks.right_drawing(self.drawn(q)), ensure_ascii=False)
        return out

    def grade(self, answers) -> dict:
        """Grade a student's answers (a mapping of question id to text); see :func:`graphkin.exercises.grade`."""
        return grade_variant(self, answers)


def _fill(text: str, data) -> str:
    """Replace ``{symbol}`` in an exercise's statement by the student's value (``{{`` and ``}}`` by a brace)."""
    return fill_symbols(text, {g.symbol: pretty(g.value) for g in data})


def _choose(ex: Exercise, student: str, secret: str, attempt: int) -> tuple[Given, ...]:
    return tuple(Given(v.symbol, v.label, v.field, v.values[draw_index(secret, ex.id, student, attempt, v.symbol,
                                                                      len(v.values))])
                 for v in ex.vary)


def _build(ex: Exercise, data: tuple[Given, ...]):
    base = dict(ex.base)
    Cs = ex.Cs
    for g in data:
        for f in g.field:
            if f == "flywheel.Cs":
                Cs = to_si(g.value, "dimensionless", field=f"vary.{g.symbol}", file=ex.file)
            else:
                set_field(base, f, g.value, copy=True)
    # Named by its data, not by a student: every student who draws these values shares the problem.
    problem = build_problem(base, file=f"{ex.id} ({', '.join(g.shown for g in data)})")
    return problem, Cs, base


def _unusable(ex: Exercise, solved: Solved) -> str | None:
    """Why a draw cannot be handed out (None when it can)."""
    if ex.cycle:
        cycle = solved.cycle
        if not cycle.valid.all():
            bad = int(np.flatnonzero(~cycle.valid)[0])
            return f"{input_text(cycle.q[bad], True, digits=4)}: {cycle.analysis.reason(bad)} (the crank cannot turn fully)"
        if not cycle.closed:
            return "the positions do not make a whole turn"
        if any(q.kind in ("flywheel_E", "flywheel_I") for q in ex.questions) and not solved.flywheel.E > 0:
            return "the driving torque is constant, so there is no flywheel to size"
        if any(q.kind == "jfi_peak" for q in ex.questions) and not math.isfinite(solved.jfi.peak.value):
            return "the joint-force index is not defined (no external load)"
        if ex.design is not None and solved.design.key is None:
            return solved.design.why
    if all(q.kind in CYCLE_KINDS for q in ex.questions):
        return None
    r = solved.result
    if not r.valid[0]:
        return r.reason(0)
    ratio = _speed_ratio(solved.problem, _span_of(solved), r.kinematics)
    if ratio > ex.max_speed_ratio:
        return (f"a point moves {ratio:.0f} times as fast as the input: the linkage is near a dead point")
    c = solved.construction
    if not c.valid:
        _refuse_disagreement(ex, solved, c)
        return f"the graphical construction fails: {c.reason}"
    if c.warnings:
        return f"the graphical construction is not clean: {c.warnings[0]}"
    loads = [math.hypot(*v["F"]) for v in c.inertia.values()]
    loads += [math.hypot(*a.vector) for arrows in c.external.values() for a in arrows]
    largest = max([math.hypot(*F) for F in c.forces.values()] + [0.0])
    if max(loads + [0.0]) > 0 and largest > ex.max_force_ratio * max(loads):
        return (f"the joint forces are {largest / max(loads):.0f} times the largest load: the linkage is near a dead "
                "point")

    if any(q.kind in MOTION_KINDS or q.space in ("velocity", "acceleration") for q in ex.questions) \
            and not solved.motion.valid:
        _refuse_disagreement(ex, solved, solved.motion)
        if any(q.space in ("velocity", "acceleration") for q in ex.questions):
            return f"the velocity and acceleration polygons cannot be drawn: {solved.motion.reason}"
    for q in ex.questions:
        if q.kind not in CYCLE_KINDS:
            why = undefined(solved, q)
            if why:
                return why
    return None


def _refuse_disagreement(ex: Exercise, solved: Solved, c) -> None:
    """Stop making the exercise where the construction ``c`` disagrees with the analytical route (its
    ``disagreement``): drawing other data would hide a fault that every student drawing these values would be graded
    against."""
    if c.disagreement:
        raise GraphkinError(f"exercise {ex.id}: no key is made for the data {solved.problem.name}: {c.reason}; this "
                            "is a fault of graphkin's, please report it with the exercise file")


def _span_of(solved: Solved) -> float:
    return solved.span if solved.construction.valid else math.nan


def _speed_ratio(problem, span: float, kinematics) -> float:
    """The fastest point of the linkage at unit input rate, over the input's own speed (crank: ω·span).

    Near a dead point some link moves without bound for a finite input rate
    (v ∝ 1/sin μ, μ the transmission angle), so this ratio flags it whatever
    the loads are; inertia loads grow there too, so a force ratio alone cannot.
    """
    if problem.given or not math.isfinite(span) or span <= 0:
        return 0.0
    if np.all(problem.q_dot != 0):
        # Velocities are linear in the input rate: the solved kinematics divided by it are those at unit rate.
        kin, rate = kinematics, np.abs(problem.q_dot)
    else:
        unit = replace(problem, q_dot=np.ones_like(problem.q_dot), q_ddot=np.zeros_like(problem.q_ddot))
        kin, rate = unit.kinematics(), 1.0
    mech = problem.mechanism
    # The fastest named point is the kinematics' speed scale (found once: friction asks for it too).
    fastest = float(np.max(kin.speed_scale / rate))
    for link in mech.moving:
        fastest = max(fastest, float(np.max(np.abs(kin.omega[link]) / rate)) * span)
    reference = span if mech.driver.crank else 1.0
    return fastest / reference


CACHE_SIZE = 1024
"""Variants kept per process (a roster's make, key and grade, or a notebook's checks, solve each once)."""

_CACHE: OrderedDict = OrderedDict()


def make_variant(ex: Exercise, student: str, secret: str = "") -> Variant:
    """The student's variant (made once per process, then reused; see :data:`CACHE_SIZE`).

    Variants are immutable, so one made for a sheet serves the key and the
    grader. A cached variant keeps every question's answer but not the arrays
    of a whole cycle, which are recomputed if a slip needs them.
    """
    student = check_student(student)
    if not isinstance(secret, str):
        raise GraphkinError("the course secret must be text")
    # By content, not identity: a worker process receives a fresh copy of the exercise with every chunk.
    key = (ex.fingerprint or id(ex), student, secret)
    v = _CACHE.get(key)
    if v is not None and (v.exercise is ex or v.exercise.fingerprint == ex.fingerprint != ""):
        _CACHE.move_to_end(key)
        return v
    v = _make_variant(ex, student, secret)
    for q in ex.questions:
        v.expected(q)
    for name in ("cycle", "flywheel", "jfi"):
        v.solved.__dict__.pop(name, None)
    _CACHE[key] = v
    if len(_CACHE) > CACHE_SIZE:
        _CACHE.popitem(last=False)
    return v


def _make_variant(ex: Exercise, student: str, secret: str = "") -> Variant:
    """The student's variant: the first usable draw for (exercise id, student id, secret).

    Raises
    ------
    GraphkinError
        If the student id is empty or too long, or no draw in :data:`MAX_ATTEMPTS`
        can be handed out (the message says why the last one could not).
    """
    student = check_student(student)
    if not isinstance(secret, str):
        raise GraphkinError("the course secret must be text")
    why = ""
    for attempt in range(MAX_ATTEMPTS):
        data = _choose(ex, student, secret, attempt)
        solved, why = _draw(ex, data)
        if why is None:
            return Variant(ex, student, attempt, data, solved.problem, solved.Cs, solved)
        if not ex.vary:
            break
    raise GraphkinError(f"exercise {ex.id}: no usable data for student {student!r} in {MAX_ATTEMPTS} draws "
                        f"(the last: {why}); narrow the ranges in [vary]")


_DRAWS: OrderedDict = OrderedDict()
"""Solved draws kept per process, by exercise and values (:data:`CACHE_SIZE` of them)."""


def draw_shard(ex: Exercise, student: str, secret: str, shards: int) -> int:
    """Which of ``shards`` workers should make ``student``'s variant: the same for the same first draw.

    Students whose first draw has the same values go to the same worker, which
    then solves that draw once for all of them (:func:`_draw`); a student id that
    cannot be read goes to the first, which reports it.
    """
    try:
        values = "\x1f".join(g.value for g in _choose(ex, check_student(student), secret, 0))
    except GraphkinError:
        return 0
    return int.from_bytes(hashlib.sha256(values.encode("utf-8")).digest()[:8], "big") % shards


def _draw(ex: Exercise, data: tuple[Given, ...]) -> tuple[Solved, str | None]:
    """The draw ``data`` solved, and why it cannot be handed out (None when it can), made once per process.

    A draw is fixed by its values alone, whoever drew it: an exercise varying two
    values over 23 and 13 choices has 299 draws, so most of a class of 1000
    shares one with a classmate and is solved and checked once.
    """
    key = (ex.fingerprint or id(ex), tuple(g.value for g in data))
    hit = _DRAWS.get(key)
    if hit is not None and (hit[0].exercise is ex or hit[0].exercise.fingerprint == ex.fingerprint != ""):
        _DRAWS.move_to_end(key)
        return hit
    problem, Cs, base = _build(ex, data)
    solved = Solved(problem, ex, Cs, data=base)
    hit = (solved, _unusable(ex, solved))
    _DRAWS[key] = hit
    if len(_DRAWS) > CACHE_SIZE:
        _DRAWS.popitem(last=False)
    return hit


def _altered(v: Variant, slip: str) -> Solved | None:
    p = v.problem
    moving = p.mechanism.moving
    if slip == "no_inertia_torque":
        given = dict(p.given) | {(k, "alpha"): 0.0 for k in moving}
        return Solved(replace(p, given=given), v.exercise, v.Cs)
    if slip == "no_inertia_force":
        given = dict(p.given) | {(k, "a_G"): (0.0, 0.0) for k in moving}
        return Solved(replace(p, given=given), v.exercise, v.Cs)
    if slip in ("no_normal", "coriolis_reversed", "image_misplaced"):
        solved = Solved(p, v.exercise, v.Cs, slip)
        solved.__dict__["result"] = v.solved.result  # the positions and input rates are the student's own
        return solved
    if slip in designs.SLIPS:  # the same study, read as a student who made the slip chooses
        solved = Solved(p, v.exercise, v.Cs, slip, v.solved.data)
        solved.__dict__["design"] = v.solved.design
        return solved
    if slip == "rpm_as_rad_s":
        speed = next((g.value for g in v.data if "driver.omega" in g.field), None) or \
            v.exercise.base.get("driver", {}).get("omega")
        if not isinstance(speed, str) or not speed.strip().endswith("rpm") or p.given \
                or not p.mechanism.driver.crank or len(set(p.q_dot)) > 1:
            return None
        return Solved(p.at_speed(float(p.q_dot[0]) * 30 / math.pi), v.exercise, v.Cs)
    raise KeyError(slip)
