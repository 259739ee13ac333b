"""Design-study benchmark: 1000 designs × 360 crank angles of the strip cutter, a four-bar (issue 39).

Run from the repository: ``PYTHONPATH=. .venv/bin/python benchmarks/bench_study.py [designs] [repeats]``.

The designs: 40 crank lengths A0A from 80 to 90 mm × 25 coupler masses from 1 to 5 kg (every one turns fully), each
swept over 360 crank angles (364 positions with the samples either side of the cutting force's switching angles).
CPU time (``time.process_time``), the least of ``repeats`` runs (3 unless said) of each of

  1  ``study(...)``, as a user calls it: the designs solved in batches over designs × positions
     (graphkin/analytical/designs.py), the figures of merit read off the (designs, positions) arrays
  2  the loop of single solves it replaces: per design, set_field on the file's data, build_problem, sweep, and
     the figures of merit read off the Cycle (what tests/cycle/test_study.py compares with)

run in turn (study, loop, study, loop, ...: a load that comes and goes on the shared machine falls on both), then
where the study's time goes: the batched solve (done again on its own) and the rest (reading the file and each
field's values, the figures of merit); and the peak memory of a study (``tracemalloc``, a separate run) per
design-position. The load average is printed before and after. The aims (issue 39): the study ≤ 2 s, ≥ 20× faster
than the loop, ≤ 200 B per design-position.
"""

from __future__ import annotations

import os
import sys
import time
import tomllib
import tracemalloc

import numpy as np

from graphkin import catalog
from graphkin.analytical.designs import numbers, solve_designs
from graphkin.cycle import study, sweep
from graphkin.cycle.studies import batch_order, merit
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


def batched_solve(data: dict, vary: dict, designs: tuple, q: np.ndarray) -> float:
    """CPU time of the study's batched solve alone: every design's numbers, in the study's batches (each crank
    length's 25 coupler masses sharing one kinematic pass, ``batch_order``)."""
    problems = [_build(data, vary, d.values) for d in designs]
    mech = problems[0].mechanism
    own = [numbers(p.mechanism) for p in problems]
    values = [list(v) for v in vary.values()]
    at = np.array([[values[f].index(v) for f, v in enumerate(d.values)] for d in designs])
    batches = [(rows.tolist(), per) for rows, per in batch_order(at, [0], len(q))]  # field 0 (the crank) moves it

    def solve():
        for rows, per in batches:
            solve_designs(mech, [own[i] for i in rows], q, [problems[i].q_dot[0] for i in rows],
                          [problems[i].q_ddot[0] for i in rows], per=per)

    return cpu(solve)[1]


def main(designs: int = 1000, repeats: int = 3) -> int:
    vary = grid(designs)
    data = tomllib.loads(catalog.path("strip_cutter").read_text(encoding="utf-8"))
    load = os.getloadavg()[0]
    study("strip_cutter", {"links[1].mass": ["2 kg"]}, n=N)  # warm-up: imports, pint's registry
    s = study("strip_cutter", vary, n=N)
    D, positions = len(s.designs), sweep(catalog.load("strip_cutter"), N).n
    assert all(d.ok for d in s.designs) and s.vectorised
    t_study = t_loop = t_solve = float("inf")
    q = sweep(catalog.load("strip_cutter"), N).q
    for _ in range(max(1, repeats)):
        t_study = min(t_study, cpu(lambda: study("strip_cutter", vary, n=N))[1])
        t_loop = min(t_loop, cpu(lambda: [merit(sweep(_build(data, vary, d.values), N), d.values, s.Cs)
                                          for d in s.designs])[1])
        t_solve = min(t_solve, batched_solve(data, vary, s.designs, q))
    split = {"the batched solve": t_solve, "the rest (reading the file, figures of merit)": t_study - t_solve}

    tracemalloc.start()
    study("strip_cutter", vary, n=N)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()

    cells = D * positions
    print(f"strip cutter: {D} designs × {positions} positions = {cells:,} design-positions "
          f"(vectorised over designs: {s.vectorised}); least CPU time of {max(1, repeats)} runs; "
          f"load average {load:.1f} before, {os.getloadavg()[0]:.1f} after")
    print(f"{'':28}{'CPU s':>9}{'designs/s':>12}{'µs/design-position':>20}{'speed-up':>10}")
    for name, t in (("study(...)", t_study), ("loop of single solves", t_loop)):
        print(f"{name:28}{t:9.3f}{D / t:12.0f}{1e6 * t / cells:20.3f}{t_loop / t:9.2f}×")
    print("the study's time:")
    for name, t in split.items():
        print(f"  {name:48}{t:9.3f} s{1e6 * t / cells:10.3f} µs/design-position")
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
    sys.exit(main(*(int(a) for a in sys.argv[1:3])))
