"""Full-cycle analysis: sweep, power balance, flywheel (Norton §11.11), joint-force index (§11.12),
shaking force and moment, transmission angle.

The strip cutter is Söylemez, Mechanisms §6.4.1 (catalog ``strip_cutter``): crank at 900 rpm,
2000 N cutting forces on links 3 and 4 at C for 124° < θ12 < 156°.
"""

import math
from dataclasses import replace

import numpy as np
import pytest

from graphkin import catalog
from graphkin.cycle import joint_force_index, size_flywheel, sweep
from graphkin.cycle.sweep import SWITCH
from graphkin.cycle.turn import weights
from graphkin.errors import GraphkinError, GraphkinWarning
from graphkin.model import PointForce
from tests.strategies import toggle_fourbar

DEG = math.pi / 180


@pytest.fixture(scope="module")
def cutter():
    return catalog.load("strip_cutter")


@pytest.fixture(scope="module")
def cycle(cutter):
    return sweep(cutter)


def _jumps(problem):
    """Jumps of T12 where the cutting force switches on (124°) and off (156°) [N·m]."""
    e = 1e-9
    T = problem.solve(at=np.radians([124 - e, 124 + e, 156 - e, 156 + e])).effort
    return T[1] - T[0], T[3] - T[2]


# -- the sweep ------------------------------------------------------------------------------------


@pytest.mark.parametrize("n", [None, 90])
def test_sweep_equals_single_position_solves(cutter, n):
    c = sweep(cutter, n)
    grid = cutter.q if n is None else np.linspace(0, 2 * math.pi, n, endpoint=False)
    switches = np.radians([124.0, 124.0, 156.0, 156.0]) + np.array([-1, 1, -1, 1]) * SWITCH
    # The grid, plus a sample just before and just after each switching angle of the cutting force.
    assert c.n == len(grid) + 4 and c.closed
    np.testing.assert_allclose(c.q, np.sort(np.concatenate([grid, switches])), rtol=0, atol=1e-15)
    assert np.all(np.diff(c.q) > 0)
    # The cutting force acts just inside the interval, not just outside it.
    assert list(cutter.mechanism.loads[0].active.mask(switches)) == [False, True, True, False]
    scale = max(np.abs(F).max() for F in c.analysis.forces.values())
    for k, q in enumerate(c.q):
        one = cutter.solve(at=[q])
        assert one.effort[0] == pytest.approx(c.torque[k], rel=1e-12, abs=1e-12 * scale)
        for key, F in c.analysis.forces.items():
            np.testing.assert_allclose(one.forces[key][0], F[k], rtol=1e-12, atol=1e-12 * scale)


def test_sweep_n_is_for_cranks_only():
    with pytest.raises(GraphkinError, match="slider"):
        sweep(catalog.load("double_slider"), 36)


def test_average_power_peaks_polar(cycle):
    T = cycle.torque
    # The periodic trapezoid over the (unequal) steps; equally spaced, it is the plain mean.
    assert cycle.average == pytest.approx(np.sum(weights(cycle.q, 2 * DEG) * T) / (2 * math.pi), rel=1e-12)
    plain = sweep(catalog.load("slider_crank_friction"), 72)
    assert plain.average == pytest.approx(plain.torque.mean(), rel=1e-12)
    np.testing.assert_allclose(cycle.power, T * 30 * math.pi, rtol=1e-12)  # ω = 900 rpm
    peaks = cycle.peaks()
    assert set(peaks.forces) == {"F12", "F23", "F34", "F14"}
    for name, pk in peaks.forces.items():
        size = np.hypot(*cycle.analysis[name].T)
        assert pk.value == size.max() and pk.at == cycle.q[np.argmax(size)] and pk.index == np.argmax(size)
    assert peaks.effort_max.value == T.max() and peaks.effort_max.at == cycle.q[np.argmax(T)]
    assert peaks.effort_min.value == T.min() and peaks.effort_min.at == cycle.q[np.argmin(T)]
    size, angle = cycle.polar("F23")
    np.testing.assert_allclose(np.stack([size * np.cos(angle), size * np.sin(angle)], 1), cycle.analysis["F23"], atol=1e-9)
    size32, angle32 = cycle.polar("F32")
    np.testing.assert_allclose(size32, size)
    np.testing.assert_allclose(np.cos(angle32 - angle), -1.0, atol=1e-12)
    with pytest.raises(GraphkinError, match="torque"):
        cycle.polar("T12")


