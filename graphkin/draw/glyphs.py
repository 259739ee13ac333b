"""Text laid out once per process: each new string shaped once, for its size and its outline; each glyph loaded
once; each formula parsed once. :mod:`graphkin.draw.text` measures and :mod:`graphkin.draw.backend_svg` writes the
figures' text through it.

It stands on matplotlib's private API, every name of which is in :data:`graphkin.draw.matplotlib_private.TEXT`:
import it only where :data:`~graphkin.draw.matplotlib_private.FAST_TEXT` holds."""

from __future__ import annotations

import functools
import math
import os
from collections import OrderedDict
from typing import NamedTuple

import matplotlib
import numpy as np
from matplotlib import _api, _mathtext, rcParams
from matplotlib._text_helpers import warn_on_missing_glyph
from matplotlib.font_manager import FontProperties, findfont
from matplotlib.ft2font import LoadFlags
from matplotlib.mathtext import MathTextParser
from matplotlib.path import Path
from matplotlib.textpath import TextToPath

_GLYPH_DEFS: dict = {}
"""A glyph's path data in an SVG file's definitions, by the id of its vertices (arrays that :class:`_TextToPathOnce`
keeps for the process; None until first written)."""

_LAST_RESORT = os.path.realpath(os.path.join(matplotlib.get_data_path(), "fonts", "ttf", "LastResortHE-Regular.ttf"))
"""The font file matplotlib falls back on for a character no font of the text's has (it draws a box for it), as
``font_manager`` finds it."""


class _Glyph(NamedTuple):
    """A glyph as :class:`_TextToPathOnce` keeps it, its font set to FONT_SCALE at DPI."""

    name: str
    """``TextToPath._get_glyph_repr``: the glyph's id in an SVG file."""
    path: tuple
    """Its outline: vertices [font units] and codes, read-only."""
    advance: int
    """How far it moves the pen [64ths of a font unit], unhinted."""
    low: float
    high: float
    """The bottom and top of its control box [64ths of a font unit]; 0 for a glyph with no outline."""


