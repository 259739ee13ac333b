"""A gear mesh's efficiency (issue 35, item 6): the driven gear receives η times the power the driving gear gives,
relative to the carrier, and the side that loses follows the way the power flows.

Checked against the arithmetic a book does, written out here without graphkin:

- on fixed axes, Khurmi & Gupta's way with a train's efficiency (ch. 13, Ex. 13.23: the output torque is η times
  the ideal, the fixed member's torque follows from the equilibrium of the whole, T_out − T_in): with mesh
  efficiencies η1, η2, … along the path, that is graphkin's answer with η = η1 η2 …, whichever gear drives;
- in an epicyclic train (Khurmi & Gupta, Ex. 13.20, catalog ``epicyclic_khurmi``: the sun driven with 100 N·m, the
  annulus held, the arm the output), where the meshes lose only what flows through them relative to the arm:
  relative to the arm the train is sun → planet → annulus on fixed axes, so the annulus's torque is η² (or 1/η²,
  when the power flows the other way) times the ideal 400 N·m, and the arm takes the rest;
- the power lost is (1 − η) of the power through each mesh relative to its carrier;
- both routes and the matrix method agree at every position (the tooth force's line off the pitch point).
"""

from __future__ import annotations

from importlib.resources import files

import numpy as np
import pytest

from graphkin import catalog
from graphkin.analytical.matrix import solve_matrix
from graphkin.analytical.virtual_work import effort_by_virtual_work
from graphkin.errors import GraphkinError
from graphkin.graphical import construct_forces
from graphkin.problem import parse_problem
from graphkin.report import constructions, cross_check
from tests.bad_input.test_catalogue import solve_refuses

GEARSET = (files("graphkin.catalog") / "gearset.toml").read_text(encoding="utf-8")
"""Gear 2 (100 mm, driven at 120 rpm) and pinion 3 (40 mm) on fixed axes; 8 N·m on the pinion."""
EPICYCLIC = catalog.path("epicyclic_khurmi").read_text(encoding="utf-8")
RING = 'radii = ["160 mm", "60 mm"]\ninternal = true'


def edit(text, *pairs):
    for old, new in pairs:
        assert old in text, old
        text = text.replace(old, new, 1)
    return text


def pair(eta: float, load: str = "8 N*m", alpha: str = "0 rad/s^2") -> str:
    return edit(GEARSET, ('pressure_angle = "20 deg"', f'pressure_angle = "20 deg"\nefficiency = {eta}'),
                ('alpha = "50 rad/s^2"', f'alpha = "{alpha}"'), ('torque = "8 N*m"', f'torque = "{load}"'))


