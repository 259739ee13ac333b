"""Kinematics of random linkages of every family, checked without trusting the solver's rates.

- velocities and accelerations (ω, α of links; v, a of points and centres of
  mass) against finite differences of the positions, by the chain rule;
- positions satisfy every joint's constraint (pins coincide, slider points
  lie on their guides, gears roll);
- the assembly branch is continuous over a full crank cycle and means what
  the docstring of :mod:`graphkin.kinematics.groups` says;
- positions that cannot be assembled give nan, ``valid`` False and a reason;
- the Söylemez double-slider example.

Finite differences
------------------
Five-point central stencils in the input q with step h = 1e-3 (rad for a
crank; 1e-3 × the shortest pin-to-pin length of a moving link for a slider,
the crank a driving piston turns: a step of the mechanism's size, with a
planet's arm five times the crank, was truncated at 1.4e-6 relative):

    X'  ≈ (X₋₂ − 8X₋₁ + 8X₁ − X₂) / 12h,   truncation h⁴/30·|X⁽⁵⁾|,
    X'' ≈ (−X₋₂ + 16X₋₁ − 30X₀ + 16X₁ − X₂) / 12h², truncation h⁴/90·|X⁽⁶⁾|.

Round-off: ≈ 1.5·ε|X|/h ≈ 1e-12 and ≈ 5.3·ε|X|/h² ≈ 4e-9 relative to the
derivative's size for |X| up to ~3 sizes from the origin. Truncation: h⁴ =
1e-12 times the growth of higher derivatives, which the strategies bound by
keeping every transmission sine ≥ 0.2 (growth ≲ 5ᵏ): ≲ 1e-10. FD_RTOL = 1e-6
is therefore > 100× the expected error, while a wrong term (a missing
Coriolis or centripetal part, a sign) is an O(1) relative error. The
time derivatives follow by the chain rule,
dX/dt = X' q̇ and d²X/dt² = X'' q̇² + X' q̈, with q̇, q̈ the input rates. (A
three-point stencil with h = 1e-5 would have second-derivative round-off
≈ 4ε|X|/h² ≈ 1e-5, too close to a 1e-5 tolerance.)
"""

from __future__ import annotations

import math
import os

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphkin.analytical import solve_forces
from graphkin.kinematics import Dyad, decompose, solve_kinematics
from graphkin.model import Driver, GearMesh, Link, Mechanism, Prismatic, Revolute
from tests.physics import pitch_point
from tests.strategies import crank_families, families, gear_families, length_scale, planet_on_a_rocker
from tests.vectors import cross, dot, perp

FD_STEP = 1e-3
FD_RTOL = 1e-6
GEOM_RTOL = 1e-12  # constraints hold to rounding: a few ε times the coordinates' size

FAMILIES = sorted(families)
SETTINGS = settings(
    # GRAPHKIN_EXAMPLES=500 for a thorough run; the default keeps the file fast.
    max_examples=int(os.environ.get("GRAPHKIN_EXAMPLES", 20)),
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)


def _shortest_pin_distance(mech) -> float:
    """The shortest distance between two pins of one moving link (a slider's stroke turns the crank by it)."""
    pins = {}
    for joint in mech.joints:
        if isinstance(joint, Revolute):
            for link in joint.links:
                pins.setdefault(link, set()).add(joint.point)
    gaps = [math.dist(mech.link(link).points[a], mech.link(link).points[b])
            for link, names in pins.items() if link in mech.moving
            for a in names for b in names if a < b]
    return min(g for g in gaps if g > 0)


def wrap(x):
    """Angle (difference) mapped to (−π, π]."""
    return np.angle(np.exp(1j * np.asarray(x)))


def _points(mech, link):
    """Every named point of a link and its centre of mass (as local coordinates)."""
    body = mech.link(link)
    return [*body.points, body.G]


def _extent(kin):
    """Largest distance of any point from the origin, per position."""
    mech = kin.mechanism
    ext = np.zeros(kin.n)
    for link in mech.moving:
        for p in _points(mech, link):
            ext = np.maximum(ext, np.linalg.norm(kin.position(link, p), axis=-1))
    return ext


