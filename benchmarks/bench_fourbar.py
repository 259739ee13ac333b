"""Four-bar benchmark: graphkin's vectorised force analysis vs pylinkage's numba kinematics.

Run with ``make bench`` (installs the ``bench`` extra, ``pylinkage[numba]``)
or directly: ``.venv/bin/python benchmarks/bench_fourbar.py``.

One crank-rocker -- ``pylinkage_side.FOURBAR``: ground A0B0 = 0.5 m, crank
A0A = 0.085 m, coupler AB = 0.235 m, rocker B0B = 0.55 m, open branch (B
above the ground line) -- driven at a constant 900 rpm, with the strip
cutter's masses on links 2, 3 and 4, is analysed at n = 360, 3600 and
100 000 equally spaced crank angles by:

  1  graphkin ``solve_kinematics``: positions, velocities, accelerations
  2  graphkin ``solve`` = ``solve_forces(solve_kinematics(...))``: the above
     plus every joint force and the driving torque T12
  3  row 2 called once per position in a Python loop (the way a scalar
     library is used); timed at n = 360 and 3600, *extrapolated* linearly
     from the n = 3600 per-position time at n = 100 000 (a run would take
     ~100 s)
  4  ``graphkin.analytical.matrix.solve_matrix(result)``: the general matrix
     [A]{x} = {b} assembled and solved with ``numpy.linalg.solve`` per
     position (kinematics and the ForceAnalysis it takes are precomputed, so
     this is assembly + LAPACK only)
  5  pylinkage's numba-compiled kinematics (positions, velocities,
     accelerations only; no forces): ``pylinkage_side.time_pylinkage(n)``,
     the public ``Linkage.step_fast_with_kinematics``; 5b is the bare
     numba kernel (pylinkage's floor), for information
  6  the whole force analysis of row 2 as one hand-written numba loop
     (``numba_floor.py``): the floor for row 2, for information

Every time is the best of k runs with ``time.perf_counter`` after a warm-up
(garbage collector off while timing, as ``timeit`` does); k is chosen per
row so the whole script takes well under 60 s.

Then row 2 alone at n = 10^4, 10^5 and 10^6: time per position, minor page
faults and kernel (system) time per call (``getrusage``), and at n = 10^6
the bytes a result keeps per position (``tracemalloc``: what is still
allocated while the result is held) and the peak on the way.

Before timing it checks that graphkin and pylinkage both reproduce the
closed-form ``pylinkage_side.reference_kinematics`` (so both sides analyse
the same linkage), that graphkin's force answers agree between rows 2, 3
and 4 and with row 6, and that B is above the ground line.

The aims (issue 15) are printed with MET / NOT MET:
  * whole force analysis (row 2) <= pylinkage kinematics (row 5) at each n timed (360, 3600, 100 000)
  * whole force analysis (row 2) <= 0.15 ms at n = 360
  * whole force analysis (row 2) <= 0.5 x pylinkage kinematics at n = 3600 and 100 000
  * row 2's time per position does not grow from n = 10^4 to 10^6 (within 10 %), beyond the time to
    allocate and write arrays as large as its result (at 10^6 that memory is new to the process on every
    call, for any solver that returns new arrays; at 10^4 the allocator hands back the last call's)
  * a result keeps <= 150 bytes per position at n = 10^6

It measures, it does not judge: the exit code is always 0.
"""

from __future__ import annotations

import datetime
import gc
import os
import platform
import resource
import sys
import time
import tracemalloc
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import pylinkage_side as ps  # noqa: E402
from fourbar_linkage import MECH  # noqa: E402

import graphkin  # noqa: E402
from graphkin.analytical import solve  # noqa: E402
from graphkin.analytical.matrix import solve_matrix  # noqa: E402
from graphkin.kinematics import solve_kinematics  # noqa: E402

N_SIZES = ps.N_SIZES  # (360, 3600, 100_000)
LOOP_SIZES = (360, 3600)  # the Python loop is extrapolated beyond these
SCALING_SIZES = (10_000, 100_000, 1_000_000)
AIM_360_S = 0.15e-3
AIM_RATIO = 0.5  # of pylinkage's kinematics, at n = 3600 and 100 000
AIM_GROWTH = 1.10  # ns per position at 10^6 over that at 10^4
AIM_BYTES = 150  # kept per position at 10^6
BUDGET_S = 1.5  # wall time allowed per (row, n) measurement, beyond warm-up
K_MIN, K_MAX = 3, 200


