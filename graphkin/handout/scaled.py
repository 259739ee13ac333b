"""The handout's drawings at stated scales: which scales fit the page, and the pictures drawn at them.

Each drawing of the mechanism, its free bodies or its force polygons is given its room on an A4 page first
(:mod:`graphkin.graphical.paper`), then the largest standard scale that fits it there is chosen, and the
picture is printed at its own size (:class:`graphkin.handout.figures.Picture` with ``natural=True``), so the
scales it states (1:k, 1 mm = X N) are the scales on paper. A free-body figure draws every body at one force
scale; a polygon figure every polygon at one force scale.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from graphkin.graphical import Arrow, Line, Step
from graphkin.graphical.paper import (
    FIGURE_WIDTH,
    LENGTH_SCALES,
    force_scale,
    force_text,
    length_scale,
    length_text,
    polygon_size,
    sheet_reach,
)
from graphkin.handout import maths as M
from graphkin.handout.document import Subject
from graphkin.handout.figures import Picture
from graphkin.model import GearMesh
from graphkin.notation import num

FREE_BODY_ROOM = (FIGURE_WIDTH, 120.0)
"""Room for a figure of every free body [mm]."""
POLYGON_CELL = (74.0, 58.0)
"""Room for one polygon in a key's figure of polygons [mm] (two side by side)."""
GAP = 5.0


def statement(k: float | None = None, X: float | None = None) -> str:
    """The scales a caption states: ``"Scale 1:5; forces 1 mm = 20 N."``."""
    parts = []
    if k is not None:
        parts.append(f"scale {length_text(k)}")
    if X is not None:
        parts.append(f"forces {force_text(X)}")
    text = "; ".join(parts)
    return text[:1].upper() + text[1:] + "." if text else ""


def _bigger_k(k: float) -> float:
    later = [x for x in LENGTH_SCALES if x > k * (1 + 1e-9)]
    return later[0] if later else k


def _bigger_X(X: float) -> float:
    return force_scale(X * 1.0001, 1.0)


# -- free bodies ---------------------------------------------------------------------------------------------------
def _loads(c, link: int) -> list[tuple[np.ndarray, np.ndarray]]:
    """(point [mm], force [N]) of every force a free body shows, known and found."""
    out = [(np.asarray(a.at, float) * 1e3, np.asarray(a.vector, float)) for a in c.forces_on(link)]
    out += [(np.asarray(a.at, float) * 1e3, np.asarray(a.vector, float)) for a in c.external.get(link, [])]
    inert = c.inertia.get(link)
    if inert is not None and math.hypot(*inert["F"]) > 0:
        out.append((np.asarray(c.G[link], float) * 1e3, np.asarray(inert["F"], float)))
    d = c.mechanism.driver
    if d.link == link and not d.crank and c.driver_vector is not None:
        joint = c.mechanism.joint_between(c.mechanism.frame, link)
        out.append((np.asarray(c.points[link][joint.point], float) * 1e3, np.asarray(c.driver_vector, float)))
    return out


def _outline(c, link: int) -> list[np.ndarray]:
    """The points [mm] a drawing of ``link`` reaches: its points, its centre of mass, and a gear's teeth (its pitch
    circle and a little more), which reach far beyond its one point, the centre."""
    pts = [np.asarray(p, float) * 1e3 for p in c.points[link].values()]
    if link in c.G:
        pts.append(np.asarray(c.G[link], float) * 1e3)
    for mesh in c.mechanism.joints:
        if isinstance(mesh, GearMesh) and link in mesh.links:
            k = list(mesh.links).index(link)
            centre, r = np.asarray(c.points[link][mesh.centers[k]], float) * 1e3, 1.15 * mesh.radii[k] * 1e3
            pts += [centre + (r, 0.0), centre - (r, 0.0), centre + (0.0, r), centre - (0.0, r)]
    return pts


