"""A problem over its cycle as plain data, for a browser to draw: :func:`scene`.

The whole cycle is solved once, vectorised (:func:`graphkin.cycle.sweep`), and every number a drawing of it needs is
put in arrays over the positions: each link's named points, every joint force at its point by both routes, each
external load, each inertia resultant on its offset line, the driving effort, each moving link's free body
(:mod:`graphkin.scene.bodies`), the graphical route's force polygons (:mod:`graphkin.scene.polygons`) and, when
asked, the velocity and acceleration polygons (:mod:`graphkin.scene.motion`). The browser draws these and computes
nothing of the mechanics: a drawing that scrubs through a cycle is a lookup. The layout is docs/json.md's "scene";
its version is :data:`SCHEMA`.

A vector over the positions is one flat list ``[x0, y0, x1, y1, …]`` (2n numbers), a scalar one list of n, each
``null`` where the position has no value (the linkage cannot reach it, or the graphical route was not built or
disagreed there). Every value is rounded to :data:`PRECISION` of its kind's scale (the mechanism's size for
lengths, the largest force for forces): the text is about half as long as with every digit, and a drawing cannot
show the difference.
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from graphkin.analytical.loads import applied, inertia
from graphkin.analytical.meshes import pitch
from graphkin.cycle import sweep
from graphkin.graphical.construction import nice_scale
from graphkin.graphical.guard import mechanism_size
from graphkin.model import GearMesh, PointForce, Prismatic, Revolute
from graphkin.scene.bodies import free_bodies
from graphkin.scene.labels import label
from graphkin.scene.motion import motion_polygons
from graphkin.scene.polygons import force_polygons
from graphkin.scene.speed import PRESOLVED, linearity, parts
from graphkin.units.systems import SI

SCHEMA = 3
"""The version of the scene's layout (docs/json.md): raised whenever a reader of an older scene would misread it."""

PRECISION = 1e-9
"""Every value is rounded to this fraction of its kind's scale (the mechanism's size, the largest force, …)."""

ARROW = 0.35
"""The largest force over the cycle is drawn at most this fraction of the mechanism's size long (the force scale is
that rounded up to 1, 2 or 5 times a power of ten)."""


def scene(problem, n: int = 360, *, polygons: bool = True, motion: bool = False, units=None) -> dict:
    """The problem over its cycle as plain data a browser draws (docs/json.md, "scene").

    Parameters
    ----------
    problem : graphkin.Problem
        The mechanism, its input motion and loads.
    n : int
        Crank angles over one turn (a load that switches on or off adds two samples either side of each switch,
        as :func:`graphkin.cycle.sweep` does). A slider-driven problem is drawn at its own positions.
    polygons : bool
        Build the graphical route at every position: its joint forces beside the analytical ones, and each
        link's force polygon. The costly part (~1.5 ms a position for the strip cutter); without it the scene
        holds the analytical route only.
    motion : bool
        Build the velocity and acceleration polygons at every position (~0.3–0.8 ms a position).
    units : graphkin.units.systems.UnitSystem, optional
        The book's units, which the page offers beside SI for reading a value (default: graphkin's report units,
        :data:`graphkin.units.systems.SI`: mm, N, N·m).

    Returns
    -------
    dict
        Plain data: lists, numbers, strings (:func:`scene_json` writes it).

    Examples
    --------
    >>> from graphkin import catalog
    >>> s = scene(catalog.load("strip_cutter"), 36, polygons=False)
    >>> s["schema"], s["n"], s["effort"]["label"], s["speed"]["kind"]
    (3, 40, {'symbol': 'T', 'sub': '12', 'mark': '', 'unit': 'N*m'}, 'superpose')
    """
    problem = drawn(problem)
    out, graphical = _at_speed(problem, n, polygons, motion)
    out["speed"] = _speed(problem, n, out, graphical)
    out["book"] = _book(units)
    return out


def _book(units) -> dict:
    """The scene's ``book`` field: the units a reader may switch to, each kind's symbol and its factor from SI."""
    u = SI if units is None else units
    return {"name": u.name, **{kind: {"unit": u.symbol(kind), "scale": u.scales[kind]}
                               for kind in ("length", "force", "torque", "velocity", "acceleration")}}


