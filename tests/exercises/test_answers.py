"""Tests for graphkin.exercises.answers: a student's typed answer read as data."""

from __future__ import annotations

import math
import subprocess
import sys
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphkin.exercises.answers import MAX_CHARS, Reading, Unreadable, read_answer

REPO = Path(__file__).resolve().parents[2]
REL = 1e-12

# The question each test reads for: dimension, unit.
FORCE = dict(dimension="force", unit="N")
TORQUE = dict(dimension="torque", unit="N*m")
ANGLE = dict(dimension="angle", unit="deg")
LENGTH = dict(dimension="length", unit="mm")
ENERGY = dict(dimension="energy", unit="J")
INERTIA = dict(dimension="moment_of_inertia", unit="kg*m^2")
RATIO = dict(dimension="dimensionless", unit="")
QUESTIONS = [FORCE, TORQUE, ANGLE, LENGTH, ENERGY, INERTIA, RATIO]

DIRECTION = math.radians(-73.78)
POLAR_XY = (27.06 * math.cos(DIRECTION), 27.06 * math.sin(DIRECTION))


def unreadable(text, question=FORCE) -> str:
    """Read ``text`` expecting Unreadable; check the message is one sentence; return it."""
    with pytest.raises(Unreadable) as info:
        read_answer(text, **question)
    message = str(info.value)
    assert_one_sentence(message)
    return message


def assert_one_sentence(message: str) -> None:
    assert message and message.isprintable(), repr(message)
    assert len(message.splitlines()) == 1, repr(message)
    assert message.endswith("."), repr(message)
    assert not message.endswith(".."), repr(message)


# ---------------------------------------------------------------------------
# import hygiene


