"""Text as the figures write it: subscripted names, numbers with a true minus, polar form, the input, a halo;
and text measured and written into SVG files as laid out once per process (:mod:`graphkin.draw.glyphs`)."""

from __future__ import annotations

import re
import threading
from collections import OrderedDict
from contextlib import contextmanager

import numpy as np
from matplotlib.backends import backend_svg
from matplotlib.backends.backend_agg import RendererAgg
from matplotlib.path import Path
from matplotlib.patheffects import withStroke
from matplotlib.text import Text
from matplotlib.transforms import Affine2D

from graphkin import notation
from graphkin.draw.glyphs import _GLYPH_DEFS, _TEXT_TO_PATH

_NAME = re.compile(r"^([−-]?)([A-Za-z])([a-z]?\d+(?:,\d+)?[a-z]?)([′″‴⁗]|⁽[⁰¹²³⁴⁵⁶⁷⁸⁹]+⁾)?$")
SUBSCRIPTS = dict(zip("0123456789aehijklmnoprstuvx,", "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ,"))
"""Characters that Unicode has a subscript for, and that subscript."""
_UNSUB = {v: k for k, v in SUBSCRIPTS.items() if k != ","}


def subscript(text: str) -> str:
    """Every character of ``text`` as a subscript where Unicode has one: ``12`` → ``₁₂``."""
    return "".join(SUBSCRIPTS.get(ch, ch) for ch in text)


def sub(name: str) -> str:
    """A force or point name with its subscript typeset: ``F23`` → ``F₂₃``, ``R3i`` → ``R₃ᵢ``, ``A0`` → ``A₀``.

    Unicode subscripts rather than mathtext: as legible, and text is laid
    out some twenty times faster. A subscript with a letter Unicode has no
    subscript for (``Fc3``: there is no subscript c) is set in upright
    mathtext instead, ``$\\mathregular{F_{c3}}$``. A leading minus (``−F23``,
    or ``-F23``) stays in front, as a true minus: ``−F₂₃``; a sub-problem's
    mark stays behind: ``F23″`` → ``F₂₃″``. Names that are
    not a letter and a numeric subscript (``FP``, ``O``) are returned as
    they are; anything after the first space is kept as plain text
    (``Fc3 (cutting)`` → F_c3 and `` (cutting)``).
    """
    head, sep, rest = name.partition(" ")
    m = _NAME.match(head)
    if not m:
        return name
    sign, letter, index, mark = m.groups()
    sign = "−" if sign else ""
    mark = mark or ""
    if all(ch in SUBSCRIPTS for ch in index):
        return sign + letter + subscript(index) + mark + sep + rest
    # Only the name goes into mathtext, so a note after it keeps the text font and plain characters.
    return sign + rf"$\mathregular{{{letter}_{{{index}}}}}$" + mark + sep + rest


_VECTOR = re.compile(r"^([va])(?:\^([ntcr]))?_([A-Za-z0-9]+)$")
_IMAGE = re.compile(r"^([a-z])(\d*)([′″]*)$")


def motion_name(name: str) -> str:
    r"""A name of the velocity and acceleration polygons as the books print it.

    A vector's subscript and superscript are set (``a^t_BA`` → a with t above and BA below, ``v_B3B2`` → v with
    B3B2 below), in upright mathtext: Unicode has no subscript capitals. An image point's number is a
    subscript (``g3`` → ``g₃``, ``c3′`` → ``c₃′``). Anything else is returned as it is.

    Examples
    --------
    >>> print(motion_name("a^t_BA"), motion_name("v_A"), motion_name("g3"), motion_name("o′"))
    $\mathregular{a^{t}_{BA}}$ $\mathregular{v_{A}}$ g₃ o′
    """
    m = _VECTOR.match(name)
    if m:
        letter, sup, index = m.groups()
        return rf"$\mathregular{{{letter}{f'^{{{sup}}}' if sup else ''}_{{{index}}}}}$"
    m = _IMAGE.match(name)
    if m:
        letter, number, mark = m.groups()
        return letter + subscript(number) + mark
    return name


