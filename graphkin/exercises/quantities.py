"""What each question's answer is, computed from a variant's solved problem.

Every value is SI inside (N, N·m, m, rad, J, kg·m²); the key prints it as the
books do, in the question's unit. Vectors and points are complex numbers
x + iy here, as in the solvers.
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass

import numpy as np

from graphkin.exercises import designs
from graphkin.exercises.drawn import drawing_slack
from graphkin.exercises.drawn_tasks import Undefined as DrawnUndefined
from graphkin.exercises.drawn_tasks import within_words
from graphkin.exercises.exercise import MOTION_KINDS, Question, dimension_of
from graphkin.exercises.precision import ANGLE, LENGTH
from graphkin.graphical.paper import (
    POLYGON_ROOM,
    READING,
    force_text,
    length_text,
    motion_scales,
    motion_text,
    reading_error,
    sheet_scales,
)
from graphkin.kinematics import DriverGroup
from graphkin.kinematics.plan import plan_of
from graphkin.model.names import parse_force_name
from graphkin.notation import num, polar_text, unit_text
from graphkin.units import to_si

# SI unit of each dimension, as printed in keys.
_SI = {"force": "N", "torque": "N*m", "length": "m", "angle": "rad", "energy": "J",
       "moment_of_inertia": "kg*m^2", "dimensionless": "", "angular_velocity": "rad/s",
       "angular_acceleration": "rad/s^2", "acceleration": "m/s^2", "mass": "kg", "velocity": "m/s"}


@dataclass(frozen=True)
class Expected:
    """A question's answer for one variant.

    Attributes
    ----------
    question : Question
    form : str
        ``"scalar"`` (signed), ``"magnitude"``, ``"direction"`` (an angle, compared
        modulo 360°), ``"vector"`` (a force, x + iy) or ``"point"`` (a position, x + iy).
    value : float or complex
        SI (angles in rad).
    slack : float
        The largest difference that still earns full marks [SI; rad for angles].
    text : str
        As the book prints it, in the question's unit.
    hint : str
        Where the value comes from: the construction step or equations to revisit.
    anchor : complex or None
        For an inertia resultant's point: the centre of mass G it is offset from.
    undefined : str or None
        Why the question has no answer in this variant (then the variant is not handed out).
    """

    question: Question
    form: str
    value: float | complex
    slack: float
    text: str
    hint: str = ""
    anchor: complex | None = None
    undefined: str | None = None

    @property
    def si_unit(self) -> str:
        return _SI[dimension_of(self.question.kind, self.question.part)]

    def si_data(self):
        """The value as plain data: a float, or [x, y] for vectors and points."""
        if isinstance(self.value, complex):
            return [self.value.real, self.value.imag]
        return float(self.value)

    def close(self, value) -> bool:
        """Whether ``value`` (same form, SI) is within the slack of this answer."""
        return _distance(self.form, value, self.value) <= self.slack


def _distance(form: str, a, b) -> float:
    if form == "direction":
        return abs(math.remainder(a - b, 2 * math.pi))
    return abs(a - b)


@functools.cache
def unit_factor(unit: str, dimension: str) -> float:
    """SI value of one ``unit`` (1 for ``"mm"`` → 0.001)."""
    if not unit:
        return 1.0

    return to_si(f"1 {unit}", dimension, field="unit")


def question_data(q: Question) -> dict:
    """A question as the student sees it (no answer)."""
    return {"id": q.id, "ask": q.ask, "find": q.find, "part": q.part, "unit": q.unit, "points": q.points,
            "route": q.route, "tolerance": q.tolerance, "form": _form(q)}


def _form(q: Question) -> str:
    if q.kind == "drawing":
        return "drawing"
    if q.part in ("direction", "at"):
        return "direction"
    if q.part in ("vector", "point", "magnitude"):  # a concurrency point's only part is "point"
        return q.part
    return "scalar"


def _num(x: float, digits: int = 4) -> str:
    """A number as a student reads it: a true minus, and a power of ten written out (``1.5×10^−5``)."""
    return num(x, digits, power=True)


def format_value(form: str, value, unit: str, dimension: str, *, torque: bool = False) -> str:
    """A value as the book prints it: ``27.06 N ∠ −73.78°``, ``108.9 N·m CCW``, ``(120.5, −33.3) mm``."""
    f = unit_factor(unit, dimension)
    u = (" " + unit_text(unit)) if unit else ""
    if form == "direction":
        return f"{math.degrees(value):.2f}°".replace("-", "−")
    if form == "vector":
        return polar_text((value.real / f, value.imag / f), unit and unit_text(unit))
    if form == "point":
        return f"({_num(value.real / f)}, {_num(value.imag / f)}){u}"
    if torque and value:
        # As the books print a torque: its size and its sense (a signed number with CW would read as −(−T)).
        return f"{_num(abs(value) / f)}{u} {'CCW' if value > 0 else 'CW'}"
    return f"{_num(value / f)}{u}"


def value_of(solved, q: Question):
    """The raw answer of ``q`` on a solved problem (SI; vectors complex); None where it has none, as where it is
    read off a construction that is not valid (a slip's, which is not refused as the key's is)."""
    kind, part = q.kind, q.part
    if (q.route == "graphical" and kind in ("force", "driver_torque", "driver_force")) or kind == "concurrency":
        if not solved.construction.valid:  # it disagrees with the analytical route, or could not be drawn
            return None
    if kind in ("force", "inertia_force"):
        if kind == "force":
            src = solved.construction if q.route == "graphical" else solved.result
            F = np.asarray(src[q.find], dtype=float)
            F = F[0] if F.ndim == 2 else F
        else:
            F = solved.result.inertia(q.link).F[0]
        z = complex(F[0], F[1])
        return {"vector": z, "magnitude": abs(z), "direction": math.atan2(z.imag, z.real) if z else None,
                "x": z.real, "y": z.imag}[part]
    if kind in ("driver_torque", "driver_force"):
        src = solved.construction if q.route == "graphical" else solved.result
        e = src.effort if q.route == "graphical" else src.effort[0]
        return float(e)
    if kind == "inertia_torque":
        return float(solved.result.inertia(q.link).T[0])
    if kind == "h":
        inn = solved.result.inertia(q.link)
        if not np.isfinite(inn.h[0]):
            return None
        return float(inn.h[0]) if part == "magnitude" else complex(*inn.line_point[0])
    if kind == "concurrency":
        for step in solved.construction.steps:
            if f"I{q.link}" in step.points:
                return complex(*step.points[f"I{q.link}"])
        return None
    if kind in MOTION_KINDS:
        return _motion_value(solved, q)
    if kind in designs.DESIGN_KINDS:  # the key, or the design of a student who made the solved draw's slip
        chosen = solved.design
        return chosen.slips.get(solved.slip) if solved.slip in designs.SLIPS else chosen.key
    cycle = solved.cycle
    if kind in ("peak_torque", "lowest_torque"):
        p = cycle.peaks().effort_max if kind == "peak_torque" else cycle.peaks().effort_min
        return p.value if part == "value" else p.at
    if kind == "average_torque":
        return cycle.average
    if kind == "peak_force":
        i, j = parse_force_name(solved.problem.mechanism, q.find.split(".", 1)[1])
        p = cycle.peaks().forces[cycle.analysis.name_of(min(i, j), max(i, j))]
        return p.value if part == "magnitude" else p.at
    if kind == "flywheel_E":
        return solved.flywheel.E
    if kind == "flywheel_I":
        return solved.flywheel.I_s
    if kind == "jfi_peak":
        p = solved.jfi.peak
        return p.value if part == "value" else p.at
    raise KeyError(kind)  # pragma: no cover - the exercise reader admits only the kinds above


def _vector_part(z: complex, part: str):
    return {"vector": z, "magnitude": abs(z), "direction": math.atan2(z.imag, z.real) if z else None,
            "x": z.real, "y": z.imag}[part]


def _misplaced_g(mc, link: int) -> complex | None:
    """The acceleration a student reads who takes G's image at the wrong point of the link's image: at the link's
    named point nearest to G that moves (its end, or the pin the polygon found; a frame pivot's image is the pole)."""
    body = mc.mechanism.link(link)
    G = np.asarray(body.G, float)
    top = max([math.hypot(*a) for a in mc.acceleration.values()] + [0.0])
    near = sorted((math.dist(p, G), name) for name, p in body.points.items()
                  if (link, name) in mc.acceleration and math.hypot(*mc.acceleration[(link, name)]) > 1e-9 * top
                  and math.dist(p, G) > 1e-9)
    return complex(*mc.acceleration[(link, near[0][1])]) if near else None


def _motion_value(solved, q: Question):
    """ω, α of link ``q.link``, a_G of its centre of mass, or the Coriolis component of the sliding pair whose
    guide it is, as read off the polygons (SI; vectors complex)."""
    mc = solved.motion
    if not mc.valid:
        return None
    k = q.link
    if q.kind == "omega":
        return float(mc.omega[k])
    if q.kind == "alpha":
        return float(mc.alpha[k])
    if q.kind == "a_G":
        z = complex(*mc.a_G[k]) if k in mc.a_G else None
        if getattr(solved, "slip", None) == "image_misplaced":
            z = _misplaced_g(mc, k)
        return None if z is None else _vector_part(z, q.part)
    # The Coriolis component of a sliding pair of link k: "a^c_B3B2" (B of link 3 relative to link 2), its links
    # the numbers in its name; the largest if several.
    found = [complex(*v.vector) for v in mc.vectors("acceleration")
             if v.name.startswith("a^c_") and k in map(int, re.findall(r"\d+", v.name[4:]))]
    if not found:
        return None
    return _vector_part(max(found, key=abs), q.part)


def _scale(solved, q: Question) -> float:
    """The size of the largest value of the question's kind in this variant, for the absolute floor."""
    kind = q.kind
    if kind in ("peak_torque", "lowest_torque", "average_torque"):
        return float(np.nanmax(np.abs(solved.cycle.torque)))
    if kind in ("peak_force",):
        return max(p.value for p in solved.cycle.peaks().forces.values())
    if kind in ("flywheel_E", "flywheel_I", "jfi_peak"):
        return abs(value_of(solved, q) if q.part != "at" else 1.0)
    if kind in MOTION_KINDS:
        mc = solved.motion
        table = {"omega": mc.omega.values(), "alpha": mc.alpha.values()}.get(kind)
        return max([abs(x) for x in table] if table is not None else [math.hypot(*a) for a in mc.a_G.values()]
                   + [0.0])
    c = solved.construction
    forces = [math.hypot(*F) for F in c.forces.values()] + [math.hypot(*v["F"]) for v in c.inertia.values()]
    span = solved.span
    if kind in ("h", "concurrency"):
        return span
    if kind in ("driver_torque", "inertia_torque"):
        return max([abs(c.effort), max(forces + [0.0]) * span] + [abs(v["T"]) for v in c.inertia.values()])
    return max(forces + [abs(c.effort) if kind == "driver_force" else 0.0])


_READ = {"force": "force", "driver_force": "force", "inertia_force": "force", "concurrency": "length",
         "h": "length", "driver_torque": "torque"}
"""What a graphical answer of each kind is measured as on the worksheet."""


def measured_as(q: Question) -> str | None:
    """What a graphical answer is measured as on the worksheet (``"force"``, ``"length"``, ``"torque"``), or None."""
    return _READ.get(q.kind) if q.route == "graphical" else None


def measurable(solved, q: Question) -> float:
    """The smallest error a graphical answer can be read to at the worksheet's printed scales [SI] (0 where the
    kind is not measured off a drawing): :func:`graphkin.graphical.paper.reading_error`; for a value read off the
    velocity or acceleration polygon, :data:`~graphkin.graphical.paper.READING` at the worksheet's polygon scale
    (over the link's length for ω and α, a relative vector over the length it turns about)."""
    if q.kind in MOTION_KINDS:
        return _motion_reading(solved, q) if q.route == "graphical" else 0.0
    what = measured_as(q)
    c = solved.construction
    if what is None or not c.valid:
        return 0.0
    return reading_error(c, what)


def drawing_error(solved, q: Question, value) -> float:
    """What a careful student's drawing makes of a graphical answer [SI; rad for a direction]: the stated precision
    of each line carried through the construction (:func:`graphkin.exercises.drawn.drawing_slack`), or where
    the drawing is not replayed (or the value is not drawn but computed), the final reading alone
    (:func:`measurable`)."""
    drawn = drawing_slack(solved, q, value)
    if drawn is not None:
        return drawn
    return 0.0 if _form(q) == "direction" else measurable(solved, q)


def within(q: Question, solved=None) -> str:
    """A question's tolerance as every sheet, key, command and platform states it.

    ``"1 %"``; an angle's ``"1.7°"`` or a sweep's ``"the step of the sweep"``; a graphical answer measured off
    the worksheet or off a velocity or acceleration polygon (``solved`` given) also states what a careful
    drawing allows at its printed scales, the larger of the two being what the grader allows
    (:func:`drawing_error`): ``"3 % or ±0.2646 N (each line drawn to ±0.5 mm and ±0.5° at 1:5 and
    1 mm = 0.2 N), the larger"``, or where only the final reading is counted ``"3 % or ±2.5 N (±0.5 mm at
    1 mm = 5 N), the larger"``.

    Parameters
    ----------
    q : Question
    solved : graphkin.exercises.variants.Solved, optional
        The student's solved draw (for graphical questions: the scales they are drawn at).

    Returns
    -------
    str
    """
    if q.part == "at":
        return "the step of the sweep"
    if q.kind == "drawing":
        return within_words(q, solved)
    if q.kind in designs.DESIGN_KINDS:
        return designs.grid_text(solved.exercise.design) if solved is not None else "one step of the grid"
    text = (f"{math.degrees(math.atan(q.tolerance)):.2g}°" if _form(q) == "direction"
            else f"{100 * q.tolerance:g} %")
    if solved is None:
        return text
    if q.route == "graphical":
        drawn = _drawn_text(solved, q)
        if drawn:
            return f"{text} or {drawn}, the larger"
    if _form(q) == "direction":
        return text
    if q.kind in MOTION_KINDS:
        error = _motion_reading(solved, q) if q.route == "graphical" else 0.0
        if not error > 0:
            return text
        unit = {"omega": "rad/s", "alpha": "rad/s²"}.get(q.kind, "m/s²")
        return (f"{text} or ±{num(error, 4, power=True)} {unit} (±{READING:g} mm on the polygon at its printed "
                "scale), the larger")
    what = measured_as(q)
    construction = solved.construction if what is not None else None
    if construction is None or not construction.valid:
        return text
    error = reading_error(construction, what)
    if not error > 0:
        return text
    scales = sheet_scales(construction)
    if what == "length":
        return (f"{text} or ±{num(error * 1e3, 4, power=True)} mm (±{READING:g} mm on the drawing at "
                f"{length_text(scales.length)}), the larger")
    if what == "torque":
        return f"{text} or ±{num(error, 4, power=True)} N·m (a reading to ±{READING:g} mm on each drawing), the larger"
    return f"{text} or ±{num(error, 4, power=True)} N (±{READING:g} mm at {force_text(scales.polygon)}), the larger"


def _drawn_text(solved, q: Question) -> str:
    """The slack the stated precision gives a graphical answer, and the precision, in words ("" where the
    construction is not replayed)."""
    value = value_of(solved, q)
    drawn = None if value is None else drawing_slack(solved, q, value)
    if drawn is None:
        return ""
    if q.kind in MOTION_KINDS:
        Xv, Xa = motion_scales(solved.motion, POLYGON_ROOM)
        at = f"{motion_text(Xv, 'velocity')} and {motion_text(Xa, 'acceleration')}"
    else:
        scales = sheet_scales(solved.construction)
        at = f"{length_text(scales.length)} and {force_text(scales.polygon)}"
    how = f"each line drawn to ±{LENGTH:g} mm and ±{ANGLE:g}° at {at}"
    if _form(q) == "direction":
        return f"±{math.degrees(drawn):.2g}° ({how})"
    unit = q.unit or ""
    size = drawn / unit_factor(unit, dimension_of(q.kind, q.part))
    return f"±{num(size, 4, power=True)}{' ' + unit_text(unit) if unit else ''} ({how})"


def _motion_reading(solved, q: Question) -> float:
    mc = solved.motion
    if not mc.valid:
        return 0.0
    Xv, Xa = motion_scales(mc, POLYGON_ROOM)
    if q.kind in ("a_G", "coriolis"):
        return READING * Xa
    pts = list(mc.mechanism.link(q.link).points.values())
    arm = max([math.dist(p, r) for n, p in enumerate(pts) for r in pts[n + 1:]] or [0.0])
    if not arm > 0:
        return 0.0
    return READING * (Xv if q.kind == "omega" else Xa) / arm


def _span(c) -> float:
    """The mechanism's size at this position: the largest distance between two of its points [m]."""
    pts = np.array([p for link in c.points.values() for p in link.values()] or [(0.0, 0.0)])
    return float(np.max(np.hypot(*(pts[:, None, :] - pts[None, :, :]).transpose(2, 0, 1))))


# A caption that quotes a value (e.g. "h = |T|/|F| = 33.33 mm") would give the answer away in the feedback.
_VALUE = re.compile(r"\d\s*(?:N|mm|m|°|rad|J|kg)\b|=\s*[−-]?\d")
_KIND_WORDS = {
    "resultant": "link {k}'s inertia force −m a_G and torque −I_G α combined into one resultant offset by h = |T|/|F|",
    "polygon": "the force polygon of link {k}, closed tip to tail",
    "three-force": "link {k} as a three-force member and its point of concurrency",
    "two-force": "link {k} as a two-force member",
    "superpose": "the superposition of the loads of link {k}",
    "driver": "the driver's equilibrium (the driving torque or force)",
    "line": "the line of action of the tooth force",
    "couple": "link {k} loaded by a couple",
    "sub-problem": "a sub-problem of the superposition: only one link's loads at a time",
    "readings": "the forces and driving torque read off a sub-problem's polygons",
}


def _step_hint(n: int, step) -> str:
    if _VALUE.search(step.caption):
        return f"step {n} of the construction: " + _KIND_WORDS.get(step.kind, "step {k}").format(k=step.link)
    return f"step {n} of the construction: {step.caption}"


def equilibrium_steps(mech) -> list[tuple[int, object]]:
    """The analytical solution's steps after the inertia loads (step 1): each group's equilibrium, numbered from 2,
    from the last group located to the driver (the order the closed-form solve takes). A key prints these numbers
    (:mod:`graphkin.handout.equilibrium`) and the feedback points to them."""
    return list(enumerate(reversed(plan_of(mech).groups), 2))  # decomposed once, when the problem was built


def _analytical_hint(solved, q: Question) -> str:
    """The step of the analytical solution that gives ``q``: the inertia loads first, then each group's
    equilibrium from the last group to the driver (the order the closed-form solve takes)."""
    kind = q.kind
    if kind in ("inertia_force", "inertia_torque", "h"):
        then = "; then h = |T_i|/|F_i|, offset to the side that turns the link as T_i does" if kind == "h" else ""
        return (f"step 1 of the analytical solution: link {q.link}'s inertia loads, F_i = −m a_G and T_i = −I_G α, "
                f"from its accelerations{then}")
    mech = solved.problem.mechanism
    if kind in ("driver_torque", "driver_force"):
        want = None
    else:
        i, j = parse_force_name(mech, q.find)
        want = {i, j}
    for n, g in equilibrium_steps(mech):
        if isinstance(g, DriverGroup) and want is None:
            return (f"step {n} of the analytical solution: the equilibrium of the driver (link {g.links[0]}): ΣF = 0 "
                    f"and ΣM = 0 about its pivot, with the forces of the links it drives, give {q.find}")
        if want is not None and any(set(joint.links) == want for joint in g.joints):
            links = " and ".join(map(str, g.links))
            return (f"step {n} of the analytical solution: the equilibrium of the {g.label} (ΣF = 0 and ΣM = 0 for "
                    f"link{'s' if len(g.links) > 1 else ''} {links}, solved together: their rows of [A]{{x}} = {{b}})")
    return "the equilibrium equations ΣF = 0, ΣM = 0 of every link (the rows of [A]{x} = {b})"


_POLYGONS = "of the construction of the polygons"
"""Where a motion question's hint points: a step of the velocity and acceleration polygons, which a key numbers
apart from the force construction's."""


def _motion_hint(solved, q: Question) -> str:
    """The step of the velocity or acceleration polygon that finds the value (its caption's numbers left out)."""
    mc = solved.motion
    polygon = "velocity" if q.kind == "omega" else "acceleration"
    for n, step in enumerate(mc.steps, 1):
        if step.polygon != polygon or q.link not in step.links:
            continue
        if q.kind == "a_G" and step.kind == "image":
            return f"step {n} {_POLYGONS}: the acceleration image of link {q.link} and its point g{q.link}′"
        if q.kind == "coriolis" and any(v.name.startswith("a^c_") for v in step.vectors):
            return f"step {n} {_POLYGONS}: the Coriolis component 2ωv of the sliding pair, and its sense"
        if q.kind in ("omega", "alpha") and step.kind in ("dyad", "gear", "driver"):
            what = "relative velocity" if q.kind == "omega" else "tangential component"
            return (f"step {n} {_POLYGONS}: the {what} of link {q.link} in the {polygon} polygon, over the "
                    "length it turns about")
    return f"the {polygon} polygon"


def _hint(solved, q: Question) -> str:
    """The step of the question's route a student should revisit for ``q``: a step of the graphical
    construction on the graphical route, a step of the analytical solution on the analytical one."""
    kind = q.kind
    if kind in designs.DESIGN_KINDS:
        return designs.hint(solved.exercise.design)
    if kind in ("peak_torque", "lowest_torque", "average_torque"):
        return "the driving torque at every crank angle of the cycle (sweep), then its extremes and mean"
    if kind == "peak_force":
        return "the magnitude of the joint force at every crank angle of the cycle"
    if kind in ("flywheel_E", "flywheel_I"):
        return ("the energy table (Norton §11.11): the areas of the pulses of T − T_avg, E the largest swing, "
                "I_s = E / (C_s ω_avg²)")
    if kind == "jfi_peak":
        return "the static joint forces (masses set to zero) divided by the external load (Norton §11.12)"
    if kind in MOTION_KINDS:
        return _motion_hint(solved, q)
    if q.route == "analytical" and kind != "concurrency":
        return _analytical_hint(solved, q)
    c = solved.construction
    want = {"force": q.find, "driver_torque": q.find, "driver_force": q.find}.get(kind)
    for n, step in enumerate(c.steps, 1):
        # The whole problem's driver step: a sub-problem's (superposition) gives only its own part of the torque.
        if want and step.kind in ("driver",) and kind.startswith("driver") and not getattr(step, "sub", ""):
            return _step_hint(n, step)
        if want and (want in step.values or any(a.name == want and not a.known for a in step.polygon)):
            return _step_hint(n, step)
        if kind in ("inertia_force", "inertia_torque", "h") and step.kind == "resultant" and step.link == q.link:
            return _step_hint(n, step)
        if kind == "concurrency" and f"I{q.link}" in step.points:
            return _step_hint(n, step)
    # The force is not drawn in a step of its own (it closes a polygon as the reaction of another, say).
    return "the force polygons of the construction, each closed tip to tail" if kind == "force" else ""


_TORQUE_KINDS = ("driver_torque", "inertia_torque", "peak_torque", "lowest_torque", "average_torque")


def message_words(solved, q: Question, exp: Expected) -> dict:
    """The words grading messages use for ``q``: its name, its reverse (F32 for F23), the links, the sense,
    the step to revisit, and the crank speed (for a speed read in the wrong unit). Plain data."""
    # A force or torque by its textbook name (F23, T12); a cycle quantity by its question id (T_peak).
    name = q.find if q.kind in ("force", "driver_torque", "driver_force", "inertia_force", "inertia_torque") else q.id
    other, i, j = name, "", ""
    if q.kind == "force":
        i, j = parse_force_name(solved.problem.mechanism, q.find)
        other = f"{q.find[0]}{j}{i}"
    sense = ""
    if q.kind in _TORQUE_KINDS and isinstance(exp.value, float):
        sense = "counter-clockwise (positive)" if exp.value > 0 else "clockwise (negative)"
    if q.kind == "h":
        T = float(solved.result.inertia(q.link).T[0])
        sense = "counter-clockwise" if T > 0 else "clockwise"
    omega = float(np.ravel(solved.problem.q_dot)[0]) if np.size(solved.problem.q_dot) else 0.0
    # Step captions end with a full stop; the messages put their own.
    words = {"name": name, "other": other, "i": str(i), "j": str(j), "sense": sense,
             "hint": (exp.hint or "the solution").rstrip("."), "rpm": f"{omega * 30 / math.pi:.4g}",
             "omega": f"{omega:.4g}"}
    if q.kind in designs.DESIGN_KINDS:
        words |= designs.design_words(solved.exercise.design, solved.design)
    return words


def undefined(solved, q: Question) -> str | None:
    """Why ``q`` has no answer on this solved problem (None when it has one)."""
    if q.kind == "drawing":
        try:
            solved.drawn(q)
        except DrawnUndefined as exc:
            return str(exc)
        return None
    value = value_of(solved, q)
    if value is not None and not (isinstance(value, float) and not math.isfinite(value)):
        return None
    return {"h": f"link {q.link}'s inertia force is zero, so h is not defined",
            "concurrency": f"link {q.link} has no point of concurrency at this position",
            "force": f"{q.find} has no direction (it is zero)"}.get(q.kind, f"{q.find} is not defined")


def expected(variant, q: Question) -> Expected:
    """The answer to ``q`` for ``variant`` (anything with ``.solved`` and ``.exercise``)."""
    solved = variant.solved
    form = _form(q)
    if form == "drawing":
        # The answer is a drawing: its targets are the solved draw's (:meth:`Solved.drawn`); the key states the
        # right drawing's numbers, the slack is the drawing's length tolerance [SI of its space].
        try:
            d = solved.drawn(q)
        except DrawnUndefined as exc:
            return Expected(q, form, 0.0, 0.0, "", undefined=str(exc))
        return Expected(q, form, 0.0, d["tolerance"]["length"], d["text"], d["hint"])
    dim = dimension_of(q.kind, q.part)
    value = value_of(solved, q)
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return Expected(q, form, 0.0, 0.0, "", undefined=undefined(solved, q))
    if q.kind in designs.DESIGN_KINDS:
        slack = designs.slack(solved.exercise.design, q.tolerance, value)
    elif form == "direction":
        slack = math.atan(q.tolerance)
        if q.part == "at":
            # A peak's position is known only to the grid of the sweep.
            grid = np.diff(np.sort(solved.cycle.q))
            slack = max(slack, float(np.max(grid)) if len(grid) else 0.0)
    else:
        floor = q.floor if q.floor is not None else 1e-3 * _scale(solved, q)
        size = solved.span if form == "point" else abs(value)
        slack = max(q.tolerance * size, floor)
    if q.route == "graphical":
        # Measured off a printed drawing: no finer than a careful student draws and reads at the worksheet's scales.
        slack = max(slack, drawing_error(solved, q, value))
    hint = _hint(solved, q)
    anchor = None
    if q.kind == "h" and q.part == "point":
        anchor = complex(*solved.result.kinematics.G(q.link)[0])
    torque = q.kind in _TORQUE_KINDS
    text = format_value(form, value, q.unit, dim, torque=torque and form == "scalar")
    return Expected(q, form, value, slack, text, hint, anchor)
