"""The mechanism to scale at one position: bars, plates, pins, ground, sliders on their guides, gears."""

from __future__ import annotations

import math

import numpy as np
from matplotlib.patches import Circle, Polygon, Rectangle

from graphkin.draw import style as _style
from graphkin.draw.arrows import arc_points, perp, unit
from graphkin.draw.axes import (
    MM,
    PT_PER_MM,
    Drawn,
    fit,
    had_content,
    line,
    markers,
    new_axes,
    points_per_unit,
    put,
    set_limits,
    setup_axes,
)
from graphkin.draw.gears import draw_annulus, frame_gears, gear_outline
from graphkin.draw.geometry import Geometry
from graphkin.draw.labels import Labeler, point_label_candidates
from graphkin.draw.scales import nice_round, scale_bar
from graphkin.draw.text import sub
from graphkin.graphical.paper import length_text, sheet_reach
from graphkin.model import Prismatic, Revolute


def _band(ax, pts, s, out, alpha=1.0, zorder=2.0):
    """A bar as an outlined band of constant width in points."""
    x, y = np.asarray(pts, float).T
    outer = line(ax, x, y, color=s.ink, lw=s.link_lw, solid_capstyle="round", zorder=zorder, alpha=alpha)
    inner = line(ax, x, y, color=s.link_fill, lw=s.link_lw - 2 * s.outline_lw, solid_capstyle="round",
                 zorder=zorder + 0.01, alpha=alpha)
    out += [outer, inner]


def _hull(points):
    import shapely

    hull = shapely.MultiPoint([tuple(p) for p in points]).convex_hull
    if hull.geom_type == "Polygon":
        return np.asarray(hull.exterior.coords)[:-1]
    if hull.geom_type == "LineString":
        return np.asarray(hull.coords)
    return np.asarray([points[0]])


def _rect(centre, u, length, width):
    n = perp(u)
    c = np.asarray(centre, float)
    return np.array([c - u * length / 2 - n * width / 2, c + u * length / 2 - n * width / 2,
                     c + u * length / 2 + n * width / 2, c - u * length / 2 + n * width / 2])


def draw_link_body(ax, geom: Geometry, n: int, s, labeler: Labeler | None = None, *, guides=True):
    """Draw link n alone: its bar or plate, its slider blocks, its gear, its pins and points. Returns the artists."""
    out = []
    pts = geom.link_points(n)
    coords = list(pts.values())
    sliders = [j for j in geom.prismatic if j.slider == n]
    gears = [(mesh, k) for mesh in geom.gears for k, m in enumerate(mesh.links) if m == n]
    if len(coords) == 2:
        _band(ax, coords, s, out)
        if labeler:
            labeler.segment(coords[0], coords[1], s.link_lw)
    elif len(coords) >= 3:
        hull = _hull(coords)
        if len(hull) >= 3:
            poly = Polygon(hull, closed=True, facecolor=s.plate_fill, edgecolor=s.ink, lw=s.outline_lw * 1.4,
                           joinstyle="round", zorder=2.0)
            put(ax, poly, hull)  # its corners are its extent: add_patch would find them through its transforms
            out.append(poly)
            if labeler:
                labeler.polyline(hull, closed=True)
        else:
            _band(ax, hull, s, out)
    for mesh, k in gears:
        out += (draw_annulus if mesh.ring == n else _gear)(ax, geom, n, pts[mesh.centers[k]], mesh.radii[k] * MM, s, labeler)
    for j in sliders:
        X, u = geom.guide(j)
        block = Polygon(_rect(X, u, 3.4 * geom.sym, 2.0 * geom.sym), closed=True, facecolor=s.link_fill,
                        edgecolor=s.ink, lw=s.outline_lw * 1.3, zorder=2.5)
        put(ax, block, block.get_xy())
        out.append(block)
        if labeler:
            corners = np.asarray(block.get_xy(), float)
            labeler.polyline(corners, closed=True)
            # A label inside a block would hide it: the block is a mark, not only an outline.
            labeler.box(*corners.min(axis=0), *corners.max(axis=0))
    if len(coords) == 1 and not sliders and not gears:
        dot = markers(ax, *coords[0], color=s.ink, ms=4, zorder=3)
        out.append(dot)
    # Pins and points of this link.
    joint_points = {j.point for j in geom.mech.joints_of(n) if isinstance(j, Revolute)}
    # A run of pins (or of dots) one after the other is one line of markers: drawn in the same order, a line
    # less to make and draw for each.
    runs: list = []
    for name, X in pts.items():
        joint = name in joint_points
        if runs and runs[-1][0] == joint:
            runs[-1][1].append(X)
        else:
            runs.append((joint, [X]))
        if labeler:
            labeler.dot(X, s.pin_size + s.outline_lw * 1.2 if joint else 3.6)
    for joint, points in runs:
        x, y = np.asarray(points, float).T
        if joint:
            out.append(markers(ax, x, y, ms=s.pin_size, mfc="white", mec=s.ink, mew=s.outline_lw * 1.2, zorder=5))
        else:
            out.append(markers(ax, x, y, ms=3.6, color=s.ink, zorder=5))
    return out


