"""Tests for graphkin.units: the boundary between problem-file strings and SI."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphkin.errors import ProblemFileError
from graphkin.units import DIMENSIONS, SI_UNITS, format_si, registry, to_si, to_si_array, to_si_vector, written

FILE = "problems/slider_crank.toml"
FIELD = "links[2].value"
REPO = Path(__file__).resolve().parents[2]


def raises_pfe(value, dimension, *, field=FIELD, file=FILE, fn=to_si):
    """Call ``fn`` expecting a ProblemFileError naming the file and field."""
    with pytest.raises(ProblemFileError) as info:
        fn(value, dimension, field=field, file=file)
    err = info.value
    text = str(err)
    assert err.file == file and err.field == field
    assert file in text and field in text
    return err.message


# ---------------------------------------------------------------------------
# import hygiene


def test_import_does_not_load_pint():
    code = (
        "import sys, graphkin.units; "
        "assert 'pint' not in sys.modules, 'pint loaded'; print('ok')"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], cwd=REPO, capture_output=True, text=True
    )
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "ok"


def test_registry_is_shared_and_prints_in_written_order():
    ureg = registry()
    assert registry() is ureg
    assert ureg.formatter.default_sort_func is None
    assert format(ureg.Unit("N*m"), "~P") == "N·m"


def test_tables_cover_the_same_dimensions():
    required = {
        "length", "angle", "mass", "time", "velocity", "acceleration",
        "angular_velocity", "angular_acceleration", "force", "torque",
        "moment_of_inertia", "density", "dimensionless",
    }
    assert required <= set(DIMENSIONS)
    assert set(SI_UNITS) == set(DIMENSIONS)
    ureg = registry()
    for dim, text in DIMENSIONS.items():
        # every value parses as a pint dimensionality
        ureg.get_dimensionality(text)
        if SI_UNITS[dim]:
            assert ureg.parse_units(SI_UNITS[dim]).dimensionality == (
                ureg.get_dimensionality(text)
            )


# ---------------------------------------------------------------------------
# conversions


@pytest.mark.parametrize(
    "value, dimension, expected",
    [
        ("500 mm", "length", 0.5),
        ("500mm", "length", 0.5),
        ("  500 mm  ", "length", 0.5),
        ("900 rpm", "angular_velocity", 94.2477796076938),
        ("900 rev/min", "angular_velocity", 94.2477796076938),
        ("90 deg/s", "angular_velocity", math.pi / 2),
        ("3 rad/s", "angular_velocity", 3.0),
        ("2 m/s", "velocity", 2.0),
        ("5 kg", "mass", 5.0),
        ("250 g", "mass", 0.25),
        ("7.6 deg", "angle", 0.132645023151569),
        ("0.5 rev", "angle", math.pi),
        ("1 turn", "angle", 2 * math.pi),
        ("1.2 rad", "angle", 1.2),
        ("-2000 N", "force", -2000.0),
        ("2.5 kN", "force", 2500.0),
        ("0.10417 kg*m^2", "moment_of_inertia", 0.10417),
        ("104170 kg*mm^2", "moment_of_inertia", 0.10417),
        ("8.312 rad/s^2", "angular_acceleration", 8.312),
        ("865 N*mm", "torque", 0.865),
        ("50.8 N*m", "torque", 50.8),
        ("50.8 N m", "torque", 50.8),
        ("50.8 N·m", "torque", 50.8),
        ("1.2 kN*m", "torque", 1200.0),
        ("9.81 m/s^2", "acceleration", 9.81),
        ("7850 kg/m^3", "density", 7850.0),
        ("7.85 g/cm^3", "density", 7850.0),
        ("20 ms", "time", 0.02),
        ("1e-3 m", "length", 1e-3),
        ("+2 m", "length", 2.0),
        ("0.3", "dimensionless", 0.3),
        ("30 percent", "dimensionless", 0.3),
        (0.3, "dimensionless", 0.3),
        (1, "dimensionless", 1.0),
        (np.float64(0.15), "dimensionless", 0.15),
    ],
)
def test_to_si_converts(value, dimension, expected):
    got = to_si(value, dimension, field="x")
    assert type(got) is float
    assert got == pytest.approx(expected, rel=1e-12)


def test_to_si_accepts_pint_quantities():
    ureg = registry()
    assert to_si(ureg.Quantity(865, "N*mm"), "torque", field="t") == pytest.approx(0.865)
    assert to_si(ureg.Quantity(90, "deg"), "angle", field="a") == pytest.approx(math.pi / 2)
    message = raises_pfe(ureg.Quantity(5, "N"), "length")
    assert "length" in message and "force" in message


@pytest.mark.parametrize("value, dimension, unit, size, half", [
    ("862.5 rpm", "angular_velocity", "rpm", math.pi / 30, 0.05),
    ("1500 rpm", "angular_velocity", "rpm", math.pi / 30, 0.5),
    ("-1.5e3 rpm", "angular_velocity", "rpm", math.pi / 30, 50.0),
    ("2.50E-1 m/s", "velocity", "m/s", 1.0, 0.0005),
    ("0 deg", "angle", "deg", math.pi / 180, 0.5),
    (".25 mm", "length", "mm", 1e-3, 0.005),
])
def test_written_says_a_values_unit_and_its_rounding(value, dimension, unit, size, half):
    """Half a unit in the last digit written, in SI: what a book's printed number may differ from its value by."""
    w = written(value, dimension, field="x")
    assert w.unit == unit and w.size == pytest.approx(size, rel=1e-15)
    assert w.rounding == pytest.approx(half * size, rel=1e-12)


