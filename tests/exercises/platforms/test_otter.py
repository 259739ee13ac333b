"""The otter-grader export, with the real tool: ``otter assign``, then handed-in notebooks and zips graded.

Two ways a hand-in reaches otter, both run here on the real otter:

- **the README's steps, as printed** (bash, in the export folder): ``otter assign``, the check of the
  solutions, ``graphkin exercise strip`` then ``otter run`` on every hand-in of ``submissions/``,
  ``graphkin exercise collect``, and the regrade outside otter. The hand-ins: a right notebook (s002's
  key), one with slips (s001), notebooks that cannot be read (60 MB, 100 000-deep JSON, not UTF-8, not
  JSON, not a notebook), and zips (two notebooks and otter's log; no notebook; a damaged zip);
- **raw, as Gradescope hands them to otter** (no strip): zips of a tampering notebook
  (:mod:`tests.exercises.platforms.tampering`) and files beside it (shadow ``graphkin/``, ``otter/``,
  ``nbgrader/``, ``IPython/`` packages, ``sitecustomize.py``, a ``.pth``, a ``json.py``, an
  ``ipykernel_launcher.py``, a forged ``.OTTER_LOG`` and results pickles, a shadow ``vendor/`` and
  ``tests/``, links to the keys), graded by otter's own runner (``otter.run.main``, what ``otter run``
  calls) in one process, so that otter starts once for all of them.

Each earns exactly what its notebook's literal answers earn (or is refused with graphkin's sentence), the
regrade agrees, nothing handed in ever runs (every payload would leave a file in a canary folder), and no
secret, key or environment value reaches a file a student gets. The grading machine's environment holds the
course secret and a marker.
"""

from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import graphkin
from graphkin import exercises
from graphkin.errors import GraphkinError
from graphkin.exercises.handins import REFUSALS
from graphkin.exercises.platforms import bundle, export, otter, runtime
from tests.exercises.platforms.tampering import (
    MARKER,
    NAME,
    SECRET,
    Tamper,
    beside,
    catalogue,
    expected_report,
    fill,
    leaks,
    refused_report,
    unreadable,
    with_extra_grade_cells,
    write_zip,
)

nbformat = pytest.importorskip("nbformat")

ROSTER = ["s001", "s002"]
BIN = Path(sys.executable).parent
TAMPERING = catalogue("s001", "s002")
# The raw zips: each tampering notebook with a group of files beside it (None: the notebook alone, in a zip).
GROUPS = {"code_patches": "pickles", "answers_as_code": "packages", "magics": "startup", "html_payload": "export",
          "hostile_literals": "links", "sleeps": None, "exits": None, "classmate": None}
UNREADABLE = unreadable()
# README hand-ins that are zips: what each holds besides its one notebook (if any), and its refusal.
ZIPS = {"two_notebooks": None, "no_notebook": "no_notebook", "bad_zip": "bad_zip"}
pytestmark = [pytest.mark.slow,  # runs the real platform
              pytest.mark.skipif(not (BIN / "otter").exists(), reason="otter-grader is not installed in this venv")]


def _env() -> dict:
    # The teacher's shell: the venv first on PATH, this graphkin first on sys.path (otter imports the plugin
    # from it), the course secret and a marker in the environment.
    return {**os.environ, "PATH": f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}", "GRAPHKIN_SECRET": SECRET,
            "GRAPHKIN_MARKER": MARKER, "PYTHONPATH": str(Path(graphkin.__file__).resolve().parents[1])}


def _bash(folder: Path, commands: str, timeout: float):
    done = subprocess.run(["bash", "-euo", "pipefail", "-c", commands], cwd=folder, env=_env(), capture_output=True,
                          text=True, timeout=timeout)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    return done


def _flip_sense(torque: str) -> str:
    return torque.replace("CCW", "@").replace("CW", "CCW").replace("@", "CW")


def _key(student: str) -> dict:
    return {q["id"]: q["answer"]["text"] for q in exercises.key(NAME, student, secret=SECRET)["questions"]}


