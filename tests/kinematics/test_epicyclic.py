"""Epicyclic (planetary) trains: gears on a moving carrier, located group by group (issue 25).

A planet pivoted on a driven arm meshes with a sun or an annulus: relative to the arm the two turn as a gear
pair on fixed axes (Willis): (ω_planet − ω_arm) / (ω_sun − ω_arm) = −r_sun / r_planet for an external mesh,
+r_annulus / r_planet for an internal one. These tests write Willis's equation out by hand and check the
solver against it, and against the rolling of the pitch circles.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin.errors import ModelError
from graphkin.kinematics import GearGroup, decompose, solve_kinematics
from graphkin.model import Driver, GearMesh, Link, Mechanism, Revolute, Torque


def train(sun: bool = True, ring: bool = False, r_ring=0.150, r_planet=0.060, r_sun=0.030):
    """Arm 2 about O; planet 3 at C on the arm; an annulus on the frame (``ring``) or a sun on the frame (not ``ring``);
    with ``sun`` and ``ring``, also sun 4 turning about O and meshing with the planet."""
    arm = (r_ring - r_planet) if ring else (r_sun + r_planet)
    links = [Link(1, {"O": (0.0, 0.0)}), Link(2, {"O": (0.0, 0.0), "C": (arm, 0.0)}, name="arm"),
             Link(3, {"C": (0.0, 0.0)}, name="planet")]
    joints = [Revolute((1, 2), "O"), Revolute((2, 3), "C")]
    if ring:
        joints.append(GearMesh((1, 3), ("O", "C"), (r_ring, r_planet), internal=True))
        if sun:
            links.append(Link(4, {"O": (0.0, 0.0)}, name="sun"))
            joints += [Revolute((1, 4), "O"), GearMesh((4, 3), ("O", "C"), (r_sun, r_planet))]
    else:
        joints.append(GearMesh((1, 3), ("O", "C"), (r_sun, r_planet)))
    return Mechanism(links, joints, Driver(2), [Torque(3, 10.0)])


def test_a_planet_on_a_driven_arm_rolls_on_a_fixed_sun():
    mech = train(ring=False)
    groups = decompose(mech)
    assert isinstance(groups[1], GearGroup) and (groups[1].k, groups[1].j, groups[1].b) == (3, 1, 2)
    th = np.radians([0.0, 30.0, 200.0])
    kin = solve_kinematics(mech, th, 12.0, 3.0)
    # Willis, sun fixed: ω3 − ω2 = −(r_sun / r_planet)(0 − ω2) = 0.5 ω2, so ω3 = 1.5 ω2.
    np.testing.assert_allclose(kin.omega[3], 1.5 * 12.0, rtol=1e-15)
    np.testing.assert_allclose(kin.alpha[3], 1.5 * 3.0, rtol=1e-15)
    np.testing.assert_allclose(kin.theta[3], 1.5 * th, rtol=1e-15, atol=1e-15)


def test_a_planet_in_a_fixed_annulus_turns_backwards():
    mech = train(ring=True, sun=False)
    kin = solve_kinematics(mech, [0.4], 10.0, 0.0)
    # Willis, annulus fixed: ω3 − ω2 = +(150/60)(0 − ω2), ω3 = −1.5 ω2.
    assert kin.omega[3][0] == pytest.approx(-15.0, rel=1e-15)
    # The planet's pitch point on the annulus is still: v(C) + ω3 × (P − C) = 0 with P beyond C, 60 mm out.
    C = kin.position(3, "C")[0]
    P = C + 0.060 * C / np.hypot(*C)
    v = kin.velocity(3, "C")[0] + kin.omega[3][0] * np.array([-(P - C)[1], (P - C)[0]])
    assert np.hypot(*v) <= 1e-14 * np.hypot(*kin.velocity(3, "C")[0])


def test_a_sun_on_the_arms_axis_is_located_from_the_planet():
    """Sun 4, pivoted on the frame at O where the arm turns, meshes with the planet on the arm: its group's carrier
    is the arm (both centres are points of it), though the sun's pin is on the frame."""
    mech = train(ring=True, sun=True)
    g = decompose(mech)[-1]
    assert isinstance(g, GearGroup) and (g.k, g.j, g.b, g.support) == (4, 3, 2, 1)
    kin = solve_kinematics(mech, [1.0], 10.0, 2.0)
    # Sun, planet and annulus on the arm (Willis): (ω4 − ω2)/(0 − ω2) = −r_ring / r_sun → ω4 = ω2 (1 + 150/30).
    assert kin.omega[4][0] == pytest.approx(60.0, rel=1e-14)
    assert kin.alpha[4][0] == pytest.approx(12.0, rel=1e-14)
    np.testing.assert_allclose(kin.position(4, "O")[0], [0.0, 0.0], atol=1e-17)


