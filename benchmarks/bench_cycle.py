"""Whole-cycle benchmark: the strip cutter at n = 3600 crank angles.

Run directly: ``.venv/bin/python benchmarks/bench_cycle.py [n] [k]``.

Times, each the best of k runs with ``time.perf_counter`` after a warm-up
(garbage collector off while timing, as ``timeit`` does):

  1  ``sweep(problem, n)``: kinematics + every joint force + T12 at n angles
  2  ``cycle.flywheel(0.05)``: Norton's flywheel sizing on that torque curve
  3  ``joint_force_index(problem, n)``: a second, static force analysis and the index
  4  ``cycle.peaks()``: peak of every joint force and of T12 (for information)
  5  ``flywheel.smoothed_torque()``: the motor's torque with the flywheel
     (a linear recurrence over the n steps, for information)

The aim (from the issue) is rows 1 + 2 + 3 <= 50 ms. If it is not met, the
script profiles one run of the three and prints where the time goes.
"""

from __future__ import annotations

import cProfile
import gc
import io
import pstats
import sys
import time

from graphkin import catalog
from graphkin.cycle import joint_force_index, sweep

AIM = 0.050  # s


def best_of(fn, k: int, clock=time.perf_counter) -> float:
    """The shortest of ``k`` runs of ``fn`` after a warm-up, the collector off [s of ``clock``]."""
    fn()  # warm-up
    gc_was = gc.isenabled()
    gc.disable()
    try:
        best = float("inf")
        for _ in range(k):
            t = clock()
            fn()
            best = min(best, clock() - t)
    finally:
        if gc_was:
            gc.enable()
    return best


def main(n: int = 3600, k: int = 20) -> int:
    problem = catalog.load("strip_cutter")
    cycle = sweep(problem, n)
    rows = [
        ("sweep(problem, n)", best_of(lambda: sweep(problem, n), k)),
        ("cycle.flywheel(0.05)", best_of(lambda: cycle.flywheel(0.05), k)),
        ("joint_force_index(problem, n)", best_of(lambda: joint_force_index(problem, n), k)),
    ]
    total = sum(t for _, t in rows)
    peaks = best_of(cycle.peaks, k)
    flywheel = cycle.flywheel(0.05)
    smoothed = best_of(flywheel.smoothed_torque, k)
    print(f"strip cutter, n = {n} crank angles, best of {k}")
    print(f"{'part':<34}{'time [ms]':>11}{'share':>8}")
    for name, t in rows:
        print(f"{name:<34}{t * 1e3:>11.3f}{t / total:>8.0%}")
    print(f"{'total (sweep + flywheel + JFI)':<34}{total * 1e3:>11.3f}{'':>8}")
    print(f"{'cycle.peaks() (information)':<34}{peaks * 1e3:>11.3f}")
    print(f"{'smoothed_torque() (information)':<34}{smoothed * 1e3:>11.3f}")
    met = total <= AIM
    print(f"aim: total <= {AIM * 1e3:g} ms: {'MET' if met else 'NOT MET'}")
    if not met:
        print("\nwhere the time goes (one run, cumulative, top 15):")
        prof = cProfile.Profile()
        prof.enable()
        sweep(problem, n).flywheel(0.05)
        joint_force_index(problem, n)
        prof.disable()
        buf = io.StringIO()
        pstats.Stats(prof, stream=buf).sort_stats("cumulative").print_stats(15)
        print(buf.getvalue())
    return 0 if met else 1


if __name__ == "__main__":
    sys.exit(main(*(int(a) for a in sys.argv[1:3])))
