"""An HTML handout with the figure a student moves (issue 37, item 2): the scene inlined beside the figure printed to
scale, at the position worked out, and nothing fetched."""

from __future__ import annotations

import json
import math
import re
from html.parser import HTMLParser

import pytest

import graphkin as gk
from graphkin import handout
from graphkin.handout.html import render
from graphkin.scene import scene


class _Tags(HTMLParser):
    def __init__(self):
        super().__init__()
        self.tags, self.attrs, self.scripts, self._in = [], [], [], None

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        self.attrs += [k for k, _ in attrs]
        if tag == "script":
            self._in = dict(attrs)
            self.scripts.append([self._in, ""])

    def handle_endtag(self, tag):
        if tag == "script":
            self._in = None

    def handle_data(self, data):
        if self._in is not None:
            self.scripts[-1][1] += data


@pytest.fixture(scope="module")
def cutter():
    doc = handout.build("strip_cutter")
    s = scene(gk.load("strip_cutter"), 72, polygons=False)
    return doc, s, render({**doc, "scene": s})


def test_the_scene_is_inlined_after_the_first_figure_printed_to_scale(cutter):
    doc, s, page = cutter
    parsed = _Tags()
    parsed.feed(page)
    assert {"link", "iframe", "img", "object", "embed"}.isdisjoint(parsed.tags) and "src" not in parsed.attrs
    kinds = [a.get("type") for a, _ in parsed.scripts]
    assert kinds == ["application/json", "module"]
    assert json.loads(parsed.scripts[0][1]) == json.loads(gk.scene.scene_json(s))
    first = next(b for b in doc["blocks"] if b["kind"] == "figure" and all(p.natural for p in b["pictures"]))
    # The moving figure follows the printed one (its caption names it) and comes before the next figure.
    live = page.index('<figure class="live">')
    assert page.rindex(first["label"] + ". ", 0, live) < live < page.index("Figure 2. ")
    assert f"{first['label']}, moving" in page[live:live + 400]
    printed = page[page.index("@media print {"):]
    assert "figure.live { display: none; }" in printed[:printed.index("} }\n") + 3]  # left out on paper


def test_it_opens_at_the_position_worked_out(cutter):
    doc, s, page = cutter
    k = int(re.search(r"window\.graphkin\.view\.show\((\d+)\)", page)[1])
    q = doc["worked"][0]["q"]
    gaps = [abs(math.remainder(x - q, 2 * math.pi)) for x in s["input"]["values"]]
    assert gaps[k] == min(gaps)


def test_a_handout_without_a_scene_has_no_script():
    page = render(handout.build("double_slider"))
    parsed = _Tags()
    parsed.feed(page)
    assert "script" not in parsed.tags and "figure.live" in page  # the print rule only
