"""Grading: each answer against the key, and a diagnosis of the slip when it is not right.

An answer within the question's tolerance earns full marks. Otherwise the grader asks which common
slip would have produced it. Every slip it knows is a candidate value: the right answer with the sign
or sense reversed, a power of ten off, degrees for radians, a direction turned by 180°, a vector's
components swapped or its angle measured from +y or clockwise, the inertia resultant on the wrong side
of G, the variant re-solved with the speed in rpm used as rad/s or without the inertia torque or force,
and (when the grader is given the class) every classmate's answer. Each candidate has a slack (the
question's tolerance of that value); of those within their slack, the **nearest** wins, measured in
slacks. When two are about as near (within a tenth of a slack), the one worth more is given and the
feedback names the other too. An answer that fits another student's data earns nothing and is named as
such, once that student's data explain two of the sheet's answers (then even where it also fits a slip).

Any other wrong answer gets, besides the step of its route to revisit (or, when it is close, to carry
more digits), what the exercise's ``feedback`` allows. By default (``"parts"``) that is which part is
wrong, never how far off: a vector's size or direction, a scalar's sign or sense, a size more than ten
times off (counted on the decades of the question's unit), so that the feedback cannot be inverted into
the key (each word is true on a whole region, whose bounds are either fixed, as the decades and the sign
are, or a few slacks wide around the key, as "close" and the slips are). With ``"distance"`` it also says
how far off (%, degrees, mm), from which the key follows in one more submission.

The grader never raises on anything a student typed and never evaluates it: answers are read as data
by :mod:`graphkin.exercises.answers` (and, from a notebook, by :mod:`graphkin.exercises.notebooks`). What
a student is told, sentence by sentence, is :mod:`graphkin.exercises.feedback`.

It asks a variant for four things only, so the same code grades a live
:class:`graphkin.exercises.Variant` and a student's precomputed key
(:class:`graphkin.exercises.keys.KeyedVariant`): ``expected(q)``, ``slip_value(q, slip)``,
``words(q)`` and its ``exercise``.
"""

from __future__ import annotations

import cmath
import math
import sys
import traceback
from collections import Counter
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from graphkin.errors import GraphkinError
from graphkin.exercises import designs
from graphkin.exercises.answers import Reading
from graphkin.exercises.drawn_grading import grade_drawn
from graphkin.exercises.exercise import CYCLE_KINDS, FEEDBACK, MOTION_KINDS, dimension_of
from graphkin.exercises.feedback import (
    _TORQUE_KINDS,
    DIMENSION_WORDS,
    MESSAGES,
    PARTS,
    SLIP_WORDS,
    Refusal,
    _factor,
    answer_example,
    how_far_off,
    read_given,
    tolerance_text,
    which_part,
)
from graphkin.exercises.notebooks import NotData
from graphkin.exercises.quantities import Expected, _distance
from graphkin.notation import unit_text

#: Verdicts a question can get ("refused": the whole submission is not graded as this student's, e.g. it
#: carries another student's id; every question then says why).
VERDICTS = ("correct", "slip", "wrong", "unreadable", "missing", "refused")

#: Slips found by solving the variant again as the student did.
RESOLVED_SLIPS = ("rpm_as_rad_s", "no_inertia_torque", "no_inertia_force", "no_normal", "coriolis_reversed",
                  "image_misplaced", *designs.SLIPS)

#: The polygon slips, and the questions each can change (read off the acceleration polygon).
_POLYGON_SLIPS = {"no_normal": ("alpha", "a_G"), "coriolis_reversed": ("alpha", "a_G", "coriolis"),
                  "image_misplaced": ("a_G",)}

#: How many of a sheet's answers one classmate's data must explain before the grader names them: one answer
#: near one classmate's is as likely a slip of the student's own.
CORROBORATE = 2

#: Two candidates are "about as near" when their distances differ by less than this share of a slack.
TIE = 0.1

#: A wrong answer within this many slacks of the right one is a rounding slip, not a wrong method.
CLOSE = 2.5

#: The same, where the feedback does not say how far off (feedback = "parts"): narrower, because where "close" begins
#: is what a search for the key learns from each submission (the band's width sets how many submissions it takes);
#: 1.5 slacks still holds the rounding slip of a 1 % question (1.5 %) and the drawing slip of a 3 % one (4.5 %).
CLOSE_PARTS = 1.5

