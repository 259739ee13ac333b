"""A whole roster at once: sheets, keys or grades for every student, on all cores.

Each student's variant is independent of every other's, so a roster is cut
into one shard per core, each solved by its own worker process; the results
come back as plain data in the roster's order. A student always goes to the
same worker (the shard follows the values of their first draw, so classmates
who drew the same values share a worker, which solves that draw once), and
the workers live for the whole session, so the variants a worker made for
the sheets serve the keys and the grades too (see
:data:`graphkin.exercises.variants.CACHE_SIZE`). Small rosters (or one core)
run in this process, where starting workers would cost more than it saves.
"""

from __future__ import annotations

import atexit
import gc
import os
from collections import OrderedDict
from concurrent.futures import ProcessPoolExecutor
from contextlib import contextmanager

from graphkin.errors import GraphkinError
from graphkin.exercises.exercise import Exercise
from graphkin.exercises.grading import Classmates, grade_variant
from graphkin.exercises.keys import student_entry
from graphkin.exercises.variants import draw_shard, make_variant

PARALLEL_FROM = 200
"""Rosters of at least this many students are spread over the cores."""

_CHUNK = 50
_GC_THRESHOLD = (100_000, 10, 10)
"""A worker's garbage-collector thresholds (Python's default is (700, 10, 10)); see :func:`_start_worker`."""
_WORKERS: list[ProcessPoolExecutor] = []
_SHARDS: OrderedDict = OrderedDict()
"""Each student's worker by (exercise, secret, workers): found once for a session's passes (see :func:`_shards`)."""
_IN_WORKER = False
"""True in a worker process (set by :func:`_start_worker`)."""


def _one(exercise: Exercise, action: str, student: str, secret: str, answers, reveal, classmates):
    try:
        v = make_variant(exercise, student, secret)
    except GraphkinError as exc:
        return {"student": student, "error": str(exc)}
    if action == "make":
        return v.sheet()
    if action == "key":
        return v.key()
    if action == "values":
        return {"student": v.student, "values": {q.id: v.expected(q).value for q in exercise.questions
                                                 if v.expected(q).undefined is None}}
    if action == "entry":
        return {"student": v.student, "entry": student_entry(v)}
    return grade_variant(v, answers or {}, reveal=reveal, classmates=classmates)


def _chunk(args):
    exercise, action, items, secret, reveal, classmates = args
    rows = [_one(exercise, action, student, secret, answers, reveal, classmates) for student, answers in items]
    if _IN_WORKER:
        # What the chunk made and kept (the variants and draws of the caches) lives for the session: out of the
        # collector's walks from now on (see _start_worker).
        gc.freeze()
    return rows


def _start_worker():
    """Set up a worker process: its cyclic garbage collector runs less often and leaves the caches alone.

    A worker keeps the draws it solved (a few hundred small objects each, up
    to :data:`~graphkin.exercises.variants.CACHE_SIZE` of them) for the whole
    session, and solving makes next to no reference cycles: an object is freed
    by its reference count. At Python's default thresholds the collector still
    walked that cache again and again, freeing nothing: 0.49 s of a 4.1 s make
    pass of 1000 students of ``strip_cutter_cut``, 0 objects collected. Here
    what a chunk leaves alive is frozen (:func:`gc.freeze`) when it ends, and
    the young generation holds 100 000 objects, more than a chunk of
    :data:`_CHUNK` students leaves (about 20 000 for the largest draws): the
    collector runs only after a chunk that allocates more, and never walks the
    draws. With 10 000 it still took 5-10 % of a session of the heaviest
    exercises (39 collections in one of ``strip_cutter_cut``, 126 in one of
    ``shaper_polygons`` with slipped answers graded), collecting nothing. The
    price: a cycle that a chunk makes and drops is frozen with the rest and
    stays until the worker ends, with the session (a full collection after
    sessions of 1000 students of four exercises found 32 such objects, against
    10 with the smaller threshold; the same peak memory).
    """
    global _IN_WORKER
    _IN_WORKER = True
    gc.set_threshold(*_GC_THRESHOLD)


def _workers(n: int) -> list[ProcessPoolExecutor]:
    """``n`` single-process pools, started once and kept for the session."""
    while len(_WORKERS) < n:
        if not _WORKERS:
            atexit.register(_shutdown)
        _WORKERS.append(ProcessPoolExecutor(max_workers=1, initializer=_start_worker))
    return _WORKERS[:n]


