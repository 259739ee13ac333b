"""Shared drawing helpers: the result container, arrows, labels that keep clear, dimensions, scale bars."""

from __future__ import annotations

import math
import re
from contextlib import contextmanager

import numpy as np
from matplotlib.axes import Axes
from matplotlib.axis import XAxis, YAxis
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import ArrowStyle, FancyArrowPatch
from matplotlib.path import Path
from matplotlib.transforms import ScaledTranslation, TransformedPatchPath

MM = 1e3
"""Metres to millimetres: every mechanism drawing is in mm."""


class Drawn(list):
    """The artists one drawing call made, in drawing order.

    A list (so ``len``, iteration and ``ax.patches`` checks work as for any
    list of artists), with named access:

    Attributes
    ----------
    ax : matplotlib.axes.Axes
        The axes drawn on (``ax.figure`` is the figure).
    arrows : dict of str to FancyArrowPatch
        Force arrows by force name (``"F23"``, ``"R3i"``, ``"T12"``).
    labels : dict of str to Text
        Labels by the name they show.
    ends : dict of str to ((x, y), (x, y))
        Tail and tip of each force arrow in data coordinates [mm].
    scale : float or None
        Force scale of the arrows [N per mm of the drawing's data units].
    """

    def __init__(self, ax):
        super().__init__()
        self.ax = ax
        self.arrows: dict = {}
        self.labels: dict = {}
        self.ends: dict = {}
        self.scale = None

    @property
    def figure(self):
        return self.ax.figure

    def _repr_png_(self):
        """Show the drawing, not the list, when it is the last value of a notebook cell."""
        import io

        buffer = io.BytesIO()
        self.ax.figure.savefig(buffer, format="png", bbox_inches="tight", facecolor="white")
        return buffer.getvalue()

    def add(self, artist):
        self.append(artist)
        return artist


class _LazyTicks:
    """An Axis that makes no tick until one is asked for.

    Matplotlib makes one tick of each kind (each a handful of lines and
    texts) while it sets an axes up, only to apply the grid and clip settings
    to them; the settings are kept for later ticks anyway. A drawing with its
    axis off never asks for a tick, and an axes made without them is ready in
    half the time. Ticks made later (the axis turned back on) get every
    setting and the clip path as usual.
    """

    @contextmanager
    def _no_new_ticks(self):
        made = [k for k in ("majorTicks", "minorTicks") if k not in vars(self)]
        for k in made:
            setattr(self, k, [])  # shadows the lazy list while the settings are stored
        try:
            yield
        finally:
            for k in made:
                if not vars(self).get(k):
                    vars(self).pop(k, None)

    def set_tick_params(self, which="major", reset=False, **kwargs):
        with self._no_new_ticks():
            super().set_tick_params(which, reset, **kwargs)

    def set_clip_path(self, path, transform=None):
        self._tick_clip = (path, transform)
        with self._no_new_ticks():
            super().set_clip_path(path, transform)

    def _get_tick(self, major):
        tick = super()._get_tick(major)
        clip = getattr(self, "_tick_clip", None)
        if clip is not None:
            tick.set_clip_path(*clip)
        return tick


class _XAxis(_LazyTicks, XAxis):
    pass


class _YAxis(_LazyTicks, YAxis):
    pass


class PanelAxes(Axes):
    """Axes whose x and y axes make their ticks only when asked (see :class:`_LazyTicks`).

    Pass as ``axes_class`` to ``Figure.add_subplot`` or ``Figure.add_axes``.
    """

    def _init_axis(self):
        self.xaxis = _XAxis(self, clear=False)
        self.spines.bottom.register_axis(self.xaxis)
        self.spines.top.register_axis(self.xaxis)
        self.yaxis = _YAxis(self, clear=False)
        self.spines.left.register_axis(self.yaxis)
        self.spines.right.register_axis(self.yaxis)


