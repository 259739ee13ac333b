"""Every command an export's README prints runs as printed, for a teacher's own exercise and problem files.

The catalog exercise's commands are run by each platform's own test; here a teacher's exercise file
(``mine.toml``, on a problem file of their own, ``my_link.toml``) is exported to every platform with a
roster and a secret, and the README's commands run in bash, in the folder the README says, with the real
tools. The sample student's answers must score full marks.
"""

from __future__ import annotations

import csv
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import graphkin
from graphkin import catalog, exercises
from graphkin.exercises import platforms
from graphkin.exercises.platforms import gradescope, nbgrader, otter, prairielearn

pytestmark = pytest.mark.slow  # runs the real platforms

nbformat = pytest.importorskip("nbformat")

BIN = Path(sys.executable).parent
SECRET = "readme-secret-41b"
ROSTER = ["r001", "r002"]
NAME = "mine"


def _env() -> dict:
    # This graphkin first on sys.path: the platforms import graphkin's plugin and preprocessors from it.
    return {**os.environ, "PATH": f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}", "GRAPHKIN_SECRET": SECRET,
            "PYTHONPATH": str(Path(graphkin.__file__).resolve().parents[1])}


def _run(folder: Path, commands: str, timeout: float = 600) -> subprocess.CompletedProcess:
    done = subprocess.run(["bash", "-euo", "pipefail", "-c", commands], cwd=folder, env=_env(), capture_output=True,
                          text=True, timeout=timeout)
    assert done.returncode == 0, commands + "\n" + done.stdout[-3000:] + done.stderr[-3000:]
    return done


def _printed(readme: Path, commands: str) -> None:
    """The commands are in the README exactly (indented in a fenced block, or as they are)."""
    text = readme.read_text(encoding="utf-8")
    indented = "".join(f"   {line}\n" for line in commands.splitlines())
    assert commands in text or indented in text, commands


@pytest.fixture(scope="module")
def teacher(tmp_path_factory) -> Path:
    """A teacher's folder: their exercise file on their own problem file, and a roster."""
    folder = tmp_path_factory.mktemp("teacher")
    (folder / "my_link.toml").write_text(catalog.path("single_link").read_text(encoding="utf-8"), encoding="utf-8")
    text = exercises.path("single_link").read_text(encoding="utf-8").replace('problem = "single_link"',
                                                                            'problem = "my_link.toml"')
    assert "my_link.toml" in text
    (folder / f"{NAME}.toml").write_text(text, encoding="utf-8")
    (folder / "roster.csv").write_text("student\n" + "\n".join(ROSTER) + "\n", encoding="utf-8")
    return folder


def _export(teacher: Path, to: str) -> tuple[Path, object]:
    dest = teacher / to
    platforms.export(teacher / f"{NAME}.toml", to, dest, secret=SECRET, students=ROSTER)
    return dest, platforms.bundle(teacher / f"{NAME}.toml", secret=SECRET, students=ROSTER)


def test_gradescope_readme(teacher):
    dest, b = _export(teacher, "gradescope")
    shutil.copy(teacher / "roster.csv", dest / "roster.csv")
    cmd = gradescope.readme_commands(b)
    for step in cmd.values():
        _printed(dest / "README.md", step)
    _run(dest, cmd["make"])
    assert [r["student"] for r in csv.DictReader((dest / "sheets.csv").open(encoding="utf-8"))] == ROSTER
    _run(dest, cmd["try"])
    results = json.loads((dest / "try" / "results" / "results.json").read_text(encoding="utf-8"))
    assert results["score"] == sum(q.points for q in b.exercise.questions)


def test_prairielearn_readme(teacher):
    dest, b = _export(teacher, "prairielearn")
    cmd = prairielearn.readme_commands(b)
    for step in cmd.values():
        _printed(dest / "README.md", step)
    assert _run(dest, cmd["check"]).stdout.splitlines()[-1] == "score 1"
    key = _run(dest, cmd["key"]).stdout
    assert "r001" not in key and "pl-1" in key


@pytest.mark.skipif(not (BIN / "otter").exists(), reason="otter-grader is not installed in this venv")
def test_otter_readme(teacher):
    dest, b = _export(teacher, "otter")
    cmd = otter.readme_commands(b)
    for step in cmd.values():
        _printed(dest / "README.md", step)
    _run(dest, cmd["assign"])
    _run(dest, cmd["check"])
    check = json.loads((dest / "check" / "results.json").read_text(encoding="utf-8"))
    assert all(t["score"] == t["max_score"] for t in check["tests"] if "score" in t)
    (dest / "submissions").mkdir()
    shutil.copy(dest / "dist" / "autograder" / f"{NAME}.ipynb", dest / "submissions" / "sample.ipynb")
    _run(dest, cmd["grade"])
    (row,) = csv.DictReader((dest / "class.csv").open(encoding="utf-8"))
    assert (row["student"], float(row["score"])) == (ROSTER[0], float(row["max"]))
    _run(dest, cmd["regrade"])
    (again,) = csv.DictReader((dest / "regraded.csv").open(encoding="utf-8"))
    assert (again["student"], float(again["score"])) == (ROSTER[0], float(row["max"]))


def test_nbgrader_readme(teacher):
    pytest.importorskip("nbgrader")
    export, b = _export(teacher, "nbgrader")
    course = teacher / "course"
    course.mkdir()
    shutil.copytree(export, course / "export")
    (course / "nbgrader_config.py").write_text(
        'c = get_config()\nc.CourseDirectory.course_id = "mine"\n'
        f'c.CourseDirectory.db_url = "sqlite:///{(course / "gradebook.db").as_posix()}"\n'
        + "\n".join(nbgrader.config_lines()) + "\n", encoding="utf-8")
    cmd = nbgrader.readme_commands(b)
    for step in cmd.values():
        _printed(export / "README.md", step)
    _run(course, cmd["setup"])
    _run(course, cmd["generate"])
    # The sample student hands in the source notebook's solutions (their own answers).
    folder = course / "submitted" / ROSTER[0] / NAME
    shutil.copytree(course / "release" / NAME, folder)
    nb = nbformat.read(course / "source" / NAME / f"{NAME}.ipynb", as_version=4)
    for cell in nb.cells:
        if "### BEGIN SOLUTION" in cell.source:
            cell.source = cell.source.split("### BEGIN SOLUTION\n")[1].split("\n### END SOLUTION")[0]
    nbformat.write(nb, folder / f"{NAME}.ipynb")
    _run(course, cmd["autograde"])
    _run(course, cmd["feedback"])
    _run(course, cmd["regrade"])
    (row,) = csv.DictReader((course / "grades.csv").open(encoding="utf-8"))
    total = sum(q.points for q in b.exercise.questions)
    assert float(row["score"]) == total
    (again,) = csv.DictReader((course / "regraded.csv").open(encoding="utf-8"))
    assert (again["student"], float(again["score"])) == (ROSTER[0], total)
