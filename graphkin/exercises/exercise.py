"""Exercise files: a base problem, the data that vary per student, and the questions.

An exercise is TOML beside the problem files (format: ``docs/exercises.md``).
Reading one checks every field and names the file and field at fault, as
problem files do; the base problem is read too, so an exercise that cannot
be solved fails when it is loaded, not when the first student asks.
"""

from __future__ import annotations

import hashlib
import re
import tomllib
from dataclasses import dataclass
from decimal import Decimal, InvalidOperation
from pathlib import Path

from graphkin import catalog
from graphkin.errors import GraphkinError, ProblemFileError
from graphkin.exercises import designs
from graphkin.exercises.drawn_tasks import DRAW_KINDS, SPACE_OF
from graphkin.exercises.symbols import symbol_problem
from graphkin.files import read_text
from graphkin.model import Prismatic
from graphkin.model.names import parse_force_name
from graphkin.problem import FieldReader, build_problem
from graphkin.problem.fields import missing, set_field
from graphkin.units import to_si

_TOP = {"title", "source", "problem", "intro", "route", "vary", "questions", "partial", "positions", "flywheel",
        "reveal", "max_force_ratio", "max_speed_ratio", "draw", "decimal_comma", "feedback", "design"}
_VARY = {"field", "from", "to", "step", "values", "label"}
_QUESTION = {"id", "ask", "find", "part", "unit", "tolerance", "floor", "points", "route"}
# A drawn question (find = "drawing"): what is drawn, and the link or the point it is about.
_DRAWN = {"id", "ask", "find", "draw", "link", "point", "points"}
_FLYWHEEL = {"Cs"}

#: What the feedback on a wrong answer says (the exercise file's ``feedback``): ``"parts"`` (the default) names the
#: slip, else which part is wrong (sign or sense, size or direction, a size more than ten times off), never how
#: far off; ``"distance"`` says how far off too (%, degrees, mm), from which the answer follows in one more try.
FEEDBACK = ("parts", "distance")

#: Slips the grader can diagnose, with the share of the question's points each earns by default.
SLIPS: dict[str, float] = {
    "sign": 0.5,            # F_ji given for F_ij, CW for CCW
    "opposite": 0.5,        # a direction off by 180°
    "power_of_ten": 0.5,    # N·mm read as N·m, kN as N: ×10^±3 or ×10^±6
    "degrees_radians": 0.5,  # an angle in radians written as degrees, or the reverse
    "rpm_as_rad_s": 0.25,   # the speed in rpm used as if it were rad/s
    "no_inertia_torque": 0.25,  # −I_G α left out
    "no_inertia_force": 0.25,   # −m a_G left out
    "wrong_side": 0.5,      # the inertia resultant offset by h to the wrong side of G
    "swapped": 0.5,         # a vector's x and y components swapped (its angle measured clockwise from +y)
    "angle_from_y": 0.5,    # a vector's angle measured from +y instead of +x
    "clockwise": 0.5,       # a vector's angle measured clockwise from +x
    "direction": 0.25,      # a vector's size right, its direction wrong
    "dimension": 0.0,       # a unit of another quantity (J for a torque, N for N·m)
    "no_normal": 0.25, "coriolis_reversed": 0.25, "image_misplaced": 0.25,  # polygons: no ω² r, 2ωv reversed, g′ amiss
    # Drawn questions (graphkin.exercises.drawn_tasks): the slips a drawing shows.
    "through_G": 0.25,      # the inertia resultant drawn through G (its couple left out)
    "scale_factor": 0.25,   # a length laid off at ×10 or ÷10
    "wrong_member": 0.0,    # a member that is not two-force taken as one
    "wrong_order": 0.5,     # a polygon closed with its two unknown directions in the other order
    "sense_reversed": 0.5,  # a vector drawn with its sense reversed
    "normal_outward": 0.25,  # a normal component ω²r drawn away from the centre
    **designs.SLIPS,  # a design: the cheapest without the limits, the best for the limit (graphkin.exercises.designs)
}

