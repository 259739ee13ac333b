"""docs/lesson_cache.py: a lesson's kept outputs are thrown away exactly when what they depend on changed."""

from __future__ import annotations

import pytest
from lesson_cache import source_digest


@pytest.fixture
def root(tmp_path):
    (tmp_path / "graphkin" / "draw").mkdir(parents=True)
    (tmp_path / "graphkin" / "draw" / "axes.py").write_text("SCALE = 1\n")
    (tmp_path / "graphkin" / "catalog").mkdir()
    (tmp_path / "graphkin" / "catalog" / "double_slider.toml").write_text('title = "double slider"\n')
    (tmp_path / "lessons").mkdir()
    (tmp_path / "lessons" / "01_newtonian_method.ipynb").write_text("{}")
    (tmp_path / "lessons" / "01_newtonian_method.py").write_text("# %%\n")
    (tmp_path / "lessons" / "bar.csv").write_text("1,2\n")
    (tmp_path / "pyproject.toml").write_text('[project]\nname = "graphkin"\n')
    return tmp_path


@pytest.mark.parametrize("path, text", [
    ("graphkin/draw/axes.py", "SCALE = 2\n"),  # graphkin's code
    ("graphkin/catalog/double_slider.toml", 'title = "the double slider"\n'),  # a problem a lesson loads
    ("graphkin/draw/new.py", ""),  # a file added
    ("lessons/bar.csv", "1,3\n"),  # a file a lesson reads
    ("lessons/helpers.py", "def f(): pass\n"),  # a module a lesson imports (no notebook of its own)
    ("pyproject.toml", '[project]\nname = "graphkin"\ndependencies = ["numpy>=2"]\n'),
])
def test_what_a_lesson_s_outputs_depend_on_changes_the_digest(root, path, text):
    before = source_digest(root)
    (root / path).write_text(text)
    assert source_digest(root) != before


@pytest.mark.parametrize("path", ["lessons/01_newtonian_method.ipynb", "lessons/01_newtonian_method.py",
                                  "graphkin/draw/__pycache__/axes.cpython-311.pyc"])
def test_the_lesson_itself_and_bytecode_do_not(root, path):
    """A lesson's own code is jupyter-cache's to compare (the other lessons stay cached); bytecode is no change."""
    before = source_digest(root)
    (root / path).parent.mkdir(exist_ok=True)
    (root / path).write_text("changed")
    assert source_digest(root) == before