def _rate_scale(kin, f):
    """Largest |v| (or |a|) of any point of the mechanism, per position, plus ω·size (α·size)."""
    mech = kin.mechanism
    L = length_scale(mech)
    rate = kin.omega if f.__name__ == "velocity" else kin.alpha
    ext = _extent(kin)  # once: it visits every point of every link
    out = np.zeros(kin.n)
    for link in mech.moving:
        out = np.maximum(out, np.abs(rate[link]) * (L + ext))
        for p in _points(mech, link):
            out = np.maximum(out, np.linalg.norm(f(link, p), axis=-1))
    if f.__name__ == "acceleration":  # centripetal parts
        for link in mech.moving:
            out = np.maximum(out, kin.omega[link] ** 2 * (L + ext))
    return out


# --------------------------------------------------------------------------
# finite differences
# --------------------------------------------------------------------------
@pytest.mark.parametrize("family", FAMILIES)
@SETTINGS
@given(data=st.data())
def test_rates_match_finite_differences_of_positions(family, data):
    mech, q, q_dot, q_ddot = data.draw(families[family])
    n = len(q)
    L = length_scale(mech)
    h = FD_STEP if mech.driver.kind == "crank" else FD_STEP * _shortest_pin_distance(mech)
    offsets = np.arange(-2, 3)
    grid = solve_kinematics(mech, (q[:, None] + h * offsets[None, :]).ravel())
    assert grid.valid.all()
    kin = solve_kinematics(mech, q, q_dot, q_ddot)
    assert kin.valid.all()

    c1 = np.array([1, -8, 0, 8, -1]) / (12 * h)
    c2 = np.array([-1, 16, -30, 16, -1]) / (12 * h * h)

    def derivs(values):  # values (5n, ...) -> first, second derivative in q, (n, ...)
        v = values.reshape(n, 5, *values.shape[1:])
        return np.tensordot(c1, v, axes=(0, 1)), np.tensordot(c2, v, axes=(0, 1))

    ang, pts = {}, {}
    for link in mech.moving:
        th = grid.theta[link].reshape(n, 5)
        th = (th[:, 2:3] + wrap(th - th[:, 2:3])).ravel()  # unwrapped about the centre
        ang[link] = derivs(th)
        for k, p in enumerate(_points(mech, link)):
            pts[(link, k)] = (p, *derivs(grid.position(link, p)))

    # Scales (in length units): the largest first and second q-derivative.
    S1 = np.zeros(n)
    S2 = np.zeros(n)
    for link, (d1, d2) in ang.items():
        S1, S2 = np.maximum(S1, L * np.abs(d1)), np.maximum(S2, L * np.abs(d2))
    for _, d1, d2 in pts.values():
        S1, S2 = np.maximum(S1, np.linalg.norm(d1, axis=-1)), np.maximum(S2, np.linalg.norm(d2, axis=-1))
    tol_v = FD_RTOL * S1 * np.abs(q_dot) + 1e-300
    tol_a = FD_RTOL * (S2 * q_dot**2 + S1 * np.abs(q_ddot)) + 1e-300

    for link, (d1, d2) in ang.items():
        err = np.abs(kin.omega[link] - d1 * q_dot)
        assert np.all(err <= tol_v / L), f"ω{link}: {kin.omega[link]} vs FD {d1 * q_dot}"
        err = np.abs(kin.alpha[link] - (d2 * q_dot**2 + d1 * q_ddot))
        assert np.all(err <= tol_a / L), f"α{link}: {kin.alpha[link]} vs FD {d2 * q_dot**2 + d1 * q_ddot}"
    for (link, k), (p, d1, d2) in pts.items():
        v_fd = d1 * q_dot[:, None]
        a_fd = d2 * (q_dot**2)[:, None] + d1 * q_ddot[:, None]
        v, a = kin.velocity(link, p), kin.acceleration(link, p)
        assert np.all(np.linalg.norm(v - v_fd, axis=-1) <= tol_v), f"v of link {link} point {p}: {v} vs FD {v_fd}"
        assert np.all(np.linalg.norm(a - a_fd, axis=-1) <= tol_a), f"a of link {link} point {p}: {a} vs FD {a_fd}"
    for link in mech.moving:  # the centre-of-mass accessors agree with the point accessors
        G = mech.link(link).G
        np.testing.assert_array_equal(kin.G(link), kin.position(link, G))
        np.testing.assert_array_equal(kin.v_G(link), kin.velocity(link, G))
        np.testing.assert_array_equal(kin.a_G(link), kin.acceleration(link, G))