class _TextToPathOnce(TextToPath):
    """Text laid out, and turned into outlines, once per process for every SVG renderer.

    matplotlib gives each renderer a :class:`~matplotlib.textpath.TextToPath` of its own, and the SVG
    renderer asks it for every text's size and, for a text with a halo (drawn as its outline), for the
    outline: a handout's twenty figures laid the same names (``A``, ``F₂₃``, ``0``) out twenty times, a
    tenth of a student's handout. What a text becomes depends on the string, its font properties and the
    font file they resolve to (in the key, so that a change of ``rcParams["font.*"]`` makes a new entry),
    never on the renderer. TeX text is left to matplotlib.
    """

    @staticmethod
    def _key(prop):
        # A copy: FontProperties is mutable and hashes by its state (matplotlib's own text cache does so too).
        return prop.copy(), findfont(prop)

    def get_text_width_height_descent(self, s, prop, ismath):
        if ismath == "TeX":
            return super().get_text_width_height_descent(s, prop, ismath)
        return self._size(s, *self._key(prop), ismath)

    @functools.lru_cache(8192)
    def _size(self, s, prop, font, ismath):
        if ismath:
            return super().get_text_width_height_descent(s, prop, ismath)
        # TextToPath.get_text_width_height_descent (matplotlib 3.11), its FT2Font.set_text, a shaping of the string
        # of its own, replaced by the layout that the text's outline is drawn from (:meth:`_glyphs`).
        w, h, d = self._glyphs(self._get_font(prop), s, None, None)[2]
        scale = prop.get_size_in_points() / self.FONT_SCALE
        return w / 64.0 * scale, h / 64.0 * scale, d / 64.0 * scale

    def get_text_path(self, prop, s, ismath=False, *, features=None, language=None):
        if ismath == "TeX":
            return super().get_text_path(prop, s, ismath, features=features, language=language)
        return self._outline(s, *self._key(prop), ismath, None if features is None else tuple(features), language)

    def get_glyphs_with_font(self, font, s, glyph_map=None, return_new_glyphs_only=False, *, features=None,
                             language=None):
        # Its callers (the SVG renderer's text drawn as glyphs, TextToPath.get_text_path, :meth:`_outline`) take
        # ``font`` from _get_font, which sets it to FONT_SCALE at DPI: the glyphs depend on the font and string only.
        info, paths, _ = self._glyphs(font, s, None if features is None else tuple(features), language)
        if glyph_map is None:
            glyph_map = OrderedDict()
        new = OrderedDict() if return_new_glyphs_only else glyph_map
        for glyph_repr, path in paths.items():
            if glyph_repr not in glyph_map:
                new[glyph_repr] = path
        return list(info), new, []

    @functools.lru_cache(4096)
    def _glyphs(self, font, s, features, language):
        """Each glyph of ``s`` (its name, x, y and scale), the outline of each glyph in order of first use, and the
        string's width, height and descent [64ths of a font unit] as ``FT2Font.set_text`` gives them.

        ``TextToPath.get_glyphs_with_font``, with each glyph's outline loaded once per process
        (:meth:`_glyph`) rather than once per string: ``_text_helpers.layout``, which it lays the string out
        with, loads every glyph as it goes, a third of the time of a new label. This is that function's loop
        (matplotlib 3.11) without the loading: ``FT2Font._layout`` shapes the string (libraqm) and gives each
        glyph's font, index and place. A character that no font of the text's has warns, as set_text warns.

        The size is what ``set_text`` (a second shaping of the same string) makes of the same layout: the width is
        where the pen ends, the last glyph's place plus its advance; the height and descent are those of the box
        around every glyph's control box (its outline's points) at its place, a glyph with no outline counting as
        the point where it stands, and all three are 0 for a string with no glyph. All are whole numbers of 64ths,
        so the floats here are exact (``tests/draw/test_svg_text.py`` compares them with ``set_text``'s).
        """
        info, paths = [], OrderedDict()
        low, high = math.inf, -math.inf
        known = self._GLYPHS
        for item in font._layout(s, LoadFlags.NO_HINTING, features=features, language=language):
            # Each attribute of a layout item is read once (each read makes a new Python object).
            ft_object, index, x, y = item.ft_object, item.glyph_index, item.x, item.y
            fname = ft_object.fname
            if fname == _LAST_RESORT:
                # As set_text warns, and _layout does not: no font of the text's has the character.
                warn_on_missing_glyph(ord(item.char), font.family_name)
            glyph = known.get((fname, index)) or self._glyph(ft_object, index)
            info.append((glyph.name, x, y, 1.0))
            paths.setdefault(glyph.name, glyph.path)
            low, high = min(low, glyph.low + y * 64), max(high, glyph.high + y * 64)
        if not info:
            return (), paths, (0.0, 0.0, 0.0)
        # 0.0 - low: set_text's descent of 0 is a 0, never a -0.0.
        return tuple(info), paths, (info[-1][1] * 64 + glyph.advance, high - low, 0.0 - low)

    _GLYPHS: dict = {}

    def _glyph(self, font, index) -> _Glyph:
        """A glyph's name, outline, advance and height, loaded once per process.

        Every outline is loaded with the font set to FONT_SCALE at DPI, as ``TextToPath`` loads them (a text's font
        comes so from ``_get_font``; a formula's fonts are set so before each glyph is loaded, as
        ``get_glyphs_mathtext`` does), so a glyph follows from its font file and index.
        """
        key = (font.fname, index)
        known = self._GLYPHS.get(key)
        if known is None:
            font.set_size(self.FONT_SCALE, self.DPI)
            advance = font.load_glyph(index, flags=LoadFlags.NO_HINTING).horiAdvance
            verts, codes = font.get_path()
            verts.flags.writeable = codes.flags.writeable = False  # shared by every text that uses the glyph
            _GLYPH_DEFS[id(verts)] = None  # kept for the process: its SVG definition can be kept too
            # Its control box's bottom and top: the outline's points, not the (0, 0) that closes each contour.
            ys = verts[codes != Path.CLOSEPOLY, 1] * 64
            low, high = (float(ys.min()), float(ys.max())) if len(ys) else (0.0, 0.0)
            known = self._GLYPHS[key] = _Glyph(self._get_glyph_repr(font, index), (verts, codes), advance, low, high)
        return known

    @functools.lru_cache(2048)
    def _outline(self, s, prop, font, ismath, features, language):
        # TextToPath.get_text_path's vertices from the glyphs, each loaded once (:meth:`_glyph`), a glyph at a time
        # rather than a vertex row at a time (the same numbers).
        if ismath:
            # TextToPath.get_glyphs_mathtext (matplotlib 3.11), its glyphs loaded once.
            math = prop.copy()
            math.set_size(self.FONT_SCALE)
            _, _, _, glyphs, rects = self.mathtext_parser.parse(s, self.DPI, math)
            outlines = [(self._glyph(f, i).path, size / self.FONT_SCALE, x, y) for f, size, _, i, x, y in glyphs]
            verts = [v * k + [x, y] for (v, _), k, x, y in outlines]
            codes = [c for (_, c), _, _, _ in outlines]
            for x, y, w, h in rects:
                verts.append(np.array([(x, y), (x, y + h), (x + w, y + h), (x + w, y), (x, y), (0, 0)], float))
                codes.append(np.array([Path.MOVETO] + [Path.LINETO] * 4 + [Path.CLOSEPOLY], np.uint8))
        else:
            info, paths, _ = self._glyphs(self._get_font(prop), s, features, language)
            verts = [paths[r][0] * size + [x, y] for r, x, y, size in info]
            codes = [paths[r][1] for r, _, _, _ in info]
        verts = np.concatenate(verts or [np.empty((0, 2))])
        codes = np.concatenate(codes or [np.empty(0, np.uint8)])
        # Two arrays rather than matplotlib's list of vertex rows (a tenth of the memory), read-only because
        # every figure shares them: the renderer only reads them into a Path.
        verts, codes = np.asarray(verts, float).reshape(-1, 2), np.asarray(codes, np.uint8)
        verts = verts.view(_Outline)
        verts.codes = codes
        verts.flags.writeable = codes.flags.writeable = False
        return verts, codes