def test_import_does_not_load_pint():
    code = (
        "import sys, graphkin.exercises.answers; "
        "assert 'pint' not in sys.modules, 'pint loaded'; print('ok')"
    )
    out = subprocess.run([sys.executable, "-c", code], cwd=REPO, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "ok"


def test_unreadable_is_a_value_error():
    assert issubclass(Unreadable, ValueError)


# ---------------------------------------------------------------------------
# scalars


@pytest.mark.parametrize(
    "text, number, value, unit",
    [
        ("1.29 kN", 1.29, 1290.0, "kN"),
        ("1290 N", 1290.0, 1290.0, "N"),
        ("1.29e3 N", 1290.0, 1290.0, "N"),
        ("1.29E+3 N", 1290.0, 1290.0, "N"),
        ("+1290N", 1290.0, 1290.0, "N"),
        ("1.29 × 10³ N", 1290.0, 1290.0, "N"),
        ("1.29*10^3 N", 1290.0, 1290.0, "N"),
        ("  1290 N  ", 1290.0, 1290.0, "N"),
        ("1290 N.", 1290.0, 1290.0, "N"),
        ("1290\u00a0N", 1290.0, 1290.0, "N"),
        (".5 kN", 0.5, 500.0, "kN"),
        ("-2 kN", -2.0, -2000.0, "kN"),
        ("- 2 kN", -2.0, -2000.0, "kN"),
    ],
)
def test_force_scalars(text, number, value, unit):
    r = read_answer(text, **FORCE)
    assert r.form == "scalar"
    assert r.number == pytest.approx(number, rel=REL)
    assert r.value == pytest.approx(value, rel=REL)
    assert r.unit == unit and r.dimension == "force"
    assert r.vector is None and r.angle is None and r.sense is None and not r.bare
    assert r.text == text.strip()


def test_bare_number_is_in_the_questions_unit():
    r = read_answer("1290", **FORCE)
    assert (r.value, r.number, r.unit, r.dimension, r.bare) == (1290.0, 1290.0, "", None, True)
    assert read_answer("1.29", dimension="force", unit="kN").value == pytest.approx(1290.0, rel=REL)
    assert read_answer("120.5", **LENGTH).value == pytest.approx(0.1205, rel=REL)


@pytest.mark.parametrize(
    "text, value, unit, sense",
    [
        ("108.9 N*m", 108.9, "N*m", None),
        ("108.9 N·m", 108.9, "N*m", None),
        ("108.9 N⋅m", 108.9, "N*m", None),
        ("108.9 N m", 108.9, "N*m", None),
        ("108.9 N * m", 108.9, "N*m", None),
        ("108.9 N·m CCW", 108.9, "N*m", 1),
        ("108.9 N*m cw", -108.9, "N*m", -1),
        ("108.9 N·m clockwise", -108.9, "N*m", -1),
        ("108.9 N·m Clockwise.", -108.9, "N*m", -1),
        ("108.9 N·m counterclockwise", 108.9, "N*m", 1),
        ("108.9 N·m counter-clockwise", 108.9, "N*m", 1),
        ("108.9 N·m anticlockwise", 108.9, "N*m", 1),
        ("108.9 N·m anti-clockwise", 108.9, "N*m", 1),
        ("108.9 N·m (CW)", -108.9, "N*m", -1),
        ("-108.9 N m", -108.9, "N*m", None),
        ("−108.9 N·m", -108.9, "N*m", None),
        ("–108.9 N·m", -108.9, "N*m", None),
        ("108900 N*mm", 108.9, "N*mm", None),
        ("0.1089 kN*m", 108.9, "kN*m", None),
        ("0.1089 kN·m CW", -108.9, "kN*m", -1),
    ],
)
def test_torque_scalars(text, value, unit, sense):
    r = read_answer(text, **TORQUE)
    assert r.form == "scalar" and r.dimension == "torque" and not r.bare
    assert r.value == pytest.approx(value, rel=REL)
    assert r.unit == unit and r.sense == sense


def test_a_sense_word_gives_the_sign_of_a_size():
    r = read_answer("108.9 N·m CW", **TORQUE)
    assert (r.number, r.value, r.sense) == (-108.9, -108.9, -1)
    r = read_answer("108.9 CW", **TORQUE)  # bare, with a sense
    assert (r.value, r.sense, r.bare) == (-108.9, -1, True)
    # A signed number and a sense word could mean either sense: refused, saying how to write it.
    for text in ("-108.9 N·m CW", "−108.9 N·m CCW"):
        with pytest.raises(Unreadable, match="not both"):
            read_answer(text, **TORQUE)


@pytest.mark.parametrize(
    "text, value, unit",
    [
        ("-73.78°", DIRECTION, "deg"),
        ("-73.78 °", DIRECTION, "deg"),
        ("-73.78 deg", DIRECTION, "deg"),
        ("-73.78 degrees", DIRECTION, "degrees"),
        ("-1.2877 rad", -1.2877, "rad"),
        ("-73.78", DIRECTION, ""),
        ("286.22°", math.radians(286.22), "deg"),
    ],
)
def test_angles(text, value, unit):
    r = read_answer(text, **ANGLE)
    assert r.value == pytest.approx(value, rel=REL)
    assert r.unit == unit and r.bare == (unit == "")
    assert r.dimension == (None if r.bare else "angle")


def test_bare_angle_in_radians_when_the_question_is():
    assert read_answer("-1.2877", dimension="angle", unit="rad").value == -1.2877


@pytest.mark.parametrize(
    "text, question, value, unit",
    [
        ("237.2 J", ENERGY, 237.2, "J"),
        ("0.2372 kJ", ENERGY, 237.2, "kJ"),
        ("237.2 N*m", ENERGY, 237.2, "N*m"),  # a moment's unit, read as energy here
        ("237.2 N·m", ENERGY, 237.2, "N*m"),
        ("0.534 kg*m^2", INERTIA, 0.534, "kg*m^2"),
        ("0.534 kg·m²", INERTIA, 0.534, "kg*m^2"),
        ("0.534 kg m**2", INERTIA, 0.534, "kg*m**2"),
        ("534000 kg*mm^2", INERTIA, 0.534, "kg*mm^2"),
        ("1.41", RATIO, 1.41, ""),
        ("141 %", RATIO, 1.41, "%"),
        ("5 µm", LENGTH, 5e-6, "µm"),
        ("5 μm", LENGTH, 5e-6, "μm"),
        ("3 m/s", dict(dimension="velocity", unit="m/s"), 3.0, "m/s"),
        ("9.81 m·s⁻²", dict(dimension="acceleration", unit="m/s^2"), 9.81, "m*s^-2"),
        ("900 rpm", dict(dimension="angular_velocity", unit="rad/s"), 30 * math.pi, "rpm"),
    ],
)
def test_other_dimensions(text, question, value, unit):
    r = read_answer(text, **question)
    assert r.value == pytest.approx(value, rel=REL)
    assert r.unit == unit
    assert r.dimension == (None if unit == "" else question["dimension"])


# ---------------------------------------------------------------------------
# vectors


@pytest.mark.parametrize(
    "text, unit",
    [
        ("27.06 N ∠ -73.78°", "N"),
        ("27.06 N ∠ −73.78 deg", "N"),
        ("27.06 N at -73.78 deg", "N"),
        ("27.06 N AT -73.78 deg", "N"),
        ("27.06 N @ -73.78°", "N"),
        ("27.06N@-73.78°", "N"),
        ("27.06 ∠ -73.78", ""),
        ("27.06 ∠ -73.78°", ""),
        ("0.02706 kN ∠ -73.78°", "kN"),
        ("27.06 N ∠ 286.22°", "N"),
    ],
)
def test_polar(text, unit):
    r = read_answer(text, **FORCE)
    assert r.form == "polar" and r.unit == unit and r.bare == (unit == "")
    assert r.vector == pytest.approx(POLAR_XY, rel=1e-11)
    assert r.value is None and r.sense is None
    assert r.dimension == (None if r.bare else "force")
    assert math.cos(r.angle) == pytest.approx(math.cos(DIRECTION), rel=1e-11)


def test_polar_keeps_the_magnitude_and_angle_as_written():
    r = read_answer("27.06 N ∠ -1.2877 rad", **FORCE)
    assert r.number == 27.06 and r.angle == -1.2877
    xy = (27.06 * math.cos(-1.2877), 27.06 * math.sin(-1.2877))
    assert r.vector == pytest.approx(xy, rel=REL)
    r = read_answer("0.02706 kN ∠ 286.22°", **FORCE)
    assert r.number == 0.02706
    assert r.angle == pytest.approx(math.radians(286.22), rel=REL)  # not wrapped


def test_polar_on_an_axis_is_exactly_zero():
    assert read_answer("5 N @ 90°", **FORCE).vector == (0.0, 5.0)
    assert read_answer("5 N @ 180 deg", **FORCE).vector == (-5.0, 0.0)


@pytest.mark.parametrize(
    "text, question, xy, unit",
    [
        ("(7.56, -25.98) N", FORCE, (7.56, -25.98), "N"),
        ("(7.56 N, -25.98 N)", FORCE, (7.56, -25.98), "N"),
        ("(7.56, -25.98)", FORCE, (7.56, -25.98), ""),
        ("( 7.56 ,−25.98 )N", FORCE, (7.56, -25.98), "N"),
        ("[7.56, -25.98] N", FORCE, (7.56, -25.98), "N"),
        ("(7.56; -25.98) N", FORCE, (7.56, -25.98), "N"),
        ("(0.00756, -0.02598) kN", FORCE, (7.56, -25.98), "kN"),
        ("(120.5, -33.3) mm", LENGTH, (0.1205, -0.0333), "mm"),
        ("(120.5, -33.3)", LENGTH, (0.1205, -0.0333), ""),
    ],
)
def test_cartesian(text, question, xy, unit):
    r = read_answer(text, **question)
    assert r.form == "vector" and r.unit == unit and r.bare == (unit == "")
    assert r.vector == pytest.approx(xy, rel=REL)
    assert r.number is None and r.value is None and r.angle is None and r.sense is None


# ---------------------------------------------------------------------------
# a unit of another dimension is read, not refused


@pytest.mark.parametrize(
    "text, question, dimension",
    [
        ("237.2 J", TORQUE, "energy"),
        ("0.2372 kJ", TORQUE, "energy"),
        ("237.2 W*s", TORQUE, "energy"),
        ("237.2 W", TORQUE, "power"),
        ("108.9 N*m", FORCE, "torque"),
        ("108.9 J", FORCE, "energy"),
        ("5 mm", FORCE, "length"),
        ("5 rad/s", ANGLE, "angular_velocity"),
        ("5 N", ANGLE, "force"),
        ("5 deg", RATIO, "angle"),
        ("5 Hz", dict(dimension="angular_velocity", unit="rad/s"), "1 / [time]"),
        ("5 kg", INERTIA, "mass"),
        ("5 kg*m", INERTIA, "[mass] * [length]"),
        ("5 N*m/rad", TORQUE, "[mass] * [length] ** 2 / [time] ** 2 * [angle] ** -1"),
        ("5 rad^2", ANGLE, "[angle] ** 2"),
    ],
)
def test_wrong_dimension_is_named(text, question, dimension):
    r = read_answer(text, **question)
    assert r.value is None and r.vector is None and not r.bare
    assert r.number == float(text.split()[0])
    assert r.dimension == dimension


def test_wrong_dimension_vectors():
    r = read_answer("(1, 2) mm", **FORCE)
    assert (r.vector, r.dimension, r.form) == (None, "length", "vector")
    r = read_answer("27.06 N*m ∠ 30°", **FORCE)
    assert (r.vector, r.dimension, r.number) == (None, "torque", 27.06)
    assert r.angle == pytest.approx(math.radians(30), rel=REL)


# ---------------------------------------------------------------------------
# numbers instead of text


def test_numbers_are_bare_answers():
    r = read_answer(1290, **FORCE)
    assert (r.text, r.value, r.bare, r.form) == ("1290", 1290.0, True, "scalar")
    assert read_answer(-73.78, **ANGLE).value == pytest.approx(DIRECTION, rel=REL)
    assert read_answer(1.41, **RATIO).value == 1.41


@pytest.mark.parametrize(
    "value, word",
    [(None, "None"), (True, "bool"), ([1], "list"), ({}, "dict"),
     (b"1 N", "bytes"), ((1, 2), "tuple")],
)
def test_other_types_are_refused(value, word):
    assert word in unreadable(value)


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf, 10**400])
def test_non_finite_numbers_are_refused(value):
    unreadable(value)


