"""The Gradescope export: the autograder zip, run as Gradescope runs it.

Each test lays out a folder as Gradescope lays out ``/autograder`` (``source/``
unpacked from the zip, ``submission/``, ``submission_metadata.json``,
``results/``) and runs ``bash run_autograder`` in a subprocess, with
``GRAPHKIN_AUTOGRADER_ROOT`` pointing at it. The scores are compared with
``exercises.grade`` for the same student, answers and secret.
"""

from __future__ import annotations

import json
import os
import shutil
import stat
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

from graphkin import exercises
from graphkin.exercises import platforms
from graphkin.exercises.platforms import gradescope, runtime

pytestmark = pytest.mark.slow  # runs the real platform

NAME = "strip_cutter_cut"
SECRET = "gs-course-secret-2025"
ROSTER = ["s001", "s002", "s003"]
VISIBILITY = {"hidden", "after_due_date", "after_published", "visible"}
MARKER = "gs-env-marker-77a1"


@pytest.fixture(scope="module")
def export(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("gradescope") / "export"
    platforms.export(NAME, "gradescope", out, secret=SECRET, students=ROSTER)
    return out


def key_answers(student: str) -> dict:
    return {q["id"]: q["answer"]["text"] for q in exercises.key(NAME, student, secret=SECRET)["questions"]}


def toml(answers: dict, student: str | None = None) -> str:
    lines = [f"student = {json.dumps(student, ensure_ascii=False)}"] if student else []
    lines += [f"{k} = {json.dumps(v, ensure_ascii=False)}" for k, v in answers.items()]
    return "\n".join(lines) + "\n"


def user(sid, email="", name="A Student", uid=7):
    return {"email": email, "id": uid, "name": name, "sid": sid}


def unpack(zip_path: Path, dest: Path) -> None:
    """Unzip as unzip does: the files, with the Unix permissions the zip records."""
    with zipfile.ZipFile(zip_path) as zf:
        for info in zf.infolist():
            target = dest / info.filename
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(zf.read(info))
            mode = (info.external_attr >> 16) & 0o777
            if mode:
                os.chmod(target, mode)


def run_autograder(export: Path, tmp_path: Path, files: dict, users: list[dict], python=None):
    """Lay out tmp_path/autograder as Gradescope does, run run_autograder, return (results, stdout, root)."""
    root = tmp_path / "autograder"
    unpack(export / "autograder.zip", root / "source")
    (root / "results").mkdir(parents=True)
    for rel, text in files.items():
        p = root / "submission" / rel
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_bytes(text if isinstance(text, bytes) else text.encode("utf-8"))
    (root / "submission").mkdir(exist_ok=True)
    meta = {"id": 99, "created_at": "2025-03-01T10:00:00.000000-08:00", "assignment": {"id": 5, "title": "HW"},
            "submission_method": "upload", "users": users, "previous_submissions": []}
    (root / "submission_metadata.json").write_text(json.dumps(meta), encoding="utf-8")
    # The grading machine's environment holds the secret and a marker: neither may come back.
    env = dict(os.environ, GRAPHKIN_AUTOGRADER_ROOT=str(root), GRAPHKIN_PYTHON=python or sys.executable,
               GRAPHKIN_SECRET=SECRET, GRAPHKIN_MARKER=MARKER)
    proc = subprocess.run(["bash", str(root / "source" / "run_autograder")], cwd=root, env=env,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    results = json.loads((root / "results" / "results.json").read_text(encoding="utf-8"))
    check_schema(results)
    shown = json.dumps(results, ensure_ascii=False)
    assert SECRET not in shown and MARKER not in shown and MARKER not in proc.stdout
    return results, proc.stdout, root


def check_schema(results: dict) -> None:
    """The fields of Gradescope's results.json specification, with their types."""
    allowed = {"score", "execution_time", "output", "visibility", "stdout_visibility", "extra_data", "tests",
               "leaderboard", "output_format"}
    assert set(results) <= allowed
    assert isinstance(results["score"], (int, float))
    assert isinstance(results["output"], str) and results["output"]
    assert results["visibility"] in VISIBILITY and results["stdout_visibility"] in VISIBILITY
    for t in results["tests"]:
        assert set(t) <= {"score", "max_score", "status", "name", "name_format", "number", "output",
                          "output_format", "tags", "visibility", "extra_data"}
        assert isinstance(t["name"], str) and isinstance(t["output"], str)
        assert isinstance(t["score"], (int, float)) and isinstance(t["max_score"], (int, float))
        assert 0 <= t["score"] <= t["max_score"]
        assert t["visibility"] in VISIBILITY and t["status"] in {"passed", "failed"}


def by_id(results: dict) -> dict:
    return {t["name"].split(":")[0]: t for t in results["tests"]}


def assert_matches_report(results: dict, report: dict) -> None:
    assert results["score"] == report["score"]
    tests = by_id(results)
    assert list(tests) == [q["id"] for q in report["questions"]]
    for q in report["questions"]:
        t = tests[q["id"]]
        assert (t["score"], t["max_score"]) == (q["score"], q["max"])
        assert t["output"] == runtime.feedback_line(q)
        assert q["feedback"] in t["output"]


# ---------------------------------------------------------------------------------------------------
# The exported files
# ---------------------------------------------------------------------------------------------------

def test_export_files_and_zip_layout(export):
    files = sorted(p.relative_to(export).as_posix() for p in export.rglob("*") if p.is_file())
    # The exercise file sits beside the README too: its regrade command names it.
    assert files == ["README.md", "autograder.zip", "sample_submission/answers.toml",
                     "sample_submission/submission_metadata.json", f"{NAME}.toml", "student_template/answers.toml"]
    with zipfile.ZipFile(export / "autograder.zip") as zf:
        names = zf.namelist()
        infos = {i.filename: i for i in zf.infolist()}
        # Gradescope finds setup.sh and run_autograder at the root of the zip, not in a folder.
        for name in ("setup.sh", "run_autograder", "grade.py", "requirements.txt", "config.json", f"{NAME}.toml",
                     "vendor/graphkin/__init__.py", "vendor/graphkin/exercises/platforms/runtime.py"):
            assert name in names
        for script in ("setup.sh", "run_autograder"):
            assert (infos[script].external_attr >> 16) & 0o111 == 0o111
        assert (infos["grade.py"].external_attr >> 16) & 0o777 == 0o644
        assert names == sorted(names)
        assert {i.date_time for i in zf.infolist()} == {(1980, 1, 1, 0, 0, 0)}
        setup = zf.read("setup.sh").decode()
        assert zf.read("requirements.txt").decode().split() == platforms.requirements()
        config = json.loads(zf.read("config.json"))
        members = {n: zf.read(n) for n in names}
    assert "pip install -r" in setup and "requirements.txt" in setup
    # graphkin's bytecode is compiled into the image once, not by every submission's Python.
    assert '-m compileall -q "$ROOT/source/vendor"' in setup
    assert config["roster"] == ROSTER and config["exercise_file"] == f"{NAME}.toml" and "secret" not in config
    # The autograder grades with the roster's precomputed keys: the secret is in no file of the zip.
    assert gradescope.KEYS in members
    assert [n for n, data in members.items() if SECRET.encode() in data] == []


def test_the_zip_is_the_same_bytes_every_time(export):
    again = gradescope.build(platforms.bundle(NAME, secret=SECRET, students=ROSTER))
    assert again["autograder.zip"] == (export / "autograder.zip").read_bytes()


def test_scripts_are_valid_bash(export, tmp_path):
    unpack(export / "autograder.zip", tmp_path)
    for script in ("setup.sh", "run_autograder"):
        assert os.stat(tmp_path / script).st_mode & stat.S_IXUSR
        subprocess.run(["bash", "-n", str(tmp_path / script)], check=True)


def test_the_secret_stays_in_the_zip(export):
    for rel in ("README.md", "student_template/answers.toml", "sample_submission/answers.toml",
                "sample_submission/submission_metadata.json"):
        assert SECRET not in (export / rel).read_text(encoding="utf-8"), rel


def test_student_template_and_sample_are_toml_of_the_questions(export):
    import tomllib

    ids = [q["id"] for q in exercises.make(NAME, "s001", secret=SECRET)["questions"]]
    blank = tomllib.loads((export / "student_template/answers.toml").read_text(encoding="utf-8"))
    assert blank == {"student": "", **{i: "" for i in ids}}
    sample = tomllib.loads((export / "sample_submission/answers.toml").read_text(encoding="utf-8"))
    assert sample == {"student": "s001", **key_answers("s001")}
    assert "Do not give this file to students" in (export / "sample_submission/answers.toml").read_text()


# ---------------------------------------------------------------------------------------------------
# run_autograder, as Gradescope runs it
# ---------------------------------------------------------------------------------------------------

def test_readme_commands_grade_the_sample_in_full(export, tmp_path):
    """The commands the README prints, run as they are, give full marks to the sample submission."""
    folder = tmp_path / "export"
    shutil.copytree(export, folder)
    commands = gradescope.local_try_commands()
    assert commands in (folder / "README.md").read_text(encoding="utf-8")
    guide = Path(__file__).resolve().parents[3] / "docs" / "platforms" / "gradescope.md"
    assert commands in guide.read_text(encoding="utf-8")
    env = dict(os.environ, PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}")
    proc = subprocess.run(["bash", "-ec", commands], cwd=folder, env=env, capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 0, proc.stderr
    results = json.loads((folder / "try/results/results.json").read_text(encoding="utf-8"))
    check_schema(results)
    assert results["score"] == 3.0 and [t["score"] for t in results["tests"]] == [1.0, 1.0, 1.0]
    assert "Graded as student 's001': 3 / 3 points." in results["output"]


def test_correct_submission_scores_full_marks_from_the_vendored_graphkin(export, tmp_path):
    answers = key_answers("s002")
    results, stdout, root = run_autograder(export, tmp_path, {"answers.toml": toml(answers, "s002")},
                                           [user("s002", "b@uni.edu")])
    assert_matches_report(results, exercises.grade(NAME, "s002", answers, secret=SECRET))
    assert results["score"] == 3.0
    assert all(t["status"] == "passed" for t in results["tests"])
    shown = [d["shown"] for d in exercises.make(NAME, "s002", secret=SECRET)["data"]]
    assert "Graded as student 's002': 3 / 3 points." in results["output"]
    assert "Your data: " + ", ".join(shown) + "." in results["output"]
    # The grade came from the graphkin inside the zip, not the one installed on this machine.
    assert f"from {root / 'source' / 'vendor' / 'graphkin'}" in stdout


def test_partial_credit_is_graphkins_score_and_feedback(export, tmp_path):
    answers = key_answers("s002")
    torque = answers["T12"]
    answers["T12"] = torque.replace("CCW", "CW") if torque.endswith("CCW") else torque.replace("CW", "CCW")
    del answers["F23"]
    results, _, _ = run_autograder(export, tmp_path, {"answers.toml": toml(answers)}, [user("s002")])
    report = exercises.grade(NAME, "s002", answers, secret=SECRET)
    assert_matches_report(results, report)
    assert results["score"] == 1.5
    tests = by_id(results)
    assert (tests["T12"]["score"], tests["T12"]["status"]) == (0.5, "failed")
    assert "T12: slip (sign), 0.5 / 1 — The size is right but the sense is wrong" in tests["T12"]["output"]
    assert tests["F23"]["output"] == "F23: missing, 0 / 1 — No answer was given for F23."
    # The score and each question's verdict and slip, for the teacher's statistics (Gradescope keeps extra_data
    # unshown); the rest of the report stays out (tests/exercises/test_trust_more.py).
    assert results["extra_data"]["graphkin"] == json.loads(json.dumps(gradescope.statistics(report)))


def test_json_answers_anywhere_in_the_submission(export, tmp_path):
    answers = key_answers("s003")
    results, _, _ = run_autograder(export, tmp_path, {"work/answers.json": json.dumps(answers)},
                                   [user("s003")])
    assert results["score"] == 3.0


def test_malformed_toml_scores_zero_with_a_sentence(export, tmp_path):
    results, stdout, _ = run_autograder(export, tmp_path, {"answers.toml": 'F23 = 27.06 N\nT12 = "1 N*m"\n'},
                                        [user("s002")])
    assert results["score"] == 0.0
    assert [t["score"] for t in results["tests"]] == [0.0, 0.0, 0.0]
    assert [t["max_score"] for t in results["tests"]] == [1.0, 1.0, 1.0]
    out = results["output"]
    assert "Not graded: answers.toml is not valid TOML (" in out and "at line 1" in out
    assert 'for example F23 = "27.06 N ∠ −73.78°"' in out
    assert "Traceback" not in out and "Traceback" not in stdout


def test_not_utf8_and_two_files_and_no_file(export, tmp_path):
    results, _, _ = run_autograder(export, tmp_path / "a", {"answers.toml": "F23 = \"é\"".encode("latin-1")},
                                   [user("s002")])
    assert results["score"] == 0.0 and "answers.toml is not text in UTF-8" in results["output"]
    results, _, _ = run_autograder(export, tmp_path / "b", {"answers.toml": "", "old/answers.json": "{}"},
                                   [user("s002")])
    assert results["score"] == 0.0
    assert "Your submission has 2 answers files (answers.toml, old/answers.json): upload only one" \
        in results["output"]
    results, _, _ = run_autograder(export, tmp_path / "c", {"answers.txt": "F23 = 1"}, [user("s002")])
    assert results["score"] == 0.0
    assert "No answers file was found in your submission (you uploaded: answers.txt)" in results["output"]


def test_another_students_answers_score_zero(export, tmp_path):
    # s002 hands in s003's file (s003's id and s003's correct answers).
    results, _, _ = run_autograder(export, tmp_path, {"answers.toml": toml(key_answers("s003"), "s003")},
                                   [user("s002")])
    assert results["score"] == 0.0
    sentence = runtime.identity_error("s003", "s002")
    assert sentence and sentence[1:] in results["output"]


def test_an_account_off_the_roster_is_told_so(export, tmp_path):
    results, _, _ = run_autograder(export, tmp_path, {"answers.toml": toml(key_answers("s001"))},
                                   [user("", "someone@uni.edu")])
    assert results["score"] == 0.0
    assert "Your Gradescope account (someone@uni.edu) is not on this exercise's roster" in results["output"]


def test_group_submission_is_graded_on_the_member_the_file_names(export, tmp_path):
    users = [user("s002", name="Ada", uid=1), user("s003", name="Bo", uid=2)]
    results, _, _ = run_autograder(export, tmp_path, {"answers.toml": toml(key_answers("s003"), "s003")}, users)
    assert results["score"] == 3.0
    assert "Group submission (Ada, Bo): graded on the data of Bo (student 's003')" in results["output"]


def test_a_broken_graphkin_or_python_still_leaves_a_results_file(export, tmp_path):
    # grade.py cannot import the vendored graphkin: it writes the result itself.
    root = tmp_path / "broken"
    run_autograder(export, root, {"answers.toml": toml(key_answers("s002"))}, [user("s002")])
    init = root / "autograder/source/vendor/graphkin/__init__.py"
    init.write_text("raise ImportError('numpy is missing')\n")
    env = dict(os.environ, GRAPHKIN_AUTOGRADER_ROOT=str(root / "autograder"), GRAPHKIN_PYTHON=sys.executable)
    proc = subprocess.run(["bash", str(root / "autograder/source/run_autograder")], env=env, check=True,
                          capture_output=True, text=True, timeout=60)
    assert "graphkin could not be imported: ImportError: numpy is missing" in proc.stdout
    results = json.loads((root / "autograder/results/results.json").read_text())
    check_schema(results)
    assert results["score"] == 0.0 and results["output"].startswith("The autograder could not start")
    # No Python at all: run_autograder writes it.
    results, _, _ = run_autograder(export, tmp_path / "nopython", {"answers.toml": ""}, [user("s002")],
                                   python="/bin/false")
    assert results["score"] == 0.0 and results["output"].startswith("The autograder could not start")


# ---------------------------------------------------------------------------------------------------
# Whom a submission is graded as (no roster: sid, else email)
# ---------------------------------------------------------------------------------------------------

def test_whom_to_grade_without_a_roster():
    assert gradescope.whom_to_grade([user("123", "a@b.edu")], None, None) == ("123", [])
    assert gradescope.whom_to_grade([user("", "a@b.edu")], None, None) == ("a@b.edu", [])
    assert gradescope.whom_to_grade([user(None, "a@b.edu")], None, None) == ("a@b.edu", [])
    # A file naming the submitter's email is graded as that email (it is theirs).
    assert gradescope.whom_to_grade([user("123", "a@b.edu")], "a@b.edu", None) == ("a@b.edu", [])
    with pytest.raises(gradescope.SubmissionError, match="neither a student id nor an email"):
        gradescope.whom_to_grade([user("", "")], None, None)


def test_an_interrupted_export_says_how_far_it_got(tmp_path, monkeypatch, capsys):
    """Issue 12: a batch of files says which it wrote; Ctrl-C part-way leaves whole files only."""
    import graphkin.exercises.platforms as p
    from graphkin.cli import main

    real, calls = p.write_bytes, []

    def write_then_stop(*args, **kwargs):
        if calls:
            raise KeyboardInterrupt
        calls.append(args[0])
        return real(*args, **kwargs)

    monkeypatch.setattr(p, "write_bytes", write_then_stop)
    code = main(["exercise", "export", NAME, "--to", "gradescope", "-o", str(tmp_path / "gs")])
    assert code == 130
    files = [f for f in (tmp_path / "gs").rglob("*") if f.is_file()]
    assert files == [calls[0]] and not [f for f in files if f.name.endswith(".tmp")]
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"graphkin: interrupted: 1 of 6 files of the export were written to {tmp_path / 'gs'}; "
                   "run the export again"]


def test_hostile_answers_void_nothing_else_and_leak_nothing(export, tmp_path):
    """A 5000-digit number, a 1 MB answer and an HTML payload are each their own question's unreadable
    answer; the right answer beside them scores; nothing of the secret or the keys comes back."""
    right = key_answers("s002")
    text = ("F23 = 1" + "0" * 5000 + "\n" + f"F14 = {json.dumps('<img src=x onerror=alert(1)> ' + 'z' * 1_000_000)}\n"
            f"T12 = {json.dumps(right['T12'])}\n")
    results, _, root = run_autograder(export, tmp_path, {"answers.toml": text}, [user("s002")])
    tests = by_id(results)
    assert (tests["T12"]["score"], results["score"]) == (1.0, 1.0)
    assert tests["F23"]["score"] == tests["F14"]["score"] == 0.0
    assert "too long (5001 characters" in tests["F23"]["output"] and "too long" in tests["F14"]["output"]
    shown = json.dumps(results, ensure_ascii=False)
    assert len(shown) < 20_000
    # What students see (extra_data is the teacher's, never shown) is marked as plain text, which Gradescope
    # shows as it is, never as HTML: a tag in an answer is quoted as text (escaping it too would show "&lt;").
    html = {"F23": "<img src=x onerror=alert(1)> N", "F14": "<script>alert('x')</script>", "T12": right["T12"]}
    results, _, _ = run_autograder(export, tmp_path / "html", {"answers.toml": toml(html)}, [user("s002")])
    assert results["output_format"] == "text" and {t["output_format"] for t in results["tests"]} == {"text"}
    assert 'Could not read "<img src=x onerror=alert(1)> N"' in by_id(results)["F23"]["output"]
    keys = json.loads((root / "source" / gradescope.KEYS).read_text(encoding="utf-8"))
    for student, entry in keys["students"].items():
        for q in entry["questions"].values():
            for v in q["value"] if isinstance(q["value"], list) else [q["value"]]:
                assert not (isinstance(v, float) and abs(v) > 1 and repr(v) in shown), student


# Answers that name what sits on the grading machine: its environment, its files, format fields. The grader
# reads every answer as data, so none is expanded, opened or formatted (issue 23, item 2).
PROBES = ["$GRAPHKIN_SECRET", "${GRAPHKIN_MARKER}", "%GRAPHKIN_SECRET%",
          "$(cat {source}/keys.json)", "`cat {source}/config.json`", "@{source}/keys.json",
          "file://{source}/keys.json", "{source}/keys.json", "../source/config.json",
          "{{secret}}", "{0.__class__.__mro__}", "%(secret)s"]


def test_answers_naming_the_environment_or_the_grading_folder_bring_nothing_back(export, tmp_path):
    right = key_answers("s002")
    ids = list(right)
    source = "/autograder/source"
    probes = [p.replace("{source}", source) for p in PROBES]
    for k in range(0, len(probes), len(ids)):
        answers = dict(zip(ids, probes[k:k + len(ids)]))
        results, stdout, root = run_autograder(export, tmp_path / str(k), {"answers.toml": toml(answers)},
                                               [user("s002")])  # asserts the secret and the marker stay out
        shown = json.dumps(results, ensure_ascii=False) + stdout
        # Nothing of the grading folder's data beyond the student's own sheet: no text of keys.json or
        # config.json (the exercise's file, every student's entry), no classmate's id, no key's value.
        sheet = json.dumps(exercises.make(NAME, "s002", secret=SECRET), ensure_ascii=False)
        for name in (gradescope.KEYS, gradescope.CONFIG):
            for line in _texts(json.loads((root / "source" / name).read_text(encoding="utf-8"))):
                if len(line) >= 12 and line not in sheet and not any(line in p for p in probes):
                    assert line not in shown, (name, line)
        keys = json.loads((root / "source" / gradescope.KEYS).read_text(encoding="utf-8"))
        for student, entry in keys["students"].items():
            assert student == "s002" or student not in shown
            for q in entry["questions"].values():
                for v in q["value"] if isinstance(q["value"], list) else [q["value"]]:
                    assert not (isinstance(v, float) and repr(v) in shown), (student, v)
        # Every probe is an unreadable answer of its own question, quoted as typed, and scores 0.
        tests = by_id(results)
        for qid, text in answers.items():
            assert tests[qid]["score"] == 0.0 and "Could not read" in tests[qid]["output"], (qid, text)


def _texts(data) -> list[str]:
    """Every line of every string in a JSON document (its keys too)."""
    if isinstance(data, dict):
        return [t for k, v in data.items() for t in _texts(k) + _texts(v)]
    if isinstance(data, list):
        return [t for v in data for t in _texts(v)]
    return [line.strip() for line in data.splitlines()] if isinstance(data, str) else []
