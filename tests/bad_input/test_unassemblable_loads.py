"""Every kind of load on a cycle that leaves the assembly range (issue 35).

A position the linkage cannot reach says why in its row (nan, not valid, the reason); every other position is
solved as if it had been asked for alone; ``graphkin solve`` and ``graphkin cycle`` end in one line naming the
position and exit 2, never in a traceback. Two linkages: the six-bar of ``sixbar_leaves_range.toml`` (a crank,
with slider friction and gravity), no solution from θ12 ≈ 181.4° to ≈ 341.3°, and the catalog's double slider
driven past its reach (s = ±600 mm; ±500 mm are dead points).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

from graphkin import catalog
from graphkin.cli import main
from graphkin.cycle import sweep
from graphkin.graphical import construct_forces
from graphkin.notation import position_text
from tests.bad_input.test_catalogue import one_error_line

SIXBAR = (Path(__file__).parents[1] / "problem" / "files" / "sixbar_leaves_range.toml").read_text(encoding="utf-8")
DOUBLE_SLIDER = catalog.path("double_slider").read_text(encoding="utf-8").replace(
    's = "200 mm"', 's = ["-600 mm", "-500 mm", "-300 mm", "0 mm", "200 mm", "450 mm", "500 mm", "550 mm", "600 mm"]')

CRANK_LOADS = {
    "force": '''
type = "force"
link = 3
point = "D"
force = ["10 N", "-50 N"]''',
    "force-active": '''
type = "force"
link = 6
point = "S"
force = ["10 N", "-50 N"]
active = { from = "100 deg", to = "300 deg" }''',
    "force-table": '''
type = "force"
link = 4
point = "B"
direction = "180 deg"
table = """
angle [deg], force [N]
0, 100
180, 400
"""''',
    "force-opposes-motion": '''
type = "force"
link = 6
point = "C"
force = ["30 N", "0 N"]
sense = "opposes motion"''',
    "force-working-stroke": '''
type = "force"
link = 4
point = "B"
force = ["-300 N", "0 N"]
sense = "working stroke"''',
    "torque": '''
type = "torque"
link = 6
torque = "5 N*m"''',
    "torque-table": '''
type = "torque"
link = 5
table = """
angle [deg], torque [N*m]
0, 1
180, 3
"""''',
    "torque-opposes-motion": '''
type = "torque"
link = 6
torque = "2 N*m"
sense = "opposes motion"''',
    # A power's stated speed is its link's at every position of the file (a contradicting one is refused): on the
    # crank, whose speed is constant, over the whole cycle.
    "power": '''
type = "power"
link = 2
power = "100 W"
speed = "300 rpm"''',
    "power-on-the-crank": '''
type = "power"
link = 2
power = "1 kW"''',
    "pressure": '''
type = "pressure"
link = 4
point = "B"
bore = "50 mm"
pressure = "0.5 MPa"
direction = "180 deg"''',
    "pressure-table": '''
type = "pressure"
link = 4
point = "B"
bore = "50 mm"
direction = "180 deg"
table = """
angle [deg], pressure [MPa]
0, 2
90, 1
360, 0.1
"""''',
    # Its outer dead centre (≈ 188.2°) is among the positions the six-bar cannot reach.
    "pressure-against-the-stroke": '''
type = "pressure"
link = 4
point = "B"
bore = "50 mm"
rod = "10 mm"
side = "crank"
back_pressure = "0.1 MPa"
direction = "180 deg"
from = "inner dead centre"
table = """
stroke [mm], pressure [MPa], return [MPa]
0, 2, 0.1
60, 1, 0.1
130, 0.2, 0.1
"""''',
    "spring-to-the-frame": '''
type = "spring"
links = [1, 6]
points = ["Q", "S"]
rate = "2 N/mm"
free_length = "80 mm"''',
    "spring-between-moving-links": '''
type = "spring"
links = [2, 6]
points = ["A", "C"]
rate = "1 N/mm"
free_length = "50 mm"''',
}

SLIDER_LOADS = {
    "force": '''
type = "force"
link = 3
point = "B"
force = ["0 N", "-40 N"]''',
    "force-table": '''
type = "force"
link = 4
point = "B"
direction = "270 deg"
table = """
position [mm], force [N]
-600, 10
600, 50
"""''',
    "force-opposes-motion": '''
type = "force"
link = 4
point = "B"
force = ["0 N", "20 N"]
sense = "opposes motion"''',
    "torque": '''
type = "torque"
link = 3
torque = "3 N*m"''',
    "torque-table": '''
type = "torque"
link = 3
table = """
position [mm], torque [N*m]
-600, -2
600, 4
"""''',
    # No power: its stated speed must be its link's at every position, and no link of the double slider turns at
    # one speed over the file's positions (the crank family above has one).
    "pressure-table": '''
type = "pressure"
link = 4
point = "B"
bore = "40 mm"
direction = "-90 deg"
table = """
position [mm], pressure [MPa]
-600, 0.1
600, 0.3
"""''',
    "spring": '''
type = "spring"
links = [1, 3]
points = ["O", "B"]
rate = "1 N/mm"
free_length = "300 mm"''',
}


@dataclass(frozen=True)
class Case:
    """A problem file's text, a position it cannot reach and one it can (as ``--at`` takes them)."""

    text: str
    unreached: str
    shown: str
    reached: str


def _loads(loads) -> str:
    return "".join(f"\n[[loads]]{body}\n" for body in loads)


