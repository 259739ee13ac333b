"""Tests for graphkin.model.mass: textbook formulas, exact polygons, composites."""

from __future__ import annotations

import math
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely import affinity
from shapely.geometry import LineString, MultiPolygon, Point, Polygon, box

from graphkin.errors import ModelError
from graphkin.model.mass import (
    MassProperties,
    combine,
    disk,
    from_shape,
    hollow_cylinder,
    link_outline,
    rectangular_plate,
    thin_rod,
)

RHO_STEEL = 7800.0  # kg/m^3
REL = 1e-12


def assert_same(a: MassProperties, b: MassProperties, rel: float = 1e-9, L: float = 1.0):
    """a == b to ``rel``; L is the problem's length scale, so that absolute
    errors in G are judged against L and those in I_G against m L^2."""
    assert a.m == pytest.approx(b.m, rel=rel, abs=rel * 1e-300)
    assert a.G[0] == pytest.approx(b.G[0], rel=rel, abs=rel * L)
    assert a.G[1] == pytest.approx(b.G[1], rel=rel, abs=rel * L)
    assert a.I_G == pytest.approx(b.I_G, rel=rel, abs=rel * (b.m * L * L + b.I_G))


# --- primitives against their textbook formulas ------------------------------


def test_thin_rod_formula():
    # m L^2 / 12 about the middle; m L^2 / 3 about an end.
    rod = thin_rod(0.3, 2.0, start=(1.0, 2.0), angle=math.pi / 2)
    assert rod.m == 2.0
    assert rod.G == pytest.approx((1.0, 2.15), abs=1e-15)
    assert rod.I_G == pytest.approx(2.0 * 0.3**2 / 12, rel=REL)
    assert rod.about((1.0, 2.0)) == pytest.approx(2.0 * 0.3**2 / 3, rel=REL)
    assert rod.k == pytest.approx(0.3 / math.sqrt(12), rel=REL)


def test_massless_rod():
    rod = thin_rod(1.0, 0.0)
    assert (rod.m, rod.I_G, rod.k) == (0.0, 0.0, 0.0)
    assert rod.G == (0.5, 0.0)


def test_rectangular_plate_formula():
    p = rectangular_plate(0.2, 0.05, 0.01, RHO_STEEL, center=(0.1, -0.3), angle=0.4)
    m = RHO_STEEL * 0.2 * 0.05 * 0.01
    assert p.m == pytest.approx(m, rel=REL)
    assert p.G == (0.1, -0.3)
    assert p.I_G == pytest.approx(m * (0.2**2 + 0.05**2) / 12, rel=REL)


def test_disk_formula():
    d = disk(0.05, 0.01, RHO_STEEL, center=(1.0, 1.0))
    m = RHO_STEEL * math.pi * 0.05**2 * 0.01
    assert d.m == pytest.approx(m, rel=REL)
    assert d.I_G == pytest.approx(m * 0.05**2 / 2, rel=REL)
    # About a point on the rim: 3/2 m r^2.
    assert d.about((1.05, 1.0)) == pytest.approx(1.5 * m * 0.05**2, rel=REL)


def test_hollow_cylinder_formula():
    c = hollow_cylinder(0.01, 0.03, 0.02, RHO_STEEL, center=(0.2, 0.0))
    m = RHO_STEEL * math.pi * (0.03**2 - 0.01**2) * 0.02
    assert c.m == pytest.approx(m, rel=REL)
    assert c.I_G == pytest.approx(m * (0.01**2 + 0.03**2) / 2, rel=REL)
    # The same thing as a solid disk minus its bore.
    bore = disk(0.01, 0.02, RHO_STEEL, center=(0.2, 0.0))
    assert_same(disk(0.03, 0.02, RHO_STEEL, center=(0.2, 0.0)) - bore, c, rel=1e-12)
    # r_inner = 0 is a solid cylinder.
    assert_same(hollow_cylinder(0.0, 0.03, 0.02, RHO_STEEL), disk(0.03, 0.02, RHO_STEEL), rel=1e-15)


