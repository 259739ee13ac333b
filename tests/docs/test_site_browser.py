"""The built documentation site's explorers drawn in Chromium with the network off (issue 37, item 7).

``make docs`` runs these on the site it has just built, as it runs test_site.py; they need Playwright's Python
package and Debian's Chromium (``make e2e`` installs both, and ``.ci/run`` runs it before ``make docs``): without
them they are skipped with the reason. Every request a page makes to anything but a file of the site is refused,
so a page that needs the network shows nothing and fails here.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import pytest
from offline import SCENES

SITE = os.environ.get("GRAPHKIN_DOCS_SITE")
CHROMIUM = os.environ.get("GRAPHKIN_CHROMIUM", "/usr/bin/chromium")
pytestmark = pytest.mark.skipif(not SITE, reason="make docs builds the site and runs these on it")

DRAWN = "() => !!document.querySelector('svg.gk-mechanism') && window.graphkin && window.graphkin.view"
INDEX = "() => window.graphkin.view.index"


@pytest.fixture(scope="module")
def browser():
    playwright = pytest.importorskip("playwright.sync_api", reason="make e2e installs Playwright's package")
    if not os.path.exists(CHROMIUM):
        pytest.skip(f"no Chromium at {CHROMIUM} (make e2e installs it)")
    with playwright.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=["--no-sandbox"])
        yield b
        b.close()


@pytest.fixture()
def page(browser):
    context = browser.new_context(viewport={"width": 1200, "height": 900})
    refused = []

    def only_the_site(route):
        url = route.request.url
        if url.startswith("file://"):
            route.continue_()
        else:
            refused.append(url)
            route.abort()

    context.route("**/*", only_the_site)
    pg = context.new_page()
    errors = []
    pg.on("pageerror", lambda e: errors.append(str(e)))
    yield pg
    context.close()
    assert not errors, errors
    assert not refused, f"the page asked the network for {refused}"


def _scene_frame(page, name: str = ""):
    """The frame of the page's explorer ``name`` (any explorer without one), scrolled to (a frame loads lazily) and
    loaded: waited for as a reader waits, up to 10 s."""
    page.locator(f'iframe[src*="{SCENES}/{name}"]').first.scroll_into_view_if_needed()
    for _ in range(100):
        frame = next((f for f in page.frames if f"/{SCENES}/{name}" in f.url), None)
        if frame is not None:
            return frame
        page.wait_for_timeout(100)
    raise AssertionError(f"the explorer {name or ''} did not load")


def _moves_with_a_key(frame):
    """The scene drawn in ``frame``, and one arrow key steps it to the next presolved position."""
    frame.wait_for_function(DRAWN, timeout=30_000)
    n = frame.evaluate("() => window.graphkin.view.scene.n")
    start = frame.evaluate(INDEX)
    frame.locator("svg.gk-mechanism").first.click()
    frame.locator("body").press("ArrowRight")
    frame.wait_for_function(f"() => window.graphkin.view.index === {(start + 1) % n}", timeout=10_000)


def test_a_lesson_s_explorer_draws_and_moves_offline(page):
    page.goto((Path(SITE).resolve() / "lessons" / "03_full_cycle.html").as_uri())
    _moves_with_a_key(_scene_frame(page))


def test_each_catalog_problem_s_explorer_draws_and_moves_offline(page):
    page.goto((Path(SITE).resolve() / "docs" / "catalog.html").as_uri())
    names = re.findall(rf"{SCENES}/([a-z0-9_]+)\.html", " ".join(
        page.eval_on_selector_all("iframe", "fs => fs.map(f => f.getAttribute('src'))")))
    assert len(names) > 20
    for name in names:
        _moves_with_a_key(_scene_frame(page, f"{name}.html"))


def test_each_practice_page_draws_offline_and_says_no_grade_is_recorded(page):
    """Issue 38, item 4: the docs site offers the drawn exercises as self-check; a Check with nothing drawn says it
    is not finished and that no grade is recorded."""
    page.goto((Path(SITE).resolve() / "docs" / "exercises.html").as_uri())
    names = re.findall(rf"{SCENES}/practice-([a-z0-9_]+)\.html", " ".join(
        page.eval_on_selector_all("iframe", "fs => fs.map(f => f.getAttribute('src'))")))
    assert sorted(names) == ["draw_shaper_polygons", "draw_strip_cutter"]
    for name in names:
        frame = _scene_frame(page, f"practice-{name}.html")
        frame.wait_for_function("() => window.graphkin && window.graphkin.views.length > 0", timeout=30_000)
        n = frame.evaluate("() => window.graphkin.views.length")
        assert n == frame.evaluate("() => window.graphkin.tasks.filter(t => t.check).length") >= 2
        first = frame.locator("section").first
        first.locator("[data-do=check]").click()
        assert "no grade is recorded" in first.inner_text()
