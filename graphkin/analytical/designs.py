"""Designs of one linkage solved as one batch: designs × positions, each design's constants an array.

A design study (:func:`graphkin.cycle.study`) solves one linkage with other lengths, masses, I_G, loads or speed.
Designs that differ in those numbers only -- the same links, joints and named points, the same branch, loads of
the same kinds at the same points over the same windows, solved at the same positions -- share the plan's groups
and its compiled steps. Here their positions are laid end to end, design after design, and each constant that
differs between them (a point in its link's frame, m, I_G, G, a weight, a load's value, ω, α) becomes an array
with the design's own value at each of its positions (:func:`graphkin.kinematics.solver.plan_with`). The
kinematic and force steps then run once over the whole batch, doing to each design's numbers what a solve of that
design alone does. Designs in a row that share every point and the input's rates (g groups of m: a study's coupler
masses for each crank length) share their kinematics too: the kinematic pass runs over g N positions, and the force
pass broadcasts its arrays, of shape (g, 1, N), against the designs' masses, I_G, G and loads, of shape (g, m, 1), so
that a term of the kinematics alone is worked out once for its group and a term with a number that differs between its
designs once for each design-position, by the same arithmetic as before. The results agree to rounding, not always to
the last bit: one design alone works some constants out as Python numbers (a bar's e^{iθ} factor, conj(d)/|d|²), the
batch as NumPy arrays, and the two round complex products and quotients differently in the last bit; a value that is
the difference of larger ones (a couple that is nearly 0) then differs by the rounding of those
(tests/analytical/test_designs.py).

What cannot share a batch (:func:`batch_key` says why): a gear train (its gears' branches are sampled over a
turn of each design alone) and a load that varies over the cycle (a table, a spring, a sense that follows the
motion), whose values are not numbers of the plan.
"""