def free_body_size(c, link: int, k: float, X: float) -> tuple[float, float]:
    """Width and height [mm] a free body takes printed at 1:k and 1 mm = X N, its margins and title included
    (an estimate: each force drawn from its point, towards the link or away from it as the drawing does)."""
    pts = _outline(c, link)
    centre = np.mean(pts, axis=0)
    pts = [p / k for p in pts]
    for P, F in _loads(c, link):
        v = F / X
        push = float(np.dot(F, centre - P)) > 0
        pts.append(P / k - v if push else P / k + v)
    pts = np.asarray(pts, float)
    w, h = np.ptp(pts, axis=0)
    # The labels around it (a "5 mm" margin each side in the drawing, and the labels beyond), and its title.
    return float(max(w + 22.0, 40.0)), float(h + 26.0)


def _rows_height(sizes, width: float) -> float:
    rows, used, row_h, total = 0, 0.0, 0.0, 0.0
    for w, h in sizes:
        if used and used + GAP + w > width:
            total += row_h + GAP
            used, row_h = 0.0, 0.0
        used += (GAP if used else 0.0) + w
        row_h = max(row_h, h)
        rows += 1
    return total + row_h


SHORTEST_LINK = 15.0
"""The shortest a link of two or more points may print on a free body [mm]: shorter, its pins, arrows and labels
pile up on one spot (an engine's crank at 1:100 printed 3 mm long, four labels on one point)."""


def _span(c, link: int) -> float:
    """The length [mm, true] of ``link`` drawn as a bar or plate: the longest distance between two of its points;
    0 for a link of one point (a slider, a gear drawn about its centre)."""
    pts = [np.asarray(p, float) * 1e3 for p in c.points[link].values()]
    return max([math.dist(p, q) for n, p in enumerate(pts) for q in pts[n + 1:]] + [0.0])


def free_body_scales(c, links, room=FREE_BODY_ROOM) -> tuple[float, float]:
    """(k, X) for the free bodies of ``links``: the largest link about 55 mm at most, the largest force about 40 mm;
    where a body is then larger than ``room``, its forces are drawn shorter first, then its links smaller. The
    bodies are laid out in as many figures as they take, a link too short to read at k in one of its own
    (:func:`free_body_plan`)."""
    size = max([float(np.max(np.ptp(np.asarray(_outline(c, n), float), axis=0))) for n in links] + [10.0])
    k = length_scale(size, 55.0)
    largest = max([math.hypot(*F) for n in links for _, F in _loads(c, n)] + [1e-9])
    X = force_scale(largest, 40.0)
    for _ in range(12):
        if not all(w <= room[0] and h <= room[1] for w, h in (free_body_size(c, n, k, X) for n in links)):
            # A body larger than the room: shorter forces first (up to a quarter of their length), then smaller links.
            if X < force_scale(largest, 10.0):
                X = _bigger_X(X)
            else:
                k = _bigger_k(k)
            continue
        # All in one figure, both scales smaller together, while every link readable now stays readable.
        readable = [n for n in links if _span(c, n) / k >= SHORTEST_LINK * (1 - 1e-9)]
        sizes = [free_body_size(c, n, k if n in readable or not _span(c, n) else _readable_k(c, n, X, room), X)
                 for n in links]
        smaller = _bigger_k(k)
        if _rows_height(sizes, room[0]) <= room[1] or \
                any(_span(c, n) / smaller < SHORTEST_LINK * (1 - 1e-9) for n in readable) or smaller == k:
            break
        k, X = smaller, _bigger_X(X)
    return k, X


def _readable_k(c, link: int, X: float, room) -> float:
    """The smallest drawing of ``link`` (the largest standard k) at which it prints :data:`SHORTEST_LINK` long and
    fits ``room``, or the largest that fits when none is that long."""
    span = _span(c, link)
    fits = [k for k in LENGTH_SCALES if all(a <= b for a, b in zip(free_body_size(c, link, k, X), room))]
    readable = [k for k in fits if span / k >= SHORTEST_LINK * (1 - 1e-9)]
    return readable[-1] if readable else fits[0] if fits else LENGTH_SCALES[-1]


