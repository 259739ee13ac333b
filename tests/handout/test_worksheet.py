"""A worksheet a student can work (issue 24, item 3).

``strip_cutter --at "140 deg" --blank`` used to say 0°–360° in steps of 2° for its position, give no kinematics
or inertia values, and ask for polygons at 1 mm = 20 N in boxes smaller than the polygons. Here: the position and
every given at it, equal to ``graphkin solve --json``; a box per polygon, measured on the printed page, that holds
the polygon at the stated scale; the mechanism drawn with room for the lines of action; and a graphical
question's tolerance no finer than a careful drawing allows at the printed scales, stated on the sheet and used by the
grader.
"""

from __future__ import annotations

import io
import json
import math
from contextlib import redirect_stderr, redirect_stdout

import numpy as np
import pytest

pypdf = pytest.importorskip("pypdf")

from graphkin import exercises, handout  # noqa: E402
from graphkin.graphical.paper import READING, force_text, length_text, polygon_size, sheet_scales  # noqa: E402
from graphkin.handout import maths as M  # noqa: E402
from graphkin.handout.compact import worked_steps  # noqa: E402
from graphkin.handout.scaled import resultant_step  # noqa: E402
from tests.handout.pdfgeometry import MM, paths  # noqa: E402

AT = "140 deg"


def _solve_json(name: str, at: str) -> dict:
    from graphkin import cli

    out = io.StringIO()
    with redirect_stdout(out), redirect_stderr(io.StringIO()):
        assert cli.main(["solve", name, "--json", "--at", at]) == 0
    return json.loads(out.getvalue())


def _text(runs) -> str:
    return "".join(r if isinstance(r, str) else M.to_text(r) for r in runs)


def _cells(doc, header_starts: str, columns: int) -> list[list[str]]:
    """The rows of the first table of ``columns`` columns whose first header is ``header_starts``, as text."""
    table = next(b for b in doc["blocks"] if b["kind"] == "table" and _text(b["header"][0]) == header_starts
                 and len(b["header"]) == columns)
    return [[_text(c) for c in row] for row in table["rows"]]


@pytest.fixture(scope="module")
def sheet(tmp_path_factory):
    doc = handout.build("strip_cutter", at=AT, version="blank")
    # The mechanism's drawing, read before the PDF is written (a picture keeps only its SVG then).
    pic = next(p for b in doc["blocks"] if b["kind"] == "figure" for p in b["pictures"]
               if p.key.startswith("sheet-mechanism"))
    ax = pic.figure().axes[0]
    limits = (sorted(ax.get_xlim()), sorted(ax.get_ylim()))
    path = tmp_path_factory.mktemp("worksheet") / "sheet.pdf"
    handout.write(doc, path)
    c = handout.document.subject("strip_cutter", at=AT).construction(0)
    return {"doc": doc, "path": path, "c": c, "json": _solve_json("strip_cutter", AT)["positions"][0],
            "mechanism_limits": limits}


def test_the_worksheet_states_its_position_not_the_file_s_range(sheet):
    rows = [["".join(r if isinstance(r, str) else M.to_text(r) for r in c) for c in row]
            for b in sheet["doc"]["blocks"] if b["kind"] == "table" for row in b["rows"]]
    driver = next(r for r in rows if r[0].startswith("driver"))
    assert driver[1].startswith("θ12 = 140°") and "360" not in driver[1], driver


def test_every_given_at_the_position_is_stated_as_solve_json_gives_it(sheet):
    entry = sheet["json"]
    rows = {r[0]: r for r in _cells(sheet["doc"], "link", 8)}
    for link, d in entry["links"].items():
        row = rows[f"link {link}"]
        assert row[1] == M.fmt_fixed(math.degrees(d["theta"])).replace("-", "−")
        assert row[2] == M.fmt(d["omega"]).replace("-", "−") and row[3] == M.fmt(d["alpha"]).replace("-", "−")
        if any(d["inertia_force"]):
            assert row[5].startswith(M.fmt(math.hypot(*d["inertia_force"])) + " N"), row
            assert row[6] == M.to_text(M.qty(d["inertia_torque"], "N·m")), row
            assert row[7] == M.to_text(M.qty(d["h"] * 1e3, "mm")), row
    loads = _cells(sheet["doc"], "load", 3)
    assert loads  # the cut acts at 140°
    assert [r[2] for r in loads] == [M.to_text(M.polar(M.size_of(ld["force"]), M.angle_of(ld["force"]), "N"))
                                     for ld in entry["loads"] if "force" in ld and any(ld["force"])]


