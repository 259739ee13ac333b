"""Properties of whole-cycle sweeps that any correct implementation satisfies (hypothesis).

* A load switched on over an interval is sampled just before and just after each switching
  angle, so the sweep brackets every jump of the driving torque.
* With the jumps bracketed, the trapezoidal average of the torque meets the second-order
  trapezoid bound against the exact −W/2π, wherever the interval lies (Söylemez §6.4.1 strip cutter, its
  cutting force moved to random angles): the work of a constant force is exact from the
  blade positions at the two ends, and the inertia loads do no net work over a turn.
* An offset slider-crank at an exact dead centre has a still slider: no Coulomb friction,
  for any crank, rod and offset.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from graphkin import catalog
from graphkin.cycle.sweep import SWITCH, sweep, switching_samples
from graphkin.model import Active, Prismatic

TURN = 2 * math.pi
CUTTER = catalog.load("strip_cutter")
SLIDER_CRANK = catalog.load("slider_crank_friction")

angles = st.floats(0.0, TURN, exclude_max=True, allow_nan=False)


def _cut_between(a: float, b: float):
    """The strip cutter with both cutting forces acting for a < θ12 < b (mod 2π)."""
    loads = tuple(dataclasses.replace(load, active=Active(a, b)) for load in CUTTER.mechanism.loads)
    return dataclasses.replace(CUTTER, mechanism=dataclasses.replace(CUTTER.mechanism, loads=loads))


def _work(problem, a: float, b: float) -> float:
    """Work done against the (constant) cutting forces while they act [J]: −F·(r(b) − r(a)) per blade."""
    kin = problem.kinematics(at=[a, b])
    return -sum(float(np.dot(load.force, np.diff(kin.position(load.link, load.point), axis=0)[0]))
                for load in problem.mechanism.loads)


@settings(max_examples=60, deadline=None)
@given(a=angles, b=angles, n=st.integers(8, 400))
def test_every_switch_is_bracketed(a, b, n):
    assume(1e-6 < (b - a) % TURN < TURN - 1e-6)  # an interval, not (within rounding) nothing or the whole turn
    problem = _cut_between(a, b)
    grid = np.linspace(0.0, TURN, n, endpoint=False)
    q = switching_samples(problem, grid)
    assert np.all(np.diff(q) > 0) and np.all(np.isin(grid, q))
    active = problem.mechanism.loads[0].active
    for end in (a, b):
        before, after = (end - SWITCH) % TURN, (end + SWITCH) % TURN
        assert np.any(np.isclose(q, before, rtol=0, atol=1e-15)) and np.any(np.isclose(q, after, rtol=0, atol=1e-15))
        assert active.mask(before) != active.mask(after)  # the load switches between the two samples


def _curvature(problem, a: float, b: float, n: int = 3600) -> float:
    """max |T''| [N·m/rad²] on the smooth pieces of the torque curve, by second differences on a fine grid."""
    theta = np.linspace(0.0, TURN, n, endpoint=False)
    T = problem.solve(at=theta).effort
    h = TURN / n
    d2 = (np.roll(T, -1) - 2 * T + np.roll(T, 1)) / h**2
    near = np.zeros(n, bool)
    for end in (a, b):  # second differences across a jump measure the jump, not the curvature
        near |= np.abs((theta - end + math.pi) % TURN - math.pi) < 2.5 * h
    return float(np.abs(d2[~near]).max())


@settings(max_examples=25, deadline=None)
@given(a=angles, width=st.floats(math.radians(5), math.radians(120)))
def test_average_torque_is_second_order_wherever_the_cut_is(a, width):
    """|T_avg,h − (−W/2π)| ≤ (h²/12) max|T''|: the composite trapezoid bound on the smooth pieces.

    On a plain grid a jump J inside a step adds up to h|J|/2 (first order) and breaks this bound.
    """
    b = (a + width) % TURN
    problem = _cut_between(a, b)
    exact = _work(problem, a, b) / TURN
    bound = 1.2 * _curvature(problem, a, b) / 12  # 1.2: the fine-grid estimate of max|T''| may fall short of it
    for n in (90, 360, 1440):
        h = TURN / n
        assert abs(sweep(problem, n).average - exact) <= bound * h**2


@settings(max_examples=40, deadline=None)
@given(r=st.floats(0.02, 0.1), ratio=st.floats(2.5, 6.0), offset=st.floats(0.0, 0.5))
def test_no_friction_at_the_dead_centres(r, ratio, offset):
    l, e = ratio * r, offset * r
    mech = SLIDER_CRANK.mechanism
    links = {link.number: link for link in mech.links}
    links[1] = dataclasses.replace(links[1], points={**links[1].points, "E": (0.0, e)})
    links[2] = dataclasses.replace(links[2], points={**links[2].points, "A": (r, 0.0)}, G=(r / 3, 0.0))
    links[3] = dataclasses.replace(links[3], points={**links[3].points, "B": (l, 0.0)}, G=(l / 2, 0.0))
    problem = dataclasses.replace(SLIDER_CRANK, mechanism=dataclasses.replace(mech, links=tuple(links.values())))
    dead = np.array([math.asin(e / (l + r)), math.pi + math.asin(e / (l - r))])
    kin = problem.kinematics(at=dead)
    assert np.all(kin.valid)
    guide = next(j for j in mech.joints if isinstance(j, Prismatic))
    np.testing.assert_array_equal(kin.slide_sense(guide, guide.slider), [0.0, 0.0])
    with_mu, without = problem.solve(at=dead), problem.with_friction(0.0).solve(at=dead)
    scale = np.abs(without.effort).max() + 1e-9 * r * 500
    np.testing.assert_allclose(with_mu.effort, without.effort, rtol=0, atol=1e-9 * scale)
