"""The velocity and acceleration polygons over a cycle, for a scene: each vector's tail and tip, position by position.

:func:`graphkin.graphical.construct_kinematics` builds one position's polygons from the pole (~0.3–0.8 ms). A vector
a construction draws twice (``v_A`` found by the driver's step, then taken as known by a dyad's) is kept once, as
first drawn. The polygons of a cycle differ little from position to position, so each distinct one (its kind and its
vectors' names), a *template*, is written once with its vectors over the positions beside it, as the force polygons
are (:mod:`graphkin.scene.polygons`); a position whose polygons are not valid holds null.
"""

from __future__ import annotations

import numpy as np

from graphkin.graphical.polygons import construct_kinematics
from graphkin.scene.labels import label

UNITS = {"velocity": "m/s", "acceleration": "m/s^2"}


def _label(name: str, unit: str) -> dict:
    """``"v_BA"`` → v, subscript BA; ``"a^n_BA"`` → a, subscript BA, superscript n (the component: n, t, c, r)."""
    head, _, sub = name.partition("_")
    symbol, _, component = head.partition("^")
    return {**label(symbol, unit), "sub": sub, "sup": component}


def motion_polygons(kin, valid: np.ndarray) -> dict:
    """The scene's ``motion`` field (docs/json.md) before rounding: the velocity and acceleration polygons at every
    valid position of ``kin``.

    Parameters
    ----------
    kin : graphkin.kinematics.Kinematics
        The cycle's kinematics.
    valid : ndarray of bool, shape (n,)
        The positions the analytical route solves.

    Returns
    -------
    dict
        ``{"valid", "invalid", "polygons"}``; each polygon ``{"kind", "unit", "names", "labels", "known", "box",
        "vectors"}`` with ``vectors`` an ndarray of shape (n, 4 m): each vector's tail x, y and tip x, y
        [m/s or m/s²], nan where the polygon is not drawn.
    """
    n = kin.n
    ok = np.zeros(n, bool)
    reasons: dict[int, str] = {}
    templates: dict[tuple, int] = {}
    polygons: list[dict] = []
    for i in np.flatnonzero(valid).tolist():
        c = construct_kinematics(kin, i)
        if not c.valid:
            reasons[i] = c.reason
            continue
        ok[i] = True
        for kind in UNITS:
            first = {}
            for v in c.vectors(kind):
                first.setdefault(v.name, v)
            key = (kind, tuple(first))
            k = templates.get(key)
            if k is None:
                k = templates[key] = len(polygons)
                polygons.append({"kind": kind, "unit": UNITS[kind], "names": list(first),
                                 "labels": [_label(name, UNITS[kind]) for name in first],
                                 "known": [v.known for v in first.values()],
                                 "vectors": np.full((n, 4 * len(first)), np.nan)})
            polygons[k]["vectors"][i] = [x for v in first.values() for x in (*v.tail, *v.tip)]
    for p in polygons:
        V = p["vectors"].reshape(n, -1, 2)
        finite = V[np.isfinite(V).all(axis=2)]
        p["box"] = [float(finite[:, 0].min()), float(finite[:, 1].min()), float(finite[:, 0].max()),
                    float(finite[:, 1].max())]
    return {"valid": ok, "invalid": [{"index": i, "reason": why} for i, why in sorted(reasons.items())],
            "polygons": polygons}
