"""The sliding velocity, sliding acceleration and Coriolis component of each slider on a moving guide, as fields of
``solve --json`` (``positions[].sliding``) and lines of the printed report (issue 35, item 6).

Checked three ways:

- against the velocity and acceleration polygons (:func:`graphkin.graphical.construct_kinematics`), which build
  the same vectors v_B3B2, a^c_B3B2 and a^r_B3B2 by construction, over a turn of the shaper;
- against what the shaper's book (Marghitu's MATLAB programs, Ex. 6.1; catalog ``shaper_six_bar``) prints: the
  block's v_B and a_B, the lever's ω3 and α3 and the points; the sliding pair's rates follow from them by hand,
  a_B = a_B3 + a^c + a^r u, to the digits those printed values carry;
- against Bevan's rotary engine (*The Theory of Machines*, 3rd ed., ch. 3, Ex. 8, p. 112; FOSSEE Python Textbook
  Companion, ch3): the cylinders turn at 1200 rpm about O, the piston slides in them, its rod CP turns about the
  fixed crank pin C (OC = 3 in, CP = 9 in, the cylinder 55° from OC). The book's figure gives the sliding velocity
  as ω · OM (OM = 2.95 in: 30.9 ft/s), the Coriolis component as ω² · OU (OU = 5.90 in: 2ω v = 7764 ft/s²) and the
  acceleration of P relative to Q, the cylinder's point under it, as ω² · OV (OV = 6.06 in). The figure is drawn to
  about 0.3 %: OP, which the geometry fixes at 10.379 in, reads 10.35 in. (The companion also prints UV = 1.29 in,
  1698 ft/s², as the sliding acceleration; that reading disagrees with the figure's own OU and OV, whose sliding
  component is √(6.06² − 5.90²) = 1.38 in, and is not used.)
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from graphkin import catalog
from graphkin.cli import main
from graphkin.graphical import construct_kinematics
from graphkin.problem import parse_problem
from graphkin.report import solution
from graphkin.units.systems import unit_system

ROTARY = """title = "Bevan, ch. 3, Ex. 8: a rotary engine, the cylinders turning about O and the crank pin C fixed"
[frame]
points = { O = ["0 in", "0 in"], C = ["3 in", "0 in"] }
[[links]]
number = 2
name = "cylinders"
points = { O = ["0 in", "0 in"] }
mass = "0 kg"
[[links]]
number = 3
name = "connecting rod CP"
points = { C = ["0 in", "0 in"], P = ["9 in", "0 in"] }
mass = "0 kg"
[[links]]
number = 4
name = "piston"
points = { P = ["0 in", "0 in"] }
mass = "0 kg"
[[joints]]
type = "revolute"
links = [1, 2]
point = "O"
[[joints]]
type = "revolute"
links = [1, 3]
point = "C"
[[joints]]
type = "revolute"
links = [3, 4]
point = "P"
[[joints]]
type = "prismatic"
guide = 2
slider = 4
point = "P"
through = "O"
direction = "0 deg"
[driver]
type = "crank"
link = 2
theta = "55 deg"
omega = "1200 rpm"
sense = "clockwise"
"""


def _sliding(problem, at=None):
    return solution(problem, problem.solve(at))["positions"]


def _vectors(kin, i):
    c = construct_kinematics(kin, i)
    assert c.valid, c.reason
    return {v.name: complex(*v.vector) for s in c.steps for v in s.vectors}


@pytest.mark.parametrize("name, at, pair", [
    ("shaper_six_bar", np.radians(np.arange(0.0, 360.0, 15.0)), ("B3B2", -1.0)),  # the polygon names B on the lever
    ("rotary", np.radians(np.arange(0.0, 360.0, 30.0)), ("PP2", 1.0)),  # P (on the piston) relative to P2
])
def test_the_fields_are_the_polygons_vectors(name, at, pair):
    """The polygons construct v_r, a^c and a^r from the positions alone; the JSON's fields are the same vectors
    (reversed where the polygon takes the pair the other way round) to 1e-9 of the largest."""
    problem = catalog.load(name) if name != "rotary" else parse_problem(ROTARY)
    kin = problem.kinematics(at=at)
    positions = _sliding(problem, at)
    polygon, sign = pair
    for i, p in enumerate(positions):
        assert p["valid"], p["reason"]
        (s,) = p["sliding"]
        u = complex(*s["guide_direction"])
        vec = _vectors(kin, i)
        scale_v = max(abs(v) for k, v in vec.items() if k.startswith("v_"))
        scale_a = max(abs(v) for k, v in vec.items() if k.startswith("a"))
        assert abs(sign * vec[f"v_{polygon}"] - s["velocity"] * u) <= 1e-9 * scale_v
        assert abs(sign * vec[f"a^r_{polygon}"] - s["acceleration"] * u) <= 1e-9 * scale_a
        assert abs(sign * vec[f"a^c_{polygon}"] - complex(*s["coriolis"])) <= 1e-9 * scale_a


def test_the_coriolis_component_is_twice_the_guides_omega_times_the_sliding_velocity():
    problem = catalog.load("shaper_six_bar")
    for p in _sliding(problem, np.radians([20.0, 45.0, 200.0])):
        (s,) = p["sliding"]
        w3 = p["links"]["3"]["omega"]
        u = complex(*s["guide_direction"])
        assert complex(*s["coriolis"]) == pytest.approx(2j * w3 * s["velocity"] * u, rel=1e-13)
        # and the decomposition closes on the block's own acceleration: a_B2 = a_B3 + a^c + a^r u
        B = p["links"]["2"]["points"]["B"]
        D = p["links"]["3"]["points"]["D"]
        r = complex(*B["position"]) - complex(*D["position"])
        a_B3 = (1j * p["links"]["3"]["alpha"] - w3**2) * r
        a_B2 = complex(*B["acceleration"])
        assert a_B2 == pytest.approx(a_B3 + complex(*s["coriolis"]) + s["acceleration"] * u, rel=1e-12)


# -- the shaper's book -------------------------------------------------------------------------------------------

PRINTED = {  # Ex. 6.1's printed values and half a unit of their last digit
    "vB": ((-2.96, 2.96), 0.005), "aB": ((-62.034, -62.034), 0.0005),  # aB printed as aC2 = aB
    "omega3": (6.46, 0.005), "alpha3": (30.4, 0.05), "rB": ((0.141, 0.141), 0.0005), "rD": ((0.0, -0.400), 0.0005),
}


def _by_hand(x):
    """v_r, a^r and |a^c| of the block B on the lever DC from the printed values: B3 turns with the lever about D."""
    vB, aB, w3, al3, rB, rD = complex(x[0], x[1]), complex(x[2], x[3]), x[4], x[5], complex(x[6], x[7]), complex(x[8], x[9])
    r = rB - rD
    u = r / abs(r)
    v_r = ((vB - 1j * w3 * r) * u.conjugate()).real
    a_r = ((aB - (1j * al3 - w3**2) * r) * u.conjugate()).real
    return np.array([v_r, a_r, abs(2 * w3 * v_r)])


def test_the_shapers_sliding_pair_from_the_books_printed_values():
    """Worked by hand from what the program prints, each result good to the sum of what each printed digit leaves
    open (half a unit of its last digit, times how much the result moves with it)."""
    x, half = [], []
    for value, h in PRINTED.values():
        for c in np.atleast_1d(value):
            x.append(float(c))
            half.append(h)
    x, half = np.array(x), np.array(half)
    book = _by_hand(x)
    tolerance = sum(np.abs(_by_hand(x + h * e) - _by_hand(x - h * e)) / 2 for h, e in zip(half, np.eye(len(x))))
    (s,) = _sliding(catalog.load("shaper_six_bar"))[0]["sliding"]
    ours = np.array([s["velocity"], s["acceleration"], math.hypot(*s["coriolis"])])
    assert np.all(np.abs(ours - book) <= tolerance), (ours, book, tolerance)


# -- Bevan's rotary engine ---------------------------------------------------------------------------------------

DRAWN = 0.003  # the figure's accuracy: OP reads 10.35 in where the geometry gives 10.379 in
IN, FT = 0.0254, 0.3048


def test_the_rotary_engine_is_bevans_geometry():
    kin = parse_problem(ROTARY).kinematics()
    OP = math.hypot(*kin.position(4, "P")[0]) / IN
    assert OP == pytest.approx(3 * math.cos(math.radians(55)) + math.sqrt(81 - (3 * math.sin(math.radians(55))) ** 2),
                               rel=1e-12)
    assert OP == pytest.approx(10.35, rel=DRAWN)


def test_the_rotary_engines_sliding_pair_is_bevans():
    problem = parse_problem(ROTARY)
    (p,) = _sliding(problem)
    (s,) = p["sliding"]
    w = 1200 * math.pi / 30
    assert (s["slider"], s["guide"], s["point"]) == (4, 2, "P")
    assert abs(s["velocity"]) / w / IN == pytest.approx(2.95, rel=DRAWN)  # OM
    assert abs(s["velocity"]) / FT == pytest.approx(30.9, rel=DRAWN)  # printed
    a_c = complex(*s["coriolis"])
    assert abs(a_c) / w**2 / IN == pytest.approx(5.90, rel=DRAWN)  # OU
    assert abs(a_c) / FT == pytest.approx(7764, rel=DRAWN)  # printed
    u = complex(*s["guide_direction"])
    assert abs(a_c + s["acceleration"] * u) / w**2 / IN == pytest.approx(6.06, rel=DRAWN)  # OV: a_P − a_Q


def test_the_report_prints_them_in_the_units_asked(capsys, tmp_path):
    """Bevan's engine in feet per second: v_P4P2 and its Coriolis component, and the JSON says its units."""
    path = tmp_path / "rotary.toml"
    path.write_text(ROTARY, encoding="utf-8")
    assert main(["solve", str(path), "--units", "US"]) == 0
    out = capsys.readouterr().out
    line = next(x for x in out.splitlines() if "v_P4P2" in x)
    (s,) = _sliding(parse_problem(ROTARY))[0]["sliding"]
    assert f"v_P4P2 = {s['velocity'] / FT:.4g} ft/s" in line and "P of link 4 on link 2" in line
    assert f"a^r_P4P2 = {s['acceleration'] / FT:.4g} ft/s²" in line
    assert "Coriolis a^c_P4P2 = 2 ω2 × v_P4P2 = 7753 ft/s²" in out
    assert main(["solve", str(path), "--units", "US", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["units"]["positions[].sliding[].velocity"] == unit_system("US").units["velocity"]
    assert data["positions"][0]["sliding"][0]["velocity"] == pytest.approx(s["velocity"] / FT, rel=1e-12)


def test_a_linkage_without_a_moving_guide_has_none():
    (p,) = _sliding(catalog.load("double_slider"))
    assert p["sliding"] == []