# ---------------------------------------------------------------------------
# refusals: one sentence that says how to write it


@pytest.mark.parametrize(
    "text, question, fix",
    [
        ("", FORCE, '"27.06 N"'),
        ("   ", FORCE, '"27.06 N"'),
        ("1" * (MAX_CHARS + 1), FORCE, str(MAX_CHARS)),
        ("1,290 N", FORCE, "decimal point"),
        ("1 2", RATIO, "one number"),
        ("12 foo", FORCE, '"foo"'),
        ("12 Newton", FORCE, '"Newton"'),
        ("5 m2", LENGTH, '"m^2"'),
        ("12 5 N", FORCE, "one number"),
        ("27.06 -73.78", FORCE, "one number"),
        ("1290 N 1.29 kN", FORCE, "one number"),
        ("__import__('os')", FORCE, '"27.06 N"'),
        ("1e999 N", FORCE, "too large"),
        ("1e308 kN", FORCE, "too large"),
        ("nan", FORCE, "nan"),
        ("-inf N", FORCE, "inf"),
        ("NaN N", FORCE, "nan"),
        ("1 m^2^3", LENGTH, "one power"),
        ("9**9**9", FORCE, "one power"),
        ("5 m^999", LENGTH, "unit"),
        ("27.06 N ∠ 30 N", FORCE, "angle"),
        ("27.06 N @ 30 rad/s", FORCE, "angle"),
        ("27.06 N @ 30 @ 40", FORCE, "one direction"),
        ("27.06 N @", FORCE, "@"),
        ("27.06 N @ 30° CW", FORCE, "single number"),
        ("1.41 ratio", RATIO, 'write a number, such as "27.06"'),
        ("(1, 2, 3) N", FORCE, "two components"),
        ("(1) N", FORCE, "two components"),
        ("()", FORCE, "two components"),
        ("(7.56 N, -25.98 kN)", FORCE, "one unit"),
        ("(7.56 N, -25.98)", FORCE, "one unit"),
        ("(7.56 N, -25.98 N) N", FORCE, "unit once"),
        ("(7.56, -25.98) N CCW", FORCE, "single number"),
        ("7.56, -25.98 N", FORCE, "brackets"),
        ("N 12", FORCE, '"27.06 N"'),
        ("CW", TORQUE, '"27.06 N*m"'),
        ("1.41 x", RATIO, '"x"'),
        ("twelve newtons", FORCE, '"27.06 N"'),
        ("12 N\x00", FORCE, "unit"),
        ("1 kg/(m*s", FORCE, "unit"),
    ],
)
def test_refusals_say_how_to_write_it(text, question, fix):
    message = unreadable(text, question)
    assert fix in message, message
    assert message.startswith(("Could not read", "The answer is"))


