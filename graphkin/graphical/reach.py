"""Where a construction draws on the mechanism: every point a student must reach with a ruler, and the steps drawn
another way because a point of theirs lies far off.

A construction on paper needs room: a resultant's line is found where the lines of its parts meet, a three-force
member's forces where their lines meet, an inertia resultant's line lies h from G. Each of these points must lie
inside the drawing of the mechanism at its printed scale. Most lie near the links; some lie very far (two lines
nearly parallel meet metres away, an inertia torque large against a small force puts the line far from G). A
point within :data:`REACH` mechanism sizes of the mechanism's centre is a :class:`Mark` the drawing makes room for;
a point beyond it is not drawn, and its step is drawn another way (a :class:`Detour`):

``"offset"``
    A resultant whose parts' lines meet far off: its line is drawn directly, parallel to the resultant (read off
    its polygon) at the distance h = |ΣM_G| / |R| from G, to the side that turns the link as the loads do.
``"moments"``
    A three-force member whose lines meet far off: moments about the point of the force whose direction is not
    known give the size of the force whose line is known, |F| d_F = |R| d_R (each d the perpendicular from that
    point to the line), and the polygon closes on the third.

Everything here is plain numbers in SI (m, N), read off the construction.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.model import GearMesh

REACH = 1.5
"""How far a point of the construction may lie from the mechanism's centre and still be drawn, in mechanism sizes
(the larger of its width and height): further, the drawing would shrink the links to make room for it."""


@dataclass(frozen=True)
class Mark:
    """A point the construction draws on the mechanism.

    Attributes
    ----------
    what : str
        What it is, as a sentence names it: ``"R3i's line"``, ``"I3"``, ``"where R3i's and Fc3's lines meet"``.
    at : (float, float)
        Where [m]; for a line, its point nearest the link it acts on.
    step : int
        The index of the step it belongs to, in ``construction.steps``.
    """

    what: str
    at: tuple[float, float]
    step: int


@dataclass(frozen=True)
class Detour:
    """A step drawn another way, because a point it needs lies far off (module docstring).

    Attributes
    ----------
    kind : str
        ``"offset"`` or ``"moments"``.
    step : int
        The step's index in ``construction.steps``.
    link : int
    far : Mark
        The point that lies far off.
    name : str
        ``"offset"``: the resultant whose line is drawn at h (``"R3"``); ``"moments"``: the force whose size the
        moments give (``"F43′"``).
    about : str
        ``"offset"``: the point the offset is measured from (``"G3"``); ``"moments"``: the point the moments are
        taken about (``"A"``).
    arms : dict of str to float
        ``"offset"``: ``{name: h}``; ``"moments"``: each known line's perpendicular distance from ``about`` [m].
    sense : str
        ``"offset"``: ``"CCW"`` or ``"CW"``, how the resultant turns the link about G; ``""`` otherwise.
    parts : tuple of str
        ``"offset"``: the loads the resultant sums (``("R3i", "Fc3")``), whose lines are not drawn.
    """

    kind: str
    step: int
    link: int
    far: Mark
    name: str
    about: str
    arms: dict
    sense: str = ""
    parts: tuple = ()


@dataclass(frozen=True)
class Reach:
    """What a construction draws on the mechanism: the marks within reach, and the detours for those beyond it.

    Attributes
    ----------
    marks : tuple of Mark
        Every point drawn on the mechanism (the detours' own points included); each within reach.
    detours : tuple of Detour
    centre : (float, float)
        The mechanism's centre [m] (the mean of its points).
    size : float
        The mechanism's size [m]: the larger of its width and height.
    box : ((float, float), (float, float)) or None
        The drawing's box [m], lower left and upper right corners, where a drawing chose it
        (:func:`graphkin.graphical.paper.sheet_reach`): every mark lies in it.
    """

    marks: tuple[Mark, ...]
    detours: tuple[Detour, ...]
    centre: tuple[float, float]
    size: float
    box: tuple | None = None

    def holds(self, X) -> bool:
        """Whether the point X [m] lies in :attr:`box` (within :data:`REACH` sizes of the centre without one)."""
        X = np.asarray(X, float)
        if not np.all(np.isfinite(X)):
            return False
        if self.box is None:
            return math.hypot(*(X - self.centre)) <= REACH * self.size
        lo, hi = self.box
        return bool(np.all((X >= np.asarray(lo) - 1e-9) & (X <= np.asarray(hi) + 1e-9)))

    def points(self) -> list[tuple[float, float]]:
        """Every mark's point [m]: what a drawing of the mechanism makes room for."""
        return [m.at for m in self.marks]


def _unit(v) -> np.ndarray:
    v = np.asarray(v, float)
    return v / math.hypot(*v)


def _cross(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def _foot(P, d, X) -> np.ndarray:
    """The point of the line through ``P`` along unit ``d`` nearest ``X``."""
    P = np.asarray(P, float)
    return P + d * float(np.dot(np.asarray(X, float) - P, d))


def _meet(P1, d1, P2, d2) -> np.ndarray | None:
    """Where two lines meet (None when they are parallel)."""
    det = _cross(d1, d2)
    if abs(det) < 1e-12:
        return None
    t = _cross(np.asarray(P2, float) - P1, d2) / det
    return np.asarray(P1, float) + t * np.asarray(d1, float)


def _point_name(construction, link: int, X) -> str:
    """The name of ``link``'s point at ``X`` (``"A"``), or ``"the pin"`` when none is there."""
    for name, P in construction.points.get(link, {}).items():
        if math.hypot(*(np.asarray(P, float) - X)) < 1e-9:
            return name
    return "the pin"


def reach(construction, near=None) -> Reach:
    """What ``construction`` draws on the mechanism, and which of its steps are drawn another way.

    Parameters
    ----------
    construction : graphkin.graphical.Construction
    near : callable, optional
        ``near(X)``: whether the point X [m] can be drawn (a drawing's box at its scale,
        :func:`graphkin.graphical.paper.sheet_reach`). Default: within :data:`REACH` mechanism sizes of its
        centre.

    Returns
    -------
    Reach
    """
    c = construction
    pts = [np.asarray(p, float) for d in c.points.values() for p in d.values()] or [np.zeros(2)]
    # A gear reaches its pitch circle, well beyond its one point, the centre.
    for mesh in (j for j in c.mechanism.joints if isinstance(j, GearMesh)):
        for link, name, r in zip(mesh.links, mesh.centers, mesh.radii):
            O = np.asarray(c.points[link][name], float)
            pts += [O - r, O + r]
    pts = np.asarray(pts, float)
    centre = pts.mean(axis=0)
    size = max(float(np.max(np.ptp(pts, axis=0))), 1e-3)

    drawable = near

    def near(X) -> bool:
        if X is None or not np.all(np.isfinite(X)):
            return False
        return bool(drawable(X)) if drawable is not None else math.hypot(*(X - centre)) <= REACH * size

    marks: list[Mark] = []
    detours: list[Detour] = []
    for n, st in enumerate(c.steps):
        if st.kind == "resultant":
            _resultant(c, n, st, near, marks, detours)
        elif st.kind == "three-force":
            _three_force(c, n, st, near, marks, detours)
        else:
            G = centre if st.link is None else np.asarray(c.G.get(st.link, centre), float)
            for line in st.lines:
                X = _foot(line.point, _unit(line.direction), G)
                if near(X):
                    marks.append(Mark(f"{line.name}'s line", tuple(X), n))
            marks += [Mark(name, tuple(np.asarray(X, float)), n) for name, X in st.points.items()
                      if near(np.asarray(X, float))]
    return Reach(tuple(marks), tuple(detours), tuple(centre), size)


def _resultant(c, n, st, near, marks, detours):
    """A resultant's parts on their lines, where they meet, and its own line; or its line at h (``"offset"``)."""
    L = st.link
    G = np.asarray(c.G.get(L, c.points[L][next(iter(c.points[L]))]), float)
    parts = [(line.name, np.asarray(line.point, float), _unit(line.direction)) for line in st.lines
             if line.name == f"R{L}i"]
    parts += [(a.name, np.asarray(a.at, float), _unit(a.vector)) for a in c.external.get(L, [])
              if a.at is not None and math.hypot(*a.vector) > 0]
    whole = [line for line in st.lines if line.name not in {p[0] for p in parts}]
    meets = []
    if len(parts) >= 2:
        # The parts combined two at a time, as a drawing does: the first two where their lines meet, their sum
        # with the third where its line meets the sum's, and so on.
        (_, P, d), F = parts[0], np.asarray(st.values.get(parts[0][0].replace("R", "F", 1), (0.0, 0.0)), float)
        loads = {a.name: np.asarray(a.vector, float) for a in c.external.get(L, [])}
        F = F if math.hypot(*F) > 0 else loads.get(parts[0][0], d)
        for name, Q, e in parts[1:]:
            if abs(_cross(Q - P, d)) < 1e-9 and abs(_cross(d, e)) < 1e-9:
                F = F + loads.get(name, e)  # on one line (a piston's loads): their sum acts along it
                continue
            X = _meet(P, d, Q, e)
            meets.append((name, X))
            if X is None:
                break  # parallel lines: the sum's line is found by its offset
            F = F + loads.get(name, e)
            if math.hypot(*F) == 0:
                break
            P, d = X, _unit(F)
    names = " and ".join(f"{p[0]}'s" for p in parts)
    if meets and all(near(X) for _, X in meets):
        for name, P, d in parts:
            X = _foot(P, d, G)
            marks.append(Mark(f"{name}'s line", tuple(X), n))
        for _, X in meets:
            marks.append(Mark(f"where {names} lines meet", tuple(X), n))
    for line in whole:
        d = _unit(line.direction)
        X = _foot(line.point, d, G)
        R = np.asarray(st.values.get(line.name, d), float)
        sense = "CCW" if _cross(np.asarray(line.point, float) - G, R) > 0 else "CW"
        far = next((Y for _, Y in meets if not near(Y)), False) if meets else False
        if far is not False:
            # Its parts' lines meet far off: its own line is drawn at h from G instead.
            far = Mark(f"where {names} lines meet", (math.inf, math.inf) if far is None else tuple(far), n)
        elif not near(X):
            far = Mark(f"{line.name}'s line", tuple(X), n)  # itself far: given by h, and not drawn
        if far is not False:
            detours.append(Detour("offset", n, L, far, line.name, f"G{L}", {line.name: math.hypot(*(X - G))}, sense,
                                  tuple(p[0] for p in parts)))
        if near(X):
            marks.append(Mark(f"{line.name}'s line", tuple(X), n))


def _three_force(c, n, st, near, marks, detours):
    """The three lines and where they meet; or moments about the pin of the found force (``"moments"``)."""
    L = st.link
    found = [line for line in st.lines if line.role == "found"]
    others = [line for line in st.lines if line.role != "found"]
    G = np.asarray(c.G.get(L, (0.0, 0.0)), float)
    for line in st.lines:
        X = _foot(line.point, _unit(line.direction), G if line.role == "resultant" else line.point)
        if near(X):
            marks.append(Mark(f"{line.name}'s line", tuple(X), n))
    for name, X in st.points.items():
        X = np.asarray(X, float)
        if near(X):
            marks.append(Mark(name, tuple(X), n))
            continue
        if len(found) != 1 or len(others) != 2 or not any(line.role == "known direction" for line in others):
            continue  # no moments to take (a gear's line drawn in a step before): the point is named, not drawn
        A = np.asarray(found[0].point, float)
        arms = {}
        for line in others:
            d = _unit(line.direction)
            foot = _foot(line.point, d, A)
            arms[line.name] = math.hypot(*(foot - A))
            if near(foot):
                marks.append(Mark(f"the foot of the perpendicular from {_point_name(c, L, A)} to {line.name}'s line",
                                  tuple(foot), n))
        known = next((line.name for line in others if line.role == "known direction"), "")
        detours.append(Detour("moments", n, L, Mark(name, tuple(X) if np.all(np.isfinite(X)) else
                                                     (math.inf, math.inf), n), known, _point_name(c, L, A), arms))
