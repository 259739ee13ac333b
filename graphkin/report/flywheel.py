"""What ``graphkin flywheel`` reports, as plain data in SI units (:func:`flywheel_data`) and as text."""

from __future__ import annotations

import math

from graphkin.report.plain import floats, number


def flywheel_data(problem, fly) -> dict:
    """Everything ``graphkin flywheel`` reports, as plain data in SI units (schema: docs/json.md).

    Parameters
    ----------
    problem : graphkin.cycle.flywheel_file.FlywheelProblem
    fly : graphkin.cycle.Flywheel
        ``problem.size()``.
    """
    speed = fly.speed_extremes()
    a_max, a_min = fly.acceleration_extremes()
    return {
        "problem": problem.name, "title": problem.title, "source": problem.source,
        "units": {"angle": "rad", "torque": "N*m", "energy": "J", "inertia": "kg*m^2", "angular_velocity": "rad/s",
                  "angular_acceleration": "rad/s^2"},
        "given": "Cs" if problem.Cs is not None else "I",
        "omega_avg": fly.omega_avg, "Cs": fly.Cs, "I_s": fly.I_s, "E": fly.E, "T_avg": fly.T_avg,
        "period": fly.period,
        "driving": {"text": problem.driving_text, "values": floats(fly.driving)},
        "resisting": {"text": problem.resisting_text, "values": floats(fly.resisting)},
        "theta": floats(fly.theta),
        "table": [{"from": p.start, "to": p.end, "area": p.area, "accumulated": p.accumulated} for p in fly.table()],
        "speed": {"max": {"value": speed.omega_max, "at": number(speed.at_max)},
                  "min": {"value": speed.omega_min, "at": number(speed.at_min)}},
        "acceleration": {"values": floats(fly.acceleration()),
                         "max": {"value": a_max.value, "at": a_max.at, "index": a_max.index},
                         "min": {"value": a_min.value, "at": a_min.at, "index": a_min.index}},
    }


def _deg(x) -> str:
    return "—" if x is None else f"{math.degrees(x):.6g}°"


def format_flywheel(data: dict) -> str:
    """The text report of ``graphkin flywheel``, from :func:`flywheel_data`."""
    w = data["omega_avg"]
    out = [data["title"] or data["problem"]]
    if data["source"]:
        out.append(f"source: {data['source']}")
    cycle = "one turn" if math.isclose(data["period"], 2 * math.pi) else f"one cycle of {_deg(data['period'])}"
    out += [f"driving torque T_d: {data['driving']['text']}",
            f"resisting torque T_r: {data['resisting']['text']}",
            f"over {cycle}: T_avg = {data['T_avg']:.6g} N·m, ω_avg = {w:.6g} rad/s ({w * 30 / math.pi:.6g} rpm)",
            "",
            "Energy table (Norton §11.11, Table 11-1): pulses of T_r − T_d between their crossings",
            f"  {'from':>10}{'to':>11}{'area [J]':>14}{'accumulated [J]':>18}   shaft"]
    for row in data["table"]:
        sense = "slows" if row["area"] > 0 else "speeds up" if row["area"] < 0 else ""
        out.append(f"  {_deg(row['from']):>10}{_deg(row['to']):>11}{row['area']:>+14.6g}{row['accumulated']:>+18.6g}   {sense}")
    if not data["table"]:
        out.append("  (the torques never cross: the speed is constant)")
    out.append(f"  E = largest accumulated − smallest (0 included) = {data['E']:.6g} J")
    out.append("")
    if data["given"] == "Cs":
        out.append(f"Flywheel for C_s = {data['Cs']:.6g}: I_s = E / (C_s ω_avg²) = {data['I_s']:.6g} kg·m² "
                   "(system inertia on the shaft)")
    else:
        out.append(f"With I_s = {data['I_s']:.6g} kg·m² on the shaft: C_s = E / (I_s ω_avg²) = {data['Cs']:.6g}")
    sp = data["speed"]
    out.append(f"  ω_max = {sp['max']['value']:.6g} rad/s at θ = {_deg(sp['max']['at'])} (after the largest energy "
               "returned to the shaft)")
    out.append(f"  ω_min = {sp['min']['value']:.6g} rad/s at θ = {_deg(sp['min']['at'])} (after the largest energy "
               "taken from it)")
    ac = data["acceleration"]
    out.append(f"  α = (T_d − T_r)/I_s: largest {ac['max']['value']:.6g} rad/s² at θ = {_deg(ac['max']['at'])}, "
               f"smallest {ac['min']['value']:.6g} rad/s² at θ = {_deg(ac['min']['at'])}")
    return "\n".join(out)
