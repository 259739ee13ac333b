"""Designs of one linkage solved as one batch: designs × positions, each design's constants an array.

A design study (:func:`graphkin.cycle.study`) solves one linkage with other lengths, masses, I_G, loads or speed.
Designs that differ in those numbers only -- the same links, joints and named points, the same branch, loads of
the same kinds at the same points over the same windows, solved at the same positions -- share the plan's groups
and its compiled steps. Here their positions are laid end to end, design after design, and each constant that
differs between them (a point in its link's frame, m, I_G, G, a weight, a load's value, ω, α) becomes an array
with the design's own value at each of its positions (:func:`graphkin.kinematics.solver.plan_with`). The
kinematic and force steps then run once over the whole batch, doing to each design's numbers what a solve of
that design alone does. The results agree to rounding, not always to the last bit: one design alone works some
constants out as Python numbers (a bar's e^{iθ} factor, conj(d)/|d|²), the batch as NumPy arrays, and the two
round complex products and quotients differently in the last bit; a value that is the difference of larger ones
(a couple that is nearly 0) then differs by the rounding of those (tests/analytical/test_designs.py).

What cannot share a batch (:func:`batch_key` says why): a gear train (its gears' branches are sampled over a
turn of each design alone) and a load that varies over the cycle (a table, a spring, a sense that follows the
motion), whose values are not numbers of the plan.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping, Sequence

import numpy as np

from graphkin.analytical.kinetostatics import _pass, _program
from graphkin.kinematics import Kinematics
from graphkin.kinematics.plan import plan_of
from graphkin.kinematics.solver import plan_with, run
from graphkin.model import GearMesh, Mechanism, PointForce

__all__ = ["Batch", "batch_key", "numbers", "solve_designs"]

NOT_FINITE = "the motion is not finite there (no group says why)"
""":meth:`graphkin.kinematics.Kinematics.reason`'s words for a position no group explains."""


def batch_key(mech: Mechanism) -> tuple[tuple | None, str | None]:
    """What designs must share to be solved in one batch, and why a linkage cannot be (None and the reason).

    Returns
    -------
    key : tuple or None
        Hashable: the links' numbers and point names, the joints, the driver, gravity, the branch and the loads'
        kinds, links, points and windows. Two designs with equal keys (and positions) can share a batch.
    why : str or None
        Why none can be made, in a clause: "a gear train ...".
    """
    if any(isinstance(joint, GearMesh) for joint in mech.joints):
        return None, "a gear train (its gears' branches are found over a turn of each design alone)"
    if any(load.varies for load in mech.loads):
        return None, ("a load that varies over the cycle (a table, a spring, or a sense that follows the motion), "
                      "which is not a number of the plan")
    loads = tuple((type(load), load.link, getattr(load, "point", None), load.active, load.name, load.sense)
                  for load in mech.loads)
    key = (tuple((link.number, tuple(link.points)) for link in mech.links), mech.joints, mech.driver,
           mech.gravity, tuple(sorted(mech.assembly.items())), mech.frame, loads)
    try:
        hash(key)
    except TypeError:  # a part that holds arrays: such designs are solved one by one
        return None, "a part of the model that is not made of numbers"
    return key, None


