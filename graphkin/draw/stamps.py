"""An Agg canvas that draws each distinct text once and stamps its pixels after that.

matplotlib's Agg backend renders text glyph by glyph on every draw. The
explorer redraws some ninety labels per update, most of them the same
strings as last time (point names, force names, scale bars), and that
rendering was its largest single cost. :class:`StampCanvas` renders each
(string, font, angle, colour) seen a second time once into a small offscreen Agg
buffer and afterwards pastes those pixels with ``draw_image``, the public
renderer call that images use. The text lands on whole pixels (at most half
a pixel from where Agg would put it), which no one can see at the
explorer's resolution.

Only the public renderer interface is used (``RendererAgg.draw_text``,
``buffer_rgba``, ``draw_image``), so a matplotlib upgrade can change how
glyphs are rendered without breaking this.
"""

from __future__ import annotations

import math
from collections import OrderedDict

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg, RendererAgg

CAPACITY = 4096
"""Stamps kept (least recently used dropped first); one label is a few kB."""

SEEN = object()
"""Cache entry of a text drawn once (stamped on its second drawing)."""


class StampRenderer(RendererAgg):
    """A RendererAgg whose plain (non-mathtext) text is drawn from a cache of rendered stamps."""

    def __init__(self, width, height, dpi, stamps: OrderedDict):
        super().__init__(width, height, dpi)
        self._stamps = stamps

    def draw_text(self, gc, x, y, s, prop, angle, ismath=False, mtext=None):
        if ismath or not s.strip():
            return super().draw_text(gc, x, y, s, prop, angle, ismath, mtext)
        rgb = tuple(gc.get_rgb())
        key = (s, hash(prop), round(float(angle), 6), rgb, gc.get_alpha(), gc.get_forced_alpha(),
               bool(gc.get_antialiased()), self.dpi)
        stamp = self._stamps.get(key)
        if stamp is None:
            # Seen once: drawn as usual. Values that change with the position ("F₂₃ = 1972 N")
            # are mostly seen once, and a stamp would only cost them an offscreen render.
            self._stamps[key] = SEEN
            self._evict()
            return super().draw_text(gc, x, y, s, prop, angle, ismath, mtext)
        if stamp is SEEN:
            stamp = self._stamps[key] = self._render(gc, s, prop, angle, mtext)
        self._stamps.move_to_end(key)
        image, left, top = stamp
        if image is None:
            return
        # Agg's text origin is measured down from the top of the canvas (its renderer flips y);
        # draw_image wants the image's lower-left corner measured up from the bottom.
        x0 = round(x) + left
        y_bottom = self.height - (round(y) + top + image.shape[0])
        self.draw_image(gc, x0, y_bottom, image)

    def _evict(self):
        while len(self._stamps) > CAPACITY:
            self._stamps.popitem(last=False)

    def _render(self, gc, s, prop, angle, mtext):
        """The text drawn alone at a whole-pixel origin: (RGBA pixels cropped to the ink, left, top) offsets."""
        # A canvas certainly larger than the text, without laying it out twice: no glyph is wider
        # than its font size and the string is one line.
        em = prop.get_size_in_points() * self.dpi / 72.0
        reach = int(math.ceil(em * (len(s) + 2)))
        if float(angle) % 360.0 == 0.0:
            width, height = reach + 4, int(math.ceil(4 * em)) + 4
            ox, oy = 2, height // 2
        else:
            width = height = 2 * reach
            ox = oy = reach
        off = RendererAgg(width, height, self.dpi)
        g = off.new_gc()
        g.copy_properties(gc)
        g.set_clip_rectangle(None)
        g.set_clip_path(None)
        RendererAgg.draw_text(off, g, ox, oy, s, prop, angle, False, mtext)
        g.restore()
        rgba = np.asarray(off.buffer_rgba())
        ink = rgba[..., 3] > 0
        if not ink.any():
            return None, 0, 0
        rows, cols = np.flatnonzero(ink.any(axis=1)), np.flatnonzero(ink.any(axis=0))
        r0, r1, c0, c1 = rows[0], rows[-1] + 1, cols[0], cols[-1] + 1
        # draw_image takes the first row as the bottom one: store the rows bottom-up.
        image = np.ascontiguousarray(rgba[r0:r1, c0:c1][::-1])
        return image, int(c0 - ox), int(r0 - oy)


class StampCanvas(FigureCanvasAgg):
    """A FigureCanvasAgg whose renderer stamps repeated text (see the module docstring)."""

    def __init__(self, figure=None):
        super().__init__(figure)
        self._stamp_cache: OrderedDict = OrderedDict()

    def get_renderer(self):
        w, h = self.get_width_height(physical=True)
        key = w, h, self.figure.dpi
        if self._lastKey != key:
            self.renderer = StampRenderer(w, h, self.figure.dpi, self._stamp_cache)
            self._lastKey = key
        return self.renderer
