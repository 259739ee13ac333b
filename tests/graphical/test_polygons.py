"""The velocity and acceleration polygons and the instant centres: steps, degenerate cases, bad input."""

import dataclasses
import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphkin import catalog
from graphkin.errors import GraphkinError
from graphkin.graphical import construct_kinematics, instant_centres, kinematics_from_polygons
from graphkin.kinematics import Dyad, GearGroup, decompose, solve_kinematics
from graphkin.model import Driver, GearMesh, Link, Mechanism, Prismatic, Revolute
from tests.physics import polygons_equal_analytical
from tests.strategies import Case


def _four_bar(d: float) -> Mechanism:
    """Crank 1, coupler 1, rocker 1 on a frame of length d: a non-Grashof chain with dead points."""
    return Mechanism([Link(1, {"A0": (0, 0), "B0": (d, 0)}), Link(2, {"A0": (0, 0), "A": (1, 0)}),
                      Link(3, {"A": (0, 0), "B": (1, 0)}), Link(4, {"B0": (0, 0), "B": (1, 0)})],
                     [Revolute((1, 2), "A0"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), Revolute((1, 4), "B0")],
                     Driver(2))


@pytest.fixture(scope="module")
def strip_cutter():
    return construct_kinematics(catalog.load("strip_cutter").kinematics(), 0)


def test_steps_come_velocity_first_and_every_link_is_imaged(strip_cutter):
    c = strip_cutter
    polygons = [s.polygon for s in c.steps]
    assert polygons == sorted(polygons, key=["velocity", "acceleration"].index)
    for polygon in ("velocity", "acceleration"):
        imaged = {s.links[0] for s in c.steps if s.polygon == polygon and s.kind == "image"}
        assert imaged == set(c.mechanism.moving)


def test_each_vector_is_tip_to_tail_in_its_polygon(strip_cutter):
    """A vector's ends are image points of its polygon (or the pole): the polygon is one connected figure."""
    c = strip_cutter
    for polygon in ("velocity", "acceleration"):
        images = list(c.images[polygon].values())
        for v in c.vectors(polygon):
            if v.known == "found":
                assert any(np.allclose(v.tip, p, atol=1e-12 * max(map(np.hypot, *zip(*images)))) for p in images)


def test_rrr_caption_says_what_is_known_and_perpendicular(strip_cutter):
    vel = next(s for s in strip_cutter.steps if s.polygon == "velocity" and s.kind == "dyad")
    acc = next(s for s in strip_cutter.steps if s.polygon == "acceleration" and s.kind == "dyad")
    assert "⊥" in vel.caption and "The two lines meet" in vel.caption
    assert "a^n_" in acc.caption and "a^t_" in acc.caption and "(known)" in acc.caption
    # The normal component drawn is ω² times the arm, from the point towards the pin.
    (normal,) = [v for v in acc.vectors if v.name.startswith("a^n_") and "B0" not in v.name]
    w3 = strip_cutter.omega[3]
    assert math.hypot(*normal.vector) == pytest.approx(acc.values[normal.name], rel=1e-12)
    AB = np.subtract(*[strip_cutter.mechanism.link(3).point(p) for p in ("B", "A")])
    assert math.hypot(*normal.vector) == pytest.approx(w3 ** 2 * math.hypot(*AB), rel=1e-12)


def test_a_dead_point_is_a_message_never_a_polygon():
    d = 2.5
    theta = math.acos((d * d - 3) / (2 * d))  # coupler and rocker in line: |A B0| = 2
    kin = solve_kinematics(_four_bar(d), [theta], 10.0)
    c = construct_kinematics(kin, 0)
    assert not c.valid and "dead point" in c.reason and not c.steps
    # Forced past the solver's check, the polygon itself finds its two lines parallel and says so.
    forced = construct_kinematics(dataclasses.replace(kin, valid=np.ones(1, bool)), 0)
    assert not forced.valid and "parallel" in forced.reason
    assert forced.steps[-1].kind == "note" and "parallel" in forced.steps[-1].caption