def _gear(ax, geom: Geometry, n: int, centre, r, s, labeler):
    """A gear: its teeth, its dashed pitch circle, a white hub and a spoke on the link's x-axis, all turning with it."""
    teeth, phase, module = geom.teeth[n]
    outline = gear_outline(centre, r, teeth, phase, module)
    body = Polygon(outline, closed=True, facecolor=s.plate_fill, edgecolor=s.ink, lw=s.outline_lw, joinstyle="miter",
                   zorder=1.6)
    pitch = Circle(centre, r, fill=False, edgecolor=s.ink, lw=s.thin_lw, linestyle=(0, (10, 3, 2, 3)), zorder=1.7)
    hub_r = 0.16 * r
    hub = Circle(centre, hub_r, facecolor="white", edgecolor=s.ink, lw=s.thin_lw, zorder=1.8)
    for p in (body, pitch, hub):
        ax.add_patch(p)
    # The reference mark: a spoke along the link's x-axis, from the hub to the roots of the teeth.
    th = geom.link_angle(n)
    e = np.array([math.cos(th), math.sin(th)])
    spoke = np.array([centre + e * hub_r, centre + e * (r - 1.6 * module)])
    mark = line(ax, *spoke.T, color=s.ink, lw=2.4, solid_capstyle="round", zorder=1.75)
    if labeler:
        labeler.polyline(outline, closed=True)
        labeler.polyline(arc_points(centre, hub_r, 0.0, 2 * math.pi, 25))
        labeler.segment(*spoke, 2.4)
    return [body, pitch, hub, mark]


def centre_of_mass(ax, X, s, zorder=5.2):
    """The centre-of-mass symbol: a small circle with a cross."""
    a = markers(ax, *X, ms=7, mfc="white", mec=s.ink, mew=1.0, zorder=zorder)
    b = markers(ax, *X, "+", ms=7, color=s.ink, mew=1.0, zorder=zorder + 0.01)
    return [a, b]


def _ground(ax, X, size, s, direction, out, labeler=None):
    """A ground symbol at pivot X: a triangle to a hatched base, on the side ``direction``."""
    d = unit(direction)
    n = perp(d)
    top = X
    base = X + d * 1.25 * size
    tri = Polygon([top, base + n * 0.85 * size, base - n * 0.85 * size], closed=True, facecolor="white",
                  edgecolor=s.ink, lw=s.outline_lw, zorder=1.2)
    line_pts = np.array([base + n * 1.3 * size, base - n * 1.3 * size])
    base_line = line(ax, *line_pts.T, color=s.ink, lw=s.outline_lw * 1.3, zorder=1.2, solid_capstyle="butt")
    hatch = Polygon([base + n * 1.3 * size, base - n * 1.3 * size, base - n * 1.3 * size + d * 0.55 * size,
                     base + n * 1.3 * size + d * 0.55 * size], closed=True, fill=False, hatch=s.ground_hatch,
                    edgecolor=s.ink, lw=0, zorder=1.1)
    for p in (tri, hatch):
        put(ax, p, p.get_xy())
    base_line.set_zorder(2.6)
    tri.set_zorder(2.6)
    hatch.set_zorder(2.55)
    out += [tri, base_line, hatch]
    if labeler:
        labeler.polyline([top, base + n * 0.85 * size, base - n * 0.85 * size], closed=True)
        labeler.segment(*line_pts)
        labeler.polyline(hatch.get_xy(), closed=True)  # the hatching: a label on it is hard to read


