"""The handout as a PDF: typst source written from the document's blocks, compiled by the ``typst`` package.

Typst (from PyPI, compiled in-process, offline) typesets the mathematics
natively; the figures go in as SVG, so the PDF is vector throughout. Only
the fonts typst carries inside it are used (Libertinus Serif for the text,
New Computer Modern Math for the equations), never the machine's own: the
same handout gives the same pages on every computer, which the page-image
test relies on.

A typst error, or a font typst does not have, is a
:class:`graphkin.errors.GraphkinError` with one line of text.
"""

from __future__ import annotations

from graphkin.errors import GraphkinError
from graphkin.handout import maths as M

FONT = "Libertinus Serif"
MATH_FONT = "New Computer Modern Math"

_ALIGN = {"l": "left", "c": "center", "r": "right"}

MARGIN_X = 18.0
"""The page's left and right margins [mm] (A4, 210 mm wide)."""
TEXT_WIDTH = (210.0 - 2 * MARGIN_X) * 72 / 25.4
"""The width of the text [pt]."""


def _string(text: str) -> str:
    """A typst string literal: markup characters in it stay plain text."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _inline(runs) -> str:
    out = []
    for r in runs:
        if r == "\n":
            out.append(" \\ ")  # a line break inside a table's cell
        elif isinstance(r, str):
            if r:
                out.append(f"#{_string(r)}")
        else:
            out.append(f"${M.to_typst(r)}$")
    return "".join(out)


def _fit(body: str) -> str:
    """Content scaled down to the line's width when wider (a 9×9 matrix), as it is otherwise.

    Typst lays such content out twice (to measure it, then in place): a line that cannot be wider than the page
    (:func:`_equation`) is set as it is.
    """
    return (f"#layout(size => {{ let it = [{body}]; let w = measure(it).width; "
            f"if w > size.width {{ scale(size.width / w * 100%, reflow: true, it) }} else {{ it }} }})")


def _equation(line, size: float) -> str:
    """One displayed line of maths, at ``size`` [pt]: scaled down to the page only if it might be wider."""
    body = f"$ {M.to_typst(line)} $"
    return body if M.width_bound(line) * size <= TEXT_WIDTH else _fit(body)


def equation_size(b: dict) -> float:
    """The type size [pt] an equation block is set at: 8 pt small (a wide matrix), 9 pt stacked (rows read one
    after another), else 10 pt."""
    return 8.0 if b.get("small") else 9.0 if b.get("stacked") else 10.0


def _block(b: dict, floats: bool = False) -> str:
    kind = b["kind"]
    if kind == "heading":
        return f"#heading(level: {b['level']})[#{_string(b['text'])}]"
    if kind == "text":
        # Headings are sticky in typst already; a paragraph that leads to the next block is made so too.
        return f"#block(sticky: true)[{_inline(b['runs'])}]" if b.get("keep") else _inline(b["runs"])
    if kind == "list":
        mark = "+" if b["ordered"] else "-"
        body = "\n".join(f"{mark} {_inline(item)}" for item in b["items"])
        return f"#text(size: 9pt)[\n{body}\n]" if b.get("small") else body
    if kind == "table":
        cols = len(b["header"])
        align = ", ".join(_ALIGN[a] + " + horizon" for a in b["align"])
        head = ", ".join(f"[*{_inline(h)}*]" for h in b["header"])
        cells = ",\n  ".join(", ".join(f"[{_inline(c)}]" for c in row) for row in b["rows"])
        inset = ", inset: (x: 5pt, y: 7pt)" if b.get("tall") else ""
        if b.get("wide"):
            cols = "(auto, " + ", ".join(["1fr"] * (cols - 1)) + ")"
        table = (f"#table(columns: {cols}, align: ({align},){inset}, table.header({head}),\n  {cells},\n)")
        if b.get("caption"):
            table += f"\n#block(above: 0.4em)[#text(size: 8.5pt, style: \"italic\")[#{_string(b['caption'])}]]"
        if b.get("small"):
            table = f"#[#show table: set text(size: 7.5pt)\n{table}\n]"
        if b.get("boxed"):
            # The answers, boxed as a book boxes them: on one page, framed.
            table = f"#block(stroke: 1.2pt, inset: 7pt, breakable: false)[\n{table}\n]"
        return table
    if kind == "equation":
        size = equation_size(b)
        body = "\n".join(_equation(line, size) for line in b["lines"])
        if b.get("stacked"):
            # A set of equations read row by row (a link's ΣF and ΣM): set closer, from the left, as a book does.
            # One block, never split over a page: a group's equations and what they give are read together.
            return (f"#block(inset: (left: 1.5em), breakable: false)[#set block(spacing: 0.75em)\n"
                    f"#show math.equation.where(block: true): set align(left)\n#text(size: 9pt)[{body}]]")
        return f"#text(size: 8pt)[{body}]" if b.get("small") else body
    if kind == "figure" and all(p.natural for p in b["pictures"]):
        # Printed at their own size: the scale a drawing states is the scale on the page.
        images = [f"image(bytes({_string(p.svg())}), format: \"svg\", width: {p.size()[0]:.3f}pt, "
                  f"alt: {_string(p.alt)})" for p in b["pictures"]]
        body = images[0] if len(images) == 1 else ("stack(dir: ltr, spacing: 1em, " + ", ".join(images) + ")")
        # A compact key floats its drawings to the top or bottom of a page, as a textbook sets them, so that text
        # fills the page instead of a gap before each figure that does not fit where it is named.
        place = "placement: auto, " if floats and not b.get("inline") else ""
        return f"#figure({body}, caption: [{_inline(b['runs'])}], {place}numbering: none, supplement: none)"
    if kind == "figure":
        pics = b["pictures"]
        images = [f"image(bytes({_string(p.svg())}), format: \"svg\", width: 100%, height: {p.height:g}mm, "
                  f"fit: \"contain\", alt: {_string(p.alt)})" for p in pics]
        total = sum(p.width for p in pics)
        widths = ", ".join(f"{100 * p.width / max(total, 1.0):.1f}%" for p in pics)
        body = images[0] if len(pics) == 1 else (f"grid(columns: ({widths}), column-gutter: 1em, align: horizon, "
                                                 + ", ".join(images) + ")")
        width = min(total, 1.0)
        return (f"#figure(box(width: {100 * width:.1f}%, {body}), caption: [{_inline(b['runs'])}], "
                f"numbering: none, supplement: none)")
    if kind == "space":
        label = _string(b["label"])
        extra = f" ${M.to_typst(b['math'])}$" if b.get("math") else ""
        return (f"#block(width: 100%, height: {b['height']:g}mm, stroke: 0.5pt + luma(150), inset: 6pt, "
                f"breakable: false)[#text(size: 9pt)[#{label}{extra}]]")
    if kind == "pagebreak":
        return "#pagebreak(weak: true)"
    if kind == "flush":
        return "#place.flush()"
    raise ValueError(f"unknown block {kind!r}")


def source(doc: dict, *, font: str | None = None, math_font: str | None = None) -> str:
    """The typst source of a handout (figures inline as SVG bytes), set in ``font`` (default :data:`FONT`)."""
    font, math_font = font or FONT, math_font or MATH_FONT
    head = f"""#set document(title: {_string(doc['title'])})
