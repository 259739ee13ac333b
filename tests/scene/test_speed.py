"""A scene's speed (issue 37, item 3): where the forces are linear in ω², its two parts give every speed of the
file's sense exactly; where they are not, the problem is marked with the reason and carries presolved speeds."""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest

import graphkin as gk
from graphkin.cycle import sweep
from graphkin.model import GearMesh, Prismatic
from graphkin.scene import PRECISION, scene, scene_json
from graphkin.scene.build import drawn
from graphkin.scene.polygons import force_polygons
from graphkin.scene.speed import PRESOLVED, linearity

N = 24
KINDS = {name: linearity(drawn(gk.load(name)))[0] for name in gk.catalog.names()}


def _read(problem) -> dict:
    return json.loads(scene_json(scene(problem, N, polygons=False)))


def _flat(values) -> np.ndarray:
    return np.array([np.nan if v is None else v for v in values], float)


def _direct(problem, rate):
    """The cycle solved directly at another input rate, at the scene's positions."""
    other = drawn(problem).at_speed(rate)
    return (sweep(other, N) if problem.mechanism.driver.crank else sweep(other)).analysis


@pytest.mark.parametrize("name", [k for k, v in KINDS.items() if v == "superpose"])
@pytest.mark.parametrize("factor", [0.3, 1.7])
def test_superposed_forces_equal_a_direct_solve_at_another_speed(name, factor):
    problem = gk.load(name)
    s = _read(problem)
    speed = s["speed"]
    rate = factor * speed["value"]
    r = _direct(problem, rate)
    top = max(float(np.nanmax(np.hypot(*r.force(f["of"], f["on"]).T))) for f in s["forces"])
    for f, part in zip(s["forces"], speed["superpose"]["forces"]):
        # What the page computes from the scene's numbers: F_rest + ω² F_ω².
        found = _flat(part["rest"]) + rate**2 * _flat(part["omega2"])
        np.testing.assert_allclose(found, r.force(f["of"], f["on"]).reshape(-1), rtol=0, atol=1e-9 * top)
        if "couple" in part:  # a sliding pair's couple, drawn on its free bodies, follows the same way
            found = _flat(part["couple"]["rest"]) + rate**2 * _flat(part["couple"]["omega2"])
            np.testing.assert_allclose(found, r.couple[(f["of"], f["on"])], rtol=0, atol=1e-9 * top * s["size"])
    assert [("couple" in part) for part in speed["superpose"]["forces"]] == [f["kind"] == "prismatic"
                                                                              for f in s["forces"]]
    effort = speed["superpose"]["effort"]
    found = _flat(effort["rest"]) + rate**2 * _flat(effort["omega2"])
    arm = s["size"] if s["driver"]["kind"] == "crank" else 1.0
    np.testing.assert_allclose(found, r.effort, rtol=0, atol=1e-9 * top * arm)
    # At the file's own speed the parts give the scene's own forces.
    for f, part in zip(s["forces"], speed["superpose"]["forces"]):
        own = _flat(part["rest"]) + speed["value"] ** 2 * _flat(part["omega2"])
        np.testing.assert_allclose(own, _flat(f["analytical"]), rtol=0, atol=2 * PRECISION * top / factor**2)
    # Each inertia resultant scales by (ω/ω₀)², its line unmoved.
    for inn in s["inertia"]:
        exact = r.inertia(inn["link"])
        np.testing.assert_allclose(factor**2 * _flat(inn["force"]), exact.F.reshape(-1), rtol=0, atol=1e-9 * top)
        np.testing.assert_allclose(_flat(inn["line_point"]), exact.line_point.reshape(-1), rtol=0,
                                   atol=PRECISION * s["size"])


@pytest.mark.parametrize("name", [k for k, v in KINDS.items() if v == "presolved"])
def test_presolved_speeds_equal_direct_solves(name):
    problem = gk.load(name)
    s = _read(problem)
    speed = s["speed"]
    assert [p["value"] for p in speed["presolved"]] == [f * speed["value"] for f in PRESOLVED]
    for p in speed["presolved"]:
        r = _direct(problem, p["value"])
        top = max(float(np.nanmax(np.hypot(*r.force(f["of"], f["on"]).T))) for f in s["forces"])
        for f, F, C in zip(s["forces"], p["forces"], p["couples"]):
            np.testing.assert_allclose(_flat(F), r.force(f["of"], f["on"]).reshape(-1), rtol=0,
                                       atol=2 * PRECISION * top)
            assert (C is not None) == (f["kind"] == "prismatic")
            if C is not None:
                np.testing.assert_allclose(_flat(C), r.couple[(f["of"], f["on"])], rtol=0,
                                           atol=2 * PRECISION * top * s["size"])
        for inn, found in zip(s["inertia"], p["inertia"]):
            np.testing.assert_allclose(_flat(found["force"]), r.inertia(inn["link"]).F.reshape(-1), rtol=0,
                                       atol=2 * PRECISION * top)


def test_every_problem_not_linear_in_the_speed_is_marked_with_its_reason():
    for name, kind in KINDS.items():
        problem = drawn(gk.load(name))  # a crank's cycle: the motion its input gives, a book's [given] values dropped
        speed = _read(problem)["speed"] if name in ("slider_crank_friction", "fourbar_dynamic_makdin") else None
        mech = problem.mechanism
        friction = [j for j in mech.joints if isinstance(j, Prismatic) and j.mu]
        losses = [j for j in mech.joints if isinstance(j, GearMesh) and j.efficiency < 1]
        reason = linearity(problem)[1]
        if problem.static:
            assert kind == "static", name
        elif problem.given:
            assert kind == "fixed" and "[given]" in reason, name
        elif friction:
            assert kind == "presolved" and "friction" in reason and f"μ = {friction[0].mu:g}" in reason, name
        elif losses:
            assert kind == "presolved" and "η" in reason, name
        elif problem.q_ddot[0] != 0:
            assert kind == "presolved" and "accelerates" in reason, name
        else:
            assert kind == "superpose", name
        if speed is not None:
            assert speed["kind"] == kind and speed["reason"] == reason
            assert ("presolved" in speed) == (kind == "presolved") and ("superpose" in speed) == (kind == "superpose")


