"""docs/offline.py: what a page fetches from another host is found, a widget is drawn from its saved state, and an
explorer is matched to the catalog problem it explores only when the lesson's code says so plainly."""

from __future__ import annotations

import base64

import pytest
from offline import explored_problem, explored_problems, external_references, is_explorer, scene_frame, static_widget

# -- what a page fetches ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("tag", [
    '<script src="https://cdn.jsdelivr.net/npm/x/embed-amd.js"></script>',
    '<script src="//cdnjs.cloudflare.com/require.js"></script>',
    '<link rel="stylesheet" href="https://fonts.googleapis.com/css?family=Lato">',
    '<link rel="preload" as="font" href="https://example.org/a.woff2">',
    '<link rel="icon" href="http://example.org/favicon.ico">',
    '<img src="https://raw.githubusercontent.com/graphkin/graphkin/main/figures/double_slider.png">',
    '<img srcset="a.png 1x, https://example.org/b.png 2x">',
    '<iframe src="https://example.org/app"></iframe>',
    '<video poster="https://example.org/p.png"></video>',
    '<div style="background: url(https://example.org/bg.png)"></div>',
    "<style>@import 'https://example.org/x.css';</style>",
    "<style>@font-face { src: url(\"https://example.org/f.woff2\") }</style>",
])
def test_a_resource_from_another_host_is_found(tag):
    found = external_references(f"<html><head></head><body>{tag}</body></html>")
    assert len(found) == 1 and found[0][1].replace('"', "") in tag.replace('"', "")


@pytest.mark.parametrize("tag", [
    '<script src="../_static/doctools.js"></script>',
    '<link rel="stylesheet" href="_static/styles/theme.css">',
    '<img src="data:image/png;base64,iVBORw0KGgo=">',
    '<iframe src="../_scenes/strip_cutter.html"></iframe>',
    '<a href="https://github.com/graphkin/graphkin">a link is followed by a person, not fetched</a>',
    '<link rel="canonical" href="https://example.org/page.html">',
    '<div style="background: url(_static/bg.png)"></div>',
])
def test_what_the_site_holds_and_plain_links_are_not(tag):
    assert external_references(f"<body>{tag}</body>") == []


def test_a_style_sheet_s_imports_and_urls():
    css = ("@import \"../basic.css\"; @import url(//fonts.example.org/a.css);\n"
           "@font-face { src: url(../vendor/fa.woff2) format('woff2'), url('https://example.org/f.woff') }\n"
           "a { background: url(\"data:image/svg+xml;charset=utf-8,%3Csvg xmlns='http://www.w3.org/2000/svg'%3E\") }")
    assert external_references(css, css=True) == [("css", "//fonts.example.org/a.css"),
                                                   ("css", "https://example.org/f.woff")]


# -- a widget from its saved state ----------------------------------------------------------------------------------

PNG = base64.b64encode(b"\x89PNG\r\n\x1a\n" + b"\0" * 8).decode()


def _box():
    """An exercise box's and an explorer's widgets, as ipywidgets saves them in a notebook's metadata."""
    return {
        "root": {"model_name": "VBoxModel", "state": {"children": ["IPY_MODEL_title", "IPY_MODEL_row", "IPY_MODEL_img",
                                                                   "IPY_MODEL_probe"]}},
        "title": {"model_name": "HTMLModel", "state": {"value": "<h4>Strip cutter &amp; its torque</h4>"}},
        "row": {"model_name": "HBoxModel", "state": {"children": ["IPY_MODEL_slider", "IPY_MODEL_id", "IPY_MODEL_tick",
                                                                  "IPY_MODEL_check", "IPY_MODEL_layout"]}},
        "slider": {"model_name": "IntSliderModel", "state": {"description": "θ (deg)", "min": 0, "max": 360,
                                                             "value": 140}},
        "id": {"model_name": "TextModel", "state": {"description": "Your id", "value": 'a"b<c', "placeholder": "id"}},
        "tick": {"model_name": "CheckboxModel", "state": {"description": "polygons", "value": True}},
        "check": {"model_name": "ButtonModel", "state": {"description": "Check"}},
        "layout": {"model_name": "LayoutModel", "state": {"width": "60%"}},
        "img": {"model_name": "ImageModel", "state": {"format": "png", "_dom_classes": ["graphkin-image"]},
                "buffers": [{"path": ["value"], "data": PNG, "encoding": "base64"}]},
        "probe": {"model_name": "AnyModel", "state": {"_esm": "export default {}"}},
    }


