"""The built documentation site is whole offline: no page, style sheet or script asks another host for anything,
every widget is drawn (no blank box), and everything a page fetches is in the site.

``make docs`` runs these on the site it has just built (``GRAPHKIN_DOCS_SITE=build/docs``); without that variable
they are skipped, so that ``make test`` does not judge whatever stale site a checkout holds.
"""

from __future__ import annotations

import os
import re
from pathlib import Path
from urllib.parse import unquote, urlsplit

import pytest
from offline import SCENES, WIDGET_VIEW, external_references, fetched

SITE = os.environ.get("GRAPHKIN_DOCS_SITE")
pytestmark = pytest.mark.skipif(not SITE, reason="make docs builds the site and runs these on it")

CDN = re.compile(r"cdn\.jsdelivr\.net|unpkg\.com|cdnjs\.cloudflare\.com|fonts\.googleapis\.com|fonts\.gstatic\.com|"
                 r"cdn\.plot\.ly|mathjax", re.I)
"""Hosts a documentation tool fetches scripts, styles and fonts from: a script naming one may fetch from it."""


@pytest.fixture(scope="module")
def site() -> Path:
    root = Path(SITE).resolve()
    assert (root / "index.html").is_file(), f"no site in {root}: make docs"
    return root


@pytest.fixture(scope="module")
def pages(site) -> dict[Path, str]:
    found = {p: p.read_text(encoding="utf-8", errors="replace") for p in sorted(site.rglob("*.html"))}
    # the theme copies a Jinja template of its own into _static: a page's source, never shown
    found = {p: text for p, text in found.items() if "{% macro" not in text}
    assert len(found) > 20
    return found


def test_no_page_fetches_from_another_host(pages, site):
    bad = {str(p.relative_to(site)): refs for p, text in pages.items() if (refs := external_references(text))}
    assert bad == {}


def test_no_style_sheet_fetches_from_another_host(site):
    sheets = sorted(site.rglob("*.css"))
    assert sheets
    bad = {str(p.relative_to(site)): refs for p in sheets
           if (refs := external_references(p.read_text(encoding="utf-8", errors="replace"), css=True))}
    assert bad == {}


def test_no_script_names_a_cdn(site, pages):
    scripts = {p: p.read_text(encoding="utf-8", errors="replace") for p in sorted(site.rglob("*.js"))}
    inline = {p: "".join(re.findall(r"<script\b[^>]*>(.*?)</script>", t, re.S | re.I)) for p, t in pages.items()}
    bad = {str(p.relative_to(site)): CDN.findall(text) for p, text in {**scripts, **inline}.items() if CDN.search(text)}
    assert bad == {}


def test_everything_a_page_fetches_is_in_the_site(pages, site):
    missing = []
    for page, text in pages.items():
        for what, url in fetched(text):
            parts = urlsplit(url)
            if parts.scheme or parts.netloc or not parts.path:  # data: URLs (others are refused above)
                continue
            target = (site / unquote(parts.path).lstrip("/")) if parts.path.startswith("/") else \
                page.parent / unquote(parts.path)
            if not target.exists():
                missing.append((str(page.relative_to(site)), what, url))
    assert missing == []


def test_every_widget_is_drawn(pages, site):
    """No output is left as a reference to a widget that only a CDN's script would draw (a blank box offline)."""
    blank = [str(p.relative_to(site)) for p, text in pages.items() if WIDGET_VIEW in text or "widget-state+json" in text]
    assert blank == []


def test_each_explorer_of_the_lessons_is_a_scene_page(pages, site):
    lessons = {p.stem: t for p, t in pages.items() if p.parent.name == "lessons"}
    frames = {name: re.findall(rf'<iframe src="\.\./{SCENES}/([a-z0-9_]+)\.html"', text) for name, text in lessons.items()}
    shown = {name: found for name, found in frames.items() if found}
    assert shown, "no lesson shows an explorer's scene page"
    for name, found in shown.items():
        for problem in found:
            page = pages[site / SCENES / f"{problem}.html"]
            assert 'id="graphkin-scene"' in page and "export default" in page, (name, problem)


def test_each_catalog_problem_s_section_shows_its_explorer(pages, site):
    """The catalog page: every problem graphkin ships has its scene page in a frame, and the page is in the site."""
    from graphkin import catalog

    text = pages[site / "docs" / "catalog.html"]
    framed = re.findall(rf'<iframe src="\.\./{SCENES}/([a-z0-9_]+)\.html"', text)
    assert sorted(framed) == sorted(catalog.names())
    for name in framed:
        page = pages[site / SCENES / f"{name}.html"]
        assert 'id="graphkin-scene"' in page and "export default" in page, name