# What a question may ask for (``find``), with the parts it allows; the first part is the default.
# Joint forces and the driver are named as in the results (F23, G14, T12 ...), see :func:`_kind_of`.
_PARTS = {
    "force": ("vector", "magnitude", "direction", "x", "y"),
    "driver_torque": ("value",),
    "driver_force": ("value",),
    "inertia_force": ("vector", "magnitude", "direction", "x", "y"),
    "inertia_torque": ("value",),
    "h": ("magnitude", "point"),
    "concurrency": ("point",),
    "peak_torque": ("value", "at"),
    "lowest_torque": ("value", "at"),
    "average_torque": ("value",),
    "peak_force": ("magnitude", "at"),
    "flywheel_E": ("value",),
    "flywheel_I": ("value",),
    "jfi_peak": ("value", "at"), "omega": ("value",), "alpha": ("value",),
    "a_G": ("magnitude", "vector", "direction", "x", "y"), "coriolis": ("magnitude", "vector", "direction", "x", "y"),
    **dict.fromkeys(designs.DESIGN_KINDS, ("value",)),
}
# Quantities read off the velocity and acceleration polygons (graphkin.graphical.construct_kinematics), and their dimension.
MOTION_KINDS = {"omega": "angular_velocity", "alpha": "angular_acceleration", "a_G": "acceleration", "coriolis": "acceleration"}
# Quantities over the whole cycle (the exercise's problem is swept, not solved at one position).
# A design (``find = "design"``) is chosen from a study of the cycle of every value of a grid: a cycle kind too.
CYCLE_KINDS = {"peak_torque", "lowest_torque", "average_torque", "peak_force", "flywheel_E", "flywheel_I",
               "jfi_peak"} | designs.DESIGN_KINDS

# Default units a bare number is read in, by (kind, part): the units the books print.
_DEFAULT_UNIT = {
    "force": "N", "driver_force": "N", "inertia_force": "N", "peak_force": "N",
    "driver_torque": "N*m", "inertia_torque": "N*m", "peak_torque": "N*m", "lowest_torque": "N*m",
    "average_torque": "N*m", "h": "mm", "concurrency": "mm", "flywheel_E": "J", "flywheel_I": "kg*m^2",
    "jfi_peak": "", "omega": "rad/s", "alpha": "rad/s^2", "a_G": "m/s^2", "coriolis": "m/s^2",
    **{f"design_{d}": unit for d, unit in designs.DIMENSIONS.items()},
}

_NUMBER_UNIT = re.compile(r"^\s*([+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?)\s*(.*?)\s*$")
_MAX_GRID = 10_000


@dataclass(frozen=True)
class Vary:
    """One value that differs from student to student.

    Attributes
    ----------
    symbol : str
        What the student sees, e.g. ``"θ12"``.
    field : tuple of str
        Where it goes: dotted paths in the problem file (``"driver.theta"``,
        ``"links[1].mass"``, ``"loads[0].force.magnitude"``) or ``"flywheel.Cs"``;
        several paths take the same value (the cutting force on both blades).
    values : tuple of str
        Every value it may take, as written in the file (``"135 deg"``).
    label : str
        Words for it (``"crank angle"``).
    """

    symbol: str
    field: tuple[str, ...]
    values: tuple[str, ...]
    label: str = ""


