"""A scene's free bodies, motion polygons, times and book units (issue 37, items 1 and 3): each free body balances
with the forces the scene refers it to, each motion polygon's vectors are the solver's velocities and accelerations,
and each position's time is when the crank reaches it."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import graphkin as gk
from graphkin.scene import SCHEMA, scene, scene_json
from graphkin.units.systems import SI, unit_system


def _read(problem, n, **options) -> dict:
    return json.loads(scene_json(scene(problem, n, **options)))


def _xy(flat, i):
    return None if flat[2 * i] is None else np.array(flat[2 * i:2 * i + 2])


def _drive(s: dict, b: dict, i: int):
    """A slider driver's force on its free body at position i [N], as the page draws it: the effort times the guide's
    direction the scene gives (None on every other free body)."""
    if b.get("drive") is None:
        return None
    return s["effort"]["analytical"][i] * _xy(s["effort"]["direction"], i)


BALANCED = ["strip_cutter", "shaper_six_bar", "slider_crank_friction", "gearset", "engine_double_acting_khurmi",
            "double_slider", "spring_link_hibbeler", "single_link", "epicyclic_khurmi", "fourbar_two_loads_makdin"]


@pytest.mark.parametrize("name", BALANCED)
def test_each_free_body_balances_with_the_forces_it_refers_to(name):
    """Σ of the joint forces (times the scene's sign), the loads, the inertia force and a slider driver's driving
    force on each moving link is 0: the references and signs say which force acts on which link. A link driven by a
    torque balances its forces too."""
    s = _read(gk.load(name), 24)
    moving = [lk["number"] for lk in s["links"] if lk["number"] != s["frame"]]
    assert [b["link"] for b in s["free_bodies"]] == moving
    top = max(np.nanmax(np.abs(np.array(f["analytical"], float))) for f in s["forces"])
    for b in s["free_bodies"]:
        for f in b["forces"]:
            sf = s["forces"][f["index"]]
            assert b["link"] in (sf["of"], sf["on"])
            assert f["sign"] == (1 if sf["on"] == b["link"] else -1)
            other = sf["of"] if f["sign"] == 1 else sf["on"]
            assert f["name"][1:].replace(",", "") == f"{other}{b['link']}"
        assert (b["drive"] is not None) == (s["driver"]["kind"] == "slider" and s["driver"]["link"] == b["link"])
        for i in range(s["n"]):
            if not s["valid"][i]:
                continue
            total = sum(f["sign"] * _xy(s["forces"][f["index"]]["analytical"], i) for f in b["forces"])
            total = total + sum((_xy(s["loads"][k]["force"], i) for k in b["loads"] if "force" in s["loads"][k]),
                                np.zeros(2))
            if b["inertia"] is not None:
                total = total + _xy(s["inertia"][b["inertia"]]["force"], i)
            if b["drive"] is not None:
                total = total + _drive(s, b, i)
            np.testing.assert_allclose(total, 0, atol=1e-6 * top, err_msg=f"link {b['link']} at {i}")


def _cross(r, F) -> float:
    return float(r[0] * F[1] - r[1] * F[0])


def couple_value(s: dict, t: dict, i: int):
    """A free body's couple at position i [N·m] as the page draws it: its array's value; the inertia torque only where
    the scene's resultant has no line (the printed free body's rule, graphkin.draw.fbd.loads_on). The browser's
    read-back (tests/e2e/test_scene_bodies.py) uses it too."""
    if t["of"] == "effort":
        return s["effort"]["analytical"][i]
    if t["of"] == "load":
        return s["loads"][t["index"]]["torque"][i]
    if t["of"] == "joint":
        C = s["forces"][t["index"]]["couple"][i]
        return None if C is None else t["sign"] * C
    inn = s["inertia"][t["index"]]
    return inn["torque"][i] if _xy(inn["line_point"], i) is None else None


@pytest.mark.parametrize("name", BALANCED)
def test_each_free_body_balances_in_moments_with_its_couples(name):
    """Σ M about the origin on each link is 0 with the forces and couples the scene draws on it: the driving torque on
    the crank (or a slider driver's force at its point), each external torque, a sliding pair's couple beside its
    force at the slider's point, and the inertia torque where it acts alone (elsewhere the resultant's offset line
    carries it). The printed free body (graphkin.draw.fbd) draws the same couples."""
    s = _read(gk.load(name), 24)
    top = max(np.nanmax(np.abs(np.array(f["analytical"], float))) for f in s["forces"])
    checked = 0
    for b in s["free_bodies"]:
        names = [t["name"] for t in b["torques"]]
        if s["driver"]["link"] == b["link"]:
            assert s["effort"]["name"] in (names if s["driver"]["kind"] == "crank" else [b["drive"]["name"]])
        for i in range(s["n"]):
            if not s["valid"][i]:
                continue
            M = sum(_cross(_xy(s["forces"][f["index"]]["at"], i), f["sign"] * _xy(s["forces"][f["index"]]["analytical"],
                                                                                   i)) for f in b["forces"])
            M += sum(_cross(_xy(s["loads"][k]["at"], i), _xy(s["loads"][k]["force"], i)) for k in b["loads"]
                     if "force" in s["loads"][k])
            if b["inertia"] is not None:
                inn = s["inertia"][b["inertia"]]
                if _xy(inn["line_point"], i) is not None:
                    M += _cross(_xy(inn["line_point"], i), _xy(inn["force"], i))
            M += sum(v for v in (couple_value(s, t, i) for t in b["torques"]) if v is not None)
            if b["drive"] is not None:
                M += _cross(_xy(s["effort"]["at"], i), _drive(s, b, i))
            np.testing.assert_allclose(M, 0, atol=1e-6 * top * s["size"], err_msg=f"link {b['link']} at {i}")
            checked += 1
    assert checked


@pytest.mark.parametrize("name", ["strip_cutter", "shaper_six_bar", "gearset", "double_slider"])
def test_a_free_bodys_box_holds_its_link_the_joint_forces_and_couples_not_the_far_inertia_line(name):
    s = _read(gk.load(name), 24)
    scale = s["scales"]["force"]
    for b in s["free_bodies"]:
        x0, y0, x1, y1 = b["box"]
        link = next(lk for lk in s["links"] if lk["number"] == b["link"])
        for i in range(s["n"]):
            points = [_xy(p, i) for p in link["points"].values()]
            for f in b["forces"]:
                sf = s["forces"][f["index"]]
                points += [_xy(sf["at"], i), _xy(sf["at"], i) + f["sign"] * _xy(sf["analytical"], i) / scale]
            if b["drive"] is not None:
                points += [_xy(s["effort"]["at"], i), _xy(s["effort"]["at"], i) + _drive(s, b, i) / scale]
            for t in b["torques"]:
                C = _xy(s["forces"][t["index"]]["at"] if t["of"] == "joint"
                        else link["G"] if t["point"] == "G" else link["points"][t["point"]], i)
                points += [C - t["radius"], C + t["radius"]]
            for P in points:
                assert x0 <= P[0] <= x1 and y0 <= P[1] <= y1
        # The box is the link's, not its inertia resultant's: that line may run far off, and is cut at the box.
        if b["inertia"] is not None and name == "strip_cutter" and b["link"] == 3:
            far = [P for P in (_xy(s["inertia"][b["inertia"]]["line_point"], i) for i in range(s["n"])) if P is not None]
            assert any(not (x0 <= P[0] <= x1 and y0 <= P[1] <= y1) for P in far)


@pytest.mark.parametrize("name", ["strip_cutter", "shaper_six_bar"])
def test_motion_polygons_are_the_solvers_velocities_and_accelerations(name):
    problem = gk.load(name)
    s = _read(problem, 24, motion=True)
    assert scene(problem, 24, polygons=False)["motion"] is None  # only when asked
    m = s["motion"]
    assert all(m["valid"]) and {p["kind"] for p in m["polygons"]} == {"velocity", "acceleration"}
    sample = [0, 7, s["n"] - 1]
    kin = problem.without_given().solve(at=[s["input"]["values"][i] for i in sample]).kinematics
    for p in m["polygons"]:
        V = np.array(p["vectors"], float).reshape(s["n"], -1, 4)
        top = np.nanmax(np.abs(V))
        for k, i in enumerate(sample):
            for j, name_ in enumerate(p["names"]):
                symbol, _, point = name_.partition("_")
                if not (point.startswith("G") and point[1:].isdigit()):
                    continue  # a centre of mass: its link is in its name
                link = int(point[1:])
                want = (kin.v_G(link) if p["kind"] == "velocity" else kin.a_G(link))[k]
                np.testing.assert_allclose(V[i, j, 2:] - V[i, j, :2], want, atol=1e-6 * top, err_msg=f"{name_} at {i}")
                np.testing.assert_allclose(V[i, j, :2], 0, atol=1e-6 * top)  # from the pole
        assert all(lab["unit"] == p["unit"] for lab in p["labels"])
    normal = [lab for p in m["polygons"] for lab, n in zip(p["labels"], p["names"]) if n.startswith("a^n_")]
    assert normal and all(lab["symbol"] == "a" and lab["sup"] == "n" for lab in normal)


@pytest.mark.parametrize("name", ["strip_cutter", "engine_double_acting_khurmi"])
def test_each_position_is_reached_at_its_time(name):
    """θ_k − θ_0 = ω t_k over a turn of 2π/|ω|, whichever the sense (the Khurmi engine turns clockwise)."""
    s = scene(gk.load(name), 36, polygons=False)
    omega = s["input"]["rate"][0]
    period = s["input"]["period"]
    assert period == pytest.approx(2 * math.pi / abs(omega), rel=1e-12)
    q = np.array(s["input"]["values"])
    t = np.array(s["input"]["time"])
    assert (t >= 0).all() and (t < period).all()
    turned = np.mod(omega * t - (q - q[0]), 2 * math.pi)
    np.testing.assert_allclose(np.minimum(turned, 2 * math.pi - turned), 0, atol=1e-9)


def test_a_static_problem_has_no_time_to_play_at():
    s = scene(gk.load("engine_inch_bevan"), 12, polygons=False)
    assert s["input"]["time"] is None and s["input"]["period"] is None


def test_the_book_units_are_the_report_systems():
    cutter = gk.load("strip_cutter")
    s = scene(cutter, 12, polygons=False)
    assert s["schema"] == SCHEMA == 3
    assert s["book"]["name"] == "SI" and s["book"]["length"] == {"unit": "mm", "scale": 1e3}
    us = unit_system("US")
    b = scene(cutter, 12, polygons=False, units=us)["book"]
    assert b["name"] == "US"
    for kind in ("length", "force", "torque", "velocity", "acceleration"):
        assert b[kind] == {"unit": us.symbol(kind), "scale": us.scales[kind]}
    assert b["force"]["scale"] == pytest.approx(1 / 4.4482216152605)
    assert SI.scales["force"] == 1.0


def test_the_notebook_widget_asks_for_the_motion_polygons_and_the_book_units():
    pytest.importorskip("anywidget")
    from graphkin.widgets.browser import BrowserExplorer

    us = unit_system("US")
    ex = BrowserExplorer(gk.load("strip_cutter"), 12, polygons=False, motion=True, units=us)
    sent = json.loads(ex.widget.scene)
    assert sent["motion"] is not None and sent["book"]["name"] == "US"
    ex.set("mass.3", 4.0)  # a new scene, asked for as the first
    sent = json.loads(ex.widget.scene)
    assert sent["motion"] is not None and sent["book"]["force"]["unit"] == us.symbol("force")
