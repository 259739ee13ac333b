"""What ``graphkin flywheel`` reports, as plain data in SI units (:func:`flywheel_data`) and as text."""

from __future__ import annotations

import math

from graphkin.report.plain import floats, number
from graphkin.units.systems import SI, UnitSystem


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


def _deg(x, u: UnitSystem = SI) -> str:
    if x is None:
        return "—"
    unit = u.symbol("angle")
    return f"{u.show(x, 'angle'):.6g}{unit if unit == '°' else ' ' + unit}"


def format_flywheel(data: dict, units: UnitSystem | None = None) -> str:
    """The text report of ``graphkin flywheel``, from :func:`flywheel_data` (SI), in ``units`` (default SI)."""
    u = SI if units is None else units
    w = data["omega_avg"]
    E, I, Nm = u.symbol("energy"), u.symbol("moment_of_inertia"), u.symbol("torque")
    w_unit, a_unit = u.symbol("angular_velocity"), u.symbol("angular_acceleration")

    def deg(x):
        return _deg(x, u)

    def e(x):
        return u.show(x, "energy")

    wa, wb = max(14, len(E) + 10), max(18, len(E) + 17)  # the columns' widths: their heads fit
    out = [data["title"] or data["problem"]]
    if data["source"]:
        out.append(f"source: {data['source']}")
    cycle = "one turn" if math.isclose(data["period"], 2 * math.pi) else f"one cycle of {deg(data['period'])}"
    out += [f"driving torque T_d: {data['driving']['text']}",
            f"resisting torque T_r: {data['resisting']['text']}",
            (f"over {cycle}: T_avg = {u.show(data['T_avg'], 'torque'):.6g} {Nm}, "
             f"ω_avg = {u.show(w, 'angular_velocity'):.6g} {w_unit}"
             + (f" ({w * 30 / math.pi:.6g} rpm)" if w_unit != "rpm" else "")),
            "",
            "Energy table (Norton §11.11, Table 11-1): pulses of T_r − T_d between their crossings",
            f"  {'from':>10}{'to':>11}{f'area [{E}]':>{wa}}{f'accumulated [{E}]':>{wb}}   shaft"]
    for row in data["table"]:
        sense = "slows" if row["area"] > 0 else "speeds up" if row["area"] < 0 else ""
        out.append(f"  {deg(row['from']):>10}{deg(row['to']):>11}{e(row['area']):>+{wa}.6g}"
                   f"{e(row['accumulated']):>+{wb}.6g}   {sense}")
    if not data["table"]:
        out.append("  (the torques never cross: the speed is constant)")
    out.append(f"  E = largest accumulated − smallest (0 included) = {e(data['E']):.6g} {E}")
    out.append("")
    i_s = u.show(data["I_s"], "moment_of_inertia")
    if data["given"] == "Cs":
        out.append(f"Flywheel for C_s = {data['Cs']:.6g}: I_s = E / (C_s ω_avg²) = {i_s:.6g} {I} "
                   "(system inertia on the shaft)")
    else:
        out.append(f"With I_s = {i_s:.6g} {I} on the shaft: C_s = E / (I_s ω_avg²) = {data['Cs']:.6g}")
    sp = data["speed"]
    w_max, w_min = (u.show(sp[k]["value"], "angular_velocity") for k in ("max", "min"))
    out.append(f"  ω_max = {w_max:.6g} {w_unit} at θ = {deg(sp['max']['at'])} (after the largest energy "
               "returned to the shaft)")
    out.append(f"  ω_min = {w_min:.6g} {w_unit} at θ = {deg(sp['min']['at'])} (after the largest energy "
               "taken from it)")
    ac = data["acceleration"]
    a_max, a_min = (u.show(ac[k]["value"], "angular_acceleration") for k in ("max", "min"))
    out.append(f"  α = (T_d − T_r)/I_s: largest {a_max:.6g} {a_unit} at θ = {deg(ac['max']['at'])}, "
               f"smallest {a_min:.6g} {a_unit} at θ = {deg(ac['min']['at'])}")
    return "\n".join(out)
