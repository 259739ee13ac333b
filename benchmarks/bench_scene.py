"""The scene of a presolved cycle (issue 37): its build time, its JSON's size, and the page's.

Run directly: ``.venv/bin/python benchmarks/bench_scene.py [n] [k]`` (default 360 positions, best of 3).

For the strip cutter and the shaper, the CPU time of the process (``time.process_time``: the machine is shared, and
wall time measures the neighbours too), each the best of k runs after a warm-up:

  1  ``scene(problem, n, polygons=False)``: the sweep and the analytical route's scene
  2  ``scene(problem, n)``: the same with the graphical route built and checked at every position
     (``construct_forces`` + ``guard.check_forces``) and every force polygon kept; where the scene superposes the
     speed (both problems here), built at twice the file's speed too, for the polygons' two parts in ω²
  3  ``scene_json``: the compact JSON of row 2
  4  ``page``: the self-contained HTML page (the JSON and the drawing module inlined)

and the sizes: the JSON raw and gzipped, the page. The aims (issue 37): row 2 at 360 positions ≤ 1 s for the strip
cutter and ≤ 3 s for the shaper; the strip cutter's page ≤ 1.5 MB. The drawing's time per position in Chromium is
measured by tests/e2e/test_scene_page.py (it needs a browser).
"""

from __future__ import annotations

import gzip
import sys
import time
from pathlib import Path

from graphkin import catalog

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_cycle  # noqa: E402  (benchmarks/ is not a package)

from graphkin.scene import page, scene, scene_json

AIMS = {"strip_cutter": 1.0, "shaper_six_bar": 3.0}
"""Row 2's aim per problem [s of CPU]."""


def best_of(fn, k: int) -> float:
    """CPU seconds of the best of ``k`` runs (the machine may be shared): bench_cycle's timer on process time."""
    return bench_cycle.best_of(fn, k, clock=time.process_time)


def main(n: int = 360, k: int = 3) -> int:
    print(f"scene of {n} crank angles, CPU seconds, best of {k}\n")
    print(f"{'problem':<16}{'analytical':>11}{'+ graphical':>12}{'aim':>6}{'json':>8}{'page':>8}"
          f"{'JSON raw':>11}{'gzipped':>10}{'page':>10}")
    missed = 0
    for name, aim in AIMS.items():
        problem = catalog.load(name)
        bare = best_of(lambda: scene(problem, n, polygons=False), k)
        full = best_of(lambda: scene(problem, n), k)
        data = scene(problem, n)
        as_json = best_of(lambda: scene_json(data), k)
        as_page = best_of(lambda: page(data), k)
        text = scene_json(data).encode("utf-8")
        html = page(data).encode("utf-8")
        missed += full > aim
        print(f"{name:<16}{bare:>10.3f}s{full:>11.3f}s{aim:>5.0f}s{as_json * 1e3:>6.0f}ms{as_page * 1e3:>6.0f}ms"
              f"{len(text) / 1e3:>9.0f}kB{len(gzip.compress(text)) / 1e3:>8.0f}kB{len(html) / 1e6:>8.2f}MB")
    return 1 if missed else 0


if __name__ == "__main__":
    sys.exit(main(*map(int, sys.argv[1:])))
