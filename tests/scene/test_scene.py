"""A scene (graphkin.scene.scene): the cycle as data a browser draws, equal to what the solvers give position by
position, with what cannot be reached or does not agree marked rather than drawn."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

import graphkin as gk
from graphkin.scene import PRECISION, SCHEMA, scene, scene_json
from graphkin.scene import polygons as scene_polygons
from tests.strategies import toggle_fourbar

ROOT = Path(__file__).resolve().parents[2]


def _read(problem, n, **options) -> dict:
    """The scene as a reader of its JSON gets it: nan is null (None)."""
    return json.loads(scene_json(scene(problem, n, **options)))


def _xy(flat, i):
    """Position i of a flat [x0, y0, x1, y1, …] list."""
    return flat[2 * i:2 * i + 2]


@pytest.fixture(scope="module")
def cutter():
    return _read(gk.load("strip_cutter"), 36)


@pytest.mark.parametrize("name", gk.catalog.names())
def test_every_catalog_problem_builds_and_its_json_reads_back(name):
    s = scene(gk.load(name), 12)
    assert s["schema"] == SCHEMA and s["n"] == len(s["valid"]) == len(s["input"]["values"])
    back = json.loads(scene_json(s))
    assert back["schema"] == SCHEMA and back["n"] == s["n"]
    for f in back["forces"]:
        assert len(f["analytical"]) == len(f["graphical"]) == len(f["at"]) == 2 * s["n"]
    # Every position the catalog's problems take is reachable, and both routes agree there.
    assert all(back["valid"]) and all(back["graphical"]["valid"]), back["invalid"] + back["graphical"]["invalid"]


@pytest.mark.parametrize("name", ["strip_cutter", "shaper_six_bar", "slider_crank_friction", "gearset"])
def test_values_equal_the_solvers_at_sampled_positions(name):
    problem = gk.load(name)
    s = scene(problem, 24)
    size = s["size"]
    sample = [0, 5, 13, s["n"] - 1]
    r = problem.solve(at=[s["input"]["values"][i] for i in sample])
    kin = r.kinematics
    F_top = max(float(np.nanmax(np.hypot(*r.force(f["of"], f["on"]).T))) for f in s["forces"])
    for k, i in enumerate(sample):
        for f in s["forces"]:
            exact = r.force(f["of"], f["on"])[k]
            np.testing.assert_allclose(_xy(f["analytical"], i), exact, rtol=0, atol=2 * PRECISION * F_top)
            # The graphical route's value is the construction's, checked to agree (guard.AGREEMENT = 1e-9).
            np.testing.assert_allclose(_xy(f["graphical"], i), exact, rtol=0, atol=1e-8 * F_top)
        arm = 1.0 if s["driver"]["kind"] == "slider" else size
        assert abs(s["effort"]["analytical"][i] - r.effort[k]) <= 2 * PRECISION * F_top * arm
        for link in s["links"]:
            if link["number"] == problem.mechanism.frame:
                continue
            for point, flat in link["points"].items():
                np.testing.assert_allclose(_xy(flat, i), kin.position(link["number"], point)[k], rtol=0,
                                           atol=PRECISION * size)
        for inn in s["inertia"]:
            exact = r.inertia(inn["link"])
            np.testing.assert_allclose(_xy(inn["force"], i), exact.F[k], rtol=0, atol=2 * PRECISION * F_top)
            np.testing.assert_allclose(_xy(inn["line_point"], i), exact.line_point[k], rtol=0, atol=PRECISION * size)


def test_polygons_close_and_their_sides_are_the_constructions(cutter):
    problem = gk.load("strip_cutter")
    i = 7
    r = problem.solve(at=[cutter["input"]["values"][i]])
    c = gk.construct_forces(r.kinematics, 0)
    steps = [st for st in c.steps if st.polygon]
    drawn = [p for p in cutter["graphical"]["polygons"] if _xy(p["vertices"], i * (len(p["names"]) + 1))[0]
             is not None]
    assert len(drawn) == len(steps)
    for p, st in zip(drawn, steps):
        m = len(p["names"])
        V = np.asarray(p["vertices"][2 * (m + 1) * i:2 * (m + 1) * (i + 1)]).reshape(m + 1, 2)
        assert p["names"] == [a.name for a in st.polygon]
        top = max(math.hypot(*a.vector) for a in st.polygon)
        np.testing.assert_allclose(np.diff(V, axis=0), [a.vector for a in st.polygon], rtol=0, atol=1e-8 * top)
        np.testing.assert_allclose(V[-1], V[0], rtol=0, atol=1e-8 * top)  # each polygon closes


def test_positions_the_linkage_cannot_reach_are_marked_with_their_reason():
    s = _read(toggle_fourbar(), 36)
    theta = np.asarray(s["input"]["values"])
    expected = np.cos(theta) < -0.35  # beyond the toggle
    assert expected.any() and (~expected).any()
    assert s["valid"] == (~expected).astype(int).tolist()
    listed = {entry["index"]: entry["reason"] for entry in s["invalid"]}
    assert set(listed) == set(np.flatnonzero(expected).tolist())
    assert all("cannot be assembled" in why for why in listed.values())
    for i in listed:
        assert _xy(s["links"][2]["points"]["B"], i) == [None, None]
        assert all(_xy(f["analytical"], i) == [None, None] for f in s["forces"])
        assert all(_xy(f["graphical"], i) == [None, None] for f in s["forces"])
        assert s["effort"]["analytical"][i] is None


def test_a_graphical_value_that_disagrees_is_marked_and_not_kept(monkeypatch):
    built = scene_polygons.construct_forces

    def off_at_three(kin, i):
        c = built(kin, i)
        if i != 3:
            return c
        forces = dict(c.forces)
        key = next(iter(forces))
        forces[key] = (forces[key][0] * 1.01, forces[key][1])
        return replace(c, forces=forces)

    monkeypatch.setattr(scene_polygons, "construct_forces", off_at_three)
    s = _read(gk.load("strip_cutter"), 12)
    g = s["graphical"]
    assert g["valid"][3] == 0 and sum(g["valid"]) == s["n"] - 1
    assert [e["index"] for e in g["invalid"]] == [3] and "disagree" in g["invalid"][0]["reason"]
    assert all(_xy(f["graphical"], 3) == [None, None] for f in s["forces"])
    assert all(p["vertices"][2 * 3 * (len(p["names"]) + 1)] is None for p in g["polygons"])
    assert s["effort"]["graphical"][3] is None and s["effort"]["graphical"][2] is not None


def test_labels_are_structured_text(cutter):
    by_name = {f["name"]: f["label"] for f in cutter["forces"]}
    assert by_name["F23"] == {"symbol": "F", "sub": "23", "mark": "", "unit": "N"}
    assert cutter["effort"]["label"] == {"symbol": "T", "sub": "12", "mark": "", "unit": "N*m"}
    marked = [lab for p in cutter["graphical"]["polygons"] for lab in p["labels"] if lab["mark"]]
    assert {lab["mark"] for lab in marked} == {"′", "″"}


def test_without_polygons_the_scene_holds_the_analytical_route_only():
    s = scene(gk.load("strip_cutter"), 12, polygons=False)
    assert s["graphical"] is None and all("graphical" not in f for f in s["forces"])
    assert "graphical" not in s["effort"]


def test_a_scene_and_its_page_load_no_matplotlib_ipywidgets_or_pint():
    # Reading the problem file may load pint for a unit its table lacks: that is the reader's, counted before.
    code = ("import sys, graphkin as gk\n"
            "p = gk.load('strip_cutter')\n"
            "heavy = ('matplotlib', 'ipywidgets', 'pint')\n"
            "before = {m for m in heavy if m in sys.modules}\n"
            "gk.scene.page(gk.scene.scene(p, 12))\n"
            "print(sorted({m for m in heavy if m in sys.modules} - before))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["[]"]


def test_gears_are_their_pitch_circles_and_a_constant_effort_has_an_axis():
    problem = gk.load("epicyclic_khurmi")
    s = _read(problem, 12)
    meshes = [j for j in problem.mechanism.joints if isinstance(j, gk.GearMesh)]
    want = {(k, c, j.radius(k)) for j in meshes for k, c in zip(j.links, j.centers)}
    assert {(g["link"], g["centre"], g["radius"]) for g in s["gears"]} == want
    assert [g["internal"] for g in s["gears"]].count(True) == 1  # the annulus
    by_number = {link["number"]: link for link in s["links"]}
    assert all(by_number[g["link"]]["outline"] == [] for g in s["gears"] if len(by_number[g["link"]]["points"]) == 1)
    # Each gear's mark lies on its pitch circle and turns with the gear: its angle about the centre changes as the
    # gear's own angle θ does (the frame's annulus stays still).
    kin = gk.sweep(problem, 12).analysis.kinematics
    for g in s["gears"]:
        C = np.array(by_number[g["link"]]["points"][g["centre"]], float).reshape(-1, 2)
        M = np.array(g["mark"], float).reshape(-1, 2)
        ok = np.isfinite(M[:, 0])
        np.testing.assert_allclose(np.hypot(*(M - C)[ok].T), g["radius"], rtol=0, atol=2e-6 * s["size"])
        turned = np.unwrap(np.arctan2(*(M - C)[ok][:, ::-1].T))
        if g["link"] == problem.mechanism.frame:
            assert np.ptp(turned) < 1e-9
        else:
            theta = np.unwrap(kin.theta[g["link"]][ok])
            np.testing.assert_allclose(turned - turned[0], theta - theta[0], atol=1e-5)
            assert np.ptp(turned) > 1e-3  # it turns
    # The arm's torque is the same at every angle: its axis runs from it to 0, not from it to itself.
    T = s["effort"]["analytical"]
    assert max(T) - min(T) < 1e-9 * abs(T[0])
    assert T[0] < 0 and s["effort"]["range"] == [min(T), 0.0]  # the sun is driven clockwise here
