"""Precomputed keys: everything grading a roster needs, computed where the course secret is, and carried
where grading runs instead of the secret.

The course secret decides every student's data, this term and (if it is reused) the next. A grading
platform needs only what follows from it for the students it grades: each student's data, each
answer with its slack, the words of the feedback, and the values of the slips that are found by
solving the problem again (the speed in rpm used as rad/s, the inertia torque or force left out).
:func:`make_keys` computes these for a roster, as plain JSON data together with the exercise file;
:class:`Keys` reads them back, and its :class:`KeyedVariant` answers the grader's questions exactly as
a live :class:`graphkin.exercises.Variant` does (the same numbers, through JSON's exact floats), so
a platform grading with keys gives the score ``graphkin exercise grade`` gives with the secret.

Keys are teachers' data: they hold every answer of every student on the roster. They travel only to
where grading runs and no student code does (an autograder, a course directory).

Examples
--------
>>> from graphkin import exercises
>>> from graphkin.exercises.keys import Keys, make_keys
>>> data = make_keys(exercises.load("single_link"), ["s001", "s002"], secret="course")
>>> keys = Keys(data)
>>> report = keys.grade("s001", {"T12": exercises.key("single_link", "s001", "course")["questions"][1]["answer"]["text"]})
>>> [q["verdict"] for q in report["questions"]]
['missing', 'correct']
"""

from __future__ import annotations

import json
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.exercises.exercise import Exercise, Question, parse_exercise
from graphkin.exercises.grading import RESOLVED_SLIPS, Classmates, _may, grade_variant
from graphkin.exercises.quantities import Expected, question_data, within
from graphkin.exercises.symbols import fill_symbols
from graphkin.exercises.variants import check_student, make_variant, pretty

FORMAT = "graphkin-keys-1"
"""The ``format`` of a keys file this version writes and reads."""


def _plain(value):
    """A value as JSON data: a float, ``[x, y]`` for a complex number, None."""
    if value is None:
        return None
    if isinstance(value, complex):
        return [value.real, value.imag]
    return float(value)


def _value(data):
    return complex(*data) if isinstance(data, list) else data


def student_entry(variant) -> dict:
    """What grading one student needs, as JSON data (see :func:`make_keys`)."""
    ex = variant.exercise
    questions = {}
    for q in ex.questions:
        e = variant.expected(q)
        questions[q.id] = {
            "form": e.form, "value": _plain(e.value), "slack": e.slack, "text": e.text, "hint": e.hint,
            "anchor": _plain(e.anchor), "undefined": e.undefined,
            "slips": {slip: _plain(variant.slip_value(q, slip)) for slip in RESOLVED_SLIPS if _may(q, slip)},
            "words": variant.words(q),
            "within": within(q, variant.solved),
        }
        if q.kind == "drawing":  # the task, the targets and the words: grading needs no re-solve
            questions[q.id]["drawn"] = variant.drawn(q)
    return {"attempt": variant.attempt,
            "data": [{"symbol": g.symbol, "label": g.label, "value": g.value} for g in variant.data],
            "questions": questions}


def make_keys(exercise: Exercise, students, secret: str = "", *, entries=None) -> dict:
    """The keys of a roster: the exercise (its file and a non-catalog base problem) and each student's entry.

    Parameters
    ----------
    exercise : Exercise
    students : sequence of str, or None
        The roster. ``None`` makes keys without students: the grader then draws each student's data from
        their id, which needs no secret only when there is none (an export without a secret).
    secret : str
        The course secret; it is not written into the keys.
    entries : sequence of dict, optional
        Each student's :func:`student_entry`, when already computed (a roster spread over the cores).

    Raises
    ------
    GraphkinError
        A secret without students (the keys would need the secret), or a student whose data cannot be made.
    """
    if students is None and secret:
        raise GraphkinError("keys without a roster would need the course secret to draw the data: give the roster")
    out = {"format": FORMAT, "exercise": {"id": exercise.id, "text": exercise.text, "problem": exercise.problem,
                                          "problem_text": exercise.base_text},
           "fingerprint": exercise.fingerprint, "students": None}
    if students is not None:
        students = [check_student(s) for s in students]
        if entries is None:
            entries = [student_entry(make_variant(exercise, s, secret)) for s in students]
        out["students"] = dict(zip(students, entries))
    return out


