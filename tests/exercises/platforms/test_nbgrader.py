"""The nbgrader export, with the real nbgrader: the README's commands in a temporary course directory.

One ``nbgrader autograde`` grades the whole class. Students: alice answers her variant right; bob makes a
sign slip, a wrong answer, and leaves nbgrader's ``raise NotImplementedError()`` in one answer cell; carol
hands in alice's notebook (alice's id and answers); one student per tampering notebook
(:mod:`tests.exercises.platforms.tampering`); students who hand in files beside the notebook (shadow
``graphkin/``, ``otter/``, ``nbgrader/``, ``IPython/`` packages, ``sitecustomize.py``, a ``.pth``, a
``json.py``, an ``ipykernel_launcher.py``, a ``graphkin/`` that hangs the kernel, pickles and otter's log,
links to the course's keys and to their folder, another notebook); a notebook that is a link to the keys;
extra grade cells worth 100 points; and notebooks that cannot be read (60 MB, 100 000-deep JSON, not
UTF-8, not JSON, not a notebook).

The grades nbgrader records must be those of the answers read as data, question by question (a hand-in
that cannot be read: 0, with graphkin's sentence); autograde must finish for every student; nothing handed
in may run or be loaded (every payload would leave a file in a canary folder); the regrade outside nbgrader
must agree; and no file a student gets back (the feedback folder) may hold a secret, a key or anything of
the grading machine's environment, or unescaped HTML.
"""

from __future__ import annotations

import csv
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

import graphkin
from graphkin import exercises
from graphkin.errors import GraphkinError
from graphkin.exercises import platforms
from graphkin.exercises.handins import REFUSALS
from graphkin.exercises.platforms import nbgrader as nbx
from graphkin.exercises.platforms import runtime
from tests.exercises.platforms import tampering
from tests.exercises.platforms.tampering import (
    HTML,
    NAME,
    SECRET,
    WRONG,
    Link,
    Tamper,
    beside,
    catalogue,
    expected_report,
    fill,
    leaks,
    refused_report,
    unreadable,
    with_extra_grade_cells,
    write_files,
)

pytestmark = pytest.mark.slow  # runs the real platform

nbformat = pytest.importorskip("nbformat")
pytest.importorskip("nbgrader")

BIN = Path(sys.executable).parent
LABELS = [t.label for t in catalogue("x", "alice")]
UNREADABLE = unreadable()
# Students who hand in files beside a notebook of wrong answers (or, for "hanging", their right answers).
BESIDE = {"extra_files": "packages", "startup": "startup", "pickles": "pickles", "links": "links",
          "export": "export"}
TIME_LIMIT = 15.0
"""The course's time limit per notebook in these tests [s] (the export's default is 120 s)."""
TAMPER_IDS = {label: f"t_{label}" for label in [*LABELS, *BESIDE, "hanging", "link_notebook", "extra_grade_cells",
                                                 *UNREADABLE]}
ROSTER = ["alice", "bob", "carol", *TAMPER_IDS.values()]

# A graphkin package handed in beside the notebook that tries every trick at once, if the kernel imported it.
FORGED_GRAPHKIN = b"""\
import glob, os, pathlib
ip = get_ipython()
ip.events.register("post_run_cell", lambda result: print("3.0"))
ip.display_formatter.formatters["text/plain"].for_type(float, lambda x, p, cycle: p.text("1.0"))
keys = [pathlib.Path(p).read_text() for p in glob.glob("../../../graphkin-keys/*.json")]
print(keys, os.environ.get("GRAPHKIN_SECRET"), os.environ.get("GRAPHKIN_MARKER"))
"""


def _env() -> dict:
    # The teacher's shell: the venv first on PATH (nbgrader runs alembic from it), this graphkin first on
    # sys.path (nbgrader imports graphkin's exporter and preprocessors from it), the course secret and a marker.
    env = {k: v for k, v in os.environ.items() if k != "NBGRADER_STUDENT"}
    env.update(PATH=f"{BIN}{os.pathsep}{env.get('PATH', '')}", GRAPHKIN_SECRET=SECRET, GRAPHKIN_MARKER=tampering.MARKER,
               PYTHONPATH=str(Path(graphkin.__file__).resolve().parents[1]))
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


def _own(student: str, label: str) -> Tamper:
    key = _key(student)
    return Tamper(label, (), {q: f"{q} = {json.dumps(a, ensure_ascii=False)}" for q, a in key.items()}, key)