@dataclass(frozen=True)
class Question:
    """One thing the student finds.

    Attributes
    ----------
    id : str
        Key of the answer (``"F23"``, ``"T12"``).
    ask : str
        The question as the student reads it.
    find : str
        What is asked: a force name (``"F23"``), the driver (``"T12"``), ``"F3i"``,
        ``"T3i"``, ``"h3"``, ``"I3"``, or a cycle quantity (``"peak_torque"``, ...).
    kind : str
        What ``find`` names (a key of ``_PARTS``).
    link : int or None
        The link of ``F3i``, ``T3i``, ``h3``, ``I3``.
    part : str
        ``"vector"``, ``"magnitude"``, ``"direction"``, ``"x"``, ``"y"``, ``"value"``,
        ``"point"`` or ``"at"`` (where a peak is).
    unit : str
        The unit a bare number is read in and the key is printed in (pint spelling).
    tolerance : float
        Relative tolerance for full marks.
    floor : float or None
        Absolute floor [SI] for values that are zero or nearly so (None: 0.1 % of
        the largest value of the same kind in the variant).
    points : float
    route : str
        ``"analytical"`` or ``"graphical"`` (measured off a drawn polygon).
    draw : str
        A drawn question's kind (:data:`graphkin.exercises.drawn_tasks.DRAW_KINDS`), ``""`` for the others
        (whose ``kind`` is then ``"drawing"`` and ``part`` the same as ``draw``).
    point : str
        The point whose image a velocity or acceleration step finds (``"B"``), ``""`` for the others.
    """

    id: str
    ask: str
    find: str
    kind: str
    link: int | None
    part: str
    unit: str
    tolerance: float
    floor: float | None
    points: float
    route: str
    draw: str = ""
    point: str = ""

    @property
    def space(self) -> str:
        """The space a drawn question is drawn in (``"mechanism"``, ``"force"``, ``"velocity"``,
        ``"acceleration"``); ``""`` for the others."""
        return SPACE_OF.get(self.draw, "")


@dataclass(frozen=True)
class Exercise:
    """An exercise read from its file.

    Attributes
    ----------
    id : str
        Catalog name or file stem; part of every variant's seed.
    title, source, intro : str
    problem : str
        The base problem: a catalog name, or a path (relative paths from the exercise file).
    base : dict
        The base problem file's data (TOML already read).
    vary : tuple of Vary
    questions : tuple of Question
    partial : dict of str to float
        Share of a question's points each slip earns (:data:`SLIPS` with the file's changes).
    positions : int or None
        Positions over the cycle for cycle questions (None: the problem's own).
    Cs : float or None
        Coefficient of speed fluctuation for flywheel questions.
    reveal : bool
        Whether grading shows the expected value of a wrong answer.
    max_force_ratio : float
        A variant whose largest joint force exceeds this many times the largest
        load (inertia forces included) is near a dead point and never handed out.
    max_speed_ratio : float
        Nor is one where a point moves faster than this many times the input
        (the crank pin's speed ω·span, or the driving slider's speed).
    draw : bool
        Whether the student is given the free bodies drawn to scale (graphical exercises).
    decimal_comma : bool
        Whether answers may use a decimal comma (``"1,29 kN"``); a comma that could separate
        thousands (``"1,352"``) is refused with a sentence either way.
    feedback : str
        What the feedback on a wrong answer says: one of :data:`FEEDBACK`.
    file : str
    fingerprint : str
        SHA-256 of the id, the exercise file and the base problem file: two
        Exercise objects with the same fingerprint make the same variants.
    text : str
        The exercise file's text, as read (an export carries it).
    base_text : str
        The base problem file's text.
    """

    id: str
    title: str
    source: str
    intro: str
    problem: str
    base: dict
    vary: tuple[Vary, ...]
    questions: tuple[Question, ...]
    partial: dict
    positions: int | None
    Cs: float | None
    reveal: bool
    max_force_ratio: float
    max_speed_ratio: float
    draw: bool
    file: str
    fingerprint: str = ""
    text: str = ""
    base_text: str = ""
    decimal_comma: bool = True
    feedback: str = "parts"
    design: designs.DesignTable | None = None

    @property
    def cycle(self) -> bool:
        """Whether any question needs the whole cycle."""
        return any(q.kind in CYCLE_KINDS for q in self.questions)

    def question(self, qid: str) -> Question:
        for q in self.questions:
            if q.id == qid:
                return q
        raise GraphkinError(f"{self.id}: no question {qid!r} (questions: {', '.join(q.id for q in self.questions)})")


