"""graphkin as users install it: the wheel with no extras in a fresh environment runs the core commands, and what
needs an extra says which in one line; the sdist and the wheel carry the licence and no tests, the wheel the lesson
notebooks; the README's links work on the package index (absolute)."""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tarfile
import tomllib
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

NOT_IN_THE_CORE = ("jupyterlab", "ipywidgets", "voila", "nbformat", "anywidget", "ipykernel")
"""Packages the extras bring, which a core install must not have."""


@pytest.fixture(scope="module")
def dist(tmp_path_factory):
    out = tmp_path_factory.mktemp("dist")
    r = subprocess.run([sys.executable, "-m", "build", "--sdist", "--wheel", "--outdir", str(out), str(ROOT)],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stdout[-2000:] + r.stderr[-2000:]
    (wheel,) = out.glob("graphkin-*.whl")
    (sdist,) = out.glob("graphkin-*.tar.gz")
    return wheel, sdist


@pytest.fixture(scope="module")
def core(dist, tmp_path_factory):
    """A fresh virtual environment with the wheel installed and no extra.

    This interpreter's pip installs into it (``--python``), so the environment needs no pip of its own (seeding
    one costs seconds); ``--no-compile`` leaves the bytecode to the imports the commands below make, rather than
    compiling every module of numpy and matplotlib up front: a third of the fixture's time otherwise.
    """
    venv = tmp_path_factory.mktemp("venv")
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], check=True, timeout=300)
    # (without PYTHONPATH: a checkout on it would look like graphkin installed already, and be skipped)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    pip = subprocess.run([sys.executable, "-m", "pip", "--python", str(venv / "bin" / "python"), "install", "--quiet",
                          "--no-compile", str(dist[0])], capture_output=True, text=True, timeout=1200, env=env)
    assert pip.returncode == 0, pip.stderr[-3000:]
    return venv


def _run(venv, *argv, cwd):
    return subprocess.run([str(venv / "bin" / "graphkin"), *argv], capture_output=True, text=True, cwd=cwd,
                          timeout=300)


