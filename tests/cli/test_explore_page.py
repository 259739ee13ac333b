"""``graphkin explore PROBLEM -o page.html``: one self-contained page of the presolved cycle, written atomically."""

from __future__ import annotations

import json
import re

from graphkin import catalog
from graphkin.cli import main
from graphkin.scene import scene, scene_json


def run(capsys, *argv):
    code = main(["explore", *map(str, argv)])
    out, err = capsys.readouterr()
    return code, out, err


def _scene_in(text: str) -> dict:
    found = re.search(r'<script type="application/json" id="graphkin-scene">(.*?)</script>', text, re.S)
    return json.loads(found.group(1))


def test_the_page_holds_the_scene_and_the_module_and_nothing_to_fetch(capsys, tmp_path):
    path = tmp_path / "cutter.html"
    code, out, err = run(capsys, "strip_cutter", "-o", path, "--n", 36)
    assert code == 0 and out == ""
    assert err.count("\n") == 1 and str(path) in err and "40 positions" in err
    text = path.read_text(encoding="utf-8")
    assert _scene_in(text) == json.loads(scene_json(scene(catalog.load("strip_cutter"), 36)))
    assert "export function draw(" in text and '<script type="module">' in text
    # Nothing the browser would fetch: no source or link attribute, no URL but the SVG namespace's name.
    assert not re.search(r"\b(src|href)=", text)
    assert set(re.findall(r"https?://[^\s\"'`]+", text)) == {"http://www.w3.org/2000/svg"}


def test_a_title_cannot_close_the_scene_element(tmp_path, capsys):
    problem = tmp_path / "p.toml"
    text = catalog.path("double_slider").read_text(encoding="utf-8")
    assert re.search(r'^title = ".*"$', text, re.M)
    problem.write_text(re.sub(r'^title = ".*"$', 'title = "</script><script>alert(1)</script>"', text, count=1,
                              flags=re.M), encoding="utf-8")
    path = tmp_path / "page.html"
    code, _, _ = run(capsys, problem, "-o", path)
    assert code == 0
    page = path.read_text(encoding="utf-8")
    assert "<script>alert(1)" not in page
    assert _scene_in(page)["title"] == "</script><script>alert(1)</script>"


def test_without_polygons_the_page_is_smaller(capsys, tmp_path):
    full, bare = tmp_path / "full.html", tmp_path / "bare.html"
    assert run(capsys, "strip_cutter", "-o", full, "--n", 36)[0] == 0
    assert run(capsys, "strip_cutter", "-o", bare, "--n", 36, "--no-polygons")[0] == 0
    assert _scene_in(bare.read_text(encoding="utf-8"))["graphical"] is None
    assert bare.stat().st_size < full.stat().st_size


def test_mistakes_are_one_line_and_leave_the_old_file(capsys, tmp_path):
    path = tmp_path / "page.html"
    path.write_text("old", encoding="utf-8")
    code, out, err = run(capsys, "strip_cutter", "-o", path, "--n", 1)
    assert code == 2 and "n must be a whole number" in err and path.read_text(encoding="utf-8") == "old"
    assert list(tmp_path.iterdir()) == [path]  # no temporary file left beside it
    code, _, err = run(capsys, "strip_cutter", "-o", tmp_path)
    assert code == 2 and "is a folder, not a file" in err
    code, _, err = run(capsys, "strip_cutter", "--n", 36)
    assert code == 2 and "--n, --no-polygons, --motion and --units go with -o" in err
    code, _, err = run(capsys, "strip_cutter", "-o", path, "--units", "furlongs")
    assert code == 2 and "--units 'furlongs'" in err and path.read_text(encoding="utf-8") == "old"


def test_the_motion_polygons_and_the_books_units_on_the_page(capsys, tmp_path):
    from graphkin.units.systems import unit_system

    path = tmp_path / "crank.html"
    code, _, _ = run(capsys, "slider_crank_dynamic_makdin", "-o", path, "--n", 12, "--motion", "--units", "US")
    assert code == 0
    expected = scene(catalog.load("slider_crank_dynamic_makdin"), 12, motion=True, units=unit_system("US"))
    assert _scene_in(path.read_text(encoding="utf-8")) == json.loads(scene_json(expected))
    assert expected["motion"] is not None and expected["book"] != scene(catalog.load("slider_crank_dynamic_makdin"), 12)["book"]


def test_a_base_url_that_is_not_a_path_is_one_line(capsys):
    """`graphkin explore --base-url` (behind a hub's proxy) takes a plain path; nothing is started for another."""
    import pytest

    pytest.importorskip("voila")
    for bad in ("/user/ada/../admin/", "/a b/", "http://elsewhere/x"):
        code, out, err = run(capsys, "strip_cutter", "--no-browser", "--base-url", bad)
        assert code == 2 and out == "" and err.count("\n") == 1 and "--base-url must be a path" in err, err
