"""Drawn questions' targets hold the physics of the step they ask for: the inertia resultant's line is parallel to
F_i and turns about G as T_i does, at h = |T_i|/|F_i| (d'Alembert; Söylemez, Mechanisms, §6.4); a two-force
member's line runs through its pins; three forces meet at one point; a force polygon closes; a polygon step's
components end at the point's image, and the Coriolis slip is the polygon graphkin draws with it reversed. The
exercise file's drawn questions are checked, and a construction that is not valid is never keyed."""

import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from graphkin import exercises
from graphkin.errors import GraphkinError, ProblemFileError
from graphkin.exercises.drawn_tasks import keyed, task_of
from graphkin.exercises.exercise import parse_exercise
from graphkin.graphical import construct_kinematics

DOCS = Path(__file__).resolve().parents[2] / "docs"


def targets(v, qid):
    t = task_of(v, qid, practice=True)
    return {x["slip"]: x["elements"] for x in reversed(t["check"]["targets"])}, t


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def distance_to_line(p, line):
    (x1, y1), (x2, y2) = line["through"]
    return abs(cross((x2 - x1, y2 - y1), (p[0] - x1, p[1] - y1))) / math.hypot(x2 - x1, y2 - y1)


@pytest.fixture(scope="module")
def cutter():
    return exercises.variant("draw_strip_cutter", "s003")


def test_the_inertia_line_is_parallel_to_F_at_h_on_the_side_of_T(cutter):
    t, task = targets(cutter, "R3i")
    inn = cutter.solved.result.inertia(3)
    F, T, h = inn.F[0], float(inn.T[0]), float(inn.h[0])
    G = cutter.solved.result.kinematics.G(3)[0]
    (a, b) = t[None][0]["through"]
    d = np.subtract(b, a)
    assert abs(cross(d, F)) <= 1e-9 * np.linalg.norm(d) * np.linalg.norm(F)
    assert distance_to_line(G, t[None][0]) == pytest.approx(h, rel=1e-9)
    # The resultant F on its line has the inertia torque's moment about G: (P − G) × F = T.
    assert cross(np.subtract(a, G), F) == pytest.approx(T, rel=1e-9)
    assert cross(np.subtract(t["wrong_side"][0]["through"][0], G), F) == pytest.approx(-T, rel=1e-9)
    assert distance_to_line(G, t["through_G"][0]) == pytest.approx(0, abs=1e-12)
    assert task["space"] == "mechanism" and task["draw"] == [{"kind": "line", "name": "R3i"}]
    assert task["check"]["tolerance"]["length"] == pytest.approx(3 * 0.5 * task["scale"]["si_per_mm"])


def test_the_two_force_line_runs_through_the_rocker_s_pins_and_the_slip_through_the_crank_s(cutter):
    t, _ = targets(cutter, "F43")
    pts = cutter.construction.points
    for p in (pts[4]["B"], pts[4]["B0"]):
        assert distance_to_line(p, t[None][0]) == pytest.approx(0, abs=1e-12)
    for p in (pts[2]["A0"], pts[2]["A"]):
        assert distance_to_line(p, t["wrong_member"][0]) == pytest.approx(0, abs=1e-12)


def test_three_forces_meet_at_the_point_of_concurrency(cutter):
    t, task = targets(cutter, "I3")
    I = t[None][0]["at"]
    pts = cutter.construction.points
    rocker = {"through": [pts[4]["B"], pts[4]["B0"]]}
    assert distance_to_line(I, rocker) == pytest.approx(0, abs=1e-9)
    assert distance_to_line(t["through_G"][0]["at"], rocker) == pytest.approx(0, abs=1e-9)
    # F23′ of the sub-problem acts at A along A–I3: its moment about I3 is zero, so link 3's loads alone (R3) and
    # F43′ along the rocker balance about I3 too; R3's line passes through I3.
    R3 = next(ln for ln in task["shown"]["lines"] if ln["name"] == "R3")
    R3_line = {"through": [R3["through"], np.add(R3["through"], (math.cos(R3["angle"]), math.sin(R3["angle"])))]}
    assert distance_to_line(I, R3_line) == pytest.approx(0, abs=1e-9)


