"""One guard for everything graphical (issue 35): a construction that disagrees with the analytical route is not valid.

Each test puts back a fault the guard must catch (the internal mesh's pitch point on the external side, as the
polygons and the instant centres had it before issue 35; a force route that drops a reaction) and checks that
the construction is refused with a reason that names the quantity and both values, that the report's JSON says so,
and that an exercise refuses to key it.
"""

from __future__ import annotations

import dataclasses
import json
import re

import numpy as np
import pytest

from graphkin import catalog, exercises, report
from graphkin.errors import GraphkinError
from graphkin.graphical import centres, construct_forces, construct_kinematics, instant_centres, polygons
from graphkin.graphical.guard import AGREEMENT, check_forces
from graphkin.kinematics import solve_kinematics
from graphkin.model import Driver, GearMesh, Link, Mechanism, Revolute


def _pinion_in_annulus() -> Mechanism:
    """A pinion (r = 40 mm) on the frame at O2 driving an annulus (r = 120 mm) pivoted at O3, 80 mm away."""
    return Mechanism([Link(1, {"O2": (0, 0), "O3": (-0.08, 0)}), Link(2, {"O2": (0, 0), "A": (0.03, 0.01)}),
                      Link(3, {"O3": (0, 0), "B": (0.1, 0.02)})],
                     [Revolute((1, 2), "O2"), Revolute((1, 3), "O3"),
                      GearMesh((2, 3), ("O2", "O3"), (0.04, 0.12), internal=True)], Driver(2))


def _old_polygons(mesh, k, Ck, Cj):
    """The pitch point as the polygons took it before issue 35: at the known gear j's radius from its centre
    towards gear k's, whichever is the annulus."""
    j = next(n for n in mesh.links if n != k)
    return Cj + mesh.radius(j) * (Ck - Cj) / np.abs(Ck - Cj), None, None


def _old_centres(mesh, k, Ck, Cj):
    """The pitch point as the instant centres took it before issue 35: at the first gear's radius towards the
    second."""
    return Ck + mesh.radius(k) * (Cj - Ck) / np.abs(Cj - Ck), None, None


def test_the_old_pitch_point_is_refused_with_both_values(monkeypatch):
    kin = solve_kinematics(_pinion_in_annulus(), [0.4], 10.0, 2.0)
    assert construct_kinematics(kin, 0).valid and not construct_kinematics(kin, 0).disagreement
    monkeypatch.setattr(polygons, "pitch_point", _old_polygons)
    c = construct_kinematics(kin, 0)
    assert not c.valid and c.disagreement
    assert c.omega == {} and c.velocity == {} and c.images == {}  # no number survives to be shown
    # The worst difference against its scale, named with both values: B of the annulus, which turned at −10 rad/s
    # instead of +10/3 (and α3 at −2 instead of +2/3).
    assert c.reason == ("the velocity and acceleration polygons and the analytical route disagree: a_B of link 3 is "
                        "10.2 m/s² ∠ -159.90° graphically, 1.135 m/s² ∠ -164.48° analytically")
    assert c.steps[-1].kind == "note" and c.reason in c.steps[-1].caption


def test_the_old_instant_centre_is_refused(monkeypatch):
    kin = solve_kinematics(_pinion_in_annulus(), [0.4], 10.0, 2.0)
    assert instant_centres(kin, 0).valid
    monkeypatch.setattr(centres, "pitch_point", _old_centres)
    ic = instant_centres(kin, 0)
    assert not ic.valid and ic.disagreement
    assert ic.centres == {} and ic.omega == {}
    assert ic.reason == ("the instant centres and the analytical route disagree: ω3 is -10 rad/s graphically, "
                         "3.33333 rad/s analytically")


def test_the_json_says_why_and_gives_no_polygon(monkeypatch):
    monkeypatch.setattr(polygons, "pitch_point", _old_polygons)
    monkeypatch.setattr(centres, "pitch_point", _old_centres)
    problem = catalog.load("gearset")
    mech = _pinion_in_annulus()
    problem = dataclasses.replace(problem, mechanism=dataclasses.replace(mech, loads=problem.mechanism.loads[:0]),
                                  q=np.array([0.4]), q_dot=np.array([10.0]), q_ddot=np.array([2.0]), given={})
    result = problem.solve()
    data = report.solution(problem, result, report.constructions(result),
                           report.kinematic_constructions(result.kinematics))
    gk = json.loads(json.dumps(data))["positions"][0]["graphical_kinematics"]
    assert gk["valid"] is False
    assert gk["reason"].startswith("the velocity and acceleration polygons and the analytical route disagree: ")
    assert set(gk) == {"valid", "reason", "disagreement"} and gk["disagreement"] is True
    forces = json.loads(json.dumps(data))["positions"][0]["graphical"]
    assert forces["valid"] is True and forces["disagreement"] is False


