"""Söylemez §6.4.1's closed-form four-bar solution against graphkin's solvers.

The closed form (``tests/books/soylemez_fourbar_solver.py``) is implemented from
the book independently of graphkin (its printed typos corrected there, each
with evidence). Here, on random crank-rockers with random mass properties and
external forces, both graphkin routes — dyad-by-dyad closed form and the
assembled [A]{x} = {b} — must agree with it to 1e-9 relative.
"""

import math

import numpy as np
from hypothesis import given, settings

from graphkin.analytical import solve
from graphkin.analytical.matrix import solve_matrix
from graphkin.model import Driver, Link, Mechanism, PointForce, Revolute
from tests.books.soylemez_fourbar_solver import soylemez_fourbar
from tests.books.test_soylemez_fourbar import crank_rockers


def polar(r, angle):
    return (r * math.cos(angle), r * math.sin(angle))


def graphkin_fourbar(p):
    links = [
        Link(1, {"A0": (0, 0), "B0": (p["a1"], 0)}),
        Link(2, {"A0": (0, 0), "A": (p["a2"], 0)}, p["m2"], polar(p["g2"], p["beta2"]), p["I2"]),
        Link(3, {"A": (0, 0), "B": (p["a3"], 0), "P3": polar(p["f3"], p["gamma3"])}, p["m3"], polar(p["g3"], p["beta3"]),
             p["I3"]),
        Link(4, {"B0": (0, 0), "B": (p["a4"], 0), "P4": polar(p["f4"], p["gamma4"])}, p["m4"], polar(p["g4"], p["beta4"]),
             p["I4"]),
    ]
    joints = [Revolute((1, 2), "A0"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), Revolute((1, 4), "B0")]
    loads = [PointForce(3, "P3", polar(p["F13"], p["phi3"]), name="F13"),
             PointForce(4, "P4", polar(p["F14"], p["phi4"]), name="F14")]
    # Söylemez's σ = +1 puts B clockwise of B0→A, which is graphkin's σ = +1
    # for the RRR dyad A–B–B0 (B to the left of A→B0).
    return Mechanism(links, joints, Driver(2), loads, assembly={"B": p["sigma"]})


@settings(max_examples=150, deadline=None)
@given(crank_rockers())
def test_closed_form_equals_both_graphkin_routes(case):
    theta12, omega12, alpha12, p = case
    book = soylemez_fourbar(theta12, omega12, alpha12, **p)
    r = solve(graphkin_fourbar(p), theta12, omega12, alpha12)
    assert r.valid.all()
    k = r.kinematics
    np.testing.assert_allclose(np.cos(k.theta[3] - book["theta13"]), 1.0, rtol=0, atol=1e-12)
    np.testing.assert_allclose(np.cos(k.theta[4] - book["theta14"]), 1.0, rtol=0, atol=1e-12)
    pairs = {"G14": (1, 4), "F34": (3, 4), "F23": (2, 3), "G12": (1, 2)}
    scale = max(np.abs(book[f"{n}{c}"]).max() for n in pairs for c in "xy")
    m = solve_matrix(r)
    for route in (r, m):
        for name, (i, j) in pairs.items():
            F = route.force(i, j)
            np.testing.assert_allclose(F[:, 0], book[f"{name}x"], rtol=0, atol=1e-9 * scale)
            np.testing.assert_allclose(F[:, 1], book[f"{name}y"], rtol=0, atol=1e-9 * scale)
        np.testing.assert_allclose(route.effort, book["T12"], rtol=0, atol=1e-9 * np.abs(book["T12"]).max())