def graphkin_kinematics(theta):
    return solve_kinematics(MECH, theta, ps.OMEGA2, 0.0)


def graphkin_full(theta):
    return solve(MECH, theta, ps.OMEGA2, 0.0)


def graphkin_loop(theta):
    """Row 2's code, one position per call; returns (n,) T12 and (n, 2) F34."""
    T = np.empty(len(theta))
    F34 = np.empty((len(theta), 2))
    for i, th in enumerate(theta):
        r = solve(MECH, th, ps.OMEGA2, 0.0)
        T[i] = r.effort[0]
        F34[i] = r.force(3, 4)[0]
    return T, F34


# ---------------------------------------------------------------------------
# Timing
# ---------------------------------------------------------------------------


def best_of(fn, *args, budget: float = BUDGET_S, k_max: int = K_MAX, k_min: int = K_MIN):
    """(best time [s], k): warm up once, then run k_min..k_max times within ``budget``."""
    fn(*args)  # warm-up (caches, allocator, first-call imports)
    gc.collect()
    times = []
    spent = 0.0
    enabled = gc.isenabled()
    try:
        gc.disable()
        while len(times) < k_max and (len(times) < k_min or spent < budget):
            t0 = time.perf_counter()
            fn(*args)
            dt = time.perf_counter() - t0
            times.append(dt)
            spent += dt
    finally:
        if enabled:
            gc.enable()
    return min(times), len(times)


def time_pylinkage(n: int, api: str = "linkage"):
    """(best time [s], k) of pylinkage_side.time_pylinkage, k sized to the budget."""
    ps.prepare(n)  # build + JIT/warm-up, outside timing
    one = ps.time_pylinkage(n, repeat=1, api=api)  # second warm-up, and an estimate
    k = int(min(K_MAX, max(K_MIN, BUDGET_S / max(one, 1e-9))))
    return ps.time_pylinkage(n, repeat=k, api=api), k


def time_floor(n: int):
    """(best time [s], k) of the hand-written numba loop (numba_floor.py), k sized to the budget."""
    import numba_floor

    theta = ps.crank_angles(n)
    return best_of(numba_floor.floor, theta)


def scaling(n: int) -> dict:
    """Row 2 at n positions: best time, and minor page faults and kernel time per call."""
    theta = ps.crank_angles(n)
    best, k = best_of(graphkin_full, theta, budget=BUDGET_S, k_max=50)
    before = resource.getrusage(resource.RUSAGE_SELF)
    for _ in range(k):
        graphkin_full(theta)
    after = resource.getrusage(resource.RUSAGE_SELF)
    return {"time": best, "k": k, "faults": (after.ru_minflt - before.ru_minflt) / k,
            "kernel": (after.ru_stime - before.ru_stime) / k}


def _owned_dtypes() -> list:
    """The dtypes of the arrays of n values a result of row 2 keeps (its forces, effort, masks and inputs)."""
    r = graphkin_full(ps.crank_angles(10))
    kin = r.kinematics
    arrays = [F.base if F.base is not None else F for F in r.forces.values()]
    arrays += [r.effort, r.valid, kin.valid, kin.q, kin.q_dot, kin.q_ddot]
    return [a.dtype for a in arrays]


def fresh_result(n: int, dtypes) -> float:
    """Best time [s] to allocate and write arrays as large as a result of row 2 (a lower bound for any
    solver that returns new arrays: at large n this memory is new to the process every time)."""

    def write():
        out = [np.empty(n, dt) for dt in dtypes]
        for a in out:
            a.fill(1)

    return best_of(write, budget=0.5, k_max=50)[0]


def kept_bytes(n: int) -> tuple[float, float]:
    """(bytes still allocated per position while the result is held, peak per position on the way)."""
    theta = ps.crank_angles(n)
    graphkin_full(theta[:10])
    gc.collect()
    tracemalloc.start()
    try:
        start = tracemalloc.get_traced_memory()[0]
        result = graphkin_full(theta)
        gc.collect()
        kept, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    del result
    return (kept - start) / n, (peak - start) / n


# ---------------------------------------------------------------------------
# Checks
# ---------------------------------------------------------------------------


def _maxabs(a, b) -> float:
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b))))