def test_a_sun_driven_train_says_what_cannot_be_located():
    """With the sun driven, the arm and the planet form a group that is neither a dyad nor a gear pair: the
    message says so, and the docs say to drive the arm (the same train, the same forces)."""
    mech = train(ring=True, sun=True)
    driven = Mechanism(mech.links, mech.joints, Driver(4), [Torque(2, 1.0)])
    with pytest.raises(ModelError, match="cannot be located"):
        decompose(driven)


def test_an_annulus_and_a_pinion_of_one_size_are_refused():
    with pytest.raises(ModelError, match="annulus larger than its pinion"):
        GearMesh((1, 3), ("O", "C"), (0.05, 0.05), internal=True)


def test_a_mesh_centre_away_from_the_pivot_is_refused():
    links = [Link(1, {"O": (0.0, 0.0), "Q": (0.01, 0.0)}), Link(2, {"O": (0.0, 0.0), "C": (0.09, 0.0)}),
             Link(3, {"C": (0.0, 0.0)})]
    joints = [Revolute((1, 2), "O"), Revolute((2, 3), "C"), GearMesh((1, 3), ("Q", "C"), (0.03, 0.06))]
    with pytest.raises(ModelError, match="centre Q of gear 1 is not at its pivot O"):
        decompose(Mechanism(links, joints, Driver(2)))


def test_gears_whose_centres_do_not_stay_apart_are_refused():
    """Planet 3 on arm 2, gear 4 on rocker 5 of a four-bar driven by the arm: nothing keeps their centres a fixed
    distance apart, so the mesh is refused with the reason."""
    links = [Link(1, {"O": (0.0, 0.0), "Q": (0.5, 0.0)}),
             Link(2, {"O": (0.0, 0.0), "C": (0.09, 0.0), "E": (0.0, 0.05)}), Link(3, {"C": (0.0, 0.0)}),
             Link(4, {"D": (0.0, 0.0)}), Link(5, {"Q": (0.0, 0.0), "F": (0.3, 0.0), "D": (0.2, 0.0)}),
             Link(6, {"E": (0.0, 0.0), "F": (0.45, 0.0)})]
    joints = [Revolute((1, 2), "O"), Revolute((2, 3), "C"), GearMesh((1, 3), ("O", "C"), (0.03, 0.06)),
              Revolute((2, 6), "E"), Revolute((6, 5), "F"), Revolute((1, 5), "Q"), Revolute((5, 4), "D"),
              GearMesh((3, 4), ("C", "D"), (0.06, 0.05))]
    with pytest.raises(ModelError, match="fixed distance apart"):
        decompose(Mechanism(links, joints, Driver(2)))


def test_the_external_pair_on_the_frame_is_unchanged():
    """The gear pair's step is the same arithmetic as before the carrier was generalised: the catalog's gearset."""
    from graphkin import catalog

    kin = catalog.load("gearset").kinematics()
    assert kin.omega[3][0] == -(100 / 40) * kin.omega[2][0]
    assert math.isclose(kin.theta[3][0], -(100 / 40) * kin.theta[2][0], abs_tol=0)
