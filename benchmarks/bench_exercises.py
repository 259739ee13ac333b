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

Wall-clock times follow the machine's load: on cores shared with other jobs a
worker waits for its turn. So the one-session parallel run also reports the
CPU time of its busiest worker and of this process (from ``/proc``): on free
cores the session takes about the larger of the workers' CPU plus this
process's share (the rosters it cuts and the results it reads), whatever the
load while it was measured.
"""

from __future__ import annotations

import os
import sys
import time

from graphkin import exercises
from graphkin.exercises.batch import run_roster

AIM = 2.0  # s for 1000 students
_TICK = os.sysconf("SC_CLK_TCK")


def children_cpu() -> dict[int, float]:
    """CPU time (user + system) of each live child process of this one, by pid [s] (Linux's ``/proc``)."""
    me, out = os.getpid(), {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    fields = f.read().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[1]) == me:
                out[int(entry)] = (int(fields[11]) + int(fields[12])) / _TICK
    return out


def roster_time(ex, students, workers, secret) -> tuple[float, float, float, float]:
    """(make + key + grade in one session, the three passes each from cold [s]; in the session, the CPU of the
    busiest worker and of this process [s])."""
    before, mine = children_cpu(), time.process_time()
    t = time.perf_counter()
    sheets = run_roster(ex, "make", students, secret, workers=workers)
    keys = run_roster(ex, "key", students, secret, workers=workers)
    answers = [{q["id"]: q["answer"].get("drawing", q["answer"]["text"]) for q in k["questions"]} for k in keys]
    grades = run_roster(ex, "grade", students, secret, answers=answers, workers=workers)
    session = time.perf_counter() - t
    mine = time.process_time() - mine
    busiest = max([cpu - before.get(pid, 0.0) for pid, cpu in children_cpu().items()] + [0.0])
    assert len(sheets) == len(grades) == len(students)
    assert all(g["score"] == g["max"] for g in grades), "a key's own answers must earn full marks"
    cold = 0.0
    for action in ("make", "key", "grade"):
        # A new secret is a new set of variants: nothing made before helps (three separate commands).
        secret = secret + "+"
        t = time.perf_counter()
        run_roster(ex, action, students, secret, workers=workers, answers=answers if action == "grade" else None)
        cold += time.perf_counter() - t
    return session, cold, busiest, mine


def main(n: int = 1000) -> int:
    students = [f"s{i:05d}" for i in range(n)]
    cores = os.cpu_count() or 1
    load = os.getloadavg()[0]
    print(f"make + key + grade for {n} students; {cores} cores; aim {AIM:g} s on 2 cores; load average {load:.2f}\n")
    print(f"{'':<26}{'one session [s]':>30}{'parallel session CPU [s]':>26}{'three cold passes [s]':>30}")
    print(f"{'exercise':<26}{'serial':>15}{'parallel':>15}{'worker':>13}{'feeder':>13}{'serial':>15}{'parallel':>15}"
          f"{'slipped sheet [ms]':>20}")
    worst, worst_cpu = 0.0, 0.0
    for name in exercises.names():
        ex = exercises.load(name)
        exercises.variant(ex, "warm-up").key()
        serial, serial_cold, _, _ = roster_time(ex, students, 1, f"bench-{name}-1")
        parallel, parallel_cold, busiest, feeder = roster_time(ex, students, cores, f"bench-{name}-{cores}")
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
        worst, worst_cpu = max(worst, parallel), max(worst_cpu, busiest + feeder)
        print(f"{name:<26}{serial:>15.2f}{parallel:>15.2f}{busiest:>13.2f}{feeder:>13.2f}{serial_cold:>15.2f}"
              f"{parallel_cold:>15.2f}{slip_ms:>20.1f}")
    verdict = "met" if worst <= AIM else "NOT met"
    print(f"\nslowest exercise, one session on {cores} cores: {worst:.2f} s for {n} students (aim {AIM:g} s: {verdict});"
          f" load average {os.getloadavg()[0]:.2f} at the end")
    print(f"on free cores (the busiest worker's CPU and the feeding process's, added): at most {worst_cpu:.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main(*(int(a) for a in sys.argv[1:])))
