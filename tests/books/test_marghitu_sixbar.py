"""Example 6.1 (and 6.2, the same problem by the contour method) of a dynamics textbook's MATLAB programs — by
its notation and layout Marghitu & Dupac, *Advanced Dynamics* (the files do not name the book): the R-RTR-RRT
six-bar — crank, block on a slotted lever, link, ram — with gravity and a 500 N ram load opposing the ram's motion
(catalog problem ``shaper_six_bar``).

Source: the book's MATLAB program and the results it prints, github.com/xenakas/matlab_projects,
``dynamics/dynamics_MATLAB_programs/chapter6/E6_1.m`` (commit 363c5aa5); ``E6_2.m`` prints the same forces. The
figure with the lengths is not public; the catalog file's notes show how the printed masses and positions give
them (AB = 0.2 m, CD = 0.7 m, CE = 0.3 m from m = ρ L h d; A = origin, D = (0, −0.4) m, the ram's guide y = 0.35 m).
That reconstruction is checked here too: it must reproduce every printed position and rate.

The program prints forces to 3 decimals of a newton, positions to 1 mm (3 decimals of a metre), angles to 3
decimals of a degree and some rates to 3 significant figures. Each comparison's tolerance is half a unit of the
printed last digit: graphkin reproduces every printed digit, with both routes.

Names: the program's F_ij is the force of link i on link j with the frame 0, as graphkin's; graphkin calls the
two sliding pairs' forces G (a guide's force), so the program's F05 is G05 and its F32 is G32; its M_mot is T01.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin import catalog
from graphkin.report import constructions

HALF = 0.0005  # half a unit of the printed last digit: N, m, or degrees (all printed with 3 decimals)

PRINTED_FORCES = {  # program name → (graphkin name, printed vector [N])
    "F05": ("G05", (0.000, -124.959)),
    "F54": ("F54", (500.140, -125.037)),
    "F34": ("F34", (-500.685, 124.998)),
    "F03": ("F03", (123.647, -38.376)),
    "F12": ("F12", (-625.610, 162.864)),
    "F32": ("G32", (625.114, -163.282)),
    "F01": ("F01", (-626.106, 162.525)),
}
M_MOT = 111.518  # N·m, CCW, on the crank
PRINTED_POSITIONS = {  # (link, point) → printed position [m]
    (1, "B"): (0.141, 0.141),
    (3, "C"): (0.177, 0.277),
    (5, "E"): (-0.114, 0.350),
    (3, "D"): (0.000, -0.400),
}


@pytest.fixture(scope="module")
def solved():
    problem = catalog.load("shaper_six_bar")
    result = problem.solve()
    return problem, result, constructions(result)[0]


def test_the_file_is_the_programs_data(solved):
    problem, result, _ = solved
    m = problem.mechanism
    rho, h, d, hs, ws = 8000.0, 0.01, 0.001, 0.02, 0.05  # the program's steel strips and blocks
    bar = {1: 0.2, 3: 0.7, 4: 0.3}
    for n, L in bar.items():
        assert m.link(n).mass == pytest.approx(rho * L * h * d, rel=1e-12)
    for n in (2, 5):
        assert m.link(n).mass == pytest.approx(rho * hs * ws * d, rel=1e-12)
        assert m.link(n).I_G == pytest.approx(m.link(n).mass * (hs**2 + ws**2) / 12, rel=1e-7)
    for n in (1, 3):
        assert m.link(n).I_G == pytest.approx(m.link(n).mass * (bar[n] ** 2 + h**2) / 12, rel=1e-7)
    # The program's slip, kept so that the forces are its forces: link 4's I_C with the block's mass m2.
    assert m.link(4).I_G == pytest.approx(m.link(2).mass * (0.3**2 + h**2) / 12, rel=1e-7)
    assert round(m.link(4).I_G, 8) == 6.007e-5  # as printed
    assert m.gravity == pytest.approx(9.807)
    assert problem.q_dot[0] == pytest.approx(200 * math.pi / 30, rel=1e-12)
    k = result.kinematics
    assert np.hypot(*(k.position(3, "C")[0] - k.position(3, "D")[0])) == pytest.approx(0.7, rel=1e-12)
    assert np.hypot(*(k.position(4, "E")[0] - k.position(4, "C")[0])) == pytest.approx(0.3, rel=1e-12)


def test_positions_are_the_printed_ones(solved):
    """The reconstruction of the unpublished figure reproduces every printed position (to 1 mm) and angle."""
    _, result, _ = solved
    k = result.kinematics
    for (link, point), printed in PRINTED_POSITIONS.items():
        assert np.all(np.abs(k.position(link, point)[0] - printed) <= HALF), (link, point)
    assert abs(math.degrees(k.theta[3][0]) - 75.361) <= HALF  # φ2 = φ3: the block turns with the lever
    assert abs(math.degrees(k.theta[2][0]) - 75.361) <= HALF
    assert abs(math.degrees(k.theta[4][0]) - 165.971) <= HALF


def test_rates_are_the_printed_ones(solved):
    _, result, _ = solved
    k = result.kinematics
    printed_3sf = {"omega3": (k.w(3)[0], 6.46, 0.005), "alpha3": (k.al(3)[0], 30.4, 0.05),
                   "omega4": (k.w(4)[0], 3.93, 0.005), "alpha4": (k.al(4)[0], -82.5, 0.05)}
    for name, (value, printed, half) in printed_3sf.items():
        assert abs(value - printed) <= half, name
    assert np.all(np.abs(k.velocity(3, "C")[0] - (-4.374, 1.143)) <= HALF)
    assert np.all(np.abs(k.acceleration(3, "C")[0] - (-27.947, -22.882)) <= HALF)
    assert np.all(np.abs(k.velocity(5, "E")[0] - (-4.660, 0.0)) <= HALF)
    assert np.all(np.abs(k.acceleration(5, "E")[0] - (-17.464, 0.0)) <= HALF)
    assert np.all(np.abs(k.a_G(2)[0] - (-62.034, -62.034)) <= HALF)  # aC2 = aB


@pytest.mark.parametrize("route", ["analytical", "graphical"])
@pytest.mark.parametrize("name", sorted(PRINTED_FORCES))
def test_forces_are_the_printed_ones(solved, route, name):
    _, result, c = solved
    ours, printed = PRINTED_FORCES[name]
    force = result[ours][0] if route == "analytical" else c.force(*_links(result, ours))
    assert np.all(np.abs(force - printed) <= HALF), (name, force, printed)


@pytest.mark.parametrize("route", ["analytical", "graphical"])
def test_the_driving_moment_is_the_printed_one(solved, route):
    _, result, c = solved
    T01 = result["T01"][0] if route == "analytical" else c.effort
    assert abs(T01 - M_MOT) <= HALF


def test_the_block_carries_the_levers_force_at_B(solved):
    """The program's r_Q = (0.14142, 0.14142) m, where F32 acts: B itself (the block's couple is only −I_C α)."""
    _, result, _ = solved
    B = result.kinematics.position(1, "B")[0]
    e = result.offset(2, 3)[0]  # along the slot from B
    assert abs(e) < 1e-6
    assert np.all(np.abs(B - (0.14142, 0.14142)) <= 5e-6)


def test_the_ram_load_opposes_the_ram(solved):
    """The program's Fext = −sign(v_E) 500 N: the ram moves to −x here, so the load points to +x."""
    from graphkin.analytical import applied

    problem, result, _ = solved
    (load,) = problem.mechanism.loads
    assert load.sense == "opposes motion"
    assert result.kinematics.velocity(5, "E")[0][0] < 0
    assert applied(result.kinematics, load)[0] == pytest.approx(500.0 + 0.0j)  # Fx + i Fy [N]