def test_unassemblable_position_gives_the_reason():
    kin = solve_kinematics(_four_bar(2.5), [math.pi], 10.0)  # |A B0| = 3.5: beyond coupler + rocker
    c = construct_kinematics(kin, 0)
    assert not c.valid and "cannot be assembled" in c.reason
    assert not instant_centres(kin, 0).valid


@pytest.mark.parametrize("bad", [3, -4, 1.0, True, "0"])
def test_bad_index_is_one_clear_line(bad):
    kin = catalog.load("double_slider").kinematics()
    for f in (construct_kinematics, instant_centres):
        with pytest.raises(GraphkinError) as e:
            f(kin, bad)
        assert "\n" not in str(e.value) and "index" in str(e.value)


def test_not_kinematics_is_one_clear_line():
    with pytest.raises(GraphkinError, match="takes the Kinematics"):
        construct_kinematics("strip_cutter")


@pytest.mark.parametrize("name", ["strip_cutter", "double_slider", "shaper_six_bar", "gearset"])
def test_kennedy_every_three_centres_lie_on_one_line(name):
    kin = catalog.load(name).kinematics()
    ic = instant_centres(kin, 0)
    assert ic.valid and not ic.missing
    size = max(abs(complex(*p)) for p in ic.centres.values())

    def hom(pair):  # a centre as a unit homogeneous point: (x, y, 1) scaled, or its direction with w = 0
        p = np.array([*np.divide(ic.centres[pair], size), 1.0]) if pair in ic.centres else np.array([*ic.at_infinity[pair], 0.0])
        return p / np.linalg.norm(p)

    links = [l.number for l in kin.mechanism.links]
    triples = 0
    for a, b, c in itertools.combinations(links, 3):
        assert abs(np.linalg.det([hom((a, b)), hom((a, c)), hom((b, c))])) <= 1e-9, (a, b, c)
        triples += 1
    assert triples > 0


def test_a_slider_centre_is_at_infinity_across_its_guide():
    kin = catalog.load("double_slider").kinematics()
    ic = instant_centres(kin, 0)
    for joint in kin.mechanism.joints:
        if hasattr(joint, "guide") and kin.mechanism.frame in joint.links:
            d = ic.at_infinity[tuple(sorted(joint.links))]
            assert abs(d[0] * math.cos(joint.direction) + d[1] * math.sin(joint.direction)) < 1e-12


def test_given_values_are_named_in_a_note():
    kin = catalog.load("double_slider").kinematics()
    given = kin.with_given({(3, "omega"): kin.omega[3] * 1.01})
    c = construct_kinematics(given, 0)
    assert c.valid and c.steps[0].kind == "note" and "omega of link 3" in c.steps[0].caption


def test_polygon_kinematics_refuse_given_values():
    kin = catalog.load("double_slider").kinematics()
    with pytest.raises(GraphkinError, match="already carry given values"):
        kinematics_from_polygons(kin.with_given({(3, "omega"): kin.omega[3]}))


def test_a_mechanism_at_rest_has_the_pole_for_every_image():
    kin = catalog.load("engine_static_khurmi").kinematics()
    assert float(kin.q_dot[0]) == 0
    c = construct_kinematics(kin, 0)
    assert c.valid
    for step in c.steps:
        if step.kind == "image" and step.polygon == "velocity":
            assert "at rest" in step.caption and all(p == (0.0, 0.0) for p in step.points.values())


def _slotted_crank(y0: float, offset: float) -> Mechanism:
    """Crank 2 with a slot along it (offset from O2), block 3 in the slot pinned at P to slider 4 on a frame
    guide at height y0: a PRP dyad, which no family of tests/strategies.py draws."""
    return Mechanism([Link(1, {"O2": (0, 0), "S": (0, y0)}), Link(2, {"O2": (0, 0), "T": (0, offset)}),
                      Link(3, {"P": (0, 0)}), Link(4, {"P": (0, 0)})],
                     [Revolute((1, 2), "O2"), Prismatic(2, 3, "P", "T", 0.0), Revolute((3, 4), "P"),
                      Prismatic(1, 4, "P", "S", 0.0)], Driver(2))


