"""Velocity and acceleration polygons drawn to a stated scale (1 mm = X m/s, 1 mm = Y m/s²)."""

from __future__ import annotations

import math
import textwrap

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Polygon

from graphkin.draw import style as _style
from graphkin.draw.arrows import arrow
from graphkin.draw.axes import (
    PT_PER_MM,
    Drawn,
    finish,
    had_content,
    line,
    markers,
    new_axes,
    points_per_unit,
    set_limits,
    setup_axes,
)
from graphkin.draw.labels import (
    SHORT,
    Labeler,
    arrow_label_candidates,
    fixed_table,
    point_label_candidates,
    short_table,
)
from graphkin.draw.scales import nice_round, scale_bar
from graphkin.draw.text import motion_name
from graphkin.errors import GraphkinError
from graphkin.notation import num

UNITS = {"velocity": "m/s", "acceleration": "m/s²"}


def motion_extent(construction, polygon: str, scale: float):
    """The lower left and upper right corners [mm of drawing] of every image point of a polygon at ``scale``, the
    pole at the origin: the extent :func:`draw_motion_polygon` fits its view to (at ``upto``, too)."""
    pts = np.asarray([np.asarray(p, float) / scale for p in construction.images[polygon].values()], float)
    return pts.reshape(-1, 2).min(axis=0), pts.reshape(-1, 2).max(axis=0)


