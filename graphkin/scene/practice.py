"""A practice page for drawn answers (issue 38): one self-contained HTML page on which a student draws each
construction a task asks for and checks it against the targets the task carries, in the page only.

It takes task dicts (docs/json.md, "Drawn answers": built by
:func:`graphkin.exercises.drawn_tasks.task_of` with ``practice=True``, so each carries its ``check``) and inlines
them with the drawing's module (:func:`graphkin.scene.page.module` of
:data:`graphkin.scene.page.DRAW_MODULES`) and its styles into ``js/practice.html``, as
:func:`graphkin.scene.page.page` does a scene. The page grades nothing that is kept: it says so, and sends nothing.
"""

from __future__ import annotations

import re
from html import escape
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.files import write_text
from graphkin.scene.page import DRAW_MODULES, asset, module, scene_json

DRAW_KINDS = ("line", "point", "vector")
"""What a task asks a student to draw: each element of its ``draw``."""


def _checked(tasks) -> list[dict]:
    if not isinstance(tasks, (list, tuple)) or not tasks:
        raise GraphkinError("practice page: give a list of one or more drawn tasks")
    for k, task in enumerate(tasks):
        where = f"practice page: task {k + 1}"
        if not isinstance(task, dict):
            raise GraphkinError(f"{where} is not a task (a dict of docs/json.md's 'Drawn answers')")
        for field in ("question", "space", "unit", "ask", "scale", "view", "draw"):
            if field not in task:
                raise GraphkinError(f"{where} ({task.get('question', '?')}) has no {field!r}")
        view = task["view"]
        if len(view) != 4 or not (view[0] < view[2] and view[1] < view[3]):
            raise GraphkinError(f"{where} ({task['question']}): view must be [xmin, ymin, xmax, ymax], got {view!r}")
        if not task["scale"].get("si_per_mm", 0) > 0:
            raise GraphkinError(f"{where} ({task['question']}): scale.si_per_mm must be > 0")
        for e in task["draw"]:
            if e.get("kind") not in DRAW_KINDS:
                raise GraphkinError(f"{where} ({task['question']}): draw element {e!r} is not one of "
                                    f"{', '.join(DRAW_KINDS)}")
    return list(tasks)


def practice_page(tasks, title: str = "Practice") -> str:
    """One self-contained HTML page on which the student draws each of ``tasks`` and checks it (no grade kept).

    Parameters
    ----------
    tasks : list of dict
        Drawn tasks (docs/json.md, "Drawn answers"), each with its ``check`` for the page to match against.
    title : str
        The page's title.

    Returns
    -------
    str
        The page's HTML.
    """
    text = scene_json(_checked(tasks)).replace("<", "\\u003c")
    code = module(DRAW_MODULES)
    if "</script" in code.lower():  # pragma: no cover - the shipped modules are written without one
        raise ValueError("draw.js must not contain '</script'")
    fill = {"title": escape(title), "style": asset("draw.css"), "tasks": text, "module": code}
    return re.sub(r"\{\{(title|style|tasks|module)\}\}", lambda m: fill[m[1]], asset("practice.html"))


def write_practice(tasks, path: str | Path, title: str = "Practice", what: str = "-o") -> Path:
    """Write :func:`practice_page` to ``path`` atomically (:func:`graphkin.files.write_text`).

    Parameters
    ----------
    tasks : list of dict
        Drawn tasks with their ``check``.
    path : str or Path
        The HTML file to write.
    title : str
        The page's title.
    what : str
        What names the file in an error message (the option that gave it).

    Returns
    -------
    Path
    """
    return write_text(path, practice_page(tasks, title), what)
