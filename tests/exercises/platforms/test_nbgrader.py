"""The nbgrader export, with the real nbgrader: generate_assignment, then autograde, in a temporary course.

Students of the course: alice answers her variant right; bob makes a sign
slip, a wrong answer, and leaves nbgrader's ``raise NotImplementedError()``
in one answer cell; carol hands in a notebook that carries alice's id and
alice's answers. The scores nbgrader records must be the scores of
``graphkin.exercises.grade``, question by question.
"""

import csv
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

from graphkin import exercises
from graphkin.errors import GraphkinError
from graphkin.exercises import platforms
from graphkin.exercises.platforms import nbgrader as nbx
from graphkin.exercises.platforms import runtime

pytestmark = pytest.mark.slow  # runs the real platform

nbformat = pytest.importorskip("nbformat")
pytest.importorskip("nbgrader")

NAME = "strip_cutter_cut"
SECRET = "course-secret-7f3a"
ROSTER = ["alice", "bob"]
BIN = Path(sys.executable).parent


def _nbgrader(course: Path, *args, secret=None):
    """Run the real ``nbgrader`` CLI in the course directory (the venv's bin first on PATH, for alembic)."""
    env = {k: v for k, v in os.environ.items() if k not in (nbx.SECRET_VARIABLE, "NBGRADER_STUDENT")}
    env["PATH"] = f"{BIN}{os.pathsep}{env.get('PATH', '')}"
    if secret is not None:
        env[nbx.SECRET_VARIABLE] = secret
    return subprocess.run([str(BIN / "nbgrader"), *args], cwd=course, env=env, capture_output=True, text=True,
                          timeout=120)


def _answers_of(student):
    return {q["id"]: q["answer"]["text"] for q in exercises.key(NAME, student, SECRET)["questions"]}


def _flip_sense(text):
    return text.replace("CCW", "@").replace("CW", "CCW").replace("@", "CW")


# What each student types: (STUDENT, {question: cell source}).
def _submissions():
    alice = _answers_of("alice")
    bob = _answers_of("bob")
    typed = {
        "alice": ("alice", {q: f"{q} = {json.dumps(a, ensure_ascii=False)}" for q, a in alice.items()}),
        "bob": ("bob", {
            # Right, with nbgrader's stub left under it: the cell raises, the answer still counts.
            "F23": f'F23 = "{bob["F23"]}"\n# YOUR CODE HERE\nraise NotImplementedError()',
            "F14": 'F14 = "1 N"',
            "T12": f'T12 = "{_flip_sense(bob["T12"])}"',
        }),
        # carol hands in alice's notebook: alice's id, alice's (right) answers.
        "carol": ("alice", {q: f"{q} = {json.dumps(a, ensure_ascii=False)}" for q, a in alice.items()}),
    }
    answers = {"alice": alice, "bob": {"F23": bob["F23"], "F14": "1 N", "T12": _flip_sense(bob["T12"])}}
    return typed, answers


