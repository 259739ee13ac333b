"""``graphkin explore PROBLEM -o page.html`` in a real browser, from disk with the network off (issue 37).

What is drawn is what Python computed: at sampled positions the SVG's coordinates are read back and compared with
the scene to 1e-6 of the mechanism's size (a force polygon: of its own extent). The slider, the arrow keys, dragging
the crank, play and pause, the toggles and the hover read-out are driven as a student would. The time from an
input event to the SVG updated (and to the next frame) is printed, with the time to the first frame drawn; these are
measurements, not assertions (benchmarks/README.md).
"""

from __future__ import annotations

import json
import statistics

import numpy as np
import pytest

from graphkin import catalog
from graphkin.cli import main
from graphkin.scene import scene, scene_json, write_page
from tests.strategies import toggle_fourbar

READ_BACK = """() => {
  const svg = document.querySelector("svg.gk-mechanism");
  const num = (node, k) => Number(node.getAttribute(k));
  const out = {index: window.graphkin.view.index, links: {}, points: {}, arrows: {}, polygons: {}, gears: {}};
  for (const p of svg.querySelectorAll("[data-link]")) {
    out.links[p.getAttribute("data-link")] = p.tagName === "polygon"
      ? p.getAttribute("points").trim().split(/\\s+/).map((xy) => xy.split(",").map(Number))
      : [[num(p, "x"), num(p, "y")]];
  }
  for (const c of svg.querySelectorAll("circle[data-point]")) {
    if (c.style.display !== "none") out.points[c.getAttribute("data-point")] = [num(c, "cx"), num(c, "cy")];
  }
  out.gears = {};
  for (const c of svg.querySelectorAll("circle[data-gear]")) {
    if (c.style.display !== "none") out.gears[c.getAttribute("data-gear")] = [num(c, "cx"), num(c, "cy"), num(c, "r")];
  }
  out.spokes = {};
  for (const l of svg.querySelectorAll("line[data-spoke]")) {
    if (l.style.display !== "none") out.spokes[l.getAttribute("data-spoke")] = ["x1", "y1", "x2", "y2"].map((k) => num(l, k));
  }
  for (const g of svg.querySelectorAll("g.gk-arrow")) {
    if (g.style.display === "none") continue;
    const l = g.querySelectorAll("line")[1];
    out.arrows[g.getAttribute("data-name")] = [num(l, "x1"), num(l, "y1"), num(l, "x2"), num(l, "y2")];
  }
  for (const cell of document.querySelectorAll("svg[data-polygon]")) {
    if (cell.parentNode.style.display === "none") continue;
    out.polygons[cell.getAttribute("data-polygon")] = [...cell.querySelectorAll("g.gk-arrow")].map((g) => {
      const l = g.querySelectorAll("line")[1];
      return [num(l, "x1"), num(l, "y1"), num(l, "x2"), num(l, "y2")];
    });
  }
  return out;
}"""


UNCOVERED = """() => {
  // A joint force's arrow whose middle no other drawing covers: its name and that point on the screen.
  for (const g of document.querySelectorAll("svg.gk-mechanism g.gk-forces g.gk-arrow")) {
    const r = g.querySelectorAll("line")[1].getBoundingClientRect();
    const x = r.left + r.width / 2, y = r.top + r.height / 2;
    if (document.elementFromPoint(x, y)?.closest(".gk-arrow") === g) return [g.getAttribute("data-name"), x, y];
  }
  return null;
}"""


def _xy(flat, i):
    return None if flat[2 * i] is None else np.array(flat[2 * i:2 * i + 2])


def _svg(p):
    """A scene point [m] (y up) where the page puts it (SVG's y down)."""
    return np.array([p[0], -p[1]])


