"""The joint-force index of Holte and Chase (Norton, *Design of Machinery*, §11.12).

At each position, the largest static joint force divided by the external load:

    JFI = max |F_ij| / |F_ext|      (a force load: dimensionless, eq. 11.23a)
    JFI = max |F_ij| / |T_ext|      (a torque load: units 1/m, eq. 11.23b)

The joint forces come from a *static* force analysis: the same linkage with
every mass and moment of inertia set to zero (so no inertia loads and no
weights), the external loads kept. Holte and Chase suggest keeping the index
below about 2 for linkages whose output is a force. Near an immovable position
(a toggle: the input joint cannot move the linkage) the index grows without
bound; such positions are reported, never raised.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from graphkin.analytical import ForceAnalysis
from graphkin.analytical.loads import applied
from graphkin.cycle._sampling import Peak, check_problem, peak_of, sweep_positions
from graphkin.cycle.flywheel import _positive
from graphkin.errors import GraphkinError
from graphkin.model import PointForce, Torque

if TYPE_CHECKING:
    from graphkin.problem import Problem

SINGULAR = 1e6
"""Index above which a position is taken as immovable.

Near a toggle the dyad's position comes from the square root of a small
difference, so it carries a rounding error of order √ε ≈ 1e-8 rad and the
kinematics may not flag the toggle itself as a dead point. An index of 1e6
means the linkage is within about a micro-radian of the toggle: the forces
there are rounding noise, not a property of the design.
"""


@dataclass(frozen=True)
class JointForceIndex:
    """The joint-force index over a cycle (made by :func:`joint_force_index`).

    Attributes
    ----------
    q : ndarray, shape (n,)
        Input positions: θ [rad] or s [m].
    index : ndarray, shape (n,)
        JFI at each position; nan where there is no external load, or the
        position is immovable or cannot be assembled.
    load : ndarray, shape (n,)
        The external load the index divides by: the largest magnitude of the
        external forces acting there [N] (or of the external torques [N·m],
        if the mechanism carries torque loads only).
    units : str
        ``""`` (dimensionless, force load) or ``"1/m"`` (torque load).
    joint : ndarray of str, shape (n,)
        Name of the joint force that is largest at each position (``"F34"``); '' where none.
    peak : Peak
        Largest index and where it occurs.
    limit : float
        The threshold checked (2, after Holte and Chase).
    over_limit : ndarray, shape (k,)
        Positions where the index exceeds ``limit``.
    immovable : tuple of (float, str)
        Positions with no static solution, each with the reason (a dead
        point, cannot be assembled, or an index above ``SINGULAR``).
    unloaded : ndarray, shape (k,)
        Positions where no external load acts, so the index is undefined.
    analysis : ForceAnalysis
        The static force analysis the index comes from.
    """

    q: np.ndarray
    index: np.ndarray
    load: np.ndarray
    units: str
    joint: np.ndarray
    peak: Peak
    limit: float
    over_limit: np.ndarray
    immovable: tuple[tuple[float, str], ...]
    unloaded: np.ndarray
    analysis: ForceAnalysis


def static_problem(problem: "Problem") -> "Problem":
    """The same problem with every link's mass and moment of inertia set to zero.

    Parameters
    ----------
    problem : Problem
        The mechanism with its loads.

    Returns
    -------
    Problem
        Its external loads only: what the joint-force index is measured with.
    """
    mech = problem.mechanism
    links = tuple(replace(link, mass=0.0, I_G=0.0) for link in mech.links)
    return replace(problem, mechanism=replace(mech, links=links), given={})


def _reference_load(problem: "Problem", kin) -> tuple[np.ndarray, str]:
    """The external load the index divides by at each position of ``kin``, and the index's units."""
    mech = problem.mechanism
    forces = [l for l in mech.loads if isinstance(l, PointForce)]
    torques = [l for l in mech.loads if isinstance(l, Torque)]
    if not forces and not torques:
        raise GraphkinError(f"{problem.name}: no external load, so the joint-force index is undefined")
    # What each load applies here (window, table and sense included): a tabulated gas force sets the scale.
    if forces:
        on, units = [np.abs(applied(kin, l)) for l in forces], ""
    else:
        on, units = [np.abs(applied(kin, l)) for l in torques], "1/m"
    return np.max(on, axis=0), units


def joint_force_index(problem: "Problem", n: int | None = None, *, limit: float = 2.0) -> JointForceIndex:
    """Holte and Chase's joint-force index over a cycle (Norton §11.12).

    Parameters
    ----------
    problem : Problem
        The mechanism and its external loads; its masses and inertias are
        ignored (a static analysis, :func:`static_problem`).
    n : int, optional
        As in :func:`graphkin.cycle.sweep`: n equally spaced crank angles
        over one turn, or the problem's own positions if None (and the
        samples either side of where a load switches on or off).
    limit : float
        Index to flag (2 by default).

    Returns
    -------
    JointForceIndex
        The index at every position, the joint that sets it, the load it is measured against, its peak and the
        positions over the limit.

    Notes
    -----
    With several force loads the index divides by the largest one acting at
    that position (the strip cutter's two 2000 N cutting forces give 2000 N).
    Torque loads are applied but only set the reference when there is no
    force load; then the index has units 1/m and only compares linkages of
    similar size in the same units.

    Examples
    --------
    >>> from graphkin import catalog
    >>> jfi = joint_force_index(catalog.load("strip_cutter"))
    >>> bool(np.isnan(jfi.index[0])), jfi.units      # no cutting force at θ = 0
    (True, '')
    """
    check_problem(problem, "joint_force_index")
    return index_at(problem, sweep_positions(problem, n), limit)


def index_at(problem: "Problem", at, limit: float = 2.0) -> JointForceIndex:
    """:func:`joint_force_index` at input positions ``at`` (SI; None for the problem's own)."""
    limit = _positive(limit, "limit")
    static = static_problem(problem)
    result = static.solve(at=at)
    q = result.kinematics.q
    load, units = _reference_load(problem, result.kinematics)
    names = np.array([result.name_of(i, j) for i, j in result.forces] + [""])
    F = np.array([np.hypot(f[:, 0], f[:, 1]) for f in result.forces.values()])
    finite = np.all(np.isfinite(F), axis=0)
    largest = np.max(np.where(np.isfinite(F), F, -np.inf), axis=0)
    which = np.where(finite, np.argmax(np.where(np.isfinite(F), F, -np.inf), axis=0), len(names) - 1)
    loaded = load > 0
    with np.errstate(divide="ignore", invalid="ignore"):
        raw = np.where(loaded & result.valid, largest / np.where(loaded, load, 1.0), np.nan)
    singular = result.valid & (raw > SINGULAR)
    stuck = ~result.valid | singular
    index = np.where(stuck, np.nan, raw)
    immovable = tuple(
        (float(q[i]), result.reason(i) if not result.valid[i]
         else f"joint forces over {SINGULAR:g} × the load: the linkage is at a toggle (immovable)")
        for i in np.flatnonzero(stuck)
    )
    with np.errstate(invalid="ignore"):
        over = q[index > limit]
    return JointForceIndex(q, index, load, units, np.where(stuck | ~loaded, "", names[which]), peak_of(index, q),
                           float(limit), over, immovable, q[~loaded & ~stuck], result)
