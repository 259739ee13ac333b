"""Inputs a problem file states that graphkin also computes (issue 35, item 5): a power's speed, a pressure's
direction, given values of the crank and of a slider, a given ω, α, v_G or a_G of any link.

Each contradiction was taken as given before: the power's torque P/ω with the stated ω (a sign slip turns a driving
power into a resisting one), the pressure's force along the stated direction, the given values in place of the
driver's. Now each is refused in one line naming the field and both values (exit 2); a value rounded to the
book's digits is still accepted. The list is docs/problem-files.md, "Inputs checked against what graphkin computes".
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin import catalog
from graphkin.errors import ProblemFileError
from graphkin.kinematics import solve_kinematics
from graphkin.problem import parse_problem
from tests.bad_input.test_catalogue import edit, solve_refuses

SPUR = catalog.path("spur_pair_wentzell").read_text(encoding="utf-8")
"""The pinion at 1725 rpm drives a gear of twice its radius: 5 hp is taken off the gear at −862.5 rpm."""
GEARS = catalog.path("gearset").read_text(encoding="utf-8")
"""Gear 2 at 120 rpm speeding up at 50 rad/s² drives pinion 3, 2.5 times smaller (−300 rpm)."""
CUTTER = catalog.path("strip_cutter").read_text(encoding="utf-8")
"""A crank-rocker at 900 rpm over a whole turn."""
ENGINE = catalog.path("engine_double_acting_khurmi").read_text(encoding="utf-8")
"""A clockwise crank (120 rpm), the piston on a horizontal guide."""
DIESEL = catalog.path("diesel_vertical_khurmi").read_text(encoding="utf-8")
"""A vertical engine: the piston on a guide at 90°, the gas pressing it down (270°)."""
MAKDIN = catalog.path("slider_crank_dynamic_makdin").read_text(encoding="utf-8")
"""A crank at a constant 314 rad/s; the book's accelerations of the rod and the piston given ([given.3], [given.4])."""
DOUBLE_SLIDER = catalog.path("double_slider").read_text(encoding="utf-8")
"""Slider 2 driven at 2 m/s along x, slider 4 on a guide along y; the rod's ω3 = 4.364 rad/s (Söylemez)."""

OSCILLATING = """title = "Oscillating-cylinder engine: the piston rod slides in a cylinder pivoted at Q"
analysis = "static"
[frame]
points = { O = ["0 mm", "0 mm"], Q = ["300 mm", "0 mm"] }
[[links]]
number = 2
points = { O = ["0 mm", "0 mm"], A = ["100 mm", "0 mm"] }
[[links]]
number = 3
name = "piston and rod"
points = { A = ["0 mm", "0 mm"] }
[[links]]
number = 4
name = "cylinder"
points = { Q = ["0 mm", "0 mm"] }
[[joints]]
type = "revolute"
links = [1, 2]
point = "O"
[[joints]]
type = "revolute"
links = [2, 3]
point = "A"
[[joints]]
type = "prismatic"
guide = 4
slider = 3
point = "A"
through = "Q"
direction = "0 deg"
[[joints]]
type = "revolute"
links = [1, 4]
point = "Q"
[driver]
type = "crank"
link = 2
theta = "90 deg"
[[loads]]
type = "pressure"
link = 3
point = "A"
bore = "50 mm"
pressure = "1 MPa"
direction = "341.57 deg"
"""
"""At θ2 = 90° the crank pin A is at (0, 100) mm, so the cylinder's axis from Q runs at atan2(100, −300) = 161.565°:
the gas pushes the piston along 341.565° (towards Q's side is 161.565°)."""


def gears_with_power(speed: str) -> str:
    """The gear pair at constant speed with a power taken off the pinion (link 3) at ``speed``."""
    return edit(edit(GEARS, 'alpha = "50 rad/s^2"', 'alpha = "0 rad/s^2"'),
                '[[loads]]\ntype = "torque"\nname = "T13"\nlink = 3\ntorque = "8 N*m"',
                f'[[loads]]\ntype = "power"\nlink = 3\npower = "2 kW"\nspeed = "{speed}"')


# -- a power's speed -----------------------------------------------------------------------------------------------

