"""Every construction fits its page (issue 36, item 2).

Over every catalog problem at 12 input positions and every exercise for 12 students: each point a construction
draws on the mechanism (each line of action where it passes its link, where a resultant's parts meet, where a
three-force member's lines meet) lies inside the worksheet's drawing of the mechanism at its printed scale, and
that drawing fits its room on the page; a point that does not is reached another way (its resultant's line drawn
at its offset h, or moments about a pin), which the sheet says. The drawing itself is measured on a few sheets.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin import catalog, exercises
from graphkin.graphical.paper import MECHANISM_ROOM, mechanism_size, sheet_reach, sheet_scales
from graphkin.graphical.reach import reach
from graphkin.handout.document import Subject, subject
from tests.handout.worked import exercise_constructions

STUDENTS = [f"s{n:02d}" for n in range(12)]


def _positions(s: Subject) -> np.ndarray:
    """12 input positions over the cycle, or over the file's own range of a slider's stroke."""
    if s.crank:
        return np.radians(np.arange(0.0, 360.0, 30.0))
    q = s.result.kinematics.q
    return np.linspace(q.min(), q.max(), 12)


def _constructions(name: str):
    """(label, construction) of a catalog problem at 12 positions (its own, where it gives its motion there)."""
    s = subject(name)
    if not s.problem.given:
        s = Subject(s.problem, s.raw, at=_positions(s))
    for i in range(s.n):
        c = s.construction(i)
        if c is not None and c.valid:
            yield f"{name} at {s.where(i)}", c


def _unfit(label: str, c) -> list[str]:
    """What does not fit: each point of the construction off the sheet's drawing and reached no other way, and the
    drawing itself when it is larger than its room at its scale."""
    k = sheet_scales(c).length
    r = sheet_reach(c)
    out = []
    w, h = mechanism_size(c, points=r.points())
    if w / k > MECHANISM_ROOM[0] + 1e-6 or h / k > MECHANISM_ROOM[1] + 1e-6:
        out.append(f"{label}: the drawing is {w / k:.0f} × {h / k:.0f} mm at 1:{k:g}, its room {MECHANISM_ROOM}")
    pts = np.array([p for d in c.points.values() for p in d.values()] + r.points())
    lo, hi = pts.min(axis=0) - 1e-9, pts.max(axis=0) + 1e-9
    detoured = {d.step for d in r.detours}
    for m in reach(c, near=lambda X: True).marks:
        X = np.asarray(m.at, float)
        inside = bool(np.all((X >= lo) & (X <= hi)))
        if not inside and m.step not in detoured:
            off = np.maximum(np.maximum(lo - X, X - hi), 0.0) * 1e3 / k
            out.append(f"{label}: {m.what} (step {m.step + 1}) lies {math.hypot(*off):.0f} mm off the drawing at "
                       f"1:{k:g}, and nothing draws it another way")
    return out


@pytest.mark.parametrize("name", catalog.names())
def test_every_point_of_a_problem_s_construction_lies_on_its_drawing(name):
    bad = [line for label, c in _constructions(name) for line in _unfit(label, c)]
    assert not bad, "\n".join(bad)


@pytest.mark.parametrize("name", exercises.names())
def test_every_point_of_an_exercise_s_construction_lies_on_its_drawing(name):
    bad = [line for label, c in exercise_constructions(name, STUDENTS, "fit") for line in _unfit(label, c)]
    assert not bad, "\n".join(bad)


def test_the_strip_cutter_s_sheet_draws_r3_by_its_offset_where_its_parts_meet_off_the_page():
    """The bad case of issue 36: at 140°, R3i's line lies 1228 mm from G3 and meets the cutting force's line far
    below the mechanism; the sheet draws R3's line directly, at its offset from G3, and says so."""
    s = subject("strip_cutter", at="140 deg")
    c = s.construction(0)
    r = sheet_reach(c)
    offset = {d.name: d for d in r.detours if d.kind == "offset"}
    assert "R3" in offset and set(offset["R3"].parts) == {"R3i", "Fc3 (cutting)"}
    G3, R3 = np.asarray(c.G[3], float), np.asarray(c.steps[offset["R3"].step].values["R3"], float)
    # The offset is the moment of link 3's loads about G3 over |R3|, worked out here from the loads themselves.
    C = np.asarray(c.points[3]["C"], float)
    Fc3 = next(np.asarray(a.vector, float) for a in c.external[3])
    M = c.inertia[3]["T"] + float((C - G3)[0] * Fc3[1] - (C - G3)[1] * Fc3[0])
    assert offset["R3"].arms["R3"] == pytest.approx(abs(M) / math.hypot(*R3), rel=1e-9)
    assert offset["R3"].sense == ("CCW" if M > 0 else "CW")


