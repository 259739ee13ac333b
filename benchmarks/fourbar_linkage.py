"""The benchmark's crank-rocker: pylinkage_side.FOURBAR's lengths with the strip cutter's mass properties.

One home for the linkage that bench_fourbar.py times and numba_floor.py compiles by hand.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import pylinkage_side as ps  # noqa: E402

from graphkin.model import Driver, Link, Mechanism, Revolute  # noqa: E402


def _polar(r: float, deg: float) -> tuple[float, float]:
    return (r * math.cos(math.radians(deg)), r * math.sin(math.radians(deg)))


def fourbar() -> Mechanism:
    """pylinkage_side.FOURBAR with the strip cutter's mass properties."""
    a1, a2, a3, a4 = (ps.FOURBAR[k] for k in ("a1", "a2", "a3", "a4"))
    links = [
        Link(1, {"A0": (0.0, 0.0), "B0": (a1, 0.0)}, name="frame"),
        # m2 = 3 kg, k2 = 100 mm, G2 at A0
        Link(2, {"A0": (0.0, 0.0), "A": (a2, 0.0)}, mass=3.0, G=(0.0, 0.0), I_G=3.0 * 0.100**2, name="crank"),
        # m3 = 2 kg, k3 = 268 mm, AG3 = 231 mm at -1 deg from AB
        Link(3, {"A": (0.0, 0.0), "B": (a3, 0.0)}, mass=2.0, G=_polar(0.231, -1.0), I_G=2.0 * 0.268**2,
             name="coupler"),
        # m4 = 5.1 kg, k4 = 424 mm, B0G4 = 305 mm at -7 deg from B0B
        Link(4, {"B0": (0.0, 0.0), "B": (a4, 0.0)}, mass=5.1, G=_polar(0.305, -7.0), I_G=5.1 * 0.424**2,
             name="rocker"),
    ]  # fmt: skip
    joints = [Revolute((1, 2), "A0"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), Revolute((1, 4), "B0")]
    # RRR dyad 3-4: sigma = +1 puts B left of the directed line A -> B0, i.e. above ground.
    return Mechanism(links, joints, Driver(2, "crank"), assembly={"B": +1}, title="benchmark crank-rocker")


MECH = fourbar()
