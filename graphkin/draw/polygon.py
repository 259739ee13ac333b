"""Force polygons: the forces of one step tip to tail, closing when the link is in equilibrium."""

from __future__ import annotations

import math

import numpy as np

from graphkin.draw import style as _style
from graphkin.draw.arrows import arrow, perp, unit
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
from graphkin.draw.labels import SHORT, Labeler, arrow_label_candidates, point_label_candidates, short_table
from graphkin.draw.scales import nice_round, scale_bar
from graphkin.draw.text import sub
from graphkin.notation import num

LANE = 1.8
"""Half the gap [pt] between the two lanes of a polygon that lies on one line (a two-force member)."""


def step_title(step, driver_name: str | None = None) -> str:
    """A short title for a step's polygon: ``Link 3: R3i + F43 + F23 = 0``."""
    where = f"Link {step.link}" if step.link is not None else "Polygon"
    if step.kind == "superpose":
        total = step.polygon[-1].name if step.polygon else ""
        return f"{where}: superposition of {sub(total)}"
    if step.kind == "driver":
        return f"{where} (input): " + " + ".join(sub(a.name) for a in step.polygon) + " = 0"
    return f"{where}: " + " + ".join(sub(a.name) for a in step.polygon) + " = 0"


def polygon_vertices(step, scale: float, origin=(0.0, 0.0)):
    """The forces of a step's polygon as drawn, those drawn as "= 0", and the polygon's vertices.

    A force is zero when it is rounding beside the polygon's largest, or beside the scale (under a nanometre of
    drawing): a polygon whose forces all vanish at this position (a load whose line passes through a pivot) is
    then drawn as "= 0", not blown up to its rounding residue with a scale bar reading 1e−17 N.

    Parameters
    ----------
    step : graphkin.graphical.Step
    scale : float
        Force scale [N per mm of drawing].
    origin : (float, float)
        Where the first arrow starts [mm].

    Returns
    -------
    shown : list of (Arrow, float)
        Each force drawn, with its size [N].
    zero : list of str
        The names of the forces that vanish.
    verts : ndarray, shape (len(shown) + 1, 2)
        The vertices [mm], tip to tail from ``origin``; their extent sets the view.
    """
    sizes = [math.hypot(*a.vector) for a in step.polygon]
    largest = max(sizes + [0.0])
    floor = max(1e-12 * largest, 1e-9 * abs(scale), 1e-300)
    shown = [(a, size) for a, size in zip(step.polygon, sizes) if size > floor]
    zero = [a.name for a, size in zip(step.polygon, sizes) if size <= floor]
    verts = np.cumsum([np.asarray(origin, float)] + [np.asarray(a.vector, float) / scale for a, _ in shown], axis=0)
    return shown, zero, verts


