"""Latency of the ``graphkin`` command as a person feels it (issue 15): a new process per command.

Each command is run as a user runs it, ``.venv/bin/graphkin ...`` in a new
process, its output thrown away; the wall time from start to exit is taken
over several runs and the median compared with the issue's aim. Then
``python -X importtime`` shows what the import of ``graphkin solve`` is made
of (by top-level package, and the slowest modules), and one process shows
the time spent in each phase of ``graphkin solve`` after the imports.

A person's installation has its bytecode compiled (pip compiles it, or the
first run writes it). So that a source checkout is timed the same way,
``PYTHONDONTWRITEBYTECODE`` is removed from the commands' environment and
their bytecode is kept in a private folder (``PYTHONPYCACHEPREFIX``), never in
the checkout; every command runs once before it is timed. pint's registry
cache (``graphkin.units.registry``) lives in a private folder too, made by
that first run.

A measurement, not a test: no timed assertion, exit code 0. Timings on a
machine shared with other work are noisy; compare medians of runs made under
the same conditions. ``--against DIR`` does that: each command is run in turn
with this checkout's graphkin and with the one in DIR (same interpreter,
e.g. ``git archive HEAD graphkin | tar -x -C /tmp/base``), alternately, and
both medians are shown; ``--source DIR`` times DIR's graphkin alone.

    .venv/bin/python benchmarks/bench_cli.py [--runs 9] [--source DIR | --against DIR] [--only TEXT]
"""

from __future__ import annotations

import argparse
import os
import platform
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

COMMANDS = [
    # (label, arguments after `graphkin`, aim in ms or None)
    ("graphkin solve double_slider", ["solve", "double_slider"], 150.0),
    ("graphkin solve double_slider --figure x.png", ["solve", "double_slider", "--figure", "{tmp}/x.png"], 600.0),
    ("graphkin cycle strip_cutter --n 3600 --json", ["cycle", "strip_cutter", "--n", "3600", "--json"], 250.0),
    # issue 26: `solve` without figures no slower than before the velocity and acceleration polygons came in
    ("graphkin solve strip_cutter", ["solve", "strip_cutter"], None),
    ("graphkin solve strip_cutter --json", ["solve", "strip_cutter", "--json"], None),
    # a four-bar at one position, by its file: the catalog before issue 26 had no such problem
    ("graphkin solve fourbar_dynamic_makdin.toml", ["solve", "{four}"], None),
    ("graphkin solve fourbar_dynamic_makdin.toml --json", ["solve", "{four}", "--json"], None),
    ("graphkin list", ["list"], None),
    ("graphkin --help", ["--help"], None),
]
FOUR = str(Path(__file__).resolve().parents[1] / "graphkin" / "catalog" / "fourbar_dynamic_makdin.toml")
REFERENCE = [
    # what any command pays before graphkin does anything
    ("python -c pass", ["-c", "pass"]),
    ("python -c 'import numpy'", ["-c", "import numpy"]),
]


