"""Drawn answers benchmark (issue 38, "Keep"): grading one drawn answer, and 1000 students' drawn answers from keys.

Run: ``PYTHONPATH=. .venv/bin/python benchmarks/bench_drawn.py [students] [distinct]``.

For each catalog exercise of drawn questions (``draw_*``):

  one answer   :func:`graphkin.exercises.grade_drawing` of one drawing on a student's keyed variant
               (:class:`graphkin.exercises.keys.KeyedVariant`), CPU time per answer, for the right drawing, the
               last slip's drawing (every target before it tried) and a wrong one (every target tried, then the
               faults found); aim <= 5 ms
  roster       every question of ``students`` students' sheets graded from keys (:meth:`Keys.grade`, as an
               autograder does), serial and on 2 worker processes (each reads the keys once); aim <= 5 s on 2 cores

Making the keys is not timed (it is the export's work, done once where the secret is). To keep the run short the keys
hold ``distinct`` students' entries (each a variant solved), repeated under ``students`` ids: grading reads an entry,
whoever it belongs to, so the grading cost is the same.
"""

from __future__ import annotations

import copy
import json
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor

from graphkin import exercises
from graphkin.exercises.drawn_grading import grade_drawing
from graphkin.exercises.drawn_tasks import task_of
from graphkin.exercises.keys import Keys, make_keys

AIM_ONE = 5e-3  # s per drawn answer
AIM_ROSTER = 5.0  # s for 1000 students on 2 cores

_KEYS = None


def _drawing(task, elements) -> str:
    return json.dumps({"drawing": 1, "question": task["question"], "space": task["space"], "unit": task["unit"],
                       "elements": elements})


def sheets(keys: Keys, students) -> list[dict]:
    """Each student's answers: every drawn question answered with one of its targets, in turn (right, slips)."""
    out = []
    for n, s in enumerate(students):
        v = keys.variant(s)
        answers = {}
        for q in keys.exercise.questions:
            task = task_of(v, q.id, practice=True)
            targets = task["check"]["targets"]
            answers[q.id] = _drawing(task, targets[n % len(targets)]["elements"])
        out.append(answers)
    return out


def _init(data):
    global _KEYS
    _KEYS = Keys(data)


def _grade_chunk(chunk):
    return [_KEYS.grade(s, a)["score"] for s, a in chunk]


def one_answer(keys: Keys, student: str) -> list[tuple[str, str, float]]:
    """(question, which drawing, CPU ms per grade) for the right, the last slip's and a wrong drawing."""
    v = keys.variant(student)
    rows = []
    for q in keys.exercise.questions:
        task = task_of(v, q.id, practice=True)
        targets = task["check"]["targets"]
        L = task["check"]["tolerance"]["length"]
        wrong = copy.deepcopy(targets[0]["elements"])
        for e in wrong:
            for key in ("through", "at", "from", "to"):
                for p in (e.get(key, []) if key == "through" else [e[key]] if key in e else []):
                    p[0] += 50 * L
        for label, elements in (("right", targets[0]["elements"]), (f"slip {targets[-1]['slip']}",
                                                                   targets[-1]["elements"]), ("wrong", wrong)):
            text = _drawing(task, elements)
            reps = 2000
            t = time.process_time()
            for _ in range(reps):
                grade_drawing(v, q.id, text)
            rows.append((q.id, label, (time.process_time() - t) / reps * 1e3))
    return rows


def main(n: int = 1000, distinct: int = 40) -> int:
    print(f"drawn answers: {n} students ({distinct} distinct keys entries); load average {os.getloadavg()[0]:.2f}\n")
    worst_one, worst_roster = 0.0, 0.0
    table = []
    for name in [x for x in exercises.names() if x.startswith("draw_")]:
        ex = exercises.load(name)
        base = [f"s{i:05d}" for i in range(distinct)]
        data = make_keys(ex, base)
        entries = list(data["students"].values())
        students = [f"s{i:05d}" for i in range(n)]
        data["students"] = {s: entries[i % distinct] for i, s in enumerate(students)}
        data = json.loads(json.dumps(data))  # as an autograder reads them
        keys = Keys(data)
        for qid, label, ms in one_answer(keys, students[0]):
            table.append((name, qid, label, ms))
            worst_one = max(worst_one, ms)
        work = list(zip(students, sheets(keys, students)))
        t, c = time.perf_counter(), time.process_time()
        scores = [keys.grade(s, a)["score"] for s, a in work]
        serial, serial_cpu = time.perf_counter() - t, time.process_time() - c
        chunks = [work[i::2] for i in range(2)]
        with ProcessPoolExecutor(2, initializer=_init, initargs=(data,)) as pool:
            list(pool.map(_grade_chunk, [[w] for w in work[:2]]))  # the workers up and the keys read
            t = time.perf_counter()
            par = [x for part in pool.map(_grade_chunk, chunks) for x in part]
            parallel = time.perf_counter() - t
        assert sorted(par) == sorted(scores)
        worst_roster = max(worst_roster, parallel)
        table.append((name, f"{n} students", "serial wall / CPU, 2 cores wall", (serial, serial_cpu, parallel)))
    print(f"{'exercise':<24}{'question':<16}{'drawing':<28}{'CPU ms per answer':>18}")
    for name, qid, label, ms in table:
        if isinstance(ms, tuple):
            print(f"{name:<24}{qid:<16}{label:<34}{ms[0]:>7.2f} s /{ms[1]:>6.2f} s /{ms[2]:>6.2f} s")
        else:
            print(f"{name:<24}{qid:<16}{label:<28}{ms:>18.3f}")
    met = "MET" if worst_one <= AIM_ONE * 1e3 else "NOT MET"
    print(f"\nslowest answer: {worst_one:.3f} ms (aim {AIM_ONE * 1e3:g} ms: {met})")
    print(f"slowest roster of {n} on 2 cores: {worst_roster:.2f} s (aim {AIM_ROSTER:g} s: "
          f"{'MET' if worst_roster <= AIM_ROSTER * n / 1000 else 'NOT MET'}); load average {os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(*(int(a) for a in sys.argv[1:])))