def test_power_balance_over_a_cycle(cutter):
    """∮ T12 dθ = work done against the cutting forces per cycle (no friction; kinetic energy is periodic).

    Each cutting force is constant, so its work is exact: W = −Σ F · (r_C(156°) − r_C(124°)).
    The torque jumps where the cut starts and ends; the sweep samples either side of each jump,
    so the trapezoidal rule stays second order: the error falls ~16× when the step is quartered.
    On a plain grid the jumps would leave a first-order error of up to (h/2)(|J_on| + |J_off|).
    """
    kin = cutter.kinematics(at=np.radians([124.0, 156.0]))
    W = 0.0
    for load in cutter.mechanism.loads:
        r = kin.position(load.link, load.point)
        W -= np.dot(load.force, r[1] - r[0])
    assert W > 0  # the cutter does work on the strip
    J_on, J_off = _jumps(cutter)
    errors = {}
    for n in (180, 720):
        h = 2 * math.pi / n
        errors[n] = sweep(cutter, n).average * 2 * math.pi - W
        assert abs(errors[n]) < 0.05 * h / 2 * (abs(J_on) + abs(J_off))
    assert abs(errors[720]) < abs(errors[180]) / 12
    assert abs(errors[720]) < 1e-5 * W


def test_a_plain_grid_errs_by_half_a_step_times_the_jumps(cutter):
    """Without the switching samples the average is biased by the jumps (first order): why the sweep adds them."""
    kin = cutter.kinematics(at=np.radians([124.0, 156.0]))
    W = -sum(np.dot(load.force, np.diff(kin.position(load.link, load.point), axis=0)[0]) for load in cutter.mechanism.loads)
    J_on, J_off = _jumps(cutter)
    h = 2 * DEG
    plain = cutter.solve(at=np.radians(np.arange(0.0, 360.0, 2.0))).effort.mean() * 2 * math.pi
    assert 0.5 * h / 2 * (abs(J_on) + abs(J_off)) < abs(plain - W) <= 1.05 * h / 2 * (abs(J_on) + abs(J_off))
    assert abs(sweep(cutter).average * 2 * math.pi - W) < abs(plain - W) / 20


# -- the frame --------------------------------------------------------------------------------------


def _cycle_of(name):
    p = catalog.load(name)
    if name in ("strip_cutter", "slider_crank_friction"):
        return sweep(p, 72)
    if p.mechanism.driver.kind == "slider":  # a few positions around the book's x = 200 mm
        q = np.array([0.15, 0.2, 0.3])
        return sweep(replace(p, q=q, q_dot=np.full(3, p.q_dot[0]), q_ddot=np.full(3, p.q_ddot[0]), given={}))
    return sweep(p)


@pytest.mark.parametrize("name", ["strip_cutter", "slider_crank_friction", "double_slider", "gearset", "single_link",
                                  "epicyclic_khurmi"])  # a held annulus: a gear mesh with the frame
def test_shaking_force_and_moment_two_ways(name):
    """Σ F_j1 over the frame's joints (plus the driver's reaction) = −Σ m a_G + Σ external forces and weights;
    the moment about the origin (with −T12) = Σ (r_G × (−m a_G) − I_G α) + moments of the external loads."""
    c = _cycle_of(name)
    kin = c.analysis.kinematics
    mech = c.problem.mechanism
    F = np.zeros((c.n, 2))
    M = np.zeros(c.n)
    for i in mech.moving:
        link = mech.link(i)
        G = kin.G(i)
        f = -link.mass * kin.a_G(i) + np.array([0.0, -link.mass * mech.gravity])
        F += f
        M += G[:, 0] * f[:, 1] - G[:, 1] * f[:, 0] - link.I_G * kin.al(i)
    for load in mech.loads:
        on = np.ones(c.n) if load.active is None else load.active.mask(kin.q)
        if isinstance(load, PointForce):
            f = on[:, None] * np.array(load.force)
            P = kin.position(load.link, load.point)
            F += f
            M += P[:, 0] * f[:, 1] - P[:, 1] * f[:, 0]
        else:
            M += on * load.torque
    scale = max(np.abs(F).max(), 1.0)
    np.testing.assert_allclose(c.shaking_force(), F, rtol=1e-10, atol=1e-10 * scale)
    np.testing.assert_allclose(c.shaking_moment(), M, rtol=1e-10, atol=1e-10 * max(np.abs(M).max(), 1.0))


