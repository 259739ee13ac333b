"""Property tests of the kinetostatics on random linkages of every family.

For every family of ``tests/strategies.py`` (four-bar, offset slider-crank,
double slider, inverted slider-crank, Scotch yoke, Watt II, Stephenson III,
quick return, gear pair, epicyclic train, annulus, compound planet, planet on
a driven arm, piston-driven slider-crank) with random geometry, mass
properties, loads, input rates of either sense, gravity, slider friction and
link numbering (the frame 1 or 0):

- every moving link is in d'Alembert equilibrium under the joint forces the
  solver reports, the driving effort, the external loads and gravity;
- F_ij = −F_ji, by method and by name;
- power balance (friction-free; and with friction, counting the power the
  friction forces dissipate);
- the closed-form solution equals the solution of the assembled matrix;
- Coulomb friction opposes the relative sliding and has magnitude μ|N|;
- solving a batch of positions equals solving each alone, in any order;
- a gear's tooth force lies on the pressure line and pushes (external and internal meshes);
- regression: the matrix solution does not depend on the unit of length.

Tolerances: 1e-9 relative to the largest load in the mechanism (joint
forces and couples, effort, external loads, weight, inertia loads; moments
with the mechanism's extent as lever arm).
The generated positions keep every dyad's transmission sine ≥ 0.2 (friction
tilt included), so the 2×2 systems the solver uses have condition numbers
≲ 1e2 and rounding errors stay ~1e-13 relative; 1e-9 leaves room for the
longer sums of the six-bars without hiding a wrong term (a sign or a missing
moment is an O(1) error).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from graphkin.analytical import solve_forces
from graphkin.analytical.matrix import assemble, solve_matrix
from graphkin.errors import GraphkinError
from graphkin.kinematics import solve_kinematics
from graphkin.model import GearMesh, Mechanism, Prismatic, Revolute
from tests.physics import (
    BATCH_RTOL,
    RTOL,
    SETTINGS,
    _lohi,
    _solve,
    balance,
    close,
    frictionless,
    load_scales,
    pitch_point,
    power_terms,
)
from tests.strategies import families, friction_families, gear_families
from tests.vectors import dot, perp

FAMILIES = sorted(families)
FRICTION = sorted(friction_families)


# --------------------------------------------------------------------------
# equilibrium of every link
# --------------------------------------------------------------------------
@pytest.mark.parametrize("family", FAMILIES)
@SETTINGS
@given(data=st.data())
def test_every_link_balances_with_its_inertia_loads(family, data):
    case = data.draw(families[family])
    kin, r = _solve(case)
    fs, ms = load_scales(kin, r)
    for link in case.mechanism.moving:
        F, M = balance(kin, r, link)
        ok, excess = close(F, 0.0, RTOL * fs)
        assert ok, f"link {link}: ΣF ≠ 0 (by {excess:.3g} N beyond tolerance)"
        ok, excess = close(M, 0.0, RTOL * ms)
        assert ok, f"link {link}: ΣM_G ≠ 0 (by {excess:.3g} N·m beyond tolerance)"


# --------------------------------------------------------------------------
# action and reaction
# --------------------------------------------------------------------------
@pytest.mark.parametrize("family", FAMILIES)
@SETTINGS
@given(data=st.data())
def test_action_equals_minus_reaction(family, data):
    case = data.draw(families[family])
    kin, r = _solve(case)
    mech = case.mechanism
    for joint in mech.joints:
        i, j = joint.links
        np.testing.assert_array_equal(r.force(i, j), -r.force(j, i))
        letter = joint.force_letter
        np.testing.assert_array_equal(r[f"{letter}{i}{j}"], -r[f"{letter}{j}{i}"])
        np.testing.assert_array_equal(r[f"{letter}{i}{j}"], r.force(i, j))
        wrong = "G" if letter == "F" else "F"
        if f"{wrong}{i}{j}" != mech.driver.symbol:  # "F12" names a slider driver's effort
            with pytest.raises(GraphkinError):
                r[f"{wrong}{i}{j}"]
    d = mech.driver
    if d.kind == "crank":
        np.testing.assert_array_equal(r[d.symbol], r.effort)
    else:
        u = kin.guide_direction(mech.joint_between(mech.frame, d.link))
        np.testing.assert_array_equal(r[d.symbol], r.effort[:, None] * u)


# --------------------------------------------------------------------------
# power balance
# --------------------------------------------------------------------------
@pytest.mark.parametrize("family", FAMILIES)
@SETTINGS
@given(data=st.data())
def test_power_balance_without_friction(family, data):
    """Input + external + gravity power = rate of change of kinetic energy."""
    case = data.draw(families[family])
    mech = frictionless(case.mechanism)
    kin, r = _solve(case, mech)
    P, dT, scale = power_terms(kin, r)
    ok, excess = close(P, dT, RTOL * scale)
    assert ok, f"power balance off by {excess:.3g} W beyond tolerance: in {P}, dT/dt {dT}"


@pytest.mark.parametrize("family", FRICTION)
@SETTINGS
@given(data=st.data())
def test_power_balance_with_friction(family, data):
    """With friction the sliders dissipate F·u ṡ ≤ 0, and the balance still closes."""
    case = data.draw(friction_families[family])
    kin, r = _solve(case)
    P, dT, scale = power_terms(kin, r)
    ok, excess = close(P, dT, RTOL * scale)
    assert ok, f"power balance off by {excess:.3g} W beyond tolerance"


# --------------------------------------------------------------------------
# closed form against the assembled matrix
# --------------------------------------------------------------------------
def _check_matrix(case):
    kin, r = _solve(case)
    m = solve_matrix(r)
    A = assemble(r).A
    cond = np.linalg.cond(A)
    assert m.valid.all(), (
        f"solve_matrix says singular, but cond(A) = {cond} "
        f"(|det A| = {np.abs(np.linalg.det(A))}, max|A|^m = {np.abs(A).max(axis=(1, 2)) ** A.shape[1]}); "
        "see test_matrix_singularity_test_is_scale_invariant"
    )
    f_scale, m_scale = load_scales(kin, r)
    assert set(m.forces) == set(r.forces)
    for key in r.forces:
        ok, excess = close(m.forces[key], r.forces[key], RTOL * f_scale)
        assert ok, f"force {key}: matrix and closed form differ by {excess:.3g} N beyond tolerance"
    for key in r.normal:
        ok, excess = close(m.normal[key], r.normal[key], RTOL * f_scale)
        assert ok, f"normal force {key} differs by {excess:.3g} N beyond tolerance"
        ok, excess = close(m.couple[key], r.couple[key], RTOL * m_scale)
        assert ok, f"couple {key} differs by {excess:.3g} N·m beyond tolerance"
    scale = m_scale if case.mechanism.driver.kind == "crank" else f_scale
    ok, excess = close(m.effort, r.effort, RTOL * scale)
    assert ok, f"driving effort differs by {excess:.3g} beyond tolerance"


@pytest.mark.parametrize("family", FAMILIES)
@SETTINGS
@given(data=st.data())
def test_closed_form_equals_matrix_solution(family, data):
    _check_matrix(data.draw(families[family]))


@pytest.mark.parametrize("family", FRICTION)
@SETTINGS
@given(data=st.data())
def test_closed_form_equals_matrix_solution_with_friction(family, data):
    _check_matrix(data.draw(friction_families[family]))


# --------------------------------------------------------------------------
# Coulomb friction
# --------------------------------------------------------------------------
@pytest.mark.parametrize("family", FRICTION)
@SETTINGS
@given(data=st.data())
def test_friction_opposes_sliding_with_magnitude_mu_N(family, data):
    case = data.draw(friction_families[family])
    kin, r = _solve(case)
    f_scale, _ = load_scales(kin, r)
    pairs = [j for j in case.mechanism.joints if isinstance(j, Prismatic)]
    assert pairs and all(j.mu > 0 for j in pairs)
    for joint in pairs:
        lo, hi = _lohi(joint)
        u = kin.guide_direction(joint)
        for on, other in ((hi, lo), (lo, hi)):
            F = r.force(other, on)
            N = dot(F, perp(u))
            T = dot(F, u)
            s = kin.slide_rate(joint, on)
            if on == hi:
                ok, excess = close(N, r.normal[(lo, hi)], RTOL * f_scale)
                assert ok, f"{joint.label}: normal force ≠ component of G{lo}{hi} along k×u"
            # friction opposes the sliding of `on` relative to `other` ...
            assert np.all(T * s <= RTOL * f_scale * np.abs(s)), f"{joint.label}: friction on {on} helps it slide"
            # ... with magnitude μ|N| while sliding (none where it is at rest: a slide rate that is rounding, below
            # STILL of the fastest point's speed, is rest, as at a dead centre — Kinematics.slide_sense)
            expected = np.where(kin.slide_sense(joint, on) != 0, joint.mu * np.abs(N), 0.0)
            ok, excess = close(np.abs(T), expected, RTOL * f_scale)
            assert ok, f"{joint.label}: |friction| ≠ μ|N| (off by {excess:.3g} N beyond tolerance)"


# --------------------------------------------------------------------------
# vectorisation
# --------------------------------------------------------------------------
def _same(a, b, scale):
    a, b = np.asarray(a, float), np.asarray(b, float)
    assert a.shape == b.shape
    tol = BATCH_RTOL * scale
    np.testing.assert_array_less(np.abs(a - b), tol + np.finfo(float).tiny)


@pytest.mark.parametrize("family", FAMILIES)
@SETTINGS
@given(data=st.data())
def test_batch_equals_one_position_at_a_time(family, data):
    case = data.draw(families[family])
    kin, r = _solve(case)
    mech = case.mechanism
    f_scale, m_scale = load_scales(kin, r)
    order = np.array(data.draw(st.permutations(range(len(case.q)))), dtype=int)
    kin_p = solve_kinematics(mech, case.q[order], case.q_dot[order], case.q_ddot[order])
    r_p = solve_forces(kin_p)
    singles = []
    for i in range(len(case.q)):
        k1 = solve_kinematics(mech, case.q[i], case.q_dot[i], case.q_ddot[i])
        singles.append((k1, solve_forces(k1)))
    for i, (k1, r1) in enumerate(singles):
        p = int(np.flatnonzero(order == i)[0])
        for rr, kk, at in ((r, kin, i), (r_p, kin_p, p)):
            assert bool(rr.valid[at]) == bool(r1.valid[0])
            fs, ms = f_scale[i], m_scale[i]
            for link in mech.moving:
                for store, other in ((kk.theta, k1.theta), (kk.omega, k1.omega), (kk.alpha, k1.alpha)):
                    _same(store[link][at], other[link][0], max(1.0, abs(other[link][0])))
                for name in [*mech.link(link).points, mech.link(link).G]:
                    for f in ("position", "velocity", "acceleration"):
                        x, x1 = getattr(kk, f)(link, name)[at], getattr(k1, f)(link, name)[0]
                        _same(x, x1, max(1.0, np.abs(x1).max()))
            for key in r1.forces:
                _same(rr.forces[key][at], r1.forces[key][0], fs)
            for key in r1.couple:
                _same(rr.normal[key][at], r1.normal[key][0], fs)
                _same(rr.couple[key][at], r1.couple[key][0], ms)
            _same(rr.effort[at], r1.effort[0], ms if mech.driver.kind == "crank" else fs)


# --------------------------------------------------------------------------
# gear mesh: the tooth force lies on the pressure line
# --------------------------------------------------------------------------
@pytest.mark.parametrize("family", gear_families)
@SETTINGS
@given(data=st.data())
def test_gear_tooth_force_on_the_pressure_line(family, data):
    """On each gear of each mesh, external or internal: the tooth force pushes the gear's tooth into its body (inside
    the pitch circle; an annulus's outside it), inclined by the pressure angle to the common tangent."""
    case = data.draw(families[family])
    kin, r = _solve(case)
    for mesh in (j for j in case.mechanism.joints if isinstance(j, GearMesh)):
        for gear, other in (mesh.links, mesh.links[::-1]):
            W = r.force(other, gear)
            P = pitch_point(kin, mesh, gear)
            C = kin.position(gear, mesh.centers[mesh.links.index(gear)])
            into = (C - P) / np.linalg.norm(C - P, axis=-1)[:, None] * (-1.0 if gear == mesh.ring else 1.0)
            radial = dot(W, into)
            tangential = dot(W, perp(into))
            tol = RTOL * np.linalg.norm(W, axis=-1)
            assert np.all(radial >= -tol), f"{mesh.label}: the tooth force pulls gear {gear}"
            ok, excess = close(radial, np.abs(tangential) * np.tan(mesh.pressure_angle), tol)
            assert ok, f"{mesh.label}: tooth force on gear {gear} off the pressure line by {excess:.3g} N beyond tolerance"