def _ground_direction(geom: Geometry, name: str, X):
    """The side of a frame pivot with most room: down unless a link goes that way."""
    dirs = []
    for j in geom.mech.joints:
        if isinstance(j, Revolute) and j.point == name and geom.mech.frame in j.links:
            n = (set(j.links) - {geom.mech.frame}).pop()
            for k, Y in geom.link_points(n).items():
                if k != name and np.hypot(*(Y - X)) > 1e-9:
                    dirs.append(unit(Y - X))
    cands = [np.array([0.0, -1.0]), np.array([-1.0, 0.0]), np.array([1.0, 0.0]), np.array([0.0, 1.0])]
    if not dirs:
        return cands[0]

    def room(c):
        return min(math.acos(max(-1.0, min(1.0, float(np.dot(c, d))))) for d in dirs)

    for c in cands:
        if room(c) >= math.radians(70):
            return c
    return max(cands, key=room)


def _rails(ax, geom: Geometry, j: Prismatic, s, out, labeler=None):
    """The guide of a prismatic pair: its centre line, and hatched rails for a frame guide or a slot in a moving one."""
    X, u = geom.guide(j)
    n = perp(u)
    h = 1.0 * geom.sym  # half the block's width
    R = 3.4 * geom.sym * 1.6
    T = geom.P[j.guide][j.through]
    t_through = float(np.dot(T - X, u))
    lo, hi = min(t_through, -R), max(t_through, R)
    cl = np.array([X + u * (lo - 0.6 * geom.sym), X + u * (hi + 0.6 * geom.sym)])
    centre = line(ax, *cl.T, color=s.ink, lw=s.thin_lw * 0.8, linestyle=(0, (10, 3, 2, 3)), zorder=1.0)
    out.append(centre)
    for side in (1.0, -1.0):
        a, b = X - u * R + side * n * h, X + u * R + side * n * h
        rail = line(ax, *np.array([a, b]).T, color=s.ink, lw=s.outline_lw * 1.3, zorder=1.3, solid_capstyle="butt")
        out.append(rail)
        if labeler:
            labeler.segment(a, b)
        if j.guide == geom.mech.frame:
            w = 0.55 * geom.sym
            hatch = Polygon([a, b, b + side * n * w, a + side * n * w], closed=True, fill=False, hatch=s.ground_hatch,
                            edgecolor=s.ink, lw=0, zorder=1.1)
            put(ax, hatch, hatch.get_xy())
            out.append(hatch)
            if labeler:
                labeler.polyline(hatch.get_xy(), closed=True)  # the hatching: a label on it is hard to read
    return cl