# How much of an answer the report echoes (the feedback quotes at most the reader's short excerpt).
_ECHO_CHARS = 120


class Classmates:
    """The other students' answers to each question, to tell an answer worked from other data.

    Parameters
    ----------
    answers : mapping of str to mapping of str to float or complex
        Student id → question id → the key's value (SI; vectors and points complex, angles in rad).
    """

    def __init__(self, answers: Mapping):
        self._ids: dict[str, list[str]] = {}
        self._values: dict[str, np.ndarray] = {}
        for student, values in answers.items():
            for qid, value in values.items():
                if value is None or (isinstance(value, float) and not math.isfinite(value)):
                    continue
                self._ids.setdefault(qid, []).append(student)
                self._values.setdefault(qid, []).append(value)
        self._values = {qid: np.asarray(v) for qid, v in self._values.items()}

    @classmethod
    def from_keys(cls, keys) -> Classmates:
        """From keys as :func:`graphkin.exercises.key` gives them (entries with an ``error`` are passed over)."""
        answers = {}
        for key in keys:
            if "error" in key:
                continue
            answers[key["student"]] = {q["id"]: _si_value(q["answer"]["si"]) for q in key["questions"]}
        return cls(answers)

    def __len__(self) -> int:
        return len({s for ids in self._ids.values() for s in ids})

    def only(self, students) -> Classmates:
        """The same class, with only ``students``' answers."""
        keep = set(students)
        out = Classmates({})
        for qid, ids in self._ids.items():
            mask = np.array([s in keep for s in ids], dtype=bool)
            if mask.any():
                out._ids[qid] = [s for s, m in zip(ids, mask) if m]
                out._values[qid] = self._values[qid][mask]
        return out

    def nearest(self, exp: Expected, student: str, a) -> tuple[float, str] | None:
        """The classmate whose answer ``a`` fits best, as (distance in their slack, their id); None if none fits."""
        qid = exp.question.id
        if qid not in self._values:
            return None
        values = self._values[qid]
        if exp.form == "direction":
            d = np.abs(np.remainder(a - values + np.pi, 2 * np.pi) - np.pi)
            own = np.abs(np.remainder(exp.value - values + np.pi, 2 * np.pi) - np.pi)
            slack = np.full(len(values), exp.slack)
        else:
            d, own = np.abs(a - values), np.abs(exp.value - values)
            slack = np.full(len(values), exp.slack) if exp.form == "point" else \
                np.maximum(exp.slack, exp.question.tolerance * np.abs(values))
        # A classmate with the same answer as this student (the same data, or data that give the same) is not
        # "other data": the answer is right for this student too.
        fits = (d <= slack) & (own > exp.slack) & (np.asarray(self._ids[qid]) != student)
        if not fits.any():
            return None
        ratio = np.where(fits, d / np.where(slack > 0, slack, 1.0), np.inf)
        k = int(np.argmin(ratio))
        return float(ratio[k]), self._ids[qid][k]


def _si_value(si):
    return complex(*si) if isinstance(si, list) else si


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


def _verdict(exp: Expected, verdict: str, slip: str | None, score: float, feedback: str, answer: str, reveal: bool,
             **extra):
    q = exp.question
    out = {"id": q.id, "verdict": verdict, "slip": slip, "score": score, "max": q.points, "feedback": feedback,
           "answer": answer, **extra}
    if reveal:
        out["expected"] = exp.text
    return out


@dataclass(frozen=True)
class _Fit:
    """A slip that explains an answer: its name, how near (in its slack), the words of its message."""

    slip: str
    ratio: float
    words: dict
    msg: str
    other: str | None = None  # the classmate, for other_data


