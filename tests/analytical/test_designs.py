"""A batch of designs (graphkin.analytical.designs): every design's numbers are those of a solve of it alone.

Random linkages of the families below (tests/strategies.py), each with a few variants that move every
point of every link, change every mass, I_G and G and every load's value, and run at a speed of their own: the
batch's validity and reasons must equal solve_forces(solve_kinematics(...)) of each design, and its forces,
couples and effort equal them to 1e-12 relative to the design's forces at that position (N; N·m for the couples
and a crank's torque, with the linkage's size as the arm). Relative to the forces, not to each value: one design
alone rounds some constant products in Python's complex arithmetic, the batch in NumPy's, which differ in the
last bit; a couple that is nearly 0 (the difference of moments of hundreds of N·m) differs by that rounding.
"""

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from graphkin.analytical import solve_forces
from graphkin.analytical.designs import batch_key, numbers, solve_designs
from graphkin.errors import GraphkinError
from graphkin.kinematics import solve_kinematics
from graphkin.model import PointForce
from tests.strategies import families, friction_families

REL = 1e-12
# The four-bar and the slider-crank, a dyad of each other kind (RPR, the six-bar's two RRR loops, RPP), a slider
# driver, and Coulomb friction (the general groups read the batch's points through the Kinematics).
FAMILIES = {**{name: families[name] for name in ("fourbar", "slider_crank", "inverted_slider_crank", "watt2",
                                                   "double_slider")},
            "slider_crank (friction)": friction_families["slider_crank"]}


def _near(draw, x: float, spread: float = 0.2) -> float:
    return x * (1 + draw(st.floats(-spread, spread)))


def variant(draw, mech, scale: float):
    """``mech`` with every number a study may vary redrawn near its own value (the same links, joints, loads)."""
    def moved(p):
        return (p[0] + scale * draw(st.floats(-0.03, 0.03)), p[1] + scale * draw(st.floats(-0.03, 0.03)))

    links = tuple(replace(link, points={name: moved(p) for name, p in link.points.items()},
                          mass=_near(draw, link.mass) if link.mass else draw(st.sampled_from([0.0, 1.5])),
                          I_G=_near(draw, link.I_G), G=moved(link.G))
                  for link in mech.links)
    loads = tuple(replace(load, force=(_near(draw, load.force[0]), _near(draw, load.force[1])))
                  if isinstance(load, PointForce) else replace(load, torque=_near(draw, load.torque))
                  for load in mech.loads)
    return replace(mech, links=links, loads=loads)


def close(a, b, scale):
    """|a − b| ≤ 1e-12 · scale at every position (``scale`` > 0 wherever b is not 0)."""
    assert np.all(np.abs(a - b) <= REL * scale), (a, b, scale)


def _each_as_alone(b, designs, q, w, al, scale):
    """Each design of the batch ``b`` equals a solve of it alone: its valid positions and their reasons, and every
    force, normal force, couple and effort to 1e-12 of the position's force scale (times ``scale`` [m] for a couple
    or a torque)."""
    for d, m in enumerate(designs):
        kin = solve_kinematics(m, q, w[d], al[d])
        r = solve_forces(kin)
        assert np.array_equal(kin.valid, b.kin_valid[d]) and np.array_equal(r.valid, b.valid[d])
        ok = r.valid
        # The force scale at each position: the largest joint force or the driving force.
        force = np.max([np.hypot(F[:, 0], F[:, 1]) for F in r.forces.values()], axis=0)[ok]
        if not m.driver.crank:
            force = np.maximum(force, np.abs(r.effort[ok]))
        for key, F in r.forces.items():
            close(b.forces[key][d][ok], (F[:, 0] + 1j * F[:, 1])[ok], force)
        for key, N in r.normal.items():
            close(b.normal[key][d][ok], N[ok], force)
            close(b.couple[key][d][ok], r.couple[key][ok], force * scale)
        close(b.effort[d][ok], r.effort[ok], force * scale if m.driver.crank else force)
        for i in np.flatnonzero(~ok):
            assert b.reason(d, int(i)) == r.reason(int(i))



