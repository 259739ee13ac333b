"""The velocity and acceleration polygons, and the instant centres, as plain data (``graphical_kinematics``).

One entry per position of ``graphkin solve --json`` (schema: ``docs/json.md``): SI numbers, every vector
with its name, ends, components and the step that found it, and how far the polygons are from the
analytical kinematics.
"""

from __future__ import annotations

import math

from graphkin import graphical
from graphkin.kinematics import Kinematics

# The polygons' modules load when first used (graphkin.graphical's PEP 562 names): `graphkin solve` without
# --motion-polygons imports this module and never builds a polygon.


def kinematic_constructions(kin: Kinematics) -> list:
    """The polygons and instant centres of every position: ``(MotionConstruction, InstantCentres)`` each."""
    return [(graphical.construct_kinematics(kin, i), graphical.instant_centres(kin, i)) for i in range(kin.n)]


def _xy(v) -> list[float]:
    return [float(v[0]), float(v[1])]


def _polygon(c: graphical.MotionConstruction, which: str) -> dict:
    return {"images": {name: list(p) for name, p in c.images[which].items()},
            "vectors": [{"name": v.name, "tail": list(v.tail), "tip": list(v.tip), "components": list(v.vector),
                         "known": v.known, "step": v.step} for v in c.vectors(which)]}


def _difference(c: graphical.MotionConstruction, kin: Kinematics) -> dict:
    """Largest |polygon − analytical| of each kind, over the largest analytical value of that kind.

    The analytical values are worked out at this position only (rigid-body motion of each link's frame),
    so that the data of n positions costs n times one, not n².
    """
    i, mech = c.index, c.mechanism
    out = {}
    motion = {l: (complex(kin.O[l][i]), complex(kin.e[l][i]), complex(kin.v_O[l][i]), complex(kin.a_O[l][i]),
                  float(kin.omega[l][i]), float(kin.alpha[l][i])) for l in mech.moving}
    exact_v, exact_a = {}, {}
    for (l, name) in c.velocity:
        O, e, v_O, a_O, w, al = motion[l]
        r = e * complex(*mech.link(l).point(name))
        exact_v[l, name], exact_a[l, name] = v_O + 1j * w * r, a_O + (1j * al - w * w) * r
    for kind, ours, exact in (("velocity", c.velocity, exact_v), ("acceleration", c.acceleration, exact_a)):
        scale = max([abs(z) for z in exact.values()] + [0.0])
        diff = max([abs(complex(*ours[k]) - exact[k]) for k in ours] + [0.0])
        out[kind] = diff / scale if scale else diff
    for kind, ours, column in (("omega", c.omega, 4), ("alpha", c.alpha, 5)):
        scale = max(abs(m[column]) for m in motion.values())
        diff = max(abs(ours[l] - m[column]) for l, m in motion.items())
        out[kind] = diff / scale if scale else diff
    return out


def _centres(ic: graphical.InstantCentres, steps: bool) -> dict:
    return {"centres": {f"I{a}{b}": list(p) for (a, b), p in ic.centres.items()},
            "at_infinity": {f"I{a}{b}": list(d) for (a, b), d in ic.at_infinity.items()},
            "missing": [f"I{a}{b}" for a, b in ic.missing], **({"steps": list(ic.steps)} if steps else {}),
            "omega": {str(l): w for l, w in ic.omega.items()},
            "velocity": {str(l): {name: list(v) for (link, name), v in ic.velocity.items() if link == l}
                         for l in ic.omega}}


def _step(s, full: bool) -> dict:
    if not full:
        return {"polygon": s.polygon, "kind": s.kind, "links": list(s.links)}
    return {"polygon": s.polygon, "kind": s.kind, "caption": s.caption, "links": list(s.links),
            "points": {k: list(v) for k, v in s.points.items()},
            "lines": [{"name": l.name, "point": list(l.point), "direction": list(l.direction)} for l in s.lines],
            "values": {k: float(v) for k, v in s.values.items()}}


def graphical_kinematics_data(kin: Kinematics, c: graphical.MotionConstruction,
                              ic: graphical.InstantCentres | None = None, *,
                              steps: bool = True) -> dict:
    """One position's polygons (and instant centres) as plain data; see ``docs/json.md``.

    Parameters
    ----------
    kin : Kinematics
        The analytical kinematics the construction was built from (for the differences).
    c : graphkin.graphical.MotionConstruction
        The velocity and acceleration polygons at one position.
    ic : graphkin.graphical.InstantCentres, optional
        The instant centres at the same position.
    steps : bool
        Each step in full: its caption, points, lines and values, and the instant centres' reasoning. False
        keeps of each step only its polygon, kind and links (what a vector's ``"step"`` refers to): the
        captions are most of the data.

    Returns
    -------
    dict
        ``{"valid", "reason", ...}``; when valid also the scales, ω and α, every point's and G's
        velocity and acceleration, both polygons, the steps and the relative differences.
    """
    if not c.valid:
        return {"valid": False, "reason": c.reason, "disagreement": c.disagreement}
    mech = c.mechanism
    data = {
        "valid": True, "reason": "", "disagreement": False,
        "velocity_scale_m_per_s_per_mm": c.velocity_scale,
        "acceleration_scale_m_per_s2_per_mm": c.acceleration_scale,
        "omega": {str(l): w for l, w in c.omega.items() if l != mech.frame},
        "alpha": {str(l): a for l, a in c.alpha.items() if l != mech.frame},
        "points": {str(l): {name: {"velocity": _xy(c.velocity[l, name]), "acceleration": _xy(c.acceleration[l, name])}
                            for name in mech.link(l).points} for l in mech.moving},
        "G": {str(l): {"velocity": _xy(c.v_G[l]), "acceleration": _xy(c.a_G[l])} for l in mech.moving},
        "velocity_polygon": _polygon(c, "velocity"),
        "acceleration_polygon": _polygon(c, "acceleration"),
        "steps": [_step(s, steps) for s in c.steps],
        "relative_difference": {k: (v if math.isfinite(v) else None) for k, v in _difference(c, kin).items()},
    }
    if ic is not None:
        data["instant_centres"] = _centres(ic, steps) if ic.valid else {"valid": False, "reason": ic.reason,
                                                                         "disagreement": ic.disagreement}
    return data
