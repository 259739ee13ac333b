"""The animation's web page in a real browser with the network off: it plays, pauses and steps, and asks for nothing."""

from __future__ import annotations

import time

from graphkin import catalog, draw


def test_page_plays_offline_and_loads_nothing(browser, tmp_path):
    film = draw.animate(catalog.load("strip_cutter"), tmp_path / "cutter.html", frames=6, fps=20, dpi=30)
    anim_requests = []
    context = browser.new_context(offline=True)
    try:
        page = context.new_page()
        page.on("request", lambda r: anim_requests.append(r.url))
        errors = []
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto((tmp_path / "cutter.html").as_uri())
        count = page.locator("[data-do=count]")
        seen = set()
        end = time.monotonic() + 5.0
        while len(seen) < 3 and time.monotonic() < end:  # playing: the frame counter moves on by itself
            seen.add(count.text_content())
            page.wait_for_timeout(30)
        assert len(seen) >= 3, seen
        page.click("[data-do=play]")  # pause
        paused = count.text_content()
        page.wait_for_timeout(300)
        assert count.text_content() == paused
        page.click("[data-do=next]")
        k = int(paused.split(" / ")[0])
        assert count.text_content() == f"{k % 6 + 1} / 6"
        src = page.locator("img").get_attribute("src")
        assert src.startswith("data:image/png;base64,")
        assert errors == []
    finally:
        context.close()
    assert len(film.frames) == 6
    # The page itself, then only the frames it holds: nothing from the network, nothing from the disk.
    assert anim_requests[0].startswith("file://")
    assert all(u.startswith("data:") for u in anim_requests[1:]), anim_requests
