"""An HTML handout with the figure a student moves, in a real browser from disk with the network off (issue 37,
item 2): what is drawn is the scene at the position worked out, the keys and the drag move it, and nothing is
fetched."""

from __future__ import annotations

import math

from graphkin import catalog, handout
from graphkin.scene import scene
from tests.e2e.test_scene_page import READ_BACK, _open, _scene_of, _xy, check_drawn


def test_the_handouts_moving_figure_draws_the_scene_offline(browser, tmp_path):
    path = tmp_path / "cutter.html"
    doc = handout.build("strip_cutter")
    handout.write({**doc, "scene": scene(catalog.load("strip_cutter"), 72)}, path)
    context, page, asked, errors = _open(browser, path)
    try:
        s = _scene_of(page)
        start = page.evaluate("window.graphkin.view.index")
        # The position worked out (θ = 40°), within half a step of the 72.
        assert abs(math.remainder(s["input"]["values"][start] - doc["worked"][0]["q"], 2 * math.pi)) <= math.pi / 72
        check_drawn(page.evaluate(READ_BACK), s, start)
        # The arrow keys are the figure's once it is clicked; elsewhere they scroll the handout.
        page.keyboard.press("ArrowRight")
        assert page.evaluate("window.graphkin.view.index") == start
        page.focus("#graphkin")
        page.keyboard.press("ArrowRight")
        check_drawn(page.evaluate(READ_BACK), s, (start + 1) % s["n"])
        # Dragging the crank's handle on the drawing.
        handle = next(lk for lk in s["links"] if lk["number"] == s["driver"]["link"])["points"][s["driver"]["handle"]]

        def screen(i):
            return page.evaluate("([x, y]) => { const p = new DOMPoint(x, -y).matrixTransform("
                                 "document.querySelector('svg.gk-mechanism').getScreenCTM()); return [p.x, p.y]; }",
                                 _xy(handle, i).tolist())

        page.locator("svg.gk-mechanism").scroll_into_view_if_needed()
        page.mouse.move(*screen((start + 1) % s["n"]))
        page.mouse.down()
        for j in range(start + 2, start + 12):
            page.mouse.move(*screen(j % s["n"]))
        page.mouse.up()
        check_drawn(page.evaluate(READ_BACK), s, (start + 11) % s["n"])
        assert errors == []
    finally:
        context.close()
    assert asked == [path.as_uri()]