def draw_mechanism(construction, *, ax=None, labels=True, faint=False, emphasis=None, place=True, length_scale=None,
                   room=False, bar=True, **style) -> Drawn:
    """Draw the mechanism to scale at the construction's position, in mm.

    Links are bars between their points (plates for ternary links), pins
    small circles, frame pivots carry hatched ground symbols, sliders are
    blocks on hatched rails aligned with their guide, gears show their teeth,
    their pitch circles and a spoke along their x-axis (all turning with
    them), points and centres of mass are labelled (points too close for a
    label each share one), and a scale bar gives the length in mm.

    Parameters
    ----------
    construction : graphkin.graphical.Construction
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new headless figure when omitted.
    labels : bool
        Label the points (A, B, G3, ...).
    faint : bool
        Draw everything pale (a background for construction steps).
    emphasis : int, optional
        With ``faint``, a link drawn at full strength.
    place : bool
        Place the labels now. False when a drawing on top adds labels of its own and places them all
        (:func:`graphkin.draw.steps.draw_step_geometry` does): each placement lays every label out afresh,
        so placing the mechanism's alone first would be work thrown away.
    length_scale : float, optional
        k: print the drawing at 1:k (a true length of k mm printed 1 mm long; below 1, an enlargement). The
        scale bar states it; on a figure of its own the figure is sized so that it prints at that scale
        (:func:`graphkin.draw.paper.fit`); on a given ``ax``, the caller lays the figure out.
    room : bool
        Leave room for the points the construction finds (a point of concurrency), where a student draws the
        lines of action to them; the points are not drawn.
    bar : bool
        Draw the length scale bar. False when the caller draws one for all (a figure of several panels at one
        scale) or one that stays put (an animation).
    **style
        Overrides of :class:`graphkin.draw.style.Style` fields.

    Returns
    -------
    Drawn
        The artists; ``.labels`` maps point names to their texts.
    """
    s = _style.resolve(**style)
    own = ax is None
    paper = 1.0 / length_scale if length_scale else None
    # A drawing printed at a scale on a figure of its own sets its limits and never shows an axis.
    ax = new_axes(ax, (6.0, 4.5), s, bare=bool(own and paper))
    existing = had_content(ax)
    setup_axes(ax)
    drawn = Drawn(ax)
    c = construction
    if not c.points:
        t = ax.text(0.5, 0.5, f"No drawing: {c.reason or 'no geometry'}", transform=ax.transAxes, ha="center",
                    va="center", fontsize=s.label_size, color=s.unknown, wrap=True)
        drawn.add(t)
        return drawn
    geom = Geometry(c)
    lab = Labeler(ax, s)
    extent = [p for d in geom.P.values() for p in d.values()]
    # Ground and guides first (underneath).
    for j in geom.prismatic:
        before = len(drawn)
        cl = _rails(ax, geom, j, s, drawn, lab)
        extent += list(cl)
        if faint:
            for a in drawn[before:]:
                a.set_alpha(s.faint_alpha)
    for name, X in geom.frame_pivots().items():
        before = len(drawn)
        d = _ground_direction(geom, name, X)
        _ground(ax, X, geom.sym, s, d, drawn, lab)
        extent.append(X + d * 2.0 * geom.sym)
        if faint:
            for a in drawn[before:]:
                a.set_alpha(s.faint_alpha)
    for mesh, centre, r in frame_gears(geom):  # a held sun or annulus, under the planets
        gear = (draw_annulus if mesh.ring == geom.mech.frame else _gear)(ax, geom, geom.mech.frame, centre, r, s, lab)
        drawn += gear
        extent += [centre - 1.2 * r, centre + 1.2 * r]
        for a in gear if faint else ():
            a.set_alpha(s.faint_alpha)
    for n in geom.mech.moving:
        before = len(drawn)
        drawn += draw_link_body(ax, geom, n, s, lab)
        for mesh in geom.gears:
            for m, centre, r in geom.gear_circles(mesh):
                if m == n:
                    extent += [centre - 1.1 * r, centre + 1.1 * r]
        if faint and n != emphasis:
            for a in drawn[before:]:
                a.set_alpha(s.faint_alpha)
    # Frame points that are not pivots (a guide's reference point): a small dot.
    pivots = geom.frame_pivots()
    for name, X in geom.P.get(geom.mech.frame, {}).items():
        if name not in pivots:
            dot = markers(ax, *X, ms=3.6, color=s.ink, zorder=5, alpha=s.faint_alpha if faint else None)
            drawn.add(dot)
            lab.dot(X, 3.6)
    for n, X in geom.G.items():
        if geom.mech.link(n).mass > 0:
            for a in centre_of_mass(ax, X, s):
                if faint and n != emphasis:
                    a.set_alpha(s.faint_alpha)
                drawn.add(a)
            lab.dot(X, 8.0)
    for key, P in c.pitch_points.items():
        X = np.asarray(P, float) * MM
        dot = markers(ax, *X, ms=3.6, color=s.ink, zorder=5.1, alpha=s.faint_alpha if faint else None)
        drawn.add(dot)
        lab.dot(X, 3.6)
    if room:
        # Every point the construction draws here (those far off are drawn another way: graphical.paper.sheet_reach).
        extent += [np.asarray(X, float) * MM for X in sheet_reach(c).points()]
    # A length scale: the drawing is to scale, in mm.
    arr = np.asarray(extent, float)
    lo = arr.min(axis=0)
    value = nice_round(0.2 * geom.size)
    if paper:
        # On paper a bar some 20–40 mm long reads best, whatever the scale.
        value = nice_round(30.0 / paper)
    if bar:
        bar_at = np.array([lo[0], lo[1] - 0.1 * geom.size])
        drawn += scale_bar(ax, bar_at, value, value, s=s, unit_text="mm", tick=0.012 * geom.size, labeler=lab,
                           alpha=s.faint_alpha if faint else None,
                           note=f"scale {length_text(length_scale)}" if paper else None)
        extent += [bar_at, bar_at + [value, 0.0]]
    set_limits(ax, extent, margin=0.09, existing=existing)
    if room:
        # The room to draw in, framed: a worksheet's drawing area, kept whole when the figure is cropped.
        drawn.add(ax.add_patch(Rectangle((0, 0), 1, 1, transform=ax.transAxes, fill=False, lw=0.6,
                                         edgecolor=_style.GREY, zorder=0.5)))
    if own and paper:
        fit(ax, paper)
    if labels:
        view = float(np.max(np.ptp(np.asarray(extent, float), axis=0))) * 1.18
        ppu = paper * PT_PER_MM if paper else points_per_unit(ax, view)
        _label_points(ax, geom, c, s, lab, drawn, faint, emphasis, near=NEAR / ppu)
    if place:
        lab.place()
        drawn += lab.leaders
    ax._graphkin_labeler = lab  # what a drawing on top (a construction step) keeps off
    return drawn