def draw_force_polygon(step, *, scale: float, ax=None, origin=(0.0, 0.0), values=True, title=None,
                       driver_name: str | None = None, scale_note=False, paper=None, bar=True, place=True,
                       **style) -> Drawn:
    """Draw a step's force polygon, arrows tip to tail.

    Known loads are heavy with solid heads, the unknowns the step finds are
    lighter with open heads; each arrow is labelled with its name (and size);
    a ring marks the start, where the last arrow's tip closes the polygon;
    a scale bar reads ``0 — 10 N``.

    A polygon whose sides all lie on one line (two equal and opposite forces,
    or a superposition of parallel ones) is drawn in two lanes a few points
    apart: the arrows that go one way on one side of the line, those that
    come back on the other, so that no arrow hides another.

    Parameters
    ----------
    step : graphkin.graphical.Step
        A step with a ``polygon``.
    scale : float
        Force scale [N per mm of drawing], e.g. ``construction.force_scale``.
    ax : matplotlib.axes.Axes, optional
    origin : (float, float)
        Where the first arrow starts [mm].
    values : bool
        Write each force's size next to its name.
    title : str or False, optional
        The axes title; by default the polygon's equation.
    driver_name : str, optional
        The driving effort's name (``"F12"``), drawn in the driver's colour.
    scale_note : bool
        Add the drawing scale to the scale bar's reading (``1 mm = 10 N``).
    paper : float, optional
        Millimetres of paper per unit of the drawing (1 when it is printed at
        ``scale`` N per mm; :mod:`graphkin.draw.paper` sizes the figure).
    bar : bool
        Draw the scale bar (a figure of several polygons at one scale draws one for all).
    place : bool
        Place the labels now (see :func:`graphkin.draw.axes.finish`).
    **style
        Overrides of :class:`graphkin.draw.style.Style` fields.

    Returns
    -------
    Drawn
        ``.arrows``, ``.ends`` (tail, tip [mm], as drawn: in a lane, a few
        points off the polygon's line) and ``.labels`` by force name;
        ``.scale`` [N per mm].
    """
    s = _style.resolve(**style)
    ax = new_axes(ax, (4.5, 4.5), s)
    existing = had_content(ax)
    setup_axes(ax)
    drawn = Drawn(ax)
    drawn.scale = scale
    if title is None:
        title = step_title(step)
    if title:
        ax.set_title(title, fontsize=s.title_size, color=s.ink)
    lab = Labeler(ax, s)
    start = np.asarray(origin, float)
    shown, zero, verts = polygon_vertices(step, scale, origin)
    span = float(np.max(np.ptp(verts, axis=0))) if len(verts) > 1 else 0.0
    span = span or 10.0
    ppu = paper * PT_PER_MM if paper else points_per_unit(ax, 1.5 * span)
    # One line? Then two lanes, LANE points either side of it.
    far = verts[int(np.argmax(np.hypot(*(verts - start).T)))]
    along = unit(far - start)
    side = perp(along)
    flat = len(shown) >= 2 and float(np.max(np.abs((verts - start) @ side))) < 0.02 * span
    centre = verts.mean(axis=0)
    index = {}  # each force's arrow among the Labeler's, for its label to keep nearest
    for (a, size), tail0, tip0 in zip(shown, verts[:-1], verts[1:]):
        shift = side * (LANE / ppu) * (1 if float(np.dot(tip0 - tail0, along)) > 0 else -1) if flat else np.zeros(2)
        tail, tip = tail0 + shift, tip0 + shift
        if driver_name and a.name == driver_name:
            color = s.driver
        else:
            color = s.known if a.known else s.unknown
        art = arrow(ax, tail, tip, color=color, lw=s.known_lw if a.known else s.unknown_lw,
                    s=s, hollow=not a.known, zorder=4.5 if a.known else 4.6, gid=f"polygon:{a.name}", pt_per_unit=ppu)
        drawn.arrows[a.name] = art
        drawn.ends[a.name] = (tuple(tail), tuple(tip))
        drawn.add(art)
        if a.known:
            # A light band under a known load highlights it (and shows it where an unknown runs back over it).
            band = line(ax, [tail[0], tip[0]], [tail[1], tip[1]], color=color, lw=7.5, alpha=0.22,
                        solid_capstyle="butt", zorder=4.0)
            drawn.add(band)
            lab.segment(tail, tip, 7.5)
        index[a.name] = lab.arrow(tail, tip, art.get_linewidth(), art.get_mutation_scale())
    # The start, where the polygon closes.
    ring = markers(ax, *start, ms=8, mfc="none", mec=s.ink, mew=1.0, zorder=5)
    dots = markers(ax, *verts[1:-1].T, ms=3, color=s.ink, zorder=5)
    drawn += [ring, dots]
    lab.dot(start, 9.0)
    for v in verts[1:-1]:
        lab.dot(v, 3.0)
    # The forces too short to carry their label, listed beside the polygon; a label that finds no clean spot
    # beside its arrow joins them.
    short = [(a.name, f"{sub(a.name)} = {num(math.hypot(*a.vector), power='superscript')} N") for a, _ in shown
             if values and float(np.hypot(*np.subtract(*drawn.ends[a.name]))) * ppu < SHORT]
    table = short_table(lab, short, "polygon", verts, s) if values else None
    if table is not None:
        for name, _ in short:
            drawn.labels[name] = table
        drawn.add(table)
    for a, _ in shown:
        tail, tip = (np.asarray(p) for p in drawn.ends[a.name])
        if a.name in dict(short):
            continue
        mid = 0.5 * (tail + tip)
        away = mid - centre
        if flat:
            away = side * (1 if float(np.dot(tip - tail, along)) > 0 else -1)
        elif np.hypot(*away) < 1e-9 * span:
            away = np.array([-(tip - tail)[1], (tip - tail)[0]]) * (1 if a.known else -1)
        text = sub(a.name) + (f" = {num(math.hypot(*a.vector), power='superscript')} N" if values else "")
        color = s.driver if driver_name and a.name == driver_name else s.known if a.known else s.unknown
        t = lab.label(text, arrow_label_candidates(tail, tip, away, s.label_pad), color=color,
                      own=index[a.name], spare=table, gid=f"label:polygon:{a.name}")
        drawn.labels[a.name] = t
        drawn.add(t)
    for name in zero:
        t = lab.label(f"{sub(name)} = 0", [spot for pad in (9.0, 16.0, 26.0)
                                           for spot in point_label_candidates(start, np.array([-1.0, 1.0]), pad)],
                      color=s.known)
        drawn.labels[name] = t
        drawn.add(t)
    lo = verts.min(axis=0)
    extent = list(verts)
    if bar:
        value = nice_round(0.3 * span * scale)
        bar_at = np.array([lo[0], lo[1] - 0.16 * span])
        note = f"1 mm = {num(scale)} N" if scale_note else None
        drawn += scale_bar(ax, bar_at, value / scale, value, s=s, tick=0.015 * span, labeler=lab, note=note)
        extent += [bar_at, bar_at + [value / scale, 0]]
    if paper:
        # A margin of its own on paper: room for the labels around the polygon, whatever its size.
        pad = 9.0 / paper
        corners = np.asarray(extent, float)
        extent += [corners.min(axis=0) - pad, corners.max(axis=0) + pad]
    set_limits(ax, extent, margin=0.2 if not paper else 0.0, existing=existing)
    return finish(ax, lab, drawn, place)
