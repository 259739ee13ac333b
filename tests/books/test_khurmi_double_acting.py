"""Khurmi & Gupta, *Theory of Machines*, 14th ed., Example 15.12 (p. 538): a horizontal double-acting steam engine
with a piston rod; the turning moment, the thrust on the bearings and the flywheel's acceleration (catalog problem
``engine_double_acting_khurmi``), written as the book gives it: pressures on both faces, θ from the inner dead
centre, a clockwise crank, 20 kW taken off a flywheel (issue 25).

Data (the statement as quoted on askfilo.com): 120 rpm, bore 250 mm, stroke 400 mm (r = 200 mm), connecting rod
0.6 m (n = 3), reciprocating parts 60 kg, θ = 45° from the I.D.C., 550 kN/m² on the cover end and 70 kN/m² on the
crank end, piston rod 50 mm; 20 kW, flywheel 60 kg with k = 0.6 m. The book's answers as quoted: 3920 N·m,
11.96 kN, 107.8 rad/s². The FOSSEE Python Textbook Companion (Khurmi ch15, Example 15.12), which types the book's
method out, prints 3929.026139 N·m, 11.98 kN and 108.2 rad/s².

The book's method: F_L = p1 A − p2 (A − a), F_I = m ω² r (cos θ + cos 2θ / n) (a two-term series for the piston's
acceleration), F_P = F_L − F_I, sin φ = sin θ / n, F_Q = F_P / cos φ, F_T = F_Q sin(θ + φ), T = F_T r,
F_B = F_Q cos(θ + φ), T_R = P / ω, α = (T − T_R) / (m k²).

Deviations, each explained, none a tolerance chosen to pass:
- graphkin against the book's method with the exact piston acceleration (written out below without graphkin):
  1e-9 relative, both routes.
- The companion's printed digits are the book's method to the last digit (tested: 3929.026139 N·m to 1e-9 N·m).
  graphkin differs from them only by the series: the tolerance against each companion value is the difference
  between the series chain and the exact chain (computed here) plus half a unit of the printed last digit.
- The book's 3920 N·m lies 0.23 % below its own method's 3929.03 N·m (rounded intermediates; the page itself was
  not available). Its 107.8 rad/s² is (3920 − 1591.5)/21.6 to the printed digit, so it follows from the 3920
  (tested), and its 11.96 kN lies 0.13 % below the method's 11.98 kN. These are asserted as what they are: the
  printed values' distance from the method, not graphkin's.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin import catalog
from graphkin.report import constructions, solution

OMEGA = 120 * 2 * math.pi / 60  # rad/s
R, L, M = 0.2, 0.6, 60.0  # m, m, kg
D, d = 0.25, 0.05  # m
P1, P2 = 550e3, 70e3  # Pa
THETA = math.radians(45.0)
I_FLYWHEEL = 60.0 * 0.6**2  # kg·m²
T_R = 20e3 / OMEGA  # N·m
COMPANION = {"T": 3929.026139, "F_B": 11.98e3, "alpha": 108.2}
HALF_UNIT = {"T": 0.5e-6, "F_B": 5.0, "alpha": 0.05}
BOOK = {"T": 3920.0, "F_B": 11.96e3, "alpha": 107.8}


def chain(a_P):
    """The book's method from the piston's acceleration a_P (m/s², along the line of stroke away from the crank)."""
    A, a = math.pi * D**2 / 4, math.pi * d**2 / 4
    F_L = P1 * A - P2 * (A - a)
    F_P = F_L + M * a_P  # the inertia force −m a_P, with a_P < 0 (towards the crank) here
    phi = math.asin(math.sin(THETA) * R / L)
    F_Q = F_P / math.cos(phi)
    T = F_Q * math.sin(THETA + phi) * R
    return {"F_L": F_L, "T": T, "F_B": F_Q * math.cos(THETA + phi), "alpha": (T - T_R) / I_FLYWHEEL}


def series():
    n = L / R
    return chain(-OMEGA**2 * R * (math.cos(THETA) + math.cos(2 * THETA) / n))


def exact():
    """x = r cos θ + √(l² − r² sin² θ), differentiated twice at constant ω."""
    s, c = math.sin(THETA), math.cos(THETA)
    root = math.sqrt(L**2 - R**2 * s**2)
    x_tt = -R * c - (R**2 * (c**2 - s**2)) / root - (R**4 * s**2 * c**2) / root**3
    return chain(OMEGA**2 * x_tt)


@pytest.fixture(scope="module")
def solved():
    problem = catalog.load("engine_double_acting_khurmi")
    result = problem.solve()
    return problem, result, solution(problem, result, constructions(result))["positions"][0]


def graphkin_values(result, entry):
    """T, F_B and α as the book means them: the turning moment and α in the sense of rotation (clockwise here)."""
    C, O = result.kinematics.position(2, "C")[0], result.kinematics.position(2, "O")[0]
    along = (C - O) / np.hypot(*(C - O))
    F32 = -result.force(2, 3)[0]  # the rod's force on the crank pin
    sense = -1.0  # clockwise
    return {"T": sense * -float(result.effort[0]), "F_B": abs(float(F32 @ along)),
            "alpha": sense * entry["forward"]["alpha"]}


def test_the_book_input_conventions_place_the_crank_45_degrees_clockwise_of_the_inner_dead_centre(solved):
    problem, result, entry = solved
    assert problem.q[0] == pytest.approx(-THETA, abs=1e-15)
    assert problem.q_dot[0] == pytest.approx(-OMEGA, rel=1e-15)
    assert result.kinematics.position(4, "P")[0][0] > 0  # the piston on +x: the crank pointed at it at θ = 0
    load = problem.mechanism.loads[0]
    assert -load.force[0] == pytest.approx(exact()["F_L"], rel=1e-12)


def test_graphkin_is_the_books_method_with_the_exact_acceleration(solved):
    _, result, entry = solved
    got, want = graphkin_values(result, entry), exact()
    for key in ("T", "F_B", "alpha"):
        assert got[key] == pytest.approx(want[key], rel=1e-9), key
    g = entry["graphical"]
    assert g["valid"] and g["driver"]["value"] == pytest.approx(entry["driver"]["value"], rel=1e-9)


def test_the_companion_prints_the_books_method():
    assert series()["T"] == pytest.approx(COMPANION["T"], abs=HALF_UNIT["T"] * 2)
    for key in ("F_B", "alpha"):
        assert abs(series()[key] - COMPANION[key]) <= HALF_UNIT[key], key


def test_graphkin_against_the_printed_answers(solved):
    _, result, entry = solved
    got = graphkin_values(result, entry)
    for key, printed in COMPANION.items():
        allowed = abs(series()[key] - exact()[key]) + HALF_UNIT[key]
        assert abs(got[key] - printed) <= allowed, (key, got[key], printed, allowed)


def test_the_books_own_printed_answers_follow_from_its_3920():
    """The book's α is (3920 − T_R)/I to its printed digit; its T and F_B lie 0.23 % and 0.13 % below its method."""
    assert abs((BOOK["T"] - T_R) / I_FLYWHEEL - BOOK["alpha"]) < 0.05
    assert BOOK["T"] / series()["T"] - 1 == pytest.approx(-0.0023, abs=0.0001)
    assert BOOK["F_B"] / series()["F_B"] - 1 == pytest.approx(-0.0013, abs=0.0001)


def test_the_forward_step_is_in_the_json_and_the_report(solved):
    problem, result, entry = solved
    f = entry["forward"]
    assert f["I"] == pytest.approx(I_FLYWHEEL, rel=1e-15)
    assert f["T_driving"] == pytest.approx(-result.effort[0], rel=1e-15)
    assert f["T_resisting"] == pytest.approx(T_R, rel=1e-12)  # against the clockwise ω: CCW, positive
    assert f["alpha"] == pytest.approx((f["T_driving"] + f["T_resisting"]) / f["I"], rel=1e-15)
    from graphkin.report import format_solution

    text = format_solution(problem, result)
    assert "Forward step" in text and "α = -108.1 rad/s²" in text
