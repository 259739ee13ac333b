"""Every lesson, new ones too: its jupytext source and its notebook agree, it is short, and it reads without asserts.

Issue 27: a lesson holds about 1,500 words of prose at most (markdown cells only); the checks that keep
its numbers right sit in the tests or in one hidden check cell per section, tagged ``remove-input``, never
as asserts in the cells a student reads.

The cells a student reads (code cells not tagged ``remove-input``) are short and use the public library only:

* **Short**: at most :data:`CODE_LINES` lines each, not counting blank lines nor the lines inside a
  multi-line string literal (the text of a file a teacher would write, such as an exercise's TOML, shown as
  it sits in the file; it counts as the one line that opens it). Lessons 01–05 need at most 6; two more leave
  room for a small table.
* **Public only**: graphkin is imported as ``import graphkin as gk`` and nothing else (no
  ``from graphkin... import``, no ``import graphkin.x``); every name reached from ``gk`` is public: ``gk.A``
  has ``A`` in ``graphkin.__all__``, and where ``gk.A`` (or ``gk.A.B``) is a module the next name is in that
  module's ``__all__`` (``gk.exercises.grade``, not ``gk.exercises.quantities.value_of``), or, for a module
  without ``__all__``, has no leading underscore; and no attribute anywhere is ``_private`` (a single
  leading underscore).
"""

from __future__ import annotations

import ast
import io
import re
import tokenize
import types
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
CODE_LINES = 8


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


def _visible_code(nb):
    return [(k + 1, c.source) for k, c in enumerate(nb.cells)
            if c.cell_type == "code" and HIDDEN not in c.metadata.get("tags", ())]


def _python(source: str) -> str:
    """The cell as Python: an IPython magic or shell line (``%matplotlib inline``, ``!ls``) becomes ``pass``."""
    return "\n".join(re.sub(r"^(\s*)[%!].*", r"\1pass", line) for line in source.splitlines())


def _code_lines(source: str) -> int:
    """Non-blank lines, a multi-line string literal counting as the one line that opens it."""
    inside = set()
    for tok in tokenize.generate_tokens(io.StringIO(_python(source)).readline):
        if tok.type == tokenize.STRING or getattr(tokenize, "FSTRING_START", None) == tok.type:
            inside.update(range(tok.start[0] + 1, tok.end[0] + 1))
    return sum(1 for n, line in enumerate(source.splitlines(), 1) if line.strip() and n not in inside)


def _not_public(source: str) -> list[str]:
    """What a cell reaches in graphkin beyond its public names (see the module's docstring)."""
    import graphkin

    bad = []
    tree = ast.parse(_python(source))
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and (node.module or "").split(".")[0] == "graphkin":
            bad.append(f"from {node.module} import ...")
        elif isinstance(node, ast.Import):
            bad += [f"import {a.name}" for a in node.names
                    if a.name.split(".")[0] == "graphkin" and (a.name, a.asname) != ("graphkin", "gk")]
        elif isinstance(node, ast.Attribute) and re.match(r"_[^_]", node.attr):
            bad.append(f".{node.attr}")
    for node in ast.walk(tree):
        chain = []
        while isinstance(node, ast.Attribute):
            chain.append(node.attr)
            node = node.value
        if not (isinstance(node, ast.Name) and node.id == "gk" and chain):
            continue
        where, reached = graphkin, "gk"
        for name in reversed(chain):
            if not isinstance(where, types.ModuleType):
                break
            public = where.__all__ if hasattr(where, "__all__") else [n for n in dir(where) if not n.startswith("_")]
            if name not in public:
                bad.append(f"{reached}.{name}")
                break
            where, reached = getattr(where, name), f"{reached}.{name}"
    return sorted(set(bad))


@pytest.mark.parametrize("source", SOURCES, ids=[p.stem for p in SOURCES])
def test_visible_code_cells_are_short(source):
    long = [(k, n) for k, src in _visible_code(jupytext.read(source)) if (n := _code_lines(src)) > CODE_LINES]
    assert not long, f"{source.name}: visible code cells longer than {CODE_LINES} lines (cell, lines): {long}"


@pytest.mark.parametrize("source", SOURCES, ids=[p.stem for p in SOURCES])
def test_visible_code_cells_use_the_public_library_only(source):
    found = {k: bad for k, src in _visible_code(jupytext.read(source)) if (bad := _not_public(src))}
    assert not found, f"{source.name}: library internals in the reading path (cell: names): {found}"


def test_the_code_rules_catch_what_they_are_for():
    assert _code_lines('%matplotlib inline\n\nX = """\na\nb\n"""\ny = f"""{X}\n"""\n') == 3
    assert _not_public("import graphkin as gk\ngk.exercises.grade(1)\ngk.draw.draw_grades(r).savefig('a')") == []
    assert _not_public("from graphkin.exercises.quantities import value_of") == [
        "from graphkin.exercises.quantities import ..."]
    assert _not_public("import graphkin.draw\nimport graphkin") == ["import graphkin", "import graphkin.draw"]
    assert _not_public("gk.exercises.quantities.value_of(v, q)") == ["gk.exercises.quantities"]
    assert _not_public("v._memo\ngk._LATER") == ["._LATER", "._memo", "gk._LATER"]
