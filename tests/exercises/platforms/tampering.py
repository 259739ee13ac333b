"""A catalogue of notebooks that try to forge a grade or read what they must not, for the notebook platforms.

Each :class:`Tamper` is what a student hands in: the answer cells they type (a literal, or code that
tries to compute or fetch an answer) and extra cells placed after the id cell. The platform tests
(otter, nbgrader) run the real tool on each and check that the notebook earns exactly what its
answers, read as data, earn (``read``: the values the grader must see), never more; that grading
neither hangs nor fails; and that no secret, key or environment value reaches anything students see.

The exercise is ``strip_cutter_cut`` (questions F23, F14, T12).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from graphkin import exercises
from graphkin.exercises.notebooks import NotData

NAME = "strip_cutter_cut"
MARKER = "env-marker-3f9d1c"
"""A value put in the grading machine's environment (``GRAPHKIN_MARKER``): it must reach no student."""

WRONG = {"F23": "1 N ∠ 0°", "F14": "1 N", "T12": "1 N*m CCW"}
"""Answers that earn nothing for any student of the exercise."""

# What a forging notebook would like a test to say: full marks.
_FULL = ('{"id": "T12", "verdict": "correct", "slip": None, "score": 1.0, "max": 1.0, "feedback": "ok", '
         '"answer": "", "expected": ""}')


@dataclass(frozen=True)
class Tamper:
    """One tampering notebook.

    Attributes
    ----------
    label : str
        Short name (a folder or file name).
    cells : tuple of str
        Extra code cells, placed right after the id cell (so they run before any answer or test).
    answers : dict
        Question id → the source of its answer cell (a whole cell, literal or not).
    read : dict
        Question id → the value the grader must read from that cell (text, a number or NotData).
    key_of : str or None
        When set, the answers are that student's key (right answers): ``answers``/``read`` are filled in
        by :func:`catalogue`.
    kinds : tuple of str
        The ways of tampering it tries (one notebook may try several).
    """

    label: str
    cells: tuple = ()
    answers: dict = field(default_factory=dict)
    read: dict = field(default_factory=dict)
    key_of: str | None = None
    kinds: tuple = ()


def _literal(qid: str, value: str) -> str:
    return f"{qid} = {value!r}"


def _wrong() -> tuple[dict, dict]:
    return {q: _literal(q, v) for q, v in WRONG.items()}, dict(WRONG)


PATCH_GRAPHKIN = f"""\
import sys
sys.path.append("vendor")
import graphkin.exercises.grading as g
import graphkin.exercises.platforms.runtime as r
full = lambda *a, **k: dict({_FULL})
g.grade_question = r.grade_question = full
g.grade_variant = r.grade = lambda *a, **k: {{"score": 3.0, "max": 3.0, "questions": []}}
r.readable_problem = lambda *a, **k: None
r.feedback_line = lambda *a, **k: "T12: correct, 1 / 1"
"""

PATCH_PLATFORM = """\
try:
    import otter
    otter.Notebook.check = lambda self, *a, **k: None
    otter.Notebook.check_all = lambda self, *a, **k: None
except ImportError:
    pass
import sys
sys.path.append("vendor")
import graphkin.exercises.platforms.otter as go
import graphkin.exercises.platforms.nbgrader as gn
go.readable = go.graded_by_plugin = lambda *a, **k: None
gn.check_answer = gn.not_read_as_data = lambda *a, **k: None
gn.read_as_data = lambda nb, resources: (nb, resources)
"""

PATCH_BUILTINS = """\
import builtins
builtins.AssertionError = type("AssertionError", (Warning,), {})
builtins.float = lambda *a, **k: 1.0
builtins.round = lambda *a, **k: 1.0
builtins.print = lambda *a, **k: None
"""

PATCH_SYS_MODULES = """\
import sys, types
fake = types.ModuleType("graphkin")
fake.__path__ = []
for name in [n for n in sys.modules if n.startswith("graphkin")] + ["graphkin", "graphkin.exercises",
             "graphkin.exercises.platforms", "graphkin.exercises.platforms.runtime",
             "graphkin.exercises.platforms.otter", "graphkin.exercises.platforms.nbgrader"]:
    m = types.ModuleType(name)
    m.__path__ = []
    m.__getattr__ = lambda attr: (lambda *a, **k: 1.0)
    sys.modules[name] = m
"""