def _transforms(exp: Expected):
    """The slips an answer shows by a transformation of the answer itself: (slip, message, undo, make, extra
    words), where ``undo`` takes the slipped answer back to the right one and ``make`` makes the slip."""
    q, form = exp.question, exp.form
    out = []
    if form == "vector":
        force = q.kind == "force"
        # A Coriolis component reversed is a slip of its own (its sense rule), re-solved: not a sign convention.
        if q.kind != "coriolis":
            out.append(("sign", "sign_force" if force else "sign_value", lambda a: -a, lambda a: -a, {}))
        out += [("swapped", "swapped", lambda a: complex(a.imag, a.real), lambda a: complex(a.imag, a.real), {}),
                ("angle_from_y", "angle_from_y", lambda a: a * 1j, lambda a: a * -1j, {}),
                ("clockwise", "clockwise", lambda a: a.conjugate(), lambda a: a.conjugate(), {})]
    elif form == "scalar":
        msg = "sign_torque" if q.kind in _TORQUE_KINDS else "sign_value"
        out.append(("sign", msg, lambda a: -a, lambda a: -a, {}))
    elif form == "magnitude":
        out.append(("sign", "sign_magnitude", lambda a: -a, lambda a: -a, {}))
    elif form == "direction":
        if q.part == "direction":  # a crank angle where a peak occurs has no "opposite": only a force's direction
            if q.kind != "coriolis":
                out.append(("opposite", "opposite" if q.kind == "force" else "opposite_other", lambda a: a + math.pi,
                            lambda a: a + math.pi, {}))
            out += [("swapped", "swapped", lambda a: math.pi / 2 - a, lambda a: math.pi / 2 - a, {}),
                    ("angle_from_y", "angle_from_y", lambda a: a + math.pi / 2, lambda a: a - math.pi / 2, {}),
                    ("clockwise", "clockwise", lambda a: -a, lambda a: -a, {})]
        for factor, wrong, right in ((180 / math.pi, "radians", "degrees"), (math.pi / 180, "degrees", "radians")):
            out.append(("degrees_radians", "degrees_radians", lambda a, f=factor: a * f, lambda a, f=factor: a / f,
                        {"wrong": wrong, "right": right}))
    if form in ("scalar", "magnitude", "vector", "point"):
        for k in (3, -3, 6, -6):
            out.append(("power_of_ten", "power_of_ten", lambda a, k=k: a / 10.0**k, lambda a, k=k: a * 10.0**k,
                        {"factor": f"10^{abs(k)}", "way": "large" if k > 0 else "small"}))
    if form == "point" and exp.anchor is not None:
        out.append(("wrong_side", "wrong_side", lambda a: 2 * exp.anchor - a, lambda a: 2 * exp.anchor - a, {}))
    return out


def _fits(exp: Expected, a, variant, classmates: Classmates | None) -> list[_Fit]:
    """Every slip that explains ``a`` within its slack, nearest first."""
    q, form, e = exp.question, exp.form, exp.value
    words = variant.words(q)
    fits = []
    if exp.slack > 0 and (e or form in ("direction", "point")):
        for slip, msg, undo, make, extra in _transforms(exp):
            # A slip that leaves the right answer where it is (the sign of a value within its slack of 0, the
            # components of a vector at 45°) cannot be told from it.
            if exp.close(make(e)):
                continue
            d = _distance(form, undo(a), e)
            if d <= exp.slack:
                fits.append(_Fit(slip, d / exp.slack, {**words, **extra}, msg))
    for slip in RESOLVED_SLIPS:
        if not _may(q, slip):
            continue
        other = variant.slip_value(q, slip)
        if other is None or exp.close(other):  # the slip leaves this answer unchanged: it cannot be told apart
            continue
        slack = _slack_of(exp, other)
        d = _distance(form, a, other)
        if slack > 0 and d <= slack:
            fits.append(_Fit(slip, d / slack, words, slip))
    if classmates is not None:
        near = classmates.nearest(exp, variant.student, a)
        if near is not None:
            fits.append(_Fit("other_data", near[0], words, "other_data", near[1]))
    return sorted(fits, key=lambda f: f.ratio)


def _may(q, slip: str) -> bool:
    """Whether a re-solved slip can change this question's answer at all."""
    if q.kind == "drawing":
        return False  # a drawing's slips are its own targets (graphkin.exercises.drawn_tasks)
    if (slip in designs.SLIPS) != (q.kind in designs.DESIGN_KINDS):
        # A design's slips are its own, and it takes no other: a study per slip, for a design that fails the limit.
        return False
    if slip in designs.SLIPS:
        return True
    if slip == "rpm_as_rad_s":
        return True
    if slip in _POLYGON_SLIPS:
        return q.kind in _POLYGON_SLIPS[slip]
    if q.kind in MOTION_KINDS:
        return False  # the polygons do not read the inertia loads
    # Leaving out an inertia load makes the inertia questions themselves zero or undefined: a wrong answer
    # there is not that slip. Over the cycle they are not tried (a sweep per slip, for little diagnosis).
    return q.kind not in ("inertia_force", "inertia_torque", "h") and q.kind not in CYCLE_KINDS


