"""The pylinkage side of the four-bar benchmark.

What this measures
------------------
pylinkage (>= 1.3, the project's optional ``bench`` extra) computes the
*kinematics* of a linkage -- positions, velocities and accelerations of its
joints -- in a numba-compiled loop.  It has no force analysis.  This module
drives that compiled loop for the crank-rocker in ``FOURBAR`` at a constant
crank speed ``OMEGA2`` over ``n`` equally spaced crank angles, so that the
benchmark can put its time next to graphkin's vectorised force analysis of
the same linkage.

Which pylinkage API, and why
----------------------------
``pylinkage.Linkage.step_fast_with_kinematics(iterations, dt)`` -- the
public, documented entry point of pylinkage's numba path.  It is a thin
Python wrapper (it copies the 4 joint positions into the solver arrays,
calls the kernel, copies the final state back) around the ``@njit`` kernel
``pylinkage.solver.simulate_with_kinematics``, which in one compiled loop,
for every step, rotates the crank, intersects the two circles for B
(choosing the root nearest the previous B, i.e. it keeps the assembly
branch), and then solves the velocity and acceleration constraint
equations *analytically* (2x2 linear systems from differentiating the
circle constraints once and twice -- no finite differences).  So pylinkage
really does give velocities AND accelerations, exactly, from compiled code.

``time_pylinkage`` times that public call by default.  ``api="kernel"``
times the bare kernel on the pre-built ``SolverData`` arrays instead (also
exported by ``pylinkage.solver``), which is the floor of what pylinkage can
do; the difference is a few microseconds of Python per call and only shows
at n = 360.

Facts of pylinkage's model that the benchmark must respect:

* The crank advances ``angular_velocity * dt`` radians *per step* (a step
  count, not time); the physical ``omega``/``alpha`` used for velocities and
  accelerations are separate inputs set with ``Linkage.set_input_velocity``.
  Here: ``angular_velocity = 2*pi/n``, ``dt = 1``, ``omega = OMEGA2``,
  ``alpha = 0``.
* The kernel rotates *before* it records, so the crank starts at
  ``-2*pi/n``; recorded step k is then at theta2 = 2*pi*k/n, k = 0..n-1,
  the same angles as ``reference_kinematics``.
* The loop is sequential (each step starts from the previous crank angle,
  read back with atan2, and from the previous B for branch choice), so it
  cannot be vectorised over angles; it runs on one core.
* numba itself is *not* a hard dependency of pylinkage: without it the
  ``@njit`` decorators are no-ops and the same code runs as (very slow)
  pure Python.  Install ``pylinkage[numba]``; ``prepare`` refuses to run
  without numba so the benchmark never silently times the fallback.

Run ``python benchmarks/pylinkage_side.py`` for the correctness check
against the closed-form numpy four-bar and the timings.
"""

from __future__ import annotations

import timeit
from math import pi

import numpy as np

FOURBAR = dict(a1=0.500, a2=0.085, a3=0.235, a4=0.550)
"""m: ground A0B0, crank A0A, coupler AB, rocker B0B; A0=(0,0), B0=(a1,0);
open assembly (B above the ground line)."""

OMEGA2 = 900 * 2 * pi / 60
"""rad/s, constant crank speed (900 rpm, counter-clockwise)."""

N_SIZES = (360, 3600, 100_000)

_PREPARED: dict[int, dict] = {}


# ---------------------------------------------------------------------------
# Closed-form numpy reference
# ---------------------------------------------------------------------------


def crank_angles(n: int) -> np.ndarray:
    """The n equally spaced crank angles used by both sides: 2*pi*k/n."""
    return 2 * pi * np.arange(n) / n


def _cross_k(v: np.ndarray) -> np.ndarray:
    """k x v for planar vectors v of shape (..., 2)."""
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


def _solve2(c1: np.ndarray, c2: np.ndarray, rhs: np.ndarray):
    """Cramer's rule for x*c1 + y*c2 = rhs, row-wise over (n, 2) arrays."""
    det = c1[:, 0] * c2[:, 1] - c1[:, 1] * c2[:, 0]
    x = (rhs[:, 0] * c2[:, 1] - rhs[:, 1] * c2[:, 0]) / det
    y = (c1[:, 0] * rhs[:, 1] - c1[:, 1] * rhs[:, 0]) / det
    return x, y


