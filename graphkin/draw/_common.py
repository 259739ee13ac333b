"""Shared drawing helpers: the result container, arrows, labels that keep clear, dimensions, scale bars."""

from __future__ import annotations

import math
import re

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import ArrowStyle, FancyArrowPatch
from matplotlib.path import Path

from . import style as _style

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

    def add(self, artist):
        self.append(artist)
        return artist


def new_axes(ax=None, figsize=(6.0, 4.5), s=None):
    """``ax``, or a fresh axes on a new headless Figure."""
    if ax is not None:
        return ax
    s = s or _style.STYLE
    fig = Figure(figsize=figsize, dpi=100)
    return fig.add_subplot()


def setup_axes(ax):
    """Textbook look: no frame, no ticks, equal scale in x and y."""
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_axis_off()


# -- text ---------------------------------------------------------------------

_NAME = re.compile(r"^([A-Za-z])(\d+(?:,\d+)?[a-z]?|[A-Z])$")


def tex(name: str) -> str:
    """A force or point name with its subscript as mathtext: ``F23`` → ``$F_{23}$``, ``R3i`` → ``$R_{3i}$``.

    Names that do not look like a letter and a subscript are returned as they are;
    anything after the first space is kept as plain text (``F14 (cutting)``).
    """
    head, sep, rest = name.partition(" ")
    m = _NAME.match(head)
    if not m:
        return name
    return f"${m.group(1)}_{{{m.group(2)}}}$" + sep + rest


def plain(text: str) -> str:
    """Text with mathtext markup removed: ``$F_{23}$ = 27 N`` → ``F23 = 27 N``."""
    return re.sub(r"[${}]|_(?=\{)|\\mathrm", "", text)


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
    """``θ12 = 30°`` for a crank, ``s = 200 mm`` for a slider driver."""
    d = construction.mechanism.driver
    if d.kind == "crank":
        return f"θ1{d.link} = {num(math.degrees(construction.q), 6)}°"
    return f"s = {num(construction.q * MM, 6)} mm"


# -- forces ----------------------------------------------------------------------


def arrow(ax, tail, tip, *, color, lw, s, hollow=False, zorder=4.0, gid=None, alpha=None):
    """A force arrow from ``tail`` to ``tip`` (data coordinates); its head's point is at ``tip``."""
    a = FancyArrowPatch(
        tuple(map(float, tail)), tuple(map(float, tip)),
        arrowstyle=ArrowStyle("-|>", head_length=0.75, head_width=0.3),
        mutation_scale=s.head * (0.95 if hollow else 1.0), shrinkA=0, shrinkB=0, lw=lw,
        edgecolor=color, facecolor="white" if hollow else color,
        capstyle="butt", joinstyle="miter", zorder=zorder, alpha=alpha)
    if gid:
        a.set_gid(gid)
    ax.add_patch(a)
    return a


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
    ax.add_patch(a)
    mid = pts[len(pts) // 2]
    return a, pts, mid


def unit(v):
    v = np.asarray(v, dtype=float)
    n = float(np.hypot(*v))
    return v / n if n else np.array([1.0, 0.0])


def perp(v):
    return np.array([-v[1], v[0]], dtype=float)


# -- labels that keep clear of arrows and of each other ------------------------------


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


class Labeler:
    """Places labels next to their anchors on the side where they overlap nothing.

    Each label has candidate positions ``(anchor, direction, pad)``: the text
    sits ``pad`` points from ``anchor`` (data coordinates) towards
    ``direction``, aligned so that it lies wholly on that side. Obstacles are
    segments (arrows, bars, lines of action) and labels placed before.
    :meth:`place` runs once the axes limits are final.
    """

    def __init__(self, ax, s):
        self.ax, self.s = ax, s
        self.items = []
        self.segments = []
        self.boxes = []

    def segment(self, p, q):
        self.segments.append((np.asarray(p, float), np.asarray(q, float)))

    def polyline(self, pts, closed=False):
        pts = np.asarray(pts, float)
        for a, b in zip(pts[:-1], pts[1:]):
            self.segment(a, b)
        if closed and len(pts) > 2:
            self.segment(pts[-1], pts[0])

    def label(self, text, candidates, *, color=None, size=None, zorder=6.0, **kw):
        """Add a label; ``candidates`` is a list of (anchor, direction, pad [pt]), best first."""
        anchor, d, pad = candidates[0]
        d = unit(d)
        ha, va = _align(d)
        t = self.ax.annotate(text, tuple(map(float, anchor)), xytext=tuple(float(x) for x in d * pad),
                             textcoords="offset points", ha=ha, va=va, color=color or self.s.ink,
                             fontsize=size or self.s.label_size, zorder=zorder, annotation_clip=False, **kw)
        t.set_in_layout(False)
        self.items.append((t, candidates))
        return t

    def box(self, x0, y0, x1, y1):
        """An obstacle box in data coordinates (e.g. a text drawn elsewhere)."""
        self.boxes.append(("data", (x0, y0, x1, y1)))

    def place(self):
        ax = self.ax
        ax.apply_aspect()
        to = ax.transData.transform
        segs = [(to(p), to(q)) for p, q in self.segments]
        axbox = ax.get_window_extent()
        placed = []
        for kind, b in self.boxes:
            (x0, y0), (x1, y1) = to((b[0], b[1])), to((b[2], b[3]))
            placed.append((min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1)))
        for t, candidates in self.items:
            best, best_score = None, math.inf
            for rank, (anchor, d, pad) in enumerate(candidates):
                d = unit(d)
                ha, va = _align(d)
                t.xy = tuple(map(float, anchor))
                t.set_position(tuple(float(x) for x in d * pad))
                t.set_ha(ha)
                t.set_va(va)
                bb = t.get_window_extent()
                grow = 1.5
                box = (bb.x0 - grow, bb.y0 - grow, bb.x1 + grow, bb.y1 + grow)
                score = 10 * sum(_seg_hits_box(p, q, box) for p, q in segs)
                score += 25 * sum(not (box[2] < o[0] or box[0] > o[2] or box[3] < o[1] or box[1] > o[3]) for o in placed)
                outside = (max(0.0, axbox.x0 - box[0]) + max(0.0, box[2] - axbox.x1)
                           + max(0.0, axbox.y0 - box[1]) + max(0.0, box[3] - axbox.y1))
                score += 0.5 * outside + 0.5 * rank
                if score < best_score:
                    best, best_score = (anchor, d, pad, ha, va, box), score
                if score == 0:
                    break
            anchor, d, pad, ha, va, box = best
            t.xy = tuple(map(float, anchor))
            t.set_position(tuple(float(x) for x in d * pad))
            t.set_ha(ha)
            t.set_va(va)
            placed.append(box)