def drawn(problem):
    """The problem a scene draws: a crank's cycle is the motion its input produces, so a book's measured values
    ([given]), which hold at its own position only, are dropped (a slider-driven problem is drawn at its own
    positions, with them).

    Parameters
    ----------
    problem : graphkin.Problem

    Returns
    -------
    graphkin.Problem
    """
    return problem.without_given() if problem.mechanism.driver.crank else problem


def _cycle(problem, n):
    """The cycle's force analysis: n crank angles, or a slider-driven problem's own positions."""
    return (sweep(problem, n) if problem.mechanism.driver.crank else sweep(problem)).analysis


def _at_speed(problem, n: int, polygons: bool, motion: bool = False):
    """The scene at the problem's own input rate, without its ``speed`` field, and its graphical route
    (:class:`graphkin.scene.polygons.Polygons`, or None without polygons)."""
    mech = problem.mechanism
    result = _cycle(problem, n)
    kin = result.kinematics
    valid = np.asarray(result.valid, bool)
    size = mechanism_size(mech)
    length = _Rounder(size)
    links = [_link(kin, link, valid, length) for link in mech.links]
    forces = [_joint(result, joint, valid) for joint in mech.joints]
    loads = _loads(kin, valid)
    inertias = [_inertia(kin, k, valid) for k in mech.moving if mech.link(k).mass and not kin.static]
    every = [f["analytical"] for f in forces] + [ld["force"] for ld in loads if "force" in ld]
    every += [i["force"] for i in inertias]
    biggest = max([float(np.nanmax(np.hypot(*F.T))) for F in every if np.isfinite(F).any()] + [0.0])
    force = _Rounder(biggest)
    scale = nice_scale(biggest, ARROW * size)  # N per metre of the drawing
    graphical = force_polygons(result, valid) if polygons else None
    gears = _gears(mech)
    drive = None if mech.driver.crank else (_masked(kin.position(mech.driver.link, mech.joint_between(
        mech.frame, mech.driver.link).point), valid), _masked(result.driver_force(), valid))
    bodies = free_bodies(mech, links, forces, loads, inertias, scale, result.driver_name, gears, drive)
    moving = motion_polygons(kin, valid) if motion and not kin.static else None
    out = {
        "schema": SCHEMA,
        "problem": problem.name,
        "title": problem.title,
        "source": problem.source,
        "units": {"length": "m", "angle": "rad", "force": "N", "torque": "N*m", "time": "s", "velocity": "m/s",
                  "acceleration": "m/s^2"},
        "precision": PRECISION,
        "n": int(result.n),
        "input": _input(kin, mech, length),
        "valid": valid.astype(int).tolist(),
        "invalid": [{"index": i, "reason": result.reason(i)} for i in np.flatnonzero(~valid).tolist()],
        "size": size,
        "view": _view(links, forces, loads, gears, scale, size),
        "scales": {"force": scale},
        "frame": mech.frame,
        "driver": _driver(mech, length),
        "links": [_round_link(link, length) for link in links],
        "guides": _guides(kin, valid, length),
        "gears": [{**gear, "mark": length(_gear_mark(kin, gear, valid))} for gear in gears],
        "forces": [],
        "loads": [],
        "inertia": [],
        "effort": {**_effort(result, valid, force, size), **_drive(kin, mech, valid, length)},
        "free_bodies": [{**body, "box": length.scalars(body["box"])} for body in bodies],
        "graphical": None,
        "motion": None,
        "speed": None,
        "book": None,
    }
    for f in forces:
        key = f.pop("key")
        f.update(at=length(f["at"]), analytical=force(f["analytical"]))
        if "couple" in f:
            f["couple"] = force.torque(f["couple"], size)
        if graphical is not None:
            f["graphical"] = force(graphical.forces[key])
        out["forces"].append(f)
    for ld in loads:
        ld["at"] = length(ld["at"])
        if "force" in ld:
            ld["force"] = force(ld["force"])
        else:
            ld["torque"] = force.torque(ld["torque"], size)
        out["loads"].append(ld)
    for inn in inertias:
        out["inertia"].append({**inn, "G": length(inn["G"]), "line_point": length(inn["line_point"]),
                               "force": force(inn["force"]), "torque": force.torque(inn["torque"], size),
                               "h": length.scalars(inn["h"])})
    if graphical is not None:
        out["effort"]["graphical"] = force.torque(graphical.effort, size) if mech.driver.crank else \
            force.scalars(graphical.effort)
        out["graphical"] = graphical.data(force)
    if moving is not None:
        out["motion"] = _motion(moving)
    return out, graphical