def test_refusal_quotes_long_or_odd_text_short_and_printable():
    message = unreadable("1 " + "x\n" * 90)
    assert len(message) < 200 and "…" in message
    message = unreadable("\x00\u2028\x1b[31m")
    assert "\x1b" not in message


def test_question_errors_are_plain_value_errors():
    for bad in (dict(dimension="speed", unit="m/s"), dict(dimension="force", unit="J"),
                dict(dimension="torque", unit="J"), dict(dimension="angle", unit=""),
                dict(dimension="force", unit=None), dict(dimension=["force"], unit="N")):
        with pytest.raises(ValueError) as info:
            read_answer("1", **bad)
        assert not isinstance(info.value, Unreadable)


# ---------------------------------------------------------------------------
# properties and fuzzing

INJECTIONS = [
    "__import__('os').system('x')",
    "__import__('os')",
    "{{7*7}}",
    "${7*7}",
    "eval('1')",
    "exec('1')",
    "1; import os",
    "1 N; import os",
    "1 N*__import__('os')",
    "1 N*__class__",
    "1 N*().__class__.__bases__",
    "1 lambda: 0",
    "1 N if 1 else m",
    "\x00",
    "1\x00N",
    "1 N\r\nX-Header: 1",
    "<script>alert(1)</script>",
    "'; DROP TABLE answers; --",
    "1 N" + " " * 10_000,
    "1" * 10_000,
    "(" * 5_000 + ")" * 5_000,
    "1 " + "(" * 50 + "N" + ")" * 50,
    "1 " + "m*" * 29 + "m",
    "1 " + "m^99*" * 9 + "m",
    "1 m" + "^2" * 50,
    "9" + "**9" * 60,
    "1e" + "9" * 150 + " N",
    "1 × 10^" + "9" * 150 + " N",
    "0x1F N",
    "1_000 N",
    "1j N",
    "infinity",
    "1 nan",
    "1 inf",
    "1 %%",
    "1 N @ nan",
    "(nan, 1)",
    "(1, inf) N",
    "∠∠∠",
    "@@@",
    "1 at at 2",
]

