"""The mechanism to scale at one position: bars, plates, pins, ground, sliders on their guides, gears."""

from __future__ import annotations

import math

import numpy as np
from matplotlib.patches import Circle, Polygon

from ..model import GearMesh, Prismatic, Revolute
from . import style as _style
from ._common import (MM, Drawn, Labeler, had_content, line, markers, new_axes, perp, point_label_candidates,
                      set_limits, setup_axes, sub, unit)


class Geometry:
    """The mechanism's geometry at the construction's position, in mm, with what drawing needs.

    Attributes
    ----------
    P : dict of int to dict of str to ndarray
        Every named point of every link [mm].
    G : dict of int to ndarray
        Centres of mass of the moving links [mm].
    size : float
        Largest extent of the drawing [mm].
    sym : float
        Size of ground symbols and slider blocks [mm].
    """

    def __init__(self, c):
        self.c = c
        self.mech = c.mechanism
        self.P = {n: {k: np.asarray(v, float) * MM for k, v in pts.items()} for n, pts in c.points.items()}
        self.G = {n: np.asarray(v, float) * MM for n, v in c.G.items()}
        pts = [p for d in self.P.values() for p in d.values()]
        for mesh in self.gears:
            for n, centre, r in self.gear_circles(mesh):
                pts += [centre - r, centre + r]
        pts = np.asarray(pts, float).reshape(-1, 2)
        ext = pts.max(axis=0) - pts.min(axis=0) if len(pts) else np.zeros(2)
        self.size = max(float(np.max(ext)) if len(pts) else 0.0, 1.0)
        self.sym = 0.032 * self.size

    @property
    def gears(self):
        return [j for j in self.mech.joints if isinstance(j, GearMesh)]

    @property
    def prismatic(self):
        return [j for j in self.mech.joints if isinstance(j, Prismatic)]

    def gear_circles(self, mesh):
        """(link, centre [mm], pitch radius [mm]) of both gears of a mesh."""
        return [(n, self.P[n][cname], r * MM) for n, cname, r in zip(mesh.links, mesh.centers, mesh.radii)]

    def angle(self, n: int):
        """Angle θ of link n's frame [rad] from two of its points (0 for the frame); None with fewer than two."""
        if n == self.mech.frame:
            return 0.0
        local = self.mech.link(n).points
        names = [k for k in local if k in self.P.get(n, {})]
        best, pair = 0.0, None
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                d = math.dist(local[a], local[b])
                if d > best:
                    best, pair = d, (a, b)
        if pair is None:
            return None
        a, b = pair
        (xa, ya), (xb, yb) = local[a], local[b]
        g = self.P[n][b] - self.P[n][a]
        return math.atan2(g[1], g[0]) - math.atan2(yb - ya, xb - xa)

    def guide(self, joint: Prismatic):
        """The guide line of a prismatic pair: (slider point [mm], unit direction).

        Its direction is θ_guide + ``joint.direction``; θ_guide comes from two
        points of the guide link, or from the slider's orientation
        (θ_slider = θ_guide + direction − slider_direction) when the guide
        link carries one point only.
        """
        X = self.P[joint.slider][joint.point]
        th = self.angle(joint.guide)
        if th is None:
            ts = self.angle(joint.slider)
            th = 0.0 if ts is None else ts - joint.direction + joint.slider_direction
        a = th + joint.direction
        return X, np.array([math.cos(a), math.sin(a)])

    def link_points(self, n):
        return self.P.get(n, {})

    def centroid(self, n):
        pts = list(self.link_points(n).values())
        return np.mean(pts, axis=0) if pts else None

    def pins(self):
        """Revolute joint points: {(name, link a, link b): position}."""
        out = {}
        for j in self.mech.joints:
            if isinstance(j, Revolute):
                a, b = j.links
                n = b if a == self.mech.frame else a
                out[(j.point, a, b)] = self.P[n][j.point]
        return out

    def frame_pivots(self):
        """Frame points of revolute joints: {name: position}."""
        return {j.point: self.P[self.mech.frame][j.point] for j in self.mech.joints
                if isinstance(j, Revolute) and self.mech.frame in j.links}


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
            ax.add_patch(poly)
            out.append(poly)
            if labeler:
                labeler.polyline(hull, closed=True)
        else:
            _band(ax, hull, s, out)
    for mesh, k in gears:
        centre = pts[mesh.centers[k]]
        r = mesh.radii[k] * MM
        add = max(0.05 * r, 0.004 * geom.size)
        body = Circle(centre, r + add, facecolor=s.plate_fill, edgecolor=s.ink, lw=s.outline_lw, zorder=1.6)
        pitch = Circle(centre, r, fill=False, edgecolor=s.ink, lw=s.thin_lw, linestyle=(0, (10, 3, 2, 3)), zorder=1.7)
        hub = Circle(centre, 0.22 * r, facecolor="white", edgecolor=s.ink, lw=s.thin_lw, zorder=1.8)
        for p in (body, pitch, hub):
            ax.add_patch(p)
        out += [body, pitch, hub]
        if labeler:
            labeler.polyline(np.asarray(pitch.get_path().vertices) * r + centre)
    for j in sliders:
        X, u = geom.guide(j)
        block = Polygon(_rect(X, u, 3.4 * geom.sym, 2.0 * geom.sym), closed=True, facecolor=s.link_fill,
                        edgecolor=s.ink, lw=s.outline_lw * 1.3, zorder=2.5)
        ax.add_patch(block)
        out.append(block)
        if labeler:
            labeler.polyline(block.get_xy(), closed=True)
    if len(coords) == 1 and not sliders and not gears:
        dot = markers(ax, *coords[0], color=s.ink, ms=4, zorder=3)
        out.append(dot)
    # Pins and points of this link.
    joint_points = {j.point for j in geom.mech.joints_of(n) if isinstance(j, Revolute)}
    for name, X in pts.items():
        if name in joint_points:
            pin = markers(ax, *X, ms=s.pin_size, mfc="white", mec=s.ink, mew=s.outline_lw * 1.2, zorder=5)
        else:
            pin = markers(ax, *X, ms=3.6, color=s.ink, zorder=5)
        out.append(pin)
    return out


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
        ax.add_patch(p)
    base_line.set_zorder(2.6)
    tri.set_zorder(2.6)
    hatch.set_zorder(2.55)
    out += [tri, base_line, hatch]
    if labeler:
        labeler.polyline([top, base + n * 0.85 * size, base - n * 0.85 * size], closed=True)
        labeler.segment(*line_pts)


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
            ax.add_patch(hatch)
            out.append(hatch)
    return cl