def _motion(moving: dict) -> dict:
    """The motion polygons rounded, each kind at the scale of its largest vector."""
    for p in moving["polygons"]:
        V = p["vectors"]
        p["vectors"] = _Rounder(float(np.nanmax(np.abs(V))) if np.isfinite(V).any() else 0.0)(V)
    return {**moving, "valid": moving["valid"].astype(int).tolist()}


class _Rounder:
    """Rounds arrays to :data:`PRECISION` of one scale and makes them plain lists (nan stays nan: JSON's null)."""

    def __init__(self, scale: float):
        self.decimals = int(-math.floor(math.log10(PRECISION * scale))) if scale > 0 else 12

    def scalars(self, x) -> list:
        return np.round(np.asarray(x, float), self.decimals).tolist()

    def __call__(self, xy) -> list:
        """A vector over the positions, shape (n, 2), as the flat list x0, y0, x1, y1, …"""
        return self.scalars(np.asarray(xy, float).reshape(-1))

    def torque(self, T, size: float) -> list:
        """A torque [N·m], rounded as the force that gives it on an arm of the mechanism's size."""
        decimals = self.decimals - int(math.floor(math.log10(size))) if size > 0 else self.decimals
        return np.round(np.asarray(T, float), decimals).tolist()


def _speed(problem, n: int, out: dict, graphical) -> dict:
    """The scene's ``speed`` field (docs/json.md): how its forces change with the input speed
    (:func:`graphkin.scene.speed.linearity`), with the two parts that rescale them exactly, or the forces at a few
    presolved speeds; the graphical route's too where the scene has it (``graphical``, its
    :class:`graphkin.scene.polygons.Polygons`)."""
    kind, reason = linearity(problem)
    crank = problem.mechanism.driver.crank
    rates = set(problem.q_dot)
    field = {"kind": kind, "reason": reason, "value": float(problem.q_dot[0]) if len(rates) == 1 else None,
             "unit": "rad/s" if crank else "m/s"}
    if kind == "superpose":
        rate = field["value"]
        a, b = _cycle(problem, n), _cycle(problem.at_speed(2 * rate), n)
        found = [parts(a.force(f["of"], f["on"]), b.force(f["of"], f["on"]), rate, 2 * rate) for f in out["forces"]]
        couples = [parts(a.couple[(f["of"], f["on"])], b.couple[(f["of"], f["on"])], rate, 2 * rate)
                   if "couple" in f else None for f in out["forces"]]
        effort = parts(a.effort, b.effort, rate, 2 * rate)
        valid = np.asarray(a.valid, bool)
        size = out["size"]
        rounders = []
        for k in range(2):  # each part rounded at its own scale: F_ω² is multiplied by ω² on the page
            top = [float(np.nanmax(np.abs(F[k]))) for F in found if np.isfinite(F[k]).any()]
            rounders.append(_Rounder(max(top + [0.0])))
        torque = (lambda r, T: r.torque(np.where(valid, T, np.nan), size)) if crank else \
            (lambda r, T: r.scalars(np.where(valid, T, np.nan)))
        field["superpose"] = {
            "forces": [{"rest": rounders[0](_masked(F[0], valid)), "omega2": rounders[1](_masked(F[1], valid)),
                        **({} if C is None else {"couple": {"rest": rounders[0].torque(np.where(valid, C[0], np.nan), size),
                                                            "omega2": rounders[1].torque(np.where(valid, C[1], np.nan),
                                                                                         size)}})}
                       for F, C in zip(found, couples)],
            "effort": {"rest": torque(rounders[0], effort[0]), "omega2": torque(rounders[1], effort[1])}}
        if graphical is not None:
            field["superpose"]["graphical"] = _graphical_parts(graphical.parts(force_polygons(b, np.asarray(
                b.valid, bool)), rate, 2 * rate), out, crank)
    elif kind == "presolved":
        field["presolved"] = []
        for fraction in PRESOLVED:
            other, _ = _at_speed(problem.at_speed(fraction * field["value"]), n, graphical is not None)
            field["presolved"].append({
                "value": fraction * field["value"],
                "forces": [f["analytical"] for f in other["forces"]],
                "couples": [f.get("couple") for f in other["forces"]],
                "effort": other["effort"]["analytical"],
                "inertia": [{k: inn[k] for k in ("force", "torque", "h", "line_point")} for inn in other["inertia"]],
                "graphical": None if other["graphical"] is None else {
                    **other["graphical"], "forces": [f["graphical"] for f in other["forces"]],
                    "effort": other["effort"]["graphical"]}})
    return field


