"""Each moving link's free body over the cycle, for a scene: which of the scene's forces act on it, and a box to draw
it in.

A free body holds no vector of its own: each arrow is one of the scene's joint forces, loads or inertia resultants,
referred to by its place in the scene's list, with the sign that makes it the force *on* this link. The scene's
joint force ``F_ij`` is link i's on link j (the lower number first, docs/json.md); on link i acts ``F_ji = −F_ij``,
drawn with ``sign`` −1. A drawing multiplies by the sign the scene states; it decides nothing of the mechanics.

A slider driver's free body carries its driving force F1j (``drive``): the scene's effort times the guide's
direction, at the slider's point (``effort.at``, ``effort.direction``).

The couples on a link are drawn as curved arrows, as the printed free body draws them
(:func:`graphkin.draw.fbd.draw_free_body`): each external torque at G, the crank's driving torque at its pivot, the
couple C_ij a sliding pair transmits beside its force (at the slider's point, where it is not nil), and
the inertia torque −I_G α at G where it acts alone. Where the inertia force does not vanish the torque is carried by
the single inertia resultant on its line offset h = |T|/|F| from G, and no couple is drawn; where it vanishes (G on a
fixed pivot) the resultant has no line (its ``line_point`` is null there) and the couple T_ki is drawn instead. Each
couple refers to the scene's array of its values (the effort, a load's torque, an inertia torque), so it follows the
speed as the forces do; its ring around its centre (radius, start angle) is the drawing's, fixed over the cycle.
"""

from __future__ import annotations

import math

import numpy as np

from graphkin.model import Revolute
from graphkin.model.names import force_name
from graphkin.scene.labels import label

MARGIN = 0.1
"""The box's margin around what is drawn in it, as a fraction of its larger side."""

RING = 0.09
"""A couple's curved arrow: its radius as a fraction of the free body's extent (the next couple around the same
centre 0.05 more, outside a gear's pitch circle), as :func:`graphkin.draw.fbd.draw_free_body` draws them."""

SPAN = 1.5 * math.pi
"""The arc a couple's arrow sweeps [rad], from its ``start`` (counter-clockwise for a positive torque)."""


def free_bodies(mech, links: list[dict], forces: list[dict], loads: list[dict], inertias: list[dict],
                scale: float, effort: str = "", gears: list[dict] = (), drive=None) -> list[dict]:
    """Every moving link's free body (docs/json.md, "free_bodies"), before rounding.

    Parameters
    ----------
    mech : graphkin.model.Mechanism
    links, forces, loads, inertias : list of dict
        The scene's, with their arrays still ndarrays of shape (n, 2) [m, N].
    scale : float
        The scene's force scale [N per metre of drawing].
    effort : str
        The driving effort's name (T12): a crank's free body carries it as a couple at its pivot.
    gears : list of dict
        The scene's pitch circles: a gear's couples are drawn outside its own.
    drive : tuple of ndarray, optional
        A slider driver's force on its link, (at, F) of shape (n, 2) [m, N]: where it acts and its value.

    Returns
    -------
    list of dict
        ``{"link", "forces": [{"index", "sign", "name", "label"}], "loads": [index], "inertia": index or None,
        "torques": [{"name", "label", "of", "index", "sign", "point", "radius", "start", "span"}],
        "drive": {"name", "label"} or None, "box": [xmin, ymin, xmax, ymax]}`` [m], one per moving link, in the
        links' order.
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
        driven = drive is not None and mech.driver.link == k
        if driven:
            xy += [drive[0], drive[0] + drive[1] / scale]
        on = [index for index, ld in enumerate(loads) if ld["link"] == k]
        xy += [ld["at"] + ld["force"] / scale for ld in (loads[i] for i in on) if "force" in ld]
        # Not the inertia resultant: its line lies far off where its force nearly vanishes beside its torque
        # (h = |T|/|F|), and a box that held it would leave the link a speck (as the scene's view, which cuts it off).
        resultant = next((index for index, inn in enumerate(inertias) if inn["link"] == k), None)
        own = np.concatenate([p for p in link["points"].values()] + [link["G"]])
        own = own[np.isfinite(own).all(axis=1)]
        L = float(np.max(np.ptp(own, axis=0))) if own.size else 0.0
        gear = max([g["radius"] for g in gears if g["link"] == k] + [0.0])
        torques = _torques(mech, k, link, forces, acting, loads, on, resultant, effort, L, gear)
        for t in torques:
            centre = _centre(link, forces, t)
            xy += [centre - 1.15 * t["radius"], centre + 1.15 * t["radius"]]
        every = np.concatenate(xy)
        every = every[np.isfinite(every).all(axis=1)]
        lo, hi = (every.min(axis=0), every.max(axis=0)) if every.size else (np.zeros(2), np.zeros(2))
        margin = MARGIN * max(float(np.max(hi - lo)), 1e-9)
        out.append({"link": k, "name": link["name"], "forces": acting, "loads": on, "inertia": resultant,
                    "torques": torques, "drive": {"name": effort, "label": label(effort, "N")} if driven else None,
                    "box": [float(lo[0] - margin), float(lo[1] - margin), float(hi[0] + margin),
                                                float(hi[1] + margin)]})
    return out


def _centre(link: dict, forces: list[dict], t: dict) -> np.ndarray:
    """A couple's centre at every position, shape (n, 2) [m]: its link's point or G, or (a sliding pair's couple)
    the point its force is drawn at."""
    if t["of"] == "joint":
        return forces[t["index"]]["at"]
    return link["G"] if t["point"] == "G" else link["points"][t["point"]]


def _torques(mech, k: int, link: dict, forces: list[dict], acting: list[dict], loads: list[dict], on: list[int],
             resultant, effort: str, L: float, gear: float) -> list:
    """The couples on link k, each on its ring around its centre (see the module's docstring): couples about one
    point (a crank's G on its pivot) on rings of growing radius."""
    found = [(loads[i]["name"], "load", i, 1, "G") for i in on if "torque" in loads[i]]
    if resultant is not None:
        found.append((f"T{k}i", "inertia", resultant, 1, "G"))
    d = mech.driver
    if d.crank and d.link == k and effort:
        pivot = mech.joint_between(mech.frame, k)
        found.append((effort, "effort", None, 1, pivot.point if isinstance(pivot, Revolute) else "G"))
    largest = max([float(np.nanmax(np.hypot(*f["analytical"].T))) for f in forces
                   if np.isfinite(f["analytical"]).any()] + [0.0])
    for a in acting:
        C = forces[a["index"]].get("couple")
        # As the printed free body (graphkin.draw.fbd): a couple drawn only where it is not rounding's.
        if C is not None and np.nanmax(np.abs(C), initial=0.0) > 1e-9 * max(largest * L, 1e-300):
            found.append((f"C{a['name'][1:]}", "joint", a["index"], a["sign"], None))
    rings: dict[tuple, int] = {}
    out = []
    for name, of, index, sign, point in found:
        centre = _centre(link, forces, {"of": of, "index": index, "point": point})
        first = centre[np.isfinite(centre).all(axis=1)]
        where = tuple(np.round(first[0] / max(L, 1e-12), 6)) if len(first) else (point,)
        ring = rings.get(where, 0)
        rings[where] = ring + 1
        out.append({"name": name, "label": label(name, "N*m"), "of": of, "index": index, "sign": sign,
                    "point": point, "radius": max(RING * L, 0.3 * gear) + 0.05 * ring * L,
                    "start": -0.7 * math.pi + 0.35 * ring, "span": SPAN})
    return out
