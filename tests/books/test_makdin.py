""""Makina Dinamiği" (Machine Dynamics) lecture notes, public repository Alphyn12/MekanizmaV2, file
"Machine Dynamics.pdf": Örnek 6 (static four-bar with two loads, graphical superposition; catalog
``fourbar_two_loads_makdin``) and Örnek 7 (the same four-bar, dynamic, matrix method; catalog
``fourbar_dynamic_makdin``), both with the geometry of Örnek 1 and the drawing's angles θ3 = 26°, θ4 = 85°.

Örnek 7 prints the matrix method's equations (PDF pp. 25–28) and every intermediate: a11 = −l4 sin θ4,
a12 = l4 cos θ4, a21 = l3 sin θ3, a22 = −l3 cos θ3, b1 = F4x r4 sin θ4 − F4y r4 cos θ4 − T4,
b2 = F3x r3 sin θ3 − F3y r3 cos θ3 − T3, [a] F34 = b, F14 = −F34 − F4, F23 = F34 − F3, F12 = F23,
T = F23y l2 cos θ2 − F23x l2 sin θ2. They are written out below, without graphkin: fed the notes' own rounded
inertia loads they give every printed digit (tested), and fed the exact ones graphkin agrees with them to 1e-9.
So the only gap between graphkin and the print is the notes' rounding of F3, F4, T3, T4 before the matrix.

Örnek 6's answers are read off a drawing at 2 N/mm, the arms h to the millimetre: each printed value is graphkin's
to within that reading (half a unit of the last digit read: 1 N for a force read in whole newtons, 0.5 mm for an
arm), carried through T = F h.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin import catalog
from graphkin.report import constructions, solution

L2, L3, L4, R3, R4 = 50.0, 151.0, 111.0, 75.5, 55.5  # mm
TH2, TH3, TH4 = (math.radians(a) for a in (120.0, 26.0, 85.0))


def matrix_method(F3, F4, T3, T4):
    """The notes' matrix method (N, N·mm): F3, F4 the inertia forces (x, y) [N], T3, T4 the inertia torques [N·mm]."""
    a = np.array([[-L4 * math.sin(TH4), L4 * math.cos(TH4)], [L3 * math.sin(TH3), -L3 * math.cos(TH3)]])
    b = np.array([F4[0] * R4 * math.sin(TH4) - F4[1] * R4 * math.cos(TH4) - T4,
                  F3[0] * R3 * math.sin(TH3) - F3[1] * R3 * math.cos(TH3) - T3])
    F34 = np.linalg.solve(a, b)
    F14 = -F34 - np.asarray(F4)
    F23 = F34 - np.asarray(F3)
    T = F23[1] * L2 * math.cos(TH2) - F23[0] * L2 * math.sin(TH2)
    return {"F34": F34, "F14": F14, "F23": F23, "F12": F23, "T": T}


PRINTED_7 = {"F34": (31.6, 110.5), "F14": (-11.1, -166.9), "F23": (113.6, -57.5), "F12": (113.6, -57.5), "T": -3481.5}
ROUNDED_7 = {"F3": (-82.0, 168.0), "F4": (-20.5, 56.4), "T3": -1211.6, "T4": 1020.6}  # as the notes print them


def test_the_notes_equations_with_their_rounded_loads_give_every_printed_digit():
    got = matrix_method(**ROUNDED_7)
    for key, printed in PRINTED_7.items():
        np.testing.assert_allclose(got[key], printed, rtol=0, atol=0.05 if key != "T" else 0.5)


@pytest.fixture(scope="module")
def dynamic():
    r = catalog.load("fourbar_dynamic_makdin").solve()
    return r


def test_oernek_7_graphkin_is_the_matrix_method_with_its_exact_inertia_loads(dynamic):
    r = dynamic
    inn3, inn4 = r.inertia(3), r.inertia(4)
    want = matrix_method(inn3.F[0], inn4.F[0], inn3.T[0] * 1e3, inn4.T[0] * 1e3)
    for key in ("F34", "F14", "F23", "F12"):
        a, b = (int(c) for c in key[1:])
        np.testing.assert_allclose(r.force(a, b)[0], want[key], rtol=1e-9)
    assert r.effort[0] * 1e3 == pytest.approx(want["T"], rel=1e-9)
    g = constructions(r)[0]
    assert g.valid and g.effort == pytest.approx(r.effort[0], rel=1e-9)