def arrow_label_candidates(tail, tip, away, pad):
    """Candidate label spots for an arrow: beside its middle (the ``away`` side first), then beside the ends."""
    tail, tip = np.asarray(tail, float), np.asarray(tip, float)
    u = unit(tip - tail)
    n = perp(u)
    if np.dot(n, away) < 0:
        n = -n
    mid = 0.5 * (tail + tip)
    out = []
    for t in (0.5, 0.72, 0.3):
        P = tail + t * (tip - tail)
        out.append((P, n, pad))
        out.append((P, -n, pad))
    out.append((tip, u, pad))
    out.append((tail, -u, pad))
    out.append((mid, n, 3 * pad))
    out.append((mid, -n, 3 * pad))
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
        ax.add_patch(a)
        out.append(a)
        labeler.segment(p, q)
        e = unit(q - p)
    else:
        e = unit(q - p) if L > 0 else np.array([1.0, 0.0])
        one = ArrowStyle("-|>", head_length=0.6, head_width=0.22)
        for start, end in ((p - e * small, p), (q + e * small, q)):
            a = FancyArrowPatch(tuple(start), tuple(end), arrowstyle=one, mutation_scale=s.head * 0.9, shrinkA=0,
                                shrinkB=0, lw=s.thin_lw, color=color, zorder=3.5)
            ax.add_patch(a)
            out.append(a)
            labeler.segment(start, end)
        (line,) = ax.plot([p[0], q[0]], [p[1], q[1]], color=color, lw=s.thin_lw, zorder=3.5)
        out.append(line)
    n = perp(e)
    mid = 0.5 * (p + q)
    cands = [(mid, n, s.label_pad), (mid, -n, s.label_pad), (q + e * small, e, s.label_pad), (p - e * small, -e, s.label_pad)]
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


def scale_bar(ax, at, length: float, value: float, *, s, unit_text="N", tick=None):
    """A scale bar: a bar ``length`` data units long, starting at ``at``, reading ``0 — value N``.

    Returns the artists.
    """
    x, y = map(float, at)
    tick = tick if tick is not None else length * 0.06
    (bar,) = ax.plot([x, x + length], [y, y], color=s.ink, lw=1.4, solid_capstyle="butt", zorder=5)
    (ticks,) = ax.plot([x, x, np.nan, x + length, x + length], [y - tick, y + tick, np.nan, y - tick, y + tick],
                       color=s.ink, lw=1.0, zorder=5)
    t0 = ax.annotate("0", (x, y), xytext=(-3, 0), textcoords="offset points", ha="right", va="center",
                     fontsize=s.small_size, color=s.ink, annotation_clip=False)
    t1 = ax.annotate(f"{num(value)} {unit_text}", (x + length, y), xytext=(3, 0), textcoords="offset points",
                     ha="left", va="center", fontsize=s.small_size, color=s.ink, annotation_clip=False)
    for t in (t0, t1):
        t.set_in_layout(False)
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
