"""Design studies (graphkin.cycle.studies): every design's figures of merit equal a single sweep of that design.

Each design is rebuilt here on its own, the problem file's data with the values put in by ``set_field`` and read by
``build_problem``, swept by ``graphkin.cycle.sweep``, and its figures of merit read off that Cycle; the study's
must equal them to 1e-12 relative, over grids that cross the four-bar's and the slider-crank's parameters, with
designs that cannot be assembled among them, and over random grids (hypothesis) of the numbers a study varies:
lengths and point positions, masses, I_G, a counterweight (the crank's mass and G), loads, the speed, the offset.
The study solves the designs in batches over designs and positions (graphkin.analytical.designs), the single
sweep one design at a time.
"""

import itertools
import math
import tomllib

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphkin import catalog
from graphkin.cycle import study, sweep
from graphkin.cycle.studies import VaryError
from graphkin.errors import GraphkinError
from graphkin.problem import build_problem
from graphkin.problem.fields import set_field

REL = 1e-12


def data_of(name):
    return tomllib.loads(catalog.path(name).read_text(encoding="utf-8"))


def single(name, fields, values, n):
    """One design swept on its own, the study's figures of merit computed here from its Cycle."""
    data = data_of(name)
    for f, v in zip(fields, values):
        set_field(data, f, v)
    c = sweep(build_problem(data), n)
    return c


def close(a, b):
    return (math.isnan(a) and math.isnan(b)) or math.isclose(a, b, rel_tol=REL, abs_tol=0.0)


GRIDS = [
    # the four-bar: the crank's length (some designs cannot turn), the coupler's mass, the rocker's G
    ("strip_cutter", {"links[0].points.A[0]": ["70 mm", "85 mm", "150 mm", "240 mm"],
                      "links[1].mass": ["1 kg", "2 kg", "3.5 kg"],
                      "links[2].G.r": ["250 mm", "305 mm"]}, 72),
    # the slider-crank: crank and rod lengths (a rod shorter than the crank plus the offset cannot turn), mass
    ("slider_crank_friction", {"links[0].points.A": [["40 mm", "0 mm"], ["60 mm", "0 mm"], ["250 mm", "0 mm"]],
                               "links[2].mass": ["0.5 kg", "2 kg"]}, 60),
]


@pytest.mark.parametrize(("name", "vary", "n"), GRIDS, ids=[g[0] for g in GRIDS])
def test_every_design_equals_a_single_sweep_of_it(name, vary, n):
    s = study(name, vary, n=n, Cs=0.03)
    assert s.vectorised
    failed = assert_single_sweeps(name, vary, n, s)
    assert 0 < failed < len(s.designs), "the grid should hold designs that turn and designs that cannot"


def _values(lo: float, hi: float, unit: str):
    """Values of a field as a problem file writes them, to 0.1 of the unit."""
    return st.integers(round(lo * 10), round(hi * 10)).map(lambda k: f"{k / 10} {unit}")


FIELDS = {
    "strip_cutter": {
        "links[0].points.A[0]": _values(60, 200, "mm"), "frame.points.B0[0]": _values(520, 620, "mm"),
        "links[1].mass": _values(0, 6, "kg"), "links[1].k": _values(100, 400, "mm"),
        "links[0].mass": _values(0, 8, "kg"), "links[0].G[0]": _values(-80, 80, "mm"),  # a counterweight
        "links[0].G[1]": _values(-80, 80, "mm"), "links[2].G.r": _values(100, 500, "mm"),
        "loads[0].force.magnitude": _values(0, 4000, "N"), "driver.omega": _values(100, 1500, "rpm"),
    },
    "slider_crank_friction": {
        "links[0].points.A[0]": _values(30, 120, "mm"), "links[1].points.B[0]": _values(120, 300, "mm"),
        "frame.points.E[1]": _values(-60, 60, "mm"), "links[1].mass": _values(0, 3, "kg"),
        "links[0].G[0]": _values(-40, 40, "mm"), "links[0].I_G": _values(0, 0.01, "kg*m^2"),
        "loads[0].force[0]": _values(-1000, 0, "N"), "driver.omega": _values(50, 1000, "rpm"),
    },
}


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_a_random_grid_of_designs_equals_single_sweeps(data):
    name = data.draw(st.sampled_from(sorted(FIELDS)), label="problem")
    fields = data.draw(st.lists(st.sampled_from(sorted(FIELDS[name])), min_size=1, max_size=3, unique=True),
                       label="fields")
    vary = {f: data.draw(st.lists(FIELDS[name][f], min_size=1, max_size=3, unique=True), label=f) for f in fields}
    n = data.draw(st.integers(8, 48), label="n")
    s = study(name, vary, n=n, Cs=0.03)
    assert s.vectorised
    assert_single_sweeps(name, vary, n, s)


