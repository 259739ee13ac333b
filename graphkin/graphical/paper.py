"""Scales for paper: the length scale 1:k of a drawing of the mechanism and the force scale 1 mm = X N of its
forces, chosen so that the drawing fits the room a printed page gives it.

On paper the scale *is* the graphical method: a student measures a side of a polygon with a ruler and reads
the force off the scale. So a drawing is first given its room on the page (at most :data:`FIGURE_WIDTH` wide),
then drawn at the largest standard scale that fits it there, and printed at that size (never shrunk to a share
of the text width afterwards). Everything here is plain numbers: the drawing layer draws at these scales, the
handouts state them, and the grader (:mod:`graphkin.exercises.quantities`) allows what can be read off a
drawing printed at them (:data:`READING`).

Examples
--------
>>> length_scale((1030.0, 460.0), (168.0, 90.0)), length_text(10.0), length_text(0.5)
(10.0, '1:10', '2:1')
>>> force_scale(2268.0, 60.0), force_text(50.0)
(50.0, '1 mm = 50 N')
"""

from __future__ import annotations

import dataclasses
import math
import weakref
from dataclasses import dataclass
from functools import partial

import numpy as np

from graphkin.graphical.reach import reach
from graphkin.model import GearMesh, Prismatic
from graphkin.notation import num

PAGE_WIDTH = 210.0
"""A4 [mm]."""
PAGE_HEIGHT = 297.0
MARGIN = 18.0
"""Left and right margins of a handout's page [mm] (:mod:`graphkin.handout.typst` sets its page with them)."""
TEXT_WIDTH = PAGE_WIDTH - 2 * MARGIN
FIGURE_WIDTH = 168.0
"""The widest a drawing may be, its labels included [mm]: the text width less a little for the crop's margin."""

READING = 0.5
"""What a student reads off a printed drawing with a ruler [mm]: half the smallest division of a school rule."""

REDUCTIONS = (1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0)
ENLARGEMENTS = (2.0, 5.0, 10.0, 20.0, 50.0)
"""The standard scales of technical drawing (ISO 5455): 1:2, 1:5, 1:10, …, and 2:1, 5:1, 10:1, …"""

LENGTH_SCALES = tuple(sorted([1.0 / e for e in ENLARGEMENTS] + list(REDUCTIONS)))
"""Every length scale k (true length / printed length), the largest drawing first."""


def length_scale(size, room) -> float:
    """The largest standard length scale at which a drawing of ``size`` fits ``room``.

    Parameters
    ----------
    size : float or (float, float)
        The drawing's true extent [mm] (width, height; one number for both).
    room : float or (float, float)
        The room on paper [mm].

    Returns
    -------
    float
        k: a true length of k mm is printed 1 mm long (1:k); below 1, an enlargement (k = 0.5 is 2:1).
    """
    w, h = _pair(size)
    W, H = _pair(room)
    for k in LENGTH_SCALES:
        if w / k <= W and h / k <= H:
            return k
    return LENGTH_SCALES[-1]


def length_text(k: float) -> str:
    """The length scale as a drawing states it: ``"1:5"``, ``"1:1"``, ``"2:1"``."""
    if k >= 1:
        return f"1:{num(k, 4)}"
    return f"{num(1 / k, 4)}:1"


def force_scale(largest, room) -> float:
    """The smallest round force scale (1, 2, 5 × 10ⁿ N per mm) at which ``largest`` fits ``room``.

    Parameters
    ----------
    largest : float or (float, float)
        The size of what is drawn [N] (a force, or a polygon's width and height).
    room : float or (float, float)
        The room on paper [mm].

    Returns
    -------
    float
        X: 1 mm of drawing stands for X N.
    """
    w, h = _pair(largest)
    W, H = _pair(room)
    need = max(w / W, h / H)
    if not need > 0 or not math.isfinite(need):
        return 1.0
    decade = 10.0 ** math.floor(math.log10(need))
    for m in (1.0, 2.0, 5.0, 10.0):
        if m * decade >= need * (1 - 1e-12):
            return float(f"{m * decade:.12g}")  # 0.2, not 0.2000000000000001
    return 10.0 * decade  # pragma: no cover


def force_text(X: float) -> str:
    """The force scale as a drawing states it: ``"1 mm = 20 N"``."""
    return f"1 mm = {num(X, 4)} N"


def _pair(x) -> tuple[float, float]:
    if isinstance(x, (int, float)):
        return float(x), float(x)
    a, b = x
    return float(a), float(b)


# -- what is drawn, in true units ------------------------------------------------------------------------------
def polygon_size(arrows) -> tuple[float, float]:
    """Width and height [N] of a force polygon drawn tip to tail (its arrows, as a step holds them)."""
    vectors = [np.asarray(a.vector, float) for a in arrows]
    if not vectors:
        return 0.0, 0.0
    verts = np.cumsum([np.zeros(2)] + vectors, axis=0)
    w, h = np.ptp(verts, axis=0)
    return float(w), float(h)


