"""The equilibrium equations of every moving link as one matrix, [A]{x} = {b}.

This is Norton's matrix method (Design of Machinery, §11.2–11.5): three rows
per moving link — ΣFx, ΣFy and ΣM about the link's centre of mass — and one
column per unknown: two per revolute joint (F_ijx, F_ijy), two per prismatic
pair (normal force N_ij and couple C_ij), one per gear mesh (tooth force
along the pressure line) and the driving torque or force. The right-hand side
holds the known loads moved across: m a_G − ΣF_ext, I_G α − ΣM_ext.

Where a coefficient depends on the sign of an unknown — Coulomb friction
(μ|N|) or the flank a gear tooth pushes on — the sign is taken from the
closed-form solution, as the seeds do with F14x = ±μF14y and F32x = c F32y; so is
the side of a mesh with an efficiency that loses power, which moves its tooth
force's line off the pitch point (:func:`graphkin.analytical.meshes.contact`).
The lessons display this system; the tests check that solving it gives the
same answer as :func:`graphkin.analytical.solve_forces`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from graphkin.analytical.kinetostatics import _w
from graphkin.analytical.loads import known_loads
from graphkin.analytical.meshes import contact, pitch, power_flow
from graphkin.analytical.result import ForceAnalysis
from graphkin.geometry import as_xy, as_z, cross
from graphkin.geometry import zdot as dot
from graphkin.kinematics import GearGroup
from graphkin.model import GearMesh, Prismatic, Revolute


@dataclass(frozen=True)
class System:
    """[A]{x} = {b} for n positions.

    Attributes
    ----------
    A : ndarray, shape (n, m, m)
    b : ndarray, shape (n, m)
    unknowns : list of str
        Column names, e.g. ``["F12x", "F12y", ..., "N14", "C14", "T12"]``.
        Forces are of the lower-numbered link on the higher [N], couples [N·m].
    equations : list of str
        Row names, e.g. ``"link 3: ΣFx"``.
    """

    A: np.ndarray
    b: np.ndarray
    unknowns: list[str]
    equations: list[str]

    def solve(self) -> np.ndarray:
        """Solve every position; singular positions give nan. Shape (n, m)."""
        x = np.full(self.b.shape, np.nan)
        ok = np.isfinite(self.A).all(axis=(1, 2)) & np.isfinite(self.b).all(axis=1)
        # Singular at a dead point; the condition number (not the determinant,
        # which scales with the units of length) says how close.
        ok[ok] = np.linalg.cond(self.A[ok]) < 1e12
        if ok.any():
            x[ok] = np.linalg.solve(self.A[ok], self.b[ok][..., None])[..., 0]
        return x

    def format(self, i: int = 0, digits: int = 4) -> str:
        """Position i as an aligned text table: rows of A, then b."""
        cols = self.unknowns
        width = max(digits + 7, *(len(c) + 1 for c in cols))
        # Rounding noise (1e-16 where a lever arm is zero) would hide the
        # structure of the matrix: show it as 0.
        A, b = self.A[i].copy(), self.b[i].copy()
        A[np.abs(A) < 1e-12 * max(np.abs(A).max(), 1e-300)] = 0.0
        b[np.abs(b) < 1e-12 * max(np.abs(b).max(), 1e-300)] = 0.0
        A, b = A + 0.0, b + 0.0
        head = " " * 14 + "".join(f"{c:>{width}}" for c in cols) + " │" + f"{'b':>{width}}"
        lines = [head]
        for r, eq in enumerate(self.equations):
            row = "".join(f"{A[r, c]:>{width}.{digits}g}" for c in range(len(cols)))
            lines.append(f"{eq:<14}{row} │{b[r]:>{width}.{digits}g}")
        return "\n".join(lines)


def assemble(result: ForceAnalysis) -> System:
    """Build [A]{x} = {b} for the positions of a force analysis.

    Parameters
    ----------
    result : ForceAnalysis
        Supplies the kinematics and the signs of friction and tooth forces.

    Returns
    -------
    System
        [A], {b} and the names of the unknowns and of the equations, per position.
    """
    kin = result.kinematics
    mech = kin.mechanism
    n = kin.n
    moving = mech.moving
    row = {link: 3 * i for i, link in enumerate(moving)}
    m = 3 * len(moving)
    A = np.zeros((n, m, m))
    b = np.zeros((n, m))
    G = {link: kin.G(link) for link in moving}
    equations = [f"link {l}: {e}" for l in moving for e in ("ΣFx", "ΣFy", "ΣM_G")]

    def put(link, col, F, X=None, C=None):
        """Column ``col`` loads ``link`` with force F at X (per unit unknown) and couple C."""
        if link == mech.frame:
            return
        r = row[link]
        if F is not None:
            A[:, r, col] += F[:, 0]
            A[:, r + 1, col] += F[:, 1]
            A[:, r + 2, col] += cross(X - G[link], F)
        if C is not None:
            A[:, r + 2, col] += C

    unknowns: list[str] = []
    ones = np.ones(n)
    ex, ey = np.broadcast_to([1.0, 0.0], (n, 2)), np.broadcast_to([0.0, 1.0], (n, 2))
    for joint in mech.joints:
        lo, hi = sorted(joint.links)
        name = result.name_of(lo, hi)[1:]
        c = len(unknowns)
        if isinstance(joint, Revolute):
            # Each link at its own pin: the same point unless a link's angle is given (Kinematics.with_given).
            X_hi = kin.position(hi, joint.point)
            X_lo = X_hi if lo == mech.frame else kin.position(lo, joint.point)
            for k, e in enumerate((ex, ey)):
                put(hi, c + k, e, X_hi)
                put(lo, c + k, -e, X_lo)
            unknowns += [f"F{name}x", f"F{name}y"]
        elif isinstance(joint, Prismatic):
            X = kin.position(joint.slider, joint.point)
            w = as_xy(_w(kin, joint, hi, np.sign(result.normal[(lo, hi)])))
            put(hi, c, w, X)
            put(lo, c, -w, X)
            put(hi, c + 1, None, C=ones)
            put(lo, c + 1, None, C=-ones)
            unknowns += [f"N{name}", f"C{name}"]
        elif isinstance(joint, GearMesh):
            F = result.forces[(lo, hi)]
            size = np.linalg.norm(F, axis=-1)
            centre = kin.z(hi, joint.centers[joint.links.index(hi)])
            other = kin.z(lo, joint.centers[joint.links.index(lo)])
            t = pitch(joint, hi, centre, other)[1]
            # Where the tooth force acts: the pitch point, or off it with a mesh efficiency, on the side the power
            # flows (from the closed form's force on the gear its group locates, relative to its carrier).
            g = next(g for g in kin.groups if isinstance(g, GearGroup) and g.mesh is joint)
            Ck, Cj = kin.z(g.b, g.ck), kin.z(g.b, g.cj)
            on_k = as_z(result.force(g.j, g.k))
            X = as_xy(contact(joint, g.k, Ck, Cj, power_flow(kin, g, dot(on_k, pitch(joint, g.k, Ck, Cj)[1])))[0])
            # Unit direction of the tooth force on hi (its tangent where it vanishes).
            d = np.where(size[:, None] > 0, F / np.where(size > 0, size, 1.0)[:, None], as_xy(t))
            put(hi, c, d, X)
            put(lo, c, -d, X)
            unknowns.append(f"F{name}")
    c = len(unknowns)
    d = mech.driver
    if d.crank:
        put(d.link, c, None, C=ones)
    else:
        joint = mech.joint_between(mech.frame, d.link)
        put(d.link, c, kin.guide_direction(joint), kin.position(d.link, joint.point))
    unknowns.append(d.symbol)
    for link in moving:
        F, M_O = known_loads(kin, link)
        r = row[link]
        b[:, r:r + 2] = -F
        b[:, r + 2] = -(M_O - cross(G[link], F))
    return System(A, b, unknowns, equations)


def solve_matrix(result: ForceAnalysis) -> ForceAnalysis:
    """Solve the assembled matrix and return the answer as a ForceAnalysis.

    A cross-check of :func:`graphkin.analytical.solve_forces` (and what the lessons
    show); it loops inside LAPACK over positions, so it is slower.

    Parameters
    ----------
    result : ForceAnalysis
        The closed-form solution whose kinematics and loads are assembled (:func:`assemble`).

    Returns
    -------
    ForceAnalysis
        The same forces, from ``numpy.linalg.solve`` of [A]{x} = {b} at every position.
    """
    system = assemble(result)
    x = system.solve()
    kin = result.kinematics
    mech = kin.mechanism
    forces, normal, couple = {}, {}, {}
    c = 0
    for joint in mech.joints:
        lo, hi = sorted(joint.links)
        if isinstance(joint, Revolute):
            forces[(lo, hi)] = x[:, c:c + 2]
            c += 2
        elif isinstance(joint, Prismatic):
            w = as_xy(_w(kin, joint, hi, np.sign(result.normal[(lo, hi)])))
            normal[(lo, hi)], couple[(lo, hi)] = x[:, c], x[:, c + 1]
            forces[(lo, hi)] = x[:, c, None] * w
            c += 2
        else:
            column = system.A[:, 3 * mech.moving.index(hi):3 * mech.moving.index(hi) + 2, c]
            forces[(lo, hi)] = x[:, c, None] * column
            c += 1
    valid = result.kinematics.valid & np.isfinite(x).all(axis=1)
    return ForceAnalysis(kin, forces, normal, couple, x[:, c], valid)