def _shutdown():
    for pool in _WORKERS:
        pool.shutdown(cancel_futures=True)
    _WORKERS.clear()


def run_roster(exercise: Exercise, action: str, students, secret: str = "", *, answers=None, reveal=None,
               workers: int | None = None, progress=None, classmates=None) -> list[dict]:
    """Sheets (``"make"``), keys (``"key"``) or grades (``"grade"``) for every student, in order.

    Parameters
    ----------
    exercise : Exercise
    action : {"make", "key", "grade", "entry"}
        ``"entry"`` gives each student's :func:`graphkin.exercises.keys.student_entry` (for a keys file).
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
    classmates : sequence of str, optional
        For ``"grade"``: the class, whose answers an answer may fit (default: the students graded). An
        empty sequence grades each student on their own.

    Returns
    -------
    list of dict
        One per student; a student whose variant cannot be made gets
        ``{"student", "error"}`` instead of stopping the batch.
    """
    students = list(students)
    answers = list(answers) if answers is not None else [None] * len(students)
    items = list(zip(students, answers))
    cores = workers or os.cpu_count() or 1
    cls = None
    if action == "grade":
        # The class's answers first (each worker keeps the variants it makes, so grading reuses them).
        class_ids = students if classmates is None else list(classmates)
        if class_ids:
            values = _run(exercise, "values", [(s, None) for s in class_ids], secret, None, None, cores, None)
            cls = Classmates({r["student"]: r["values"] for r in values if "values" in r})
    return _run(exercise, action, items, secret, reveal, cls, cores, progress)


def _shards(exercise: Exercise, students, secret: str, cores: int) -> dict:
    """Each student's worker (:func:`~graphkin.exercises.variants.draw_shard`), found once per exercise, secret and
    number of workers: a session's passes (sheets, keys, the class's values and the grades) ask for the same
    students, and finding them is a hash per varied value of each, here in the one process that feeds the
    workers while they wait."""
    key = (exercise.fingerprint or id(exercise), secret, cores)
    kept = _SHARDS.get(key)
    if kept is None or kept[0] is not exercise and not exercise.fingerprint:
        kept = _SHARDS[key] = (exercise, {})  # the exercise is held: an unnamed one is known by its id
        if len(_SHARDS) > 8:
            _SHARDS.popitem(last=False)
    _SHARDS.move_to_end(key)
    known = kept[1]
    for s in students:
        if s not in known:
            known[s] = draw_shard(exercise, s, secret, cores)
    return known


def _run(exercise, action, items, secret, reveal, classmates, cores, progress) -> list[dict]:
    if cores == 1 or len(items) < PARALLEL_FROM:
        out: list[dict] = []
        for i in range(0, len(items), _CHUNK):
            out.extend(_chunk((exercise, action, items[i:i + _CHUNK], secret, reveal, classmates)))
            if progress:
                progress(len(items[i:i + _CHUNK]))
        return out
    with _collector_paused():
        return _spread(exercise, action, items, secret, reveal, classmates, cores, progress)


@contextmanager
def _collector_paused():
    """This process's cyclic garbage collector paused while it feeds the workers and reads their rows.

    The rows arrive as new objects (plain dicts, lists and strings: no cycles, each freed by its reference
    count), and at Python's default thresholds they set off collections that walk everything this process holds:
    after serial sessions (a notebook, the benchmark) its caches of variants, 0.16 s of a 0.22 s share of the CPU
    in a parallel session of ``strip_cutter_cut``, taken from the two cores the workers run on.
    """
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def _spread(exercise, action, items, secret, reveal, classmates, cores, progress) -> list[dict]:
    """The roster over ``cores`` workers, in chunks, and the rows back in the roster's order."""
    out = [None] * len(items)
    futures = []
    # The same student goes to the same worker in every pass, and so do classmates who drew the same values
    # (the worker solves their draw once): the shard follows the student's first draw.
    shard = _shards(exercise, [s for s, _ in items], secret, cores)
    for k, pool in enumerate(_workers(cores)):
        index = [j for j, (s, _) in enumerate(items) if shard[s] == k]
        for i in range(0, len(index), _CHUNK):
            part = index[i:i + _CHUNK]
            futures.append((part, pool.submit(_chunk, (exercise, action, [items[j] for j in part], secret, reveal,
                                                       classmates))))
    for part, future in futures:
        for j, result in zip(part, future.result()):
            out[j] = result
        if progress:
            progress(len(part))
    return out