@dataclass(frozen=True)
class Batch:
    """k designs of one linkage solved at the same N positions: every array has shape (k, N).

    Attributes
    ----------
    forces : dict of (int, int) to complex ndarray
        Force of the lower-numbered link on the higher, per joint, as Fx + i Fy [N].
    normal, couple : dict of (int, int) to ndarray
        A prismatic pair's normal force [N] and couple [N·m].
    effort : ndarray
        The driving torque [N·m] (a slider driver: its force [N]).
    valid : ndarray of bool
        Where the design has a solution.
    kin_valid : ndarray of bool
        Where its kinematics have one.
    kin_failures, failures : dict of str to ndarray of bool
        Why not, by the kinematics and by the force analysis.
    points : dict of (int, str) to complex ndarray
        The global position [m] of each point asked for, as x + iy.
    """

    forces: Mapping[tuple, np.ndarray]
    normal: Mapping[tuple, np.ndarray]
    couple: Mapping[tuple, np.ndarray]
    effort: np.ndarray
    valid: np.ndarray
    kin_valid: np.ndarray
    kin_failures: Mapping[str, np.ndarray]
    failures: Mapping[str, np.ndarray]
    points: Mapping[tuple, np.ndarray]

    def reason(self, design: int, i: int) -> str:
        """Why design ``design`` has no solution at position ``i``: the words of
        :meth:`graphkin.analytical.ForceAnalysis.reason` for that design solved alone ('' if it has one)."""
        kin = "; ".join(why for why, where in self.kin_failures.items() if where[design, i])
        kin = kin or ("" if self.kin_valid[design, i] else NOT_FINITE)
        parts = [kin] + [why for why, where in self.failures.items() if where[design, i]]
        return "; ".join(p for p in parts if p)


def _per_design(values, N: int):
    """One constant of k designs: the number itself if they all have it, else each design's value N times.

    ``values`` is a list of numbers or an array (a column of :func:`solve_designs`'s designs; a list of one number
    is every design's); the number shared is a Python number either way, as a design alone has it.
    """
    if isinstance(values, np.ndarray):
        first = values[0]
        if (values == first).all():
            return first.item()
        return np.repeat(values, N)
    first = values[0]
    if all(v == first for v in values):
        return first
    return np.repeat(np.asarray(values), N)


def _column(values) -> list:
    """A column of numbers as Python numbers, for arithmetic done design by design as a design alone does it."""
    return values.tolist() if isinstance(values, np.ndarray) else values


def numbers(mech: Mechanism) -> dict:
    """The numbers of a design that a batch takes as arrays, by what they are.

    ``("point", link, name)``: a named point in its link's frame [m], complex; ``("mass", link)`` [kg],
    ``("I_G", link)`` [kg·m²] and ``("G", link)`` [m, complex] of each link; ``("load", i)``: the force [N, complex]
    or torque [N·m] of the i-th load. Designs of one :func:`batch_key` have the same keys.
    """
    out = {("point", link.number, name): complex(x, y) for link in mech.links for name, (x, y) in link.points.items()}
    for link in mech.links:
        out["mass", link.number], out["I_G", link.number], out["G", link.number] = link.mass, link.I_G, complex(*link.G)
    for i, load in enumerate(mech.loads):
        out["load", i] = complex(*load.force) if isinstance(load, PointForce) else load.torque
    return out


def _specs(mech: Mechanism, designs: Mapping, k: int, points: dict, q: np.ndarray) -> dict:
    """:func:`graphkin.analytical.loads.load_specs` of the batch: each number one per design-position where the
    designs differ (the same expressions as for one design, design by design). A load's window is applied here,
    to each design's positions ``q`` alike: its force or torque is an array, 0 where the load does not act (as
    :func:`graphkin.analytical.loads._external_fast` makes it), and the spec's window None."""
    N = len(q)

    def each(key):
        return _per_design(designs[key], N)

    masks: dict = {}

    def acting(value, active):
        if active is None:
            return value, None
        if active not in masks:  # where it acts over one design's positions, then over every design's
            masks[active] = np.tile(active.mask(q), k)
        return masks[active] * value, None

    g, specs = mech.gravity, {}
    for link in mech.moving:
        W = [-1j * m * g if g and m else 0j for m in _column(designs["mass", link])]
        # The loads on the link in the order load_specs takes them (every design has the same loads).
        loads = [(i, load) for i, load in enumerate(mech.loads) if load.link == link]
        specs[link] = (each(("mass", link)), each(("I_G", link)), each(("G", link)), _per_design(W, N),
                       [(points[link, load.point], *acting(each(("load", i)), load.active))
                        for i, load in loads if isinstance(load, PointForce)],
                       [acting(each(("load", i)), load.active) for i, load in loads if not isinstance(load, PointForce)],
                       [])
    return specs