def _graphical_parts(found: dict, out: dict, crank: bool) -> dict:
    """The ``speed.superpose.graphical`` field: the graphical route's two parts (:meth:`Polygons.parts`), each kind
    rounded at the scale of its own largest value."""
    valid = found["valid"]
    size = out["size"]
    keys = [(f["of"], f["on"]) for f in out["forces"]]
    vectors = [found["forces"][key] for key in keys] + found["vertices"]
    rounders = []
    for k in range(2):
        top = [float(np.nanmax(np.abs(F[k]))) for F in vectors if np.isfinite(F[k]).any()]
        rounders.append(_Rounder(max(top + [0.0])))

    def effort(r, T):
        return r.torque(T, size) if crank else r.scalars(T)

    def pair(X):
        return {"rest": rounders[0](X[0]), "omega2": rounders[1](X[1])}

    return {"valid": valid.astype(int).tolist(),
            "invalid": sorted(out["graphical"]["invalid"] + [{"index": i, "reason": why}
                                                             for i, why in found["reasons"].items()],
                              key=lambda entry: entry["index"]),
            "forces": [pair(found["forces"][key]) for key in keys],
            "effort": {"rest": effort(rounders[0], found["effort"][0]), "omega2": effort(rounders[1], found["effort"][1])},
            "polygons": [pair(V) for V in found["vertices"]]}


def _masked(xy, valid) -> np.ndarray:
    xy = np.array(xy, float)
    xy[~valid] = np.nan
    return xy


def _outline(link) -> list[str]:
    """The link's points in the order of their convex hull (a bar: its two ends; a block: its one point)."""
    names = list(link.points)
    if len(names) < 3:
        return names
    hull = shapely.MultiPoint([link.points[k] for k in names]).convex_hull
    coords = list(hull.exterior.coords)[:-1] if hull.geom_type == "Polygon" else list(hull.coords)
    return [next(k for k in names if tuple(map(float, link.points[k])) == tuple(map(float, c))) for c in coords]


def _gears(mech) -> list[dict]:
    """Each gear's pitch circle, once: the link, the point at its centre, the radius [m], and whether it is an
    annulus (teeth inside)."""
    out = {}
    for joint in mech.joints:
        if isinstance(joint, GearMesh):
            for link, centre in zip(joint.links, joint.centers):
                r = joint.radius(link)
                out.setdefault((link, centre, r), {"link": link, "centre": centre, "radius": r,
                                                   "internal": joint.internal and link == joint.ring})
    return list(out.values())


def _gear_mark(kin, gear: dict, valid) -> np.ndarray:
    """A point of the gear's pitch circle that turns with it [m], at every position: the end of the spoke a page
    draws from the centre, so that a student sees the gear turn (a pitch circle alone looks still)."""
    mech = kin.mechanism
    C = np.asarray(mech.link(gear["link"]).points[gear["centre"]], float)
    mark = (float(C[0]) + gear["radius"], float(C[1]))  # in the gear's own coordinates
    if gear["link"] == mech.frame:
        return np.tile(mark, (kin.n, 1))
    return _masked(kin.position(gear["link"], mark), valid)


def _link(kin, link, valid, length) -> dict:
    number = link.number
    if number == kin.mechanism.frame:
        points = {k: np.tile(np.asarray(p, float), (kin.n, 1)) for k, p in link.points.items()}
        G = None
    else:
        points = {k: _masked(kin.position(number, k), valid) for k in link.points}
        G = _masked(kin.G(number), valid)
    # A gear is drawn as its pitch circle, not as a block at its centre.
    gear = any(isinstance(j, GearMesh) and number in j.links for j in kin.mechanism.joints)
    outline = [] if gear and len(link.points) == 1 else _outline(link)
    return {"number": number, "name": link.name, "outline": outline, "points": points, "G": G}


