"""Exercises with per-student data, graded answers and feedback that teaches.

An exercise (a TOML file, ``docs/exercises.md``) is a base problem, the values
that vary from student to student, and the questions. For each student the
values are drawn from a stable hash of (exercise, student id, course secret);
the answers are solved from the data as the student sees them; the grader
reads answers as students type them (``"27.06 N ∠ −73.78°"``, ``"108.9 N·m CCW"``)
and names the slip when one is wrong.

Every result is plain data (dicts of str, float, list), for a handout, a
notebook or a grading platform. This layer never imports matplotlib.

Examples
--------
>>> from graphkin import exercises
>>> sheet = exercises.make("double_slider_forces", "s001")
>>> [g["shown"] for g in sheet["data"]]
['x = 330 mm', 'ẋ = 3 m/s']
>>> report = exercises.grade("double_slider_forces", "s001", {"F23": "1 N"})
>>> report["questions"][0]["verdict"]
'wrong'
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.exercises.drawn_grading import grade_drawing
from graphkin.exercises.drawn_tasks import task_of
from graphkin.exercises.exercise import SLIPS, Exercise, Question, Vary, load_exercise, parse_exercise
from graphkin.exercises.grading import Classmates, grade_variant
from graphkin.exercises.roster import read_roster
from graphkin.exercises.variants import MAX_ATTEMPTS, Variant, make_variant

__all__ = ["Exercise", "Question", "Vary", "Variant", "SLIPS", "MAX_ATTEMPTS", "names", "load", "load_exercise",
           "parse_exercise", "path", "read_roster", "variant", "make", "key", "grade", "check", "task_of", "grade_drawing"]

_CACHE: dict = {}


def _folder():
    return resources.files("graphkin.catalog").joinpath("exercises")


def names() -> list[str]:
    """Names of the catalog exercises, sorted."""
    return sorted(p.name[:-5] for p in _folder().iterdir() if p.name.endswith(".toml"))


def path(name: str) -> Path:
    """Path of a catalog exercise file (to read it, or to copy it as the start of your own)."""
    if name not in names():
        raise GraphkinError(f"no catalog exercise {name!r} (the catalog has: {', '.join(names())})")
    return Path(str(_folder().joinpath(name + ".toml")))


def load(name_or_path: str | Exercise) -> Exercise:
    """An :class:`Exercise` from a catalog name or a file path (read once per process)."""
    if isinstance(name_or_path, Exercise):
        return name_or_path
    if name_or_path not in _CACHE:
        if name_or_path in names():
            ex = load_exercise(path(name_or_path), name=name_or_path)
        else:
            p = Path(name_or_path)
            if p.suffix != ".toml" and not p.exists():
                raise GraphkinError(f"{name_or_path!r} is neither a catalog exercise ({', '.join(names())}) nor a file")
            ex = load_exercise(p)
        _CACHE[name_or_path] = ex
    return _CACHE[name_or_path]


def variant(exercise: str | Exercise, student: str, secret: str = "") -> Variant:
    """The student's variant of an exercise (their data and, for the key, the solved problem)."""
    return make_variant(load(exercise), student, secret)


def make(exercise: str | Exercise, student: str, secret: str = "") -> dict:
    """The student's sheet as plain data: statement, their data, the questions; no answers."""
    return variant(exercise, student, secret).sheet()


def key(exercise: str | Exercise, student: str, secret: str = "") -> dict:
    """The sheet with every answer (SI and as printed) and its tolerance."""
    return variant(exercise, student, secret).key()


def grade(exercise: str | Exercise, student: str, answers, secret: str = "", *, reveal: bool | None = None,
          classmates=None, feedback: str | None = None) -> dict:
    """Grade a student's answers (question id → text as typed) to their variant.

    Returns plain data: ``score``, ``max`` and per question the verdict
    (``correct``, ``slip``, ``wrong``, ``unreadable``, ``missing``), the slip
    diagnosed, the points and a sentence of feedback; the expected value only
    where the exercise (or ``reveal``) allows it. With ``classmates`` (the
    class's ids), answers that fit another student's data (two of them, on a sheet
    of several questions) earn nothing and are named as such (slip ``other_data``;
    ``other`` names the classmate). ``feedback`` (``"parts"`` or ``"distance"``)
    overrides the exercise's: whether a wrong answer is told how far off it is.
    """
    ex = load(exercise)
    if classmates is not None and not isinstance(classmates, Classmates):
        classmates = Classmates({s: {q.id: v.expected(q).value for q in ex.questions if v.expected(q).undefined is None}
                                 for s, v in ((s, make_variant(ex, s, secret)) for s in classmates)})
    return grade_variant(variant(ex, student, secret), answers, reveal=reveal, classmates=classmates, feedback=feedback)


def check(exercise: str | Exercise, student: str, answers, secret: str = "", *, reveal: bool | None = None,
          feedback: str | None = None) -> str:
    """Grade answers and return the feedback as text, one line per question (for a notebook cell).

    Examples
    --------
    >>> print(check("single_link", "s001", {"T12": "4.531 N*m CW"}).splitlines()[1])
    F12: missing — No answer was given for F12.
    """
    report = grade(exercise, student, answers, secret, reveal=reveal, feedback=feedback)
    lines = [f"{report['exercise']} (student {report['student']}): {report['score']:g} / {report['max']:g} points"]
    for q in report["questions"]:
        slip = f" ({q['slip'].replace('_', ' ')})" if q["slip"] else ""
        expected = f" (expected: {q['expected']})" if "expected" in q and q["verdict"] != "correct" else ""
        lines.append(f"{q['id']}: {q['verdict']}{slip} — {q['feedback']}{expected}")
    return "\n".join(lines)
