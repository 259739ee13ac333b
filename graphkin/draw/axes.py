"""Axes and the cheap artists on them: the result container, headless panels, lines, markers, limits."""

from __future__ import annotations

from contextlib import contextmanager

import numpy as np
from matplotlib import rcParams
from matplotlib.axes import Axes
from matplotlib.axis import XAxis, YAxis
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.transforms import TransformedPatchPath

MM = 1e3
"""Metres to millimetres: every mechanism drawing is in mm."""
PT_PER_MM = 72 / 25.4
"""Typographic points per millimetre of paper."""


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
    labeler : graphkin.draw.labels.Labeler or None
        The drawing's labels, when they are left to be placed once the figure is laid out (:func:`finish`).
    """

    def __init__(self, ax):
        super().__init__()
        self.ax = ax
        self.arrows: dict = {}
        self.labels: dict = {}
        self.ends: dict = {}
        self.scale = None
        self.labeler = None

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

    def clear(self):
        # The title sits at the top of the axes (y = 1): no panel puts tick labels above its axes. With the
        # position fixed, matplotlib no longer measures every tick label at each draw to place the title
        # above them (a tenth of drawing a handout's figure with a title). The one setting is swapped by hand:
        # rc_context copies all of rcParams, a sixth of making the axes.
        titley = rcParams["axes.titley"]
        rcParams["axes.titley"] = 1.0
        try:
            super().clear()
        finally:
            rcParams["axes.titley"] = titley

    def _init_axis(self):
        self.xaxis = _XAxis(self, clear=False)
        self.spines.bottom.register_axis(self.xaxis)
        self.spines.top.register_axis(self.xaxis)
        self.yaxis = _YAxis(self, clear=False)
        self.spines.left.register_axis(self.yaxis)
        self.spines.right.register_axis(self.yaxis)


class BareAxes(PanelAxes):
    """Panel axes that never show an axis (a drawing printed at a scale): no spines, and a tick formatter that is
    never asked to print.

    Making a panel's spines (four patches) and its tick formatters (matplotlib's checks whether the font has a
    minus sign for each, a font lookup) was a third of making the axes, and a handout's figure has up to nine.
    Turned on, the axis shows no frame, and its offset text would be set in mathtext.

    Its view is never fitted to the data (autoscaling is off from the start): every drawing on such a panel sets
    its limits from what it drew (:func:`set_limits`), so the lines and patches it adds need not be merged into
    data limits on the way (:func:`follows_data`).
    """

    def _gen_axes_spines(self, locations=None, offset=0.0, units="inches"):
        return {}

    # A tick (made only when asked for: a walk over the artists, ``findobj``) sits where a spine at its default
    # place would put it, which is the axis's own transform.
    def get_xaxis_transform(self, which="grid"):
        return self._xaxis_transform

    def get_yaxis_transform(self, which="grid"):
        return self._yaxis_transform

    def _init_axis(self):
        self.xaxis = _XAxis(self, clear=False)
        self.yaxis = _YAxis(self, clear=False)

    def clear(self):
        # With mathtext asked for, the ScalarFormatter made for each axis skips its font check (its output is never
        # drawn here). Swapped by hand, as PanelAxes swaps the title's position.
        mathtext = rcParams["axes.formatter.use_mathtext"]
        rcParams["axes.formatter.use_mathtext"] = True
        try:
            super().clear()
        finally:
            rcParams["axes.formatter.use_mathtext"] = mathtext
        self.set_autoscale_on(False)


def new_axes(ax=None, figsize=(6.0, 4.5), s=None, *, bare=False):
    """``ax``, or a fresh axes on a new headless Figure (a :class:`BareAxes` if ``bare``: a drawing that sets its
    own limits and never shows an axis)."""
    if ax is not None:
        return ax
    fig = Figure(figsize=figsize, dpi=100)
    return fig.add_subplot(axes_class=BareAxes if bare else PanelAxes)


def setup_axes(ax):
    """Textbook look: no frame, no ticks, equal scale in x and y."""
    ax.set_aspect("equal", adjustable="box")
    ax.set_axis_off()


def line(ax, x, y, **props):
    """A Line2D on ``ax`` through the points (x, y), as ``ax.plot(x, y, **props)`` draws it; returns it.

    ``props`` are Line2D properties and their short names (``lw``, ``ms``,
    ``mfc``); give ``color`` (there is no colour cycle). Faster than
    ``ax.plot``: no format-string parsing, and the points join the data
    limits directly instead of through the line's transformed path (and
    not at all on axes whose view is fixed: see :func:`follows_data`).
    """
    x = np.atleast_1d(np.asarray(x, float))
    y = np.atleast_1d(np.asarray(y, float))
    artist = Line2D(x, y, **props)
    _add(ax, artist)
    if x.size and follows_data(ax):
        ax.update_datalim(np.column_stack([x, y]))
        # As ax.plot does: the view follows the data at the next draw (unless the limits were set).
        request = getattr(ax, "_request_autoscale_view", None)
        request() if request is not None else ax.autoscale_view()
    return artist


def markers(ax, x, y, marker="o", **props):
    """Markers at the points (x, y) and no line between them: ``ax.plot(x, y, "o", **props)``."""
    return line(ax, x, y, linestyle="none", marker=marker, **props)


def put(ax, patch, points):
    """Add a patch to ``ax``, with ``points`` (data coordinates) as its extent in the data limits; returns it.

    ``ax.add_patch`` finds a FancyArrowPatch's extent by laying its arrow out
    in display coordinates, most of the cost of drawing one; the arrow's
    ends are extent enough.
    """
    _add(ax, patch)
    if follows_data(ax):
        ax.update_datalim(np.asarray(points, float).reshape(-1, 2))
    return patch


def follows_data(ax) -> bool:
    """Whether the view of ``ax`` is fitted to its data at the next draw (autoscaling on in x or y).

    Only then are data limits worth keeping up to date. Axes whose view was
    fixed (the explorer's panels, redrawn in place with their limits set by
    each drawing; any axes a drawing has set the limits of) skip it: merging
    the points into the limits was a tenth of an explorer update. On such
    axes, call ``ax.relim()`` before ``ax.autoscale()`` to fit the view to
    everything drawn.
    """
    return ax.get_autoscalex_on() or ax.get_autoscaley_on()


def _add(ax, artist):
    """``ax.add_artist(artist)``, clipped to the axes by their box rather than by a path.

    The axes are a rectangle, so a clip box cuts the same pixels as the
    axes patch would, and costs less in every backend: Agg clips to a
    rectangle without rasterising a path, and SVG writes one ``clipPath``
    per box instead of naming each artist's transformed path (matplotlib
    prints that path's transform as text to tell them apart: a tenth of a
    handout's drawing time). The shared path keeps ``add_artist`` from
    building a fresh one first.
    """
    _clip_to(ax, artist)
    ax.add_artist(artist)
    if artist.get_clip_on():
        artist.set_clip_path(None)
        artist.set_clip_box(ax.bbox)


def _clip_to(ax, artist):
    """Clip ``artist`` to the axes, as ``add_artist`` would, with one clip path made once per axes.

    ``add_artist`` clips each new artist to the axes patch, building a fresh
    transformed box for every one of the hundred-odd artists an explorer
    update adds; an artist that already has this path is left alone.
    """
    if artist.get_clip_on():
        artist.set_clip_path(clip_path(ax))


def clip_path(ax) -> TransformedPatchPath:
    """The axes patch as a clip path, made once per axes (see :func:`_clip_to`)."""
    patch, path = getattr(ax, "_graphkin_clip", (None, None))
    if patch is not ax.patch:
        patch, path = ax._graphkin_clip = (ax.patch, TransformedPatchPath(ax.patch))
    return path


def points_per_unit(ax, view: float) -> float:
    """Typographic points per data unit, for a view about ``view`` data units across (equal-scale axes)."""
    box = ax.bbox
    return min(box.width, box.height) / ax.figure.dpi * 72 / max(view, 1e-300)


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


def finish(ax, labeler, drawn, place: bool):
    """Place a drawing's labels now, or leave them to whoever lays the figure out.

    Labels are placed in display coordinates, so a drawing whose axes get
    their printed size afterwards (:func:`graphkin.draw.paper.arrange`)
    keeps its :class:`~graphkin.draw.labels.Labeler` on the axes and its
    :class:`Drawn`, to be placed once the axes are where they will print.
    """
    if place:
        labeler.place()
        drawn += labeler.leaders
    else:
        ax._graphkin_labeler = labeler
        ax._graphkin_drawn = drawn
        drawn.labeler = labeler
    return drawn


def fit(ax, mm_per_unit: float, margin: float = 8.0):
    """Size the figure of a lone axes so that one data unit prints ``mm_per_unit`` mm of paper.

    The axes keep their limits and get exactly the size those limits take at that scale, with ``margin`` [mm]
    of figure all round for labels that stand out; a figure saved cropped to what is drawn keeps the scale.
    """
    fig = ax.get_figure(root=True)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    w, h = abs(x1 - x0) * mm_per_unit, abs(y1 - y0) * mm_per_unit
    W, H = w + 2 * margin, h + 2 * margin
    fig.set_size_inches(W / 25.4, H / 25.4)
    ax.set_position([margin / W, margin / H, w / W, h / H])