def _handed_in(canary: Path) -> dict:
    """Student → SimpleNamespace(claimed id, Tamper, files beside, notebook bytes or Link or None, refusal code)."""
    bob = _key("bob")
    wrong = Tamper("wrong", (), {q: f"{q} = {v!r}" for q, v in WRONG.items()}, dict(WRONG))
    slips = {"F23": bob["F23"], "F14": "1 N", "T12": _flip_sense(bob["T12"])}

    def one(claimed, t, files=None, notebook=None, refused=None, edit=None):
        return SimpleNamespace(claimed=claimed, t=t, files=files or {}, notebook=notebook, refused=refused, edit=edit)

    out = {
        "alice": one("alice", _own("alice", "alice")),
        "bob": one("bob", Tamper("bob", (), {
            # Right, with nbgrader's stub left under it: the cell raises, the answer still counts.
            "F23": f'F23 = "{bob["F23"]}"\n# YOUR CODE HERE\nraise NotImplementedError()',
            "F14": 'F14 = "1 N"',
            "T12": f'T12 = "{_flip_sense(bob["T12"])}"'}, slips)),
        "carol": one("alice", _own("alice", "alice")),
    }
    groups = beside(canary)
    for label in LABELS:
        sid = TAMPER_IDS[label]
        out[sid] = one(sid, {t.label: t for t in catalogue(sid, "alice")}[label])
    for label, group in BESIDE.items():
        files = dict(groups[group])
        if label == "extra_files":
            files["graphkin/__init__.py"] = FORGED_GRAPHKIN
        if label == "pickles":  # and another notebook, with someone's right answers
            files["alice.ipynb"] = json.dumps({"cells": [{"cell_type": "code", "source": "\n".join(
                _own("alice", "x").answers.values())}]}).encode()
        out[TAMPER_IDS[label]] = one(TAMPER_IDS[label], wrong, files)
    sid = TAMPER_IDS["hanging"]
    # A graphkin the kernel would import before the real one: it would never return.
    hangs = (tampering.payload(canary, "hanging_graphkin") + "import time\ntime.sleep(10**6)\n").encode()
    out[sid] = one(sid, _own(sid, "hanging"), {"graphkin/__init__.py": hangs})
    out[TAMPER_IDS["link_notebook"]] = one(None, wrong, notebook=Link("{keys}"), refused="link")
    out[TAMPER_IDS["extra_grade_cells"]] = one(TAMPER_IDS["extra_grade_cells"], wrong, edit=with_extra_grade_cells)
    for label, (data, code) in UNREADABLE.items():
        out[TAMPER_IDS[label]] = one(None, wrong, notebook=data, refused=code)
    return out


