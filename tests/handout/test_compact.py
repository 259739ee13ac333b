"""A key answers what its questions ask, at the positions they ask (issue 24, item 2): an exercise about the whole
cycle works out no single position (the torque_curve key was 14 pages, 12 of them a solution at 40° that no
question asks for); an exercise at a position works out that position, the student's own."""

from __future__ import annotations

import math

from graphkin import exercises, handout
from graphkin.exercises.exercise import CYCLE_KINDS

SECRET = "course-secret"


def _headings(doc: dict, level: int = 1) -> list[str]:
    return [b["text"] for b in doc["blocks"] if b["kind"] == "heading" and b["level"] == level]


def test_a_key_to_questions_about_the_whole_cycle_works_out_no_position():
    ex = exercises.load("torque_curve")
    assert all(q.kind in CYCLE_KINDS for q in ex.questions)
    doc = handout.build("torque_curve", student="alice", secret=SECRET, version="key")
    assert doc["worked"] == []
    assert "Solution" not in _headings(doc) and "Over the whole cycle" in _headings(doc)
    assert not any(b["kind"] == "figure" and b["pictures"][0].key.startswith(("free-bodies", "polygons"))
                   for b in doc["blocks"])
    # Nothing it does not ask: no flywheel, no joint-force index (the flywheel exercise's key has its flywheel).
    assert not {"Flywheel", "Joint-force index"} & set(_headings(doc, 2))
    flywheel = handout.build("flywheel", student="alice", secret=SECRET, version="key")
    assert "Flywheel" in _headings(flywheel, 2)


def test_a_key_to_questions_at_a_position_works_out_the_student_s_position():
    v = exercises.variant(exercises.load("strip_cutter_cut"), "alice", SECRET)
    theta = next(g for g in v.data if g.symbol == "θ12").shown  # "θ12 = 148°", the student's own
    doc = handout.build("strip_cutter_cut", student="alice", secret=SECRET, version="key")
    assert [w["label"] for w in doc["worked"]] == [theta]
    assert math.isclose(math.degrees(doc["worked"][0]["q"]), float(theta.split(" = ")[1].rstrip("°")))
    assert _headings(doc).count("Solution") == 1