class _Outline(np.ndarray):
    """The vertices of a text's outline [font units] as :class:`_TextToPathOnce` keeps them.

    Marked by their type (``Path`` keeps the array it is given), so that
    :class:`~graphkin.draw.backend_svg._RendererSVG` knows a text drawn as an outline when it is asked to draw it.
    Only the array the cache made carries ``codes``; an array computed from it (a view, a sum) is an ``_Outline``
    without them and is drawn as any path. ``svg`` is its SVG path data [font units], once it has been written.
    """


class _MathOnceParser(_mathtext.Parser):
    """matplotlib's mathtext parser, with the formula between each pair of ``$`` parsed once per process.

    A label such as ``$\\mathregular{a^{t}_{BA}}$ = 273.3 m/s²`` is new on every student's figures (its number
    is), but its formula is not, and parsing the formula is nearly all the time pyparsing takes over the label
    (~5 ms). The formula's boxes depend on its text and the parser's state where it starts (fonts, font, size,
    resolution, the pending operator space), and on the ``mathtext.*`` settings the fonts read: all in the key.
    The boxes are only read after parsing (laid out into the label's box and shipped), so the same ones can
    serve every label that holds the formula; the label is laid out as before (``tests/draw/test_svg_text.py``).
    """

    _MEMO_SIZE = 1024

    def __init__(self):
        super().__init__()
        self._memo: dict = {}

    def math_string(self, toks):
        state = self.get_state()
        fonts = state.fontset
        rc = tuple(rcParams[k] for k in _MATHTEXT_RC)
        key = (toks[0], type(fonts), fonts.default_font_prop.copy(), fonts.load_glyph_flags, state.font,
               state.font_class, state.fontsize, state.dpi, self._needs_space_after_subsuper, rc)
        known = self._memo.get(key)
        if known is None:
            boxes = super().math_string(toks)
            if len(self._memo) >= self._MEMO_SIZE:
                self._memo.clear()
            # A copy in and a copy out: pyparsing appends the tokens that follow to the list it is handed.
            self._memo[key] = (boxes.copy(), self._needs_space_after_subsuper)
            return boxes
        boxes, self._needs_space_after_subsuper = known
        self.pop_state()  # what parsing the formula does last (``Parser.math``, which pairs with ``non_math``)
        return boxes.copy()


_MATHTEXT_RC = tuple(sorted(k for k in rcParams if k.startswith("mathtext.")))


_FONT_RC = tuple(sorted(k for k in rcParams if k.startswith(("font.", "mathtext."))))


def _font_settings() -> tuple:
    """The ``font.*`` and ``mathtext.*`` settings, as a key (a list of families as a tuple)."""
    return tuple(tuple(v) if isinstance(v, list) else v for v in (rcParams[k] for k in _FONT_RC))


class _MathTextOnce(MathTextParser):
    r"""A ``MathTextParser`` whose parser is :class:`_MathOnceParser` (made on first use: it takes ~0.1 s), and whose
    fonts for a font and the font settings are made once.

    matplotlib makes the fontset (each face a formula may use, found by name: some fifty font lookups) anew for
    every string it parses, half the time of a label such as ``$\mathregular{v_{B}}$ = 5.341 m/s``. A fontset
    only finds things (faces, glyph metrics) and keeps what it found; what a parse builds goes into the parse's
    own output, so one fontset serves every parse with the same font, flags and ``font.*``/``mathtext.*``
    settings (in the key).
    """

    _parser = None
    _fontsets: dict = {}

    @functools.lru_cache(1024)
    def _parse_cached(self, s, dpi, prop, antialiased, load_glyph_flags):
        # MathTextParser._parse_cached (matplotlib 3.11), with the parser and the fontset kept; more labels kept than
        # its 50, so that a label measured to place it is not parsed again when its file draws it.
        if _MathTextOnce._parser is None:
            _MathTextOnce._parser = _MathOnceParser()
        if prop is None:
            prop = FontProperties()
        fontset_class = _api.getitem_checked(self._font_type_mapping, fontset=prop.get_math_fontfamily())
        # A copy of the font: FontProperties can be changed in place, and hashes by its state.
        key = (fontset_class, prop.copy(), load_glyph_flags, _font_settings())
        fontset = self._fontsets.get(key)
        if fontset is None:
            if len(self._fontsets) >= 64:
                self._fontsets.clear()
            fontset = self._fontsets[key] = fontset_class(key[1], load_glyph_flags)
        box = self._parser.parse(s, fontset, prop.get_size_in_points(), dpi)
        output = _mathtext.ship(box)
        if self._output_type == "vector":
            return output.to_vector()
        return output.to_raster(antialiased=antialiased)


_TEXT_TO_PATH = _TextToPathOnce()
_TEXT_TO_PATH.mathtext_parser = _MathTextOnce("path")
