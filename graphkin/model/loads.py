"""External loads: point forces and torques on links, and gravity.

A load may act only over a range of the input coordinate, like the cutting
force of the strip cutter (Söylemez §6.4.1: 2000 N for 124° < θ12 < 156°);
its size may follow a table against the input (an engine's gas force
against crank angle, :class:`Table`); and its sense may follow the motion
(a resistance that always opposes its point's velocity, or one that acts on
the working stroke only, :data:`SENSES`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.errors import ModelError
from graphkin.ranges import check, check_array, finite, point

EDGE = 1e-12
"""Relative distance from an end of an :class:`Active` interval within which a position counts as on the end."""


@dataclass(frozen=True)
class Active:
    """The open interval ``start < q < stop`` of the input where a load acts.

    For a crank the interval is in radians and taken modulo one turn, so
    ``Active(radians(350), radians(10))`` acts across 0°.
    """

    start: float
    stop: float
    periodic: bool = True

    def __post_init__(self):
        kind, unit = ("angle", "rad") if self.periodic else ("coordinate", "m")
        for name in ("start", "stop"):
            what = f"active window: {name}"
            object.__setattr__(self, name, check(finite(getattr(self, name), what, unit), kind, what))

    @property
    def width(self) -> float:
        """Width of the window [rad or m] (modulo one turn for a crank)."""
        return (self.stop - self.start) % (2 * math.pi) if self.periodic else self.stop - self.start

    def mask(self, q):
        """Boolean array: where the load acts, for input positions ``q``.

        The interval is open: a position within rounding (:data:`EDGE`,
        relative) of ``start`` or ``stop`` is outside, so 124° computed two
        ways gives the same answer.
        """
        q = np.asarray(q, dtype=float)
        if not self.periodic:
            tol = EDGE * max(abs(self.start), abs(self.stop), 1.0)
            return (q > self.start + tol) & (q < self.stop - tol)
        turn = 2 * math.pi
        tol = EDGE * turn
        width = (self.stop - self.start) % turn
        d = (q - self.start) % turn
        return (d > tol) & (d < width - tol)


SENSES = ("fixed", "opposes motion", "working stroke")
"""How a load's sense is set.