# --------------------------------------------------------------------------
# joint constraints
# --------------------------------------------------------------------------
@pytest.mark.parametrize("family", FAMILIES)
@SETTINGS
@given(data=st.data())
def test_positions_satisfy_every_joint(family, data):
    mech, q, q_dot, q_ddot = data.draw(families[family])
    kin = solve_kinematics(mech, q, q_dot, q_ddot)
    assert kin.valid.all()
    tol = GEOM_RTOL * 100 * (_extent(kin) + length_scale(mech))
    pivoted = {link for link in mech.moving if any(isinstance(jt, Revolute) and mech.frame in jt.links
                                                  for jt in mech.joints_of(link))}
    rate_scale = {f.__name__: _rate_scale(kin, f) for f in (kin.velocity, kin.acceleration)}  # once, not per joint
    for joint in mech.joints:
        if isinstance(joint, Revolute):
            i, j = joint.links
            gap = np.linalg.norm(kin.position(i, joint.point) - kin.position(j, joint.point), axis=-1)
            assert np.all(gap <= tol), f"{joint.label}: pins apart by {gap}"
            for f in (kin.velocity, kin.acceleration):
                gap = np.linalg.norm(f(i, joint.point) - f(j, joint.point), axis=-1)
                assert np.all(gap <= 1e-9 * rate_scale[f.__name__] + 1e-300), f"{joint.label}: pins move apart ({f.__name__})"
        elif isinstance(joint, Prismatic):
            u = kin.guide_direction(joint)
            X = kin.position(joint.slider, joint.point)
            Y = kin.position(joint.guide, joint.through)
            off = cross(u, X - Y)
            assert np.all(np.abs(off) <= tol), f"{joint.label}: slider point off its guide by {off}"
            turn = wrap(kin.theta[joint.slider] - kin.theta[joint.guide] - (joint.direction - joint.slider_direction))
            assert np.all(np.abs(turn) <= 1e-12), f"{joint.label}: slider turned by {turn} relative to its guide"
            np.testing.assert_allclose(np.linalg.norm(u, axis=-1), 1.0, rtol=1e-14)
        else:  # gear mesh: the pitch points roll on each other (equal velocities)
            (a, b), (ca, cb), (ra, rb) = joint.links, joint.centers, joint.radii
            Ca, Cb = kin.position(a, ca), kin.position(b, cb)
            d = np.linalg.norm(Cb - Ca, axis=-1)
            np.testing.assert_allclose(d, abs(ra - rb) if joint.internal else ra + rb, rtol=1e-12)
            P = pitch_point(kin, joint, a)
            va = kin.velocity(a, ca) + kin.omega[a][:, None] * perp(P - Ca)
            vb = kin.velocity(b, cb) + kin.omega[b][:, None] * perp(P - Cb)
            # The pitch point may be still (on a fixed gear): the scale is that of the gears' own motions.
            scale = (np.linalg.norm(kin.velocity(a, ca), axis=-1) + np.linalg.norm(kin.velocity(b, cb), axis=-1)
                     + np.abs(kin.omega[a]) * ra + np.abs(kin.omega[b]) * rb + 1e-300)
            assert np.all(np.linalg.norm(va - vb, axis=-1) <= 1e-12 * scale), "gears slip at the pitch point"
            if a in (mech.frame, *pivoted) and b in (mech.frame, *pivoted):  # both centres still: the ratio of the pitch radii
                np.testing.assert_allclose(kin.omega[b] * rb, (1 if joint.internal else -1) * kin.omega[a] * ra,
                                           rtol=1e-12, atol=1e-300)
    d = mech.driver
    J = mech.joint_between(mech.frame, d.link)
    if d.kind == "crank":
        assert np.all(np.abs(wrap(kin.theta[d.link] - q)) <= 1e-12)
        np.testing.assert_array_equal(kin.omega[d.link], q_dot)
        np.testing.assert_array_equal(kin.alpha[d.link], q_ddot)
    else:
        u = kin.guide_direction(J)
        X = kin.position(mech.frame, J.through) + q[:, None] * u
        assert np.all(np.linalg.norm(kin.position(d.link, J.point) - X, axis=-1) <= tol)
        np.testing.assert_allclose(dot(kin.velocity(d.link, J.point), u), q_dot, rtol=1e-12, atol=1e-300)
        np.testing.assert_allclose(dot(kin.acceleration(d.link, J.point), u), q_ddot, rtol=1e-12, atol=1e-300)
        np.testing.assert_array_equal(kin.omega[d.link], 0.0)