def test_written_has_no_digits_for_a_pint_quantity_and_checks_as_to_si_does():
    assert written(registry().Quantity(90, "deg"), "angle", field="a") == ("rad", 1.0, 0.0)
    assert "angular velocity" in raises_pfe("5 N", "angular_velocity", fn=written)


_UNIT_TABLE = [
    ("mm", "length", 1e-3),
    ("cm", "length", 1e-2),
    ("m", "length", 1.0),
    ("km", "length", 1e3),
    ("g", "mass", 1e-3),
    ("ms", "time", 1e-3),
    ("kN", "force", 1e3),
    ("N*mm", "torque", 1e-3),
    ("rad", "angle", 1.0),
]

_finite_floats = st.floats(
    min_value=-1e300, max_value=1e300, allow_nan=False, allow_infinity=False
).filter(lambda x: x == 0.0 or abs(x) > 1e-290)


@settings(max_examples=300, deadline=None)
@given(x=_finite_floats)
def test_millimetres_property(x):
    assert math.isclose(to_si(f"{x} mm", "length", field="x"), x / 1000, rel_tol=1e-12)


@settings(max_examples=300, deadline=None)
@given(x=_finite_floats, entry=st.sampled_from(_UNIT_TABLE))
def test_unit_table_property(x, entry):
    unit, dimension, factor = entry
    got = to_si(f"{x} {unit}", dimension, field="x")
    assert math.isclose(got, x * factor, rel_tol=1e-12)


# ---------------------------------------------------------------------------
# errors


@pytest.mark.parametrize(
    "value, dimension, example",
    [
        ("500", "length", '"500 mm"'),
        (500, "length", '"500 mm"'),
        (500.0, "length", '"500 mm"'),
        ("5", "mass", '"5 kg"'),
        ("-2000", "force", '"-2000 N"'),
        ("865", "torque", '"865 N*m"'),
    ],
)
def test_missing_units(value, dimension, example):
    message = raises_pfe(value, dimension)
    assert "units are missing" in message
    assert f"write it as {example}" in message


@pytest.mark.parametrize("value", ["7.6", 7.6, 90])
def test_bare_angle_is_ambiguous(value):
    message = raises_pfe(value, "angle")
    assert "units are missing" in message
    assert "degrees or radians" in message
    assert "deg" in message and "rad" in message


