"""matplotlib's private names that graphkin uses, every one listed here, and whether this matplotlib has them.

The figures' text is laid out once per process (:mod:`graphkin.draw.glyphs`), measured with that layout
(:func:`graphkin.draw.text.measuring_agg`, :func:`graphkin.draw.text.text_extent`, :mod:`graphkin.draw.extent`)
and written into SVG files by an SVG backend of graphkin's own (:mod:`graphkin.draw.backend_svg`): a student's
sheet and key take ~0.55 s of CPU this way and ~0.95 s through stock matplotlib (``strip_cutter_cut``,
``benchmarks/bench_handout.py --in-process``). That fast path stands on matplotlib's
private API, which changes between releases without notice (``FT2Font._layout`` is new in 3.11), so each name
it reads, calls or overrides is in :data:`TEXT`, and :data:`FAST_TEXT` says whether this matplotlib has them all.
Where one is missing, graphkin measures and writes text with stock matplotlib: the same pages, the same layout
(stock matplotlib measures the same unhinted outlines), only slower and with larger SVG files.

:data:`ELSEWHERE` lists the few private attributes of axes that the drawings and the explorer use with no
fallback (each in every matplotlib since 3.8); ``tests/draw/test_matplotlib_private.py`` checks that these lists
hold every private name graphkin's source reads from matplotlib, and that they resolve on the matplotlib installed.
"""

from __future__ import annotations

import importlib
import types

TEXT = (
    # Glyphs laid out and loaded once (graphkin.draw.glyphs).
    "matplotlib.ft2font:FT2Font._layout",
    "matplotlib.ft2font:LayoutItem",
    "matplotlib.ft2font:LoadFlags",
    "matplotlib._text_helpers:warn_on_missing_glyph",
    "matplotlib.textpath:TextToPath._get_font",
    "matplotlib.textpath:TextToPath._get_glyph_repr",
    # Formulas parsed once, fontsets made once (graphkin.draw.glyphs).
    "matplotlib._api:getitem_checked",
    "matplotlib._mathtext:Parser.math_string",
    "matplotlib._mathtext:Parser.get_state",
    "matplotlib._mathtext:Parser.pop_state",
    "matplotlib._mathtext:Parser.parse",
    "matplotlib._mathtext:Parser._needs_space_after_subsuper",
    "matplotlib._mathtext:ParserState.fontset",
    "matplotlib._mathtext:ParserState.font",
    "matplotlib._mathtext:ParserState.font_class",
    "matplotlib._mathtext:ParserState.fontsize",
    "matplotlib._mathtext:ParserState.dpi",
    "matplotlib._mathtext:Fonts.default_font_prop",
    "matplotlib._mathtext:Fonts.load_glyph_flags",
    "matplotlib._mathtext:ship",
    "matplotlib._mathtext:Output.to_vector",
    "matplotlib._mathtext:Output.to_raster",
    "matplotlib.mathtext:MathTextParser._parse_cached",
    "matplotlib.mathtext:MathTextParser._font_type_mapping",
    "matplotlib.mathtext:MathTextParser._output_type",
    "matplotlib.mathtext:MathTextParser._parser",
    # A text's box and layout kept (graphkin.draw.text, graphkin.draw.backend_svg).
    "matplotlib.text:Text._get_layout",
    "matplotlib.text:Text._get_multialignment",
    "matplotlib.text:Text._renderer",
    # A figure's extent from the kept boxes, as Figure.get_tightbbox finds it (graphkin.draw.extent).
    "matplotlib.axes._base:_AxesBase._point_in_data_domain",
    "matplotlib.transforms:BboxBase._is_finite",
    # The SVG writer (graphkin.draw.backend_svg).
    "matplotlib.backends.backend_svg:RendererSVG._text2path",
    "matplotlib.backends.backend_svg:RendererSVG._update_glyph_map_defs",
    "matplotlib.backends.backend_svg:RendererSVG._glyph_map",
    "matplotlib.backends.backend_svg:RendererSVG._adjust_glyph_repr",
    "matplotlib.backends.backend_svg:RendererSVG._convert_path",
    "matplotlib.backends.backend_svg:RendererSVG._get_clip_attrs",
    "matplotlib.backends.backend_svg:RendererSVG._get_style_dict",
    "matplotlib.backends.backend_svg:_short_float_fmt",
    "matplotlib.backends.backend_svg:_generate_transform",
    "matplotlib.backends.backend_svg:_generate_css",
    "matplotlib.backends.backend_mixed:MixedModeRenderer._renderer",
    # A halo's two passes in one call (graphkin.draw.backend_svg).
    "matplotlib.patheffects:AbstractPathEffect._offset",
    "matplotlib.patheffects:AbstractPathEffect._update_gc",
    "matplotlib.patheffects:withStroke._gc",
)
"""The fast text path's private names (and the few public ones newer than graphkin's oldest matplotlib), each as
``module:Class.attribute``."""

ELSEWHERE = (
    # Panels made without the spines and tick formatters they never show (graphkin.draw.axes).
    "matplotlib.axes._base:_AxesBase._init_axis",
    "matplotlib.axes._base:_AxesBase._gen_axes_spines",
    "matplotlib.axes._base:_AxesBase._xaxis_transform",
    "matplotlib.axes._base:_AxesBase._yaxis_transform",
    "matplotlib.axes:Axes._subclass_uses_cla",
    # Panels emptied without ax.cla() (graphkin.draw.animation, graphkin.widgets.canvas) and their titles measured
    # and placed (graphkin.draw.extent, graphkin.draw.labels, graphkin.widgets.canvas).
    "matplotlib.axes._base:_AxesBase._children",
    "matplotlib.axes._base:_AxesBase._left_title",
    "matplotlib.axes._base:_AxesBase._right_title",
    "matplotlib.axes._base:_AxesBase._autotitlepos",
    "matplotlib.axes._base:_AxesBase._update_title_position",
    # The cycle plots' tick labels as drawn (graphkin.draw.cycle).
    "matplotlib.axis:Axis._update_ticks",
)
"""Private names used with no fallback."""


def _stored_by(cls: type, name: str) -> bool:
    """Whether a function of ``cls`` or of a class it derives from names the attribute ``name`` (as ``self.name =``
    in ``__init__`` makes an instance attribute)."""
    return any(isinstance(f, types.FunctionType) and name in f.__code__.co_names
               for k in cls.__mro__ for f in vars(k).values())


def resolves(name: str) -> bool:
    """Whether ``module:Class.attribute`` is there: the module, then each attribute; the last may be one that the
    class's instances are given by its methods.

    Examples
    --------
    >>> resolves("matplotlib.text:Text._renderer"), resolves("matplotlib.text:Text._no_such_thing")
    (True, False)
    """
    module, _, path = name.partition(":")
    try:
        obj = importlib.import_module(module)
    except ImportError:
        return False
    rest = path.split(".")
    for i, attr in enumerate(rest):
        if hasattr(obj, attr):
            obj = getattr(obj, attr)
        else:
            return i == len(rest) - 1 and isinstance(obj, type) and _stored_by(obj, attr)
    return True


MISSING = tuple(name for name in TEXT if not resolves(name))
"""The names of :data:`TEXT` that this matplotlib lacks."""

FAST_TEXT = not MISSING
"""Whether text is laid out once per process and SVG files are written by :mod:`graphkin.draw.backend_svg`; else
stock matplotlib measures and writes it. Read where it is used (never copied at import), so that a test can set it."""
