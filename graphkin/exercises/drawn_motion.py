"""The velocity and acceleration polygons as a careful student draws them, for :mod:`graphkin.exercises.precision`.

The polygons are replayed step by step at the worksheet's printed scales, each drawn line within the stated
precision: a vector laid off from the data or from values read before (a normal component ω² r from the ω
the student measured, a Coriolis component 2 ω v from the ω and the sliding velocity measured), each line
of known direction carried from the mechanism, the image point where two lines meet, ω and α measured off
a relative vector, and the image of a link placed by similarity on two image points drawn before (or on
one, turned and scaled by the link's ω and α as the student found them), each point within the precision.
"""

from __future__ import annotations

import math

import numpy as np

from graphkin.exercises.precision import ANGLE, LENGTH, Errors
from graphkin.graphical.paper import POLYGON_ROOM, motion_scales


class _Polygons:
    """The polygons as drawn: image points, relative vectors, ω and α (arrays over the drawings)."""

    def __init__(self, mc, errors: Errors):
        self.mc, self.err = mc, errors
        Xv, Xa = motion_scales(mc, POLYGON_ROOM)
        self.X = {"velocity": Xv, "acceleration": Xa}
        self.turn = math.radians(ANGLE)
        self.exact: dict[str, complex] = {}  # image points by name, as the construction has them
        self.images: dict[str, np.ndarray] = {}  # and as drawn
        self.vectors: dict[str, tuple] = {}  # a relative vector by name: (as drawn, exact)
        self.omega: dict[int, np.ndarray] = {}
        self.alpha: dict[int, np.ndarray] = {}
        self.coriolis: dict[str, tuple] = {}  # a Coriolis component by name: (as laid off, exact)

    # -- one drawn vector or point ----------------------------------------------------------------------------------
    def lay_off(self, V: complex, polygon: str, size=None) -> np.ndarray:
        """A vector laid off at the polygon's scale: ``size`` (as the student computed it; else V's) and V's
        direction, each within the stated precision."""
        size = abs(V) if size is None else size
        return (size + self.err(LENGTH * self.X[polygon])) * np.exp(1j * (np.angle(V) + self.err(self.turn)))

    def place(self, P, polygon: str) -> np.ndarray:
        """A point placed in the polygon, within the stated precision in x and in y."""
        e = LENGTH * self.X[polygon]
        return P + self.err(e) + 1j * self.err(e)

    def read(self, V, exact: complex, polygon: str) -> np.ndarray:
        """The length of a drawn vector as measured, signed along the exact one."""
        along = (V * np.conj(exact)).real / abs(exact)
        return along + self.err(LENGTH * self.X[polygon])

    def at(self, z: complex):
        """The drawn point whose exact place is ``z`` (the pole, or an image point drawn before), or None."""
        size = max([abs(p) for p in self.exact.values()] + [1.0])
        if abs(z) <= 1e-9 * size:
            return 0j
        for name, p in self.exact.items():
            if abs(p - z) <= 1e-9 * size:
                return self.images[name]
        return None

    # -- the steps ------------------------------------------------------------------------------------------------
    def step(self, s) -> bool:
        if s.kind == "note":
            return True
        if s.kind == "driver":
            for key, value in s.values.items():
                if key.startswith(("omega", "alpha")) and key[5:].isdigit():
                    table = self.omega if key.startswith("omega") else self.alpha
                    table[int(key[5:])] = np.full(self.err.n, float(value))  # the data: no error
            return True
        if s.kind == "dyad":
            return self.dyad(s)
        if s.kind == "image":
            return self.image(s)
        return False

    def dyad(self, s) -> bool:
        polygon = s.polygon
        drawn: dict[tuple, np.ndarray] = {}

        def at(z: complex):
            found = self.at(z)
            if found is not None:
                return found
            return next((p for key, p in drawn.items() if abs(complex(*key) - z) <= 1e-9 * max(abs(z), 1.0)), None)

        for v in s.vectors:
            if v.known != "size and direction":
                continue
            tail, tip = complex(*v.tail), complex(*v.tip)
            start = at(tail)
            if start is None:
                return False
            if tail == 0 and at(tip) is not None:
                continue  # from the pole to an image point drawn before
            V = tip - tail
            if not V:
                drawn[v.tip] = start  # nothing to draw (ω² r or 2 ω v of a link that does not turn)
                continue
            size = self.computed(v.name, V)
            if size is None:
                return False
            if v.name.startswith("a^c_"):
                # 2 ω v turned 90°: the sliding velocity's direction as drawn, turned.
                rel = self.vectors[f"v_{v.name[4:]}"]
                V = V * (rel[0] / np.abs(rel[0])) / (rel[1] / abs(rel[1]))
            laid = self.lay_off(V, polygon, size)
            drawn[v.tip] = start + laid
            if v.name.startswith("a^c_"):
                self.coriolis[v.name] = (laid, tip - tail)
        lines = []
        for line in s.lines:
            p = at(complex(*line.point))
            if p is None:
                return False
            lines.append((p, complex(*line.direction) * np.exp(1j * self.err(self.turn))))
        if len(lines) != 2 or len(s.points) != 1:
            return False
        (p, u), (q, w) = lines
        meet = p + u * _cross(q - p, w) / _cross(u, w)
        name, exact = next(iter(s.points.items()))
        self.exact[name], self.images[name] = complex(*exact), meet
        for v in s.vectors:
            if v.known == "direction":
                tail = at(complex(*v.tail))
                self.vectors[v.name] = (meet - tail, complex(*v.tip) - complex(*v.tail))
        return self.rates(s)

    def computed(self, name: str, V: complex):
        """The size of a known vector as the student computes it: ω² r with their ω, 2 ω v with their ω and v;
        a vector of the data as it is. None when it is neither."""
        kind, _, pair = name.partition("_")
        if kind == "a^n":
            k = self.link_of(pair)
            w = self.omega.get(k)
            exact = float(self.mc.omega[k]) if k is not None else 0.0
            if w is None or not exact:
                return None
            return abs(V) * (w / exact) ** 2
        if kind == "a^c":
            rel = self.vectors.get(f"v_{pair}")
            if rel is None:
                return None
            # The guide's ω: the link of the pair whose ω gives the component's size, 2 |ω| |v|.
            for k in self.links_of(pair):
                exact = float(self.mc.omega.get(k, 0.0))
                if k in self.omega and math.isclose(2 * abs(exact) * abs(rel[1]), abs(V), rel_tol=1e-6):
                    return abs(V) * (self.omega[k] / exact) * np.abs(rel[0]) / abs(rel[1])
            return None
        return abs(V)

    def rates(self, s) -> bool:
        """ω (α) of each link of the dyad, from the relative vector of two of its points, as measured; a link
        that translates has none, and a block turns with its guide."""
        kind = "omega" if s.polygon == "velocity" else "alpha"
        table, exact = (self.omega, self.mc.omega) if kind == "omega" else (self.alpha, self.mc.alpha)
        prefix = "v_" if kind == "omega" else "a^t_"
        links = [int(key[len(kind):]) for key in s.values if key.startswith(kind)]
        for k in links:
            rel = next((v for n, v in self.vectors.items() if n.startswith(prefix) and v[1]
                        and self.link_of(n[len(prefix):]) == k), None)
            if rel is not None:
                table[k] = float(exact[k]) * self.read(rel[0], rel[1], s.polygon) / abs(rel[1])
        for k in links:
            if k in table:
                continue
            twin = next((j for j in links if j in table and float(exact[j]) == float(exact[k])), None)
            if not float(exact[k]):
                table[k] = np.zeros(self.err.n)
            elif twin is not None:
                table[k] = table[twin]
            else:
                return False
        return True

    def image(self, s) -> bool:
        if len(s.links) != 1 or len(s.vectors) != len(s.points):
            return False
        k = s.links[0]
        names = list(s.points)
        exact = {n: complex(*p) for n, p in s.points.items()}
        size = max([abs(p) for p in exact.values()] + [abs(p) for p in self.exact.values()] + [1e-300])
        known = [n for n in names if n in self.images or abs(exact[n]) <= 1e-9 * size]  # or at the pole
        if not known:
            return False
        drawn = {n: self.images.get(n, 0j) for n in known}
        base = known[0]
        other = next((n for n in known[1:] if abs(exact[n] - exact[base]) > 1e-9 * max(abs(exact[base]), 1.0)), None)
        if other is not None:
            # Placed by similarity on two images drawn before.
            turn = (drawn[other] - drawn[base]) / (exact[other] - exact[base])
        else:
            w, a = float(self.mc.omega.get(k, 0.0)), float(self.mc.alpha.get(k, 0.0))
            f = 1j * w if s.polygon == "velocity" else complex(-w * w, a)
            if f == 0:
                turn = 1.0  # a link that translates: its image is one point
            elif k in self.omega and (s.polygon == "velocity" or k in self.alpha):
                wd = self.omega[k]
                turn = (1j * wd if s.polygon == "velocity" else -wd * wd + 1j * self.alpha[k]) / f
            else:
                return False
        for n in names:
            if n in known:
                continue
            self.exact[n] = exact[n]
            self.images[n] = self.place(drawn[base] + turn * (exact[n] - exact[base]), s.polygon)
        for n in known:
            self.exact.setdefault(n, exact[n])
            self.images.setdefault(n, drawn[n])
        return True

    # -- which link a pair of points belongs to ---------------------------------------------------------------------
    def links_of(self, pair: str) -> list[int]:
        """The links of the two points named in ``pair`` (``"BA"``, ``"B3B2"``, ``"BB0"``), one per point."""
        for cut in range(1, len(pair)):
            first, second = self.point_link(pair[:cut]), self.point_link(pair[cut:])
            if first and second:
                common = set(first) & set(second)
                if common:
                    return [min(common)] * 2
                return [first[0], second[0]]
        return []

    def link_of(self, pair: str):
        """The link both points of ``pair`` belong to (None for a sliding pair, on two links)."""
        links = self.links_of(pair)
        return links[0] if links and links[0] == links[1] else None

    def point_link(self, token: str) -> list[int]:
        mech = self.mc.mechanism
        found = [link.number for link in mech.links if token in link.points]
        if not found and token[-1:].isdigit() and token[:-1].isalpha():
            found = [int(token[-1])]  # B3: the point of link 3 at B
        return found