def _round_link(link: dict, length) -> dict:
    return {**link, "points": {k: length(p) for k, p in link["points"].items()},
            "G": None if link["G"] is None else length(link["G"])}


def _joint(result, joint, valid) -> dict:
    """A joint force, as the lower-numbered link's on the higher, at the point where it acts [m]."""
    kin = result.kinematics
    i, j = sorted(joint.links)
    if isinstance(joint, Prismatic):
        kind, at = "prismatic", kin.position(joint.slider, joint.point)
    elif isinstance(joint, GearMesh):
        # Each gear's centre is a point of the gear; the tooth force is drawn at the pitch point.
        k, other = joint.links
        Ck, Cj = kin.z(k, joint.centers[0]), kin.z(other, joint.centers[1])
        P = pitch(joint, k, Ck, Cj)[0]
        kind, at = "gear", np.column_stack([P.real, P.imag])
    else:
        kind, at = "revolute", kin.position(j, joint.point)
    name = result.name_of(i, j)
    out = {"key": (i, j), "name": name, "label": label(name, "N"), "of": i, "on": j, "kind": kind,
           "at": _masked(at, valid), "analytical": _masked(result.force(i, j), valid)}
    if kind == "prismatic":
        # The couple the pair transmits beside its force drawn at the slider's point (the force's line lies
        # e = C/N along the guide from it): a free body balances in moments only with it.
        out["couple"] = np.where(valid, result.couple[(i, j)], np.nan)
    return out


def _loads(kin, valid) -> list[dict]:
    """Each link's weight, then every external load of the file, in its order, with what it applies."""
    mech = kin.mechanism
    out = []
    if mech.gravity:
        for k in mech.moving:
            m = mech.link(k).mass
            if m:
                name = f"W{k}"
                out.append({"name": name, "label": label(name, "N"), "link": k, "point": "G",
                            "at": _masked(kin.G(k), valid),
                            "force": _masked(np.tile([0.0, -m * mech.gravity], (kin.n, 1)), valid)})
    for ld in mech.loads:
        value = applied(kin, ld)
        name = ld.name or ("F" if isinstance(ld, PointForce) else "T")
        if isinstance(ld, PointForce):
            out.append({"name": name, "label": label(name, "N"), "link": ld.link, "point": ld.point,
                        "at": _masked(kin.position(ld.link, ld.point), valid),
                        "force": _masked(np.column_stack([value.real, value.imag]), valid)})
        else:
            out.append({"name": name, "label": label(name, "N*m"), "link": ld.link, "point": "G",
                        "at": _masked(kin.G(ld.link), valid),
                        "torque": np.where(valid, value, np.nan)})
    return out


def _inertia(kin, k: int, valid) -> dict:
    found = inertia(kin, k)
    name = f"R{k}i"  # the builder's name for the single resultant of the inertia loads
    return {"link": k, "name": name, "label": label(name, "N"), "G": _masked(kin.G(k), valid),
            "force": _masked(found.F, valid), "torque": np.where(valid, found.T, np.nan),
            "h": np.where(valid, found.h, np.nan), "line_point": _masked(found.line_point, valid)}


def _input(kin, mech, length) -> dict:
    crank = mech.driver.crank
    values = np.round(kin.q, 12).tolist() if crank else length.scalars(kin.q)
    return {"name": "theta" if crank else "s", "label": label(mech.driver.input_symbol, "rad" if crank else "m"),
            "values": values, "rate": np.asarray(kin.q_dot, float).tolist(), **_time(kin, crank)}


def _time(kin, crank: bool) -> dict:
    """When each position is reached [s], from the first, over one turn of ``period`` = 2π/|ω| [s] (null where
    the crank does not turn at one constant speed: a static problem, a slider-driven one, a varying ω)."""
    rate = np.unique(np.asarray(kin.q_dot, float))
    if not crank or rate.size != 1 or rate[0] == 0:
        return {"time": None, "period": None}
    omega = float(rate[0])
    period = 2 * math.pi / abs(omega)
    t = np.mod((np.asarray(kin.q, float) - float(kin.q[0])) / omega, period)
    return {"time": np.round(t, 15).tolist(), "period": period}


