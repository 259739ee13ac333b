"""Text as the figures write it: subscripted names, numbers with a true minus, polar form, the input, a halo;
and text measured as the SVG files print it, laid out once per process where this matplotlib allows
(:mod:`graphkin.draw.matplotlib_private`)."""

from __future__ import annotations

import re

from matplotlib.backends.backend_agg import RendererAgg
from matplotlib.patheffects import withStroke
from matplotlib.text import Text

from graphkin import notation
from graphkin.draw import matplotlib_private

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
    """A white outline behind text, so a label stays legible where a line runs under it.

    A ``withStroke``; where :mod:`graphkin.draw.backend_svg` writes the SVG files, one that it draws in one call.
    """
    return (_Halo if matplotlib_private.FAST_TEXT else withStroke)(linewidth=width, foreground="white")


class _Halo(withStroke):
    """matplotlib's ``withStroke`` (the outline stroked, then drawn as it is) that an SVG file's renderer draws in
    one call.

    A haloed text's outline is drawn twice; through matplotlib's path effects each pass finds the outline's
    placement and style anew, a twentieth of a handout's figure.
    :meth:`graphkin.draw.backend_svg._RendererSVG.draw_haloed` writes both passes at once, the same bytes; any
    other renderer, and an outline it does not take, is drawn as ``withStroke`` draws it. A halo has no offset
    (``Stroke``'s offset is for a shadow).
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



def svg_backend() -> str | None:
    """The ``backend`` to pass to ``savefig(format="svg")``: :mod:`graphkin.draw.backend_svg`, which writes each text
    outline once and lays each text out once per process, or None (matplotlib's own) where this matplotlib lacks a
    private name it needs (:data:`~graphkin.draw.matplotlib_private.FAST_TEXT`)."""
    return "module://graphkin.draw.backend_svg" if matplotlib_private.FAST_TEXT else None


class _MeasuringAgg(RendererAgg):
    """An Agg renderer whose text sizes are those of the SVG files (see :func:`measuring_agg`)."""

    def __init__(self, width, height, dpi, text_to_path):
        super().__init__(width, height, dpi)
        self.text_to_path = text_to_path

    def get_text_width_height_descent(self, s, prop, ismath):
        if ismath == "TeX":
            return super().get_text_width_height_descent(s, prop, ismath)
        w, h, d = self.text_to_path.get_text_width_height_descent(s, prop, ismath)
        k = self.dpi / 72.0
        return w * k, h * k, d * k


def measuring_agg(dpi: float) -> RendererAgg:
    """An Agg renderer (1 × 1 px) at ``dpi`` that measures text as the SVG files lay it out.

    A headless figure's labels are measured to place them and to find the figure's extent, and its SVG file
    then lays each text out again, at 72 dpi, as unhinted outlines (a ``TextToPath``): the boxes here are those
    (its sizes [pt] times ``dpi / 72``), where Agg's own are hinted to its pixels. Where
    :data:`~graphkin.draw.matplotlib_private.FAST_TEXT` holds, they come from the SVG files' own shared cache
    (:class:`~graphkin.draw.glyphs._TextToPathOnce`), so each string is laid out once, not twice (a mathtext
    label, such as ``a^t_BA = 273.3 m/s²``, is parsed once); else from matplotlib's ``text_to_path``, the same
    numbers. Only for measuring, never for drawing.

    Parameters
    ----------
    dpi : float
        Resolution the sizes are given at [pixels per inch].
    """
    if matplotlib_private.FAST_TEXT:
        from graphkin.draw.glyphs import _TEXT_TO_PATH as text_to_path
    else:
        from matplotlib.textpath import text_to_path
    return _MeasuringAgg(1, 1, dpi, text_to_path)


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
    find the figure's extent, and names and titles come back on every figure. Where
    :data:`~graphkin.draw.matplotlib_private.FAST_TEXT` does not hold, this is ``t.get_window_extent(renderer)``.

    Parameters
    ----------
    t : matplotlib.text.Text
    renderer : RendererBase

    Returns
    -------
    matplotlib.transforms.Bbox
        In display units.
    """
    if not (matplotlib_private.FAST_TEXT and box_kept(t) and t.get_visible() and t.get_text() != ""):
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