def test_a_problem_held_to_its_own_speed_says_why():
    base = gk.load("double_slider")  # slider-driven: drawn at its own positions, a book's values with them
    given = replace(base, given={(3, "omega"): np.array([1.0])})
    at_rest = replace(base, q_dot=np.zeros_like(base.q_dot))
    assert linearity(given) == ("fixed", "the file gives kinematic values ([given]) that hold at its own speed only")
    kind, reason = linearity(at_rest)
    assert kind == "fixed" and "at rest (v = 0)" in reason
    assert scene(at_rest, polygons=False)["speed"] == {"kind": kind, "reason": reason, "value": 0.0, "unit": "m/s"}


def _template(p) -> tuple:
    return p["sub"], p["link"], p["kind"], tuple(p["names"]), tuple(p["known"])


@pytest.mark.parametrize("name", [k for k, v in KINDS.items() if v == "superpose"])
@pytest.mark.parametrize("factor", [0.3, 1.7])
def test_superposed_polygons_equal_a_construction_at_another_speed(name, factor):
    """The graphical route follows the speed as the analytical one does: each polygon's vertices, each joint force
    and the effort the page adds up from the scene's two parts equal the construction built at that speed, to 1e-9 of
    its largest value (every arrow is linear in the loads' wrenches, each load in ω²: scene/polygons.py)."""
    problem = gk.load(name)
    s = json.loads(scene_json(scene(problem, N)))
    sup = s["speed"]["superpose"]["graphical"]
    rate = factor * s["speed"]["value"]
    r = _direct(problem, rate)
    direct = force_polygons(r, np.asarray(r.valid, bool))
    valid = np.array(sup["valid"], bool)
    # Every position the scene's construction holds is in the parts: both speeds took the same steps.
    assert valid.tolist() == (np.array(s["graphical"]["valid"], bool) & direct.valid).tolist()
    assert valid.sum() >= 0.9 * sum(s["valid"])
    index = {_template(t): k for k, t in enumerate(direct.templates)}
    top = max(float(np.nanmax(np.abs(V[valid]))) for V in direct.vertices)
    for p, part in zip(s["graphical"]["polygons"], sup["polygons"]):
        found = (_flat(part["rest"]) + rate**2 * _flat(part["omega2"])).reshape(direct.vertices[0].shape[0], -1, 2)
        want = direct.vertices[index[_template(p)]]
        np.testing.assert_allclose(found[valid], want[valid], rtol=0, atol=1e-9 * top, err_msg=str(p["names"]))
    # The polygons the construction at that speed draws are those the parts give, position by position.
    for k in np.flatnonzero(valid):
        here = {_template(p) for p, part in zip(s["graphical"]["polygons"], sup["polygons"])
                if part["rest"][2 * (len(p["names"]) + 1) * k] is not None}
        assert here == {_template(t) for t, V in zip(direct.templates, direct.vertices) if np.isfinite(V[k]).all()}
    for f, part in zip(s["forces"], sup["forces"]):
        found = (_flat(part["rest"]) + rate**2 * _flat(part["omega2"])).reshape(-1, 2)
        np.testing.assert_allclose(found[valid], direct.forces[f["of"], f["on"]][valid], rtol=0, atol=1e-9 * top)
    found = _flat(sup["effort"]["rest"]) + rate**2 * _flat(sup["effort"]["omega2"])
    arm = s["size"] if s["driver"]["kind"] == "crank" else 1.0
    np.testing.assert_allclose(found[valid], direct.effort[valid], rtol=0, atol=1e-9 * top * arm)


def test_presolved_speeds_carry_their_own_graphical_route():
    problem = gk.load("slider_crank_friction")
    s = json.loads(scene_json(scene(problem, N)))
    for p in s["speed"]["presolved"]:
        r = _direct(problem, p["value"])
        direct = force_polygons(r, np.asarray(r.valid, bool))
        g = p["graphical"]
        assert g["valid"] == direct.valid.astype(int).tolist()
        assert [_template(t) for t in g["polygons"]] == [_template(t) for t in direct.templates]
        top = max(float(np.nanmax(np.abs(V))) for V in direct.vertices)
        for t, V in zip(g["polygons"], direct.vertices):
            np.testing.assert_allclose(_flat(t["vertices"]), V.reshape(-1), rtol=0, atol=2 * PRECISION * top)
        for f, F in zip(s["forces"], g["forces"]):
            np.testing.assert_allclose(_flat(F), direct.forces[f["of"], f["on"]].reshape(-1), rtol=0,
                                       atol=2 * PRECISION * top)


def test_the_docs_list_each_catalog_problem_under_its_kind():
    """docs/json.md names which catalog problems a page rescales exactly, which it offers at presolved speeds and
    which are static: the list is linearity's."""
    from pathlib import Path

    text = (Path(__file__).resolve().parents[2] / "docs" / "json.md").read_text(encoding="utf-8")
    block = text.split("The catalog's problems by kind", 1)[1].split("\n\n", 2)[1]
    listed = {}
    for item in block.split("\n- "):
        kind, _, names = item.lstrip("- ").partition(": ")
        for name in names.replace("\n", " ").split(","):
            listed[name.split("(")[0].strip()] = kind
    assert listed == KINDS
