"""A uniform link held by a spring: Hibbeler & Gupta, *Engineering Mechanics: Statics and Dynamics*, Ex. 11.5,
p. 433 (FOSSEE Python and Scilab companions; catalog ``spring_link_hibbeler``).

Printed: θ = 53.8° for equilibrium (stable, d²V/dθ² = 46.9 at 53.8°; θ = 0° unstable, −29.4). The book's method is
the potential energy V(θ) = ½ k l² (1 − cos θ)² − (W l / 2)(2 − cos θ) with W = 98.1 N, k = 200 N/m, l = 0.6 m;
dV/dθ = 0 gives cos θ = 1 − W / (2 k l), θ = 53.7542°.

graphkin works it as a static force analysis instead: the slider A is placed at each angle and its force F12 is
the effort that holds the link there; virtual work makes F12 = dV/dx_A = V'(θ) / (l cos θ), zero at the equilibrium.
The deviation: none but the print's rounding to 0.1° (graphkin's root equals the closed form to 1e-9).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin import catalog
from graphkin.report import constructions, cross_check

W, K, L = 10 * 9.81, 200.0, 0.6
PRINTED = {"theta_deg": 53.8, "V2_at_53_8": 46.9, "V2_at_0": -29.4}


def dV(theta):
    """The book's dV/dθ [J/rad]."""
    return K * L**2 * (1 - math.cos(theta)) * math.sin(theta) - W * L / 2 * math.sin(theta)


def d2V(theta):
    """The book's d²V/dθ² [J/rad²] (the Scilab companion's expression)."""
    return K * L**2 * (math.cos(theta) - math.cos(2 * theta)) - W * L / 2 * math.cos(theta)


def theta_book():
    return math.acos(1 - W / (2 * K * L))


def bisect(f, a, b, tol=1e-14):
    """The root of f between a and b (f changes sign there)."""
    fa = f(a)
    while b - a > tol:
        m = (a + b) / 2
        fm = f(m)
        if (fm > 0) == (fa > 0):
            a, fa = m, fm
        else:
            b = m
    return (a + b) / 2


def effort(problem, theta):
    """graphkin's F12 [N] with the link at θ from the vertical (slider A at x = l sin θ)."""
    return float(problem.solve(at=[L * math.sin(theta)]).effort[0])


def test_the_book_method_gives_every_printed_digit():
    assert round(math.degrees(theta_book()), 1) == PRINTED["theta_deg"]
    assert round(d2V(math.radians(53.8)), 1) == PRINTED["V2_at_53_8"]
    assert round(d2V(0.0), 1) == PRINTED["V2_at_0"]


def test_the_file_is_at_the_printed_angle():
    r = catalog.load("spring_link_hibbeler").solve()
    assert r.kinematics.q[0] == pytest.approx(L * math.sin(math.radians(53.8)), rel=1e-12)
    assert math.degrees(r.kinematics.theta[3][0]) == pytest.approx(90 + 53.8, rel=1e-12)
    assert cross_check(r, constructions(r)).valid.all()


def test_the_holding_force_is_the_derivative_of_the_potential():
    p = catalog.load("spring_link_hibbeler")
    for deg in (10.0, 30.0, 45.0, 53.8, 60.0, 75.0):
        th = math.radians(deg)
        assert effort(p, th) == pytest.approx(dV(th) / (L * math.cos(th)), rel=1e-9, abs=1e-12), deg


def test_graphkin_holds_the_link_unaided_at_the_book_angle_and_it_is_stable():
    p = catalog.load("spring_link_hibbeler")
    root = bisect(lambda th: effort(p, th), math.radians(40), math.radians(70))
    assert root == pytest.approx(theta_book(), rel=1e-9)
    assert round(math.degrees(root), 1) == PRINTED["theta_deg"]
    # Stable: pushing A out needs more force past the root, the slope being V''/(l cos θ) there.
    h = 1e-6
    slope = (effort(p, root + h) - effort(p, root - h)) / (2 * h)
    assert slope * L * math.cos(root) == pytest.approx(d2V(root), rel=1e-6)
    assert d2V(root) > 0 > d2V(0.0)
    # At θ = 0 the link is also in equilibrium (unstable): no force holds it.
    assert abs(effort(p, 1e-9)) < 1e-6


def test_both_routes_agree_over_a_sweep():
    p = catalog.load("spring_link_hibbeler")
    r = p.solve(at=L * np.sin(np.radians(np.linspace(5, 85, 9))))
    assert cross_check(r, constructions(r)).valid.all()
