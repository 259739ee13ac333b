"""What a student is told: the sentences of the feedback, why an answer is not read, and what may be said of
a wrong one.

:data:`MESSAGES` is the catalogue, one sentence (or two) per verdict and slip. :func:`read_given` is the one
decision of whether an answer is read, which the grader and a notebook's own check both make. A wrong answer
that fits no slip is told, by default, which part of it is wrong (:func:`which_part`: the sign or sense, the size
or the direction, a size more than ten times off), never how far off: each of those words is true of a whole
region of answers whose edges are either fixed whatever the key (the sign at 0, the decades of the question's
unit) or a few slacks around it, so that reading them gives the key's sign and power of ten, not the key.
:func:`how_far_off` says how far off (%, degrees, mm), from which the key follows in one more submission: only where
the exercise's ``feedback`` is ``"distance"``.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

from graphkin.exercises.answers import Reading, Unreadable, read_answer
from graphkin.exercises.designs import DESIGN_KINDS
from graphkin.exercises.exercise import Question, dimension_of
from graphkin.exercises.notebooks import NotData, answer_variables
from graphkin.exercises.quantities import Expected, _distance, _form, unit_factor
from graphkin.notation import num, unit_text

_TORQUE_KINDS = ("driver_torque", "inertia_torque", "peak_torque", "lowest_torque", "average_torque")

#: The feedback catalogue: one sentence (or two) per slip; ``{name}`` is the quantity, ``{hint}`` the step.
MESSAGES = {
    "correct": "Correct.",
    "missing": "No answer was given for {name}.",
    "sign_force": ("The size is right but the direction is reversed: you gave {other} (the force of link {j} on "
                   "link {i}), and {name} = −{other}. Check which link acts on which."),
    "sign_torque": ("The size is right but the sense is wrong: {name} is {sense}. Positive torques turn "
                    "counter-clockwise (CCW), negative ones clockwise (CW)."),
    "sign_value": "The size is right but the sign is wrong; check the sign convention (x right, y up, CCW positive).",
    "sign_magnitude": "A magnitude is never negative: give the size of {name} and, where asked, its direction apart.",
    "opposite": ("The direction is off by 180°: that is the direction of {other}. Check which link acts on "
                 "which ({name} is the force of link {i} on link {j})."),
    "opposite_other": ("The direction is off by 180°: check which way {name} acts (angles from +x, "
                       "counter-clockwise positive)."),
    "power_of_ten": ("The digits are right but the value is {factor} too {way}: check the unit conversion "
                     "(N·mm and N·m, mm and m, kN and N)."),
    "degrees_radians": "That angle looks like {wrong} read as {right}: write the angle in degrees, e.g. \"-45 deg\".",
    "rpm_as_rad_s": ("This is the answer for a crank turning at {rpm} rad/s: the speed was given in rpm. "
                     "Convert first: ω = 2π n / 60 = {omega} rad/s."),
    "no_inertia_torque": ("This is the answer without the inertia torque −I_G α: include it (or offset the inertia "
                          "force by h = |T|/|F|). Revisit {hint}."),
    "no_inertia_force": ("This is the answer without the inertia force −m a_G (only the inertia torque kept): "
                         "include the d'Alembert force at G. Revisit {hint}."),
    "wrong_side": ("The offset h is right but on the wrong side of G: the resultant must turn the link the same way "
                   "as the inertia torque T = −I_G α ({sense}). Revisit {hint}."),
    "swapped": ("The x and y components are swapped (or the angle is measured clockwise from +y): x is along the "
                "horizontal axis, to the right, y along the vertical, up, and angles are measured from +x."),
    "angle_from_y": ("The size is right but the angle is measured from +y: angles are measured from +x, "
                     "counter-clockwise positive (yours is 90° short)."),
    "clockwise": ("The size is right but the angle is measured clockwise: angles are measured from +x, "
                  "counter-clockwise positive."),
    "direction": "The size is right but the direction is not. Revisit {hint}.",
    "direction_distance": "The size is right but the direction is {degrees}° off. Revisit {hint}.",
    "other_data": ("This is the answer for another student's data, not yours: work with the values on your own "
                   "sheet."),
    "no_normal": ("This is what the acceleration polygon gives without the normal components: each relative "
                  "acceleration of two points of a link has a normal part ω² r, towards the point it turns about, "
                  "drawn before the tangential one. Revisit {hint}."),
    "coriolis_reversed": ("This is what the acceleration polygon gives with the Coriolis component reversed: 2ωv points "
                          "along the sliding velocity turned 90° in the sense of the guide's ω. Revisit {hint}."),
    "image_misplaced": ("This is the acceleration of another point of the link, not of G: place g′ on the link's "
                        "acceleration image as G sits on the link (the same shape, turned and scaled). "
                        "Revisit {hint}."),
    "unconstrained": ("That design is the cheapest with the limits left out, and it does not meet {limit}: choose among "
                      "the designs that meet every limit. Revisit {hint}."),
    "best_for_limit": ("That design is the one best for the limit, not the one of least {cost} that meets it: a "
                       "design need only meet {limit}. Revisit {hint}."),
    "tie": " It fits {others} about as well; it is graded as the one worth more.",
    "dimension": ("{unit} is a unit of {given}, but {name} is {wanted}, measured in {right} (e.g. \"{example}\")."),
    "need_vector": "Give both the size and the direction of {name}, e.g. \"{example}\" or as components \"(x, y) N\".",
    "need_scalar": "Give one number with its unit for {name}, e.g. \"{example}\".",
    "not_data": ("{name} must be typed as text in quotes, on a line of its own (not inside an if, try, with, loop "
                 "or function), e.g. {name} = \"{example}\": the notebook is read as a file, not run, so {what} is "
                 "not an answer."),
    "wrong": "Not within {tolerance} of the answer{off}. Revisit {hint}.",
    "wrong_nohint": "Not within {tolerance} of the answer{off}.",
    "wrong_parts": "Not within {tolerance} of the answer: {parts}. Revisit {hint}.",
    "wrong_parts_nohint": "Not within {tolerance} of the answer: {parts}.",
    "close": ("Close, but not within {tolerance} of the answer{off}: carry four significant figures through every "
              "step and round only the answer."),
    "close_graphical": ("Close, but not within {tolerance} of the answer{off}: draw the construction larger and "
                        "measure its lines more carefully."),
    "error": ("This answer could not be graded because of an error in the grader, not in the answer; your "
              "teacher can read why in the grader's log."),
}

#: Which part of a wrong answer is right or wrong, in words (feedback = "parts"): each clause is true of the answer
#: and none says how far off it is. "Ten times" is counted on the decades of the question's unit (the answer's and
#: the key's powers of ten differ by two or more), so what it gives away is the key's power of ten, not the key.
PARTS = {
    "sign_right": "the sign is right", "sign_wrong": "the sign is wrong",
    "sense_right": "the sense (CCW or CW) is right", "sense_wrong": "the sense (CCW or CW) is wrong",
    "direction_right": "the direction is right", "direction_wrong": "the direction is wrong",
    "negative": "a magnitude is never negative",
    "size": "the size is not",
    "larger": "the size is more than ten times too large (check the units)",
    "smaller": "the size is more than ten times too small (check the units)",
}

#: A slip in a few words, for the sentence that names a tie.
SLIP_WORDS = {
    "sign": "the sign reversed", "opposite": "the direction turned by 180°", "power_of_ten": "a power of ten off",
    "degrees_radians": "degrees and radians mixed up", "rpm_as_rad_s": "the speed in rpm used as rad/s",
    "no_inertia_torque": "the inertia torque left out", "no_inertia_force": "the inertia force left out",
    "wrong_side": "the offset on the wrong side of G", "swapped": "the components swapped",
    "angle_from_y": "the angle measured from +y", "clockwise": "the angle measured clockwise",
    "other_data": "another student's data", "no_normal": "the normal components left out",
    "coriolis_reversed": "the Coriolis component reversed", "image_misplaced": "G's image misplaced",
    "unconstrained": "the limits left out", "best_for_limit": "the design best for the limit",
    "through_G": "the resultant drawn through G", "scale_factor": "a length laid off ×10 or ÷10",
    "wrong_member": "the wrong member taken as two-force", "wrong_order": "the polygon closed in the other order",
    "sense_reversed": "a vector's sense reversed", "normal_outward": "a normal component drawn away from the centre",
}

DIMENSION_WORDS = {"force": "a force", "torque": "a torque", "length": "a length", "angle": "an angle",
                    "energy": "an energy", "moment_of_inertia": "a moment of inertia", "dimensionless": "a pure number",
                    "power": "a power", "mass": "a mass", "velocity": "a velocity", "acceleration": "an acceleration",
                    "angular_velocity": "an angular velocity", "angular_acceleration": "an angular acceleration",
                    "time": "a time", "density": "a density"}


def answer_example(question) -> str:
    """How to write an answer to this question, with a made-up number (never the answer itself).

    Parameters
    ----------
    question : Question or Expected
        The question (an expected answer stands for its question: the example never depends on the key).
    """
    q = getattr(question, "question", question)
    form = _form(q)
    u = unit_text(q.unit)
    u = f" {u}" if u else ""
    if form == "vector":
        return f"12.3{u} ∠ −45°"
    if form == "point":
        return f"(120, −35){u}"
    if form == "direction":
        return "−45°"
    if q.kind in _TORQUE_KINDS:
        return f"12.3{u} CCW"
    return f"12.3{u}"


@dataclass(frozen=True)
class Refusal:
    """An answer the grader does not read: its verdict (``"missing"`` or ``"unreadable"``) and the sentence why."""

    verdict: str
    sentence: str


def read_given(q: Question, answer, *, decimal_comma: bool = True) -> Reading | Refusal:
    """What the grader reads of an answer to ``q``, or why it reads nothing: the one decision of readability.

    The grader (:func:`grade_question`) and a notebook's own check
    (:func:`graphkin.exercises.platforms.runtime.readable_problem`) both make it here, so that an answer the
    check calls readable is read when graded, and one the grader refuses is refused by the check with the
    same sentence. It needs neither the key nor the secret.

    Parameters
    ----------
    q : Question
    answer : object
        Text, a number, None (unanswered) or :class:`graphkin.exercises.notebooks.NotData`.
    decimal_comma : bool
        Whether a decimal comma is read (the exercise's ``decimal_comma``).

    Returns
    -------
    Reading or Refusal
    """
    if answer is None or (isinstance(answer, str) and not answer.strip()):
        return Refusal("missing", MESSAGES["missing"].format(name=q.id))
    if isinstance(answer, NotData):
        name = answer_variables([q.id])[q.id]  # the notebook variable, as the exports name it
        return Refusal("unreadable", MESSAGES["not_data"].format(name=name, example=answer_example(q),
                                                                 what=answer.reason))
    try:
        return read_answer(answer, dimension=dimension_of(q.kind, q.part), unit=q.unit, decimal_comma=decimal_comma)
    except Unreadable as exc:
        return Refusal("unreadable", str(exc))


def _factor(q) -> float:
    return unit_factor(q.unit, dimension_of(q.kind, q.part))


def which_part(exp: Expected, a) -> str:
    """Which part of a wrong answer is right or wrong (:data:`PARTS`), or "" when only the size can be wrong
    and it is within ten times; never how far off."""
    q, e, form = exp.question, exp.value, exp.form
    first = None
    if form == "scalar" and abs(e) > exp.slack and a:
        torque = q.kind in _TORQUE_KINDS
        first = ("sense" if torque else "sign") + ("_right" if (a > 0) == (e > 0) else "_wrong")
    elif form == "vector" and e:
        right = a and abs(cmath.phase(a / e)) <= math.atan(exp.slack / abs(e))
        first = "direction_right" if right else "direction_wrong"
    elif form == "magnitude" and a < 0:
        first = "negative"
    size = "size"
    if form in ("scalar", "magnitude", "vector") and a and e:
        f = _factor(q)
        decades = math.floor(math.log10(abs(a) / f)) - math.floor(math.log10(abs(e) / f))
        size = "larger" if decades >= 2 else "smaller" if decades <= -2 else "size"
    if first is None and size == "size":
        return ""
    return "; ".join(PARTS[k] for k in (first, size) if k)


def how_far_off(exp: Expected, a) -> str:
    """How far off a wrong answer is, in words: ``" (yours is +19.5 % off)"``."""
    e = exp.value
    if exp.form in ("scalar", "magnitude") and e:
        return f" (yours is {100 * (a - e) / abs(e):+.1f} % off)".replace("-", "−")
    if exp.form == "vector" and e:
        size = 100 * (abs(a) - abs(e)) / abs(e)
        turn = math.degrees(abs(cmath.phase(a / e))) if a else 180.0
        return f" (yours: the size is {size:+.1f} % off, the direction {turn:.1f}° off)".replace("-", "−")
    if exp.form == "direction":
        return f" (yours is {math.degrees(_distance('direction', a, e)):.1f}° off)"
    if exp.form == "point":
        return f" (yours is {1000 * abs(a - e):.3g} mm away)"
    return ""


def tolerance_text(exp: Expected) -> str:
    """The slack as a wrong answer's feedback states it: ``"1 %"``, ``"0.57°"``, ``"15 mm (3 % of the mechanism's
    size)"``; for a graphical answer whose slack the drawing's precision sets, that slack in the question's unit
    (``"±0.2958 N"``), as its sheet states it."""
    q = exp.question
    if q.kind in DESIGN_KINDS:  # one step of the design's grid (graphkin.exercises.designs)
        return f"±{num(exp.slack / _factor(q), 4, power=True)}" + (f" {unit_text(q.unit)}" if q.unit else "")
    if exp.form == "direction":
        return f"{math.degrees(exp.slack):.2g}°"
    tol = f"{100 * q.tolerance:g} %"
    if exp.form == "point":
        tol = f"{1000 * exp.slack:.3g} mm ({tol} of the mechanism's size)"
    elif q.route == "graphical" and exp.slack > q.tolerance * abs(exp.value) * (1 + 1e-9):
        tol = f"±{num(exp.slack / _factor(q), 4, power=True)}" + (f" {unit_text(q.unit)}" if q.unit else "")
    return tol


__all__ = ["DIMENSION_WORDS", "MESSAGES", "PARTS", "Refusal", "SLIP_WORDS", "answer_example", "how_far_off",
           "read_given", "tolerance_text", "which_part"]
