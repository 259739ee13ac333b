"""The otter-grader export, with the real tool: ``otter assign``, then ``otter run`` on two notebooks.

A correct notebook (student s002's key) and a wrong one (student s001: a sign slip, a wrong value, an
unanswered question) are made from the student notebook ``otter assign`` writes. ``otter run`` must give
each question exactly graphkin's score, and the wrong notebook's results carry graphkin's feedback.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from graphkin import exercises
from graphkin.errors import GraphkinError
from graphkin.exercises.platforms import export, otter, runtime

nbformat = pytest.importorskip("nbformat")

EXERCISE = "strip_cutter_cut"
SECRET = "otter-test-secret-5e1f"
ROSTER = ["s001", "s002"]
BIN = Path(sys.executable).parent
pytestmark = [pytest.mark.slow,  # runs the real platform
              pytest.mark.skipif(not (BIN / "otter").exists(), reason="otter-grader is not installed in this venv")]


def _env() -> dict:
    return {**os.environ, "PATH": f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}"}


def _fill(student_nb: Path, out: Path, student: str, answers: dict) -> None:
    """A handed-in notebook: the student notebook with the id and the answers typed in."""
    nb = nbformat.read(student_nb, as_version=4)
    typed = {"STUDENT": student, **{otter.variable(q): a for q, a in answers.items()}}
    for cell in nb.cells:
        if cell.cell_type == "code":
            for name, value in typed.items():
                if cell.source.strip() == f"{name} = ...":
                    cell.source = f"{name} = {value!r}"
    nbformat.write(nb, out)


def _flip_sense(torque: str) -> str:
    return torque.replace("CCW", "CW") if "CCW" in torque else torque.replace("CW", "CCW")


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """Export, ``otter assign``, and ``otter run`` on a correct and a wrong notebook (run side by side)."""
    root = tmp_path_factory.mktemp("otter")
    dest = root / "export"
    export(EXERCISE, "otter", dest, secret=SECRET, students=ROSTER)
    subprocess.run([str(BIN / "otter"), "assign", f"{EXERCISE}.ipynb", "dist"], cwd=dest, env=_env(),
                   check=True, capture_output=True, text=True)
    student_nb = dest / "dist" / "student" / f"{EXERCISE}.ipynb"
    zips = sorted((dest / "dist" / "autograder").glob(f"{EXERCISE}-autograder_*.zip"))
    assert len(zips) == 1

    good = {q["id"]: q["answer"]["text"] for q in exercises.key(EXERCISE, "s002", secret=SECRET)["questions"]}
    key1 = {q["id"]: q["answer"]["text"] for q in exercises.key(EXERCISE, "s001", secret=SECRET)["questions"]}
    mag, angle = key1["F23"].split("∠")
    number, unit = mag.split()
    bad = {"T12": _flip_sense(key1["T12"]),                                   # the sense reversed: a slip
           "F23": f"{float(number) * 1.2:.4g} {unit} ∠{angle}"}               # 20 % too large: wrong
    # F14 is left unanswered.
    subs = {"good": ("s002", good), "bad": ("s001", bad)}
    runs = {}
    for label, (student, answers) in subs.items():
        (root / "submissions").mkdir(exist_ok=True)
        nb = root / "submissions" / f"{label}.ipynb"
        _fill(student_nb, nb, student, answers)
        out = root / "results" / label
        out.mkdir(parents=True)
        runs[label] = subprocess.Popen([str(BIN / "otter"), "run", "-a", str(zips[0]), "-o", str(out), str(nb)],
                                       cwd=root, env=_env(), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                       text=True)
    results = {}
    for label, proc in runs.items():
        log, _ = proc.communicate(timeout=300)
        assert proc.returncode == 0, log
        results[label] = json.loads((root / "results" / label / "results.json").read_text(encoding="utf-8"))
    reports = {label: exercises.grade(EXERCISE, student, answers, secret=SECRET)
               for label, (student, answers) in subs.items()}
    return {"dest": dest, "results": results, "reports": reports}


def _by_question(result: dict) -> dict:
    return {t["name"]: t for t in result["tests"] if "score" in t}


@pytest.mark.parametrize("label", ["good", "bad"])
def test_otter_run_scores_are_graphkins(graded, label):
    report, tests = graded["reports"][label], _by_question(graded["results"][label])
    assert set(tests) == {q["id"] for q in report["questions"]}
    for q in report["questions"]:
        assert tests[q["id"]]["score"] == q["score"], q["id"]
        assert tests[q["id"]]["max_score"] == q["max"], q["id"]
    assert sum(t["score"] for t in tests.values()) == report["score"]


def test_the_reports_are_what_the_submissions_meant(graded):
    good, bad = graded["reports"]["good"], graded["reports"]["bad"]
    assert good["score"] == good["max"] == 3
    verdicts = {q["id"]: (q["verdict"], q["slip"], q["score"]) for q in bad["questions"]}
    assert verdicts == {"F23": ("wrong", None, 0.0), "F14": ("missing", None, 0.0), "T12": ("slip", "sign", 0.5)}


def test_the_wrong_notebook_gets_graphkins_feedback(graded):
    tests = _by_question(graded["results"]["bad"])
    for q in graded["reports"]["bad"]["questions"]:
        output = tests[q["id"]]["output"]
        assert q["feedback"] in output
        assert runtime.feedback_line(q) in output
    assert "The size is right but the sense is wrong" in tests["T12"]["output"]
    # F23 is the sum of the superposition's sub-problems (step 18), where the hint sends the student back to.
    assert "Not within 1 % of the answer. Revisit step 18 of the construction: the superposition" in tests["F23"]["output"]
    # Students see the public tests at once: they say the unanswered question has no answer.
    public = next(t for t in graded["results"]["bad"]["tests"] if t["name"] == "Public Tests")
    assert public["visibility"] == "visible" and "No answer was given for F14." in public["output"]
    assert all(t["visibility"] == "after_published" for t in tests.values())


def test_the_secret_is_only_on_the_teachers_side(graded):
    dest = graded["dest"]
    student_files = [p for p in (dest / "dist" / "student").rglob("*") if p.is_file()]
    assert any(p.name == f"{EXERCISE}.ipynb" for p in student_files)
    for p in student_files:
        assert SECRET.encode() not in p.read_bytes(), p
    # It is where grading needs it: the autograder's hidden tests.
    assert SECRET in (dest / f"{EXERCISE}.ipynb").read_text(encoding="utf-8")
    # The sheets that travel to students carry data, never answers.
    sheets = json.loads((dest / "dist" / "student" / f"{EXERCISE}-sheets.json").read_text(encoding="utf-8"))
    assert sorted(sheets) == ROSTER
    assert not any("answer" in q for s in sheets.values() for q in s["questions"])


def test_the_student_notebook_asks_and_hides(graded):
    nb = nbformat.read(graded["dest"] / "dist" / "student" / f"{EXERCISE}.ipynb", as_version=4)
    code = [c.source.strip() for c in nb.cells if c.cell_type == "code"]
    assert "STUDENT = ..." in code
    assert {"F23 = ...", "F14 = ...", "T12 = ..."} <= set(code)
    assert 'grader.check("T12")' in code
    text = nbformat.writes(nb)
    for q in exercises.key(EXERCISE, ROSTER[0], secret=SECRET)["questions"]:
        assert q["answer"]["text"] not in text


def test_the_vendored_graphkin_prints_the_sheet(graded):
    """The copy of graphkin in the student folder works on its own (imported before any installed one)."""
    folder = graded["dest"] / "dist" / "student"
    code = ("import sys; sys.path.insert(0, 'vendor'); import graphkin, pathlib; "
            "assert pathlib.Path(graphkin.__file__).resolve().is_relative_to(pathlib.Path('vendor').resolve()); "
            "from graphkin.exercises.platforms import runtime; "
            f"print(runtime.sheet_text('{EXERCISE}.toml', 's002', '{EXERCISE}-sheets.json'))")
    out = subprocess.run([sys.executable, "-c", code], cwd=folder, capture_output=True, text=True, check=True)
    from graphkin.exercises.sheets import format_sheet

    assert out.stdout.strip() == format_sheet(exercises.make(EXERCISE, "s002", secret=SECRET)).strip()


def test_readme_names_the_commands(graded):
    readme = (graded["dest"] / "README.md").read_text(encoding="utf-8")
    assert f"otter assign {EXERCISE}.ipynb dist" in readme
    assert f"otter run -a dist/autograder/{EXERCISE}-autograder_*.zip" in readme
    assert "requirements.txt" in readme and "numpy" in readme


# --- the test functions' checks, called directly (no otter needed) ---------------------------------------

def _t12(student):
    return next(q["answer"]["text"] for q in exercises.key(EXERCISE, student, secret=SECRET)["questions"]
                if q["id"] == "T12")


def _checked(graded, student, answer, *, level=1.0, metadata="/nonexistent/metadata.json"):
    dest = graded["dest"]
    try:
        otter.check(dest / f"{EXERCISE}.toml", student, "T12", answer, SECRET, level=level,
                    sheets=dest / f"{EXERCISE}-sheets.json", metadata=metadata)
    except AssertionError as exc:
        return str(exc)
    return None


def test_check_compares_the_id_with_gradescopes_metadata(graded, tmp_path):
    right = _t12("s001")
    meta = tmp_path / "submission_metadata.json"
    meta.write_text(json.dumps({"users": [{"email": "b@x.org", "sid": "s002", "name": "B"}]}), encoding="utf-8")
    message = _checked(graded, "s001", right, metadata=meta)
    assert "carries the student id 's001' but was handed in by 's002'" in message
    meta.write_text(json.dumps({"users": [{"email": "a@x.org", "sid": "s001", "name": "A"}]}), encoding="utf-8")
    assert _checked(graded, "s001", right, metadata=meta) is None
    # No student id at Gradescope: the email is the id.
    meta.write_text(json.dumps({"users": [{"email": "s001", "sid": None}]}), encoding="utf-8")
    assert _checked(graded, "s001", right, metadata=meta) is None
    assert _checked(graded, "s001", right, metadata=tmp_path / "absent.json") is None


def test_check_refuses_an_id_off_the_roster_or_none(graded):
    assert "not on this assignment's roster" in _checked(graded, "s999", "1 N*m")
    assert "carries no student id" in _checked(graded, ..., "1 N*m")


def test_check_passes_each_credit_level_a_slip_reaches(graded):
    right = _t12("s001")
    slipped = _flip_sense(right)
    assert [_checked(graded, "s001", slipped, level=lv) is None for lv in (0.25, 0.5, 1.0)] == [True, True, False]
    assert "The size is right but the sense is wrong" in _checked(graded, "s001", slipped, level=1.0)


def test_readable_leaks_nothing_and_reads_only(graded):
    toml = graded["dest"] / f"{EXERCISE}.toml"
    otter.readable(toml, "T12", "1 N*m CW")  # readable, though wrong
    with pytest.raises(AssertionError, match="No answer was given for T12"):
        otter.readable(toml, "T12", ...)
    with pytest.raises(AssertionError, match="decimal point"):
        otter.readable(toml, "T12", "12,5 N*m")


# --- build() alone ----------------------------------------------------------------------------------------

def test_a_secret_without_a_roster_is_refused(tmp_path):
    with pytest.raises(GraphkinError, match="a course secret needs --roster"):
        export(EXERCISE, "otter", tmp_path / "x", secret=SECRET)
    assert not (tmp_path / "x" / "README.md").exists()


def test_without_roster_or_secret_the_notebook_draws_from_the_id():
    from graphkin.exercises.platforms import bundle

    tree = otter.build(bundle("single_link"))
    nb = nbformat.reads(tree["single_link.ipynb"], as_version=4)
    code = "\n".join(c.source for c in nb.cells if c.cell_type == "code")
    assert "runtime.sheet_text('single_link.toml', STUDENT))" in code
    assert "secret = ''" in code and "sheets=None" in code
    assert not any(k.endswith("-sheets.json") for k in tree)
    assert "vendor/graphkin/__init__.py" in tree and "requirements.txt" in tree


def test_credit_levels_add_up_to_every_score():
    partial = {"sign": 0.3, "rpm_as_rad_s": 0.25, "dimension": 0.0}
    levels = otter.credit_levels(2.0, partial)
    assert levels == [0.5, 0.6, 2.0]
    steps = [b - a for a, b in zip([0.0, *levels], levels)]
    for score in (0.0, *levels):
        assert sum(s for s, lv in zip(steps, levels) if score >= lv) == pytest.approx(score, abs=1e-12)