def check_same_linkage(n: int, have_pylinkage: bool) -> dict:
    """Max |difference| from the closed-form reference, graphkin (and pylinkage)."""
    theta = ps.crank_angles(n)
    ref = ps.reference_kinematics(n)
    kin = graphkin_kinematics(theta)
    out = {
        "valid": bool(kin.valid.all()),
        "B_above": float(kin.position(3, "B")[:, 1].min()),
        "graphkin": {
            "pos_B": _maxabs(kin.position(3, "B"), ref["pos_B"]),
            "vel_B": _maxabs(kin.velocity(3, "B"), ref["vel_B"]),
            "acc_B": _maxabs(kin.acceleration(3, "B"), ref["acc_B"]),
            # B computed from the rocker side too: both links agree on the pin
            "acc_B(4)": _maxabs(kin.acceleration(4, "B"), ref["acc_B"]),
            "pos_A": _maxabs(kin.position(2, "A"), ref["pos_A"]),
            "acc_A": _maxabs(kin.acceleration(2, "A"), ref["acc_A"]),
        },
    }
    if have_pylinkage:
        e = ps.max_errors(n)
        out["pylinkage"] = {k: e[k] for k in ("pos_B", "vel_B", "acc_B", "pos_A", "acc_A")}
    return out


def check_forces(n: int = 360) -> dict:
    """Rows 2, 3 and 4 give the same forces and torque."""
    theta = ps.crank_angles(n)
    r = graphkin_full(theta)
    T_loop, F34_loop = graphkin_loop(theta)
    m = solve_matrix(r)
    return {
        "valid": bool(r.valid.all()),
        "max|T12|": float(np.max(np.abs(r.effort))),
        "max|F34|": float(np.max(np.linalg.norm(r.force(3, 4), axis=-1))),
        "loop-vs-vector T12": _maxabs(T_loop, r.effort),
        "loop-vs-vector F34": _maxabs(F34_loop, r.force(3, 4)),
        "matrix-vs-closed T12": _maxabs(m.effort, r.effort),
        "matrix-vs-closed F": max(_maxabs(m.forces[key], F) for key, F in r.forces.items()),
    }


# ---------------------------------------------------------------------------
# Report
# ---------------------------------------------------------------------------


def _cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def machine_info(have_pylinkage: bool, why_not: str) -> list[str]:
    try:
        usable = len(os.sched_getaffinity(0))
    except AttributeError:
        usable = os.cpu_count()
    lines = [
        f"date       {datetime.datetime.now().astimezone().isoformat(timespec='seconds')}",
        f"machine    {_cpu_model()}, {os.cpu_count()} CPUs ({usable} usable), {platform.system()} {platform.release()}",
        f"python     {platform.python_version()} ({platform.python_implementation()})",
        f"numpy      {np.__version__}",
        f"graphkin   {graphkin.__version__}",
    ]
    if have_pylinkage:
        import numba
        import pylinkage

        lines.append(f"pylinkage  {pylinkage.__version__}, numba {numba.__version__}")
    else:
        lines.append(f"pylinkage  not available ({why_not}); rows 5, 5b and the aims are skipped")
    threads = {k: v for k, v in os.environ.items() if k.endswith("_NUM_THREADS")}
    if threads:
        lines.append(f"threads    {threads}")
    if hasattr(os, "getloadavg"):
        lines.append("load avg   " + " ".join(f"{x:.2f}" for x in os.getloadavg()) + " (1, 5, 15 min)")
    return lines


def _fmt_ms(t) -> str:
    if t is None:
        return "—"
    ms = t * 1e3
    return f"{ms:.3f}" if ms < 10 else f"{ms:.1f}" if ms < 1000 else f"{ms:,.0f}"