``"fixed"``: as given. ``"opposes motion"``: the given size, with the sense
that opposes the velocity of its point along the load's line (a torque: the
link's ω), as a Coulomb resistance, F = −sign(v·u) |F| u; zero where the
point stands still along that line. ``"working stroke"``: as given, but only
while its point moves against it (the load does negative work: a tool that
cuts on the forward stroke and idles on the return); zero otherwise.
"""


@dataclass(frozen=True, eq=False)
class Table:
    """A load's size against the input, piecewise linear between the rows.

    Parameters
    ----------
    q : array_like
        The input at each row [rad for a crank, m for a slider], ascending; a
        value repeated on two rows is a jump (the value of the first row just
        before, of the second just after).
    value : array_like
        The load's size at each row [N along the load's direction, or N·m].
    periodic : bool
        True for a crank: q is taken modulo one turn and the last row runs on
        to the first (the table needs rows inside one turn, 360° apart at most).
        False for a slider: outside the rows the load is not defined.

    Examples
    --------
    >>> import math
    >>> t = Table([0.0, math.pi], [0.0, 100.0])
    >>> [round(float(v), 6) for v in t([0.0, math.pi / 2, math.pi, 3 * math.pi / 2, 2 * math.pi])]
    [0.0, 50.0, 100.0, 50.0, 0.0]
    """

    q: np.ndarray
    value: np.ndarray
    periodic: bool = True
    source: str = ""

    def __post_init__(self):
        q = np.asarray(self.q, dtype=float).ravel()
        v = np.asarray(self.value, dtype=float).ravel()
        where = f"table{' ' + self.source if self.source else ''}"
        if q.size != v.size:
            raise ModelError(f"{where}: {q.size} input values but {v.size} load values; give one per row")
        if q.size < 2:
            raise ModelError(f"{where}: needs at least two rows, got {q.size}")
        if not (np.isfinite(q).all() and np.isfinite(v).all()):
            raise ModelError(f"{where}: every value must be finite")
        step = np.diff(q)
        if (step < 0).any():
            k = int(np.argmax(step < 0))
            raise ModelError(f"{where}: the input must ascend, but row {k + 2} is below row {k + 1}")
        if ((step[1:] == 0) & (step[:-1] == 0)).any():
            raise ModelError(f"{where}: an input value appears on three rows; a jump needs two")
        if self.periodic and q[-1] - q[0] > 2 * math.pi * (1 + 1e-12):
            raise ModelError(f"{where}: spans {math.degrees(q[-1] - q[0]):.6g}°; a crank's table covers one turn "
                             "(360° at most from its first row to its last)")
        object.__setattr__(self, "q", q)
        object.__setattr__(self, "value", v)

    def __call__(self, q) -> np.ndarray:
        """The load's size at the inputs ``q`` [N or N·m].

        Raises
        ------
        ModelError
            For a slider's table, at an input outside its rows.
        """
        q = np.asarray(q, dtype=float)
        xp, fp = self.q, self.value
        if self.periodic:
            turn = 2 * math.pi
            x = xp[0] + (q - xp[0]) % turn
            # The last row runs on to the first one a turn later.
            xp, fp = np.append(xp, xp[0] + turn), np.append(fp, fp[0])
            return self._interp(x, xp, fp)
        tol = 1e-12 * max(abs(xp[0]), abs(xp[-1]), 1.0)
        outside = (q < xp[0] - tol) | (q > xp[-1] + tol)
        if outside.any():
            bad = float(np.asarray(q)[outside].flat[0])
            raise ModelError(f"table{' ' + self.source if self.source else ''}: the input {bad * 1e3:.6g} mm lies "
                             f"outside its rows ({xp[0] * 1e3:.6g} mm to {xp[-1] * 1e3:.6g} mm)")
        return self._interp(np.clip(q, xp[0], xp[-1]), xp, fp)

    @staticmethod
    def _interp(x, xp, fp):
        # np.interp takes the value of the *last* of two equal rows at the jump itself; between rows it is the
        # straight line, so a jump's two rows give the value before and after it.
        return np.interp(x, xp, fp)

    def jumps(self) -> list[float]:
        """Inputs where the table jumps (a value on two rows whose loads differ)."""
        k = np.flatnonzero((np.diff(self.q) == 0) & (np.diff(self.value) != 0))
        out = [float(self.q[i]) for i in k]
        if self.periodic and self.q[-1] - self.q[0] >= 2 * math.pi * (1 - 1e-12) and self.value[-1] != self.value[0]:
            out.append(float(self.q[0]))  # the last row is a turn after the first, with another value
        return out

    def __eq__(self, other):
        return (isinstance(other, Table) and self.periodic == other.periodic and np.array_equal(self.q, other.q)
                and np.array_equal(self.value, other.value))

    __hash__ = None


def _sense(sense: str, what: str) -> str:
    if sense not in SENSES:
        raise ModelError(f"{what}: sense must be one of {', '.join(repr(s) for s in SENSES)}, got {sense!r}")
    return sense


@dataclass(frozen=True)
class PointForce:
    """A force of fixed global direction on a link.

    Parameters
    ----------
    link : int
        Link it acts on.
    point : str
        Point of the link where it acts.
    force : (float, float)
        Force vector (Fx, Fy) [N] in global axes.
    active : Active or None
        Where it acts; None for always.
    name : str
        Label for reports, e.g. ``"F13"``.
    table : Table or None
        The force's size against the input: the force is ``table(q)`` times
        the unit vector of ``force`` (whose length then does not matter).
    sense : str
        One of :data:`SENSES`.
    """

    link: int
    point: str
    force: tuple[float, float]
    active: Active | None = None
    name: str = ""
    table: Table | None = None
    sense: str = "fixed"

    def __post_init__(self):
        what = f"force on link {self.link} at {self.point}"
        object.__setattr__(self, "force", point(self.force, what, "force"))
        if self.table is not None:
            if self.force == (0.0, 0.0):
                raise ModelError(f"{what}: a tabulated force needs a direction, got a zero vector")
            check_array(self.table.value, "force", f"{what}: table")
        _sense(self.sense, what)

    @property
    def varies(self) -> bool:
        """True if the force changes with the position (a table, or a sense that follows the motion)."""
        return self.table is not None or self.sense != "fixed"


@dataclass(frozen=True)
class SpringForce(PointForce):
    """The pull of a linear spring on one of its ends: a point force that follows the spring's length.

    The spring runs from ``point`` of ``link`` (the end this force acts on) to ``anchor_point`` of
    ``anchor_link`` (its other end, the frame or a moving link). With L the distance between the ends and L0
    the free length, the force on this end is k (L − L0) along the spring towards the other end (where the ends
    meet, L = 0, a spring with L0 > 0 has no line: its force is nan, and the position is not valid): a stretched
    spring (L > L0) pulls the ends together, a compressed one pushes them apart. The other end, if it is a
    moving link, carries its own :class:`SpringForce`, equal and opposite. Build both with :func:`spring`.

    Parameters
    ----------
    link, point : int, str
        This end.
    force : (float, float)
        Not used: (0, 0). The force is worked out at each position.
    anchor_link, anchor_point : int, str
        The other end.
    rate : float
        Spring rate k [N/m], ≥ 0.
    free_length : float
        Free length L0 [m], ≥ 0.
    """

    anchor_link: int = 1
    anchor_point: str = ""
    rate: float = 0.0
    free_length: float = 0.0

    def __post_init__(self):
        super().__post_init__()
        what = f"spring from link {self.link} at {self.point} to link {self.anchor_link} at {self.anchor_point}"
        if self.table is not None or self.sense != "fixed":
            raise ModelError(f"{what}: a spring's force follows its length; it takes no table and no sense")
        object.__setattr__(self, "rate", check(finite(self.rate, f"{what}: rate", "N/m"), "stiffness", f"{what}: rate"))
        object.__setattr__(self, "free_length", check(finite(self.free_length, f"{what}: free length", "m"),
                                                      "length0", f"{what}: free length"))

    @property
    def varies(self) -> bool:
        """Always: the force follows the spring's length."""
        return True


