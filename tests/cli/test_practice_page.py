"""``graphkin exercise practice NAME --student ID -o page.html``: every drawn question of the student's variant on one
self-contained page, each task with the targets it is matched against in the page, and the page saying that no grade
is recorded (issue 38). The drawing itself is tested in Chromium (tests/e2e/test_drawing_page.py)."""

from __future__ import annotations

import json
import re

import pytest

from graphkin import exercises
from graphkin.cli import main
from graphkin.errors import GraphkinError
from graphkin.exercises.drawn_tasks import task_of
from graphkin.scene.practice import practice_page
from tests.scene.drawn_fixtures import line_task


def run(capsys, *argv):
    code = main(["exercise", "practice", *map(str, argv)])
    out, err = capsys.readouterr()
    return code, out, err


def tasks_in(text: str) -> list:
    found = re.search(r'<script type="application/json" id="graphkin-tasks">(.*?)</script>', text, re.S)
    return json.loads(found.group(1))


def test_the_page_holds_each_drawn_questions_task_and_nothing_to_fetch(capsys, tmp_path):
    path = tmp_path / "practice.html"
    code, out, err = run(capsys, "draw_strip_cutter", "--student", "s042", "-o", path)
    assert code == 0 and out == ""
    text = path.read_text(encoding="utf-8")
    v = exercises.variant(exercises.load("draw_strip_cutter"), "s042", "")
    drawn = [q.id for q in v.exercise.questions if q.kind == "drawing"]
    assert len(drawn) >= 2 and f"{len(drawn)} drawn questions" in err
    assert tasks_in(text) == json.loads(json.dumps([task_of(v, q, practice=True) for q in drawn]))
    assert all(t["check"]["targets"][0]["slip"] is None for t in tasks_in(text))
    assert "export function drawTask(" in text and "no grade is kept" in text
    assert not re.search(r"\b(src|href)=", text)
    assert set(re.findall(r"https?://[^\s\"'`]+", text)) == {"http://www.w3.org/2000/svg"}


def test_an_exercise_without_drawn_questions_is_one_line(capsys, tmp_path):
    code, out, err = run(capsys, "fourbar_polygons", "--student", "s1", "-o", tmp_path / "p.html")
    assert code != 0 and "no drawn questions" in err and err.count("\n") == 1
    assert not (tmp_path / "p.html").exists()


def test_a_task_string_cannot_close_the_tasks_element():
    task = line_task()
    task["ask"] = "</script><script>alert(1)</script> {{module}}"
    page = practice_page([task], title="{{tasks}}")
    assert "<script>alert(1)" not in page and "<title>{{tasks}}</title>" in page
    assert tasks_in(page)[0]["ask"] == task["ask"]


@pytest.mark.parametrize("change, words", [
    (lambda t: t.pop("view"), "has no 'view'"),
    (lambda t: t.update(view=[1, 0, 0, 1]), "view must be [xmin, ymin, xmax, ymax]"),
    (lambda t: t.update(scale={"si_per_mm": 0}), "scale.si_per_mm must be > 0"),
    (lambda t: t.update(draw=[{"kind": "circle", "name": "c"}]), "is not one of line, point, vector"),
])
def test_a_task_the_page_cannot_draw_is_one_plain_message(change, words):
    task = line_task()
    change(task)
    with pytest.raises(GraphkinError, match=re.escape(words)):
        practice_page([task])
