"""Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 15, engines written as the book gives them (issue 25):
Example 15.8 (p. 534), a vertical double-acting steam engine with a piston rod and the weight of its reciprocating
parts, 125° from the top dead centre (catalog ``engine_vertical_khurmi``); Example 15.9 (p. 534), a gas engine at
1800 rpm, 33° from the dead centre (catalog ``gas_engine_khurmi``).

Printed (FOSSEE Python Textbook Companion, Khurmi ch15, whose code types the book's method out): 15.8 "Effective
turning moment of the crank shaft T = 3020 N-m"; 15.9 "Net load on the gudgeon pin FP = 1848 N", "Thrust in the
connecting rod FQ = 1865.8 N", "Reaction between the piston and cylinder FN = 254 N" (printed with %d: cut).

The book's method: F_L from the pressures, rounded to the newton; F_I = m ω² r (cos θ + cos 2θ / n), a two-term
series for the piston's acceleration; F_P = F_L − F_I (+ m g for the vertical engine); sin φ = sin θ / n;
F_Q = F_P / cos φ; F_N = F_P tan φ; T = F_P sin(θ + φ)/cos φ × r. It is written out below twice: as the companion
does it (reproducing every printed digit, tested), and with F_L unrounded and the exact acceleration (graphkin's
numbers to 1e-9, tested). The printed values then lie from graphkin's by exactly the difference of the two chains
(the series and the rounding of F_L), plus half a unit of the printed digit (or one unit where it is cut): the
tolerance is that computed difference, nothing chosen.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin import catalog
from graphkin.report import constructions, cross_check


def book_method(*, r, l, m, rpm, theta_deg, F_L, g=0.0, exact=False):
    """The book's chain: F_P, F_Q, F_N, T (N, N·m); ``exact`` takes the exact piston acceleration instead of the series."""
    omega = 2 * math.pi * rpm / 60
    th = math.radians(theta_deg)
    n = l / r
    if exact:  # x = r cos θ + √(l² − r² sin² θ), twice at constant ω; F_I = −m ẍ (away from the crank when ẍ < 0)
        s, c = math.sin(th), math.cos(th)
        root = math.sqrt(l**2 - r**2 * s**2)
        F_I = -m * omega**2 * (-r * c - r**2 * (c**2 - s**2) / root - r**4 * s**2 * c**2 / root**3)
    else:
        F_I = m * omega**2 * r * (math.cos(th) + math.cos(2 * th) / n)
    F_P = F_L - F_I + m * g
    phi = math.asin(math.sin(th) / n)
    return {"F_P": F_P, "F_Q": F_P / math.cos(phi), "F_N": F_P * math.tan(phi),
            "T": F_P * math.sin(th + phi) / math.cos(phi) * r}


# -- Example 15.8 -------------------------------------------------------------------------------------------------

A1, A_ROD = math.pi / 4 * 0.3**2, math.pi / 4 * 0.05**2
F_L_158 = 30e3 * A1 - 1.5e3 * (A1 - A_ROD)
DATA_158 = {"r": 0.225, "l": 1.2, "m": 225.0, "rpm": 200.0, "theta_deg": 125.0, "g": 9.81}


def test_15_8_the_companion_prints_the_books_method():
    assert round(book_method(**DATA_158, F_L=round(F_L_158))["T"]) == 3020


def test_15_8_graphkin_is_the_method_exactly():
    problem = catalog.load("engine_vertical_khurmi")
    assert problem.q[0] == pytest.approx(math.radians(90 + 125), abs=1e-12)  # TDC: the crank up, at the piston
    assert -problem.mechanism.loads[0].force[1] == pytest.approx(F_L_158, rel=1e-12)
    r = problem.solve()
    exact = book_method(**DATA_158, F_L=F_L_158, exact=True)
    assert -r.effort[0] == pytest.approx(exact["T"], rel=1e-9)
    assert cross_check(r, constructions(r)).valid.all()
    companion = book_method(**DATA_158, F_L=round(F_L_158))
    assert abs(-r.effort[0] - 3020.0) <= abs(companion["T"] - exact["T"]) + 0.5


# -- Example 15.9 -------------------------------------------------------------------------------------------------

F_L_159 = 0.7e6 * math.pi / 4 * 0.08**2
DATA_159 = {"r": 0.05, "l": 0.2, "m": 1.0, "rpm": 1800.0, "theta_deg": 33.0}
PRINTED_159 = {"F_P": (1848.0, 0.5), "F_Q": (1865.8, 0.05), "F_N": (254.0, 1.0)}  # value, half a unit (cut: one)


def test_15_9_the_companion_prints_the_books_method():
    got = book_method(**DATA_159, F_L=round(F_L_159))
    assert round(got["F_P"]) == 1848 and round(got["F_Q"], 1) == 1865.8 and int(got["F_N"]) == 254