def _plain() -> list[Tamper]:
    """The honest notebooks: s002 right, s001 with a sign slip, a 20 % error and no answer to F14."""
    key1 = _key("s001")
    mag, angle = key1["F23"].split("∠")
    number, unit = mag.split()
    bad = {"T12": _flip_sense(key1["T12"]), "F23": f"{float(number) * 1.2:.4g} {unit} ∠{angle}"}
    return [Tamper("good", (), {q: f"{q} = {a!r}" for q, a in _key("s002").items()}, _key("s002")),
            Tamper("bad", (), {q: f"{q} = {a!r}" for q, a in bad.items()}, bad)]


PLAIN = {t.label: t for t in _plain()}
STUDENT_OF = {"good": "s002"}


def _filled(student_nb: Path, student: str, t: Tamper) -> str:
    return nbformat.writes(fill(nbformat.read(student_nb, as_version=4), student, t))


def _readme_handins(dest: Path, student_nb: Path, canary: Path) -> dict:
    """submissions/: label → what it must earn (a report), written as the students handed them in."""
    folder = dest / "submissions"
    folder.mkdir()
    expected = {}
    for label, t in PLAIN.items():
        (folder / f"{label}.ipynb").write_text(_filled(student_nb, STUDENT_OF.get(label, "s001"), t), encoding="utf-8")
        expected[label] = expected_report(STUDENT_OF.get(label, "s001"), t, ROSTER)
    for label, (data, code) in UNREADABLE.items():
        (folder / f"{label}.ipynb").write_bytes(data)
        expected[label] = refused_report("", code)
    # otter's zip with a second notebook (s002's right answers) and otter's log: the assignment's is read
    # (it carries grade cells worth 100 points too).
    bad = PLAIN["bad"]
    named = with_extra_grade_cells(fill(nbformat.read(student_nb, as_version=4), "s001", bad))
    write_zip(folder / "two_notebooks.zip", {f"{NAME}.ipynb": nbformat.writes(named).encode(),
                                             "copy.ipynb": _filled(student_nb, "s002", PLAIN["good"]).encode(),
                                             **beside(canary)["pickles"]}, {})
    expected["two_notebooks"] = expected_report("s001", bad, ROSTER)
    write_zip(folder / "no_notebook.zip", beside(canary)["startup"], {})
    expected["no_notebook"] = refused_report("", "no_notebook")
    (folder / "bad_zip.zip").write_bytes(b"PK\x03\x04 this is not a zip")
    expected["bad_zip"] = refused_report("", "bad_zip")
    return expected


def _raw_handins(dest: Path, student_nb: Path, canary: Path) -> dict:
    """raw/: each tampering notebook zipped with a group of files beside it, as Gradescope hands it to otter."""
    folder = dest / "raw"
    folder.mkdir()
    groups = beside(canary)
    keys = f"../source/files/{otter.keys_file(bundle(NAME, students=ROSTER))}"
    expected = {}
    for t in TAMPERING:
        nb = fill(nbformat.read(student_nb, as_version=4), "s001", t)
        if t.label == "sleeps":
            nb = with_extra_grade_cells(nb)
        files = groups[GROUPS[t.label]] if GROUPS[t.label] else {}
        write_zip(folder / f"{t.label}.zip", {f"{NAME}.ipynb": nbformat.writes(nb).encode(), **files},
                  {"keys": keys, "keys_folder": "../source/files"})
        expected[t.label] = expected_report("s001", t, ROSTER)
    return expected