class _Reader(FieldReader):
    """The problem files' reader (file name in every message, unknown fields with a hint), with the
    two kinds of entry exercise files add."""

    def string(self, t: dict, key: str, where: str, default: str | None = None) -> str:
        """A non-empty string entry ``t[key]`` (``default`` when absent, or an error if there is none)."""
        if key not in t:
            if default is None:
                raise self.fail(f"{where}.{key}" if where else key, "is missing")
            return default
        value = t[key]
        if not isinstance(value, str) or not value.strip():
            raise self.fail(f"{where}.{key}" if where else key, f"must be a non-empty string, got {value!r}")
        return value.strip()

    def number(self, t: dict, key: str, where: str, default, *, low: float = 0.0, percent: bool = False):
        """A number entry ≥ ``low`` (``"1 %"`` allowed with ``percent``), or ``default`` when absent."""
        if key not in t:
            return default
        value = t[key]
        field = f"{where}.{key}" if where else key
        if percent and isinstance(value, str) and value.strip().endswith("%"):
            try:
                value = float(value.strip()[:-1]) / 100
            except ValueError:
                raise self.fail(field, f"could not read {t[key]!r}; write e.g. \"1 %\" or 0.01") from None
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not value == value or value < low \
                or value == float("inf"):
            raise self.fail(field, f"must be a number ≥ {low:g}, got {t[key]!r}")
        return float(value)


def _grid(rd: _Reader, t: dict, where: str) -> tuple[str, ...]:
    """The values a varied field takes: ``from``/``to``/``step`` in one unit, or a list ``values``."""
    if "values" in t:
        if any(k in t for k in ("from", "to", "step")):
            raise rd.fail(where, "give either values = [...] or from/to/step, not both")
        values = t["values"]
        if not isinstance(values, list) or not values or not all(isinstance(v, (str, int, float)) and
                                                                 not isinstance(v, bool) for v in values):
            raise rd.fail(f"{where}.values", "must be a non-empty list of values such as [\"4 kg\", \"5 kg\"]")
        return tuple(str(v) for v in values)
    parts = {}
    for key in ("from", "to", "step"):
        raw = rd.string(t, key, where)
        m = _NUMBER_UNIT.match(raw)
        if m is None:
            raise rd.fail(f"{where}.{key}", f'could not read "{raw}": write a number and a unit, e.g. "10 deg"')
        try:
            parts[key] = (Decimal(m[1]), m[2])
        except InvalidOperation:  # pragma: no cover - the pattern admits only decimals
            raise rd.fail(f"{where}.{key}", f'could not read "{raw}"') from None
    units = {u for _, u in parts.values()}
    if len(units) != 1:
        raise rd.fail(where, f"from, to and step must be written in one unit, got {', '.join(repr(u) for u in sorted(units))}")
    (unit,) = units
    start, stop, step = (parts[k][0] for k in ("from", "to", "step"))
    if step <= 0:
        raise rd.fail(f"{where}.step", f"must be positive, got {t['step']!r}")
    if stop < start:
        raise rd.fail(f"{where}.to", f"must not be below from ({t['from']!r})")
    count = int((stop - start) / step) + 1
    if count > _MAX_GRID:
        raise rd.fail(f"{where}.step", f"gives {count} values (at most {_MAX_GRID}); take a larger step")
    # Decimal keeps "0.1 + 0.2" as "0.3": the value shown is the value solved, on every machine.
    return tuple(f"{(start + k * step).normalize():f} {unit}".strip() for k in range(count))


def _kind_of(find: str, base_names: set[str], driver: str, design=None) -> tuple[str, int | None]:
    """What a question's ``find`` names, and the link it is about (``design``: the exercise's ``[design]`` table)."""
    if find == "design" and design is not None:
        return f"design_{design.dimension}", None
    if find in CYCLE_KINDS and find != "peak_force":
        return find, None
    if find == driver or find == "driver":
        return ("driver_torque" if driver.startswith("T") else "driver_force"), None
    m = re.fullmatch(r"([FT])(\d+)i", find)
    if m:
        return ("inertia_force" if m[1] == "F" else "inertia_torque"), int(m[2])
    m = re.fullmatch(r"h(\d+)", find)
    if m:
        return "h", int(m[1])
    m = re.fullmatch(r"I(\d+)", find)
    if m:
        return "concurrency", int(m[1])
    m = re.fullmatch(r"(omega|ω|alpha|α|aG|a_G|coriolis)(\d+)", find)
    if m:
        return {"ω": "omega", "α": "alpha", "aG": "a_G"}.get(m[1], m[1]), int(m[2])
    m = re.fullmatch(r"peak_force\.(\w+)", find)
    if m and m[1] in base_names:
        return "peak_force", None
    if find in base_names:
        return "force", None
    raise KeyError(find)


