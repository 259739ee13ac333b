"""A pressure table against the piston's stroke (an indicator diagram as books print it), against a hand calculation.

tests/problem/files/indicator_stroke.toml: crank r = 100 mm, rod l = 400 mm, the piston on +x of the crank's pivot
(inner dead centre at θ = 0, x = 500 mm), bore 100 mm; the out stroke's pressure falls from 2.0 MPa at the inner
dead centre through 1.2, 0.6 and 0.2 MPa at 50, 100 and 200 mm, the return stroke's is 0.1 MPa throughout; the
gas pushes the piston towards the crank (−x). A linkage at rest turning CCW (ω only gives the sense of motion).
By hand: x = r cos θ + √(l² − r² sin² θ), s = 500 mm − x, p by straight lines in s on the stroke the piston is on
(out from θ = 0 to 180°), F = p π D²/4, and the crank's torque by virtual work T12 = F dx/dθ (F along −x).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from graphkin import catalog
from graphkin.cli import main
from graphkin.report import constructions, cross_check
from tests.bad_input.test_catalogue import one_error_line, solve_refuses

FILE = Path(__file__).parent / "files" / "indicator_stroke.toml"
R, L, AREA = 0.1, 0.4, math.pi * 0.1**2 / 4
OUT = ([0.0, 0.05, 0.1, 0.2], [2.0e6, 1.2e6, 0.6e6, 0.2e6])


def by_hand(deg):
    t = math.radians(deg)
    root = math.sqrt(L * L - (R * math.sin(t)) ** 2)
    x = R * math.cos(t) + root
    s = 0.5 - x
    outward = 0 <= deg % 360 < 180
    p = float(np.interp(s, *OUT)) if outward else 0.1e6
    dx = -R * math.sin(t) - R * R * math.sin(t) * math.cos(t) / root
    F = p * AREA
    return s, F, F * dx  # the displacement [m], the piston force's size [N], T12 [N·m] by virtual work


@pytest.mark.parametrize("i, deg", [(0, 0.0), (1, 30.0), (2, 90.0), (3, 180.0), (4, 270.0)])
def test_the_force_follows_the_stroke_out_and_back(i, deg):
    problem = catalog.load(str(FILE))
    r = problem.solve()
    r = cross_check(r, constructions(r))
    assert r.valid[i], r.reason(i)
    from graphkin.analytical.loads import applied

    force = applied(r.kinematics, problem.mechanism.loads[0])[i]
    s, F, T = by_hand(deg)
    assert force.real == pytest.approx(-F, rel=1e-12) and abs(force.imag) <= 1e-12 * F
    assert float(r.effort[i]) == pytest.approx(T, rel=1e-9, abs=1e-9 * F * R)


def test_the_dead_centres_start_their_strokes():
    """At θ = 0 the out stroke begins (2.0 MPa), at 180° the return (0.1 MPa), not the out stroke's 0.2 MPa."""
    r = catalog.load(str(FILE)).solve()
    from graphkin.analytical.loads import applied

    f = applied(r.kinematics, r.mechanism.loads[0])
    assert -f[0].real == pytest.approx(2.0e6 * AREA, rel=1e-12)
    assert -f[3].real == pytest.approx(0.1e6 * AREA, rel=1e-12)


def test_a_sweep_samples_either_side_of_the_dead_centres():
    from graphkin.cycle import sweep
    from graphkin.cycle.sweep import switching_angles

    problem = catalog.load(str(FILE))
    ends = switching_angles(problem)
    assert any(abs(e) < 1e-9 or abs(e - 2 * math.pi) < 1e-9 for e in ends)
    assert any(abs(e - math.pi) < 1e-9 for e in ends)
    c = sweep(problem, 36)
    assert c.valid.all()


GOOD = FILE.read_text(encoding="utf-8")
BAD = [
    pytest.param('from = "inner dead centre"', 'from = "top"', ["loads[0].from", "inner dead centre"], id="from"),
    pytest.param("200, 0.2,  0.1\n", "", ["loads[0].table", "200 mm"], id="short-of-the-stroke"),
    pytest.param("50,  1.2,  0.1", "250,  1.2,  0.1", ["loads[0].table", "ascending"], id="descending"),
    pytest.param('omega = "300 rpm"\n', "", ["loads[0].table", "driver.omega"], id="return-needs-a-sense"),
    pytest.param("link = 4\npoint = \"P\"\nbore", "link = 3\npoint = \"P\"\nbore",
                 ["loads[0].link", "piston, link 4"], id="not-the-piston"),
    pytest.param("stroke [mm]", "stroke [deg]", ["loads[0].table", "stroke"], id="stroke-not-a-length"),
    pytest.param("0,   2.0,  0.1", "0,   2.0", ["loads[0].table", "cells"], id="row-short"),
]


@pytest.mark.parametrize("old, new, named", BAD)
def test_bad_stroke_table(capsys, tmp_path, old, new, named):
    assert GOOD.count(old) == 1
    solve_refuses(capsys, tmp_path, GOOD.replace(old, new), *named)


def test_from_needs_a_stroke_table(capsys, tmp_path):
    text = GOOD.replace("stroke [mm], pressure [MPa], return [MPa]", "angle [deg], pressure [MPa]")
    for row in ("0,   2.0,  0.1", "50,  1.2,  0.1", "100, 0.6,  0.1", "200, 0.2,  0.1"):
        text = text.replace(row, row.rsplit(",", 1)[0])
    f = tmp_path / "p.toml"
    f.write_text(text, encoding="utf-8")
    assert main(["solve", str(f)]) == 2
    one_error_line(capsys.readouterr().err, "loads[0].from", "crank angle")