def _submit(course: Path, student: str, h) -> None:
    """Hand in as the student would, where ``nbgrader collect`` puts it: the released files, the notebook
    filled in (or the bytes or link handed in in its place), and the files beside it."""
    folder = course / "submitted" / student / NAME
    folder.mkdir(parents=True)
    for f in (course / "release" / NAME).iterdir():
        if f.suffix != ".ipynb":
            shutil.copy(f, folder / f.name)
    fill_in = {"keys": str(course / nbx.KEYS_FOLDER / f"{NAME}.json"), "keys_folder": str(course / nbx.KEYS_FOLDER)}
    write_files(folder, h.files, fill_in)
    target = folder / f"{NAME}.ipynb"
    if isinstance(h.notebook, Link):
        os.symlink(h.notebook.target.format(**fill_in), target)
    elif isinstance(h.notebook, bytes):
        target.write_bytes(h.notebook)
    else:
        nb = nbformat.read(course / "release" / NAME / f"{NAME}.ipynb", as_version=4)
        nb = fill(nb, h.claimed, h.t, {q: f"answer_{q}" for q in h.t.answers})
        nbformat.write(h.edit(nb) if h.edit else nb, target)


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    """The README's steps in a course directory: set up, generate, hand in, autograde, export, feedback, regrade.

    First, an autograde without graphkin's lines in nbgrader_config.py (it must keep no grade), and one with
    the lines of an earlier graphkin, without its exporter (it must refuse to grade).
    """
    root = tmp_path_factory.mktemp("nbgrader")
    course, canary = root / "course", root / "canary"
    course.mkdir()
    canary.mkdir()
    platforms.export(NAME, "nbgrader", course / "export", secret=SECRET, students=ROSTER)
    b = platforms.bundle(NAME, secret=SECRET, students=ROSTER)
    cmd = nbx.readme_commands(b)
    readme = (course / "export" / "README.md").read_text(encoding="utf-8")
    for step in cmd.values():
        assert "".join(f"   {line}\n" for line in step.splitlines()) in readme
    base = (f'c = get_config()\nc.CourseDirectory.course_id = "mechanics"\n'
            f'c.CourseDirectory.db_url = "sqlite:///{(course / "gradebook.db").as_posix()}"\n')
    config = course / "nbgrader_config.py"
    config.write_text(base, encoding="utf-8")
    _bash(course, cmd["setup"])
    _bash(course, cmd["generate"])
    handed_in = _handed_in(canary)
    for student, h in handed_in.items():
        _submit(course, student, h)
    unconfigured = _bash(course, f"nbgrader autograde {NAME} --student alice", check=False)
    unconfigured_grades = _grades(course, "alice")
    lines = nbx.config_lines(TIME_LIMIT)
    config.write_text(base + "\n".join(line for line in lines if "exporter_class" not in line) + "\n",
                      encoding="utf-8")
    no_exporter = _bash(course, f"nbgrader autograde {NAME} --student alice --force", check=False)
    no_exporter_grades = _grades(course, "alice")
    config.write_text(base + "\n".join(lines) + "\n", encoding="utf-8")
    autograded = _bash(course, cmd["autograde"].replace(f"nbgrader autograde {NAME}",
                                                        f"nbgrader autograde {NAME} --force"))
    _bash(course, cmd["feedback"])
    _bash(course, cmd["regrade"])
    regraded = _bash(course, cmd["regrade"].replace("-o regraded.csv", "--json"))
    return SimpleNamespace(dir=course, canary=canary, handed_in=handed_in, unconfigured=unconfigured,
                           unconfigured_grades=unconfigured_grades, no_exporter=no_exporter,
                           no_exporter_grades=no_exporter_grades, autograde_log=autograded.stdout + autograded.stderr,
                           regraded={r["student"]: r for r in json.loads(regraded.stdout)})


def _grades(course: Path, student) -> dict:
    from nbgrader.api import Gradebook, MissingEntry

    with Gradebook(f"sqlite:///{(course / 'gradebook.db').as_posix()}", "mechanics") as gb:
        try:
            return {qid: gb.find_grade(f"test_{qid}", NAME, NAME, student).score for qid in ("F23", "F14", "T12")}
        except MissingEntry:
            return {}


def _report(course, student) -> dict:
    h = course.handed_in[student]
    if h.refused:
        return refused_report(student, h.refused)
    if h.claimed != student:
        return {"questions": [{"id": q, "score": 0.0} for q in ("F23", "F14", "T12")], "score": 0.0}
    return expected_report(student, h.t, ROSTER)


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


def test_the_class_tries_more_than_15_kinds_of_tampering():
    kinds = {k for t in catalogue("x", "alice") for k in t.kinds} | set(UNREADABLE)
    kinds |= {path for group in BESIDE.values() for path in beside("canary")[group]}
    kinds |= {"hanging", "link_notebook", "extra_grade_cells", "another_notebook", "another_students_id"}
    assert len(kinds) >= 15, sorted(kinds)


@pytest.mark.parametrize("student", ROSTER)
def test_each_notebook_earns_what_its_answers_read_as_data_earn(course, student):
    """Honest notebooks, a friend's notebook, and notebooks that replace graphkin, nbgrader's helpers,
    builtins, sys.modules or IPython's hooks, read the course's files and environment, write results,
    sleep, exit, add grade cells, or hand in files the kernel would import, pickles and links: each earns
    what its answers earn, never more; one that cannot be read earns 0 with graphkin's sentence."""
    report = _report(course, student)
    assert _grades(course.dir, student) == {q["id"]: q["score"] for q in report["questions"]}
    if report.get("refused"):
        assert all(REFUSALS[course.handed_in[student].refused] in text
                   for gid, text in _outputs(course, student).items() if gid.startswith("test_"))


def test_nothing_handed_in_ever_ran_or_was_loaded(course):
    """Imported, run at start-up, unpickled: any of it would have left a file in the canary folder."""
    assert sorted(p.name for p in course.canary.iterdir()) == []


