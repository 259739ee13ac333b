"""Grading: right answers in every accepted format earn full marks, each slip is diagnosed as itself,
wrong answers never earn full marks, and nothing a student types can make the grader raise."""

import json
import math

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from graphkin import exercises
from graphkin.exercises.drawn_tasks import right_drawing
from graphkin.exercises.exercise import dimension_of
from graphkin.exercises.grading import MESSAGES, grade_question
from graphkin.exercises.quantities import expected, unit_factor

STUDENTS = st.text(st.characters(codec="utf-8", categories=("L", "N", "P", "Zs")), min_size=1, max_size=12).filter(
    lambda s: s.strip())
SINGLE = [n for n in exercises.names() if not exercises.load(n).cycle]
SLOW = settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def g(x: float) -> str:
    """A number with 7 significant figures, as a careful student would type it."""
    return f"{x:.7g}"


def drawings(v, q) -> list:
    """A drawn question's right drawing, as JSON text and as the dict a JSON hand-in holds."""
    right = right_drawing(v.drawn(q))
    return [json.dumps(right), right]


def formats(e) -> list[str]:
    """The right answer written in every way the grader promises to read."""
    q = e.question
    dim = dimension_of(q.kind, q.part)
    f = unit_factor(q.unit, dim)
    v = e.value
    if e.form == "vector" and dim == "acceleration":  # a_G or a Coriolis component off the polygons
        mag, ang = abs(v), math.degrees(math.atan2(v.imag, v.real))
        return [f"{g(mag)} m/s^2 ∠ {g(ang)}°", f"{g(mag)} m/s² at {g(ang)} deg", f"({g(v.real)}, {g(v.imag)}) m/s^2",
                f"({g(v.real * 1000)}, {g(v.imag * 1000)}) mm/s^2", f"{g(mag)} ∠ {g(ang)}"]
    if e.form == "vector":
        mag, ang = abs(v), math.degrees(math.atan2(v.imag, v.real))
        return [f"{g(mag)} N ∠ {g(ang)}°", f"{g(mag / 1000)} kN at {g(ang)} deg", f"{g(mag)} N @ {g(math.radians(ang))} rad",
                f"({g(v.real)}, {g(v.imag)}) N", f"({g(v.real)} N, {g(v.imag)} N)", f"{g(mag)} ∠ {g(ang)}",
                f"({g(v.real / 1000)}, {g(v.imag / 1000)}) kN", f"{g(mag)} N ∠ {g(ang + 360)}°"]
    if e.form == "point":
        return [f"({g(v.real * 1000)}, {g(v.imag * 1000)}) mm", f"({g(v.real)}, {g(v.imag)}) m",
                f"({g(v.real / f)}, {g(v.imag / f)})"]
    if e.form == "direction":
        d = math.degrees(v)
        return [f"{g(d)}°", f"{g(d)} deg", f"{g(v)} rad", g(d), f"{g(d + 360)}°", f"{g(d)} °".replace("-", "−")]
    bare = g(v / f)
    if dim == "torque":
        sense = "CCW" if v > 0 else "CW"
        return [f"{g(v)} N*m", f"{g(v)} N·m", f"{g(v)} N m", f"{g(abs(v))} N·m {sense}", f"{g(v * 1000)} N*mm",
                f"{g(v / 1000)} kN*m", bare, f"{g(v)} N·m".replace("-", "−")]
    if dim == "force":
        return [f"{g(v)} N", f"{g(v / 1000)} kN", f"{g(v)}N", bare, f"{g(v * 1000)} mN"]
    if dim == "length":
        return [f"{g(v * 1000)} mm", f"{g(v)} m", f"{g(v * 100)} cm", bare]
    if dim == "energy":
        return [f"{g(v)} J", f"{g(v / 1000)} kJ", f"{g(v)} N*m", bare]
    if dim == "angular_velocity":
        return [f"{g(v)} rad/s", f"{g(v * 30 / math.pi)} rpm", bare]
    if dim in ("angular_acceleration", "acceleration"):
        return [f"{g(v)} {'rad/s^2' if dim.startswith('angular') else 'm/s^2'}", bare]
    if dim == "moment_of_inertia":
        return [f"{g(v)} kg*m^2", f"{g(v)} kg·m²", f"{g(v * 1e6)} kg*mm^2", bare]
    return [bare]


@pytest.mark.parametrize("name", exercises.names())
@SLOW
@given(student=STUDENTS)
def test_right_answers_in_every_format_earn_full_marks(name, student):
    v = exercises.variant(name, student)
    for q in v.exercise.questions:
        e = expected(v, q)
        for text in (formats(e) if e.form != "drawing" else drawings(v, q)):
            r = grade_question(v, q, text)
            assert r["verdict"] == "correct", (q.id, text, e.text, r["feedback"])
            assert r["score"] == q.points


