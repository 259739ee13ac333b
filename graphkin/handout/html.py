"""The handout as one self-contained HTML file: figures inline as SVG, mathematics as MathML.

Nothing in the file points outside it: no script, no stylesheet, no font or
image to fetch, not even a namespace address (HTML5 supplies the SVG and
MathML namespaces itself). The equations are MathML, which browsers draw
natively (Chromium from version 109, Firefox, Safari), converted from the
LaTeX writer's output by ``latex2mathml``; a reader without MathML support
still sees the symbols and digits in order.

A handout whose document carries a scene (``doc["scene"]``: :func:`graphkin.scene.scene` of its problem, docs/json.md)
has one more figure: the mechanism a student moves, drawn by the browser from that presolved cycle, after the first
figure printed to scale and at the position worked out. Its drawing module and the scene's JSON are inlined (the one
script of the page, and it fetches nothing): the file still works from disk with the network off. Printed, it is
left out — paper cannot move::

    doc = handout.build("strip_cutter")
    handout.write({**doc, "scene": gk.scene.scene(gk.load("strip_cutter"))}, "cutter.html")
"""

from __future__ import annotations

import html as _html
import math
import re

from graphkin.errors import GraphkinError
from graphkin.handout import maths as M
from graphkin.handout.figures import inline_svg
from graphkin.scene.page import asset, module, scene_json

CSS = """
body { font-family: "Libertinus Serif", "Linux Libertine", Georgia, "DejaVu Serif", serif; max-width: 52rem;
       margin: 2rem auto; padding: 0 1rem; line-height: 1.45; color: #1a1a1a; }
header { text-align: center; margin-bottom: 2rem; }
header h1 { margin-bottom: 0.2rem; }
header .source { font-style: italic; font-size: 0.9rem; }
table { border-collapse: collapse; margin: 0.6rem 0; font-size: 0.92rem; }
th, td { border: 1px solid #aaa; padding: 0.2rem 0.5rem; vertical-align: middle; }
th { background: #eee; }
td.r, th.r { text-align: right; } td.c, th.c { text-align: center; }
caption { caption-side: bottom; font-style: italic; font-size: 0.85rem; text-align: left; padding-top: 0.3rem; }
.boxed { display: inline-block; border: 2px solid #222; padding: 0.2rem 0.6rem; margin: 0.6rem 0; }
/* A math font where the system has one (macOS, Windows, TeX Live, most Linux desktops); where it has none (DejaVu
   alone), matrices and roots are drawn with borders below, so nothing needs a font's stretchy glyphs. */
math { font-family: "STIX Two Math", "Cambria Math", "Latin Modern Math", "New Computer Modern Math",
       "Libertinus Math", "DejaVu Math TeX Gyre", "TeX Gyre Termes Math", math, "DejaVu Serif", serif; }
mtable.bmat, mtable.cmat { padding: 0.1em 0.4em; }
mtable.bmat { background: linear-gradient(currentColor, currentColor) left top / 1px 100% no-repeat,
  linear-gradient(currentColor, currentColor) left top / 0.3em 1px no-repeat,
  linear-gradient(currentColor, currentColor) left bottom / 0.3em 1px no-repeat,
  linear-gradient(currentColor, currentColor) right top / 1px 100% no-repeat,
  linear-gradient(currentColor, currentColor) right top / 0.3em 1px no-repeat,
  linear-gradient(currentColor, currentColor) right bottom / 0.3em 1px no-repeat; }
mtable.cmat { border-left: 1px solid; border-right: 1px solid; border-radius: 0.6em / 1.2em; }
mrow.radicand { border-top: 1px solid; padding-top: 0.1em; }
.eq { overflow-x: auto; overflow-y: hidden; margin: 0.5rem 0; padding: 0.1rem 0; }
.eq.small { font-size: 0.8rem; }
figure { margin: 1rem 0; text-align: center; }
figure .row { display: flex; gap: 1rem; align-items: center; justify-content: center; }
figure svg { max-width: 100%; height: auto; }
figcaption { font-size: 0.9rem; text-align: left; margin-top: 0.3rem; }
.space { border: 1px solid #999; padding: 0.4rem; margin: 0.6rem 0; font-size: 0.9rem; }
/* Printed: A4 with the PDF's margins, so a drawing at its stated scale (its own size) fits the line; nothing
   that one reads as a whole is split across two pages. */
@page { size: A4; margin: 18mm 18mm 20mm 18mm; }
@media print { body { max-width: none; margin: 0; padding: 0; font-size: 10pt; }
               .pagebreak { break-after: page; }
               .space, figure, .eq, table, .boxed, li { break-inside: avoid; }
               h2, h3, h4, p.keep { break-after: avoid; }
               .eq { overflow: visible; } figure.live { display: none; } }
figure.live { text-align: left; border-top: 1px solid #ccc; padding-top: 0.5rem; }
figure.live .gk-scene:focus { outline: 1px dotted #999; }
"""