def plain(text: str) -> str:
    """Text with subscripts and mathtext markup undone: ``F₂₃ = 27 N`` → ``F23 = 27 N``.

    ``$\\mathregular{F_{c3}}$ (cutting)`` → ``Fc3 (cutting)`` too (see :func:`sub`).
    """
    text = "".join(_UNSUB.get(ch, ch) for ch in text)
    return re.sub(r"\\mathregular|[${}]|[_^](?=\{)", "", text)


def input_text(construction) -> str:
    """``θ₁₂ = 30°`` for a crank, ``s = 200 mm`` for a slider driver."""
    d = construction.mechanism.driver
    crank = d.crank
    return notation.input_text(construction.q, crank, f"θ{subscript(f'{d.frame}{d.link}')}" if crank else "s")


def halo(width: float = 2.6):
    """A white outline behind text, so a label stays legible where a line runs under it."""
    return _Halo(linewidth=width, foreground="white")


class _Halo(withStroke):
    """matplotlib's ``withStroke`` (the outline stroked, then drawn as it is) that an SVG file's renderer draws in
    one call.

    A haloed text's outline is drawn twice; through matplotlib's path effects each pass finds the outline's
    placement and style anew, a twentieth of a handout's figure. :meth:`_RendererSVG.draw_haloed` writes both
    passes at once, the same bytes; any other renderer, and an outline it does not take, is drawn as
    ``withStroke`` draws it. A halo has no offset (``Stroke``'s offset is for a shadow).
    """

    def draw_path(self, renderer, gc, tpath, affine, rgbFace):
        # A MixedModeRenderer (savefig's, around the SVG renderer) hands attributes on to the renderer it holds.
        draw_haloed = getattr(renderer, "draw_haloed", None)
        if draw_haloed is None or self._offset != (0, 0):
            return super().draw_path(renderer, gc, tpath, affine, rgbFace)
        # The stroke's graphics context as Stroke.draw_path makes it.
        stroke = renderer.new_gc()
        stroke.copy_properties(gc)
        stroke = self._update_gc(stroke, self._gc)
        try:
            if draw_haloed(stroke, gc, tpath, affine, rgbFace):
                return
        finally:
            stroke.restore()
        super().draw_path(renderer, gc, tpath, affine, rgbFace)


class _MeasuringAgg(RendererAgg):
    """An Agg renderer whose text sizes are those of the SVG files (see :func:`measuring_agg`)."""

    def get_text_width_height_descent(self, s, prop, ismath):
        if ismath == "TeX":
            return super().get_text_width_height_descent(s, prop, ismath)
        w, h, d = _TEXT_TO_PATH.get_text_width_height_descent(s, prop, ismath)
        k = self.dpi / 72.0
        return w * k, h * k, d * k


def measuring_agg(dpi: float) -> RendererAgg:
    """An Agg renderer (1 × 1 px) at ``dpi`` that measures text as the SVG files lay it out.

    A headless figure's labels are measured to place them and to find the figure's extent, and its SVG file
    then lays each text out again, at 72 dpi, through :class:`~graphkin.draw.glyphs._TextToPathOnce`. Measured
    here through that same shared cache (its sizes [pt] times ``dpi / 72``), each string is laid out once, not twice (a mathtext
    label, such as ``a^t_BA = 273.3 m/s²``, is parsed once): the boxes are the unhinted outlines the file
    prints, where Agg's own are hinted to its pixels. Only for measuring, never for drawing.

    Parameters
    ----------
    dpi : float
        Resolution the sizes are given at [pixels per inch].
    """
    return _MeasuringAgg(1, 1, dpi)


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
        """A haloed text's two passes (see :class:`_Halo`): its outline stroked with ``stroke``, then drawn with
        ``gc``; False, having drawn nothing, if either is not a text outline this renderer writes as a ``<use>``.

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


_BOXES: dict = {}
_BOXES_SIZE = 8192


def _laid_out_alike(t) -> bool:
    """Whether a text's layout follows from :func:`_layout_key` alone: not wrapped, not turned with its
    transform, not in TeX."""
    return not (t.get_wrap() or t.get_transform_rotates_text() or t.get_usetex())


def _layout_key(t) -> tuple:
    """What a text's layout around its anchor depends on: its string, font, angle, alignment, line spacing and
    the figure's resolution (never where it stands)."""
    # A copy of the font: FontProperties can be changed in place, and hashes by its state.
    return (t.get_text(), t.get_fontproperties().copy(), t.get_rotation(), t.get_rotation_mode(), t.get_ha(),
            t.get_va(), t._get_multialignment(), t.get_linespacing(), t.get_parse_math(), t.get_figure(root=True).dpi)