# --- exact polygons ----------------------------------------------------------


@pytest.mark.parametrize("angle_deg", [0.0, 30.0, 90.0, 137.0])
def test_from_shape_box_equals_closed_form(angle_deg):
    L, w, t = 0.25, 0.04, 0.012
    shape = affinity.rotate(box(-L / 2, -w / 2, L / 2, w / 2), angle_deg, origin=(0, 0))
    shape = affinity.translate(shape, 0.3, -0.1)
    exact = rectangular_plate(L, w, t, RHO_STEEL, center=(0.3, -0.1), angle=math.radians(angle_deg))
    got = from_shape(shape, t, RHO_STEEL)
    assert got.m == pytest.approx(exact.m, rel=REL)
    assert got.G == pytest.approx(exact.G, rel=REL)
    assert got.I_G == pytest.approx(exact.I_G, rel=REL)


def test_disk_from_polygon_converges():
    """``Point.buffer(r, quad_segs=n)`` is the regular N-gon (N = 4n) inscribed in
    the circle. With theta = 2 pi / N, exactly:

        A = N r^2 sin(theta) / 2,    J_G = N r^4 sin(theta) (2 + cos(theta)) / 12,

    so J_G / (pi r^4 / 2) = 1 - theta^2/3 + O(theta^4) = 1 - pi^2/(12 n^2).
    For n = 64 that is 2.0e-4: we assert < 1e-3 (and < 1.1 * pi^2/(12 n^2) for
    every n, and that the error falls as 1/n^2).
    """
    r, t = 0.05, 0.01
    exact = disk(r, t, RHO_STEEL)
    errors = {}
    for n in (4, 8, 16, 32, 64, 128):
        got = from_shape(Point(0.0, 0.0).buffer(r, quad_segs=n), t, RHO_STEEL)
        # First: the polygon itself is integrated exactly.
        N = 4 * n
        theta = 2 * math.pi / N
        J_ngon = N * r**4 * math.sin(theta) * (2 + math.cos(theta)) / 12
        assert got.I_G == pytest.approx(RHO_STEEL * t * J_ngon, rel=1e-12)
        errors[n] = abs(got.I_G / exact.I_G - 1)
        assert errors[n] < 1.1 * math.pi**2 / (12 * n * n)
    assert errors[64] < 1e-3
    for n in (4, 8, 16, 32, 64):
        # Doubling n quarters the error.
        assert errors[2 * n] / errors[n] == pytest.approx(0.25, abs=0.01)


def test_plate_with_hole_equals_plate_minus_disk():
    t = 0.01
    plate = box(-0.1, -0.05, 0.1, 0.05)
    circle = Point(0.03, 0.01).buffer(0.02, quad_segs=32)
    holed = Polygon(plate.exterior.coords, [circle.exterior.coords])
    expected = from_shape(plate, t, RHO_STEEL) - from_shape(circle, t, RHO_STEEL)
    assert_same(from_shape(holed, t, RHO_STEEL), expected, rel=1e-9, L=0.1)
    assert_same(from_shape(plate.difference(circle), t, RHO_STEEL), expected, rel=1e-9, L=0.1)
    # And the closed forms agree up to the discretisation of the hole.
    hole = disk(0.02, t, RHO_STEEL, center=(0.03, 0.01))
    closed = rectangular_plate(0.2, 0.1, t, RHO_STEEL) - hole
    assert_same(expected, closed, rel=1e-3, L=0.1)


def test_multipolygon_is_the_sum_of_its_parts():
    a, b = box(0, 0, 1, 0.5), box(2, 1, 2.5, 3)
    got = from_shape(MultiPolygon([a, b]), 0.01, 1000.0)
    assert_same(got, from_shape(a, 0.01, 1000.0) + from_shape(b, 0.01, 1000.0), rel=1e-12, L=3.0)


