"""A scene as compact JSON, and as one self-contained HTML page that draws it (no network, no build step).

The page is ``js/page.html`` with the scene's JSON, the drawing module (:func:`module`: ``js/dom.js``,
``js/speed.js``, ``js/scene.js`` and ``js/widget.js`` as one ES module) and its styles (``js/scene.css``) put in their
place: one file a student opens from disk, an LMS serves or an e-mail carries, that asks for nothing else. The JSON
goes in a ``<script type="application/json">`` element, with every ``<`` written ``\\u003c`` so that no string of the
scene (a title, a reason) can close the element.
"""

from __future__ import annotations

import re
from importlib import resources
from pathlib import Path

from graphkin.files import write_text


def scene_json(data: dict) -> str:
    """The scene as compact JSON (no spaces; nan as null), as the page and docs/json.md hold it.

    Parameters
    ----------
    data : dict
        :func:`graphkin.scene.scene`'s result.

    Returns
    -------
    str
    """
    import orjson

    return orjson.dumps(data, option=orjson.OPT_SERIALIZE_NUMPY).decode("utf-8")


def asset(name: str) -> str:
    """The text of one of the page's files shipped in the package (``scene.js``, ``scene.css``, ``page.html``, …)."""
    return resources.files("graphkin.scene").joinpath("js", name).read_text(encoding="utf-8")


MODULES = ("dom.js", "speed.js", "scene.js", "widget.js")
"""The drawing's ES modules, each importing only from those before it: :func:`module` joins them."""

DRAW_MODULES = ("dom.js", "match.js", "draw.js", "drawwidget.js")
"""The student's drawing (issue 38): the practice page's and the drawn answer widget's modules, joined the same way
(:func:`module` with ``names=DRAW_MODULES``)."""

IMPORT = re.compile(r'^import \{[^}]*\} from "\./[a-z]+\.js";\n', re.M)
"""A module's import of another of :data:`MODULES` (a page from disk, or a notebook's widget, loads one module: a
relative import has no file to come from)."""


def module(names: tuple[str, ...] = MODULES) -> str:
    """The drawing as one ES module: :data:`MODULES` (or ``names``) in their order, without their imports of one
    another.

    Exports ``draw(element, scene)`` (the page calls it; not named ``render``, which anywidget would take for its
    own), ``default`` (anywidget's ``render({model, el})``: the notebook's widget, :mod:`graphkin.widgets.browser`),
    and ``live``, ``setRate`` and ``polar``.

    Parameters
    ----------
    names : tuple of str
        The modules joined: :data:`MODULES` (the scene) or :data:`DRAW_MODULES` (the student's drawing, whose
        ``drawTask(element, task)`` the practice page calls and whose ``default`` is the drawn answer widget's).

    Returns
    -------
    str
        JavaScript.
    """
    return "\n".join(IMPORT.sub("", asset(name)) for name in names)


def page(data: dict) -> str:
    """One self-contained HTML page that draws the scene ``data`` (its JSON and the drawing module inlined).

    Parameters
    ----------
    data : dict
        :func:`graphkin.scene.scene`'s result.

    Returns
    -------
    str
        The page's HTML.
    """
    from html import escape

    text = scene_json(data).replace("<", "\\u003c")
    code = module()
    if "</script" in code.lower():  # pragma: no cover - the shipped module is written without one
        raise ValueError("scene.js must not contain '</script'")
    html = asset("page.html")
    return (html.replace("{{title}}", escape(data["title"] or data["problem"]))
            .replace("{{style}}", asset("scene.css")).replace("{{scene}}", text).replace("{{module}}", code))


def write_page(data: dict, path: str | Path, what: str = "-o") -> Path:
    """Write :func:`page` of ``data`` to ``path`` atomically (:func:`graphkin.files.write_text`).

    Parameters
    ----------
    data : dict
        :func:`graphkin.scene.scene`'s result.
    path : str or Path
        The HTML file to write.
    what : str
        What names the file in an error message (the option that gave it).

    Returns
    -------
    Path
    """
    return write_text(path, page(data), what)
