""""Makina Dinamiği" lecture notes (public repository Alphyn12/MekanizmaV2, "Machine Dynamics.pdf"), Örnek 5 and
its analytical solution Sayısal Uygulama 1: a static centric slider-crank, r = 51 mm, l = 200 mm, θ = 60°, a piston
load P = 6300 N towards the crank (catalog problem ``slider_crank_static_makdin``).

Printed, analytical: φ = 12.76°, F34 = 6459 N, F14 = 1426.7 N, T ≅ −314 628 N·mm. Graphical (1 mm = 100 N, φ and
h measured): F14 = 1450 N, F34 = F12 = 6500 N, h = 49 mm, T = 318.5 N·m clockwise.

Deviations, each explained:
- The closed form the notes print, evaluated exactly, is graphkin's T to 1e-12; the notes' "≅ −314 628 N·mm"
  lies 1.4 N·mm from it (4.5e-6; the notes mark it approximate themselves): tested against half a unit of the
  printed digit beyond that.
- F34 = 6459 N is graphkin's |F34| to half a unit; F14 = 1426.7 N is P tan φ with φ rounded to 12.76° as printed
  (graphkin's exact 1426.49 N): that chain gives the printed digit.
- The graphical answers are graphkin's within the drawing's reading: half a millimetre at 100 N/mm (50 N) for a
  force, half a millimetre for the arm h, carried through T = F h.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin import catalog
from graphkin.problem import parse_problem
from graphkin.report import constructions, cross_check

P, R, L, THETA = 6300.0, 0.051, 0.200, math.radians(60.0)


@pytest.fixture(scope="module")
def solved():
    return catalog.load("slider_crank_static_makdin").solve()


def closed_form():
    k = R / L
    return -P * R * math.sin(THETA) * (1 + k * math.cos(THETA) / math.sqrt(1 - (k * math.sin(THETA)) ** 2))


def test_the_notes_closed_form_is_graphkins_torque(solved):
    assert solved.effort[0] == pytest.approx(closed_form(), rel=1e-12)
    assert cross_check(solved, constructions(solved)).valid.all()


def test_the_printed_analytical_answers(solved):
    assert abs(closed_form() * 1e3 - (-314628.0)) <= 1.4 + 0.5  # the notes' "≅": 1.4 N·mm, plus half a unit
    phi = math.radians(12.76)  # as printed
    assert abs(P * math.tan(phi) - 1426.7) <= 0.05  # F14 from the rounded φ; the exact φ gives 1426.49 N
    assert math.hypot(*solved.force(3, 4)[0]) == pytest.approx(6459.0, abs=0.5)
    assert math.degrees(math.asin(R * math.sin(THETA) / L)) == pytest.approx(12.76, abs=0.005)


def test_the_graphical_answers_as_read_off_the_drawing(solved):
    read_F, read_h = 50.0, 0.5e-3  # N, m
    F14 = math.hypot(*solved.force(1, 4)[0])
    F12 = math.hypot(*solved.force(1, 2)[0])
    h = abs(solved.effort[0]) / F12
    assert F14 == pytest.approx(1450.0, abs=read_F)
    assert F12 == pytest.approx(6500.0, abs=read_F)
    assert h == pytest.approx(0.049, abs=read_h)
    assert -solved.effort[0] == pytest.approx(318.5, abs=read_F * 0.049 + 6500.0 * read_h)


def test_driven_by_its_piston_placed_by_the_cranks_angle():
    """The same linkage driven by the piston, placed where the crank stands at 60° (driver.place), the notes' T
    held on the crank: the piston force found is the notes' P."""
    text = catalog.path("slider_crank_static_makdin").read_text(encoding="utf-8")
    for old, new in (('type = "crank"\nlink = 2\ntheta = "60 deg"',
                      'type = "slider"\nlink = 4\nplace = { link = 2, theta = "60 deg" }'),
                     ('type = "force"\nname = "P"\nlink = 4\npoint = "C"\nforce = { magnitude = "6300 N", angle = "180 deg" }',
                      f'type = "torque"\nname = "T"\nlink = 2\ntorque = "{closed_form()!r} N*m"'),
                     # What is asked is now the piston's effort: T12 names no quantity of this problem.
                     ('asked = ["T12"]', 'asked = ["F14"]')):
        assert old in text
        text = text.replace(old, new)
    problem = parse_problem(text + '\n[assembly]\nB = -1\n')
    x = R * math.cos(THETA) + math.sqrt(L**2 - (R * math.sin(THETA)) ** 2)
    assert problem.q[0] == pytest.approx(x, rel=1e-12)
    r = problem.solve()
    assert r.effort[0] == pytest.approx(-P, rel=1e-12)  # along the guide (+x): P towards the crank


# -- Örnek 9: the same slider-crank, dynamic, with the book's accelerations (catalog slider_crank_dynamic_makdin) ----

PRINTED_9 = {"F34": (4589.2, -900.5), "F14": (0.0, 900.5), "F23": (1391.8, -5301.5), "F12": (1391.8, -5301.5)}


def test_oernek_9_every_joint_force_to_the_printed_digit():
    """The book's accelerations are given ([given.3], [given.4]): graphkin's forces are the notes' to half a unit of
    the printed 0.1 N (F34y printed as F43y = 900.5 N, F14 as F14y)."""
    r = catalog.load("slider_crank_dynamic_makdin").solve()
    for key, printed in PRINTED_9.items():
        a, b = (int(c) for c in key[1:])
        np.testing.assert_allclose(r.force(a, b)[0], printed, rtol=0, atol=0.05)
    assert cross_check(r, constructions(r)).valid.all()


def test_oernek_9_the_torque_is_the_moment_of_the_printed_crank_pin_force():
    """T = −196 660.3 N·mm is the moment about O2 of F32 = −F23 as printed (rounded to 0.1 N): reproduced to half
    a unit; graphkin's T differs from it by at most what that rounding moves, r (|ΔF23x| + |ΔF23y|) = 51 × 0.1."""
    B = np.array([51.0 * math.cos(THETA), 51.0 * math.sin(THETA)])  # mm
    Fx, Fy = (-c for c in PRINTED_9["F23"])
    T_printed = -(B[0] * Fy - B[1] * Fx)
    assert T_printed == pytest.approx(-196660.3, abs=0.5)
    r = catalog.load("slider_crank_dynamic_makdin").solve()
    assert abs(r.effort[0] * 1e3 - (-196660.3)) <= 51.0 * (0.05 + 0.05) + 0.05