def test_clockwise_polygon_gives_the_same_result():
    ccw = Polygon([(0, 0), (2, 0), (2, 1), (0, 1)])
    cw = Polygon([(0, 0), (0, 1), (2, 1), (2, 0)])
    assert_same(from_shape(cw, 1.0, 1.0), from_shape(ccw, 1.0, 1.0), rel=1e-15)


# --- link outlines -------------------------------------------------------------


def half_disk(r, t, rho, flat_center, outward):
    """Half-disk with the flat side's middle at ``flat_center``, bulging along the
    unit vector ``outward``. Its centroid is 4r/(3 pi) from the flat side and
    I about the flat side's middle is m r^2 / 2 (half of a disk)."""
    m = rho * t * math.pi * r * r / 2
    e = 4 * r / (3 * math.pi)
    G = (flat_center[0] + e * outward[0], flat_center[1] + e * outward[1])
    return MassProperties(m, G, m * r * r / 2 - m * e * e)


def test_link_outline_matches_hand_calculation():
    L, w, d, t = 0.2, 0.04, 0.016, 0.006
    outline = link_outline([(0.0, 0.0), (L, 0.0)], w, d, quad_segs=64)
    assert isinstance(outline, Polygon) and outline.is_valid
    assert len(outline.interiors) == 2
    hand = combine([
        rectangular_plate(L, w, t, RHO_STEEL, center=(L / 2, 0.0)),
        half_disk(w / 2, t, RHO_STEEL, (0.0, 0.0), (-1.0, 0.0)),
        half_disk(w / 2, t, RHO_STEEL, (L, 0.0), (1.0, 0.0)),
    ]) - disk(d / 2, t, RHO_STEEL) - disk(d / 2, t, RHO_STEEL, center=(L, 0.0))
    # Round parts are 4*64-gons: relative error of order pi^2/(12*64^2) = 2e-4 on them.
    assert_same(from_shape(outline, t, RHO_STEEL), hand, rel=1e-3, L=L)


def test_link_outline_ternary_and_chain():
    tri = [(0.0, 0.0), (0.3, 0.0), (0.1, 0.2)]
    outline = link_outline(tri, 0.04, 0.01)
    assert isinstance(outline, Polygon) and outline.is_valid
    assert len(outline.interiors) == 3
    # A plate: it covers the whole triangle between the pivots, not only its edges.
    assert outline.contains(Polygon(tri).centroid)
    chain = link_outline([(0, 0), (0.2, 0), (0.3, 0.1), (0.5, 0.1)], 0.03, 0.01)
    assert isinstance(chain, Polygon) and chain.is_valid and len(chain.interiors) == 4
    # No holes asked for, none made.
    assert len(link_outline([(0, 0), (1, 0)], 0.1).interiors) == 0


# --- combining parts (hypothesis) ---------------------------------------------

coord = st.floats(-10.0, 10.0, allow_nan=False)
mass = st.one_of(st.just(0.0), st.floats(1e-3, 100.0))
part = st.builds(
    MassProperties,
    m=mass,
    G=st.tuples(coord, coord),
    I_G=st.floats(0.0, 100.0),
)


parts_and_shuffle = st.lists(part, min_size=1, max_size=6).flatmap(
    lambda ps: st.tuples(st.just(ps), st.permutations(ps))
)


@given(parts_and_shuffle)
def test_combine_is_independent_of_order(parts_and_permutation):
    parts, shuffled = parts_and_permutation
    assert_same(combine(shuffled), combine(parts), rel=1e-9, L=10.0)
    if len(parts) >= 2:
        assert_same(parts[0] + parts[1], parts[1] + parts[0], rel=1e-12, L=10.0)