def _environment(tmp: Path, source: str | None) -> dict:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env["PYTHONPYCACHEPREFIX"] = str(tmp / "pycache")
    env["GRAPHKIN_CACHE_DIR"] = str(tmp / "cache")
    if source:
        env["PYTHONPATH"] = os.pathsep.join([source, env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    return env


def _graphkin() -> list[str]:
    """The console script beside this interpreter (as a user runs it), else ``python -m graphkin.cli``."""
    script = Path(sys.executable).with_name("graphkin")
    return [str(script)] if script.exists() else [sys.executable, "-m", "graphkin.cli"]


def _time(argv: list[str], env: dict, runs: int) -> list[float]:
    out = []
    for _ in range(runs):
        t = time.perf_counter()
        r = subprocess.run(argv, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        out.append(time.perf_counter() - t)
        if r.returncode != 0:
            raise SystemExit(f"{' '.join(argv)} failed ({r.returncode}): {r.stderr.decode()[-500:]}")
    return out


def _alternate(argv: list[str], envs: list[dict], runs: int, cpu: list | None = None) -> list[list[float]]:
    """Times of ``argv`` under each environment, taken in turn so that both see the same load; ``cpu``, a list
    per environment, gets each run's CPU time (user + system) too."""
    times: list[list[float]] = [[] for _ in envs]
    for _ in range(runs):
        for k, env in enumerate(envs):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            times[k] += _time(argv, env, 1)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            if cpu is not None:
                cpu[k].append(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime)
    return times


def _importtime(env: dict) -> list[tuple[int, int, str]]:
    """(self µs, cumulative µs, module) of every import of ``graphkin solve double_slider``, one process."""
    code = "from graphkin.cli import main; main(['solve', 'double_slider'])"
    r = subprocess.run([sys.executable, "-X", "importtime", "-c", code], env=env, capture_output=True, text=True)
    rows = []
    for line in r.stderr.splitlines():
        m = re.match(r"import time:\s+(\d+) \|\s+(\d+) \|(\s*)(\S+)", line)
        if m:
            rows.append((int(m[1]), int(m[2]), m[4]))
    return rows


PHASES = {
    "graphkin solve double_slider": r"""
import sys, time, json
t0 = time.perf_counter()
from graphkin.cli import single_threaded_blas as _single_threaded_blas
_single_threaded_blas()
t1 = time.perf_counter()
from graphkin import catalog, report
t2 = time.perf_counter()
problem = catalog.load("double_slider")
t3 = time.perf_counter()
result = problem.solve(None)
t4 = time.perf_counter()
graphical = report.constructions(result)
text = report.format_solution(problem, result, graphical)
t5 = time.perf_counter()
print(json.dumps({"numpy (one BLAS thread)": t1 - t0, "import the engine and report": t2 - t1,
                  "read the problem file": t3 - t2, "solve": t4 - t3, "construct + format": t5 - t4,
                  "pint loaded": "pint" in sys.modules}))
""",
    "graphkin cycle strip_cutter --n 3600 --json": r"""
import sys, time, json
t0 = time.perf_counter()
from graphkin.cli import single_threaded_blas as _single_threaded_blas
_single_threaded_blas()
from graphkin import catalog
from graphkin.cycle import sweep
from graphkin.files import json_text
from graphkin.report import cycle_data
t1 = time.perf_counter()
problem = catalog.load("strip_cutter")
cycle = sweep(problem, 3600)
t2 = time.perf_counter()
data = cycle_data(cycle)
t3 = time.perf_counter()
text = json_text(data)
t4 = time.perf_counter()
print(json.dumps({"imports": t1 - t0, "read + sweep": t2 - t1, "cycle_data": t3 - t2, "json_text": t4 - t3,
                  "characters": len(text)}))
""",
}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=9, help="timed runs per command (default 9)")
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--source", help="a folder holding another graphkin package to time instead")
    which.add_argument("--against", help="a folder holding another graphkin package to time alternately with this one")
    parser.add_argument("--only", metavar="TEXT", help="with --against: only the commands whose label holds TEXT")
    args = parser.parse_args()
    import json

    for name in ("source", "against"):
        if getattr(args, name):
            setattr(args, name, str(Path(getattr(args, name)).resolve()))
    with tempfile.TemporaryDirectory(prefix="graphkin-bench-cli-") as folder:
        tmp = Path(folder)
        # Every command runs in this empty folder: `python -c` puts the working folder first on sys.path, and a
        # checkout's own graphkin there would shadow --source and --against.
        os.chdir(tmp)
        env = _environment(tmp, args.source)
        where = subprocess.run([sys.executable, "-c", "import graphkin; print(graphkin.__file__)"], env=env,
                               capture_output=True, text=True).stdout.strip()
        if args.against:
            return _compare(tmp, env, args)
        print("graphkin command-line latency (issue 15)")
        print("========================================")
        _when_and_where({"graphkin": where})
        print(f"runs       {args.runs} per command, a new process each; median and fastest wall time [ms]")
        print()
        print(f"{'command':48s} {'median':>8s} {'min':>8s} {'aim':>8s}  verdict")
        print("-" * 84)
        for label, argv in REFERENCE:
            _time([sys.executable, *argv], env, 1)
            ts = _time([sys.executable, *argv], env, args.runs)
            print(f"{label:48s} {statistics.median(ts) * 1e3:8.0f} {min(ts) * 1e3:8.0f} {'':>8s}  (reference)")
        verdicts = []
        for label, argv, aim in COMMANDS:
            full = _graphkin() + [a.format(tmp=tmp, four=FOUR) for a in argv]
            _time(full, env, 1)  # bytecode and pint's cache, as after a first run
            ts = _time(full, env, args.runs)
            med = statistics.median(ts) * 1e3
            verdict = "" if aim is None else ("MET" if med <= aim else "NOT MET")
            if aim is not None:
                verdicts.append((label, med, aim, verdict))
            print(f"{label:48s} {med:8.0f} {min(ts) * 1e3:8.0f} {'' if aim is None else f'{aim:.0f}':>8s}  {verdict}")

        rows = _importtime(env)
        by_package: dict[str, int] = defaultdict(int)
        for own, _, name in rows:
            by_package[name.split(".")[0]] += own
        total = sum(by_package.values())
        print()
        print(f"imports of `graphkin solve double_slider` (python -X importtime, one run): {total / 1e3:.0f} ms")
        print("  by top-level package (self time summed):")
        for name, us in sorted(by_package.items(), key=lambda kv: -kv[1])[:12]:
            print(f"    {name:36s} {us / 1e3:7.1f} ms")
        print("  slowest modules (self time):")
        for own, cum, name in sorted(rows, reverse=True)[:10]:
            print(f"    {name:36s} {own / 1e3:7.1f} ms   (with its imports {cum / 1e3:.1f} ms)")
        print("  heavy packages loaded:", ", ".join(p for p in ("pint", "matplotlib", "ipywidgets", "scipy")
                                                  if p in by_package) or "none (no pint, matplotlib, ipywidgets)")

        for label, code in PHASES.items():
            phases = [json.loads(subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                                                text=True).stdout) for _ in range(max(3, args.runs // 2))]
            print()
            print(f"phases of `{label}` in one process (median of {len(phases)}) [ms]:")
            for key in phases[0]:
                if isinstance(phases[0][key], float):
                    print(f"    {key:36s} {statistics.median(p[key] for p in phases) * 1e3:7.1f}")
                else:
                    print(f"    {key:36s} {phases[0][key]}")

        print()
        print("aims (from the issue)")
        for label, med, aim, verdict in verdicts:
            print(f"  {label}: {med:.0f} ms vs {aim:.0f} ms -> {verdict}")
    return 0


def _when_and_where(packages: dict) -> None:
    """The run's header: date, machine, Python, the graphkin package(s) timed, the load before it."""
    print(f"date       {time.strftime('%Y-%m-%dT%H:%M:%S%z')}")
    print(f"machine    {platform.machine()}, {os.cpu_count()} CPUs, {platform.system()} {platform.release()}")
    print(f"python     {platform.python_version()} ({sys.executable})")
    for label, where in packages.items():
        print(f"{label:<10s} {where}")
    if hasattr(os, "getloadavg"):
        print("load avg   {:.2f} {:.2f} {:.2f} (1, 5, 15 min)".format(*os.getloadavg()))


def _compare(tmp: Path, env: dict, args) -> int:
    """``--against DIR``: each command with this checkout's graphkin and DIR's, alternately."""
    other = _environment(tmp, args.against)
    other["PYTHONPYCACHEPREFIX"] = str(tmp / "pycache-other")
    other["GRAPHKIN_CACHE_DIR"] = str(tmp / "cache-other")
    mine = subprocess.run([sys.executable, "-c", "import graphkin; print(graphkin.__file__)"], env=env,
                          capture_output=True, text=True).stdout.strip()
    theirs = subprocess.run([sys.executable, "-c", "import graphkin; print(graphkin.__file__)"], env=other,
                            capture_output=True, text=True).stdout.strip()
    print("graphkin command-line latency (issue 15), two versions side by side")
    _when_and_where({"A (this)": mine, "B": theirs})
    print(f"runs       {args.runs} per command and version, alternating; median (min) wall time [ms], and the least "
          "CPU time (user + system) of a run [ms]: on a machine shared with other work the wall time")
    print("           measures the others too, the CPU time much less")
    print()
    print(f"{'command':48s} {'A':>14s} {'B':>14s} {'A/B':>6s} {'aim':>6s}  {'A meets it':10s} {'A cpu':>6s} "
          f"{'B cpu':>6s} {'A/B':>5s}")
    for label, argv, aim in COMMANDS:
        if args.only and args.only not in label:
            continue
        full = _graphkin() + [a.format(tmp=tmp, four=FOUR) for a in argv]
        _alternate(full, [env, other], 1)
        cpu: list[list[float]] = [[], []]
        a, b = _alternate(full, [env, other], args.runs, cpu)
        ma, mb = statistics.median(a) * 1e3, statistics.median(b) * 1e3
        ca, cb = min(cpu[0]) * 1e3, min(cpu[1]) * 1e3
        verdict = "" if aim is None else ("MET" if ma <= aim else "NOT MET")
        print(f"{label:48s} {ma:6.0f} ({min(a) * 1e3:5.0f}) {mb:6.0f} ({min(b) * 1e3:5.0f}) {ma / mb:6.2f} "
              f"{'' if aim is None else f'{aim:.0f}':>6s}  {verdict:10s} {ca:6.0f} {cb:6.0f} {ca / cb:5.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