def box_kept(t) -> bool:
    """Whether a text's box can be kept (:func:`text_extent`): a Text (not an annotation, which moves as it is
    measured), not wrapped, not turned with its transform, not in TeX."""
    return type(t) is Text and _laid_out_alike(t)


def text_extent(t, renderer):
    """``t.get_window_extent(renderer)``, with the text's box around its anchor laid out once per process.

    A text's box depends on its string, font, alignment, angle, line spacing and the resolution, never on where
    it stands: the box is kept under those and moved to the text's anchor, the same numbers added in the same
    order as matplotlib adds them (the same box to the last bit). Labels are measured to place them and again to
    find the figure's extent, and names and titles come back on every figure.

    Parameters
    ----------
    t : matplotlib.text.Text
    renderer : RendererBase

    Returns
    -------
    matplotlib.transforms.Bbox
        In display units.
    """
    if not (box_kept(t) and t.get_visible() and t.get_text() != ""):
        return t.get_window_extent(renderer)
    t._renderer = renderer
    key = (*_layout_key(t), type(renderer), getattr(renderer, "dpi", None))
    box = _BOXES.get(key)
    if box is None:
        if len(_BOXES) >= _BOXES_SIZE:
            _BOXES.clear()
        box = _BOXES[key] = t._get_layout(renderer)[0].frozen()
    x, y = t.get_unitless_position()
    x, y = t.get_transform().transform((x, y))
    return box.translated(x, y)


_LAYOUTS: OrderedDict = OrderedDict()
_LAYOUTS_SIZE = 4096


def _layout_once(plain_layout):
    """``Text._get_layout`` that, for an SVG file's renderer (:class:`_RendererSVG`), lays each text out once per
    process.

    A text's layout (its lines' sizes and offsets from its anchor, its box around the anchor) depends on its
    string, font, alignment, angle, line spacing and the resolution, never on where it stands: the same names
    and titles come back on every figure, and were laid out again for each file. A wrapped text, one turned
    with its transform or set in TeX, and any other renderer get matplotlib's own layout.
    """

    def _get_layout(self, renderer):
        # savefig hands the SVG renderer over inside a MixedModeRenderer (which draws rasterised artists with Agg).
        if type(getattr(renderer, "_renderer", renderer)) is not _RendererSVG or not _laid_out_alike(self):
            return plain_layout(self, renderer)
        key = (*_layout_key(self), getattr(renderer, "dpi", None))
        known = _LAYOUTS.get(key)
        if known is None:
            if len(_LAYOUTS) >= _LAYOUTS_SIZE:
                _LAYOUTS.popitem(last=False)
            bbox, info, descent = plain_layout(self, renderer)
            known = _LAYOUTS[key] = (bbox.frozen(), tuple(info), descent)
        bbox, info, descent = known
        # Copies out: a caller may change the box it is given.
        return bbox.frozen(), list(info), descent

    return _get_layout


_SWAP = threading.RLock()


@contextmanager
def svg_text_laid_out_once():
    """While in the block, SVG files that matplotlib writes lay each text out once per process.

    ``savefig(format="svg")`` makes its renderer by the name ``RendererSVG`` in matplotlib's SVG backend and
    offers no way to pass one; the name points at :class:`_RendererSVG` for the block, and a text's layout for it is
    kept (:func:`_layout_once`). The drawing is the same
    (``tests/draw/test_svg_text.py`` rasterises both); the file differs only in writing each haloed text's
    outline once (see :class:`_RendererSVG`), and the same figure always gives the same bytes.
    """
    with _SWAP:  # two threads saving at once must not put each other's name back
        plain, layout = backend_svg.RendererSVG, Text._get_layout
        backend_svg.RendererSVG = _RendererSVG
        Text._get_layout = _layout_once(layout)
        try:
            yield
        finally:
            backend_svg.RendererSVG = plain
            Text._get_layout = layout
