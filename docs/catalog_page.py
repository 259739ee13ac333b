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


PRACTICE_STUDENT = "practice"
"""The id the site's practice pages are drawn for: a variant no course grades (each page carries its targets)."""


def drawn_exercises() -> list[str]:
    """The catalog exercises with drawn questions: each has a practice page on the site."""
    from graphkin import exercises

    return [n for n in exercises.names() if any(q.kind == "drawing" for q in exercises.load(n).questions)]


def write_practice_pages(folder: Path) -> list[Path]:
    """Each drawn exercise's practice page (``graphkin exercise practice NAME --student practice``) in ``folder``."""
    from graphkin import exercises
    from graphkin.scene.practice import write_practice

    out = []
    for name in drawn_exercises():
        v = exercises.variant(name, PRACTICE_STUDENT)
        tasks = [exercises.task_of(v, q.id, practice=True) for q in v.exercise.questions if q.kind == "drawing"]
        out.append(write_practice(tasks, folder / f"practice-{name}.html", title=f"{v.exercise.title} — practice"))
    return out


class PracticePages(SphinxDirective):
    """Each drawn exercise's practice page in a frame: the student draws and checks in the page, offline."""

    def run(self):
        import html
        import posixpath

        from offline import SCENES

        out = []
        for name in drawn_exercises():
            src = posixpath.relpath(f"{SCENES}/practice-{name}.html", posixpath.dirname(self.env.docname) or ".")
            out.append(nodes.raw("", (
                f'<div class="graphkin-scene graphkin-practice"><iframe src="{html.escape(src)}" title="{name}: '
                f'practice" loading="lazy" style="height: 60em"></iframe><p class="gk-note">Practice on '
                f'<code>{name}</code> with the id <code>{PRACTICE_STUDENT}</code>: draw, press Check, and the page '
                f'says which construction your drawing matches. No grade is recorded and nothing is sent '
                f'(<a href="{html.escape(src)}">open it whole</a>).</p></div>'), format="html"))
        return out


def setup(app):
    app.add_directive("catalog-problems", CatalogProblems)
    app.add_directive("practice-pages", PracticePages)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
