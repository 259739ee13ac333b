"""The free bodies, the motion polygons, the units of the read-out and playing at the true speed, in a real browser
(issue 37, item 3): what is drawn is the scene, read back from the SVG to 1e-6 of the drawing's size."""

from __future__ import annotations

import numpy as np
import pytest

from graphkin import catalog
from graphkin.scene import scene, write_page
from graphkin.units.systems import unit_system
from tests.e2e.test_scene_page import READ_BACK, _open, _scene_of, _svg, _xy, check_drawn
from tests.scene.test_bodies_motion import couple_value

READ_MORE = """() => {
  const num = (node, k) => Number(node.getAttribute(k));
  const line = (g) => {
    const l = g.querySelectorAll("line")[1];
    return [num(l, "x1"), num(l, "y1"), num(l, "x2"), num(l, "y2")];
  };
  const out = {bodies: {}, motion: {}};
  for (const svg of document.querySelectorAll("svg[data-body]")) {
    if (svg.parentNode.style.display === "none" || svg.closest(".gk-bodies").style.display === "none") continue;
    const shape = svg.querySelector("[data-link]");
    out.bodies[svg.getAttribute("data-body")] = {
      shape: shape.tagName === "polygon"
        ? shape.getAttribute("points").trim().split(/\\s+/).map((xy) => xy.split(",").map(Number))
        : shape.tagName === "circle" ? [[num(shape, "cx"), num(shape, "cy")]] : [[num(shape, "x"), num(shape, "y")]],
      arrows: [...svg.querySelectorAll("g.gk-arrow")].map((g) => [g.getAttribute("data-name"),
        g.style.display === "none" ? null : line(g)]),
      couples: [...svg.querySelectorAll("g.gk-couple")].map((g) => [g.getAttribute("data-name"),
        g.style.display === "none" ? null : g.querySelectorAll("path")[1].getAttribute("d")]),
      offset: [...svg.querySelectorAll("line[data-offset]")].map((l) => l.style.display === "none" ? null
        : [num(l, "x1"), num(l, "y1"), num(l, "x2"), num(l, "y2")]),
      viewBox: svg.getAttribute("viewBox").split(" ").map(Number),
      overflow: getComputedStyle(svg).overflow};
  }
  for (const svg of document.querySelectorAll("svg[data-motion]")) {
    if (svg.parentNode.style.display === "none" || svg.closest(".gk-motions").style.display === "none") continue;
    out.motion[svg.getAttribute("data-motion")] = [...svg.querySelectorAll("g.gk-arrow")].map(line);
  }
  return out;
}"""


def check_couples(got: dict, s: dict, b: dict, link: dict, i: int, tol: float):
    """Each couple's curved arrow: its arc on the scene's ring around its centre, counter-clockwise where the value
    is positive; and the inertia resultant's offset from G to its line."""
    assert [c[0] for c in got["couples"]] == [t["name"] for t in b["torques"]]
    for (name, d), t in zip(got["couples"], b["torques"]):
        T = couple_value(s, t, i)
        if T is None or T == 0:
            assert d is None, name
            continue
        C = _xy(s["forces"][t["index"]]["at"] if t["of"] == "joint"
                else link["G"] if t["point"] == "G" else link["points"][t["point"]], i)
        a0, a1 = (t["start"], t["start"] + t["span"]) if T > 0 else (t["start"] + t["span"], t["start"])
        M, A = d.split("A")
        start = [float(v) for v in M.strip("M ").split(",")]
        r, rest = A.split(" ", 1)
        flags, end = rest.rsplit(" ", 1)
        rx, ry = (float(v) for v in r.split(","))
        large, sweep = flags.split()[1:]
        np.testing.assert_allclose(start, _svg(C + t["radius"] * np.array([np.cos(a0), np.sin(a0)])), rtol=0,
                                   atol=tol, err_msg=name)
        np.testing.assert_allclose([float(v) for v in end.split(",")],
                                   _svg(C + t["radius"] * np.array([np.cos(a1), np.sin(a1)])), rtol=0, atol=tol,
                                   err_msg=name)
        np.testing.assert_allclose([rx, ry], t["radius"], rtol=0, atol=tol)
        assert (large, sweep) == ("1", "0" if T > 0 else "1"), name  # SVG's y is down: CCW is the negative sweep
    if b["inertia"] is None:
        assert got["offset"] == []
        return
    P = _xy(s["inertia"][b["inertia"]]["line_point"], i)
    if P is None:
        assert got["offset"] == [None]
    else:
        np.testing.assert_allclose(got["offset"][0], [*_svg(_xy(link["G"], i)), *_svg(P)], rtol=0, atol=tol)