def _submit(course: Path, student: str, claimed: str, cells: dict):
    """Fill in the released notebook as a student would, and put it where ``nbgrader collect`` puts it."""
    nb = nbformat.read(course / "release" / NAME / f"{NAME}.ipynb", as_version=4)
    for cell in nb.cells:
        gid = cell.metadata.get("nbgrader", {}).get("grade_id")
        if gid == "student":
            cell.source = f'STUDENT = "{claimed}"'
        elif gid and gid.startswith("answer_"):
            cell.source = cells[gid.removeprefix("answer_")]
    folder = course / "submitted" / student / NAME
    folder.mkdir(parents=True)
    for f in (course / "release" / NAME).iterdir():
        if f.suffix != ".ipynb":
            shutil.copy(f, folder / f.name)
    nbformat.write(nb, folder / f"{NAME}.ipynb")


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    """Export, generate_assignment, three submissions, autograde (once without the secret), export, feedback."""
    root = tmp_path_factory.mktemp("nbgrader")
    export = root / "export"
    platforms.export(NAME, "nbgrader", export, secret=SECRET, students=ROSTER)
    course = root / "course"
    course.mkdir()
    (course / "nbgrader_config.py").write_text(
        f'c = get_config()\nc.CourseDirectory.course_id = "mechanics"\n'
        f'c.CourseDirectory.db_url = "sqlite:///{(course / "gradebook.db").as_posix()}"\n', encoding="utf-8")
    shutil.copytree(export / "source", course / "source")
    run = {"generate": _nbgrader(course, "generate_assignment", NAME)}
    assert run["generate"].returncode == 0, run["generate"].stderr
    typed, answers = _submissions()
    for student, (claimed, cells) in typed.items():
        _submit(course, student, claimed, cells)
    run["no_secret"] = _nbgrader(course, "autograde", NAME, "--student", "alice")
    run["autograde"] = _nbgrader(course, "autograde", NAME, secret=SECRET)
    assert run["autograde"].returncode == 0, run["autograde"].stderr
    run["export"] = _nbgrader(course, "export")
    run["feedback"] = _nbgrader(course, "generate_feedback", NAME)
    assert run["export"].returncode == 0 and run["feedback"].returncode == 0
    return SimpleNamespace(root=root, export=export, dir=course, run=run, answers=answers)


def _grades(course, student):
    from nbgrader.api import Gradebook

    with Gradebook(f"sqlite:///{(course.dir / 'gradebook.db').as_posix()}", "mechanics") as gb:
        return {qid: gb.find_grade(f"test_{qid}", NAME, NAME, student).score for qid in ("F23", "F14", "T12")}


def _outputs(course, student):
    """Each test cell's printed text, by question id, in the autograded notebook."""
    nb = nbformat.read(course.dir / "autograded" / student / NAME / f"{NAME}.ipynb", as_version=4)
    out = {}
    for cell in nb.cells:
        gid = cell.metadata.get("nbgrader", {}).get("grade_id", "")
        text = "".join(o.get("text", "") for o in cell.get("outputs", []) if o.output_type == "stream")
        errors = " ".join(o.get("evalue", "") for o in cell.get("outputs", []) if o.output_type == "error")
        out[gid] = text + errors
    return out


@pytest.mark.parametrize("student", ["alice", "bob"])
def test_nbgrader_scores_are_graphkins_question_by_question(course, student):
    report = exercises.grade(NAME, student, course.answers[student], SECRET)
    assert _grades(course, student) == {q["id"]: q["score"] for q in report["questions"]}


def test_partial_credit_as_configured(course):
    assert _grades(course, "alice") == {"F23": 1.0, "F14": 1.0, "T12": 1.0}
    # A sign slip on T12 earns the [partial] share (0.5 of 1 point); F14 is wrong; F23 right despite the stub.
    assert _grades(course, "bob") == {"F23": 1.0, "F14": 0.0, "T12": 0.5}
    rows = {r["student_id"]: r for r in csv.DictReader((course.dir / "grades.csv").open(encoding="utf-8"))}
    assert {s: (float(r["score"]), float(r["max_score"])) for s, r in rows.items()} == {
        "alice": (3.0, 3.0), "bob": (1.5, 3.0), "carol": (0.0, 3.0)}


def test_each_test_cell_prints_the_feedback_line(course):
    for student in ("alice", "bob"):
        out = _outputs(course, student)
        for result in exercises.grade(NAME, student, course.answers[student], SECRET)["questions"]:
            assert runtime.feedback_line(result) in out[f"test_{result['id']}"]
    bob = _outputs(course, "bob")
    assert "The size is right but the sense is wrong" in bob["test_T12"]
    # The sheet cell printed the student's own data.
    assert "student: bob" in bob["sheet"]
    assert exercises.make(NAME, "bob", SECRET)["data"][0]["shown"] in bob["sheet"]


