"""Grading: each answer against the key, and a diagnosis of the slip when it is not right.

An answer within the question's tolerance earns full marks. Otherwise the
grader asks which common slip would have produced it, by testing the answer
against the correct value transformed: the sign or sense reversed, a power of
ten, degrees for radians, a direction turned by 180°, the speed in rpm used as
rad/s, the inertia torque or force left out (the variant re-solved without
them), the inertia resultant on the wrong side of G. A diagnosed slip earns
the share of the points the exercise sets (:data:`graphkin.exercises.exercise.SLIPS`)
and a sentence that says what went wrong and which step to revisit.

The grader never raises on anything a student typed and never evaluates it:
answers are read as data by :mod:`graphkin.exercises.answers`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from graphkin.exercises.answers import Reading, Unreadable, read_answer
from graphkin.exercises.exercise import CYCLE_KINDS, dimension_of
from graphkin.exercises.quantities import Expected, _distance, _unit_text, unit_factor, value_of
from graphkin.model.names import parse_force_name

#: Verdicts a question can get.
VERDICTS = ("correct", "slip", "wrong", "unreadable", "missing")

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
    "dimension": ("{unit} is a unit of {given}, but {name} is {wanted}, measured in {right} (e.g. \"{example}\")."),
    "need_vector": "Give both the size and the direction of {name}, e.g. \"{example}\" or as components \"(x, y) N\".",
    "need_scalar": "Give one number with its unit for {name}, e.g. \"{example}\".",
    "wrong": "Not within {tolerance} of the answer{off}. Revisit {hint}.",
    "wrong_nohint": "Not within {tolerance} of the answer{off}.",
}

_DIMENSION_WORDS = {"force": "a force", "torque": "a torque", "length": "a length", "angle": "an angle",
                    "energy": "an energy", "moment_of_inertia": "a moment of inertia", "dimensionless": "a pure number",
                    "power": "a power", "mass": "a mass", "velocity": "a velocity", "acceleration": "an acceleration",
                    "angular_velocity": "an angular velocity", "angular_acceleration": "an angular acceleration",
                    "time": "a time", "density": "a density"}


def answer_example(exp: Expected) -> str:
    """How to write an answer to this question, with a made-up number (never the answer itself)."""
    q = exp.question
    u = _unit_text(q.unit)
    u = f" {u}" if u else ""
    if exp.form == "vector":
        return f"12.3{u} ∠ −45°"
    if exp.form == "point":
        return f"(120, −35){u}"
    if exp.form == "direction":
        return "−45°"
    if q.kind in _TORQUE_KINDS:
        return f"12.3{u} CCW"
    return f"12.3{u}"


def _comparable(exp: Expected, r: Reading):
    """The reading in the expected value's form (SI), or the name of what is missing."""
    form = exp.form
    if form in ("vector", "point"):
        if r.vector is None:
            return "need_vector" if r.form == "scalar" else None
        return complex(*r.vector)
    if r.form != "scalar":
        if form == "magnitude" and r.vector is not None:
            return abs(complex(*r.vector))
        return "need_scalar"
    return r.value


def _verdict(exp: Expected, verdict: str, slip: str | None, score: float, feedback: str, answer: str, reveal: bool):
    q = exp.question
    out = {"id": q.id, "verdict": verdict, "slip": slip, "score": score, "max": q.points, "feedback": feedback,
           "answer": answer}
    if reveal:
        out["expected"] = exp.text
    return out


def _names(exp: Expected, variant):
    """Words for the messages: the quantity's name, its reverse, the links, the sense."""
    q = exp.question
    # A force or torque by its textbook name (F23, T12); a cycle quantity by its question id (T_peak).
    name = q.find if q.kind in ("force", "driver_torque", "driver_force", "inertia_force", "inertia_torque") else q.id
    other, i, j = name, "", ""
    if q.kind == "force":
        i, j = parse_force_name(variant.problem.mechanism, q.find)
        other = f"{q.find[0]}{j}{i}"
    sense = ""
    if q.kind in _TORQUE_KINDS and isinstance(exp.value, float):
        sense = "counter-clockwise (positive)" if exp.value > 0 else "clockwise (negative)"
    if q.kind == "h":
        T = float(variant.solved.result.inertia(q.link).T[0])
        sense = "counter-clockwise" if T > 0 else "clockwise"
    # Step captions end with a full stop; the messages put their own.
    return {"name": name, "other": other, "i": i, "j": j, "sense": sense,
            "hint": (exp.hint or "the solution").rstrip(".")}