def new_axes(ax=None, figsize=(6.0, 4.5), s=None):
    """``ax``, or a fresh axes on a new headless Figure."""
    if ax is not None:
        return ax
    fig = Figure(figsize=figsize, dpi=100)
    return fig.add_subplot(axes_class=PanelAxes)


def line(ax, x, y, **props):
    """A Line2D on ``ax`` through the points (x, y), as ``ax.plot(x, y, **props)`` draws it; returns it.

    ``props`` are Line2D properties and their short names (``lw``, ``ms``,
    ``mfc``); give ``color`` (there is no colour cycle). Faster than
    ``ax.plot``: no format-string parsing, and the points join the data
    limits directly instead of through the line's transformed path.
    """
    x = np.atleast_1d(np.asarray(x, float))
    y = np.atleast_1d(np.asarray(y, float))
    artist = Line2D(x, y, **props)
    _clip_to(ax, artist)
    ax.add_artist(artist)
    if x.size:
        ax.update_datalim(np.column_stack([x, y]))
        # As ax.plot does: the view follows the data at the next draw (unless the limits were set).
        request = getattr(ax, "_request_autoscale_view", None)
        request() if request is not None else ax.autoscale_view()
    return artist


def _clip_to(ax, artist):
    """Clip ``artist`` to the axes, as ``add_artist`` would, with one clip path made once per axes.

    ``add_artist`` clips each new artist to the axes patch, building a fresh
    transformed box for every one of the hundred-odd artists an explorer
    update adds; an artist that already has this path is left alone.
    """
    if artist.get_clip_on():
        artist.set_clip_path(_clip_path(ax))


def _clip_path(ax) -> TransformedPatchPath:
    """The axes patch as a clip path, made once per axes (see :func:`_clip_to`)."""
    patch, path = getattr(ax, "_graphkin_clip", (None, None))
    if patch is not ax.patch:
        patch, path = ax._graphkin_clip = (ax.patch, TransformedPatchPath(ax.patch))
    return path


def markers(ax, x, y, marker="o", **props):
    """Markers at the points (x, y) and no line between them: ``ax.plot(x, y, "o", **props)``."""
    return line(ax, x, y, linestyle="none", marker=marker, **props)


def put(ax, patch, points):
    """Add a patch to ``ax``, with ``points`` (data coordinates) as its extent in the data limits; returns it.

    ``ax.add_patch`` finds a FancyArrowPatch's extent by laying its arrow out
    in display coordinates, most of the cost of drawing one; the arrow's
    ends are extent enough.
    """
    _clip_to(ax, patch)
    ax.add_artist(patch)
    ax.update_datalim(np.asarray(points, float).reshape(-1, 2))
    return patch


def setup_axes(ax):
    """Textbook look: no frame, no ticks, equal scale in x and y."""
    ax.set_aspect("equal", adjustable="box")
    ax.set_axis_off()


# -- text ---------------------------------------------------------------------

_NAME = re.compile(r"^([−-]?)([A-Za-z])([a-z]?\d+(?:,\d+)?[a-z]?)$")
_SUB = dict(zip("0123456789aehijklmnoprstuvx,", "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ,"))
_UNSUB = {v: k for k, v in _SUB.items() if k != ","}


def sub(name: str) -> str:
    """A force or point name with its subscript typeset: ``F23`` → ``F₂₃``, ``R3i`` → ``R₃ᵢ``, ``A0`` → ``A₀``.

    Unicode subscripts rather than mathtext: as legible, and text is laid
    out some twenty times faster. A subscript with a letter Unicode has no
    subscript for (``Fc3``: there is no subscript c) is set in upright
    mathtext instead, ``$\\mathregular{F_{c3}}$``. A leading minus (``−F23``,
    or ``-F23``) stays in front, as a true minus: ``−F₂₃``. Names that are
    not a letter and a numeric subscript (``FP``, ``O``) are returned as
    they are; anything after the first space is kept as plain text
    (``Fc3 (cutting)`` → F_c3 and `` (cutting)``).
    """
    head, sep, rest = name.partition(" ")
    m = _NAME.match(head)
    if not m:
        return name
    sign, letter, index = m.groups()
    sign = "−" if sign else ""
    if all(ch in _SUB for ch in index):
        return sign + letter + "".join(_SUB[ch] for ch in index) + sep + rest
    # Only the name goes into mathtext, so a note after it keeps the text font and plain characters.
    return sign + rf"$\mathregular{{{letter}_{{{index}}}}}$" + sep + rest