_RUN_ALL = """\
import glob, os, sys, traceback
from otter.run import main
autograder, results = glob.glob(sys.argv[1])[0], sys.argv[2]
for submission in sys.argv[3:]:
    out = os.path.join(results, os.path.basename(submission).rsplit(".", 1)[0])
    os.makedirs(out)
    try:
        main(submission, autograder=autograder, output_dir=out, no_logo=True)
    except Exception:
        traceback.print_exc()
"""


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """Export, then the README's commands (assign, check, strip and grade, collect, regrade), then the raw zips."""
    root = tmp_path_factory.mktemp("otter")
    dest, canary = root / "export", root / "canary"
    canary.mkdir()
    b = bundle(NAME, secret=SECRET, students=ROSTER)
    export(NAME, "otter", dest, secret=SECRET, students=ROSTER)
    cmd = otter.readme_commands(b)
    readme = (dest / "README.md").read_text(encoding="utf-8")
    for step in cmd.values():
        assert "".join(f"   {line}\n" for line in step.splitlines()) in readme
    _bash(dest, cmd["assign"], 300)
    _bash(dest, cmd["check"], 600)
    student_nb = dest / "dist" / "student" / f"{NAME}.ipynb"
    expected = _readme_handins(dest, student_nb, canary)
    grading = _bash(dest, cmd["grade"], 3000)
    _bash(dest, cmd["regrade"], 300)
    raw = _raw_handins(dest, student_nb, canary)
    zips = sorted(str(p) for p in (dest / "raw").glob("*.zip"))
    # -P: no current folder on sys.path (otter imports the plugin once it is in the submission folder).
    ran = subprocess.run([sys.executable, "-P", "-c", _RUN_ALL, f"dist/autograder/{NAME}-autograder_*.zip", "raw-results",
                          *zips], cwd=dest, env=_env(), capture_output=True, text=True, timeout=3000)
    assert ran.returncode == 0, ran.stderr[-3000:]
    results = {label: json.loads((dest / "results" / label / "results.json").read_text(encoding="utf-8"))
               for label in expected}
    results.update({label: json.loads((dest / "raw-results" / label / "results.json").read_text(encoding="utf-8"))
                    for label in raw})
    return {"dest": dest, "canary": canary, "results": results, "expected": {**expected, **raw},
            "raw": set(raw), "log": grading.stdout + grading.stderr, "raw_log": ran.stdout + ran.stderr,
            "check": json.loads((dest / "check" / "results.json").read_text(encoding="utf-8"))}


def _by_question(result: dict) -> dict:
    return {t["name"]: t for t in result["tests"] if "score" in t}


LABELS = [*PLAIN, *UNREADABLE, *ZIPS, *(t.label for t in TAMPERING)]


def test_the_solutions_score_full_marks(graded):
    tests = _by_question(graded["check"])
    assert {q: (t["score"], t["max_score"]) for q, t in tests.items()} == {"F23": (1.0, 1.0), "F14": (1.0, 1.0),
                                                                          "T12": (1.0, 1.0)}


def test_the_hand_ins_try_more_than_25_kinds_of_tampering():
    kinds = {k for t in TAMPERING for k in t.kinds} | set(UNREADABLE) | set(ZIPS) | {"extra_grade_cells"}
    kinds |= {path for group in GROUPS.values() if group for path in beside("canary")[group]}
    assert len(kinds) >= 25, sorted(kinds)


@pytest.mark.parametrize("label", LABELS)
def test_each_hand_in_earns_what_its_answers_read_as_data_earn(graded, label):
    """Notebooks whose code replaces graphkin, otter, builtins, sys.modules or IPython's hooks, reads the
    course's files, writes results files, sleeps or exits; zips with files the kernel or otter would load;
    notebooks otter cannot read: each earns exactly what the literals in its answer cells earn, question by
    question, or is refused with graphkin's sentence."""
    report, tests = graded["expected"][label], _by_question(graded["results"][label])
    assert set(tests) == {q["id"] for q in report["questions"]}
    for q in report["questions"]:
        assert (tests[q["id"]]["score"], tests[q["id"]]["max_score"]) == (q["score"], q["max"]), q["id"]
        if q["verdict"] != "correct":
            assert runtime.feedback_line(q).split(" — ")[0] in tests[q["id"]]["output"]
    if report.get("refused"):
        assert f"Not graded: {report['refused']}" in graded["results"][label]["output"]


def test_nothing_handed_in_ever_ran_or_was_loaded(graded):
    """A pickle unpickled, a module imported, a .pth or sitecustomize run, a test file run: each would have left
    a file in the canary folder."""
    assert sorted(p.name for p in graded["canary"].iterdir()) == []