def _mathml(node, display: bool) -> str:
    try:
        from latex2mathml.converter import convert
    except ImportError:
        raise GraphkinError("HTML handouts need the latex2mathml package for their equations: "
                            "pip install latex2mathml") from None
    out = convert(M.to_latex(node), display="block" if display else "inline")
    # HTML5 knows the MathML namespace: the address is dropped so that the file names none.
    out = re.sub(r'\s+xmlns="[^"]*"', "", out)
    return _borders(out)


_FENCED = re.compile(r'<mrow><mo stretchy="true" fence="true" form="prefix">(\[|&#x0007B;)</mo>(<mtable>.*?</mtable>)'
                     r'<mo stretchy="true" fence="true" form="postfix">(?:\]|&#x0007D;)</mo></mrow>', re.S)


def _borders(mathml: str) -> str:
    """Matrices' brackets and roots' bars drawn by CSS, not by a font's stretchy glyphs.

    A browser stretches a bracket, or draws a root's bar, from the math font's MATH table; where the system has
    no math font (DejaVu alone), a bracket stays one line tall beside a matrix of nine. Borders (the class
    ``bmat``, ``cmat``, ``radicand`` in :data:`CSS`) look the same with any font.
    """
    def fence(m):
        cls = "bmat" if m[1] == "[" else "cmat"
        return m[2].replace("<mtable>", f'<mtable class="{cls}">', 1)

    # Innermost first: a matrix inside another's cell is a whole <mtable>…</mtable> without a nested one.
    while True:
        new = _FENCED.sub(lambda m: fence(m) if "<mtable" not in m[2][7:] else m[0], mathml)
        if new == mathml:
            break
        mathml = new
    return mathml.replace("<msqrt>", '<mrow><mo>√</mo><mrow class="radicand">').replace("</msqrt>", "</mrow></mrow>")



def _inline(runs) -> str:
    return "".join("<br>" if r == "\n" else _html.escape(r, quote=False) if isinstance(r, str) else _mathml(r, False)
                   for r in runs)


def _block(b: dict) -> str:
    kind = b["kind"]
    esc = _html.escape
    if kind == "heading":
        level = min(b["level"] + 1, 6)  # the title is the page's h1
        return f"<h{level}>{esc(b['text'])}</h{level}>"
    if kind == "text":
        return f"<p class=\"keep\">{_inline(b['runs'])}</p>" if b.get("keep") else f"<p>{_inline(b['runs'])}</p>"
    if kind == "list":
        tag = "ol" if b["ordered"] else "ul"
        return f"<{tag}>" + "".join(f"<li>{_inline(item)}</li>" for item in b["items"]) + f"</{tag}>"
    if kind == "table":
        cls = [f' class="{a}"' if a != "l" else "" for a in b["align"]]
        head = "".join(f"<th{c}>{_inline(h)}</th>" for c, h in zip(cls, b["header"]))
        body = "".join("<tr>" + "".join(f"<td{c}>{_inline(x)}</td>" for c, x in zip(cls, row)) + "</tr>"
                       for row in b["rows"])
        caption = f"<caption>{esc(b['caption'])}</caption>" if b.get("caption") else ""
        wide = ' style="width: 100%"' if b.get("wide") else ""
        table = f"<table{wide}>{caption}<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"
        if b.get("boxed"):
            block = ' style="display: block"' if wide else ""
            return f'<div class="boxed"{block}>{table}</div>'
        return table
    if kind == "equation":
        small = " small" if b.get("small") else ""
        return "".join(f'<div class="eq{small}">{_mathml(line, True)}</div>' for line in b["lines"])
    if kind == "figure":
        pics = b["pictures"]
        total = sum(p.width for p in pics)
        items = "".join(f'<div class="natural" role="img" aria-label="{esc(p.alt)}">{inline_svg(p.svg(), p.key)}</div>'
                        if p.natural else
                        f'<div style="flex: {p.width / total:.3f} 1 0; max-width: {100 * p.width:.0f}%" role="img" '
                        f'aria-label="{esc(p.alt)}">{_sized(inline_svg(p.svg(), p.key), p.height)}</div>' for p in pics)
        return f'<figure><div class="row">{items}</div><figcaption>{_inline(b["runs"])}</figcaption></figure>'
    if kind == "space":
        extra = " " + _mathml(b["math"], False) if b.get("math") else ""
        return f'<div class="space" style="height: {b["height"]:g}mm">{esc(b["label"])}{extra}</div>'
    if kind == "pagebreak":
        return '<div class="pagebreak"></div>'
    if kind == "flush":
        return ""  # a page's figures do not float here
    raise ValueError(f"unknown block {kind!r}")


