"""The SVG a handout's figure is written as: each text laid out and each glyph written once, and it looks the same.

:mod:`graphkin.draw.backend_svg`, the backend handed to ``savefig``, draws with an SVG renderer that writes a haloed text's
outline once, as a definition that two ``<use>`` place, instead of writing all its vertices twice. Both
files are rasterised by typst, which typesets the handouts, and compared pixel by pixel.
"""

from __future__ import annotations

import io
import re

import numpy as np
import pytest
from matplotlib.figure import Figure

from graphkin.draw.text import halo

OURS = "module://graphkin.draw.backend_svg"

typst = pytest.importorskip("typst")
Image = pytest.importorskip("PIL.Image")


def _figure(halo=halo) -> Figure:
    fig = Figure(figsize=(3.0, 1.6), dpi=100)
    ax = fig.add_axes([0, 0, 1, 1])
    ax.set_axis_off()
    ax.set_xlim(0, 3)
    ax.set_ylim(0, 1.6)
    ax.plot([0.1, 2.9], [0.8, 0.8], color="k", lw=1.5)
    # A haloed name with Unicode subscripts, the same again rotated, a mathtext one, and a plain text.
    ax.text(0.2, 0.85, "F₂₃ = 1234.5 N", fontsize=11, color="#0072b2", path_effects=[halo()])
    ax.text(1.7, 0.2, "F₂₃ = 1234.5 N", fontsize=11, rotation=30, color="#d55e00", path_effects=[halo()])
    ax.text(0.3, 0.3, r"$\mathregular{F_{c3}}$ (cutting)", fontsize=10, path_effects=[halo()])
    ax.text(0.2, 1.3, "Velocity polygon", fontsize=10)
    return fig


def _svg(ours: bool, fig=None) -> str:
    out = io.BytesIO()
    from matplotlib import rc_context

    fig = fig or _figure()
    with rc_context({"svg.hashsalt": "test"}):
        fig.savefig(out, format="svg", backend=OURS if ours else None, metadata={"Date": None})
    return out.getvalue().decode("utf-8")


def _pixels(svg: str) -> np.ndarray:
    src = (f'#set page(width: 3in, height: 1.6in, margin: 0pt)\n'
           f'#image(bytes("{svg.replace(chr(92), chr(92) * 2).replace(chr(34), chr(92) + chr(34))}"), '
           f'format: "svg", width: 100%)')
    png = typst.Compiler(ignore_system_fonts=True).compile(input=src.encode(), format="png", ppi=300.0)
    return np.asarray(Image.open(io.BytesIO(png)).convert("L"), float)


def test_a_haloed_text_is_written_once_and_strokes_as_wide():
    svg = _svg(True)
    ids = re.findall(r'<path id="([^"]+)"', svg)
    assert len(ids) == len(set(ids))
    # One outline per string (the two haloed "F₂₃ = 1234.5 N" share theirs), each drawn twice: halo, then text.
    outlines = [i for i in ids if i.startswith("text-outline-")]
    assert len(outlines) == 2
    # (A black text's fill needs no style.)
    uses = re.findall(r'<use xlink:href="#(text-outline-\d+)" transform="matrix\(([^)]*)\)"(?: style="([^"]*)")?/>',
                      svg)
    assert sorted(u[0] for u in uses) == sorted(outlines * 2 + [outlines[0]] * 2)
    halos = [(m, st) for _, m, st in uses if "stroke: #ffffff" in st]
    assert len(halos) == 3
    for matrix, style in halos:
        a, b, c, d, _, _ = map(float, matrix.split())
        width = float(re.search(r"stroke-width: ([0-9.]+)", style)[1])
        # Back in points through the placement's scale: the halo's 2.6 pt.
        assert width * (abs(a * d - b * c) ** 0.5) == pytest.approx(2.6, rel=1e-5)
    assert len(svg) < 0.7 * len(_svg(False))


