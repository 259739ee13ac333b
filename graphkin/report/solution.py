"""Results as plain data (SI numbers a grader or handout can consume) and as textbook text.

:func:`solution` returns dictionaries and lists of floats only, the same
content the CLI prints with ``--json`` (schema: ``docs/json.md``);
:func:`format_solution` prints it with textbook units.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from graphkin import notation
from graphkin.analytical import ForceAnalysis
from graphkin.analytical.loads import applied
from graphkin.graphical import construct_forces
from graphkin.graphical.guard import forces_disagreement, mechanism_size
from graphkin.kinematics.points import link_points
from graphkin.model import PointForce, Prismatic
from graphkin.notation import PICOMETRE, RESIDUE, input_text, largest, num, unless_rounding
from graphkin.report.polygons import graphical_kinematics_data
from graphkin.units.systems import SI, UnitSystem


def _vec(v):
    return [float(v[0]), float(v[1])]


def constructions(result: ForceAnalysis) -> list:
    """The graphical construction of every position of a result (None where invalid)."""
    return [construct_forces(result.kinematics, i) if result.valid[i] else None for i in range(result.n)]


def cross_check(result: ForceAnalysis, graphical: list) -> ForceAnalysis:
    """The result with every position where its two routes disagree marked not valid, with the reason.

    The graphical route (:func:`constructions`) solves each position with other arithmetic (resultants, two- and
    three-force members, polygons); where it gives another force or effort than the analytical route beyond
    :data:`graphkin.graphical.guard.AGREEMENT`, or cannot close where the analytical route found a solution,
    neither answer can be trusted, and the position is reported with the disagreement instead of either
    (:func:`graphkin.graphical.guard.forces_disagreement`, the one guard of everything graphical).

    Parameters
    ----------
    result : ForceAnalysis
        The analytical solution.
    graphical : list of Construction or None
        The graphical route at each of its positions (:func:`constructions`).

    Returns
    -------
    ForceAnalysis
        ``result`` itself where the routes agree everywhere; else a copy whose ``valid`` is False at the
        positions where they disagree, with the reason in its ``failures``.
    """
    failures: dict[str, np.ndarray] = {}
    size = mechanism_size(result.mechanism)
    for i, c in enumerate(graphical):
        if c is None or not result.valid[i]:
            continue
        why = forces_disagreement(result, c, i, size)
        if why:
            failures.setdefault(why, np.zeros(result.n, bool))[i] = True
    if not failures:
        return result
    valid = result.valid.copy()
    for where in failures.values():
        valid &= ~where
    return replace(result, valid=valid, failures={**result.failures, **failures})


def _graphical(result: ForceAnalysis, c, i, size: float) -> dict:
    """The graphical route at position i as plain data, with its difference from the analytical one (``size``:
    :func:`graphkin.graphical.guard.mechanism_size` of the mechanism, worked out once for every position)."""
    if c is None:
        return {"valid": False, "reason": result.reason(i), "disagreement": False}
    if not c.valid:
        return {"valid": False, "reason": c.reason, "disagreement": c.disagreement}
    forces = {}
    diff = {}
    scale = max([float(np.hypot(*result.force(a, b)[i])) for a, b in result.forces] + [1e-300])
    for a, b in result.forces:
        G, A = c.force(a, b), result.force(a, b)[i]
        forces[result.name_of(a, b)] = _vec(G)
        forces[result.name_of(b, a)] = _vec(-G)
        # Relative to the force itself, or to the largest force when it is ~0.
        diff[result.name_of(a, b)] = float(np.hypot(*(G - A)) / max(float(np.hypot(*A)), 1e-12 * scale))
    eff = result.effort[i]
    # An effort that is rounding beside the forces (T12 where [unknown] balances the driver) is compared as 0.
    # It is measured against the largest force (times the mechanism's size for a torque), as cross_check does.
    arm = scale * (size if result.mechanism.driver.crank else 1.0)
    den = abs(eff) if abs(eff) > RESIDUE * arm else arm
    diff[result.driver_name] = float(abs(c.effort - eff) / max(den, 1e-300)) if eff else float(abs(c.effort))
    subproblems = []
    for sp in c.subproblems:
        sub_forces = {}
        for a, b in result.forces:
            F = sp.force(a, b)
            sub_forces[result.name_of(a, b)] = _vec(F)
            sub_forces[result.name_of(b, a)] = _vec(-F)
        driver = {"name": c.driver_name, "value": float(sp.effort)}
        if sp.driver_vector is not None:
            driver["vector"] = _vec(sp.driver_vector)
        subproblems.append({"label": sp.label, "link": sp.link, "mark": sp.mark, "forces": sub_forces, "driver": driver})
    steps = [{"kind": s.kind, "caption": s.caption, "link": s.link, "sub": s.sub,
              "points": {k: list(v) for k, v in s.points.items()},
              "lines": [{"name": l.name, "point": list(l.point), "direction": list(l.direction), "role": l.role}
                        for l in s.lines],
              "polygon": [{"name": a.name, "vector": list(a.vector), "known": a.known} for a in s.polygon],
              "values": {k: (list(v) if isinstance(v, tuple) else v) for k, v in s.values.items()}}
             for s in c.steps]
    return {"valid": True, "reason": "", "disagreement": False, "forces": forces,
            "driver": {"name": c.driver_name, "value": float(c.effort)},
            "relative_difference": diff, "force_scale_N_per_mm": c.force_scale, "steps": steps,
            "subproblems": subproblems, "warnings": list(c.warnings)}


def solution(problem, result: ForceAnalysis, graphical: list | None = None, kinematic: list | None = None, *,
             kinematic_steps: bool = True) -> dict:
    """Everything the analysis found, as plain data in SI units.

    Parameters
    ----------
    problem : graphkin.problem.Problem
        The problem solved (its name, title and source head the data).
    result : ForceAnalysis
        Its analytical solution.
    graphical : list of Construction, optional
        The graphical route per position (:func:`constructions`); included
        under ``"graphical"`` with the relative difference per force. A
        position where the two routes disagree is not valid
        (:func:`cross_check`).
    kinematic : list of (MotionConstruction, InstantCentres), optional
        The velocity and acceleration polygons and the instant centres per position
        (:func:`graphkin.report.polygons.kinematic_constructions`); included under
        ``"graphical_kinematics"``.
    kinematic_steps : bool
        The polygons' steps in full, captions included (:func:`graphkin.report.graphical_kinematics_data`).

    Returns
    -------
    dict
        ``{"problem", "title", "source", "analysis", "frame", "units", "driver", "positions": [...]}``;
        see ``docs/json.md``.
    """
    if graphical is not None:
        result = cross_check(result, graphical)
    kin = result.kinematics
    mech = kin.mechanism
    crank = mech.driver.crank
    positions = []
    pairs = list(result.forces)
    inertia = {link: result.inertia(link) for link in mech.moving}
    points = {link: link_points(kin, link) for link in mech.moving}
    v_G = {link: np.asarray(kin.v_G(link), dtype=float) for link in mech.moving}
    applied = _applied(kin)
    forward = getattr(problem, "forward", None)
    step = forward.step(result.effort, kin.q_dot) if forward is not None else None
    unknown = getattr(problem, "unknown", None)
    found = unknown.values(result) if unknown is not None else None
    size = mechanism_size(mech)
    sliding = _sliding(kin)
    for i in range(result.n):
        entry = {
            "index": i,
            "input": {"name": "theta" if crank else "s", "value": float(kin.q[i]),
                      "rate": float(kin.q_dot[i]), "rate2": float(kin.q_ddot[i])},
            "valid": bool(result.valid[i]),
            "reason": result.reason(i),
        }
        if result.valid[i]:
            links = {}
            for link in mech.moving:
                inn = inertia[link]
                links[str(link)] = {
                    "theta": float(kin.theta[link][i]), "omega": float(kin.w(link)[i]), "alpha": float(kin.al(link)[i]),
                    "G": _vec(kin.G(link)[i]), "v_G": _vec(v_G[link][i]), "a_G": _vec(kin.a_G(link)[i]),
                    "inertia_force": _vec(inn.F[i]), "inertia_torque": float(inn.T[i]),
                    "h": None if not np.isfinite(inn.h[i]) else float(inn.h[i]),
                    "points": {name: {"position": _vec(m.position[i]), "velocity": _vec(m.velocity[i]),
                                      "acceleration": _vec(m.acceleration[i])} for name, m in points[link].items()},
                }
            forces, prismatic = {}, {}
            for a, b in pairs:
                F = result.force(a, b)[i]
                forces[result.name_of(a, b)] = _vec(F)
                forces[result.name_of(b, a)] = _vec(-F)
                if (a, b) in result.normal:
                    joint = mech.joint_between(a, b)
                    u = kin.guide_direction(joint)[i]
                    # Lever arms of 1e-16 m are rounding noise of a reaction through the slider point.
                    offset = float(result.offset(a, b)[i]) if result.normal[(a, b)][i] else None
                    if offset is not None and abs(offset) < 1e-12:
                        offset = 0.0
                    prismatic[result.name_of(a, b)] = {
                        "normal": float(result.normal[(a, b)][i]), "friction": float(F @ u),
                        "couple": float(result.couple[(a, b)][i]),
                        "offset": offset,
                        "slider_point": joint.point, "guide_direction": _vec(u),
                    }
            driver = {"name": result.driver_name, "value": float(result.effort[i])}
            if not crank:
                driver["vector"] = _vec(result.driver_force()[i])
            entry.update(links=links, forces=forces, prismatic=prismatic, driver=driver,
                         loads=[_load_entry(ld, value[i]) for ld, value in applied],
                         sliding=[{**about, "guide_direction": _vec(u[i]), "velocity": float(v_r[i]),
                                   "acceleration": float(a_r[i]), "coriolis": [float(a_c[i].real), float(a_c[i].imag)]}
                                  for about, u, v_r, a_r, a_c in sliding])
            if step is not None:
                entry["forward"] = {"I": forward.I, **{key: float(v[i]) for key, v in step.items()}}
            if found is not None:
                kind = "torque" if unknown.guide(mech) is None else "force"
                entry["unknown"] = {"name": unknown.label(mech), "link": unknown.link, "kind": kind,
                                    "value": float(found[i])}
        if graphical is not None:
            entry["graphical"] = _graphical(result, graphical[i], i, size)
        if kinematic is not None:
            entry["graphical_kinematics"] = graphical_kinematics_data(kin, *kinematic[i], steps=kinematic_steps)
        positions.append(entry)
    return {
        "problem": problem.name,
        "title": problem.title,
        "source": problem.source,
        "analysis": "static" if kin.static else "dynamic",
        "frame": mech.frame,
        "units": {"length": "m", "angle": "rad", "force": "N", "torque": "N*m", "mass": "kg", "time": "s"},
        "driver": {"link": mech.driver.link, "kind": mech.driver.kind, "name": result.driver_name},
        "given": _given(kin),
        "positions": positions,
    }


def _sliding(kin) -> list:
    """Each sliding pair between two moving links (a slider on a guide that turns) with its motion along the guide at
    every position: ``(about, u, v_r, a_r, a_c)``, ``about`` the pair's names, the rest arrays
    (:meth:`graphkin.kinematics.Kinematics.sliding`)."""
    mech = kin.mechanism
    out = []
    for joint in mech.joints:
        if isinstance(joint, Prismatic) and mech.frame not in joint.links:
            about = {"name": f"{joint.point}{joint.slider}{joint.point}{joint.guide}", "slider": joint.slider,
                     "guide": joint.guide, "point": joint.point}
            out.append((about, kin.guide_direction(joint), *kin.sliding(joint)))
    return out


def _sliding_text(entry, u: UnitSystem = SI) -> list[str]:
    """The sliding pairs on moving guides at one position, as the text report prints them (two lines each)."""
    lines = []
    v, a = u.symbol("velocity"), u.symbol("acceleration")
    kv, ka = u.scales["velocity"], u.scales["acceleration"]
    # What a rate here is rounding beside: the fastest (most accelerated) point of the mechanism at this position.
    points = [m for s in entry["links"].values() for m in s["points"].values()]
    v_max, a_max = largest(m["velocity"] for m in points), largest(m["acceleration"] for m in points)
    for s in entry.get("sliding", []):
        name, g = s["name"], s["guide"]
        still = "" if entry["links"][str(g)]["omega"] else f" (ω{g} = 0)"
        lines += [f"    {s['point']} of link {s['slider']} on link {g}, along the guide "
                  f"∠ {math.degrees(math.atan2(*s['guide_direction'][::-1])):.2f}°: "
                  f"v_{name} = {num(kv * s['velocity'], minus='-', zero=kv * RESIDUE * v_max)} {v}, "
                  f"a^r_{name} = {num(ka * s['acceleration'], minus='-', zero=ka * RESIDUE * a_max)} {a}",
                  f"      Coriolis a^c_{name} = 2 ω{g} × v_{name} = "
                  f"{_polar(s['coriolis'], 'acceleration', u, scale=a_max)}{still}"]
    return (["  Sliding on moving guides (the slider relative to the guide's coincident point)"] + lines) if lines else []


def _given(kin) -> list:
    """The values the problem gives instead of deriving them, as plain data (SI): one dict per value."""
    out = []
    for key, v in kin.given.items():
        v = np.asarray(v, dtype=float)[0]
        entry = {"link": int(key[0]), "name": key[1] if key[1] != "at" else "point"}
        if key[1] == "at":
            entry["point"] = key[2]
        entry["value"] = _vec(v) if v.ndim else float(v)
        out.append(entry)
    return out


def _given_text(given, u: UnitSystem = SI) -> list[str]:
    kinds = {"omega": ("ω", "angular_velocity"), "alpha": ("α", "angular_acceleration"), "a_G": ("a_G", "acceleration"),
             "v_G": ("v_G", "velocity")}
    out = []
    for g in given:
        n, v = g["name"], g["value"]
        if n == "theta":
            out.append(f"θ{g['link']} = {u.show(v, 'angle'):.6g}{_angle_unit(u)}")
        elif n == "point":
            x, y = (u.show(c, "length") for c in v)
            out.append(f"{g['point']} on link {g['link']} at ({x:.6g}, {y:.6g}) {u.symbol('length')}")
        else:
            sym, kind = kinds[n]
            out.append(f"{sym}{g['link']} = " + (_polar(v, kind, u) if isinstance(v, list)
                                                  else f"{u.show(v, kind):.6g} {u.symbol(kind)}"))
    return out


def _angle_unit(u: UnitSystem) -> str:
    """An angle's unit as printed after its number: ``°`` right after it, any other after a space."""
    return u.symbol("angle") if u.symbol("angle") == "°" else f" {u.symbol('angle')}"


