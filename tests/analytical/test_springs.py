"""Linear springs between two points (issue 25): Hooke's law on each end, in both routes.

The equilibrium of every link, the power balance and graphical = analytical run on random linkages with springs
drawn among their loads (tests/strategies.py); here the spring itself: its ends' forces are equal and opposite
along the spring, their power is the rate of loss of its strain energy ½ k (L − L0)², and a static linkage held
by a spring gives the torque worked out by hand.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from graphkin.analytical import applied, solve_forces
from graphkin.kinematics import solve_kinematics
from graphkin.model import Driver, Link, Mechanism, Revolute, SpringForce, spring
from graphkin.report import constructions, cross_check
from tests.physics import SETTINGS
from tests.strategies import families


def _with_a_spring(data, family):
    mech, q, q_dot, q_ddot = data.draw(families[family])
    links = [lk for lk in mech.links if lk.points]
    a, b = data.draw(st.permutations(links))[:2]
    pa, pb = data.draw(st.sampled_from(sorted(a.points))), data.draw(st.sampled_from(sorted(b.points)))
    if a.number == mech.frame and b.number == mech.frame:
        return None
    k, L0 = data.draw(st.floats(1.0, 1e4)), data.draw(st.one_of(st.just(0.0), st.floats(1e-3, 1.0)))
    loads = spring((a.number, b.number), (pa, pb), k, L0, frame=mech.frame, name="this spring")
    return Mechanism(mech.links, mech.joints, mech.driver, [*mech.loads, *loads], mech.gravity, dict(mech.assembly),
                     frame=mech.frame), \
        q, q_dot, q_ddot, (a.number, pa, b.number, pb, k, L0)


@pytest.mark.parametrize("family", sorted(families))
@SETTINGS
@given(data=st.data())
def test_a_springs_power_is_the_loss_of_its_strain_energy(family, data):
    drawn = _with_a_spring(data, family)
    if drawn is None:
        return
    mech, q, q_dot, q_ddot, (a, pa, b, pb, k, L0) = drawn
    kin = solve_kinematics(mech, q, q_dot, q_ddot)
    ends = [ld for ld in mech.loads if isinstance(ld, SpringForce) and ld.name == "this spring"]
    A, B = kin.position(a, pa), kin.position(b, pb)
    d = B - A
    L = np.hypot(*d.T)
    # Ends on one pin (A of the coupler and A of the crank) give a spring of no length and no line.
    assume(np.all(L > 1e-6 * (1.0 + float(np.abs(A).max()))))
    L_dot = np.sum(d * (kin.velocity(b, pb) - kin.velocity(a, pa)), axis=-1) / L
    power = sum(np.sum(np.column_stack([applied(kin, e).real, applied(kin, e).imag]) * kin.velocity(e.link, e.point),
                       axis=-1) for e in ends)
    speed = max(np.hypot(*kin.velocity(a, pa).T).max(), np.hypot(*kin.velocity(b, pb).T).max())
    np.testing.assert_allclose(power, -k * (L - L0) * L_dot, rtol=1e-9, atol=1e-12 * k * float((L + L0).max()) * speed)
    if len(ends) == 2:  # both ends moving: equal and opposite
        np.testing.assert_allclose(applied(kin, ends[0]), -applied(kin, ends[1]), rtol=0, atol=1e-12 * k * (L + L0).max())
    r = solve_forces(kin)
    assert cross_check(r, constructions(r)).valid.tolist() == r.valid.tolist()


def test_a_lever_held_by_a_spring():
    """A lever 2 pivoted at O, its end A 200 mm out at θ; a spring of 5 N/mm, free length 100 mm, from A to the
    frame point Q = (0, 300 mm). By hand at θ = 0: L = √(0.2² + 0.3²) = 0.36056 m, F = 5000 (L − 0.1) = 1302.8 N
    from A towards Q, moment about O: r × F = 0.2 × F_y = 0.2 × 1302.8 × 0.3/L = 216.8 N·m; the driving torque
    balances it: T12 = −216.8 N·m."""
    links = [Link(1, {"O": (0.0, 0.0), "Q": (0.0, 0.3)}), Link(2, {"O": (0.0, 0.0), "A": (0.2, 0.0)})]
    mech = Mechanism(links, [Revolute((1, 2), "O")], Driver(2), spring((2, 1), ("A", "Q"), 5000.0, 0.1))
    kin = solve_kinematics(mech, [0.0, math.pi / 2], 0.0, 0.0)
    r = solve_forces(kin)
    L = math.hypot(0.2, 0.3)
    F = 5000.0 * (L - 0.1)
    assert r.effort[0] == pytest.approx(-0.2 * F * 0.3 / L, rel=1e-14)
    # at 90° A is (0, 0.2 m), on the line OQ: the spring's pull passes through O and needs no torque
    assert r.effort[1] == pytest.approx(0.0, abs=1e-12 * F)
    for i, c in enumerate(constructions(r)):
        assert c.valid and c.effort == pytest.approx(r.effort[i], rel=1e-12, abs=1e-12 * F)