def test_autograde_graded_every_student_and_named_what_it_did_not_read(course):
    """One student's extra grade cells or unreadable notebook never stops the class: autograde ends well (the
    fixture checks its exit code) and every student after them has grades. Its log names what was handed in
    beside each notebook and why a notebook was not graded."""
    assert all(_grades(course.dir, s) for s in ROSTER)
    log = course.autograde_log
    assert "t_pickles: handed in beside the notebook, not read (graphkin): .OTTER_LOG (otter's log, a pickle)" in log
    assert "alice.ipynb (another notebook)" in log
    assert "keys.json (a link)" in log and "course-keys (a link)" in log
    assert f"t_too_deep: not graded (graphkin): {REFUSALS['too_deep']}" in log
    assert ("t_extra_grade_cells: cells of the student's own, not given to nbgrader (graphkin): 'test_F23' (again), "
            "'extra_points'") in log


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


def test_each_test_cell_shows_the_regrades_feedback_line(course):
    """Verdict by verdict, nbgrader's feedback is the regrade's (a refusal included)."""
    for student in ROSTER:
        out = _outputs(course, student)
        for result in course.regraded[student]["questions"]:
            assert runtime.feedback_line(result) in out[f"test_{result['id']}"], (student, result["id"])
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


def test_a_file_that_would_hang_the_kernel_is_gone_before_it_starts(course):
    """The graphkin/ handed in would sleep for ever once imported: it was removed before the kernel started
    (it left nothing in the canary folder), and the student's right answers earned full marks."""
    assert not (course.canary / "hanging_graphkin").exists()
    assert _grades(course.dir, TAMPER_IDS["hanging"]) == {"F23": 1.0, "F14": 1.0, "T12": 1.0}


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


def test_without_graphkins_lines_no_grade_is_kept(course):
    run = course.unconfigured
    assert "must be graded read as data" in run.stdout + run.stderr
    assert all(v == 0 for v in course.unconfigured_grades.values())


def test_without_graphkins_exporter_nothing_is_graded(course):
    """The lines of an earlier export (no exporter): the preprocessor refuses to grade, naming the line."""
    run = course.no_exporter
    assert "c.Autograde.exporter_class" in run.stdout + run.stderr
    assert all(v == 0 for v in course.no_exporter_grades.values())


def test_nothing_secret_in_any_file_a_student_gets_back(course):
    """Every file of feedback/ (what generate_feedback hands back) and of release/."""
    keys = (course.dir / "graphkin-keys" / f"{NAME}.json").read_text(encoding="utf-8")
    for p in (course.dir / "feedback").rglob("*"):
        if p.is_file() or p.is_symlink():
            assert not p.is_symlink(), p
            assert leaks(p.read_bytes().decode("utf-8", "replace"), keys) == [], p
    assert {p.parent.parent.name for p in (course.dir / "feedback").rglob(f"{NAME}.html")} == set(ROSTER)
    for p in (course.dir / "release").rglob("*"):
        if p.is_file():
            assert SECRET.encode() not in p.read_bytes() and b"graphkin-keys-1" not in p.read_bytes(), p


def test_the_kernels_folder_held_nothing_of_the_students(course):
    """What nbgrader copied of a submission (the files, the targets of its links) is gone from autograded/:
    only the notebook, the assignment's own files and nbgrader's timestamp are there."""
    own = {"timestamp.txt", f"{NAME}.ipynb", f"{NAME}.toml", f"{NAME}-sheets.json"}
    for student in ROSTER:
        folder = course.dir / "autograded" / student / NAME
        assert {p.relative_to(folder).as_posix() for p in folder.rglob("*")} <= own, student


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


def test_the_exporter_class_is_made_only_when_nbgrader_asks_for_it():
    code = ("import sys, graphkin.exercises.platforms.nbgrader as m\n"
            "assert 'nbconvert' not in sys.modules\n"
            "from nbconvert.exporters import NotebookExporter\n"
            "assert issubclass(m.HandInExporter, NotebookExporter) and m.HandInExporter is m.HandInExporter\n"
            "print(m.HandInExporter.__module__ + '.' + m.HandInExporter.__name__)\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=_env(), timeout=120)
    assert done.stdout.strip() == nbx.EXPORTER, done.stderr


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
