"""Grading trust, second pass (review h44): gaps a student's hand-in or a failing machine could slip through.

Each test here failed before its fix: an own file written back in place (half a module left by a failed write),
the whole grading report in Gradescope's results.json (a classmate's id, the key's values), a drawing at ±1e308
graded as plain "wrong", and a notebook's self-check reading the cells in the order they ran where the grader
reads them top to bottom.
"""

from __future__ import annotations

import errno
import json
import math
from pathlib import Path

import pytest

from graphkin import exercises
from graphkin.errors import GraphkinError
from graphkin.exercises.handins import FolderError, clear_folder

# -- Handins: the assignment's own files go back whole or not at all ----------------------------------------------


def _hand_in(tmp_path: Path) -> tuple[Path, dict]:
    """A hand-in's folder holding a shadowing package, and the assignment's own files to put back."""
    folder = tmp_path / "sub"
    (folder / "graphkin").mkdir(parents=True)
    (folder / "graphkin" / "__init__.py").write_text("shadow")
    return folder, {"vendor/graphkin/__init__.py": b"real", "hw.toml": b"ex"}


def test_clear_folder_puts_the_own_files_back_through_a_temporary_file(tmp_path, monkeypatch):
    """clear_folder wrote each own file in place: a write cut short (a full disk) left half a module where a kernel
    then imports it. Now each goes through a temporary file and os.replace; a failed one leaves no file and says
    which, in one sentence."""
    import graphkin.files

    folder, own = _hand_in(tmp_path)

    def full_disk(src, dst):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(graphkin.files.os, "replace", full_disk)
    written = r"assignment file .*vendor/graphkin/__init__\.py: cannot be written \(No space left on device\)"
    with pytest.raises(FolderError, match=written) as info:
        clear_folder(folder, own)
    assert "\n" not in str(info.value) and isinstance(info.value, GraphkinError)
    assert sorted(p.name for p in folder.rglob("*") if p.is_file()) == []  # no half file, no temporary file


def test_clear_folder_names_an_own_file_it_cannot_read(tmp_path):
    folder, own = _hand_in(tmp_path)
    missing = tmp_path / "source" / "hw.toml"
    with pytest.raises(FolderError, match=f"assignment file {missing}: cannot be read"):
        clear_folder(folder, {"hw.toml": missing})


def test_clear_folder_still_gives_the_own_files_back_as_they_were(tmp_path):
    folder, own = _hand_in(tmp_path)
    assert clear_folder(folder, own) == ["graphkin"]
    assert (folder / "vendor" / "graphkin" / "__init__.py").read_bytes() == b"real"
    assert (folder / "hw.toml").read_bytes() == b"ex"
    assert not [p for p in folder.rglob("*.tmp")]


# -- Gradescope: results.json keeps the teacher's statistics, nothing else of the report ----------------------------


def test_gradescope_results_keep_verdicts_and_slips_but_no_classmate_and_no_key(tmp_path):
    """results.json carried graphkin's whole report under extra_data: the classmate whose data a copied answer fits
    (``other``), with ``reveal`` the key's values (``expected``), and the student's text again. Now it keeps what
    the class's statistics read: the score, and each question's verdict and slip."""
    from graphkin.draw.grades import what_went_wrong
    from graphkin.exercises.keys import Keys, keys_text, make_keys
    from graphkin.exercises.platforms import gradescope

    ex = exercises.load("single_link")
    path = tmp_path / gradescope.KEYS
    path.write_text(keys_text(make_keys(ex, ["s-alice", "s-bob-7731"], "k")), encoding="utf-8")
    keys = Keys(path)
    bobs = {q["id"]: q["answer"]["text"] for q in exercises.key("single_link", "s-bob-7731", "k")["questions"]}
    report = keys.grade("s-alice", bobs, reveal=True)
    assert {r.get("other") for r in report["questions"]} == {"s-bob-7731"} and "expected" in report["questions"][0]
    kept = gradescope.results_from_report(ex, report, [])["extra_data"]["graphkin"]
    shown = json.dumps(kept, ensure_ascii=False)
    assert "s-bob-7731" not in shown and "expected" not in shown and "feedback" not in shown
    assert all(q["answer"]["text"] not in shown for q in exercises.key("single_link", "s-alice", "k")["questions"])
    assert kept["student"] == "s-alice" and (kept["score"], kept["max"]) == (report["score"], report["max"])
    assert kept["questions"] == [{k: r[k] for k in ("id", "verdict", "slip", "score", "max")}
                                 for r in report["questions"]]
    assert what_went_wrong([kept]) == what_went_wrong([report])  # the teacher's chart counts the same slips


# -- A drawn coordinate is a number on the drawing's page, not one near the float's limit ---------------------------


def _drawing(v, qid: str) -> dict:
    from graphkin.exercises.drawn_tasks import right_drawing

    return json.loads(json.dumps(right_drawing(v.drawn(v.exercise.question(qid)))))