@pytest.mark.parametrize(
    "value, dimension, expected, given",
    [
        ("5 N", "length", "length", "force"),
        ("500 mm", "force", "force", "length"),
        ("5 kg", "moment_of_inertia", "moment of inertia", "mass"),
        ("3 rad", "angular_velocity", "angular velocity", "angle"),
        ("2 m/s", "angular_velocity", "angular velocity", "velocity"),
        ("0.3 m", "dimensionless", "dimensionless", "length"),
        ("5 s", "angle", "angle", "time"),
    ],
)
def test_wrong_dimension(value, dimension, expected, given):
    message = raises_pfe(value, dimension)
    assert expected in message
    assert given in message
    assert value in message


@pytest.mark.parametrize(
    "value, dimension",
    [
        ("5 Hz", "angular_velocity"),
        ("5 1/s", "angular_velocity"),
        ("5 percent", "angle"),
        ("5 Hz/s", "angular_acceleration"),
    ],
)
def test_angular_values_need_an_angle_unit(value, dimension):
    message = raises_pfe(value, dimension)
    assert "no angle unit" in message


@pytest.mark.parametrize(
    "value, dimension",
    [("5 deg", "dimensionless"), ("5 N*m/rad", "torque"), ("5 deg*deg", "angle")],
)
def test_unexpected_angle_units(value, dimension):
    message = raises_pfe(value, dimension)
    assert "angle unit" in message


@pytest.mark.parametrize(
    "value, needle",
    [
        ("5 furlongz", '"furlongz"'),
        ("abc", "could not read"),
        ("mm", "could not read"),
        ("", "could not read"),
        ("   ", "could not read"),
        ("5 mm)", "could not read"),
        ("5 5 mm", "could not read"),
        ("5 m^2^3", "could not read"),
        ("7,6 mm", "decimal point"),
        ("1,000 mm", "decimal point"),
    ],
)
def test_unparseable(value, needle):
    message = raises_pfe(value, "length")
    assert needle in message


@pytest.mark.parametrize(
    "value, fix",
    [
        ("50.8 Nm", '"N*m"'),
        ("5 kNm", '"kN*m"'),
        ("865 Nmm", '"N*mm"'),
        ("865 mNm", '"mN*m"'),
    ],
)
def test_glued_torque_units_are_rejected(value, fix):
    message = raises_pfe(value, "torque")
    assert fix in message
    assert "write" in message


def test_glued_torque_units_are_rejected_for_other_dimensions_too():
    message = raises_pfe("50 Nm", "length")
    assert '"N*m"' in message


@pytest.mark.parametrize(
    "value", ["5 J", "5 kJ", "5 cal", "5 Wh", "5 kWh", "5 W*s", "5 eV", "5 mJ"]
)
def test_energy_units_are_not_torques(value):
    message = raises_pfe(value, "torque")
    assert "torque is written in N*m (J is energy)" in message


def test_n_minus_m_hint():
    message = raises_pfe("5 N-m", "torque")
    assert '"*"' in message


@pytest.mark.parametrize(
    "value, dimension",
    [
        ("nan mm", "length"),
        ("NaN mm", "length"),
        ("inf N", "force"),
        ("-inf N", "force"),
        ("1e400 mm", "length"),
        (float("nan"), "dimensionless"),
        (float("inf"), "dimensionless"),
        ("nan", "dimensionless"),
    ],
)
def test_non_finite_rejected(value, dimension):
    message = raises_pfe(value, dimension)
    assert "finite" in message


def test_overflow_in_conversion_rejected():
    message = raises_pfe("1e308 km", "length")
    assert "too large" in message


@pytest.mark.parametrize(
    "value, type_name",
    [
        (True, "bool"),
        (False, "bool"),
        (None, "None"),
        ({"magnitude": "5 N"}, "dict"),
        (["5 mm"], "list"),
        (("5 mm",), "tuple"),
        (b"5 mm", "bytes"),
        (object(), "object"),
    ],
)
def test_non_scalars_rejected_with_type_named(value, type_name):
    message = raises_pfe(value, "length")
    assert type_name in message


