"""Links, joints, loads and the mechanism made of them, read from equal tables once and shared: an exercise builds a
problem per draw from them."""

from __future__ import annotations

import copy

import pytest

from graphkin.errors import ProblemFileError
from graphkin.problem import file as problem_file
from graphkin.problem import shared as problem_shared
from graphkin.problem.file import build_problem

TABLES = {
    "frame": {"points": {"A0": ["0 mm", "0 mm"], "B0": ["100 mm", "0 mm"]}},
    "links": [{"number": 2, "points": {"A0": ["0 mm", "0 mm"], "A": ["30 mm", "0 mm"]}, "mass": "1 kg"},
              {"number": 3, "points": {"A": ["0 mm", "0 mm"], "B": ["120 mm", "0 mm"]}, "mass": "2 kg",
               "G": ["60 mm", "0 mm"], "I_G": "0.01 kg*m^2"},
              {"number": 4, "points": {"B0": ["0 mm", "0 mm"], "B": ["80 mm", "0 mm"]}, "mass": "1.5 kg"}],
    "joints": [{"type": "revolute", "links": [1, 2], "point": "A0"}, {"type": "revolute", "links": [2, 3], "point": "A"},
               {"type": "revolute", "links": [3, 4], "point": "B"}, {"type": "revolute", "links": [4, 1], "point": "B0"}],
    "driver": {"link": 2, "theta": "60 deg", "omega": "100 rpm"},
}


def _links(problem):
    return {link.number: link for link in problem.mechanism.links}


def test_equal_tables_share_their_links_and_a_changed_table_is_read_again():
    first = build_problem(copy.deepcopy(TABLES), file="a")
    other_angle = copy.deepcopy(TABLES)
    other_angle["driver"]["theta"] = "70 deg"
    second = build_problem(other_angle, file="b")
    assert all(_links(first)[n] is _links(second)[n] for n in (1, 2, 3, 4))
    heavier = copy.deepcopy(TABLES)
    heavier["links"][1]["mass"] = "2.5 kg"
    third = build_problem(heavier, file="c")
    assert _links(third)[3] is not _links(first)[3] and _links(third)[3].mass == 2.5
    assert _links(third)[2] is _links(first)[2]
    # The same mass written another way is another table, read on its own (to the same link values).
    grams = copy.deepcopy(TABLES)
    grams["links"][1]["mass"] = "2000 g"
    fourth = build_problem(grams, file="d")
    assert _links(fourth)[3] is not _links(first)[3] and _links(fourth)[3] == _links(first)[3]


def test_a_shared_link_solves_as_one_read_afresh():
    tables = copy.deepcopy(TABLES)
    build_problem(copy.deepcopy(TABLES), file="warm")
    shared = build_problem(tables, file="x").solve()
    problem_shared._READ.clear()
    fresh = build_problem(copy.deepcopy(TABLES), file="y").solve()
    assert shared.effort[0] == fresh.effort[0]


def test_a_table_that_cannot_be_read_names_each_callers_file():
    bad = copy.deepcopy(TABLES)
    bad["links"][0]["mass"] = "-1 kg"
    for name in ("first.toml", "second.toml"):
        with pytest.raises(ProblemFileError, match=rf"{name}.*links\[0\]\.mass"):
            build_problem(copy.deepcopy(bad), file=name)


def test_an_equal_load_table_is_read_once_and_a_changed_one_again():
    tables = copy.deepcopy(TABLES)
    tables["loads"] = [{"type": "force", "link": 3, "point": "B", "force": {"magnitude": "100 N", "angle": "90 deg"}},
                       {"type": "torque", "link": 4, "torque": "5 N*m"}]
    first = build_problem(copy.deepcopy(tables), file="a").mechanism.loads
    again = build_problem(copy.deepcopy(tables), file="b").mechanism.loads
    assert first[0] is again[0] and first[1] is again[1]
    tables["loads"][0]["force"]["magnitude"] = "150 N"
    changed = build_problem(tables, file="c").mechanism.loads
    assert changed[0] is not first[0] and changed[1] is first[1]
    assert abs(complex(*changed[0].force)) == 150.0


