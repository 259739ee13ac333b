"""Every lesson, new ones too: its jupytext source and its notebook agree, it is short, and it reads without asserts.

Issue 27: a lesson holds about 1,500 words of prose at most (markdown cells only); the checks that keep
its numbers right sit in the tests or in one hidden check cell per section, tagged ``remove-input``, never
as asserts in the cells a student reads.
"""

from __future__ import annotations

import re
from pathlib import Path

import jupytext
import nbformat
import pytest

LESSONS = Path(__file__).resolve().parents[2] / "lessons"
SOURCES = sorted(LESSONS.glob("[0-9][0-9]_*.py"))
NOTEBOOKS = sorted(LESSONS.glob("[0-9][0-9]_*.ipynb"))
WORD_LIMIT = 1500
HIDDEN = "remove-input"
ASSERT = re.compile(r"^\s*assert\b", re.M)


def _cells(nb) -> list[tuple[str, str, tuple[str, ...]]]:
    return [(c.cell_type, c.source.strip(), tuple(c.metadata.get("tags", ()))) for c in nb.cells]


def test_every_notebook_has_its_source_and_back():
    assert [p.stem for p in SOURCES] == [p.stem for p in NOTEBOOKS]
    assert len(SOURCES) >= 7


@pytest.mark.parametrize("source", SOURCES, ids=[p.stem for p in SOURCES])
def test_source_and_notebook_hold_the_same_cells(source):
    from_py = _cells(jupytext.read(source))
    from_ipynb = _cells(nbformat.read(source.with_suffix(".ipynb"), as_version=4))
    assert len(from_py) == len(from_ipynb), "run jupytext --sync on the .py"
    for k, (a, b) in enumerate(zip(from_py, from_ipynb, strict=True)):
        assert a == b, f"cell {k + 1} differs between {source.name} and its notebook: run jupytext --sync"


def _prose_words(nb) -> int:
    return sum(len(c.source.split()) for c in nb.cells if c.cell_type == "markdown")


def _sections(nb):
    """The cells under each level-2 heading (the cells before the first one are a section of their own)."""
    sections = [[]]
    for c in nb.cells:
        if c.cell_type == "markdown" and re.search(r"^## ", c.source, re.M):
            sections.append([])
        sections[-1].append(c)
    return sections


@pytest.mark.parametrize("source", SOURCES, ids=[p.stem for p in SOURCES])
def test_prose_is_at_most_the_limit(source):
    words = _prose_words(jupytext.read(source))
    assert words <= WORD_LIMIT, f"{source.name}: {words} words of prose, more than {WORD_LIMIT}"


@pytest.mark.parametrize("source", SOURCES, ids=[p.stem for p in SOURCES])
def test_asserts_only_in_one_hidden_check_cell_per_section(source):
    nb = jupytext.read(source)
    visible = [k + 1 for k, c in enumerate(nb.cells)
               if c.cell_type == "code" and ASSERT.search(c.source) and HIDDEN not in c.metadata.get("tags", ())]
    assert not visible, f"{source.name}: asserts in the reading path, cells {visible}"
    for section in _sections(nb):
        hidden = [c for c in section if c.cell_type == "code" and HIDDEN in c.metadata.get("tags", ())]
        assert len(hidden) <= 1, f"{source.name}: {len(hidden)} hidden check cells in one section"


def test_the_rules_catch_what_they_are_for():
    nb = jupytext.reads("# %% [markdown]\n# ## A\n\n# %%\nassert 1\n\n# %% tags=[\"remove-input\"]\nassert 2\n\n"
                        "# %% [markdown]\n# Text first.\n#\n# ## B\n", fmt="py:percent")
    assert [c.metadata.get("tags", []) for c in nb.cells] == [[], [], [HIDDEN], []]
    assert ASSERT.search(nb.cells[1].source) and not ASSERT.search("x = 'assert'")
    assert [len(s) for s in _sections(nb)] == [0, 3, 1]  # a heading below text still opens a section
    assert _prose_words(nb) == 6


@pytest.mark.parametrize("source", SOURCES, ids=[p.stem for p in SOURCES])
def test_no_empty_cells(source):
    """An empty code cell gets no prompt number in JupyterLab, so a student's Shift+Enter seems to hang on it."""
    empty = [k + 1 for k, c in enumerate(jupytext.read(source).cells) if not c.source.strip()]
    assert not empty, f"{source.name}: empty cells {empty} (two blank lines after a cell marker make one)"