def _sized(svg: str, height: float) -> str:
    """The SVG scaled to fit the column and at most ``height`` mm tall (its viewBox keeps the proportions)."""
    return svg.replace("<svg ", f'<svg style="max-height: {height:g}mm; width: auto; max-width: 100%" ', 1)


def _nearest(scene: dict, q: float) -> int:
    """The scene's position nearest the input ``q`` (a crank's angle the short way round)."""
    def gap(x):
        d = x - q
        return abs(math.remainder(d, 2 * math.pi)) if scene["input"]["name"] == "theta" else abs(d)

    return min(range(scene["n"]), key=lambda k: gap(scene["input"]["values"][k]))


def _live(doc: dict, label: str) -> str:
    """The figure a student moves: the scene drawn by the browser, shown first at the position worked out."""
    scene = doc["scene"]
    code = module()
    if "</script" in code.lower():  # pragma: no cover - the shipped module is written without one
        raise ValueError("scene.js must not contain '</script'")
    start = _nearest(scene, doc["worked"][0]["q"]) if doc.get("worked") else 0
    data = scene_json(scene).replace("<", "\\u003c")  # no string of the scene can close its element
    after = f"{label}, moving" if label else "The mechanism, moving"
    caption = (f"{after}: its whole cycle, solved once. Drag the crank, or click the figure and use the arrow keys; "
               "play, and show or hide the forces, the polygons and the free bodies.")
    return (f'<figure class="live"><div id="graphkin" tabindex="0"></div><figcaption>{_html.escape(caption)}'
            f'</figcaption></figure>\n<script type="application/json" id="graphkin-scene">{data}</script>\n'
            f'<script type="module">\n{code}\nconst scene = JSON.parse(document.getElementById("graphkin-scene")'
            f'.textContent);\nconst root = document.getElementById("graphkin");\n'
            f"window.graphkin = {{ scene, view: draw(root, scene, {{ keys: root }}) }};\n"
            f"window.graphkin.view.show({start});\n</script>")


def render(doc: dict) -> str:
    """The handout as one HTML document (a str); with ``doc["scene"]``, the figure a student moves as well."""
    esc = _html.escape
    parts = [_block(b) for b in doc["blocks"]]
    if doc.get("scene"):
        # After the first figure printed to scale (the mechanism), else at the end.
        at = next((k for k, b in enumerate(doc["blocks"]) if b["kind"] == "figure" and b["pictures"]
                   and all(p.natural for p in b["pictures"])), None)
        if at is None:
            parts.append(_live(doc, ""))
        else:
            parts.insert(at + 1, _live(doc, doc["blocks"][at]["label"]))
    body = "\n".join(parts)
    style = asset("scene.css") if doc.get("scene") else ""
    return (f'<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
            f'<meta name="viewport" content="width=device-width, initial-scale=1">\n'
            f"<title>{esc(doc['title'])} — {esc(doc['subtitle'])}</title>\n<style>{CSS}{style}</style>\n</head>\n<body>\n"
            f"<header><h1>{esc(doc['title'])}</h1><div>{esc(doc['subtitle'])}</div>"
            f"<div class=\"source\">{esc(doc['source'])}</div></header>\n<main>\n{body}\n</main>\n</body>\n</html>\n")