IPYTHON_HOOKS = """\
ip = get_ipython()
ip.events.register("post_run_cell", lambda result: print("3.0"))
ip.display_formatter.formatters["text/plain"].for_type(float, lambda x, p, cycle: p.text("1.0"))
ip.user_ns["__builtins__"].__dict__["Exception"] = type("Exception", (BaseException,), {})
"""

READS_FILES_AND_ENV = """\
import glob, os, pathlib
found = {p: pathlib.Path(p).read_text(errors="replace")[:200]
         for p in glob.glob("**/*", recursive=True) + glob.glob("../**/*", recursive=True)
         if os.path.isfile(p) and ("keys" in p or "config" in p)}
print(found, dict(os.environ))
"""

WRITES_RESULTS = """\
import atexit, json, os, pathlib
fake = {"score": 3.0, "tests": [{"name": q, "score": 1.0, "max_score": 1.0} for q in ("F23", "F14", "T12")]}
for folder in ("results", "../results", "/autograder/results", "."):
    try:
        pathlib.Path(folder, "results.json").write_text(json.dumps(fake))
    except OSError:
        pass
atexit.register(lambda: pathlib.Path("results.json").write_text(json.dumps(fake)))
"""

SLEEPS = "import time\ntime.sleep(100_000)"
EXITS = "import os\nos._exit(0)"
MAGICS = "%%capture\n!cat *keys*.json\nimport os; print(os.environ)"

HTML = '<img src=x onerror="alert(1)">'
SCRIPT = "<script>alert('x')</script>"


def catalogue(student: str, classmate: str) -> list[Tamper]:
    """The tampering notebooks, as handed in by ``student`` (``classmate``: another roster student)."""
    wrong_cells, wrong_read = _wrong()
    out = [
        # Nothing of a notebook's code runs, so one notebook tries them all.
        Tamper("code_patches", (PATCH_GRAPHKIN, PATCH_PLATFORM, PATCH_BUILTINS, PATCH_SYS_MODULES, IPYTHON_HOOKS,
                                WRITES_RESULTS), wrong_cells, wrong_read,
               kinds=("patch_graphkin", "patch_platform", "patch_builtins", "patch_sys_modules", "ipython_hooks",
                      "writes_results")),
        Tamper("answers_as_code", (READS_FILES_AND_ENV,), {
            "F23": 'F23 = open(sorted(__import__("glob").glob("**/*keys*.json", recursive=True))[0]).read()',
            "F14": 'F14 = __import__("os").environ.get("GRAPHKIN_SECRET", "") + " N"',
            "T12": 'T12 = str(dict(__import__("os").environ))',
        }, {"F23": NotData("a call"), "F14": NotData("a calculation"), "T12": NotData("a call")}),
        Tamper("magics", (MAGICS,), {**wrong_cells, "T12": "T12 = !cat *keys*.json"},
               {**wrong_read, "T12": NotData("not valid Python")}),
        Tamper("html_payload", (), {"F23": _literal("F23", SCRIPT), "F14": _literal("F14", f"12 N {HTML}"),
                                    "T12": _literal("T12", f"{HTML} N*m")},
               {"F23": SCRIPT, "F14": f"12 N {HTML}", "T12": f"{HTML} N*m"}),
        Tamper("hostile_literals", (), {"F23": "F23 = 1" + "0" * 5000, "F14": "F14 = " + repr("9" * 1_000_000),
                                        "T12": "T12 = float('nan')"},
               # Python refuses a literal of more than 4300 digits: not valid Python, read as such.
               {"F23": NotData("not valid Python"), "F14": "9" * 1_000_000, "T12": NotData("a call")}),
        Tamper("sleeps", (SLEEPS,), key_of=student),
        Tamper("exits", (EXITS,), key_of=student),
        Tamper("classmate", (), key_of=classmate),
    ]
    return [_filled(t) for t in out]


