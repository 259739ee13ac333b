"""What ``graphkin solve double_slider -o f.png`` spends its time on (issue 40: under 1.5 s, no command slower).

Three tables, each from new processes, as a person runs the command:

1. The whole command, wall and CPU time (user + system, from ``getrusage`` of the children), median and least
   over the runs, twice: with graphkin's bytecode compiled (what ``pip install`` gives, and a checkout after its
   first run) and without it (``PYTHONDONTWRITEBYTECODE=1`` on a checkout with no ``__pycache__``: every run
   compiles the ~100 graphkin modules the command imports; the installed packages keep their bytecode). With
   ``--against DIR`` the same for DIR's graphkin, run in turn with this one so that both see the same load.
2. The phases of the command in one process (CPU time): numpy, graphkin's engine and report, matplotlib and
   graphkin.draw, the solution and its construction, drawing the figure, saving the PNG.
3. The load average before and after: on a machine shared with other work the wall time measures the others
   too; the CPU time much less.

A measurement, not a test: no timed assertion, exit code 0.

    .venv/bin/python benchmarks/bench_figure.py [--runs 9] [--against DIR]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parents[1] / "graphkin"

PHASES = r"""
import json, sys, time
t = [time.process_time()]
from graphkin.cli import single_threaded_blas
single_threaded_blas()
t.append(time.process_time())
from graphkin import catalog, report
t.append(time.process_time())
from graphkin import draw
import graphkin.draw.solution
t.append(time.process_time())
problem = catalog.load("double_slider")
result = problem.solve(None)
constructions = report.constructions(result)
t.append(time.process_time())
drawn = draw.draw_solution(constructions[0], result)
t.append(time.process_time())
draw.save(drawn, sys.argv[1])
t.append(time.process_time())
print(json.dumps([b - a for a, b in zip(t, t[1:])]))
"""
PHASE_NAMES = ["numpy (one BLAS thread)", "graphkin engine + report", "matplotlib + graphkin.draw",
               "solve + construct", "draw_solution", "save the PNG"]


def _copy(source: Path, into: Path) -> Path:
    """A copy of the package ``source`` without bytecode, in ``into`` (put on PYTHONPATH)."""
    shutil.copytree(source, into / "graphkin", ignore=shutil.ignore_patterns("__pycache__"))
    return into


def _environments(tmp: Path, name: str, package: Path) -> dict[str, dict]:
    """The command's environment with graphkin's bytecode kept (its own folder, made by a first run) and with
    none (no bytecode written; the package copied without any)."""
    base = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "PYTHONPYCACHEPREFIX")}
    base["GRAPHKIN_CACHE_DIR"] = str(tmp / f"cache-{name}")
    with_bc = dict(base, PYTHONPATH=str(_copy(package, tmp / f"{name}-bytecode")))
    without = dict(base, PYTHONPATH=str(_copy(package, tmp / f"{name}-source")), PYTHONDONTWRITEBYTECODE="1")
    return {"bytecode": with_bc, "no bytecode": without}


def _run(argv: list[str], env: dict, cwd: Path) -> tuple[float, float]:
    """One run: (wall, CPU) seconds."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    r = subprocess.run(argv, env=env, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        raise SystemExit(f"{' '.join(argv)} failed ({r.returncode}): {r.stderr.decode()[-500:]}")
    return wall, after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime


def _load() -> str:
    return "{:.2f} {:.2f} {:.2f}".format(*os.getloadavg()) if hasattr(os, "getloadavg") else "n/a"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=9, help="runs per command and version (default 9)")
    parser.add_argument("--against", help="a folder holding another graphkin package, timed in turn with this one")
    args = parser.parse_args()
    versions = {"this": HERE}
    if args.against:
        versions["other"] = Path(args.against).resolve() / "graphkin"
    with tempfile.TemporaryDirectory(prefix="graphkin-bench-figure-") as folder:
        tmp = Path(folder)
        command = [sys.executable, "-m", "graphkin", "solve", "double_slider", "-o", str(tmp / "f.png")]
        envs = {(v, mode): env for v, package in versions.items()
                for mode, env in _environments(tmp, v, package).items()}
        print("graphkin solve double_slider -o f.png (issue 40: under 1.5 s on a quiet machine)")
        print("=" * 80)
        print(f"date       {time.strftime('%Y-%m-%dT%H:%M:%S%z')}")
        print(f"python     {sys.version.split()[0]} ({sys.executable}), {os.cpu_count()} CPUs")
        for v, package in versions.items():
            print(f"{v:10s} {package}")
        print(f"load avg   {_load()} (1, 5, 15 min) before")
        for env in envs.values():
            _run(command, env, tmp)  # pint's cache; the bytecode of the "bytecode" copies
        times: dict = {key: [] for key in envs}
        for _ in range(args.runs):
            for key, env in envs.items():
                times[key].append(_run(command, env, tmp))
        print()
        print(f"1. the whole command, {args.runs} runs each, in turn [s]")
        print(f"{'version':8s} {'graphkin bytecode':18s} {'wall median':>12s} {'wall min':>9s} {'CPU median':>11s} "
              f"{'CPU min':>8s}")
        for (v, mode), runs in times.items():
            wall, cpu = [w for w, _ in runs], [c for _, c in runs]
            print(f"{v:8s} {mode:18s} {statistics.median(wall):12.2f} {min(wall):9.2f} {statistics.median(cpu):11.2f} "
                  f"{min(cpu):8.2f}")
        print()
        print(f"2. its phases in one process (graphkin bytecode kept), CPU time, median of {args.runs} [s]")
        phases = {v: [] for v in versions}
        for _ in range(args.runs):
            for v in versions:
                out = subprocess.run([sys.executable, "-c", PHASES, str(tmp / "p.png")], env=envs[(v, "bytecode")],
                                     cwd=tmp, capture_output=True, text=True, check=True).stdout
                phases[v].append(json.loads(out))
        print(f"{'phase':28s} " + " ".join(f"{v:>8s}" for v in versions))
        for i, name in enumerate(PHASE_NAMES + ["total"]):
            cells = [statistics.median([sum(p) if name == "total" else p[i] for p in phases[v]]) for v in versions]
            print(f"{name:28s} " + " ".join(f"{c:8.3f}" for c in cells))
        print()
        print(f"3. load avg {_load()} (1, 5, 15 min) after")
    return 0


if __name__ == "__main__":
    sys.exit(main())