def _polar(v, kind: str, u: UnitSystem, digits: int = 4, scale: float = 0.0) -> str:
    """A vector of ``kind`` (SI) as ``u`` prints it: ``27.06 lbf ∠ -73.78°`` (``scale``: an SI force)."""
    k = u.scales[kind]
    return polar_text([k * v[0], k * v[1]], u.symbol(kind), digits, scale=k * scale)


def polar_text(v, unit="N", digits=4, scale=0.0) -> str:
    """A vector in the report's plain text: ``27.06 N ∠ -73.78°`` (:func:`graphkin.notation.polar_text`)."""
    return notation.polar_text(v, unit, digits, scale=scale, minus="-")


def _mm(x, u: UnitSystem = SI) -> str:
    """A length [m] in the report's unit (mm in SI), a rounding residue below a picometre shown as 0."""
    k = u.scales["length"]
    return num(x * k, minus="-", zero=PICOMETRE * k)


def _input_text(entry, crank, static=False, u: UnitSystem = SI):
    q = entry["input"]
    if u.is_si:
        where = input_text(q["value"], crank, minus="-")
    elif crank:
        where = f"θ = {num(u.show(q['value'], 'angle'), 6, minus='-')}{_angle_unit(u)}"
    else:
        where = f"s = {num(u.show(q['value'], 'length'), 6, minus='-')} {u.symbol('length')}"
    if static:
        # Only the position matters; a rate, if the file gives one, only sets the sense of sliding for friction.
        return where
    kinds = ("ω", "angular_velocity", "α", "angular_acceleration") if crank else ("v", "velocity", "a", "acceleration")
    return (f"{where}, {kinds[0]} = {u.show(q['rate'], kinds[1]):.6g} {u.symbol(kinds[1])}, "
            f"{kinds[2]} = {u.show(q['rate2'], kinds[3]):.6g} {u.symbol(kinds[3])}")


