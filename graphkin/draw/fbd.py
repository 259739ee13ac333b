"""Free-body diagrams: one link alone with every force and couple on it, and its inertia resultant offset by h."""

from __future__ import annotations

import math

import numpy as np

from graphkin.draw import style as _style
from graphkin.draw.arrows import arc_points, arrow, moment_arrow, perp, unit
from graphkin.draw.axes import (
    MM,
    PT_PER_MM,
    Drawn,
    finish,
    had_content,
    line,
    new_axes,
    points_per_unit,
    set_limits,
    setup_axes,
)
from graphkin.draw.geometry import Geometry
from graphkin.draw.labels import Labeler, arrow_label_candidates, measuring_renderer, point_label_candidates, text_size
from graphkin.draw.mechanism import NEAR, _label_points, centre_of_mass, draw_link_body
from graphkin.draw.scales import dimension, nice_round, scale_bar
from graphkin.draw.text import sub
from graphkin.model import Prismatic
from graphkin.notation import num

FAR_OFFSET = 1.2
"""An inertia resultant's line further from G than this many link sizes is drawn nearer, with a broken dimension."""


def loads_on(construction, link: int) -> dict:
    """Every load on a link at the construction's position, ready to draw.

    Returns
    -------
    dict
        ``"forces"``: list of (name, vector [N], point [m], kind) with kind
        ``"unknown"`` (joint forces), ``"known"`` (external forces, weight),
        ``"inertia"`` (the inertia resultant, on its offset line) or
        ``"driver"`` (a slider's driving force);
        ``"couples"``: list of (name, torque [N·m], centre [m], kind);
        ``"inertia"``: the construction's inertia entry of the link, or None.
    """
    c = construction
    mech = c.mechanism
    forces, couples = [], []
    for a in c.forces_on(link):
        forces.append((a.name, tuple(a.vector), tuple(a.at), "unknown"))
    for a in c.external.get(link, []):
        forces.append((a.name, tuple(a.vector), tuple(a.at), "known"))
    G = c.G.get(link)
    # The construction's own torques: a tabulated or motion-following one at its value here.
    for name, T in c.torques.get(link, []):
        couples.append((name, T, G, "known"))
    inert = c.inertia.get(link)
    if inert is not None:
        F, T = inert["F"], inert["T"]
        if math.hypot(*F) > 0 and inert["line_point"] is not None:
            forces.append((f"R{link}i", tuple(F), tuple(inert["line_point"]), "inertia"))
        elif T:
            couples.append((f"T{link}i", T, G, "inertia"))
    d = mech.driver
    if d.link == link and math.isfinite(c.effort):
        joint = mech.joint_between(mech.frame, link)
        if d.crank:
            couples.append((d.symbol, c.effort, c.points[mech.frame][joint.point], "driver"))
        else:
            vec = None
            for step in c.steps:
                for a in step.polygon:
                    if a.name == d.symbol:
                        vec = a.vector
            if vec is None:
                X, u = Geometry(c).guide(joint)
                vec = tuple(c.effort * u)
            forces.append((d.symbol, tuple(vec), c.points[link][joint.point], "driver"))
    largest = max([math.hypot(*f[1]) for f in forces] + [0.0])
    size = max([math.dist(p, q) for p in c.points[link].values() for q in c.points[link].values()] + [1e-3])
    for joint in mech.joints_of(link):
        if isinstance(joint, Prismatic):
            lo, hi = sorted(joint.links)
            C = c.couple.get((lo, hi), 0.0)
            C = C if link == hi else -C
            if abs(C) > 1e-9 * max(largest * size, 1e-300):
                other = lo if link == hi else hi
                couples.append((f"C{other}{link}", C, c.points[joint.slider][joint.point], "unknown"))
    return {"forces": forces, "couples": couples, "inertia": inert}


def _crowding(option, X, placed, L):
    """How much an arrow (tail, tip) would run along arrows already drawn from the same point."""
    tail, tip = option
    away = tip - X if np.hypot(*(tip - X)) > np.hypot(*(tail - X)) else tail - X
    total = 0.0
    for Y, t2, h2 in placed:
        if np.hypot(*(Y - X)) > 1e-6 * L:
            continue
        away2 = h2 - Y if np.hypot(*(h2 - Y)) > np.hypot(*(t2 - Y)) else t2 - Y
        la, lb = np.hypot(*away), np.hypot(*away2)
        if la and lb and np.dot(away, away2) / (la * lb) > math.cos(math.radians(20)):
            total += min(la, lb)
    return total