@dataclass(frozen=True)
class StrokeForce(PointForce):
    """A force on a piston that follows its displacement from a dead centre: an indicator diagram as books print it.

    The piston's point is at ``dead_centre`` at the dead centre the stroke is measured from, and moves along
    ``away`` (a unit vector) into the stroke, of length ``length``. At a displacement s the force is ``out(s)``
    along the unit vector of ``force`` while the piston moves away from that dead centre (the out stroke), and
    ``back(s)`` while it returns (``back`` None: the same table both ways). At a standstill (a dead centre) the
    stroke that begins there is taken: the out stroke at s = 0, the return at s = ``length``.

    Parameters
    ----------
    link, point, force, active, name
        As :class:`PointForce`; ``force`` gives only the direction (its length does not matter).
    dead_centre : (float, float)
        The point's position at the dead centre the stroke is measured from [m].
    away : (float, float)
        Unit vector along the guide from that dead centre into the stroke.
    length : float
        The stroke [m] (the distance between the dead centres).
    out, back : Table, Table or None
        The force [N] against the displacement [m] (non-periodic tables covering 0 to ``length``).
    """

    dead_centre: tuple[float, float] = (0.0, 0.0)
    away: tuple[float, float] = (1.0, 0.0)
    length: float = 0.0
    out: Table | None = None
    back: Table | None = None

    def __post_init__(self):
        super().__post_init__()
        what = f"force on link {self.link} at {self.point}"
        if self.table is not None or self.sense != "fixed" or self.out is None:
            raise ModelError(f"{what}: a force against the stroke takes its values from its out (and back) tables")
        if self.force == (0.0, 0.0):
            raise ModelError(f"{what}: a force against the stroke needs a direction, got a zero vector")
        for t in (self.out, self.back):
            if t is not None:
                check_array(t.value, "force", f"{what}: table")

    @property
    def varies(self) -> bool:
        """Always: the force follows the piston's displacement."""
        return True


def spring(links, points, rate: float, free_length: float, *, frame: int = 1, name: str = "",
           active: Active | None = None) -> list[SpringForce]:
    """A linear spring between two points, as the forces it puts on its moving ends.

    Parameters
    ----------
    links : (int, int)
        The links the spring's ends are fixed to (one may be the frame).
    points : (str, str)
        The point of each link it is fixed to.
    rate : float
        Spring rate k [N/m].
    free_length : float
        Free length L0 [m].
    frame : int
        The frame's number: no force is put on the frame.
    name : str
        Shown in reports (with the end's point).
    active : Active or None
        Where the spring acts; None for always.

    Returns
    -------
    list of SpringForce
        One per moving end.
    """
    (a, b), (pa, pb) = tuple(links), tuple(points)
    label = name or f"spring {pa}{pb}"
    return [SpringForce(link, p, (0.0, 0.0), active, label, anchor_link=other, anchor_point=q, rate=rate,
                        free_length=free_length)
            for link, p, other, q in ((a, pa, b, pb), (b, pb, a, pa)) if link != frame]


@dataclass(frozen=True)
class Torque:
    """A couple T [N·m] on a link, CCW positive."""

    link: int
    torque: float
    active: Active | None = None
    name: str = ""
    table: Table | None = None
    """The torque against the input (then ``torque`` is 1.0 and ignored)."""
    sense: str = "fixed"

    def __post_init__(self):
        what = f"torque on link {self.link}"
        object.__setattr__(self, "torque", check(finite(self.torque, what, "N·m"), "torque", what))
        if self.table is not None:
            check_array(self.table.value, "torque", f"{what}: table")
        _sense(self.sense, what)

    @property
    def varies(self) -> bool:
        """True if the torque changes with the position (a table, or a sense that follows the motion)."""
        return self.table is not None or self.sense != "fixed"


Load = PointForce | Torque
"""An external load (a :class:`SpringForce` is a :class:`PointForce`)."""


def standard_gravity(g: float) -> float:
    """Validate a gravitational acceleration g [m/s²] (acts along −y)."""
    g = check(finite(g, "gravity", "m/s²"), "acceleration", "gravity")
    if g < 0:
        raise ModelError(f"gravity must be ≥ 0 m/s² (it acts along −y), got {g:g}")
    return g