def free_body_plan(c, links, room=FREE_BODY_ROOM) -> list[tuple[float, float, list[int], dict]]:
    """The figures of the free bodies of ``links``: (k, X, links of the figure, {link: its own k}), in the links'
    order.

    The bodies are drawn at :func:`free_body_scales`, as many to a figure as fit ``room``; a link that would print
    shorter than :data:`SHORTEST_LINK` there (a crank beside a long connecting rod) is enlarged, at a length scale
    of its own that its panel states, at the same force scale.
    """
    k, X = free_body_scales(c, links, room)
    plan = []
    for n in links:
        own = {} if _span(c, n) == 0 or _span(c, n) / k >= SHORTEST_LINK * (1 - 1e-9) else \
            {n: _readable_k(c, n, X, room)}
        last = plan[-1] if plan else None
        if last and _rows_height([free_body_size(c, m, {**last[3], **own}.get(m, k), X) for m in last[2] + [n]],
                                 room[0]) <= room[1]:
            last[2].append(n)
            last[3].update(own)
        else:
            plan.append((k, X, [n], own))
    return plan


# -- polygons -------------------------------------------------------------------------------------------------------
def polygon_scale(steps, cell=POLYGON_CELL) -> float:
    """One force scale for every polygon of ``steps``, each fitting ``cell``."""
    return max([force_scale(polygon_size(st.polygon), cell) for st in steps if st.polygon] or [1.0])


POLYGON_FIGURE_HEIGHT = 225.0
"""The tallest a figure of polygons may print [mm]: with its caption and a heading, it fits an A4 text block."""


def polygon_groups(steps, X: float, titles, width: float = FIGURE_WIDTH, height: float = POLYGON_FIGURE_HEIGHT) -> list:
    """``steps`` in groups, each a figure of polygons at 1 mm = X N that prints no taller than ``height`` [mm].

    The rows are laid out as :func:`graphkin.draw.paper.arrange` lays them (as many panels as fit the width),
    each panel its polygon's printed size and room for its labels around it, and no narrower than its title
    (``titles``, one per step; an estimate: 1.8 mm a character at the title's 10.5 pt).
    """
    groups, group, used = [], [], 0.0
    row, row_w, row_h = [], 0.0, 0.0
    rows = []
    for st, title in zip(steps, titles):
        w, h = (np.array(polygon_size(st.polygon)) / X) + (18.0, 24.0)
        w = max(w, 1.8 * len(title))
        if row and row_w + GAP + w > width:
            rows.append((row, row_h))
            row, row_w, row_h = [], 0.0, 0.0
        row.append(st)
        row_w += (GAP if row_w else 0.0) + w
        row_h = max(row_h, h)
    if row:
        rows.append((row, row_h))
    for row, h in rows:
        if group and used + GAP + h > height:
            groups.append(group)
            group, used = [], 0.0
        group += row
        used += (GAP if used else 0.0) + h
    return groups + ([group] if group else [])


def resultant_step(c, step) -> Step | None:
    """The sum a resultant step states (R3 = R3i + Fc3), as a polygon to draw: the known loads tip to tail and
    the resultant closing it, reversed (R3i + Fc3 − R3 = 0). None when the link has one load only."""
    link = step.link
    parts = []
    inert = c.inertia.get(link)
    if inert is not None and math.hypot(*inert["F"]) > 0:
        parts.append(Arrow(f"R{link}i", tuple(inert["F"]), True))
    parts += [Arrow(a.name, tuple(a.vector), True) for a in c.external.get(link, [])]
    if len(parts) < 2:
        return None
    total = np.sum([a.vector for a in parts], axis=0)
    name = next((line.name for line in step.lines if line.name == f"R{link}"), f"R{link}")
    return Step("polygon", f"{name} = " + " + ".join(a.name for a in parts), link,
                polygon=tuple(parts) + (Arrow(f"−{name}", (-float(total[0]), -float(total[1])), False),))


# -- what a drawing of the construction holds (graphkin.graphical.reach) -------------------------------------------
def mm(x: float) -> str:
    """A length on the sheet [mm], as a ruler reads it: ``"12.5 mm"``."""
    return f"{num(x, 3)} mm"


