"""What ``graphkin cycle`` reports, as plain data in SI units (:func:`cycle_data`) and as text (:func:`format_cycle`).

The data is the JSON of ``graphkin cycle --json`` (schema: ``docs/json.md``);
handouts, exercise platforms and widgets read it too.
"""

from __future__ import annotations

import numpy as np

from graphkin.analytical import ForceAnalysis
from graphkin.cycle.sweep import peak_of, switching_angles
from graphkin.errors import GraphkinError
from graphkin.kinematics.points import link_points
from graphkin.notation import input_text
from graphkin.report.plain import floats, number, peak
from graphkin.units.systems import SI, UnitSystem

STEEL = 7850.0
"""Density of steel [kg/m³], for the flywheel disk of the cycle summary."""


DISK_THICKNESS = 0.025
"""Axial thickness of that disk [m] (an assumption, stated in the summary)."""


def _series(a, valid) -> list:
    """One value per position as a JSON list: None where the position is invalid or the value not finite."""
    return floats(np.where(valid, np.asarray(a, dtype=float), np.nan))


def _motion_series(position, velocity, acceleration, valid) -> dict:
    """A point's position, velocity and acceleration over a sweep, as plain data (see :func:`cycle_links`)."""
    return {key: {"x": _series(v[:, 0], valid), "y": _series(v[:, 1], valid)}
            for key, v in (("position", position), ("velocity", velocity), ("acceleration", acceleration))}


def cycle_links(result: ForceAnalysis) -> dict:
    """The motion of every moving link and of its points over a sweep, as plain data in SI units.

    The ``"links"`` entry of ``graphkin cycle --json`` (schema: ``docs/json.md``): per moving link, θ, ω, α
    and the position, velocity and acceleration of G and of every named point, one value per position
    (null where the position is invalid).

    Parameters
    ----------
    result : ForceAnalysis
        The sweep's force analysis (``cycle.analysis``); its kinematics are used.

    Returns
    -------
    dict
        ``{"3": {"theta": [n], "omega": [n], "alpha": [n], "G": MOTION, "points": {"A": MOTION, ...}}, ...}``
        with ``MOTION = {"position" | "velocity" | "acceleration": {"x": [n], "y": [n]}}``.
    """
    kin = result.kinematics
    valid = np.asarray(result.valid, dtype=bool)
    out = {}
    for link in kin.mechanism.moving:
        out[str(link)] = {
            "theta": _series(kin.theta[link], valid), "omega": _series(kin.w(link), valid),
            "alpha": _series(kin.al(link), valid),
            "G": _motion_series(kin.G(link), np.asarray(kin.v_G(link), dtype=float), kin.a_G(link), valid),
            "points": {name: _motion_series(m.position, m.velocity, m.acceleration, valid)
                       for name, m in link_points(kin, link).items()},
        }
    return out


def _where(cycle, q, u: UnitSystem = SI) -> str:
    """``θ12 = 62°`` for a crank, ``s = 200 mm`` for a slider driver (in the units of ``u``)."""
    d = cycle.problem.mechanism.driver
    if u.is_si or not np.isfinite(q):
        return input_text(q, d.crank, d.input_symbol, minus="-")
    kind = "angle" if d.crank else "length"
    unit = u.symbol(kind)
    return f"{d.input_symbol or ('θ' if d.crank else 's')} = {u.show(q, kind):.6g}{unit if unit == '°' else ' ' + unit}"


