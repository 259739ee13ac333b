"""Every lesson, new ones too: each drawing it talks about shows when it is run, and its checks stay folded.

Issue 36 found lesson 08 blank when run: its drawing cells ended in ``;`` (which tells IPython to show
nothing) and the check figure sat inside an ``if`` (a value inside a block is never shown). A drawing shows
when the cell's last statement is the drawing itself (a :class:`graphkin.draw.axes.Drawn`, or a Figure,
shown as a PNG), or when it is kept in a name that a later cell ends on (lesson 02's ``frames[0]``).

The maintainers' checks (cells tagged ``remove-input``: the docs site leaves their source out) are folded
in JupyterLab too, by the cell metadata it honours on opening a notebook, ``"jupyter": {"source_hidden":
true}``; JupyterLab then shows the cell's first line, so in a student's lesson that line says, in words, what the
cell is. Their outputs are not collapsed: a check that passes has none, one that fails should say so where
it failed, and the teachers' lessons (06, 07) show what a hidden set-up cell prints (a class's answers).
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import jupytext
import nbformat
import pytest

LESSONS = Path(__file__).resolve().parents[2] / "lessons"
SOURCES = sorted(LESSONS.glob("[0-9][0-9]_*.py"))
FOR_STUDENTS = [p for p in SOURCES if "(for teachers)" not in p.read_text(encoding="utf-8").split("\n# # ", 1)[1]
                .splitlines()[0]]
"""The lessons but the teachers' (06, 07, whose folded cells are set-up, each opening with what it makes)."""
HIDDEN = "remove-input"
BLOCKS = (ast.If, ast.For, ast.While, ast.With, ast.Try, ast.FunctionDef, ast.ClassDef, ast.Match)


def _tree(source: str) -> ast.Module:
    """The cell as Python: an IPython magic or shell line (``%matplotlib inline``) becomes ``pass``."""
    return ast.parse("\n".join(re.sub(r"^(\s*)[%!].*", r"\1pass", line) for line in source.splitlines()))


def _draws(node) -> bool:
    """Whether ``node`` holds a call of ``gk.draw.draw_...``."""
    for call in ast.walk(node):
        f = call.func if isinstance(call, ast.Call) else None
        if (isinstance(f, ast.Attribute) and f.attr.startswith("draw_") and isinstance(f.value, ast.Attribute)
                and f.value.attr == "draw" and isinstance(f.value.value, ast.Name) and f.value.value.id == "gk"):
            return True
    return False


def _root(node) -> str | None:
    """The name an expression starts from (``frames`` of ``frames[0].figure``)."""
    while isinstance(node, (ast.Attribute, ast.Subscript, ast.Call)):
        node = node.func if isinstance(node, ast.Call) else node.value
    return node.id if isinstance(node, ast.Name) else None


def hidden_drawings(source: str, shown_later: set[str] = frozenset()) -> list[str]:
    """The drawings of a visible code cell that Run All would not show, each with why.

    ``shown_later`` are the names that a later visible cell ends on (shown there).
    """
    tree = _tree(source)
    last = len(tree.body) - 1
    found = []
    for k, stmt in enumerate(tree.body):
        if not _draws(stmt):
            continue
        if isinstance(stmt, BLOCKS):
            found.append(f"line {stmt.lineno}: a drawing inside a block is never shown")
        elif k == last and isinstance(stmt, ast.Expr):
            if source.rstrip().endswith(";"):
                found.append(f"line {stmt.lineno}: the ';' at the end hides the drawing")
        elif not (isinstance(stmt, ast.Assign) and {_root(t) for t in stmt.targets} & set(shown_later)):
            found.append(f"line {stmt.lineno}: a drawing that is not the cell's last value, nor shown later")
    return found


def _visible(nb) -> list[tuple[int, str]]:
    return [(k + 1, c.source) for k, c in enumerate(nb.cells)
            if c.cell_type == "code" and HIDDEN not in c.metadata.get("tags", ())]