@pytest.mark.parametrize("vary", [
    # Each field its own part (a link's points, a link's body, a load, the speed): the file's numbers with each
    # field's changes put in, no file read per design.
    {"frame.points.B0[0]": ["540 mm", "600 mm"], "links[0].points.A[0]": ["80 mm", "95 mm"],
     "loads[1].force.magnitude": ["1000 N", "3000 N"], "driver.omega": ["600 rpm", "1200 rpm"]},
    # Two fields of one part (the coupler's mass and radius of gyration both set its I_G): read design by design.
    {"links[1].mass": ["1 kg", "4 kg"], "links[1].k": ["150 mm", "300 mm"]},
])
def test_fields_of_their_own_parts_or_of_one_part_equal_single_sweeps(vary):
    s = study("strip_cutter", vary, n=40, Cs=0.03)
    assert s.vectorised and assert_single_sweeps("strip_cutter", vary, 40, s) == 0


def assert_single_sweeps(name, vary, n, s) -> int:
    """Each design of the study ``s`` against a single sweep of it; returns how many cannot be assembled."""
    fields = tuple(vary)
    assert s.fields == fields and s.shape == tuple(len(v) for v in vary.values())
    assert [d.values for d in s.designs] == list(itertools.product(*vary.values()))  # the last field fastest
    failed = 0
    for d in s.designs:
        c = single(name, fields, d.values, n)
        bad = np.flatnonzero(~c.valid)
        if len(bad):
            failed += 1
            assert not d.ok and d.failed_at == c.q[bad[0]]
            assert c.analysis.reason(int(bad[0])) in d.failure and f"{len(bad)} of the {c.n} positions" in d.failure
            assert all(math.isnan(x) for x in (d.torque_peak, d.torque_rms, d.I_s, d.shaking_force_peak,
                                               d.shaking_moment_peak, d.transmission_angle_min))
            continue
        assert d.ok and math.isnan(d.failed_at)
        T = c.torque
        assert close(d.torque_peak, float(np.max(np.abs(T))))
        assert close(d.torque_rms, math.sqrt(c.mean(T**2)))
        assert d.no_flywheel == c.why_no_flywheel()
        assert close(d.I_s, math.nan if d.no_flywheel else c.flywheel(0.03).I_s)
        assert close(d.shaking_force_peak, float(np.max(np.linalg.norm(c.shaking_force(), axis=1))))
        assert close(d.shaking_moment_peak, float(np.max(np.abs(c.shaking_moment()))))
        peaks = c.peaks().forces
        assert set(d.joint_peaks) == set(peaks) and all(close(d.joint_peaks[k], peaks[k].value) for k in peaks)
        if name == "strip_cutter":
            assert close(d.transmission_angle_min, float(np.min(c.transmission_angle())))
        else:  # a slider-crank or a double slider has no four-bar transmission angle
            assert math.isnan(d.transmission_angle_min)
    return failed


@pytest.mark.parametrize("name", ["strip_cutter", "slider_crank_friction", "engine_gas_force"])
def test_a_crank_driven_linkage_of_numbers_is_solved_in_a_batch(name):
    s = study(name, {"links[1].mass": ["2 kg", "3 kg"]}, n=36)
    assert s.vectorised is True and s.why_not_vectorised is None