@pytest.mark.parametrize("x", [1e308, -1e308, float("nan"), float("inf")])
def test_a_drawn_coordinate_out_of_range_is_refused_with_a_sentence_naming_it(x):
    """A vector's end at 1e308 (finite: JSON takes it) was matched as drawn: its distance to the target overflowed
    to inf and the drawing came out a plain "wrong", as if the student had drawn it slightly off. Now it is
    unreadable, with one sentence naming the element, the coordinate and the range a coordinate must lie in."""
    from graphkin.exercises.drawn_grading import grade_drawing

    v = exercises.variant("draw_strip_cutter", "s001")
    q = next(q for q in v.exercise.questions if _drawing(v, q.id)["elements"][0]["kind"] == "vector")
    drawing = _drawing(v, q.id)
    drawing["elements"][0]["to"][1] = x
    for answer in (drawing, json.dumps(drawing)):  # as the dict and as the text (1e308, NaN, Infinity)
        r = grade_drawing(v, q.id, answer)
        assert (r["verdict"], r["score"]) == ("unreadable", 0.0), r["feedback"]
        assert "\n" not in r["feedback"] and ("elements[0].to[1]" in r["feedback"] or "NaN" in r["feedback"]
                                              or "Infinity" in r["feedback"])
        if math.isfinite(x):
            name = drawing["elements"][0]["name"]
            assert f"elements[0].to[1] of the vector {name!r} is {x:.4g} N, out of the drawing's range" in r["feedback"]
            assert "a coordinate must lie within 1000 times the view's size (" in r["feedback"]


def test_every_target_drawing_lies_within_the_range_a_coordinate_may_take():
    """The bound refuses no drawing the grader names: the right drawing and each slip's (a length laid off ×10 the
    farthest) read and match as before."""
    from graphkin.exercises.drawings import read_drawing
    from graphkin.exercises.drawn_grading import grade_drawing

    for name in ("draw_strip_cutter", "draw_shaper_polygons"):
        v = exercises.variant(name, "s001")
        for q in v.exercise.questions:
            d = v.drawn(q)
            for t in d["targets"]:
                drawing = {"drawing": 1, "question": q.id, "space": d["task"]["space"], "elements": t["elements"]}
                read_drawing(drawing, question=q.id, space=d["task"]["space"], view=d["task"]["view"])
            assert grade_drawing(v, q.id, _drawing(v, q.id))["verdict"] == "correct"


# -- A notebook's own check reads what the grader reads: the file as saved, top to bottom ---------------------------


def _saved(path: Path, cells: list[str]) -> Path:
    nb = {"cells": [{"cell_type": "code", "metadata": {}, "outputs": [], "execution_count": None, "source": c}
                    for c in cells], "metadata": {}, "nbformat": 4, "nbformat_minor": 5}
    path.write_text(json.dumps(nb), encoding="utf-8")
    return path


def _grader_reads(path: Path):
    from graphkin.exercises.grading import grade_question
    from graphkin.exercises.handins import read_handin

    v = exercises.variant("single_link", "s001")
    return grade_question(v, v.exercise.question("T12"), read_handin(path, {"T12": "T12"}).answers["T12"])


def test_the_notebook_check_reads_the_saved_file_top_to_bottom_not_the_order_cells_ran(kernel, tmp_path):
    """The check read the cells in the order they ran: a student who ran the lower cell (an f-string) first, then the
    upper one (text), was told the answer can be read; the grader reads the file top to bottom, where the f-string
    comes last, and graded it unreadable. Now the check reads the saved file as the grader does, and says when the
    cells as run give something else."""
    from graphkin.exercises.platforms import runtime

    upper, lower = 'T12 = "120.5 N*m CCW"', 'x = 120.5\nT12 = f"{x} N*m CCW"'
    path = _saved(tmp_path / "hw.ipynb", ['STUDENT = "s001"', upper, lower])
    kernel.user_ns["__session__"] = "course/hw.ipynb"  # as jupyter_server names it: relative to its root
    for cell in ('STUDENT = "s001"', lower, upper):  # the lower cell first
        kernel.run_cell(cell, store_history=True)
    graded = _grader_reads(path)
    assert graded["verdict"] == "unreadable"
    check = runtime.readable_problem(exercises.load("single_link"), "T12", kernel.user_ns["T12"], "T12")
    assert check is not None and "\n" not in check
    assert check.startswith("The notebook as saved, which the grader reads from top to bottom, gives T12 = (an f-string")
    assert "the cells as you ran them give '120.5 N*m CCW'" in check and check.endswith("As saved: " + graded["feedback"])


def test_the_notebook_check_says_when_the_saved_answer_is_not_the_one_run(kernel, tmp_path):
    from graphkin.exercises.platforms import runtime

    path = _saved(tmp_path / "hw.ipynb", ['T12 = "120.5 N*m CCW"', 'T12 = "99 N*m CW"'])
    kernel.user_ns["__session__"] = str(path)
    for cell in ('T12 = "99 N*m CW"', 'T12 = "120.5 N*m CCW"'):
        kernel.run_cell(cell, store_history=True)
    check = runtime.readable_problem(exercises.load("single_link"), "T12", kernel.user_ns["T12"], "T12")
    assert check is not None and "gives T12 = '99 N*m CW', but the cells as you ran them give '120.5 N*m CCW'" in check
    assert "As saved" not in check  # both can be read: only which one is handed in is at stake
    # Run top to bottom, the cells and the file agree: nothing to say.
    for cell in ('T12 = "120.5 N*m CCW"', 'T12 = "99 N*m CW"'):
        kernel.run_cell(cell, store_history=True)
    assert runtime.readable_problem(exercises.load("single_link"), "T12", kernel.user_ns["T12"], "T12") is None