def check_more(drawn: dict, s: dict, i: int, bodies: bool) -> list:
    """The free bodies (when shown) and the motion polygons at position i against the scene; the names of the couples
    drawn."""
    drawn_couples = []
    tol = 1e-6 * s["size"]
    scale = s["scales"]["force"]
    if not bodies:
        assert drawn["bodies"] == {}
    else:
        assert set(drawn["bodies"]) == {str(b["link"]) for b in s["free_bodies"]}
        for b in s["free_bodies"]:
            got = drawn["bodies"][str(b["link"])]
            link = next(lk for lk in s["links"] if lk["number"] == b["link"])
            names = link["outline"]
            if len(names) > 1:
                want = [_svg(_xy(link["points"][k], i)) for k in names]
            elif len(names) == 1:
                want = [_svg(_xy(link["points"][names[0]], i)) + [-0.04 * s["size"], -0.03 * s["size"]]]
            else:
                gear = next(g for g in s["gears"] if g["link"] == b["link"])
                want = [_svg(_xy(link["points"][gear["centre"]], i))]
            np.testing.assert_allclose(got["shape"], want, rtol=0, atol=tol, err_msg=f"link {b['link']}")
            expected = []
            for f in b["forces"]:
                sf = s["forces"][f["index"]]
                tail, F = _xy(sf["at"], i), f["sign"] * _xy(sf["analytical"], i)
                expected.append((f["name"], tail, F))
            if b["drive"] is not None:  # a slider driver's force: the effort along the guide's direction
                expected.append((b["drive"]["name"], _xy(s["effort"]["at"], i),
                                 s["effort"]["analytical"][i] * _xy(s["effort"]["direction"], i)))
            for k in b["loads"]:
                ld = s["loads"][k]
                if "force" in ld:
                    expected.append((ld["name"], _xy(ld["at"], i), _xy(ld["force"], i)))
            if b["inertia"] is not None:
                inn = s["inertia"][b["inertia"]]
                expected.append((inn["name"], _xy(inn["line_point"], i), _xy(inn["force"], i)))
            # The box is the scene's (the link, its forces and couples), whatever the inertia line: cut at it.
            x0, y0, x1, y1 = b["box"]
            np.testing.assert_allclose(got["viewBox"], [x0, -y1, x1 - x0, y1 - y0], rtol=0, atol=tol)
            assert got["overflow"] == "hidden"
            drawn_couples.extend(name for name, d in got["couples"] if d is not None)
            check_couples(got, s, b, link, i, tol)
            assert [a[0] for a in got["arrows"]] == [e[0] for e in expected]
            for (name, line), (_, tail, F) in zip(got["arrows"], expected):
                if tail is None or not F.any():
                    assert line is None, name
                    continue
                want = np.concatenate([_svg(tail), _svg(tail + F / scale)])
                np.testing.assert_allclose(line, want, rtol=0, atol=tol, err_msg=f"{name} on link {b['link']}")
    m = s["motion"]
    if m is None:
        assert drawn["motion"] == {}
        return drawn_couples
    assert set(drawn["motion"]) == ({str(k) for k in range(len(m["polygons"]))} if m["valid"][i] else set())
    for k, p in enumerate(m["polygons"]):
        if not m["valid"][i]:
            continue
        V = np.asarray(p["vectors"], float).reshape(s["n"], -1, 4)[i]
        extent = max(p["box"][2] - p["box"][0], p["box"][3] - p["box"][1])
        np.testing.assert_allclose(drawn["motion"][str(k)], V * [1, -1, 1, -1], rtol=0, atol=1e-6 * extent,
                                   err_msg=p["kind"])
    return drawn_couples