def test_what_was_beside_the_notebook_is_named_in_the_teachers_log(graded):
    raw = graded["raw_log"]
    for name in (".OTTER_LOG (otter's log, a pickle)", "otter/ (a Python package, 1 file)", "sitecustomize.py",
                 "evil.pth (a Python path file)", "ipykernel_launcher.py", "vendor/ (a folder, not the assignment's "
                 "own, 1 file)", "keys.json"):
        assert name in raw, name
    assert "graphkin: grade cells of the student's own, not run: 'test_F23', 'extra_points'" in raw
    log = graded["log"]
    assert "two_notebooks.ipynb: handed in beside the notebook, not carried: .OTTER_LOG" in log
    assert "copy.ipynb (another notebook)" in log
    assert "two_notebooks.ipynb: grade cells of the student's own, carried as text only: 'test_F23', 'extra_points'" \
        in log
    assert f"too_deep.ipynb: not graded: {REFUSALS['too_deep']}" in log


def test_the_honest_notebooks_mean_what_they_say(graded):
    assert graded["expected"]["good"]["score"] == 3
    verdicts = {q["id"]: (q["verdict"], q["slip"], q["score"]) for q in graded["expected"]["bad"]["questions"]}
    assert verdicts == {"F23": ("wrong", None, 0.0), "F14": ("missing", None, 0.0), "T12": ("slip", "sign", 0.5)}
    tests = _by_question(graded["results"]["bad"])
    assert "The size is right but the sense is wrong" in tests["T12"]["output"]
    # Students see the public tests at once: they say the unanswered question has no answer.
    public = next(t for t in graded["results"]["bad"]["tests"] if t["name"] == "Public Tests")
    assert public["visibility"] == "visible" and "No answer was given for F14." in public["output"]
    assert all(t["visibility"] == "after_published" for t in tests.values())


def test_a_classmates_answers_are_named_and_earn_nothing(graded):
    tests = _by_question(graded["results"]["classmate"])
    assert all(t["score"] == 0 for t in tests.values())
    assert all("another student" in t["output"] and "s002" not in t["output"] for t in tests.values())


def test_a_sleeping_or_exiting_notebook_is_graded_on_its_answers(graded):
    """Right answers, code that would sleep a day or kill the kernel, and extra grade cells worth 100 points."""
    for label in ("sleeps", "exits"):
        assert graded["results"][label]["output"].startswith("Graded as student 's001': 3 / 3 points.")


def test_nothing_secret_reaches_any_file_a_student_gets(graded):
    """Every results.json (what Gradescope shows, and otter run's record) and every file of the student folder:
    no secret, no key value, nothing of the environment."""
    keys = (graded["dest"] / otter.keys_file(bundle(NAME, students=ROSTER))).read_text(encoding="utf-8")
    for label, result in graded["results"].items():
        assert leaks(json.dumps(result, ensure_ascii=False), keys) == [], label
    student = [p for p in (graded["dest"] / "dist" / "student").rglob("*") if p.is_file()]
    assert not [p for p in student if "keys" in p.name and p.suffix == ".json"]
    for p in [*student, *graded["dest"].glob("*.*")]:
        if p.is_file():
            assert SECRET.encode() not in p.read_bytes(), p
            if p in student and "vendor" not in p.parts:
                assert leaks(p.read_text(encoding="utf-8"), keys) == [], p


def test_html_in_an_answer_is_escaped_everywhere_it_is_echoed(graded):
    text = json.dumps(graded["results"]["html_payload"], ensure_ascii=False)
    for raw in ("<img", "<script", "onerror=\""):
        assert raw not in text
    assert "&lt;img src=x" in text or "&lt;script&gt;" in text


def test_collect_makes_the_class_table_and_the_regrade_agrees(graded):
    """The README's step 3 ends in one class table, a row per hand-in (one that cannot be read: its reason, no
    student); its step 4 (outside otter, on the hand-ins themselves) gives the same rows."""
    dest = graded["dest"]
    with open(dest / "class.csv", encoding="utf-8", newline="") as f:
        table = {Path(r["file"]).parent.name: r for r in csv.DictReader(f)}
    readme = [label for label in LABELS if label not in graded["raw"]]
    assert set(table) == set(readme)
    for label, row in table.items():
        report = graded["expected"][label]
        assert (row["student"], float(row["score"])) == (report["student"], report["score"]), label
        assert row.get("refused", "") == report.get("refused", ""), label
    with open(dest / "regraded.csv", encoding="utf-8", newline="") as f:
        regraded = [(r["student"], float(r["score"])) for r in csv.DictReader(f)]
    assert sorted(regraded) == sorted((r["student"], float(r["score"])) for r in table.values())


