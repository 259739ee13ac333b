"""The worksheet that starts from the input motion (issue 26, ``--blank --from-motion``).

The blank worksheet of issue 24 gives every link's ω, α, a_G and inertia loads, so boxes for the velocity and
acceleration polygons were pointless on it (a student could read ω3 off the table): it has none now. The sheet from
the input motion gives the positions, the input's motion, the mass properties and the external loads only; a
student constructs the rest. No number they construct may be printed anywhere on it: the Markdown's text is
searched for each link's ω, α, |a_G|, inertia force and torque and h as ``solve --json`` gives them, and the same
search finds them on the ordinary blank sheet (so the search can see them).
"""

from __future__ import annotations

import io
import json
import math
import re
from contextlib import redirect_stderr, redirect_stdout

import pytest

from graphkin import cli, handout
from graphkin.handout import maths as M

CASES = [("strip_cutter", "140 deg"), ("double_slider", None)]


def _solve_json(name: str, at) -> dict:
    out = io.StringIO()
    with redirect_stdout(out), redirect_stderr(io.StringIO()):
        assert cli.main(["solve", name, "--json"] + (["--at", at] if at else [])) == 0
    return json.loads(out.getvalue())["positions"][0]


def _markdown(tmp_path, name, at, **kw) -> str:
    doc = handout.build(name, at=at, version="blank", **kw)
    path = tmp_path / f"{name}{'_motion' if kw else ''}.md"
    handout.write(doc, path)
    return path.read_text(encoding="utf-8")


def _constructed(entry: dict, driver: int) -> dict[str, float]:
    """Every number the student constructs on the sheet from the input motion, by name, as the sheet would print
    it (a size: the search is for its digits, whatever the sign)."""
    out = {}
    for link, d in entry["links"].items():
        if int(link) == driver:
            continue  # its ω and α are the input
        out[f"ω{link}"] = d["omega"]
        out[f"α{link}"] = d["alpha"]
        out[f"|a_G{link}|"] = math.hypot(*d["a_G"])
        if any(d["inertia_force"]):
            out[f"|F{link}i|"] = math.hypot(*d["inertia_force"])
            out[f"T{link}i"] = d["inertia_torque"]
            if d["h"]:
                out[f"h{link} [mm]"] = d["h"] * 1e3
    return {k: v for k, v in out.items() if abs(v) > 1e-9}


def _printed(text: str, value: float) -> bool:
    """Whether ``value``'s digits, as the handout formats it, stand as a number in ``text``."""
    digits = M.fmt(abs(value))
    return re.search(rf"(?<![\d.]){re.escape(digits)}(?![\d])", text) is not None


@pytest.mark.parametrize(("name", "at"), CASES)
def test_no_number_the_student_constructs_is_on_the_sheet(tmp_path, name, at):
    entry = _solve_json(name, at)
    driver = handout.document.subject(name, at=at).mech.driver
    wanted = _constructed(entry, driver.link)
    assert len(wanted) >= 5
    sheet = _markdown(tmp_path, name, at, from_motion=True)
    blank = _markdown(tmp_path, name, at)
    leaked = {k: M.fmt(v) for k, v in wanted.items() if _printed(sheet, v)}
    assert not leaked, leaked
    # The same search finds them where they are given: on the blank worksheet.
    assert all(_printed(blank, v) for v in wanted.values()), {k: v for k, v in wanted.items() if not _printed(blank, v)}
    # What is given is printed: the input's motion and every link's mass.
    rate = entry["input"]["rate"]
    assert _printed(sheet, rate), M.fmt(rate)
    subject = handout.document.subject(name, at=at)
    for link in subject.mech.moving:
        m = subject.mech.link(link).mass
        if m:
            assert re.search(rf"(?<![\d.]){re.escape(M.fmt(m))} \\, \\text{{kg}}", sheet), (link, m)