def _slip(exp: Expected, a, variant) -> tuple[str, dict] | None:
    """The slip that turns the right answer into ``a``, with words for its message; None if none does."""
    q, form, e = exp.question, exp.form, exp.value
    words = _names(exp, variant)
    # Sign or sense: F_ji for F_ij, CW for CCW, a negative magnitude.
    if form in ("scalar", "vector") and e and exp.close(-a):
        if q.kind == "force" and form == "vector":
            return "sign", {**words, "msg": "sign_force"}
        if q.kind in _TORQUE_KINDS:
            return "sign", {**words, "msg": "sign_torque"}
        return "sign", {**words, "msg": "sign_value"}
    if form == "magnitude" and e and exp.close(-a):
        return "sign", {**words, "msg": "sign_magnitude"}
    if form == "direction":
        # A crank angle where a peak occurs has no "opposite": only a direction of a force does.
        if q.part == "direction" and exp.close(a + math.pi):
            return "opposite", {**words, "msg": "opposite" if q.kind == "force" else "opposite_other"}
        for factor, wrong, right in ((180 / math.pi, "radians", "degrees"), (math.pi / 180, "degrees", "radians")):
            if exp.close(a * factor):
                return "degrees_radians", {**words, "wrong": wrong, "right": right}
    if form in ("scalar", "magnitude", "vector", "point") and e:
        for k in (3, -3, 6, -6):
            if exp.close(a / 10.0**k):
                return "power_of_ten", {**words, "factor": f"10^{abs(k)}", "way": "large" if k > 0 else "small"}
    if form == "point" and exp.anchor is not None and exp.close(2 * exp.anchor - a):
        return "wrong_side", words
    for slip in ("rpm_as_rad_s", "no_inertia_torque", "no_inertia_force"):
        if not _may(q, slip):
            continue
        solved = variant.altered(slip)
        if solved is None:
            continue
        try:
            other = value_of(solved, q)
        except Exception:  # the altered problem may not solve (e.g. a dead point at the wrong speed)
            continue
        if other is None or exp.close(other):  # the slip leaves this answer unchanged: it cannot be told apart
            continue
        if _distance_ok(exp, a, other):
            extra = {}
            if slip == "rpm_as_rad_s":
                rpm = float(variant.problem.q_dot[0]) * 30 / math.pi
                extra = {"rpm": f"{rpm:.4g}", "omega": f"{float(variant.problem.q_dot[0]):.4g}"}
            return slip, {**words, **extra}
    return None


def _may(q, slip: str) -> bool:
    """Whether a re-solved slip can change this question's answer at all."""
    if slip == "rpm_as_rad_s":
        return True
    # Leaving out an inertia load makes the inertia questions themselves zero or undefined: a wrong answer
    # there is not that slip.
    # there is not that slip. Over the cycle they are not tried (a sweep per slip, for little diagnosis).
    return q.kind not in ("inertia_force", "inertia_torque", "h") and q.kind not in CYCLE_KINDS


def _distance_ok(exp: Expected, a, other) -> bool:
    """Whether ``a`` is the slipped value ``other``, to the question's tolerance of that value."""
    slack = exp.slack
    if exp.form not in ("direction", "point") and abs(exp.value) > 0:
        slack = max(slack, exp.question.tolerance * abs(other))
    return _distance(exp.form, a, other) <= slack


