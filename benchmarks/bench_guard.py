"""The motion guard's cost (issue 35, "Keep"): the polygons and instant centres of graphkin checkouts, A/B, CPU time.

``construct_kinematics`` and ``instant_centres`` at every position of a few catalog problems (and the four-bar of
``bench_fourbar.py`` over 360 crank angles), timed with ``time.process_time`` (CPU time: on a machine shared with
other work, wall time measures the neighbours). Each checkout's graphkin runs in a worker process of its own (the
same interpreter, its folder first on ``sys.path``); the workers are asked in turn, round after round, so that both
see the same load; the table gives each checkout's median over the rounds [µs per position] and the ratio to the
first checkout's. "warm" repeats the positions of one kinematics (what is worked out once per kinematics is made
before the timing); "cold" goes once over the positions of a new kinematics each time (solved again before the
timing, of the same mechanism, whose plan the solver keeps), so that what is worked out once per kinematics is
timed too, spread over its positions. Then, end to end (a new process each run, its CPU time: user + system, from
``getrusage`` of the children, alternately too): ``graphkin solve PROBLEM`` and ``graphkin solve PROBLEM --json
--motion-polygons`` for a few problems of one position (``--solve``), and ``graphkin solve strip_cutter --json``
with and without ``--motion-polygons``.

    .venv/bin/python benchmarks/bench_guard.py [--rounds 15] [--runs 9] [--problems a,b] [--solve a,b] BASE_DIR [OTHER_DIR ...]

Each DIR holds a ``graphkin`` package, e.g. ``git archive 405e4a9 graphkin | tar -x -C /tmp/base`` for the commit
before the guard; this checkout is added as the last unless given. A measurement, not a test: exit code 0.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
PROBLEMS = ("strip_cutter", "slider_crank_friction", "shaper_six_bar", "gearset", "fourbar_dynamic_makdin")
SOLVED = ("gearset", "shaper_six_bar")
"""Problems of one position whose ``graphkin solve PROBLEM`` (the printed report) and ``graphkin solve PROBLEM
--json --motion-polygons`` (the polygons and instant centres too, each checked by the guard) are timed end to end."""

WORKER = r"""
import gc, json, math, sys, time
sys.path.insert(0, sys.argv[1])
sys.path.insert(1, sys.argv[2])
from fourbar_linkage import fourbar
from graphkin import catalog
from graphkin.graphical import construct_kinematics, instant_centres
from graphkin.kinematics import solve_kinematics

n = 360
mech = fourbar()
makers = {"four-bar (360)": lambda: solve_kinematics(mech, [2 * math.pi * k / n for k in range(n)], 900 * 2 * math.pi / 60)}
for name in filter(None, sys.argv[3].split(",")):
    makers[name] = catalog.load(name).kinematics
cases = {name: make() for name, make in makers.items()}
for kin in cases.values():  # a warm-up: caches filled, code paths taken once
    for i in range(kin.n):
        construct_kinematics(kin, i), instant_centres(kin, i)


def cpu(fn, name, reps, cold):
    kin = cases[name]
    best = math.inf
    for _ in range(reps):
        gc.collect()
        one = makers[name]() if cold else kin  # a new kinematics (the same mechanism): nothing kept for it yet
        t = time.process_time()
        for i in range(one.n):
            fn(one, i)
        best = min(best, time.process_time() - t)
    return best / kin.n * 1e6


for line in sys.stdin:
    out = {}
    for name, kin in cases.items():
        reps = max(1, 60 // kin.n)
        out[name] = [cpu(fn, name, reps, cold) for cold in (False, True) for fn in (construct_kinematics, instant_centres)]
    print(json.dumps(out), flush=True)
"""


def _workers(roots: list[str], problems: str) -> list[subprocess.Popen]:
    return [subprocess.Popen([sys.executable, "-c", WORKER, root, str(HERE), problems], stdin=subprocess.PIPE,
                             stdout=subprocess.PIPE, text=True, cwd=tempfile.gettempdir()) for root in roots]


def _cli_cpu(root: str, argv: list[str]) -> float:
    """CPU seconds (user + system) of one ``python -m graphkin ...`` run with ``root``'s graphkin."""
    env = {**os.environ, "PYTHONPATH": root}
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([sys.executable, "-m", "graphkin", *argv], env=env, cwd=tempfile.gettempdir(), check=True,
                   stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("roots", nargs="+", help="folders that hold a graphkin package (the first is the baseline)")
    parser.add_argument("--rounds", type=int, default=15, help="rounds of the per-position timing")
    parser.add_argument("--runs", type=int, default=9, help="runs of each command, per checkout")
    parser.add_argument("--problems", default=",".join(PROBLEMS), help="catalog problems, comma-separated")
    parser.add_argument("--solve", default=",".join(SOLVED),
                        help="catalog problems to time `graphkin solve PROBLEM` of, end to end, comma-separated")
    args = parser.parse_args()
    roots = [str(Path(r).resolve()) for r in args.roots]
    mine = str(HERE.parent)
    if mine not in roots:
        roots.append(mine)
    names = [f"#{k} {Path(r).name}" for k, r in enumerate(roots)]
    print("checkouts: " + "; ".join(f"{n} = {r}" for n, r in zip(names, roots)))

    workers = _workers(roots, args.problems)
    samples: list[dict] = [dict() for _ in roots]
    for _ in range(args.rounds):
        for w, got in zip(workers, samples):
            w.stdin.write("go\n")
            w.stdin.flush()
            for case, times in json.loads(w.stdout.readline()).items():
                got.setdefault(case, []).append(times)
    for w in workers:
        w.stdin.close()
        w.wait()

    for start, how in ((0, "warm"), (2, "cold")):
        print(f"\nCPU µs per position, {how}, median of {args.rounds} alternating rounds (ratio to {names[0]})")
        print(f"{'problem':<24}" + "".join(f"{n[:12] + ' poly':>18}{'centres':>14}" for n in names))
        for case in samples[0]:
            row = f"{case:<24}"
            base = [statistics.median(t[k] for t in samples[0][case]) for k in (start, start + 1)]
            for got in samples:
                p, c = (statistics.median(t[k] for t in got[case]) for k in (start, start + 1))
                row += f"{p:>9.1f} ({p / base[0]:4.2f}){c:>7.1f} ({c / base[1]:4.2f})"
            print(row)

    print(f"\nCPU ms of a whole command (new process), median of {args.runs} alternating runs")
    commands = [argv for name in args.solve.split(",") if name
                for argv in (["solve", name], ["solve", name, "--json", "--motion-polygons"])]
    commands += [["solve", "strip_cutter", "--json"], ["solve", "strip_cutter", "--json", "--motion-polygons"]]
    for argv in commands:
        for root in roots:  # once each before timing: bytecode compiled
            _cli_cpu(root, argv)
        runs: list[list[float]] = [[] for _ in roots]
        for _ in range(args.runs):
            for root, got in zip(roots, runs):
                got.append(_cli_cpu(root, argv))
        medians = [statistics.median(r) * 1e3 for r in runs]
        print(f"graphkin {' '.join(argv):<48}" + "".join(f"{m:>9.0f} ({m / medians[0]:4.2f})" for m in medians))
    return 0


if __name__ == "__main__":
    sys.exit(main())
