"""A class's grades at a glance: the spread of scores and what went wrong, per question (lessons 06 and 07)."""

from __future__ import annotations

from collections import Counter

import numpy as np
from matplotlib.figure import Figure

from graphkin.draw import style as _style
from graphkin.errors import GraphkinError


def what_went_wrong(reports) -> Counter:
    """How many answers went wrong each way, per question: ``(question id, slip or verdict) -> count``.

    Parameters
    ----------
    reports : iterable of dict
        Grade reports as :func:`graphkin.exercises.grade` returns them (or a mapping of student to report).

    Returns
    -------
    Counter
        A recognised slip is counted under its name (``"sign"``), any other answer not right under its
        verdict (``"wrong"``, ``"unreadable"``, ``"missing"``); right answers are not counted.
    """
    return Counter((q["id"], q["slip"] or q["verdict"]) for r in _reports(reports) for q in r["questions"]
                   if q["verdict"] != "correct")


def draw_grades(reports, *, title: str = "", **style) -> Figure:
    """The scores of a class and its slips: two panels, side by side.

    Left, how many students earned each score [points]; right, one bar per way an answer went wrong and
    question (``F23: sign``), the most frequent on top: the tallest bars are what to go over again.

    Parameters
    ----------
    reports : iterable of dict
        Grade reports as :func:`graphkin.exercises.grade` returns them (``score``, ``max`` [points] and
        ``questions``), or a mapping of student to report; ``graphkin exercise grade --json`` holds them, and
        Gradescope's ``results.json`` (under ``extra_data``) what this reads of them.
    title : str, optional
        A title over both panels.
    **style
        Overrides of :class:`graphkin.draw.style.Style` fields.

    Returns
    -------
    Figure
        ``axes[0]`` the scores (one bar per score earned), ``axes[1]`` the counts of
        :func:`what_went_wrong`.

    Raises
    ------
    GraphkinError
        If there are no reports.
    """
    reports = _reports(reports)
    if not reports:
        raise GraphkinError("draw_grades: no grade reports to draw")
    s = _style.resolve(**style)
    scores = Counter(float(r["score"]) for r in reports)
    top = max(float(r["max"]) for r in reports)
    fig = Figure(figsize=(10.0, 3.6), dpi=100, layout="constrained")
    ax1, ax2 = fig.subplots(1, 2, width_ratios=[1, 1.4])
    x = sorted(scores)
    gaps = np.diff(x)  # the bars as wide as the scores lie close, up to a point's width
    ax1.bar(x, [scores[v] for v in x], width=0.8 * min(gaps.min() if len(gaps) else 1.0, 1.0), color=s.known,
            edgecolor="white")
    mean = sum(v * n for v, n in scores.items()) / len(reports)
    ax1.set(xlabel=f"score (of {top:g} points)", ylabel="students", xlim=(-0.5, top + 0.5))
    ax1.set_title(f"Scores of {len(reports)} students, mean {mean:.2f}", fontsize=s.title_size)
    ax1.xaxis.get_major_locator().set_params(integer=True)
    ax1.yaxis.get_major_locator().set_params(integer=True)
    wrong = what_went_wrong(reports).most_common()
    labels = [f"{qid}: {what.replace('_', ' ')}" for (qid, what), _ in wrong]
    ax2.barh(labels[::-1], [n for _, n in wrong][::-1], color=s.unknown)
    ax2.set_xlabel("answers")
    ax2.set_title("What went wrong, per question" if wrong else "Every answer right", fontsize=s.title_size)
    ax2.tick_params(axis="y", labelsize=s.small_size)
    ax2.xaxis.get_major_locator().set_params(integer=True)
    if title:
        fig.suptitle(title, fontsize=s.suptitle_size)
    return fig


def _reports(reports) -> list:
    if isinstance(reports, dict) and "questions" not in reports:
        return list(reports.values())
    return list(reports)
