"""The nbgrader export, with the real nbgrader: the README's commands in a temporary course directory.

Students: alice answers her variant right; bob makes a sign slip, a wrong answer, and leaves nbgrader's
``raise NotImplementedError()`` in one answer cell; carol hands in alice's notebook (alice's id and
answers); and one student per tampering notebook (:mod:`tests.exercises.platforms.tampering`), plus one
who hands in extra files beside the notebook and one whose extra file hangs the kernel (right answers: the
grade must not wait on the kernel, and the notebook's time limit must end the wait).
The grades nbgrader records must be the grades of the
answers read as data, question by question; the feedback nbgrader hands back must hold no secret, no
key, nothing of the grading machine's environment, and no unescaped HTML.
"""

from __future__ import annotations

import csv
import json
import os
import re
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
from tests.exercises.platforms import tampering
from tests.exercises.platforms.tampering import (
    HTML,
    NAME,
    SECRET,
    WRONG,
    Tamper,
    catalogue,
    expected_report,
    fill,
    leaks,
)

pytestmark = pytest.mark.slow  # runs the real platform

nbformat = pytest.importorskip("nbformat")
pytest.importorskip("nbgrader")

BIN = Path(sys.executable).parent
LABELS = [t.label for t in catalogue("x", "alice")]
EXTRA_FILES = "extra_files"
HANGING = "hanging_kernel"
TAMPER_IDS = {label: f"t_{label}" for label in [*LABELS, EXTRA_FILES, HANGING]}
TIME_LIMIT = 15.0
"""The course's time limit per notebook in these tests [s] (the export's default is 120 s)."""
HANGING_GRAPHKIN = "import time\ntime.sleep(10**6)  # the kernel imports this before the real graphkin\n"
ROSTER = ["alice", "bob", "carol", *TAMPER_IDS.values()]

# Files handed in beside the notebook: a package named graphkin that the kernel (started in the folder
# nbgrader copies the submission into) imports before the real one, and that tries every trick at once.
FORGED_GRAPHKIN = """\
import glob, os, pathlib
ip = get_ipython()
ip.events.register("post_run_cell", lambda result: print("3.0"))
ip.display_formatter.formatters["text/plain"].for_type(float, lambda x, p, cycle: p.text("1.0"))
keys = [pathlib.Path(p).read_text() for p in glob.glob("../../../graphkin-keys/*.json")]
print(keys, os.environ.get("GRAPHKIN_SECRET"), os.environ.get("GRAPHKIN_MARKER"))
"""


def _env() -> dict:
    # The teacher's shell: the venv first on PATH (nbgrader runs alembic from it), the course secret and a
    # marker in the environment.
    env = {k: v for k, v in os.environ.items() if k != "NBGRADER_STUDENT"}
    env.update(PATH=f"{BIN}{os.pathsep}{env.get('PATH', '')}", GRAPHKIN_SECRET=SECRET, GRAPHKIN_MARKER=tampering.MARKER)
    return env


def _bash(course: Path, commands: str, *, check=True, timeout=1800):
    done = subprocess.run(["bash", "-eu", "-c", commands], cwd=course, env=_env(), capture_output=True, text=True,
                          timeout=timeout)
    if check:
        assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    return done


def _key(student):
    return {q["id"]: q["answer"]["text"] for q in exercises.key(NAME, student, SECRET)["questions"]}


def _flip_sense(text):
    return text.replace("CCW", "@").replace("CW", "CCW").replace("@", "CW")