@pytest.mark.parametrize("name", SINGLE)
@SLOW
@given(student=STUDENTS, times=st.floats(1.2, 100), way=st.sampled_from([1, -1]))
def test_wrong_answers_never_earn_full_marks(name, student, times, way):
    v = exercises.variant(name, student)
    for q in v.exercise.questions:
        e = expected(v, q)
        if e.form in ("scalar", "magnitude", "vector"):
            assume(e.value != 0)
            # Off by more than the slack (the tolerance, or the absolute floor near zero), either way.
            value = e.value + way * times * e.slack * (e.value / abs(e.value))
            text = formats(type(e)(**{**e.__dict__, "value": value}))[0]
            r = grade_question(v, q, text)
            assert r["verdict"] != "correct", (q.id, text, e.text)
            assert r["score"] < q.points


def slipped(name, student, qid, slip, *, drawn=True):
    """Grade the right answer of ``qid`` with ``slip`` made (``drawn``: inside a hypothesis test)."""
    v = exercises.variant(name, student)
    q = v.exercise.question(qid)
    e = expected(v, q)
    val = e.value
    if slip == "sign":
        val = -val
    elif slip == "opposite":
        val = val + math.pi
    elif slip == "power_of_ten":
        val = val * 1000
    elif slip == "degrees_radians":
        val = math.radians(val)  # the number in radians, typed as degrees
    elif slip == "wrong_side":
        val = 2 * e.anchor - val
    else:
        from graphkin.exercises.quantities import value_of

        alt = v.altered(slip)
        val = value_of(alt, q)
        # Where the slipped value also reads as another slip (e.g. exactly 1000 times the answer), the grader
        # names the first in its order; such coincidences are not this slip's test.
        ambiguous = (e.form == "scalar" and any(e.close(val / 10.0**k) for k in (3, -3, 6, -6))) \
            or (e.form == "scalar" and e.close(-val))
        if drawn:
            assume(not ambiguous)
        assert not ambiguous
    # A slip that does not move the answer out of its slack (a torque of 0.05 N·m with its sense reversed,
    # within the absolute floor) is a right answer, not this slip's test.
    if drawn:
        assume(not e.close(val))
    assert not e.close(val)
    text = formats(type(e)(**{**e.__dict__, "value": val}))[0]
    return v, q, grade_question(v, q, text)


DIRECTION = """
title = "Directions"
problem = "strip_cutter"
intro = "θ12 = {θ12}"
[vary."θ12"]
field = "driver.theta"
from = "0 deg"
to = "110 deg"
step = "5 deg"
[[questions]]
id = "F23_dir"
find = "F23"
part = "direction"
[[questions]]
id = "T12"
find = "T12"
"""


@pytest.mark.parametrize("name, qid, slip", [
    ("double_slider_forces", "F23", "sign"),
    ("strip_cutter_cut", "T12", "sign"),
    ("gear_pair", "F12", "sign"),
    ("strip_cutter_cut", "T12", "power_of_ten"),
    ("double_slider_forces", "h3", "power_of_ten"),
    ("inertia_resultant", "F3i", "rpm_as_rad_s"),
    ("strip_cutter_cut", "F14", "rpm_as_rad_s"),
    ("strip_cutter_cut", "T12", "rpm_as_rad_s"),
    ("strip_cutter_cut", "F23", "no_inertia_torque"),
    ("strip_cutter_cut", "F23", "no_inertia_force"),
    ("slider_crank_friction", "T12", "no_inertia_force"),
    ("inertia_resultant", "line3", "wrong_side"),
    (DIRECTION, "F23_dir", "opposite"),
    (DIRECTION, "F23_dir", "degrees_radians"),
])
@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(student=STUDENTS)
def test_each_slip_is_diagnosed_as_itself(name, qid, slip, student):
    ex = exercises.parse_exercise(name, id="directions") if "\n" in name else name
    v, q, r = slipped(ex, student, qid, slip)
    assert r["verdict"] == "slip", (r, slip)
    assert r["slip"] == slip
    assert r["score"] == pytest.approx(q.points * v.exercise.partial[slip])
    assert r["feedback"].endswith(".") and "\n" not in r["feedback"]


def test_slip_messages_point_to_the_step_to_revisit():
    v, q, r = slipped("strip_cutter_cut", "s001", "F23", "no_inertia_torque", drawn=False)
    assert "inertia torque" in r["feedback"] and "step" in r["feedback"]
    v, q, r = slipped("double_slider_forces", "s001", "F23", "sign", drawn=False)
    assert "F32" in r["feedback"]
    v = exercises.variant("strip_cutter_cut", "s001")
    r = grade_question(v, v.exercise.question("T12"), "1 N")
    assert r["verdict"] == "slip" and r["slip"] == "dimension" and r["score"] == 0 and "a force" in r["feedback"]
    e = expected(v, v.exercise.question("T12"))
    r = grade_question(v, v.exercise.question("T12"), f"{g(e.value)} J")
    assert r["slip"] == "dimension" and "energy" in r["feedback"] and "N·m" in r["feedback"]


