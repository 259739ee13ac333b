"""Rebuild every figure in figures/: the side-by-side figure and construction frames of the problems the
README and the lessons show (:data:`SHOWN`; name others on the command line), the whole-cycle figures of
lessons 03–05, and the worked-solution handouts of figures/handouts/. The docs site's catalog page draws
every catalog problem when it is built, so figures/ need not hold them all.

Run with ``make figures``. A problem with several positions is drawn at one
representative position, named below.
"""

from __future__ import annotations

import math
import shutil
import sys
from pathlib import Path

import numpy as np

from graphkin import catalog, draw
from graphkin.graphical import construct_forces

HERE = Path(__file__).resolve().parent
SHOWN = ("double_slider", "engine_gas_force", "engine_static_khurmi", "gearset", "shaper_six_bar", "single_link",
         "slider_crank_friction", "strip_cutter")
"""The problems whose figures the README, the lessons and docs/ show."""
AT = {
    "strip_cutter": math.radians(140.0),  # mid-cut: the 2000 N cutting force acts
    "slider_crank_friction": math.radians(60.0),
}


def build(name: str) -> list[Path]:
    problem = catalog.load(name)
    at = [AT[name]] if name in AT else None
    result = problem.solve(at)
    c = construct_forces(result.kinematics, 0)
    if not c.valid:
        raise SystemExit(f"{name}: {c.reason}")
    written = [draw.save(draw.draw_solution(c, result), HERE / f"{name}.png")]
    frames = HERE / name
    shutil.rmtree(frames, ignore_errors=True)
    frames.mkdir()
    for k, fig in enumerate(draw.draw_steps(c), start=1):
        written.append(draw.save(fig, frames / f"step{k:02d}.png", dpi=110))
    return written


CYCLES = {
    # name: (positions over the turn, coefficient of speed fluctuation for the flywheel)
    "strip_cutter": (360, 0.05),  # lessons 03 (torque, polar plots, peaks) and 04 (flywheel)
    "slider_crank_friction": (360, 0.05),  # lesson 05
}


def build_cycle(name: str) -> list[Path]:
    """The cycle figure (torque with its pulses, polar joint forces, energy) and the flywheel's before/after."""
    from graphkin.cycle import sweep

    n, Cs = CYCLES[name]
    cycle = sweep(catalog.load(name), n)
    written = [draw.save(draw.draw_cycle(cycle, Cs=Cs), HERE / f"{name}_cycle.png")]
    before_after = draw.draw_torque_curve(cycle, flywheel=cycle.flywheel(Cs))
    written.append(draw.save(before_after, HERE / f"{name}_flywheel.png"))
    return written


def build_handouts(names=None) -> list[Path]:
    """The worked-solution handouts of figures/handouts/ (their PDFs and page images), by its own build.py."""
    import runpy

    handouts = runpy.run_path(str(HERE / "handouts" / "build.py"))
    return [p for name in handouts["PROBLEMS"] if not names or name in names for p in handouts["build"](name)]


def main(names=None) -> int:
    for name in names or SHOWN:
        for path in build(name) + (build_cycle(name) if name in CYCLES else []):
            print(path.relative_to(HERE.parent))
    path = draw.save(draw.draw_sign_convention().ax.figure, HERE / "sign_convention.png")
    print(path.relative_to(HERE.parent))
    for path in build_handouts(names):
        print(path.relative_to(HERE.parent))
    return 0


if __name__ == "__main__":
    np.seterr(all="raise")
    sys.exit(main(sys.argv[1:]))