@pytest.mark.parametrize("name", ["strip_cutter", "shaper_six_bar", "gearset", "slider_crank_friction",
                                  "double_slider"])
def test_free_bodies_and_motion_polygons_drawn_are_the_scene(browser, tmp_path, name):
    path = tmp_path / f"{name}.html"
    write_page(scene(catalog.load(name), 36, motion=True), path)
    context, page, asked, errors = _open(browser, path)
    try:
        s = _scene_of(page)
        slider = page.locator("[data-do=position]")
        first = min(3, s["n"] - 1)  # a slider driver is drawn at its own positions: the double slider's one
        slider.fill(str(first))
        assert page.locator(".gk-bodies").is_hidden()  # off at first
        check_more(page.evaluate(READ_MORE), s, first, bodies=False)
        page.check("[data-toggle=bodies]")
        couples = set()
        for i in sorted({min(k, s["n"] - 1) for k in (3, 17, s["n"] - 1)}):  # a slider driver: its own positions
            slider.fill(str(i))
            check_drawn(page.evaluate(READ_BACK), s, i)
            couples |= set(check_more(page.evaluate(READ_MORE), s, i, bodies=True))
        if s["driver"]["kind"] == "crank":
            assert s["effort"]["name"] in couples  # the driving torque on the crank's free body
        else:  # the driving force on the slider's free body, an arrow (checked against the scene above)
            assert [b["drive"]["name"] for b in s["free_bodies"] if b["drive"]] == [s["effort"]["name"]]
        if name == "shaper_six_bar":
            assert {t["name"] for b in s["free_bodies"] for t in b["torques"] if t["of"] == "joint"} <= couples
        if name == "gearset":
            assert {"T13", "T2i", "T3i"} <= couples  # an external torque; inertia torques alone (G on the pivot)
        page.uncheck("[data-toggle=motion]")
        assert page.locator(".gk-motions").is_hidden()
        assert errors == []
    finally:
        context.close()
    assert asked == [path.as_uri()]


def _number(text: str) -> float:
    return float(text.replace("−", "-"))


def test_a_hovered_force_reads_in_si_or_the_books_units(browser, tmp_path):
    path = tmp_path / "cutter.html"
    us = unit_system("US")
    write_page(scene(catalog.load("strip_cutter"), 36, motion=True, units=us), path)
    context, page, asked, errors = _open(browser, path)
    try:
        s = _scene_of(page)
        i = 5
        page.locator("[data-do=position]").fill(str(i))
        page.check("[data-toggle=bodies]")
        # The reaction F32 on the crank's free body: −F23 of the scene.
        body = next(b for b in s["free_bodies"] if b["link"] == s["driver"]["link"])
        ref = next(f for f in body["forces"] if f["sign"] == -1)
        F = ref["sign"] * _xy(s["forces"][ref["index"]]["analytical"], i)
        arrow = page.locator(f"svg[data-body='{body['link']}'] g.gk-arrow[data-name='{ref['name']}'] line").nth(1)
        arrow.hover(force=True)
        readout = page.locator(".gk-readout")

        def polar():
            text = readout.text_content()
            name, _, rest = text.partition(" = ")
            assert len(rest.split(" ")) == 4, text
            size, unit, _, angle = rest.split(" ")
            return name, _number(size), unit, _number(angle.rstrip("°"))

        name, size, unit, angle = polar()
        assert (name, unit) == (ref["name"], "N")
        assert size == pytest.approx(np.hypot(*F), rel=1e-3)
        assert angle == pytest.approx(np.degrees(np.arctan2(F[1], F[0])), abs=0.01)
        page.select_option("[data-do=units]", "book")
        name, size, unit, angle = polar()  # the same force, now in the book's units
        assert (name, unit) == (ref["name"], us.symbol("force"))
        assert size == pytest.approx(us.scales["force"] * np.hypot(*F), rel=1e-3)
        # The table follows the units too; the read-out follows the position.
        row = page.locator(f".gk-table tr[data-name='{s['forces'][0]['name']}'] td").first.text_content()
        assert f" {us.symbol('force')} ∠ " in row
        page.evaluate(f"window.graphkin.view.show({i + 9})")  # the pointer left where it is
        F = ref["sign"] * _xy(s["forces"][ref["index"]]["analytical"], i + 9)
        assert polar()[1] == pytest.approx(us.scales["force"] * np.hypot(*F), rel=1e-3)
        # A motion polygon's vector reads in m/s, then in the book's ft/s.
        vector = page.locator("svg[data-motion='0'] g.gk-arrow").nth(1)
        vector.locator("line").nth(1).hover(force=True)
        assert readout.text_content().split(" ")[3] == us.symbol("velocity")
        # The driving torque's curved arrow on the crank reads its value, unit and sense, in the units chosen.
        page.evaluate(f"window.graphkin.view.show({i})")
        couple = page.locator(f"svg[data-body='{body['link']}'] g.gk-couple[data-name='{s['effort']['name']}']")
        couple.locator("text").hover(force=True)  # its label (an arc's box centre is off its stroke)
        T = s["effort"]["analytical"][i]
        name, _, rest = readout.text_content().partition(" = ")
        size, unit, sense = rest.rsplit(" ", 2)
        assert (name, unit, sense) == (s["effort"]["name"], us.symbol("torque"), "CCW" if T > 0 else "CW")
        assert _number(size) == pytest.approx(us.scales["torque"] * abs(T), rel=1e-3)
        assert errors == []
    finally:
        context.close()
    assert asked == [path.as_uri()]