@pytest.mark.slow
def test_the_core_install_has_no_notebook_stack(core):
    # Every distribution the environment holds, as its own interpreter sees them (it has no pip to ask).
    code = "import importlib.metadata as m\nfor d in m.distributions():\n    print(d.metadata['Name'])\n"
    r = subprocess.run([str(core / "bin" / "python"), "-I", "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    installed = {line.strip().lower() for line in r.stdout.splitlines()}
    assert not installed & set(NOT_IN_THE_CORE), sorted(installed & set(NOT_IN_THE_CORE))
    assert "graphkin" in installed


@pytest.mark.slow
@pytest.mark.parametrize("argv, expect", [
    (["--version"], "graphkin 0.1.0"),
    (["list"], "strip_cutter"),
    (["solve", "double_slider"], "F12 = 7.559 N ∠ 0.00°"),
    (["cycle", "strip_cutter", "--n", "36", "--json"], '"effort"'),
    (["flywheel", "three_cylinder"], "Energy table"),
    (["exercise", "key", "single_link", "--student", "s1"], "answer:"),
    (["handout", "double_slider", "-o", "h.pdf"], ""),
    (["exercise", "export", "single_link", "--to", "gradescope", "-o", "gs"], ""),
    (["exercise", "export", "single_link", "--to", "prairielearn", "-o", "pl"], ""),
    (["animate", "strip_cutter", "-o", "a.gif", "--frames", "3", "--dpi", "20"], "3 frames"),
    (["explore", "strip_cutter", "-o", "page.html", "--n", "12"], "page.html"),  # the wheel's JavaScript
    (["lessons", "course"], "lessons written to course (01_"),
])
def test_the_core_commands_run_without_any_extra(core, tmp_path, argv, expect):
    r = _run(core, *argv, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert expect in r.stdout + r.stderr


@pytest.mark.slow
@pytest.mark.parametrize("argv, extra", [
    (["exercise", "export", "single_link", "--to", "otter", "-o", "ot"], "platforms"),
    (["exercise", "export", "single_link", "--to", "nbgrader", "-o", "nb"], "platforms"),
    (["explore", "double_slider", "--no-browser"], "explore"),
])
def test_what_needs_an_extra_says_which_in_one_line(core, tmp_path, argv, extra):
    r = _run(core, *argv, cwd=tmp_path)
    assert r.returncode == 2 and "Traceback" not in r.stderr, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and f"pip install 'graphkin[{extra}]'" in lines[0], r.stderr


@pytest.mark.slow
def test_the_explorer_in_python_names_the_notebook_extra(core, tmp_path):
    code = ("import graphkin as gk\n"
            "try:\n"
            "    gk.explore(gk.load('double_slider'))\n"
            "except gk.GraphkinError as exc:\n"
            "    print(exc)\n")
    r = subprocess.run([str(core / "bin" / "python"), "-c", code], capture_output=True, text=True, cwd=tmp_path,
                       timeout=120)
    assert r.returncode == 0 and "pip install 'graphkin[notebook]'" in r.stdout, r.stdout + r.stderr


@pytest.mark.slow
def test_python_m_graphkin_is_the_command(core, tmp_path):
    r = subprocess.run([str(core / "bin" / "python"), "-m", "graphkin", "--version"], capture_output=True, text=True,
                       cwd=tmp_path, timeout=60)
    assert r.returncode == 0 and r.stdout.strip() == "graphkin 0.1.0"


@pytest.mark.slow
def test_the_wheel_and_the_sdist_carry_the_licence_and_the_sdist_no_tests(dist):
    wheel, sdist = dist
    with zipfile.ZipFile(wheel) as z:
        names = z.namelist()
    assert any(n.endswith("dist-info/licenses/LICENSE") for n in names)
    drawing = {f"graphkin/scene/js/{name}" for name in ("dom.js", "scene.js", "speed.js", "widget.js", "scene.css",
                                                          "page.html", "draw.js", "match.js")}
    assert drawing <= set(names)  # the browser's drawing
    metadata = next(n for n in names if n.endswith("dist-info/METADATA"))
    with zipfile.ZipFile(wheel) as z:
        meta = z.read(metadata).decode()
    assert "License-Expression: MIT" in meta and "Classifier: Topic :: Education" in meta
    assert "Project-URL: Documentation" in meta
    with tarfile.open(sdist) as t:
        members = [m.name.split("/", 1)[1] for m in t.getmembers() if "/" in m.name]
    assert "LICENSE" in members and "pyproject.toml" in members
    assert not [m for m in members if m.startswith("tests/")]  # the tests need the repository: run them from a clone


@pytest.mark.slow
def test_the_wheel_carries_every_lesson_as_committed(dist):
    """``graphkin lessons DIR`` copies them from the wheel: each notebook of lessons/, byte for byte."""
    with zipfile.ZipFile(dist[0]) as z:
        packed = {n.rsplit("/", 1)[1]: z.read(n) for n in z.namelist() if n.startswith("graphkin/lessons/")}
    assert packed == {p.name: p.read_bytes() for p in sorted((ROOT / "lessons").glob("[0-9][0-9]_*.ipynb"))}


def test_the_version_is_written_once():
    """graphkin/__init__.py's __version__ is the version; pyproject.toml reads it (dynamic) and writes none."""
    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text())
    assert "version" not in pyproject["project"] and "version" in pyproject["project"]["dynamic"]
    assert pyproject["tool"]["setuptools"]["dynamic"]["version"] == {"attr": "graphkin.__version__"}
    assert re.search(r'^__version__ = "\d+\.\d+\.\d+"$', (ROOT / "graphkin" / "__init__.py").read_text(), re.M)


def test_the_readme_links_work_on_the_package_index():
    """The package index shows README.md without the repository around it: every link and image is absolute."""
    text = (ROOT / "README.md").read_text()
    targets = re.findall(r"!?\[[^\]]*\]\(([^)\s]+)\)", text)
    assert targets
    relative = [t for t in targets if not re.match(r"^(https?://|#)", t)]
    assert relative == []


def _extras() -> dict[str, set[str]]:
    """Each extra and every distribution it brings, through the extras it names (``graphkin[a,b]``)."""
    declared = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]

    def brings(extra, seen=()):
        out = set()
        for req in declared[extra]:
            name, _, rest = re.match(r"([A-Za-z0-9_.-]+)(\[([^\]]*)\])?", req).groups()
            if name == "graphkin":
                for inner in rest.split(","):
                    assert inner not in seen, f"extra {extra} names itself through {inner}"
                    out |= brings(inner.strip(), (*seen, extra))
            else:
                out.add(name.lower())
        return out

    return {extra: brings(extra) for extra in declared}


def test_the_extras_bring_what_their_users_expect():
    """Issue 40: [notebook] pulled all of JupyterLab (115 packages) where the widgets need about 51."""
    extras = _extras()
    assert {"ipywidgets", "anywidget", "ipykernel"} <= extras["notebook"] and "jupyterlab" not in extras["notebook"]
    assert extras["notebook"] | {"jupyterlab"} <= extras["lab"]
    assert "voila" in extras["explore"] and "jupyterlab" not in extras["explore"]
    assert "nbformat" in extras["platforms"]
    assert extras["study"] == {"scipy"}  # Study.optimum and graphkin study --optimize, nothing more
    assert set().union(*(extras[e] for e in ("notebook", "lab", "explore", "platforms", "study"))) <= extras["all"]
    # make e2e drives the lessons cell by cell in JupyterLab and as pages in Voilà.
    assert {"jupyterlab", "voila", "playwright"} <= extras["e2e"]


def test_every_extra_the_docs_and_messages_name_exists():
    from graphkin.optional import EXTRAS

    named = set(EXTRAS.values())
    for page in [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]:
        for group in re.findall(r"(?:graphkin|\.)\[([\w,-]+)\]", page.read_text(encoding="utf-8")):
            named |= set(group.split(","))
    assert named >= {"notebook", "lab", "explore", "platforms", "all", "e2e"}
    assert named - set(_extras()) == set()