NEAR = 9.0
"""Points closer than this [pt] on the drawing share one label (``C₃, C₄``; ``B, G₃``)."""


def _candidates(X, away, spread=0.0):
    """Label spots around a point (or a cluster of points ``spread`` points across): near ones first."""
    return point_label_candidates(X, away, [pad + spread for pad in (6.0, 13.0, 22.0, 34.0, 48.0, 64.0)])


def _point_name(name: str, links, shared) -> str:
    """A point's label; a name that two links use for different points gets the link: ``C₃``, ``C₄``."""
    if name not in shared or len(links) != 1:
        return sub(name)
    return sub(f"{name}{links[0]}") if name.isalpha() and len(name) == 1 else f"{sub(name)} (link {links[0]})"


def _label_points(ax, geom, c, s, lab, drawn, faint, emphasis, only=None, near=0.0):
    """Label the points, centres of mass and pitch points (of link ``only``, or all).

    A centre of mass on a named point is named with it (``B (G₄)``); points
    within ``near`` [mm] of each other, too close for a label each, share
    one (``C₃, C₄``).
    """
    seen = {}
    for n, pts in geom.P.items():
        if only is not None and n != only:
            continue
        for name, X in pts.items():
            key = (name, round(float(X[0]), 6), round(float(X[1]), 6))
            seen.setdefault(key, []).append(n)
    # Two links may use one name for different points (the strip cutter's blades, C on 3 and on 4).
    places = {}
    for name, _, _ in seen:
        places[name] = places.get(name, 0) + 1
    shared = {name for name, count in places.items() if count > 1}
    tol = 1e-6 * geom.size
    g_at = {}
    for n, X in geom.G.items():
        if geom.mech.link(n).mass > 0 and (only is None or n == only):
            for (name, x, y), links in seen.items():
                if n in links and math.hypot(X[0] - x, X[1] - y) <= tol:
                    g_at[n] = (name, x, y)
                    break
    # (text, position, direction away from the links, keys, links it belongs to)
    entries = []
    for (name, x, y), links in seen.items():
        X = np.array([x, y])
        cents = [geom.centroid(n) for n in links if n != geom.mech.frame and len(geom.link_points(n)) > 1]
        away = (X - np.mean(cents, axis=0) if cents else np.array([0.0, -1.0]) if geom.mech.frame in links
                else np.array([0.0, 1.0]))
        if np.hypot(*away) <= tol:
            away = np.array([-1.0, 0.4])
        gs = [n for n, k in g_at.items() if k == (name, x, y)]
        text = _point_name(name, links, shared) + "".join(f" ({sub(f'G{n}')})" for n in gs)
        taken = name in drawn.labels or any(e[3][0] == name for e in entries)
        key = f"{name}@{'/'.join(map(str, links))}" if taken else name
        entries.append((text, X, away, [key] + [f"G{n}" for n in gs], set(links)))
    for n, X in geom.G.items():
        if geom.mech.link(n).mass > 0 and n not in g_at and (only is None or n == only):
            cent = geom.centroid(n)
            away = X - cent if cent is not None and np.hypot(*(X - cent)) > tol else np.array([1.0, -1.0])
            entries.append((sub(f"G{n}"), X, away, [f"G{n}"], {n}))
    for key, P in c.pitch_points.items():
        if only is not None and only not in key:
            continue
        # One mesh's pitch point is P, as the books write it; several are told apart by their gears (P23, P34).
        text = "P" if len(c.pitch_points) == 1 else sub(f"P{key[0]}{key[1]}")
        entries.append((text, np.asarray(P, float) * MM, np.array([0.0, 1.0]), [f"P{key[0]}{key[1]}"], set(key)))
    # Points nearer each other than ``near`` share a label, in the order they were named.
    groups = []
    for e in entries:
        for g in groups:
            if any(math.dist(e[1], f[1]) < near for f in g):
                g.append(e)
                break
        else:
            groups.append([e])
    for g in groups:
        X = np.mean([e[1] for e in g], axis=0)
        away = np.sum([unit(e[2]) for e in g], axis=0)
        spread = max(math.dist(e[1], X) for e in g) / max(near, 1e-300) * NEAR
        t = lab.label(", ".join(e[0] for e in g), _candidates(X, away, spread), size=s.label_size)
        links = set().union(*(e[4] for e in g))
        if faint and emphasis not in links:
            t.set_alpha(s.faint_alpha + 0.2)
        for e in g:
            for key in e[3]:
                drawn.labels[key] = t
        drawn.add(t)
