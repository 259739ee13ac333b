"""A class's handouts at once: a sheet and a key per student, on all cores.

Each student's handouts depend on nothing but their own variant, so the
roster is spread over a pool of worker processes, a few students per task
(one student's sheet and key are made in the same task, from one solved
variant, sharing their drawings). Every file is written atomically by the
worker that made it (:func:`graphkin.files.write_bytes`): an interrupted
batch leaves whole files or none, never half a PDF.
"""

from __future__ import annotations

import gc
import hashlib
import multiprocessing
import os
import re
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.handout import build, write
from graphkin.handout.document import subject

CHUNK = 2
"""Students per task. Sending a task costs about a millisecond and a student's sheet and key nearly a second,
so small tasks cost nothing and keep every core busy to the end (the last task is all one core waits for)."""

PARALLEL_FROM = 4
"""Rosters smaller than this are made in this process: starting workers would cost more than it saves."""

SUFFIX = {"pdf": ".pdf", "html": ".html", "md": ".md"}


def file_stem(student: str) -> str:
    """A file name for a student id: the id if it is plain, else a cleaned id and a short hash of it.

    Two different ids never share a file, and an id cannot climb out of the
    folder (``../x``) or hide a file (``.x``).

    Examples
    --------
    >>> file_stem("s001"), file_stem("Ana María")
    ('s001', 'Ana_Mar_a-8358ed')
    """
    clean = re.sub(r"[^A-Za-z0-9_-]", "_", student).strip("_") or "student"
    if clean == student:
        return clean
    return f"{clean[:60]}-{hashlib.sha256(student.encode('utf-8')).hexdigest()[:6]}"


def _one(exercise: str, student: str, secret: str, versions: tuple, fmt: str, folder: str, Cs) -> tuple:
    """Make one student's handouts; (student, files written, error or "")."""
    try:
        s = subject(exercise, student=student, secret=secret, Cs=Cs)
        written = []
        for version in versions:
            doc = build(s, version=version)
            path = Path(folder) / f"{file_stem(student)}_{version}{SUFFIX[fmt]}"
            written += [str(p) for p in write(doc, path)]
        return student, written, ""
    except GraphkinError as exc:
        return student, [], str(exc)


_WORKER: list = []
"""Set in a roster's worker process (:func:`worker_start`): ``[False]``, then ``[True]`` once it has settled."""


def worker_start():
    """A roster's worker process starts: it settles (:func:`_settle`) after its first task."""
    _WORKER.append(False)


def _settle():
    """After a worker's first task: what it has loaded for good (modules, fonts, the typst compiler, text laid out
    once) is put out of the garbage collector's reach, and it collects less often.

    Every figure leaves reference cycles behind, so the collector runs hundreds of times a student, and each
    full pass walked the hundred thousand objects the worker keeps for its life: 8 % of a student's time,
    half of that after :func:`gc.freeze`, two fifths with the larger first threshold as well. Only a worker process
    does this; a roster made in the caller's process (a notebook) leaves its collector as it is.
    """
    gc.collect()
    gc.freeze()
    gc.set_threshold(5000, 10, 10)
    _WORKER[0] = True


def write_chunk(args) -> list[tuple]:
    """One task of a roster: each of its students' handouts written, as rows ``(student, paths, error)``.

    ``args`` is ``(exercise, students, secret, versions, fmt, folder, Cs)``, as :func:`make_roster` cuts them.
    """
    exercise, students, secret, versions, fmt, folder, Cs = args
    rows = [_one(exercise, st, secret, versions, fmt, folder, Cs) for st in students]
    if _WORKER == [False]:
        _settle()
    return rows


def make_roster(exercise: str, students, folder, *, secret: str = "", versions=("sheet", "key"), fmt: str = "pdf",
                Cs=None, workers: int | None = None, progress=None) -> list[tuple]:
    """Write every student's handouts into ``folder``.

    Parameters
    ----------
    exercise : str
        Catalog name or file of the exercise (each worker reads it once).
    students : sequence of str
    folder : str or Path
        Made if missing; each student's files are ``<id>_sheet.pdf``, ``<id>_key.pdf``.
    secret : str
    versions : tuple of {"sheet", "key", "blank"}
    fmt : {"pdf", "html", "md"}
    Cs : float, optional
    workers : int, optional
        Processes (default: every core).
    progress : callable, optional
        Called with the number of students just finished.

    Returns
    -------
    list of (student, files, error)
        In roster order; ``error`` is "" for a student whose handouts were written.
    """
    students = list(students)
    folder = str(folder)
    cores = workers or os.cpu_count() or 1
    tasks = [(exercise, students[k:k + CHUNK], secret, tuple(versions), fmt, folder, Cs)
             for k in range(0, len(students), CHUNK)]
    results: dict[int, list] = {}
    if cores == 1 or len(students) < PARALLEL_FROM:
        for k, task in enumerate(tasks):
            results[k] = write_chunk(task)
            if progress:
                progress(len(task[1]))
    else:
        # Fresh interpreters, not forks: a fork of a process whose other threads hold a lock (typst's
        # compiler threads once a PDF has been made here, a notebook's kernel) can wait on it for ever.
        spawn = multiprocessing.get_context("spawn")
        with ProcessPoolExecutor(max_workers=min(cores, len(tasks)), mp_context=spawn,
                                 initializer=worker_start) as pool:
            futures = {pool.submit(write_chunk, task): k for k, task in enumerate(tasks)}
            for future in as_completed(futures):
                k = futures[future]
                results[k] = future.result()
                if progress:
                    progress(len(results[k]))
    return [row for k in range(len(tasks)) for row in results[k]]