def main() -> int:
    t_start = time.perf_counter()
    try:
        ps.prepare(N_SIZES[0])
        have_pylinkage, why_not = True, ""
    except Exception as exc:  # missing pylinkage or numba: still time graphkin
        have_pylinkage, why_not = False, f"{type(exc).__name__}: {exc}"

    print("graphkin four-bar benchmark")
    print("=" * 27)
    for line in machine_info(have_pylinkage, why_not):
        print(line)
    f = ps.FOURBAR
    print(
        f"linkage    crank-rocker a1={f['a1']} a2={f['a2']} a3={f['a3']} a4={f['a4']} m, open branch, "
        f"crank 900 rpm = {ps.OMEGA2:.3f} rad/s constant"
    )
    print("           m2=3 kg k2=100 mm G2@A0; m3=2 kg k3=268 mm AG3=231 mm @-1°; m4=5.1 kg k4=424 mm B0G4=305 mm @-7°")

    # -- checks -------------------------------------------------------------
    print("\nsame linkage? max |x - closed-form reference| (m, m/s, m/s²)")
    for n in N_SIZES:
        c = check_same_linkage(n, have_pylinkage)
        g = ", ".join(f"{k} {v:.1e}" for k, v in c["graphkin"].items())
        print(f"  n={n:>6} graphkin : {g}   all valid: {c['valid']}, min y_B = {c['B_above']:.4f} m > 0: {c['B_above'] > 0}")
        if "pylinkage" in c:
            p = ", ".join(f"{k} {v:.1e}" for k, v in c["pylinkage"].items())
            print(f"  {'':>8} pylinkage: {p}")
    acc_scale = float(np.max(np.abs(ps.reference_kinematics(360)["acc_B"])))
    print(f"  (scale: max |acc_B| = {acc_scale:.1f} m/s²)")
    fc = check_forces(360)
    print(
        "same forces? n=360: max|T12| = {:.2f} N·m, max|F34| = {:.1f} N; max diff loop-vs-vectorised T12 {:.1e} N·m, "
        "F34 {:.1e} N; matrix-vs-closed-form T12 {:.1e} N·m, all joint forces {:.1e} N; all valid: {}".format(
            fc["max|T12|"], fc["max|F34|"], fc["loop-vs-vector T12"], fc["loop-vs-vector F34"],
            fc["matrix-vs-closed T12"], fc["matrix-vs-closed F"], fc["valid"],
        )
    )  # fmt: skip

    try:
        import numba_floor

        numba_floor.prepare()
        have_floor = True
        print(f"same as the numba floor (row 6)? max |numba - graphkin| / max |graphkin| over T12 and every joint "
              f"force, n=3600: {numba_floor.max_difference(3600):.1e}")
    except Exception as exc:  # no numba: no floor
        have_floor = False
        print(f"numba floor (row 6) not available: {type(exc).__name__}: {exc}")

    # -- timings ------------------------------------------------------------
    rows = [
        ("1", "graphkin solve_kinematics (pos, vel, acc)"),
        ("2", "graphkin solve: kinematics + all forces + T12"),
        ("3", "row 2 once per position in a Python loop"),
        ("4", "solve_matrix(result): assemble + np.linalg.solve"),
        ("5", "pylinkage numba kinematics (public API)"),
        ("5b", "pylinkage bare numba kernel (floor)"),
        ("6", "row 2 as a hand-written numba loop (floor)"),
    ]
    T: dict[tuple[str, int], float | None] = {}
    K: dict[tuple[str, int], str] = {}
    extrapolated = set()
    for n in N_SIZES:
        theta = ps.crank_angles(n)
        T["1", n], k1 = best_of(graphkin_kinematics, theta)
        T["2", n], k2 = best_of(graphkin_full, theta)
        if n in LOOP_SIZES:
            T["3", n], k3 = best_of(graphkin_loop, theta, budget=3.0 if n > 1000 else BUDGET_S, k_min=2 if n > 1000 else K_MIN)
        else:
            m = max(LOOP_SIZES)
            T["3", n], k3 = T["3", m] / m * n, 0
            extrapolated.add(n)
        result = graphkin_full(theta)
        T["4", n], k4 = best_of(solve_matrix, result)
        del result
        K.update({("1", n): k1, ("2", n): k2, ("3", n): k3, ("4", n): k4})
        if have_pylinkage:
            T["5", n], K["5", n] = time_pylinkage(n)
            T["5b", n], K["5b", n] = time_pylinkage(n, api="kernel")
        else:
            T["5", n] = T["5b", n] = None
            K["5", n] = K["5b", n] = 0
        if have_floor:
            T["6", n], K["6", n] = time_floor(n)
        else:
            T["6", n], K["6", n] = None, 0

    w = 50
    print("\ntimes: best of k runs, milliseconds (k in brackets; ~ = extrapolated, not run)")
    head = f"{'':3}{'':{w}}" + "".join(f"{'n=' + format(n, ','):>19}" for n in N_SIZES)
    print(head)
    print("-" * len(head))
    for key, label in rows:
        cells = []
        for n in N_SIZES:
            t = T[key, n]
            if t is None:
                cells.append(f"{'n/a':>19}")
            elif (key == "3" and n in extrapolated):
                cells.append(f"{'~' + _fmt_ms(t):>12}{'(extr)':>7}")
            else:
                cells.append(f"{_fmt_ms(t):>12}{'[' + str(K[key, n]) + ']':>7}")
        print(f"{key:<3}{label:<{w}}" + "".join(cells))
    print("\nper position, nanoseconds")
    for key, label in rows:
        cells = []
        for n in N_SIZES:
            t = T[key, n]
            text = "n/a" if t is None else ("~" if key == "3" and n in extrapolated else "") + format(t / n * 1e9, ",.1f")
            cells.append(f"{text:>19}")
        print(f"{key:<3}{label:<{w}}" + "".join(cells))
    print("\nratios")
    for n in N_SIZES:
        parts = [f"full/kinematics {T['2', n] / T['1', n]:.2f}", f"loop/vectorised {T['3', n] / T['2', n]:,.0f}x",
                 f"matrix/closed-form forces {T['4', n] / T['2', n]:.1f}x"]  # fmt: skip
        if T["5", n] is not None:
            parts.append(f"graphkin full/pylinkage kinematics {T['2', n] / T['5', n]:.2f}")
            parts.append(f"graphkin kinematics/pylinkage kinematics {T['1', n] / T['5', n]:.2f}")
        if T["6", n] is not None:
            parts.append(f"graphkin full/numba floor {T['2', n] / T['6', n]:.1f}x")
        print(f"  n={n:>6}: " + ", ".join(parts))
    if extrapolated:
        print(f"  row 3 at n={', '.join(format(n, ',') for n in sorted(extrapolated))}: extrapolated linearly from the "
              f"n={max(LOOP_SIZES)} per-position time (not run: it would take that long)")  # fmt: skip

    # -- row 2 at large n: time per position, page faults, memory -----------
    print("\nrow 2 at large n: best time, per position, and per call: minor page faults, kernel time; then the time")
    print("to allocate and write arrays as large as its result (new memory at 10^6, whoever computes it)")
    S = {n: scaling(n) for n in SCALING_SIZES}
    dtypes = _owned_dtypes()
    for n, x in S.items():
        x["fresh"] = fresh_result(n, dtypes)
        print(f"  n={n:>9,}: {_fmt_ms(x['time']):>9} ms [{x['k']}]  {x['time'] / n * 1e9:6.1f} ns/position  "
              f"{x['faults']:8,.0f} faults  {x['kernel'] * 1e3:6.2f} ms kernel   result's memory "
              f"{x['fresh'] / n * 1e9:5.1f} ns/position")
    kept, peak = kept_bytes(max(SCALING_SIZES))
    print(f"  n={max(SCALING_SIZES):>9,}: a result keeps {kept:.0f} bytes per position (outputs: 72), "
          f"peak {peak:.0f} bytes per position on the way; max resident {_max_rss_mb():.0f} MB")

    # -- aims ---------------------------------------------------------------
    print("\naims (issue 15)")

    def verdict(ok):
        return "MET" if ok else "NOT MET"

    t = T["2", 360]
    print(f"  whole force analysis ≤ 0.15 ms at n=360: {t * 1e3:.3f} ms -> {verdict(t <= AIM_360_S)}")
    for n in N_SIZES:
        if T["5", n] is None:
            print(f"  whole force analysis ≤ pylinkage kinematics at n={n:,}: n/a (pylinkage not available)")
            continue
        a, b = T["2", n], T["5", n]
        aim = 1.0 if n == 360 else AIM_RATIO
        print(f"  whole force analysis ≤ {aim:g} × pylinkage kinematics at n={n:,}: {a * 1e3:.3f} ms vs "
              f"{b * 1e3:.3f} ms ({a / b:.2f}) -> {verdict(a <= aim * b)}")
    lo, hi = ((S[n]["time"] - S[n]["fresh"]) / n for n in (min(SCALING_SIZES), max(SCALING_SIZES)))
    print(f"  no growth in time per position from n=10^4 to 10^6, beyond writing the result's own memory: "
          f"{lo * 1e9:.1f} -> {hi * 1e9:.1f} ns ({hi / lo:.2f}) -> {verdict(hi <= AIM_GROWTH * lo)}")
    print(f"  ≤ {AIM_BYTES} bytes kept per position at n=10^6: {kept:.0f} -> {verdict(kept <= AIM_BYTES)}")
    print(f"\n(total benchmark time {time.perf_counter() - t_start:.1f} s)")
    return 0


def _max_rss_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


if __name__ == "__main__":
    try:
        main()
    except Exception:  # it measures, it does not judge: report, but exit 0
        import traceback

        traceback.print_exc()
    sys.exit(0)
