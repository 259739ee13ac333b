"""The claims of lesson 03 (the strip cutter over a whole cycle), checked: they left the reading path (issue 27).

The sweep against three one-position routes, the cut's torque by virtual work, the trapezoidal rule's
orders on a curve with jumps (the lesson keeps this detour once; lesson 04 points to it), the power
balance, the polar peaks, the shaking force and moment, the transmission angle, the explorer driven from
code, the speed and cutting-range predictions, the exercises' keys and the animation.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

import graphkin as gk
from graphkin.cycle.sweep import SWITCH
from tests.lessons.explorer_reads import effort, force, force_tol, scene_of, torque_tol

RPM = math.pi / 30


def at_angle(cycle, degrees):
    i = int(np.argmin(abs((np.degrees(cycle.q) - degrees + 180) % 360 - 180)))
    assert math.isclose(np.degrees(cycle.q[i]), degrees, abs_tol=1e-9)
    return i


def cutting_work(problem):
    W = 0.0
    for load in problem.mechanism.loads:
        r_C = problem.kinematics(at=[load.active.start, load.active.stop]).position(load.link, load.point)
        W -= float(np.asarray(load.force) @ (r_C[1] - r_C[0]))
    return W


@pytest.fixture(scope="module")
def cutter():
    p = gk.load("strip_cutter")
    cyc = gk.sweep(p)
    no_cut = replace(p, mechanism=replace(p.mechanism, loads=()))
    return p, cyc, no_cut, gk.sweep(no_cut)


def T_cut_of(cyc, problem):
    kin = cyc.analysis.kinematics
    return -sum(kin.velocity(ld.link, ld.point) @ np.asarray(ld.force) for ld in problem.mechanism.loads) / kin.omega[2]


def test_the_machine_and_the_sweep(cutter):
    p, cyc, _, _ = cutter
    mech = p.mechanism
    assert len(p.q) == 180 and np.allclose(np.diff(p.q), math.radians(2))
    assert math.isclose(float(p.q_dot[0]) / RPM, 900) and np.allclose([abs(ld.force[1]) for ld in mech.loads], 2000)
    assert cyc.closed and cyc.valid.all() and cyc.n == len(p.q) + 4 and np.all(np.isin(p.q, cyc.q))
    extra = ~np.isin(cyc.q, p.q)
    switches = np.array([mech.loads[0].active.start, mech.loads[0].active.stop])
    assert np.allclose(np.sort(cyc.q[extra]), np.repeat(switches, 2) + [-SWITCH, SWITCH] * 2, rtol=0, atol=1e-15)
    r = cyc.analysis
    for a in (40, 140, 342):  # the sweep against the three one-position routes
        i = at_angle(cyc, a)
        one = p.solve(at=[math.radians(a)])
        system = gk.assemble(one)
        x = dict(zip(system.unknowns, np.linalg.solve(system.A[0], system.b[0]), strict=True))
        c = gk.construct_forces(one.kinematics, 0)
        for name in r.names()[:-1]:
            F = r[name][i]
            for other in (one[name][0], [x[name + "x"], x[name + "y"]], c[name]):
                assert np.linalg.norm(np.subtract(other, F)) < 1e-9 * np.linalg.norm(F)
        for other in (one.effort[0], x["T12"], c.effort):
            assert math.isclose(other, cyc.torque[i], rel_tol=1e-9, abs_tol=1e-9)


def test_what_the_cut_adds_is_its_virtual_work(cutter):
    p, cyc, no_cut, cyc0 = cutter
    mech = p.mechanism
    T0 = no_cut.solve(at=cyc.q).effort
    on = mech.loads[0].active.mask(cyc.q)
    extra = ~np.isin(cyc.q, p.q)
    T_cut = T_cut_of(cyc, p)
    assert cyc0.n == len(p.q) and np.allclose(cyc0.torque, T0[~extra], rtol=0, atol=1e-12)
    assert not on[at_angle(cyc, 124)] and not on[at_angle(cyc, 156)]
    assert np.allclose(cyc.torque - T0, np.where(on, T_cut, 0.0), rtol=0, atol=1e-9)
    i_sw = np.flatnonzero(extra)
    jumps = cyc.torque[i_sw[1::2]] - cyc.torque[i_sw[::2]]
    assert np.allclose(jumps, [T_cut[i_sw[1]], -T_cut[i_sw[2]]], rtol=1e-6)
    assert np.all(T_cut[on] > 0) and round(jumps[0]) == 116 and round(-jumps[1]) == 58
    assert np.ptp(cyc0.torque) > 4 * T_cut[on].max()
    pk = cyc.peaks()
    assert not on[pk.effort_max.index] and not on[pk.effort_min.index]


def test_average_work_and_the_trapezoidal_rule(cutter):
    p, cyc, _, cyc0 = cutter
    omega = float(p.q_dot[0])
    assert abs(cyc0.average) < 1e-9 * abs(cyc0.torque).max()
    W_cut = cutting_work(p)
    exact = W_cut / (2 * math.pi)
    assert round(W_cut) == 50 and round(abs(cyc.average / exact - 1), 4) == 0.0001
    plain = p.solve(at=np.radians(np.arange(0, 360, 2.0))).effort.mean()
    assert round(plain / exact - 1, 2) == -0.06
    ns = (180, 360, 720, 1440, 2880)
    plain_err = [p.solve(at=np.linspace(0, 2 * math.pi, n, endpoint=False)).effort.mean() - exact for n in ns]
    sweep_err = [gk.sweep(p, n).average - exact for n in ns]
    assert np.all(abs(np.divide(plain_err[:-1], plain_err[1:]) - 2) < 0.05)  # first order
    assert np.all(abs(np.divide(sweep_err[:-1], sweep_err[1:]) - 4) < 0.05)  # second order
    T_cut = T_cut_of(cyc, p)
    missed = math.radians(2) / 2 * (T_cut[at_angle(cyc, 124)] + T_cut[at_angle(cyc, 156)])
    assert math.isclose(plain + missed / (2 * math.pi), cyc.average, rel_tol=0, abs_tol=1e-6)
    assert np.allclose(cyc.power, cyc.torque * omega)
    assert round(exact * omega / 1e3, 2) == 0.76
    assert round(cyc.power.min() / 1e3) == -31 and round(cyc.power.max() / 1e3) == 24


def test_power_balance_at_every_position(cutter):
    p, cyc, _, _ = cutter
    r, kin = cyc.analysis, cyc.analysis.kinematics
    on = p.mechanism.loads[0].active.mask(cyc.q)
    P_inertia = sum(np.sum(r.inertia(j).F * kin.v_G(j), axis=1) + r.inertia(j).T * kin.omega[j]
                    for j in p.mechanism.moving)
    P_cut = np.where(on, sum(kin.velocity(ld.link, ld.point) @ np.asarray(ld.force) for ld in p.mechanism.loads), 0)
    assert abs(cyc.power + P_cut + P_inertia).max() < 1e-9 * abs(cyc.power).max()


def test_polar_forces_and_peaks(cutter):
    p, cyc, _, cyc0 = cutter
    r = cyc.analysis
    on = p.mechanism.loads[0].active.mask(cyc.q)
    pk, pk_fine, pk0 = cyc.peaks(), gk.sweep(p, 1800).peaks(), cyc0.peaks()
    for name in r.names()[:-1]:
        size, angle = cyc.polar(name)
        assert np.allclose(size * np.cos(angle), r[name][:, 0]) and np.allclose(size * np.sin(angle), r[name][:, 1])
    assert np.allclose(r["F12"], r["F23"], rtol=0, atol=1e-9)
    for name, peak in pk.forces.items():
        fp = pk_fine.forces[name]
        assert peak.value <= fp.value < peak.value * 1.001 and abs(np.degrees(fp.at - peak.at)) <= 2.0
        assert not on[peak.index] and peak.value > 2 * 2000
        assert math.isclose(pk0.forces[name].value, peak.value) and pk0.forces[name].at == peak.at


def test_shaking_force_and_moment(cutter):
    import matplotlib

    matplotlib.use("Agg")
    p, cyc, _, _ = cutter
    r, kin, mech = cyc.analysis, cyc.analysis.kinematics, p.mechanism
    S, M = cyc.shaking_force(), cyc.shaking_moment()
    S_check = sum(r.inertia(j).F for j in mech.moving)
    M_check = sum(gk.cross(kin.G(j), r.inertia(j).F) + r.inertia(j).T for j in mech.moving)
    for load in mech.loads:
        act = load.active.mask(cyc.q)
        S_check = S_check + np.where(act[:, None], load.force, 0.0)
        M_check = M_check + np.where(act, gk.cross(kin.position(load.link, load.point), load.force), 0.0)
    assert np.allclose(S, S_check, rtol=0, atol=1e-9 * abs(S).max())
    assert np.allclose(M, M_check, rtol=0, atol=1e-9 * abs(M).max())
    lo, hi = gk.draw.draw_shaking(cyc).axes[1].get_ylim()
    assert lo <= M.min() and hi >= M.max() and hi - lo < 1.5 * np.ptp(M)
    assert np.hypot(*S.T).max() > 5000


def test_transmission_angle(cutter):
    p, cyc, _, _ = cutter
    mech = p.mechanism
    on = mech.loads[0].active.mask(cyc.q)

    def length(link, P, Q):
        return math.dist(mech.link(link).points[P], mech.link(link).points[Q])

    a, b, c, d = length(2, "A0", "A"), length(3, "A", "B"), length(4, "B0", "B"), length(1, "A0", "B0")
    mu_cos = np.arccos((b**2 + c**2 - (a**2 + d**2 - 2 * a * d * np.cos(cyc.q))) / (2 * b * c))
    mu = cyc.transmission_angle()
    assert np.allclose(mu, np.minimum(mu_cos, np.pi - mu_cos), atol=1e-9)
    assert {round(np.degrees(cyc.q[np.argmin(mu_cos)])), round(np.degrees(cyc.q[np.argmax(mu_cos)]))} == {0, 180}
    assert np.all(abs(mu_cos - np.pi / 2) < math.radians(50)) and np.all(np.pi / 2 - mu[on] < math.radians(13))


def test_the_explorer_driven_from_code(cutter):
    """The explorer's scene, as the browser draws it, at angles set from Python: the sweep's joint forces and torque,
    the graphical route's torque agreeing, and the torque curve the sweep's own."""
    pytest.importorskip("anywidget")
    p, _, _, _ = cutter
    cyc = gk.sweep(p, 360)
    r = cyc.analysis
    ex = gk.explore(p)
    s = scene_of(ex)
    assert s["n"] == cyc.n == 360 + 4 and np.allclose(s["input"]["values"], cyc.q, atol=1e-9)
    assert np.allclose(s["effort"]["analytical"], cyc.torque, rtol=0, atol=torque_tol(s))
    for a in (140.0, 40.0, 130.0):
        ex.position = a
        i = ex.index
        assert i == at_angle(cyc, a) and math.isclose(ex.position, a, abs_tol=1e-9)
        assert s["valid"][i] and s["graphical"]["valid"][i]
        assert abs(effort(s, i) - cyc.torque[i]) <= torque_tol(s)
        assert abs(effort(s, i, "graphical") - cyc.torque[i]) <= 1e-9 * abs(cyc.torque[i]) + torque_tol(s)
        for name in ("F23", "F34", "F14"):
            assert np.allclose(force(s, name, i), r[name][i], rtol=0, atol=force_tol(s))


@pytest.mark.parametrize(("speed", "start"), [(450, "124 deg"), (900, "118 deg")])
def test_speed_and_cutting_range_predictions(cutter, speed, start):
    p, _, no_cut, _ = cutter
    omega = float(p.q_dot[0])
    text = gk.catalog.path("strip_cutter").read_text()
    assert 'from = "124 deg"' in text
    mine = gk.parse_problem(text.replace('from = "124 deg"', f'from = "{start}"')).at_speed(speed * RPM)
    cm = gk.sweep(mine)
    w = float(mine.q_dot[0])
    on = mine.mechanism.loads[0].active.mask(cm.q)
    predicted = no_cut.solve(at=cm.q).effort * (w / omega) ** 2 + np.where(on, T_cut_of(cm, mine), 0.0)
    assert np.allclose(cm.torque, predicted, atol=1e-9)
    exact = cutting_work(mine) / (2 * math.pi)
    assert abs(cm.average - exact) < 1e-3 * abs(exact)
    if speed == 450:  # at half the speed some joint forces peak inside the cut
        assert any(on[peak.index] for peak in cm.peaks().forces.values())


def test_the_exercises_keys_are_the_lessons_tools():
    student = "your-id"
    key1 = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("torque_curve", student)["questions"]}
    mine = gk.sweep(gk.exercises.variant("torque_curve", student).problem, 360)
    pk = mine.peaks()
    assert math.isclose(pk.effort_max.value, key1["T_peak"], rel_tol=1e-9)
    assert math.isclose(pk.effort_max.at, key1["T_peak_at"], rel_tol=1e-9)
    assert math.isclose(pk.effort_min.value, key1["T_low"], rel_tol=1e-9)
    assert math.isclose(mine.average, key1["T_avg"], rel_tol=1e-9)
    assert math.isclose(pk.forces["F23"].value, key1["F23_peak"], rel_tol=1e-9)
    key2 = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("strip_cutter_cut", student)["questions"]}
    r_cut = gk.exercises.variant("strip_cutter_cut", student).problem.solve()
    assert np.allclose(r_cut["F23"][0], key2["F23"], rtol=1e-9, atol=0)
    assert math.isclose(np.linalg.norm(r_cut["F14"][0]), key2["F14"], rel_tol=1e-9)
    assert math.isclose(r_cut["T12"][0], key2["T12"], rel_tol=1e-9)


def test_the_feedback_and_the_answer_box():
    pytest.importorskip("ipywidgets")
    demo = "example"
    key = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("torque_curve", demo)["questions"]}
    slipped = {"T_peak": f"{-key['T_peak']:.4g} N*m", "T_avg": f"{key['T_avg']:.4g} N*m"}
    report = gk.exercises.grade("torque_curve", demo, slipped)
    verdict = {q["id"]: (q["verdict"], q["slip"], q["score"] / q["max"]) for q in report["questions"]}
    assert verdict["T_peak"] == ("slip", "sign", 0.5) and verdict["T_avg"] == ("correct", None, 1.0)
    assert all(verdict[q][0] == "missing" for q in ("T_peak_at", "T_low", "F23_peak"))
    box = gk.exercise("torque_curve", "")
    box.student.value = demo
    assert all(g["shown"] in box.data.value for g in gk.exercises.make("torque_curve", demo)["data"])
    for q in gk.exercises.key("torque_curve", demo)["questions"]:
        box.answers[q["id"]].value = q["answer"]["text"]
    assert box.check()["score"] == 5
    box.answers["T_peak"].value = slipped["T_peak"]
    assert box.check()["score"] == 4.5 and box.report["questions"][0]["slip"] == "sign"