# --------------------------------------------------------------------------
# regression: the matrix solver's singularity test must not depend on units
# --------------------------------------------------------------------------
def _watt2(k):
    """A Watt II six-bar with every length multiplied by k [m]; masses fixed, I_G ∝ k²."""
    from graphkin.model import Driver, Link

    def L(*p):
        return tuple(k * x for x in p)

    links = [
        Link(1, {"O2": L(0, 0), "O4": L(1, 0), "O6": L(1.6, 1.2)}),
        Link(2, {"O2": L(0, 0), "A": L(0.3, 0)}, mass=1, G=L(0.15, 0), I_G=0.01 * k * k),
        Link(3, {"A": L(0, 0), "B": L(1, 0)}, mass=2, G=L(0.5, 0), I_G=0.2 * k * k),
        Link(4, {"O4": L(0, 0), "B": L(0.8, 0), "C": L(0.6, 0.4)}, mass=2, G=L(0.5, 0.1), I_G=0.1 * k * k),
        Link(5, {"C": L(0, 0), "D": L(1, 0)}, mass=2, G=L(0.5, 0), I_G=0.2 * k * k),
        Link(6, {"O6": L(0, 0), "D": L(0.9, 0)}, mass=2, G=L(0.45, 0), I_G=0.15 * k * k),
    ]
    joints = [Revolute((1, 2), "O2"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), Revolute((4, 1), "O4"),
              Revolute((4, 5), "C"), Revolute((5, 6), "D"), Revolute((6, 1), "O6")]
    return Mechanism(links, joints, Driver(2))


