"""Exercise text and step captions set as the rest of the handout sets them (F_ij → F with subscript ij), the
tolerance of a question stated alike everywhere, and the lines of action each titled by what it draws."""

from __future__ import annotations

import re

from graphkin import exercises, handout
from graphkin.exercises.platforms.prairielearn import marks
from graphkin.exercises.sheets import format_sheet
from graphkin.handout import maths as M
from graphkin.handout.typst import source
from graphkin.widgets.exercise_box import html_text


def _texts(runs) -> str:
    return "".join(r for r in runs if isinstance(r, str))


def _subs(runs) -> list:
    return [r for r in runs if isinstance(r, list) and r[0] == "sub"]


def test_the_exercise_text_sets_its_symbols_with_subscripts():
    doc = handout.build("strip_cutter_cut", student="s001")
    para = next(b["runs"] for b in doc["blocks"] if b["kind"] == "text"
                and "is the force of link i on link j" in _texts(b["runs"]))
    assert M.sym("F", "ij") in _subs(para)
    assert "F_ij" not in _texts(para)
    doc = handout.build("inertia_resultant", student="s001")
    table = next(b for b in doc["blocks"] if b["kind"] == "table" and b["header"][-1] == ["your answer"])
    asks = [cell for row in table["rows"] for cell in row[1:2]]
    assert M.sym("a", "G3") in _subs(asks[0]) and M.sym("I", "G3") in _subs(asks[1])
    text = source(doc)
    for plain in ("a_G3", "I_G3", "F_ij"):
        assert plain not in text
    # The widget shows the same text as HTML, with the same subscripts.
    assert html_text("T3i = −I_G3 α3") == "<i>T</i><sub>3i</sub> = −<i>I</i><sub>G3</sub> <i>α</i><sub>3</sub>"


def test_a_step_caption_says_minus_m_times_a_g_with_subscripts():
    doc = handout.build("strip_cutter", at="140 deg", detail="full")
    fig = next(b for b in doc["blocks"] if b["kind"] == "figure" and "Link 3: its inertia force" in b["caption"])
    assert "F3i = −m3·a_G3 = " in fig["caption"] and "∠" in fig["caption"]
    assert "T3i = −I_G3·α3 = −379.4 N·m" in fig["caption"]
    subs = _subs(fig["runs"])
    for node in (M.sym("m", "3"), M.sym("a", "G3"), M.sym("I", "G3"), M.sym("α", "3"), M.sym("F", "3i")):
        assert node in subs
    assert "a_G" not in source(doc)


def test_each_panel_of_the_lines_of_action_has_its_own_title():
    doc = handout.build("gearset")
    pic = next(p for b in doc["blocks"] if b["kind"] == "figure" for p in b["pictures"]
               if p.key.startswith("construction"))
    titles = [ax.get_title() for ax in pic.figure().axes if ax.get_title()]
    assert len(titles) == 2 and len(set(titles)) == 2, titles
    assert all(t.startswith("Link 3: ") for t in titles)  # both are the pinion's: its tooth force and its couple


def test_a_question_s_tolerance_is_stated_alike_by_the_command_the_platform_and_the_sheet():
    v = exercises.variant("double_slider_graphical", "s001")
    sheet = v.sheet()
    text = format_sheet(sheet)
    doc = handout.build("double_slider_graphical", student="s001")
    table = next(b for b in doc["blocks"] if b["kind"] == "table" and b["header"][-1] == ["your answer"])
    printed = [_texts(row[2]) for row in table["rows"]]
    graphical = 0
    for q, cell in zip(sheet["questions"], printed):
        assert f"within {q['within']}," in text
        assert f"within {q['within']}," in marks(q)
        assert f"within {q['within']}," in cell.replace("-", "−")
        if q["route"] == "graphical" and q["form"] != "direction":
            graphical += 1
            assert q["within"].startswith("3 % or ±") and q["within"].endswith("the larger"), q["within"]
    assert graphical == len(sheet["questions"])
    assert "within 3 %," not in text  # the bare 3 % the command printed before


def test_a_sub_problem_s_primed_force_and_the_cutting_force_are_subscripted_too():
    assert M.prose("F43′ and F23″ meet") == (M.subsup(M.i("F"), M.t("43"), M.t("′")), " and ",
                                            M.subsup(M.i("F"), M.t("23"), M.t("″")), " meet")
    assert M.name("Fc3") == M.sym("F", "c3") and M.prose("Fc3 (cutting)")[0] == M.sym("F", "c3")
    doc = handout.build("strip_cutter", at="140 deg")
    # Every text of the handout (not the drawings' SVG, whose element ids keep the plain names).
    text = re.sub(r'bytes\("(?:[^"\\]|\\.)*"\)', "", source(doc))
    assert '"Fc3' not in text and "F43′" not in text and '"θ12' not in text