def plain(text: str) -> str:
    """Text with subscripts and mathtext markup undone: ``F₂₃ = 27 N`` → ``F23 = 27 N``.

    ``$\\mathregular{F_{c3}}$ (cutting)`` → ``Fc3 (cutting)`` too (see :func:`sub`).
    """
    text = "".join(_UNSUB.get(ch, ch) for ch in text)
    return re.sub(r"\\mathregular|[${}]|_(?=\{)", "", text)


def num(x: float, digits: int = 4) -> str:
    """A number with ``digits`` significant figures and a true minus sign."""
    if x == 0 or not math.isfinite(x):
        return "0" if x == 0 else str(x)
    return f"{x:.{digits}g}".replace("-", "−")


def polar_text(v, unit: str = "N", digits: int = 4) -> str:
    """``27.06 N ∠ −73.78°`` (the README's polar form)."""
    from ..report import polar

    size, angle = polar(v)
    if size == 0:
        return f"0 {unit}"
    return f"{num(size, digits)} {unit} ∠ {angle:.2f}°".replace("-", "−")


def input_text(construction) -> str:
    """``θ₁₂ = 30°`` for a crank, ``s = 200 mm`` for a slider driver."""
    d = construction.mechanism.driver
    if d.kind == "crank":
        return f"θ{''.join(_SUB.get(ch, ch) for ch in f'{d.frame}{d.link}')} = {num(math.degrees(construction.q), 6)}°"
    return f"s = {num(construction.q * MM, 6)} mm"


# -- forces ----------------------------------------------------------------------


def points_per_unit(ax, view: float) -> float:
    """Typographic points per data unit, for a view about ``view`` data units across (equal-scale axes)."""
    box = ax.bbox
    return min(box.width, box.height) / ax.figure.dpi * 72 / max(view, 1e-300)


def arrow(ax, tail, tip, *, color, lw, s, hollow=False, zorder=4.0, gid=None, alpha=None, pt_per_unit=None):
    """A force arrow from ``tail`` to ``tip`` (data coordinates); its head's point is at ``tip``.

    With ``pt_per_unit`` (points per data unit), the head of a short arrow is
    shrunk to at most half the arrow's length, so it never outgrows it.
    """
    head = s.head * (0.95 if hollow else 1.0)
    if pt_per_unit:
        length_pt = float(np.hypot(*(np.asarray(tip, float) - np.asarray(tail, float)))) * pt_per_unit
        head = min(head, max(length_pt * 0.5 / 0.75, 2.0))
    a = FancyArrowPatch(
        tuple(map(float, tail)), tuple(map(float, tip)),
        arrowstyle=ArrowStyle("-|>", head_length=0.75, head_width=0.3),
        mutation_scale=head, shrinkA=0, shrinkB=0, lw=lw,
        edgecolor=color, facecolor="white" if hollow else color,
        capstyle="butt", joinstyle="miter", zorder=zorder, alpha=alpha)
    if gid:
        a.set_gid(gid)
    return put(ax, a, [tail, tip])


def arc_points(centre, radius, a0, a1, n=48):
    t = np.linspace(a0, a1, n)
    return np.column_stack([centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)])


