"""Each moving link's free body over the cycle, for a scene: which of the scene's forces act on it, and a box to draw
it in.

A free body holds no vector of its own: each arrow is one of the scene's joint forces, loads or inertia resultants,
referred to by its place in the scene's list, with the sign that makes it the force *on* this link. The scene's
joint force ``F_ij`` is link i's on link j (the lower number first, docs/json.md); on link i acts ``F_ji = −F_ij``,
drawn with ``sign`` −1. A drawing multiplies by the sign the scene states; it decides nothing of the mechanics.
"""

from __future__ import annotations

import numpy as np

from graphkin.model.names import force_name
from graphkin.scene.labels import label

MARGIN = 0.1
"""The box's margin around what is drawn in it, as a fraction of its larger side."""


def free_bodies(mech, links: list[dict], forces: list[dict], loads: list[dict], inertias: list[dict],
                scale: float) -> list[dict]:
    """Every moving link's free body (docs/json.md, "free_bodies"), before rounding.

    Parameters
    ----------
    mech : graphkin.model.Mechanism
    links, forces, loads, inertias : list of dict
        The scene's, with their arrays still ndarrays of shape (n, 2) [m, N].
    scale : float
        The scene's force scale [N per metre of drawing].

    Returns
    -------
    list of dict
        ``{"link", "forces": [{"index", "sign", "name", "label"}], "loads": [index], "inertia": index or None,
        "box": [xmin, ymin, xmax, ymax]}`` [m], one per moving link, in the links' order.
    """
    out = []
    for link in links:
        k = link["number"]
        if k == mech.frame:
            continue
        xy = [p for p in link["points"].values()] + ([link["G"]] if link["G"] is not None else [])
        acting = []
        for index, f in enumerate(forces):
            if k not in (f["of"], f["on"]):
                continue
            sign = 1 if f["on"] == k else -1
            other = f["of"] if sign == 1 else f["on"]
            name = force_name(mech, other, k)
            acting.append({"index": index, "sign": sign, "name": name, "label": label(name, "N")})
            xy += [f["at"], f["at"] + sign * f["analytical"] / scale]
        on = [index for index, ld in enumerate(loads) if ld["link"] == k]
        xy += [ld["at"] + ld["force"] / scale for ld in (loads[i] for i in on) if "force" in ld]
        # Not the inertia resultant: its line lies far off where its force nearly vanishes beside its torque
        # (h = |T|/|F|), and a box that held it would leave the link a speck (as the scene's view, which cuts it off).
        resultant = next((index for index, inn in enumerate(inertias) if inn["link"] == k), None)
        every = np.concatenate(xy)
        every = every[np.isfinite(every).all(axis=1)]
        lo, hi = (every.min(axis=0), every.max(axis=0)) if every.size else (np.zeros(2), np.zeros(2))
        margin = MARGIN * max(float(np.max(hi - lo)), 1e-9)
        out.append({"link": k, "name": link["name"], "forces": acting, "loads": on, "inertia": resultant,
                    "box": [float(lo[0] - margin), float(lo[1] - margin), float(hi[0] + margin),
                            float(hi[1] + margin)]})
    return out