def test_the_figure_looks_the_same_as_matplotlib_writes_it():
    ours, theirs = _pixels(_svg(True)), _pixels(_svg(False))
    assert ours.shape == theirs.shape
    differ = np.abs(ours - theirs)
    # Anti-aliasing at the edges of glyphs may round the other way (32 of 255 at most, here), no more: a halo half
    # as wide, or a glyph a pixel off, changes whole pixels.
    assert differ.max() <= 64
    assert differ.mean() < 0.01
    # And there is something drawn to compare.
    assert (theirs < 128).mean() > 0.01


@pytest.mark.parametrize("text", ["F₂₃ = 1234.5 N", "θ₁₂ = 30°", "A", " ", ""])
@pytest.mark.parametrize("weight", ["normal", "bold"])
def test_a_text_outline_from_the_glyphs_laid_out_once_is_matplotlibs(text, weight):
    """The shared layout gives the vertices and codes matplotlib's own TextToPath gives, number for number."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextToPath

    from graphkin.draw.glyphs import _TEXT_TO_PATH

    prop = FontProperties(size=9, weight=weight)
    want_verts, want_codes = TextToPath().get_text_path(prop, text)
    verts, codes = _TEXT_TO_PATH.get_text_path(prop, text)
    assert np.array_equal(verts, np.asarray(want_verts, float).reshape(-1, 2))
    assert np.array_equal(codes, np.asarray(want_codes, np.uint8))
    # Shared by every figure: nobody may change them.
    assert not verts.flags.writeable and not codes.flags.writeable


def test_a_halo_drawn_in_one_call_writes_what_withstroke_writes(monkeypatch):
    """The SVG renderer draws a halo's two passes at once (``_RendererSVG.draw_haloed``): the file is the one
    matplotlib's own ``withStroke`` gives through the same renderer, byte for byte; elsewhere a halo is a
    ``withStroke``."""
    from matplotlib.patheffects import withStroke

    from graphkin.draw.backend_svg import _RendererSVG

    def stroke(width=2.6):
        return withStroke(linewidth=width, foreground="white")

    drawn = []
    plain = _RendererSVG.draw_haloed
    monkeypatch.setattr(_RendererSVG, "draw_haloed", lambda *a: drawn.append(plain(*a)) or drawn[-1])
    ours = _svg(True, _figure())
    assert drawn == [True] * 3  # each of the three haloed texts in one call
    theirs = _svg(True, _figure(halo=stroke))
    assert len(drawn) == 3
    assert ours == theirs
    assert ours.count("stroke: #ffffff") == 3
    assert isinstance(halo(), withStroke)
    # Without the SVG renderer (Agg), the same pixels as withStroke.
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    a, b = _figure(), _figure(halo=stroke)
    FigureCanvasAgg(a).draw()
    FigureCanvasAgg(b).draw()
    assert np.array_equal(np.asarray(a.canvas.buffer_rgba()), np.asarray(b.canvas.buffer_rgba()))


FORMULAS = [r"$\mathregular{a^{t}_{BA}}$ = 273.3 m/s²", r"$\mathregular{a^{t}_{BA}}$ = 9.125 m/s²",
            r"R₃ = R₃ᵢ + $\mathregular{F_{c3}}$ (cutting)", r"$x^2$ and $x^2$ and $-x_{1}$", r"$\alpha_{2} + \beta^{n}$",
            r"$a_{b}^{c}$ - $a_{b}^{c}$", r"$\sum_{i} x_i$ = $\sum_{i} x_i$"]


@pytest.mark.parametrize("math_font", ["dejavusans", "cm"])
def test_a_formula_parsed_once_lays_labels_out_as_matplotlib_does(math_font):
    """The same glyphs at the same places as matplotlib's own parser, whether the formula is new or known."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.mathtext import MathTextParser

    from graphkin.draw.glyphs import _MathTextOnce

    prop = FontProperties(size=100, math_fontfamily=math_font)
    theirs, ours = MathTextParser("path"), _MathTextOnce("path")
    for _ in range(2):  # new formulas, then the same formulas in their memo (the first formula of each twice)
        for s in FORMULAS:
            for dpi in (72, 100):
                # The caches of whole labels (matplotlib's, ours): parse each afresh.
                MathTextParser._parse_cached.cache_clear()
                _MathTextOnce._parse_cached.cache_clear()
                want, got = theirs.parse(s, dpi, prop), ours.parse(s, dpi, prop)
                assert (got.width, got.height, got.depth) == (want.width, want.height, want.depth)
                assert [g[1:] for g in got.glyphs] == [g[1:] for g in want.glyphs]
                assert [g[0].fname for g in got.glyphs] == [g[0].fname for g in want.glyphs]
                assert got.rects == want.rects
    # Each formula was parsed once per font, size and resolution, not once per label.
    memo = [k for k in _MathTextOnce._parser._memo
            if k[0] == r"$\mathregular{a^{t}_{BA}}$" and k[2].get_math_fontfamily() == math_font]
    assert sorted(k[7] for k in memo) == [72, 100]
    # And every label in this font was parsed with the one fontset made for it.
    assert len([k for k in _MathTextOnce._fontsets if k[1] == prop]) == 1


