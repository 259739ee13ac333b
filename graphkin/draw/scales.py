"""Dimension lines and scale bars: how long a length is, and how many N (or mm) a length of drawing stands for."""

from __future__ import annotations

import math

import numpy as np
from matplotlib.patches import ArrowStyle, FancyArrowPatch

from graphkin.draw.arrows import perp, unit
from graphkin.draw.axes import line, put
from graphkin.draw.labels import offset_text
from graphkin.notation import num


def dimension(ax, labeler, p, q, text, *, s, small: float, color=None, broken=False):
    """A dimension line between p and q with arrowheads and its text beside it.

    ``small`` [data units]: below it the arrows are drawn outside, pointing in.
    ``broken``: the line carries a break mark (a zigzag across its middle),
    the drafting sign for a distance drawn shorter than it is.
    Returns the artists.
    """
    p, q = np.asarray(p, float), np.asarray(q, float)
    color = color or s.ink
    L = float(np.hypot(*(q - p)))
    out = []
    style = ArrowStyle("<|-|>", head_length=0.6, head_width=0.22)
    if L >= small:
        a = FancyArrowPatch(tuple(p), tuple(q), arrowstyle=style, mutation_scale=s.head * 0.9, shrinkA=0, shrinkB=0,
                            lw=s.thin_lw, color=color, zorder=3.5, gid="dimension")
        put(ax, a, [p, q])
        out.append(a)
        labeler.arrow(p, q, s.thin_lw, s.head * 0.9)
        labeler.curve([q, p], 0.0, s.head * 0.9)
        e = unit(q - p)
    else:
        e = unit(q - p) if L > 0 else np.array([1.0, 0.0])
        one = ArrowStyle("-|>", head_length=0.6, head_width=0.22)
        out_len = 0.8 * small
        for start, end in ((p - e * out_len, p), (q + e * out_len, q)):
            a = FancyArrowPatch(tuple(start), tuple(end), arrowstyle=one, mutation_scale=s.head * 0.9, shrinkA=0,
                                shrinkB=0, lw=s.thin_lw, color=color, zorder=3.5, gid="dimension")
            put(ax, a, [start, end])
            out.append(a)
            labeler.arrow(start, end, s.thin_lw, s.head * 0.9)
        out.append(line(ax, [p[0], q[0]], [p[1], q[1]], color=color, lw=s.thin_lw, zorder=3.5))
    n = perp(e)
    mid = 0.5 * (p + q)
    if broken and L > 0:
        # A zigzag across the middle, on a white gap: the length between is left out.
        z = 0.05 * L
        zig = np.array([mid - e * 1.2 * z, mid - e * 0.4 * z + n * z, mid + e * 0.4 * z - n * z, mid + e * 1.2 * z])
        out.append(line(ax, *np.array([mid - e * 1.3 * z, mid + e * 1.3 * z]).T, color="white", lw=s.thin_lw * 4,
                        solid_capstyle="butt", zorder=3.55))
        out.append(line(ax, *zig.T, color=color, lw=s.thin_lw, zorder=3.6, solid_joinstyle="miter"))
        labeler.polyline(zig)
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


def scale_bar(ax, at, length: float, value: float, *, s, unit_text="N", tick=None, labeler=None, note=None,
              alpha=None, transform=None):
    """A scale bar: a bar ``length`` data units long, starting at ``at``, reading ``0 — value N``.

    ``note`` follows the reading (``"1 mm = 10 N"`` for a force polygon
    drawn to a construction's scale). With a :class:`Labeler`, its labels
    keep off the bar and both texts. ``transform``: ``at``, ``length`` and
    ``tick`` are in its coordinates rather than the axes' data, and the bar
    is drawn outside the axes too (a strip of scale bars under a figure's
    panels, in millimetres of paper: :func:`graphkin.draw.paper.scale_strip`).
    Returns the artists.
    """
    x, y = map(float, at)
    tick = tick if tick is not None else length * 0.06
    where = {} if transform is None else {"transform": transform, "clip_on": False}
    bar = line(ax, [x, x + length], [y, y], color=s.ink, lw=1.4, solid_capstyle="butt", zorder=5, alpha=alpha,
               **where)
    ticks = line(ax, [x, x, np.nan, x + length, x + length], [y - tick, y + tick, np.nan, y - tick, y + tick],
                 color=s.ink, lw=1.0, zorder=5, alpha=alpha, **where)
    reading = f"{num(value)} {unit_text}" + (f"   ({note})" if note else "")
    t0 = offset_text(ax, "0", (x, y), (-3, 0), ha="right", va="center", fontsize=s.small_size, color=s.ink,
                     alpha=alpha, base=transform)
    t1 = offset_text(ax, reading, (x + length, y), (3, 0), ha="left", va="center", fontsize=s.small_size,
                     color=s.ink, alpha=alpha, base=transform)
    if labeler is not None:
        # Boxes, not a segment: a label may cross an arrow when it must, but it would hide the bar's reading.
        labeler.box(x, y - tick, x + length, y + tick, pad=1.0)  # the lines' half width
        labeler.keep_off([t0, t1])
    return [bar, ticks, t0, t1]