def draw_motion_polygon(construction, polygon: str = "velocity", *, scale: float | None = None, ax=None,
                        values: bool = True, title=None, upto: int | None = None, paper=None, bar=True,
                        place=True, origin=(0.0, 0.0), table_at=None, **style) -> Drawn:
    """Draw the velocity or acceleration polygon of a position to a stated scale.

    The pole is a ring; each vector a step draws is an arrow (known ones heavy with solid heads, those whose
    size the step found lighter with open heads); the lines two vectors were known to lie on are dashed
    through the image point they meet at; each link's image is a light patch through its image points, which
    are labelled (``a``, ``b``, ``g3``; primed in the acceleration polygon). The scale bar reads
    ``0 — 2 m/s   (1 mm = 0.05 m/s)``.

    Parameters
    ----------
    construction : graphkin.graphical.MotionConstruction
        The polygons of one position (:func:`graphkin.graphical.construct_kinematics`).
    polygon : {"velocity", "acceleration"}
    scale : float, optional
        Drawing scale [m/s or m/s² per mm]; the construction's round scale by default.
    ax : matplotlib.axes.Axes, optional
    values : bool
        Write each drawn vector's size next to its name.
    title : str or False, optional
        The axes title; by default the polygon's name and scale.
    upto : int, optional
        Draw the polygon as it stands after step ``upto`` of ``construction.steps`` (the view stays that of
        the whole polygon, so that frames of successive steps line up).
    paper : float, optional
        Millimetres of paper per unit of the drawing (1 when it is printed at ``scale`` per mm;
        :func:`graphkin.draw.paper.draw_motion_paper` sizes the figure).
    bar : bool
        Draw the scale bar (a printed figure draws one strip of bars for both polygons).
    place : bool
        Place the labels now; False leaves them to whoever lays the figure out (:func:`graphkin.draw.axes.finish`).
    origin : (float, float)
        Where the pole is drawn [mm of drawing] (a panel of a figure of several drawn on one axes).
    table_at : (float, float), optional
        Where the table of short vectors starts, its upper left corner [mm of drawing], in a column kept free for
        it (:func:`graphkin.draw.paper.draw_motion_paper`); by default the Labeler places it beside the polygon.
    **style
        Overrides of :class:`graphkin.draw.style.Style` fields.

    Returns
    -------
    Drawn
        ``.arrows`` and ``.ends`` (tail, tip [mm of drawing]) by vector name, ``.labels`` by image point,
        ``.scale`` [m/s or m/s² per mm].
    """
    if polygon not in UNITS:
        raise GraphkinError(f"draw_motion_polygon: polygon must be 'velocity' or 'acceleration', got {polygon!r}")
    if not construction.valid:
        raise GraphkinError(f"there are no polygons to draw at this position: {construction.reason}")
    unit = UNITS[polygon]
    if scale is None:
        scale = construction.velocity_scale if polygon == "velocity" else construction.acceleration_scale
    if not (isinstance(scale, (int, float)) and math.isfinite(scale) and scale > 0):
        raise GraphkinError(f"draw_motion_polygon: scale must be a positive number of {unit} per mm, got {scale!r}")
    s = _style.resolve(**style)
    ax = new_axes(ax, (4.5, 4.5), s)
    existing = had_content(ax)
    setup_axes(ax)
    drawn = Drawn(ax)
    drawn.scale = scale
    if title is None:
        title = f"{polygon.capitalize()} polygon (1 mm = {num(scale)} {unit})"
    if title:
        ax.set_title(title, fontsize=s.title_size, color=s.ink)
    lab = Labeler(ax, s)
    steps = [st for k, st in enumerate(construction.steps) if st.polygon == polygon and (upto is None or k <= upto)]
    pole_name = "o" if polygon == "velocity" else "o′"
    O = np.asarray(origin, float)
    every = {name: O + np.asarray(p, float) / scale for name, p in construction.images[polygon].items()}
    shown = {pole_name} | {name for st in steps for name in st.points}
    images = {name: p for name, p in every.items() if name in shown}
    pts = list(every.values())
    span = float(np.max(np.ptp(np.asarray(pts), axis=0))) if len(pts) > 1 else 0.0
    span = span or 10.0
    ppu = paper * PT_PER_MM if paper else points_per_unit(ax, 1.5 * span)
    floor = 1e-9 * span

    for st in steps:
        if st.kind != "image" or len(st.points) < 3:
            continue
        corners = np.asarray([images[k] for k in st.points if not k.startswith("g")], float)
        if len(corners) >= 3:
            patch = Polygon(corners, closed=True, facecolor=s.known, alpha=0.08, edgecolor="none", zorder=3)
            ax.add_patch(patch)
            drawn.add(patch)

    vectors = {}  # each arrow drawn, by its ends: the names of the vectors it draws, and its index in the Labeler
    for st in steps:
        if st.kind == "image":
            continue
        for ln in st.lines:
            (x, y), (ux, uy) = O + np.asarray(ln.point) / scale, ln.direction
            end = O + np.asarray(next(iter(st.points.values()), ln.point), float) / scale
            t = (end - (x, y)) @ np.array([ux, uy])
            reach = 0.15 * span
            a, b = (x, y) + np.array([ux, uy]) * (min(0.0, t) - reach), (x, y) + np.array([ux, uy]) * (max(0.0, t) + reach)
            drawn.add(line(ax, [a[0], b[0]], [a[1], b[1]], color=s.ink, lw=s.thin_lw, ls="--", alpha=0.5, zorder=3.2))
        for v in st.vectors:
            tail, tip = O + np.asarray(v.tail, float) / scale, O + np.asarray(v.tip, float) / scale
            if float(np.hypot(*(tip - tail))) <= floor:
                continue
            # Two vectors with the same ends (v_P, and v_PP1 along a fixed guide) are one arrow with both names.
            key = (tuple(np.round(tail / floor)), tuple(np.round(tip / floor)))
            if key in vectors:
                names = vectors[key][0]
                if v.name not in names:
                    names.append(v.name)
                    drawn.arrows[v.name] = drawn.arrows[names[0]]
                    drawn.ends[v.name] = drawn.ends[names[0]]
                continue
            known = v.known == "size and direction"
            color = s.known if known else s.unknown
            art = arrow(ax, tail, tip, color=color, lw=s.known_lw if known else s.unknown_lw, s=s, hollow=not known,
                        zorder=4.5 if known else 4.6, gid=f"{polygon}:{v.name}", pt_per_unit=ppu)
            drawn.arrows[v.name] = art
            drawn.ends[v.name] = (tuple(tail), tuple(tip))
            drawn.add(art)
            vectors[key] = ([v.name], lab.arrow(tail, tip, art.get_linewidth(), art.get_mutation_scale()))
    pole = images[pole_name]
    drawn += [markers(ax, *pole, ms=8, mfc="none", mec=s.ink, mew=1.0, zorder=5)]
    lab.dot(pole, 9.0)
    centre = np.mean(np.asarray(pts), axis=0)
    # Every image point in one line of markers (the same dots, in the same order, as one line each).
    dots = np.asarray(list(images.values()), float).reshape(-1, 2)
    drawn.add(markers(ax, dots[:, 0], dots[:, 1], ms=3, color=s.ink, zorder=5))
    for p in images.values():
        lab.dot(p, 3.0)
    for name, p in images.items():
        away = p - centre if np.hypot(*(p - centre)) > floor else np.array([-1.0, 1.0])
        t = lab.label(motion_name(name), point_label_candidates(p, away, (6.0, 12.0, 20.0)), color=s.ink,
                      gid=f"point:{polygon}:{name}")
        drawn.labels[name] = t
        drawn.add(t)
    if values:
        rows, beside = [], []  # the vectors too short to carry their label (listed beside the polygon), the others
        for names, k in vectors.values():
            tail, tip = (np.asarray(p) for p in drawn.ends[names[0]])
            size = float(np.hypot(*(tip - tail))) * scale
            text = " = ".join(motion_name(name) for name in names) + f" = {num(size)} {unit}"
            (rows if float(np.hypot(*(tip - tail))) * ppu < SHORT else beside).append((names[0], text, tail, tip, k))
        listed = [(name, text) for name, text, *_ in rows]
        table = (short_table(lab, listed, polygon, np.asarray(pts), s) if table_at is None
                 else fixed_table(ax, listed, polygon, table_at, s))
        drawn.add(table)
        for name, text, tail, tip, k in beside:
            mid = 0.5 * (tail + tip)
            t = lab.label(text, arrow_label_candidates(tail, tip, mid - centre, s.label_pad), color=s.ink,
                          size=s.small_size, own=k, spare=table, gid=f"label:{polygon}:{name}")
            drawn.add(t)
    lo = np.min(np.asarray(pts), axis=0)
    extent = list(pts)
    if bar:
        value = nice_round(0.3 * span * scale)
        bar_at = np.array([lo[0], lo[1] - 0.16 * span])
        drawn += scale_bar(ax, bar_at, value / scale, value, s=s, unit_text=unit, tick=0.015 * span, labeler=lab,
                           note=f"1 mm = {num(scale)} {unit}")
        extent += [bar_at, bar_at + [value / scale, 0]]
    if paper:
        # A margin of its own on paper: room for the labels around the polygon, whatever its size.
        pad = 9.0 / paper
        corners = np.asarray(extent, float)
        extent += [corners.min(axis=0) - pad, corners.max(axis=0) + pad]
    set_limits(ax, extent, margin=0.2 if not paper else 0.0, existing=existing)
    return finish(ax, lab, drawn, place)