def cross(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def both_routes_agree(result):
    assert cross_check(result, constructions(result)).valid.all()
    matrix = solve_matrix(result)
    np.testing.assert_allclose(matrix.effort, result.effort, rtol=1e-11)
    for key, F in result.forces.items():
        np.testing.assert_allclose(matrix.forces[key], F, rtol=0, atol=1e-10 * np.abs(F).max())


@pytest.mark.parametrize("eta", [1.0, 0.97, 0.8])
def test_a_resisting_pinion_needs_the_ideal_torque_over_eta(eta):
    """The pinion resists (8 N·m against its clockwise turning): the power flows from gear 2 to it, and T12 ω2 = −T13
    ω3 / η (the output torque is η times the ideal, so the input is the ideal over η)."""
    r = parse_problem(pair(eta)).solve(np.radians([0.0, 70.0, 200.0]))
    w2, w3 = r.kinematics.omega[2], r.kinematics.omega[3]
    np.testing.assert_allclose(r.effort * w2, -8.0 * w3 / eta, rtol=1e-13)
    assert r.effort[0] == pytest.approx(20.0 / eta, rel=1e-13)
    both_routes_agree(r)


@pytest.mark.parametrize("eta", [0.97, 0.8])
def test_an_overhauling_pinion_loses_on_the_other_side(eta):
    """With the load turned round (it drives the pinion the way it turns) the power flows from the pinion to gear 2:
    gear 2 now receives η times the ideal, T12 ω2 = −η T13 ω3."""
    r = parse_problem(pair(eta, load="-8 N*m")).solve(np.radians([0.0, 130.0]))
    w2, w3 = r.kinematics.omega[2], r.kinematics.omega[3]
    np.testing.assert_allclose(r.effort * w2, -eta * -8.0 * w3, rtol=1e-13)
    both_routes_agree(r)


def test_the_frame_holds_the_difference():
    """Khurmi's holding torque: the frame (the gearbox) takes −(T_in + T_out), through the pivots' forces."""
    eta = 0.9
    r = parse_problem(pair(eta)).solve()
    kin = r.kinematics
    held = sum(cross(kin.position(link, f"O{link}")[0], r.force(link, 1)[0]) for link in (2, 3))
    assert held == pytest.approx(r.effort[0] + 8.0, rel=1e-12)
    assert r.effort[0] + 8.0 == pytest.approx(20.0 / eta + 8.0)


THREE = '''title = "Three gears on fixed axes: 2 drives the idler 3, which drives 4"
analysis = "static"
[frame]
points = { O2 = ["0 mm", "0 mm"], O3 = ["140 mm", "0 mm"], O4 = ["140 mm", "100 mm"] }
[[links]]
number = 2
points = { O2 = ["0 mm", "0 mm"] }
[[links]]
number = 3
points = { O3 = ["0 mm", "0 mm"] }
[[links]]
number = 4
points = { O4 = ["0 mm", "0 mm"] }
[[joints]]
type = "revolute"
links = [1, 2]
point = "O2"
[[joints]]
type = "revolute"
links = [1, 3]
point = "O3"
[[joints]]
type = "revolute"
links = [1, 4]
point = "O4"
[[joints]]
type = "gear"
links = [2, 3]
centers = ["O2", "O3"]
radii = ["100 mm", "40 mm"]
efficiency = 0.96
[[joints]]
type = "gear"
links = [3, 4]
centers = ["O3", "O4"]
radii = ["40 mm", "60 mm"]
efficiency = "95 %"
[driver]
type = "crank"
link = 2
theta = "10 deg"
omega = "100 rpm"
[[loads]]
type = "torque"
link = 4
torque = "-30 N*m"
'''


def test_a_train_on_fixed_axes_has_the_product_of_its_meshes_efficiencies():
    """Output ω4 = ω2 r2/r4 (the idler only turns it round); the output torque is η2 η3 times the ideal."""
    r = parse_problem(THREE).solve()
    w = r.kinematics.omega
    assert w[4][0] == pytest.approx(w[2][0] * 100 / 60, rel=1e-13)
    assert r.effort[0] * w[2][0] == pytest.approx(30.0 * w[4][0] / (0.96 * 0.95), rel=1e-13)
    both_routes_agree(r)


# -- the epicyclic train -----------------------------------------------------------------------------------------

def epicyclic(eta: float, omega: str = "100 rpm") -> str:
    return edit(EPICYCLIC, (RING, f"{RING}\nefficiency = {eta}"),
                ('radii = ["40 mm", "60 mm"]', f'radii = ["40 mm", "60 mm"]\nefficiency = {eta}'),
                ('theta = "30 deg"', f'theta = "30 deg"\nomega = "{omega}"'))


def _moment_on_frame(r, i):
    # The tooth force of the planet on the annulus acts on the line through the mesh's contact; its moment about O
    # is the same from any point of that line: take it from the graphical route's contact point.
    c = construct_forces(r.kinematics, i)
    X = c.contacts[(1, 3)]
    return cross(X, r.force(3, 1)[i])


@pytest.mark.parametrize("eta", [1.0, 0.98, 0.9])
@pytest.mark.parametrize("omega, into_the_sun", [("100 rpm", True), ("-100 rpm", False)])
def test_khurmis_train_with_mesh_efficiencies(eta, omega, into_the_sun):
    """Relative to the arm (N_S/N_C = 5: the sun turns at 4 ω_C, the annulus at −ω_C) the sun's 100 N·m puts
    400 ω_C in (ω_C > 0), and the annulus takes η² of it out: its holding torque is 400 η². Turning the other way
    the annulus puts the power in and the sun takes η² of it: 400 / η². The arm balances the rest."""
    r = parse_problem(epicyclic(eta, omega)).solve(np.radians([30.0, 100.0, 250.0]))
    T_E = 400.0 * eta**2 if into_the_sun else 400.0 / eta**2
    np.testing.assert_allclose(r.effort, -(100.0 + T_E), rtol=1e-13)  # the arm's torque, the output
    for i in range(r.n):
        assert -_moment_on_frame(r, i) == pytest.approx(T_E, rel=1e-12)
    both_routes_agree(r)


def test_the_power_lost_is_what_each_mesh_passes_relative_to_the_arm_times_one_less_eta():
    eta = 0.9
    r = parse_problem(epicyclic(eta)).solve()
    w = r.kinematics.omega
    w_arm, w_sun = w[2][0], w[4][0]
    into_the_train = 100.0 * w_sun + r.effort[0] * w_arm  # the sun's torque and the arm's, absolute
    through_sun_mesh = 100.0 * (w_sun - w_arm)  # relative to the arm
    lost = (1 - eta) * through_sun_mesh + (1 - eta) * eta * through_sun_mesh
    assert into_the_train == pytest.approx(lost, rel=1e-12)
    assert into_the_train / (100.0 * w_sun) == pytest.approx(1 - (0.2 + 0.8 * eta**2), rel=1e-12)


def test_the_graphical_route_says_where_the_tooth_force_acts():
    c = construct_forces(parse_problem(epicyclic(0.98)).kinematics(), 0)
    captions = [s.caption for s in c.steps if s.kind == "line" and "efficiency" in s.caption]
    assert len(captions) == 2
    # Named by its mesh (P34′), as each of the train's two meshes is named apart (issue 36).
    assert "η = 0.98" in captions[0] and "P34′" in captions[0] and "driven gear 3" in captions[0]
    pitch, contact = np.array(c.pitch_points[(3, 4)]), np.array(c.contacts[(3, 4)])
    # The sun drives: its arm grows from 40 mm, the planet's shrinks from 60 mm, in the ratio η r_P / r_S.
    rho_sun = np.hypot(*contact)
    assert rho_sun > np.hypot(*pitch)
    assert (0.1 - rho_sun) / rho_sun == pytest.approx(0.98 * 60 / 40, rel=1e-12)


# -- what it refuses ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("eta, named", [
    ("1.2", ["at most 1"]), ("0", ["above 0"]), ('"80 mm"', ["dimensionless"]),
    ("0.3", ["internal mesh", "0.375"]),
])
def test_an_efficiency_no_mesh_can_have_is_refused(capsys, tmp_path, eta, named):
    text = edit(EPICYCLIC, (RING, f"{RING}\nefficiency = {eta}"),
                ('theta = "30 deg"', 'theta = "30 deg"\nomega = "100 rpm"'))
    solve_refuses(capsys, tmp_path, text, "joints[3].efficiency", *named)


def test_an_efficiency_needs_the_motion(capsys, tmp_path):
    text = edit(EPICYCLIC, (RING, f"{RING}\nefficiency = 0.98"))
    solve_refuses(capsys, tmp_path, text, "joints[3].efficiency", "driver.omega")


def test_an_unknown_effort_does_not_combine_with_an_efficiency(capsys, tmp_path):
    text = epicyclic(0.98) + '\n[unknown]\nlink = 4\n'
    text = edit(text, ('[[loads]]\ntype = "torque"\nname = "TS"\nlink = 4\ntorque = "100 N*m"', ""))
    solve_refuses(capsys, tmp_path, text, "unknown", "joints[3]", "drive")


def test_virtual_work_says_it_cannot_see_the_loss():
    with pytest.raises(GraphkinError, match="efficiency of 0.98"):
        effort_by_virtual_work(parse_problem(epicyclic(0.98)).kinematics())


def test_a_percentage_is_a_fraction():
    mech = parse_problem(THREE).mechanism
    assert mech.joints[3].efficiency == 0.96
    assert mech.joints[4].efficiency == pytest.approx(0.95, rel=1e-15)  # "95 %" through pint's percent
