"""Design-study benchmark: 1000 designs × 360 crank angles of the strip cutter (issue 39).

Run directly: ``.venv/bin/python benchmarks/bench_study.py [designs]``.

The designs: 40 crank lengths A0A from 80 to 90 mm × 25 coupler masses from 1 to 5 kg (every one turns fully), each
swept over 360 crank angles (364 positions with the samples either side of the cutting force's switching angles).
CPU time (``time.process_time``) of one run each:

  1  ``study(...)``: the whole study, as a user calls it
  2  the loop of single solves: per design, set_field on the file's data, build_problem, sweep, and the figures
     of merit read off the Cycle (what the equality test does)
  3  its parts, summed over the designs: building the problems, the sweeps, the figures of merit
  4  for reference, the floor a broadcast over designs would approach: one design swept at D·N positions in one
     batch, and 5 the arrays its figures of merit are read from (peaks, shaking force and moment, μ)

and the peak memory of the study (``tracemalloc``, a separate run) per design-position. The aims (issue 39):
the study ≤ 2 s and ≥ 20× faster than the loop, ≤ 200 B per design-position. Today the study *is* a loop over
designs (``Study.vectorised`` is False: see graphkin/cycle/study.py for what a broadcast needs), so row 1 ≈ row 2
and the speed-up aim is NOT MET by construction; rows 3 say where the time goes.
"""

from __future__ import annotations

import sys
import time
import tomllib
import tracemalloc

import numpy as np

from graphkin import catalog
from graphkin.cycle import study, sweep
from graphkin.cycle.study import merit
from graphkin.problem import build_problem
from graphkin.problem.fields import set_field

N = 360
AIM_TIME, AIM_SPEEDUP, AIM_BYTES = 2.0, 20.0, 200.0


def cpu(fn):
    t = time.process_time()
    value = fn()
    return value, time.process_time() - t


def grid(designs: int) -> dict:
    masses = 25 if designs >= 25 else 1
    lengths = max(1, designs // masses)
    return {"links[0].points.A[0]": [f"{x!r} mm" for x in np.linspace(80, 90, lengths).tolist()],
            "links[1].mass": [f"{x!r} kg" for x in np.linspace(1, 5, masses).tolist()]}


def main(designs: int = 1000) -> int:
    vary = grid(designs)
    data = tomllib.loads(catalog.path("strip_cutter").read_text(encoding="utf-8"))
    study("strip_cutter", {"links[1].mass": ["2 kg"]}, n=N)  # warm-up: imports, pint's registry
    s, t_study = cpu(lambda: study("strip_cutter", vary, n=N))
    D, positions = len(s.designs), sweep(catalog.load("strip_cutter"), N).n
    assert all(d.ok for d in s.designs)

    problems, t_build = cpu(lambda: [_build(data, vary, d.values) for d in s.designs])
    cycles, t_sweep = cpu(lambda: [sweep(p, N) for p in problems])
    _, t_merit = cpu(lambda: [merit(c, d.values, s.Cs) for c, d in zip(cycles, s.designs)])
    _, t_loop = cpu(lambda: [merit(sweep(_build(data, vary, d.values), N), d.values, s.Cs) for d in s.designs])
    # The floor a broadcast over designs would approach: one mechanism swept at D·N positions in one batch, and
    # the arrays the figures of merit are read from (the same work per position, no per-design Python).
    at = np.linspace(0.0, 2 * np.pi, len(s.designs) * sweep(problems[0], N).n, endpoint=False)
    batch, t_batch = cpu(lambda: sweep(problems[0], at=at))
    _, t_arrays = cpu(lambda: (batch.peaks(), batch.shaking_force(), batch.shaking_moment(),
                               batch.transmission_angle()))

    tracemalloc.start()
    study("strip_cutter", vary, n=N)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()

    cells = D * positions
    print(f"strip cutter: {D} designs × {positions} positions = {cells:,} design-positions "
          f"(vectorised over designs: {s.vectorised})")
    rows = [("1 study(...)", t_study), ("2 loop of single solves", t_loop), ("3a   build_problem", t_build),
            ("3b   sweep", t_sweep), ("3c   figures of merit", t_merit),
            ("4 one sweep of D·N positions", t_batch), ("5   its figures' arrays", t_arrays)]
    print(f"{'':28}{'CPU s':>9}{'µs/design-position':>20}{'ms/design':>11}")
    for name, t in rows:
        print(f"{name:28}{t:9.3f}{1e6 * t / cells:20.3f}{1e3 * t / D:11.3f}")
    per_cell = peak / cells
    print(f"peak memory of the study: {peak / 1e6:.1f} MB, {per_cell:.1f} B per design-position")
    scale = 1000 / D
    print(f"aim: study ≤ {AIM_TIME:g} s at 1000 designs: {'MET' if t_study * scale <= AIM_TIME else 'NOT MET'} "
          f"({t_study * scale:.2f} s)")
    speedup = t_loop / t_study
    print(f"aim: ≥ {AIM_SPEEDUP:g}× the loop: {'MET' if speedup >= AIM_SPEEDUP else 'NOT MET'} ({speedup:.2f}×)")
    print(f"aim: ≤ {AIM_BYTES:g} B per design-position: {'MET' if per_cell <= AIM_BYTES else 'NOT MET'}")
    return 0


def _build(data: dict, vary: dict, values: tuple):
    trial = dict(data)
    for field, value in zip(vary, values):
        set_field(trial, field, value, copy=True)
    return build_problem(trial)


if __name__ == "__main__":
    sys.exit(main(*(int(a) for a in sys.argv[1:2])))
