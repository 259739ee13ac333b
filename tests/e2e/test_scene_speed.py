"""The speed box of ``graphkin explore PROBLEM -o page.html`` in a real browser (issue 37, item 3).

Where the forces are linear in ω² a student types any speed of the file's sense and what is drawn — the mechanism's
arrows, the force polygons, the graphical route's values in the table — equals a direct solve and a construction at
that speed (to 1e-6 of the mechanism's size, of a polygon's extent, as tests/e2e/test_scene_page.py reads it back);
elsewhere the box offers the presolved speeds only, and each is drawn as its direct solve and construction; a static
problem's speed is stated.
"""

from __future__ import annotations

import copy
import json
import math

import numpy as np
import pytest

from graphkin import catalog
from graphkin.cli import main
from graphkin.scene import scene, scene_json
from graphkin.scene.build import drawn
from tests.e2e.test_scene_bodies import READ_MORE, check_more
from tests.e2e.test_scene_page import READ_BACK, _open, _scene_of, check_drawn

N = 36


def _template(p) -> tuple:
    return p["sub"], p["link"], p["kind"], tuple(p["names"]), tuple(p["known"])


def _direct(s: dict, name: str, rate: float, scale: float, templates: str = "scene", n: int = N) -> dict:
    """The scene ``s`` with the forces, the inertia resultants, the effort and the graphical route of a scene built
    directly at ``rate`` (a solve and a construction there), and the page's force scale: what the page must draw at
    that speed. ``templates``: the polygons in the scene's order (a superposed speed) or the construction's own (a
    presolved speed: its own steps)."""
    other = json.loads(scene_json(scene(drawn(catalog.load(name)).at_speed(rate), n,
                                        polygons=s["graphical"] is not None)))  # as a page reads it: nan is null
    out = copy.deepcopy(s)
    for f, g in zip(out["forces"], other["forces"]):
        f["analytical"] = g["analytical"]
        f["graphical"] = g.get("graphical")
    for inn, g in zip(out["inertia"], other["inertia"]):
        inn.update({k: g[k] for k in ("force", "torque", "h", "line_point")})
        for i in range(out["n"]):  # a force rounded to nothing has no line (the noise of a G on its pivot)
            if g["force"][2 * i] == 0 and g["force"][2 * i + 1] == 0:
                inn["line_point"][2 * i:2 * i + 2] = [None, None]
    out["effort"]["analytical"] = other["effort"]["analytical"]
    out["effort"]["graphical"] = other["effort"].get("graphical")
    out["scales"]["force"] = scale
    if other["graphical"] is None:
        return out
    index = {_template(t): t for t in other["graphical"]["polygons"]}
    order = [_template(p) for p in s["graphical"]["polygons"]] if templates == "scene" else list(index)
    out["graphical"] = {"valid": other["graphical"]["valid"], "polygons": [
        index[key] if key in index else {"names": list(key[3]), "box": [0, 0, 1, 1],
                                         "vertices": [None] * (2 * (len(key[3]) + 1) * s["n"])} for key in order]}
    return out


def _largest(flat) -> float:
    return max([abs(v) for v in flat if v is not None] + [0.0])


def rounding(s: dict, want: dict, rate: float) -> float:
    """How far a polygon's vertex the page adds up, rest + ω² omega2 (each part rounded to the scene's precision of
    its own largest value), may be from the same vertex of a scene built at that speed (rounded to its precision of
    its largest force) [N]: half a unit of each rounding."""
    half = 0.5 * s["precision"]
    sup = s["speed"].get("superpose", {}).get("graphical")
    if sup is None:
        return 0.0
    parts = [f for f in sup["forces"]] + sup["polygons"]
    rest = max(_largest(p["rest"]) for p in parts)
    omega2 = max(_largest(p["omega2"]) for p in parts)
    top = max([_largest(f["analytical"]) for f in want["forces"]] + [_largest(x["force"]) for x in want["inertia"]]
              + [_largest(ld["force"]) for ld in want["loads"] if "force" in ld])
    return half * (rest + rate**2 * omega2 + top)


def _flat(xy) -> list:
    """A vector over the positions as the scene holds it: flat, null (None) where it has no value."""
    return [None if np.isnan(v) else float(v) for v in np.asarray(xy, float).reshape(-1)]


def _drawn(page) -> dict:
    return page.evaluate(READ_BACK)


def check_table(page, want: dict, i: int):
    """The table's graphical column at position i: each joint force's polar form as the construction at that speed
    gives it, to the four figures and two decimals of a degree the page writes."""
    rows = page.locator(".gk-table tbody tr")
    for k, f in enumerate(want["forces"]):
        text = rows.nth(k).locator("td").nth(1).text_content().replace("−", "-")
        G = f["graphical"][2 * i:2 * i + 2]
        if G[0] is None:
            assert text == "—"
            continue
        size, _, angle = text.partition(" N ∠ ")
        assert math.isclose(float(size), math.hypot(*G), rel_tol=1e-3), (f["name"], text, G)
        if math.hypot(*G) > 1e-6 * max(abs(v) for v in f["graphical"] if v is not None):
            turn = (float(angle.rstrip("°")) - math.degrees(math.atan2(G[1], G[0])) + 180) % 360 - 180
            assert abs(turn) <= 0.006, (f["name"], text, G)