def test_a_power_at_its_links_speed_with_the_sign_lost_is_refused(tmp_path, capsys):
    """Wentzell's 5 hp taken off the gear, written at +862.5 rpm: the gear turns clockwise, so T = P/ω would turn
    with it, and the power taken off would drive it."""
    solve_refuses(capsys, tmp_path, edit(SPUR, 'speed = "-862.5 rpm"', 'speed = "862.5 rpm"'),
                  "loads[0].speed", '"862.5 rpm"', "link 3 turns at -862.5 rpm (CW)", "θ = 0°")


def test_a_power_at_another_speed_than_its_links_is_refused(tmp_path, capsys):
    solve_refuses(capsys, tmp_path, gears_with_power("-250 rpm"), "loads[0].speed", '"-250 rpm"',
                  "link 3 turns at -300 rpm (CW)")


def test_a_power_on_a_clockwise_crank_at_a_positive_speed_is_refused(tmp_path, capsys):
    text = edit(ENGINE, "\n[forward]\n", '\n[[loads]]\ntype = "power"\nlink = 2\npower = "20 kW"\nspeed = "120 rpm"\n'
                "role = \"driving\"\n\n[forward]\n")
    solve_refuses(capsys, tmp_path, text, "loads[1].speed", '"120 rpm"', "link 2 turns at -120 rpm (CW)")


@pytest.mark.parametrize("speed", ["-862.5 rpm", "-862 rpm", "-863 rpm", "-90.32 rad/s", "-90.3 rad/s", "-90 rad/s",
                                   "-14.375 rev/s"])
def test_a_speed_rounded_to_the_books_digits_is_accepted(speed):
    """−862.5 rpm is −90.3208 rad/s: each of these is it, rounded to the digits written (or to 0.1 %)."""
    problem = parse_problem(edit(SPUR, 'speed = "-862.5 rpm"', f'speed = "{speed}"'))
    (load,) = problem.mechanism.loads
    omega = float(solve_kinematics(problem.mechanism, problem.q, problem.q_dot, 0.0).omega[3][0])
    assert omega == pytest.approx(-862.5 * math.pi / 30, rel=1e-12)
    assert load.torque * omega < 0  # resisting: against the gear's rotation


@pytest.mark.parametrize("speed", ["-859 rpm", "-866 rpm", "-89 rad/s", "-91 rad/s"])
def test_a_speed_beyond_its_rounding_is_refused(speed):
    with pytest.raises(ProblemFileError) as caught:
        parse_problem(edit(SPUR, 'speed = "-862.5 rpm"', f'speed = "{speed}"'))
    assert caught.value.field == "loads[0].speed" and "turns at -" in caught.value.message


def test_a_power_on_a_rocker_is_checked_at_each_of_the_files_positions():
    """The rocker's speed changes with the crank angle: a power at its speed at one position is the file's statement
    there; over a whole turn the same speed holds at few positions, and the first where it does not is named."""
    one = edit(CUTTER, 'theta = { start = "0 deg", stop = "360 deg", step = "2 deg" }', 'theta = "140 deg"')
    p = parse_problem(one)
    omega4 = float(solve_kinematics(p.mechanism, p.q, p.q_dot, p.q_ddot).omega[4][0])
    speed = f"{omega4:.4f} rad/s"
    text = edit(one, '[[loads]]\ntype = "force"', f'[[loads]]\ntype = "power"\nlink = 4\npower = "500 W"\n'
                f'speed = "{speed}"\n\n[[loads]]\ntype = "force"')
    (power,) = [ld for ld in parse_problem(text).mechanism.loads if ld.link == 4 and not hasattr(ld, "point")]
    assert power.torque == pytest.approx(-500 / omega4, rel=1e-4)
    with pytest.raises(ProblemFileError) as caught:
        parse_problem(edit(text, 'theta = "140 deg"', 'theta = { start = "0 deg", stop = "360 deg", step = "2 deg" }'))
    assert caught.value.field == "loads[0].speed"
    assert f'"{speed}" but link 4 turns at' in caught.value.message and "θ = 0°" in caught.value.message


def test_a_power_where_the_input_does_not_move_has_no_speed_to_check():
    """A static analysis without driver.omega states no motion: the power's speed is the file's only one."""
    text = edit(gears_with_power("-250 rpm"), 'omega = "120 rpm"\nalpha = "0 rad/s^2"\n', "")
    text = 'analysis = "static"\n' + text
    (load,) = parse_problem(text).mechanism.loads
    assert load.torque == pytest.approx(2e3 / (250 * math.pi / 30), rel=1e-12)


