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
    """

    label: str
    cells: tuple = ()
    answers: dict = field(default_factory=dict)
    read: dict = field(default_factory=dict)
    key_of: str | None = None


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
        Tamper("patch_graphkin", (PATCH_GRAPHKIN,), wrong_cells, wrong_read),
        Tamper("patch_platform", (PATCH_PLATFORM,), wrong_cells, wrong_read),
        Tamper("patch_builtins", (PATCH_BUILTINS,), wrong_cells, wrong_read),
        Tamper("patch_sys_modules", (PATCH_SYS_MODULES,), wrong_cells, wrong_read),
        Tamper("ipython_hooks", (IPYTHON_HOOKS,), wrong_cells, wrong_read),
        Tamper("writes_results", (WRITES_RESULTS,), wrong_cells, wrong_read),
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
    if t.key_of is None:
        return t
    key = {q["id"]: q["answer"]["text"] for q in exercises.key(NAME, t.key_of, SECRET)["questions"]}
    return Tamper(t.label, t.cells, {q: _literal(q, a) for q, a in key.items()}, key, t.key_of)


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