def _color(kind, s):
    return {"unknown": s.unknown, "known": s.known, "inertia": s.known, "driver": s.driver}[kind]


def draw_free_body(construction, link: int, *, ax=None, force_scale=None, title=True, unknowns=True, paper=None,
                   bar=True, place=True, **style) -> Drawn:
    """The free-body diagram of one link.

    The link alone, every force on it as an arrow at its point of application
    (joint forces F_ij / G_ij of the other links on it, external loads and
    weight, a slider's driving force), couples as curved arrows (the crank's
    driving torque, external torques, a pure inertia torque), and its inertia
    resultant on its line offset from G by h, with h dimensioned. An arrow
    that pushes on the link ends at its point, one that pulls starts there.

    Where h is more than :data:`FAR_OFFSET` times the link's size, the
    resultant's line is drawn nearer G (at 0.75 of the link's size) and the
    dimension carries a break mark and reads "h = … mm (not to scale)":
    drawn true, the link would shrink to a speck beside it.

    At a sliding pair with friction, the guide's normal is drawn (dashed)
    through the slider's point, with the friction angle ρ (tan ρ = μ) marked
    between it and the guide's force.

    Parameters
    ----------
    construction : graphkin.graphical.Construction
    link : int
        A moving link.
    ax : matplotlib.axes.Axes, optional
    force_scale : float, optional
        Arrow scale [N per mm of the drawing]; by default the construction's
        ``force_scale`` times the 1–2–5 factor that draws the largest force
        about 40 % as long as the link. A scale bar shows it.
    title : bool
        Put "Free body: link 3 (rod AB)" above.
    unknowns : bool
        Draw the forces the construction finds (joint forces, the driver's
        effort). ``False`` leaves only what a student is given — the inertia
        resultant on its offset line, external loads, the scale bar — for an
        exercise in which they draw the polygon themselves.
    paper : float, optional
        Millimetres of paper per millimetre of the mechanism (1/k at 1:k), for a
        drawing printed at a stated scale (:mod:`graphkin.draw.paper` sizes the
        figure): sizes in points (arrowheads, gaps) are worked out for it.
    bar : bool
        Draw the force scale bar (a figure of several free bodies draws one for all).
    place : bool
        Place the labels now. False when the figure is laid out afterwards
        (:func:`graphkin.draw.paper.arrange` places them once the axes have their printed size).
    **style
        Overrides of :class:`graphkin.draw.style.Style` fields.

    Returns
    -------
    Drawn
        ``.arrows`` and ``.ends`` (tail, tip [mm]) by force name, ``.labels``
        by name (forces, couples, points, ``"h"``, and ``"rho"`` and
        ``"normal"`` at a sliding pair with friction), ``.scale`` [N per mm].
    """
    s = _style.resolve(**style)
    c = construction
    ax = new_axes(ax, (5.5, 5.0), s)
    existing = had_content(ax)
    setup_axes(ax)
    drawn = Drawn(ax)
    mech = c.mechanism
    body = mech.link(link)
    if link == mech.frame or link not in mech.moving:
        raise ValueError(f"link {link} is not a moving link of the mechanism (moving: {mech.moving})")
    if title:
        title = title if isinstance(title, str) else f"Free body: {body.label}"
        if not paper and _too_wide(ax, title, s, size=s.title_size, share=1.0):
            # A long link name in a small panel (the explorer's) would run into the next panel's title.
            title = title.replace(" (", "\n(", 1)
        ax.set_title(title, fontsize=s.title_size, color=s.ink)
    if not c.valid or not c.points:
        drawn.add(ax.text(0.5, 0.5, f"No solution here: {c.reason}", transform=ax.transAxes, ha="center", va="center",
                          fontsize=s.label_size, color=s.unknown, wrap=True))
        return drawn
    geom = Geometry(c)
    lab = Labeler(ax, s)
    drawn += draw_link_body(ax, geom, link, s, lab)
    G = geom.G[link]
    if body.mass > 0:
        drawn += centre_of_mass(ax, G, s)
        lab.dot(G, 8.0)
    loads = loads_on(c, link)
    if not unknowns:
        loads = {**loads, "forces": [f for f in loads["forces"] if f[3] not in ("unknown", "driver")],
                 "couples": [m for m in loads["couples"] if m[3] not in ("unknown", "driver")]}
    pts = list(geom.link_points(link).values())
    centroid = np.mean(pts, axis=0) if pts else G
    extent = list(pts) + [G]
    for mesh in geom.gears:
        for n, centre, r in geom.gear_circles(mesh):
            if n == link:
                extent += [centre - 1.1 * r, centre + 1.1 * r]
    if len(pts) == 1:
        extent += [pts[0] - 2.5 * geom.sym, pts[0] + 2.5 * geom.sym]
    own = float(np.max(np.ptp(np.asarray(extent, float), axis=0)))
    # The inertia resultant's line, drawn nearer G when it is far off (see above).
    inert = loads["inertia"]
    line_point = None
    broken = False
    if inert is not None and inert["line_point"] is not None:
        line_point = np.asarray(inert["line_point"], float) * MM
        size = max(own, 6 * geom.sym)
        far = float(np.hypot(*(line_point - G)))
        if far > FAR_OFFSET * size:
            line_point = G + (line_point - G) * (0.75 * size / far)
            broken = True
        extent.append(line_point)
        loads = {**loads, "forces": [(n, F, tuple(line_point / MM) if kind == "inertia" else at, kind)
                                     for n, F, at, kind in loads["forces"]]}
    ext = np.ptp(np.asarray(extent, float), axis=0)
    L = max(float(np.max(ext)), 14 * geom.sym)
    largest = max([math.hypot(*f[1]) for f in loads["forces"]] + [0.0])
    if force_scale is None:
        base = c.force_scale if c.force_scale > 0 else 1.0
        force_scale = base * nice_round(largest / (0.42 * L) / base) if largest > 0 else base
    drawn.scale = force_scale
    ends = []
    placed = []
    own = {}  # each force's arrow, by name, for its label to keep nearer it than any other (Labeler.arrow)
    ppu = paper * PT_PER_MM if paper else points_per_unit(ax, 1.4 * L)
    # Forces.
    for name, F, at, kind in loads["forces"]:
        F = np.asarray(F, float)
        X = np.asarray(at, float) * MM
        size = math.hypot(*F)
        color = _color(kind, s)
        if size <= 1e-9 * max(largest, 1e-300):
            t = lab.label(f"{sub(name)} = 0", _around(X, X - centroid, (8.0, 15.0, 24.0)), color=color)
            drawn.labels[name] = t
            drawn.add(t)
            continue
        v = F / force_scale
        pull, push = (X, X + v), (X - v, X)  # starts at its point / ends there
        prefer = push if kind != "inertia" and float(np.dot(F, centroid - X)) > 1e-9 * size * L else pull
        other = pull if prefer is push else push
        tail, tip = min((prefer, other), key=lambda o: (_crowding(o, X, placed, L), o is not prefer))
        placed.append((X, tail, tip))
        a = arrow(ax, tail, tip, color=color, lw=s.known_lw if kind in ("known", "inertia") else s.unknown_lw, s=s,
                  hollow=kind == "unknown", zorder=4.2, gid=f"fbd{link}:{name}", pt_per_unit=ppu)
        drawn.arrows[name] = a
        drawn.ends[name] = (tuple(tail), tuple(tip))
        drawn.add(a)
        own[name] = lab.arrow(tail, tip, a.get_linewidth(), a.get_mutation_scale())
        ends += [tail, tip]
    if line_point is not None and math.hypot(*inert["F"]) > 0:
        P = line_point
        e = unit(inert["F"])
        ell = math.hypot(*inert["F"]) / force_scale
        ln = np.array([P - e * max(0.45 * ell, 0.2 * L), P + e * max(1.4 * ell, ell + 0.2 * L)])
        drawn.add(line(ax, *ln.T, color=s.known, lw=s.thin_lw, linestyle=(0, (6, 3)), zorder=3.0))
        lab.segment(*ln, soft=True)
        h = inert["h"] or 0.0
        if h * MM > 1e-6 * L:
            text = f"h = {num(h * MM, power='superscript')} mm" + (" (not to scale)" if broken else "")
            # Points per mm of drawing, roughly (the view spans about 1.3 L): arrows go outside below ~16 pt.
            drawn += dimension(ax, lab, G, P, text, s=s, small=16 / ppu, color=s.ink, broken=broken)
            drawn.labels["h"] = drawn[-1]
            # A short dimension's arrows stand outside it, pointing in (0.8 × small, scales.dimension): the view
            # and the scale bar under it keep clear of them.
            d = unit(P - G) if np.hypot(*(P - G)) > 0 else np.array([1.0, 0.0])
            extent += [G - d * 0.8 * 16 / ppu, P + d * 0.8 * 16 / ppu]
        elif len(pts) > 1:
            # A body that turns: its resultant passes through G, said in words. A slider (one point) never turns:
            # "h = 0" there would be one more label on its one crowded point.
            away = G - centroid if np.hypot(*(G - centroid)) else (1, -1)
            t = lab.label("h = 0", _around(G, away, (9.0, 16.0, 26.0)), size=s.small_size)
            drawn.labels["h"] = t
            drawn.add(t)
    if unknowns:
        ends += _friction_angle(ax, c, geom, link, drawn, lab, s, ppu)
    # Couples, on rings of growing radius around each centre (outside a gear's hub).
    gear_r = max([r for mesh in geom.gears for n, _, r in geom.gear_circles(mesh) if n == link] + [0.0])
    rings: dict = {}
    for name, T, centre, kind in loads["couples"]:
        X = np.asarray(centre if centre is not None else G / MM, float) * MM
        key = (round(float(X[0]), 6), round(float(X[1]), 6))
        k = rings.get(key, 0)
        rings[key] = k + 1
        r = max(0.09 * L, 0.3 * gear_r) + 0.05 * k * L
        color = _color(kind, s)
        a, arc, mid = moment_arrow(ax, X, r, T > 0, color=color, lw=s.known_lw if kind != "unknown" else s.unknown_lw,
                                   s=s, start=-0.7 * math.pi + 0.35 * k, zorder=4.1, gid=f"fbd{link}:{name}")
        drawn.arrows[name] = a
        drawn.add(a)
        lab.curve(arc, a.get_linewidth(), a.get_mutation_scale(), named=True)
        extent += [X - 1.15 * r, X + 1.15 * r]
        text = f"{sub(name)} = {num(abs(T), power='superscript')} N·m {'CCW' if T > 0 else 'CW'}"
        if not paper and _too_wide(ax, text, s):
            # In a small panel (the explorer's) a long reading finds no spot clear of a long link: the unit and
            # the sense go on a second line.
            text = text.replace(" N·m ", "\nN·m ")
        pads = [s.label_pad, 3 * s.label_pad, 7 * s.label_pad, 12 * s.label_pad]
        if gear_r:
            # Just outside the teeth, where the gear's face is too busy.
            rim = (1.08 * gear_r - r) * ppu
            pads += [rim + s.label_pad, rim + 3 * s.label_pad, rim + 7 * s.label_pad]
        cands = [(p, p - X, pad) for pad in pads for p in [mid] + list(arc[::4])]
        t = lab.label(text, cands, color=color)
        drawn.labels[name] = t
        drawn.add(t)
    # Force labels, after every arrow is known as an obstacle.
    for name, F, at, kind in loads["forces"]:
        if name not in drawn.ends:
            continue
        tail, tip = (np.asarray(p) for p in drawn.ends[name])
        mid = 0.5 * (tail + tip)
        t = lab.label(sub(name), arrow_label_candidates(tail, tip, mid - centroid, s.label_pad), color=_color(kind, s),
                      own=own[name], gid=f"label:fbd{link}:{name}")
        drawn.labels[name] = t
        drawn.add(t)
    extent += ends
    arr = np.asarray(extent, float)
    lo, hi = arr.min(axis=0), arr.max(axis=0)
    span = float(np.max(hi - lo))
    if bar:
        value = nice_round(0.22 * span * force_scale)
        bar_at = np.array([lo[0], lo[1] - 0.1 * span])
        drawn += scale_bar(ax, bar_at, value / force_scale, value, s=s, tick=0.012 * span, labeler=lab)
        extent += [bar_at, bar_at + [value / force_scale, 0]]
    set_limits(ax, extent, margin=0.1, existing=existing)
    if paper:
        # Room for the labels around a small link, whatever its size on paper.
        pad = 5.0 / paper
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        ax.set_xlim(x0 - pad, x1 + pad)
        ax.set_ylim(y0 - pad, y1 + pad)
    near = NEAR / (ppu if paper else points_per_unit(ax, 1.2 * span))
    _label_points(ax, geom, c, s, lab, drawn, False, None, only=link, near=near)
    return finish(ax, lab, drawn, place)


