"""Sphinx configuration of graphkin's documentation site: ``make docs`` builds it into build/docs.

The site is whole offline: no page asks another host for a script, a style sheet, a font or an image
(docs/offline.py; tests/docs/ checks every page).

The source folder is the repository itself, so that the guide (docs/), the
lessons (lessons/*.ipynb) and the README keep the links they have on GitHub;
``include_patterns`` lists what is a page. The lessons are executed at build
time (myst-nb), the formulas become MathML as it is built (docs/mathml.py),
the API reference is made from the numpydoc docstrings, and
the catalog page from the catalog itself (one section and figure per problem).

Why Sphinx rather than MkDocs: graphkin's docstrings are numpydoc, which
Sphinx reads natively (the numpydoc extension is numpy's own), myst-nb runs
and renders the lessons from the same Markdown dialect as the guide, and
the pydata theme is the one numpy, SciPy and matplotlib users know.
"""

from __future__ import annotations

import hashlib
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "docs"))

import graphkin  # noqa: E402

project = "graphkin"
author = "The graphkin developers"
copyright = "2026, the graphkin developers"
release = version = graphkin.__version__

root_doc = "docs/index"
include_patterns = ["docs/**", "lessons/*.ipynb", "lessons/README.md", "README.md"]
exclude_patterns = ["build", ".venv", "docs/_templates/**", "**/.ipynb_checkpoints"]

extensions = [
    "myst_nb",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "catalog_page",
    "mathml",  # formulas as MathML, drawn by the browser: no script from a CDN (docs/mathml.py)
    "offline",  # widgets drawn without a CDN, the README's images local (docs/offline.py)
    "lesson_cache",  # the lessons run before reading, on every core, once per change (docs/lesson_cache.py)
]

# -- MyST and the notebooks ---------------------------------------------------------------------------------
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist", "attrs_inline"]
myst_heading_anchors = 3  # links such as exercises.md#grading-platforms
# The lessons' outputs are what graphkin computes now: a lesson runs again whenever its code, graphkin, the files
# beside it or an installed package changed (docs/lesson_cache.py); otherwise its last run is taken from the cache.
nb_execution_mode = "cache"
nb_execution_cache_path = str(ROOT / "build" / ".docs-cache" / "jupyter")
nb_execution_timeout = 600
nb_execution_raise_on_error = True
nb_execution_in_temp = False  # a lesson reads and writes beside itself, as in JupyterLab
nb_merge_streams = True
nb_ipywidgets_js = {}  # no require.js and widget manager from CDNs: docs/offline.py draws the widgets

# -- the API reference ---------------------------------------------------------------------------------------
autosummary_generate = True
autosummary_imported_members = True
autodoc_typehints = "none"  # the numpydoc sections carry types with units
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False
numpydoc_validation_checks = set()  # checked in tests/test_namespace.py, on the public API

# -- HTML ------------------------------------------------------------------------------------------------------
html_theme = "pydata_sphinx_theme"
html_math_renderer = "mathml"
html_title = f"graphkin {version}"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": [],
}
html_static_path = ["_static"]
html_css_files = ["graphkin.css"]  # MathML display formulas in the theme
html_extra_path = ["_extra"]  # relative to this folder  # the site's root index.html, which leads to docs/index.html
html_last_updated_fmt = None
html_show_sourcelink = False
html_copy_source = False

suppress_warnings = ["mystnb.unknown_mime_type"]

# Sphinx reads a page again when it or a setting changed, not when an extension's code did: this setting is the
# code of the site's own extensions (docs/*.py), so that a change to how a page is made remakes every page.
docs_code = hashlib.sha256(b"".join(p.read_bytes() for p in sorted((ROOT / "docs").glob("*.py")))).hexdigest()


def setup(app):
    app.add_config_value("docs_code", "", "env")