def reference_kinematics(n: int, omega2: float = OMEGA2) -> dict[str, np.ndarray]:
    """Closed-form, vectorised kinematics of the open crank-rocker.

    Positions from the circle-circle intersection (upper root); velocities
    and accelerations from the vector loop A + AB = B0 + B0B differentiated
    once and twice, solved for (omega3, omega4) and (alpha3, alpha4) by
    Cramer's rule; constant crank speed (alpha2 = 0).
    """
    a1, a2, a3, a4 = (FOURBAR[k] for k in ("a1", "a2", "a3", "a4"))
    th = crank_angles(n)
    A = a2 * np.stack([np.cos(th), np.sin(th)], axis=-1)
    B0 = np.array([a1, 0.0])

    d = B0 - A
    L = np.hypot(d[:, 0], d[:, 1])
    e = d / L[:, None]
    x = (a3**2 - a4**2 + L**2) / (2 * L)
    h = np.sqrt(a3**2 - x**2)
    B = A + x[:, None] * e + h[:, None] * _cross_k(e)  # k x e points up: open

    r3 = B - A  # coupler A->B
    r4 = B - B0  # rocker B0->B
    vA = omega2 * _cross_k(A)
    aA = -(omega2**2) * A
    # vA + w3 k x r3 = w4 k x r4
    w3, w4 = _solve2(_cross_k(r3), -_cross_k(r4), -vA)
    vB = w4[:, None] * _cross_k(r4)
    # aA + al3 k x r3 - w3^2 r3 = al4 k x r4 - w4^2 r4
    rhs = -aA + (w3**2)[:, None] * r3 - (w4**2)[:, None] * r4
    al3, al4 = _solve2(_cross_k(r3), -_cross_k(r4), rhs)
    aB = al4[:, None] * _cross_k(r4) - (w4**2)[:, None] * r4
    return dict(pos_A=A, vel_A=vA, acc_A=aA, pos_B=B, vel_B=vB, acc_B=aB)


# ---------------------------------------------------------------------------
# pylinkage side
# ---------------------------------------------------------------------------


def _build(n: int) -> dict:
    """Build the pylinkage four-bar whose recorded steps are crank_angles(n)."""
    from pylinkage import Crank, Ground, Linkage, RRRDyad

    a1, a2, a3, a4 = (FOURBAR[k] for k in ("a1", "a2", "a3", "a4"))
    step = 2 * pi / n
    theta0 = -step  # the kernel rotates before recording step 0

    # Start B exactly on the open branch; the solver then follows it
    # (nearest-root hysteresis).
    ax, ay = a2 * np.cos(theta0), a2 * np.sin(theta0)
    dx, dy = a1 - ax, -ay
    L = np.hypot(dx, dy)
    ex, ey = dx / L, dy / L
    x = (a3**2 - a4**2 + L**2) / (2 * L)
    h = np.sqrt(a3**2 - x**2)
    bx, by = ax + x * ex - h * ey, ay + x * ey + h * ex

    A0 = Ground(0.0, 0.0, name="A0")
    B0 = Ground(a1, 0.0, name="B0")
    crank = Crank(anchor=A0, radius=a2, angular_velocity=step, initial_angle=theta0, name="A")
    coupler_rocker = RRRDyad(crank.output, B0, distance1=a3, distance2=a4, x=float(bx), y=float(by), name="B")
    linkage = Linkage([A0, B0, crank, coupler_rocker], name="crank-rocker")
    linkage.set_input_velocity(crank, omega=OMEGA2, alpha=0.0)
    linkage.compile()  # builds the numba SolverData once

    components = list(linkage.components)
    return dict(
        linkage=linkage,
        start=linkage.get_coords(),  # to restart every call at theta0
        iA=components.index(crank),
        iB=components.index(coupler_rocker),
    )


def prepare(n: int) -> dict:
    """Once per n, outside timing: build the linkage, JIT-compile/warm up."""
    from pylinkage._numba_compat import HAS_NUMBA

    if not HAS_NUMBA:
        raise RuntimeError(
            "numba is not installed: pylinkage would run its pure-Python fallback. "
            "Install it with: pip install 'pylinkage[numba]'"
        )
    if n not in _PREPARED:
        _PREPARED[n] = _build(n)
        pylinkage_kinematics(n)  # JIT (or load numba's on-disk cache)
        _kernel_call(n)
    return _PREPARED[n]


def pylinkage_kinematics(n: int) -> dict[str, np.ndarray]:
    """Positions, velocities, accelerations of A and B over n equally spaced
    crank angles using pylinkage's compiled path. Returns a dict of numpy
    arrays (shape (n, 2) each): pos_A, vel_A, acc_A, pos_B, vel_B, acc_B.

    Uses the public ``Linkage.step_fast_with_kinematics``; the linkage is put
    back at its start pose first so every call computes the same n angles.
    """
    st = _PREPARED.get(n) or prepare(n)
    linkage = st["linkage"]
    linkage.set_coords(st["start"])
    pos, vel, acc = linkage.step_fast_with_kinematics(iterations=n, dt=1.0)
    iA, iB = st["iA"], st["iB"]
    return dict(
        pos_A=pos[:, iA], vel_A=vel[:, iA], acc_A=acc[:, iA],
        pos_B=pos[:, iB], vel_B=vel[:, iB], acc_B=acc[:, iB],
    )  # fmt: skip


