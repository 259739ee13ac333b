"""Speed of the handouts: one problem's key in each format, and a class's sheets and keys on all cores.

Issue 11's target: 200 students (a sheet and a key each, PDF) in at most 60 s on 2 cores.

    .venv/bin/python benchmarks/bench_handout.py                 # 200 students of each exercise
    .venv/bin/python benchmarks/bench_handout.py --students 40 --exercise strip_cutter_cut
    .venv/bin/python benchmarks/bench_handout.py --students 0 --in-process 8 --exercise strip_cutter_cut

Prints a table; nothing is asserted (speed is measured here, never in a test). On a shared machine the
wall time counts other people's work too, so each roster's line also gives the CPU time its workers took
and the load average (1 min) before and after it: CPU / cores is what the roster takes on free cores.
Even the workers' CPU moves with the machine's load (two busy processes on two cores slow each other), so
``--in-process N`` also times N students one by one in this process, after one warm-up student: the
steadiest number to compare two versions by, run alternately (``PYTHONPATH`` at a copy of the other).
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import tempfile
import time
from pathlib import Path

EXERCISES = ("double_slider_forces", "strip_cutter_cut")
"""A four-figure key (the double slider) and a twenty-four-figure one (the strip cutter's graphical route)."""


def one_handout(name: str, folder: Path) -> list[tuple[str, float]]:
    from graphkin import handout

    rows = []
    t = time.perf_counter()
    doc = handout.build(name)
    rows.append((f"{name}: build (solve, construct)", time.perf_counter() - t))
    for fmt in ("pdf", "html", "md"):
        # The first format draws every figure; the others reuse the SVG.
        t = time.perf_counter()
        handout.write(doc, folder / f"{name}.{fmt}")
        rows.append((f"{name}: write .{fmt}", time.perf_counter() - t))
    return rows


def _children_cpu() -> float:
    """CPU seconds of the finished worker processes so far (user + system)."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def roster(exercise: str, students: int, folder: Path) -> dict:
    """Wall and worker CPU time of one class's sheets and keys, with the load around it."""
    from graphkin.handout.batch import make_roster

    ids = [f"s{k:04d}" for k in range(students)]
    load = os.getloadavg()[0]
    cpu = _children_cpu()
    t = time.perf_counter()
    rows = make_roster(exercise, ids, folder, secret="bench")
    elapsed = time.perf_counter() - t
    # The workers' CPU: what the roster costs whatever else the machine is doing.
    cpu = _children_cpu() - cpu
    failed = [r for r in rows if r[2]]
    if failed:
        raise SystemExit(f"{len(failed)} students failed, e.g. {failed[0]}")
    return {"wall": elapsed, "cpu": cpu, "files": sum(len(r[1]) for r in rows), "load": (load, os.getloadavg()[0])}


def in_process(exercise: str, students: int, folder: Path) -> list[float]:
    """CPU seconds of each student's sheet and key (PDF) made in this process, after one warm-up student."""
    from graphkin.handout.batch import worker_start, write_chunk

    def one(student: str) -> float:
        t = time.process_time()
        (row,) = write_chunk((exercise, [student], "bench", ("sheet", "key"), "pdf", str(folder), None))
        if row[2]:
            raise SystemExit(f"{student} failed: {row[2]}")
        return time.process_time() - t

    folder.mkdir(parents=True, exist_ok=True)
    worker_start()  # as a roster's worker: it settles after its first task
    one("warm-up")  # imports, fonts, the catalog, typst's compiler: what a worker pays once
    return [one(f"s{k:04d}") for k in range(students)]


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--students", type=int, default=200)
    p.add_argument("--in-process", type=int, default=0, metavar="N",
                   help="also time N students one by one in this process (CPU per student, median and fastest)")
    p.add_argument("--exercise", action="append",
                   help=f"an exercise (repeat for several; default: {', '.join(EXERCISES)})")
    args = p.parse_args()
    folder = Path(tempfile.mkdtemp(prefix="graphkin-bench-handout-"))
    cores = os.cpu_count() or 1
    try:
        t = time.perf_counter()
        import graphkin.handout  # noqa: F401  (what the command pays before any work)

        rows = [("import graphkin.handout", time.perf_counter() - t)]
        for name in ("double_slider", "strip_cutter"):
            rows += one_handout(name, folder)
        print(f"{'what':<52}{'seconds':>10}")
        for what, s in rows:
            print(f"{what:<52}{s:>10.2f}")
        for exercise in args.exercise or EXERCISES:
            if args.in_process:
                cpu = sorted(in_process(exercise, args.in_process, folder / f"{exercise}-one"))
                what = f"{exercise}: CPU per student, in one process"
                print(f"{what:<52}{statistics.median(cpu):>10.3f}   median of {len(cpu)} (fastest {cpu[0]:.3f})")
            if args.students <= 0:
                continue
            r = roster(exercise, args.students, folder / exercise)
            what = f"{exercise}: {args.students} students, {r['files']} PDFs"
            print(f"{what:<52}{r['wall']:>10.1f}"
                  f"   wall on {cores} cores (target ≤ 60 s); load {r['load'][0]:.2f} → {r['load'][1]:.2f}")
            print(f"{'  CPU of the workers':<52}{r['cpu']:>10.1f}   {r['cpu'] / args.students:.2f} s per student: "
                  f"{r['cpu'] / cores:.0f} s on {cores} free cores")
    finally:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