def _handed_in() -> dict:
    """Student → (the id the notebook carries, the Tamper it is, extra files)."""
    alice, bob = _key("alice"), _key("bob")
    right = Tamper("alice", (), {q: f"{q} = {json.dumps(a, ensure_ascii=False)}" for q, a in alice.items()}, alice)
    slips = {"F23": bob["F23"], "F14": "1 N", "T12": _flip_sense(bob["T12"])}
    out = {
        "alice": ("alice", right, {}),
        "bob": ("bob", Tamper("bob", (), {
            # Right, with nbgrader's stub left under it: the cell raises, the answer still counts.
            "F23": f'F23 = "{bob["F23"]}"\n# YOUR CODE HERE\nraise NotImplementedError()',
            "F14": 'F14 = "1 N"',
            "T12": f'T12 = "{_flip_sense(bob["T12"])}"'}, slips), {}),
        "carol": ("alice", right, {}),
    }
    for label, sid in TAMPER_IDS.items():
        if label == EXTRA_FILES:
            t = Tamper(label, (), {q: f"{q} = {v!r}" for q, v in WRONG.items()}, dict(WRONG))
            out[sid] = (sid, t, {"graphkin/__init__.py": FORGED_GRAPHKIN})
        elif label == HANGING:
            own = _key(sid)
            t = Tamper(label, (), {q: f"{q} = {json.dumps(a, ensure_ascii=False)}" for q, a in own.items()}, own)
            out[sid] = (sid, t, {"graphkin/__init__.py": HANGING_GRAPHKIN})
        else:
            out[sid] = (sid, {t.label: t for t in catalogue(sid, "alice")}[label], {})
    return out


def _submit(course: Path, student: str, claimed: str, t: Tamper, extra: dict):
    """Fill in the released notebook as the student would, and put it where ``nbgrader collect`` puts it."""
    nb = nbformat.read(course / "release" / NAME / f"{NAME}.ipynb", as_version=4)
    nb = fill(nb, claimed, t, {q: f"answer_{q}" for q in t.answers})
    folder = course / "submitted" / student / NAME
    folder.mkdir(parents=True)
    for f in (course / "release" / NAME).iterdir():
        if f.suffix != ".ipynb":
            shutil.copy(f, folder / f.name)
    for rel, text in extra.items():
        (folder / rel).parent.mkdir(parents=True, exist_ok=True)
        (folder / rel).write_text(text, encoding="utf-8")
    nbformat.write(nb, folder / f"{NAME}.ipynb")


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    """The README's steps in a course directory: set up, generate, hand in, autograde, export, feedback, regrade.

    First an autograde without graphkin's lines in nbgrader_config.py: it must keep no grade.
    """
    root = tmp_path_factory.mktemp("nbgrader")
    course = root / "course"
    course.mkdir()
    platforms.export(NAME, "nbgrader", course / "export", secret=SECRET, students=ROSTER)
    b = platforms.bundle(NAME, secret=SECRET, students=ROSTER)
    cmd = nbx.readme_commands(b)
    readme = (course / "export" / "README.md").read_text(encoding="utf-8")
    for step in cmd.values():
        assert "".join(f"   {line}\n" for line in step.splitlines()) in readme
    base = (f'c = get_config()\nc.CourseDirectory.course_id = "mechanics"\n'
            f'c.CourseDirectory.db_url = "sqlite:///{(course / "gradebook.db").as_posix()}"\n')
    (course / "nbgrader_config.py").write_text(base, encoding="utf-8")
    _bash(course, cmd["setup"])
    _bash(course, cmd["generate"])
    handed_in = _handed_in()
    for student, (claimed, t, extra) in handed_in.items():
        _submit(course, student, claimed, t, extra)
    unconfigured = _bash(course, f"nbgrader autograde {NAME} --student alice", check=False)
    unconfigured_grades = _grades(course, "alice")
    (course / "nbgrader_config.py").write_text(base + "\n".join(nbx.config_lines(TIME_LIMIT)) + "\n",
                                               encoding="utf-8")
    autograded = _bash(course, cmd["autograde"].replace(f"nbgrader autograde {NAME}",
                                                        f"nbgrader autograde {NAME} --force"))
    _bash(course, cmd["feedback"])
    _bash(course, cmd["regrade"])
    return SimpleNamespace(dir=course, handed_in=handed_in, unconfigured=unconfigured,
                           unconfigured_grades=unconfigured_grades, autograde_log=autograded.stdout + autograded.stderr)


