"""The exercise box of a notebook: the student's own data, each question as their sheet asks it."""

from __future__ import annotations

import pytest

pytest.importorskip("ipywidgets")

from graphkin import exercises  # noqa: E402
from graphkin.widgets import exercise  # noqa: E402


def test_each_question_states_how_close_an_answer_must_be_once_an_id_is_typed():
    box = exercise("double_slider_graphical", "")
    assert all("within" not in html.value for html in box.asks.values())  # no variant yet: no tolerance to state
    box.student.value = "s1"
    sheet = exercises.variant(exercises.load("double_slider_graphical"), "s1").sheet()
    for q in sheet["questions"]:
        shown = box.asks[q["id"]].value
        # The tolerance a graphical question allows follows its printed scale: the box says it as the sheet does.
        assert f"(within {q['within']})" in shown.replace("&#x27;", "'"), shown
    assert "each line drawn to ±0.5 mm and ±0.5° at 1:" in box.asks["F23"].value


def test_a_student_id_that_cannot_be_read_keeps_the_questions_as_written():
    box = exercise("single_link", "")
    before = {k: html.value for k, html in box.asks.items()}
    box.student.value = "x" * 500
    assert "color:#b00" in box.data.value
    assert {k: html.value for k, html in box.asks.items()} == before
