"""What a careful student's drawing is accurate to, and what that makes of each answer read off it.

A graphical answer is only as good as the lines it is measured off. A careful student draws each line of
the construction within :data:`LENGTH` (a point placed, an offset or a side laid off, a length measured,
on paper) and :data:`ANGLE` (a direction drawn or carried over with set squares), at the worksheet's
printed scales (:func:`graphkin.graphical.paper.sheet_scales`). A force read off a polygon carries the
errors of every line drawn before it: the lines of action in the mechanism, the point where two of them
meet, the sides laid off in this polygon and in the polygons whose results it takes over.

:func:`drawn` replays the construction's steps as a student draws them, each line with its own error,
for many sets of errors at once. :func:`drawing_slack` carries the stated precision through that replay
to each answer: every error moves the answer by its sensitivity (found from the replay), each error is
taken as uniform within its stated bound (standard deviation bound/√3), and the slack is the bound of their
sum that holds :data:`HELD` of careful constructions (:data:`COVERAGE`).

Steps replayed: an inertia or load resultant on its line, a two-force member, a three-force member and
its point of concurrency, a force polygon with up to two unknowns, and the driver (a crank or a slider).
A construction with other steps (superposition, gears, couples) is not replayed: its answers keep the
reading of the final measurement alone (:func:`graphkin.graphical.paper.reading_error`).
"""

from __future__ import annotations

import math
import re
from statistics import NormalDist

import numpy as np

from graphkin.graphical.paper import READING, sheet_scales

LENGTH = READING
"""A careful student's error on paper [mm], each way: a point placed, an offset or a side laid off, a length
measured (half the smallest division of a school rule)."""

ANGLE = 0.5
"""A careful student's error in a drawn direction [°], each way: a line drawn at a given angle, or a direction
carried from the mechanism to the polygon with set squares (half a degree of a protractor)."""

HELD = 0.975
"""The share of careful constructions the slack is set to hold. A course promises 95 %; aiming higher leaves room
for what the linear estimate leaves out (a construction is not quite linear in its errors, a sum of a few uniform
errors not quite normal)."""

COVERAGE = NormalDist().inv_cdf(0.5 + HELD / 2) / math.sqrt(3)
"""The slack in units of the root sum of squares of the stated bounds' effects: an error uniform within ±b has
a standard deviation of b/√3, and 2.24 standard deviations hold 97.5 % of a sum of such errors (1.29 bounds)."""

_REPLAYED = {"resultant", "two-force", "three-force", "polygon", "driver", "note"}
_FORCE = re.compile(r"^([FG])(\d)(\d)(\D*)$")


class Errors:
    """The errors of one set of drawings, source by source, as arrays over the ``n`` drawings.

    Parameters
    ----------
    n : int
        How many drawings are replayed at once.
    rng : numpy.random.Generator, optional
        Draws each error uniformly within its bound (a Monte Carlo of careful students).
    probe : float, optional
        Instead of random errors: drawing ``1 + i`` moves source ``i`` alone, by ``probe`` times its bound
        (drawing 0 has no error), to find each source's effect.
    """

    def __init__(self, n: int, *, rng=None, probe: float | None = None):
        self.n, self.rng, self.probe = n, rng, probe
        self.count = 0

    def __call__(self, bound: float) -> np.ndarray:
        """The error of the next source, within ±``bound`` (its unit), one value per drawing."""
        i = self.count
        self.count += 1
        if self.rng is not None:
            return self.rng.uniform(-bound, bound, self.n)
        e = np.zeros(self.n)
        if self.probe is not None and 1 + i < self.n:
            e[1 + i] = self.probe * bound
        return e


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
        self.points[next(iter(s.points))] = I_
        P = self.place(found[0].point)
        d = (I_ - P) / np.abs(I_ - P)  # the line drawn through the pin and I
        self.lines.setdefault(found[0].name, (P, d))
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


def drawing_slack(construction, q, exact) -> float | None:
    """The slack of a graphical answer that the stated precision gives [SI; rad for a direction].

    Each error's effect on the answer is found by replaying the construction with that error alone; the slack
    is :data:`COVERAGE` times the root sum of squares of the effects at the stated bounds. None when the answer
    is not measured off a construction this module replays.

    Parameters
    ----------
    construction : graphkin.graphical.Construction
        The student's construction, at the position asked about.
    q : Question
    exact : float or complex
        The key's value (SI).

    Returns
    -------
    float or None
    """
    if not construction.valid:
        return None
    errors = Errors(1)
    d = drawn(construction, errors)
    m = None if d is None else measured(d, q, exact)
    # A replay that does not give the key's value back without errors is not this construction's: not used.
    if m is None or not abs(_off(q, m[0], exact)) <= 1e-9 * max(abs(exact), 1e-300):
        return None
    small = 1e-6  # of each bound: the effects are linear this near
    errors = Errors(1 + errors.count, probe=small)
    m = measured(drawn(construction, errors), q, exact)
    effects = np.abs(_off(q, m[1:], m[0])) / small
    return float(COVERAGE * np.sqrt(np.sum(effects**2)))


def _off(q, a, b):
    """a − b, an angle's wrapped to (−π, π]."""
    if q.part == "direction":
        return np.remainder(a - b + math.pi, 2 * math.pi) - math.pi
    return a - b
