"""The graphical route over a cycle, for a scene: its joint forces and each step's force polygon, position by position.

:func:`graphkin.graphical.construct_forces` builds one position's construction (~1.5 ms for the strip cutter; its
captions are written only when read, and a scene reads none). Each is checked against the analytical route by
:func:`graphkin.graphical.guard.check_forces` before any of its numbers is kept: a position where the routes
disagree is marked not valid, with the guard's reason, and holds no graphical number.

A polygon is kept as its vertices, tip to tail from the first arrow's tail (m arrows, m + 1 vertices) [N], so that a
drawing places what it is given. The polygons of a construction differ little from position to position (the same
steps, the same names), so each distinct one, a *template* (its sub-problem, link, kind, arrow names and which are
known), is written once, with its vertices over the positions beside it; a position whose construction has no such
step (a load switched off, a sub-problem fewer) holds null there.
"""

from __future__ import annotations

import numpy as np

from graphkin.graphical import construct_forces
from graphkin.graphical.guard import check_forces
from graphkin.scene.labels import label


class Polygons:
    """The graphical route at every position of a force analysis (see the module's docstring).

    Attributes
    ----------
    forces : dict of (int, int) to ndarray, shape (n, 2)
        Each joint force as the lower-numbered link's on the higher [N], nan where not built or not valid.
    effort : ndarray, shape (n,)
        The driving torque [N·m] or force along the guide [N].
    valid : ndarray of bool, shape (n,)
    reasons : dict of int to str
        Why each position the analytical route solves has no graphical values.
    templates : list of dict
        ``{"sub", "link", "kind", "names", "known"}`` per distinct polygon.
    vertices : list of ndarray, shape (n, m + 1, 2)
        Each template's vertices over the positions [N].
    """

    def __init__(self, result, valid: np.ndarray):
        n = result.n
        self.forces = {key: np.full((n, 2), np.nan) for key in result.forces}
        self.effort = np.full(n, np.nan)
        self.valid = np.zeros(n, bool)
        self.reasons: dict[int, str] = {}
        self.templates: list[dict] = []
        self.vertices: list[np.ndarray] = []
        self._index: dict[tuple, int] = {}
        kin = result.kinematics
        for i in np.flatnonzero(valid).tolist():
            c = check_forces(result, construct_forces(kin, i), i)
            if not c.valid:
                self.reasons[i] = c.reason
                continue
            self.valid[i] = True
            for key in self.forces:
                self.forces[key][i] = c.force(*key)
            self.effort[i] = c.effort
            for step in c.steps:
                if step.polygon:
                    self._keep(i, step, n)

    def _keep(self, i: int, step, n: int):
        names = tuple(a.name for a in step.polygon)
        key = (step.sub, step.link, step.kind, names, tuple(a.known for a in step.polygon))
        k = self._index.get(key)
        if k is None:
            k = self._index[key] = len(self.templates)
            self.templates.append({"sub": step.sub, "link": step.link, "kind": step.kind, "names": list(names),
                                   "known": list(key[4])})
            self.vertices.append(np.full((n, len(names) + 1, 2), np.nan))
        tips = np.cumsum([(0.0, 0.0)] + [a.vector for a in step.polygon], axis=0)
        self.vertices[k][i] = tips

    def data(self, force) -> dict:
        """As the scene holds it (docs/json.md): ``force`` rounds a force array and makes it a list."""
        polygons = []
        for template, V in zip(self.templates, self.vertices):
            finite = V[np.isfinite(V).all(axis=(1, 2))]
            box = [float(finite[..., 0].min()), float(finite[..., 1].min()), float(finite[..., 0].max()),
                   float(finite[..., 1].max())]
            polygons.append({**template, "labels": [label(name, "N") for name in template["names"]],
                             "box": box, "vertices": force(V.reshape(len(V), -1))})
        return {"valid": self.valid.astype(int).tolist(),
                "invalid": [{"index": i, "reason": why} for i, why in sorted(self.reasons.items())],
                "polygons": polygons}


def force_polygons(result, valid: np.ndarray) -> Polygons:
    """The graphical route at every valid position of ``result``, each construction checked (:class:`Polygons`)."""
    return Polygons(result, valid)
