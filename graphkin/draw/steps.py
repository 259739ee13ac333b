"""The construction step by step: one frame per step, or all of them on one sheet."""

from __future__ import annotations

import math
import textwrap

import numpy as np
from matplotlib.figure import Figure

from graphkin.draw import style as _style
from graphkin.draw.arrows import arrow, perp, unit
from graphkin.draw.axes import MM, PanelAxes, markers, points_per_unit, set_limits
from graphkin.draw.geometry import Geometry
from graphkin.draw.labels import Labeler, point_label_candidates
from graphkin.draw.mechanism import draw_mechanism
from graphkin.draw.polygon import draw_force_polygon, step_title
from graphkin.draw.text import input_text, sub
from graphkin.graphical.construction import STEP_TITLES
from graphkin.notation import num

KIND_TITLE = STEP_TITLES
"""A short title for each kind of step (:data:`graphkin.graphical.construction.STEP_TITLES`)."""

FAR = 3.0
"""Points further than this many mechanism sizes from it are noted at the edge rather than drawn."""


def _wrap(text: str, width_in: float, size: float) -> str:
    chars = max(20, int(width_in * 72 / (0.53 * size)))
    return textwrap.fill(text, chars)


def _magnitude(step, name: str) -> float:
    """The size [N] of the load named ``name`` that a step found or combined (0 when it names none)."""
    for key in (name, name.replace("R", "F", 1) if name.startswith("R") and name.endswith("i") else None):
        v = step.values.get(key) if key else None
        if isinstance(v, (tuple, list)) and len(v) == 2:
            return math.hypot(*v)
    return 0.0


def draw_step_geometry(construction, step, *, ax, place=True, force_scale=None, narrow=False, **style) -> list:
    """The step's lines of action and points, bold, on an axes that already shows the mechanism (in mm).

    Lines are drawn by role: a known load's line solid with an arrowhead for
    its sense, a known direction dashed, a found line dash-dot. Points far
    from the mechanism (a concurrency point nearly at infinity) are named in
    a note instead of stretching the view. With ``force_scale`` [N per mm of the
    drawing's units] a known load is drawn to that scale on its line; without, its
    sense is a head on the line. With ``place=False`` the labels are
    left for the figure's layout to place (:func:`graphkin.draw.paper.arrange`).
    ``narrow``: the axes is a panel of a printed figure, so the note of a far point goes in its title (after
    the title the panel already has), where the figure's layout leaves room, rather than over the drawing.
    Returns the artists.
    """
    s = _style.resolve(**style)
    c = construction
    geom = Geometry(c)
    # The mechanism drawn underneath: its labels are placed again with the step's, so that they keep off the
    # step's lines and arrows as well as the step's labels keep off the links.
    lab = getattr(ax, "_graphkin_labeler", None)
    if lab is None:
        lab = Labeler(ax, s)
        lab.avoid(ax.texts)
        for n in geom.mech.moving:
            pts = list(geom.link_points(n).values())
            if len(pts) >= 2:
                lab.polyline(pts, closed=len(pts) > 2, width=s.link_lw)
    out = []
    mech_pts = np.asarray([p for d in geom.P.values() for p in d.values()], float)
    centre = mech_pts.mean(axis=0)
    extent = list(mech_pts)
    far = []
    for line in step.lines:
        P = np.asarray(line.point, float) * MM
        d = unit(line.direction)
        color = _style.line_color(line.role, s)
        dash = _style.LINE_DASH.get(line.role, "-")
        art = ax.axline(tuple(P), tuple(P + d * geom.size * 0.1), color=color, lw=1.7, linestyle=dash, zorder=3.5)
        out.append(art)
        near = np.hypot(*(P - centre)) <= FAR * geom.size
        if not near:
            # Show the line where it passes closest to the mechanism.
            P = P + d * float(np.dot(centre - P, d))
        extent.append(P)
        size = _magnitude(step, line.name)
        if line.role == "resultant" and force_scale and size:
            # The load itself, to the figure's force scale, on its line.
            half = d * size / force_scale / 2
            a = arrow(ax, P - half, P + half, color=color, lw=s.known_lw, s=s, zorder=4.5,
                      pt_per_unit=points_per_unit(ax, 1.3 * geom.size))
            out.append(a)
            lab.arrow(P - half, P + half, a.get_linewidth(), a.get_mutation_scale())
            extent += [P - half, P + half]
        elif line.role == "resultant":
            # Its sense only, as a head on the line: a drawing with no force scale draws no force's length.
            angle = math.degrees(math.atan2(d[1], d[0])) - 90
            m = markers(ax, *P, marker=(3, 0, angle), ms=9, color=color, zorder=4.5)
            out.append(m)
            lab.dot(P, 9.0)
        n = perp(d)
        # The line itself: a label may cross it, at a price (the axline is drawn across the whole view).
        lab.segment(P - d * 3 * geom.size, P + d * 3 * geom.size, soft=True)
        spots = [(P + d * k * geom.size, side, pad) for pad in (4.0, 10.0)
                 for k in (0.12, -0.12, 0.25, -0.25, 0.4, -0.4) for side in (n, -n)]
        t = lab.label(sub(line.name), spots, color=color)
        out.append(t)
    for name, X in step.points.items():
        X = np.asarray(X, float) * MM
        if np.hypot(*(X - centre)) > FAR * geom.size:
            at = ", ".join(num(v, power="superscript") for v in X)
            far.append(f"{name} is off the drawing, at ({at}) mm")
            continue
        m = markers(ax, *X, ms=6.5, mfc=s.found, mec="white", mew=0.8, zorder=6)
        out.append(m)
        extent.append(X)
        lab.dot(X, 7.3)
        t = lab.label(sub(name), [spot for pad in (6.0, 12.0, 20.0)
                                  for spot in point_label_candidates(X, np.array([1.0, 1.0]), pad)], color=s.found)
        out.append(t)
    if far and narrow:
        # Under the panel's title, where the figure's layout leaves room for it, not over the drawing.
        t = ax.set_title("\n".join([ax.get_title()] * bool(ax.get_title()) + far), fontsize=s.small_size,
                         color=s.ink)
        out.append(t)
    elif far:
        t = ax.text(0.01, 0.01, "\n".join(far), transform=ax.transAxes, ha="left", va="bottom", fontsize=s.small_size,
                    color=s.found)
        out.append(t)
    set_limits(ax, extent, margin=0.1, existing=True)  # keeps the mechanism's own view (gears, ground)
    if not place:
        ax._graphkin_labeler = lab
        return out
    lab.place()
    return out + lab.leaders