@given(st.lists(part, min_size=1, max_size=6), coord, coord)
def test_translation_moves_G_not_I_G(parts, dx, dy):
    whole = combine(parts)
    moved = combine(p.moved(dx, dy) for p in parts)
    assert moved.m == whole.m
    assert moved.G == pytest.approx((whole.G[0] + dx, whole.G[1] + dy), abs=1e-9)
    assert moved.I_G == pytest.approx(whole.I_G, rel=1e-9, abs=1e-9 * (whole.m * 400 + 1))


@given(
    L=st.floats(0.01, 10.0),
    w=st.floats(0.01, 10.0),
    a=st.floats(0.01, 0.99),
    angle=st.floats(-math.pi, math.pi),
    center=st.tuples(coord, coord),
)
def test_split_rectangle_recombines(L, w, a, angle, center):
    t, rho = 0.01, 2700.0
    u = (math.cos(angle), math.sin(angle))  # along the length

    def at(s):  # a point s along the length from the centre
        return (center[0] + s * u[0], center[1] + s * u[1])

    # Cut across the length at a*L from one end.
    left = rectangular_plate(a * L, w, t, rho, center=at(-L / 2 + a * L / 2), angle=angle)
    right = rectangular_plate((1 - a) * L, w, t, rho, center=at(a * L / 2), angle=angle)
    whole = rectangular_plate(L, w, t, rho, center=center, angle=angle)
    assert_same(left + right, whole, rel=1e-9, L=10.0 + L)


@settings(max_examples=50)
@given(L=st.floats(0.01, 10.0), w=st.floats(0.01, 10.0), a=st.floats(0.01, 0.99))
def test_split_box_from_shape_recombines(L, w, a):
    left, right = box(0, 0, a * L, w), box(a * L, 0, L, w)
    got = from_shape(left, 0.01, 1000.0) + from_shape(right, 0.01, 1000.0)
    assert_same(got, from_shape(box(0, 0, L, w), 0.01, 1000.0), rel=1e-9, L=L + w)


@given(part, st.tuples(coord, coord))
def test_parallel_axis(p, P):
    assert p.about(p.G) == p.I_G
    d2 = (P[0] - p.G[0]) ** 2 + (P[1] - p.G[1]) ** 2
    assert p.about(P) == pytest.approx(p.I_G + p.m * d2, rel=1e-12)
    # The same moment, measured after moving everything so that P is the origin.
    assert p.moved(-P[0], -P[1]).about((0.0, 0.0)) == pytest.approx(p.about(P), rel=1e-9, abs=1e-9)
    assert p.k == (math.sqrt(p.I_G / p.m) if p.m else 0.0)


@given(st.floats(0.01, 10.0), st.floats(0.0, 100.0), st.tuples(coord, coord), st.floats(-4, 4))
def test_rod_about_its_end(L, m, start, angle):
    # Textbook: I of a slender rod about one end is m L^2 / 3.
    rod = thin_rod(L, m, start=start, angle=angle)
    assert rod.about(start) == pytest.approx(m * L * L / 3, rel=1e-9, abs=1e-12)


heavy = st.builds(
    MassProperties, m=st.floats(0.1, 10.0), G=st.tuples(coord, coord), I_G=st.floats(0.0, 100.0)
)


@given(heavy, heavy)
def test_subtraction_undoes_addition(a, b):
    assert_same((a + b) - b, a, rel=1e-6, L=10.0)


def test_subtracting_a_part_from_itself_leaves_nothing():
    p = disk(0.1, 0.01, RHO_STEEL, center=(0.3, 0.2))
    assert (p - p).m == 0.0 and (p - p).I_G == 0.0


def test_all_massless_parts():
    a = MassProperties(0.0, (0.0, 0.0), 0.0)
    b = MassProperties(0.0, (2.0, 0.0), 0.0)
    assert (a + b) == (b + a) == MassProperties(0.0, (1.0, 0.0), 0.0)
    # A massless part does not move G or change I_G.
    c = disk(0.1, 0.01, RHO_STEEL, center=(0.5, 0.5))
    assert_same(c + a, c, rel=1e-15)


