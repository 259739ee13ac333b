"""Mass properties of links built from simple shapes.

A real link is rarely a uniform rod. Norton (*Design of Machinery*, ch. 11,
"practical considerations") models it as simple solids -- hollow cylinders
(bosses) at the pivots and a rectangular prism between them -- computes the
mass, centre of mass G and moment of inertia I_G of each, and combines them
with the parallel-axis theorem. This module does exactly that, and can also
take the exact outline of a plate link as a shapely polygon.

Everything is SI: metres, kilograms, kg m^2. The mechanism is planar, so the
only moment of inertia that matters is about the axis normal to the plane;
``I_G`` is that moment about the centre of mass G.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import LineString, MultiPoint, MultiPolygon, Point, Polygon
from shapely.geometry.polygon import orient
from shapely.validation import explain_validity

from graphkin.errors import ModelError
from graphkin.ranges import finite

__all__ = [
    "MassProperties",
    "combine",
    "thin_rod",
    "rectangular_plate",
    "disk",
    "hollow_cylinder",
    "from_shape",
    "link_outline",
]


_EPS = float(np.finfo(float).eps)


# --- input checks: one-line messages that name the argument at fault --------


def _number(name: str, value, unit: str) -> float:
    return finite(value, name, unit)


def _positive(name: str, value, unit: str) -> float:
    x = _number(name, value, unit)
    if x <= 0.0:
        raise ModelError(f"{name} must be positive [{unit}], got {x!r}")
    return x


def _non_negative(name: str, value, unit: str) -> float:
    x = _number(name, value, unit)
    if x < 0.0:
        raise ModelError(f"{name} must not be negative [{unit}], got {x!r}")
    return x


def _point(name: str, value) -> tuple[float, float]:
    try:
        x, y = value
    except (TypeError, ValueError):
        raise ModelError(f"{name} must be a point (x, y) [m], got {value!r}") from None
    return (_number(f"{name}[0]", x, "m"), _number(f"{name}[1]", y, "m"))


# --- the mass properties of one rigid part -----------------------------------


@dataclass(frozen=True)
class MassProperties:
    """Planar mass properties of a rigid part.

    Parameters
    ----------
    m : float
        Mass [kg]; 0 for a massless part.
    G : tuple of float
        Centre of mass (x, y) in the link's frame [m].
    I_G : float
        Moment of inertia about the axis through G normal to the plane
        [kg m^2].

    Notes
    -----
    Parts add with ``+`` (and holes are removed with ``-``) by the
    parallel-axis theorem, :math:`I_O = I_G + m d^2`.
    """

    m: float
    G: tuple[float, float]
    I_G: float

    def __post_init__(self):
        # Store plain floats so that equality and repr behave predictably.
        object.__setattr__(self, "m", _non_negative("m", self.m, "kg"))
        object.__setattr__(self, "G", _point("G", self.G))
        object.__setattr__(self, "I_G", _non_negative("I_G", self.I_G, "kg m^2"))

    @property
    def k(self) -> float:
        """Radius of gyration :math:`k = \\sqrt{I_G/m}` [m]; 0 when m == 0."""
        return math.sqrt(self.I_G / self.m) if self.m > 0.0 else 0.0

    def moved(self, dx: float, dy: float) -> MassProperties:
        """The same part translated by (dx, dy) [m]; I_G does not change.

        Parameters
        ----------
        dx, dy : float
            Translation [m].

        Returns
        -------
        MassProperties
        """
        dx, dy = _number("dx", dx, "m"), _number("dy", dy, "m")
        return MassProperties(self.m, (self.G[0] + dx, self.G[1] + dy), self.I_G)

    def about(self, point) -> float:
        """Moment of inertia about an axis through ``point`` normal to the plane.

        Parallel-axis theorem: :math:`I_P = I_G + m\\,|P - G|^2`.

        Parameters
        ----------
        point : tuple of float
            (x, y) [m].

        Returns
        -------
        float
            I_P [kg m^2].
        """
        px, py = _point("point", point)
        d2 = (px - self.G[0]) ** 2 + (py - self.G[1]) ** 2
        return self.I_G + self.m * d2

    def __add__(self, other: MassProperties) -> MassProperties:
        if not isinstance(other, MassProperties):
            return NotImplemented
        return combine((self, other))

    def __sub__(self, other: MassProperties) -> MassProperties:
        """Remove a part (a hole, a lightening pocket) that lies inside this one."""
        if not isinstance(other, MassProperties):
            return NotImplemented
        m = self.m - other.m
        # Relative tolerance: removing a part from itself must give exactly
        # "nothing left", not a tiny negative mass from rounding.
        m_tol = 1e-12 * self.m
        if m < -m_tol:
            raise ModelError(
                f"other: removing {other.m!r} kg from a part of {self.m!r} kg leaves negative mass"
            )
        if m <= m_tol:
            return MassProperties(0.0, self.G, 0.0)
        # Work relative to self.G to keep the numbers small (less cancellation).
        ux, uy = other.G[0] - self.G[0], other.G[1] - self.G[1]
        Gx, Gy = -other.m * ux / m, -other.m * uy / m  # new G, relative to self.G
        # I about self.G of what remains = I of the whole - I of the removed part.
        I_0 = self.I_G - (other.I_G + other.m * (ux * ux + uy * uy))
        I_G = I_0 - m * (Gx * Gx + Gy * Gy)
        if I_G < 0.0:
            # Allow for rounding: G is known to about eps*|G|, and removing most
            # of the mass magnifies that error by self.m/m.
            delta = 16 * _EPS * (math.hypot(*self.G) + math.hypot(*other.G)) * self.m / m
            I_tol = 1e-9 * (self.I_G + other.about(self.G))
            I_tol += m * delta * (2 * math.hypot(Gx, Gy) + delta)
            if I_G < -I_tol:
                raise ModelError(
                    "other: removing it leaves a negative moment of inertia; "
                    "it is not a part of this body"
                )
            I_G = 0.0  # rounding only
        return MassProperties(m, (self.G[0] + Gx, self.G[1] + Gy), I_G)


def combine(parts: Iterable[MassProperties]) -> MassProperties:
    """Combine parts into one rigid body (parallel-axis theorem).

    .. math::

        m = \\sum m_i, \\quad G = \\frac{\\sum m_i G_i}{m}, \\quad
        I_G = \\sum \\left( I_{G_i} + m_i |G_i - G|^2 \\right)

    Parameters
    ----------
    parts : iterable of MassProperties
        At least one part; massless parts are allowed.

    Returns
    -------
    MassProperties
        When every part is massless, G is the plain mean of the parts' G
        (so the result does not depend on their order) and I_G is the sum of
        their I_G.
    """
    parts = list(parts)
    if not parts:
        raise ModelError("parts must hold at least one MassProperties, got none")
    for i, p in enumerate(parts):
        if not isinstance(p, MassProperties):
            raise ModelError(f"parts[{i}] must be a MassProperties, got {type(p).__name__}")
    m_i = np.array([p.m for p in parts])
    G_i = np.array([p.G for p in parts])
    I_i = np.array([p.I_G for p in parts])
    m = float(m_i.sum())
    w = m_i / m if m > 0.0 else np.full(len(parts), 1.0 / len(parts))
    G = w @ G_i
    d2 = ((G_i - G) ** 2).sum(axis=1)
    I_G = float((I_i + m_i * d2).sum())
    return MassProperties(m, (float(G[0]), float(G[1])), I_G)


# --- textbook primitives ----------------------------------------------------


def thin_rod(length, mass, *, start=(0.0, 0.0), angle=0.0) -> MassProperties:
    """A slender uniform rod, :math:`I_G = m L^2 / 12`.

    Parameters
    ----------
    length : float
        L [m], > 0.
    mass : float
        m [kg], >= 0 (0 gives a massless link).
    start : tuple of float
        The end the rod starts from [m].
    angle : float
        Direction of the rod from ``start`` [rad], counter-clockwise from x.

    Returns
    -------
    MassProperties
        G is at the middle of the rod.
    """
    L = _positive("length", length, "m")
    m = _non_negative("mass", mass, "kg")
    x0, y0 = _point("start", start)
    theta = _number("angle", angle, "rad")
    G = (x0 + 0.5 * L * math.cos(theta), y0 + 0.5 * L * math.sin(theta))
    return MassProperties(m, G, m * L * L / 12.0)


def rectangular_plate(length, width, thickness, density, *, center=(0.0, 0.0), angle=0.0):
    """A rectangular plate (prism), :math:`I_G = m (L^2 + w^2) / 12`.

    Parameters
    ----------
    length, width : float
        Sides L and w in the plane [m], > 0.
    thickness : float
        Out-of-plane thickness t [m], > 0.
    density : float
        rho [kg/m^3], > 0.
    center : tuple of float
        Centre of the rectangle = G [m].
    angle : float
        Direction of the length side [rad]. It is checked but does not change
        the result: the polar moment about G is invariant under rotation.

    Returns
    -------
    MassProperties
        m = rho L w t.
    """
    L = _positive("length", length, "m")
    w = _positive("width", width, "m")
    t = _positive("thickness", thickness, "m")
    rho = _positive("density", density, "kg/m^3")
    G = _point("center", center)
    _number("angle", angle, "rad")
    m = rho * L * w * t
    return MassProperties(m, G, m * (L * L + w * w) / 12.0)


def disk(radius, thickness, density, *, center=(0.0, 0.0)) -> MassProperties:
    """A solid disk in the plane, :math:`I_G = m r^2 / 2`.

    Parameters
    ----------
    radius : float
        r [m], > 0.
    thickness : float
        t [m], > 0.
    density : float
        rho [kg/m^3], > 0.
    center : tuple of float
        Centre = G [m].

    Returns
    -------
    MassProperties
        m = rho pi r^2 t.
    """
    r = _positive("radius", radius, "m")
    t = _positive("thickness", thickness, "m")
    rho = _positive("density", density, "kg/m^3")
    G = _point("center", center)
    m = rho * math.pi * r * r * t
    return MassProperties(m, G, 0.5 * m * r * r)


def hollow_cylinder(r_inner, r_outer, length, density, *, center=(0.0, 0.0)):
    """A hollow cylinder (a boss around a pin), axis normal to the plane.

    :math:`I_G = m (r_i^2 + r_o^2) / 2`.

    Parameters
    ----------
    r_inner : float
        Bore radius r_i [m], 0 <= r_i < r_o (0 gives a solid cylinder).
    r_outer : float
        Outside radius r_o [m], > 0.
    length : float
        Axial length h [m] (the boss's thickness out of the plane), > 0.
    density : float
        rho [kg/m^3], > 0.
    center : tuple of float
        Axis position = G [m].

    Returns
    -------
    MassProperties
        m = rho pi (r_o^2 - r_i^2) h.
    """
    ri = _non_negative("r_inner", r_inner, "m")
    ro = _positive("r_outer", r_outer, "m")
    if ri >= ro:
        raise ModelError(f"r_inner must be smaller than r_outer ({ro!r} m), got {ri!r}")
    h = _positive("length", length, "m")
    rho = _positive("density", density, "kg/m^3")
    G = _point("center", center)
    m = rho * math.pi * (ro * ro - ri * ri) * h
    return MassProperties(m, G, 0.5 * m * (ri * ri + ro * ro))


# --- exact polygons ---------------------------------------------------------


def _ring_moments(xy: np.ndarray) -> tuple[float, float, float]:
    """First and polar second moments of one closed ring, by Green's theorem.

    With :math:`c_i = x_i y_{i+1} - x_{i+1} y_i` over the edges,

    .. math::

        Q_y = \\int x\\,dA = \\tfrac16 \\sum (x_i + x_{i+1}) c_i, \\quad
        Q_x = \\int y\\,dA = \\tfrac16 \\sum (y_i + y_{i+1}) c_i,

        J_O = \\int (x^2 + y^2)\\,dA
            = \\tfrac1{12} \\sum (x_i^2 + x_i x_{i+1} + x_{i+1}^2
                               + y_i^2 + y_i y_{i+1} + y_{i+1}^2)\\, c_i.

    Signed: positive for a counter-clockwise ring, negative for clockwise, so
    holes (clockwise after ``orient``) subtract themselves.
    """
    x0, y0 = xy[:-1, 0], xy[:-1, 1]
    x1, y1 = xy[1:, 0], xy[1:, 1]
    c = x0 * y1 - x1 * y0
    Q_y = ((x0 + x1) * c).sum() / 6.0
    Q_x = ((y0 + y1) * c).sum() / 6.0
    J_O = ((x0 * x0 + x0 * x1 + x1 * x1 + y0 * y0 + y0 * y1 + y1 * y1) * c).sum() / 12.0
    return float(Q_y), float(Q_x), float(J_O)


def from_shape(shape, thickness, density) -> MassProperties:
    """Mass properties of a plate cut to an exact outline.

    Parameters
    ----------
    shape : shapely.Polygon or shapely.MultiPolygon
        The outline in the link's frame [m]; holes (pin bores, lightening
        holes) allowed. Curves are whatever polygon shapely holds, so a
        ``Point.buffer`` circle is its inscribed polygon.
    thickness : float
        t [m], > 0.
    density : float
        rho [kg/m^3], > 0.

    Returns
    -------
    MassProperties
        m = rho t A and I_G = rho t J_G, with A and G from shapely and the
        polar second moment of area J_G = I_xx + I_yy about G computed
        exactly for the polygon.
    """
    if not isinstance(shape, (Polygon, MultiPolygon)):
        kind = type(shape).__name__
        raise ModelError(f"shape must be a shapely Polygon or MultiPolygon, got {kind}")
    if shape.is_empty:
        raise ModelError("shape is empty")
    if not shape.is_valid:
        raise ModelError(f"shape is not valid: {explain_validity(shape)}")
    A = shape.area
    if not A > 0.0:
        raise ModelError("shape has zero area")
    t = _positive("thickness", thickness, "m")
    rho = _positive("density", density, "kg/m^3")

    G = shape.centroid
    ref = np.array([G.x, G.y])
    Q_y = Q_x = J = 0.0
    polygons = shape.geoms if isinstance(shape, MultiPolygon) else (shape,)
    for polygon in polygons:
        # Exterior counter-clockwise, holes clockwise: each ring then carries
        # its own sign and the sum over rings is the net plate.
        polygon = orient(polygon, sign=1.0)
        for ring in (polygon.exterior, *polygon.interiors):
            # Coordinates relative to G keep the sums small (less cancellation).
            xy = np.asarray(ring.coords)[:, :2] - ref
            q_y, q_x, j = _ring_moments(xy)
            Q_y, Q_x, J = Q_y + q_y, Q_x + q_x, J + j
    # shapely's centroid is G to rounding; the parallel-axis step removes even
    # that, so J is exactly about the centroid of these vertices.
    J_G = J - (Q_x * Q_x + Q_y * Q_y) / A
    m = rho * t * A
    return MassProperties(m, (G.x, G.y), rho * t * max(J_G, 0.0))


def link_outline(centers, width, hole_diameter=0.0, *, quad_segs=16) -> Polygon:
    """A textbook "dog-bone" link outline with pin holes.

    Parameters
    ----------
    centers : sequence of (x, y)
        Pivot centres [m], two or more, all distinct.
    width : float
        Width of the bar w [m], > 0; the ends are rounded with radius w/2.
    hole_diameter : float
        Diameter of the pin hole at every centre [m], 0 <= d < w
        (0: no holes).
    quad_segs : int
        Segments per quarter circle for the rounded ends and holes.

    Returns
    -------
    shapely.Polygon
        Two centres: a bar with rounded ends. Three centres: their convex
        hull (a triangular ternary plate) with rounded edges. Four or more:
        the polygonal chain through the centres in order.
    """
    try:
        P = np.asarray(centers, dtype=float)
    except (TypeError, ValueError):
        raise ModelError(f"centers must be a sequence of (x, y) points [m], got {centers!r}") \
            from None
    if P.ndim != 2 or P.shape[1] != 2 or P.shape[0] < 2:
        raise ModelError(f"centers must hold at least two (x, y) points [m], got {centers!r}")
    if not np.isfinite(P).all():
        raise ModelError("centers must be finite [m]")
    w = _positive("width", width, "m")
    d = _non_negative("hole_diameter", hole_diameter, "m")
    if d >= w:
        # A hole as wide as the bar would cut the link in two.
        raise ModelError(f"hole_diameter must be smaller than width ({w!r} m), got {d!r}")
    if isinstance(quad_segs, bool) or not isinstance(quad_segs, (int, np.integer)) or quad_segs < 1:
        raise ModelError(f"quad_segs must be an integer >= 1, got {quad_segs!r}")
    n = len(P)
    for i in range(n):
        for j in range(i + 1, n):
            if np.array_equal(P[i], P[j]):
                raise ModelError(f"centers[{i}] and centers[{j}] coincide at {tuple(P[i])}")

    if n == 3:
        # Ternary link: the plate spanning all three pivots (a line if collinear).
        skeleton = MultiPoint(P).convex_hull
    else:
        skeleton = LineString(P)
    outline = skeleton.buffer(w / 2.0, quad_segs=int(quad_segs))
    if d > 0.0:
        holes = shapely.union_all([Point(p).buffer(d / 2.0, quad_segs=int(quad_segs)) for p in P])
        outline = outline.difference(holes)
    if not isinstance(outline, Polygon) or not outline.is_valid:
        raise ModelError("centers give an outline that is not one valid polygon")
    return outline

