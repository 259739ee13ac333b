"""``[unknown]``: the effort on the link the book asks about, against hand calculations by virtual work.

Both files (tests/problem/files/) are linkages at rest with a given crank torque T2 = 100 N·m (50 N·m on the
slider-crank) and no other load, so virtual work gives the unknown alone: T2 δθ2 + T4 δθ4 = 0 for a rocker,
T2 δθ2 + P δx = 0 for a piston.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from graphkin import catalog
from graphkin.cli import main
from graphkin.report import constructions, cross_check

FILES = Path(__file__).parent / "files"


def fourbar_by_hand(theta2, a=0.1, b=0.25, c=0.2, d=0.3):
    """θ3, θ4 by intersecting the circles (the open branch), and ω4/ω2 = a sin(θ3 − θ2) / (c sin(θ3 − θ4))."""
    A = complex(a * math.cos(theta2), a * math.sin(theta2))
    O4 = complex(d, 0.0)
    e = O4 - A
    L = abs(e)
    x = (b * b - c * c + L * L) / (2 * L)
    h = math.sqrt(b * b - x * x)
    B = A + e / L * complex(x, h)  # the intersection on the left of A -> O4: the one graphkin assembles here
    theta3, theta4 = np.angle(B - A), np.angle(B - O4)
    return theta3, theta4, a * math.sin(theta3 - theta2) / (c * math.sin(theta3 - theta4))


def test_the_rockers_torque_is_virtual_work():
    problem = catalog.load(str(FILES / "fourbar_unknown.toml"))
    r = problem.solve()
    theta3, theta4, ratio = fourbar_by_hand(math.radians(60.0))
    assert float(r.kinematics.theta[4][0]) == pytest.approx(theta4, abs=1e-12)
    T4 = problem.unknown.values(r)[0]
    assert T4 == pytest.approx(-100.0 / ratio, rel=1e-12)  # -342.94 N·m
    assert T4 == pytest.approx(-342.9405, abs=5e-5)
    # The driver is then balanced: T12 is rounding beside the forces; the coupler a two-force member along AB.
    F = r.force(3, 4)[0]
    assert abs(float(r.effort[0])) < 1e-12 * float(np.hypot(*F))
    assert math.atan2(F[1], F[0]) % math.pi == pytest.approx(theta3 % math.pi, abs=1e-12)
    assert cross_check(r, constructions(r)).valid.all()


def test_the_piston_force_is_virtual_work_and_a_dead_centre_has_none():
    problem = catalog.load(str(FILES / "slider_unknown.toml"))
    r = cross_check(problem.solve(), constructions(problem.solve()))
    r_, l = 0.1, 0.3
    P = problem.unknown.values(r)
    for i, deg in enumerate((45.0, 120.0, 180.0, 300.0)):
        t = math.radians(deg)
        dx = -r_ * math.sin(t) - r_ * r_ * math.sin(t) * math.cos(t) / math.sqrt(l * l - (r_ * math.sin(t)) ** 2)
        if deg == 180.0:
            assert not r.valid[i] and "dead point" in r.reason(i) and "P4" in r.reason(i)
            continue
        assert r.valid[i], r.reason(i)
        assert P[i] == pytest.approx(-50.0 / dx, rel=1e-12), deg  # 569.08 N, 699.04 N, -491.75 N


def test_report_and_json_name_the_unknown(capsys):
    assert main(["solve", str(FILES / "fourbar_unknown.toml"), "--json"]) == 0
    entry = json.loads(capsys.readouterr().out)["positions"][0]
    assert entry["unknown"]["name"] == "T4" and entry["unknown"]["kind"] == "torque"
    assert entry["unknown"]["value"] == pytest.approx(-342.9405, abs=5e-5)
    assert main(["solve", str(FILES / "fourbar_unknown.toml")]) == 0
    out = capsys.readouterr().out
    assert "Unknown effort (asked): T4 = -342.9405 N·m CW on link 4" in out
    assert main(["solve", str(FILES / "fourbar_unknown.toml"), "--units", "US", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["units"]["positions[].unknown.value"] == "lbf*ft"
    assert data["positions"][0]["unknown"]["value"] == pytest.approx(-342.9405 / (4.4482216152605 * 0.3048),
                                                                     abs=1e-4)


def test_a_sweep_finds_the_unknown_at_every_position():
    problem = catalog.load(str(FILES / "fourbar_unknown.toml"))
    angles = np.radians(np.arange(0.0, 360.0, 15.0))
    r = problem.solve(angles)
    T4 = problem.unknown.values(r)
    for i, t in enumerate(angles):
        if not r.valid[i]:
            continue
        assert T4[i] == pytest.approx(-100.0 / fourbar_by_hand(t)[2], rel=1e-9), math.degrees(t)
    assert r.valid.sum() >= 20
