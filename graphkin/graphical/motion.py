"""The velocity and acceleration polygons as data: ordered steps, each with its caption, vectors and lines.

The polygons are drawn from a pole ``o`` (velocities) and ``o′`` (accelerations); a point P of a link has
its image ``p`` (``p′``) in the polygon, and the vector from the pole to the image is P's velocity
(acceleration). Everything here is plain numbers (SI: m/s, m/s², rad/s, rad/s²) and strings; vectors are
``(x, y)`` tuples. :func:`graphkin.graphical.construct_kinematics` builds it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import NamedTuple

from graphkin.errors import GraphkinError
from graphkin.graphical.captions import Caption


class Vector(NamedTuple):
    """One vector of a polygon, from ``tail`` to ``tip`` (both measured from the pole).

    A named tuple rather than a frozen dataclass: as immutable, and a position's polygons hold dozens, which
    a tuple makes several times faster.

    Attributes
    ----------
    name : str
        What it is, as books write it: ``"v_A"``, ``"v_BA"`` (B relative to A), ``"a^n_BA"`` (normal),
        ``"a^t_BA"`` (tangential), ``"a^c_B3B4"`` (Coriolis), ``"a_r_B3B4"`` (sliding).
    tail, tip : (float, float)
        Its ends in the polygon [m/s or m/s²].
    known : str
        ``"size and direction"`` (known before the step), ``"direction"`` (its line is known, its size is
        found by the step) or ``"found"`` (read off the polygon once it is drawn).
    step : int
        Index of the step that found it in :attr:`MotionConstruction.steps`.
    """

    name: str
    tail: tuple[float, float]
    tip: tuple[float, float]
    known: str
    step: int

    @property
    def vector(self) -> tuple[float, float]:
        """Its components [m/s or m/s²]."""
        return (self.tip[0] - self.tail[0], self.tip[1] - self.tail[1])


class PolygonLine(NamedTuple):
    """A line drawn in a polygon, on which an image point must lie (a named tuple, as :class:`Vector`).

    Attributes
    ----------
    name : str
        The vector whose size it leaves open, e.g. ``"v_BA"`` (perpendicular to AB).
    point : (float, float)
        A point of the line, in the polygon [m/s or m/s²].
    direction : (float, float)
        Unit direction.
    """

    name: str
    point: tuple[float, float]
    direction: tuple[float, float]


@dataclass(frozen=True)
class MotionStep:
    """One step of a velocity or acceleration polygon.

    Attributes
    ----------
    polygon : str
        ``"velocity"`` or ``"acceleration"``.
    kind : str
        ``"driver"`` (the input link's motion), ``"dyad"`` (two lines meet at an image point), ``"gear"``
        (the pitch point is common to both gears), ``"image"`` (the image of a link: its other points and
        G) or ``"note"``.
    caption : str
        What a student does in this step, in words.
    links : tuple of int
        The links the step is about.
    vectors : tuple of Vector
        The vectors it draws.
    lines : tuple of PolygonLine
        The lines it intersects (empty where nothing is intersected).
    points : dict of str to (float, float)
        Image points it adds, e.g. ``"b"`` or ``"g3"`` [m/s or m/s²].
    values : dict of str to float
        Values read off: ``"omega3"`` [rad/s], ``"alpha3"`` [rad/s²], sizes of vectors.
    """

    polygon: str
    kind: str
    caption: str = Caption()  # may be written when first read (graphical.captions.Later)
    links: tuple[int, ...] = ()
    vectors: tuple[Vector, ...] = ()
    lines: tuple[PolygonLine, ...] = ()
    points: dict = field(default_factory=dict)
    values: dict = field(default_factory=dict)

    def __init__(self, polygon: str, kind: str, caption: str, links: tuple[int, ...] = (),
                 vectors: tuple[Vector, ...] = (), lines: tuple[PolygonLine, ...] = (), points: dict | None = None,
                 values: dict | None = None):
        d = self.__dict__
        d["polygon"], d["kind"], d["caption"], d["links"], d["vectors"], d["lines"] = (polygon, kind, caption, links,
                                                                                        vectors, lines)
        d["points"], d["values"] = {} if points is None else points, {} if values is None else values

    def __getstate__(self):
        # A caption not yet written is written before the step is copied or pickled.
        return {**self.__dict__, "caption": self.caption}


@dataclass(frozen=True)
class MotionConstruction:
    """The velocity and acceleration polygons of one position, and what they give.

    Attributes
    ----------
    mechanism : Mechanism
    index : int
        Position index in the kinematics it was built from.
    q : float
        The input coordinate there (θ [rad] or s [m]).
    steps : tuple of MotionStep
        The velocity polygon's steps, then the acceleration polygon's.
    omega, alpha : dict of int to float
        Angular velocity [rad/s] and acceleration [rad/s²] of every link (the frame's are 0), CCW positive.
    velocity, acceleration : dict of (int, str) to (float, float)
        Every named point of every moving link, keyed ``(link, name)`` [m/s, m/s²].
    v_G, a_G : dict of int to (float, float)
        Each moving link's centre of mass [m/s, m/s²].
    images : dict of str to dict of str to (float, float)
        ``"velocity"`` and ``"acceleration"``: each image point of the polygon by name (``"o"``, ``"a"``,
        ``"b3"``, ``"g3"``) [m/s, m/s²].
    velocity_scale, acceleration_scale : float
        Round drawing scales [m/s per mm, m/s² per mm].
    valid : bool
    reason : str
        Why there are no polygons, when not valid.
    disagreement : bool
        True where the polygons are not valid because a value they yield disagrees with the analytical route
        (:mod:`graphkin.graphical.guard`): a fault in graphkin's arithmetic, to be reported, not a position the
        linkage cannot take (the ``reason`` names the quantity and both values).
    """

    mechanism: object
    index: int
    q: float
    steps: tuple[MotionStep, ...] = ()
    omega: dict = field(default_factory=dict)
    alpha: dict = field(default_factory=dict)
    velocity: dict = field(default_factory=dict)
    acceleration: dict = field(default_factory=dict)
    v_G: dict = field(default_factory=dict)
    a_G: dict = field(default_factory=dict)
    images: dict = field(default_factory=dict)
    velocity_scale: float = 1.0
    acceleration_scale: float = 1.0
    valid: bool = True
    reason: str = ""
    disagreement: bool = False

    def vectors(self, polygon: str) -> list[Vector]:
        """Every vector of the ``"velocity"`` or ``"acceleration"`` polygon, in the order drawn."""
        if polygon not in ("velocity", "acceleration"):
            raise GraphkinError(f"polygon must be 'velocity' or 'acceleration', got {polygon!r}")
        return [v for s in self.steps if s.polygon == polygon for v in s.vectors]

    def v(self, link: int, point: str) -> tuple[float, float]:
        """Velocity of a named point of a link [m/s], as read off the velocity polygon."""
        return _lookup(self.velocity, link, point, "velocity")

    def a(self, link: int, point: str) -> tuple[float, float]:
        """Acceleration of a named point of a link [m/s²], as read off the acceleration polygon."""
        return _lookup(self.acceleration, link, point, "acceleration")


def _lookup(table: dict, link: int, point: str, what: str):
    try:
        return table[(link, point)]
    except KeyError:
        raise GraphkinError(f"the {what} polygon has no point {point} of link {link}") from None