# The characters answers are made of, for a denser fuzz of near-answers.
ANSWER_ALPHABET = "0123456789.,eE+-−*/^()[]@∠°·² NmkJgsdradCW%"

NUMBERISH = st.from_regex(
    r"\A[ +\-−]{0,2}[0-9]{0,4}[.,]?[0-9]{0,4}([eE][+-]?[0-9]{1,4})?"
    r"( ?(N|kN|N\*m|N·m|Nm|mm|deg|°|rad|J|kg\*m\^2|m\^2\^3|foo|CW|ccw|[,;@∠()]|at|x10\^3))*\Z",
    fullmatch=False,
)


def read_or_refuse(text, question):
    try:
        r = read_answer(text, **question)
    except Unreadable as exc:
        assert_one_sentence(str(exc))
        return None
    assert isinstance(r, Reading)
    assert r.form in ("scalar", "polar", "vector")
    for x in (r.number, r.value, r.angle, *(r.vector or ())):
        assert x is None or math.isfinite(x)
    return r


@pytest.mark.slow
@settings(max_examples=10_000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(text=st.text(), question=st.sampled_from(QUESTIONS))
def test_fuzz_any_text_reads_or_is_unreadable(text, question):
    read_or_refuse(text, question)


@pytest.mark.slow
@settings(max_examples=1_000, deadline=None)
@given(text=NUMBERISH, question=st.sampled_from(QUESTIONS))
def test_fuzz_numberish_text(text, question):
    read_or_refuse(text, question)


@settings(max_examples=500, deadline=None)
@given(
    text=st.text(alphabet=st.sampled_from(ANSWER_ALPHABET), max_size=40),
    question=st.sampled_from(QUESTIONS),
)
@pytest.mark.slow
def test_fuzz_answer_alphabet(text, question):
    read_or_refuse(text, question)


@pytest.mark.parametrize("text", INJECTIONS)
@pytest.mark.parametrize("question", QUESTIONS)
def test_injections_read_or_are_unreadable(text, question):
    before = time.perf_counter()
    read_or_refuse(text, question)
    assert time.perf_counter() - before < 0.5


@settings(max_examples=300, deadline=None)
@given(
    x=st.floats(allow_nan=False, allow_infinity=False, min_value=-1e9, max_value=1e9),
    unit=st.sampled_from([("N", 1.0), ("kN", 1e3), ("mN", 1e-3)]),
    sense=st.sampled_from([("", 1), (" CCW", 1), (" cw", -1)]),
)
def test_written_number_round_trips(x, unit, sense):
    if sense[0]:
        x = abs(x)  # a sense word goes with a size (a signed number and a sense word are refused)
    r = read_answer(f"{x!r} {unit[0]}{sense[0]}", **FORCE)
    assert r.number == sense[1] * x
    assert r.value == pytest.approx(sense[1] * x * unit[1], rel=REL, abs=1e-300)


@settings(max_examples=300, deadline=None)
@given(
    r=st.floats(min_value=-1e6, max_value=1e6, allow_nan=False),
    deg=st.floats(min_value=-720, max_value=720, allow_nan=False),
)
def test_polar_agrees_with_cartesian(r, deg):
    polar = read_answer(f"{r!r} N @ {deg!r}°", **FORCE).vector
    a = math.radians(deg)
    cartesian = read_answer(f"({r * math.cos(a)!r}, {r * math.sin(a)!r}) N", **FORCE).vector
    assert polar == pytest.approx(cartesian, rel=1e-9, abs=1e-9 * abs(r))


def test_a_thousand_answers_take_well_under_a_second():
    answers = ["1.29 kN", "1290", "108.9 N·m CCW", "27.06 N ∠ -73.78°", "(7.56, -25.98) N",
               "12,5 N", "108.9 Nm", "237.2 J"]
    questions = [FORCE, FORCE, TORQUE, FORCE, FORCE, FORCE, TORQUE, TORQUE]
    for text, q in zip(answers, questions):  # warm the caches
        read_or_refuse(text, q)
    before = time.perf_counter()
    for i in range(1000):
        read_or_refuse(answers[i % 8], questions[i % 8])
    assert time.perf_counter() - before < 0.5


# ---------------------------------------------------------------------------
# answers as people write them (issue 23)


@pytest.mark.parametrize("text, value", [
    ("168 N-m CCW", 168.0), ("168 N.m", 168.0), ("168 Nm", 168.0), ("168 N m", 168.0), ("168 N·m", 168.0),
    ("168 newton metres", 168.0), ("168 newton meter", 168.0), ("168 newton-metres CW", -168.0),
    ("0.168 kN·m", 168.0), ("0.168 kNm", 168.0), ("168000 Nmm", 168.0), ("168000 N-mm", 168.0),
    ("1 ft·lbf", 1.3558179483314004), ("1 ft-lbf", 1.3558179483314004), ("12 in·lbf", 1.3558179483314004),
    ("1 lbf*ft", 1.3558179483314004),
])
def test_torque_spellings(text, value):
    assert read_answer(text, **TORQUE).value == pytest.approx(value, rel=REL)


def test_pound_force_is_converted():
    assert read_answer("100 lbf", **FORCE).value == pytest.approx(444.8221615260501, rel=REL)


@pytest.mark.parametrize("text, value", [("1,29 kN", 1290.0), ("12,5 N", 12.5), ("-0,5 N", -0.5),
                                         ("1,29e3 N", 1290.0),
                                         # Three digits after the comma, but no thousands separator follows a
                                         # 0 or a group of four digits: a decimal comma (issue 34).
                                         ("0,799 kN", 799.0), ("-0,799 kN", -799.0), ("1234,567 N", 1234.567)])
def test_a_decimal_comma_where_the_exercise_allows_it(text, value):
    assert read_answer(text, **FORCE).value == pytest.approx(value, rel=REL)
    message = unreadable_with(text, decimal_comma=False)
    assert "decimal point" in message


def unreadable_with(text, question=FORCE, **options) -> str:
    with pytest.raises(Unreadable) as info:
        read_answer(text, **question, **options)
    assert_one_sentence(str(info.value))
    return str(info.value)


def test_decimal_commas_in_vectors_need_a_semicolon_or_a_space():
    assert read_answer("(7,56; -25,98) N", **FORCE).vector == pytest.approx((7.56, -25.98))
    assert read_answer("(7,56, -25,98) N", **FORCE).vector == pytest.approx((7.56, -25.98))
    assert read_answer("(7.56,-25.98) N", **FORCE).vector == pytest.approx((7.56, -25.98))
    assert '";"' in unreadable_with("(7,56,-25,98) N")


@pytest.mark.parametrize("text, says", [
    ("1,352 N", '"1,352" could be 1.352 or 1352'),
    ("1,290 N", '"1,290" could be 1.290 or 1290'),
    ("12,352.5 N", "write 12352.5 without a thousands separator"),
    ("1,234,567 N", "write 1234567 without a thousands separator"),
])
def test_an_ambiguous_comma_gets_a_sentence(text, says):
    assert says in unreadable_with(text)


def test_a_decimal_comma_in_a_vector_with_three_decimals():
    assert read_answer("(0,799; -1,5) kN", **FORCE).vector == pytest.approx((799.0, -1500.0))


def test_without_decimal_commas_a_thousands_comma_still_gets_a_sentence():
    assert "write 1352 without a thousands separator, or 1.352 with a decimal point" in \
        unreadable_with("1,352 N", decimal_comma=False)


@pytest.mark.parametrize("text, words", [("12 N approx", '"approx"'), ("251 N*m CCW about A0", '"about A0"'),
                                         ("251 N·m about the pivot", '"about the pivot"')])
def test_trailing_words_get_a_sentence(text, words):
    message = unreadable_with(text, TORQUE if "m" in text.split()[1] else FORCE)
    assert f"{words} after the unit is not part of an answer" in message


@pytest.mark.parametrize("text", ["\u202e12 N", "12 N\u200f", "\x1b[31m12 N", "1\x00 N", "12\u2066 N"])
def test_control_and_bidi_characters_are_never_echoed(text):
    try:
        read_answer(text, **FORCE)
    except Unreadable as exc:
        assert str(exc).isprintable()
        for c in "\u202e\u200f\x1b\x00\u2066":
            assert c not in str(exc)


def test_huge_numbers_never_raise_anything_but_unreadable():
    assert "too large" in unreadable_with(10**5000)
    assert "too large" in unreadable_with(-(10**400))
    assert "too long" in unreadable_with("1" * 5000)
    assert "too long" in unreadable_with("1" * 1_000_000 + " N")
