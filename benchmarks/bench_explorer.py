"""What the notebook explorer (``gk.explore``, drawn by the browser) costs the kernel.

The browser draws every position of a presolved cycle (graphkin/scene/js); the kernel works only when an explorer is
shown and when something the scene cannot express changes (``BrowserExplorer.set``: a length, a mass, a load). For
each catalog problem, the CPU time (``time.process_time``, this process only: the machine is shared) of:

* ``explore(problem)``: the scene of 360 positions with the graphical route, and its JSON in the widget's trait;
* ``ex.set("mass.K", ...)``: a new mass of the link with the largest inertia force: a new scene, its JSON;

the JSON's size (sent once per scene), and the messages a moved position costs the kernel: none. The browser's side
(an input event to the SVG updated) is measured by ``bench_scene_browser.py`` and ``make e2e``.

The kernel-drawn explorer this replaced cost the kernel 14–156 ms per new position after a pause and 30–190 ms on a
jump (benchmarks/README.md, "The notebook explorer").

    PYTHONPATH=. .venv/bin/python benchmarks/bench_explorer.py
"""

from __future__ import annotations

import time

import numpy as np

from graphkin import catalog
from graphkin.widgets import explore


def _cpu(f):
    t = time.process_time()
    out = f()
    return out, time.process_time() - t


def main():
    print(f"{'problem':<36}{'positions':>10}{'explore s':>11}{'set mass s':>12}{'JSON kB':>9}"
          f"{'messages a position':>21}")
    for name in catalog.names():
        problem = catalog.load(name)
        ex, shown = _cpu(lambda: explore(problem))  # noqa: B023 - called at once
        sizes = {k["link"]: float(np.nanmax(np.abs(np.array(k["force"], float)))) for k in ex.scene["inertia"]}
        changed = "-"
        if sizes:
            link = max(sizes, key=sizes.get)
            mass = 2 * problem.mechanism.link(link).mass
            _, spent = _cpu(lambda: ex.set(f"mass.{link}", mass))  # noqa: B023 - called at once
            changed = f"{spent:.2f}"
        print(f"{name:<36}{ex.scene['n']:>10}{shown:>11.2f}{changed:>12}{len(ex.widget.scene) / 1e3:>9.0f}{0:>21}")


if __name__ == "__main__":
    main()