def detour_text(d, k: float, numbers: bool) -> tuple:
    """A sentence for a step drawn another way (:class:`graphkin.graphical.reach.Detour`) on a drawing at 1:k:
    the resultant's line by its offset, or moments about a pin; ``numbers=False`` leaves the offsets and arms
    out (a sheet whose student finds the inertia loads)."""
    if d.kind == "offset":
        h = d.arms[d.name] * 1e3
        if d.far.what.startswith("where ") and d.parts:
            names = []
            for n, part in enumerate(d.parts):
                names += ([" and " if n == len(d.parts) - 1 else ", "] if n else []) + [M.name(part), "'s"]
            head = (*names, " lines meet off the page")
        else:
            head = (d.far.what[:1].upper() + d.far.what[1:] + " lies off the page",)
        if not numbers:
            return (*head, ": draw ", M.name(d.name), "'s line directly, parallel to ", M.name(d.name),
                    f", at h = |ΣM| / |{d.name}| from {d.about} (the moment of link {d.link}'s loads about "
                    f"{d.about} over the size of their sum), to the side that turns link {d.link} as that moment does.")
        return (*head, ": draw ", M.name(d.name), "'s line directly, parallel to ", M.name(d.name),
                f" from its polygon, {mm(h / k)} from {d.about} on the drawing (h = {mm(h)}), to the side that turns "
                f"link {d.link} {d.sense} about {d.about}.")
    (R, a_R), (F, a_F) = sorted(d.arms.items(), key=lambda kv: kv[0] == d.name)
    arms = ("; on the drawing ", M.sub("d", F), f" = {mm(a_F * 1e3 / k)} and ", M.sub("d", R),
            f" = {mm(a_R * 1e3 / k)}") if numbers else ()
    return (f"The lines of link {d.link}'s three forces meet at ", M.name(d.far.what), ", off the page: take moments "
            f"about {d.about} instead, |", M.name(F), "| ", M.sub("d", F), " = |", M.name(R), "| ", M.sub("d", R),
            f", each d the perpendicular from {d.about} to the force's line", *arms, "; the polygon then closes on "
            "the third force.")


def drawable(c, step) -> Step:
    """``step`` as a drawing on the mechanism shows it: only the lines and points inside the sheet's box
    (:func:`graphkin.graphical.paper.sheet_reach`), each line by a point of it there. What lies beyond is drawn
    another way, which the text says (:func:`detour_text`)."""
    r = sheet_reach(c)
    ref = next((np.asarray(P, float) for P in step.points.values() if r.holds(P)), None)
    if ref is None:
        ref = np.asarray(c.G.get(step.link, r.centre) if step.link is not None else r.centre, float)
    lines = []
    for line in step.lines:
        P, d = np.asarray(line.point, float), np.asarray(line.direction, float)
        foot = P + d * float(np.dot(ref - P, d))
        if r.holds(P) or r.holds(foot):
            lines.append(Line(line.name, tuple(P if r.holds(P) else foot), line.direction, line.role))
    points = {name: P for name, P in step.points.items() if r.holds(P)}
    return dataclasses.replace(step, lines=tuple(lines), points=points)


def resultant_panel(c, step) -> Step | None:
    """How a resultant's line is found, as a drawing on the mechanism shows it: the lines of its parts (R3i, Fc3)
    and K3, where they meet, which its line (R3) passes through. None when the resultant has one part only, or
    when they meet off the page: its line is then drawn at its offset (:class:`graphkin.graphical.reach.Detour`),
    in the panel of the step that uses it."""
    L = step.link
    r = sheet_reach(c)
    parts = [line for line in step.lines if line.name == f"R{L}i"]
    parts += [Line(a.name, a.at, tuple(np.asarray(a.vector, float) / math.hypot(*a.vector)), "resultant")
              for a in c.external.get(L, []) if a.at is not None and math.hypot(*a.vector) > 0]
    if len(parts) < 2:
        return None
    whole = [Line(line.name, line.point, line.direction, "found") for line in step.lines
             if line.name not in {p.name for p in parts}]
    detoured = any(d.kind == "offset" and d.link == L and not d.far.what.endswith("'s line") for d in r.detours
                   if c.steps[d.step] is step)
    meets = [m.at for m in r.marks if c.steps[m.step] is step and m.what.startswith("where ")]
    if detoured or not meets:
        return None  # its line is drawn at its offset, in the panel of the step that uses it
    return drawable(c, Step("resultant", f"Link {L}: R{L}'s line", L, tuple(parts + whole), {f"K{L}": meets[-1]}))


