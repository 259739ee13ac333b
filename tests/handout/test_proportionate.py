"""Worksheets in proportion (issue 36, item 5): a polygon of loads that print as dots gets no box.

The shaper's worksheet was 13 pages, 19 polygon boxes, most for sub-problems of a link's own weight and inertia
(under 1 N beside a 500 N cutting force, a fraction of a millimetre at its scale). Each is now named and set
aside in one sentence, with the fraction it is negligible under.
"""

from __future__ import annotations

import math

import pypdf
import pytest

from graphkin import handout
from graphkin.graphical.paper import sheet_scales
from graphkin.handout import maths as M
from graphkin.handout import scaled
from graphkin.handout.compact import polygon_equation, worked_steps
from graphkin.handout.document import subject
from graphkin.handout.scaled import NEGLIGIBLE, set_aside


def _sheet_steps(name: str):
    s = subject(name)
    c = s.construction(s.worked()[0])
    sums = [scaled.resultant_step(c, st) for st in c.steps if st.kind == "resultant" and not st.sub]
    return c, [st for st in sums if st is not None] + worked_steps(c)


def test_the_shaper_s_worksheet_is_six_pages_at_most(tmp_path):
    path = tmp_path / "shaper.pdf"
    handout.write(handout.build("shaper_six_bar", version="blank"), path)
    assert len(pypdf.PdfReader(path).pages) <= 6


@pytest.mark.parametrize("name", ["shaper_six_bar", "strip_cutter", "double_slider", "epicyclic_khurmi"])
def test_a_polygon_is_set_aside_only_when_it_prints_as_a_dot(name):
    c, steps = _sheet_steps(name)
    kept, aside, limit = set_aside(steps)
    assert sorted(map(id, kept + aside)) == sorted(map(id, steps))
    largest = max(math.hypot(*a.vector) for st in steps for a in st.polygon)
    assert limit == pytest.approx(NEGLIGIBLE * largest)
    for st in aside:
        sizes = [math.hypot(*a.vector) for a in st.polygon]
        if st.kind == "superpose":
            # A sum of one part that counts: it is that part.
            assert sum(x >= limit for x in sizes[:-1]) <= 1
        else:
            assert max(sizes) < limit
    for st in kept:
        assert max(math.hypot(*a.vector) for a in st.polygon) >= limit
    # A polygon set aside would print as a dot: its largest force under a millimetre at the sheet's force scale.
    X = sheet_scales(c).polygon
    assert all(max(math.hypot(*a.vector) for a in st.polygon) / X < 1.0 for st in aside if st.kind != "superpose")


def test_the_shaper_s_sheet_names_what_it_sets_aside_and_boxes_the_rest():
    doc = handout.build("shaper_six_bar", version="blank")
    c, steps = _sheet_steps("shaper_six_bar")
    kept, aside, _ = set_aside(steps)
    assert 0 < len(kept) < len(steps)
    boxes = [b for b in doc["blocks"] if b["kind"] == "space" and b["label"].startswith("Polygon")]
    assert len(boxes) == len(kept)
    said = next(b for b in doc["blocks"] if b["kind"] == "text"
                and "".join(r if isinstance(r, str) else "" for r in b["runs"]).startswith("Set aside"))
    text = "".join(r if isinstance(r, str) else M.to_text(r) for r in said["runs"])
    assert f"{NEGLIGIBLE:.1%}" in text
    assert all(M.to_text(polygon_equation(st)) in text for st in aside)


@pytest.mark.parametrize("name, from_motion, asked", [("strip_cutter", False, True), ("shaper_six_bar", False, True),
                                                     ("strip_cutter", True, False)])
def test_a_sheet_that_asks_for_both_routes_has_room_for_the_analytical_one(name, from_motion, asked):
    """The problem says "both analytically and graphically": its worksheet has a box per step of the analytical
    solution, numbered as the key numbers them; a sheet that starts from the input motion asks for the polygons."""
    from graphkin.exercises.quantities import equilibrium_steps

    doc = handout.build(name, version="blank", from_motion=from_motion)
    steps = [b["label"] for b in doc["blocks"] if b["kind"] == "space" and b["label"].startswith("Step ")]
    said = " ".join(M.to_text(r) if not isinstance(r, str) else r for b in doc["blocks"] if b["kind"] == "text"
                    for r in b["runs"])
    mech = subject(name).mech
    answers = next(b for b in doc["blocks"] if b["kind"] == "table" and b["caption"]
                   and "".join(r if isinstance(r, str) else M.to_text(r) for r in b["caption"]).startswith("Every"))
    caption = "".join(r if isinstance(r, str) else M.to_text(r) for r in answers["caption"])
    if asked:
        assert "both analytically and graphically" in said
        assert [label.split(".")[0] for label in steps] == [f"Step {n}" for n, _ in equilibrium_steps(mech)]
        assert "found again by your equations" in caption  # the answers come from both, not the polygons alone
    else:
        assert steps == []
        assert "equations" not in caption


@pytest.mark.parametrize("name", ["double_slider_graphical", "shaper_polygons", "fourbar_polygons"])
def test_an_exercise_sheet_has_room_for_the_analytical_part_only_when_it_asks(name):
    from graphkin import exercises

    doc = handout.build(name, student="s1", secret="x")
    steps = [b for b in doc["blocks"] if b["kind"] == "space" and b["label"].startswith("Step ")]
    asks = "analytic" in exercises.variant(name, "s1", "x").sheet()["intro"].lower()
    assert bool(steps) == asks