def _sliding(mech) -> set[int]:
    """The links of the sliding pairs between two moving links: those with a Coriolis component 2ωv (on a guide
    of the frame, ω = 0 and there is none)."""
    return {link for joint in mech.joints if isinstance(joint, Prismatic) and mech.frame not in joint.links
            for link in joint.links}


def _drawn_question(rd: _Reader, t: dict, where: str, qid: str, moving, points: set[str]) -> Question:
    """A drawn question: ``draw`` (what is drawn) and ``link`` or ``point`` (what it is about)."""
    rd.table(t, where, _DRAWN)
    draw = rd.string(t, "draw", where)
    if draw not in DRAW_KINDS:
        raise rd.fail(f"{where}.draw", f"must be one of {', '.join(DRAW_KINDS)}, got {draw!r}")
    link, point = None, ""
    if draw in ("velocity-step", "acceleration-step"):
        if "link" in t:
            raise rd.fail(f"{where}.link", f"a {draw} is named by the point whose image it finds: write point = \"B\"")
        point = rd.string(t, "point", where)
        # A point, or a point of one link where links share it (B3: the point B of link 3, as the polygons name it).
        if point not in points and point.rstrip("0123456789") not in points:
            raise rd.fail(f"{where}.point", f"{point!r} is no point of the mechanism (points: {', '.join(sorted(points))}; "
                                            "B3 names B of link 3)")
    else:
        if "point" in t:
            raise rd.fail(f"{where}.point", f"a {draw} is named by its link: write link = 3")
        if "link" not in t:
            raise rd.fail(f"{where}.link", f"is missing: the moving link the {draw} is about (moving: "
                                           f"{', '.join(map(str, moving))})")
        link = t["link"]
        if isinstance(link, bool) or not isinstance(link, int) or link not in moving:
            raise rd.fail(f"{where}.link", f"must be a moving link's number ({', '.join(map(str, moving))}), "
                                           f"got {link!r}")
    points_ = rd.number(t, "points", where, 1.0)
    ask = rd.string(t, "ask", where, f"Draw the {draw.replace('-', ' ')}")
    return Question(qid, ask, "drawing", "drawing", link, draw, "", 0.0, None, points_, "graphical", draw, point)


