"""Lesson 14's drawn keys hold the physics of d'Alembert's principle and equilibrium, checked from the kinematics
alone, not from graphkin's construction.

Söylemez, *Mechanisms*, §6.4 (the inertia force −m a_G and torque −I_G α replaced by one force on a line offset
by h = |T|/|F| from G, on the side whose moment about G is the torque) and §6.4.1 (the strip cutter, solved by
superposition: with the coupler's loads alone the rocker is a two-force member, the coupler a three-force one whose
forces meet at one point, and its force polygon closes).
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from graphkin import exercises

STUDENTS = ["s001", "s002", "your-id"]


def _right(v, qid: str) -> dict:
    key = {q["id"]: q["answer"] for q in v.key()["questions"]}
    return json.loads(key[qid]["drawing"])


def _cross(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


@pytest.mark.parametrize("student", STUDENTS)
def test_the_keyed_inertia_line_carries_the_inertia_force_and_torque(student):
    v = exercises.variant("draw_strip_cutter", student)
    k = v.problem.solve().kinematics
    link = next(x for x in v.problem.mechanism.links if x.number == 3)
    G, a_G, alpha = k.G(3)[0], k.a_G(3)[0], float(k.alpha[3][0])
    F, T = -link.mass * a_G, -link.I_G * alpha  # d'Alembert [N], [N·m]
    (line,) = _right(v, "R3i")["elements"]
    P, Q = (np.asarray(p) for p in line["through"])
    d = (Q - P) / np.linalg.norm(Q - P)
    assert abs(_cross(d, F / np.linalg.norm(F))) < 1e-9  # along F
    # The moment of F on that line about G is the inertia torque: offset h = |T|/|F|, on the torque's side.
    assert _cross(P - G, F) == pytest.approx(T, rel=1e-9)


@pytest.mark.parametrize("student", STUDENTS)
def test_the_keyed_polygon_closes_along_the_lines_of_action(student):
    v = exercises.variant("draw_strip_cutter", student)
    task = exercises.task_of(v, "polygon3")
    drawn = _right(v, "polygon3")["elements"]
    known = [np.subtract(g["to"], g["from"]) for g in task["shown"]["vectors"]]
    sides = [np.subtract(e["to"], e["from"]) for e in drawn]
    # Tip to tail: each drawn side starts where the one before it ends, and the last ends at the pole o.
    ends = [task["shown"]["vectors"][-1]["to"], *[e["to"] for e in drawn]]
    for e, start in zip(drawn, ends):
        assert np.allclose(e["from"], start, atol=1e-9 * np.linalg.norm(known[0]))
    total = np.sum(known + sides, axis=0)
    assert np.linalg.norm(total) <= 1e-9 * max(np.linalg.norm(s) for s in known + sides)
    # F43′ along the rocker's pins (a two-force member): the keyed line of the two-force question.
    (line,) = _right(v, "F43")["elements"]
    along = np.subtract(line["through"][1], line["through"][0])
    assert abs(_cross(along / np.linalg.norm(along), sides[0] / np.linalg.norm(sides[0]))) < 1e-9


@pytest.mark.parametrize("student", STUDENTS)
def test_the_keyed_point_of_concurrency_lies_on_both_known_lines(student):
    v = exercises.variant("draw_strip_cutter", student)
    task = exercises.task_of(v, "I3")
    (point,) = _right(v, "I3")["elements"]
    I3 = np.asarray(point["at"])
    for line in task["shown"]["lines"]:
        u = np.array([np.cos(line["angle"]), np.sin(line["angle"])])
        assert abs(_cross(I3 - np.asarray(line["through"]), u)) < 1e-9 * max(1.0, np.linalg.norm(I3))
