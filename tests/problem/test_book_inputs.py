"""Loads and inputs as books give them (issue 25): a pressure on a piston, a power at a speed, a crank angle from a
dead centre with its sense of rotation, a slider placed by another link's angle.

Each is checked against the arithmetic a student would do by hand, written out here without graphkin, and
through the whole solve where the meaning is in the result (both routes).
"""

from __future__ import annotations

import math
from importlib.resources import files

import numpy as np
import pytest

from graphkin.kinematics import solve_kinematics
from graphkin.problem import parse_problem
from graphkin.report import constructions, cross_check

ENGINE = (files("graphkin.catalog") / "engine_double_acting_khurmi.toml").read_text(encoding="utf-8")
GEARSET = (files("graphkin.catalog") / "gearset.toml").read_text(encoding="utf-8")


def edit(text, *pairs):
    for old, new in pairs:
        assert old in text, old
        text = text.replace(old, new, 1)
    return text


def force_of(problem):
    (load,) = [ld for ld in problem.mechanism.loads if ld.link == 4]
    return np.asarray(load.force)


# -- pressures ---------------------------------------------------------------------------------------------------

A_COVER = math.pi * 0.25**2 / 4  # m², bore 250 mm
A_CRANK = math.pi * (0.25**2 - 0.05**2) / 4  # m², round a 50 mm rod


def test_a_double_acting_pressure_is_the_cover_ends_force_less_the_crank_ends():
    F = force_of(parse_problem(ENGINE))
    np.testing.assert_allclose(F, [-(550e3 * A_COVER - 70e3 * A_CRANK), 0.0], rtol=1e-15, atol=1e-9)


def test_a_pressure_on_the_crank_end_pushes_the_piston_back_on_the_annulus_round_the_rod():
    F = force_of(parse_problem(edit(ENGINE, ('back_pressure = "70 kN/m^2"', 'side = "crank"'))))
    np.testing.assert_allclose(F, [550e3 * A_CRANK, 0.0], rtol=1e-15, atol=1e-9)
    # and without a rod the two faces are alike
    F = force_of(parse_problem(edit(ENGINE, ('rod = "50 mm"\n', ""), ('back_pressure = "70 kN/m^2"', 'side = "crank"'))))
    np.testing.assert_allclose(F, [550e3 * A_COVER, 0.0], rtol=1e-15, atol=1e-9)


def test_an_indicator_diagram_against_the_crank_angle_is_a_tabulated_force():
    text = edit(ENGINE, ('pressure = "550 kN/m^2"', 'table = """\nangle [deg], pressure [kPa]\n0, 800\n180, 100\n"""'))
    problem = parse_problem(text)
    (load,) = problem.mechanism.loads
    q = np.radians([0.0, 45.0, 90.0, 270.0])
    p = np.interp(np.degrees(q), [0, 180, 360], [800e3, 100e3, 800e3])  # the last row runs on to the first
    np.testing.assert_allclose(load.table(q), p * A_COVER - 70e3 * A_CRANK, rtol=1e-14)  # along −x, the direction
    np.testing.assert_allclose(load.force, [-1.0, 0.0], atol=1e-15)
    r = problem.solve(q)
    assert cross_check(r, constructions(r)).valid.all()


# -- a power at a speed ------------------------------------------------------------------------------------------

def test_a_power_taken_off_the_pinion_at_its_speed_is_the_torque_against_it():
    """The gear pair at constant speed (no inertia loads: each gear turns about its centre of mass): the driver's
    power equals the power taken off, T12 ω2 = P."""
    text = edit(GEARSET, ('alpha = "50 rad/s^2"', 'alpha = "0 rad/s^2"'),
                ('type = "torque"\nname = "T13"\nlink = 3\ntorque = "8 N*m"',
                 'type = "power"\nlink = 3\npower = "2 kW"\nspeed = "-300 rpm"'))
    problem = parse_problem(text)
    (load,) = problem.mechanism.loads
    omega3 = -300 * math.pi / 30
    assert load.torque == pytest.approx(-2e3 / omega3, rel=1e-15)  # CCW, against the pinion's CW rotation
    r = problem.solve()
    omega2 = 120 * math.pi / 30
    assert r.kinematics.omega[3][0] == pytest.approx(omega3, rel=1e-14)  # the speed given is the pinion's own
    assert r.effort[0] * omega2 == pytest.approx(2e3, rel=1e-12)
    driving = parse_problem(edit(text, ('speed = "-300 rpm"', 'speed = "-300 rpm"\nrole = "driving"')))
    assert driving.mechanism.loads[0].torque == pytest.approx(-load.torque, rel=1e-15)


def test_a_power_on_the_crank_takes_the_cranks_own_speed():
    text = edit(ENGINE, ('\n[forward]\n', '\n[[loads]]\ntype = "power"\nlink = 2\npower = "20 kW"\n\n[forward]\n'))
    (_, load) = parse_problem(text).mechanism.loads
    assert load.torque == pytest.approx(20e3 / (120 * math.pi / 30), rel=1e-15)  # against the clockwise crank


# -- a crank angle from a dead centre ----------------------------------------------------------------------------