# --- a Norton-style composite link -----------------------------------------


def test_norton_composite_link():
    """A steel link built as Norton suggests (Norton, *Design of Machinery*,
    §11.13 practical considerations): a hollow cylinder (boss) at each pivot and
    a rectangular prism between them, combined by the parallel-axis theorem.

    Pivots A = (0, 0) and B = (0.200, 0) m; rho = 7800 kg/m^3.

    Bosses: r_i = 0.005 m, r_o = 0.015 m, axial length h = 0.020 m
        m_c = rho pi (r_o^2 - r_i^2) h = 7800 pi (2.25e-4 - 2.5e-5)(0.020)
            = 0.0312 pi                                   = 0.0980177 kg
        I_c = m_c (r_i^2 + r_o^2) / 2 = m_c (1.25e-4)    = 1.22522e-5 kg m^2

    Prism between the bosses: from x = 0.015 to 0.185, so L = 0.170 m,
    w = 0.020 m, t = 0.010 m, centre (0.100, 0)
        m_p = rho L w t = 7800 (0.170)(0.020)(0.010)     = 0.265200 kg
        I_p = m_p (L^2 + w^2) / 12 = 0.2652 (0.0293) / 12 = 6.47530e-4 kg m^2

    Link:
        m   = m_p + 2 m_c                                 = 0.461235 kg
        G   = (0.100, 0) by symmetry
        I_G = I_p + 2 (I_c + m_c d^2),  d = 0.100 m
            = 6.47530e-4 + 2 (1.22522e-5 + 9.80177e-4)   = 2.63239e-3 kg m^2
        k   = sqrt(I_G / m)                               = 0.0755464 m
        I_A = I_G + m d^2 = 2.63239e-3 + 4.61235e-3      = 7.24474e-3 kg m^2
    """
    boss_A = hollow_cylinder(0.005, 0.015, 0.020, RHO_STEEL, center=(0.0, 0.0))
    boss_B = hollow_cylinder(0.005, 0.015, 0.020, RHO_STEEL, center=(0.200, 0.0))
    prism = rectangular_plate(0.170, 0.020, 0.010, RHO_STEEL, center=(0.100, 0.0))
    link = boss_A + prism + boss_B

    # The hand calculation, as formulas: exact to rounding.
    m_c = RHO_STEEL * math.pi * (0.015**2 - 0.005**2) * 0.020
    I_c = m_c * (0.005**2 + 0.015**2) / 2
    m_p = RHO_STEEL * 0.170 * 0.020 * 0.010
    I_p = m_p * (0.170**2 + 0.020**2) / 12
    assert link.m == pytest.approx(m_p + 2 * m_c, rel=1e-12)
    assert link.I_G == pytest.approx(I_p + 2 * (I_c + m_c * 0.1**2), rel=1e-12)

    # The hand calculation, as the numbers written above (6 figures).
    assert link.m == pytest.approx(0.461235, rel=1e-5)
    assert link.G == pytest.approx((0.100, 0.0), abs=1e-12)
    assert link.I_G == pytest.approx(2.63239e-3, rel=1e-5)
    assert link.k == pytest.approx(0.0755464, rel=1e-5)
    assert link.about((0.0, 0.0)) == pytest.approx(7.24474e-3, rel=1e-5)


# --- bad input: ModelError, one line, naming the argument ---------------------

BOWTIE = Polygon([(0, 0), (1, 1), (1, 0), (0, 1)])
UNIT = MassProperties(1.0, (0.0, 0.0), 0.1)

