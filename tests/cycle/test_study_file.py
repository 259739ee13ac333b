"""A problem file's ``[study]`` table (graphkin.problem.study_table) and a study's designs as ordinary problems.

The table states a study in the words of ``--vary``; ``gk.study(FILE)`` must then be the study of the same fields and
values given as arguments, design for design, and each design (:meth:`Study.design`, and the file written of it) must
be the problem whose single sweep gives that design's figures of merit to 1e-12 relative.
"""

import math
import tomllib

import numpy as np
import pytest

from graphkin import catalog
from graphkin.cycle import study, sweep
from graphkin.cycle.merit import merit
from graphkin.errors import GraphkinError, ProblemFileError
from graphkin.problem import build_problem, load_problem
from graphkin.problem.toml_text import toml_text

REL = 1e-12
FIGURES = ("torque_peak", "torque_rms", "I_s", "shaking_force_peak", "shaking_moment_peak", "transmission_angle_min")


def data_of(name):
    return tomllib.loads(catalog.path(name).read_text(encoding="utf-8"))


def same(a, b, rel=0.0):
    """Two designs' figures of merit equal (to ``rel`` relative; nan where both are nan)."""
    pairs = [(getattr(a, f), getattr(b, f)) for f in FIGURES] + [(a.joint_peaks[j], b.joint_peaks[j])
                                                                 for j in a.joint_peaks]
    assert a.joint_peaks.keys() == b.joint_peaks.keys()
    return all((math.isnan(x) and math.isnan(y)) or math.isclose(x, y, rel_tol=rel, abs_tol=0.0) for x, y in pairs)


@pytest.fixture(scope="module")
def cutter():
    return study("strip_cutter_study")


def test_the_catalogs_table_is_the_study_of_its_fields_given_as_arguments(cutter):
    mm = [f"{x!r} mm" for x in np.linspace(60, 120, 7).tolist()]
    kg = [f"{x!r} kg" for x in np.linspace(1, 4, 4).tolist()]
    given = study("strip_cutter", {"links[0].points.A[0]": mm, "links[1].mass": kg}, n=360, Cs=0.05)
    assert cutter.fields == given.fields and cutter.grid == given.grid and (cutter.n, cutter.Cs) == (360, 0.05)
    assert all(same(a, b) and a.values == b.values for a, b in zip(cutter.designs, given.designs))
    assert cutter.stated.best == "torque_peak" and cutter.stated.require == ("transmission_angle_min >= 30 deg",)
    assert cutter.stated.optimize == "minimise torque_peak"


def test_arguments_override_the_table():
    s = study("strip_cutter_study", {"links[2].mass": ["4 kg", "6 kg"]}, n=36, Cs=0.1)
    assert s.fields == ("links[2].mass",) and s.n == 36 and s.Cs == 0.1 and len(s.designs) == 2
    heavier = s.designs[1].torque_peak > s.designs[0].torque_peak  # a heavier rocker costs torque
    assert heavier


def test_a_list_written_on_one_line_and_a_list_of_points():
    data = data_of("strip_cutter")
    data["study"] = {"vary": {"links[1].mass": "2 kg, 4 kg",
                              "links[0].points.A": [["80 mm", "0 mm"], ["90 mm", "0 mm"]]}, "n": 36}
    s = study(data)
    assert s.grid == (("2 kg", "4 kg"), (["80 mm", "0 mm"], ["90 mm", "0 mm"])) and s.n == 36
    alone = study("strip_cutter", {"links[1].mass": ["2 kg", "4 kg"],
                                   "links[0].points.A": [["80 mm", "0 mm"], ["90 mm", "0 mm"]]}, n=36)
    assert all(same(a, b) for a, b in zip(s.designs, alone.designs))


def test_a_file_without_a_table_needs_vary():
    with pytest.raises(GraphkinError, match=r"give the fields to vary .* or a \[study\] table"):
        study("strip_cutter")


def test_a_solve_of_the_file_ignores_its_table():
    a = catalog.load("strip_cutter_study").solve(np.radians(140.0))
    b = catalog.load("strip_cutter").solve(np.radians(140.0))
    assert np.array_equal(a.effort, b.effort)
    assert all(np.array_equal(a.forces[k], b.forces[k]) for k in b.forces)


@pytest.mark.parametrize("index", [0, 9, 27])
def test_a_design_is_the_problem_whose_sweep_gives_its_figures(cutter, index):
    p = cutter.design(index)
    d = cutter.designs[index]
    assert same(merit(sweep(p, cutter.n), d.values, cutter.Cs), d, REL)
    x = float(d.values[0].split()[0]) / 1000
    assert p.mechanism.link(2).points["A"] == pytest.approx((x, 0.0), abs=0.0)
    # The design is an ordinary problem: solve it, and its design data has no [study] left.
    assert "study" not in cutter.design_data(index)
    assert np.isfinite(p.solve(np.radians(30.0)).effort).all()


def test_the_written_design_reads_back_to_the_same_numbers(cutter, tmp_path):
    index = cutter.best("torque_peak", ["transmission_angle_min >= 30 deg"]).index
    path = cutter.write_design(index, tmp_path / "design.toml")
    assert tomllib.loads(path.read_text(encoding="utf-8")) == cutter.design_data(index)
    d = cutter.designs[index]
    assert same(merit(sweep(load_problem(path), cutter.n), d.values, cutter.Cs), d, REL)


def test_a_design_by_its_values_and_a_wrong_count_of_values(cutter):
    p = cutter.design(("75 mm", "2.5 kg"))
    assert p.mechanism.link(3).mass == 2.5 and p.mechanism.link(2).points["A"][0] == pytest.approx(0.075, abs=0)
    with pytest.raises(GraphkinError, match="one value for each of the 2 fields"):
        cutter.design(("75 mm",))


def test_every_catalog_problem_reads_back_from_its_toml_text():
    for name in catalog.names():
        data = data_of(name)
        assert tomllib.loads(toml_text(data)) == data, name
    assert build_problem(tomllib.loads(toml_text(data_of("strip_cutter")))).mechanism == \
        catalog.load("strip_cutter").mechanism


def test_a_value_the_table_gives_that_the_problem_rejects_names_the_tables_field():
    data = data_of("strip_cutter")
    data["study"] = {"vary": {"links[1].mass": ["2 kg", "-1 kg"]}}
    with pytest.raises(ProblemFileError) as e:
        study(data)
    assert e.value.field == "study.vary.links[1].mass" and "-1 kg" in str(e.value)


def test_a_design_is_one_call_from_its_handout_and_explorer(cutter, tmp_path):
    from graphkin import handout
    from graphkin.optional import available

    path = cutter.write_design(3, tmp_path / "design.toml")
    doc = handout.build(str(path), at="30 deg")
    assert doc["title"] == load_problem(path).title and "[study]" not in path.read_text(encoding="utf-8")
    if available("ipywidgets") and available("anywidget"):
        from graphkin.widgets import explore

        assert explore(cutter.design(3), n=12).problem.mechanism.link(3).mass == 4.0