@settings(max_examples=40, deadline=None)
@given(theta=st.floats(0.35, 2.8), y0=st.floats(0.2, 2.0), offset=st.floats(-0.1, 0.1),
       w=st.floats(-50, 50).filter(lambda x: abs(x) > 0.1), al=st.floats(-500, 500))
def test_a_prp_dyad_equals_analytical(theta, y0, offset, w, al):
    mech = _slotted_crank(y0, offset)
    assert [g.type for g in decompose(mech) if isinstance(g, Dyad)] == ["PRP"]
    assert polygons_equal_analytical(Case(mech, np.array([theta]), np.array([w]), np.array([al]))) == 1


def _geared_four_bar() -> Mechanism:
    """A four-bar whose coupler 3 carries a gear (centre A) meshing with gear 5 pivoted on the crank at D: a gear
    on a moving carrier, which no family of tests/strategies.py draws."""
    return Mechanism([Link(1, {"O2": (0, 0), "O4": (1.0, 0)}), Link(2, {"O2": (0, 0), "A": (0.25, 0), "D": (0.55, 0)}),
                      Link(3, {"A": (0, 0), "B": (1.0, 0)}), Link(4, {"O4": (0, 0), "B": (0.8, 0)}),
                      Link(5, {"D": (0, 0)}, G=(0.05, 0.02))],
                     [Revolute((1, 2), "O2"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), Revolute((1, 4), "O4"),
                      Revolute((2, 5), "D"), GearMesh((3, 5), ("A", "D"), (0.1, 0.2))], Driver(2))


@pytest.mark.parametrize("theta", [0.3, 1.7, 3.5, 5.2])
def test_a_gear_on_a_moving_carrier_equals_analytical(theta):
    mech = _geared_four_bar()
    assert any(isinstance(g, GearGroup) and g.b == 2 for g in decompose(mech))
    assert polygons_equal_analytical(Case(mech, np.array([theta]), np.array([12.0]), np.array([-30.0]))) == 1


def _pinion_in_annulus() -> Mechanism:
    """A pinion (r = 40 mm) on the frame at O2 driving an annulus (r = 120 mm) pivoted at O3, 80 mm away."""
    return Mechanism([Link(1, {"O2": (0, 0), "O3": (-0.08, 0)}), Link(2, {"O2": (0, 0)}), Link(3, {"O3": (0, 0)})],
                     [Revolute((1, 2), "O2"), Revolute((1, 3), "O3"),
                      GearMesh((2, 3), ("O2", "O3"), (0.04, 0.12), internal=True)], Driver(2))


def test_an_annulus_found_from_its_pinion_turns_its_way():
    """Issue 35: a pinion at 10 rad/s drives an annulus of three times its radius at +10/3 rad/s (the same sense).

    The polygons took the pitch point on the external side (ω3 = −10 rad/s) and the instant centre I23 with it.
    """
    kin = solve_kinematics(_pinion_in_annulus(), [0.4], 10.0, 2.0)
    c = construct_kinematics(kin, 0)
    assert c.valid
    assert c.omega[3] == pytest.approx(10.0 / 3, rel=1e-12)
    assert c.alpha[3] == pytest.approx(2.0 / 3, rel=1e-12)
    assert c.images["velocity"]["p23"] == pytest.approx((0.0, 0.4), abs=1e-15)  # the pitch point at (40, 0) mm
    ic = instant_centres(kin, 0)
    assert ic.centres[(2, 3)] == pytest.approx((0.04, 0.0), abs=1e-15)
    assert polygons_equal_analytical(Case(kin.mechanism, np.array([0.4, 2.0]), np.array([10.0, -7.0]),
                                          np.array([2.0, 5.0]))) == 2