def _engine(offset_mm=0.0, guide="0 deg"):
    frame = f'points = {{ O = ["0 mm", "0 mm"], E = ["0 mm", "{offset_mm} mm"] }}'
    return edit(ENGINE, ('through = "O"', 'through = "E"'), ('points = { O = ["0 mm", "0 mm"] }', frame),
                ('direction = "0 deg"\n\n[driver]', f'direction = "{guide}"\n\n[driver]'))


@pytest.mark.parametrize("offset, guide", [(0.0, "0 deg"), (50.0, "0 deg"), (-80.0, "0 deg"), (30.0, "180 deg")])
@pytest.mark.parametrize("which, reach", [("inner dead centre", 0.8), ("outer dead centre", 0.4)])
def test_a_dead_centre_is_where_crank_and_rod_lie_in_line(offset, guide, which, reach):
    """At θ = 0° from a dead centre the crank pin lies on the line from the pivot to the piston's pin, r + l (inner)
    or l − r (outer) from the pivot, for an offset engine and a guide either way."""
    text = edit(_engine(offset, guide), ('from = "inner dead centre"', f'from = "{which}"'),
                ('theta = "45 deg"', 'theta = "0 deg"'))
    problem = parse_problem(text)
    kin = problem.kinematics()
    O, C, P = (kin.position(link, name)[0] for link, name in ((2, "O"), (2, "C"), (4, "P")))
    assert np.hypot(*(P - O)) == pytest.approx(reach, rel=1e-12)
    u, w = (C - O) / np.hypot(*(C - O)), (P - O) / np.hypot(*(P - O))
    assert u @ w == pytest.approx(1.0 if which.startswith("inner") else -1.0, abs=1e-12)
    # 45° on in the sense of rotation (clockwise) turns the crank by −45°.
    later = parse_problem(edit(text, ('theta = "0 deg"', 'theta = "45 deg"')))
    assert later.q[0] == pytest.approx(problem.q[0] - math.pi / 4, abs=1e-12)


def test_the_inner_dead_centre_is_the_pistons_farthest_point():
    problem = parse_problem(edit(_engine(50.0), ('theta = "45 deg"', 'theta = "0 deg"')))
    q = problem.q[0] + np.radians(np.linspace(-3, 3, 61))
    kin = solve_kinematics(problem.mechanism, q, 1.0, 0.0)
    x = np.hypot(*(kin.position(4, "P") - kin.position(2, "O")).T)
    assert np.argmax(x) == 30


def test_a_clockwise_crank_turns_at_a_negative_omega():
    p = parse_problem(edit(ENGINE, ('omega = "120 rpm"', 'omega = "120 rpm"\nalpha = "2 rad/s^2"')))
    assert (p.q_dot[0], p.q_ddot[0]) == (pytest.approx(-4 * math.pi), -2.0)
    ccw = parse_problem(edit(ENGINE, ('sense = "clockwise"', 'sense = "counter-clockwise"')))
    assert ccw.q_dot[0] == pytest.approx(4 * math.pi) and ccw.q[0] == pytest.approx(math.pi / 4)


# -- a slider placed by a link's angle ---------------------------------------------------------------------------

@pytest.mark.parametrize("theta2, branch", [(60.0, -1), (60.0, 1), (145.0, -1), (-30.0, 1)])
def test_a_slider_placed_by_the_cranks_angle_puts_the_crank_there(theta2, branch):
    from tests.bad_input.test_issue25_fields import SLIDER_PLACED

    text = edit(SLIDER_PLACED, ('theta = "60 deg"', f'theta = "{theta2} deg"'), ("C = -1", f"C = {branch}"))
    problem = parse_problem(text)
    kin = problem.kinematics()
    assert math.remainder(kin.theta[2][0] - math.radians(theta2), 2 * math.pi) == pytest.approx(0.0, abs=1e-12)
    # by hand: the piston's pin on the x-axis, l from the crank pin
    r, l = 0.051, 0.200
    c, s = math.cos(math.radians(theta2)), math.sin(math.radians(theta2))
    roots = [r * c + sign * math.sqrt(l**2 - (r * s) ** 2) for sign in (1, -1)]
    assert min(abs(problem.q[0] - x) for x in roots) <= 1e-12


def test_a_placement_only_on_the_other_branch_says_which_branch_has_it(capsys, tmp_path):
    """The rod of this slider-crank (branch C = −1) never stands at 10°; on branch C = 1 it does, at two slider
    positions: the message names the branch and the positions instead of 'never'."""
    from graphkin.cli import main
    from tests.bad_input.test_catalogue import one_error_line
    from tests.bad_input.test_issue25_fields import SLIDER_PLACED

    f = tmp_path / "p.toml"
    f.write_text(edit(SLIDER_PLACED, ("link = 2, theta", "link = 3, theta"), ('theta = "60 deg"', 'theta = "10 deg"')),
                 encoding="utf-8")
    assert main(["solve", str(f)]) == 2
    one_error_line(capsys.readouterr().err, "driver.place.theta", "other branch at C", "[assembly] C = 1",
                   "159.614 mm", "234.309 mm")
