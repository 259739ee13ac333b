"""``gk.explore(problem)`` (issue 37): the browser draws the scene with the shipped module; the kernel
answers only a change the scene cannot express, with a new scene equal to one built directly."""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest

import graphkin as gk
from graphkin.errors import GraphkinError
from graphkin.scene import scene, scene_json
from graphkin.scene.page import MODULES, asset, module
from graphkin.widgets.browser import BrowserExplorer, changed

N = 24


def _same_scene(ex, problem):
    assert json.loads(ex.widget.scene) == json.loads(scene_json(scene(problem, N)))


@pytest.fixture
def cutter():
    return gk.explore(gk.load("strip_cutter"), n=N)


def test_the_widget_is_the_shipped_module_and_its_scene_is_the_problems(cutter):
    assert isinstance(cutter, BrowserExplorer)
    w = cutter.widget
    assert w._esm == module() and w._css == asset("scene.css")
    for name in MODULES:  # every shipped file is in it, its imports of the others aside
        body = [line for line in asset(name).splitlines() if not line.startswith("import {")]
        assert "\n".join(body) in w._esm
    assert "export default" in w._esm and "cdn" not in w._esm.lower() and "http" not in w._esm.replace(
        "http://www.w3.org/2000/svg", "")
    _same_scene(cutter, cutter.problem)
    assert json.loads(scene_json(cutter.scene)) == json.loads(w.scene)


def test_a_change_the_scene_cannot_express_sends_a_new_scene(cutter):
    p = cutter.problem
    before = json.loads(cutter.widget.scene)
    cutter.set("mass.3", 4.0)
    assert cutter.problem.mechanism.link(3).mass == 4.0
    _same_scene(cutter, cutter.problem)
    after = json.loads(cutter.widget.scene)
    assert after["forces"] != before["forces"] and after["links"] == before["links"]
    cutter.set("point.3.B", (0.25, 0.0))  # a length: |AB| 235 → 250 mm
    _same_scene(cutter, cutter.problem)
    B = np.array(json.loads(cutter.widget.scene)["links"][2]["points"]["B"][:2])
    A = np.array(json.loads(cutter.widget.scene)["links"][2]["points"]["A"][:2])
    assert abs(np.hypot(*(B - A)) - 0.25) < 1e-9
    name = p.mechanism.loads[0].name
    cutter.set(f"load.{name}", (-100.0, 0.0))
    assert cutter.problem.mechanism.loads[0].force == (-100.0, 0.0)
    _same_scene(cutter, cutter.problem)


@pytest.mark.parametrize("field, value, words", [
    ("colour", 1, "not one the explorer changes"),
    ("mass.9", 1.0, "link's number"),
    ("point.3", (0, 0), "link's number"),
    ("point.3.Z", (0, 0), "no point 'Z'"),
    ("load.nothing", (0, 0), "no external load is named 'nothing'"),
    ("mass.3", -1.0, "link 3"),
])
def test_a_field_it_cannot_change_is_one_plain_message(field, value, words):
    with pytest.raises(GraphkinError, match=words):
        changed(gk.load("strip_cutter"), field, value)


def test_a_length_of_a_slider_driven_problem_with_given_kinematics_is_refused():
    # Drawn at its own positions with the book's values, which hold for the book's geometry only.
    given = replace(gk.load("double_slider"), given={(3, "omega"): np.array([1.0])})
    with pytest.raises(GraphkinError, match=r"\[given\]"):
        changed(given, "point.3.B", (0.1, 0.0))


def test_a_crank_problems_given_values_are_not_drawn_so_its_lengths_change():
    p = gk.load("fourbar_dynamic_makdin")
    point = list(p.mechanism.link(3).points)[-1]
    q = changed(p, f"point.3.{point}", (0.1, 0.02))
    assert not q.given and q.mechanism.link(3).points[point] == (0.1, 0.02)


def test_the_speed_and_friction_are_new_problems_too():
    p = gk.load("slider_crank_friction")
    assert changed(p, "mu", 0.0).mechanism == p.with_friction(0.0).mechanism
    assert float(changed(p, "speed", 10.0).q_dot[0]) == 10.0


def test_the_position_shown_from_python_is_one_of_the_scene(cutter):
    cutter.index = 5
    assert cutter.widget.index == 5
    with pytest.raises(GraphkinError, match="not a position"):
        cutter.index = cutter.scene["n"]