# -- a pressure's direction ----------------------------------------------------------------------------------------

def test_a_pressure_across_its_pistons_guide_is_refused(tmp_path, capsys):
    """The vertical engine's gas pressure written along −x (a horizontal engine's habit) pushed the piston across its
    guide: the guide took it all, and the crank none."""
    solve_refuses(capsys, tmp_path, edit(DIESEL, 'direction = "270 deg"', 'direction = "180 deg"'),
                  "loads[0].direction", '"180 deg"', "link 4, slides on the frame along 90°", "joints[3]",
                  '"90 deg" or "270 deg"')


def test_a_pressure_table_off_the_guide_is_refused():
    text = edit(ENGINE, 'pressure = "550 kN/m^2"', 'table = """\nangle [deg], pressure [kPa]\n0, 800\n180, 100\n"""')
    parse_problem(text)
    with pytest.raises(ProblemFileError) as caught:
        parse_problem(edit(text, 'direction = "180 deg"', 'direction = "175 deg"'))
    assert caught.value.field == "loads[0].direction" and "along 0°" in caught.value.message


@pytest.mark.parametrize("direction", ["270 deg", "90 deg", "-90 deg", "270.02 deg", "4.71239 rad"])
def test_a_pressure_along_its_guide_either_way_is_accepted(direction):
    """The sense is the book's (which end the pressure acts on); only the line is checked."""
    problem = parse_problem(edit(DIESEL, 'direction = "270 deg"', f'direction = "{direction}"'))
    (load,) = problem.mechanism.loads
    assert abs(load.force[0]) <= 1e-3 * abs(load.force[1])


def test_a_pressure_on_a_turning_cylinder_follows_the_cylinder_at_the_files_position(tmp_path, capsys):
    problem = parse_problem(OSCILLATING)
    (load,) = problem.mechanism.loads
    kin = solve_kinematics(problem.mechanism, problem.q, 0.0, 0.0)
    axis = np.angle(kin.z_guide(problem.mechanism.joints[2]))[0]
    assert math.degrees(axis) % 180 == pytest.approx(math.degrees(math.atan2(100, -300)), abs=1e-9)
    assert abs(math.sin(math.atan2(load.force[1], load.force[0]) - axis)) < 1e-3
    solve_refuses(capsys, tmp_path, edit(OSCILLATING, 'direction = "341.57 deg"', 'direction = "180 deg"'),
                  "loads[0].direction", '"180 deg"', "link 3, slides on link 4 along 161.565°", "θ = 90°")


def test_a_pressure_on_a_link_that_slides_on_nothing_is_refused(tmp_path, capsys):
    solve_refuses(capsys, tmp_path, edit(DIESEL, 'link = 4\npoint = "P"', 'link = 3\npoint = "P"'), "loads[0].link",
                  "link 3 slides on no guide")


# -- given values ----------------------------------------------------------------------------------------------------

def test_a_given_acceleration_of_a_crank_at_constant_speed_is_refused(tmp_path, capsys):
    solve_refuses(capsys, tmp_path, MAKDIN + '\n[given.2]\nalpha = "150 rad/s^2"\n', "given.2.alpha",
                  '"150 rad/s^2"', "link 2 is the crank", "constant speed")


def test_a_given_omega_of_the_crank_is_the_drivers(tmp_path, capsys):
    parse_problem(GEARS + '\n[given.2]\nomega = "12.57 rad/s"\nalpha = "50 rad/s^2"\n')  # 120 rpm, rounded
    solve_refuses(capsys, tmp_path, GEARS + '\n[given.2]\nomega = "-12.57 rad/s"\n', "given.2.omega",
                  '"-12.57 rad/s"', "ω = 12.5664 rad/s (CCW)", "driver.omega")


def test_a_clockwise_crank_given_a_positive_omega_is_refused():
    """driver.sense = "clockwise" makes ω2 negative; a given ω is CCW positive, like every ω in graphkin."""
    with pytest.raises(ProblemFileError) as caught:
        parse_problem(ENGINE + '\n[given.2]\nomega = "12.566 rad/s"\n')
    assert caught.value.field == "given.2.omega" and "-12.5664 rad/s (CW)" in caught.value.message
    parse_problem(ENGINE + '\n[given.2]\nomega = "-12.566 rad/s"\n')