def _driver(mech, length) -> dict:
    """The driver, and the point of it a student drags: a crank's point farthest from its pivot, a slider's point."""
    d = mech.driver
    link = mech.link(d.link)
    if d.crank:
        pivot = mech.joint_between(mech.frame, d.link)
        P0 = np.asarray(link.points[pivot.point], float) if isinstance(pivot, Revolute) else np.zeros(2)
        handle = max(link.points, key=lambda k: float(np.hypot(*(np.asarray(link.points[k], float) - P0))))
    else:
        handle = mech.joint_between(mech.frame, d.link).point
    return {"link": d.link, "kind": d.kind, "name": d.symbol, "label": label(d.symbol, "N*m" if d.crank else "N"),
            "handle": handle}


def _guides(kin, valid, length) -> list[dict]:
    """Each sliding pair's rail: the stretch of its guide line the slider's point covers over the cycle (plus a
    margin of a tenth of the mechanism's size), as two end points [m] at every position."""
    mech = kin.mechanism
    size = mechanism_size(mech)
    out = []
    for joint in mech.joints:
        if not isinstance(joint, Prismatic):
            continue
        u = _masked(kin.guide_direction(joint), valid)
        T = _masked(kin.position(joint.guide, joint.through), valid)
        P = _masked(kin.position(joint.slider, joint.point), valid)
        s = np.einsum("ij,ij->i", P - T, u)
        if not np.isfinite(s).any():
            s = np.zeros_like(s)
        lo, hi = np.nanmin(s) - 0.1 * size, np.nanmax(s) + 0.1 * size
        out.append({"guide": joint.guide, "slider": joint.slider, "point": joint.point,
                    "ends": [length(T + lo * u), length(T + hi * u)]})
    return out


def _effort(result, valid, force, size) -> dict:
    """The driving effort over the cycle, and its curve's axis: from the least to the greatest value, 0 included (a
    constant effort, the epicyclic train's, would otherwise have an axis of no height)."""
    crank = result.mechanism.driver.crank
    values = np.where(valid, result.effort, np.nan)
    rounded = np.asarray(force.torque(values, size) if crank else force.scalars(values), float)
    finite = rounded[np.isfinite(rounded)]
    lo, hi = (min(float(finite.min()), 0.0), max(float(finite.max()), 0.0)) if finite.size else (0.0, 0.0)
    return {"name": result.driver_name, "label": label(result.driver_name, "N*m" if crank else "N"),
            "analytical": rounded.tolist(), "range": [lo, hi] if hi > lo else [-1.0, 1.0]}


def _drive(kin, mech, valid, length) -> dict:
    """A slider driver's force on its free body: where it acts (the slider's point) and the guide's unit direction
    along which a positive effort F1j pushes, at every position (nothing for a crank, whose effort is a couple). The
    page draws effort × direction there, so it follows the effort when the speed changes."""
    if mech.driver.crank:
        return {}
    joint = mech.joint_between(mech.frame, mech.driver.link)
    return {"at": length(_masked(kin.position(joint.slider, joint.point), valid)),
            "direction": np.round(_masked(kin.guide_direction(joint), valid), 12).reshape(-1).tolist()}


def _view(links, forces, loads, gears, scale, size) -> list[float]:
    """[xmin, ymin, xmax, ymax] [m]: every point at every position, every gear's pitch circle, and the tip of every
    joint force and load drawn there. Not the inertia resultants: where the inertia force nearly vanishes beside its
    torque, its line lies far off (h = |T|/|F|), and a view that held it would leave the mechanism a speck; such an
    arrow is cut off."""
    xy = [p for link in links for p in link["points"].values()]
    xy += [link["G"] for link in links if link["G"] is not None]
    for at, F in [(f["at"], f["analytical"]) for f in forces] + [(ld["at"], ld["force"]) for ld in loads
                                                                 if "force" in ld]:
        xy.append(at + F / scale)
    by_number = {link["number"]: link for link in links}
    for gear in gears:
        C = by_number[gear["link"]]["points"][gear["centre"]]
        xy += [C - gear["radius"], C + gear["radius"]]
    every = np.concatenate(xy)
    every = every[np.isfinite(every).all(axis=1)]
    if not every.size:
        return [-size, -size, size, size]
    margin = 0.08 * size
    lo, hi = every.min(axis=0) - margin, every.max(axis=0) + margin
    return [float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1])]