def test_play_runs_at_the_chosen_fraction_of_the_true_speed(browser, tmp_path):
    """The page's clock is Playwright's (rAF and performance.now run as told): after a second played at 1/50 of
    900 rpm, the crank has turned 1000/50 ms of its 66.7 ms turn, and the position shown is the last one reached."""
    path = tmp_path / "cutter.html"
    write_page(scene(catalog.load("strip_cutter"), 360, polygons=False), path)
    context = browser.new_context(offline=True, viewport={"width": 1300, "height": 1000})
    page = context.new_page()
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.clock.install()
    page.goto(path.as_uri())
    page.wait_for_function("window.graphkin && window.graphkin.view")
    page.clock.pause_at(page.evaluate("Date.now()") + 1000)  # time stands still but when run
    try:
        s = _scene_of(page)
        t, period = np.array(s["input"]["time"]), s["input"]["period"]
        options = page.locator("[data-do=speed] option")
        labels = [options.nth(k).text_content() for k in range(options.count())]
        assert labels[0] == "true speed" and "slowed ×1/50" in labels
        # At first the fastest that takes at least two seconds a turn: 1/50 (3.3 s), not 1/20 (1.3 s).
        assert page.locator("[data-do=speed]").input_value() == str(1 / 50)
        start = page.evaluate("window.graphkin.view.index")
        page.click("[data-do=play]")
        page.clock.run_for(1000)
        page.click("[data-do=play]")
        k = page.evaluate("window.graphkin.view.index")
        # Mechanism time gone by: at most 1000/50 ms; at least that less two frames (the clicks' and the last).
        gone = (t[k] - t[start]) % period
        assert 1.0 / 50 - 2 * 0.017 / 50 <= gone + (period / s["n"]) and gone <= 1.0 / 50
        # At the true speed a second is 15 turns: the position shown is where the crank is then.
        page.select_option("[data-do=speed]", "1")
        start = k
        page.click("[data-do=play]")
        page.clock.run_for(500)
        page.click("[data-do=play]")
        k = page.evaluate("window.graphkin.view.index")
        gone = (t[k] - t[start]) % period
        assert gone <= 0.5 % period and 0.5 % period - 2 * 0.017 <= gone + period / s["n"]
        assert errors == []
    finally:
        context.close()