def draw_mechanism(construction, *, ax=None, labels=True, faint=False, emphasis=None, **style) -> Drawn:
    """Draw the mechanism to scale at the construction's position, in mm.

    Links are bars between their points (plates for ternary links), pins
    small circles, frame pivots carry hatched ground symbols, sliders are
    blocks on hatched rails aligned with their guide, gears show their pitch
    circles, and points and centres of mass are labelled.

    Parameters
    ----------
    construction : graphkin.graphic.Construction
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new headless figure when omitted.
    labels : bool
        Label the points (A, B, G3, ...).
    faint : bool
        Draw everything pale (a background for construction steps).
    emphasis : int, optional
        With ``faint``, a link drawn at full strength.
    **style
        Overrides of :class:`graphkin.draw.style.Style` fields.

    Returns
    -------
    Drawn
        The artists; ``.labels`` maps point names to their texts.
    """
    s = _style.resolve(**style)
    ax = new_axes(ax, (6.0, 4.5), s)
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
    for n, X in geom.G.items():
        if geom.mech.link(n).mass > 0:
            for a in centre_of_mass(ax, X, s):
                if faint and n != emphasis:
                    a.set_alpha(s.faint_alpha)
                drawn.add(a)
    for key, P in c.pitch_points.items():
        X = np.asarray(P, float) * MM
        dot = markers(ax, *X, ms=3.6, color=s.ink, zorder=5.1, alpha=s.faint_alpha if faint else None)
        drawn.add(dot)
    if labels:
        _label_points(ax, geom, c, s, lab, drawn, faint, emphasis)
    set_limits(ax, extent, margin=0.09, existing=existing)
    lab.place()
    return drawn


def _candidates(X, away):
    out = []
    for pad in (6.0, 13.0, 22.0):
        out += point_label_candidates(X, away, pad)
    return out


def _point_name(name: str, links, shared) -> str:
    """A point's label; a name that two links use for different points gets the link: ``C₃``, ``C₄``."""
    if name not in shared or len(links) != 1:
        return sub(name)
    return sub(f"{name}{links[0]}") if name.isalpha() and len(name) == 1 else f"{sub(name)} (link {links[0]})"


def _label_points(ax, geom, c, s, lab, drawn, faint, emphasis, only=None):
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
    # A centre of mass on a named point is named with it: "B (G4)".
    tol = 1e-6 * geom.size
    g_at = {}
    for n, X in geom.G.items():
        if geom.mech.link(n).mass > 0 and (only is None or n == only):
            for (name, x, y), links in seen.items():
                if n in links and math.hypot(X[0] - x, X[1] - y) <= tol:
                    g_at[n] = (name, x, y)
                    break
    for (name, x, y), links in seen.items():
        X = np.array([x, y])
        cents = [geom.centroid(n) for n in links if n != geom.mech.frame and len(geom.link_points(n)) > 1]
        away = (X - np.mean(cents, axis=0) if cents else np.array([0.0, -1.0]) if geom.mech.frame in links
                else np.array([0.0, 1.0]))
        if np.hypot(*away) <= tol:
            away = np.array([-1.0, 0.4])
        gs = [n for n, k in g_at.items() if k == (name, x, y)]
        text = _point_name(name, links, shared) + "".join(f" ({sub(f'G{n}')})" for n in gs)
        t = lab.label(text, _candidates(X, away), size=s.label_size)
        if faint and emphasis not in links:
            t.set_alpha(s.faint_alpha + 0.2)
        key = name if name not in drawn.labels else f"{name}@{'/'.join(map(str, links))}"
        drawn.labels[key] = t
        for n in gs:
            drawn.labels[f"G{n}"] = t
        drawn.add(t)
    for n, X in geom.G.items():
        if geom.mech.link(n).mass > 0 and n not in g_at and (only is None or n == only):
            cent = geom.centroid(n)
            away = X - cent if cent is not None and np.hypot(*(X - cent)) > tol else np.array([1.0, -1.0])
            t = lab.label(sub(f"G{n}"), _candidates(X, away), size=s.label_size)
            if faint and n != emphasis:
                t.set_alpha(s.faint_alpha + 0.2)
            drawn.labels[f"G{n}"] = t
            drawn.add(t)
    for key, P in c.pitch_points.items():
        if only is not None and only not in key:
            continue
        X = np.asarray(P, float) * MM
        t = lab.label("P", _candidates(X, np.array([0.0, 1.0])), size=s.label_size)
        drawn.labels[f"P{key[0]}{key[1]}"] = t
        drawn.add(t)