def moment_arrow(ax, centre, radius, ccw: bool, *, color, lw, s, start=-0.75 * math.pi, span=1.5 * math.pi, zorder=4.0,
                 gid=None):
    """A curved arrow of a couple around ``centre``: counter-clockwise when ``ccw``.

    Returns (patch, polyline of the arc, the point at the arc's middle).
    """
    a0, a1 = (start, start + span) if ccw else (start + span, start)
    pts = arc_points(centre, radius, a0, a1)
    a = FancyArrowPatch(path=Path(pts), arrowstyle=ArrowStyle("-|>", head_length=0.75, head_width=0.3),
                        mutation_scale=s.head, shrinkA=0, shrinkB=0, lw=lw, edgecolor=color, facecolor=color,
                        capstyle="butt", joinstyle="miter", zorder=zorder)
    if gid:
        a.set_gid(gid)
    put(ax, a, pts)
    mid = pts[len(pts) // 2]
    return a, pts, mid


def unit(v):
    v = np.asarray(v, dtype=float)
    n = float(np.hypot(*v))
    return v / n if n else np.array([1.0, 0.0])


def perp(v):
    return np.array([-v[1], v[0]], dtype=float)


# -- labels that keep clear of arrows and of each other ------------------------------


def _offset(ax, shift_pt):
    """Data coordinates, then a shift of ``shift_pt`` (x, y) typographic points."""
    return ax.transData + ScaledTranslation(float(shift_pt[0]) / 72.0, float(shift_pt[1]) / 72.0,
                                            ax.figure.dpi_scale_trans)


def offset_text(ax, text, anchor, shift_pt, **props):
    """A text ``shift_pt`` points from ``anchor`` (data coordinates), drawn even outside the axes.

    What ``ax.annotate(text, anchor, xytext=shift_pt, textcoords="offset points")``
    shows, as a plain Text: an Annotation recomputes its offset transform on
    every draw, a cost the explorer pays for each of its labels.
    """
    t = ax.text(float(anchor[0]), float(anchor[1]), text, transform=_offset(ax, shift_pt), clip_on=False,
                clip_path=_clip_path(ax), **props)
    return t


def halo(width: float = 2.6):
    """A white outline behind text, so a label stays legible where a line runs under it."""
    from matplotlib.patheffects import withStroke

    return withStroke(linewidth=width, foreground="white")


def _align(d):
    ha = "left" if d[0] > 0.2 else "right" if d[0] < -0.2 else "center"
    va = "bottom" if d[1] > 0.2 else "top" if d[1] < -0.2 else "center"
    return ha, va


def _seg_hits_box(p, q, box):
    """Does the segment p–q (display coordinates) cross the box (x0, y0, x1, y1)? Liang–Barsky clipping."""
    x0, y0, x1, y1 = box
    dx, dy = q[0] - p[0], q[1] - p[1]
    t0, t1 = 0.0, 1.0
    for pp, qq in ((-dx, p[0] - x0), (dx, x1 - p[0]), (-dy, p[1] - y0), (dy, y1 - p[1])):
        if pp == 0:
            if qq < 0:
                return False
        else:
            r = qq / pp
            if pp < 0:
                t0 = max(t0, r)
            else:
                t1 = min(t1, r)
            if t0 > t1:
                return False
    return True


_MEASURING: dict = {}


def renderer_of(fig):
    """A renderer for measuring text on ``fig``: its canvas's own, or (a headless Figure) a shared Agg one.

    Text extents depend on the resolution only, not on the size of the
    canvas, so one small Agg renderer per dpi serves every figure; and
    matplotlib caches text metrics per renderer, so a label measured once
    (``A``, ``F₂₃``, ``0``) is not laid out again on the next figure.
    """
    root = fig.get_figure(root=True) if hasattr(fig, "get_figure") else fig
    get = getattr(root.canvas, "get_renderer", None)
    if get is not None:
        return get()
    r = _MEASURING.get(root.dpi)
    if r is None:
        from matplotlib.backends.backend_agg import RendererAgg

        r = _MEASURING[root.dpi] = RendererAgg(1, 1, root.dpi)
    return r


_SIZES: dict = {}


def text_size(t, renderer) -> tuple[float, float]:
    """Width and height [px] of a text's box, measured once per string, font, angle and resolution.

    A label's size does not depend on where it is placed, and the same names
    (``A``, ``F₂₃``, ``0``) come back on every drawing; measuring through
    ``get_window_extent`` each time was the larger part of placing them.
    """
    key = (t.get_text(), hash(t.get_fontproperties()), t.get_rotation(), t.get_linespacing(), renderer.dpi)
    size = _SIZES.get(key)
    if size is None:
        if len(_SIZES) > 8192:
            _SIZES.clear()
        bb = t.get_window_extent(renderer)
        size = _SIZES[key] = (bb.width, bb.height)
    return size


_HA = {"left": 0.0, "center": 0.5, "right": 1.0}
_VA = {"bottom": 0.0, "baseline": 0.0, "center": 0.5, "center_baseline": 0.5, "top": 1.0}


def _text_box(t, renderer) -> tuple[float, float, float, float]:
    """Display box (x0, y0, x1, y1) of an unrotated text, from its cached size, anchor and alignment.

    ``get_window_extent`` lays the text out again; this is arithmetic once
    :func:`text_size` has seen the string (the axes' transforms must be final).
    """
    w, h = text_size(t, renderer)
    x, y = t.get_transform().transform(t.get_unitless_position())
    x0 = x - w * _HA.get(t.get_ha(), 0.0)
    y0 = y - h * _VA.get(t.get_va(), 0.0)
    return float(x0), float(y0), float(x0 + w), float(y0 + h)


def _hits_many(P, Q, W, boxes):
    """For each box (x0, y0, x1, y1) in ``boxes`` (n×4), how many segments P[k]–Q[k] cross it.

    Display coordinates; segment k is W[k] wide on either side. Liang–Barsky
    clipping (as :func:`_seg_hits_box`), vectorised over boxes × segments.
    """
    n = len(boxes)
    if not len(P) or not n:
        return np.zeros(n)
    lo, hi = np.minimum(P, Q) - W[:, None], np.maximum(P, Q) + W[:, None]
    bx0, by0, bx1, by1 = (boxes[:, k, None] for k in range(4))
    near = (lo[None, :, 0] <= bx1) & (hi[None, :, 0] >= bx0) & (lo[None, :, 1] <= by1) & (hi[None, :, 1] >= by0)
    if not near.any():
        return np.zeros(n)
    x0, y0, x1, y1 = bx0 - W, by0 - W, bx1 + W, by1 + W
    px, py = P[:, 0], P[:, 1]
    dx, dy = Q[:, 0] - px, Q[:, 1] - py
    t0 = np.zeros(near.shape)
    t1 = np.ones(near.shape)
    out = np.zeros(near.shape, bool)
    with np.errstate(divide="ignore", invalid="ignore"):
        for pp, qq in ((-dx, px - x0), (dx, x1 - px), (-dy, py - y0), (dy, y1 - py)):
            zero = pp == 0
            qq = np.broadcast_to(qq, near.shape)
            out |= zero & (qq < 0)
            r = qq / pp
            t0 = np.where(~zero & (pp < 0), np.maximum(t0, r), t0)
            t1 = np.where(~zero & (pp > 0), np.minimum(t1, r), t1)
    return np.count_nonzero(near & ~out & (t0 <= t1), axis=1).astype(float)


class Labeler:
    """Places labels next to their anchors on the side where they overlap nothing.

    Each label has candidate positions ``(anchor, direction, pad)``: the text
    sits ``pad`` points from ``anchor`` (data coordinates) towards
    ``direction``, aligned so that it lies wholly on that side. Obstacles are
    segments (arrows, bars, lines of action), which a label may cross at a
    price, and boxes (labels placed before, texts drawn elsewhere, a scale
    bar), which it covers only when every spot covers one.
    :meth:`place` runs once the axes limits are final.
    """

    def __init__(self, ax, s):
        self.ax, self.s = ax, s
        self.items = []
        self.segments = []
        self.boxes = []
        self.texts = []
        self.fixed = []

    def segment(self, p, q, width=0.0):
        """An obstacle segment (data coordinates), ``width`` points wide."""
        self.segments.append((np.asarray(p, float), np.asarray(q, float), float(width)))

    def polyline(self, pts, closed=False, width=0.0):
        pts = np.asarray(pts, float)
        for a, b in zip(pts[:-1], pts[1:]):
            self.segment(a, b, width)
        if closed and len(pts) > 2:
            self.segment(pts[-1], pts[0], width)

    def label(self, text, candidates, *, color=None, size=None, zorder=6.0, **kw):
        """Add a label; ``candidates`` is a list of (anchor, direction, pad [pt]), best first."""
        anchor, d, pad = candidates[0]
        d = unit(d)
        ha, va = _align(d)
        t = offset_text(self.ax, text, anchor, d * pad, ha=ha, va=va, color=color or self.s.ink,
                        fontsize=size or self.s.label_size, zorder=zorder, **kw)
        t.set_path_effects([halo()])
        self.items.append((t, candidates))
        return t

    def avoid(self, texts):
        """Texts already on the axes that the labels must not cover."""
        self.texts += list(texts)

    def box(self, x0, y0, x1, y1, pad=0.0):
        """An obstacle box in data coordinates (e.g. a text drawn elsewhere), grown by ``pad`` points all round."""
        self.boxes.append(("data", (x0, y0, x1, y1), float(pad)))

    def keep_off(self, texts):
        """Unrotated one-line texts the labels must not cover, measured by arithmetic when the labels are placed.

        As :meth:`avoid`, without laying each text out again: its size is
        cached by string (:func:`text_size`) and its box follows from its
        anchor and alignment. For texts this module draws (scale bars).
        """
        self.fixed += list(texts)

    def place(self):
        ax = self.ax
        ax.apply_aspect()
        to = ax.transData.transform
        dpi = ax.figure.dpi
        if self.segments:
            P = to(np.array([p for p, _, _ in self.segments]))
            Q = to(np.array([q for _, q, _ in self.segments]))
            W = np.array([w for _, _, w in self.segments]) * dpi / 72 / 2
        else:
            P = Q = np.zeros((0, 2))
            W = np.zeros(0)
        # The room the axes were given (an equal-scale axes may have shrunk inside it).
        from matplotlib.transforms import TransformedBbox

        axbox = TransformedBbox(ax.get_position(original=True), ax.figure.transSubfigure)
        room = np.array([axbox.x0, axbox.y0, axbox.x1, axbox.y1])
        placed = []
        for kind, b, pad in self.boxes:
            (x0, y0), (x1, y1) = to((b[0], b[1])), to((b[2], b[3]))
            g = pad * dpi / 72
            placed.append((min(x0, x1) - g, min(y0, y1) - g, max(x0, x1) + g, max(y0, y1) + g))
        scale = ax.figure.dpi / 72.0
        renderer = renderer_of(ax.figure)
        for t in self.texts:
            bb = t.get_window_extent(renderer)
            placed.append((bb.x0, bb.y0, bb.x1, bb.y1))
        placed += [_text_box(t, renderer) for t in self.fixed]
        grow = 1.5
        # Every label's candidate boxes first: a label's size does not depend on where it goes, and
        # the segments it would cross do not depend on the other labels, so one vectorised test
        # serves them all; only the overlaps with labels placed before need the loop.
        spots = []
        for t, candidates in self.items:
            w, h = text_size(t, renderer)
            n = len(candidates)
            A = to(np.array([a for a, _, _ in candidates], float).reshape(n, 2))
            D = np.array([d for _, d, _ in candidates], float).reshape(n, 2)
            norm = np.hypot(D[:, 0], D[:, 1])
            D = np.where(norm[:, None] > 0, D / np.where(norm > 0, norm, 1.0)[:, None], [1.0, 0.0])
            pads = np.array([pad for _, _, pad in candidates], float)
            XY = A + D * pads[:, None] * scale
            # _align, for every candidate: where the text's box starts relative to its anchor point.
            fx = np.where(D[:, 0] > 0.2, 0.0, np.where(D[:, 0] < -0.2, 1.0, 0.5))
            fy = np.where(D[:, 1] > 0.2, 0.0, np.where(D[:, 1] < -0.2, 1.0, 0.5))
            x0 = XY[:, 0] - w * fx
            y0 = XY[:, 1] - h * fy
            spots.append((D, pads, np.column_stack([x0 - grow, y0 - grow, x0 + w + grow, y0 + h + grow])))
        if not spots:
            return
        every = np.concatenate([boxes for _, _, boxes in spots])
        hits = np.split(10.0 * _hits_many(P, Q, W, every), np.cumsum([len(b) for _, _, b in spots])[:-1])
        outside = (np.maximum(0.0, room[0] - every[:, 0]) + np.maximum(0.0, every[:, 2] - room[2])
                   + np.maximum(0.0, room[1] - every[:, 1]) + np.maximum(0.0, every[:, 3] - room[3]))
        outside = np.split(3.0 * outside, np.cumsum([len(b) for _, _, b in spots])[:-1])
        for (t, candidates), (D, pads, boxes), hit, out in zip(self.items, spots, hits, outside):
            score = hit + out
            if placed:
                o = np.asarray(placed, float)
                overlap = ~((boxes[:, None, 2] < o[None, :, 0]) | (boxes[:, None, 0] > o[None, :, 2])
                            | (boxes[:, None, 3] < o[None, :, 1]) | (boxes[:, None, 1] > o[None, :, 3]))
                score = score + 200.0 * np.count_nonzero(overlap, axis=1)
            # The first spot, in order of preference, that covers nothing ends the search; the best so far wins.
            n = len(score)
            clean = np.flatnonzero(score == 0)
            last = int(clean[0]) + 1 if len(clean) else n
            k = int(np.argmin(score[:last] + 0.3 * np.arange(last)))
            anchor, d = candidates[k][0], D[k]
            ha, va = _align(d)
            t.set_position(tuple(map(float, anchor)))
            t.set_transform(_offset(ax, d * pads[k]))
            t.set_ha(ha)
            t.set_va(va)
            placed.append(tuple(boxes[k]))


def arrow_label_candidates(tail, tip, away, pad):
    """Candidate label spots for an arrow: beside its middle (the ``away`` side first), then beside the ends."""
    tail, tip = np.asarray(tail, float), np.asarray(tip, float)
    u = unit(tip - tail)
    n = perp(u)
    if np.dot(n, away) < 0:
        n = -n
    out = []
    for k in (1.0, 2.6):
        for t in (0.5, 0.7, 0.3, 0.85, 0.15):
            P = tail + t * (tip - tail)
            out.append((P, n, k * pad))
            out.append((P, -n, k * pad))
        out.append((tip, u, k * pad))
        out.append((tail, -u, k * pad))
    for k in (5.0, 8.0):
        for t in (0.5, 0.8, 0.2):
            P = tail + t * (tip - tail)
            out.append((P, n, k * pad))
            out.append((P, -n, k * pad))
    return out


def point_label_candidates(P, away, pad):
    """Candidate spots around a point, the ``away`` direction first, then the 8 compass directions."""
    away = unit(away) if np.hypot(*away) > 0 else np.array([0.0, 1.0])
    dirs = [away]
    for k in range(8):
        a = math.pi / 4 * k
        dirs.append(np.array([math.cos(a), math.sin(a)]))
    dirs.sort(key=lambda d: -float(np.dot(d, away)))
    return [(P, d, pad) for d in dirs]


# -- dimensions and scale bars ---------------------------------------------------------


def dimension(ax, labeler, p, q, text, *, s, small: float, color=None):
    """A dimension line between p and q with arrowheads and its text beside it.

    ``small`` [data units]: below it the arrows are drawn outside, pointing in.
    Returns the artists.
    """
    p, q = np.asarray(p, float), np.asarray(q, float)
    color = color or s.ink
    L = float(np.hypot(*(q - p)))
    out = []
    style = ArrowStyle("<|-|>", head_length=0.6, head_width=0.22)
    if L >= small:
        a = FancyArrowPatch(tuple(p), tuple(q), arrowstyle=style, mutation_scale=s.head * 0.9, shrinkA=0, shrinkB=0,
                            lw=s.thin_lw, color=color, zorder=3.5)
        put(ax, a, [p, q])
        out.append(a)
        labeler.segment(p, q)
        e = unit(q - p)
    else:
        e = unit(q - p) if L > 0 else np.array([1.0, 0.0])
        one = ArrowStyle("-|>", head_length=0.6, head_width=0.22)
        out_len = 0.8 * small
        for start, end in ((p - e * out_len, p), (q + e * out_len, q)):
            a = FancyArrowPatch(tuple(start), tuple(end), arrowstyle=one, mutation_scale=s.head * 0.9, shrinkA=0,
                                shrinkB=0, lw=s.thin_lw, color=color, zorder=3.5)
            put(ax, a, [start, end])
            out.append(a)
            labeler.segment(start, end)
        out.append(line(ax, [p[0], q[0]], [p[1], q[1]], color=color, lw=s.thin_lw, zorder=3.5))
    n = perp(e)
    mid = 0.5 * (p + q)
    cands = []
    for pad in (s.label_pad, 3 * s.label_pad, 6 * s.label_pad):
        cands += [(mid, n, pad), (mid, -n, pad), (q + e * small, e, pad), (p - e * small, -e, pad),
                  (q + e * small, n, pad), (p - e * small, n, pad), (q + e * small, -n, pad), (p - e * small, -n, pad)]
    t = labeler.label(text, cands, color=color, size=s.small_size)
    out.append(t)
    return out


def nice_round(x: float) -> float:
    """The 1–2–5 number nearest ``x`` in ratio."""
    if not x > 0:
        return 1.0
    d = 10 ** math.floor(math.log10(x))
    best = min((1, 2, 5, 10), key=lambda m: abs(math.log(m * d / x)))
    return float(best * d)


def scale_bar(ax, at, length: float, value: float, *, s, unit_text="N", tick=None, labeler=None):
    """A scale bar: a bar ``length`` data units long, starting at ``at``, reading ``0 — value N``.

    With a :class:`Labeler`, its labels keep off the bar and both numbers.
    Returns the artists.
    """
    x, y = map(float, at)
    tick = tick if tick is not None else length * 0.06
    bar = line(ax, [x, x + length], [y, y], color=s.ink, lw=1.4, solid_capstyle="butt", zorder=5)
    ticks = line(ax, [x, x, np.nan, x + length, x + length], [y - tick, y + tick, np.nan, y - tick, y + tick],
                 color=s.ink, lw=1.0, zorder=5)
    t0 = offset_text(ax, "0", (x, y), (-3, 0), ha="right", va="center", fontsize=s.small_size, color=s.ink)
    t1 = offset_text(ax, f"{num(value)} {unit_text}", (x + length, y), (3, 0), ha="left", va="center",
                     fontsize=s.small_size, color=s.ink)
    if labeler is not None:
        # Boxes, not a segment: a label may cross an arrow when it must, but it would hide the bar's reading.
        labeler.box(x, y - tick, x + length, y + tick, pad=1.0)  # the lines' half width
        labeler.keep_off([t0, t1])
    return [bar, ticks, t0, t1]


def set_limits(ax, pts, margin=0.08, existing=False):
    """Fit the view to the points (a margin around them), keeping what the axes showed before if ``existing``."""
    pts = np.asarray([p for p in pts if np.all(np.isfinite(p))], float).reshape(-1, 2)
    if not len(pts):
        return
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    size = max(float(np.max(hi - lo)), 1e-9)
    lo, hi = lo - margin * size, hi + margin * size
    if existing:
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        lo = np.minimum(lo, [x0, y0])
        hi = np.maximum(hi, [x1, y1])
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])


def had_content(ax) -> bool:
    return bool(ax.lines or ax.patches or ax.collections or ax.texts)