def _around(X, away, pads):
    return [spot for pad in pads for spot in point_label_candidates(X, away, pad)]


def _friction_angle(ax, c, geom, link, drawn, lab, s, ppu) -> list:
    """At each sliding pair of ``link`` with friction: the guide's normal through the slider's point (dashed), and
    the friction angle ρ between it and the guide's force on the link (tan ρ = μ while it slides).

    Returns points of what was drawn (for the view's extent).
    """
    mech = c.mechanism
    extent = []
    for joint in mech.joints_of(link):
        if not isinstance(joint, Prismatic) or not joint.mu > 0:
            continue
        other = (set(joint.links) - {link}).pop()
        name = f"{joint.force_letter}{other}{link}"
        if name not in drawn.ends:
            continue
        X = np.asarray(c.points[joint.slider][joint.point], float) * MM
        tail, tip = (np.asarray(p, float) for p in drawn.ends[name])
        body = tail - X if np.hypot(*(tail - X)) > np.hypot(*(tip - X)) else tip - X
        ell = float(np.hypot(*body))
        if ell == 0:
            continue
        _, u = geom.guide(joint)
        n = perp(u)
        n = n if float(np.dot(n, body)) >= 0 else -n
        b = body / ell
        rho = math.atan2(abs(float(n[0] * b[1] - n[1] * b[0])), float(np.dot(n, b)))
        # Clear of the block (and legible) however short the arrow: ρ is an angle between directions.
        radius = max(0.62 * ell, 3.4 * geom.sym, 24.0 / ppu)
        reach = max(1.2 * ell, 1.35 * radius)
        normal = np.array([X - n * 0.25 * reach, X + n * reach])
        drawn.add(line(ax, *normal.T, color=s.ink, lw=s.thin_lw, linestyle=(0, (4, 2.5)), zorder=3.2))
        lab.segment(*normal, soft=True)
        extent += list(normal)
        t = lab.label("normal", [(normal[1], n, 2.0), (normal[1], -perp(n), 3.0), (normal[1], perp(n), 3.0),
                                 (normal[0], -n, 2.0)] + _around(normal[1], n, (6.0, 12.0)),
                      color=s.ink, size=s.small_size)
        drawn.labels["normal"] = t
        drawn.add(t)
        if math.degrees(rho) < 0.05:
            continue  # no sliding here (a dead centre): the guide pushes along its normal
        if radius > 0.8 * ell:
            # The arrow is shorter than the arc's radius: its line carries on, dashed, to meet the arc.
            more = np.array([X + b * ell, X + b * 1.2 * radius])
            drawn.add(line(ax, *more.T, color=s.unknown, lw=s.thin_lw, linestyle=(0, (4, 2.5)), zorder=3.2))
            lab.segment(*more, soft=True)
        a0 = math.atan2(n[1], n[0])
        a1 = math.atan2(b[1], b[0])
        a1 = a0 + (a1 - a0 + math.pi) % (2 * math.pi) - math.pi
        arc = arc_points(X, radius, a0, a1, 24)
        drawn.add(line(ax, *arc.T, color=s.ink, lw=s.thin_lw * 1.4, zorder=3.4))
        lab.polyline(arc)
        extent += [arc[0], arc[-1]]
        # Beside the wedge first (a small angle leaves no room inside it), then around the arc.
        aside = unit(b - n * float(np.dot(b, n)))
        cands = [(arc[-1], aside, pad) for pad in (3.0, 8.0)] + [(arc[0], -aside, pad) for pad in (3.0, 8.0)]
        for pad in (2.0, 5.0, 10.0, 18.0, 30.0):
            for P in arc[[12, 6, 18, 0, 23]]:
                cands.append((P, unit(P - X), pad))
        cands += [(P, -unit(P - X), pad) for pad in (3.0, 8.0) for P in arc[[12, 0, 23]]]
        t = lab.label(f"ρ = {math.degrees(rho):.2f}°", cands, color=s.ink, size=s.small_size)
        drawn.labels["rho"] = t
        drawn.add(t)
    return extent


def _too_wide(ax, text: str, s, *, size=None, share=0.5) -> bool:
    """Whether a text would take more than ``share`` of its panel's width (measured as the Labeler measures)."""
    from matplotlib.text import Text

    t = Text(0, 0, text, fontsize=size or s.label_size, figure=ax.figure)
    w, _ = text_size(t, measuring_renderer(ax.figure))
    return w > share * ax.get_position(original=True).width * ax.figure.bbox.width
