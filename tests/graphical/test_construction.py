"""The graphical route: the seed's construction, agreement with the analytical route, degenerate cases."""

import math

import numpy as np
import pytest

from graphkin import catalog
from graphkin.analytical import solve
from graphkin.geometry import cross
from graphkin.graphical import construct_forces
from graphkin.graphical.construction import Arrow, Step, nice_scale
from graphkin.model import Driver, Link, Mechanism, PointForce, Prismatic, Revolute
from graphkin.notation import polar


def agree(c, r, i=0, rel=1e-9):
    """Every joint force and the driver of construction c equal analytical r at position i."""
    scale = max(np.abs(r.force(*k)[i]).max() for k in r.forces)
    for key in r.forces:
        np.testing.assert_allclose(c.force(*key), r.force(*key)[i], rtol=0, atol=rel * scale)
    for key in r.normal:
        np.testing.assert_allclose(c.couple[key], r.couple[key][i], rtol=0, atol=rel * scale * 10)
    assert c.effort == pytest.approx(r.effort[i], rel=rel, abs=rel * scale)


class TestSoylemezDoubleSlider:
    """Söylemez, Mechanisms, §6.4, double-slider example, graphical method (seed 000)."""

    @pytest.fixture(scope="class")
    @classmethod
    def c(cls):
        return construct_forces(catalog.load("double_slider").kinematics(), 0)

    def test_resultant_and_h(self, c):
        first = c.steps[0]
        assert first.kind == "resultant" and first.link == 3
        assert first.values["h"] * 1e3 == pytest.approx(33.31, rel=2e-3)
        (line,) = first.lines
        assert line.name == "R3i"
        # The offset line reproduces the torque's sense: moment of R3i about G3 equals T3i.
        G = np.array(c.G[3])
        F = np.array(first.values["F3i"])
        assert cross(np.array(line.point) - G, F) == pytest.approx(first.values["T3i"], rel=1e-12)

    def test_link_4_is_a_two_force_member(self, c):
        step = next(s for s in c.steps if s.kind == "two-force")
        assert step.link == 4 and "two-force member" in step.caption and "F43" in step.caption

    def test_concurrency_point_lies_on_the_three_lines(self, c):
        step = next(s for s in c.steps if s.kind == "three-force")
        I = np.array(step.points["I3"])
        R3i = c.steps[0].lines[0]
        assert abs(cross(I - np.array(R3i.point), np.array(R3i.direction))) < 1e-12
        B, A = np.array(c.points[4]["B"]), np.array(c.points[3]["A"])
        assert I[1] == pytest.approx(B[1], abs=1e-12)  # on F43's line: horizontal through B
        assert abs(cross(I - A, c.force(2, 3))) < 1e-12 * np.linalg.norm(c.force(2, 3))  # F23 through A and I3

    def test_polygon_closes_with_the_books_numbers(self, c):
        step = next(s for s in c.steps if s.kind == "polygon" and s.link == 3)
        assert step.closure() < 1e-12
        assert [a.name for a in step.polygon] == ["R3i", "F43", "F23"]
        assert polar(step.values["F43"]) == pytest.approx((7.555, 180.0), rel=2e-3)
        assert polar(step.values["F23"]) == pytest.approx((27.04, -73.78), rel=2e-3)

    def test_book_relations_and_driver(self, c):
        # "G12 = −R3i and F12 = −F43"
        np.testing.assert_allclose(c.force(1, 2), -np.array(c.inertia[3]["F"]), atol=1e-12)
        assert c.effort == pytest.approx(-c.force(4, 3)[0], rel=1e-12)
        assert polar(c.force(1, 2)) == pytest.approx((25.97, -90.0), rel=2e-3)

    def test_force_scale_is_round(self, c):
        assert c.force_scale == nice_scale(27.06) == 0.5


@pytest.mark.parametrize("name", catalog.names())
def test_graphical_equals_analytical_at_every_catalog_position(name):
    problem = catalog.load(name)
    r = problem.solve()
    for i in range(r.n):
        c = construct_forces(r.kinematics, i)
        assert c.valid and not c.warnings
        agree(c, r, i)
        for step in c.steps:
            assert step.closure() < 1e-9