def cycle_data(cycle, Cs=None) -> dict:
    """Everything ``graphkin cycle`` reports, as plain data in SI units (schema: docs/json.md).

    Parameters
    ----------
    cycle : graphkin.cycle.Cycle
        The sweep (:func:`graphkin.cycle.sweep`).
    Cs : float, optional
        Coefficient of speed fluctuation: size a flywheel (its ``"flywheel"`` is null without it).

    Returns
    -------
    dict
        The driving effort, input power, joint forces and their peaks, shaking force and moment,
        transmission angle, flywheel and joint-force index over the cycle, each as lists of floats
        (None where a position is invalid); see ``docs/json.md``.

    Raises
    ------
    GraphkinError
        If a flywheel is asked for where none can be sized (a slider, not one full turn, a failed position).
    """
    problem, r = cycle.problem, cycle.analysis
    mech = problem.mechanism
    crank = mech.driver.crank
    peaks = cycle.peaks()
    omega = float(np.mean(cycle.q_dot))
    constant = crank and bool(np.allclose(cycle.q_dot, omega))
    power = cycle.power
    forces = {}
    for (i, j), F in r.forces.items():
        name = r.name_of(i, j)
        size, angle = cycle.polar(name)
        forces[name] = {"x": floats(F[:, 0]), "y": floats(F[:, 1]), "magnitude": floats(size),
                        "angle": floats(angle), "peak": peak(peaks.forces[name])}
    S = cycle.shaking_force()
    try:
        mu = floats(cycle.transmission_angle())
    except GraphkinError:
        mu = None
    flywheel = None
    if Cs is not None:
        f = cycle.flywheel(Cs)
        disk = f.disk(STEEL, DISK_THICKNESS)
        flywheel = {
            "Cs": f.Cs, "omega_avg": f.omega_avg, "T_avg": f.T_avg, "E": f.E, "I_s": f.I_s,
            "crossings": floats(f.crossings), "areas": floats(f.areas), "accumulated": floats(f.accumulated),
            "energy": floats(f.U),
            "disk": {"material": "steel", "density": disk.density, "thickness": disk.thickness,
                     "radius": disk.radius, "mass": disk.mass, "I": disk.I},
        }
    try:
        jfi = cycle.joint_force_index()
    except GraphkinError as exc:
        index = {"defined": False, "reason": str(exc)}
    else:
        index = {
            "defined": True, "reason": "", "units": jfi.units, "limit": jfi.limit, "values": floats(jfi.index),
            "load": floats(jfi.load), "joint": [str(x) for x in jfi.joint], "peak": peak(jfi.peak),
            "over_limit": floats(jfi.over_limit),
            "immovable": [{"at": float(q), "reason": why} for q, why in jfi.immovable],
            "unloaded": floats(jfi.unloaded),
        }
    return {
        "problem": problem.name, "title": problem.title, "source": problem.source,
        "units": {"length": "m", "angle": "rad", "force": "N", "torque": "N*m", "power": "W", "energy": "J",
                  "inertia": "kg*m^2", "mass": "kg", "time": "s"},
        "driver": {"link": mech.driver.link, "kind": mech.driver.kind, "name": mech.driver.symbol},
        "n": cycle.n,
        "closed": cycle.closed,
        "input": {"name": "theta" if crank else "s", "values": floats(cycle.q), "rate": floats(cycle.q_dot)},
        "valid": [bool(v) for v in cycle.valid],
        "invalid": [{"index": int(i), "reason": r.reason(int(i))} for i in np.flatnonzero(~cycle.valid)],
        "links": cycle_links(r),
        "effort": {"name": mech.driver.symbol, "values": floats(cycle.torque), "average": number(cycle.average),
                   "max": peak(peaks.effort_max), "min": peak(peaks.effort_min)},
        "power": {"values": floats(power),
                  "average": number(cycle.average * omega) if constant else None,
                  "max": peak(peak_of(power, cycle.q)), "min": peak(peak_of(power, cycle.q, lowest=True))},
        "forces": forces,
        "shaking": {"force": {"x": floats(S[:, 0]), "y": floats(S[:, 1])}, "moment": floats(cycle.shaking_moment())},
        "transmission_angle": mu,
        "flywheel": flywheel,
        "joint_force_index": index,
    }


