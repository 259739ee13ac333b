"""draw_grades: a class's scores and slips, from the grader's own reports (lessons 06 and 07)."""

from __future__ import annotations

from collections import Counter

import pytest

from graphkin import draw, exercises
from graphkin.errors import GraphkinError

NAME = "strip_cutter_cut"


@pytest.fixture(scope="module")
def reports():
    """Four students: all right, a sign slip on T12, a blank, an unreadable F14 and a slip."""
    out = {}
    for n, kind in enumerate(["right", "sign", "blank", "mixed"]):
        s = f"s{n:03d}"
        key = exercises.key(NAME, s)
        answers = {q["id"]: q["answer"]["text"] for q in key["questions"]}
        if kind == "sign":
            answers["T12"] = answers["T12"].replace("CCW", "CW") if "CCW" in answers["T12"] else \
                answers["T12"].replace("CW", "CCW")
        elif kind == "blank":
            answers = {}
        elif kind == "mixed":
            answers["F14"] = "see my drawing"
            answers["T12"] = answers["T12"].replace("CCW", "CW") if "CCW" in answers["T12"] else \
                answers["T12"].replace("CW", "CCW")
        out[s] = exercises.grade(NAME, s, answers)
    return out


def test_what_went_wrong_counts_each_slip_and_verdict_but_no_right_answer(reports):
    wrong = draw.what_went_wrong(reports)
    assert wrong == Counter({("T12", "sign"): 2, ("F23", "missing"): 1, ("F14", "missing"): 1,
                             ("T12", "missing"): 1, ("F14", "unreadable"): 1})
    assert draw.what_went_wrong(list(reports.values())) == wrong


def test_the_bars_are_the_scores_and_the_counts(reports):
    fig = draw.draw_grades(reports)
    scores_ax, wrong_ax = fig.axes
    scores = Counter(r["score"] for r in reports.values())
    drawn = {round(b.get_x() + b.get_width() / 2, 9): b.get_height() for b in scores_ax.patches}
    assert drawn == {round(v, 9): n for v, n in scores.items()}
    assert scores_ax.get_title().startswith("Scores of 4 students, mean ")
    labels = [t.get_text() for t in wrong_ax.get_yticklabels()]
    widths = [b.get_width() for b in wrong_ax.patches]
    assert labels[-1] == "T12: sign" and widths[-1] == 2   # the most frequent on top
    assert dict(zip(labels, widths, strict=True)) == {
        f"{q}: {what}": n for (q, what), n in draw.what_went_wrong(reports).items()}


def test_no_reports_is_told_so():
    with pytest.raises(GraphkinError, match="no grade reports"):
        draw.draw_grades([])