def _question(rd: _Reader, t: dict, where: str, names: set[str], driver: str, route: str, moving,
              sliding=frozenset(), design=None, points: frozenset = frozenset()) -> Question:
    qid = rd.string(t, "id", where)
    if not re.fullmatch(r"[A-Za-z_][\w.]*", qid):
        raise rd.fail(f"{where}.id", f"must be a name of letters, digits, _ and . (it keys the answers), got {qid!r}")
    find = rd.string(t, "find", where)
    if find == "drawing":
        return _drawn_question(rd, t, where, qid, moving, points)
    rd.table(t, where, _QUESTION)
    try:
        kind, link = _kind_of(find, names, driver, design)
    except KeyError:
        known = sorted(names) + [driver, "F<k>i", "T<k>i", "h<k>", "I<k>", "omega<k>", "alpha<k>", "aG<k>",
                                 "coriolis<k>"] + sorted(CYCLE_KINDS - {"peak_force"}) \
            + ["peak_force.<F> (e.g. peak_force.F23)", "design (with a [design] table)"]
        raise rd.fail(f"{where}.find", f"{find!r} names nothing this problem has (it has: {', '.join(known)})") from None
    if link is not None and link not in moving:
        raise rd.fail(f"{where}.find", f"{find!r}: link {link} is not a moving link (moving: {', '.join(map(str, moving))})")
    if kind == "coriolis" and link not in sliding:
        # A Coriolis component 2ωv belongs to a sliding pair on a turning guide: asked of a link without one, no
        # variant could have it, and every student's draw would be refused.
        has = ", ".join(map(str, sorted(sliding))) or "none"
        raise rd.fail(f"{where}.find", f"{find!r}: link {link} slides on no moving link, so it has no Coriolis "
                      f"component (a guide of the frame has ω = 0); links that have one: {has}")
    parts = _PARTS[kind]
    part = rd.string(t, "part", where, parts[0])
    if part not in parts:
        raise rd.fail(f"{where}.part", f"must be one of {', '.join(parts)} for {find}, got {part!r}")
    q_route = rd.string(t, "route", where, route)
    if q_route not in ("analytical", "graphical"):
        raise rd.fail(f"{where}.route", f"must be 'analytical' or 'graphical', got {q_route!r}")
    if part in ("direction", "at"):
        unit = "deg"
    elif kind == "h" and part == "point":
        unit = "mm"
    else:
        unit = _DEFAULT_UNIT[kind]
    unit = rd.string(t, "unit", where, unit) if "unit" in t else unit
    tolerance = rd.number(t, "tolerance", where, 0.03 if q_route == "graphical" else 0.01, percent=True)
    if not 0 < tolerance < 1:
        raise rd.fail(f"{where}.tolerance", f"must lie between 0 and 100 %, got {t['tolerance']!r}")
    floor = None
    if "floor" in t and part in ("direction", "at"):
        raise rd.fail(f"{where}.floor", "applies to values, not to angles (an angle's slack comes from the tolerance)")
    if "floor" in t:
        floor = to_si(t["floor"], dimension_of(kind, part), field=f"{where}.floor", file=rd.file)
        if floor < 0:
            raise rd.fail(f"{where}.floor", f"must not be negative, got {t['floor']!r}")

    if unit:
        # The unit must suit the question: "mm" for a force is a slip in the file, not the student's.
        try:
            to_si(f"1 {unit}", dimension_of(kind, part), field=f"{where}.unit", file=rd.file)
        except ProblemFileError as exc:
            raise rd.fail(f"{where}.unit", exc.message) from None
    points = rd.number(t, "points", where, 1.0)
    ask = rd.string(t, "ask", where, f"{find} ({part})")
    return Question(qid, ask, find, kind, link, part, unit, tolerance, floor, points, q_route)


def dimension_of(kind: str, part: str) -> str:
    """The dimension (a :data:`graphkin.units.DIMENSIONS` key, or ``"energy"``) of a question's answer."""
    if part in ("direction", "at"):
        return "angle"
    if kind in ("h", "concurrency"):
        return "length"
    if kind in ("force", "driver_force", "inertia_force", "peak_force"):
        return "force"
    if kind == "flywheel_E":
        return "energy"
    if kind == "flywheel_I":
        return "moment_of_inertia"
    if kind == "jfi_peak":
        return "dimensionless"
    if kind in designs.DESIGN_KINDS:
        return kind.removeprefix("design_")
    if kind == "drawing":  # the space it is drawn in
        return {"force-polygon": "force", "velocity-step": "velocity", "acceleration-step": "acceleration"}.get(
            part, "length")
    return MOTION_KINDS.get(kind, "torque")



def load_exercise(source: str | Path, *, name: str | None = None) -> Exercise:
    """Read an exercise file (a path; catalog names through :func:`graphkin.exercises.load`).

    Raises
    ------
    ProblemFileError
        Naming the file and the field at fault.
    """
    path = Path(source)
    file = name or str(path)
    text = read_text(path, "exercise", shown=file)
    return parse_exercise(text, file=file, id=name or path.stem, folder=path.parent)