def check_drawn(drawn: dict, s: dict, i: int, rounding: float = 0.0):
    """The page's SVG at position i against the scene, to 1e-6 of the mechanism's size (of a polygon's extent);
    ``rounding`` [N]: how far the scene's own numbers may be from those drawn (a polygon the page added up from two
    rounded parts, against a scene rounded at another speed: tests/e2e/test_scene_speed.py)."""
    assert drawn["index"] == i
    tol = 1e-6 * s["size"]
    scale = s["scales"]["force"]
    for link in s["links"]:
        if link["number"] == s["frame"]:
            continue
        names = link["outline"]
        for k, flat in link["points"].items():
            np.testing.assert_allclose(drawn["points"][f"{link['number']}.{k}"], _svg(_xy(flat, i)), rtol=0, atol=tol)
        if not names:  # a gear: its pitch circle
            assert str(link["number"]) not in drawn["links"]
            continue
        got = np.asarray(drawn["links"][str(link["number"])])
        want = np.array([_svg(_xy(link["points"][k], i)) for k in names])
        if len(names) == 1:  # a block: a rectangle centred on its point
            want = want + [-0.04 * s["size"], -0.03 * s["size"]]
        np.testing.assert_allclose(got, want, rtol=0, atol=tol, err_msg=f"link {link['number']}")
    links = {link["number"]: link for link in s["links"]}
    assert len(drawn["gears"]) == len(s["gears"])
    for gear in s["gears"]:
        C = _svg(_xy(links[gear["link"]]["points"][gear["centre"]], i))
        np.testing.assert_allclose(drawn["gears"][f"{gear['link']}.{gear['centre']}"], [*C, gear["radius"]], rtol=0,
                                   atol=tol)
        if "mark" in gear:  # the spoke that shows the gear turning: from its centre to its mark
            np.testing.assert_allclose(drawn["spokes"][f"{gear['link']}.{gear['centre']}"],
                                       [*C, *_svg(_xy(gear["mark"], i))], rtol=0, atol=tol)
    for f in s["forces"]:
        tail, F = _xy(f["at"], i), _xy(f["analytical"], i)
        want = np.concatenate([_svg(tail), _svg(tail + F / scale)])
        np.testing.assert_allclose(drawn["arrows"][f["name"]], want, rtol=0, atol=tol, err_msg=f["name"])
    for inn in s["inertia"]:
        P = _xy(inn["line_point"], i)
        if P is not None:
            want = np.concatenate([_svg(P), _svg(P + _xy(inn["force"], i) / scale)])
            np.testing.assert_allclose(drawn["arrows"][inn["name"]], want, rtol=0, atol=tol, err_msg=inn["name"])
    g = s["graphical"]
    if g is None or not g["valid"][i]:
        assert drawn["polygons"] == {}
        return
    here = {str(k) for k, p in enumerate(g["polygons"]) if p["vertices"][2 * (len(p["names"]) + 1) * i] is not None}
    assert set(drawn["polygons"]) == here
    for k in here:
        p = g["polygons"][int(k)]
        m = len(p["names"])
        V = np.asarray(p["vertices"][2 * (m + 1) * i:2 * (m + 1) * (i + 1)]).reshape(m + 1, 2) * [1, -1]
        want = np.concatenate([V[:-1], V[1:]], axis=1)
        extent = max(p["box"][2] - p["box"][0], p["box"][3] - p["box"][1])
        np.testing.assert_allclose(drawn["polygons"][k], want, rtol=0, atol=1e-6 * extent + rounding,
                                   err_msg=str(p["names"]))


def _open(browser, path):
    """The page from file:// in a context with the network off and every request but the page's refused."""
    context = browser.new_context(offline=True, viewport={"width": 1300, "height": 1000})
    asked = []

    def refuse(route):
        asked.append(route.request.url)
        if route.request.url == path.as_uri():
            route.continue_()
        else:
            route.abort()

    context.route("**/*", refuse)
    page = context.new_page()
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.goto(path.as_uri())
    page.wait_for_function("window.graphkin && window.graphkin.view")
    return context, page, asked, errors


def _scene_of(page) -> dict:
    return page.evaluate("JSON.parse(document.getElementById('graphkin-scene').textContent)")


def _ms(values) -> str:
    values = sorted(values)
    return f"median {statistics.median(values):.2f} ms, p99 {values[int(0.99 * (len(values) - 1))]:.2f} ms"