def _grades(course: Path, student) -> dict:
    from nbgrader.api import Gradebook, MissingEntry

    with Gradebook(f"sqlite:///{(course / 'gradebook.db').as_posix()}", "mechanics") as gb:
        try:
            return {qid: gb.find_grade(f"test_{qid}", NAME, NAME, student).score for qid in ("F23", "F14", "T12")}
        except MissingEntry:
            return {}


def _report(course, student) -> dict:
    claimed, t, _ = course.handed_in[student]
    if claimed != student:
        return {"questions": [{"id": q, "score": 0.0} for q in ("F23", "F14", "T12")], "score": 0.0}
    return expected_report(student, t, ROSTER)


def _feedback(course, student) -> str:
    return (course.dir / "feedback" / student / NAME / f"{NAME}.html").read_text(encoding="utf-8")


def _outputs(course, student):
    """Each test cell's printed text, by grade id, in the autograded notebook."""
    nb = nbformat.read(course.dir / "autograded" / student / NAME / f"{NAME}.ipynb", as_version=4)
    out = {}
    for cell in nb.cells:
        gid = cell.metadata.get("nbgrader", {}).get("grade_id", "")
        out[gid] = "".join(o.get("text", "") for o in cell.get("outputs", []) if o.output_type == "stream")
    return out


@pytest.mark.parametrize("student", ROSTER)
def test_each_notebook_earns_what_its_answers_read_as_data_earn(course, student):
    """Honest notebooks, a friend's notebook, and notebooks that replace graphkin, nbgrader's helpers,
    builtins, sys.modules or IPython's hooks, read the course's files and environment, write results,
    sleep, exit, or hand in files that the kernel imports: each earns what its answers earn, never more."""
    report = _report(course, student)
    assert _grades(course.dir, student) == {q["id"]: q["score"] for q in report["questions"]}


def test_grades_csv_is_the_class_table(course):
    rows = {r["student_id"]: r for r in csv.DictReader((course.dir / "grades.csv").open(encoding="utf-8"))}
    assert {s: float(r["score"]) for s, r in rows.items()} == {s: _report(course, s)["score"] for s in ROSTER}
    assert (float(rows["alice"]["score"]), float(rows["bob"]["score"])) == (3.0, 1.5)


def test_the_regrade_outside_nbgrader_agrees(course):
    with open(course.dir / "regraded.csv", encoding="utf-8", newline="") as f:
        regraded = {r["student"]: float(r["score"]) for r in csv.DictReader(f)}
    rows = {r["student_id"]: float(r["score"]) for r in csv.DictReader((course.dir / "grades.csv").open(
        encoding="utf-8"))}
    assert regraded == rows


def test_each_test_cell_shows_the_feedback_line(course):
    for student in ("alice", "bob"):
        out = _outputs(course, student)
        for result in _report(course, student)["questions"]:
            assert runtime.feedback_line(result) in out[f"test_{result['id']}"]
    bob = _outputs(course, "bob")
    assert "The size is right but the sense is wrong" in bob["test_T12"]
    # The sheet cell shows whom the notebook was graded as, and their data.
    assert bob["sheet"].startswith("Graded as student 'bob': 1.5 / 3 points.")
    assert exercises.make(NAME, "bob", SECRET)["data"][0]["shown"] in bob["sheet"]


def test_a_submission_carrying_another_students_id_scores_nothing(course):
    sentence = runtime.identity_error("alice", "carol")
    assert sentence == ("this submission carries the student id 'alice' but was handed in by 'carol': "
                        "each student answers their own variant")
    out = _outputs(course, "carol")
    assert all(sentence in out[f"test_{q}"].replace("This", "this") for q in ("F23", "F14", "T12"))


def test_a_hanging_kernel_waits_at_most_its_notebooks_time_limit(course):
    """A file handed in beside the notebook hangs the kernel: nbclient logs each wait it ended, and each is
    at most what was left of the notebook's time limit, not nbgrader's per-cell limit."""
    waits = [int(w) for w in re.findall(r"Timeout waiting for execute reply \((\d+)s\)", course.autograde_log)]
    assert waits, "the hanging kernel was never timed out: " + course.autograde_log[-2000:]
    assert max(waits) <= TIME_LIMIT, waits
    assert sum(w for w in waits if w > 1) <= TIME_LIMIT, waits  # the first wait spends the budget; later ones 1 s
    report = _report(course, TAMPER_IDS[HANGING])
    assert report["score"] == 3.0
    assert _grades(course.dir, TAMPER_IDS[HANGING]) == {q["id"]: q["score"] for q in report["questions"]}


