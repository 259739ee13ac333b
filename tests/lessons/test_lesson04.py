"""The claims of lesson 04 (sizing a flywheel, the joint-force index), checked: they left the reading path (issue 27).

Norton's Table 11-1 arithmetic, the energy table on a curve integrated by hand, the strip cutter's
average from the work of the cut and the grid-order argument for E, the table's reading, E from the
links' kinetic energy, the scalings of I_s, a disk and a rim, the speed and the motor's torque against
a simulation of the shaft, the joint-force index against the matrix and a linkage that toggles, the
explorer at 600 rpm, and the exercises' keys.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import graphkin as gk
from tests.lessons.explorer_reads import effort, force, force_tol, scene_of, superposed_effort, torque_tol

TURN = 2 * math.pi
RPM = math.pi / 30
STEEL, CAST_IRON = 7850.0, 7200.0


@pytest.fixture(scope="module")
def cutter():
    p = gk.load("strip_cutter")
    c = gk.sweep(p)
    return p, c, c.flywheel(0.05)


def exact_average(p):
    cut = list(p.mechanism.loads)
    ends = p.kinematics(at=[cut[0].active.start, cut[0].active.stop])
    W_cut = sum(np.array(ld.force) @ (ends.position(ld.link, ld.point)[1] - ends.position(ld.link, ld.point)[0])
                for ld in cut)
    return W_cut, -W_cut / TURN


def test_nortons_table_arithmetic():
    E_book = 200.73 - (-60.32)  # in·lb, Norton §11.11 (Table 11-1)
    assert math.isclose(E_book, 261.05, abs_tol=0.005)


def test_the_energy_table_on_a_curve_integrated_by_hand():
    T0, a, b = 10.0, 20.0, 30.0
    theta = (np.arange(720) + 0.5) * TURN / 720
    f = gk.size_flywheel(theta, T0 + a * np.cos(theta) + b * np.sin(2 * theta), omega_avg=100.0, Cs=0.05)
    phi = math.asin(-a / (2 * b))
    crossings = np.array([math.pi / 2, math.pi - phi, 3 * math.pi / 2, TURN + phi])
    areas = np.diff([a * math.sin(x) + b * math.sin(x) ** 2 for x in np.append(crossings, crossings[0] + TURN)])
    acc = np.cumsum(areas)
    E_exact = max(acc.max(), 0) - min(acc.min(), 0)
    assert math.isclose(f.T_avg, T0, rel_tol=1e-12)
    assert np.allclose(f.crossings, crossings, atol=1e-4)
    assert np.allclose(f.areas, areas, atol=2e-3)
    assert math.isclose(E_exact, 160 / 3) and math.isclose(f.E, E_exact, rel_tol=1e-4)
    assert math.isclose(f.I_s, f.E / (0.05 * 100.0**2))


def test_the_strip_cutter_over_a_turn(cutter):
    p, c, f = cutter
    peaks = c.peaks()
    W_cut, T_exact = exact_average(p)
    assert c.closed and c.valid.all() and c.n == 184 and len(p.q) == 180
    assert math.isclose(float(c.q_dot[0]) / RPM, 900)
    assert round(peaks.effort_max.value) == 256 and round(-peaks.effort_min.value) == 325
    assert round(c.average) == 8 and round(abs(c.average / T_exact - 1), 4) == 0.0001
    assert round(-W_cut) == 50


def test_E_converges_at_second_order_with_the_samples_at_the_jumps(cutter):
    p, c, f = cutter
    omega = float(c.q_dot[0])
    _, T_exact = exact_average(p)
    ns = (180, 360, 720, 1440, 2880, 5760)
    err_plain, err_sweep, E_plain, E_sweep = [], [], [], []
    for m in ns:
        grid = np.linspace(0.0, TURN, m, endpoint=False)
        fp = gk.size_flywheel(grid, p.solve(at=grid).effort, omega_avg=omega, Cs=0.05)
        fs = gk.sweep(p, m).flywheel(0.05)
        err_plain.append(fp.T_avg - T_exact)
        err_sweep.append(fs.T_avg - T_exact)
        E_plain.append(fp.E)
        E_sweep.append(fs.E)
    r_plain, r_sweep = np.divide(err_plain[:-1], err_plain[1:]), np.divide(err_sweep[:-1], err_sweep[1:])
    assert np.all(abs(r_plain - 2) < 0.05) and np.all(abs(r_sweep - 4) < 0.05)
    assert round(E_plain[0] / E_sweep[-1] - 1, 3) == -0.003
    A, B = f.crossings[:2]
    assert np.allclose(np.degrees([A, B]), [10, 76], atol=0.5)
    assert round(-err_plain[0], 2) == 0.48 and round(B - A, 2) == 1.16
    assert math.isclose(-err_plain[0] * (B - A), E_sweep[0] - E_plain[0], rel_tol=0.01)
    assert abs(E_sweep[0] / E_sweep[-1] - 1) < 0.001


def test_reading_the_energy_table(cutter):
    _, _, f = cutter
    assert np.allclose(np.interp(f.crossings, f.theta, f.T, period=TURN), f.T_avg, atol=1e-9 * np.abs(f.T).max())
    assert abs(f.areas.sum()) < 1e-12 * f.E
    for first in range(len(f.areas)):
        running = np.cumsum(np.roll(f.areas, -first))
        assert math.isclose(max(running.max(), 0) - min(running.min(), 0), f.E, rel_tol=1e-12)
    assert len(f.crossings) == 4 and np.allclose(np.degrees(f.crossings[:2]), [9.6, 75.8], atol=0.05)
    assert round(f.areas[0], 1) == -237.2 and round(f.areas[-1], 1) == 211.8
    assert np.argmin(f.accumulated) == 0 and abs(f.accumulated[-1]) < 1e-9
    assert round(f.E, 1) == 237.2


def test_E_from_the_kinetic_energy_of_the_links(cutter):
    p, c, f = cutter
    W_cut, T_exact = exact_average(p)
    cut = list(p.mechanism.loads)
    start, stop = cut[0].active.start, cut[0].active.stop
    ends = p.kinematics(at=[start, stop])
    fine = np.linspace(0.0, TURN, 7200, endpoint=False)
    kin, mech = p.kinematics(at=fine), p.mechanism
    K = sum(0.5 * mech.link(j).mass * np.sum(kin.v_G(j) ** 2, axis=1) + 0.5 * mech.link(j).I_G * kin.omega[j] ** 2
            for j in mech.moving)
    in_cut = p.kinematics(at=np.clip(fine, start, stop))
    W_upto = sum((in_cut.position(ld.link, ld.point) - ends.position(ld.link, ld.point)[0]) @ np.array(ld.force)
                 for ld in cut)
    U = K - K[0] - W_upto - T_exact * fine
    E_energy = U.max() - U.min()
    assert f.E < E_energy and abs(f.E - E_energy) < 0.001 * E_energy
    assert abs(gk.sweep(p, 11520).flywheel(0.05).E - E_energy) < 0.0002 * E_energy
    assert np.allclose(np.degrees(f.crossings[:2]), np.degrees([fine[np.argmax(U)], fine[np.argmin(U)]]), atol=0.1)
    assert round(np.ptp(K), -1) == 230 and round(K.min()) == 215 and round(K.max()) == 443


def test_the_system_inertia_a_disk_and_a_rim(cutter):
    _, c, f = cutter
    omega = float(c.q_dot[0])
    assert math.isclose(f.I_s, f.E / (0.05 * omega**2), rel_tol=1e-12)
    assert math.isclose(gk.size_flywheel(f.theta, f.T, omega_avg=f.omega_avg, Cs=0.025).I_s, 2 * f.I_s, rel_tol=1e-12)
    assert math.isclose(gk.size_flywheel(f.theta, f.T, omega_avg=f.omega_avg / 2, Cs=0.05).I_s, 4 * f.I_s,
                        rel_tol=1e-12)
    disk = f.disk(density=STEEL, thickness=0.050)
    m_hand = STEEL * math.pi * disk.radius**2 * disk.thickness
    assert math.isclose(disk.mass, m_hand, rel_tol=1e-12) and math.isclose(0.5 * m_hand * disk.radius**2, f.I_s)
    assert math.isclose(gk.mass.disk(disk.radius, disk.thickness, STEEL).I_G, f.I_s, rel_tol=1e-12)
    rim = f.rim(density=CAST_IRON, mean_radius=0.250, thickness=0.050)
    ring = gk.mass.hollow_cylinder(rim.inner_radius, rim.outer_radius, rim.thickness, CAST_IRON)
    assert math.isclose(ring.I_G, f.I_s, rel_tol=1e-12) and math.isclose(ring.m, rim.mass, rel_tol=1e-12)
    assert math.isclose(f.disk(STEEL, 0.1).mass / f.disk(STEEL, 0.025).mass, 2.0, rel_tol=1e-12)
    assert rim.mass < disk.mass


def test_before_and_after_against_a_simulation_of_the_shaft(cutter):
    _, c, f = cutter
    Cs, slip = 0.05, 0.05
    w = f.speed()
    assert abs(np.ptp(w) / f.omega_avg - Cs) < 0.01 * Cs
    assert abs(0.5 * f.I_s * (w.max() ** 2 - w.min() ** 2) - f.E) < 0.01 * f.E
    k_m = f.T_avg * (1 - slip) / (slip * f.omega_avg)
    steps = np.diff(np.append(f.theta, f.theta[0] + TURN))

    def shaft(x, w):
        return (f.T_avg - k_m * (w - f.omega_avg) - np.interp(x, f.theta, f.T, period=TURN)) / (f.I_s * w)

    w_sim = f.omega_avg
    for _ in range(60):
        one_turn = np.empty(len(f.theta))
        for i, (x, h) in enumerate(zip(f.theta, steps, strict=True)):
            one_turn[i] = w_sim
            k1 = shaft(x, w_sim)
            k2 = shaft(x + h / 2, w_sim + h / 2 * k1)
            k3 = shaft(x + h / 2, w_sim + h / 2 * k2)
            k4 = shaft(x + h, w_sim + h * k3)
            w_sim = w_sim + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    Tm_sim = f.T_avg - k_m * (one_turn - f.omega_avg)
    w_mean = np.sum(0.5 * (one_turn + np.roll(one_turn, -1)) * steps) / TURN
    Tm = f.smoothed_torque(slip)
    assert abs(w_sim - one_turn[0]) < 1e-4
    assert np.abs(Tm - Tm_sim).max() < 0.02 * np.ptp(Tm)
    assert abs(np.ptp(one_turn) / f.omega_avg - Cs) < 0.05 * Cs
    assert abs(w_mean - f.omega_avg) < 1e-3 * Cs * f.omega_avg
    assert round(Tm.min()) == 5 and round(Tm.max(), 1) == 12.7
    assert round(f.T.min()) == -325 and round(f.T.max()) == 256
    swing = f.T_avg * Cs * (1 - slip) / slip
    assert abs(np.ptp(Tm) - swing) < 0.02 * swing
    assert abs(np.ptp(Tm) / np.ptp(c.flywheel(0.01).smoothed_torque(slip)) - 5.0) < 0.1


def test_the_joint_force_index(cutter):
    p, c, _ = cutter
    jfi = gk.joint_force_index(p)
    defined = np.isfinite(jfi.index)
    cut = list(p.mechanism.loads)
    assert np.array_equal(jfi.q, c.q)
    assert defined.sum() + len(jfi.unloaded) == c.n and not jfi.immovable and len(jfi.over_limit) == 0
    assert np.array_equal(defined, cut[0].active.mask(jfi.q))
    assert np.all(abs(jfi.index[defined] - 1.4) < 0.05)
    static = gk.static_problem(p)
    assert all(link.mass == 0 and link.I_G == 0 for link in static.mechanism.links)
    system = gk.assemble(static.solve(at=[jfi.peak.at]))
    x = dict(zip(system.unknowns, np.linalg.solve(system.A[0], system.b[0]), strict=True))
    pins = {name: math.hypot(x[name + "x"], x[name + "y"]) for name in ("F12", "F23", "F34", "F14")}
    assert math.isclose(max(pins.values()) / 2000.0, jfi.peak.value, rel_tol=1e-9)
    assert np.allclose([x["F34x"], x["F34y"]], np.array([x["F23x"], x["F23y"]]) + cut[0].force)


def test_a_linkage_that_toggles():
    text = gk.catalog.path("strip_cutter").read_text()
    crank = 'A = ["85 mm", "0 mm"]'
    assert text.count(crank) == 1
    long_crank = gk.parse_problem(text.replace(crank, 'A = ["245 mm", "0 mm"]'))
    jfi = gk.joint_force_index(long_crank)
    cycle = gk.sweep(long_crank)
    mu = np.degrees(cycle.transmission_angle())
    ok = np.isfinite(jfi.index)
    stuck = np.array([q for q, _ in jfi.immovable])

    def length(j, P, Q):
        return math.dist(long_crank.mechanism.link(j).points[P], long_crank.mechanism.link(j).points[Q])

    a1, a2, a3, a4 = length(1, "A0", "B0"), length(2, "A0", "A"), length(3, "A", "B"), length(4, "B0", "B")
    theta_t = math.acos((a2**2 + a1**2 - (a3 + a4) ** 2) / (2 * a2 * a1))
    q = jfi.q
    assert np.array_equal(cycle.q, q)
    assert np.array_equal(stuck, q[(q > theta_t) & (q < TURN - theta_t)])
    assert np.array_equal(np.isin(q, stuck), ~long_crank.kinematics(at=q).valid)
    assert np.all(np.diff(jfi.index[ok]) > 0) and np.all(np.diff(mu[ok]) < 0)
    assert jfi.peak.index == np.flatnonzero(ok)[-1] and jfi.peak.value > 5
    assert np.array_equal(jfi.over_limit, q[ok])


def test_the_explorer_at_600_rpm(cutter):
    """600 rpm typed in the explorer's speed box: the browser sums the scene's two presolved parts (the strip cutter's
    forces are linear in ω²); that sum is the sweep of the file at 600 rpm, and so is the scene Python sends for it."""
    pytest.importorskip("anywidget")
    p, _, _ = cutter
    text = gk.catalog.path("strip_cutter").read_text()
    speed_line = 'omega = "900 rpm"'
    assert text.count(speed_line) == 1
    ex = gk.explore(p)
    s = scene_of(ex)
    c600 = gk.sweep(gk.parse_problem(text.replace(speed_line, 'omega = "600 rpm"')), ex.n)
    c900 = gk.sweep(p, ex.n)
    T_static = gk.static_problem(p).solve(at=c900.q).effort
    assert ex.n == 360 and s["n"] == 364 and np.allclose(s["input"]["values"], c600.q)
    assert s["speed"]["kind"] == "superpose" and math.isclose(s["speed"]["value"], 900 * RPM)
    typed = superposed_effort(s, 600 * RPM)
    assert np.allclose(typed, c600.torque, rtol=0, atol=2 * torque_tol(s))
    assert np.allclose(c600.torque, T_static + (600 / 900) ** 2 * (c900.torque - T_static), rtol=1e-9, atol=1e-9)
    for k, f in enumerate(s["forces"]):
        parts = s["speed"]["superpose"]["forces"][k]
        F = np.array(parts["rest"], float) + (600 * RPM) ** 2 * np.array(parts["omega2"], float)
        assert np.allclose(F.reshape(-1, 2), c600.analysis[f["name"]], rtol=0, atol=2 * force_tol(s)), f["name"]
    f600, f900 = c600.flywheel(0.05), c900.flywheel(0.05)
    assert f600.E < 0.5 * f900.E and f600.I_s > f900.I_s
    i_max = int(np.argmax(c600.torque))
    assert i_max == np.flatnonzero(p.mechanism.loads[0].active.mask(c600.q))[0]
    theta = math.ceil(math.degrees(c600.q[i_max]))
    assert theta == 125
    # The same speed asked of Python: a new scene, at the file's 600 rpm, shown at 125°.
    ex.set("speed", 600 * RPM)
    ex.position = theta
    s600, i_at = scene_of(ex), ex.index
    assert math.isclose(math.degrees(c600.q[i_at]), theta, abs_tol=1e-9)
    assert abs(effort(s600, i_at) - c600.torque[i_at]) <= torque_tol(s600)
    assert abs(effort(s600, i_at, "graphical") - c600.torque[i_at]) <= 1e-9 * abs(c600.torque[i_at]) + torque_tol(s600)
    for f in s600["forces"]:
        assert np.allclose(force(s600, f["name"], i_at), c600.analysis[f["name"]][i_at], rtol=0, atol=force_tol(s600))


def test_the_exercises_keys_and_the_feedback():
    pytest.importorskip("ipywidgets")
    student, demo = "your-id", "example"
    key = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("flywheel", demo)["questions"]}
    slipped = {"E": f"{key['E'] / 1000:.4g} J", "I_s": f"{key['I_s']:.4g} kg*m^2"}
    report = gk.exercises.grade("flywheel", demo, slipped)
    verdict = {q["id"]: (q["verdict"], q["slip"], q["score"] / q["max"]) for q in report["questions"]}
    assert verdict["E"] == ("slip", "power_of_ten", 0.5) and verdict["I_s"] == ("correct", None, 1.0)
    mine = gk.exercises.variant("flywheel", student)
    assert f"Cs = {mine.Cs:g}" in [g["shown"] for g in gk.exercises.make("flywheel", student)["data"]]
    key1 = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("flywheel", student)["questions"]}
    f_mine = gk.sweep(mine.problem, 360).flywheel(mine.Cs)
    assert math.isclose(f_mine.E, key1["E"], rel_tol=1e-9) and math.isclose(f_mine.I_s, key1["I_s"], rel_tol=1e-9)
    key2 = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("joint_force_index", student)["questions"]}
    jfi_mine = gk.joint_force_index(gk.exercises.variant("joint_force_index", student).problem, 360)
    assert math.isclose(jfi_mine.peak.value, key2["JFI"], rel_tol=1e-9)
    assert math.isclose(jfi_mine.peak.at, key2["JFI_at"], rel_tol=1e-9)
    box = gk.exercise("flywheel", "")
    box.student.value = demo
    for q in gk.exercises.key("flywheel", demo)["questions"]:
        box.answers[q["id"]].value = q["answer"]["text"]
    assert box.check()["score"] == 2
    box.answers["E"].value = slipped["E"]
    assert box.check()["score"] == 1.5 and box.report["questions"][0]["slip"] == "power_of_ten"


def test_a_longer_crank_raises_the_index_over_the_exercises_range():
    """Exercise 2 asks the student to reason from their crank length (70-100 mm) to their index."""
    text = gk.catalog.path("strip_cutter").read_text()
    peaks = [gk.joint_force_index(gk.parse_problem(text.replace('A = ["85 mm", "0 mm"]', f'A = ["{a} mm", "0 mm"]')),
                                  360).peak for a in range(70, 101, 5)]
    assert np.all(np.diff([pk.value for pk in peaks]) > 0)
    assert all(140 < math.degrees(pk.at) < 156 for pk in peaks)  # late in the cut
