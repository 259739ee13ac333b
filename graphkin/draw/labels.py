"""Labels that keep clear: text offset from an anchor, its measured box, and the Labeler that picks each spot.

The Labeler knows what a label must not cover (outlines and arrows, marks,
other texts) and what it may cross at a small price (dashed lines of
action), tries each label's candidate spots in order of preference and keeps
the first that covers nothing. Sizes are measured once per string with a
shared renderer (:func:`measuring_renderer`).
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.transforms import ScaledTranslation, TransformedBbox

from graphkin.draw import matplotlib_private
from graphkin.draw.arrows import perp, unit
from graphkin.draw.axes import clip_path, line
from graphkin.draw.text import halo, measuring_agg, text_extent

TEXT_COST = 400.0
"""Price of a label's box on another text's box: never, unless every spot does."""
HARD_COST = 100.0
"""Price of a label on an outline, an arrow or a mark (pins, scale bars)."""
SOFT_COST = 4.0
"""Price of a label across a dashed line (a line of action, a centre line): its halo keeps it legible."""
OUTSIDE_COST = 3.0
"""Price per pixel of a label outside the room its axes were given."""
OFF_PAGE_COST = 60.0
"""Price per pixel of a label outside the figure (cut off in the explorer's image)."""
LEADER_COST = 40.0
"""Price of a label put away from its anchor, with a leader line: worth it rather than covering an outline."""
ASTRAY_COST = 60.0
"""Price of a vector's label nearer another arrow than its own: it reads as that arrow's name. Dearer than a
leader line, which ties the label to its arrow."""
ASTRAY_MARGIN = 4.0
"""How much nearer [px] its own arrow than any other a vector's label must be: the Labeler sees an arrow as its
line and its head's width, the measure in tests/draw/test_polygon_labels.py reads the head as drawn."""
GROW = 1.5
"""Margin [px] around each label's box while placing it."""


def _offset(ax, shift_pt, base=None):
    """Data coordinates (or ``base``, another transform to display), then a shift of ``shift_pt`` (x, y)
    typographic points."""
    return (ax.transData if base is None else base) + ScaledTranslation(
        float(shift_pt[0]) / 72.0, float(shift_pt[1]) / 72.0, ax.figure.dpi_scale_trans)


def offset_text(ax, text, anchor, shift_pt, *, base=None, **props):
    """A text ``shift_pt`` points from ``anchor`` (data coordinates, or those of the transform ``base``), drawn
    even outside the axes.

    What ``ax.annotate(text, anchor, xytext=shift_pt, textcoords="offset points")``
    shows, as a plain Text: an Annotation recomputes its offset transform on
    every draw, a cost the explorer pays for each of its labels.
    """
    return ax.text(float(anchor[0]), float(anchor[1]), text, transform=_offset(ax, shift_pt, base), clip_on=False,
                   clip_path=clip_path(ax), **props)


def _align(d):
    ha = "left" if d[0] > 0.2 else "right" if d[0] < -0.2 else "center"
    va = "bottom" if d[1] > 0.2 else "top" if d[1] < -0.2 else "center"
    return ha, va


def segment_hits_box(p, q, box) -> bool:
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


def measuring_renderer(fig):
    """A renderer for measuring text on ``fig``: its canvas's own, or (a headless Figure) a shared Agg one.

    Text extents depend on the resolution only, not on the size of the
    canvas, so one small Agg renderer per dpi serves every figure; and
    matplotlib caches text metrics per renderer, so a label measured once
    (``A``, ``F₂₃``, ``0``) is not laid out again on the next figure. The
    shared renderer measures text as the SVG files lay it out
    (:func:`graphkin.draw.text.measuring_agg`).
    """
    root = fig.get_figure(root=True) if hasattr(fig, "get_figure") else fig
    get = getattr(root.canvas, "get_renderer", None)
    if get is not None:
        return get()
    # By the text path too, so that a renderer made while the fast one held is not used where it does not.
    key = (root.dpi, matplotlib_private.FAST_TEXT)
    r = _MEASURING.get(key)
    if r is None:
        r = _MEASURING[key] = measuring_agg(root.dpi)
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
        bb = text_extent(t, renderer)
        size = _SIZES[key] = (bb.width, bb.height)
    return size


_HA = {"left": 0.0, "center": 0.5, "right": 1.0}
_VA = {"bottom": 0.0, "baseline": 0.0, "center": 0.5, "center_baseline": 0.5, "top": 1.0}


def text_box(t, renderer) -> tuple[float, float, float, float]:
    """Display box (x0, y0, x1, y1) of an unrotated text, from its cached size, anchor and alignment.

    ``get_window_extent`` lays the text out again; this is arithmetic once
    :func:`text_size` has seen the string (the axes' transforms must be final).
    """
    w, h = text_size(t, renderer)
    x, y = t.get_transform().transform(t.get_unitless_position())
    x0 = x - w * _HA.get(t.get_ha(), 0.0)
    y0 = y - h * _VA.get(t.get_va(), 0.0)
    return float(x0), float(y0), float(x0 + w), float(y0 + h)


def _hits_many(P, Q, W, C, boxes):
    """For each box (x0, y0, x1, y1) in ``boxes`` (n×4), the summed price C[k] of the segments P[k]–Q[k] it meets.

    Display coordinates; segment k is W[k] wide on either side. Liang–Barsky
    clipping (as :func:`segment_hits_box`), vectorised over the box–segment pairs whose extents meet.
    """
    n = len(boxes)
    b, k = _hit_pairs(P, Q, W, boxes)
    return np.bincount(b, weights=C[k], minlength=n) if len(b) else np.zeros(n)


def _hit_pairs(P, Q, W, boxes):
    """The pairs (box b, segment k) where segment P[k]–Q[k], W[k] wide on either side, meets box b: two index
    arrays (see :func:`_hits_many`)."""
    none = np.zeros(0, int)
    if not len(P) or not len(boxes):
        return none, none
    lo, hi = np.minimum(P, Q) - W[:, None], np.maximum(P, Q) + W[:, None]
    bx0, by0, bx1, by1 = (boxes[:, k, None] for k in range(4))
    near = (lo[None, :, 0] <= bx1) & (hi[None, :, 0] >= bx0) & (lo[None, :, 1] <= by1) & (hi[None, :, 1] >= by0)
    # Only the pairs whose extents meet are clipped: a box is near a few of the segments.
    b, k = np.nonzero(near)
    if not len(b):
        return none, none
    w = W[k]
    x0, y0, x1, y1 = boxes[b, 0] - w, boxes[b, 1] - w, boxes[b, 2] + w, boxes[b, 3] + w
    px, py = P[k, 0], P[k, 1]
    dx, dy = Q[k, 0] - px, Q[k, 1] - py
    t0 = np.zeros(len(b))
    t1 = np.ones(len(b))
    out = np.zeros(len(b), bool)
    with np.errstate(divide="ignore", invalid="ignore"):
        for pp, qq in ((-dx, px - x0), (dx, x1 - px), (-dy, py - y0), (dy, y1 - py)):
            zero = pp == 0
            out |= zero & (qq < 0)
            r = qq / pp
            t0 = np.where(~zero & (pp < 0), np.maximum(t0, r), t0)
            t1 = np.where(~zero & (pp > 0), np.minimum(t1, r), t1)
    hit = ~out & (t0 <= t1)
    return b[hit], k[hit]


def _box_overlaps(boxes, others, costs):
    """For each candidate box, the summed price of the ``others`` boxes it overlaps."""
    if not len(others):
        return np.zeros(len(boxes))
    o = np.asarray(others, float)
    hit = ~((boxes[:, None, 2] < o[None, :, 0]) | (boxes[:, None, 0] > o[None, :, 2])
            | (boxes[:, None, 3] < o[None, :, 1]) | (boxes[:, None, 1] > o[None, :, 3]))
    return hit @ np.asarray(costs, float)


class Labeler:
    """Places labels next to their anchors on the side where they cover nothing.

    Each label has candidate positions ``(anchor, direction, pad)``: the text
    sits ``pad`` points from ``anchor`` (data coordinates) towards
    ``direction``, aligned so that it lies wholly on that side. What a label
    must not cover: other texts (labels placed before it, texts drawn
    elsewhere, the axes' title), outlines and arrows (:meth:`segment`,
    :meth:`polyline`), marks (:meth:`dot`, :meth:`box`). What it may cross at
    a small price: dashed lines (``soft=True``). Each label takes the first
    of its spots that covers nothing, or the cheapest one (:data:`TEXT_COST`,
    :data:`HARD_COST`, :data:`SOFT_COST`, :data:`OUTSIDE_COST`,
    :data:`OFF_PAGE_COST`). A label whose best spot would still cover
    something goes where its panel has room, joined to its anchor by a thin
    leader line (:attr:`leaders`), when that costs less (:data:`LEADER_COST`).
    :meth:`place` runs once the axes limits are final.
    """

    def __init__(self, ax, s):
        self.ax, self.s = ax, s
        self.items = []
        self.owns = []
        self.spares = []
        self.segments = []
        self.boxes = []
        self.texts = []
        self.fixed = []
        self.heads = []
        self.vectors = []
        """The arrows a label may name (:meth:`arrow`'s index): (tail, tip) [data], head [pt]."""
        self.leaders = []
        """Leader lines drawn by :meth:`place` from a label put away from its anchor to the anchor."""
        self.room = None
        """The box (x0, y0, x1, y1) [data] the labels are kept in: a panel of a figure drawn on one axes with
        others (:func:`graphkin.draw.paper.draw_polygons`). None: the axes' own box."""
        self.fence = None
        """Boxes (x0, y0, x1, y1) [data] a label keeps out of, when its panel shares a figure with others: the other
        panels and the scale strip (:data:`OUTSIDE_COST` per pixel into one). With a fence, a label may leave its
        own :attr:`room` for the figure's free space, beside a polygon its panel's margin is too narrow for; its
        panel's title row above stays out of bounds. None: the room holds."""
        self.taken = []
        """Boxes (x0, y0, x1, y1) [display] that texts placed elsewhere take: the labels keep off them too (the
        labels of the panels placed before, already measured)."""
        self.placed = []
        """The boxes [display] :meth:`place` gave the labels, for the labels placed after them to keep off."""
        self.prices = {}
        """What each label placed covers at its spot (:meth:`place`), by its Text: 0 where it covers nothing."""

    def segment(self, p, q, width=0.0, *, soft=False):
        """An obstacle segment (data coordinates), ``width`` points wide; ``soft`` for a dashed line."""
        self.segments.append((np.asarray(p, float), np.asarray(q, float), float(width),
                              SOFT_COST if soft else HARD_COST))

    def polyline(self, pts, closed=False, width=0.0, *, soft=False):
        pts = np.asarray(pts, float)
        for a, b in zip(pts[:-1], pts[1:]):
            self.segment(a, b, width, soft=soft)
        if closed and len(pts) > 2:
            self.segment(pts[-1], pts[0], width, soft=soft)

    def arrow(self, tail, tip, lw=0.0, head=0.0) -> int:
        """An arrow as an obstacle: its shaft ``lw`` points wide, and its head (matplotlib's mutation scale
        ``head`` [pt], as :func:`graphkin.draw.arrows.arrow` draws it) as wide as the head is.

        Returns the arrow's index, for a label that names it (:meth:`label`'s ``own``): a polygon's label is
        kept nearer its own arrow than any other, or it would read as the other's name.
        """
        self.segment(tail, tip, lw)
        if head > 0:
            self.heads.append((np.asarray(tail, float), np.asarray(tip, float), float(head)))
        self.vectors.append((np.asarray(tail, float), np.asarray(tip, float), float(head)))
        return len(self.vectors) - 1

    def curve(self, pts, lw=0.0, head=0.0, *, named=False):
        """A curved arrow (a couple's arc) as an obstacle: the polyline, and a head at its last point. ``named``: an
        arrow with a name of its own, as :meth:`arrow`'s, that a label naming another arrow must not lie nearer
        than its own (a force's label beside the couple's arc at its pin would read as the couple's)."""
        pts = np.asarray(pts, float)
        self.polyline(pts, width=lw)
        if head > 0 and len(pts) > 1:
            self.heads.append((pts[-2], pts[-1], float(head)))
        if named:
            for a, b in zip(pts[:-1], pts[1:]):
                self.vectors.append((a, b, 0.0))
            if head > 0 and len(pts) > 1:
                self.vectors[-1] = (pts[-2], pts[-1], float(head))

    def dot(self, P, size):
        """A mark ``size`` points across centred on ``P`` (a pin, a centre of mass)."""
        self.box(P[0], P[1], P[0], P[1], pad=size / 2.0)

    def label(self, text, candidates, *, color=None, size=None, zorder=6.0, own=None, spare=None, **kw):
        """Add a label; ``candidates`` is a list of (anchor, direction, pad [pt]), best first; ``own``: the index
        of the arrow it names (:meth:`arrow`), which it must lie nearer than any other (:data:`ASTRAY_COST`);
        ``spare``: a table (a label added after this one, :func:`short_table`) that takes the label as a row
        when no spot beside its arrow or at a leader's end is clean of other arrows and texts."""
        anchor, d, pad = candidates[0]
        d = unit(d)
        ha, va = _align(d)
        t = offset_text(self.ax, text, anchor, d * pad, ha=ha, va=va, color=color or self.s.ink,
                        fontsize=size or self.s.label_size, zorder=zorder, **kw)
        t.set_path_effects([halo()])
        self.items.append((t, candidates))
        self.owns.append(own)
        self.spares.append(spare)
        return t

    def avoid(self, texts):
        """Texts already on the axes that the labels must not cover."""
        self.texts += list(texts)

    def box(self, x0, y0, x1, y1, pad=0.0):
        """An obstacle box in data coordinates (a mark, a block), grown by ``pad`` points all round."""
        self.boxes.append(((x0, y0, x1, y1), float(pad)))

    def keep_off(self, texts):
        """Unrotated one-line texts the labels must not cover, measured by arithmetic when the labels are placed.

        As :meth:`avoid`, without laying each text out again: its size is
        cached by string (:func:`text_size`) and its box follows from its
        anchor and alignment. For texts this module draws (scale bars).
        """
        self.fixed += list(texts)

    def place(self):
        """Place every label, once the axes limits are final; a label with a ``spare`` table that finds no clean
        spot becomes a row of its table, and the labels are placed again without it."""
        # A table is placed after the labels that may join it: it takes what room they leave.
        tables = {id(t) for t in self.spares if t is not None}
        last = [id(t) in tables for t, _ in self.items]
        order = sorted(range(len(self.items)), key=lambda k: last[k])
        self.items, self.owns, self.spares = ([v[k] for k in order] for v in (self.items, self.owns, self.spares))
        while True:
            # Each round moves a label or more to its table, or ends: the table grows, and may push another out.
            covers = self._place()
            moved = [k for k, c in enumerate(covers) if self.spares[k] is not None and c >= ASTRAY_COST]
            if not moved:
                self.prices = {t: c for (t, _), c in zip(self.items, covers)}
                return
            for k in moved:
                t, table = self.items[k][0], self.spares[k]
                table.set_text("\n".join(filter(None, [table.get_text(), t.get_text()])))
                rows = [table.get_gid()[len("table:"):], t.get_gid()[len("label:"):]]
                table.set_gid("table:" + "|".join(filter(None, rows)))
                t.set_visible(False)
            keep = [k for k in range(len(self.items)) if k not in moved]
            self.items, self.owns, self.spares = ([v[k] for k in keep] for v in (self.items, self.owns, self.spares))

    def _place(self) -> list[float]:
        """Place each label at its cheapest spot; returns what each covers there (its price, a leader's own
        price and the preference for nearer spots left out)."""
        ax = self.ax
        for leader in self.leaders:  # placed again: the leaders of last time go
            leader.remove()
        self.leaders = []
        ax.apply_aspect()
        to = ax.transData.transform
        dpi = ax.figure.dpi
        if self.segments:
            P = to(np.array([p for p, _, _, _ in self.segments]))
            Q = to(np.array([q for _, q, _, _ in self.segments]))
            W = np.array([w for _, _, w, _ in self.segments]) * dpi / 72 / 2
            C = np.array([c for _, _, _, c in self.segments])
        else:
            P = Q = np.zeros((0, 2))
            W = C = np.zeros(0)
        if self.heads:
            # A head (ArrowStyle "-|>", head_length 0.75, head_width 0.3 of the mutation scale) back from the tip.
            B = to(np.array([b for b, _, _ in self.heads]))
            T = to(np.array([t for _, t, _ in self.heads]))
            size = np.array([h for _, _, h in self.heads]) * dpi / 72
            d = T - B
            u = d / np.maximum(np.hypot(d[:, 0], d[:, 1]), 1e-300)[:, None]
            P = np.vstack([P, T - u * (0.75 * size)[:, None]])
            Q = np.vstack([Q, T])
            W = np.concatenate([W, 0.3 * size])
            C = np.concatenate([C, np.full(len(size), HARD_COST)])
        if self.room is not None:
            room = to(np.asarray(self.room, float).reshape(2, 2)).ravel()
        else:
            # The room the axes were given (an equal-scale axes may have shrunk inside it), and the figure's edges.
            axbox = TransformedBbox(ax.get_position(original=True), ax.figure.transSubfigure)
            room = np.array([axbox.x0, axbox.y0, axbox.x1, axbox.y1])
        page = np.asarray(ax.figure.bbox.extents, float)
        marks = np.zeros((0, 4))
        if self.boxes:
            # Both corners of every mark in one transform (x0, y0), (x1, y1), (x0, y0), ...
            corners = to(np.array([b for b, _ in self.boxes], float).reshape(-1, 2))
            g = np.array([pad for _, pad in self.boxes], float)[:, None] * dpi / 72
            a, b = corners[0::2], corners[1::2]
            marks = np.hstack([np.minimum(a, b) - g, np.maximum(a, b) + g])
        scale = dpi / 72.0
        renderer = measuring_renderer(ax.figure)
        placed = []
        title = [t for t in (ax.title, ax._left_title, ax._right_title) if t.get_text().strip()]
        for t in self.texts + title:
            bb = text_extent(t, renderer)
            placed.append((bb.x0, bb.y0, bb.x1, bb.y1))
        placed += [text_box(t, renderer) for t in self.fixed]
        placed += [tuple(b) for b in self.taken]
        first = len(placed)
        self.placed = []

        def outside(b, box, top=1.0):
            return (np.maximum(0.0, box[0] - b[:, 0]) + np.maximum(0.0, b[:, 2] - box[2])
                    + np.maximum(0.0, box[1] - b[:, 1]) + top * np.maximum(0.0, b[:, 3] - box[3]))

        fence = (to(np.asarray(self.fence, float).reshape(-1, 2)).reshape(-1, 4) if self.fence is not None
                 else None)

        def beyond(b):
            """How far [px] each box leaves its room, or (a fenced panel) runs into the fence or above its room."""
            if fence is None:
                # Above the room is the title's row: a label there reads as part of the title.
                return outside(b, room, top=3.0)
            above = 3.0 * np.maximum(0.0, b[:, 3] - room[3]) * (b[:, 2] > room[0]) * (b[:, 0] < room[2])
            if not len(fence):
                return above
            lo, hi = np.minimum(fence[:, :2], fence[:, 2:]), np.maximum(fence[:, :2], fence[:, 2:])
            ox = np.minimum(b[:, None, 2], hi[None, :, 0]) - np.maximum(b[:, None, 0], lo[None, :, 0])
            oy = np.minimum(b[:, None, 3], hi[None, :, 1]) - np.maximum(b[:, None, 1], lo[None, :, 1])
            # Another panel's arrows are not this Labeler's obstacles: its box is kept as dear as an arrow.
            into = np.maximum(0.0, np.minimum(ox, oy))
            return above + (into + HARD_COST / OUTSIDE_COST * (into > 0)).sum(axis=1)

        def cost(b):
            """What a box covers that does not depend on the other labels."""
            return (_hits_many(P, Q, W, C, b) + _box_overlaps(b, marks, [HARD_COST] * len(marks))
                    + OUTSIDE_COST * beyond(b) + OFF_PAGE_COST * outside(b, page))

        # Every label's candidate boxes first: a label's size does not depend on where it goes, and
        # the obstacles other than labels do not depend on the other labels, so one vectorised test
        # serves them all; only the overlaps with labels placed before need the loop.
        if not self.items:
            return []
        # All the candidates of all the labels at once: numpy's cost per call, not per spot, was most of this.
        counts = [len(candidates) for _, candidates in self.items]
        spots = [spot for _, candidates in self.items for spot in candidates]
        A = to(np.array([a for a, _, _ in spots], float).reshape(-1, 2))
        D = np.array([d for _, d, _ in spots], float).reshape(-1, 2)
        norm = np.hypot(D[:, 0], D[:, 1])
        D = np.where(norm[:, None] > 0, D / np.where(norm > 0, norm, 1.0)[:, None], [1.0, 0.0])
        pads = np.array([pad for _, _, pad in spots], float)
        sizes = np.array([text_size(t, renderer) for t, _ in self.items], float).reshape(-1, 2)
        w, h = np.repeat(sizes, counts, axis=0).T
        XY = A + D * pads[:, None] * scale
        # _align, for every candidate: where the text's box starts relative to its anchor point.
        fx = np.where(D[:, 0] > 0.2, 0.0, np.where(D[:, 0] < -0.2, 1.0, 0.5))
        fy = np.where(D[:, 1] > 0.2, 0.0, np.where(D[:, 1] < -0.2, 1.0, 0.5))
        x0 = XY[:, 0] - w * fx
        y0 = XY[:, 1] - h * fy
        every = np.column_stack([x0 - GROW, y0 - GROW, x0 + w + GROW, y0 + h + GROW])
        cuts = np.cumsum(counts)[:-1]
        fixed = cost(every)
        firsts = np.concatenate([[0], cuts])
        # Per label: its directions, pads and boxes, its first anchor (display) and its size.
        spots = [(d, p, b, A[k], float(wh[0]), float(wh[1])) for d, p, b, k, wh in
                 zip(np.split(D, cuts), np.split(pads, cuts), np.split(every, cuts), firsts, sizes)]
        leaders = []  # display segments of the leaders drawn so far: later labels keep off them
        covers = []
        if self.vectors:
            ends = to(np.array([e for v in self.vectors for e in v[:2]], float).reshape(-1, 2))
            # A head is drawn whole however short its arrow: it reaches 0.75 of its size back from the tip, 0.3 wide.
            T, B = ends[1::2], ends[0::2]
            size = np.array([v[2] for v in self.vectors]) * dpi / 72
            u = (T - B) / np.maximum(np.hypot(*(T - B).T), 1e-300)[:, None]
            reach = np.maximum(np.hypot(*(T - B).T), 0.75 * size)
            vectors = (T - u * reach[:, None], T, 0.3 * size)
        for (t, candidates), (D, pads, boxes, A0, w, h), score, own in zip(self.items, spots, np.split(fixed, cuts),
                                                                           self.owns):
            score = score + _box_overlaps(boxes, placed, [TEXT_COST] * len(placed)) + self._on_leaders(boxes, leaders)
            if own is not None:
                score = score + ASTRAY_COST * _astray(boxes, *vectors, own)
            # The first spot, in order of preference, that covers nothing ends the search; the best so far wins.
            n = len(score)
            clean = np.flatnonzero(score == 0)
            last = int(clean[0]) + 1 if len(clean) else n
            k = int(np.argmin(score[:last] + 0.3 * np.arange(last)))
            if score[k] >= LEADER_COST:
                far = self._with_leader(t, A0, w, h, room, page, cost, placed, leaders, score[k])
                if far is not None:
                    placed.append(far[0])
                    covers.append(far[1])
                    continue
            covers.append(float(score[k]))
            anchor, d = candidates[k][0], D[k]
            ha, va = _align(d)
            t.set_position(tuple(map(float, anchor)))
            t.set_transform(_offset(ax, d * pads[k]))
            t.set_ha(ha)
            t.set_va(va)
            placed.append(tuple(boxes[k]))
        self.placed = placed[first:]
        return covers

    @staticmethod
    def _on_leaders(boxes, leaders):
        if not leaders:
            return np.zeros(len(boxes))
        P = np.array([p for p, _ in leaders])
        Q = np.array([q for _, q in leaders])
        return _hits_many(P, Q, np.zeros(len(leaders)), np.full(len(leaders), HARD_COST), boxes)

    def _with_leader(self, t, A, w, h, room, page, cost, placed, leaders, worst):
        """Put a label that has no clean spot beside its anchor where there is room in its panel, joined to the
        anchor ``A`` (display) by a thin leader line; None when that is no better. Returns the box taken and what
        it covers there.

        A vector's label so joined names its arrow wherever it stands: the leader ends on it."""
        grow = (w, h) if self.fence is not None else (0.0, 0.0)  # a fenced label may stand beside its room
        x0, y0 = max(room[0] - grow[0], page[0]), max(room[1] - grow[1], page[1])
        x1, y1 = min(room[2] + grow[0], page[2]), min(room[3], page[3])
        if x1 - x0 < w or y1 - y0 < h:
            return None
        cx, cy = np.meshgrid(np.linspace(x0 + w / 2 + GROW, x1 - w / 2 - GROW, 14),
                             np.linspace(y0 + h / 2 + GROW, y1 - h / 2 - GROW, 12))
        cx, cy = cx.ravel(), cy.ravel()
        boxes = np.column_stack([cx - w / 2 - GROW, cy - h / 2 - GROW, cx + w / 2 + GROW, cy + h / 2 + GROW])
        # Where the leader meets each text: its box's point nearest the anchor, half the margin off the text as
        # measured (drawn, it may come a pixel wider or narrower): on neither the text nor far from it.
        ends = np.column_stack([np.clip(A[0], boxes[:, 0] + GROW / 2, boxes[:, 2] - GROW / 2),
                                np.clip(A[1], boxes[:, 1] + GROW / 2, boxes[:, 3] - GROW / 2)])
        reach = np.hypot(*(ends - A).T)
        score = cost(boxes) + _box_overlaps(boxes, placed, [TEXT_COST] * len(placed)) + self._on_leaders(boxes, leaders)
        # The leader itself should not run through a text.
        if placed:
            # Each leader against every text at once (segment_hits_box over the pairs, vectorised).
            _, k = _hit_pairs(np.broadcast_to(np.asarray(A, float), ends.shape), ends, np.zeros(len(ends)),
                              np.asarray(placed, float))
            score += TEXT_COST * np.bincount(k, minlength=len(boxes))
        covers = score
        score = score + LEADER_COST + 0.05 * reach
        j = int(np.argmin(score))
        if not score[j] < worst:
            return None
        ax = self.ax
        back = ax.transData.inverted().transform
        t.set_position(tuple(map(float, back((cx[j], cy[j])))))
        t.set_transform(ax.transData)
        t.set_ha("center")
        t.set_va("center")
        if reach[j] > 0:
            a, b = back(A), back(ends[j])
            self.leaders.append(line(ax, [a[0], b[0]], [a[1], b[1]], color=t.get_color(), lw=0.7,
                                     solid_capstyle="butt", zorder=t.get_zorder() - 0.1,
                                     gid=f"leader:{t.get_gid()}" if t.get_gid() else None))
            leaders.append((np.asarray(A, float), ends[j]))
        return tuple(boxes[j]), float(covers[j])


def _box_segment_distance(boxes, P, Q):
    """Distance [px] from each box (x0, y0, x1, y1) to each segment P[k]–Q[k]: an array, boxes × segments.

    Zero where they meet; elsewhere the nearest of a segment's ends to the box, or of the box's corners to the
    segment (two convex shapes apart are nearest at a vertex of one of them).
    """
    boxes = np.asarray(boxes, float)
    n, m = len(boxes), len(P)
    x0, y0, x1, y1 = (boxes[:, k, None] for k in range(4))

    def to_box(X):  # each end X[k] to each box
        dx = np.maximum(np.maximum(x0 - X[None, :, 0], X[None, :, 0] - x1), 0.0)
        dy = np.maximum(np.maximum(y0 - X[None, :, 1], X[None, :, 1] - y1), 0.0)
        return np.hypot(dx, dy)

    out = np.minimum(to_box(P), to_box(Q))
    d = Q - P
    dd = np.maximum(np.einsum("ij,ij->i", d, d), 1e-300)
    for cx, cy in ((x0, y0), (x0, y1), (x1, y0), (x1, y1)):
        rx, ry = cx - P[None, :, 0], cy - P[None, :, 1]
        s = np.clip((rx * d[None, :, 0] + ry * d[None, :, 1]) / dd[None, :], 0.0, 1.0)
        out = np.minimum(out, np.hypot(rx - s * d[None, :, 0], ry - s * d[None, :, 1]))
    b, k = _hit_pairs(P, Q, np.zeros(m), boxes)
    out[b, k] = 0.0
    return out.reshape(n, m)


def _astray(boxes, P, Q, R, own):
    """1 for each box nearer another arrow P[k]–Q[k] (its head R[k] wide on either side) than arrow ``own``'s shaft
    (by :data:`ASTRAY_MARGIN`), else 0.

    An arrow drawn over its own (the same ends) is no other.
    """
    D = _box_segment_distance(boxes, P, Q)
    same = (np.hypot(*(P - P[own]).T) < 0.5) & (np.hypot(*(Q - Q[own]).T) < 0.5)
    others = np.where(same[None, :], np.inf, D - R[None, :])
    return (others.min(axis=1) < D[:, own] + ASTRAY_MARGIN).astype(float)


def arrow_label_candidates(tail, tip, away, pad):
    """Candidate label spots for an arrow: beside its middle (the ``away`` side first), then beside the ends,
    then further out."""
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
        for e in (tip, tail):
            out.append((e, n, k * pad))
            out.append((e, -n, k * pad))
        # Beyond an end and to one side: off a polygon's vertex, where the next arrow starts on the other side.
        for e, along in ((tip, u), (tail, -u)):
            out.append((e, unit(along + n), k * pad))
            out.append((e, unit(along - n), k * pad))
    for k in (5.0, 8.0, 12.0):
        for t in (0.5, 0.8, 0.2, 1.0, 0.0):
            P = tail + t * (tip - tail)
            out.append((P, n, k * pad))
            out.append((P, -n, k * pad))
        out.append((tip, u, k * pad))
        out.append((tail, -u, k * pad))
    return out


SHORT = 14.0
"""Length [pt] under which a polygon's arrow is too short to carry its label beside it (5 mm): a label there sits
as near the arrows that meet it at its ends, so it is listed in a table beside the polygon instead
(:func:`table_candidates`)."""


def table_candidates(lo, hi, pad):
    """Candidate spots for a table beside a polygon whose extent runs from ``lo`` to ``hi`` [data]: outside each
    corner, then beside each side's middle, nearest first, then further out."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    mid = (lo + hi) / 2
    corners = [(np.array([x, y]), np.array([np.sign(x - mid[0]), np.sign(y - mid[1])]))
               for x in (hi[0], lo[0]) for y in (lo[1], hi[1])]
    sides = [(np.array([hi[0], mid[1]]), np.array([1.0, 0.0])), (np.array([lo[0], mid[1]]), np.array([-1.0, 0.0])),
             (np.array([mid[0], lo[1]]), np.array([0.0, -1.0])), (np.array([mid[0], hi[1]]), np.array([0.0, 1.0]))]
    return [(P, unit(d), k * pad) for k in (1.0, 3.0, 6.0) for P, d in corners + sides]


def short_table(lab, rows, kind: str, pts, s):
    """The vectors too short to carry a label beside their arrow (under :data:`~graphkin.draw.labels.SHORT`),
    listed one a line beside the polygon whose points are ``pts`` [data]: ``rows`` of (name, text), perhaps none
    yet; the labels that find no clean spot join them (:meth:`Labeler.label`'s ``spare``).

    Its gid names each vector's arrow (``table:velocity:v_B|velocity:v_BA``), for a test to find them listed.
    """
    pts = np.asarray(pts, float).reshape(-1, 2)
    return lab.label("\n".join(text for _, text in rows), table_candidates(pts.min(axis=0), pts.max(axis=0),
                                                                          2 * s.label_pad),
                     color=s.ink, size=s.small_size, gid="table:" + "|".join(f"{kind}:{name}" for name, _ in rows))


def fixed_table(ax, rows, kind: str, at, s):
    """A table of short vectors (as :func:`short_table`) at a spot of its own: its upper left corner at ``at``
    [data], in a column the figure keeps free for it (:func:`graphkin.draw.paper.draw_motion_paper`). The Labeler
    does not move it; the labels that find no clean spot still join it (:meth:`Labeler.label`'s ``spare``)."""
    return offset_text(ax, "\n".join(text for _, text in rows), at, (0.0, 0.0), ha="left", va="top", color=s.ink,
                       fontsize=s.small_size, zorder=6.0, path_effects=[halo()],
                       gid="table:" + "|".join(f"{kind}:{name}" for name, _ in rows))


def _compass():
    dirs = []
    for k in range(16):
        a = math.pi / 8 * k
        d = np.array([math.cos(a), math.sin(a)])
        d.flags.writeable = False  # shared by every candidate list
        dirs.append(d)
    return tuple(dirs)


_COMPASS = _compass()
"""The 16 directions a point's label may go, made once: a drawing asks for them some fifty times."""


def point_label_candidates(P, away, pad):
    """Candidate spots around a point, the ``away`` direction first, then 16 directions nearest it first.

    ``pad`` [pt] is a number, or several (nearest first): every direction at the first pad, then every
    direction at the next, the directions sorted once.
    """
    away = unit(away) if np.hypot(*away) > 0 else np.array([0.0, 1.0])
    dirs = sorted((away,) + _COMPASS, key=lambda d: -float(np.dot(d, away)))
    pads = pad if isinstance(pad, (list, tuple)) else (pad,)
    return [(P, d, p) for p in pads for d in dirs]