def _frame(target, construction, step, number, *, s, style, header=True, caption_size=None):
    """Draw one step on a Figure or SubFigure."""
    c = construction
    fig_w, fig_h = _size(target)
    caption_size = caption_size or s.caption_size
    caption = _wrap(step.caption, fig_w * 0.94, caption_size)
    lines = caption.count("\n") + 1
    cap_h = (lines * caption_size * 1.35 + 10) / 72 / fig_h  # figure fraction
    head_h = 0.42 / fig_h if header else 0.05
    bottom = cap_h + 0.02
    height = max(0.2, 1 - head_h - bottom - 0.02)
    axes = []
    if step.polygon:
        ax = target.add_axes([0.01, bottom, 0.58, height], axes_class=PanelAxes)
        ax2 = target.add_axes([0.62, bottom, 0.37, height], axes_class=PanelAxes)
    else:
        ax, ax2 = target.add_axes([0.01, bottom, 0.98, height], axes_class=PanelAxes), None
    draw_mechanism(c, ax=ax, faint=True, emphasis=step.link, **style)
    draw_step_geometry(c, step, ax=ax, **style)
    axes.append(ax)
    if ax2 is not None:
        draw_force_polygon(step, scale=c.force_scale, ax=ax2, title=False, driver_name=c.driver_name, **style)
        axes.append(ax2)
    if header:
        kind = KIND_TITLE.get(step.kind, step.kind)
        where = f"link {step.link}: " if step.link is not None else ""
        text = f"Step {number}. {where}{kind}"
        if step.polygon:
            text += "   —   " + step_title(step)
        target.text(0.015, 1 - 0.12 / fig_h, text, ha="left", va="top", fontsize=s.title_size, color=s.ink,
                    fontweight="bold")
    target.text(0.015, cap_h - 0.01, caption, ha="left", va="top", fontsize=caption_size, color=s.ink,
                linespacing=1.3)
    return axes


def _size(target):
    """Width and height [in] of a Figure or SubFigure."""
    bb = target.bbox
    dpi = target.get_figure(root=True).dpi if hasattr(target, "get_figure") else target.figure.dpi
    return bb.width / dpi, bb.height / dpi


def draw_steps(construction, *, figsize=(9.0, 5.6), **style) -> list[Figure]:
    """One figure per step of the construction.

    Each frame shows the mechanism faint (the step's link at full strength),
    the step's lines of action and points bold, its force polygon beside the
    mechanism when it has one, and the step's caption wrapped underneath.

    Returns
    -------
    list of matplotlib.figure.Figure
        In the order of ``construction.steps``; a single frame naming the
        reason when the construction is not valid.
    """
    s = _style.resolve(**style)
    c = construction
    if not c.valid and not c.steps:
        fig = Figure(figsize=figsize)
        fig.text(0.5, 0.5, f"No construction at {input_text(c)}: {c.reason}", ha="center", va="center",
                 fontsize=s.label_size, color=s.unknown, wrap=True)
        return [fig]
    figs = []
    for k, step in enumerate(c.steps, start=1):
        fig = Figure(figsize=figsize, dpi=100)
        _frame(fig, c, step, k, s=s, style=style)
        figs.append(fig)
    return figs


def draw_step_grid(construction, *, ncols=3, cell=(5.6, 4.3), **style) -> Figure:
    """Every step of the construction on one sheet, in reading order, captions under each frame."""
    s = _style.resolve(**style)
    c = construction
    steps = c.steps
    n = max(len(steps), 1)
    ncols = min(ncols, n)
    nrows = math.ceil(n / ncols)
    head = 0.7
    fig = Figure(figsize=(cell[0] * ncols, cell[1] * nrows + head), dpi=100)
    fig.suptitle(f"{c.mechanism.title or 'Mechanism'} — {input_text(c)}: the graphical construction step by step",
                 fontsize=s.suptitle_size, y=1 - 0.2 / (cell[1] * nrows + head), va="top")
    if not steps:
        fig.text(0.5, 0.5, f"No construction: {c.reason}", ha="center", va="center", color=s.unknown)
        return fig
    outer = fig.subfigures(2, 1, height_ratios=[head, cell[1] * nrows])
    grid = outer[1].subfigures(nrows, ncols, squeeze=False, wspace=0.02, hspace=0.02)
    for k, step in enumerate(steps):
        r, col = divmod(k, ncols)
        _frame(grid[r][col], c, step, k + 1, s=s, style=style, caption_size=s.small_size)
    return fig
