"""The force construction as a careful student draws it, for :mod:`graphkin.exercises.drawn`.

The construction's steps are replayed as drawn at the worksheet's printed scales
(:func:`graphkin.graphical.paper.sheet_scales`), each line within the stated precision
(:mod:`graphkin.exercises.precision`): each line of action offset and turned, the point of concurrency where
two drawn lines meet, the line through a pin and that point, each polygon's known sides laid off (a force
found in an earlier polygon taken over with its errors), the unknown sides' directions carried over, the
crank's arm, and the answer measured.

Steps replayed: an inertia or load resultant on its line, a two-force member, a three-force member and its
point of concurrency, a force polygon with one or two unknowns, and the driver (a crank or a slider). A
construction with other steps (superposition, gears, couples) is not replayed.
"""

from __future__ import annotations

import math
import re

import numpy as np

from graphkin.exercises.precision import ANGLE, LENGTH, Errors
from graphkin.graphical.paper import sheet_scales

_REPLAYED = {"resultant", "two-force", "three-force", "polygon", "driver", "note"}
_FORCE = re.compile(r"^([FG])(\d)(\d)(\D*)$")


class _Drawing:
    """A construction as drawn: each line, point and force as the student has it (complex arrays over drawings)."""

    def __init__(self, construction, errors: Errors):
        scales = sheet_scales(construction)
        self.k = scales.length * 1e-3  # true metres per paper millimetre
        self.X = scales.polygon  # newtons per paper millimetre
        self.err = errors
        self.turn = math.radians(ANGLE)
        self.lines: dict[str, tuple] = {}
        self.forces: dict[str, np.ndarray] = {}  # as drawn
        self.exact: dict[str, complex] = {}  # as the construction has them
        self.points: dict[str, np.ndarray] = {}
        self.crank = None  # a crank driver's load R and its arm d about the pivot, as drawn [N, m]

    # -- one drawn line, point or side ---------------------------------------------------------------------------
    def place(self, P) -> np.ndarray:
        """A point of the mechanism placed on paper, within the stated precision in x and in y."""
        return complex(*P) + self.err(LENGTH * self.k) + 1j * self.err(LENGTH * self.k)

    def line(self, line) -> tuple:
        """A line drawn through its point at its direction, offset and turned within the stated precision."""
        u = complex(*line.direction)
        p = complex(*line.point) + 1j * u * self.err(LENGTH * self.k)
        return p, u * np.exp(1j * self.err(self.turn))

    def lay_off(self, F) -> np.ndarray:
        """A side of a polygon laid off at the force scale: its length and its direction within the precision."""
        return (np.abs(F) + self.err(LENGTH * self.X)) * np.exp(1j * (np.angle(F) + self.err(self.turn)))

    def carry(self, u) -> np.ndarray:
        """A direction carried from the mechanism to the polygon."""
        return u * np.exp(1j * self.err(self.turn))

    # -- the steps --------------------------------------------------------------------------------------------------
    def step(self, s) -> bool:
        """Draw one step; False when it is not one this replay draws."""
        if s.kind not in _REPLAYED or s.sub:
            return False
        if s.kind == "three-force":
            return self.three_force(s)
        for line in s.lines:
            self.lines.setdefault(line.name, self.line(line))
        if s.kind == "resultant":
            self.resultant(s)
        if s.polygon and not self.polygon(s):
            return False
        return s.kind != "driver" or self.driver(s)

    def resultant(self, s) -> None:
        for name, value in s.values.items():
            # A link's resultant R2 (not an inertia force F3i or its resultant R3i, which are given): it takes over
            # the forces found on the link before, with their errors (R2 = F32).
            if name == f"R{s.link}":
                self.forces[name] = self.inherited(s.link, complex(*value))
                self.exact[name] = complex(*value)

    def inherited(self, link: int, R: complex) -> np.ndarray:
        drawn, exact = 0j, 0j
        for name, F in self.forces.items():
            m = _FORCE.match(name)
            if m and int(m.group(3)) == link:
                drawn, exact = drawn + F, exact + self.exact[name]
            elif m and int(m.group(2)) == link:
                drawn, exact = drawn - F, exact - self.exact[name]
        given = R - exact  # the link's own loads, laid off from the data
        return drawn + (self.lay_off(given) if abs(given) > 1e-9 * abs(R) else 0j)

    def three_force(self, s) -> bool:
        known = [line for line in s.lines if line.role != "found"]
        found = [line for line in s.lines if line.role == "found"]
        if len(known) != 2 or len(found) != 1 or len(s.points) != 1:
            return False
        for line in known:
            self.lines.setdefault(line.name, self.line(line))
        (p, u), (q, w) = (self.lines[line.name] for line in known)
        I_ = p + u * _cross(q - p, w) / _cross(u, w)  # where the two drawn lines meet
        name, I_exact = next(iter(s.points.items()))
        self.points[name] = I_
        line = found[0]
        if abs(complex(*line.point) - complex(*I_exact)) <= 1e-9 * max(abs(complex(*I_exact)), 1.0):
            # A line whose direction is known (normal to a guide) is drawn through I at that direction.
            self.lines.setdefault(line.name, (I_, complex(*line.direction) * np.exp(1j * self.err(self.turn))))
            return True
        P = self.place(line.point)
        self.lines.setdefault(line.name, (P, (I_ - P) / np.abs(I_ - P)))  # the line through the pin and I
        return True

    def polygon(self, s) -> bool:
        total = 0j
        unknown = []
        for a in s.polygon:
            if not a.known:
                unknown.append(a)
                continue
            F = complex(*a.vector)
            before = self.known(a.name)
            total = total + self.lay_off(F if before is None else before)
        if len(unknown) == 1:
            found = [-total]
        elif len(unknown) == 2:
            d = []
            for a in unknown:
                F = complex(*a.vector)
                drawn = self.lines.get(a.name)
                if drawn is None and not F:
                    return False
                d.append(self.carry(drawn[1] if drawn is not None else F / abs(F)))
            # The two unknowns' sizes along their drawn directions close the polygon: c1·d1 + c2·d2 = −Σ known.
            den = _cross(d[0], d[1])
            found = [_cross(-total, d[1]) / den * d[0], _cross(d[0], -total) / den * d[1]]
        else:
            return False
        for a, F in zip(unknown, found):
            self.forces[a.name] = F
            self.exact[a.name] = complex(*a.vector)
        return True

    def known(self, name: str):
        """A side drawn before (a force found, or its reverse), as the student has it; None for a given load."""
        if name in self.forces:
            return self.forces[name]
        m = _FORCE.match(name)
        other = m and f"{m.group(1)}{m.group(3)}{m.group(2)}{m.group(4)}"
        return -self.forces[other] if other in self.forces else None

    def driver(self, s) -> bool:
        if "d" not in s.values:
            return True  # a slider: its driving force is a side of the polygon
        pivot = [line for line in s.lines if line.role == "found"]
        R = s.polygon[0].name if s.polygon else None
        if len(pivot) != 1 or R not in self.lines or R not in self.forces:
            return False
        p = self.lines[R][0]
        u = self.forces[R] / np.abs(self.forces[R])
        self.crank = self.forces[R], np.abs(_cross(self.place(pivot[0].point) - p, u))
        return True


