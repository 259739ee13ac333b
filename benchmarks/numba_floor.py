"""The floor: the whole four-bar force analysis as one hand-written numba loop.

For information beside ``bench_fourbar.py``: the same crank-rocker
(``pylinkage_side.FOURBAR``, open branch, 900 rpm) with the same masses
(``fourbar_linkage.fourbar()``), analysed position by position in compiled
code -- the crank's sin and cos, the circle intersection for B, the
velocity and acceleration equations by Cramer's rule, the inertia loads of
links 2, 3 and 4, the dyad's three joint forces and the crank's pivot force
and driving torque -- with the same formulas as graphkin's vectorised
solver (``graphkin/kinematics/groups.py`` and ``graphkin/analytical/kinetostatics.py``),
nothing cached between calls but the compiled function. It is what numpy's
temporaries and per-call overhead cost graphkin: the time a compiled loop
needs for the same numbers.

It is a benchmark, not part of graphkin (numba is only in the ``bench``
extra). Run ``python benchmarks/numba_floor.py`` for its check against
graphkin and its times; ``bench_fourbar.py`` prints it as row 6.
"""

from __future__ import annotations

import math
import sys
import timeit
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import pylinkage_side as ps  # noqa: E402
from fourbar_linkage import MECH  # noqa: E402

N_SIZES = (360, 3600, 100_000, 1_000_000)


def _constants():
    """Lengths, masses and centres of mass of fourbar_linkage.fourbar(), as numbers for the kernel."""
    a1, a2, a3, a4 = (ps.FOURBAR[k] for k in ("a1", "a2", "a3", "a4"))
    l2, l3, l4 = (MECH.link(i) for i in (2, 3, 4))
    # G of the coupler from A, of the rocker from B0, in their own frames (x along AB, along B0B).
    return (a1, a2, a3, a4, l2.I_G, l3.mass, l3.G[0], l3.G[1], l3.I_G, l4.mass, l4.G[0], l4.G[1], l4.I_G)


def _compile():
    from numba import njit

    @njit(cache=False, error_model="numpy")
    def analyse(theta, w2, al2, c, T12, F12, F23, F34, F14, valid):
        a1, a2, a3, a4, I2, m3, g3x, g3y, I3, m4, g4x, g4y, I4 = c
        half_c = 0.5 * (a3 * a3 - a4 * a4)
        dead = 1e-7 * a3 * a4
        for i in range(theta.shape[0]):
            cs, sn = math.cos(theta[i]), math.sin(theta[i])
            # Crank pin A; its velocity and acceleration (A0 fixed at the origin).
            Ax, Ay = a2 * cs, a2 * sn
            vAx, vAy = -w2 * Ay, w2 * Ax
            aAx, aAy = -al2 * Ay - w2 * w2 * Ax, al2 * Ax - w2 * w2 * Ay
            # B: X1 + D z with D = B0 - A, z = t + i h/|D| (sigma = +1).
            Dx, Dy = a1 - Ax, -Ay
            dd2 = Dx * Dx + Dy * Dy
            t = 0.5 + half_c / dd2
            h2 = a3 * a3 / dd2 - t * t
            size = dd2 * math.sqrt(h2) if h2 >= 0 else math.nan
            if not size > dead:  # cannot be assembled, or at a dead point
                valid[i] = False
                T12[i] = math.nan
                continue
            s = size / dd2
            r12x, r12y = Dx * t - Dy * s, Dy * t + Dx * s  # A -> B
            r23x, r23y = Dx - r12x, Dy - r12y  # B -> B0
            det = -size  # r12 x r23
            # Velocities: -vA = w3 k x r12 + w4 k x r23.
            w3 = -(vAx * r23x + vAy * r23y) / det
            w4 = (r12x * vAx + r12y * vAy) / det
            # Accelerations: the same columns, with the centripetal terms.
            rx = w3 * w3 * r12x - aAx + w4 * w4 * r23x
            ry = w3 * w3 * r12y - aAy + w4 * w4 * r23y
            al3 = (rx * r23x + ry * r23y) / det
            al4 = -(r12x * rx + r12y * ry) / det
            # Inertia of the coupler: G from A, e3 = r12 / a3; a_G = a_A + (i al - w^2) rho.
            e3x, e3y = r12x / a3, r12y / a3
            p3x, p3y = e3x * g3x - e3y * g3y, e3x * g3y + e3y * g3x
            F3x = -m3 * (aAx - al3 * p3y - w3 * w3 * p3x)
            F3y = -m3 * (aAy + al3 * p3x - w3 * w3 * p3y)
            # Inertia of the rocker: G from B0, e4 = -r23 / a4, B0 fixed.
            e4x, e4y = -r23x / a4, -r23y / a4
            p4x, p4y = e4x * g4x - e4y * g4y, e4x * g4y + e4y * g4x
            F4x = -m4 * (-al4 * p4y - w4 * w4 * p4x)
            F4y = -m4 * (al4 * p4x - w4 * w4 * p4y)
            # Moments about B: G - B = rho - r12 on the coupler, rho + r23 on the rocker.
            Mj = (p3x - r12x) * F3y - (p3y - r12y) * F3x - I3 * al3
            Mk = (p4x + r23x) * F4y - (p4y + r23y) * F4x - I4 * al4
            # The dyad's reactions: F1 (2 on 3), F3 (1 on 4), F2 = F1 + F_3 (3 on 4).
            Tx, Ty = F3x + F4x, F3y + F4y
            b3 = Mk - (r23x * Ty - r23y * Tx)
            F1x = (b3 * r12x - Mj * r23x) / -det
            F1y = (b3 * r12y - Mj * r23y) / -det
            F23[i, 0], F23[i, 1] = F1x, F1y
            F34[i, 0], F34[i, 1] = F1x + F3x, F1y + F3y
            F14[i, 0], F14[i, 1] = -(Tx + F1x), -(Ty + F1y)
            # The crank (G2 on the pivot): pivot force and driving torque.
            F12[i, 0], F12[i, 1] = F1x, F1y
            T12[i] = (Ax * F1y - Ay * F1x) + I2 * al2
            valid[i] = True

    return analyse


