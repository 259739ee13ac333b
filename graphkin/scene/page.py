"""A scene as compact JSON, and as one self-contained HTML page that draws it (no network, no build step).

The page is ``js/page.html`` with the scene's JSON and the ES module ``js/scene.js`` put in its place: one file a
student opens from disk, an LMS serves or an e-mail carries, that asks for nothing else. The JSON goes in a
``<script type="application/json">`` element, with every ``<`` written ``\\u003c`` so that no string of the scene
(a title, a reason) can close the element.
"""

from __future__ import annotations

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
    """The text of one of the page's files shipped in the package (``scene.js``, ``page.html``)."""
    return resources.files("graphkin.scene").joinpath("js", name).read_text(encoding="utf-8")


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
    module = asset("scene.js")
    if "</script" in module.lower():  # pragma: no cover - the shipped module is written without one
        raise ValueError("scene.js must not contain '</script'")
    html = asset("page.html")
    return (html.replace("{{title}}", escape(data["title"] or data["problem"]))
            .replace("{{scene}}", text).replace("{{module}}", module))


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