def draw_motion_polygons(construction, *, velocity_scale: float | None = None,
                         acceleration_scale: float | None = None, **style) -> Figure:
    """The velocity and acceleration polygons of one position side by side, each to its stated scale.

    Parameters
    ----------
    construction : graphkin.graphical.MotionConstruction
        The polygons of one position.
    velocity_scale, acceleration_scale : float, optional
        Drawing scales [m/s per mm, m/s² per mm]; the construction's round scales by default.
    **style
        Overrides of :class:`graphkin.draw.style.Style` fields.

    Returns
    -------
    matplotlib.figure.Figure
        Two axes: the velocity polygon, then the acceleration polygon.
    """
    # dpi 100 as new_axes uses: the style's dpi is the saving resolution.
    fig = Figure(figsize=(10.0, 5.0), dpi=100)
    left, right = fig.subplots(1, 2)
    draw_motion_polygon(construction, "velocity", scale=velocity_scale, ax=left, **style)
    draw_motion_polygon(construction, "acceleration", scale=acceleration_scale, ax=right, **style)
    return fig


def draw_motion_steps(construction, **style) -> list[Figure]:
    """The polygons step by step: one frame per step, the polygon as it stands, the step's caption under it.

    Parameters
    ----------
    construction : graphkin.graphical.MotionConstruction
        The polygons of one position.
    **style
        Overrides of :class:`graphkin.draw.style.Style` fields.

    Returns
    -------
    list of matplotlib.figure.Figure
        One per step, in order; each polygon at the construction's scale throughout.
    """
    if not construction.valid:
        raise GraphkinError(f"there are no polygons to draw at this position: {construction.reason}")
    s = _style.resolve(**style)
    frames = []
    for k, step in enumerate(construction.steps):
        fig = Figure(figsize=(6.0, 6.4), dpi=100)
        ax = fig.add_axes((0.05, 0.3, 0.9, 0.62))
        draw_motion_polygon(construction, step.polygon, ax=ax, upto=k, values=False,
                            title=f"Step {k + 1}: {step.polygon} polygon, {step.kind}", **style)
        fig.text(0.05, 0.26, textwrap.fill(step.caption, 95), ha="left", va="top", fontsize=s.small_size,
                 color=s.ink, wrap=True)
        frames.append(fig)
    return frames