# --------------------------------------------------------------------------
# assembly branch
# --------------------------------------------------------------------------
def _joint_point(kin, joint, link):
    if isinstance(joint, Prismatic):
        return kin.position(joint.slider, joint.point)
    return kin.position(link, joint.point)


def branch_signs(kin):
    """For each dyad with two assemblies: (label, σ asked for, sign found per position).

    Meanings (docstring of graphkin.kinematics.groups):
    RRR: σ = +1 puts J2 left of J1 → J3;  RRP: J2 beyond the foot of the
    perpendicular from J1, along u;  RPR: u points from the guide link's pin
    to the slider link's pin.
    """
    mech = kin.mechanism
    out = []
    for g in decompose(mech):
        if not isinstance(g, Dyad) or g.type not in ("RRR", "RRP", "RPR"):
            continue
        sigma = mech.assembly.get(g.key, 1)
        X1, X2, X3 = _joint_point(kin, g.J1, g.j), _joint_point(kin, g.J2, g.k), _joint_point(kin, g.J3, g.k)
        if g.type == "RRR":
            s = cross(X3 - X1, X2 - X1)
        elif g.type == "RRP":
            s = dot(X2 - X1, kin.guide_direction(g.J3))
        else:
            P = g.J2
            pins = {g.j: kin.position(g.j, g.J1.point), g.k: kin.position(g.k, g.J3.point)}
            s = dot(pins[P.slider] - pins[P.guide], kin.guide_direction(P))
        out.append((g.label, sigma, np.sign(s)))
    return out


@pytest.mark.parametrize("family", FAMILIES)
@SETTINGS
@given(data=st.data())
def test_assembly_branch_means_what_the_docs_say(family, data):
    mech, q, q_dot, q_ddot = data.draw(families[family])
    kin = solve_kinematics(mech, q, q_dot, q_ddot)
    for label, sigma, sign in branch_signs(kin):
        assert np.all(sign == sigma), f"{label}: asked σ = {sigma}, got {sign}"


@pytest.mark.parametrize("family", crank_families)
@SETTINGS
@given(data=st.data())
def test_branch_is_continuous_over_a_crank_cycle(family, data):
    """A 360-point sweep of the crank: no jumps between consecutive positions.

    Consecutive angles and points must differ by what the rates predict
    (trapezoid rule: error Δq³/12·|X'''|, i.e. ≈ 2.5e-5·|X'''/X'|·|ΔX|; we
    allow 5 % of the largest step, which a jump to the other branch -- a
    finite change over one step -- exceeds).
    """
    mech = data.draw(families[family]).mechanism
    N = 360
    q = np.linspace(0.0, 2 * math.pi, N + 1)  # closes the cycle: q[N] ≡ q[0]
    kin = solve_kinematics(mech, q, 1.0, 0.0)
    assert kin.valid.all(), "the constructed linkage turns fully: every position assembles"
    dq = q[1] - q[0]
    for link in mech.moving:
        w = kin.omega[link]
        step = wrap(np.diff(kin.theta[link]))
        predicted = 0.5 * (w[1:] + w[:-1]) * dq
        allowed = 0.05 * np.abs(w).max() * dq + 1e-12
        assert np.all(np.abs(step - predicted) <= allowed), f"θ{link} jumps at q = {q[1:][np.abs(step - predicted) > allowed]}"
        for p in _points(mech, link):
            X, v = kin.position(link, p), kin.velocity(link, p)
            step = np.diff(X, axis=0)
            predicted = 0.5 * (v[1:] + v[:-1]) * dq
            allowed = 0.05 * np.linalg.norm(v, axis=-1).max() * dq + 1e-12 * length_scale(mech)
            assert np.all(np.linalg.norm(step - predicted, axis=-1) <= allowed), f"point {p} of link {link} jumps"
        # the cycle closes: the same configuration after one turn (not for a
        # gear, whose period is the crank's times the gear ratio)
        if not any(isinstance(j, GearMesh) for j in mech.joints):
            assert abs(wrap(kin.theta[link][-1] - kin.theta[link][0])) <= 1e-9
    for label, sigma, sign in branch_signs(kin):
        assert np.all(sign == sigma), f"{label}: the branch changes during the cycle"