def _slack_of(exp: Expected, other) -> float:
    """The slack of a slipped value ``other``: the question's tolerance of that value (at least the answer's)."""
    if exp.form in ("direction", "point") or not abs(exp.value) > 0:
        return exp.slack
    return max(exp.slack, exp.question.tolerance * abs(other))


def _credit(exercise, slip: str) -> float:
    return 0.0 if slip == "other_data" else exercise.partial.get(slip, 0.0)


def _diagnose(exp: Expected, a, variant, classmates, copied: bool) -> tuple[_Fit, list[_Fit], _Fit | None] | None:
    """The slip to name (the nearest, or of the about-as-near ones the one worth more), the others as near, and
    the classmate whose data explain the answer (if any). With ``copied`` (the classmates are known to have lent
    this sheet answers) a classmate's data come first, whatever slip the answer also fits."""
    fits = _fits(exp, a, variant, classmates)
    if not fits:
        return None
    theirs = next((f for f in fits if f.slip == "other_data"), None)
    if copied and theirs is not None:
        return theirs, [], theirs
    near = [f for f in fits if f.ratio - fits[0].ratio <= TIE]
    # One fit per slip: the same slip may fit twice (×10³ and ×10⁶ are never both near; a tie of one slip with
    # itself says nothing).
    seen, unique = set(), []
    for f in near:
        if f.slip not in seen:
            seen.add(f.slip)
            unique.append(f)
    ex = variant.exercise
    chosen = max(unique, key=lambda f: (_credit(ex, f.slip), -f.ratio))
    return chosen, [f for f in unique if f is not chosen], theirs


def _mode(exercise, feedback: str | None) -> str:
    """The feedback a wrong answer gets: ``feedback`` when given, else the exercise's (:data:`FEEDBACK`)."""
    mode = exercise.feedback if feedback is None else feedback
    if mode not in FEEDBACK:
        raise GraphkinError(f"feedback must be {' or '.join(map(repr, FEEDBACK))}, got {mode!r}")
    return mode


def _wrong(exp: Expected, a, variant, text: str, reveal: bool, mode: str) -> dict:
    """A wrong answer's verdict: the size right (a vector), close (rounding), or which part is wrong (``mode``
    "parts") or how far off (``mode`` "distance"), and where to look."""
    q = exp.question
    words = variant.words(q)
    distance = mode == "distance"
    tol, off = tolerance_text(exp), how_far_off(exp, a) if distance else ""
    if exp.form == "vector" and exp.value and abs(abs(a) - abs(exp.value)) <= exp.slack:
        degrees = f"{math.degrees(abs(cmath.phase(a / exp.value))):.1f}" if a else "180"
        msg = MESSAGES["direction_distance" if distance else "direction"].format(degrees=degrees, hint=words["hint"])
        return _verdict(exp, "slip", "direction", q.points * variant.exercise.partial["direction"], msg, text, reveal)
    if exp.slack > 0 and _distance(exp.form, a, exp.value) <= (CLOSE if distance else CLOSE_PARTS) * exp.slack:
        msg = MESSAGES["close_graphical" if q.route == "graphical" else "close"].format(tolerance=tol, off=off)
        return _verdict(exp, "wrong", None, 0.0, msg, text, reveal)
    hint = exp.hint.rstrip(".") if exp.hint else ""
    parts = "" if distance else which_part(exp, a)
    if q.kind in designs.DESIGN_KINDS and distance:
        # Whether a design meets the limits is bounded by the key itself (the lightest that meets them), so a search
        # bisects on it: said only where the feedback says how far off anyway, which gives the key away as it is.
        parts = designs.design_part(exp, a, words, variant.exercise.design.step) + off
    if parts:
        msg = MESSAGES["wrong_parts" if hint else "wrong_parts_nohint"].format(tolerance=tol, parts=parts, hint=hint)
    else:
        msg = MESSAGES["wrong" if hint else "wrong_nohint"].format(tolerance=tol, off=off, hint=hint)
    return _verdict(exp, "wrong", None, 0.0, msg, text, reveal)