def _applied(kin) -> list:
    """Each external load with what it applies at every position (table, window and sense included)."""
    return [(ld, applied(kin, ld)) for ld in kin.mechanism.loads]


def _load_entry(load, value) -> dict:
    """One external load at one position, as plain data: a force's vector [N] or a torque [N·m]."""
    out = {"name": load.name, "link": load.link}
    if isinstance(load, PointForce):
        out.update(point=load.point, force=[float(value.real) + 0.0, float(value.imag) + 0.0])
    else:
        out["torque"] = float(value) + 0.0
    out["acting"] = bool(value != 0)
    return out


def _loads_text(entry, u: UnitSystem = SI) -> list[str]:
    """The external loads at one position, as the text report prints them."""
    lines = []
    N, Nm = u.symbol("force"), u.symbol("torque")
    for ld in entry.get("loads", []):
        name = ld["name"] or ("P" if "force" in ld else "T")
        if "force" in ld:
            value = _polar(ld["force"], "force", u) if ld["acting"] else f"0 {N} (not acting here)"
            lines.append(f"    {name:<5} on link {ld['link']} at {ld['point']}: {value}")
        else:
            value = (f"{num(u.show(ld['torque'], 'torque'), minus='-')} {Nm}" if ld["acting"]
                     else f"0 {Nm} (not acting here)")
            lines.append(f"    {name:<5} on link {ld['link']}: {value}")
    return (["  External loads"] + lines) if lines else []


