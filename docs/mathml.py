"""Sphinx renders the site's mathematics as MathML at build time, with ``latex2mathml`` (a core dependency).

MathJax would load a script from a CDN when a page opens: a course site behind a
firewall, or a laptop offline in a lecture hall, would show TeX source. MathML
is drawn by the browser itself (Chromium, Firefox and Safari), as the HTML
handouts already do (:mod:`graphkin.handout.html`). A formula latex2mathml
cannot read is a build warning naming the page, so ``make docs`` (``-W``)
fails rather than printing a broken formula.
"""

from __future__ import annotations

import html
import re

from docutils import nodes
from latex2mathml.converter import convert
from sphinx.util import logging

logger = logging.getLogger(__name__)

# latex2mathml lays out align*, split and array as tables but reads aligned, align and gather(ed) as one row
# with a literal "&": the environments are renamed to ones it lays out (the same layout in amsmath).
_RENAMED = {"aligned": "align*", "align": "align*", "gathered": "array}{c", "gather": "array}{c",
            "gather*": "array}{c", "equation": None, "equation*": None}
_ENVIRONMENT = re.compile(r"\\(begin|end)\{(" + "|".join(re.escape(k) for k in _RENAMED) + r")\}")


def _renamed(latex: str) -> str:
    def swap(m):
        new = _RENAMED[m.group(2)]
        if new is None:  # equation: its body alone
            return ""
        return rf"\begin{{{new}}}" if m.group(1) == "begin" else rf"\end{{{new.split('}')[0]}}}"
    return _ENVIRONMENT.sub(swap, latex)


def _mathml(node, latex: str, display: bool) -> str:
    try:
        out = convert(_renamed(latex), display="block" if display else "inline")
        if "<mi>&amp;</mi>" in out or "<mi>&</mi>" in out or 'linebreak="newline"' in out:
            raise ValueError("an alignment or a line break it would print as text")
    except Exception as exc:  # latex2mathml raises several kinds; each means the same thing here
        logger.warning("a formula MathML cannot be made of: %s (%s)", latex.strip()[:80], exc, location=node)
        out = f"<code>{html.escape(latex)}</code>"
    return re.sub(r'\s+xmlns="[^"]*"', "", out)  # HTML5 knows the MathML namespace


def _visit_math(self, node):
    self.body.append(_mathml(node, node.astext(), display=False))
    raise nodes.SkipNode


def _visit_math_block(self, node):
    self.body.append(f'<div class="math notranslate">{_mathml(node, node.astext(), display=True)}</div>')
    raise nodes.SkipNode


def setup(app):
    app.add_html_math_renderer("mathml", (_visit_math, None), (_visit_math_block, None))
    return {"parallel_read_safe": True, "parallel_write_safe": True}
