"""The mechanism's geometry at one position, in millimetres, with what drawing it needs: points, guides, gear teeth."""

from __future__ import annotations

import math

import numpy as np

from graphkin.draw.axes import MM
from graphkin.draw.gears import mesh_phase
from graphkin.model import GearMesh, Prismatic, Revolute

PINION_TEETH = 16
"""Teeth on the smallest gear of a train (the others have as many more as their radius is larger)."""


class Geometry:
    """The mechanism's geometry at the construction's position, in mm, with what drawing needs.

    Attributes
    ----------
    P : dict of int to dict of str to ndarray
        Every named point of every link [mm].
    G : dict of int to ndarray
        Centres of mass of the moving links [mm].
    size : float
        Largest extent of the drawing [mm].
    sym : float
        Size of ground symbols and slider blocks [mm].
    """

    def __init__(self, c):
        self.c = c
        self.mech = c.mechanism
        self.P = {n: {k: np.asarray(v, float) * MM for k, v in pts.items()} for n, pts in c.points.items()}
        self.G = {n: np.asarray(v, float) * MM for n, v in c.G.items()}
        pts = [p for d in self.P.values() for p in d.values()]
        for mesh in self.gears:
            for n, centre, r in self.gear_circles(mesh):
                pts += [centre - r, centre + r]
        pts = np.asarray(pts, float).reshape(-1, 2)
        ext = pts.max(axis=0) - pts.min(axis=0) if len(pts) else np.zeros(2)
        self.size = max(float(np.max(ext)) if len(pts) else 0.0, 1.0)
        self.sym = 0.032 * self.size
        self.teeth = self._teeth()

    @property
    def gears(self):
        return [j for j in self.mech.joints if isinstance(j, GearMesh)]

    @property
    def prismatic(self):
        return [j for j in self.mech.joints if isinstance(j, Prismatic)]

    def gear_circles(self, mesh):
        """(link, centre [mm], pitch radius [mm]) of both gears of a mesh."""
        return [(n, self.P[n][cname], r * MM) for n, cname, r in zip(mesh.links, mesh.centers, mesh.radii)]

    def link_angle(self, n: int) -> float:
        """Angle θ of link n's frame [rad]: the construction's, else from two of its points, else 0."""
        th = getattr(self.c, "angles", {}).get(n)
        if th is None:
            th = self.angle(n)
        return float(th or 0.0)

    def _teeth(self) -> dict:
        """Teeth of every gear: {link: (number of teeth, angle of a tooth's middle [rad], module [mm])}.

        Gears in mesh share a module, chosen so that the smallest of them has
        :data:`PINION_TEETH` teeth. The first gear of a train has a tooth on
        its frame's x-axis; each gear meshing with a gear already placed is
        turned so that its teeth fit that gear's at the pitch point. The
        teeth roll as the pitch circles do (r₂ dθ₂ = −r₃ dθ₃), so the fit
        worked out at one position is the same turn of the gear at every
        other: the teeth move with the gear.
        """
        meshes = self.gears
        out: dict = {}
        radius = {}
        for mesh in meshes:
            for n, r in zip(mesh.links, mesh.radii):
                radius[n] = r * MM
        todo = list(radius)
        while todo:
            # One train: the gears linked to the first one left by meshes.
            train, grow = {todo[0]}, True
            while grow:
                grow = False
                for mesh in meshes:
                    a, b = mesh.links
                    if (a in train) != (b in train):
                        train |= {a, b}
                        grow = True
            m = 2.0 * min(radius[n] for n in train) / PINION_TEETH
            first = todo[0]
            out[first] = (max(6, round(2 * radius[first] / m)), self.link_angle(first), m)
            placed = True
            while placed:
                placed = False
                for mesh in meshes:
                    a, b = mesh.links
                    if (a in out) == (b in out) or a not in train:
                        continue
                    if b in out:
                        a, b = b, a
                    ca = self.P[a][mesh.centers[mesh.links.index(a)]]
                    cb = self.P[b][mesh.centers[mesh.links.index(b)]]
                    za, phase_a, _ = out[a]
                    zb = max(6, round(2 * radius[b] / m))
                    psi = math.atan2(*(cb - ca)[::-1])  # from a's centre towards the pitch point
                    ra = radius[a]
                    # Arc from a's nearest tooth back to the pitch point, and b's gap there (see above).
                    sa = ra * ((psi - phase_a) % (2 * math.pi / za))
                    out[b] = (zb, mesh_phase(self, mesh, a, b, out[a], zb, psi, sa), m)
                    placed = True
            todo = [n for n in todo if n not in out]
        return out

    def angle(self, n: int):
        """Angle θ of link n's frame [rad] from two of its points (0 for the frame); None with fewer than two."""
        if n == self.mech.frame:
            return 0.0
        local = self.mech.link(n).points
        names = [k for k in local if k in self.P.get(n, {})]
        best, pair = 0.0, None
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                d = math.dist(local[a], local[b])
                if d > best:
                    best, pair = d, (a, b)
        if pair is None:
            return None
        a, b = pair
        (xa, ya), (xb, yb) = local[a], local[b]
        g = self.P[n][b] - self.P[n][a]
        return math.atan2(g[1], g[0]) - math.atan2(yb - ya, xb - xa)

    def guide(self, joint: Prismatic):
        """The guide line of a prismatic pair: (slider point [mm], unit direction).

        Its direction is θ_guide + ``joint.direction``; θ_guide comes from two
        points of the guide link, or from the slider's orientation
        (θ_slider = θ_guide + direction − slider_direction) when the guide
        link carries one point only.
        """
        X = self.P[joint.slider][joint.point]
        th = self.angle(joint.guide)
        if th is None:
            ts = self.angle(joint.slider)
            th = 0.0 if ts is None else ts - joint.direction + joint.slider_direction
        a = th + joint.direction
        return X, np.array([math.cos(a), math.sin(a)])

    def link_points(self, n):
        return self.P.get(n, {})

    def centroid(self, n):
        pts = list(self.link_points(n).values())
        return np.mean(pts, axis=0) if pts else None

    def pins(self):
        """Revolute joint points: {(name, link a, link b): position}."""
        out = {}
        for j in self.mech.joints:
            if isinstance(j, Revolute):
                a, b = j.links
                n = b if a == self.mech.frame else a
                out[(j.point, a, b)] = self.P[n][j.point]
        return out

    def frame_pivots(self):
        """Frame points of revolute joints: {name: position}."""
        return {j.point: self.P[self.mech.frame][j.point] for j in self.mech.joints
                if isinstance(j, Revolute) and self.mech.frame in j.links}
