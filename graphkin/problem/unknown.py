"""The unknown effort where the book asks for it: the torque (or slider force) on a link other than the driver.

A book gives the crank's torque and asks for the torque on the output link that holds the linkage in equilibrium
(or the force on the piston). The problem file writes the given torque as a load and names the link that carries
the unknown effort::

    [[loads]]
    type = "torque"
    link = 2
    torque = "100 N*m"      # the crank's torque, given

    [unknown]
    link = 4                # the torque on link 4 that balances it: what the book asks

The input link still sets the motion (``[driver]``); its effort T12 is then what the frame would have to add,
and the unknown is chosen at each position so that it is zero. Everything is linear in a load, so two solutions
find it: the driver's effort e0 without the unknown, and e1 with a unit of it; the unknown is X = −e0/(e1 − e0).
The problem is then solved once more with X applied as an ordinary load, so that both routes, the report and the
drawings see it like any other (T12 comes out as rounding). Where the unknown's link does not move with the input
(e1 = e0: a dead point for it) no effort there can balance the driver, and the position is not valid.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from graphkin.analytical.loads import applied
from graphkin.errors import GraphkinError
from graphkin.model import GearMesh, PointForce, Prismatic, Torque
from graphkin.model.loads import Table


@dataclass(frozen=True)
class Unknown:
    """The link that carries the unknown effort (the file's ``[unknown]``).

    Parameters
    ----------
    link : int
        A moving link other than the driver. On a slider (a link in a sliding pair with the frame) the effort is a
        force along the guide at the slider's point; on any other link, a torque (CCW positive).
    name : str
        How reports name it (default ``T4`` or ``P4``).
    """

    link: int
    name: str = ""

    def guide(self, mech) -> Prismatic | None:
        """The sliding pair of the unknown's link with the frame, if it is a slider (else None: a torque)."""
        for j in mech.joints:
            if isinstance(j, Prismatic) and j.slider == self.link and j.guide == mech.frame:
                return j
        return None

    def label(self, mech) -> str:
        """The unknown's name in reports."""
        return self.name or (f"P{self.link}" if self.guide(mech) is not None else f"T{self.link}")

    def _load(self, kin, values: np.ndarray):
        """The unknown as a load of ``values`` at the positions of ``kin`` (a table through them when several)."""
        mech = kin.mechanism
        j = self.guide(mech)
        name = self.label(mech)
        q = np.asarray(kin.q, dtype=float)
        crank = mech.driver.crank
        table = None
        if len(q) > 1:
            key = np.mod(q, 2 * math.pi) if crank else q
            order = np.argsort(key, kind="stable")
            table = Table(key[order], values[order], periodic=crank, source=f"of the unknown {name}")
        if j is None:
            return Torque(self.link, float(values[0]), name=name, table=table)
        u = np.asarray(kin.guide_direction(j), dtype=float)[0]  # a guide on the frame keeps its direction
        if table is None:  # one position: the force itself (a table needs two rows)
            return PointForce(self.link, j.point, (float(values[0] * u[0]), float(values[0] * u[1])), name=name)
        return PointForce(self.link, j.point, (float(u[0]), float(u[1])), name=name, table=table)

    def solve(self, kin, solve_forces):
        """The force analysis with the unknown found at every position and applied as a load.

        Parameters
        ----------
        kin : Kinematics
            The problem's kinematics (its mechanism without the unknown).
        solve_forces : callable
            :func:`graphkin.analytical.solve_forces`.

        Returns
        -------
        ForceAnalysis
            With the unknown among the mechanism's loads (named :meth:`label`); a position where it cannot balance
            the driver is not valid, with the reason.
        """
        mech = kin.mechanism
        lossy = [j for j in mech.joints if isinstance(j, GearMesh) and j.efficiency < 1]
        if lossy:
            raise GraphkinError(f"the unknown effort on link {self.link} is found from two solutions, as the loads "
                                f"are linear; the {lossy[0].label}'s efficiency makes them not so (its loss changes "
                                "side with the way the power flows): give the effort as a load and drive that link")
        e0 = np.asarray(solve_forces(kin).effort, dtype=float)
        unit = self._load(kin, np.ones(len(kin.q)))
        e1 = np.asarray(solve_forces(replace(kin, mechanism=replace(mech, loads=(*mech.loads, unit)))).effort,
                        dtype=float)
        per_unit = e1 - e0
        scale = np.maximum(np.abs(e0), np.abs(e1))
        dead = ~(np.abs(per_unit) > 1e-12 * np.maximum(scale, 1e-300))
        with np.errstate(divide="ignore", invalid="ignore"):
            x = np.where(dead, 0.0, -e0 / np.where(dead, 1.0, per_unit))
        x = np.where(np.isfinite(x), x, 0.0)
        load = self._load(kin, x)
        result = solve_forces(replace(kin, mechanism=replace(mech, loads=(*mech.loads, load))))
        if not dead.any():
            return result
        what = "force" if self.guide(mech) is not None else "torque"
        why = (f"the unknown {load.name} cannot balance the driver here: link {self.link} does not move with the "
               f"input at this position (a dead point for it), so no {what} on it does work")
        bad = dead & np.asarray(result.valid, dtype=bool)
        if not bad.any():
            return result
        return replace(result, valid=np.asarray(result.valid, dtype=bool) & ~bad,
                       failures={**result.failures, why: bad})

    def values(self, result) -> np.ndarray:
        """The unknown's value at each position of a result it was found for [N·m, or N along the guide]."""
        kin = result.kinematics
        load = next(ld for ld in kin.mechanism.loads if ld.name == self.label(kin.mechanism))
        value = applied(kin, load)
        if isinstance(load, Torque):
            return np.asarray(value, dtype=float)
        u = np.asarray(kin.guide_direction(self.guide(kin.mechanism)), dtype=float)
        return np.real(value) * u[:, 0] + np.imag(value) * u[:, 1]
