"""Shared drawing helpers: the result container, arrows, labels that keep clear, dimensions, scale bars."""

from __future__ import annotations

import math
import re
import weakref

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

    def _repr_png_(self):
        """Show the drawing, not the list, when it is the last value of a notebook cell."""
        import io

        buffer = io.BytesIO()
        self.ax.figure.savefig(buffer, format="png", bbox_inches="tight", facecolor="white")
        return buffer.getvalue()

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
    ax.set_aspect("equal", adjustable="box")
    ax.set_axis_off()


# -- text ---------------------------------------------------------------------

_NAME = re.compile(r"^([A-Za-z])(\d+(?:,\d+)?[a-z]?)$")
_SUB = dict(zip("0123456789aehijklmnoprstuvx,", "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ,"))
_UNSUB = {v: k for k, v in _SUB.items() if k != ","}


def sub(name: str) -> str:
    """A force or point name with its subscript typeset: ``F23`` → ``F₂₃``, ``R3i`` → ``R₃ᵢ``, ``A0`` → ``A₀``.

    Unicode subscripts rather than mathtext: as legible, and text is laid
    out some twenty times faster. Names that are not a letter and a numeric
    subscript (``FP``, ``O``) are returned as they are; anything after the first space is
    kept as plain text (``F14 (cutting)`` → ``F₁₄ (cutting)``).
    """
    head, sep, rest = name.partition(" ")
    m = _NAME.match(head)
    if not m:
        return name
    return m.group(1) + "".join(_SUB.get(ch, ch) for ch in m.group(2)) + sep + rest


def plain(text: str) -> str:
    """Text with subscripts and mathtext markup undone: ``F₂₃ = 27 N`` → ``F23 = 27 N``."""
    text = "".join(_UNSUB.get(ch, ch) for ch in text)
    return re.sub(r"[${}]|_(?=\{)", "", text)


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
        return f"θ{''.join(_SUB.get(ch, ch) for ch in f'1{d.link}')} = {num(math.degrees(construction.q), 6)}°"
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


_RENDERERS: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def renderer_of(fig):
    """A renderer for measuring text on ``fig`` (made once per figure; Agg when the canvas has none)."""
    root = fig.get_figure(root=True) if hasattr(fig, "get_figure") else fig
    r = _RENDERERS.get(root)
    if r is None or (r.width, r.height, r.dpi) != (root.bbox.width, root.bbox.height, root.dpi):
        get = getattr(root.canvas, "get_renderer", None)
        if get is not None:
            r = get()
        else:
            from matplotlib.backends.backend_agg import RendererAgg

            r = RendererAgg(root.bbox.width, root.bbox.height, root.dpi)
        _RENDERERS[root] = r
    return r


def _hits(P, Q, W, box, lo=None, hi=None) -> int:
    """How many segments P[k]–Q[k] (display coordinates, half-widths W[k]) cross the box; Liang–Barsky, vectorised.

    ``lo``, ``hi``: the segments' bounding boxes (min and max corners), to skip the far ones quickly.
    """
    if not len(P):
        return 0
    if lo is None:
        lo, hi = np.minimum(P, Q) - W[:, None], np.maximum(P, Q) + W[:, None]
    near = (lo[:, 0] <= box[2]) & (hi[:, 0] >= box[0]) & (lo[:, 1] <= box[3]) & (hi[:, 1] >= box[1])
    if not near.any():
        return 0
    P, Q, W = P[near], Q[near], W[near]
    x0, y0, x1, y1 = box[0] - W, box[1] - W, box[2] + W, box[3] + W
    d = Q - P
    t0 = np.zeros(len(P))
    t1 = np.ones(len(P))
    out = np.zeros(len(P), bool)
    for pp, qq in ((-d[:, 0], P[:, 0] - x0), (d[:, 0], x1 - P[:, 0]), (-d[:, 1], P[:, 1] - y0), (d[:, 1], y1 - P[:, 1])):
        zero = pp == 0
        out |= zero & (qq < 0)
        r = np.divide(qq, pp, out=np.zeros_like(qq), where=~zero)
        t0 = np.where(~zero & (pp < 0), np.maximum(t0, r), t0)
        t1 = np.where(~zero & (pp > 0), np.minimum(t1, r), t1)
    return int(np.count_nonzero(~out & (t0 <= t1)))


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
        self.texts = []

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
        t = self.ax.annotate(text, tuple(map(float, anchor)), xytext=tuple(float(x) for x in d * pad),
                             textcoords="offset points", ha=ha, va=va, color=color or self.s.ink,
                             fontsize=size or self.s.label_size, zorder=zorder, annotation_clip=False, **kw)
        t.set_path_effects([halo()])
        self.items.append((t, candidates))
        return t

    def avoid(self, texts):
        """Texts already on the axes that the labels must not cover."""
        self.texts += list(texts)

    def box(self, x0, y0, x1, y1):
        """An obstacle box in data coordinates (e.g. a text drawn elsewhere)."""
        self.boxes.append(("data", (x0, y0, x1, y1)))

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
        lo, hi = np.minimum(P, Q) - W[:, None], np.maximum(P, Q) + W[:, None]
        # The room the axes were given (an equal-scale axes may have shrunk inside it).
        from matplotlib.transforms import TransformedBbox

        axbox = TransformedBbox(ax.get_position(original=True), ax.figure.transSubfigure)
        placed = []
        for kind, b in self.boxes:
            (x0, y0), (x1, y1) = to((b[0], b[1])), to((b[2], b[3]))
            placed.append((min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1)))
        scale = ax.figure.dpi / 72.0
        renderer = renderer_of(ax.figure)
        for t in self.texts:
            bb = t.get_window_extent(renderer)
            placed.append((bb.x0, bb.y0, bb.x1, bb.y1))
        for t, candidates in self.items:
            bb = t.get_window_extent(renderer)
            w, h = bb.width, bb.height
            best, best_score = None, math.inf
            for rank, (anchor, d, pad) in enumerate(candidates):
                d = unit(d)
                ha, va = _align(d)
                x, y = to(np.asarray(anchor, float)) + d * pad * scale
                x0 = x if ha == "left" else x - w if ha == "right" else x - w / 2
                y0 = y if va == "bottom" else y - h if va == "top" else y - h / 2
                grow = 1.5
                box = (x0 - grow, y0 - grow, x0 + w + grow, y0 + h + grow)
                score = 10 * _hits(P, Q, W, box, lo, hi)
                score += 200 * sum(not (box[2] < o[0] or box[0] > o[2] or box[3] < o[1] or box[1] > o[3]) for o in placed)
                outside = (max(0.0, axbox.x0 - box[0]) + max(0.0, box[2] - axbox.x1)
                           + max(0.0, axbox.y0 - box[1]) + max(0.0, box[3] - axbox.y1))
                score += 3.0 * outside
                clean = score == 0
                score += 0.3 * rank
                if score < best_score:
                    best, best_score = (anchor, d, pad, ha, va, box), score
                if clean:
                    break  # the first spot, in order of preference, that covers nothing
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
        ax.add_patch(a)
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
            ax.add_patch(a)
            out.append(a)
            labeler.segment(start, end)
        (line,) = ax.plot([p[0], q[0]], [p[1], q[1]], color=color, lw=s.thin_lw, zorder=3.5)
        out.append(line)
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