def format_solution(problem, result: ForceAnalysis, graphical: list | None = None,
                    units: UnitSystem | None = None) -> str:
    """The solution as text with textbook units (mm, degrees, N, N·m); both routes when ``graphical`` is given.

    Parameters
    ----------
    problem : graphkin.problem.Problem
        The problem solved (its title, source and driver name the report).
    result : ForceAnalysis
        Its analytical solution.
    graphical : list of Construction, optional
        The graphical route per position (:func:`constructions`).
    units : graphkin.units.systems.UnitSystem, optional
        The units to print in (``--units``); default SI: mm, degrees, N, N·m, rad/s. The graphical route's
        step captions and its polygon scale stay in SI (they describe a drawing made in N and mm).

    Returns
    -------
    str
        What ``graphkin solve`` prints.
    """
    u = SI if units is None else units
    N, Nm, L = u.symbol("force"), u.symbol("torque"), u.symbol("length")
    data = solution(problem, result, graphical)
    crank = data["driver"]["kind"] == "crank"
    mech = result.mechanism
    out = [data["title"] or data["problem"]]
    if data["source"]:
        out.append(f"source: {data['source']}")
    static = data["analysis"] == "static"
    frame = data["frame"]
    out.append(f"convention: F_ij is the force of link i on link j; link {frame} is the frame; angles and torques CCW "
               "positive")
    if static:
        out.append("analysis: static (no inertia loads: the links carry their external loads"
                   + (" and weights" if mech.gravity else "") + " only)")
    if data["given"]:
        out.append("given (instead of derived): " + "; ".join(_given_text(data["given"], u)))
    for entry in data["positions"]:
        out.append("")
        out.append(f"Position {entry['index'] + 1} of {len(data['positions'])}: {_input_text(entry, crank, static, u)}")
        if not entry["valid"]:
            out.append(f"  no solution: {entry['reason']}")
            continue
        if static:
            out.append("  Positions")
            out.append(f"    {'link':<6}{_head('θ', 'angle', u):>10}")
            for link, s in entry["links"].items():
                out.append(f"    {link:<6}{u.show(s['theta'], 'angle'):>10.3f}")
        else:
            out.append("  Kinematics")
            out.append(f"    {'link':<6}{_head('θ', 'angle', u):>10}{_head('ω', 'angular_velocity', u):>12}"
                       f"{_head('α', 'angular_acceleration', u):>13}   {_head('a_G', 'acceleration', u)}")
            for link, s in entry["links"].items():
                out.append(f"    {link:<6}{u.show(s['theta'], 'angle'):>10.3f}{u.show(s['omega'], 'angular_velocity'):>12.4f}"
                           f"{u.show(s['alpha'], 'angular_acceleration'):>13.4f}   {_polar(s['a_G'], 'acceleration', u)}")
            out.extend(_sliding_text(entry, u))
            out.append("  Inertia loads (d'Alembert: F_i = −m a_G at G, T_i = −I_G α, h = |T_i|/|F_i|)")
        for link, s in ([] if static else entry["links"].items()):
            if mech.link(int(link)).mass == 0:
                out.append(f"    link {link}: massless")
                continue
            h = "—" if s["h"] is None else f"{_mm(s['h'], u)} {L}"
            T = s["inertia_torque"]
            sense = "CCW" if T > 0 else "CW" if T < 0 else ""
            if abs(T) <= PICOMETRE * math.hypot(*s["inertia_force"]):
                T, sense = 0.0, ""  # rounding: the resultant passes through G (h under a picometre)
            out.append(f"    link {link}: F_i = {_polar(s['inertia_force'], 'force', u)}   "
                       f"T_i = {num(u.show(T, 'torque'), minus='-')} {Nm} {sense}   h = {h}")
        out.extend(_loads_text(entry, u))
        out.append("  Joint forces")
        biggest = largest(entry["forces"].values())  # what a force or torque here is rounding beside
        for a, b in result.forces:
            name, back = result.name_of(a, b), result.name_of(b, a)
            F = entry["forces"][name]
            Fx, Fy = (u.show(c, "force") for c in F)
            out.append(f"    {name:<5} = ({Fx:>10.4f}, {Fy:>10.4f}) {N} = {_polar(F, 'force', u, scale=biggest):<24} "
                       f"{back} = −{name}")
            if name in entry["prismatic"]:
                s = entry["prismatic"][name]
                floor = RESIDUE * biggest
                where = ("—" if s["offset"] is None or abs(s["normal"]) <= floor else
                         f"{_mm(s['offset'], u)} {L} from {s['slider_point']} along the guide")
                k = u.scales["force"]
                out.append(f"          normal {num(k * s['normal'], minus='-', zero=k * floor)} {N}, "
                           f"friction {num(k * s['friction'], minus='-', zero=k * floor)} {N}, line acts {where}")
        d = entry["driver"]
        if crank:
            T = unless_rounding(d["value"], biggest)  # 0 at a dead centre
            sense = "CCW" if T > 0 else "CW" if T < 0 else ""
            out.append(f"  Driver: {d['name']} = {u.show(T, 'torque'):.4f} {Nm} {sense}".rstrip())  # none at a dead centre
            if "forward" in entry:
                f = entry["forward"]
                out.append(f"  Forward step: I α = T_driving + T_resisting (CCW positive), "
                           f"I = {u.show(f['I'], 'moment_of_inertia'):.6g} {u.symbol('moment_of_inertia')}: "
                           f"T_driving = −{d['name']} = {num(u.show(f['T_driving'], 'torque'), minus='-')} {Nm}, "
                           f"T_resisting = {num(u.show(f['T_resisting'], 'torque'), minus='-')} {Nm}, "
                           f"α = {num(u.show(f['alpha'], 'angular_acceleration'), minus='-')} "
                           f"{u.symbol('angular_acceleration')}")
        else:
            out.append(f"  Driver: {d['name']} = {_polar(d['vector'], 'force', u)} "
                       f"({u.show(d['value'], 'force'):.4f} {N} along the guide)")
        if "unknown" in entry:
            k = entry["unknown"]
            x = u.show(k["value"], k["kind"])
            sense = ("CCW" if x > 0 else "CW" if x < 0 else "") if k["kind"] == "torque" else "along the guide"
            out.append(f"  Unknown effort (asked): {k['name']} = {x:.4f} {u.symbol(k['kind'])} {sense} on link "
                       f"{k['link']}, balancing the given loads ({d['name']} is then 0)")
        if "graphical" in entry:
            out.extend(_format_graphical(entry, crank, u))
    return "\n".join(out)