_KERNEL = None
_CONSTANTS = None


def prepare():
    """Compile the kernel (outside timing); raises if numba is missing."""
    global _KERNEL, _CONSTANTS
    if _KERNEL is None:
        _KERNEL, _CONSTANTS = _compile(), _constants()
        floor(np.zeros(4))
    return _KERNEL


def floor(theta: np.ndarray, omega2: float = ps.OMEGA2, alpha2: float = 0.0) -> dict[str, np.ndarray]:
    """The whole force analysis at crank angles ``theta``: T12 and the four joint forces, fresh arrays."""
    kernel = _KERNEL or prepare()
    n = len(theta)
    out = dict(T12=np.empty(n), F12=np.empty((n, 2)), F23=np.empty((n, 2)), F34=np.empty((n, 2)),
               F14=np.empty((n, 2)), valid=np.empty(n, bool))
    kernel(theta, omega2, alpha2, _CONSTANTS, out["T12"], out["F12"], out["F23"], out["F34"], out["F14"], out["valid"])
    return out


def max_difference(n: int = 3600) -> float:
    """Largest difference from graphkin's solve over every output, relative to its largest value."""
    from graphkin.analytical import solve

    theta = ps.crank_angles(n)
    got, r = floor(theta), solve(MECH, theta, ps.OMEGA2, 0.0)
    worst = np.max(np.abs(got["T12"] - r.effort)) / np.max(np.abs(r.effort))
    for name in ("F12", "F23", "F34", "F14"):
        want = r[name]
        worst = max(worst, np.max(np.abs(got[name] - want)) / np.max(np.abs(want)))
    return float(worst)


def time_floor(n: int, repeat: int = 7) -> float:
    """Best-of-``repeat`` wall time [s] of :func:`floor` at n positions (compiled beforehand)."""
    prepare()
    theta = ps.crank_angles(n)
    return min(timeit.repeat(lambda: floor(theta), number=1, repeat=repeat))


if __name__ == "__main__":
    import numba

    prepare()
    print(f"numba {numba.__version__}, numpy {np.__version__}")
    print(f"max |numba - graphkin| / max |graphkin| over T12, F12, F23, F34, F14 (n = 3600): {max_difference():.1e}")
    print(f"\n{'n':>9}  {'time':>10}  {'per position':>12}")
    for n in N_SIZES:
        t = time_floor(n, repeat=max(3, min(200, int(2e6 / n))))
        print(f"{n:>9,}  {t * 1e3:7.3f} ms  {t / n * 1e9:9.1f} ns")