@pytest.mark.parametrize("family", FAMILIES)
@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(data=st.data())
def test_each_design_of_a_batch_equals_a_solve_of_it_alone(family, data):
    case = data.draw(FAMILIES[family], label="case")
    # A load that varies over the cycle (a spring) cannot share a batch: the rest of the linkage can.
    mech = replace(case.mechanism, loads=tuple(x for x in case.mechanism.loads if not x.varies))
    assume(batch_key(mech)[0] is not None)
    scale = max(abs(complex(*p)) for link in mech.links for p in link.points.values())
    designs = [mech]
    for _ in range(data.draw(st.integers(1, 3), label="variants")):
        try:
            designs.append(variant(data.draw, mech, scale))
        except GraphkinError:  # a variant the model refuses (two pins on one point): not a design
            continue
    assert len({batch_key(m)[0] for m in designs}) == 1
    # Rates in steps of 0.01 (graphkin refuses a rate so small it is surely a mistake, 1e-47 rad/s).
    rate = st.integers(-3000, 3000).map(lambda k: k / 100 * (1.0 if mech.driver.crank else scale / 10))
    same = data.draw(st.booleans(), label="one speed")
    w = [data.draw(rate)] * len(designs) if same else [data.draw(rate) for _ in designs]
    al = [data.draw(rate) * 10] * len(designs)
    q = case.q

    b = solve_designs(mech, [numbers(m) for m in designs], q, w, al)

    _each_as_alone(b, designs, q, w, al, scale)


def loaded(draw, mech, which: set):
    """``mech`` with the numbers ``which`` names changed by 5 to 30 % (a 0 made 0.01 to 1): ``(link, "mass")``,
    ``(link, "I_G")``, ``(link, "G")`` (moved by 0.5 to 3 % of the linkage's size), ``("load", i)``. The same points,
    so the same kinematics."""
    scale = max(abs(complex(*p)) for link in mech.links for p in link.points.values())

    def other(x):
        return x * (1 + draw(st.sampled_from([-1, 1])) * draw(st.floats(0.05, 0.3))) if x \
            else draw(st.floats(0.01, 1.0))

    def moved(p):
        return (p[0] + scale * draw(st.sampled_from([-1, 1])) * draw(st.floats(0.005, 0.03)), p[1])

    links = tuple(replace(link, mass=other(link.mass) if (link.number, "mass") in which else link.mass,
                          I_G=other(link.I_G) if (link.number, "I_G") in which else link.I_G,
                          G=moved(link.G) if (link.number, "G") in which else link.G)
                  for link in mech.links)
    loads = tuple((replace(load, force=(other(load.force[0]), other(load.force[1])))
                   if isinstance(load, PointForce) else replace(load, torque=other(load.torque)))
                  if ("load", i) in which else load for i, load in enumerate(mech.loads))
    return replace(mech, links=links, loads=loads)


@pytest.mark.parametrize("family", FAMILIES)
@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(data=st.data())
def test_designs_that_share_their_kinematics_each_equal_a_solve_alone(family, data):
    """Groups of designs with the same points and speed, differing in some of their masses, I_G, G and loads (a
    study's designs, ordered by the fields that move the linkage): the kinematics solved once per group, the force
    pass broadcasting them, each design's numbers those of a solve of it alone."""
    case = data.draw(FAMILIES[family], label="case")
    mech = replace(case.mechanism, loads=tuple(x for x in case.mechanism.loads if not x.varies))
    assume(batch_key(mech)[0] is not None)
    scale = max(abs(complex(*p)) for link in mech.links for p in link.points.values())
    rate = st.integers(-3000, 3000).map(lambda k: k / 100 * (1.0 if mech.driver.crank else scale / 10))
    # What a study's fields that do not move the linkage vary: one or two of a link's m, I_G or G, or a load's value.
    numbers_ = [(link.number, kind) for link in mech.links for kind in ("mass", "I_G", "G")]
    which = data.draw(st.sets(st.sampled_from(numbers_ + [("load", i) for i in range(len(mech.loads))]),
                              min_size=1, max_size=2), label="varied")
    m = data.draw(st.integers(2, 3), label="designs per group")
    designs, w, al = [], [], []
    for _ in range(data.draw(st.integers(1, 3), label="groups")):
        try:
            shape = variant(data.draw, mech, scale)
        except GraphkinError:  # a variant the model refuses (two pins on one point): not a design
            continue
        speed, speeding = data.draw(rate), data.draw(rate) * 10
        designs += [shape] + [loaded(data.draw, shape, which) for _ in range(m - 1)]
        w += [speed] * m
        al += [speeding] * m
    assume(designs)
    q = case.q
    b = solve_designs(mech, [numbers(x) for x in designs], q, w, al)
    if family in ("fourbar", "watt2"):  # every group has a compiled force step: the kinematics were shared
        assert b.per > 1 and b.per % m == 0
    else:  # the rest solve every design-position on its own
        assert b.per == 1

    _each_as_alone(b, designs, q, w, al, scale)


def test_what_cannot_share_a_batch_says_why():
    from graphkin import catalog

    key, why = batch_key(catalog.load("gearset").mechanism)
    assert key is None and "gear train" in why
    assert "varies over the cycle" in batch_key(catalog.load("shaper_six_bar").mechanism)[1]
    key, why = batch_key(catalog.load("strip_cutter").mechanism)
    assert why is None and hash(key)