def parse_exercise(text: str, *, file: str = "<exercise>", id: str = "exercise", folder: Path | None = None,
                   problems: dict | None = None) -> Exercise:
    """Build an :class:`Exercise` from TOML text (relative problem paths from ``folder``, or the text of a
    problem file from ``problems``, file name → text, as an export's keys carry it)."""
    rd = _Reader(file)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise rd.fail("", f"is not valid TOML ({exc})") from None
    rd.table(data, "", _TOP)
    problem = rd.string(data, "problem", "")
    if problems and problem in problems:
        base_text = problems[problem]
    else:
        if problem in catalog.names():
            base_path = catalog.path(problem)
        else:
            base_path = (folder or Path(".")) / problem
            if not base_path.is_file():
                raise rd.fail("problem", f"{problem!r} is neither a catalog problem ({', '.join(catalog.names())}) "
                                         "nor a file")
        base_text = read_text(base_path, "problem", shown=str(base_path))
    try:
        base = tomllib.loads(base_text)
    except tomllib.TOMLDecodeError as exc:
        raise rd.fail("problem", f"{problem!r} cannot be read ({exc})") from None

    problem_obj = build_problem(base, file=problem)
    mech = problem_obj.mechanism

    names = set()
    for J in mech.joints:
        i, j = J.links
        for a, b in ((i, j), (j, i)):
            name = f"{J.force_letter}{a}{b}"
            parse_force_name(mech, name)
            names.add(name)
    driver = mech.driver.symbol
    route = rd.string(data, "route", "", "analytical")
    if route not in ("analytical", "graphical"):
        raise rd.fail("route", f"must be 'analytical' or 'graphical', got {route!r}")
    vary_table = rd.table(data.get("vary", {}), "vary", set(data.get("vary", {})))
    vary = []
    for symbol, t in vary_table.items():
        where = f"vary.{symbol}"
        rd.table(t, where, _VARY)
        raw = t.get("field")
        if isinstance(raw, list) and raw and all(isinstance(f, str) and f.strip() for f in raw):
            field = tuple(f.strip() for f in raw)
        else:
            field = (rd.string(t, "field", where),)
        values = _grid(rd, t, where)
        vary.append(Vary(symbol, field, values, rd.string(t, "label", where, "") if "label" in t else ""))
    design = _design(rd, data, base, problem)
    questions_raw = data.get("questions")
    if not isinstance(questions_raw, list) or not questions_raw:
        raise rd.fail("questions", "must be a non-empty list of [[questions]] tables")
    point_names = frozenset(J.point for J in mech.joints if getattr(J, "point", None)) | \
        frozenset(n for link in mech.moving for n in mech.link(link).points)
    questions = tuple(_question(rd, t, f"questions[{i}]", names, driver, route, mech.moving, _sliding(mech), design,
                                point_names)
                      for i, t in enumerate(questions_raw))
    asks = any(q.kind in designs.DESIGN_KINDS for q in questions)
    if design is not None and not asks:
        raise rd.fail("design", "no question asks for the design: add one with find = \"design\"")
    ids = [q.id for q in questions]
    if len(set(ids)) != len(ids):
        dup = sorted({i for i in ids if ids.count(i) > 1})
        raise rd.fail("questions", f"question ids must differ; repeated: {', '.join(dup)}")
    partial = dict(SLIPS)
    for key, value in rd.table(data.get("partial", {}), "partial", set(SLIPS)).items():
        share = rd.number({key: value}, key, "partial", None)
        if share > 1:
            raise rd.fail(f"partial.{key}", f"is a share of the question's points, between 0 and 1, got {value!r}")
        partial[key] = share
    positions = None
    if "positions" in data:
        positions = data["positions"]
        if isinstance(positions, bool) or not isinstance(positions, int) or not 8 <= positions <= 36_000:
            raise rd.fail("positions", f"must be a whole number from 8 to 36000, got {positions!r}")
    fly = rd.table(data.get("flywheel", {}), "flywheel", _FLYWHEEL)
    Cs = rd.number(fly, "Cs", "flywheel", None) if "Cs" in fly else None
    if Cs is not None and not 0 < Cs < 1:
        raise rd.fail("flywheel.Cs", f"the coefficient of speed fluctuation must lie between 0 and 1, got {fly['Cs']!r}")
    if any(q.kind in CYCLE_KINDS for q in questions):
        if not mech.driver.crank:
            raise rd.fail("questions", "questions over the cycle need a crank driver (a whole turn)")
        if positions is None and len(problem_obj.q) < 8:
            positions = 360  # the problem is given at one position: sweep a whole turn in 1° steps
    if any(q.kind in ("flywheel_E", "flywheel_I") for q in questions) and Cs is None \
            and not any("flywheel.Cs" in v.field for v in vary):
        raise rd.fail("flywheel.Cs", "is missing: a flywheel question needs the coefficient of speed fluctuation")
    for v in vary:
        for f in v.field:
            if f != "flywheel.Cs":
                _check_field(rd, base, v.symbol, f)
    _check_values(rd, base, problem, vary)
    reveal = data.get("reveal", False)
    if not isinstance(reveal, bool):
        raise rd.fail("reveal", f"must be true or false, got {reveal!r}")
    draw = data.get("draw", route == "graphical")
    if not isinstance(draw, bool):
        raise rd.fail("draw", f"must be true or false, got {draw!r}")
    decimal_comma = data.get("decimal_comma", True)
    if not isinstance(decimal_comma, bool):
        raise rd.fail("decimal_comma", f"must be true or false, got {decimal_comma!r}")
    feedback = data.get("feedback", "parts")
    if feedback not in FEEDBACK:
        raise rd.fail("feedback", f"must be {' or '.join(map(repr, FEEDBACK))}, got {feedback!r}")
    intro = rd.string(data, "intro", "", "")
    symbols = [v.symbol for v in vary]
    for where, statement in [("intro", intro)] + [(f"questions[{i}].ask", q.ask) for i, q in enumerate(questions)]:
        slip = symbol_problem(statement, symbols)
        if slip:
            raise rd.fail(where, slip)
    return Exercise(id, rd.string(data, "title", ""), rd.string(data, "source", "", ""), intro,
                    problem, base, tuple(vary), questions, partial, positions, Cs, reveal,
                    rd.number(data, "max_force_ratio", "", 20.0, low=1.0),
                    rd.number(data, "max_speed_ratio", "", 5.0, low=1.0), draw, file,
                    hashlib.sha256("\x1f".join((id, text, base_text)).encode("utf-8")).hexdigest(), text, base_text,
                    decimal_comma, feedback, design)