def test_bool_rejected_for_dimensionless():
    message = raises_pfe(True, "dimensionless")
    assert "bool" in message


def test_unknown_dimension_is_a_programming_error():
    with pytest.raises(ValueError, match="unknown dimension") as info:
        to_si("5 N", "forse", field="x")
    assert not isinstance(info.value, ProblemFileError)


def test_default_file_name():
    with pytest.raises(ProblemFileError) as info:
        to_si("500", "length", field="crank.length")
    assert str(info.value).startswith("<input>: crank.length: ")


# ---------------------------------------------------------------------------
# vectors


def test_vector_components():
    assert to_si_vector(["3 N", "-4 N"], "force", field="F") == (3.0, -4.0)
    assert to_si_vector(("3 mm", "4 mm"), "length", field="r") == (0.003, 0.004)


@pytest.mark.parametrize(
    "angle, expected",
    [
        ("0 deg", (5.0, 0.0)),
        ("90 deg", (0.0, 5.0)),
        ("180 deg", (-5.0, 0.0)),
        ("270 deg", (0.0, -5.0)),
        ("-90 deg", (0.0, -5.0)),
        ("30 deg", (5 * math.cos(math.pi / 6), 2.5)),
        ("0.5 rev", (-5.0, 0.0)),
    ],
)
def test_vector_polar(angle, expected):
    x, y = to_si_vector({"magnitude": "5 N", "angle": angle}, "force", field="F")
    assert x == pytest.approx(expected[0], rel=1e-12, abs=0.0)
    assert y == pytest.approx(expected[1], rel=1e-12, abs=0.0)


def test_vector_polar_exact_zeros():
    x, y = to_si_vector({"magnitude": "2000 N", "angle": "90 deg"}, "force", field="F")
    assert x == 0.0 and y == 2000.0


def test_vector_polar_negative_magnitude_points_the_other_way():
    x, y = to_si_vector({"magnitude": "-5 N", "angle": "0 deg"}, "force", field="F")
    assert (x, y) == (-5.0, 0.0)


def test_vector_errors_name_the_component():
    with pytest.raises(ProblemFileError) as info:
        to_si_vector(["3 N", "4"], "force", field="loads[0].F", file=FILE)
    assert info.value.field == "loads[0].F[1]"
    assert "loads[0].F[1]" in str(info.value) and FILE in str(info.value)

    with pytest.raises(ProblemFileError) as info:
        to_si_vector({"magnitude": "5 N", "angle": "30"}, "force", field="F", file=FILE)
    assert info.value.field == "F.angle"
    assert "degrees or radians" in info.value.message

    with pytest.raises(ProblemFileError) as info:
        to_si_vector({"magnitude": "5 m", "angle": "30 deg"}, "force", field="F")
    assert info.value.field == "F.magnitude"


@pytest.mark.parametrize(
    "value, needle",
    [
        (["3 N"], "2 components"),
        (["3 N", "4 N", "5 N"], "2 components"),
        ({"magnitude": "5 N"}, "missing angle"),
        ({"magnitude": "5 N", "angle": "3 deg", "x": "1 N"}, "unknown key x"),
        ("5 N", "str"),
        (5, "int"),
        (None, "None"),
    ],
)
def test_vector_shape_errors(value, needle):
    message = raises_pfe(value, "force", fn=to_si_vector)
    assert needle in message


# ---------------------------------------------------------------------------
# arrays and ranges


def test_array_single_and_list():
    a = to_si_array("30 deg", "angle", field="theta")
    assert a.shape == (1,) and a.dtype == float
    assert a[0] == pytest.approx(math.pi / 6)
    b = to_si_array(["0 deg", "90 deg", "1 rad"], "angle", field="theta")
    assert b.shape == (3,)
    np.testing.assert_allclose(b, [0.0, math.pi / 2, 1.0])
    c = to_si_array(0.2, "dimensionless", field="mu")
    assert c.shape == (1,) and c[0] == 0.2