def grade_question(variant, q, answer, *, reveal: bool = False, classmates: Classmates | None = None,
                   copied: bool = False, feedback: str | None = None) -> dict:
    """Grade one answer; never raises on the answer, whatever it is.

    Parameters
    ----------
    variant : Variant or KeyedVariant
        The student's variant (live, or from precomputed keys).
    q : Question
    answer : object
        What the student gave: text, a number, None (unanswered), or
        :class:`graphkin.exercises.notebooks.NotData`; anything else is refused with a sentence.
    reveal : bool
        Show the expected value.
    classmates : Classmates, optional
        The class's answers: an answer that fits another student's data is named as such (the nearer of it
        and a slip wins, as between two slips).
    copied : bool
        Whether ``classmates`` are known to have lent this sheet answers (:func:`grade_variant`: their data
        explain two or more of its answers): an answer their data explain then earns nothing, even when it
        also fits a slip.
    feedback : str, optional
        What the feedback on a wrong answer says (:data:`graphkin.exercises.exercise.FEEDBACK`); default the
        exercise's ``feedback``.
    """
    exp = variant.expected(q)
    try:
        if q.kind == "drawing":
            return grade_drawn(variant, q, answer, reveal=reveal)
        return _grade(variant, q, exp, answer, reveal, classmates, copied, _mode(variant.exercise, feedback))
    except Exception:  # a bug in the grader must not void this answer's neighbours, nor show a traceback
        print(f"graphkin: grading {q.id} of {variant.student!r} failed:", file=sys.stderr)
        traceback.print_exc(file=sys.stderr)
        return _verdict(exp, "unreadable", None, 0.0, MESSAGES["error"], echo(answer), reveal)


def _grade(variant, q, exp: Expected, answer, reveal: bool, classmates, copied: bool, mode: str) -> dict:
    r = read_given(q, answer, decimal_comma=variant.exercise.decimal_comma)
    if isinstance(r, Refusal):
        return _verdict(exp, r.verdict, None, 0.0, r.sentence, "" if r.verdict == "missing" else echo(answer), reveal)
    dim = dimension_of(q.kind, q.part)
    text = echo(r.text)
    if r.value is None and r.vector is None and not r.bare:
        right = unit_text(q.unit) or "no unit"
        words = variant.words(q)
        given = DIMENSION_WORDS.get(r.dimension, r.dimension or "something else")
        msg = MESSAGES["dimension"].format(unit=echo(unit_text(r.unit), 40), given=given, name=words["name"],
                                           wanted=DIMENSION_WORDS.get(dim, dim), right=right,
                                           example=answer_example(exp))
        share = variant.exercise.partial["dimension"]
        # A wrong dimension earns the share (0 by default) only when the number itself is right.
        number_right = r.number is not None and exp.form in ("scalar", "magnitude") and \
            exp.close(r.number * _factor(q))
        return _verdict(exp, "slip", "dimension", q.points * share if number_right else 0.0, msg, text, reveal)
    a = _comparable(exp, r)
    if isinstance(a, str) or a is None:
        key = a or "need_scalar"
        return _verdict(exp, "wrong", None, 0.0, MESSAGES[key].format(name=q.find, example=answer_example(exp)), text,
                        reveal)
    if exp.close(a):
        return _verdict(exp, "correct", None, q.points, MESSAGES["correct"], text, reveal)
    found = _diagnose(exp, a, variant, classmates, copied)
    if found is None:
        return _wrong(exp, a, variant, text, reveal, mode)
    fit, ties, theirs = found
    msg = MESSAGES[fit.msg].format(**fit.words)
    if ties:
        msg += MESSAGES["tie"].format(others=" and ".join(SLIP_WORDS.get(t.slip, t.slip) for t in ties))
    if fit.slip == "other_data":
        return _verdict(exp, "wrong", "other_data", 0.0, msg, text, reveal, other=fit.other)
    # A classmate whose data explain the answer too, slip or not: for the teacher (and to count how many of the
    # sheet's answers they explain); the feedback names them only when about as near as the slip.
    other = {"other": theirs.other} if theirs is not None else {}
    return _verdict(exp, "slip", fit.slip, q.points * variant.exercise.partial[fit.slip], msg, text, reveal, **other)