def test_transmission_angle_law_of_cosines(cycle):
    a, b, c, d = 0.085, 0.235, 0.550, 0.565  # crank A0A, coupler AB, rocker B0B, frame A0B0
    f2 = a * a + d * d - 2 * a * d * np.cos(cycle.q)
    mu = np.arccos((b * b + c * c - f2) / (2 * b * c))
    np.testing.assert_allclose(cycle.transmission_angle(), np.minimum(mu, np.pi - mu), atol=1e-12)
    with pytest.raises(GraphkinError, match="four-bar"):
        _cycle_of("slider_crank_friction").transmission_angle()


# -- flywheel -----------------------------------------------------------------------------------------


def test_energy_table_closes_and_matches_a_dense_grid(cutter):
    """Pulse areas sum to zero about the trapezoidal average; E agrees with a dense grid.

    Reference: 36000 positions (0.01°, and the samples either side of each jump), cumulative trapezoid
    of T − T_avg over the actual steps, max − min. With the torque's jumps sampled on both sides, the
    curve is smooth between samples and E_h errs by O(h²): quartering the step cuts the error ~16×.
    (On a plain grid each jump would add up to h|J|/2, first order.)
    """
    dense = sweep(cutter, 36000)
    D = dense.torque - dense.average
    h = np.diff(np.append(dense.q, dense.q[0] + 2 * math.pi))
    U = np.concatenate([[0.0], np.cumsum(0.5 * (D + np.roll(D, -1)) * h)])
    E_ref = U.max() - U.min()
    err = {}
    for n in (180, 720):
        f = sweep(cutter, n).flywheel(0.05)
        assert len(f.crossings) == len(f.areas) == 4
        assert abs(f.areas.sum()) < 1e-12 * np.abs(f.areas).sum()
        assert f.accumulated[-1] == pytest.approx(0.0, abs=1e-12 * np.abs(f.areas).sum())
        assert f.E == pytest.approx(f.accumulated.max(initial=0) - f.accumulated.min(initial=0))
        rows = f.table()
        assert [r.start for r in rows[1:]] == [r.end for r in rows[:-1]]
        assert rows[-1].end == pytest.approx(rows[0].start + 2 * math.pi)
        err[n] = abs(f.E - E_ref)
    J = abs(_jumps(cutter)[0]) + abs(_jumps(cutter)[1])
    assert err[180] < 0.05 * (2 * math.pi / 180) * J  # far inside the first-order bound of a plain grid
    assert err[720] < err[180] / 10


def test_flywheel_by_hand(cycle):
    f = cycle.flywheel(0.05)
    omega = 900 * 2 * math.pi / 60
    assert f.T_avg == pytest.approx(cycle.average, rel=1e-12)
    assert f.I_s == pytest.approx(f.E / (0.05 * omega**2), rel=1e-12)
    disk = f.disk(7850.0, 0.025)
    r = (2 * f.I_s / (math.pi * 7850.0 * 0.025)) ** 0.25
    assert disk.radius == pytest.approx(r, rel=1e-12)
    assert disk.mass == pytest.approx(7850.0 * math.pi * r**2 * 0.025, rel=1e-12)
    assert disk.I == pytest.approx(f.I_s, rel=1e-12)
    rim = f.rim(7850.0, 0.25, 0.03)
    assert rim.outer_radius - rim.inner_radius == pytest.approx(rim.width)
    assert 0.5 * rim.mass * (rim.outer_radius**2 + rim.inner_radius**2) == pytest.approx(f.I_s, rel=1e-12)
    assert rim.mass < disk.mass  # the rim uses less material for the same inertia
    with pytest.raises(GraphkinError, match="width"):
        f.rim(7850.0, 0.01, 0.001)
    # Speed with the flywheel: ω_avg (1 ± Cs/2), up to the sampling of the extremes.
    w = f.speed()
    assert w.max() == pytest.approx(omega * 1.025, rel=1e-4) and w.min() == pytest.approx(omega * 0.975, rel=1e-4)
    # The motor's torque swing collapses from hundreds of N·m to about T_avg Cs (1 − s)/s.
    s = 0.05
    Tm = f.smoothed_torque(slip=s)
    # ∮ T_m dθ = ∮ T dθ exactly for the filter; the trapezoid of T_m (not linear between samples)
    # errs by O(h²): small on the 2° grid, and 16× smaller on a grid four times finer.
    def error(f):
        return np.sum(weights(f.theta, f.gap) * f.smoothed_torque(slip=s)) / (2 * math.pi) - f.T_avg

    assert abs(error(f)) < 1e-3 * f.T_avg
    fine = sweep(cycle.problem, 720)
    assert abs(error(size_flywheel(fine.q, fine.torque, omega_avg=omega, Cs=0.05))) < abs(error(f)) / 10
    assert np.ptp(Tm) < 0.02 * np.ptp(cycle.torque)
    assert np.ptp(Tm) <= 1.1 * f.T_avg * 0.05 * (1 - s) / s
    # A stiffer motor (less slip) cannot let the flywheel work: more of the swing reaches it.
    assert np.ptp(f.smoothed_torque(slip=0.005)) > np.ptp(Tm)