def _head(symbol: str, kind: str, u: UnitSystem) -> str:
    """A table column's head, ``θ [deg]`` or ``ω [rpm]``."""
    unit = "deg" if u.symbol(kind) == "°" else u.symbol(kind)
    return f"{symbol} [{unit}]"


def _format_subproblems(entry, crank, u: UnitSystem = SI) -> list[str]:
    """The superposition as a table: each sub-problem's readings and driving effort, then their sum."""
    g = entry["graphical"]
    subs = g.get("subproblems") or []
    if not subs:
        return []
    width = 26
    out = ["    Superposition: each sub-problem's readings and driving " + ("torque" if crank else "force")
           + ", then their sum (the whole problem)"]
    head = "".join(f"{sp['label'] + ' (link ' + str(sp['link']) + ')':>{width}}" for sp in subs)
    out.append(f"    {'force':<7}{head}{'sum':>{width}}")
    names = [name for name in g["relative_difference"] if name != g["driver"]["name"]]
    biggest = largest(entry["forces"].values())
    for name in names:
        cells = "".join(f"{_polar(sp['forces'][name], 'force', u, scale=biggest):>{width}}" for sp in subs)
        out.append(f"    {name:<7}{cells}{_polar(g['forces'][name], 'force', u, scale=biggest):>{width}}")
    name, kind = g["driver"]["name"], "torque" if crank else "force"
    unit = u.symbol(kind)
    cells = "".join(f"{u.show(sp['driver']['value'], kind):>{width - 4}.4f} {unit:<3}" for sp in subs)
    out.append(f"    {name:<7}{cells}{u.show(g['driver']['value'], kind):>{width - 4}.4f} {unit:<3}")
    return out


