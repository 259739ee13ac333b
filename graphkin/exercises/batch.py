"""A whole roster at once: sheets, keys or grades for every student, on all cores.

Each student's variant is independent of every other's, so a roster is cut
into chunks that worker processes solve; the results come back as plain data
in the roster's order. Small rosters (or one core) run in this process, where
starting workers would cost more than it saves.
"""

from __future__ import annotations

import os
from concurrent.futures import ProcessPoolExecutor

from .exercise import Exercise

PARALLEL_FROM = 200
"""Rosters of at least this many students are spread over the cores."""

_CHUNK = 50


def _one(exercise: Exercise, action: str, student: str, secret: str, answers, reveal):
    from ..errors import GraphkinError

    try:
        v = exercise.variant(student, secret)
    except GraphkinError as exc:
        return {"student": student, "error": str(exc)}
    if action == "make":
        return v.sheet()
    if action == "key":
        return v.key()
    from .grading import grade_variant

    return grade_variant(v, answers or {}, reveal=reveal)


def _chunk(args):
    exercise, action, items, secret, reveal = args
    return [_one(exercise, action, student, secret, answers, reveal) for student, answers in items]


def run_roster(exercise: Exercise, action: str, students, secret: str = "", *, answers=None, reveal=None,
               workers: int | None = None, progress=None) -> list[dict]:
    """Sheets (``"make"``), keys (``"key"``) or grades (``"grade"``) for every student, in order.

    Parameters
    ----------
    exercise : Exercise
    action : {"make", "key", "grade"}
    students : sequence of str
    secret : str
    answers : sequence of mapping, optional
        For ``"grade"``: each student's answers (question id → text), in roster order.
    reveal : bool, optional
        For ``"grade"``: show expected values (default: the exercise's choice).
    workers : int, optional
        Processes to use (default: every core, for rosters of :data:`PARALLEL_FROM` or more).
    progress : callable, optional
        Called with the number of students just finished (e.g. a tqdm bar's ``update``).

    Returns
    -------
    list of dict
        One per student; a student whose variant cannot be made gets
        ``{"student", "error"}`` instead of stopping the batch.
    """
    students = list(students)
    answers = list(answers) if answers is not None else [None] * len(students)
    items = list(zip(students, answers))
    chunks = [items[i:i + _CHUNK] for i in range(0, len(items), _CHUNK)]
    cores = workers or os.cpu_count() or 1
    out: list[dict] = []
    if cores == 1 or len(items) < PARALLEL_FROM:
        for chunk in chunks:
            out.extend(_chunk((exercise, action, chunk, secret, reveal)))
            if progress:
                progress(len(chunk))
        return out
    with ProcessPoolExecutor(max_workers=cores) as pool:
        for chunk, done in zip(chunks, pool.map(_chunk, [(exercise, action, c, secret, reveal) for c in chunks])):
            out.extend(done)
            if progress:
                progress(len(chunk))
    return out