@pytest.mark.parametrize("text", ["F₂₃ = 1234.5 N", r"$\mathregular{v_{A}}$ = 5.341 m/s", "A"])
def test_the_measuring_renderer_gives_the_sizes_the_svg_prints(text):
    """Sizes [px] at 100 dpi: the SVG renderer's own [pt] times 100/72."""
    from matplotlib.backends.backend_svg import RendererSVG
    from matplotlib.font_manager import FontProperties

    from graphkin.draw.glyphs import _TEXT_TO_PATH
    from graphkin.draw.text import measuring_agg

    prop = FontProperties(size=9)
    ismath = "$" in text
    svg = RendererSVG(100, 100, io.StringIO())
    svg._text2path = _TEXT_TO_PATH
    w, h, d = svg.get_text_width_height_descent(text, prop, ismath)
    got = measuring_agg(100).get_text_width_height_descent(text, prop, ismath)
    assert got == pytest.approx((w * 100 / 72, h * 100 / 72, d * 100 / 72), rel=1e-12)
    assert min(got[:2]) > 0


def test_a_text_laid_out_once_is_laid_out_again_when_it_changes():
    """Through :mod:`graphkin.draw.backend_svg` each text's layout is kept; a text whose font, alignment, angle or
    string changes between two files is laid out anew: the second file is what a fresh figure with the changed
    text writes."""
    from matplotlib import rc_context

    from graphkin.draw import backend_svg

    def saved(fig) -> str:
        out = io.BytesIO()
        with rc_context({"svg.hashsalt": "test"}):
            fig.savefig(out, format="svg", backend=OURS, metadata={"Date": None})
        return out.getvalue().decode("utf-8")

    for change in ({"fontsize": 15}, {"ha": "right"}, {"va": "top"}, {"rotation": 45}, {"text": "F₂₃ = 99 N"},
                   {"linespacing": 2.0, "text": "two\nlines"}):
        fig = _figure()
        saved(fig)
        assert backend_svg._LAYOUTS
        for t in fig.axes[0].texts:
            t.set(**change)
        got = saved(fig)  # with the layouts of the texts before the change kept
        backend_svg._LAYOUTS.clear()
        fresh = _figure()
        for t in fresh.axes[0].texts:
            t.set(**change)
        assert got == saved(fresh), change


