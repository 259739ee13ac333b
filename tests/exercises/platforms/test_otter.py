"""The otter-grader export, with the real tool: ``otter assign``, then the README's commands on handed-in notebooks.

The README's steps run as printed (bash, in the export folder): ``otter assign``, the check of the
solutions, ``otter run`` on every notebook of ``submissions/`` and ``graphkin exercise collect``, and the
regrade outside otter. The notebooks: a right one (s002's key), one with slips (s001), and the catalogue
of tampering notebooks (:mod:`tests.exercises.platforms.tampering`), each handed in as s001. The grading
machine's environment holds the course secret and a marker: neither may reach what a student sees.
"""

from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from graphkin import exercises
from graphkin.errors import GraphkinError
from graphkin.exercises.platforms import bundle, export, otter, runtime
from tests.exercises.platforms.tampering import MARKER, NAME, SECRET, Tamper, catalogue, expected_report, fill, leaks

nbformat = pytest.importorskip("nbformat")

ROSTER = ["s001", "s002"]
BIN = Path(sys.executable).parent
TAMPERING = catalogue("s001", "s002")
pytestmark = [pytest.mark.slow,  # runs the real platform
              pytest.mark.skipif(not (BIN / "otter").exists(), reason="otter-grader is not installed in this venv")]


def _env() -> dict:
    # The teacher's shell: the venv first on PATH, the course secret and a marker in the environment.
    return {**os.environ, "PATH": f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}", "GRAPHKIN_SECRET": SECRET,
            "GRAPHKIN_MARKER": MARKER}


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


STUDENT_OF = {"good": "s002"}


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """Export, then the README's commands: assign, check, grade every notebook, collect, regrade."""
    root = tmp_path_factory.mktemp("otter")
    dest = root / "export"
    b = bundle(NAME, secret=SECRET, students=ROSTER)
    export(NAME, "otter", dest, secret=SECRET, students=ROSTER)
    cmd = otter.readme_commands(b)
    readme = (dest / "README.md").read_text(encoding="utf-8")
    for step in cmd.values():
        assert "".join(f"   {line}\n" for line in step.splitlines()) in readme
    _bash(dest, cmd["assign"], 300)
    _bash(dest, cmd["check"], 600)
    student_nb = dest / "dist" / "student" / f"{NAME}.ipynb"
    (dest / "submissions").mkdir()
    handed_in = {}
    for t in [*_plain(), *TAMPERING]:
        nb = fill(nbformat.read(student_nb, as_version=4), STUDENT_OF.get(t.label, "s001"), t)
        nbformat.write(nb, dest / "submissions" / f"{t.label}.ipynb")
        handed_in[t.label] = t
    grading = _bash(dest, cmd["grade"], 3000)
    _bash(dest, cmd["regrade"], 300)
    results = {label: json.loads((dest / "results" / label / "results.json").read_text(encoding="utf-8"))
               for label in handed_in}
    return {"dest": dest, "results": results, "handed_in": handed_in, "log": grading.stdout + grading.stderr,
            "check": json.loads((dest / "check" / "results.json").read_text(encoding="utf-8"))}


def _by_question(result: dict) -> dict:
    return {t["name"]: t for t in result["tests"] if "score" in t}


def _report(graded, label: str) -> dict:
    return expected_report(STUDENT_OF.get(label, "s001"), graded["handed_in"][label], ROSTER)


def test_the_solutions_score_full_marks(graded):
    tests = _by_question(graded["check"])
    assert {q: (t["score"], t["max_score"]) for q, t in tests.items()} == {"F23": (1.0, 1.0), "F14": (1.0, 1.0),
                                                                          "T12": (1.0, 1.0)}


@pytest.mark.parametrize("label", ["good", "bad", *(t.label for t in TAMPERING)])
def test_each_notebook_earns_what_its_answers_read_as_data_earn(graded, label):
    """The tampering notebooks replace graphkin, otter, builtins, sys.modules or IPython's hooks, read the
    course's files and environment, write results files, sleep, exit, or hand in a classmate's answers:
    each earns exactly what the literals in its answer cells earn, question by question."""
    report, tests = _report(graded, label), _by_question(graded["results"][label])
    assert set(tests) == {q["id"] for q in report["questions"]}
    for q in report["questions"]:
        assert (tests[q["id"]]["score"], tests[q["id"]]["max_score"]) == (q["score"], q["max"]), q["id"]
        if q["verdict"] != "correct":
            assert runtime.feedback_line(q).split(" — ")[0] in tests[q["id"]]["output"]


def test_the_honest_notebooks_mean_what_they_say(graded):
    assert _report(graded, "good")["score"] == 3
    verdicts = {q["id"]: (q["verdict"], q["slip"], q["score"]) for q in _report(graded, "bad")["questions"]}
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
    for label in ("sleeps", "exits"):
        assert graded["results"][label]["output"].startswith("Graded as student 's001': 3 / 3 points.")


def test_nothing_secret_reaches_what_students_see(graded):
    """results.json (what Gradescope shows, and otter run's record) holds no secret, key or environment value."""
    keys = (graded["dest"] / otter.keys_file(bundle(NAME, students=ROSTER))).read_text(encoding="utf-8")
    for label, result in graded["results"].items():
        assert leaks(json.dumps(result, ensure_ascii=False), keys) == [], label
    # The student's folder carries no key and no secret; the export holds the secret nowhere.
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
    """The README's step 3 ends in one class table; its step 4 (outside otter) gives the same scores."""
    dest = graded["dest"]
    with open(dest / "class.csv", encoding="utf-8", newline="") as f:
        table = {Path(r["file"]).parent.name: r for r in csv.DictReader(f)}
    assert set(table) == set(graded["handed_in"])
    for label, row in table.items():
        assert row["student"] == STUDENT_OF.get(label, "s001")
        assert float(row["score"]) == _report(graded, label)["score"], label
    with open(dest / "regraded.csv", encoding="utf-8", newline="") as f:
        regraded = [(r["student"], float(r["score"])) for r in csv.DictReader(f)]
    assert sorted(regraded) == sorted((r["student"], float(r["score"])) for r in table.values())


def test_the_regrade_of_the_handed_in_notebooks_is_otters_grade(graded):
    """The teacher's own regrade (read as data, outside otter, with the same keys) gives otter's scores."""
    dest = graded["dest"]
    keys = otter.keys_file(bundle(NAME, students=ROSTER))
    labels = sorted(graded["handed_in"])
    done = subprocess.run([str(BIN / "graphkin"), "exercise", "grade", f"{NAME}.toml", "--keys", keys, "--json",
                           "--answers", *(f"submissions/{label}.ipynb" for label in labels)], cwd=dest, env=_env(),
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    for label, report in zip(labels, json.loads(done.stdout)):
        tests = _by_question(graded["results"][label])
        assert {q["id"]: q["score"] for q in report["questions"]} == {q: t["score"] for q, t in tests.items()}, label


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


# --- without otter --------------------------------------------------------------------------------------

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