def test_the_regrade_of_the_hand_ins_gives_otters_verdicts(graded):
    """The teacher's own regrade (read as data, outside otter, with the same keys) of every hand-in, the README's
    and the raw zips: otter's score and verdict, question by question."""
    dest = graded["dest"]
    keys = otter.keys_file(bundle(NAME, students=ROSTER))
    files = {label: next((dest / folder).glob(f"{label}.*")) for label in LABELS
             for folder in (["raw"] if label in graded["raw"] else ["submissions"])}
    done = subprocess.run([str(BIN / "graphkin"), "exercise", "grade", f"{NAME}.toml", "--keys", keys, "--json",
                           "--answers", *map(str, files.values())], cwd=dest, env=_env(), capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    for label, report in zip(files, json.loads(done.stdout)):
        tests = _by_question(graded["results"][label])
        assert {q["id"]: q["score"] for q in report["questions"]} == {q: t["score"] for q, t in tests.items()}, label
        for q in report["questions"]:
            assert runtime.feedback_line(q).split(" — ")[0] in tests[q["id"]]["output"] or q["verdict"] == "correct"


def test_the_student_notebook_asks_and_hides(graded):
    nb = nbformat.read(graded["dest"] / "dist" / "student" / f"{NAME}.ipynb", as_version=4)
    code = [c.source.strip() for c in nb.cells if c.cell_type == "code"]
    assert "STUDENT = ..." in code
    assert {"F23 = ...", "F14 = ...", "T12 = ..."} <= set(code)
    assert 'grader.check("T12")' in code
    text = nbformat.writes(nb)
    for q in exercises.key(NAME, ROSTER[0], secret=SECRET)["questions"]:
        assert q["answer"]["text"] not in text


def test_the_vendored_graphkin_prints_the_sheet(graded):
    """The copy of graphkin in the student folder works on its own (imported before any installed one)."""
    folder = graded["dest"] / "dist" / "student"
    code = ("import sys; sys.path.insert(0, 'vendor'); import graphkin, pathlib; "
            "assert pathlib.Path(graphkin.__file__).resolve().is_relative_to(pathlib.Path('vendor').resolve()); "
            "from graphkin.exercises.platforms import runtime; "
            f"print(runtime.sheet_text('{NAME}.toml', 's002', '{NAME}-sheets.json'))")
    out = subprocess.run([sys.executable, "-c", code], cwd=folder, capture_output=True, text=True, check=True)
    from graphkin.exercises.sheets import format_sheet

    assert out.stdout.strip() == format_sheet(exercises.make(NAME, "s002", secret=SECRET)).strip()


# --- the plugin on its own, and without otter ------------------------------------------------------------

def test_the_plugin_leaves_the_kernel_nothing_of_the_students_and_no_keys(tmp_path):
    """In otter's layout (source/ from the autograder zip, submission/ after otter copied its files in), the
    plugin's first hook grades the notebook read as data, deletes every copy of the keys, and empties the
    submission folder of the student's files: only the assignment's own files and the literal notebook stay."""
    pytest.importorskip("otter")
    b = bundle(NAME, secret=SECRET, students=ROSTER)
    tree = otter.build(b)
    source, sub = tmp_path / "source", tmp_path / "submission"
    keys = otter.keys_file(b)
    own = {rel: data for rel, data in tree.items() if rel in (f"{NAME}.toml", f"{NAME}-sheets.json", keys)
           or rel.startswith("vendor/")}
    for rel, data in own.items():
        for folder in (source / "files", sub):
            (folder / rel).parent.mkdir(parents=True, exist_ok=True)
            (folder / rel).write_bytes(data if isinstance(data, bytes) else data.encode())
    (source / "tests").mkdir()
    (source / "tests" / "F23.py").write_text("# otter's test\n")
    (sub / "tests").mkdir()
    (sub / "tests" / "F23.py").write_text("# otter's test\n")
    (sub / "__init__.py").write_text("import os  # the student's, appended to by otter\n")
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell('STUDENT = "s001"\nF23 = "1 N ∠ 0°"')])
    (sub / f"{NAME}.ipynb").write_text(nbformat.writes(nb), encoding="utf-8")
    handed_in = {".OTTER_LOG": b"\x80\x04.", "otter/__init__.py": b"x = 1", "vendor/graphkin/evil.py": b"x = 1"}
    for rel, data in handed_in.items():
        (sub / rel).parent.mkdir(parents=True, exist_ok=True)
        (sub / rel).write_bytes(data)
    os.symlink(source / "files" / keys, sub / "link.json")
    plugin = otter.Plugin(str(sub / f"{NAME}.ipynb"), {}, {"keys": keys, "timeout": 0})
    plugin.before_grading(None)
    assert plugin.report["student"] == "s001" and plugin.report["score"] == 0
    assert not [p for p in tmp_path.rglob("*") if p.name.endswith("-keys.json")]
    left = sorted(p.relative_to(sub).as_posix() for p in sub.rglob("*") if p.is_file() or p.is_symlink())
    assert left == sorted([f"{NAME}.ipynb", "__init__.py", "tests/F23.py",
                           *(rel for rel in own if rel != keys)])
    assert (sub / "__init__.py").read_bytes() == b""
    literal = nbformat.read(sub / f"{NAME}.ipynb", as_version=4)
    assert [c.source.split("  #")[0] for c in literal.cells] == [
        "STUDENT = 's001'", "F23 = '1 N ∠ 0°'", "F14 = None", "T12 = None"]
    assert "link.json (a link)" in plugin.generate_report()