def _cross(a, b):
    return (np.conj(a) * b).imag


def motion_answer(mc, q, exact, errors: Errors):
    """What a careful student measures for ``q`` (ω, α, a_G or a Coriolis component) off the polygons as drawn
    with ``errors`` (an array over the drawings; SI), or None where the polygons are not replayed."""
    d = _Polygons(mc, errors)
    for s in mc.steps:
        if not d.step(s):
            return None
    k = q.link
    if q.kind == "omega":
        return d.omega.get(k)
    if q.kind == "alpha":
        return d.alpha.get(k)
    if q.kind == "a_G":
        g = d.images.get(f"g{k}′")
        return None if g is None else _measured(d, g, q.part)
    # The component the key gives (the largest of the link's, if several).
    found = [V for V, E in d.coriolis.values() if abs(_part(E, q.part) - exact) <= 1e-9 * abs(E)]
    return _measured(d, found[0], q.part) if found else None


def _part(V: complex, part: str):
    return {"vector": V, "magnitude": abs(V), "direction": math.atan2(V.imag, V.real), "x": V.real,
            "y": V.imag}[part]


def _measured(d: _Polygons, V, part: str):
    """A vector of the acceleration polygon as measured: its length and its direction, within the precision."""
    read = LENGTH * d.X["acceleration"]
    if part in ("x", "y"):
        return (V.real if part == "x" else V.imag) + d.err(read)
    size, angle = np.abs(V) + d.err(read), np.angle(V) + d.err(d.turn)
    return {"magnitude": size, "direction": angle, "vector": size * np.exp(1j * angle)}.get(part)