def _filled(t: Tamper) -> Tamper:
    kinds = t.kinds or (t.label,)
    if t.key_of is None:
        return Tamper(t.label, t.cells, t.answers, t.read, None, kinds)
    key = {q["id"]: q["answer"]["text"] for q in exercises.key(NAME, t.key_of, SECRET)["questions"]}
    return Tamper(t.label, t.cells, {q: _literal(q, a) for q, a in key.items()}, key, t.key_of, kinds)


SECRET = "tamper-course-secret-8c2e"


def expected_report(student: str, t: Tamper, roster) -> dict:
    """What the notebook's answers, read as data, earn: graded here, outside any platform."""
    return exercises.grade(NAME, student, t.read, SECRET, classmates=list(roster))


def fill(nb, student: str, t: Tamper, answer_grade_ids: dict | None = None):
    """The student notebook ``nb`` (nbformat) as handed in: the id typed, ``t``'s cells and answers in.

    Answer cells are found by their source ``NAME = ...`` (otter) or, with ``answer_grade_ids`` (question
    id → nbgrader grade id), by nbgrader's metadata.
    """
    import nbformat

    cells = []
    for cell in nb.cells:
        source = cell.source.strip()
        gid = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id")
        if cell.cell_type == "code" and (source == "STUDENT = ..." or gid == "student"):
            cell.source = f"STUDENT = {student!r}"
            cells.append(cell)
            cells += [nbformat.v4.new_code_cell(c) for c in t.cells]
            continue
        for qid, src in t.answers.items():
            if cell.cell_type == "code" and (source == f"{qid} = ..." or (answer_grade_ids or {}).get(qid) == gid
                                             and gid is not None):
                cell.source = src
        cells.append(cell)
    nb.cells = cells
    return nb


def leaks(text: str, keys_text: str) -> list[str]:
    """What of the secret, the keys or the environment ``text`` (something a student sees) holds."""
    import json

    found = [s for s in (SECRET, MARKER) if s in text]
    keys = json.loads(keys_text)
    for student, entry in keys["students"].items():
        for qid, q in entry["questions"].items():
            value = q["value"]
            for v in value if isinstance(value, list) else [value]:
                if isinstance(v, float) and abs(v) > 1 and repr(v) in text:
                    found.append(f"{student}.{qid} = {v!r}")
    if "graphkin-keys" in text:
        found.append("the keys' format name")
    return found


# ---------------------------------------------------------------------------------------------------------
# What a student hands in beside the notebook, and notebooks that cannot be read
#
# Each payload, if anything ever ran or loaded it (an import, a .pth line, unpickling), leaves a file named
# after its kind in the test's canary folder: the platform tests check that the folder stays empty.


@dataclass(frozen=True)
class Link:
    """A symbolic link handed in: ``target`` is a path, or ``"{keys}"`` / ``"{keys_folder}"`` for the course's
    keys file and the folder holding it (the platform test fills them in)."""

    target: str


class _Loads:
    """An object whose pickle runs ``code`` when it is loaded (what a forged ``.OTTER_LOG`` or results pickle is)."""

    def __init__(self, code: str):
        self.code = code

    def __reduce__(self):
        return exec, (self.code,)


def payload(canary, kind: str) -> str:
    """Python that leaves ``canary/kind`` behind when anything runs it, and tries to read the keys."""
    return (f"import glob, pathlib\n"
            f"found = [p for p in glob.glob('**/*keys*', recursive=True)] + glob.glob('../**/*keys*', recursive=True)\n"
            f"pathlib.Path({str(canary)!r}, {kind!r}).write_text(repr(found))\n")


def pickled(canary, kind: str) -> bytes:
    import pickle

    return pickle.dumps(_Loads(payload(canary, kind)))