def _cases():
    crank = dict(unreached="240 deg", shown="θ = 240°", reached="10 deg")
    for name, body in CRANK_LOADS.items():
        yield pytest.param(Case(SIXBAR + _loads([body]), **crank), id=f"crank-{name}")
    every = SIXBAR + _loads(CRANK_LOADS.values())
    yield pytest.param(Case(every, **crank), id="crank-every-load")
    yield pytest.param(Case(every + "\n[unknown]\nlink = 6\n", **crank), id="crank-every-load-unknown")
    yield pytest.param(Case(every + '\n[forward]\nI = "2 kg*m^2"\ntorque = "10 N*m"\n', **crank),
                       id="crank-every-load-forward")
    slider = dict(unreached="600 mm", shown="s = 600 mm", reached="200 mm")
    for name, body in SLIDER_LOADS.items():
        yield pytest.param(Case(DOUBLE_SLIDER + _loads([body]), **slider), id=f"slider-{name}")
    yield pytest.param(Case(DOUBLE_SLIDER + _loads(SLIDER_LOADS.values()), **slider), id="slider-every-load")


CASES = list(_cases())


def _write(tmp_path, case) -> str:
    path = tmp_path / "leaves_range.toml"
    path.write_text(case.text, encoding="utf-8")
    return str(path)


def _same(got, alone):
    """The values of a position solved among others equal those of the position solved alone (to rounding)."""
    got, alone = np.asarray(got), np.asarray(alone)
    assert got.shape == alone.shape and np.isfinite(alone).all()
    np.testing.assert_allclose(got, alone, rtol=1e-12, atol=1e-12 * max(np.abs(alone).max(), 1.0))


def _same_data(got, alone):
    """Two JSON values alike: the same keys and texts, numbers equal to rounding (:func:`_same`)."""
    if isinstance(alone, dict):
        assert got.keys() == alone.keys()
        for key in alone:
            _same_data(got[key], alone[key])
    elif isinstance(alone, list):
        assert len(got) == len(alone)
        for a, b in zip(got, alone):
            _same_data(a, b)
    elif isinstance(alone, float):
        _same([got], [alone])
    else:
        assert got == alone


def _unreached(why: str) -> bool:
    return "cannot be assembled" in why or "dead point" in why


@pytest.mark.parametrize("case", CASES)
def test_the_api_solves_every_position_it_can(tmp_path, case):
    problem = catalog.load(_write(tmp_path, case))
    r = problem.solve()
    assert r.valid.any() and not r.valid.all()
    for i in np.flatnonzero(~r.valid):
        assert _unreached(r.reason(i)), r.reason(i)
        assert math.isnan(r.effort[i]) and all(np.isnan(r[name][i]).all() for name in r.names())
    alone = problem.solve(at=problem.q[r.valid])
    assert alone.valid.all()
    _same(r.effort[r.valid], alone.effort)
    for name in r.names():
        _same(r[name][r.valid], alone[name])
    # The graphical route says why too, and a whole cycle (with its samples either side of every switch) the same.
    kin = problem.kinematics()
    bad = int(np.flatnonzero(~r.valid)[0])
    drawn = construct_forces(kin, bad)
    assert not drawn.valid and drawn.reason == kin.reason(bad)
    cycle = sweep(problem).analysis
    assert cycle.valid.any() and not cycle.valid.all()
    _same(cycle.effort[cycle.valid], problem.solve(at=cycle.kinematics.q[cycle.valid]).effort)


@pytest.mark.parametrize("case", CASES)
def test_solve_names_the_position_it_cannot_reach(tmp_path, capsys, case):
    path = _write(tmp_path, case)
    assert main(["solve", path, "--at", case.unreached]) == 2
    out, err = capsys.readouterr()
    one_error_line(err, path, case.shown, "cannot be assembled")
    assert "no solution: " in out
    # With a position it can reach: that one is solved as if alone.
    assert main(["solve", path, "--json", "--at", f"{case.unreached},{case.reached}"]) == 2
    out, err = capsys.readouterr()
    one_error_line(err, path, case.shown, "cannot be assembled")
    lost, found = json.loads(out)["positions"]
    assert not lost["valid"] and "cannot be assembled" in lost["reason"] and not lost["graphical"]["valid"]
    assert main(["solve", path, "--json", "--at", case.reached]) == 0
    out, err = capsys.readouterr()
    alone = json.loads(out)["positions"][0]
    assert found["valid"] and found.pop("index") == 1 and alone.pop("index") == 0
    _same_data(found, alone)


@pytest.mark.parametrize("case", CASES)
def test_cycle_names_the_first_position_it_cannot_reach(tmp_path, capsys, case):
    path = _write(tmp_path, case)
    problem = catalog.load(path)
    assert main(["cycle", path, "--json"]) == 2
    out, err = capsys.readouterr()
    data = json.loads(out)
    q, valid = np.array(data["input"]["values"]), np.array(data["valid"])
    assert valid.any() and not valid.all()
    first = position_text(q[np.flatnonzero(~valid)[0]], problem.mechanism.driver.crank)
    one_error_line(err, path, "positions have no solution", f"the first at {first}")
    reasons = {entry["index"]: entry["reason"] for entry in data["invalid"]}
    assert sorted(reasons) == list(np.flatnonzero(~valid)) and all(map(_unreached, reasons.values()))
    effort = data["effort"]["values"]
    assert all(effort[i] is None for i in reasons)
    alone = problem.solve(at=q[valid])
    _same([effort[i] for i in np.flatnonzero(valid)], alone.effort)
    for name, F in data["forces"].items():
        xy = np.array([[F["x"][i], F["y"][i]] for i in np.flatnonzero(valid)])
        _same(xy, alone[name])
    # The text report too: the cycle's results, then the same line.
    assert main(["cycle", path]) == 2
    out, text_err = capsys.readouterr()
    assert text_err == err and "Peak joint forces" in out