def test_flywheel_of_a_harmonic_torque():
    """T = T0 + A sin θ: crossings at 0 and π, E = 2A; the motor sees A/√(1 + τ²) with τ = ω I_s/k_m."""
    theta = np.linspace(0, 2 * math.pi, 720, endpoint=False)
    T0, A, omega, Cs, s = 10.0, 4.0, 50.0, 0.02, 0.05
    f = size_flywheel(theta, T0 + A * np.sin(theta), omega_avg=omega, Cs=Cs)
    assert f.T_avg == pytest.approx(T0, rel=1e-12)
    # θ = 0 counts as on the positive side, so its crossing is found on the step that closes the turn; it is
    # reported at 0°, where it is (issue 13: it was reported at 360°), and the table starts there.
    np.testing.assert_allclose(f.crossings, [0.0, math.pi], atol=1e-12)
    np.testing.assert_allclose(f.areas, [2 * A, -2 * A], rtol=1e-4)  # trapezoid error (h²/12)
    np.testing.assert_allclose(f.accumulated, [2 * A, 0.0], rtol=1e-4, atol=1e-12)
    assert f.E == pytest.approx(2 * A, rel=1e-4)
    tau = omega * f.I_s / (T0 * (1 - s) / (s * omega))
    Tm = f.smoothed_torque(slip=s)
    assert np.ptp(Tm) / 2 == pytest.approx(A / math.sqrt(1 + tau**2), rel=1e-4)
    # The repeated end point form (0° … 360°) gives the same flywheel.
    g = size_flywheel(np.append(theta, 2 * math.pi), T0 + A * np.sin(np.append(theta, 2 * math.pi)), omega_avg=omega, Cs=Cs)
    assert g.E == pytest.approx(f.E, rel=1e-12) and g.T_avg == pytest.approx(f.T_avg, rel=1e-12)
    np.testing.assert_allclose(g.smoothed_torque(slip=s)[:-1], Tm, rtol=1e-12)
    with pytest.raises(GraphkinError, match="turn"):
        size_flywheel(theta[:300], np.ones(300), omega_avg=omega, Cs=Cs)


# -- joint-force index ----------------------------------------------------------------------------


def test_joint_force_index_toward_a_toggle():
    t = math.acos(-0.35)
    approach = t - np.radians([30, 10, 3, 1, 0.3, 0.1, 0.01, 1e-4])
    theta = np.concatenate([approach, [t, t + DEG]])
    jfi = joint_force_index(toggle_fourbar(theta))
    assert jfi.units == ""
    assert all(link.mass == 0 and link.I_G == 0 for link in jfi.analysis.mechanism.links)  # static
    idx = jfi.index[:8]
    # Rises toward the toggle, like 1/√(θ_t − θ): 0.01° away it is ~25, 1e-4° away ~250.
    assert np.all(np.isfinite(idx)) and np.all(np.diff(idx) > 0)
    assert idx[0] < 1.5 and idx[-1] > 100 and jfi.peak.index == 7
    np.testing.assert_allclose(jfi.over_limit, theta[:8][idx > 2])
    # The toggle and the position beyond it have no index, and are listed with a reason.
    assert np.all(np.isnan(jfi.index[8:]))
    listed = dict(jfi.immovable)
    assert set(listed) == {theta[8], theta[9]}
    assert all(isinstance(why, str) and why for why in listed.values())
    assert "cannot be assembled" in listed[theta[9]] and "dead point" not in listed[theta[9]]  # one reason, the true one
    assert "dead point" in listed[theta[8]]
    # Which joint carries the largest force, and none where there is no index.
    assert set(jfi.joint[:8]) <= {"F12", "F23", "F34", "F14"} and list(jfi.joint[8:]) == ["", ""]