def test_partial_credit_is_configurable():
    text = DIRECTION + "\n[partial]\nsign = 0.75\n"
    ex = exercises.parse_exercise(text, id="directions")
    v, q, r = slipped(ex, "s1", "T12", "sign", drawn=False)
    assert r["score"] == 0.75


def test_expected_value_only_when_allowed():
    answers = {"F23": "1 N"}
    report = exercises.grade("double_slider_forces", "s1", answers)
    assert all("expected" not in q for q in report["questions"])
    report = exercises.grade("double_slider_forces", "s1", answers, reveal=True)
    assert all(q["expected"] for q in report["questions"])


def test_report_is_plain_data():
    report = exercises.grade("strip_cutter_cut", "s1", {"F23": "(1, 2) N", "T12": "3 N*m CW", "bogus": "x"})
    assert json.loads(json.dumps(report)) == report
    assert report["ignored"] == ["bogus"]
    assert [q["verdict"] for q in report["questions"]] == ["wrong", "missing", "wrong"]
    report = exercises.grade("strip_cutter_cut", "s1", {"F23": [1, 2], "T12": {"a": 1}})
    assert [q["verdict"] for q in report["questions"]] == ["unreadable", "missing", "unreadable"]


INJECTIONS = ["__import__('os').system('touch /tmp/graphkin_pwned')", "eval('1+1')", "exec('x=1')", "{{7*7}}",
              "${7*7}", "1; import os", "1 N; __import__('os')", "\x00", "1e999 N", "nan N", "(1, 2, 3) N",
              "1 N" * 500, "'; DROP TABLE students; --", "lambda: 0", "().__class__.__bases__[0].__subclasses__()",
              "1 N ∠ 1 N", "∠", "(,) N", "1 ** 1 ** 1 N", "9**9**9", "1 m^2^3", "\u202e1 N", "١٢ N"]

JSON = st.recursive(st.none() | st.booleans() | st.floats() | st.integers() | st.text(max_size=40),
                    lambda c: st.lists(c, max_size=4) | st.dictionaries(st.text(max_size=8), c, max_size=4),
                    max_leaves=10)


@settings(max_examples=10_000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(text=st.one_of(st.text(max_size=60), st.sampled_from(INJECTIONS), JSON,
                      st.from_regex(r"[-+]?\d{1,4}(\.\d{1,3})? ?(N|kN|N\*m|N·m|J|deg|°|rad|mm|m)?( CW| CCW)?",
                                    fullmatch=True)),
       qid=st.sampled_from(["F23", "F34", "G12", "F12", "h3"]))
@pytest.mark.slow
def test_grader_never_raises_on_anything_typed(text, qid):
    v = _fuzz_variant()
    report = v.grade({qid: text})
    assert 0 <= report["score"] <= report["max"]
    (r,) = [q for q in report["questions"] if q["id"] == qid]
    assert r["verdict"] in ("correct", "slip", "wrong", "unreadable", "missing")
    assert isinstance(r["feedback"], str) and r["feedback"]


@pytest.mark.slow
@settings(max_examples=500, deadline=None)
@given(answers=JSON)
def test_grader_takes_any_json_as_the_answer_sheet(answers):
    report = _fuzz_variant().grade(answers)
    assert 0 <= report["score"] <= report["max"]


def test_no_injection_ran():
    import os

    for text in INJECTIONS:
        _fuzz_variant().grade({"F23": text})
    assert not os.path.exists("/tmp/graphkin_pwned")


_V = {}


def _fuzz_variant():
    if not _V:
        _V["v"] = exercises.variant("double_slider_forces", "fuzz")
    return _V["v"]


def test_message_catalogue_is_sentences():
    for key, text in MESSAGES.items():
        assert text.endswith("."), key


@pytest.mark.parametrize("name", exercises.names())
def test_the_keys_printed_answers_earn_full_marks(name):
    """The key as printed (4 significant figures, the sense in words) is itself a right answer."""
    for i in range(15):
        key = exercises.key(name, f"s{i}")
        report = exercises.grade(name, f"s{i}", {q["id"]: q["answer"].get("drawing", q["answer"]["text"])
                                                 for q in key["questions"]})
        assert report["score"] == report["max"], [q for q in report["questions"] if q["verdict"] != "correct"]


@pytest.mark.parametrize("name", exercises.names())
def test_feedback_never_gives_the_answer_away(name):
    """Unless the teacher reveals answers, no message quotes the expected value (nor a step caption that does)."""
    v = exercises.variant(name, "s7")
    for q in v.exercise.questions:
        e = v.expected(q)
        digits = e.text.split()[0].strip("(,").replace("−", "")
        for text in ["1", "1 N", "1 N*m", "1 J", "(1, 2) N", "1 N ∠ 3°", "abc", "", formats(e)[0].replace("1", "7")]:
            r = grade_question(v, q, text)
            assert digits not in r["feedback"], (q.id, text, r["feedback"])