def test_oernek_7_the_notes_inertia_loads_are_graphkins_rounded(dynamic):
    """F3 = 186.75 N ∠116° printed as (−82, 168) N; F4 = 60 N ∠110° as (−20.5, 56.4) N; T3, T4 to 0.1 N·mm."""
    inn3, inn4 = dynamic.inertia(3), dynamic.inertia(4)
    np.testing.assert_allclose(inn3.F[0], ROUNDED_7["F3"], atol=0.5)
    np.testing.assert_allclose(inn4.F[0], ROUNDED_7["F4"], atol=0.05)
    assert inn3.T[0] * 1e3 == pytest.approx(ROUNDED_7["T3"], abs=0.05)
    assert 0 <= inn4.T[0] * 1e3 - ROUNDED_7["T4"] < 0.1  # 1020.656 N·mm, cut (not rounded) to 1020.6 in the notes


# -- Örnek 6: the same four-bar, static, two loads, by graphical superposition -------------------------------------

PRINTED_6 = {
    "I": {"F43": 100.0, "F23": 114.0, "h": 19.0, "T": -2166.0},
    "II": {"F14": 68.0, "F34": 25.5, "h": 50.0, "T": -1275.0},
    "sum": {"F12": 127.5, "F34": 115.0, "F14": 168.0, "T": -3441.0},
}
READ = {"F": 1.0, "h": 0.5}  # half a unit of the drawing's reading: 2 N/mm read to the newton, arms to the mm


@pytest.fixture(scope="module")
def static():
    problem = catalog.load("fourbar_two_loads_makdin")
    r = problem.solve()
    return r, solution(problem, r, constructions(r))["positions"][0]


def test_oernek_6_is_oernek_7_with_the_inertia_torques_folded_into_offset_forces(static, dynamic):
    """The loads of Örnek 6 sit where Örnek 7's inertia forces, offset by h = |T|/|F|, do: the notes' 69 mm from B
    and 96 mm from O4 are 75.5 − 6.5 and 55.5 + 17 mm rounded; the answers agree to that rounding."""
    r6, _ = static
    assert dynamic.inertia(3).h[0] * 1e3 == pytest.approx(6.5, abs=0.05)
    assert dynamic.inertia(4).h[0] * 1e3 == pytest.approx(17.0, abs=0.05)
    # the notes round the offsets to 0.5 mm and the loads to 1 N: T moves by at most |F| × 0.5 mm per load
    assert r6.effort[0] * 1e3 == pytest.approx(dynamic.effort[0] * 1e3, abs=187 * 0.5 + 60 * 0.5)


def test_oernek_6_each_sub_problem_as_read_off_the_drawing(static):
    r, entry = static
    g = entry["graphical"]
    assert g["valid"] and [sp["link"] for sp in g["subproblems"]] == [3, 4]
    for sp, label in zip(g["subproblems"], ("I", "II")):
        printed = PRINTED_6[label]
        forces = {name: math.hypot(*v) for name, v in sp["forces"].items()}
        F12 = forces["F12"]
        T = sp["driver"]["value"] * 1e3  # N·mm
        h = abs(T) / F12
        for name in set(printed) - {"h", "T"}:
            assert forces[name] == pytest.approx(printed[name], abs=READ["F"]), (label, name)
        assert h == pytest.approx(printed["h"], abs=READ["h"]), label
        # T = F h as the notes multiply them: each factor within its reading
        assert T == pytest.approx(printed["T"], abs=READ["F"] * printed["h"] + F12 * READ["h"]), label


def test_oernek_6_the_sum(static):
    r, entry = static
    printed = PRINTED_6["sum"]
    for name in ("F12", "F34", "F14"):
        assert math.hypot(*entry["forces"][name]) == pytest.approx(printed[name], abs=READ["F"]), name
    # the sum of the two readings' allowances
    allowed = sum(READ["F"] * PRINTED_6[k]["h"] + PRINTED_6[k]["F23" if k == "I" else "F34"] * READ["h"]
                  for k in ("I", "II"))
    assert entry["driver"]["value"] * 1e3 == pytest.approx(printed["T"], abs=allowed)
    assert entry["graphical"]["driver"]["value"] == pytest.approx(entry["driver"]["value"], rel=1e-9)