@pytest.mark.parametrize("name, at", [("strip_cutter", "140 deg"), ("strip_cutter", "0 deg"),
                                      ("shaper_six_bar", None), ("engine_gas_force", None),
                                      ("epicyclic_khurmi", None), ("spur_pair_wentzell", None)])
def test_the_sheet_s_drawing_holds_every_point_it_draws(name, at):
    """Measured on the drawing itself: its view holds every mark, and it prints within its room."""
    from graphkin import draw

    s = subject(name, at=at)
    c = s.construction(s.worked()[0])
    k = sheet_scales(c).length
    drawn = draw.draw_mechanism(c, length_scale=k, room=True)
    ax = drawn.ax
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    for m in sheet_reach(c).marks:
        X, Y = np.asarray(m.at, float) * 1e3
        assert x0 <= X <= x1 and y0 <= Y <= y1, f"{m.what} at ({X:.0f}, {Y:.0f}) mm is outside the view"
    assert (x1 - x0) / k <= MECHANISM_ROOM[0] + 2.0 and (y1 - y0) / k <= MECHANISM_ROOM[1] + 2.0


def _list_text(doc) -> str:
    from graphkin.handout import maths as M

    return "\n".join("".join(r if isinstance(r, str) else M.to_text(r) for r in item)
                     for b in doc["blocks"] if b["kind"] == "list" for item in b["items"])


@pytest.mark.parametrize("version", ["key", "blank"])
def test_the_strip_cutter_s_key_and_sheet_say_how_r3_s_line_is_drawn_at_140_deg(version):
    from graphkin import handout

    doc = handout.build("strip_cutter", at="140 deg", version=version)
    c = subject("strip_cutter", at="140 deg").construction(0)
    h = next(d for d in sheet_reach(c).detours if d.name == "R3").arms["R3"] * 1e3
    text = _list_text(doc)
    assert "R3's line directly" in text.replace("₃", "3")
    assert f"(h = {h:.3g} mm)" in text


@pytest.mark.parametrize("name", catalog.names())
def test_the_key_draws_how_each_resultant_s_line_is_found(name):
    """Each resultant of two or more loads: a panel of the key draws its parts' lines and K, where they meet, on
    the sheet's drawing; or its step is drawn another way (its line at its offset)."""
    from graphkin.handout import scaled

    s = subject(name)
    for i in s.worked():
        c = s.construction(i)
        if c is None or not c.valid:
            continue
        r = sheet_reach(c)
        for n, st in enumerate(c.steps):
            if st.kind != "resultant" or st.sub:
                continue
            parts = [ln for ln in st.lines if ln.name == f"R{st.link}i"] + [
                a for a in c.external.get(st.link, []) if a.at is not None and math.hypot(*a.vector) > 0]
            if len(parts) < 2 or any(d.step == n for d in r.detours):
                continue
            panel = scaled.resultant_panel(c, st)
            collinear = panel is None and not any(m.step == n and m.what.startswith("where ") for m in r.marks)
            if collinear:
                continue  # its parts act on one line (a piston's): so does it
            assert panel is not None, f"{name}: link {st.link}'s resultant is not drawn"
            K = np.asarray(panel.points[f"K{st.link}"], float)
            assert r.holds(K)
            names = {ln.name for ln in panel.lines}
            assert f"R{st.link}" in names and {getattr(p, "name", "") for p in parts} <= names
