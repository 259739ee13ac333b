"""Lesson 11 (gear trains): the epicyclic exercise against Willis's speed ratio and the planet's free body.

Khurmi & Gupta, *Theory of Machines*, 14th ed., Example 13.20 (catalog problem epicyclic_khurmi): sun 16 teeth,
planet 24, annulus 64 (held), module 5 mm (r_S = 40 mm), pressure angle 20°. By Willis's method
N_S/N_C = 1 + T_E/T_S = 5; the power balance T_S ω_S + T_C ω_C = 0 gives T_C = −5 T_S (T12, the frame's torque
on the arm); the planet's free body gives equal tooth forces W_t / cos φ with W_t = T_S / r_S. None of these
depends on the arm's angle.
"""

from __future__ import annotations

import math

import pytest

from graphkin import exercises


@pytest.mark.parametrize("student", ["s001", "s002", "s003", "lesson-11", "your-id"])
def test_epicyclic_key_is_the_books_reasoning(student):
    data = {g["symbol"]: g["value"] for g in exercises.variant("epicyclic_torques", student).sheet()["data"]}
    T_S = float(data["TS"].split()[0])
    key = {q["id"]: q["answer"]["si"] for q in exercises.key("epicyclic_torques", student)["questions"]}
    tooth = T_S / 0.040 / math.cos(math.radians(20))
    assert key["T12"] == pytest.approx(-(1 + 64 / 16) * T_S, rel=1e-9)
    assert key["F43"] == pytest.approx(tooth, rel=1e-9)
    assert key["F31"] == pytest.approx(tooth, rel=1e-9)