def test_a_submission_carrying_another_students_id_scores_nothing(course):
    assert _grades(course, "carol") == {"F23": 0.0, "F14": 0.0, "T12": 0.0}
    sentence = runtime.identity_error("alice", "carol")
    assert sentence == ("this submission carries the student id 'alice' but was handed in by 'carol': "
                        "each student answers their own variant")
    out = _outputs(course, "carol")
    assert all(sentence in out[f"test_{q}"] for q in ("F23", "F14", "T12"))


def test_autograde_without_the_secret_stops_and_keeps_no_grade(course):
    run = course.run["no_secret"]
    assert run.returncode != 0
    assert ("graphkin: cannot grade 'alice': GRAPHKIN_SECRET is not set, so the data it draws differs from the "
            "student's sheet") in run.stderr + run.stdout


def test_the_secret_is_nowhere_students_look(course):
    # Not in the export at all (the hidden tests read it while autograde runs), so not in release/ nor in the
    # feedback nbgrader hands back (which shows the hidden tests' code).
    for folder in (course.export, course.dir / "source", course.dir / "release", course.dir / "feedback"):
        files = [p for p in folder.rglob("*") if p.is_file()]
        assert files
        for p in files:
            assert SECRET.encode() not in p.read_bytes(), p
    released = (course.dir / "release" / NAME / f"{NAME}.ipynb").read_text(encoding="utf-8")
    assert "HIDDEN TESTS" not in released and "grade_question" not in released
    for answer in _answers_of("alice").values():  # the sample student's answers stay in the source notebook
        assert json.dumps(answer, ensure_ascii=False) not in released
    assert (course.dir / "feedback" / "bob" / NAME / f"{NAME}.html").is_file()


def test_export_files_and_readme(course):
    files = sorted(p.relative_to(course.export).as_posix() for p in course.export.rglob("*") if p.is_file())
    assert files == ["README.md", "nbgrader_config.example.py", f"source/{NAME}/{NAME}-sheets.json",
                     f"source/{NAME}/{NAME}.ipynb", f"source/{NAME}/{NAME}.toml"]
    sheets = json.loads((course.export / "source" / NAME / f"{NAME}-sheets.json").read_text(encoding="utf-8"))
    assert sorted(sheets) == ROSTER and sheets["bob"] == exercises.make(NAME, "bob", SECRET)
    assert "answer" not in json.dumps(sheets)
    readme = (course.export / "README.md").read_text(encoding="utf-8")
    for command in (f"nbgrader generate_assignment {NAME}", f"GRAPHKIN_SECRET=<the course secret> nbgrader "
                    f"autograde {NAME}", "nbgrader export", *platforms.requirements()):
        assert command in readme


def test_source_notebook_cells(course):
    nb = nbformat.read(course.export / "source" / NAME / f"{NAME}.ipynb", as_version=4)
    meta = {c.metadata["nbgrader"]["grade_id"]: c.metadata["nbgrader"] for c in nb.cells}
    assert meta["student"]["solution"] and not meta["student"]["locked"]
    assert meta["sheet"]["locked"] and not meta["sheet"]["solution"]
    for q in exercises.load(NAME).questions:
        assert meta[f"test_{q.id}"] == {"grade": True, "grade_id": f"test_{q.id}", "locked": True,
                                        "points": q.points, "schema_version": 3, "solution": False}
        assert meta[f"answer_{q.id}"]["solution"]


# ---------------------------------------------------------------------------
# Without the tool: the export's refusals and the helpers the cells call


def test_a_secret_without_a_roster_is_refused(tmp_path):
    with pytest.raises(GraphkinError, match="needs a roster"):
        platforms.export(NAME, "nbgrader", tmp_path / "out", secret=SECRET)
    assert not (tmp_path / "out" / "README.md").exists()


def _sources(tree):
    """The exported source notebook's cells: grade id → source."""
    nb = nbformat.reads(tree[f"source/{NAME}/{NAME}.ipynb"], as_version=4)
    return {c.metadata["nbgrader"]["grade_id"]: c.source for c in nb.cells}