def test_the_time_limit_is_per_notebook():
    now = [100.0]
    limit = nbx.TimeLimit(20, clock=lambda: now[0])
    limit.start(notebook=None)
    assert limit.cell_timeout(None) == 20
    now[0] += 12.5
    assert limit.cell_timeout(None) == 8  # what is left, rounded up
    now[0] += 30
    assert limit.cell_timeout(None) == 1  # spent: one second, for nbclient to interrupt and go on
    limit.start(notebook=None)  # the next notebook starts with the whole budget
    assert limit.cell_timeout(None) == 20
    with pytest.raises(GraphkinError, match="positive number of seconds"):
        nbx.TimeLimit(0)


def test_without_graphkins_preprocessors_no_grade_is_kept(course):
    run = course.unconfigured
    assert "must be graded read as data" in run.stdout + run.stderr
    assert all(v == 0 for v in course.unconfigured_grades.values())


def test_nothing_secret_in_the_feedback_students_get(course):
    keys = (course.dir / "graphkin-keys" / f"{NAME}.json").read_text(encoding="utf-8")
    for student in ROSTER:
        html = _feedback(course, student)
        assert leaks(html, keys) == [], student
    # Nor in what is released to students.
    for p in (course.dir / "release").rglob("*"):
        if p.is_file():
            assert SECRET.encode() not in p.read_bytes() and b"graphkin-keys-1" not in p.read_bytes(), p


def test_what_the_kernel_printed_reaches_no_student(course):
    """The handed-in graphkin package ran in the kernel (it printed the keys and "3.0" after every cell):
    none of it is in the autograded notebook or the feedback; the grade is that of the answers."""
    sid = TAMPER_IDS[EXTRA_FILES]
    out = _outputs(course, sid)
    assert out["sheet"].splitlines()[0] == f"Graded as student {sid!r}: 0 / 3 points."
    assert not any("3.0" == line.strip() for text in out.values() for line in text.splitlines())
    keys = (course.dir / "graphkin-keys" / f"{NAME}.json").read_text(encoding="utf-8")
    autograded = (course.dir / "autograded" / sid / NAME / f"{NAME}.ipynb").read_text(encoding="utf-8")
    assert leaks(autograded, keys) == []


def test_html_in_an_answer_is_escaped_in_the_feedback(course):
    html = _feedback(course, TAMPER_IDS["html_payload"])
    assert HTML not in html and "<script>alert" not in html
    assert "onerror=" in html  # escaped, as text: &lt;img src=x onerror=...


def test_export_files(course):
    export = course.dir / "export"
    files = sorted(p.relative_to(export).as_posix() for p in export.rglob("*") if p.is_file())
    assert files == ["README.md", f"graphkin-keys/{NAME}.json", "nbgrader_config.example.py",
                     f"source/{NAME}/{NAME}-sheets.json", f"source/{NAME}/{NAME}.ipynb", f"source/{NAME}/{NAME}.toml"]
    sheets = json.loads((export / "source" / NAME / f"{NAME}-sheets.json").read_text(encoding="utf-8"))
    assert sorted(sheets) == sorted(ROSTER) and sheets["bob"] == exercises.make(NAME, "bob", SECRET)
    assert not any("answer" in q for sheet in sheets.values() for q in sheet["questions"])
    assert SECRET not in "".join(p.read_text(encoding="utf-8") for p in export.rglob("*") if p.is_file())


