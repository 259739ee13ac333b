"""Speed of the notebook explorer (graphkin.widgets): one update = construction + redraw + PNG.

Prints, for each catalog problem and two screens (a plain one, 100 dpi, and a
HiDPI one with pixel ratio 2, 200 dpi), the median and 90th percentile of 30
slider updates over the input range, and MET/NOT MET against the aim on a
plain screen (issue 15: 50 ms; issue 4's was 100 ms). Where the time of an
update goes is shown beside it (means over the same updates): the
``graphkin.draw`` calls that make the artists, Agg's rendering, and the PNG
(palette + zlib); the rest is the construction, the analytical solution and
the bookkeeping. Also compares the two ways of showing the PNG: assigning it
to an ipywidgets.Image (binary buffer) or displaying it in an
ipywidgets.Output (base64 text in a display message).

A second table times what a key press costs once the explorer has drawn its
neighbours ahead (``explore(..., ahead=2)``, idle in an event loop as in a
kernel): the browser's value taken and the finished frame shown, and how
long after a move the neighbours (two steps either side) are all drawn, and
the longest step of that drawing (it goes a panel at a time, the rendering and
the PNG each a step): the most a key press can wait behind it.

The time a person waits, from a key press in the browser to the new image, is
measured by the browser test (``make e2e``: build/e2e/timings.json); it adds
the explorer's settling time (``graphkin.widgets.SETTLE``) and the transfer to
this update.

    .venv/bin/python benchmarks/bench_explorer.py
"""

from __future__ import annotations

import asyncio
import base64
import contextlib
import time

import numpy as np

from graphkin import catalog, draw
from graphkin.widgets import explore

AIM_MS = 50.0
UPDATES = 30


DPIS = (100, 200)
"""A plain screen and a HiDPI one (pixel ratio 2)."""


@contextlib.contextmanager
def _timed(spent: dict, key: str, owner, *names):
    """Add the time spent in ``owner.<name>`` calls to ``spent[key]`` while inside."""
    saved = {n: getattr(owner, n) for n in names}

    def timing(f):
        def call(*args, **kwargs):
            t = time.perf_counter()
            try:
                return f(*args, **kwargs)
            finally:
                spent[key] = spent.get(key, 0.0) + time.perf_counter() - t
        return call

    for n, f in saved.items():
        setattr(owner, n, timing(f))
    try:
        yield
    finally:
        for n, f in saved.items():
            setattr(owner, n, f)


def bench(name: str, dpi: int):
    from PIL import Image

    ex = explore(catalog.load(name), dpi=dpi)
    lo, hi = ex.limits
    values = np.linspace(lo, hi, UPDATES + 1)[:-1] + 0.37 * (hi - lo) / UPDATES
    ex.update()  # warm caches (fonts, text metrics)
    ex.timings.clear()
    spent: dict = {}
    with (_timed(spent, "artists", draw, "draw_mechanism", "draw_free_body", "draw_force_polygon"),
          _timed(spent, "render", ex.figure.canvas, "draw"),
          _timed(spent, "png", Image.Image, "quantize", "save")):
        for v in values:
            ex.slider.value = float(v)
    ms = np.array(ex.timings) * 1e3
    split = {k: v / len(values) * 1e3 for k, v in spent.items()}
    png = ex.png()
    t = time.perf_counter()
    for _ in range(10):
        ex.image.value = png
    t_image = (time.perf_counter() - t) / 10 * 1e3
    t = time.perf_counter()
    for _ in range(10):
        base64.b64encode(png)
    t_output = (time.perf_counter() - t) / 10 * 1e3
    return float(np.median(ms)), float(np.percentile(ms, 90)), len(png), t_image, t_output, split, float(ms.mean())


def key_presses(name: str, presses: int = 12):
    """Arrow-key presses in a running event loop with drawing ahead: (median ms per press, median ms until the
    neighbours (``ahead`` steps either side) are all drawn, presses served from a frame drawn ahead, presses,
    the longest step of drawing ahead [ms]: the most a press can wait behind it)."""
    ex = explore(catalog.load(name), dpi=DPIS[0])
    lo, hi = ex.limits
    start = ex._snap(lo + 0.37 * (hi - lo))
    steps = []  # how long each step of drawing ahead kept the kernel busy
    step = ex._draw_ahead

    def timed_step():
        t = time.perf_counter()
        step()
        steps.append(time.perf_counter() - t)

    ex._draw_ahead = timed_step

    async def neighbours_drawn():
        t = time.perf_counter()
        while not set(ex._neighbours()) <= set(ex._frames):
            await asyncio.sleep(0.002)
        return time.perf_counter() - t

    async def session():
        ex.slider.value = start
        await neighbours_drawn()
        press, ready, served = [], [], 0
        for _ in range(presses):
            await asyncio.sleep(0.3)  # a person reading the position
            v = ex._snap(ex.value + ex.step)
            drawn = len(ex.timings)
            t = time.perf_counter()
            ex.slider.set_state({"value": v})  # what a key press in the browser sends
            press.append(time.perf_counter() - t)
            served += len(ex.timings) == drawn and ex.value == v
            ready.append(await neighbours_drawn())
        return press, ready, served

    press, ready, served = asyncio.run(session())
    return float(np.median(press)) * 1e3, float(np.median(ready)) * 1e3, served, presses, max(steps) * 1e3


def main():
    print(f"{'problem':24s} {'dpi':>4s} {'median ms':>10s} {'p90 ms':>8s} {'PNG kB':>7s} {'Image ms':>9s} {'b64 ms':>7s}"
          f"  aim {AIM_MS:.0f} ms   mean ms: artists / render / PNG / rest")
    for name in catalog.names():
        for dpi in DPIS:
            med, p90, size, t_image, t_output, split, mean = bench(name, dpi)
            verdict = ("MET" if med <= AIM_MS else "NOT MET") if dpi == DPIS[0] else ""
            parts = [split.get(k, 0.0) for k in ("artists", "render", "png")]
            print(f"{name:24s} {dpi:4d} {med:10.1f} {p90:8.1f} {size / 1024:7.1f} {t_image:9.2f} {t_output:7.2f}  "
                  f"{verdict:7s}      {' / '.join(f'{x:.0f}' for x in parts)} / {mean - sum(parts):.0f}")
    print(f"\nKey presses with drawing ahead ({DPIS[0]} dpi, idle 0.3 s between presses): the kernel's time "
          f"per press, aim {AIM_MS:.0f} ms")
    print(f"{'problem':24s} {'press ms':>9s} {'neighbours ready ms':>20s} {'from a frame':>13s} "
          f"{'longest step ms':>16s}")
    for name in catalog.names():
        press, ready, served, presses, longest = key_presses(name)
        verdict = "MET" if press <= AIM_MS else "NOT MET"
        print(f"{name:24s} {press:9.2f} {ready:20.0f} {served:>8d} of {presses:<3d} {longest:16.1f}  {verdict}")


if __name__ == "__main__":
    main()