def _last_value(source: str) -> str | None:
    tree = _tree(source)
    if tree.body and isinstance(tree.body[-1], ast.Expr) and not source.rstrip().endswith(";"):
        return _root(tree.body[-1].value)
    return None


@pytest.mark.parametrize("source", SOURCES, ids=[p.stem for p in SOURCES])
def test_every_drawing_is_shown(source):
    cells = _visible(jupytext.read(source))
    found = {}
    for i, (k, src) in enumerate(cells):
        later = {name for _, after in cells[i + 1:] if (name := _last_value(after))}
        if why := hidden_drawings(src, later):
            found[k] = why
    assert not found, f"{source.name}: drawings a student never sees (cell: why): {found}"


def test_the_drawing_rule_catches_what_it_is_for():
    assert hidden_drawings("gk.draw.draw_mechanism(c)") == []
    assert hidden_drawings("%matplotlib inline\ngk.draw.draw_mechanism(c).figure") == []
    assert hidden_drawings("gk.draw.draw_mechanism(c);") == ["line 1: the ';' at the end hides the drawing"]
    assert hidden_drawings("if me:\n    gk.draw.draw_mechanism(c)") == [
        "line 1: a drawing inside a block is never shown"]
    assert hidden_drawings("d = gk.draw.draw_mechanism(c)\nprint(1)") == [
        "line 1: a drawing that is not the cell's last value, nor shown later"]
    assert hidden_drawings("frames = gk.draw.draw_steps(c)", {"frames"}) == []
    assert hidden_drawings("x = gk.load('a')\nprint(x)") == []  # no drawing
    assert _last_value("frames[0]") == "frames" and _last_value("frames[0];") is None


@pytest.mark.parametrize("source", SOURCES, ids=[p.stem for p in SOURCES])
def test_checks_are_folded(source):
    """In the notebook JupyterLab opens, not only in its jupytext source."""
    cells = nbformat.read(source.with_suffix(".ipynb"), as_version=4).cells
    unfolded = [k + 1 for k, c in enumerate(cells) if HIDDEN in c.metadata.get("tags", ())
                and c.metadata.get("jupyter", {}).get("source_hidden") is not True]
    assert not unfolded, (f"{source.name}: cells {unfolded} are tagged {HIDDEN} but show their source in "
                          'JupyterLab: give them jupyter={"source_hidden": true} beside the tag')


@pytest.mark.parametrize("source", FOR_STUDENTS, ids=[p.stem for p in FOR_STUDENTS])
def test_a_folded_check_reads_as_a_label(source):
    """JupyterLab shows a folded cell's first line: in a student's lesson it says what the cell is, in words."""
    nb = jupytext.read(source)
    bare = [k + 1 for k, c in enumerate(nb.cells) if HIDDEN in c.metadata.get("tags", ())
            and not c.source.startswith("# The lesson's own check (folded)")]
    assert not bare, f"{source.name}: folded cells {bare} open with code, which JupyterLab shows as their one line"


def _drawing_cells(nb) -> list[int]:
    return [k for k, c in enumerate(nb.cells) if c.cell_type == "code" and HIDDEN not in c.metadata.get("tags", ())
            and _draws(_tree(c.source))]


def test_lesson_08_shows_each_drawing_when_run():
    """Run as JupyterLab's Run All runs it (a kernel, ``%matplotlib inline``): one image per drawing cell."""
    from nbclient import NotebookClient

    path = LESSONS / "08_velocity_and_acceleration_polygons.ipynb"
    nb = nbformat.read(path, as_version=4)
    NotebookClient(nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(LESSONS)}}).execute()
    cells = _drawing_cells(nb)
    images = {k + 1: sum("image/png" in out.get("data", {}) for out in nb.cells[k].outputs) for k in cells}
    assert cells and all(n == 1 for n in images.values()), f"images per drawing cell: {images}"
