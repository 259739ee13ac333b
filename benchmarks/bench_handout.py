"""Speed of the handouts: one problem's key in each format, and a class's sheets and keys on all cores.

Issue 11's target: 200 students (a sheet and a key each, PDF) in at most 60 s on 2 cores.

    .venv/bin/python benchmarks/bench_handout.py                 # 200 students
    .venv/bin/python benchmarks/bench_handout.py --students 40 --exercise strip_cutter_cut

Prints a table; nothing is asserted (speed is measured here, never in a test).
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import tempfile
import time
from pathlib import Path


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


def roster(exercise: str, students: int, folder: Path) -> tuple[float, int]:
    from graphkin.handout.batch import make_roster

    ids = [f"s{k:04d}" for k in range(students)]
    t = time.perf_counter()
    rows = make_roster(exercise, ids, folder, secret="bench")
    elapsed = time.perf_counter() - t
    # CPU time of the workers: on a shared machine the wall time also counts other people's work.
    cpu = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = cpu.ru_utime + cpu.ru_stime
    failed = [r for r in rows if r[2]]
    if failed:
        raise SystemExit(f"{len(failed)} students failed, e.g. {failed[0]}")
    return elapsed, cpu, sum(len(r[1]) for r in rows)


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--students", type=int, default=200)
    p.add_argument("--exercise", default="double_slider_forces")
    args = p.parse_args()
    folder = Path(tempfile.mkdtemp(prefix="graphkin-bench-handout-"))
    try:
        t = time.perf_counter()
        import graphkin.handout  # noqa: F401  (what the command pays before any work)

        rows = [("import graphkin.handout", time.perf_counter() - t)]
        for name in ("double_slider", "strip_cutter"):
            rows += one_handout(name, folder)
        elapsed, cpu, files = roster(args.exercise, args.students, folder / "class")
        cores = os.cpu_count() or 1
        print(f"{'what':<48}{'seconds':>10}")
        for what, s in rows:
            print(f"{what:<48}{s:>10.2f}")
        print(f"{f'{args.exercise}: {args.students} students, {files} PDFs':<48}{elapsed:>10.1f}"
              f"   wall, {cores} cores (target ≤ 60 s)")
        print(f"{'  CPU of the workers':<48}{cpu:>10.1f}   {cpu / args.students:.2f} s per student: "
              f"{cpu / cores:.0f} s on {cores} free cores")
    finally:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