def merged(panels, n: int) -> list[Step]:
    """Resultant panels (:func:`resultant_panel`) drawn ``n`` to a panel, so that a mechanism of many loaded links
    takes few panels: ``Links 3, 4: resultants' lines``."""
    out = []
    for k in range(0, len(panels), n):
        group = panels[k:k + n]
        if len(group) == 1:
            out.append(group[0])
            continue
        links = ", ".join(str(p.link) for p in group)
        out.append(Step("resultant", f"Links {links}: the resultants' lines", None,
                        tuple(line for p in group for line in p.lines), {k: v for p in group for k, v in p.points.items()}))
    return out


NEGLIGIBLE = 0.005
"""A polygon whose every force is under this fraction of the largest force of the construction is set aside on a
worksheet (and its key): it would print as a dot (the shaper's sub-problems of a link's own weight and inertia, under 1 N beside
its 500 N cutting force), and what it adds to any answer is under what a ruler reads."""


def set_aside(steps) -> tuple[list, list, float]:
    """``steps`` split into those a worksheet gives a box and those it sets aside as negligible (:data:`NEGLIGIBLE`):
    a polygon of negligible forces only, and a sum of the sub-problems with one part that is not negligible (it
    equals that part). Returns (kept, set aside, the limit [N])."""
    largest = max((math.hypot(*a.vector) for st in steps for a in st.polygon), default=0.0)
    limit = NEGLIGIBLE * largest
    kept, aside = [], []
    for st in steps:
        sizes = [math.hypot(*a.vector) for a in st.polygon]
        parts = sizes[:-1] if st.kind == "superpose" else sizes
        small = max(sizes, default=0.0) < limit or st.kind == "superpose" and sum(x >= limit for x in parts) <= 1
        (aside if small and st.kind != "driver" else kept).append(st)
    return kept, aside, limit


def set_aside_text(aside, limit: float, X: float, equation) -> tuple:
    """The sentence that names the polygons set aside (:func:`set_aside`) at 1 mm = X N, each by its ``equation``."""
    return (f"Set aside, negligible at this scale (each of its forces under {NEGLIGIBLE:.1%} of the largest, "
            f"{M.fmt(limit)} N, which prints under {M.fmt(limit / X, 2)} mm): ",
            *[x for n, st in enumerate(aside) for x in ([", "] if n else []) + [equation(st)]],
            ". A sum whose other parts are set aside equals its one part to the drawing's precision.")


# -- pictures ---------------------------------------------------------------------------------------------------------
def mechanism(s: Subject, c, i: int, k: float, *, room=False, key="mechanism") -> Picture:
    from graphkin import draw

    return s.picture(f"{key}-{i}", lambda: draw.draw_mechanism(c, length_scale=k, room=room), alt=
                     f"the mechanism at {s.where(i)}, drawn at {length_text(k)}", natural=True)


def free_body_figures(doc, s: Subject, c, i: int, links, caption: str, **kw) -> str:
    """The free bodies of ``links`` in as many figures as fit the page (:func:`free_body_plan`), each at the same
    scales (:func:`free_body_scales`), the first captioned ``caption`` and its scales. Returns its label."""
    first = None
    for k, X, group, own in free_body_plan(c, links):
        said = statement(k, X)
        if own:
            said = said.replace("; forces", "".join(f"; link {n} at {length_text(m)}, enlarged to read"
                                                     for n, m in own.items()) + "; forces")
        label = doc.figure([free_bodies(s, c, i, group, k, X, enlarged=own, **kw)],
                           (caption if first is None else "The free bodies, continued.") + " " + said)
        first = first or label
    return first


def free_bodies(s: Subject, c, i: int, links, k: float, X: float, *, unknowns=True, inertia=True,
                enlarged=None) -> Picture:
    """The free bodies of ``links`` at 1:k and 1 mm = X N; ``unknowns=False`` leaves out the forces the
    construction finds, ``inertia=False`` the inertia resultants too (a sheet whose student finds them from the
    input motion: only the external loads are drawn)."""
    from graphkin.draw import paper

    shown = c if inertia else dataclasses.replace(c, inertia={})
    key = f"free-bodies-{i}-{'all' if unknowns else 'given'}{'' if inertia else '-external'}"
    if list(links) != list(c.mechanism.moving):
        key += "-" + "-".join(str(n) for n in links)
    key += "".join(f"-{n}at{m:g}" for n, m in (enlarged or {}).items())
    return s.picture(key, lambda: paper.draw_free_bodies(shown, links, length_scale=k, force_scale=X,
                                                         unknowns=unknowns, enlarged=enlarged),
                     alt=f"the free bodies at {length_text(k)}, forces at {force_text(X)}", natural=True)