def _kernel_call(n: int):
    """The bare numba kernel on the pre-built SolverData (no Python wrapper)."""
    from pylinkage.solver import simulate_with_kinematics

    st = _PREPARED[n]
    data = st["linkage"]._solver_data  # filled in by compile() + first call
    if "start_arr" not in st:
        st["start_arr"] = np.array(st["start"], dtype=np.float64)
    data.positions[:] = st["start_arr"]
    return simulate_with_kinematics(
        data.positions, data.velocities, data.accelerations, data.constraints,
        data.joint_types, data.parent_indices, data.constraint_offsets,
        data.solve_order, data.omega_values, data.alpha_values,
        data.crank_indices, n, 1.0,
    )  # fmt: skip


def time_pylinkage(n: int, repeat: int = 7, api: str = "linkage") -> float:
    """Best-of-``repeat`` wall time in seconds of the kinematics only (JIT
    warmed up by ``prepare``).

    api="linkage": the public ``pylinkage_kinematics(n)`` call (default).
    api="kernel":  the bare ``pylinkage.solver.simulate_with_kinematics``.
    """
    prepare(n)
    fn = {"linkage": pylinkage_kinematics, "kernel": _kernel_call}[api]
    return min(timeit.repeat(lambda: fn(n), number=1, repeat=repeat))


def _time_reference(n: int, repeat: int = 7) -> float:
    return min(timeit.repeat(lambda: reference_kinematics(n), number=1, repeat=repeat))


def max_errors(n: int) -> dict[str, float]:
    """Max |pylinkage - closed form| over the n angles, per quantity."""
    got, ref = pylinkage_kinematics(n), reference_kinematics(n)
    return {k: float(np.max(np.abs(got[k] - ref[k]))) for k in ref}


def _reference_self_check(n: int = 100_000) -> dict[str, float]:
    """Relative max error of the reference's v and a against central finite
    differences of its own positions (checks the closed form itself)."""
    r = reference_kinematics(n)
    dt = (2 * pi / n) / OMEGA2

    def ddt(x):
        return (np.roll(x, -1, axis=0) - np.roll(x, 1, axis=0)) / (2 * dt)

    out = {}
    for p in "AB":
        for k, (num, ana) in {
            "vel": (ddt(r[f"pos_{p}"]), r[f"vel_{p}"]),
            "acc": (ddt(r[f"vel_{p}"]), r[f"acc_{p}"]),
        }.items():
            out[f"{k}_{p}"] = float(np.max(np.abs(num - ana)) / np.max(np.abs(ana)))
    return out


if __name__ == "__main__":
    import numba
    import pylinkage

    print(f"pylinkage {pylinkage.__version__}, numba {numba.__version__}, numpy {np.__version__}")
    print(f"four-bar {FOURBAR} m, omega2 = {OMEGA2:.4f} rad/s")
    print("\nreference self-check (closed form vs central differences, relative):")
    print("  " + ", ".join(f"{k} {v:.1e}" for k, v in _reference_self_check().items()))

    for n in N_SIZES:
        prepare(n)
    print("\ncorrectness: max |pylinkage - closed form| (m, m/s, m/s^2)")
    for n in N_SIZES:
        e = max_errors(n)
        print(f"  n={n:>6}: " + ", ".join(f"{k} {v:.1e}" for k, v in e.items()))

    scale = {"acc": np.max(np.abs(reference_kinematics(360)["acc_B"]))}
    print(f"  (for scale: max |acc_B| = {scale['acc']:.1f} m/s^2)")

    print("\ntimings, best of 7 (positions + velocities + accelerations of all joints)")
    print(f"  {'n':>6}  {'Linkage.step_fast_with_kinematics':>34}  {'bare numba kernel':>18}  {'numpy closed form':>18}")
    for n in N_SIZES:
        t_pub = time_pylinkage(n)
        t_ker = time_pylinkage(n, api="kernel")
        t_ref = _time_reference(n)
        print(f"  {n:>6}  {t_pub * 1e3:>31.3f} ms  {t_ker * 1e3:>15.3f} ms  {t_ref * 1e3:>15.3f} ms")
