"""Exercises benchmark: make + key + grade for a roster of 1000 students, and the grader alone.

Run directly: ``.venv/bin/python benchmarks/bench_exercises.py [students]``.

For each catalog exercise, the time to make every student's sheet and key
and grade their answers (the key's own printed answers, so every question
goes through the whole grader) through :func:`graphkin.exercises.batch.run_roster`,
the path ``graphkin exercise ... --roster`` takes:

  serial     one process
  parallel   every core (``os.cpu_count()``), chunks of 50 students

and the same three passes each from cold (a new secret for each, as three
separate ``graphkin exercise`` commands would be), and the time to grade one
answer sheet whose answers are all slipped (the sign reversed: the grader then
searches the slips, re-solving where needed). In one session a worker keeps
the variants it made for the sheets, so the keys and grades reuse them.
The aim (issue 9) is make + key + grade for 1000 students in <= 2 s on 2 cores.
"""

from __future__ import annotations

import os
import sys
import time

from graphkin import exercises
from graphkin.exercises.batch import run_roster

AIM = 2.0  # s for 1000 students


def roster_time(ex, students, workers, secret) -> tuple[float, float]:
    """(make + key + grade in one session, the three passes each from cold) [s]."""
    t = time.perf_counter()
    sheets = run_roster(ex, "make", students, secret, workers=workers)
    keys = run_roster(ex, "key", students, secret, workers=workers)
    answers = [{q["id"]: q["answer"]["text"] for q in k["questions"]} for k in keys]
    grades = run_roster(ex, "grade", students, secret, answers=answers, workers=workers)
    session = time.perf_counter() - t
    assert len(sheets) == len(grades) == len(students)
    assert all(g["score"] == g["max"] for g in grades), "a key's own answers must earn full marks"
    cold = 0.0
    for action in ("make", "key", "grade"):
        # A new secret is a new set of variants: nothing made before helps (three separate commands).
        secret = secret + "+"
        t = time.perf_counter()
        run_roster(ex, action, students, secret, workers=workers, answers=answers if action == "grade" else None)
        cold += time.perf_counter() - t
    return session, cold


def main(n: int = 1000) -> int:
    students = [f"s{i:05d}" for i in range(n)]
    cores = os.cpu_count() or 1
    print(f"make + key + grade for {n} students; {cores} cores; aim {AIM:g} s on 2 cores\n")
    print(f"{'':<26}{'one session [s]':>30}{'three cold passes [s]':>30}")
    print(f"{'exercise':<26}{'serial':>15}{'parallel':>15}{'serial':>15}{'parallel':>15}{'slipped sheet [ms]':>20}")
    worst = 0.0
    for name in exercises.names():
        ex = exercises.load(name)
        exercises.variant(ex, "warm-up").key()
        serial, serial_cold = roster_time(ex, students, 1, f"bench-{name}-1")
        parallel, parallel_cold = roster_time(ex, students, cores, f"bench-{name}-{cores}")
        v = exercises.variant(ex, "slips")
        slipped = {}
        for q in v.key()["questions"]:
            text = q["answer"]["text"]
            slipped[q["id"]] = text[1:] if text.startswith("−") else "−" + text
        t = time.perf_counter()
        for _ in range(20):
            v = exercises.variant(ex, "slips")
            v.grade(slipped)
        slip_ms = (time.perf_counter() - t) / 20 * 1e3
        worst = max(worst, parallel)
        print(f"{name:<26}{serial:>15.2f}{parallel:>15.2f}{serial_cold:>15.2f}{parallel_cold:>15.2f}{slip_ms:>20.1f}")
    verdict = "met" if worst <= AIM else "NOT met"
    print(f"\nslowest exercise, one session on {cores} cores: {worst:.2f} s for {n} students (aim {AIM:g} s: {verdict})")
    return 0


if __name__ == "__main__":
    sys.exit(main(*(int(a) for a in sys.argv[1:])))
