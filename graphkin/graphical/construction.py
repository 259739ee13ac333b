"""The graphical solution as data: ordered steps, each with its caption and geometry.

Everything here is plain numbers (SI: m for the mechanism, N for forces) and
strings, so a handout, a grader or the drawing layer can use it without
re-solving anything. Vectors are ``(x, y)`` tuples.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from graphkin.errors import GraphkinError
from graphkin.graphical.captions import Caption
from graphkin.model import GearMesh, Prismatic
from graphkin.model.names import force_name, parse_force_name


@dataclass(frozen=True)
class Line:
    """A line of action drawn in the mechanism.

    Attributes
    ----------
    name : str
        What acts along it, e.g. ``"R3"`` or ``"F23"``.
    point : (float, float)
        A point of the line [m].
    direction : (float, float)
        Unit direction.
    role : str
        ``"resultant"`` (known load), ``"known direction"`` (a reaction whose
        line is known, its size not), ``"found"`` (a line found by the step).
    """

    name: str
    point: tuple[float, float]
    direction: tuple[float, float]
    role: str = "known direction"

    # Written by hand, as Arrow's and Step's: a frozen dataclass's own __init__ sets each field through
    # object.__setattr__, and a construction makes hundreds of these (an exercise's draws, thousands of
    # constructions). The fields are the dataclass's; the instance is as frozen.
    def __init__(self, name: str, point: tuple[float, float], direction: tuple[float, float],
                 role: str = "known direction"):
        d = self.__dict__
        d["name"], d["point"], d["direction"], d["role"] = name, point, direction, role


@dataclass(frozen=True)
class Arrow:
    """A force in a polygon, drawn tip to tail in order.

    Attributes
    ----------
    name : str
    vector : (float, float)
        The force [N].
    known : bool
        True for loads known before the step, False for the unknowns it finds.
    at : (float, float) or None
        Where it acts in the mechanism [m] (its point of application), if it has one.
    """

    name: str
    vector: tuple[float, float]
    known: bool
    at: tuple[float, float] | None = None

    def __init__(self, name: str, vector: tuple[float, float], known: bool, at: tuple[float, float] | None = None):
        d = self.__dict__
        d["name"], d["vector"], d["known"], d["at"] = name, vector, known, at


@dataclass(frozen=True)
class Step:
    """One step of the construction.

    Attributes
    ----------
    kind : str
        ``"resultant"``, ``"two-force"`` (a member with two forces: they
        share one line), ``"three-force"``, ``"couple"`` (a member loaded by a
        couple alone: its two forces are an opposite couple), ``"line"`` (a
        force whose line of action is known, e.g. a gear's pressure line),
        ``"polygon"``, ``"superpose"`` (a force as the sum of its parts from
        the sub-problems), ``"sub-problem"`` (announces a sub-problem of a
        superposition), ``"readings"`` (what a sub-problem found), ``"driver"``
        or ``"note"``.
    caption : str
        What a student does in this step, in words.
    link : int or None
        The link the step is about.
    lines : tuple of Line
    points : dict of str to (float, float)
        Named points the step adds, e.g. the concurrency point ``"I3"`` [m].
    polygon : tuple of Arrow
        A force polygon, tip to tail; it closes when the link is in equilibrium.
    values : dict of str to float or (float, float)
        Values read off the step (forces [N], torques [N·m], distances [m]).
    sub : str
        The sub-problem of a superposition the step belongs to (``"I"``,
        ``"II"``, …; a part of a sub-problem split once more is ``"I.a"``),
        ``""`` for a step of the whole problem. Forces found in sub-problem k
        carry its marks (:attr:`SubProblem.mark`): ``F23′`` in I, ``F23″`` in II.
    """

    kind: str
    caption: str = Caption()
    link: int | None = None
    lines: tuple[Line, ...] = ()
    points: dict = field(default_factory=dict)
    polygon: tuple[Arrow, ...] = ()
    values: dict = field(default_factory=dict)
    sub: str = ""

    def __init__(self, kind: str, caption: str, link: int | None = None, lines: tuple[Line, ...] = (),
                 points: dict | None = None, polygon: tuple[Arrow, ...] = (), values: dict | None = None,
                 sub: str = ""):
        d = self.__dict__
        d["kind"], d["caption"], d["link"], d["lines"] = kind, caption, link, lines
        d["points"] = {} if points is None else points
        d["polygon"], d["values"], d["sub"] = polygon, {} if values is None else values, sub

    def __getstate__(self):
        # A caption not yet written is written before the step is copied or pickled.
        return {**self.__dict__, "caption": self.caption}

    def closure(self) -> float:
        """|Σ polygon| / max |arrow|: 0 for a polygon that closes."""
        if not self.polygon:
            return 0.0
        total = math.hypot(math.fsum(a.vector[0] for a in self.polygon), math.fsum(a.vector[1] for a in self.polygon))
        size = max(math.hypot(*a.vector) for a in self.polygon)
        return float(total / size) if size else 0.0


@dataclass(frozen=True)
class SubProblem:
    """One sub-problem of a superposition: the loads of one link alone, every other link unloaded.

    At a fixed position the equilibrium equations are linear in the loads
    (with the side of each guide's friction and each tooth's flank fixed by
    the whole problem), so the forces and driving efforts of the
    sub-problems add up to those of the whole problem.

    Attributes
    ----------
    label : str
        ``"I"``, ``"II"``, … in the order of the loaded links' numbers.
    link : int
        The one link whose own loads (inertia, weight, external) act.
    mark : str
        How the steps mark its forces: ``"′"`` (F23′), ``"″"``, ``"‴"``, …
    forces : dict of (int, int) to (float, float)
        Force of the lower-numbered link on the higher, per joint [N].
    normal, couple : dict of (int, int) to float
        For prismatic pairs: normal force [N] and couple [N·m].
    effort : float
        This sub-problem's driving torque [N·m] or force along the guide [N].
    driver_vector : (float, float) or None
        A slider driver's force as a vector [N] (None for a crank).
    """

    label: str
    link: int
    mark: str
    forces: dict = field(default_factory=dict)
    normal: dict = field(default_factory=dict)
    couple: dict = field(default_factory=dict)
    effort: float = math.nan
    driver_vector: tuple[float, float] | None = None

    def force(self, i: int, j: int) -> np.ndarray:
        """Force of link i on link j in this sub-problem [N], shape (2,)."""
        return _force_of(self.forces, i, j)


def _force_of(forces: dict, i: int, j: int) -> np.ndarray:
    """Force of link i on link j [N] from forces kept as the lower-numbered link's on the higher."""
    key = (min(i, j), max(i, j))
    if key not in forces:
        raise GraphkinError(f"links {i} and {j} share no joint")
    F = np.asarray(forces[key], dtype=float)
    return F if i < j else -F


STEP_TITLES = {
    "resultant": "resultant of the known loads",
    "two-force": "two-force member",
    "three-force": "three-force member",
    "line": "a known line of action",
    "couple": "a couple balanced by a couple",
    "polygon": "force polygon",
    "superpose": "superposition",
    "sub-problem": "a sub-problem of the superposition",
    "readings": "what the sub-problem found",
    "driver": "the input link",
    "note": "note",
}
"""A short title for each kind of step, as a figure or a handout heads it."""


def nice_scale(largest: float, length: float = 80.0) -> float:
    """A round force scale [N per mm of drawing] drawing ``largest`` [N] about ``length`` mm long.

    Examples
    --------
    >>> nice_scale(27.04)
    0.5
    >>> nice_scale(2377.0)
    50.0
    """
    if not largest > 0:
        return 1.0
    raw = largest / length
    decade = 10 ** math.floor(math.log10(raw))
    for m in (1, 2, 5, 10):
        if m * decade >= raw:
            return float(m * decade)
    return float(10 * decade)  # pragma: no cover


@dataclass(frozen=True)
class Construction:
    """The graphical solution of one position.

    Attributes
    ----------
    mechanism : Mechanism
    index : int
        Position index in the kinematics it was built from.
    q : float
        The input coordinate at that position (θ [rad] or s [m]).
    steps : tuple of Step
    forces : dict of (int, int) to (float, float)
        Force of the lower-numbered link on the higher, per joint [N].
    normal, couple : dict of (int, int) to float
        For prismatic pairs: normal force N [N] and couple C [N·m], as in
        :class:`graphkin.analytical.ForceAnalysis`.
    effort : float
        Driving torque T1j [N·m] or force F1j along the guide [N].
    force_scale : float
        Round scale for drawing the polygons [N per mm].
    points : dict of int to dict of str to (float, float)
        Position of every named point of every link at this position [m].
    G : dict of int to (float, float)
        Centre of mass of each moving link [m].
    inertia : dict of int to dict
        Per moving link with mass: ``{"F": (x, y) [N], "T": N·m, "h": m or None,
        "line_point": (x, y) or None}`` — the inertia force, torque, offset h
        and a point of the single resultant's line.
    external : dict of int to list of Arrow
        External forces (and weight) on each link, at their points.
    pitch_points : dict of (int, int) to (float, float)
        Pitch point of each gear mesh [m].
    contacts : dict of (int, int) to (float, float)
        Where each gear mesh's tooth force acts [m]: its pitch point, or with a mesh efficiency the point of the
        line of centres its line crosses (:func:`graphkin.analytical.meshes.contact`).
    torques : dict of int to list of (str, float)
        External torques acting on each link at this position [N·m].
    guides : dict of (int, int) to (float, float)
        Unit direction of each prismatic pair's guide.
    angles : dict of int to float
        Angle θ of each link's frame [rad].
    driver_vector : (float, float) or None
        A slider driver's force F1j as a vector [N] (None for a crank).
    subproblems : tuple of SubProblem
        The sub-problems of a superposition, one per loaded link, whose forces
        and efforts add up to :attr:`forces` and :attr:`effort`; empty when
        the construction needs none (no dyad with both links loaded).
    valid : bool
    reason : str
        Why the construction cannot close, when not valid.
    warnings : tuple of str
        Polygons that failed to close within tolerance, and similar notes.
    disagreement : bool
        True where the construction is not valid because a value it yields disagrees with the analytical route
        (:mod:`graphkin.graphical.guard`): a fault in graphkin's arithmetic, to be reported, not a position the
        linkage cannot take (the ``reason`` names the quantity and both values).
    """

    mechanism: object
    index: int
    q: float
    steps: tuple[Step, ...] = ()
    forces: dict = field(default_factory=dict)
    normal: dict = field(default_factory=dict)
    couple: dict = field(default_factory=dict)
    effort: float = math.nan
    force_scale: float = 1.0
    valid: bool = True
    reason: str = ""
    warnings: tuple[str, ...] = ()
    points: dict = field(default_factory=dict)
    G: dict = field(default_factory=dict)
    inertia: dict = field(default_factory=dict)
    external: dict = field(default_factory=dict)

    def forces_on(self, link: int) -> list[Arrow]:
        """Every joint force acting on ``link``, named F_ij (of i on link), at its point of application.

        A prismatic pair's force is placed at the slider point; the couple it
        also transmits is in :attr:`couple` (see :meth:`couple_on`).
        """
        out = []
        for joint in self.mechanism.joints_of(link):
            other = (set(joint.links) - {link}).pop()
            F = self.force(other, link)
            if isinstance(joint, Prismatic):
                at = self.points[joint.slider][joint.point]
            elif isinstance(joint, GearMesh):
                at = self.contacts[tuple(sorted(joint.links))]
            else:
                at = self.points[link][joint.point]
            out.append(Arrow(force_name(self.mechanism, other, link), (float(F[0]), float(F[1])), False, at))
        return out

    def couple_on(self, link: int) -> float:
        """Sum of the couples the sliding pairs of ``link`` apply to it [N·m]."""
        total = 0.0
        for (lo, hi), C in self.couple.items():
            if link == hi:
                total += C
            elif link == lo:
                total -= C
        return total

    pitch_points: dict = field(default_factory=dict)
    contacts: dict = field(default_factory=dict)
    torques: dict = field(default_factory=dict)
    guides: dict = field(default_factory=dict)
    angles: dict = field(default_factory=dict)
    driver_vector: tuple[float, float] | None = None
    subproblems: tuple[SubProblem, ...] = ()
    disagreement: bool = False

    @property
    def driver_name(self) -> str:
        return self.mechanism.driver.symbol

    def force(self, i: int, j: int) -> np.ndarray:
        """Force of link i on link j [N], shape (2,)."""
        return _force_of(self.forces, i, j)

    def __getitem__(self, name: str):
        if name == self.driver_name:
            # As in ForceAnalysis: a torque is a number, a slider's force a vector.
            return self.effort if self.driver_vector is None else np.asarray(self.driver_vector)
        return self.force(*parse_force_name(self.mechanism, name))

    def values(self) -> dict:
        """Every force the construction found, by name (both orders) [N], and the driver's effort.

        The driver's entry is the torque T1j [N·m] of a crank or the force
        vector F1j [N] of a slider.
        """
        out = {}
        for (i, j), F in self.forces.items():
            out[force_name(self.mechanism, i, j)] = tuple(F)
            out[force_name(self.mechanism, j, i)] = (-F[0], -F[1])
        out[self.driver_name] = self.effort if self.driver_vector is None else tuple(self.driver_vector)
        return out