def beside(canary) -> dict[str, dict]:
    """Files handed in beside the notebook, by group (a group goes into one hand-in): path → bytes or Link."""
    def code(kind):
        return payload(canary, kind).encode()

    return {
        "packages": {"graphkin/__init__.py": code("shadow_graphkin"), "otter/__init__.py": code("shadow_otter"),
                     "nbgrader/__init__.py": code("shadow_nbgrader"), "IPython/__init__.py": code("shadow_IPython")},
        "startup": {"sitecustomize.py": code("sitecustomize"), "usercustomize.py": code("usercustomize"),
                    "evil.pth": payload(canary, "pth").replace("\n", "; ").encode() + b"\n",
                    "json.py": code("shadow_json"), "ipykernel_launcher.py": code("shadow_ipykernel_launcher")},
        "pickles": {".OTTER_LOG": pickled(canary, "otter_log"), "results.pkl": pickled(canary, "results_pickle"),
                    "results/results.pkl": pickled(canary, "results_folder_pickle")},
        "export": {"vendor/graphkin/__init__.py": code("shadow_vendor"), "tests/F23.py": code("shadow_tests"),
                   "__init__.py": code("package_init")},
        "links": {"keys.json": Link("{keys}"), "course-keys": Link("{keys_folder}"), "passwd": Link("/etc/passwd")},
    }


def unreadable() -> dict[str, tuple[bytes, str]]:
    """Notebooks that cannot be read, by kind: (the file's bytes, the refusal code graphkin gives)."""
    cells = '{"cells": [{"cell_type": "code", "source": "STUDENT = \\"s001\\"\\nF14 = \\"1 N\\""}], "metadata": {}'
    return {
        # Outputs of 60 MB: more than a notebook of answers may be.
        "too_big": ((cells + ', "outputs": "').encode() + b"x" * 60_000_000 + b'"}', "too_big"),
        "too_deep": (b'{"cells": [], "x": ' + b"[" * 100_000 + b"]" * 100_000 + b"}", "too_deep"),
        "not_utf8": ((cells + ', "title": "\u00e9tude"}').encode("latin-1"), "not_utf8"),
        "not_json": (b'STUDENT = "s001"\nF14 = "1 N"\n', "not_json"),
        "not_a_notebook": (b'{"cells": "STUDENT = \\"s001\\""}', "not_notebook"),
    }


def write_files(folder, files: dict, fill: dict) -> None:
    """Write ``files`` (path → bytes or Link) under ``folder``; a Link's target is formatted with ``fill``."""
    import os
    from pathlib import Path

    for rel, content in files.items():
        path = Path(folder, rel)
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(content, Link):
            os.symlink(content.target.format(**fill), path)
        else:
            path.write_bytes(content)


def write_zip(path, files: dict, fill: dict) -> None:
    """Write ``files`` (path → bytes or Link) as a zip, a Link as a zip's symbolic-link entry."""
    import stat
    import zipfile

    with zipfile.ZipFile(path, "w") as z:
        for rel, content in files.items():
            if isinstance(content, Link):
                info = zipfile.ZipInfo(rel)
                info.external_attr = (stat.S_IFLNK | 0o777) << 16
                z.writestr(info, content.target.format(**fill))
            else:
                z.writestr(rel, content)


def refused_report(student: str, code: str) -> dict:
    """What a hand-in that cannot be read earns: every question refused, with graphkin's sentence."""
    from graphkin.exercises.handins import REFUSALS
    from graphkin.exercises.platforms.isolated import refused

    return refused(exercises.load(NAME), student, REFUSALS[code])


def with_extra_grade_cells(nb):
    """``nb`` with cells the student added: nbgrader grade cells worth 100 points each that end in full marks
    (one under a test cell's own grade id, one under a new id), and otter test metadata saying all pass."""
    import nbformat

    for gid in ("test_F23", "extra_points"):
        cell = nbformat.v4.new_code_cell("print('F23: correct, 100 / 100')\n100.0")
        cell.metadata["nbgrader"] = {"grade": True, "grade_id": gid, "locked": True, "points": 100.0,
                                     "schema_version": 3, "solution": False}
        nb.cells.append(cell)
    passing = "from otter.test_files import test_case\nOK_FORMAT = False\nname = {q!r}\npoints = 100\n" \
              "@test_case(points=100)\ndef passes():\n    pass\n"
    nb.metadata.setdefault("otter", {})["tests"] = {q: passing.format(q=q) for q in WRONG}
    return nb