from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType
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
        The global position [m] of each point asked for, as x + iy: shape (k // per, N), one row for each group of
        ``per`` designs in a row that share their kinematics.
    per : int
        Designs in a row that share every point and rate, and so the kinematics (1: each its own).
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
    per: int = 1

    def reason(self, design: int, i: int) -> str:
        """Why design ``design`` has no solution at position ``i``: the words of
        :meth:`graphkin.analytical.ForceAnalysis.reason` for that design solved alone ('' if it has one)."""
        kin = "; ".join(why for why, where in self.kin_failures.items() if where[design, i])
        kin = kin or ("" if self.kin_valid[design, i] else NOT_FINITE)
        parts = [kin] + [why for why, where in self.failures.items() if where[design, i]]
        return "; ".join(p for p in parts if p)


def _per_design(values, N: int, grid: tuple | None = None):
    """One constant of k designs: the number itself if they all have it, else each design's value N times.

    ``values`` is a list of numbers or an array (a column of :func:`solve_designs`'s designs; a list of one number
    is every design's); the number shared is a Python number either way, as a design alone has it. With ``grid``
    = (g, m), the designs g groups of m (see :func:`solve_designs`): each design's value once, shape (g, m, 1),
    to broadcast over the positions.
    """
    same, values = _every_designs(values)
    if same is not None:
        return same
    return np.repeat(values, N) if grid is None else values.reshape(*grid, 1)


def _every_designs(values) -> tuple:
    """(the number every design has, as a Python number, None) if they all have one; else (None, the values as an
    array)."""
    first = values[0]
    if isinstance(values, np.ndarray):
        return (first.item(), None) if (values == first).all() else (None, values)
    return (first, None) if all(v == first for v in values) else (None, np.asarray(values))


def _per_group(values, N: int, m: int, shape: tuple | None = None):
    """A constant every design of a group of m has (a point, a rate: see :func:`solve_designs`): the number itself
    if every design has it, else each group's value N times (shape (g N,)), or once in ``shape`` (g, 1, 1)."""
    same, values = _every_designs(values)
    if same is not None:
        return same
    values = values[::m]
    return np.repeat(values, N) if shape is None else values.reshape(shape)


def _groups(designs: Mapping, q_dot, q_ddot, k: int) -> int:
    """m, if the k designs are groups of m in a row that share every point and rate (their kinematics), else 1.

    ``designs`` holds the designs' numbers by key, each a column (a list of one number: every design's).
    """
    columns = [np.asarray(c) for key, c in designs.items() if key[0] == "point" and len(c) > 1]
    columns += [np.asarray(q_dot, dtype=float), np.asarray(q_ddot, dtype=float)]
    m = k
    for c in columns:  # the first run: the designs that have the first design's numbers
        if len(c) > 1:
            other = np.flatnonzero(c[1:m] != c[0])
            if len(other):
                m = int(other[0]) + 1
    if m == 1 or k % m:
        return 1
    for c in columns:
        if len(c) > 1:
            rows = c.reshape(k // m, m)
            if not (rows == rows[:, :1]).all():
                return 1
    return m


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


def _specs(mech: Mechanism, designs: Mapping, k: int, points: dict, q: np.ndarray, grid: tuple | None = None) -> dict:
    """:func:`graphkin.analytical.loads.load_specs` of the batch: each number one per design-position where the
    designs differ (the same expressions as for one design, design by design). A load's window is applied here,
    to each design's positions ``q`` alike: its force or torque is an array, 0 where the load does not act (as
    :func:`graphkin.analytical.loads._external_fast` makes it), and the spec's window None. With ``grid`` (g, m),
    each number that differs is of shape (g, m, 1) and a window's mask of shape (N,): they broadcast."""
    N = len(q)

    def each(key):
        return _per_design(designs[key], N, grid)

    masks: dict = {}

    def acting(value, active):
        if active is None:
            return value, None
        if active not in masks:  # where it acts over one design's positions, then over every design's
            masks[active] = active.mask(q) if grid is not None else np.tile(active.mask(q), k)
        return masks[active] * value, None

    g, specs = mech.gravity, {}
    for link in mech.moving:
        W = [-1j * m * g if g and m else 0j for m in _column(designs["mass", link])]
        # The loads on the link in the order load_specs takes them (every design has the same loads).
        loads = [(i, load) for i, load in enumerate(mech.loads) if load.link == link]
        specs[link] = (each(("mass", link)), each(("I_G", link)), each(("G", link)), _per_design(W, N, grid),
                       [(points[link, load.point], *acting(each(("load", i)), load.active))
                        for i, load in loads if isinstance(load, PointForce)],
                       [acting(each(("load", i)), load.active) for i, load in loads if not isinstance(load, PointForce)],
                       [])
    return specs




class _Groups:
    """The kinematic pass's state for g groups of positions, seen by the force pass as arrays of shape (g, 1, N),
    the designs' numbers of shape (g, m, 1): the fields :func:`graphkin.analytical.kinetostatics._pass` and its
    compiled steps read (a mechanism whose every group has one, :func:`solve_designs`)."""

    given = MappingProxyType({})

    def __init__(self, st, shape: tuple, grid: tuple):
        self.mechanism, self.static, self.al0, self.n = st.mechanism, st.static, st.al0, shape
        self.q = st.q
        self.e, self.O, self.omega, self.alpha = (_by_group(getattr(st, name), grid)
                                                  for name in ("e", "O", "omega", "alpha"))


def _by_group(d: dict, grid: tuple) -> dict:
    """Each array of ``d`` (last axis g N) as (..., g, 1, N)."""
    return {key: _grouped(x, grid) for key, x in d.items()}


def _grouped(x, grid: tuple):
    """An array whose last axis is g N positions as (..., g, 1, N); anything else as it is."""
    if isinstance(x, np.ndarray) and x.ndim:
        return x.reshape(x.shape[:-1] + grid)
    return x


def solve_designs(mech: Mechanism, designs: Sequence[dict], q, q_dot, q_ddot, *, static: bool = False,
                  points: Sequence[tuple] = (), per: int | None = None) -> Batch:
    """Kinematics and kinetostatics of k designs of one linkage at the same N positions, as one batch.

    Designs in a row that differ only in masses, I_G, G and loads (g groups of m, each group with the same points and
    input rates: a study orders its designs so, :func:`graphkin.cycle.study`) share their kinematics: the kinematic
    pass runs over one design of each group, g N positions, and the force pass takes its arrays as (g, 1, N) and
    the designs' numbers as (g, m, 1), NumPy broadcasting the two. Every design-position's numbers come of the same
    arithmetic either way. A mechanism with a group that has no compiled force step (a slider's pair, friction,
    a gear) is solved the other way, design after design laid end to end (every design-position its own).

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
    per : int, optional
        How many designs in a row share every point and rate, if the caller knows (else found here: 1 if they
        are not groups of one size).

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
    if not isinstance(q_dot, np.ndarray):
        q_dot = list(q_dot)
    if not isinstance(q_ddot, np.ndarray):
        q_ddot = list(q_ddot)
    q = np.asarray(q, dtype=float)
    base = plan_of(mech)
    m = per if per is not None else _groups(designs, q_dot, q_ddot, k) if k > 1 else 1
    if m > 1:
        g = k // m
        forces_plan = plan_with(base, {key: _per_group(designs[("point", *key)], N, m, (g, 1, 1))
                                       for key in base.points})
        forces_plan.compiled["loads"] = _specs(mech, designs, k, forces_plan.points, q, (g, m))
        forces_plan.compiled["axes"] = 3
        _program(forces_plan, mech)
        if not forces_plan.compiled["general"]:
            return _shared(mech, base, forces_plan, designs, q, q_dot, q_ddot, (g, m), static, points)
    plan = plan_with(base, {key: _per_design(designs[("point", *key)], N) for key in base.points})
    plan.compiled["loads"] = _specs(mech, designs, k, plan.points, q)
    w, al = _per_design(q_dot, N), _per_design(q_ddot, N)
    rates = (float(w), float(al)) if not (np.ndim(w) or np.ndim(al)) else (None, None)
    n = k * N
    qs = np.tile(q, k)
    crank = mech.driver.crank
    with np.errstate(all="ignore"):  # positions that cannot be assembled carry nan, by design
        # A crank's e^{iq} over one design's positions, repeated: the same numbers as over the batch's.
        st, kin_valid = run(plan, mech, qs, np.broadcast_to(w, (n,)).astype(float),
                            np.broadcast_to(al, (n,)).astype(float), rates, angles=False,
                            e_q=np.tile(np.exp(1j * q), k) if crank else None)
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


def _shared(mech, base, forces_plan, designs, q, q_dot, q_ddot, grid: tuple, static: bool, points) -> Batch:
    """:func:`solve_designs` of g groups of m designs, each group's kinematics solved once (``forces_plan``: the
    batch's plan with its points and load specs of the shapes the force pass broadcasts, compiled)."""
    g, m = grid
    k, N = g * m, len(q)
    n = g * N
    plan = plan_with(base, {key: _per_group(designs[("point", *key)], N, m) for key in base.points})
    w, al = _per_group(q_dot, N, m), _per_group(q_ddot, N, m)
    rates = (float(w), float(al)) if not (np.ndim(w) or np.ndim(al)) else (None, None)
    crank = mech.driver.crank
    shape = (g, 1, N)
    with np.errstate(all="ignore"):  # positions that cannot be assembled carry nan, by design
        st, kin_valid = run(plan, mech, np.tile(q, g), np.broadcast_to(w, (n,)).astype(float),
                            np.broadcast_to(al, (n,)).astype(float), rates, angles=False,
                            e_q=np.tile(np.exp(1j * q), g) if crank else None)
        st.static = static
        loops = {index: tuple(_grouped(x, shape) for x in loop) for index, loop in st.loops.items()}
        forces, normal, couple, effort, valid, failures = _pass(
            _Groups(st, (g, m, N), shape), forces_plan, np.broadcast_to(kin_valid.reshape(shape), (g, m, N)), loops)
        where = {key: np.broadcast_to(plan.points[key], (n,)) if key[0] == mech.frame
                 else st.O[key[0]] + st.e[key[0]] * plan.points[key] for key in points}

    def shaped(d: dict) -> dict:
        return {key: x.reshape(k, N) for key, x in d.items()}

    def each(where: np.ndarray) -> np.ndarray:  # a group's row for each of its designs
        return np.repeat(where.reshape(g, N), m, axis=0)

    return Batch(shaped(forces), shaped(normal), shaped(couple), effort.reshape(k, N), valid.reshape(k, N),
                 each(kin_valid), {why: each(x) for why, x in st.failures.items()}, shaped(failures),
                 {key: x.reshape(g, N) for key, x in where.items()}, m)
