"""A study's optimum between its grid values (graphkin.cycle.optimum): scipy.optimize over the batch solver.

The optimum must lie within the grid's bounds, meet every limit, be no worse than the grid's best, and be a design
whose own sweep gives its figures of merit (1e-12 relative). Over one field it must do as well as a grid ten
times finer, to the rounding of that grid's spacing: a continuous optimum is what the grid only approaches.
"""

import math
import sys

import numpy as np
import pytest

from graphkin.cycle import study, sweep
from graphkin.cycle.merit import merit
from graphkin.errors import GraphkinError
from graphkin.optional import available

needs_scipy = pytest.mark.skipif(not available("scipy"), reason="scipy (the study extra) is not installed")

REL = 1e-12


def figures_equal(a, b):
    names = ("torque_peak", "torque_rms", "I_s", "shaking_force_peak", "shaking_moment_peak", "transmission_angle_min")
    return all(math.isclose(getattr(a, f), getattr(b, f), rel_tol=REL, abs_tol=0.0) for f in names)


@pytest.fixture(scope="module")
def coupler():
    """The strip cutter's coupler mass: the peak torque has a least value inside 1..5 kg (its inertia torque
    first offsets the cut's, then adds to the torque elsewhere in the turn)."""
    return study("strip_cutter", {"links[1].mass": [f"{x!r} kg" for x in np.linspace(1, 5, 5).tolist()]}, n=180)


@needs_scipy
def test_one_field_does_as_well_as_a_grid_ten_times_finer(coupler):
    o = coupler.optimum("minimise torque_peak")
    assert 1.0 <= o.x[0] <= 5.0 and o.units == ("kg",) and o.values == (f"{o.x[0]!r} kg",)
    grid = min(d.torque_peak for d in coupler.designs)
    assert o.design.torque_peak <= grid and o.start == int(np.argmin([d.torque_peak for d in coupler.designs]))
    fine = study("strip_cutter", {"links[1].mass": [f"{x!r} kg" for x in np.linspace(1, 5, 41).tolist()]}, n=180)
    assert o.design.torque_peak <= min(d.torque_peak for d in fine.designs) * (1 + 1e-9)
    assert o.value == o.design.torque_peak and o.evaluations > 0 and o.method == "SLSQP"


@needs_scipy
def test_the_optimum_is_the_design_its_sweep_gives(coupler):
    o = coupler.optimum("torque_peak")
    assert figures_equal(merit(sweep(o.problem, coupler.n), o.values, coupler.Cs), o.design)
    assert o.data["links"][1]["mass"] == o.values[0]


@needs_scipy
def test_two_fields_under_a_limit_stay_in_bounds_and_meet_it():
    s = study("strip_cutter_study", n=90)
    limit = "transmission_angle_min >= 45 deg"
    o = s.optimum("minimise torque_peak", [limit])
    assert 60.0 <= o.x[0] <= 120.0 and 1.0 <= o.x[1] <= 4.0
    assert o.design.transmission_angle_min >= math.radians(45) * (1 - 1e-9)
    grid = s.best("torque_peak", [limit])
    assert o.start == grid.index and o.design.torque_peak <= s.designs[grid.index].torque_peak
    assert figures_equal(merit(sweep(o.problem, s.n), o.values, s.Cs), o.design)


@needs_scipy
def test_maximise_takes_the_greatest():
    # A shorter crank swings the coupler less: the least transmission angle is greatest at the shortest crank.
    s = study("strip_cutter", {"links[0].points.A[0]": ["60 mm", "90 mm", "120 mm"]}, n=90)
    o = s.optimum("maximise transmission_angle_min")
    mu = [d.transmission_angle_min for d in s.designs]
    assert mu[0] == max(mu) and o.sense == "maximise" and o.design.transmission_angle_min >= mu[0]
    assert o.x[0] == pytest.approx(60.0, abs=1e-6)


@pytest.mark.parametrize(("vary", "objective", "require", "words"), [
    ({"links[1].mass": ["1 kg", "2 kg"]}, "minimise torque", (), "no such figure of merit"),
    ({"links[1].mass": ["1 kg", "2 kg"]}, "lessen torque_peak", (), "write it \"minimise FIGURE\""),
    ({"links[0].points.A": [["80 mm", "0 mm"], ["90 mm", "0 mm"]]}, "torque_peak", (),
     "links[0].points.A's values are not numbers of one unit"),
    ({"links[1].mass": ["1 kg"]}, "torque_peak", (), "every varied field has a single value"),
    ({"links[1].mass": ["1 kg", "2 kg"]}, "torque_peak", ("torque_peak <= 1 N*m",), "there is nowhere to start"),
])
def test_a_bad_objective_or_grid_is_one_line(vary, objective, require, words):
    # Told before scipy is imported: with or without it.
    s = study("strip_cutter", vary, n=36)
    with pytest.raises(GraphkinError) as e:
        s.optimum(objective, require)
    assert words in str(e.value) and "\n" not in str(e.value)


def test_without_scipy_the_message_names_the_extra(monkeypatch):
    s = study("strip_cutter", {"links[1].mass": ["1 kg", "2 kg"]}, n=36)
    monkeypatch.setitem(sys.modules, "scipy.optimize", None)  # as if scipy were not installed: import fails
    with pytest.raises(GraphkinError, match=r"needs scipy, which is not installed: pip install 'graphkin\[study\]'"):
        s.optimum("torque_peak")