def test_each_polygon_fits_its_printed_box_at_the_stated_scale(sheet):
    c, doc = sheet["c"], sheet["doc"]
    X = sheet_scales(c).polygon
    steps = [st for st in (resultant_step(c, s) for s in c.steps if s.kind == "resultant" and not s.sub) if st]
    steps += worked_steps(c)
    boxes = [b for b in doc["blocks"] if b["kind"] == "space" and b["label"].startswith("Polygon")]
    assert len(boxes) == len(steps) and all(force_text(X) in b["label"] for b in boxes)
    # The boxes as printed: the grey frames the pages stroke, each as tall as the document says.
    printed = []
    reader = pypdf.PdfReader(sheet["path"])
    for page in reader.pages:
        for p in paths(reader, page):
            if p.stroke is not None and p.fill is None and len(p.points) >= 4:
                w, h = np.ptp(p.points, axis=0) / MM
                if abs(h - boxes[0]["height"]) < 1.0:
                    printed.append((w, h))
    # No box for the velocity and acceleration polygons: this sheet gives the motion.
    assert len(printed) == len(boxes)
    for st, (w, h) in zip(steps, printed):
        pw, ph = np.array(polygon_size(st.polygon)) / X
        # The polygon at 1 mm = X N, and room for its labels around it.
        assert pw + 10.0 <= w and ph + 10.0 <= h, (st.caption, (pw, ph), (w, h))


def test_the_mechanism_is_drawn_with_room_for_the_lines_of_action(sheet):
    """Each point of concurrency the construction finds near the linkage lies inside the drawing of the mechanism,
    so a student can draw the lines of action to it."""
    c = sheet["c"]
    pts = np.array([p for d in c.points.values() for p in d.values()]) * 1e3
    size = float(np.max(np.ptp(pts, axis=0)))
    wanted = [np.asarray(P, float) * 1e3 for st in c.steps if st.kind == "three-force" for P in st.points.values()]
    wanted = [P for P in wanted if np.hypot(*(P - pts.mean(axis=0))) <= 3 * size]
    assert wanted
    (x0, x1), (y0, y1) = sheet["mechanism_limits"]
    for P in wanted:
        assert x0 < P[0] < x1 and y0 < P[1] < y1, (P, (x0, x1), (y0, y1))


def test_a_graphical_tolerance_is_what_a_careful_drawing_allows_at_the_printed_scale():
    """double_slider_graphical asked for 3 % of a force measured off a short arrow: the sheet states both the
    exercise's tolerance and what a careful drawing allows at the printed scales (each line within ±0.5 mm and
    ±0.5°, carried through the construction: graphkin.exercises.precision), and the grader allows the larger. A
    student whose force is small enough that the drawing's slack is the larger is found, and graded just inside
    and just outside it."""
    ex = exercises.load("double_slider_graphical")
    for k in range(40):
        v = exercises.variant(ex, f"s{k:03d}", "course-secret")
        small = [q for q in v.key()["questions"] if q["route"] == "graphical" and q["unit"] == "N"
                 and v.expected(ex.question(q["id"])).slack > q["tolerance"] * abs(q["answer"]["si"])]
        if small:
            break
    else:
        pytest.fail("no student of 40 has a force whose drawing's slack is wider than 3 %")
    q = small[0]
    slack = v.expected(ex.question(q["id"])).slack
    scales = sheet_scales(v.construction)
    doc = handout.build("double_slider_graphical", student=v.student, secret="course-secret")
    rows = [row for b in doc["blocks"] if b["kind"] == "table" and len(b["header"]) == 4 for row in b["rows"]]
    row = next(r for r in rows if "".join(x for x in r[0] if isinstance(x, str)) == q["id"])
    stated = "".join(x for x in row[2] if isinstance(x, str))
    assert (f"within 3 % or ±{M.fmt(slack)} N (each line drawn to ±{READING:g} mm and ±0.5° at "
            f"{length_text(scales.length)} and {force_text(scales.polygon)})") in stated, stated
    value = abs(q["answer"]["si"])
    inside = v.grade({q["id"]: f"{value + 0.9 * slack:.6g} N"})
    outside = v.grade({q["id"]: f"{value + 1.5 * slack:.6g} N"})
    mark = {g["id"]: g for g in inside["questions"]}[q["id"]]
    assert mark["verdict"] == "correct" and mark["score"] == mark["max"], mark
    assert {g["id"]: g for g in outside["questions"]}[q["id"]]["verdict"] != "correct"


def test_an_exercise_sheet_shows_the_student_s_own_mechanism_first():
    """An exercise sheet described the mechanism in words and tables only: it now draws the student's mechanism
    from their data (their crank angle), at a stated scale, before the questions, with nothing found on it."""
    v = exercises.variant(exercises.load("strip_cutter_cut"), "alice", "course-secret")
    theta = next(g for g in v.data if g.symbol == "θ12").shown
    doc = handout.build("strip_cutter_cut", student="alice", secret="course-secret")
    kinds = [(b["kind"], b.get("text")) for b in doc["blocks"]]
    first = next(k for k, b in enumerate(doc["blocks"]) if b["kind"] == "figure")
    assert first < kinds.index(("heading", "Questions"))
    figure = doc["blocks"][first]
    assert [p.key for p in figure["pictures"]] == ["mechanism-0"]
    assert f"Your mechanism at {theta}, drawn from your data. Scale 1:" in figure["caption"]
    # Nothing found is drawn on the sheet: no free body with its forces, no polygon.
    keys = [p.key for b in doc["blocks"] if b["kind"] == "figure" for p in b["pictures"]]
    assert not any(key.startswith(("free-bodies", "polygons", "step")) for key in keys), keys
