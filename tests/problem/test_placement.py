"""``driver.place`` at and near the dead centres, and beyond a link's reach (issue 35).

A slider-crank driven by its piston (crank r = 51 mm, rod l = 200 mm, the guide along x at a height e above the
crank's pivot), placed by the crank's angle: every angle the crank reaches is placed, its dead centres included,
at the positions the closed form gives on the file's branch; the rod, whose lean is bounded, is refused beyond its
reach with the angles it does reach. Before the fix the crank was refused within about 6.5° of a dead centre.
"""

from __future__ import annotations

import math

import pytest

from graphkin.errors import ProblemFileError
from graphkin.problem import parse_problem

R, L = 0.051, 0.200  # m

TEXT = """title = "Slider-crank driven by its piston, placed by an angle"
analysis = "static"
[frame]
points = {{ O = ["0 mm", "0 mm"], E = ["0 mm", "{e} mm"] }}
[[links]]
number = 2
points = {{ O = ["0 mm", "0 mm"], C = ["51 mm", "0 mm"] }}
[[links]]
number = 3
points = {{ C = ["0 mm", "0 mm"], P = ["200 mm", "0 mm"] }}
[[links]]
number = 4
points = {{ P = ["0 mm", "0 mm"] }}
[[joints]]
type = "revolute"
links = [1, 2]
point = "O"
[[joints]]
type = "revolute"
links = [2, 3]
point = "C"
[[joints]]
type = "revolute"
links = [3, 4]
point = "P"
[[joints]]
type = "prismatic"
guide = 1
slider = 4
point = "P"
through = "E"
direction = "0 deg"
[driver]
type = "slider"
link = 4
place = {{ link = {link}, theta = "{theta!r} deg" }}
[assembly]
C = {branch}
"""


def dead_centres(e):
    """The crank's angle [rad] at the four dead centres, by hand: the crank and the rod in line, the piston's pin
    l + r (outer) or l − r (inner) from the pivot, on the guide's right (x > 0) or left."""
    outer, inner = math.asin(e / (L + R)), math.asin(e / (L - R))
    return {"right outer": outer, "right inner": math.pi + inner, "left outer": math.pi - outer, "left inner": -inner}


def by_hand(theta, e, branch):
    """The piston's positions x [m] with the crank at θ, on the file's branch: |P − C| = l with P = (x, e), C on
    the crank. Branch +1 puts C left of the line from P to the pivot O (docs/problem-files.md, [assembly]); at a
    dead centre C is on that line, on both branches."""
    cx, cy = R * math.cos(theta), R * math.sin(theta)
    out = []
    for sign in (1, -1):
        x = cx + sign * math.sqrt(L**2 - (e - cy) ** 2)
        left = (0 - x) * (cy - e) - (0 - e) * (cx - x)  # (O − P) × (C − P)
        if abs(left) <= 1e-9 * R * L or math.copysign(1, left) == branch:
            out.append(x)
    return sorted(out)


def solve_at(e, branch, link, theta_deg):
    """The problem placed at ``theta_deg``, or the error it raises."""
    try:
        return parse_problem(TEXT.format(e=e, branch=branch, link=link, theta=theta_deg), file="placed.toml")
    except ProblemFileError as exc:
        return exc


def crank_cases():
    for e in (0.0, 20.0):
        for branch in (1, -1):
            for where, theta in dead_centres(e / 1e3).items():
                for off in (0.0, 0.01, -0.01, 1.0, -1.0):
                    yield pytest.param(e, branch, math.degrees(theta), off, id=f"e{e:g}-branch{branch:+d}-{where}{off:+g}deg")


@pytest.mark.parametrize("e, branch, dead_centre, off", list(crank_cases()))
def test_the_crank_is_placed_wherever_it_stands(e, branch, dead_centre, off):
    theta = math.radians(dead_centre + off)
    expected = by_hand(theta, e / 1e3, branch)
    found = solve_at(e, branch, 2, dead_centre + off)
    if not expected:
        # Beyond the dead centre on the file's branch (the offset guide leaves the crank an arc it never reaches
        # there): refused, with the arc it does reach (this dead centre one of its ends) and where the other
        # branch has it.
        assert isinstance(found, ProblemFileError)
        message = str(found)
        assert "never stands at" in message and "there it stands from" in message, message
        end = math.remainder(dead_centre, 360.0)
        assert f"{end:.6g}°" in message or f"{end + 360:.6g}°" in message, message
        other = by_hand(theta, e / 1e3, -branch)
        assert other and f"other branch at C (s = {', '.join(f'{x * 1e3:.6g} mm' for x in other)})" in message
        return
    if len(expected) > 1:
        # One angle, two places on the guide (a dead centre on one side is an angle the other side reaches too):
        # both are named, to give the book's as s.
        assert isinstance(found, ProblemFileError) and "more than one slider position" in str(found)
        assert f"({', '.join(f's = {x * 1e3:.6g} mm' for x in expected)})" in str(found)
        return
    assert not isinstance(found, ProblemFileError), found
    # s(θ) is well-conditioned, even where θ(s) is not (near a dead centre θ changes as √s): s to the last digits.
    assert found.q[0] == pytest.approx(expected[0], rel=1e-12)
    if off == 0.0:
        # The piston drives the crank through no dead centre: the position stands, and says it is a dead point.
        kin = found.kinematics()
        assert not kin.valid[0] and "dead point" in kin.reason(0)


def test_the_rod_at_its_greatest_lean():
    """The rod (e = 0, branch +1) leans most, asin(r/l), with the crank at −90°: the piston at √(l² − r²)."""
    found = solve_at(0.0, 1, 3, math.degrees(math.asin(R / L)))
    assert found.q[0] == pytest.approx(math.sqrt(L**2 - R**2), rel=1e-6)  # θ(s) is flat there: s to √ε
    near = solve_at(0.0, 1, 3, math.degrees(math.asin(R / L)) - 0.01)
    assert isinstance(near, ProblemFileError) and "more than one slider position" in str(near)


@pytest.mark.parametrize("beyond", [0.01, 1.0])
def test_the_rod_beyond_its_reach_is_refused_with_the_angles_it_reaches(beyond):
    lean = math.degrees(math.asin(R / L))
    found = solve_at(0.0, 1, 3, lean + beyond)
    assert isinstance(found, ProblemFileError)
    message = str(found)
    assert "driver.place.theta" in message and "never stands at" in message
    # Branch +1: on the right of the pivot the crank is below the guide, the rod leans from 0 up to asin(r/l);
    # on the left the crank is above it, the rod points back, from 180° to 180° + asin(r/l).
    assert f"from 0° to {lean:.6g}° for s = {(L - R) * 1e3:.6g} mm to {(L + R) * 1e3:.6g} mm" in message
    assert f"from 180° to {180 + lean:.6g}° for s = -{(L + R) * 1e3:.6g} mm to -{(L - R) * 1e3:.6g} mm" in message
