"""The velocity and acceleration polygons of one position, and the instant centres: time per position.

Run with ``.venv/bin/python benchmarks/bench_polygons.py`` (or ``make bench``). Prints a table (best of k
runs, milliseconds per position): the benchmark's four-bar (``fourbar_linkage.fourbar``, 900 rpm) over 360
crank angles, then every catalog problem at its own positions. "polygons" is
:func:`graphkin.graphical.construct_kinematics` (both polygons with their captions), "centres" is
:func:`graphkin.graphical.instant_centres`, "JSON data" the polygons written as ``solve --json`` writes
them. The aim (issue 26): the four-bar's kinematic construction ≤ 1 ms per position.
"""

from __future__ import annotations

import math
import sys
import timeit
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from fourbar_linkage import fourbar  # noqa: E402

from graphkin import catalog  # noqa: E402
from graphkin.graphical import construct_kinematics, instant_centres  # noqa: E402
from graphkin.kinematics import solve_kinematics  # noqa: E402
from graphkin.report import graphical_kinematics_data  # noqa: E402

AIM_MS = 1.0


def best_of(fn, k=5):
    """The fastest of k calls after a warm-up one [ms]; timeit keeps the garbage collector off while it times."""
    fn()
    return min(timeit.repeat(fn, repeat=k, number=1)) * 1e3


def per_position(kin) -> tuple[float, float, float]:
    n = kin.n
    polygons = [construct_kinematics(kin, i) for i in range(n)]
    return (best_of(lambda: [construct_kinematics(kin, i) for i in range(n)]) / n,
            best_of(lambda: [instant_centres(kin, i) for i in range(n)]) / n,
            best_of(lambda: [graphical_kinematics_data(kin, c) for c in polygons]) / n)


def main() -> int:
    print(f"{'mechanism':<28}{'n':>6}{'polygons':>11}{'centres':>11}{'JSON data':>11}   ms per position")
    n = 360
    kin = solve_kinematics(fourbar(), [2 * math.pi * k / n for k in range(n)], 900 * 2 * math.pi / 60)
    four = per_position(kin)
    print(f"{'four-bar (bench_fourbar)':<28}{n:>6}{four[0]:>11.3f}{four[1]:>11.3f}{four[2]:>11.3f}")
    for name in catalog.names():
        kin = catalog.load(name).kinematics()
        t = per_position(kin)
        print(f"{name:<28}{kin.n:>6}{t[0]:>11.3f}{t[1]:>11.3f}{t[2]:>11.3f}")
    print(f"\nfour-bar polygons: {four[0]:.3f} ms per position (aim ≤ {AIM_MS:g} ms) -> "
          f"{'MET' if four[0] <= AIM_MS else 'NOT MET'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
