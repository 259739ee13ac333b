"""Lesson 09 (engines): the exercise the student works by hand, and the cycle claims, against the book's method.

Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 15 ('Inertia forces in reciprocating parts'), the method of
Examples 15.7 and 15.9: F_L = p πD²/4, F_I = m_R a_P, F_P = F_L − F_I, sin φ = sin θ / n, F_Q = F_P / cos φ,
F_N = F_P tan φ, T = F_Q sin(θ + φ) r. Written out here without graphkin, with the piston's exact acceleration
(the book's two-term series is an approximation of it), so graphkin must agree to round-off.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin import catalog, exercises
from graphkin.cycle import sweep
from graphkin.problem import parse_problem

# Khurmi & Gupta Ex. 15.9's engine: crank r, rod l, bore D, reciprocating mass m_R.
R, L, BORE, M_R = 0.050, 0.200, 0.080, 1.0


def exact_piston_acceleration(theta: float, omega: float) -> float:
    """a_P towards the crank [m/s²], from x = r cos θ + sqrt(l² − r² sin² θ) differentiated twice (ω constant)."""
    s, c = math.sin(theta), math.cos(theta)
    root = math.sqrt(L**2 - R**2 * s**2)
    x_ddot = -R * omega**2 * c - (R**2 * omega**2 * (c**2 - s**2)) / root - (R**4 * omega**2 * s**2 * c**2) / root**3
    return -x_ddot


def book_method(theta: float, omega: float, p: float) -> dict:
    """The engine's efforts at θ from the I.D.C. by the book's resolution of forces (exact a_P)."""
    F_L = p * math.pi * BORE**2 / 4
    F_P = F_L - M_R * exact_piston_acceleration(theta, omega)
    phi = math.asin(math.sin(theta) / (L / R))
    F_Q = F_P / math.cos(phi)
    return {"F_Q": abs(F_Q), "F_N": abs(F_P * math.tan(phi)), "T12": -F_Q * math.sin(theta + phi) * R}


@pytest.mark.parametrize("student", ["s001", "s002", "s003", "lesson-09", "your-id"])
def test_engine_efforts_key_is_the_books_method(student):
    variant = exercises.variant("engine_efforts", student)
    data = {g["symbol"]: g["value"] for g in variant.sheet()["data"]}
    theta = math.radians(float(data["θ"].split()[0]))
    omega = float(data["N"].split()[0]) * 2 * math.pi / 60
    p = float(data["p"].split()[0]) * 1e6
    expected = book_method(theta, omega, p)
    key = {q["id"]: q["answer"]["si"] for q in exercises.key("engine_efforts", student)["questions"]}
    for name, value in expected.items():
        assert key[name] == pytest.approx(value, rel=1e-9), name


def test_engine_efforts_grades_the_hand_answer_and_a_wrong_sense():
    key = {q["id"]: q["answer"]["si"] for q in exercises.key("engine_efforts", "s001")["questions"]}
    right = {"F_Q": f"{key['F_Q']:.5g} N", "F_N": f"{key['F_N']:.5g} N", "T12": f"{key['T12']:.5g} N*m"}
    report = exercises.grade("engine_efforts", "s001", right)
    assert report["score"] == report["max"] == 3
    flipped = dict(right, T12=f"{-key['T12']:.5g} N*m")  # the engine's turning moment given for T12
    verdicts = {q["id"]: q["verdict"] for q in exercises.grade("engine_efforts", "s001", flipped)["questions"]}
    assert verdicts["T12"] != "correct" and verdicts["F_Q"] == "correct"


def test_single_acting_engine_mean_turning_moment_is_the_gas_work_per_turn():
    # Khurmi & Gupta Ex. 15.7's engine with the gas load on the out-stroke only, as lesson 09 writes it: the gas
    # does F_L · 2r per turn; the inertia of the reciprocating parts does none at constant speed.
    text = catalog.path("engine_gas_force").read_text(encoding="utf-8")
    single = sweep(parse_problem(text + 'active = { from = "0 deg", to = "180 deg" }\n'), 720)
    F_L, r = 68722.3393, 0.3
    assert -single.average == pytest.approx(F_L * 2 * r / (2 * math.pi), rel=2e-5)
    both = sweep(catalog.load("engine_gas_force"), 720)
    assert abs(both.average) < 1e-9 * np.abs(both.torque).max()
