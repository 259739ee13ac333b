"""Rebuild figures/handouts/: the worked-solution handouts of the lessons' examples.

Writes each key as PDF (what ``graphkin handout NAME -o NAME.pdf`` writes), the handout each lesson
links to; for the double slider and the strip cutter also, as PNG, the first page and the page with
the first force polygon, for the README to show.

    .venv/bin/python figures/handouts/build.py

Needs pypdfium2 (in the test extras) to render the pages.
"""

from __future__ import annotations

from pathlib import Path

import pypdfium2 as pdfium

from graphkin import handout
from graphkin.files import replacing

HERE = Path(__file__).resolve().parent
PROBLEMS = ("single_link", "double_slider", "strip_cutter", "slider_crank_friction", "gearset")
"""The examples of lessons 01–05."""
PAGE_IMAGES = ("double_slider", "strip_cutter")
"""The handouts shown as page images."""
DPI = 110


def polygon_page(pdf) -> int:
    """The first page that shows the force polygons (a figure's caption says so)."""
    for k in range(len(pdf)):
        text = pdf[k].get_textpage().get_text_range()
        if "The force polygons, tip to tail" in text or "Force polygon of link" in text:
            return k
    return 0


def build(name: str) -> list[Path]:
    doc = handout.build(name)
    path = HERE / f"{name}.pdf"
    handout.write(doc, path)
    pdf = pdfium.PdfDocument(path)
    written = [path]
    # Page images are named by page: a change of layout moves them, so last build's go first.
    for old in HERE.glob(f"{name}_page*.png"):
        old.unlink()
    for k in sorted({0, polygon_page(pdf)}) if name in PAGE_IMAGES else ():
        png = HERE / f"{name}_page{k + 1}.png"
        # Whole or not at all, as every file graphkin writes: a build stopped half-way leaves no half image.
        with replacing(png, "page image") as tmp:
            pdf[k].render(scale=DPI / 72).to_pil().save(tmp, format="PNG", optimize=True)
        written.append(png)
    print(f"{name}: {len(pdf)} pages")
    return written


if __name__ == "__main__":
    for name in PROBLEMS:
        for p in build(name):
            print(f"  {p.relative_to(HERE.parent.parent)}")