def test_the_sub_problems_add_up_to_the_printed_moment(solved):
    """Graphical superposition: five sub-problems (every link carries its weight); the ram's gives nearly all."""
    _, result, c = solved
    efforts = [s.effort for s in c.subproblems]
    assert len(efforts) == 5
    assert sum(efforts) == pytest.approx(result["T01"][0], rel=1e-12)
    assert abs(sum(efforts) - M_MOT) <= HALF
    assert efforts[-1] > 0.99 * M_MOT


def _links(result, name):
    """The (i, j) of a force name such as ``G32``."""
    from graphkin.model.names import parse_force_name

    return parse_force_name(result.mechanism, name)


def test_a_polygon_of_rounding_residues_is_drawn_as_zero():
    """At φ = 90° the lever stands vertical through A and D: its own loads (weight, the pull towards D) pass
    through D, so in sub-problem III the crank carries nothing, 1e-17 N of rounding. Its polygon shows "= 0",
    not that residue blown up to a scale bar of 1e−17 N."""
    from graphkin import draw
    from graphkin.graphical import construct_forces

    problem = catalog.load("shaper_six_bar")
    c = construct_forces(problem.kinematics(at=[math.radians(90.0)]), 0)
    third = c.subproblems[2]
    assert third.link == 3 and abs(third.effort) < 1e-12
    step = next(s for s in c.steps if s.polygon and "R1‴" in [a.name for a in s.polygon])
    assert max(math.hypot(*a.vector) for a in step.polygon) < 1e-12  # rounding, not a force
    drawn = draw.draw_force_polygon(step, scale=c.force_scale)
    assert not drawn.arrows
    assert sorted(t.get_text() for t in drawn.labels.values()) == ["F₀₁‴ = 0", "R₁‴ = 0"]