class KeyedVariant:
    """A student's variant read from keys: what the grader asks of a :class:`graphkin.exercises.Variant`.

    Attributes
    ----------
    exercise : Exercise
    student : str
    attempt : int
    """

    def __init__(self, exercise: Exercise, student: str, entry: dict):
        self.exercise = exercise
        self.student = student
        self.attempt = int(entry["attempt"])
        self._data = entry["data"]
        self._questions = entry["questions"]

    def _entry(self, q: Question) -> dict:
        return self._questions[q.id]

    def expected(self, q: Question) -> Expected:
        e = self._entry(q)
        anchor = _value(e["anchor"])
        return Expected(q, e["form"], _value(e["value"]), e["slack"], e["text"], e["hint"],
                        None if anchor is None else complex(anchor), e["undefined"])

    def slip_value(self, q: Question, slip: str):
        return _value(self._entry(q)["slips"].get(slip))

    def words(self, q: Question) -> dict:
        return self._entry(q)["words"]

    def drawn(self, q: Question) -> dict:
        """A drawn question's task, targets, tolerance and words, as the keys carry them."""
        return self._entry(q)["drawn"]

    def sheet(self) -> dict:
        """The student's sheet, as :meth:`graphkin.exercises.Variant.sheet` gives it."""
        values = {g["symbol"]: pretty(g["value"]) for g in self._data}
        ex = self.exercise
        return {"exercise": ex.id, "title": ex.title, "source": ex.source, "student": self.student,
                "intro": fill_symbols(ex.intro, values), "draw": ex.draw,
                "data": [{"symbol": g["symbol"], "label": g["label"], "value": g["value"],
                          "shown": f"{g['symbol']} = {pretty(g['value'])}"} for g in self._data],
                "questions": [{**question_data(q), "ask": fill_symbols(q.ask, values),
                               "within": self._entry(q).get("within") or within(q)} for q in ex.questions]}


class Keys:
    """Keys read back (from :func:`make_keys`'s data or a file): the exercise and each student's variant.

    Parameters
    ----------
    source : dict, str or Path
        The keys as data, or the JSON file that holds them.
    """

    def __init__(self, source):
        data = source if isinstance(source, dict) else _read(source)
        if not isinstance(data, dict) or data.get("format") != FORMAT:
            raise GraphkinError(f"not graphkin keys of format {FORMAT} (export again with this graphkin)")
        e = data["exercise"]
        problems = {e["problem"]: e["problem_text"]}
        self.exercise = parse_exercise(e["text"], file=f"{e['id']}.toml", id=e["id"], problems=problems)
        self._students = data["students"]
        self._classmates = None

    @property
    def roster(self) -> list[str] | None:
        """The students the keys hold, or None (keys that draw each student's data from the id)."""
        return None if self._students is None else list(self._students)

    def variant(self, student: str):
        """The student's :class:`KeyedVariant` (or, for keys without a roster, their live variant).

        Raises
        ------
        GraphkinError
            A student who is not on the roster (the sentence says so).
        """
        student = check_student(student)
        if self._students is None:
            return make_variant(self.exercise, student, "")
        if student not in self._students:
            raise GraphkinError(f"student id {student!r} is not on this assignment's roster: check the id you typed "
                                "(as your teacher gave it), or ask your teacher to add you")
        return KeyedVariant(self.exercise, student, self._students[student])

    def classmates(self) -> Classmates | None:
        """Every roster student's answers, to tell an answer worked from a classmate's data (None without a roster)."""
        if self._students is None:
            return None
        if self._classmates is None:
            self._classmates = Classmates({s: {qid: _value(e["value"]) for qid, e in entry["questions"].items()
                                               if e["undefined"] is None}
                                           for s, entry in self._students.items()})
        return self._classmates

    def grade(self, student: str, answers, *, reveal=None, feedback=None) -> dict:
        """Grade a student's answers (question id → text as typed), as :func:`graphkin.exercises.grade` does,
        with the roster as the class."""
        return grade_variant(self.variant(student), answers, reveal=reveal, classmates=self.classmates(),
                             feedback=feedback)


def _read(path) -> dict:
    p = Path(path)
    try:
        return json.loads(p.read_text(encoding="utf-8"))
    except OSError as exc:
        raise GraphkinError(f"keys {p}: cannot be read ({exc.strerror or exc})") from None
    except ValueError as exc:
        raise GraphkinError(f"keys {p}: not JSON ({exc})") from None


def keys_text(keys: dict) -> str:
    """Keys as the text of a JSON file: exact floats, and never ``NaN`` (an undefined answer is null)."""
    return json.dumps(keys, ensure_ascii=False, sort_keys=True, indent=1, allow_nan=False) + "\n"


__all__ = ["FORMAT", "KeyedVariant", "Keys", "keys_text", "make_keys", "student_entry"]