def mechanism_size(construction, *, points=None) -> tuple[float, float]:
    """Width and height [mm] of a drawing of the mechanism at the construction's position, as
    :func:`graphkin.draw.draw_mechanism` draws it: its points, each gear's pitch circle and teeth, each slider's
    rails along its guide, the ground symbols and the scale bar under them, and a margin of 9 % of the larger side
    all round.

    ``points`` [m]: points the drawing also shows or leaves room for (a point of concurrency, where a student
    draws lines of action to: :func:`sheet_reach` chooses them).
    """
    c = construction
    pts = [np.asarray(p, float) * 1e3 for link in c.points.values() for p in link.values()] or [np.zeros(2)]
    gears = [(np.asarray(c.points[n][name], float) * 1e3, r * 1e3) for mesh in c.mechanism.joints
             if isinstance(mesh, GearMesh) for n, name, r in zip(mesh.links, mesh.centers, mesh.radii)]
    for O, r in gears:
        pts += [O - r, O + r]
    size = max(float(np.max(np.ptp(np.asarray(pts), axis=0))), 1.0)
    sym = 0.032 * size  # graphkin.draw.geometry's symbol size: a slider's rails are 2 × 5.44 of it long
    for O, r in gears:
        pts += [O - 1.2 * r, O + 1.2 * r]
    for joint in c.mechanism.joints:
        if isinstance(joint, Prismatic):
            u = np.asarray(c.guides.get(tuple(sorted((joint.guide, joint.slider))), (1.0, 0.0)), float)
            X = np.asarray(c.points[joint.slider][joint.point], float) * 1e3
            pts += [X - u * 6.04 * sym, X + u * 6.04 * sym]
    pts += [np.asarray(P, float) * 1e3 for P in points or () if np.all(np.isfinite(P))]
    w, h = np.ptp(np.asarray(pts), axis=0)
    # The ground symbols (2 sym) and the scale bar (0.1 size) under everything.
    h = h + 2 * sym + 0.1 * size
    margin = 0.18 * max(w, h)
    return float(w + margin), float(h + margin)


# -- the scales of a student's worksheet ----------------------------------------------------------------------
MECHANISM_ROOM = (FIGURE_WIDTH, 125.0)
"""Room for the worksheet's drawing of the mechanism [mm]: large, with room to draw the lines of action."""
POLYGON_ROOM = (150.0, 88.0)
"""Room for one force polygon inside its box on a worksheet [mm]."""


@dataclass(frozen=True)
class SheetScales:
    """The scales a worksheet prints its drawings at.

    Attributes
    ----------
    length : float
        k of the mechanism's drawing (1:k), where the lines of action are drawn.
    polygon : float
        X of the polygon boxes [N per mm]: every polygon of the construction fits its box at it.
    """

    length: float
    polygon: float

    def force_reading(self) -> float:
        """What a force measured off a polygon can be read to [N]: :data:`READING` at the polygon scale."""
        return READING * self.polygon

    def length_reading(self) -> float:
        """What a length measured off the mechanism's drawing can be read to [m]."""
        return READING * self.length * 1e-3


_KEPT: dict[int, tuple] = {}
"""What :func:`sheet_scales` and :func:`motion_scales` found, by the id of the construction (with a weak reference to
it, whose callback drops the entry when the construction goes)."""


def _forget(key: int, ref: weakref.ref, kept=_KEPT) -> None:
    # ``kept`` is bound here: at interpreter exit the module's globals may be gone before the last callbacks.
    entry = kept.get(key)
    if entry is not None and entry[0] is ref:
        kept.pop(key, None)


def _once(construction, key, find):
    """``find()``, worked out once per construction and ``key`` while the construction lives.

    A construction is frozen and its scales follow from it alone, but an exercise asks for them again and again:
    every sheet, key and grade of each graphical question, for every student who drew the same values (each time
    a few hundred numpy calls, most of a sheet's cost).
    """
    entry = _KEPT.get(id(construction))
    if entry is None or entry[0]() is not construction:
        try:
            ref = weakref.ref(construction, partial(_forget, id(construction)))
        except TypeError:  # an object that takes no weak reference is not kept
            return find()
        entry = _KEPT[id(construction)] = (ref, {})
    found = entry[1]
    if key not in found:
        found[key] = find()
    return found[key]


def sheet_scales(construction) -> SheetScales:
    """The scales of a worksheet of this construction (the same for the sheet and for its grader)."""
    return _once(construction, "sheet", partial(_sheet_scales, construction))


def sheet_reach(construction):
    """What a worksheet's drawing of the mechanism has room for (:class:`graphkin.graphical.reach.Reach`).

    The drawing keeps the mechanism as large as it can: at the largest standard scale at which the mechanism and
    every point its construction draws (lines of action near their links, where they meet) fit
    :data:`MECHANISM_ROOM`, or one scale smaller than the mechanism alone needs when they do not. At that scale
    the points are taken nearest the mechanism first, as many as fit; a point further off is not drawn, and its
    step is drawn another way (:mod:`graphkin.graphical.reach`). The key draws the same points.
    """
    return _once(construction, "reach", partial(_sheet_reach, construction))