def test_source_notebook_cells(course):
    nb = nbformat.read(course.dir / "export" / "source" / NAME / f"{NAME}.ipynb", as_version=4)
    meta = {c.metadata["nbgrader"]["grade_id"]: c.metadata["nbgrader"] for c in nb.cells}
    assert meta["student"]["solution"] and not meta["student"]["locked"]
    assert meta["sheet"]["locked"] and not meta["sheet"]["solution"]
    for q in exercises.load(NAME).questions:
        assert meta[f"test_{q.id}"] == {"grade": True, "grade_id": f"test_{q.id}", "locked": True,
                                        "points": q.points, "schema_version": 3, "solution": False}
        assert meta[f"answer_{q.id}"]["solution"]


# ---------------------------------------------------------------------------
# Without the tool


def test_a_secret_without_a_roster_is_refused(tmp_path):
    with pytest.raises(GraphkinError, match="needs a roster"):
        platforms.export(NAME, "nbgrader", tmp_path / "out", secret=SECRET)
    assert not (tmp_path / "out" / "README.md").exists()


def test_without_secret_or_roster_the_sheet_is_drawn_from_the_id():
    tree = nbx.build(platforms.bundle(NAME))
    assert sorted(tree) == ["README.md", f"graphkin-keys/{NAME}.json", "nbgrader_config.example.py",
                            f"source/{NAME}/{NAME}.ipynb", f"source/{NAME}/{NAME}.toml"]
    nb = nbformat.reads(tree[f"source/{NAME}/{NAME}.ipynb"], as_version=4)
    cells = {c.metadata["nbgrader"]["grade_id"]: c.source for c in nb.cells}
    assert cells["sheet"].endswith(f'print(runtime.sheet_text("{NAME}.toml", STUDENT))')
    assert 'STUDENT = "sample"' in cells["student"]
    assert "no course secret" in tree["README.md"]


def test_write_grades_replaces_whatever_the_kernel_printed():
    cells = [nbformat.v4.new_code_cell("x") for _ in range(3)]
    for cell, gid in zip(cells, ("sheet", "test_T12", "other")):
        cell.metadata["nbgrader"] = {"grade_id": gid}
        cell.outputs = [nbformat.v4.new_output("execute_result", data={"text/plain": "3.0"}, execution_count=1)]
    nb = nbformat.v4.new_notebook(cells=cells)
    resources = {nbx.GRADES: {"tests": {"test_T12": ("T12: slip (sign), 0.5 / 1 — …", 0.5)}, "sheet": "Graded"}}
    nb, _ = nbx.write_grades(nb, resources)
    assert [o.get("text") for o in cells[0].outputs] == ["Graded\n"]
    assert cells[1].outputs[1]["data"]["text/plain"] == "0.5" and cells[1].outputs[0]["text"].startswith("T12")
    assert cells[2].outputs == []
    # Another assignment's notebook (no grades from read_as_data) passes through as it is.
    other = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("1")])
    other.cells[0].outputs = [nbformat.v4.new_output("stream", name="stdout", text="hi")]
    assert nbx.write_grades(other, {})[0].cells[0].outputs[0]["text"] == "hi"


def test_check_answer_tells_only_whether_it_can_be_read(tmp_path, capsys):
    f = tmp_path / f"{NAME}.toml"
    f.write_text(exercises.load(NAME).text, encoding="utf-8")
    nbx.check_answer(f, "T12", "12.3 N*m CW")  # wrong, but readable: passes
    assert "can be read" in capsys.readouterr().out
    with pytest.raises(AssertionError, match="No answer was given for T12"):
        nbx.check_answer(f, "T12", ...)
    with pytest.raises(AssertionError, match="could be 1.352 or 1352"):
        nbx.check_answer(f, "T12", "1,352 N*m")


def test_question_ids_that_are_not_python_names():
    def fake(*ids):
        return SimpleNamespace(name="ex", question_ids=lambda: list(ids))

    assert nbx.variables(fake("F23", "peak.at", "lambda", "runtime", "_x")) == {
        "F23": "F23", "peak.at": "answer_peak_at", "lambda": "answer_lambda", "runtime": "answer_runtime",
        "_x": "answer__x"}
    with pytest.raises(GraphkinError, match="same notebook variable"):
        nbx.variables(fake("peak.at", "answer_peak_at"))