@pytest.mark.parametrize("name", catalog.names())
def test_what_is_drawn_is_the_scene(browser, tmp_path, name):
    path = tmp_path / f"{name}.html"
    assert main(["explore", name, "-o", str(path), "--n", "36"]) == 0
    context, page, asked, errors = _open(browser, path)
    try:
        s = _scene_of(page)
        slider = page.locator("[data-do=position]")
        for i in sorted({k for k in (0, 5, s["n"] // 2, s["n"] - 1) if k < s["n"]}):
            slider.fill(str(i))
            check_drawn(page.evaluate(READ_BACK), s, i)
        assert errors == []
    finally:
        context.close()
    assert asked == [path.as_uri()]


@pytest.mark.parametrize("name", ["strip_cutter", "shaper_six_bar"])
def test_keys_drag_play_toggles_and_hover_at_screen_rate(browser, tmp_path, timings, name):
    path = tmp_path / f"{name}.html"
    assert main(["explore", name, "-o", str(path)]) == 0  # 360 positions, polygons shown
    size_mb = path.stat().st_size / 1e6
    context, page, asked, errors = _open(browser, path)
    try:
        s = _scene_of(page)
        first = page.evaluate("window.graphkin.view.ready")
        # Arrow keys step one presolved position, and wrap around the turn.
        page.locator("h1").click()
        for _ in range(3):
            page.keyboard.press("ArrowLeft")
        check_drawn(page.evaluate(READ_BACK), s, s["n"] - 3)
        reset = "for (const k of ['timings', 'frames', 'work']) window.graphkin.view[k].length = 0"
        page.evaluate(reset)
        for _ in range(200):
            page.keyboard.press("ArrowRight")
        check_drawn(page.evaluate(READ_BACK), s, (s["n"] - 3 + 200) % s["n"])
        got = "[window.graphkin.view.timings, window.graphkin.view.frames, window.graphkin.view.work]"
        keys = page.evaluate(got)
        # A key pressed in the speed box is the box's: the position stays.
        page.focus("[data-do=speed]")
        page.keyboard.press("ArrowDown")
        assert page.evaluate("window.graphkin.view.index") == (s["n"] - 3 + 200) % s["n"]
        page.locator("h1").click()
        # Dragging the crank: from its handle at the position shown to where the handle is at position j.
        handle = next(lk for lk in s["links"] if lk["number"] == s["driver"]["link"])["points"][s["driver"]["handle"]]

        def screen(i):
            x, y = _xy(handle, i)
            return page.evaluate("([x, y]) => { const svg = document.querySelector('svg.gk-mechanism'); "
                                 "const p = new DOMPoint(x, -y).matrixTransform(svg.getScreenCTM()); "
                                 "return [p.x, p.y]; }", [x, y])

        start = page.evaluate("window.graphkin.view.index")
        page.mouse.move(*screen(start))
        page.mouse.down()
        page.evaluate(reset)
        target = (start + s["n"] // 3) % s["n"]
        for j in range(start + 1, start + s["n"] // 3 + 1):
            page.mouse.move(*screen(j % s["n"]))
        page.mouse.up()
        drag = page.evaluate(got)
        drawn = page.evaluate(READ_BACK)
        # The nearest presolved handle to the pointer: position j, or one whose handle is as near (a drawn pixel).
        assert np.hypot(*(_xy(handle, drawn["index"]) - _xy(handle, target))) < 1e-3 * s["size"]
        check_drawn(drawn, s, drawn["index"])
        # Play, then pause: the position moves on by itself, then stays.
        page.click("[data-do=play]")
        page.wait_for_timeout(400)
        page.click("[data-do=play]")
        paused = page.evaluate("window.graphkin.view.index")
        assert paused != drawn["index"]
        page.wait_for_timeout(200)
        assert page.evaluate("window.graphkin.view.index") == paused
        # Toggles hide what they name; the polygons come back drawn for the position shown.
        page.uncheck("[data-toggle=polygons]")
        assert page.locator(".gk-polygons").is_hidden()
        page.keyboard.press("ArrowRight")
        page.check("[data-toggle=polygons]")
        check_drawn(page.evaluate(READ_BACK), s, (paused + 1) % s["n"])
        page.uncheck("[data-toggle=forces]")
        assert page.locator("svg.gk-mechanism g.gk-forces").is_hidden()
        page.check("[data-toggle=forces]")
        # Hovering a joint force reads it in polar form, by both routes.
        hovered, x, y = page.evaluate(UNCOVERED)
        f = next(f for f in s["forces"] if f["name"] == hovered)
        page.mouse.move(x, y)
        readout = page.locator(".gk-readout").text_content()
        F = _xy(f["analytical"], (paused + 1) % s["n"])
        assert readout.startswith(f"{f['name']} = ") and "analytically" in readout and "graphically" in readout
        assert f"{np.hypot(*F):.4g}" in readout.replace("−", "-")
        # The table is HTML a screen reader reads: a row per joint force and the effort.
        rows = page.locator(".gk-table tbody tr")
        assert rows.count() == len(s["forces"]) + 1
        assert errors == []
    finally:
        context.close()
    assert asked == [path.as_uri()]
    timings[f"scene page {name}"] = {"keys_update_ms": keys[0], "keys_frame_ms": keys[1], "keys_drawing_ms": keys[2],
                                     "drag_update_ms": drag[0], "drag_frame_ms": drag[1], "drag_drawing_ms": drag[2],
                                     "first_frame_ms": first, "page_mb": size_mb}
    print(f"\n{name}: page {size_mb:.2f} MB, first frame drawn {first:.0f} ms after the page's start")
    for what, t in (("arrow key", keys), ("drag move", drag)):
        print(f"  {what} → SVG updated: {_ms(t[0])}; → next frame: {_ms(t[1])}; the drawing alone: {_ms(t[2])} "
              f"({len(t[0])} events)")


def test_a_position_the_linkage_cannot_reach_shows_why(browser, tmp_path):
    path = tmp_path / "toggle.html"
    s = scene(toggle_fourbar(), 36)
    write_page(s, path)
    i = next(e["index"] for e in s["invalid"])
    context, page, asked, errors = _open(browser, path)
    try:
        page.locator("[data-do=position]").fill(str(i))
        reason = page.locator("svg.gk-mechanism .gk-reason").text_content()
        assert reason.startswith("Not reachable: ") and "cannot be assembled" in reason
        assert page.locator("svg.gk-mechanism [data-link]").first.is_hidden()
        assert page.locator("svg.gk-mechanism g.gk-arrow:visible").count() == 0
        cells = page.locator(".gk-table tbody td")
        assert {cells.nth(k).text_content() for k in range(cells.count())} == {"—"}
        ok = s["valid"].index(1)
        page.locator("[data-do=position]").fill(str(ok))
        assert page.locator("svg.gk-mechanism .gk-reason").text_content() == ""
        check_drawn(page.evaluate(READ_BACK), json.loads(scene_json(s)), ok)
        assert errors == []
    finally:
        context.close()
    assert asked == [path.as_uri()]


MOVES = """([points, wait]) => new Promise((done) => {
  // Pointer moves as Chromium reports them at once ("pointerrawupdate"), all in one task: the position drawn after
  // each, then the one drawn at the next frame. The page's clock is the test's: each drawing takes `wait` ms of it
  // (the position's text, which every drawing writes, advances it), whatever the machine's load makes of the real
  // drawing's time, so which moves the budget holds back is decided by `wait` alone.
  const svg = document.querySelector("svg.gk-mechanism");
  const view = window.graphkin.view;
  const M = svg.getScreenCTM();
  let clock = 0;
  const now = performance.now;
  performance.now = () => clock;
  const where = document.querySelector("[data-do=where]");
  const own = Object.getOwnPropertyDescriptor(Node.prototype, "textContent");
  Object.defineProperty(where, "textContent", { configurable: true, set(v) {
    clock += wait;
    own.set.call(this, v);
  } });
  const shown = points.map(([x, y]) => {
    const p = new DOMPoint(x, -y).matrixTransform(M);
    svg.dispatchEvent(new PointerEvent("pointerrawupdate", {clientX: p.x, clientY: p.y, pointerId: 1,
      pointerType: "mouse", bubbles: true}));
    return view.index;
  });
  requestAnimationFrame(() => {
    const index = view.index;  // the move held for the frame is drawn in the page's own callback, before this one
    performance.now = now;
    delete where.textContent;
    done([shown, index]);
  });
})"""


def test_a_drag_move_is_drawn_when_it_comes_and_a_frame_holds_a_bounded_drawing(browser, tmp_path):
    """Chromium holds "pointermove" back to the next frame; the drag draws on "pointerrawupdate", in its handler.
    Moves that come faster than the frames are drawn at once up to a budget of the frame's time, the last of the
    rest at the frame."""
    path = tmp_path / "strip_cutter.html"
    assert main(["explore", "strip_cutter", "-o", str(path), "--n", "36"]) == 0
    context, page, asked, errors = _open(browser, path)
    try:
        s = _scene_of(page)
        handle = next(lk for lk in s["links"] if lk["number"] == s["driver"]["link"])["points"][s["driver"]["handle"]]
        start = page.evaluate("window.graphkin.view.index")
        x, y = page.evaluate(
            "([x, y]) => { const p = new DOMPoint(x, -y).matrixTransform("
            "document.querySelector('svg.gk-mechanism').getScreenCTM()); return [p.x, p.y]; }",
            _xy(handle, start).tolist())
        page.mouse.move(x, y)
        page.mouse.down()
        targets = [(start + k) % s["n"] for k in range(1, 4)]
        shown, _ = page.evaluate(MOVES, [[_xy(handle, j).tolist() for j in targets], 0])
        assert shown == targets  # each drawn in its own handler, none waiting for a frame
        check_drawn(page.evaluate(READ_BACK), s, targets[-1])
        # Moves whose drawing takes the frame's budget: the first drawn at once, the last at the frame.
        more = [(targets[-1] + k) % s["n"] for k in range(1, 6)]
        shown, framed = page.evaluate(MOVES, [[_xy(handle, j).tolist() for j in more], 4])
        assert shown[:2] == more[:2] and shown[2:] == [more[1]] * 3  # 8 ms spent: the rest held
        assert framed == more[-1]
        check_drawn(page.evaluate(READ_BACK), s, more[-1])
        page.mouse.up()
        assert errors == []
    finally:
        context.close()
    assert asked == [path.as_uri()]