def _sheet_reach(construction):
    every = reach(construction, near=lambda X: True)
    alone = length_scale(mechanism_size(construction), MECHANISM_ROOM)
    if length_scale(mechanism_size(construction, points=every.points()), MECHANISM_ROOM) <= alone * (1 + 1e-9):
        box = np.asarray(every.points() + [p for link in construction.points.values() for p in link.values()])
        return dataclasses.replace(every, box=(tuple(box.min(axis=0)), tuple(box.max(axis=0))))
    smaller = next((k for k in LENGTH_SCALES if k > alone * (1 + 1e-9)), alone)
    centre = np.asarray(every.centre, float)
    kept = []
    for P in sorted(every.points(), key=lambda P: math.hypot(*(np.asarray(P) - centre))):
        w, h = mechanism_size(construction, points=kept + [P])
        if w / smaller <= MECHANISM_ROOM[0] and h / smaller <= MECHANISM_ROOM[1]:
            kept.append(P)
    box = np.asarray(kept or [every.centre], float)
    lo, hi = box.min(axis=0) - 1e-9, box.max(axis=0) + 1e-9
    pts = np.array([p for link in construction.points.values() for p in link.values()])
    lo, hi = np.minimum(lo, pts.min(axis=0)), np.maximum(hi, pts.max(axis=0))
    held = reach(construction, near=lambda X: bool(np.all((X >= lo) & (X <= hi))))
    return dataclasses.replace(held, box=(tuple(lo), tuple(hi)))


def _sheet_scales(construction) -> SheetScales:
    # Room for every point the construction draws on the mechanism; a point further off is drawn another way.
    points = sheet_reach(construction).points()
    k = length_scale(mechanism_size(construction, points=points), MECHANISM_ROOM)
    sizes = [polygon_size(step.polygon) for step in construction.steps if step.polygon]
    X = max([force_scale(size, POLYGON_ROOM) for size in sizes] or [1.0])
    return SheetScales(k, X)


def reading_error(construction, what: str) -> float:
    """What a student measuring on a worksheet printed at :func:`sheet_scales` can read a value to [SI].

    ``what``: ``"force"`` (a side of a polygon, :data:`READING` at the polygon scale [N]), ``"length"`` (a
    length or a point on the mechanism's drawing, :data:`READING` at its length scale [m]) or ``"torque"``
    (the input's torque |R| d, each read to its own scale [N·m]; 0 where the construction has no crank arm).
    A graphical question's tolerance is at least this: a finer one cannot be met with a ruler.
    """
    scales = sheet_scales(construction)
    if what == "force":
        return scales.force_reading()
    if what == "length":
        return scales.length_reading()
    if what == "torque":
        for step in construction.steps:
            if step.kind == "driver" and not step.sub and "d" in step.values:
                R = max((math.hypot(*a.vector) for a in step.polygon if a.known), default=0.0)
                return scales.force_reading() * abs(step.values["d"]) + R * scales.length_reading()
        return 0.0
    raise ValueError(f"what must be 'force', 'length' or 'torque', got {what!r}")


# -- velocity and acceleration polygons ----------------------------------------------------------------------------
MOTION_CELL = (80.0, 62.0)
"""Room for one of a position's velocity and acceleration polygons in a handout's figure [mm] (two side by side)."""


def motion_size(construction, polygon: str) -> tuple[float, float]:
    """Width and height of the ``"velocity"`` [m/s] or ``"acceleration"`` [m/s²] polygon of a
    :class:`graphkin.graphical.MotionConstruction` (the extent of its image points, the pole among them)."""
    pts = np.asarray(list(construction.images[polygon].values()) or [(0.0, 0.0)], float)
    w, h = np.ptp(pts, axis=0)
    return float(w), float(h)


def motion_scales(construction, room=MOTION_CELL) -> tuple[float, float]:
    """The round scales (1, 2, 5 × 10ⁿ per mm) at which the velocity and the acceleration polygon each fit ``room``.

    Returns
    -------
    (float, float)
        m/s per mm of the velocity polygon, m/s² per mm of the acceleration polygon.
    """
    return _once(construction, ("motion", _pair(room)), partial(_motion_scales, construction, room))


def _motion_scales(construction, room) -> tuple[float, float]:
    return (force_scale(motion_size(construction, "velocity"), room),
            force_scale(motion_size(construction, "acceleration"), room))


def motion_text(X: float, polygon: str) -> str:
    """A motion polygon's scale as a drawing states it: ``"1 mm = 0.2 m/s"`` or ``"1 mm = 20 m/s²"``."""
    return f"1 mm = {num(X, 4)} {'m/s' if polygon == 'velocity' else 'm/s²'}"