def test_each_svgs_arrowheads_are_its_own(browser, tmp_path):
    """An id is the document's: every polygon's and free body's SVG drew the mechanism's arrowheads, at the
    mechanism's size, while each had markers of the same ids. Each arrow's head is now a marker of its own SVG."""
    path = tmp_path / "cutter.html"
    write_page(scene(catalog.load("strip_cutter"), 12, motion=True), path)
    context, page, asked, errors = _open(browser, path)
    try:
        ids = page.evaluate("[...document.querySelectorAll('marker')].map((m) => m.id)")
        assert len(ids) == len(set(ids))
        foreign = page.evaluate("""() => [...document.querySelectorAll('line[marker-end]')].filter((l) => {
          const id = l.getAttribute('marker-end').slice(5, -1);
          return l.ownerSVGElement.querySelector(`marker[id="${id}"]`) === null;
        }).length""")
        assert foreign == 0
        assert page.locator("svg[data-body]").count() and page.locator("svg[data-motion]").count()
        assert errors == []
    finally:
        context.close()
    assert asked == [path.as_uri()]


def test_tapping_a_force_reads_it_on_a_touch_screen(browser, tmp_path):
    from tests.e2e.test_scene_page import UNCOVERED

    path = tmp_path / "cutter.html"
    write_page(scene(catalog.load("strip_cutter"), 36), path)
    context = browser.new_context(offline=True, has_touch=True, viewport={"width": 1300, "height": 1000})
    context.route("**/*", lambda route: route.continue_() if route.request.url == path.as_uri() else route.abort())
    page = context.new_page()
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    try:
        page.goto(path.as_uri())
        page.wait_for_function("window.graphkin && window.graphkin.view")
        s = _scene_of(page)
        name, x, y = page.evaluate(UNCOVERED)
        page.touchscreen.tap(x, y)
        F = _xy(next(f for f in s["forces"] if f["name"] == name)["analytical"], 0)
        text = page.locator(".gk-readout").text_content()
        assert text.startswith(f"{name} = ") and f"{np.hypot(*F):.4g}" in text.replace("−", "-")
        assert errors == []
    finally:
        context.close()


@pytest.mark.parametrize("name", ["strip_cutter", "shaper_six_bar"])
def test_at_another_speed_the_free_bodies_follow_and_the_motion_polygons_go(browser, tmp_path, name):
    """The free bodies refer to the forces, so they are drawn at the speed typed (a sliding pair's couple too); the
    motion polygons are presolved at the file's speed only, and each position is reached at its time × ω₀/ω."""
    path = tmp_path / "cutter.html"
    write_page(scene(catalog.load(name), 36, motion=True), path)
    context, page, asked, errors = _open(browser, path)
    try:
        s = _scene_of(page)
        page.check("[data-toggle=bodies]")
        box = page.locator("[data-do=rate]")
        box.fill(repr(float(box.input_value()) * 1.5))
        box.dispatch_event("change")
        live = page.evaluate("window.graphkin.view.scene")
        assert live["motion"] is None and "motion polygons" in page.locator("[data-do=rate-note]").text_content()
        np.testing.assert_allclose(live["input"]["period"], s["input"]["period"] / 1.5, rtol=1e-12)
        np.testing.assert_allclose(live["input"]["time"], np.array(s["input"]["time"]) / 1.5, rtol=1e-12)
        for i in (4, 20):
            page.locator("[data-do=position]").fill(str(i))
            check_more(page.evaluate(READ_MORE), live, i, bodies=True)
        # The live forces are not the file's: the free bodies moved with them.
        assert live["forces"][0]["analytical"] != s["forces"][0]["analytical"]
        couples = [k for k, f in enumerate(s["forces"]) if any(f.get("couple") or [])]  # the shaper's block's
        assert len(couples) == (name == "shaper_six_bar")
        assert all(live["forces"][k]["couple"] != s["forces"][k]["couple"] for k in couples)
        assert page.locator(".gk-motions").is_hidden()
        assert errors == []
    finally:
        context.close()
    assert asked == [path.as_uri()]