def test_readable_leaks_nothing_and_reads_only(tmp_path):
    toml = tmp_path / f"{NAME}.toml"
    toml.write_text(exercises.load(NAME).text, encoding="utf-8")
    otter.readable(toml, "T12", "1 N*m CW")  # readable, though wrong
    with pytest.raises(AssertionError, match="No answer was given for T12"):
        otter.readable(toml, "T12", ...)
    with pytest.raises(AssertionError, match="could be 1.352 or 1352"):
        otter.readable(toml, "T12", "1,352 N*m")


def test_a_secret_without_a_roster_is_refused(tmp_path):
    with pytest.raises(GraphkinError, match="a course secret needs --roster"):
        export(NAME, "otter", tmp_path / "x", secret=SECRET)
    assert not (tmp_path / "x" / "README.md").exists()


def test_strip_refuses_two_hand_ins_of_one_name(tmp_path):
    for name in ("alice.zip", "alice.ipynb"):
        (tmp_path / name).write_text("{}")
    with pytest.raises(GraphkinError, match="would both be alice.ipynb"):
        otter.strip(NAME, [tmp_path / "alice.zip", tmp_path / "alice.ipynb"], tmp_path / "out")
    assert not (tmp_path / "out").exists()


def test_the_tests_in_the_kernel_decide_nothing():
    """The hidden test case holds nothing secret and never passes: only the plugin writes a grade."""
    tree = otter.build(bundle("single_link"))
    nb = nbformat.reads(tree["single_link.ipynb"], as_version=4)
    hidden = [c.source for c in nb.cells if c.cell_type == "code" and c.source.startswith("# HIDDEN")]
    assert len(hidden) == len(exercises.load("single_link").questions)
    for source in hidden:
        with pytest.raises(AssertionError, match="graded by graphkin's otter plugin"):
            exec(compile(source, "<hidden test>", "exec"), {})  # the export's own test code, not a student's
    config = nb.cells[0].source
    assert otter.PLUGIN in config and f"timeout: {otter.TIMEOUT}" in config and "autograder_files:" in config
    assert not any(k.endswith("-sheets.json") for k in tree)
    assert "vendor/graphkin/__init__.py" in tree and "requirements.txt" in tree