@pytest.mark.parametrize("k", [1e-3, 1e-2, 1.0, 20.0, 50.0])
def test_matrix_singularity_test_is_scale_invariant(k):
    """GRAPHKIN BUG found by these tests (fixed upstream in 083ec5a, which
    tests cond(A) instead): System.solve declared a system singular when
    |det A| < 1e-12·max|A|^m. det A carries units of length^(number of moment
    rows), so a well-conditioned six-bar system (cond(A) ≈ 30–8000) of 50 m
    links, or of 1 mm links, came back as nan from solve_matrix; so did a
    quick-return of 3–13 m links with cond(A) ≈ 116. A dead point is a
    property of the geometry, not of the unit of length: the answer must
    scale (T12 ∝ k² here, with ω fixed, m fixed and I_G ∝ k²)."""
    q, w, a = np.array([1.0, 2.5]), np.array([10.0, -4.0]), np.array([0.0, 30.0])
    ref = solve_forces(solve_kinematics(_watt2(1.0), q, w, a))
    r = solve_forces(solve_kinematics(_watt2(k), q, w, a))
    m = solve_matrix(r)
    A = assemble(r).A
    assert (np.linalg.cond(A) < 1e5).all()  # far from singular
    assert m.valid.all(), f"cond(A) = {np.linalg.cond(A)}, yet solve_matrix returned nan"
    np.testing.assert_allclose(m.effort, r.effort, rtol=1e-9)
    np.testing.assert_allclose(r.effort, k * k * ref.effort, rtol=1e-9)
