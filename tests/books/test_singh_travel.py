"""V. P. Singh, *Theory of Machines*, Example 13.3: an engine placed by its piston's travel from the inner dead
centre (``driver.travel``).

The statement and the book's answers as a course sheet quotes them (scribd.com/document/468809524, item [3],
"S-13.3 V.P. Singh"): "In a reciprocating engine, length of stroke is 30 cm and connecting rod is 60 cm long between
centres. When the piston has travelled 8 cm from the inner centre, find (i) angular position of the crank,
(ii) velocity and acceleration of the piston, (iii) angular velocity of the connecting rod, if the engine speed is
240 rpm." Answers: 56.4°, 3.57 m/s, 43.25 (m/s², printed "rad/s²"), 3.55 rad/s.

The book solves with the approximate displacement of the piston, x = r [(1 − cos θ) + sin²θ / (2n)] (n = l/r), which
gives 56.4°, and works the rest at that angle with the approximate formulas v = ω r (sin θ + sin 2θ / (2n)) and
a = ω² r (cos θ + cos 2θ / n). graphkin places the crank exactly: x = r (1 − cos θ) + l − √(l² − r² sin²θ) =
80 mm at θ = 56.34°. The tests check that exact angle by hand, that the book's approximation gives the book's
56.4°, that the two differ by what the approximation leaves out, and the book's rates at its own angle.
"""

from __future__ import annotations

import math

import pytest

from graphkin.problem import parse_problem

R, L, N, X = 0.150, 0.600, 240.0, 0.080  # crank (half the 30 cm stroke), rod, rpm, travel [m]
THETA, V, A, OMEGA_ROD = 56.4, 3.57, 43.25, 3.55  # printed: deg, m/s, m/s², rad/s

ENGINE = f"""title = "V. P. Singh, Ex. 13.3: the crank angle when the piston has travelled 8 cm"
[frame]
points = {{ O = ["0 mm", "0 mm"] }}
[[links]]
number = 2
points = {{ O = ["0 mm", "0 mm"], C = ["{R * 1e3} mm", "0 mm"] }}
mass = "0 kg"
[[links]]
number = 3
points = {{ C = ["0 mm", "0 mm"], P = ["{L * 1e3} mm", "0 mm"] }}
mass = "0 kg"
[[links]]
number = 4
points = {{ P = ["0 mm", "0 mm"] }}
mass = "0 kg"
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
through = "O"
direction = "0 deg"
[driver]
type = "crank"
link = 2
travel = "8 cm"
from = "inner dead centre"
omega = "{N} rpm"
"""

N_RATIO = L / R


def exact_x(theta):
    return R * (1 - math.cos(theta)) + L - math.sqrt(L**2 - (R * math.sin(theta)) ** 2)


def approximate_x(theta):
    return R * ((1 - math.cos(theta)) + math.sin(theta) ** 2 / (2 * N_RATIO))


def bisect(f, lo, hi):
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi)


@pytest.fixture(scope="module")
def problem():
    return parse_problem(ENGINE)


def test_the_crank_stands_where_the_piston_has_travelled_8_cm(problem):
    theta = float(problem.q[0])  # the inner dead centre is at 0° here: the crank points at the piston (+x)
    assert 0 < theta < math.pi  # on the out stroke, as the book takes it
    assert exact_x(theta) == pytest.approx(X, abs=1e-15)
    kin = problem.kinematics()
    assert (R + L) - kin.position(4, "P")[0][0] == pytest.approx(X, abs=1e-15)


def test_the_books_approximation_gives_the_books_angle_and_differs_by_what_it_leaves_out(problem):
    approx = bisect(lambda t: approximate_x(t) - X, 0.0, math.pi / 2)
    assert round(math.degrees(approx), 1) == THETA
    theta = float(problem.q[0])
    # The approximation drops r⁴ sin⁴θ / (8 l³) (and smaller terms) from the displacement; the angle moves by
    # that over dx/dθ.
    dropped = R**4 * math.sin(theta) ** 4 / (8 * L**3)
    slope = R * (math.sin(theta) + math.sin(2 * theta) / (2 * N_RATIO))
    assert math.degrees(approx - theta) == pytest.approx(math.degrees(dropped / slope), rel=0.05)


def test_the_books_answers_are_its_formulas_at_its_angle():
    """Our reading of the book: its approximate formulas at its approximate angle give every printed digit."""
    theta = bisect(lambda t: approximate_x(t) - X, 0.0, math.pi / 2)
    w = N * math.pi / 30
    v = w * R * (math.sin(theta) + math.sin(2 * theta) / (2 * N_RATIO))
    a = w**2 * R * (math.cos(theta) + math.cos(2 * theta) / N_RATIO)
    omega_rod = w * math.cos(theta) / math.sqrt(N_RATIO**2 - math.sin(theta) ** 2)
    assert (round(v, 2), round(a, 2), round(omega_rod, 2)) == (V, A, OMEGA_ROD)


def test_graphkins_rates_at_the_travel_are_the_exact_ones(problem):
    """graphkin's rates at the exact angle are the exact derivatives of x(θ) by hand: v = ω dx/dθ, a = ω² d²x/dθ²
    at constant ω, and the rod's ω3 = ω cos θ / √(n² − sin²θ). They differ from the printed ones by the book's
    approximation (3.582 against 3.57 m/s, 43.51 against 43.25 m/s², 3.560 against 3.55 rad/s)."""
    theta, w = float(problem.q[0]), N * math.pi / 30
    s, c = math.sin(theta), math.cos(theta)
    root = math.sqrt(L**2 - (R * s) ** 2)
    dx = R * s + R**2 * s * c / root
    ddx = R * c + R**2 * (c * c - s * s) / root + R**4 * (s * c) ** 2 / root**3
    kin = problem.kinematics()
    # x grows as the piston leaves the inner dead centre, towards −x here.
    assert -kin.velocity(4, "P")[0][0] == pytest.approx(w * dx, rel=1e-12)
    assert -kin.acceleration(4, "P")[0][0] == pytest.approx(w**2 * ddx, rel=1e-12)
    assert abs(kin.omega[3][0]) == pytest.approx(w * c / math.sqrt(N_RATIO**2 - s * s), rel=1e-12)