def test_array_list_error_names_the_element():
    with pytest.raises(ProblemFileError) as info:
        to_si_array(["0 deg", "90"], "angle", field="sweep", file=FILE)
    assert info.value.field == "sweep[1]"
    assert "sweep[1]" in str(info.value) and FILE in str(info.value)


def test_full_turn_excludes_stop():
    a = to_si_array(
        {"start": "0 deg", "stop": "360 deg", "step": "2 deg"}, "angle", field="s"
    )
    assert a.shape == (180,)
    assert a[0] == 0.0
    assert a[-1] == pytest.approx(math.radians(358))
    np.testing.assert_allclose(np.diff(a), math.radians(2))


def test_full_turn_from_nonzero_start_and_downwards():
    a = to_si_array(
        {"start": "90 deg", "stop": "450 deg", "step": "90 deg"}, "angle", field="s"
    )
    np.testing.assert_allclose(np.degrees(a), [90, 180, 270, 360])
    b = to_si_array(
        {"start": "360 deg", "stop": "0 deg", "step": "-90 deg"}, "angle", field="s"
    )
    np.testing.assert_allclose(np.degrees(b), [360, 270, 180, 90])
    c = to_si_array({"start": "0 rev", "stop": "1 rev", "step": "0.25 rev"}, "angle", field="s")
    assert c.shape == (4,)


def test_full_turn_with_num():
    a = to_si_array({"start": "0 deg", "stop": "360 deg", "num": 180}, "angle", field="s")
    b = to_si_array(
        {"start": "0 deg", "stop": "360 deg", "step": "2 deg"}, "angle", field="s"
    )
    np.testing.assert_allclose(a, b, atol=1e-15)


def test_partial_turn_includes_stop_on_grid():
    a = to_si_array(
        {"start": "0 deg", "stop": "180 deg", "step": "2 deg"}, "angle", field="s"
    )
    assert a.shape == (91,)
    assert a[-1] == math.radians(180) == to_si("180 deg", "angle", field="x")


def test_two_turns_include_stop():
    a = to_si_array(
        {"start": "0 deg", "stop": "720 deg", "step": "90 deg"}, "angle", field="s"
    )
    assert a.shape == (9,)


def test_non_angle_includes_stop_on_grid_exactly():
    a = to_si_array({"start": "0 s", "stop": "1 s", "step": "0.1 s"}, "time", field="t")
    assert a.shape == (11,)
    assert a[-1] == 1.0
    np.testing.assert_allclose(a, np.linspace(0, 1, 11), atol=1e-15)
    # a length range of exactly 2*pi metres is not a full turn
    b = to_si_array(
        {"start": "0 m", "stop": f"{2 * math.pi!r} m", "num": 5}, "length", field="x"
    )
    assert b[-1] == pytest.approx(2 * math.pi)


def test_stop_off_grid_is_not_reached():
    a = to_si_array({"start": "0 s", "stop": "1 s", "step": "0.3 s"}, "time", field="t")
    np.testing.assert_allclose(a, [0.0, 0.3, 0.6, 0.9])
    b = to_si_array(
        {"start": "0 deg", "stop": "360 deg", "step": "7 deg"}, "angle", field="s"
    )
    assert b.shape == (52,)
    assert np.degrees(b[-1]) == pytest.approx(357)


def test_range_with_num_includes_both_ends():
    a = to_si_array({"start": "0 deg", "stop": "180 deg", "num": 181}, "angle", field="s")
    assert a.shape == (181,)
    assert a[-1] == pytest.approx(math.pi)
    b = to_si_array({"start": "10 mm", "stop": "0 mm", "num": 3}, "length", field="x")
    np.testing.assert_allclose(b, [0.01, 0.005, 0.0])