def test_the_sheet_holds_the_motion_boxes_a_table_to_fill_and_the_external_loads_only():
    doc = handout.build("strip_cutter", at="140 deg", version="blank", from_motion=True)
    assert doc["from_motion"] and doc["subtitle"] == "Worksheet from the input motion"
    spaces = [b["label"] for b in doc["blocks"] if b["kind"] == "space"]
    assert [s.split(",")[0] for s in spaces[:2]] == ["Velocity polygon", "Acceleration polygon"]
    assert "m/s:" in spaces[0] and "m/s²:" in spaces[1]
    assert spaces[2:] and all(s.startswith("Polygon") for s in spaces[2:])
    # The table to fill: a row per moving link, its cells empty but the driving crank's ω and α (the input).
    table = next(b for b in doc["blocks"] if b["kind"] == "table" and len(b["header"]) == 7)
    rows = [["".join(r if isinstance(r, str) else M.to_text(r) for r in c) for c in row] for row in table["rows"]]
    assert [r[0] for r in rows] == ["link 2", "link 3", "link 4"]
    assert rows[0][1] == "94.25" and rows[0][2] == "0" and not any(rows[0][3:])
    assert not any(cell for r in rows[1:] for cell in r[1:])
    # The free bodies carry the cutting forces, not the inertia resultants: those are the student's to draw.
    pic = next(p for b in doc["blocks"] if b["kind"] == "figure" for p in b["pictures"]
               if p.key.startswith("free-bodies"))
    gids = {a.get_gid() for ax in pic.figure().axes for a in ax.patches if a.get_gid()}  # the arrows
    assert gids == {"fbd3:Fc3 (cutting)", "fbd4:Fc4 (cutting)"}, gids
    blank = handout.build("strip_cutter", at="140 deg", version="blank")
    pic = next(p for b in blank["blocks"] if b["kind"] == "figure" for p in b["pictures"]
               if p.key.startswith("free-bodies"))
    gids = {a.get_gid() for ax in pic.figure().axes for a in ax.patches if a.get_gid()}  # the arrows
    assert {"fbd3:R3i", "fbd4:R4i"} <= gids


def test_the_blank_worksheet_gives_the_motion_and_has_no_motion_polygon_boxes():
    doc = handout.build("strip_cutter", at="140 deg", version="blank")
    assert not doc["from_motion"]
    labels = [b["label"] for b in doc["blocks"] if b["kind"] == "space"]
    # A box per force polygon, and (the problem asks for both routes) per step of the analytical solution.
    assert labels and all(s.startswith(("Polygon", "Step ")) for s in labels)


@pytest.mark.parametrize("name", ["fourbar_polygons", "shaper_polygons"])
def test_a_motion_only_exercise_sheet_keeps_its_motion_boxes(name):
    doc = handout.build(name, student="s001", secret="k", version="blank")
    labels = [b["label"].split(",")[0] for b in doc["blocks"] if b["kind"] == "space"]
    assert labels == ["Velocity polygon", "Acceleration polygon"]


@pytest.mark.parametrize(("args", "says"), [
    (["strip_cutter", "--key", "--from-motion"], "not a key"),
    (["strip_cutter", "--from-motion"], "add --blank"),
    (["fourbar_two_loads_makdin", "--blank", "--from-motion"], "is static"),
    (["fourbar_dynamic_makdin", "--blank", "--from-motion"], "gives the book's accelerations"),
    (["strip_cutter_cut", "--roster", "roster.csv", "--blank", "--from-motion"], "a problem's worksheet"),
    (["double_slider_graphical", "--student", "s1", "--secret", "k", "--blank", "--from-motion"],
     "a problem's worksheet"),
])
def test_from_motion_where_it_cannot_be_is_one_line_and_exit_2(tmp_path, args, says):
    err = io.StringIO()
    with redirect_stdout(io.StringIO()), redirect_stderr(err):
        code = cli.main(["handout", *args, "-o", str(tmp_path / "x.md")])
    lines = err.getvalue().strip().splitlines()
    assert code == 2 and len(lines) == 1 and "--from-motion" in lines[0] and says in lines[0], lines
    assert not (tmp_path / "x.md").exists()