def solve_designs(mech: Mechanism, designs: Sequence[dict], q, q_dot, q_ddot, *, static: bool = False,
                  points: Sequence[tuple] = ()) -> Batch:
    """Kinematics and kinetostatics of k designs of one linkage at the same N positions, as one batch.

    Parameters
    ----------
    mech : Mechanism
        One of the designs, with a :func:`batch_key` (not None): its links, joints, loads and driver are every
        design's.
    designs : sequence of dict, or dict of key to sequence
        Each design's :func:`numbers`; or, by key of those numbers, each design's value (a list or an array, a
        column of the designs' numbers: a study builds them so, without a dict per design; a list of one number
        where every design has it).
    q : ndarray, shape (N,)
        Input positions [rad or m], every design's.
    q_dot, q_ddot : sequence of float, length k
        Each design's constant input speed and acceleration [rad/s, rad/s² or m/s, m/s²].
    static : bool, optional
        A static force analysis (no inertia loads).
    points : sequence of (int, str)
        Named points whose global positions the result should keep.

    Returns
    -------
    Batch
        Each design's numbers those of a solve of that design alone, to rounding
        (:func:`graphkin.analytical.solve_forces` of :func:`graphkin.kinematics.solve_kinematics`).

    Examples
    --------
    >>> from graphkin import catalog
    >>> m = catalog.load("strip_cutter").mechanism
    >>> longer = numbers(m) | {("point", 2, "A"): 0.09 + 0j}
    >>> b = solve_designs(m, [numbers(m), longer], np.radians([0.0, 90.0]), [94.25] * 2, [0.0] * 2)
    >>> b.effort.shape, bool(b.valid.all())
    ((2, 2), True)
    """
    k, N = len(q_dot), len(q)
    if not isinstance(designs, Mapping):  # a dict per design: as columns, a list per number
        designs = {key: [d[key] for d in designs] for key in designs[0]}
    base = plan_of(mech)
    plan = plan_with(base, {key: _per_design(designs[("point", *key)], N) for key in base.points})
    plan.compiled["loads"] = _specs(mech, designs, k, plan.points, np.asarray(q, dtype=float))
    w, al = _per_design(q_dot if isinstance(q_dot, np.ndarray) else list(q_dot), N), \
        _per_design(q_ddot if isinstance(q_ddot, np.ndarray) else list(q_ddot), N)
    rates = (float(w), float(al)) if not (np.ndim(w) or np.ndim(al)) else (None, None)
    n = k * N
    qs = np.tile(np.asarray(q, dtype=float), k)
    crank = mech.driver.crank
    with np.errstate(all="ignore"):  # positions that cannot be assembled carry nan, by design
        # A crank's e^{iq} over one design's positions, repeated: the same numbers as over the batch's.
        st, kin_valid = run(plan, mech, qs, np.broadcast_to(w, (n,)).astype(float),
                            np.broadcast_to(al, (n,)).astype(float), rates, angles=False,
                            e_q=np.tile(np.exp(1j * np.asarray(q, dtype=float)), k) if crank else None)
        st.static = static
        _program(plan, mech)
        kin = Kinematics(mech, st.q, st.q_dot, st.q_ddot, st.theta, st.omega, st.alpha, st.e, st.O, st.v_O, st.a_O,
                         kin_valid, st.failures, plan.groups, static=static, points=plan.points) \
            if plan.compiled["general"] else st
        forces, normal, couple, effort, valid, failures = _pass(kin, plan, kin_valid, st.loops)
        # A point of the frame is where the frame has it (its own, or each design's, repeated over its positions).
        where = {key: np.broadcast_to(plan.points[key], (n,)) if key[0] == mech.frame
                 else st.O[key[0]] + st.e[key[0]] * plan.points[key] for key in points}

    def shaped(d: dict) -> dict:
        return {key: x.reshape(k, N) for key, x in d.items()}

    return Batch(shaped(forces), shaped(normal), shaped(couple), effort.reshape(k, N), valid.reshape(k, N),
                 kin_valid.reshape(k, N), shaped(st.failures), shaped(failures), shaped(where))