def test_a_slider_driven_linkage_is_solved_in_a_batch_and_equals_single_sweeps():
    # The double slider at its own positions, its rod's length and mass varied; a slider has no flywheel.
    vary = {"links[1].points.B[0]": ["450 mm", "500 mm", "600 mm"], "links[1].mass": ["3 kg", "5 kg"]}
    s = study("double_slider", vary, Cs=0.03)
    assert s.vectorised and not s.crank
    assert assert_single_sweeps("double_slider", vary, None, s) == 0
    assert all("slider" in d.no_flywheel for d in s.designs)


@pytest.mark.parametrize(("name", "vary", "words"), [
    ("shaper_six_bar", {"links[1].mass": ["2 kg", "3 kg"]}, "a load that varies over the cycle"),
    ("gearset", {"links[1].mass": ["2 kg", "3 kg"]}, "a gear train"),
    ("spring_link_hibbeler", {"links[0].mass": ["2 kg", "3 kg"]}, "a load that varies over the cycle"),
])
def test_designs_that_cannot_share_a_batch_are_swept_alone_and_it_says_so(name, vary, words):
    n = 36 if name != "spring_link_hibbeler" else None  # a slider driver is swept at its own positions
    s = study(name, vary, n=n)
    assert s.vectorised is False and s.why_not_vectorised.startswith("2 of the 2 designs were swept one after another")
    assert words in s.why_not_vectorised
    fields = tuple(vary)
    for d in s.designs:  # the loop's numbers are a single sweep's too
        c = single(name, fields, d.values, n)
        assert close(d.torque_peak, float(np.max(np.abs(c.torque))))


def test_a_design_without_a_flywheel_says_why():
    s = study("strip_cutter", {"driver.omega": ["0 rpm", "900 rpm"]}, n=36)
    still, turning = s.designs
    assert math.isnan(still.I_s) and "ω = 0" in still.no_flywheel
    assert turning.no_flywheel is None and turning.I_s > 0


@pytest.mark.parametrize(("vary", "words"), [
    ({"links[9].mass": ["1 kg"]}, "vary links[9].mass: the problem has no links[9]"),
    ({"links[1].mas": ["1 kg"]}, "vary links[1].mas: '1 kg': unknown field"),
    ({"links[1]..mass": ["1 kg"]}, "vary links[1]..mass: is not a field path"),
    ({"links[1].mass": ["2 kg", "1 m"]}, "vary links[1].mass: '1 m': expected a mass"),
    ({"links[1].mass": "1 kg"}, "vary links[1].mass: give a list of one or more values"),
    ({"links[1].mass": []}, "vary links[1].mass: give a list of one or more values"),
])
def test_a_bad_field_or_value_is_named(vary, words):
    with pytest.raises(VaryError) as exc:
        study("strip_cutter", vary, n=36)
    assert str(exc.value).startswith(words) and exc.value.field == next(iter(vary))
    assert "\n" not in str(exc.value)


@pytest.mark.parametrize(("problem", "vary", "words"), [
    ("no_such_problem", {"links[1].mass": ["1 kg"]}, "neither a catalog problem"),
    (3, {"links[1].mass": ["1 kg"]}, "study takes a catalog name"),
    ("strip_cutter", {}, "vary must be a dict of at least one field"),
    ("strip_cutter", ["links[1].mass"], "vary must be a dict of at least one field"),
])
def test_bad_input_is_one_plain_error(problem, vary, words):
    with pytest.raises(GraphkinError, match=words):
        study(problem, vary)


def test_problem_data_is_taken_and_left_unchanged():
    data = data_of("strip_cutter")
    before = tomllib.loads(catalog.path("strip_cutter").read_text(encoding="utf-8"))
    s = study(data, {"links[1].mass": ["4 kg"]}, n=36)
    assert data == before
    assert s.designs[0].torque_peak == study("strip_cutter", {"links[1].mass": ["4 kg"]}, n=36).designs[0].torque_peak