def test_a_planet_on_a_rocker_turns_without_a_jump():
    """A crank-rocker whose rocker 4 swings across 180° carries a planet 5 meshing with a sun fixed at the rocker's
    pivot: over a turn of the crank, the planet's angle changes step by step by what its ω gives, as the rocker's does.

    The shrunk case the property test above found on the family ``driven_arm`` (issue 35, item 2): the planet's
    angle jumped by 10.03 rad (1.6 turns) at θ12 = 2.69 rad and back at 5.48 rad, where θ14 crosses ±π.
    """
    mech = planet_on_a_rocker()
    q = np.linspace(0.0, 2 * math.pi, 361)
    kin = solve_kinematics(mech, q, 1.0, 0.0)
    assert kin.valid.all()
    dq = q[1] - q[0]
    assert np.ptp(np.unwrap(kin.theta[4])) < math.pi  # a rocker: it never turns round
    for link in (4, 5):
        w = kin.omega[link]
        step = np.diff(kin.theta[link])
        predicted = 0.5 * (w[1:] + w[:-1]) * dq
        jumps = q[1:][np.abs(wrap(step - predicted)) > 0.05 * np.abs(w).max() * dq]
        assert not jumps.size, f"θ1{link} jumps at θ12 = {jumps} rad"


# A gear's period is not one crank turn.
@pytest.mark.parametrize("family", [f for f in crank_families if f not in gear_families])
@SETTINGS
@given(data=st.data())
def test_whole_turns_of_the_crank_change_nothing(family, data):
    """q and q + 2πk give the same kinematics and forces (loads active over an
    interval of the crank angle included): the input angle is taken modulo a turn."""
    mech, q, q_dot, q_ddot = data.draw(families[family])
    k = data.draw(st.integers(-3, 3))
    a = solve_kinematics(mech, q, q_dot, q_ddot)
    b = solve_kinematics(mech, q + 2 * math.pi * k, q_dot, q_ddot)
    # q + 2πk is rounded: an absolute error ≈ |q + 2πk|·ε ≈ 1e-14 rad in the input
    scales = {"position": _extent(a) + length_scale(mech),  # once, not per point: each visits every point
              "velocity": _rate_scale(a, a.velocity), "acceleration": _rate_scale(a, a.acceleration)}
    for link in mech.moving:
        assert np.all(np.abs(wrap(a.theta[link] - b.theta[link])) <= 1e-11)
        for p in _points(mech, link):
            for f in ("position", "velocity", "acceleration"):
                x, y = getattr(a, f)(link, p), getattr(b, f)(link, p)
                scale = scales[f]
                assert np.all(np.linalg.norm(x - y, axis=-1) <= 1e-9 * scale + 1e-300)
    ra, rb = solve_forces(a), solve_forces(b)
    size = np.abs(ra.effort) + max((np.abs(F).max() for F in ra.forces.values()), default=0.0) * length_scale(mech) + 1e-300
    np.testing.assert_allclose(rb.effort, ra.effort, rtol=0, atol=1e-9 * size.max())


# --------------------------------------------------------------------------
# positions that cannot be assembled
# --------------------------------------------------------------------------
@st.composite
def long_crank_fourbars(draw):
    """A four-bar whose crank is too long to turn: a1 + a2 > a3 + a4 (and maybe |a1 − a2| < |a3 − a4|)."""
    f = st.floats(0.5, 1.5)
    a1, a3, a4 = draw(f), draw(f), draw(f)
    lo = max(a3 + a4 - a1, 0.0) + 0.05
    a2 = draw(st.floats(lo, lo + 2.0))
    O2 = np.array([draw(st.floats(-1, 1)), draw(st.floats(-1, 1))])
    gamma = draw(st.floats(-math.pi, math.pi))
    O4 = O2 + a1 * np.array([math.cos(gamma), math.sin(gamma)])
    beta = draw(st.floats(-math.pi, math.pi))  # the crank bar's angle in its own frame
    A_loc = (a2 * math.cos(beta) + 0.1, a2 * math.sin(beta) - 0.2)
    links = [
        Link(1, {"O2": tuple(O2), "O4": tuple(O4)}),
        Link(2, {"O2": (0.1, -0.2), "A": A_loc}, mass=1.0, G=(0.3, 0.0), I_G=0.1),
        Link(3, {"A": (0.0, 0.0), "B": (a3, 0.0)}, mass=2.0, G=(a3 / 2, 0.1), I_G=0.2),
        Link(4, {"O4": (0.0, 0.0), "B": (0.0, a4)}, mass=1.5, G=(0.0, a4 / 2), I_G=0.1),
    ]
    joints = [Revolute((1, 2), "O2"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), Revolute((4, 1), "O4")]
    mech = Mechanism(links, joints, Driver(2), gravity=9.81, assembly={"B": draw(st.sampled_from((1, -1)))})
    return mech, (O2, O4, beta, a2, a3, a4)