@pytest.mark.parametrize("text", FORMULAS)
@pytest.mark.parametrize("math_font", ["dejavusans", "cm"])
def test_a_formula_outline_from_glyphs_loaded_once_is_matplotlibs(text, math_font):
    """A formula's outline, each glyph loaded once per process, has matplotlib's vertices and codes, number for
    number, whether its glyphs are new or already loaded (a text's own in its second round)."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextToPath

    from graphkin.draw.glyphs import _TEXT_TO_PATH

    for size in (9, 10.5):
        prop = FontProperties(size=size, math_fontfamily=math_font)
        want_verts, want_codes = TextToPath().get_text_path(prop, text, ismath=True)
        verts, codes = _TEXT_TO_PATH.get_text_path(prop, text, ismath=True)
        assert np.array_equal(verts, np.asarray(want_verts, float).reshape(-1, 2))
        assert np.array_equal(codes, np.asarray(want_codes, np.uint8))
        assert len(codes) > 0


def _strings(n: int, seed: int) -> list[str]:
    """Strings such as the figures write (names with subscripts, numbers, units, angles), and any mix of them."""
    import random

    alphabet = ("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789 .,:;-−+=()[]/°′″∠·×²³"
                "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓθωαΔμ%'_|")
    rng = random.Random(seed)
    return ["".join(rng.choice(alphabet) for _ in range(rng.randint(1, 14))) for _ in range(n)]


EDGES = ["", " ", "  ", "°", " °", "° ", "‾", "_", "AV", "To", "Wa", "fi", "F₂₃ = 1311 N", "θ₁₂ = 30°", "−0.5",
         "ω₂ = 10 rad/s", "1:2000", "Velocity polygon"]


@pytest.mark.parametrize("weight", ["normal", "bold"])
@pytest.mark.parametrize("style", ["normal", "italic"])
def test_a_text_measured_from_its_layout_has_set_texts_size(weight, style):
    """A plain text's width, height and descent [pt], from the layout its outline is drawn from (one shaping, not
    two): FT2Font.set_text's, number for number and zero for zero, for any string and font size."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextToPath

    from graphkin.draw.glyphs import _TEXT_TO_PATH

    theirs = TextToPath()
    for k, text in enumerate(EDGES + _strings(300, seed=10 * len(weight) + len(style))):
        prop = FontProperties(size=[7, 8, 9, 10.5, 12][k % 5], weight=weight, style=style)
        want = theirs.get_text_width_height_descent(text, prop, False)
        got = _TEXT_TO_PATH.get_text_width_height_descent(text, prop, False)
        assert got == want, text
        assert [type(x) for x in got] == [float] * 3
        assert [np.copysign(1, x) for x in got] == [np.copysign(1, x) for x in want], text
        # And the outline of the same layout is matplotlib's.
        verts, codes = _TEXT_TO_PATH.get_text_path(prop, text)
        want_verts, want_codes = theirs.get_text_path(prop, text)
        assert np.array_equal(verts, np.asarray(want_verts, float).reshape(-1, 2)), text
        assert np.array_equal(codes, np.asarray(want_codes, np.uint8)), text


def test_a_character_no_font_has_warns_as_matplotlib_warns():
    """Measured from its layout, a text with a character that no font of its has still warns (as FT2Font.set_text
    does): the figure would show a box for it."""
    import warnings

    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextToPath

    from graphkin.draw.glyphs import _TEXT_TO_PATH

    text, prop = "F\U0001d6fc = 3 N", FontProperties(size=9)
    with warnings.catch_warnings(record=True) as theirs:
        warnings.simplefilter("always")
        want = TextToPath().get_text_width_height_descent(text, prop, False)
    with warnings.catch_warnings(record=True) as ours:
        warnings.simplefilter("always")
        got = _TEXT_TO_PATH.get_text_width_height_descent(text, prop, False)
    assert got == want
    assert [str(w.message) for w in ours] == [str(w.message) for w in theirs]
    assert "missing from font(s)" in str(ours[0].message)


def test_a_glyph_defined_from_its_kept_path_data_is_defined_as_matplotlib_defines_it():
    """A text without a halo is a ``<use>`` of each glyph; each glyph's definition, its path data kept for the
    process, is matplotlib's own, in the first file and in the next."""
    from graphkin.draw.glyphs import _GLYPH_DEFS

    def defs(svg):
        return re.findall(r'<path id="DejaVuSans-[^"]*" d="[^"]*" transform="[^"]*"/>', svg)

    theirs = defs(_svg(False))
    assert len(theirs) >= 10  # "Velocity polygon": its letters
    first, second = defs(_svg(True)), defs(_svg(True))
    assert first == theirs and second == theirs
    assert sum(data is not None for data in _GLYPH_DEFS.values()) >= len(theirs)