@pytest.mark.parametrize("name, factor", [("strip_cutter", 1.7), ("shaper_six_bar", 0.4), ("double_slider", 2.5)])
def test_any_speed_of_a_linear_problem_is_drawn_as_its_direct_solve(browser, tmp_path, name, factor):
    path = tmp_path / f"{name}.html"
    assert main(["explore", name, "-o", str(path), "--n", str(N)]) == 0
    context, page, asked, errors = _open(browser, path)
    try:
        s = _scene_of(page)
        assert s["speed"]["kind"] == "superpose"
        box = page.locator("[data-do=rate]")
        typed = float(box.input_value()) * factor  # rpm for a crank, m/s for a slider
        box.fill(repr(typed))
        box.dispatch_event("change")
        rate = typed * np.pi / 30 if s["speed"]["unit"] == "rad/s" else typed
        scale = page.evaluate("window.graphkin.view.scene.scales.force")
        assert scale >= s["scales"]["force"]
        want = _direct(s, name, rate, scale)
        sample = sorted({0, s["n"] // 3, s["n"] - 1})  # a slider-driven problem: its own positions
        assert page.locator(".gk-polygons").is_visible()
        for i in sample:
            page.locator("[data-do=position]").fill(str(i))
            check_drawn(_drawn(page), want, i, rounding(s, want, rate))
            check_table(page, want, i)
        # The polygons drawn moved with the speed: they are not the file's.
        assert page.evaluate("window.graphkin.view.scene.graphical.polygons[0].vertices") != \
            s["graphical"]["polygons"][0]["vertices"]
        # A speed of the other sense is refused, and the box says why.
        box.fill(repr(-typed))
        box.dispatch_event("change")
        assert "sense" in page.locator("[data-do=rate-note]").text_content()
        check_drawn(_drawn(page), want, sample[-1], rounding(s, want, rate))
        assert errors == []
    finally:
        context.close()
    assert asked == [path.as_uri()]


def test_a_problem_with_friction_offers_its_presolved_speeds_only(browser, tmp_path):
    name = "slider_crank_friction"
    path = tmp_path / f"{name}.html"
    assert main(["explore", name, "-o", str(path), "--n", str(N)]) == 0
    context, page, asked, errors = _open(browser, path)
    try:
        s = _scene_of(page)
        speed = s["speed"]
        assert speed["kind"] == "presolved" and "friction" in page.locator("[data-do=rate-note]").text_content()
        box = page.locator("[data-do=rate]")
        values = box.locator("option").evaluate_all("os => os.map((o) => Number(o.value))")
        assert values == [p["value"] for p in speed["presolved"]]
        rate = values[-1]
        box.select_option(json.dumps(rate))
        want = _direct(s, name, rate, page.evaluate("window.graphkin.view.scene.scales.force"), "construction")
        for i in (0, N // 2):
            page.locator("[data-do=position]").fill(str(i))
            check_drawn(_drawn(page), want, i)
            check_table(page, want, i)
        assert errors == []
    finally:
        context.close()


def test_a_static_problem_states_its_speed_and_why_it_does_not_matter(browser, tmp_path):
    path = tmp_path / "static.html"
    assert main(["explore", "slider_crank_static_makdin", "-o", str(path), "--n", str(N)]) == 0
    context, page, asked, errors = _open(browser, path)
    try:
        assert page.locator("output[data-do=rate]").count() == 1
        assert "static" in page.locator("[data-do=rate-note]").text_content()
        assert errors == []
    finally:
        context.close()


@pytest.mark.parametrize("name", catalog.names())
def test_every_problem_is_drawn_as_its_scene_before_and_after_a_speed_change(browser, tmp_path, name):
    """Issue 37, item 4, for every catalog problem: the mechanism, the force polygons, the free bodies with their
    couples, read back from the SVG at sampled positions, equal the scene; after a change of speed (a superposed
    one, or the last presolved one) they equal the direct solve and the construction at that speed."""
    path = tmp_path / f"{name}.html"
    assert main(["explore", name, "-o", str(path), "--n", "12"]) == 0
    context, page, asked, errors = _open(browser, path)
    try:
        s = _scene_of(page)
        slider = page.locator("[data-do=position]")
        page.check("[data-toggle=bodies]")
        sample = sorted({0, s["n"] // 2, s["n"] - 1})
        for i in sample:
            slider.fill(str(i))
            check_drawn(page.evaluate(READ_BACK), s, i)
            check_more(page.evaluate(READ_MORE), s, i, bodies=True)
        speed = s["speed"]
        if speed["kind"] in ("superpose", "presolved"):
            box = page.locator("[data-do=rate]")
            if speed["kind"] == "superpose":
                typed = float(box.input_value()) * 1.3
                box.fill(repr(typed))
                box.dispatch_event("change")
                rate = typed * np.pi / 30 if speed["unit"] == "rad/s" else typed
            else:
                rate = speed["presolved"][-1]["value"]
                box.select_option(json.dumps(rate))
            scale = page.evaluate("window.graphkin.view.scene.scales.force")
            want = _direct(s, name, rate, scale, "scene" if speed["kind"] == "superpose" else "construction", 12)
            for i in sample:
                slider.fill(str(i))
                check_drawn(page.evaluate(READ_BACK), want, i, rounding(s, want, rate))
                check_more(page.evaluate(READ_MORE), want, i, bodies=True)
        assert errors == []
    finally:
        context.close()
    assert asked == [path.as_uri()]
