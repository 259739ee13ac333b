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
from graphkin.scene.speed import parts


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

    def parts(self, other: Polygons, rate: float, other_rate: float) -> dict:
        """The graphical route's two parts, X(ω) = X_rest + ω² X_ω², from this cycle's constructions and ``other``'s
        at another input rate of the same sense (the same positions).

        Every arrow of a construction is a force the statics of its step makes linear in the loads' wrenches (a
        sub-problem's unknowns in its one resultant load, a superposition's sums in the sub-problems' values), and
        every load is its rest part plus ω² times its part at unit speed: so each vertex, a sum of arrows, is too,
        while the construction keeps its steps. Where the two speeds' constructions differ (a step one of them lacks,
        a position the guard refused at one only) the parts are nan and the position not valid.

        Parameters
        ----------
        other : Polygons
            The same problem's graphical route at ``other_rate``.
        rate, other_rate : float
            The input rates [rad/s or m/s] of this cycle and of ``other``.

        Returns
        -------
        dict
            ``"valid"`` (n,) bool; ``"reasons"``: index → why a position valid here is not in the parts;
            ``"forces"``: key → (rest, omega2), each (n, 2) [N, N/(rad/s)²]; ``"effort"``: (rest, omega2), each
            (n,); ``"vertices"``: one (rest, omega2) per template of this cycle, each (n, m + 1, 2).
        """
        valid = self.valid & other.valid
        reasons = {i: f"the construction is refused at {other_rate:g} (the second speed its parts are found from): "
                      f"{other.reasons[i]}" for i in np.flatnonzero(self.valid & ~other.valid).tolist()}
        # The same steps at both speeds, position by position: else the parts would mix two constructions.
        mine, theirs = self._present(), other._present()
        same = np.ones(len(valid), bool)
        for key, k in self._index.items():
            j = other._index.get(key)
            same &= mine[:, k] == (theirs[:, j] if j is not None else False)
        for key, j in other._index.items():
            if key not in self._index:
                same &= ~theirs[:, j]
        for i in np.flatnonzero(valid & ~same).tolist():
            reasons[i] = f"the construction takes other steps at {other_rate:g} (the second speed its parts are found from)"
        valid &= same
        mask = np.where(valid, 1.0, np.nan)
        forces = {key: parts(F * mask[:, None], other.forces[key] * mask[:, None], rate, other_rate)
                  for key, F in self.forces.items()}
        effort = parts(self.effort * mask, other.effort * mask, rate, other_rate)
        vertices = []
        for key, k in self._index.items():
            j = other._index.get(key)
            V = self.vertices[k] * mask[:, None, None]
            W = other.vertices[j] if j is not None else np.full_like(V, np.nan)
            vertices.append(parts(V, W, rate, other_rate))
        return {"valid": valid, "reasons": reasons, "forces": forces, "effort": effort, "vertices": vertices}

    def _present(self) -> np.ndarray:
        """(n, templates) bool: which template's polygon each position's construction has."""
        if not self.vertices:
            return np.zeros((len(self.valid), 0), bool)
        return np.stack([np.isfinite(V).all(axis=(1, 2)) for V in self.vertices], axis=1)

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