def _format_graphical(entry, crank, u: UnitSystem = SI) -> list[str]:
    g = entry["graphical"]
    out = ["  Graphical route (force polygons)"]
    if not g["valid"]:
        return out + [f"    cannot close: {g['reason']}"]
    if not u.is_si:
        out.append("    (the construction is drawn in N and mm: its steps and its scale are in SI)")
    out += [f"    {k + 1}. {s['caption']}" for k, s in enumerate(g["steps"])]
    out.append(f"    polygon scale: {g['force_scale_N_per_mm']:g} N per mm")
    out += _format_subproblems(entry, crank, u)
    out.append(f"    {'force':<6}{'analytical':>26}{'graphical':>26}{'rel. diff':>11}")
    biggest = largest(entry["forces"].values())
    for name, rel in g["relative_difference"].items():
        if name == g["driver"]["name"]:
            kind = "torque" if crank else "force"
            unit = u.symbol(kind)
            a, c = (u.show(unless_rounding(x, biggest), kind) for x in (entry["driver"]["value"], g["driver"]["value"]))
            out.append(f"    {name:<6}{a:>22.4f} {unit:<3}{c:>22.4f} {unit:<3}{rel:>11.1e}")
        else:
            out.append(f"    {name:<6}{_polar(entry['forces'][name], 'force', u, scale=biggest):>26}"
                       f"{_polar(g['forces'][name], 'force', u, scale=biggest):>26}{rel:>11.1e}")
    out += [f"    warning: {w}" for w in g["warnings"]]
    return out