#set page(paper: "a4", margin: (x: {MARGIN_X:g}mm, top: 18mm, bottom: 20mm),
  footer: context [#set text(size: 8pt); #{_string(doc['title'])} #h(1fr) #counter(page).display("1 / 1", both: true)])
#set text(font: {_string(font)}, size: 10pt, lang: "en")
#show math.equation: set text(font: {_string(math_font)})
#set par(justify: true, leading: 0.6em)
#set heading(numbering: none)
#show heading.where(level: 1): set text(size: 14pt)
#show heading.where(level: 2): set text(size: 12pt)
#show heading.where(level: 3): set text(size: 10.5pt)
#set table(stroke: 0.5pt + luma(160), inset: (x: 5pt, y: 3.5pt))
#show table: set text(size: 9pt)
#show figure.caption: set text(size: 9pt)
#align(center)[
  #text(size: 17pt, weight: "bold")[#{_string(doc['title'])}] \\
  #v(0.2em) #text(size: 11pt)[#{_string(doc['subtitle'])}] \\
  #v(0.2em) #text(size: 8.5pt, style: "italic")[#{_string(doc['source'])}]
]
"""
    if not (doc.get("version") == "key" and doc.get("detail") == "compact"):
        return head + "\n\n".join(_block(b) for b in doc["blocks"]) + "\n"
    # A compact key sets its steps' headings close to their equations, as a book sets a worked solution's steps.
    tight = ("#show heading.where(level: 3): set block(above: 1em, below: 0.6em)\n#set text(size: 9.5pt)\n"
             "#show table: set text(size: 8.5pt)\n")
    return head + tight + "\n\n".join(_floating(doc["blocks"])) + "\n"


def _floating(blocks: list) -> list[str]:
    """A compact key's blocks, each drawing floated to the top or bottom of a page as a textbook sets it.

    Text then fills each page instead of leaving a gap before a drawing that does not fit where it is
    named. A section that opens with a drawing (its heading, the paragraphs that lead to it, the drawing)
    floats whole, so the heading stays with its figure.
    """
    out, k = [], 0
    while k < len(blocks):
        b = blocks[k]
        end = k + 1
        if b["kind"] == "heading":
            while end < len(blocks) and blocks[end]["kind"] == "text":
                end += 1
        last = blocks[end - 1] if b["kind"] != "heading" else (blocks[end] if end < len(blocks) else b)
        if b["kind"] == "heading" and last["kind"] == "figure" and all(p.natural for p in last["pictures"]):
            inner = "\n\n".join(_block(x) for x in blocks[k:end + 1])
            out.append(f"#place(auto, float: true, clearance: 1.2em, align(left, block(width: 100%)[\n{inner}\n]))")
            k = end + 1
            continue
        out.append(_block(b, floats=True))
        k += 1
    return out


_COMPILER: list = []


def _compiler():
    """One typst compiler per process, kept: typst memoises what a compilation laid out (fonts, figures, text),
    so the next document (a student's key after their sheet, the next student's) reuses what they share. The
    PDF is the same, byte for byte, as from a fresh compiler."""
    import typst

    if not _COMPILER:
        _COMPILER.append(typst.Compiler(ignore_system_fonts=True))
    return _COMPILER[0]


def render(doc: dict, *, font: str | None = None, math_font: str | None = None) -> bytes:
    """The handout as PDF bytes.

    Raises
    ------
    GraphkinError
        On a typst error, or when typst has no font named ``font`` or
        ``math_font`` (typst would quietly fall back to another; a handout
        silently set in the wrong font is not what was asked for).
    """
    import typst

    text = source(doc, font=font, math_font=math_font)
    try:
        # Fixed timestamp (2000-01-01): the same handout gives the same bytes.
        pdf, warnings = _compiler().compile_with_warnings(input=text.encode("utf-8"), format="pdf",
                                                          timestamp=946684800)
    except typst.TypstError as exc:
        raise GraphkinError(f"typst: {_one_line(exc.message)}") from None
    for w in warnings:
        if "font" in w.message:
            raise GraphkinError(f"typst: {_one_line(w.message)} (fonts available: "
                                f"{', '.join(typst.Fonts(include_system_fonts=False).families())})")
    return pdf


def _one_line(text: str) -> str:
    return " ".join(str(text).split())