def massless_double_slider(load_point, force):
    links = [Link(1, {"O": (0, 0)}), Link(2, {"A": (0, 0)}), Link(3, {"A": (0, 0), "B": (0.5, 0), "M": (0.25, 0)}),
             Link(4, {"B": (0, 0)})]
    joints = [Prismatic(1, 2, "A", "O", 0.0), Revolute((2, 3), "A"), Revolute((3, 4), "B"),
              Prismatic(1, 4, "B", "O", math.pi / 2)]
    return Mechanism(links, joints, Driver(2, "slider"), [PointForce(3, load_point, force, name="P")])


def test_parallel_lines_meet_at_infinity_and_the_polygon_still_closes():
    # A horizontal load on link 3 is parallel to F43 (horizontal through B).
    r = solve(massless_double_slider("M", (10.0, 0.0)), 0.2, 2.0, 0.0)
    c = construct_forces(r.kinematics, 0)
    step = next(s for s in c.steps if s.kind == "three-force")
    assert "infinity" in step.caption and "I3" not in step.points
    assert all(s.closure() < 1e-12 for s in c.steps)
    agree(c, r)


def test_lines_already_concurrent():
    # A load through A, the outer pin of link 3: F43 must vanish.
    r = solve(massless_double_slider("A", (3.0, 4.0)), 0.2, 2.0, 0.0)
    c = construct_forces(r.kinematics, 0)
    step = next(s for s in c.steps if s.kind == "three-force")
    assert "already passes through A" in step.caption
    assert np.allclose(c.force(4, 3), 0.0, atol=1e-12)
    agree(c, r)


def test_link_with_zero_resultant_gets_no_construction():
    mech = massless_double_slider("M", (0.0, 0.0))
    r = solve(mech, 0.2, 2.0, 0.0)
    c = construct_forces(r.kinematics, 0)
    assert not any(s.kind == "three-force" for s in c.steps)
    assert all(np.allclose(F, 0.0) for F in c.forces.values()) and c.effort == 0.0


def test_dead_point_is_reported_not_crashed():
    problem = catalog.load("double_slider")
    c = construct_forces(problem.kinematics(at=[0.5]), 0)
    assert not c.valid and "dead point" in c.reason


def test_closure_check_flags_an_open_polygon():
    open_polygon = Step("polygon", "test", polygon=(Arrow("a", (1.0, 0.0), True), Arrow("b", (0.0, 1.0), False)))
    closed = Step("polygon", "test", polygon=(Arrow("a", (1.0, 0.0), True), Arrow("b", (-1.0, 0.0), False)))
    assert open_polygon.closure() == pytest.approx(math.sqrt(2))
    assert closed.closure() == 0.0


def test_construction_values_answer_both_orders():
    c = construct_forces(catalog.load("double_slider").kinematics(), 0)
    v = c.values()
    assert v["F32"] == tuple(-x for x in v["F23"]) and "G14" in v and "G41" in v
    assert v["F12"] == pytest.approx((c.effort, 0.0)) and c["F12"] == pytest.approx([c.effort, 0.0])
    np.testing.assert_allclose(c["F23"], -c["F32"])


def test_a_gear_loaded_by_a_couple_alone_is_no_three_force_member():
    """Gearset (seed 001): the pinion carries only the input torque, so tooth and pivot forces are a couple."""
    c = construct_forces(catalog.load("gearset").kinematics())
    couple = [s for s in c.steps if s.link == 3 and "couple" in s.caption and s.kind == "couple"]
    assert [s.kind for s in c.steps if s.link == 3][:3] == ["resultant", "line", "couple"]  # pressure line, then the couple
    assert couple and "three-force" not in {s.kind for s in c.steps if s.link == 3}
    F_mesh, F_pivot = c.force(2, 3), c.force(1, 3)
    np.testing.assert_allclose(F_pivot, -F_mesh, atol=1e-9 * np.hypot(*F_mesh))
    polygon = [s for s in c.steps if s.link == 3 and s.kind == "polygon"][0]
    assert len(polygon.polygon) == 2 and all(np.hypot(*a.vector) > 0 for a in polygon.polygon)  # no zero-length R3