def test_15_9_graphkin_is_the_method_exactly():
    r = catalog.load("gas_engine_khurmi").solve()
    F34 = r.force(3, 4)[0]
    got = {"F_P": float(F34[0]), "F_Q": float(np.hypot(*F34)), "F_N": float(np.hypot(*r.force(1, 4)[0]))}
    exact = book_method(**DATA_159, F_L=F_L_159, exact=True)
    companion = book_method(**DATA_159, F_L=round(F_L_159))
    for key, (printed, unit) in PRINTED_159.items():
        assert got[key] == pytest.approx(exact[key], rel=1e-9), key
        assert abs(got[key] - printed) <= abs(companion[key] - exact[key]) + unit, key
    assert cross_check(r, constructions(r)).valid.all()


def _crank_pin_forces(r):
    """The rod's force on the crank pin, across the crank (F_T, in the sense of rotation: CCW here) and along it
    away from the pivot's side (F_B, the thrust on the bearings as the book signs it)."""
    kin = r.kinematics
    C, O = kin.position(2, "C")[0], kin.position(2, "O")[0]
    u = (C - O) / np.hypot(*(C - O))
    F32 = r.force(3, 2)[0]
    return float(u[0] * F32[1] - u[1] * F32[0]), float(-(F32 @ u))


# -- Example 15.13 ------------------------------------------------------------------------------------------------

F_L_1513 = (2.2e6 - 0.1e6) * math.pi / 4 * 0.3**2
DATA_1513 = {"r": 0.25, "l": 1.125, "m": 280.0, "rpm": 180.0, "theta_deg": 45.0, "g": 9.81}
PRINTED_1513 = {"F_T": (109.501e3, 0.5), "F_B": (79.438e3, 0.5), "T": (27.38e3, 5.0)}


def _tangential(chain, theta_deg=45.0):
    th = math.radians(theta_deg)
    phi = math.asin(math.sin(th) / 4.5)
    return {"F_T": chain["F_P"] * math.sin(th + phi) / math.cos(phi),
            "F_B": chain["F_P"] * math.cos(th + phi) / math.cos(phi), "T": chain["T"]}


def test_15_13_the_companion_prints_the_books_method():
    got = _tangential(book_method(**DATA_1513, F_L=F_L_1513))
    assert round(got["F_T"] / 1e3, 3) == 109.501 and round(got["F_B"] / 1e3, 3) == 79.438
    assert round(got["T"] / 1e3, 2) == 27.38


def test_15_13_graphkin_is_the_method_exactly():
    r = catalog.load("diesel_vertical_khurmi").solve()
    F_T, F_B = _crank_pin_forces(r)
    got = {"F_T": F_T, "F_B": F_B, "T": -float(r.effort[0])}
    exact = _tangential(book_method(**DATA_1513, F_L=F_L_1513, exact=True))
    companion = _tangential(book_method(**DATA_1513, F_L=F_L_1513))
    for key, (printed, unit) in PRINTED_1513.items():
        assert got[key] == pytest.approx(exact[key], rel=1e-9), key
        assert abs(got[key] - printed) <= abs(companion[key] - exact[key]) + unit, key
    assert cross_check(r, constructions(r)).valid.all()


# -- Example 15.11 ------------------------------------------------------------------------------------------------

F_L_1511 = 700e3 * math.pi / 4 * 0.1**2
DATA_1511 = {"r": 0.06, "l": 0.25, "m": 1.1, "rpm": 2000.0, "theta_deg": 20.0, "g": 9.81}


def test_15_11_the_companion_prints_the_books_net_force_and_two_slips_of_its_own():
    """F_P = 2255.6 N is the book's method with F_I rounded to the newton. The companion's 2265 N is F_P / cos(φ)
    with φ from sin(20) taken in radians and then used as radians; its 185.4 N is F_P tan 4.7° (φ typed in): not the
    book's F_Q and F_N, which the next test checks against the method done right."""
    omega = 2 * math.pi * 2000 / 60
    th = math.radians(20.0)
    F_I = round(1.1 * omega**2 * 0.06 * (math.cos(th) + math.cos(2 * th) / (0.25 / 0.06)))
    F_P = F_L_1511 - F_I + 1.1 * 9.81
    assert round(F_P, 1) == 2255.6
    phi_slip = math.degrees(math.asin(math.sin(20.0) / (0.25 / 0.06)))
    assert round(F_P / math.cos(phi_slip)) == 2265 and round(F_P * math.tan(math.radians(4.7)), 1) == 185.4


def test_15_11_graphkin_is_the_method_exactly():
    r = catalog.load("petrol_vertical_khurmi").solve()
    F34 = r.force(3, 4)[0]
    got = {"F_P": float(F34[1]), "F_Q": float(np.hypot(*F34)), "F_N": float(np.hypot(*r.force(1, 4)[0]))}
    exact = book_method(**DATA_1511, F_L=F_L_1511, exact=True)
    for key in got:
        assert got[key] == pytest.approx(exact[key], rel=1e-9), key
    # the printed F_P, the method with the series and F_I rounded: their difference from the exact chain, no more
    series = book_method(**DATA_1511, F_L=F_L_1511)
    assert abs(got["F_P"] - 2255.6) <= abs(series["F_P"] - exact["F_P"]) + 0.5 + 0.05
    assert cross_check(r, constructions(r)).valid.all()
