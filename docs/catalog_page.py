"""A Sphinx directive that writes the catalog: one section per problem, with its family, source, figure and explorer.

``catalog-problems`` reads :mod:`graphkin.catalog` at build time, so the page lists exactly the problems
graphkin ships; each figure is the side-by-side solution ``make figures`` draws (``figures/NAME.png``), and each
explorer the problem's scene page (``_scenes/NAME.html``, as ``graphkin explore NAME --motion -o`` writes it, built
by docs/lesson_cache.py): the browser draws every position of its cycle, offline.
"""

from __future__ import annotations

from pathlib import Path

from docutils import nodes
from offline import scene_frame
from sphinx.util.docutils import SphinxDirective

from graphkin import catalog

FIGURES = Path(__file__).resolve().parents[1] / "figures"


class CatalogProblems(SphinxDirective):
    """One section per catalog problem: its title, family, source, the command that solves it, its figure and its
    explorer (the scene page in a frame, loaded when scrolled to)."""

    def run(self):
        out = []
        for name in catalog.names():
            problem = catalog.load(name)
            section = nodes.section(ids=[nodes.make_id(f"problem-{name}")], names=[nodes.fully_normalize_name(name)])
            section += nodes.title(text=f"{name}: {problem.title}")
            for label, text in (("Family", catalog.family(name)), ("Source", problem.source)):
                para = nodes.paragraph()
                para += nodes.strong(text=f"{label}: ")
                para += nodes.Text(text)
                section += para
            command = nodes.paragraph()
            command += nodes.literal(text=f"graphkin solve {name} -o {name}.png")
            section += command
            figure = FIGURES / f"{name}.png"
            if figure.exists():
                self.env.note_dependency(str(figure))
                section += nodes.image(uri=f"/figures/{name}.png", alt=f"{name} solved both ways", width="100%")
            section += nodes.raw("", scene_frame(name, self.env.docname), format="html")
            out.append(section)
        return out


def setup(app):
    app.add_directive("catalog-problems", CatalogProblems)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