def polygons(s: Subject, key: str, steps, X: float, driver_name=None, titles=None) -> Picture:
    from graphkin.draw import paper

    return s.picture(key, lambda: paper.draw_polygons(steps, force_scale=X, driver_name=driver_name, titles=titles),
                     alt=f"force polygons at {force_text(X)}", natural=True)


def step(s: Subject, c, i: int, n: int, st, k: float, X: float, extra=None) -> Picture:
    """Step ``n``'s lines of action at 1:k, and its polygon (or ``extra``, a resultant's sum) at 1 mm = X N."""
    from graphkin.draw import paper

    return s.picture(f"step-{i}-{n}", lambda: paper.draw_step(c, st, length_scale=k, force_scale=X, polygon=extra),
                     alt=f"step {n} at {length_text(k)}", natural=True)


def constructions(s: Subject, c, i: int, steps, k: float, titles=None) -> Picture:
    from graphkin.draw import paper

    return s.picture(f"construction-{i}", lambda: paper.draw_constructions(c, steps, length_scale=k, titles=titles),
                     alt=f"the lines of action at {length_text(k)}", natural=True)


def _step_extent(c, step, k: float, X: float | None) -> tuple[float, float]:
    """Width and height [mm, printed at 1:k] of a step's drawing on the mechanism: the mechanism, the points the
    step finds (within three mechanism sizes, as drawn), and each known load on its line at 1 mm = X N."""
    pts = [np.asarray(p, float) * 1e3 for d in c.points.values() for p in d.values()]
    pts = np.asarray(pts, float)
    centre, size = pts.mean(axis=0), float(np.max(np.ptp(pts, axis=0)))
    out = list(pts)
    # Gears are drawn as their pitch circles: an annulus reaches well past the points (its centre is the sun's).
    for mesh in (j for j in c.mechanism.joints if isinstance(j, GearMesh)):
        for n, name, r in zip(mesh.links, mesh.centers, mesh.radii):
            O = np.asarray(c.points[n][name], float) * 1e3
            out += [O - r * 1e3, O + r * 1e3]
    for P in step.points.values():
        P = np.asarray(P, float) * 1e3
        if np.all(np.isfinite(P)) and np.hypot(*(P - centre)) <= 3 * size:
            out.append(P)
    for line in step.lines:
        P, d = np.asarray(line.point, float) * 1e3, np.asarray(line.direction, float)
        if np.hypot(*(P - centre)) > 3 * size:
            P = P + d * float(np.dot(centre - P, d))
        out.append(P)
        F = step.values.get(line.name) or step.values.get(line.name.replace("R", "F", 1))
        if X and line.role == "resultant" and isinstance(F, (tuple, list)):
            half = d * math.hypot(*F) / X * k / 2
            out += [P - half, P + half]
    w, h = np.ptp(np.asarray(out, float), axis=0)
    # The drawing's margins (a tenth each side, and the ground's and the labels' room) at its printed size.
    return float(w * 1.25 / k + 16.0), float(h * 1.25 / k + 16.0)


def step_scale(c, steps, X: float | None, room) -> float:
    """The largest standard k at which every step's drawing on the mechanism fits ``room`` [mm]."""
    W, H = room
    for k in LENGTH_SCALES:
        if all(w <= W and h <= H for w, h in (_step_extent(c, st, k, X) for st in steps)):
            return k
    return LENGTH_SCALES[-1]


def construction_scale(c, steps, width: float = FIGURE_WIDTH, height: float = 85.0) -> float:
    """k for the mechanism with each step's lines of action, one panel per step, up to two panels a row."""
    n = max(1, min(len(steps), 2))
    w = (width - GAP * (n - 1)) / n
    return step_scale(c, steps, None, (w, height))
