"""Animation benchmark: the strip cutter over one turn, 120 frames at 100 dpi (640 px wide).

Run directly: ``.venv/bin/python benchmarks/bench_animate.py [frames] [dpi]``.

Times of one run each (an animation is made once, not in a loop), with
``time.perf_counter``:

  1  the graphical construction at every frame (``construct_forces``)
  2  ``Film(...)``: the view of the whole turn (every frame's mechanism laid out once) and the force scale
  3  drawing and rendering every frame to PNG
  4  ``animate(problem, frames=...)``: rows 1–3 as one call, the total a user waits for
  5  writing the GIF (Pillow), and 6 the web page

With ``--polygons`` the force polygons are drawn too. The aim (issue 27) is
row 4 + row 5 <= 30 s on 2 cores; the process uses one.
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from graphkin import catalog, draw
from graphkin.draw.animation import Film
from graphkin.graphical import construct_forces

AIM = 30.0  # s


def timed(fn):
    t = time.perf_counter()
    value = fn()
    return value, time.perf_counter() - t


def main(frames: int = 120, dpi: float = 100, polygons: bool = False) -> int:
    problem = catalog.load("strip_cutter")
    draw.animate(problem, frames=2, dpi=20)  # warm-up: imports, fonts
    kin = problem.kinematics(at=np.linspace(0.0, 2 * np.pi, frames, endpoint=False))
    cs, t_construct = timed(lambda: [construct_forces(kin, i) for i in range(frames)])
    film, t_view = timed(lambda: Film(cs, polygons=polygons, dpi=dpi))
    _, t_frames = timed(lambda: [film.png(c) for c in cs])
    anim, t_total = timed(lambda: draw.animate(problem, frames=frames, dpi=dpi, polygons=polygons))
    with tempfile.TemporaryDirectory() as tmp:
        gif, t_gif = timed(lambda: anim.save(Path(tmp) / "cutter.gif"))
        page, t_html = timed(lambda: anim.save(Path(tmp) / "cutter.html"))
        sizes = gif.stat().st_size, page.stat().st_size
    w, h = anim.size
    print(f"strip cutter, {frames} frames of {w} x {h} px ({dpi:g} dpi){', with force polygons' if polygons else ''}")
    rows = [
        ("1 construct_forces at every frame", t_construct, ""),
        ("2 Film(...): view and force scale", t_view, ""),
        ("3 draw + render every frame (PNG)", t_frames, f"{1e3 * t_frames / frames:.0f} ms a frame"),
        ("4 animate(problem, frames)", t_total, "rows 1-3 in one call"),
        ("5 write GIF", t_gif, f"{sizes[0] / 1e6:.1f} MB"),
        ("6 write HTML", t_html, f"{sizes[1] / 1e6:.1f} MB"),
    ]
    print(f"{'':38s} {'time [s]':>9s}")
    for name, t, note in rows:
        print(f"{name:38s} {t:9.2f}   {note}")
    total = t_total + t_gif
    print(f"{'animate + GIF':38s} {total:9.2f}   aim <= {AIM:g} s: {'MET' if total <= AIM else 'NOT MET'}")
    return 0


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    sys.exit(main(int(args[0]) if args else 120, float(args[1]) if len(args) > 1 else 100,
                  "--polygons" in sys.argv))