def test_equal_parts_share_one_mechanism_and_its_plan():
    from graphkin.kinematics.plan import plan_of

    first = build_problem(copy.deepcopy(TABLES), file="a")
    other_angle = copy.deepcopy(TABLES)
    other_angle["driver"]["theta"] = "70 deg"
    second = build_problem(other_angle, file="b")
    assert second.mechanism is first.mechanism and plan_of(second.mechanism) is plan_of(first.mechanism)
    assert second.q[0] != first.q[0]
    heavier = copy.deepcopy(TABLES)
    heavier["links"][1]["mass"] = "2.5 kg"
    third = build_problem(heavier, file="c")
    assert third.mechanism is not first.mechanism and third.mechanism.link(3).mass == 2.5
    assert third.mechanism.joints == first.mechanism.joints
    assert all(a is b for a, b in zip(third.mechanism.joints, first.mechanism.joints))  # read once too
    crossed = copy.deepcopy(TABLES)
    crossed["assembly"] = {"B": -1}
    assert build_problem(crossed, file="d").mechanism is not first.mechanism


def test_a_shared_mechanism_solves_as_one_made_afresh():
    build_problem(copy.deepcopy(TABLES), file="warm").solve()
    shared = build_problem(copy.deepcopy(TABLES), file="x")
    problem_shared._MECHANISMS.clear()
    problem_shared._READ.clear()
    fresh = build_problem(copy.deepcopy(TABLES), file="y")
    assert fresh.mechanism is not shared.mechanism
    a, b = shared.solve(), fresh.solve()
    assert a.effort[0] == b.effort[0] and all((a.force(*k) == b.force(*k)).all() for k in a.forces)


def test_a_shared_joint_with_unusual_friction_is_warned_of_every_time():
    from graphkin.errors import GraphkinWarning

    tables = {
        "frame": {"points": {"A0": ["0 mm", "0 mm"], "P": ["0 mm", "0 mm"]}},
        "links": [{"number": 2, "points": {"A0": ["0 mm", "0 mm"], "A": ["30 mm", "0 mm"]}, "mass": "1 kg"},
                  {"number": 3, "points": {"A": ["0 mm", "0 mm"], "B": ["120 mm", "0 mm"]}, "mass": "2 kg"},
                  {"number": 4, "points": {"B": ["0 mm", "0 mm"]}, "mass": "1 kg"}],
        "joints": [{"type": "revolute", "links": [1, 2], "point": "A0"},
                   {"type": "revolute", "links": [2, 3], "point": "A"},
                   {"type": "revolute", "links": [3, 4], "point": "B"},
                   {"type": "prismatic", "guide": 1, "slider": 4, "point": "B", "through": "P", "mu": 1.5}],
        "driver": {"link": 2, "theta": "60 deg", "omega": "100 rpm"},
    }
    for name in ("first.toml", "second.toml"):
        with pytest.warns(GraphkinWarning, match=rf"{name}: joints\[3\]\.mu: a friction coefficient of 1.5"):
            build_problem(copy.deepcopy(tables), file=name)


def test_an_equal_pressure_is_read_once_and_a_stroke_table_every_time():
    tables = copy.deepcopy(TABLES)
    tables["frame"]["points"]["P"] = ["0 mm", "0 mm"]
    tables["links"][2] = {"number": 4, "points": {"B": ["0 mm", "0 mm"]}, "mass": "1.5 kg"}
    tables["joints"][3] = {"type": "prismatic", "guide": 1, "slider": 4, "point": "B", "through": "P"}
    tables["loads"] = [{"type": "pressure", "link": 4, "point": "B", "bore": "80 mm", "direction": "180 deg",
                        "pressure": "0.7 N/mm^2"}]
    first = build_problem(copy.deepcopy(tables), file="a")
    again = build_problem(copy.deepcopy(tables), file="b")
    assert again.mechanism.loads[0] is first.mechanism.loads[0] and again.mechanism is first.mechanism
    tables["loads"][0]["pressure"] = "0.8 N/mm^2"
    higher = build_problem(copy.deepcopy(tables), file="c")
    assert higher.mechanism.loads[0] is not first.mechanism.loads[0]
    assert abs(complex(*higher.mechanism.loads[0].force)) / abs(complex(*first.mechanism.loads[0].force)) == \
        pytest.approx(8 / 7, rel=1e-12)
    # A pressure against the stroke waits for the mechanism's dead centres: read afresh each time.
    import tomllib
    from pathlib import Path

    stroke = tomllib.loads((Path(__file__).parent / "files" / "indicator_stroke.toml").read_text(encoding="utf-8"))
    problem_shared._READ.clear()
    loads = [build_problem(copy.deepcopy(stroke), file=name).mechanism.loads[0] for name in ("d", "e")]
    assert loads[0] is not loads[1] and loads[0] == loads[1]
    assert not any(key[0] is problem_file._load for key in problem_shared._READ)
