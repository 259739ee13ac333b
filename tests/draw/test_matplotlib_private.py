"""matplotlib's private names: every one graphkin uses is listed in :mod:`graphkin.draw.matplotlib_private`, and
without the fast text path they stand for, figures and handouts come out as before, the text drawn by stock
matplotlib."""

from __future__ import annotations

import ast
import inspect
import io
import re
import sys
from pathlib import Path

import pytest

from graphkin.draw import matplotlib_private as M

PACKAGE = Path(__file__).resolve().parents[2] / "graphkin"

NOT_MATPLOTLIB = {"_exit": "os._exit", "_property_lock": "ipywidgets.Widget._property_lock"}
"""Private names graphkin reads from other libraries."""


def _listed() -> set[str]:
    return {name.rpartition(".")[2].rpartition(":")[2] for name in M.TEXT + M.ELSEWHERE}


def test_the_names_used_with_no_fallback_are_in_this_matplotlib():
    assert [name for name in M.ELSEWHERE if not M.resolves(name)] == []
    assert M.MISSING == tuple(name for name in M.TEXT if not M.resolves(name))
    assert not M.resolves("matplotlib.text:Text._no_such_name") and not M.resolves("matplotlib._no_such_module:x")


def test_every_private_name_read_from_matplotlib_is_listed():
    """A private attribute read anywhere in graphkin that graphkin does not define itself, and every private module
    of matplotlib's imported, is in the lists."""
    defined, read, modules = set(), {}, set()
    for path in PACKAGE.rglob("*.py"):
        for n in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                defined.add(n.name)
            elif isinstance(n, ast.Name) and not isinstance(n.ctx, ast.Load):
                defined.add(n.id)
            elif isinstance(n, ast.Attribute) and not isinstance(n.ctx, ast.Load):
                defined.add(n.attr)
            elif isinstance(n, ast.arg):
                defined.add(n.arg)
            elif isinstance(n, ast.keyword) and n.arg:
                defined.add(n.arg)
            if isinstance(n, ast.Attribute) and n.attr.startswith("_") and not n.attr.startswith("__"):
                read.setdefault(n.attr, set()).add(path.name)
            if isinstance(n, ast.ImportFrom) and n.module and n.module.startswith("matplotlib"):
                names = [n.module] + [f"{n.module}.{a.name}" for a in n.names]
                modules.update(m for m in names if "._" in m)
    unlisted = {k: v for k, v in read.items() if k not in defined | _listed() | set(NOT_MATPLOTLIB)}
    assert unlisted == {}
    prefixes = {name.partition(":")[0] for name in M.TEXT + M.ELSEWHERE}
    prefixes |= {f"{p}.{name.partition(':')[2].partition('.')[0]}" for p, name in
                 ((n.partition(":")[0], n) for n in M.TEXT + M.ELSEWHERE)}
    assert {m for m in modules if m not in prefixes} == set()


def test_every_private_method_overridden_is_listed():
    """A graphkin class's private attribute that a matplotlib class it derives from has (an override) is listed."""
    import graphkin.draw.axes
    import graphkin.draw.backend_svg
    import graphkin.draw.glyphs  # noqa: F401

    overridden = set()
    for name, module in list(sys.modules.items()):
        if not name.startswith("graphkin."):
            continue
        for cls in vars(module).values():
            if not (inspect.isclass(cls) and cls.__module__ == name):
                continue
            for attr in vars(cls):
                if attr.startswith("_") and not attr.startswith("__") and any(
                        attr in vars(base) for base in cls.__mro__[1:] if base.__module__.startswith("matplotlib")):
                    overridden.add(attr)
    assert {"_update_glyph_map_defs", "_init_axis"} <= overridden  # the scan sees overrides
    assert overridden - _listed() == set()


def _layout(fig):
    """Where each text of a figure stands and what it says, and the figure's drawn extent [in]."""
    from matplotlib.text import Text

    from graphkin.draw.extent import drawn_extent

    texts = [(t.get_text(), tuple(t.get_position()), t.get_ha(), t.get_va()) for t in fig.findobj(Text)]
    return texts, tuple(drawn_extent(fig).bounds)


def _solution():
    from graphkin import catalog, draw
    from graphkin.graphical import construct_forces

    p = catalog.load("double_slider")
    return draw.draw_solution(construct_forces(p.kinematics(), 0), p.solve())


def test_without_the_fast_text_path_a_figure_is_laid_out_the_same(monkeypatch):
    """Stock matplotlib measures the labels (the same unhinted outlines) and writes the SVG; no module that needs a
    private name is imported (each is made unimportable), and matplotlib's classes are never swapped."""
    from matplotlib.backends import backend_svg
    from matplotlib.text import Text

    from graphkin.draw.text import halo, svg_backend

    fast = _layout(_solution())
    if M.FAST_TEXT:  # where this matplotlib has every name: graphkin's backend, which changes nothing of matplotlib's
        plain_svg, plain_layout = backend_svg.RendererSVG, Text._get_layout
        fig = _solution()
        assert type(fig.findobj(lambda a: bool(a.get_path_effects()))[0].get_path_effects()[0]).__name__ == "_Halo"
        out = io.BytesIO()
        fig.savefig(out, format="svg", backend=svg_backend())
        assert b"text-outline-" in out.getvalue()  # each haloed text's outline written once, by graphkin's backend
        assert backend_svg.RendererSVG is plain_svg and Text._get_layout is plain_layout
        assert not [t for t in fig.findobj(Text) if "_get_layout" in vars(t)]

    monkeypatch.setattr(M, "FAST_TEXT", False)
    for name in ("graphkin.draw.glyphs", "graphkin.draw.backend_svg"):
        monkeypatch.setitem(sys.modules, name, None)
    assert svg_backend() is None and type(halo()).__name__ == "withStroke"
    fig = _solution()
    assert _layout(fig) == fast
    out = io.BytesIO()
    fig.savefig(out, format="svg", backend=svg_backend())
    assert b"text-outline-" not in out.getvalue() and b"<use" in out.getvalue()


def test_without_the_fast_text_path_a_handout_is_written(monkeypatch, tmp_path):
    """The handout's pages: each figure the size it is with the fast path (its drawn extent, to the last digit
    written), the PDF's pages the same in number, size and text."""
    pypdf = pytest.importorskip("pypdf")
    from graphkin import handout

    def written(folder):
        doc = handout.build("double_slider")
        handout.write(doc, folder / "h.pdf")
        handout.write(doc, folder / "h.html")
        sizes = re.findall(r'<svg width="([0-9.]+pt)" height="([0-9.]+pt)"', (folder / "h.html").read_text("utf-8"))
        pages = pypdf.PdfReader(folder / "h.pdf").pages
        return sizes, [tuple(p.mediabox) for p in pages], [p.extract_text() for p in pages]

    (tmp_path / "fast").mkdir()
    (tmp_path / "stock").mkdir()
    fast, fast_path = written(tmp_path / "fast"), M.FAST_TEXT
    monkeypatch.setattr(M, "FAST_TEXT", False)
    for name in ("graphkin.draw.glyphs", "graphkin.draw.backend_svg"):
        monkeypatch.setitem(sys.modules, name, None)
    stock = written(tmp_path / "stock")
    assert len(fast[0]) == 4 and len(fast[1]) >= 1
    assert stock == fast
    assert ("text-outline-" in (tmp_path / "fast" / "h.html").read_text(encoding="utf-8")) == fast_path
    assert "text-outline-" not in (tmp_path / "stock" / "h.html").read_text(encoding="utf-8")