@SETTINGS
@given(long_crank_fourbars())
def test_unassemblable_positions_give_nan_and_a_reason(drawn):
    mech, (O2, O4, beta, a2, a3, a4) = drawn
    q = np.linspace(0.0, 2 * math.pi, 360, endpoint=False)
    kin = solve_kinematics(mech, q, 2.0, 1.0)
    # Independently: the dyad 3–4 closes iff |a3 − a4| ≤ |A − O4| ≤ a3 + a4.
    A = O2 + a2 * np.stack([np.cos(q + beta), np.sin(q + beta)], -1)
    d = np.linalg.norm(A - O4, axis=-1)
    ok = (d <= a3 + a4) & (d >= abs(a3 - a4))
    clear = (np.abs(d - (a3 + a4)) > 1e-6) & (np.abs(d - abs(a3 - a4)) > 1e-6)
    assert not ok.all()
    np.testing.assert_array_equal(kin.valid[clear], ok[clear])
    bad = ~kin.valid
    # Out of reach (not on the boundary, where the dyad stands straight or folded: a dead point, or pins that
    # coincide, whose positions are invalid with their own reasons): nothing of links 3 and 4 is placed.
    out = ~ok & clear
    assert not kin.valid[out].any()
    for link in (3, 4):
        for store in (kin.theta, kin.omega, kin.alpha):
            assert np.isnan(store[link][out]).all()
        assert np.isnan(kin.position(link, "B")[out]).all()
        assert np.isnan(kin.acceleration(link, "B")[out]).all()
        assert np.isfinite(kin.acceleration(link, "B")[kin.valid]).all()
    np.testing.assert_allclose(kin.position(2, "A"), A, atol=1e-12)  # the driver is always placed
    for i in np.flatnonzero(out):
        assert "cannot be assembled" in kin.reason(i)
    for i in np.flatnonzero(bad):  # every invalid position says why, in the dyad's words
        assert kin.reason(i).startswith("RRR dyad 3–4"), kin.reason(i)
    for i in np.flatnonzero(kin.valid):
        assert kin.reason(i) == ""
    # Forces: invalid where the kinematics is, nan there, and the valid
    # positions are not contaminated by the invalid ones.
    r = solve_forces(kin)
    np.testing.assert_array_equal(r.valid, kin.valid)
    assert np.isnan(r.effort[bad]).all() and np.isfinite(r.effort[kin.valid]).all()
    for i in np.flatnonzero(out)[:3]:
        assert "cannot be assembled" in r.reason(i)
    good = np.flatnonzero(kin.valid)
    if len(good):
        r_good = solve_forces(solve_kinematics(mech, q[good], 2.0, 1.0))
        np.testing.assert_allclose(r_good.effort, r.effort[good], rtol=1e-12, atol=1e-12 * np.abs(r.effort[good]).max())
        for key in r.forces:
            np.testing.assert_allclose(r_good.forces[key], r.forces[key][good], rtol=1e-12,
                                       atol=1e-12 * np.abs(r.forces[key][good]).max())


