"""``graphkin handout … -o key.html``: an HTML key carries the figure a student moves; a sheet never does."""

from __future__ import annotations

import json
import re

import pytest

from graphkin import catalog, exercises
from graphkin.cli import main
from graphkin.scene import scene, scene_json

SCENE = re.compile(r'<script type="application/json" id="graphkin-scene">(.*?)</script>', re.S)


def _written(capsys, tmp_path, *argv) -> str:
    path = tmp_path / "out.html"
    assert main(["handout", *argv, "-o", str(path)]) == 0, capsys.readouterr().err
    return path.read_text(encoding="utf-8")


def test_a_problems_key_moves_and_is_the_problems_scene(capsys, tmp_path):
    page = _written(capsys, tmp_path, "slider_crank_dynamic_makdin")
    found = SCENE.search(page)
    assert found, "the key has no moving figure"
    assert json.loads(found.group(1)) == json.loads(scene_json(scene(catalog.load("slider_crank_dynamic_makdin"))))


@pytest.mark.parametrize("argv", [
    ["slider_crank_dynamic_makdin", "--blank"],  # a worksheet: the forces are the student's to find
    ["double_slider_graphical", "--student", "s1", "--secret", "x"],  # a student's sheet
])
def test_a_sheet_has_no_moving_figure(capsys, tmp_path, argv):
    page = _written(capsys, tmp_path, *argv)
    assert not SCENE.search(page) and "<script" not in page


def test_a_students_key_moves_their_own_variant(capsys, tmp_path):
    page = _written(capsys, tmp_path, "double_slider_graphical", "--student", "s1", "--secret", "x", "--key")
    mine = exercises.variant("double_slider_graphical", "s1", "x").problem
    assert json.loads(SCENE.search(page).group(1)) == json.loads(scene_json(scene(mine)))
