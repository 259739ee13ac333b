"""The handout's figures: drawn by :mod:`graphkin.draw` when a renderer first asks, kept as SVG.

A :class:`Picture` holds a callable that returns a matplotlib figure (or a
:class:`graphkin.draw.Drawn`); nothing is drawn until a renderer asks for
:meth:`Picture.svg`, and then only once, so the PDF, the HTML and the
Markdown of one handout (or a student's sheet and key, which share their
pictures) draw each figure a single time. This module never imports
matplotlib: the drawing layer does.
"""

from __future__ import annotations

import io
import re


class Picture:
    """One figure of a handout, drawn on demand and kept as SVG text.

    Parameters
    ----------
    key : str
        A name unique within the handout (``"step-3"``); Markdown names the
        figure's file after it, HTML prefixes the SVG's ids with it.
    draw : callable
        Returns the matplotlib Figure (or a ``Drawn``/axes of one) to show.
    width : float
        Share of the text width the picture takes (0–1].
    height : float
        The most height it may take [mm]: a tall mechanism is shown smaller
        rather than filling a page.
    alt : str
        Alternative text: what the picture shows, for a reader who cannot see it.
    natural : bool
        Print the picture at its own size (a drawing at a stated scale: :mod:`graphkin.draw.paper` sized it
        for the page), never scaled to ``width`` or ``height``: a scaled drawing's stated scale would be false.
    """

    def __init__(self, key: str, draw, width: float = 1.0, alt: str = "", height: float = 80.0, natural=False):
        self.key, self.draw, self.width, self.alt, self.height = key, draw, width, alt, height
        self.natural = natural
        self._svg: str | None = None
        self._figure = None

    def __repr__(self) -> str:
        return f"Picture({self.key!r})"

    def figure(self):
        """The matplotlib Figure the picture draws, drawn on the first call (before :meth:`svg`, which lets it go).

        Returns
        -------
        matplotlib.figure.Figure
        """
        if self._figure is None:
            if self.draw is None:
                raise ValueError(f"{self!r} is drawn and kept as SVG only")
            fig = self.draw()
            fig = getattr(fig, "ax", fig)              # a Drawn
            fig = getattr(fig, "figure", fig) if not hasattr(fig, "savefig") else fig
            if hasattr(fig, "get_figure"):
                fig = fig.get_figure(root=True)
            self._figure = fig
        return self._figure

    def svg(self) -> str:
        """The figure as a standalone SVG document (text drawn as paths: no font needed to show it)."""
        if self._svg is None:
            fig = self.figure()
            from graphkin.draw.extent import drawn_extent

            # The drawing's own extent, measured with the drawing layer's shared renderer and each text's box
            # kept once laid out: bbox_inches="tight" would find the same box by drawing the whole figure once
            # more, a third of the cost of a figure.
            box = drawn_extent(fig).padded(0.04)
            out = io.BytesIO()
            # No date in the file and ids from a fixed salt (matplotlib draws them at random otherwise): the same
            # handout gives the same bytes, so a teacher can diff this year's HTML against last year's.
            from matplotlib import rc_context

            from graphkin.draw.text import svg_backend

            with rc_context({"svg.hashsalt": f"graphkin-{self.key}"}):
                fig.savefig(out, format="svg", backend=svg_backend(), bbox_inches=box, facecolor="white",
                            metadata={"Date": None})
            self._svg = out.getvalue().decode("utf-8")
            self.draw = self._figure = None  # the figure and its data can go
        return self._svg


    def size(self) -> tuple[float, float]:
        """Width and height [pt] the SVG states for itself (matplotlib writes them in points)."""
        head = self.svg()[:2000]
        w = re.search(r'<svg[^>]*\swidth="([0-9.]+)pt"', head, re.S)
        h = re.search(r'<svg[^>]*\sheight="([0-9.]+)pt"', head, re.S)
        return float(w[1]), float(h[1])


_PROLOG = re.compile(r"^\s*<\?xml[^>]*\?>\s*(<!DOCTYPE[^>]*>\s*)?", re.S)
_ID = re.compile(r'\bid="([^"]+)"')


def inline_svg(svg: str, prefix: str) -> str:
    """An SVG document made fit to sit inside HTML beside others.

    The XML prolog, the DOCTYPE and matplotlib's RDF metadata go (they name
    web addresses, and HTML needs none of them), and so do the namespace
    declarations, which HTML5 adds itself; every id gets ``prefix`` so that two figures' clip paths and
    glyphs cannot take each other's place.
    """
    svg = _PROLOG.sub("", svg)
    svg = re.sub(r"<metadata>.*?</metadata>\s*", "", svg, flags=re.S)
    svg = re.sub(r'\s+xmlns(:xlink)?="[^"]*"', "", svg)
    # A figure of several panels may name two artists alike (each polygon's "polygon:F23"): in HTML every id is
    # one element's, so a repeated name is numbered (such names are labels of artists, never referred to).
    seen: dict = {}

    def once(m):
        n = seen[m[1]] = seen.get(m[1], 0) + 1
        return m[0] if n == 1 else f'id="{m[1]}-{n}"'

    svg = _ID.sub(once, svg)
    ids = set(_ID.findall(svg))
    if ids:
        svg = _ID.sub(lambda m: f'id="{prefix}-{m[1]}"', svg)
        svg = re.sub(r'(href="#|url\(#)([^")]+)', lambda m: m[1] + (f"{prefix}-{m[2]}" if m[2] in ids else m[2]), svg)
    return svg.strip()
