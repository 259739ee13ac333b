"""One position, graphically: construction, and construction plus the side-by-side figure.

Run with ``make bench`` or ``.venv/bin/python benchmarks/bench_graphical.py``.
Prints a table (best of k runs, milliseconds) for every catalog problem at
the position ``make figures`` draws. The aim (from the issue): construction
plus side-by-side figure ≤ 150 ms. "Figure" is timed two ways: building it
(every artist created and every label placed, which measures text with the
renderer) and, for information, also rendering it to a PNG in memory (that
part is matplotlib's rasteriser, at 100 dpi).
"""

from __future__ import annotations

import importlib.util
import io
import sys
import timeit
from pathlib import Path

import matplotlib  # noqa: E402

matplotlib.use("Agg")

from graphkin import catalog, draw  # noqa: E402
from graphkin.graphical import construct_forces  # noqa: E402


def _figure_positions() -> dict:
    # figures/build.py by its path: a module named "build" on sys.path would shadow (or be shadowed by) PyPA's build.
    spec = importlib.util.spec_from_file_location("_figures_build", Path(__file__).resolve().parents[1] / "figures" / "build.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.AT


AT = _figure_positions()
AIM_MS = 150.0


def best_of(fn, k=7):
    """The fastest of k calls after a warm-up one [ms]; timeit keeps the garbage collector off while it times."""
    fn()
    return min(timeit.repeat(fn, repeat=k, number=1)) * 1e3


def main() -> int:
    print(f"{'problem':<24}{'construct':>12}{'+ figure':>12}{'+ PNG':>12}   aim ≤ {AIM_MS:.0f} ms (construct + figure)")
    worst = 0.0
    for name in catalog.names():
        problem = catalog.load(name)
        result = problem.solve([AT[name]] if name in AT else None)
        kin = result.kinematics

        def construct():
            return construct_forces(kin, 0)

        def figure():
            return draw.draw_solution(construct_forces(kin, 0), result)

        def png():
            figure().savefig(io.BytesIO(), format="png", dpi=100)

        t = (best_of(construct), best_of(figure, 3), best_of(png, 3))
        worst = max(worst, t[1])
        print(f"{name:<24}{t[0]:>12.2f}{t[1]:>12.1f}{t[2]:>12.1f}   {'MET' if t[1] <= AIM_MS else 'NOT MET'}")
    print(f"\nslowest construct + figure: {worst:.1f} ms -> {'MET' if worst <= AIM_MS else 'NOT MET'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