def test_joint_force_index_by_hand():
    # One link with a force at its tip: the pin carries exactly the load, JFI = 1.
    single = joint_force_index(catalog.load("single_link"))
    assert single.index[0] == pytest.approx(1.0, rel=1e-12) and single.units == ""
    # A torque load on the pinion: tooth force T/(r3 cos φ) at the mesh and both pivots, JFI in 1/m.
    gears = joint_force_index(catalog.load("gearset"))
    assert gears.units == "1/m"
    assert gears.index[0] == pytest.approx(1 / (0.040 * math.cos(20 * DEG)), rel=1e-12)


def test_joint_force_index_of_the_strip_cutter(cutter):
    jfi = joint_force_index(cutter)
    cut = (jfi.q > 124 * DEG) & (jfi.q < 156 * DEG)
    # 126° … 154° on the 2° grid and the samples just inside 124° and 156°: the same positions as the sweep.
    assert cut.sum() == 17 and np.array_equal(jfi.q, sweep(cutter).q)
    assert np.all(np.isfinite(jfi.index[cut])) and np.all(np.isnan(jfi.index[~cut]))
    np.testing.assert_allclose(jfi.unloaded, jfi.q[~cut])
    assert jfi.immovable == ()
    np.testing.assert_allclose(jfi.load[cut], 2000.0)
    static = jfi.analysis
    largest = np.max([np.hypot(*F.T) for F in static.forces.values()], axis=0)
    np.testing.assert_allclose(jfi.index[cut], largest[cut] / 2000.0, rtol=1e-12)
    assert jfi.peak.value == pytest.approx(np.nanmax(jfi.index))


def test_sweep_at_given_positions_and_the_mean_over_unequal_steps(cutter, cycle):
    same = sweep(cutter, at=cycle.q)
    np.testing.assert_array_equal(same.q, cycle.q)
    np.testing.assert_allclose(same.torque, cycle.torque, rtol=0, atol=0)
    with pytest.raises(GraphkinError, match="not both"):
        sweep(cutter, 36, at=cycle.q)
    # The mean of any array uses the average's rule, so mean(power) = ω · average exactly.
    assert cycle.mean(cycle.power) == pytest.approx(cycle.average * cycle.q_dot[0], rel=1e-12)
    assert cycle.mean(cycle.torque) == cycle.average
    with pytest.raises(GraphkinError, match="one value per position"):
        cycle.mean(np.ones(3))


def test_a_book_s_given_values_are_never_swept_over_the_cycle():
    """Makdin's slider-crank gives θ3, α3 and the a_G measured at θ = 60°: they held at every angle of a sweep, so
    `graphkin cycle --n 8` printed torques from the coupler standing at −13° throughout (exit 0). Now solving it
    elsewhere is refused; at the book's own position it is solved with them; a sweep says so and solves the motion
    its input produces."""
    p = catalog.load("slider_crank_dynamic_makdin")
    with pytest.raises(GraphkinError, match=r"\[given\].* own position only \(θ = 60°\), not at θ = 0°"):
        p.solve(at=[0.0, math.radians(60)])
    assert p.solve(at=p.q).valid.all()
    with pytest.warns(GraphkinWarning, match=r"\[given\] values hold at θ = 60° only; the cycle is solved with"):
        derived = sweep(p, 8).analysis.kinematics
    assert np.ptp(np.unwrap(derived.theta[3])) > 0.1  # the coupler swings as the crank turns
    assert derived.theta[3] == pytest.approx(sweep(p.without_given(), 8).analysis.kinematics.theta[3], abs=0)