def test_a_widget_is_drawn_as_it_was_left_with_its_controls_disabled():
    out = static_widget(_box(), "root")
    assert out.startswith('<div class="graphkin-static-widget">')
    assert "<h4>Strip cutter &amp; its torque</h4>" in out  # an HTML widget's value is its HTML
    assert '<input type="range" min="0" max="360" value="140" disabled>' in out
    assert 'value="a&quot;b&lt;c"' in out  # a text box's value is text
    assert '<input type="checkbox" checked disabled> polygons' in out
    assert "<button disabled>Check</button>" in out
    assert f'src="data:image/png;base64,{PNG}"' in out  # the figure the kernel last drew, from the state's buffers
    assert 'class="gk-hbox"' in out and "export default" not in out
    assert "the controls work when the notebook runs" in out


def test_a_widget_that_saved_nothing_to_show_says_so():
    state = {"root": {"model_name": "VBoxModel", "state": {"children": ["IPY_MODEL_gone"]}}}
    assert "saved nothing to show" in static_widget(state, "root")
    assert "saved nothing to show" not in static_widget(_box(), "root")


# -- which problem an explorer explores -----------------------------------------------------------------------------

@pytest.mark.parametrize("cells, expected", [
    (['p = gk.load("strip_cutter")', "x = 1", "ex = gk.explore(p)\nex"], "strip_cutter"),
    (['import graphkin as gk\np = gk.load("gearset")', "", "%matplotlib inline\nex_g = gk.explore(p)"], "gearset"),
    (["", "", 'gk.explore(gk.load("double_slider"))'], "double_slider"),
    (['from graphkin.widgets import explore\nproblem = catalog.load("shaper_six_bar")', "", "explore(problem)"],
     "shaper_six_bar"),
    (['p = gk.load("strip_cutter")', "p = p.with_friction(0.1)", "gk.explore(p)"], None),  # no longer the catalog's
    (['p = gk.parse_problem(text)', "", "gk.explore(p)"], None),
    (['p = gk.load(name)', "", "gk.explore(p)"], None),
    (['p = gk.load("strip_cutter")', "", "gk.explore()"], None),
    (['p = gk.load("strip_cutter")', "", "gk.explore(q)"], None),
    (['p = gk.load("strip_cutter")', "", "gk.sweep(p)"], None),
    (['p = gk.load("strip_cutter")', "", "gk.explore(p"], None),  # not Python
])
def test_the_explored_problem_is_read_from_the_code(cells, expected):
    assert explored_problem(cells, 2) == expected


def test_a_later_cell_does_not_change_what_an_earlier_one_explored():
    cells = ['p = gk.load("strip_cutter")', "gk.explore(p)", 'p = gk.load("gearset")', "gk.explore(p)"]
    assert [explored_problem(cells, i) for i in (1, 3)] == ["strip_cutter", "gearset"]


def test_a_notebook_s_explored_problems(tmp_path):
    import json

    cells = [{"cell_type": "markdown", "source": ["gk.explore(p)"]},
             {"cell_type": "code", "source": ['p = gk.load("strip_cutter")\n', "ex = gk.explore(p)"]},
             {"cell_type": "code", "source": 'g = gk.load("gearset")\ngk.explore(g)'}]
    path = tmp_path / "lesson.ipynb"
    path.write_text(json.dumps({"cells": cells}))
    assert explored_problems(path) == {"strip_cutter", "gearset"}


def test_a_scene_frame_points_at_the_site_s_scene_page_from_any_folder():
    assert 'src="../_scenes/strip_cutter.html"' in scene_frame("strip_cutter", "lessons/03_full_cycle")
    assert 'src="_scenes/gearset.html"' in scene_frame("gearset", "index")


def test_an_explorer_is_known_by_the_scene_its_widget_saved():
    """gk.explore's widget (an anywidget holding the scene's JSON) is drawn as the problem's scene page; any other
    anywidget (a probe, a plot) is drawn as it was left."""
    scene = {"model_name": "AnyModel", "state": {"_esm": "export default {}", "scene": '{"schema": 2}', "index": 3}}
    models = {**_box(), "explorer": scene, "box": {"model_name": "VBoxModel", "state": {"children": ["IPY_MODEL_explorer"]}}}
    assert is_explorer(models, "IPY_MODEL_explorer") and is_explorer(models, "box")
    assert not is_explorer(models, "root") and not is_explorer(models, "probe") and not is_explorer(models, "gone")
