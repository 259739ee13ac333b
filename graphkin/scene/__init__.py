"""A problem over its cycle as data a browser draws, and the page that draws it (issue 37).

:func:`scene` solves the cycle once and returns plain data (docs/json.md, "scene"); :func:`scene_json` writes it as
compact JSON; :func:`page` is one self-contained HTML file that draws it with the ES module ``js/scene.js``
(no network, no build step), and :func:`write_page` writes that file (``graphkin explore PROBLEM -o page.html``).
"""

from __future__ import annotations

from graphkin.scene.build import PRECISION, SCHEMA, scene
from graphkin.scene.labels import label
from graphkin.scene.page import page, scene_json, write_page

__all__ = ["PRECISION", "SCHEMA", "label", "page", "scene", "scene_json", "write_page"]