def echo(answer, limit: int = _ECHO_CHARS) -> str:
    """An answer as the report repeats it: printable text on one line, at most ``limit`` characters.

    Control and bidirectional-override characters become U+FFFD; a huge integer is described, never
    converted to text (Python refuses to print one of more than 4300 digits).
    """
    if isinstance(answer, NotData):
        return f"({answer.reason}, not text)"
    if isinstance(answer, bool) or answer is None:
        return repr(answer)
    if isinstance(answer, int) and abs(answer).bit_length() > 300:
        return f"(a whole number of about {int(abs(answer).bit_length() * 0.30103) + 1} digits)"
    text = answer if isinstance(answer, str) else _safe_repr(answer)
    text = "".join(c if c.isprintable() else "\N{REPLACEMENT CHARACTER}" for c in text[:limit + 1])
    return text if len(text) <= limit else text[:limit - 1] + "…"


def _safe_repr(value) -> str:
    try:
        return repr(value)[:_ECHO_CHARS + 1]
    except Exception:  # a huge integer inside a list, say
        return f"(a {type(value).__name__})"


def grade_variant(variant, answers, *, reveal: bool | None = None, classmates: Classmates | None = None,
                  feedback: str | None = None) -> dict:
    """Grade a student's answers to their variant.

    Parameters
    ----------
    variant : graphkin.exercises.variants.Variant or graphkin.exercises.keys.KeyedVariant
    answers : mapping of str to str
        Question id → the answer as typed. Missing ids score 0; unknown ids
        are listed under ``"ignored"``.
    reveal : bool, optional
        Show the expected value of every question (default: the exercise's ``reveal``).
    classmates : Classmates, optional
        The class's answers. When one student's data explain at least :data:`CORROBORATE` of the sheet's
        answers, each answer they explain earns nothing and says so, even one that also fits a slip. One
        answer alone that fits a classmate's data is graded as the student's own (a slip's share if it fits
        one, else nothing), without naming anyone; on a one-question sheet it is named, unless a slip fits it
        at least as well.
    feedback : str, optional
        What the feedback on a wrong answer says (:data:`graphkin.exercises.exercise.FEEDBACK`); default the
        exercise's ``feedback``.

    Returns
    -------
    dict
        ``{"exercise", "student", "score", "max", "questions": [{"id", "verdict",
        "slip", "score", "max", "feedback", "answer"[, "expected"][, "other"]}], "ignored"}``;
        ``other`` names the classmate whose data an answer fits (for the teacher; the feedback does not).
    """
    ex = variant.exercise
    reveal = ex.reveal if reveal is None else bool(reveal)
    if not isinstance(answers, Mapping):
        answers = {}
    # Whatever the sheet holds (a list, a table, null) goes to the reader as it is: it refuses what is not text
    # or a number with a sentence, rather than the grader guessing at str(value).
    results = [grade_question(variant, q, answers.get(q.id), reveal=reveal, classmates=classmates, feedback=feedback)
               for q in ex.questions]
    if classmates is not None:
        named = Counter(r["other"] for r in results if r.get("other"))
        need = min(CORROBORATE, len(ex.questions))
        # Copying is shown when one classmate's data explain two or more of the sheet's answers: then each answer
        # their data explain is theirs, even one that also fits a slip of the student's own.
        copied = need == CORROBORATE and any(n >= need for n in named.values())
        if copied or any(n < need for n in named.values()):
            # One answer near one classmate's is as likely a slip of one's own (each classmate's answer has its
            # 1 % of slack, and a class covers much of the range): grade again with only the classmates whose
            # data explain several of this sheet's answers.
            kept = classmates.only(s for s, n in named.items() if n >= need)
            results = [grade_question(variant, q, answers.get(q.id), reveal=reveal, classmates=kept, copied=copied,
                                      feedback=feedback)
                       for q in ex.questions]
    known = {q.id for q in ex.questions}
    ignored = sorted(echo(k, 100) for k in answers if k not in known)[:50]
    return {"exercise": ex.id, "student": variant.student, "score": round(sum(r["score"] for r in results), 10),
            "max": sum(q.points for q in ex.questions), "questions": results, "ignored": ignored}


__all__ = ["CLOSE", "CLOSE_PARTS", "CORROBORATE", "Classmates", "MESSAGES", "PARTS", "RESOLVED_SLIPS", "Refusal",
           "SLIP_WORDS", "TIE", "VERDICTS", "answer_example", "echo", "grade_question", "grade_variant", "read_given"]
