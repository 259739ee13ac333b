"""Worked-solution handouts: one data structure, rendered as PDF (typst), HTML and Markdown.

:func:`build` gathers the worked solution of a problem (or a student's
variant of an exercise) as plain data, in the order a textbook goes: the
data, the sign convention, the kinematics, the inertia loads, the matrix
[A]{x} = {b} and its solution, the graphical route step by step, both
routes side by side, and for a whole cycle the torque curve, the flywheel
and the joint-force index (``content.py``). Three renderers read that one
structure (``typst.py``, ``html.py``, ``markdown.py``); none computes or
formats a number of its own.

Three versions: the **key** (everything), the **sheet** (an exercise's data
and questions, no answers) and the **blank** worksheet (the free bodies
drawn to the force scale, with room to draw the polygons by hand).

Importing this package loads neither matplotlib nor typst: the figures are
drawn, and the PDF compiled, when a handout is rendered.

Examples
--------
>>> from graphkin import handout
>>> doc = handout.build("double_slider")
>>> doc["worked"][0]["label"]
's = 200 mm'
>>> handout.write(doc, "double_slider.pdf")  # doctest: +SKIP
"""

from __future__ import annotations

from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.files import check_destination, write_bytes
from graphkin.handout.content import DETAILS, VERSIONS, build
from graphkin.handout.html import render as page
from graphkin.handout.markdown import render as md
from graphkin.handout.typst import render as pdf

FORMATS = {".pdf": "pdf", ".html": "html", ".htm": "html", ".md": "md"}
"""File suffixes a handout can be written to, and the format each means."""


def format_of(path) -> str:
    """``"pdf"``, ``"html"`` or ``"md"`` from a file name; a clear error for anything else."""
    suffix = Path(path).suffix.lower()
    if suffix not in FORMATS:
        raise GraphkinError(f"-o {path}: a handout is written as .pdf, .html or .md, not {suffix or 'a file without a suffix'}")
    return FORMATS[suffix]


def check_output(path) -> str:
    """Check, before any work, that a handout can be written to ``path``; returns its format."""
    fmt = format_of(path)
    check_destination(path, "-o")
    return fmt


def render(doc: dict, fmt: str, *, folder: str = "figures") -> tuple[bytes, dict[str, bytes]]:
    """A handout in one format: the document's bytes and any files that go beside it (Markdown's figures).

    Parameters
    ----------
    doc : dict
        From :func:`build`.
    fmt : {"pdf", "html", "md"}
    folder : str
        For Markdown: the figures' folder, relative to the document.
    """
    if fmt == "pdf":
        return pdf(doc), {}
    if fmt == "html":
        return page(doc).encode("utf-8"), {}
    if fmt == "md":
        text, files = md(doc, folder)
        return text.encode("utf-8"), files
    raise GraphkinError(f"unknown handout format {fmt!r} (pdf, html or md)")


def write(doc: dict, path) -> list[Path]:
    """Render a handout in the format its file name asks for and write it atomically.

    Markdown's figures go in ``<stem>_figures/`` beside it, each written
    atomically too, and before the text that links them.

    Returns
    -------
    list of Path
        Every file written, the document last.
    """
    path = Path(path)
    fmt = check_output(path)
    data, files = render(doc, fmt, folder=f"{path.stem}_figures")
    written = [write_bytes(path.parent / name, content, "-o") for name, content in files.items()]
    written.append(write_bytes(path, data, "-o"))
    return written


__all__ = ["DETAILS", "FORMATS", "VERSIONS", "build", "check_output", "format_of", "render", "write"]