def _cross(a, b):
    """The z component of a × b, for points of the plane as complex numbers."""
    return (np.conj(a) * b).imag


def drawn(construction, errors: Errors) -> _Drawing | None:
    """The construction replayed as drawn with ``errors`` (None when a step is not one this module replays)."""
    d = _Drawing(construction, errors)
    for s in construction.steps:
        if not d.step(s):
            return None
    return d


def measured(d: _Drawing, q, exact):
    """The answer to ``q`` as the student measures it off drawing ``d`` (an array over the drawings; SI, angles in
    rad), or None when ``q`` is not read off the force construction. ``exact`` is the key's value (for its sign)."""
    read_force = LENGTH * d.X  # a side measured with a ruler [N]
    read_length = LENGTH * d.k  # a length on the mechanism's drawing [m]
    if q.kind == "force":
        F = d.known(q.find)
        if F is None:
            return None
        if q.part in ("x", "y"):
            return (F.real if q.part == "x" else F.imag) + d.err(read_force)
        if q.part == "magnitude":
            return np.abs(F) + d.err(read_force)
        if q.part == "direction":
            return np.angle(F) + d.err(d.turn)
        return (np.abs(F) + d.err(read_force)) * np.exp(1j * (np.angle(F) + d.err(d.turn)))
    if q.kind == "driver_force":
        F = d.known(q.find)
        return None if F is None else math.copysign(1.0, exact) * (np.abs(F) + d.err(read_force))
    if q.kind == "driver_torque":
        if d.crank is None:
            return None
        R, arm = d.crank
        return math.copysign(1.0, exact) * (np.abs(R) + d.err(read_force)) * (arm + d.err(read_length))
    if q.kind == "concurrency":
        I_ = d.points.get(f"I{q.link}")
        return None if I_ is None else I_ + d.err(read_length) + 1j * d.err(read_length)
    return None
