"""An SVG backend for ``savefig`` that writes each text outline once and lays each text out once per process.

``figure.savefig(f, format="svg", backend="module://graphkin.draw.backend_svg")`` (what
:func:`graphkin.draw.text.svg_backend` gives while :data:`~graphkin.draw.matplotlib_private.FAST_TEXT` holds) draws
the figure with :class:`_RendererSVG`, matplotlib's SVG renderer with the text of :mod:`graphkin.draw.glyphs`, and
each text of the figure laid out once per process (:func:`_layout_once`) for the time of that save: nothing of
matplotlib's is changed for any other figure or thread. The drawing is the same as matplotlib's own
(``tests/draw/test_svg_text.py`` rasterises both); the file differs only in writing each haloed text's outline
once, and the same figure always gives the same bytes. It stands on matplotlib's private API
(:data:`graphkin.draw.matplotlib_private.TEXT`): import it only where that holds.
"""

from __future__ import annotations

import codecs
from collections import OrderedDict
from types import MethodType

import numpy as np
from matplotlib import cbook
from matplotlib.backends import backend_svg
from matplotlib.backends.backend_mixed import MixedModeRenderer
from matplotlib.path import Path
from matplotlib.text import Text
from matplotlib.transforms import Affine2D

from graphkin.draw.glyphs import _GLYPH_DEFS, _TEXT_TO_PATH
from graphkin.draw.text import _laid_out_alike, _layout_key


class _RendererSVG(backend_svg.RendererSVG):
    """matplotlib's SVG renderer with the shared :class:`~graphkin.draw.glyphs._TextToPathOnce`, and each text outline
    written once.

    A text with a halo is drawn as its outline, twice (stroked white, then filled), and matplotlib writes the
    outline's every vertex into the file each time: three fifths of a handout's figure file was such copies.
    Here the outline goes once into the file's ``<defs>``, in font units, and each drawing of it is a ``<use>``
    that places it (the same matrix matplotlib applies to the vertices) with the same style, its stroke width
    divided by the placement's scale so that it strokes as wide. A text outline drawn with a clip, a dash, a
    hatch or a link is drawn as matplotlib draws it.

    Not a ``<use>`` of each glyph, as matplotlib writes a text without a halo: the file would be a third smaller
    again, but typst, which typesets the handouts, takes half as long again over it (it places each ``<use>``
    as a copy), more than the smaller file saves.
    """

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._text2path = _TEXT_TO_PATH
        self._outlines: dict = {}

    def draw_path(self, gc, path, transform, rgbFace=None):
        verts = path.vertices
        m = self._outline_matrix(gc, verts, transform.get_matrix()) if self._takes(gc, verts) else None
        if m is None:
            return super().draw_path(gc, path, transform, rgbFace)
        self._use(gc, verts, m, rgbFace)

    def _update_glyph_map_defs(self, glyph_map_new):
        """``RendererSVG._update_glyph_map_defs`` (matplotlib 3.11), each glyph's path data made once per process.

        A text drawn without a halo is a ``<use>`` of each glyph, and each file defines the glyphs it uses, its
        outline converted to path data anew for every file. A glyph that
        :class:`~graphkin.draw.glyphs._TextToPathOnce` loaded keeps its arrays for the process, and its data is kept
        with their id (``_GLYPH_DEFS``); any other is converted as matplotlib converts it.
        """
        writer = self.writer
        if glyph_map_new:
            writer.start("defs")
            for glyph_repr, (vertices, codes) in glyph_map_new.items():
                data = _GLYPH_DEFS.get(id(vertices))
                if data is None:
                    # x64 to go back to FreeType's internal (integral) units.
                    data = self._convert_path(Path(vertices * 64, codes), simplify=False)
                    if id(vertices) in _GLYPH_DEFS:
                        _GLYPH_DEFS[id(vertices)] = data
                writer.element("path", id=self._adjust_glyph_repr(glyph_repr), d=data, transform=_SIXTY_FOURTH)
            writer.end("defs")
            self._glyph_map.update(glyph_map_new)

    def draw_haloed(self, stroke, gc, path, affine, rgbFace=None) -> bool:
        """A haloed text's two passes (see :class:`graphkin.draw.text._Halo`): its outline stroked with ``stroke``,
        then drawn with ``gc``; False, having drawn nothing, if either is not a text outline this renderer writes
        as a ``<use>``.

        The same bytes as matplotlib's ``withStroke`` through :meth:`draw_path`: the stroke's placement is
        ``affine + Affine2D().translate(0, 0)`` there, a product with the identity matrix (which turns a
        ``-0.0`` into ``0.0``), and is found by that same product here.
        """
        verts = path.vertices
        if not (self._takes(stroke, verts) and self._takes(gc, verts)):
            return False
        a = affine.get_matrix()
        halo = self._outline_matrix(stroke, verts, np.dot(_NO_OFFSET, a))
        m = self._outline_matrix(gc, verts, a)
        if halo is None or m is None:
            return False
        self._use(stroke, verts, halo, rgbFace)
        self._use(gc, verts, m, rgbFace)
        return True

    def _takes(self, gc, verts) -> bool:
        """Whether a path is a text outline (:class:`~graphkin.draw.glyphs._Outline`) drawn plainly: no clip, dash, hatch, link or
        sketch."""
        return not (getattr(verts, "codes", None) is None or gc.get_url() is not None or gc.get_hatch() is not None
                    or gc.get_sketch_params() is not None or gc.get_dashes()[1] is not None
                    or self._get_clip_attrs(gc))

    def _outline_matrix(self, gc, verts, matrix):
        """The matrix that places an outline drawn with the affine ``matrix`` in the file (y down), as
        ``_make_flip_transform`` makes it; None if it flattens the outline (drawn as matplotlib draws it)."""
        m = np.dot(Affine2D().scale(1, -1).translate(0, self.height).get_matrix(), matrix)
        if not abs(m[0, 0] * m[1, 1] - m[0, 1] * m[1, 0]):
            return None
        return m

    def _use(self, gc, verts, m, rgbFace):
        """A ``<use>`` of the outline ``verts`` placed by ``m``, its definition written first if the file has none."""
        scale = abs(m[0, 0] * m[1, 1] - m[0, 1] * m[1, 0]) ** 0.5
        style = self._get_style_dict(gc, rgbFace)
        if "stroke" in style:
            style["stroke-width"] = backend_svg._short_float_fmt(gc.get_linewidth() / scale)
        # The array itself is kept with its id: an id() is unique only while its object lives.
        known = self._outlines.get(id(verts))
        if known is None:
            known = self._outlines[id(verts)] = (verts, f"text-outline-{len(self._outlines) + 1}")
            data = vars(verts).get("svg")
            if data is None:
                # In font units, written once per process and kept with the outline.
                data = verts.svg = self._convert_path(Path(verts, verts.codes), Affine2D(), simplify=False)
            self.writer.start("defs")
            self.writer.element("path", id=known[1], d=data)
            self.writer.end("defs")
        place = backend_svg._generate_transform([("matrix", (m[0, 0], m[1, 0], m[0, 1], m[1, 1], m[0, 2], m[1, 2]))])
        self.writer.element("use", attrib={"xlink:href": f"#{known[1]}"}, transform=place,
                            style=backend_svg._generate_css(style))