def test_values_that_make_no_mechanism_together_mark_that_design():
    # Each value alone is a crank; A0 and A both at x = 50 mm make a crank of zero length.
    s = study("strip_cutter", {"links[0].points.A0[0]": ["0 mm", "50 mm"], "links[0].points.A[0]": ["85 mm", "50 mm"]},
              n=36)
    assert [d.ok for d in s.designs] == [True, True, True, False]
    last = s.designs[-1]
    assert "pins A and A0 coincide" in last.failure and math.isnan(last.failed_at) and math.isnan(last.torque_peak)


# The best design under stated limits (graphkin.cycle.choice): the least of one figure among the designs that
# assemble and meet every limit, checked against a search of the designs written out here.

CHOICE_VARY = {"links[0].points.A[0]": ["60 mm", "110 mm", "160 mm", "210 mm", "240 mm"],
               "links[1].mass": ["1 kg", "4 kg"]}


@pytest.fixture(scope="module")
def choosing():
    return study("strip_cutter", CHOICE_VARY, n=36)


@pytest.mark.parametrize(("minimise", "require", "limits"), [
    ("torque_peak", [], []),
    ("transmission_angle_min", [], []),  # least μ: the longest crank that still turns
    ("shaking_force_peak", ["transmission_angle_min >= 40 deg"], [("transmission_angle_min", ">=", math.radians(40))]),
    ("I_s", ["F23_peak < 30 kN", "torque_rms>=0.1 kN*m"], [("F23", "<", 30000.0), ("torque_rms", ">=", 100.0)]),
])
def test_the_best_design_is_the_least_that_meets_the_limits(choosing, minimise, require, limits):
    def value(d, name):
        return getattr(d, name) if hasattr(d, name) else d.joint_peaks[name]

    compare = {"<": lambda a, b: a < b, ">=": lambda a, b: a >= b}
    candidates = [k for k, d in enumerate(choosing.designs)
                  if d.ok and all(compare[op](value(d, f), bound) for f, op, bound in limits)]
    assert 0 < len(candidates) < len(choosing.designs)  # the limits and failures leave some out, not all
    expected = min(candidates, key=lambda k: value(choosing.designs[k], minimise))
    got = choosing.best(minimise, require)
    assert got.index == expected and got.why is None and [r.text for r in got.require] == [r.strip() for r in require]


def test_no_design_meeting_the_limits_says_why(choosing):
    got = choosing.best("torque_peak", ["transmission_angle_min > 89 deg"])
    assert got.index is None
    assert got.why == ("no design that assembles over its cycle meets transmission_angle_min > 89 deg and has a "
                       "torque_peak")


@pytest.mark.parametrize(("minimise", "require", "words"), [
    ("peak_torque", [], "best 'peak_torque': no such figure of merit; the study has torque_peak, "),
    ("torque_peak", ["mu >= 40 deg"], "require 'mu >= 40 deg': 'mu': no such figure of merit"),
    ("torque_peak", ["transmission_angle_min >= 40 kg"], "require 'transmission_angle_min >= 40 kg': expected an "
                                                         "angle"),
    ("torque_peak", ["torque_peak <= 3"], "require 'torque_peak <= 3': units are missing"),
    ("torque_peak", ["torque_peak == 3 N*m"], "require 'torque_peak == 3 N*m': write it FIGURE OP VALUE UNIT"),
    ("torque_peak", ["__import__('os') >= 1 m"], "write it FIGURE OP VALUE UNIT"),
])
def test_a_bad_figure_or_limit_is_named(choosing, minimise, require, words):
    with pytest.raises(GraphkinError) as e:
        choosing.best(minimise, require)
    assert words in str(e.value) and "\n" not in str(e.value)


def test_a_fields_values_as_numbers_in_their_unit():
    from graphkin.cycle.choice import field_axis

    unit, x = field_axis(["60.0 mm", "1e2 mm", "-.5 mm"])
    assert unit == "mm" and x.tolist() == [60.0, 100.0, -0.5]
    assert field_axis([2, 3.5])[0] == ""
    assert field_axis(["60 mm", "0.1 m"]) is None  # two units: not one axis
    assert field_axis([["80 mm", "0 mm"]]) is None  # a point