def test_a_force_construction_that_drops_a_reaction_is_refused():
    result = catalog.load("strip_cutter").solve()
    c = construct_forces(result.kinematics, 0)
    assert check_forces(result, c, 0) is c
    key = next(iter(c.forces))
    worse = dataclasses.replace(c, forces={**c.forces, key: (0.0, 0.0)})
    checked = check_forces(result, worse, 0)
    assert not checked.valid and checked.disagreement
    assert checked.reason.startswith("the graphical and analytical routes disagree: ")
    assert "0 N graphically" in checked.reason


def test_rounding_is_not_a_disagreement():
    """A difference far below the guard's tolerance passes; one just above it does not."""
    result = catalog.load("strip_cutter").solve()
    c = construct_forces(result.kinematics, 0)
    key = next(iter(c.forces))
    F = np.asarray(c.forces[key])
    top = max(np.hypot(*f) for f in c.forces.values())
    for factor, ok in ((0.01, True), (100.0, False)):
        nudged = dataclasses.replace(c, forces={**c.forces, key: tuple(F + [factor * AGREEMENT * top, 0.0])})
        assert check_forces(result, nudged, 0).valid is ok


def test_problems_that_give_values_are_constructed_from_the_input_motion():
    """Makdin's four-bar gives θ3, θ4, α and a_G off its drawing: the polygons are the input motion's own (placed by
    it), so they agree with graphkin's exact kinematics, and the note says which the reader is looking at."""
    problem = catalog.load("fourbar_dynamic_makdin")
    assert problem.given
    kin = problem.kinematics()
    c = construct_kinematics(kin, 0)
    assert c.valid, c.reason
    exact = solve_kinematics(problem.mechanism, problem.q, problem.q_dot, problem.q_ddot)
    for link in problem.mechanism.moving:
        assert c.omega[link] == pytest.approx(float(exact.omega[link][0]), rel=1e-12)
        assert c.alpha[link] == pytest.approx(float(exact.alpha[link][0]), rel=1e-12)
    assert "constructed from the input motion alone" in c.steps[0].caption
    assert instant_centres(kin, 0).valid


def test_an_exercise_refuses_to_key_a_disagreeing_polygon(monkeypatch):
    """At make time: no student is handed data whose key came from a construction that disagrees (issue 35)."""
    _key_refused(monkeypatch, "the velocity and acceleration polygons and the analytical route disagree: ω3 is "
                              "1 rad/s graphically, 2 rad/s analytically")


def _key_refused(monkeypatch, why: str):
    """fourbar_polygons' key, with every motion construction refused by the guard for ``why``: refused at make time."""
    ex = exercises.load("fourbar_polygons")
    exercises.variants._CACHE.clear()
    exercises.variants._DRAWS.clear()
    monkeypatch.setattr(polygons, "motion_disagreement", lambda *a: why)
    try:
        with pytest.raises(GraphkinError, match=f"no key is made .*: {re.escape(why)}"):
            exercises.key(ex, "s1")
    finally:
        exercises.variants._CACHE.clear()
        exercises.variants._DRAWS.clear()


def test_the_flag_not_the_wording_says_a_construction_disagrees(monkeypatch):
    """A position the linkage cannot take is not valid but no disagreement; a construction the guard refuses is one,
    however its reason is worded, and an exercise refuses to be made from it (before, the exercise read the wording
    of the reason, and a reason worded otherwise let it draw other data)."""
    kin = solve_kinematics(_pinion_in_annulus(), [0.4], 10.0, 2.0)
    apart = dataclasses.replace(kin, valid=np.array([False]))
    for c in (construct_kinematics(apart, 0), instant_centres(apart, 0)):
        assert not c.valid and not c.disagreement
    result = catalog.load("strip_cutter").solve()
    c = construct_forces(result.kinematics, 0)
    assert check_forces(result, c, 0) is c and not c.disagreement

    _key_refused(monkeypatch, "ω3 is 1 rad/s graphically, 2 rad/s analytically")