_SIXTY_FOURTH = backend_svg._generate_transform([("scale", (1 / 64,))])
"""A glyph definition's own placement: its path data is in 64ths of a font unit, as matplotlib writes it."""

_NO_OFFSET = Affine2D().translate(0, 0).get_matrix()
"""The matrix of a path effect's offset of (0, 0) (see :meth:`_RendererSVG.draw_haloed`)."""


_LAYOUTS: OrderedDict = OrderedDict()
_LAYOUTS_SIZE = 4096


def _layout_once(self: Text, renderer):
    """``Text._get_layout`` that, for an SVG file's renderer (:class:`_RendererSVG`), lays each text out once per
    process.

    A text's layout (its lines' sizes and offsets from its anchor, its box around the anchor) depends on its
    string, font, alignment, angle, line spacing and the resolution, never on where it stands: the same names
    and titles come back on every figure, and were laid out again for each file. A wrapped text, one turned
    with its transform or set in TeX, and any other renderer get matplotlib's own layout.
    """
    # savefig hands the SVG renderer over inside a MixedModeRenderer (which draws rasterised artists with Agg).
    if type(getattr(renderer, "_renderer", renderer)) is not _RendererSVG or not _laid_out_alike(self):
        return type(self)._get_layout(self, renderer)
    key = (*_layout_key(self), getattr(renderer, "dpi", None))
    known = _LAYOUTS.get(key)
    if known is None:
        if len(_LAYOUTS) >= _LAYOUTS_SIZE:
            _LAYOUTS.popitem(last=False)
        bbox, info, descent = type(self)._get_layout(self, renderer)
        known = _LAYOUTS[key] = (bbox.frozen(), tuple(info), descent)
    bbox, info, descent = known
    # Copies out: a caller may change the box it is given.
    return bbox.frozen(), list(info), descent


def _texts(fig):
    """The texts a figure's drawings write (the figure's, its subfigures', each axes' texts and title): not a walk
    over every artist (``findobj``), which makes each axis's ticks, twice the time of the save."""
    yield from fig.texts
    for ax in fig.axes:
        yield from ax.texts
        yield ax.title
    for sub in fig.subfigs:
        yield from _texts(sub)


class FigureCanvas(backend_svg.FigureCanvasSVG):
    """matplotlib's SVG canvas drawing with :class:`_RendererSVG`, each text laid out once per process."""

    def print_svg(self, filename, *, bbox_inches_restore=None, metadata=None, **kwargs):
        """``FigureCanvasSVG.print_svg`` (matplotlib 3.11) with :class:`_RendererSVG`; the other arguments that
        ``savefig`` hands a backend not of matplotlib's own (``dpi``, ``facecolor``, ...) are set on the figure
        already."""
        texts = [t for t in _texts(self.figure) if "_get_layout" not in vars(t)]
        with cbook.open_file_cm(filename, "w", encoding="utf-8") as fh:
            if not cbook.file_requires_unicode(fh):
                fh = codecs.getwriter("utf-8")(fh)
            dpi = self.figure.dpi
            self.figure.dpi = 72
            width, height = self.figure.get_size_inches()
            w, h = width * 72, height * 72
            renderer = MixedModeRenderer(self.figure, width, height, dpi,
                                         _RendererSVG(w, h, fh, image_dpi=dpi, metadata=metadata),
                                         bbox_inches_restore=bbox_inches_restore)
            # Each text of this figure, for this save only, laid out as :func:`_layout_once` does (an attribute of
            # the text's own, taken away after: the Text class is left alone).
            for t in texts:
                t._get_layout = MethodType(_layout_once, t)
            try:
                self.figure.draw(renderer)
            finally:
                for t in texts:
                    del t._get_layout
            renderer.finalize()