def format_cycle(cycle, data: dict, units: UnitSystem | None = None) -> str:
    """The text summary of ``graphkin cycle``, with units, from :func:`cycle_data`.

    Parameters
    ----------
    cycle : graphkin.cycle.Cycle
        The sweep the data was made from.
    data : dict
        :func:`cycle_data` of it (SI).
    units : graphkin.units.systems.UnitSystem, optional
        The units to print in (``--units``); default SI.

    Returns
    -------
    str
        What ``graphkin cycle`` prints.
    """
    u = SI if units is None else units
    mech = cycle.problem.mechanism
    crank = mech.driver.crank
    effort = "torque" if crank else "force"
    unit = u.symbol(effort)
    name = mech.driver.symbol

    def at(p):
        return _where(cycle, p["at"] if p["at"] is not None else float("nan"), u)

    def val(x, digits=6, kind=None):
        return "—" if x is None else f"{x if kind is None else u.show(x, kind):.{digits}g}"

    q0, q1 = cycle.q[0], cycle.q[-1]
    span = _where(cycle, q0, u) + (f" … {_where(cycle, q1, u).split(' = ')[1]}" if cycle.n > 1 else "")
    lines = [f"{cycle.problem.name}: {cycle.problem.title}",
             f"{cycle.n} position{'s' * (cycle.n != 1)}, {span}{' (one full turn)' if cycle.closed else ''}"]
    if crank:
        lines[-1] += f", ω = {u.show(float(np.mean(cycle.q_dot)), 'angular_velocity'):.6g} {u.symbol('angular_velocity')}"
    ends = switching_angles(cycle.problem)
    if ends:
        where = ", ".join(_where(cycle, b, u).split(" = ")[1] for b in ends)
        how = ("jump (switch on or off, step in a table, or reverse with the motion)"
               if any(ld.varies for ld in cycle.problem.mechanism.loads) else "switch on or off")
        lines.append(f"loads {how} at {where}: each sampled just before and just after")
    e = data["effort"]
    lines += ["", f"Driving {'torque' if crank else 'force'} {name}",
              f"  peak     {val(e['max']['value'], kind=effort)} {unit} at {at(e['max'])}",
              f"  lowest   {val(e['min']['value'], kind=effort)} {unit} at {at(e['min'])}",
              f"  average  {val(e['average'], kind=effort)} {unit}"]
    p = data["power"]
    W = u.symbol("power")
    lines += ["Input power",
              f"  peak     {val(p['max']['value'], kind='power')} {W} at {at(p['max'])}",
              f"  lowest   {val(p['min']['value'], kind='power')} {W} at {at(p['min'])}"]
    if p["average"] is not None:
        lines.append(f"  average  {val(p['average'], kind='power')} {W}")
    lines += ["", "Peak joint forces"]
    width = max(len(k) for k in data["forces"]) if data["forces"] else 3
    for k, f in data["forces"].items():
        lines.append(f"  {k:<{width}}  {val(f['peak']['value'], kind='force')} {u.symbol('force')} at {at(f['peak'])}")
    fw = data["flywheel"]
    if fw is not None:
        d = fw["disk"]
        L = u.symbol("length")
        lines += ["", f"Flywheel (C_s = {fw['Cs']:.6g}, ω_avg = {val(fw['omega_avg'], kind='angular_velocity')} "
                  f"{u.symbol('angular_velocity')}, Norton §11.11)",
                  f"  E        {val(fw['E'], kind='energy')} {u.symbol('energy')} (largest energy swing)",
                  f"  I_s      {val(fw['I_s'], kind='moment_of_inertia')} {u.symbol('moment_of_inertia')} "
                  "(system inertia on the crank shaft)",
                  f"  disk     radius {u.show(d['radius'], 'length'):.4g} {L}, mass {u.show(d['mass'], 'mass'):.4g} "
                  f"{u.symbol('mass')} (assuming solid steel, ρ = {d['density']:g} kg/m³, "
                  f"{u.show(d['thickness'], 'length'):.4g} {L} thick)"]
    jfi = data["joint_force_index"]
    lines += ["", "Joint-force index (static, Holte and Chase, Norton §11.12)"]
    if not jfi["defined"]:
        lines.append(f"  undefined: {jfi['reason']}")
    else:
        ju = f" {jfi['units']}" if jfi["units"] else ""
        lines.append(f"  peak     {val(jfi['peak']['value'])}{ju} at {at(jfi['peak'])}"
                     f" (limit {jfi['limit']:g}: {'over' if (jfi['peak']['value'] or 0) > jfi['limit'] else 'within'})")
        if jfi["immovable"]:
            lines.append(f"  immovable at {len(jfi['immovable'])} position(s):")
            lines += [f"    {_where(cycle, x['at'], u)}: {x['reason']}" for x in jfi["immovable"][:10]]
            if len(jfi["immovable"]) > 10:
                lines.append(f"    … and {len(jfi['immovable']) - 10} more (see --json)")
        else:
            lines.append("  immovable positions: none")
    return "\n".join(lines)