def test_without_secret_or_roster_the_sheet_is_drawn_from_the_id():
    tree = nbx.build(platforms.bundle(NAME))
    assert sorted(tree) == ["README.md", "nbgrader_config.example.py", f"source/{NAME}/{NAME}.ipynb",
                            f"source/{NAME}/{NAME}.toml"]
    cells = _sources(tree)
    assert cells["sheet"].endswith(f'print(runtime.sheet_text("{NAME}.toml", STUDENT))')
    assert 'STUDENT = "sample"' in cells["student"]
    assert '_secret = ""  # this export has no course secret' in cells["test_T12"]
    assert "no course secret" in tree["README.md"]


def test_a_roster_without_a_secret_grades_with_none():
    tree = nbx.build(platforms.bundle(NAME, students=ROSTER))
    cells = _sources(tree)
    assert cells["sheet"].endswith(f'print(runtime.sheet_text("{NAME}.toml", STUDENT, "{NAME}-sheets.json"))')
    assert 'STUDENT = "alice"' in cells["student"]
    assert '_secret = ""  # this export has no course secret' in cells["test_T12"]
    assert "course_secret" not in cells["test_T12"] and "GRAPHKIN_SECRET=" not in tree["README.md"]


def test_graded_as(monkeypatch, tmp_path):
    monkeypatch.delenv("NBGRADER_STUDENT", raising=False)
    monkeypatch.delenv("NBGRADER_EXECUTION", raising=False)
    assert nbx.graded_as("alice") == "alice"  # a student's own run, or validate: nothing to compare with
    folder = tmp_path / "autograded" / "carol" / "hw3"
    folder.mkdir(parents=True)
    monkeypatch.chdir(folder)
    monkeypatch.setenv("NBGRADER_EXECUTION", "autograde")
    assert nbx.graded_as("alice") == "carol"
    monkeypatch.setenv("NBGRADER_STUDENT", "dave")
    assert nbx.graded_as("alice") == "dave"


def test_course_secret_checks_the_sheet(monkeypatch, tmp_path):
    monkeypatch.delenv("NBGRADER_EXECUTION", raising=False)
    b = platforms.bundle(NAME, secret=SECRET, students=ROSTER)
    exercise_file = tmp_path / b.exercise_file
    exercise_file.write_text(b.files[b.exercise_file], encoding="utf-8")
    monkeypatch.setenv(nbx.SECRET_VARIABLE, SECRET)
    assert nbx.course_secret(exercise_file, "bob", b.sheets) == SECRET
    with pytest.raises(GraphkinError, match="not on this assignment's roster"):
        nbx.course_secret(exercise_file, "mallory", b.sheets)
    monkeypatch.setenv(nbx.SECRET_VARIABLE, "another-course")
    with pytest.raises(GraphkinError, match="is not the secret this assignment was exported with"):
        nbx.course_secret(exercise_file, "bob", b.sheets)


def test_check_answer_tells_only_whether_it_can_be_read(tmp_path, capsys):
    f = tmp_path / f"{NAME}.toml"
    f.write_text(exercises.load(NAME).text, encoding="utf-8")
    nbx.check_answer(f, "T12", "12.3 N*m CW")  # wrong, but readable: passes
    assert "can be read" in capsys.readouterr().out
    with pytest.raises(AssertionError, match="No answer was given for T12"):
        nbx.check_answer(f, "T12", ...)
    with pytest.raises(AssertionError, match="use a decimal point"):
        nbx.check_answer(f, "T12", "12,5 N*m")
    with pytest.raises(AssertionError, match="not read as newton-metres"):
        nbx.check_answer(f, "T12", "12 Nm")


def test_question_ids_that_are_not_python_names():
    def fake(*ids):
        return SimpleNamespace(name="ex", question_ids=lambda: list(ids))

    assert nbx.variables(fake("F23", "peak.at", "lambda", "runtime", "_x")) == {
        "F23": "F23", "peak.at": "answer_peak_at", "lambda": "answer_lambda", "runtime": "answer_runtime",
        "_x": "answer__x"}
    with pytest.raises(GraphkinError, match="same notebook variable"):
        nbx.variables(fake("peak.at", "answer_peak_at"))
