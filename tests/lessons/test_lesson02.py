"""The claims of lesson 02 (the graphical method), checked against graphkin: they left the reading path (issue 27).

Each step of the double slider's construction (Söylemez §6.4), the strip cutter by superposition
(§6.4.1), friction's assumed side, the radius of gyration moving the resultant, and the grader's slips.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import graphkin as gk


def off_line(point, line):
    return abs(float(gk.cross(np.subtract(point, line.point), line.direction)))


def rel(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return float(np.linalg.norm(a - b) / np.linalg.norm(b))


def steps_of(c, kind, link=None):
    return [s for s in c.steps if s.kind == kind and (link is None or s.link == link)]


def _vec(size, angle_deg):
    a = math.radians(angle_deg)
    return np.array([size * math.cos(a), size * math.sin(a)])


@pytest.fixture(scope="module")
def slider():
    p = gk.load("double_slider")
    return p, gk.construct_forces(p.kinematics(), 0), p.solve()


@pytest.fixture(scope="module")
def cutter():
    p2 = gk.load("strip_cutter")
    r2 = p2.solve(at=[np.radians(140)])
    return p2, gk.construct_forces(r2.kinematics, 0), r2


def test_double_slider_step_by_step(slider):
    p, c, r = slider
    assert np.isclose(p.q_dot[0], 2.0) and math.isclose(p.mechanism.link(3).mass, 5.0)
    assert math.isclose(math.dist(*p.mechanism.link(3).points.values()), 0.5)
    s1 = c.steps[0]
    h, F3i, T3i = s1.values["h"], np.array(s1.values["F3i"]), s1.values["T3i"]
    G3 = np.array(c.G[3])
    (R3i_line,) = [ln for ln in s1.lines if ln.name == "R3i"]
    assert s1.kind == "resultant" and s1.link == 3
    assert round(float(np.linalg.norm(F3i)), 2) == 25.98 and F3i[1] > 0 and abs(F3i[0]) < 1e-9 * F3i[1]
    assert T3i < 0 and math.isclose(h, abs(T3i) / np.linalg.norm(F3i))
    assert abs(h * 1e3 - 33.31) / 33.31 < 2e-3
    assert math.isclose(off_line(G3, R3i_line), h)
    assert math.isclose(float(gk.cross(np.subtract(R3i_line.point, G3), F3i)), T3i)
    assert R3i_line.point[0] < G3[0]  # "h to the left of G3"
    s3 = c.steps[2]
    I3, lines3 = np.array(s3.points["I3"]), {ln.name: ln for ln in s3.lines}
    A, B = np.array(c.points[3]["A"]), np.array(c.points[3]["B"])
    assert s3.kind == "three-force"
    assert all(off_line(I3, lines3[name]) < 1e-12 for name in ("R3i", "F43", "F23"))
    assert np.allclose(lines3["F23"].point, A) and np.allclose(I3, [R3i_line.point[0], B[1]])
    s4 = c.steps[3]
    assert s4.kind == "polygon" and s4.closure() < 1e-12
    assert np.allclose(s4.values["F23"], c.force(2, 3)) and np.allclose(s4.values["F43"], c.force(4, 3))
    (drive,) = steps_of(c, "driver")
    F12 = np.array(drive.values["F12"])
    assert drive.closure() < 1e-12
    assert np.allclose(c.force(1, 2), -np.array(c.inertia[3]["F"]), atol=1e-12)
    assert np.allclose(F12, -c.force(4, 3), atol=1e-12) and math.isclose(c.effort, F12[0])
    assert len(gk.draw.draw_steps(c)) == len(c.steps) == 6


def test_double_slider_graphical_analytical_and_book(slider):
    _, c, r = slider
    (drive,) = steps_of(c, "driver")
    graphical = {"F43": c.force(4, 3), "F23": c.force(2, 3), "G12": c.force(1, 2), "F12": drive.values["F12"]}
    book = {"F43": (7.555, 180), "F23": (27.04, -73.78), "G12": (25.97, 270), "F12": (7.555, 0)}
    for name, polar in book.items():
        assert rel(graphical[name], r[name][0]) < 1e-12
        assert rel(graphical[name], _vec(*polar)) < 3e-3
    assert rel(c.inertia[3]["h"], r.inertia(3).h[0]) < 1e-12


def test_strip_cutter_by_superposition(cutter):
    p2, c2, r2 = cutter
    assert np.allclose(p2.q_dot, 900 * 2 * math.pi / 60)
    for ld, link, up in zip(p2.mechanism.loads, (3, 4), (1, -1), strict=True):
        assert ld.link == link and np.allclose(ld.force, (0.0, up * 2000.0))
        assert np.allclose(np.degrees([ld.active.start, ld.active.stop]), [124, 156])
    assert c2.valid and not c2.warnings
    for link in (3, 4):
        (s,) = steps_of(c2, "resultant", link)
        lines = {ln.name: ln for ln in s.lines}
        (cut,) = c2.external[link]
        Ri, R = np.array(s.values[f"F{link}i"]), np.array(s.values[f"R{link}"])
        assert np.allclose(R, Ri + np.array(cut.vector))
        Li, u = np.array(lines[f"R{link}i"].point), np.array(lines[f"R{link}i"].direction)
        X, w = np.array(cut.at), np.array(cut.vector) / np.linalg.norm(cut.vector)
        crossing = Li + float(gk.cross(X - Li, w) / gk.cross(u, w)) * u
        assert off_line(crossing, lines[f"R{link}"]) < 1e-9  # R passes where its two parts cross
    part = {}
    for loaded in (3, 4):
        (three,) = steps_of(c2, "three-force", loaded)
        (poly,) = steps_of(c2, "polygon", loaded)
        I_k = np.array(three.points[f"I{loaded}"])
        assert poly.closure() < 1e-12 and all(off_line(I_k, ln) < 1e-9 for ln in three.lines)
        part[loaded] = {a.name.rstrip("′″"): np.array(a.vector) for a in poly.polygon}
    assert [sp.values.keys() for sp in steps_of(c2, "superpose")] == [{"F23"}, {"F34"}, {"F14"}]
    for sp in steps_of(c2, "superpose"):
        (name,) = sp.values
        total = sum(np.array(a.vector) for a in sp.polygon if a.known)
        assert np.allclose(total, sp.values[name])
        assert np.allclose(sp.polygon[-1].vector, -total) and sp.closure() < 1e-12
    assert np.allclose(part[3]["F23"] + part[4]["F34"], c2.force(2, 3))
    assert np.allclose(-part[3]["F43"] + part[4]["F34"], c2.force(3, 4))
    assert np.allclose(part[3]["F43"] + part[4]["F14"], c2.force(1, 4))


def test_strip_cutter_crank_is_a_couple(cutter):
    _, c2, r2 = cutter
    drive2 = steps_of(c2, "driver")[-1]
    d, T12 = drive2.values["d"], drive2.values["T12"]
    R2_step = [s for s in steps_of(c2, "resultant", 2) if "R2" in s.values][-1]
    R2 = np.array(R2_step.values["R2"])
    (R2_line,) = [ln for ln in R2_step.lines if ln.name == "R2"]
    assert not any(c2.inertia[2]["F"]) and not c2.inertia[2]["T"]
    assert math.isclose(d, off_line(np.array(c2.points[1]["A0"]), R2_line))
    assert math.isclose(abs(T12), np.linalg.norm(R2) * d)
    assert np.allclose(R2, -c2.force(2, 3)) and math.isclose(T12, c2.effort)
    for name in r2.names():
        assert rel(c2[name], r2[name][0]) < 1e-9, name


def test_friction_on_the_assumed_side():
    p3 = gk.load("slider_crank_friction")
    r3 = p3.solve(at=[np.radians(60)])
    c3 = gk.construct_forces(r3.kinematics, 0)
    assert any(s.caption.startswith("Friction") for s in steps_of(c3, "note"))
    (guide,) = [j for j in p3.mechanism.joints if getattr(j, "mu", 0)]
    G14, v4 = c3.force(1, 4), r3.kinematics.velocity(4, "B")[0]
    assert guide.mu == 0.2 and math.isclose(c3.q, math.radians(60))
    assert math.isclose(abs(G14[0]), guide.mu * abs(G14[1])) and np.sign(G14[0]) == -np.sign(v4[0])
    for name in r3.names():
        assert rel(c3[name], r3[name][0]) < 1e-9, name


def test_mass_cancels_in_h_and_the_spread_moves_it(slider, cutter):
    p, c, _ = slider
    _, c2, _ = cutter
    for deg in (100, 200):  # outside the cut, link 3 carries its inertia resultant only
        assert not gk.construct_forces(gk.load("strip_cutter").kinematics(at=[np.radians(deg)]), 0).external[3]
    text = gk.catalog.path("double_slider").read_text()
    assert 'mass = "5 kg"' in text
    ch = gk.construct_forces(gk.parse_problem(text.replace('mass = "5 kg"', 'mass = "10 kg"')).kinematics(), 0)
    assert math.isclose(ch.inertia[3]["h"], c.inertia[3]["h"]) and math.isclose(ch.effort, 2 * c.effort)
    text = gk.catalog.path("strip_cutter").read_text()
    assert 'k = "268 mm"' in text
    compact = gk.parse_problem(text.replace('k = "268 mm"', 'k = "150 mm"'))
    cc = gk.construct_forces(compact.kinematics(at=[np.radians(140)]), 0)
    assert math.isclose(cc.inertia[3]["h"] / c2.inertia[3]["h"], (150 / 268) ** 2)


def test_the_given_drawing_hides_what_the_student_measures():
    import matplotlib

    matplotlib.use("Agg")
    mine = gk.exercises.variant("double_slider_graphical", "your-id")
    fig = gk.draw.draw_given(mine.construction)
    gids = {a.get_gid() for ax in fig.axes for a in ax.patches}
    assert "fbd3:R3i" in gids and not {"fbd3:F23", "fbd3:F43"} & gids


def test_the_grader_names_the_inertia_slips():
    name = "inertia_resultant"
    key = {q["id"]: q["answer"] for q in gk.exercises.key(name, "demo")["questions"]}
    T = key["T3i"]["si"]
    G3 = gk.exercises.variant(name, "demo").problem.kinematics().G(3)[0]
    wrong_foot = (2 * G3 - np.array(key["line3"]["si"])) * 1e3
    demo = {"F3i": key["F3i"]["text"], "T3i": f"{abs(T):.4g} N*m {'CW' if T > 0 else 'CCW'}",
            "h3": key["h3"]["text"], "line3": f"({wrong_foot[0]:.1f}, {wrong_foot[1]:.1f}) mm"}
    report = {q["id"]: q for q in gk.exercises.grade(name, "demo", demo)["questions"]}
    assert report["F3i"]["verdict"] == "correct" and report["h3"]["verdict"] == "correct"
    assert (report["T3i"]["verdict"], report["T3i"]["slip"]) == ("slip", "sign")
    assert (report["line3"]["verdict"], report["line3"]["slip"]) == ("slip", "wrong_side")
    assert all(q["score"] == 0.5 for q in report.values() if q["verdict"] == "slip")
