"""Bevan, *The Theory of Machines*, 3rd ed., ch. 12, Example 3 (p. 415): a steam engine in inch-pound units, the
torque on the crankshaft from the steam pressures (catalog problem ``engine_inch_bevan``, written in inches and
psi).

Printed (FOSSEE Python and Scilab Textbook Companions, Bevan ch12, Example 3): "The torque exerted on crankshaft=
F*OM = 6110 lb ft". The companions' method: F = P1 A − P2 (A − a) (the rod on the low-pressure side),
OM = OC (sin θ + sin 2θ / 2n) — the moment arm of F about O to first order in 1/n — T = F OM / 12, printed as
floor(T). graphkin's moment arm is exact: OM = OC sin(θ + φ)/cos φ.

The one deviation: the approximate OM (8.895 in against the exact 8.905 in). The companions' chain gives the
printed digit (tested); with the exact OM it is graphkin to 1e-9 (tested); the printed value lies from graphkin's
by that difference plus one unit (floor), nothing looser.
"""

from __future__ import annotations

import math

import pytest

from graphkin import catalog
from graphkin.report import constructions, cross_check

LBF, INCH = 4.4482216152605, 0.0254
D, d, OC, CP, P1, P2, THETA = 9.0, 2.0, 12.0, 60.0, 160.0, 32.0, math.radians(40.0)  # in, psi, rad
F = P1 * math.pi * (D / 2) ** 2 - P2 * math.pi * ((D / 2) ** 2 - (d / 2) ** 2)  # lbf
N_RATIO = CP / OC


def torque(OM):
    return F * OM / 12  # lb·ft


OM_APPROX = OC * (math.sin(THETA) + math.sin(2 * THETA) / (2 * N_RATIO))
PHI = math.asin(math.sin(THETA) / N_RATIO)
OM_EXACT = OC * math.sin(THETA + PHI) / math.cos(PHI)


def test_the_companion_prints_the_method_with_the_approximate_arm():
    assert math.floor(torque(OM_APPROX)) == 6110


def test_graphkin_is_the_method_with_the_exact_arm():
    problem = catalog.load("engine_inch_bevan")
    assert -problem.mechanism.loads[0].force[0] == pytest.approx(F * LBF, rel=1e-12)
    r = problem.solve()
    T = -float(r.effort[0]) / (LBF * 12 * INCH)  # N·m to lb·ft
    assert T == pytest.approx(torque(OM_EXACT), rel=1e-9)
    assert abs(T - 6110.0) <= abs(torque(OM_APPROX) - torque(OM_EXACT)) + 1.0
    assert cross_check(r, constructions(r)).valid.all()


def test_reported_in_us_units_it_is_the_books_torque_in_lb_ft(capsys):
    """``graphkin solve engine_inch_bevan --units US``: the torque in lbf·ft as the book prints it, and the steam
    force in lbf; the same deviation from the printed 6110 as above (the approximate arm, then floor)."""
    import json

    from graphkin.cli import main

    assert main(["solve", "engine_inch_bevan", "--units", "US", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["units"]["positions[].driver.value"] == "lbf*ft"
    assert data["units"]["positions[].loads[].force"] == "lbf"
    entry = data["positions"][0]
    T = -entry["driver"]["value"]  # the torque exerted on the crankshaft, lb·ft
    assert T == pytest.approx(torque(OM_EXACT), rel=1e-9)
    assert abs(T - 6110.0) <= abs(torque(OM_APPROX) - torque(OM_EXACT)) + 1.0
    assert -entry["loads"][0]["force"][0] == pytest.approx(F, rel=1e-12)  # lbf, P1 A − P2 (A − a)
    assert main(["solve", "engine_inch_bevan", "--units", "US"]) == 0
    text = capsys.readouterr().out
    assert f"Driver: T12 = {-torque(OM_EXACT):.4f} lbf·ft CW" in text
    assert f"F (steam) on link 4 at P: {F:.4g} lbf ∠ 180.00°" in text