def grade_question(variant, q, answer, *, reveal: bool = False) -> dict:
    """Grade one answer; never raises on the answer, whatever it is."""
    exp = variant.expected(q)
    if answer is None or (isinstance(answer, str) and not answer.strip()):
        return _verdict(exp, "missing", None, 0.0, MESSAGES["missing"].format(name=q.id), "", reveal)
    dim = dimension_of(q.kind, q.part)
    try:
        r = read_answer(answer, dimension=dim, unit=q.unit)
    except Unreadable as exc:
        return _verdict(exp, "unreadable", None, 0.0, str(exc), _shown(answer), reveal)
    text = r.text
    if r.value is None and r.vector is None and not r.bare:
        right = _unit_text(q.unit) or "no unit"
        words = _names(exp, variant)
        given = _DIMENSION_WORDS.get(r.dimension, r.dimension or "something else")
        msg = MESSAGES["dimension"].format(unit=_unit_text(r.unit), given=given, name=words["name"],
                                           wanted=_DIMENSION_WORDS.get(dim, dim), right=right, example=answer_example(exp))
        share = variant.exercise.partial["dimension"]
        # A wrong dimension earns the share (0 by default) only when the number itself is right.
        number_right = r.number is not None and exp.form in ("scalar", "magnitude") and \
            exp.close(r.number * _factor(q))
        return _verdict(exp, "slip", "dimension", q.points * share if number_right else 0.0, msg, text, reveal)
    a = _comparable(exp, r)
    if isinstance(a, str) or a is None:
        key = a or "need_scalar"
        return _verdict(exp, "wrong", None, 0.0, MESSAGES[key].format(name=q.find, example=answer_example(exp)), text, reveal)
    if exp.close(a):
        return _verdict(exp, "correct", None, q.points, MESSAGES["correct"], text, reveal)
    found = _slip(exp, a, variant)
    if found is not None:
        slip, words = found
        msg = MESSAGES[words.pop("msg", slip)].format(**words)
        return _verdict(exp, "slip", slip, q.points * variant.exercise.partial[slip], msg, text, reveal)
    off = ""
    if exp.form in ("scalar", "magnitude") and exp.value:
        off = f" (yours is {100 * (a - exp.value) / abs(exp.value):+.1f} % off)".replace("-", "−")
    tol = f"{100 * q.tolerance:g} %" if exp.form != "direction" else f"{math.degrees(exp.slack):.2g}°"
    if exp.form == "point":
        tol = f"{1000 * exp.slack:.3g} mm ({tol} of the mechanism's size)"
    msg = MESSAGES["wrong" if exp.hint else "wrong_nohint"].format(tolerance=tol, off=off, hint=exp.hint.rstrip("."))
    return _verdict(exp, "wrong", None, 0.0, msg, text, reveal)


def _shown(answer) -> str:
    """An unreadable answer as text for the report (at most 200 characters)."""
    return (answer if isinstance(answer, str) else repr(answer))[:200]


def _factor(q) -> float:
    return unit_factor(q.unit, dimension_of(q.kind, q.part))


def grade_variant(variant, answers, *, reveal: bool | None = None) -> dict:
    """Grade a student's answers to their variant.

    Parameters
    ----------
    variant : graphkin.exercises.variants.Variant
    answers : mapping of str to str
        Question id → the answer as typed. Missing ids score 0; unknown ids
        are listed under ``"ignored"``.
    reveal : bool, optional
        Show the expected value of every question (default: the exercise's ``reveal``).

    Returns
    -------
    dict
        ``{"exercise", "student", "score", "max", "questions": [{"id", "verdict",
        "slip", "score", "max", "feedback", "answer"[, "expected"]}], "ignored"}``.
    """
    ex = variant.exercise
    reveal = ex.reveal if reveal is None else bool(reveal)
    if not isinstance(answers, Mapping):
        answers = {}
    results = []
    for q in ex.questions:
        # Whatever the sheet holds (a list, a table, null) goes to the reader as it is: it refuses what is not
        # text or a number with a sentence, rather than the grader guessing at str(value).
        raw = answers.get(q.id)
        results.append(grade_question(variant, q, raw, reveal=reveal))
    known = {q.id for q in ex.questions}
    ignored = sorted(str(k)[:100] for k in answers if k not in known)[:50]
    return {"exercise": ex.id, "student": variant.student, "score": round(sum(r["score"] for r in results), 10),
            "max": sum(q.points for q in ex.questions), "questions": results, "ignored": ignored}


__all__ = ["MESSAGES", "VERDICTS", "grade_question", "grade_variant"]