@pytest.mark.parametrize("extra, field, named", [
    ('omega = "2 rad/s"', "given.4.omega", "without turning: its ω is 0"),
    ('alpha = "0.5 rad/s^2"', "given.4.alpha", "without turning: its α is 0"),
    ('theta = "0 deg"', "given.4.theta", "without turning, at 90°"),
    ('a_G = { magnitude = "5 m/s^2", angle = "0 deg" }', "given.4.a_G", "no component across it (here 5 m/s^2)"),
    ('v_G = ["0.5 m/s", "-0.873 m/s"]', "given.4.v_G", "no component across it (here 0.5 m/s)"),
])
def test_a_given_value_of_a_slider_that_turns_or_leaves_its_guide_is_refused(tmp_path, capsys, extra, field, named):
    """Slider 4 runs on the frame's guide along y: it keeps its angle (90°) and its G moves along y."""
    solve_refuses(capsys, tmp_path, DOUBLE_SLIDER + f"\n[given.4]\n{extra}\n", field, "joints[3]", named)


def test_a_given_value_of_a_slider_along_its_guide_is_accepted():
    """The piston's acceleration read off the book's polygon (−1880 m/s², graphkin's −1873.7) lies along the guide:
    a reading, taken as given."""
    problem = catalog.load("slider_crank_dynamic_makdin")
    assert problem.given[(4, "a_G")] == (-1880.0, 0.0)
    problem = parse_problem(DOUBLE_SLIDER + '\n[given.4]\ntheta = "90 deg"\nomega = "0 rad/s"\n'
                            'a_G = { magnitude = "5.2 m/s^2", angle = "270 deg" }\n')
    assert problem.given[(4, "theta")] == pytest.approx(math.pi / 2)


def test_the_slider_drivers_given_velocity_is_the_drivers(tmp_path, capsys):
    parse_problem(DOUBLE_SLIDER + '\n[given.2]\nv_G = ["2 m/s", "0 m/s"]\na_G = ["0 m/s^2", "0 m/s^2"]\n')
    solve_refuses(capsys, tmp_path, DOUBLE_SLIDER + '\n[given.2]\nv_G = ["-2 m/s", "0 m/s"]\n', "given.2.v_G",
                  "(-2, 0) m/s", 'driver.v = "2 m/s"', "(2, 0) m/s")
    solve_refuses(capsys, tmp_path, DOUBLE_SLIDER + '\n[given.2]\na_G = ["1 m/s^2", "0 m/s^2"]\n', "given.2.a_G",
                  "(1, 0) m/s^2", 'driver.a = "0 m/s^2"')


@pytest.mark.parametrize("extra, field, named", [
    ('omega = "-4.364 rad/s"', "given.3.omega", ['"-4.364 rad/s" (CW)', "ω3 = 4.36436 rad/s (CCW)"]),
    ('alpha = "-8.312 rad/s^2"', "given.3.alpha", ['"-8.312 rad/s^2" (CW)', "α3 = 8.3"]),
    ('a_G = { magnitude = "5.194 m/s^2", angle = "90 deg" }', "given.3.a_G",
     ["5.194 m/s^2 ∠ 90°", "a_G3 = 5.19566 m/s^2 ∠ -90°"]),
])
def test_a_given_value_of_another_link_with_its_sign_lost_is_refused(tmp_path, capsys, extra, field, named):
    """Söylemez's double slider: the book's ω3, α3 and a_G3 are graphkin's to four digits; with the sign lost they
    are the same size the other way."""
    solve_refuses(capsys, tmp_path, DOUBLE_SLIDER + f"\n[given.3]\n{extra}\n", field, *named, "s = 200 mm")


def test_a_given_value_of_another_link_read_off_a_drawing_is_accepted():
    """Makdin's accelerations, read off the book's polygons, lie up to 3 % from graphkin's exact ones."""
    problem = catalog.load("fourbar_dynamic_makdin")
    assert problem.given[(3, "alpha")] == 1001.3
    kin = solve_kinematics(problem.mechanism, problem.q, problem.q_dot, problem.q_ddot)
    assert 0.02 < abs(1001.3 / kin.alpha[3][0] - 1) < 0.05