@pytest.mark.parametrize(
    "table, needle, field",
    [
        ({"start": "0 deg", "stop": "360 deg"}, "exactly one of step and num", "s"),
        (
            {"start": "0 deg", "stop": "360 deg", "step": "2 deg", "num": 5},
            "exactly one of step and num",
            "s",
        ),
        ({"stop": "360 deg", "step": "2 deg"}, "needs start", "s"),
        ({"start": "0 deg", "stop": "360 deg", "stpe": "2 deg"}, "unknown key stpe", "s"),
        ({"start": "0 deg", "stop": "0 deg", "step": "2 deg"}, "equal", "s"),
        ({"start": "0 deg", "stop": "360 deg", "step": "0 deg"}, "nonzero", "s.step"),
        ({"start": "0 deg", "stop": "360 deg", "step": "-2 deg"}, "towards stop", "s.step"),
        ({"start": "0 deg", "stop": "360 deg", "num": 1}, "integer >= 2", "s.num"),
        ({"start": "0 deg", "stop": "360 deg", "num": 2.5}, "integer >= 2", "s.num"),
        ({"start": "0 deg", "stop": "360 deg", "num": True}, "integer >= 2", "s.num"),
        ({"start": "0 deg", "stop": "360 deg", "num": "181"}, "integer >= 2", "s.num"),
        ({"start": "0 deg", "stop": "360 deg", "step": "2"}, "units are missing", "s.step"),
        ({"start": "0", "stop": "360 deg", "step": "2 deg"}, "units are missing", "s.start"),
        ({"start": "0 deg", "stop": "360 mm", "step": "2 deg"}, "length", "s.stop"),
        (
            {"start": "0 deg", "stop": "360 deg", "step": "1e-6 deg"},
            "too many",
            "s.step",
        ),
    ],
)
def test_range_errors(table, needle, field):
    with pytest.raises(ProblemFileError) as info:
        to_si_array(table, "angle", field="s", file=FILE)
    assert needle in info.value.message
    assert info.value.field == field
    assert FILE in str(info.value) and field in str(info.value)


def test_empty_list_rejected():
    message = raises_pfe([], "angle", fn=to_si_array)
    assert "empty" in message


# ---------------------------------------------------------------------------
# formatting


@pytest.mark.parametrize(
    "value, dimension, unit, expected",
    [
        (0.865, "torque", "N*mm", "865 N·mm"),
        (0.865, "torque", None, "0.865 N·m"),
        (94.2477796076938, "angular_velocity", "rpm", "900 rpm"),
        (0.132645023151569, "angle", "deg", "7.6 deg"),
        (0.10417, "moment_of_inertia", None, "0.1042 kg·m²"),
        (8.312, "angular_acceleration", None, "8.312 rad/s²"),
        (-2000.0, "force", "kN", "-2 kN"),
        (0.5, "length", "mm", "500 mm"),
        (0.3, "dimensionless", None, "0.3"),
        (-0.0, "force", None, "0 N"),
        (float("nan"), "torque", "N*mm", "nan N·mm"),
    ],
)
def test_format_si(value, dimension, unit, expected):
    assert format_si(value, dimension, unit) == expected


def test_format_si_digits():
    assert format_si(math.pi, "angle", digits=2) == "3.1 rad"
    assert format_si(math.pi, "angle", digits=6) == "3.14159 rad"


@pytest.mark.parametrize(
    "dimension, unit",
    [("torque", "N"), ("torque", "J"), ("length", "furlongz"), ("forse", None),
     ("angle", "1/s"), ("dimensionless", "deg")],
)
def test_format_si_bad_unit(dimension, unit):
    with pytest.raises(ValueError):
        format_si(1.0, dimension, unit)


def test_format_si_round_trip():
    for text, dimension, unit in [
        ("865 N*mm", "torque", "N*mm"),
        ("900 rpm", "angular_velocity", "rpm"),
        ("7.6 deg", "angle", "deg"),
        ("500 mm", "length", "mm"),
    ]:
        assert format_si(to_si(text, dimension, field="x"), dimension, unit) == (
            text.replace("*", "·")
        )
