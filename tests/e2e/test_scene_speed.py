"""The speed box of ``graphkin explore PROBLEM -o page.html`` in a real browser (issue 37, item 3).

Where the forces are linear in ω² a student types any speed of the file's sense and what is drawn equals a direct
solve at that speed (to 1e-6 of the mechanism's size, as tests/e2e/test_scene_page.py reads it back); elsewhere the
box offers the presolved speeds only, and each is drawn as its direct solve; a static problem's speed is stated.
"""

from __future__ import annotations

import copy
import json

import numpy as np
import pytest

from graphkin import catalog
from graphkin.cli import main
from graphkin.cycle import sweep
from graphkin.scene.build import drawn
from tests.e2e.test_scene_page import READ_BACK, _open, _scene_of, check_drawn

N = 36


def _direct(s: dict, name: str, rate: float, scale: float) -> dict:
    """The scene ``s`` with the forces of a direct solve at ``rate`` and the page's force scale: what the page must
    draw at that speed (no graphical route: it is presolved at the file's speed only)."""
    problem = drawn(catalog.load(name)).at_speed(rate)
    r = (sweep(problem, N) if problem.mechanism.driver.crank else sweep(problem)).analysis
    out = copy.deepcopy(s)
    for f in out["forces"]:
        f["analytical"] = _flat(r.force(f["of"], f["on"]))
    for inn in out["inertia"]:
        found = r.inertia(inn["link"])
        inn["force"], inn["line_point"] = _flat(found.F), _flat(found.line_point)
    out["scales"]["force"], out["graphical"] = scale, None
    return out


def _flat(xy) -> list:
    """A vector over the positions as the scene holds it: flat, null (None) where it has no value."""
    return [None if np.isnan(v) else float(v) for v in np.asarray(xy, float).reshape(-1)]


def _drawn(page) -> dict:
    drawn = page.evaluate(READ_BACK)
    assert page.locator(".gk-polygons").evaluate("e => e.style.display") == "none"
    drawn["polygons"] = {}
    return drawn


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
        for i in sample:
            page.locator("[data-do=position]").fill(str(i))
            check_drawn(_drawn(page), want, i)
        # A speed of the other sense is refused, and the box says why.
        box.fill(repr(-typed))
        box.dispatch_event("change")
        assert "sense" in page.locator("[data-do=rate-note]").text_content()
        check_drawn(_drawn(page), want, sample[-1])
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
        want = _direct(s, name, rate, page.evaluate("window.graphkin.view.scene.scales.force"))
        for i in (0, N // 2):
            page.locator("[data-do=position]").fill(str(i))
            check_drawn(_drawn(page), want, i)
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