def test_the_force_polygon_closes_and_the_wrong_order_closes_the_other_way(cutter):
    t, task = targets(cutter, "polygon3")
    known = task["shown"]["vectors"]
    assert known[0]["from"] == [0.0, 0.0]
    for slip in (None, "wrong_order"):
        chain = known + t[slip]
        for u, w in zip(chain, chain[1:]):
            assert w["from"] == pytest.approx(u["to"])
        assert chain[-1]["to"] == pytest.approx([0, 0], abs=1e-9 * max(abs(x) for x in known[0]["to"]))
    for e, f in zip(t[None], t["wrong_order"][::-1]):  # each unknown now along the other's line
        assert abs(cross(np.subtract(e["to"], e["from"]), np.subtract(f["to"], f["from"]))) < 1e-6 * \
            np.linalg.norm(np.subtract(e["to"], e["from"])) * np.linalg.norm(np.subtract(f["to"], f["from"]))


def test_a_polygon_step_ends_at_the_image_and_its_coriolis_slip_is_the_polygon_drawn_with_it_reversed():
    v = exercises.variant("draw_shaper_polygons", "s002")
    mc = v.solved.motion
    t, task = targets(v, "vB3")
    assert t[None][-1]["to"] == pytest.approx(mc.images["velocity"]["b3"])
    t, task = targets(v, "aB3")
    assert t[None][-1]["to"] == pytest.approx(mc.images["acceleration"]["b3′"])
    slipped = construct_kinematics(v.solved.result.kinematics, 0, slip="coriolis_reversed")
    assert t["coriolis_reversed"][-1]["to"] == pytest.approx(slipped.images["acceleration"]["b3′"])
    assert {"sense_reversed", "normal_outward", "scale_factor"} <= set(t)


BASE = """title = "t"
problem = "strip_cutter"
[[questions]]
id = "q"
find = "drawing"
"""


@pytest.mark.parametrize("extra, field", [
    ('draw = "circle"\nlink = 3', "questions[0].draw"),
    ('draw = "inertia-line"', "questions[0].link"),
    ('draw = "inertia-line"\nlink = 1', "questions[0].link"),
    ('draw = "inertia-line"\nlink = 3\nunit = "mm"', "unit"),
    ('draw = "velocity-step"\npoint = "Z"', "questions[0].point"),
    ('draw = "velocity-step"\nlink = 3', "questions[0].link"),
])
def test_a_drawn_question_s_bad_field_is_named(extra, field):
    with pytest.raises(ProblemFileError) as e:
        parse_exercise(BASE + extra, file="t.toml", id="t")
    assert field in str(e.value)


def test_a_step_the_polygons_do_not_have_is_refused_naming_the_question():
    ex = parse_exercise(BASE + 'draw = "velocity-step"\npoint = "A"', file="t.toml", id="t")
    with pytest.raises(GraphkinError, match=r"question q: point = 'A': no step of the velocity polygon finds v_A"):
        exercises.variant(ex, "s1")


def test_a_construction_that_is_not_valid_is_never_keyed():
    ex = exercises.load("draw_strip_cutter")
    solved = SimpleNamespace(construction=SimpleNamespace(valid=False, reason="links 3 and 4 are in line"),
                             exercise=ex, problem=SimpleNamespace(name="strip_cutter (θ12 = 130°)"))
    with pytest.raises(GraphkinError, match=r"question I3: no drawing is keyed at strip_cutter \(θ12 = 130°\): the "
                                            r"graphical construction is not valid \(links 3 and 4 are in line\)"):
        keyed(solved, ex.question("I3"))


def test_docs_state_every_kind_slip_and_task_field():
    from graphkin.exercises.drawn_tasks import DRAW_KINDS, WORDS

    json_md, ex_md = (DOCS / "json.md").read_text(encoding="utf-8"), (DOCS / "exercises.md").read_text(encoding="utf-8")
    section = json_md[json_md.index("# Drawn answers"):]
    task = task_of(exercises.variant("draw_strip_cutter", "s1"), "R3i")
    for key in list(task) + list(task["shown"]) + list(task["snap"]) + list(task["scale"]):
        assert f'"{key}"' in section, key
    for kind in DRAW_KINDS:
        assert kind in section and f"`{kind}`" in ex_md, kind
    for slip in WORDS:
        assert slip is None or f"`{slip}`" in ex_md, slip