BAD = [
    ("length", lambda: thin_rod(0.0, 1.0)),
    ("length", lambda: thin_rod(-1.0, 1.0)),
    ("mass", lambda: thin_rod(1.0, -0.1)),
    ("start", lambda: thin_rod(1.0, 1.0, start=(0.0,))),
    ("angle", lambda: thin_rod(1.0, 1.0, angle=float("nan"))),
    ("length", lambda: rectangular_plate(0.0, 1.0, 1.0, 1.0)),
    ("width", lambda: rectangular_plate(1.0, -1.0, 1.0, 1.0)),
    ("thickness", lambda: rectangular_plate(1.0, 1.0, 0.0, 1.0)),
    ("density", lambda: rectangular_plate(1.0, 1.0, 1.0, -7800.0)),
    ("center", lambda: rectangular_plate(1.0, 1.0, 1.0, 1.0, center="middle")),
    ("radius", lambda: disk(0.0, 1.0, 1.0)),
    ("thickness", lambda: disk(1.0, -1.0, 1.0)),
    ("density", lambda: disk(1.0, 1.0, 0.0)),
    ("r_inner", lambda: hollow_cylinder(0.02, 0.02, 0.01, 1.0)),
    ("r_inner", lambda: hollow_cylinder(0.03, 0.02, 0.01, 1.0)),
    ("r_inner", lambda: hollow_cylinder(-0.01, 0.02, 0.01, 1.0)),
    ("r_outer", lambda: hollow_cylinder(0.0, 0.0, 0.01, 1.0)),
    ("length", lambda: hollow_cylinder(0.01, 0.02, 0.0, 1.0)),
    ("density", lambda: hollow_cylinder(0.01, 0.02, 0.01, float("inf"))),
    ("shape", lambda: from_shape(Polygon(), 0.01, 1.0)),
    ("shape", lambda: from_shape(BOWTIE, 0.01, 1.0)),
    ("shape", lambda: from_shape(LineString([(0, 0), (1, 0)]), 0.01, 1.0)),
    ("shape", lambda: from_shape([(0, 0), (1, 0), (1, 1)], 0.01, 1.0)),
    ("thickness", lambda: from_shape(box(0, 0, 1, 1), 0.0, 1.0)),
    ("density", lambda: from_shape(box(0, 0, 1, 1), 1.0, -1.0)),
    ("centers", lambda: link_outline([(0.0, 0.0)], 0.1)),
    ("centers", lambda: link_outline([(0.0, 0.0), (0.0, 0.0)], 0.1)),
    ("centers", lambda: link_outline("AB", 0.1)),
    ("width", lambda: link_outline([(0, 0), (1, 0)], 0.0)),
    ("hole_diameter", lambda: link_outline([(0, 0), (1, 0)], 0.1, -0.01)),
    ("hole_diameter", lambda: link_outline([(0, 0), (1, 0)], 0.1, 0.1)),
    ("quad_segs", lambda: link_outline([(0, 0), (1, 0)], 0.1, quad_segs=0)),
    ("m", lambda: MassProperties(-1.0, (0.0, 0.0), 0.0)),
    ("G", lambda: MassProperties(1.0, (0.0, 0.0, 0.0), 0.0)),
    ("I_G", lambda: MassProperties(1.0, (0.0, 0.0), -0.1)),
    ("dx", lambda: UNIT.moved(float("nan"), 0.0)),
    ("point", lambda: UNIT.about(None)),
    ("other", lambda: UNIT - MassProperties(2.0, (0.0, 0.0), 0.1)),
    ("other", lambda: UNIT - MassProperties(0.5, (1.0, 0.0), 0.0)),  # not inside UNIT
    ("parts", lambda: combine([])),
    ("parts", lambda: combine([UNIT, 1.0])),
]


@pytest.mark.parametrize(("name", "call"), BAD, ids=[f"{i}-{n}" for i, (n, _) in enumerate(BAD)])
def test_bad_input_raises_model_error_naming_the_argument(name, call):
    with pytest.raises(ModelError) as info:
        call()
    message = str(info.value)
    assert "\n" not in message
    assert re.match(rf"{re.escape(name)}\b", message), message
