"""Lesson 10 (the power check): the exercise the student works by virtual work, against the formula by hand.

Khurmi & Gupta, *Theory of Machines*, Example 15.10 (catalog problem engine_static_khurmi): r = 300 mm,
n = l/r = 4.5, three loads on the piston along the stroke (gas F_L towards the crank, the given inertia 6480 N
and friction 600 N away from it). The power balance T12 ω + F_P v_P = 0 with the piston's speed towards the
crank v_P = ω r (sin θ + sin 2θ / (2 sqrt(n² − sin² θ))) gives T12 = −F_P r (sin θ + sin 2θ / (2 sqrt(n² − sin² θ))),
the book's printed 5.06 kN·m at its own data (θ = 30°, F_L = 35.343 kN).
"""

from __future__ import annotations

import math

import pytest

from graphkin import exercises


def by_hand(theta: float, F_L: float) -> float:
    r, n = 0.3, 4.5
    F_P = F_L - 6480 - 600
    return -F_P * r * (math.sin(theta) + math.sin(2 * theta) / (2 * math.sqrt(n**2 - math.sin(theta) ** 2)))


def test_by_hand_gives_the_books_answer():
    assert by_hand(math.radians(30), 35342.917353) == pytest.approx(-5060, abs=5)  # printed 5.06 kN·m


@pytest.mark.parametrize("student", ["s001", "s002", "s003", "lesson-10", "your-id"])
def test_virtual_work_key_is_the_power_balance_by_hand(student):
    data = {g["symbol"]: g["value"] for g in exercises.variant("virtual_work", student).sheet()["data"]}
    theta = math.radians(float(data["θ"].split()[0]))
    F_L = float(data["FL"].split()[0]) * 1e3
    key = exercises.key("virtual_work", student)["questions"][0]["answer"]["si"]
    assert key == pytest.approx(by_hand(theta, F_L), rel=1e-9)


def test_the_turning_moment_typed_for_T12_is_not_correct():
    key = exercises.key("virtual_work", "s001")["questions"][0]["answer"]["si"]
    right = exercises.grade("virtual_work", "s001", {"T12": f"{key:.5g} N*m"})
    wrong = exercises.grade("virtual_work", "s001", {"T12": f"{-key:.5g} N*m"})
    assert right["score"] == right["max"] and wrong["score"] < wrong["max"]
