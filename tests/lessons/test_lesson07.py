"""The claims of lesson 07 (grading platforms), checked on the lesson's own class: they left its reading path.

Issue 27: the lesson's hidden cells make the class, lay out Gradescope's ``/autograder`` and write the forged
notebook; the checks that stood at its end live here. The lesson is run once, cell by cell as Run All does
(the real ``run_autograder`` on 24 submissions), and these tests read what it computed: every grade against
graphkin's grader, every slip made named as made, and no secret in anything a student or the platform sees.
"""

from __future__ import annotations

import csv
import json
import tomllib

import pytest

import graphkin as gk
from graphkin.exercises.platforms.gradescope import statistics
from tests.lessons.lesson_run import run_lesson

pytestmark = pytest.mark.slow   # the real run_autograder, 24 times (~40 s on 2 cores): `make test` runs it


@pytest.fixture(scope="module")
def lesson():
    ns = run_lesson("07_grading_platforms")
    yield ns
    ns["workdir"].cleanup()


def test_every_grade_is_graphkin_s_and_names_what_was_made(lesson):
    students, results, made, copier = lesson["students"], lesson["results"], lesson["made"], lesson["copier"]
    for s in students:
        answers = tomllib.loads((lesson["submissions"] / s / "answers.toml").read_text(encoding="utf-8"))
        answers.pop("student", None)
        if s == copier:
            assert results[s]["score"] == 0 and "each student answers their own variant" in results[s]["output"]
            assert "extra_data" not in results[s]   # "their results.json carries no report"
            continue
        report = gk.exercises.grade(lesson["NAME"], s, answers, secret=lesson["SECRET"], classmates=students)
        assert abs(results[s]["score"] - report["score"]) < 1e-12, s
        assert results[s]["extra_data"]["graphkin"] == json.loads(json.dumps(statistics(report))), s
        for q in report["questions"]:
            assert (q["slip"] or q["verdict"]) == made[s, q["id"]], (s, q["id"], q["verdict"], q["slip"])


def test_the_chart_counts_every_answer_not_right(lesson):
    made, copier = lesson["made"], lesson["copier"]
    counts = gk.draw.what_went_wrong(lesson["reports"])
    assert sum(counts.values()) == sum(kind != "correct" for (s, _), kind in made.items() if s != copier)
    assert set(lesson["reports"]) == set(lesson["students"]) - {copier}


def test_the_student_shown_made_a_sign_or_power_of_ten_slip(lesson):
    s = lesson["slipper"]
    assert s != lesson["copier"]
    assert any(lesson["made"][s, q] in ("sign", "power_of_ten") for q in ("F23", "F14", "T12"))


def test_the_export_holds_the_keys_and_no_secret(lesson):
    source, SECRET, export, folder = lesson["source"], lesson["SECRET"], lesson["export"], lesson["folder"]
    assert (source / "keys.json").is_file() and "secret" not in json.loads((source / "config.json").read_text())
    assert not [p for p in source.rglob("*") if p.is_file() and SECRET.encode() in p.read_bytes()]
    for p in (export / "student_template", export / "README.md"):
        files = [p] if p.is_file() else list(p.rglob("*"))
        assert all(SECRET not in f.read_text(encoding="utf-8") for f in files if f.is_file())
    html = folder / "pl" / "questions" / lesson["NAME"] / "question.html"
    assert SECRET not in html.read_text(encoding="utf-8")


def test_the_forged_notebook_scores_nothing_and_its_code_answer_is_unreadable(lesson):
    printed = lesson["graphkin"]("exercise", "grade", lesson["NAME"], "--keys", "otter/strip_cutter_cut-keys.json",
                                 "--answers", "forged.ipynb")
    grade = next(csv.DictReader(printed.splitlines()))
    assert (grade["student"], float(grade["score"])) == (lesson["forger"], 0.0)
    assert grade["T12 verdict"] == "unreadable" and "as text" in grade["T12 feedback"]