# --------------------------------------------------------------------------
# a textbook example
# --------------------------------------------------------------------------
def test_soylemez_double_slider_kinematics():
    """Söylemez, Mechanisms, §6.4 example (seed 000).

    Slider 2 on a horizontal guide, slider 4 on a vertical guide through the
    same point, coupler 3 of 500 mm (A–B). At x = 200 mm, ẋ = 2 m/s, ẍ = 0:
    θ13 = 113.578°, y = 458.258 mm, ω13 = 4.364 rad/s, α13 = 8.312 rad/s²,
    ẏ = −872.872 mm/s, ÿ = −10.390 m/s², a_G3 = 5.194 m/s² ∠270°.
    """
    links = [
        Link(1, {"O": (0, 0)}),
        Link(2, {"A": (0, 0)}),
        Link(3, {"A": (0, 0), "B": (0.5, 0)}, mass=5, G=(0.25, 0), I_G=5 * 0.25 / 12),
        Link(4, {"B": (0, 0)}),
    ]
    joints = [Prismatic(1, 2, "A", "O", 0.0), Revolute((2, 3), "A"), Revolute((3, 4), "B"),
              Prismatic(1, 4, "B", "O", math.pi / 2)]
    mech = Mechanism(links, joints, Driver(2, "slider"))
    kin = solve_kinematics(mech, 0.2, 2.0, 0.0)
    rel = 1e-3  # the book prints 6 significant figures; 0.1 %
    assert kin.valid.all()
    assert math.degrees(kin.theta[3][0]) == pytest.approx(113.578, rel=rel)
    assert kin.position(4, "B")[0, 1] == pytest.approx(0.458258, rel=rel)
    assert kin.omega[3][0] == pytest.approx(4.364, rel=rel)
    assert kin.alpha[3][0] == pytest.approx(8.312, rel=rel)
    assert kin.velocity(4, "B")[0, 1] == pytest.approx(-0.872872, rel=rel)
    assert kin.acceleration(4, "B")[0, 1] == pytest.approx(-10.390, rel=rel)
    aG = kin.a_G(3)[0]
    assert np.hypot(*aG) == pytest.approx(5.194, rel=rel)
    assert math.degrees(math.atan2(aG[1], aG[0])) % 360 == pytest.approx(270.0, abs=0.1)
    # the guides hold: B stays on x = 0, A on y = 0
    assert kin.position(4, "B")[0, 0] == pytest.approx(0.0, abs=1e-12)
    assert kin.position(2, "A")[0].tolist() == pytest.approx([0.2, 0.0], abs=1e-12)


# --------------------------------------------------------------------------
# regression: the assembly branch must not depend on link numbers
# --------------------------------------------------------------------------
# GRAPHKIN BUG found by these tests (fixed upstream in 45b70aa, "Assembly
# branch no longer depends on link numbering"). Mechanism.assembly is keyed
# by the dyad's middle pin ("B"), and σ = +1 "puts J2 to the left of the
# directed line J1 → J3". J1 and J3 used to be taken in the order decompose()
# met the dyad's links, i.e. by their *numbers*: swapping the numbers of
# coupler and rocker (a pure relabelling) reversed J1 → J3 and silently
# assembled the other branch (the open four-bar became the crossed one).
def _fourbar_numbered(coupler, rocker):
    links = [
        Link(1, {"O2": (0, 0), "O4": (1, 0)}),
        Link(2, {"O2": (0, 0), "A": (0.3, 0)}),
        Link(coupler, {"A": (0, 0), "B": (1, 0)}),
        Link(rocker, {"O4": (0, 0), "B": (0.8, 0)}),
    ]
    joints = [Revolute((1, 2), "O2"), Revolute((2, coupler), "A"), Revolute((coupler, rocker), "B"), Revolute((rocker, 1), "O4")]
    return Mechanism(links, joints, Driver(2), assembly={"B": +1})


def test_assembly_branch_does_not_depend_on_link_numbering():
    q = np.radians([0.0, 60.0, 200.0])
    a = solve_kinematics(_fourbar_numbered(3, 4), q)
    b = solve_kinematics(_fourbar_numbered(4, 3), q)  # the same linkage, coupler and rocker renumbered
    np.testing.assert_allclose(b.position(4, "B"), a.position(3, "B"), atol=1e-12,
                               err_msg="assembly={'B': +1} gives a different branch when links are renumbered")


def test_a_dyad_whose_outer_pins_coincide_says_so():
    """Equal arms folded onto each other (A on O4): the dyad may turn about them, so its position is not
    determined. The position is invalid, and the reason names the pins (it was 'no group says why')."""
    links = (Link(1, {"O2": (0.0, 0.0), "O4": (1.0, 0.0)}), Link(2, {"O2": (0.0, 0.0), "A": (1.0, 0.0)}, mass=1.0),
             Link(3, {"A": (0.0, 0.0), "B": (0.5, 0.0)}, mass=1.0), Link(4, {"O4": (0.0, 0.0), "B": (0.5, 0.0)}, mass=1.0))
    joints = (Revolute((1, 2), "O2"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), Revolute((4, 1), "O4"))
    kin = solve_kinematics(Mechanism(links, joints, Driver(2)), np.array([0.0, 0.5]), 1.0, 0.0)
    assert not kin.valid[0] and kin.valid[1]
    assert kin.reason(0) == ("RRR dyad 3–4 has no definite position: its outer pins A and O4 coincide, "
                             "so it may turn about them")