def _design(rd: _Reader, data: dict, base: dict, problem: str):
    """The exercise's ``[design]`` table (:mod:`graphkin.exercises.designs`), its field and every value checked
    against the base problem; None if it has none."""
    import copy

    if "design" not in data:
        return None
    t = rd.table(data["design"], "design", designs.TABLE)
    field = rd.string(t, "field", "design")
    _check_field(rd, base, "design", field, where="design.field")
    values = _grid(rd, t, "design")
    for value in dict.fromkeys((values[0], values[len(values) // 2], values[-1])):  # as _check_values does
        trial = copy.deepcopy(base)
        set_field(trial, field, value)
        try:
            build_problem(trial, file=problem)
        except ProblemFileError as exc:
            raise rd.fail("design", f"the problem does not accept {value!r} at {field}: {exc.message}") from None
    return designs.read_design(t, values, rd.fail)


def _check_field(rd: _Reader, base: dict, symbol: str, field: str, where: str | None = None) -> None:
    """A varied (or designed) field must exist in the base problem."""
    where = where or f"vary.{symbol}.field"
    try:
        absent = missing(base, field)
    except KeyError:
        raise rd.fail(where, f"could not read the path {field!r}; write it as in the problem file, "
                             "e.g. \"driver.theta\" or \"links[1].mass\"") from None
    if absent is not None:
        raise rd.fail(where, f"{field!r}: the problem has no {absent!r}")


def _check_values(rd: _Reader, base: dict, problem: str, vary: list[Vary]) -> None:
    """Every value of every varied field must be one the problem file accepts there (units, field name)."""
    import copy

    for v in vary:
        # The ends and the middle: a unit or a field name at fault shows on any of them.
        for value in dict.fromkeys((v.values[0], v.values[len(v.values) // 2], v.values[-1])):
            trial = copy.deepcopy(base)
            for f in v.field:
                if f == "flywheel.Cs":
                    if not 0 < to_si(value, "dimensionless", field=f"vary.{v.symbol}", file=rd.file) < 1:
                        raise rd.fail(f"vary.{v.symbol}", f"C_s must lie between 0 and 1, got {value!r}")
                    continue
                set_field(trial, f, value)
            try:
                build_problem(trial, file=problem)
            except ProblemFileError as exc:
                where = f" at {exc.field}" if exc.field else ""
                raise rd.fail(f"vary.{v.symbol}", f"the problem does not accept {value!r}{where}: {exc.message}") \
                    from None
