"""``graphkin flywheel FILE``: size a flywheel from a turning-moment diagram alone (no mechanism).

::

    graphkin flywheel engine.toml           # the energy table, E, I_s (or C_s), speed and acceleration extremes
    graphkin flywheel engine.toml --json    # the same as JSON, SI units (docs/json.md)

The file format is in ``docs/problem-files.md`` ("Flywheel files"). Bad input
is a :class:`graphkin.errors.GraphkinError`, which ``graphkin``'s ``main``
prints as one line with exit code 2.
"""

from __future__ import annotations

import json
import math


def add_parser(sub) -> None:
    """Add ``flywheel`` to the ``graphkin`` subcommands."""
    f = sub.add_parser("flywheel", help="size a flywheel from a turning-moment diagram (engine torque against angle), "
                       "no mechanism needed")
    f.add_argument("file", help="a flywheel file (TOML; see docs/problem-files.md, 'Flywheel files'), or a catalog "
                   "flywheel's name (graphkin list)")
    f.add_argument("--json", action="store_true", help="print the result as JSON in SI units (schema: docs/json.md)")


def run(args) -> int:
    """Carry out ``graphkin flywheel``; returns the exit code."""
    from pathlib import Path

    from graphkin import catalog
    from graphkin.cycle.flywheel_file import load_flywheel

    # A catalog name, unless a file of that name is here.
    if not Path(args.file).exists() and args.file in catalog.flywheel_names():
        problem = load_flywheel(catalog.flywheel_path(args.file), name=args.file)
    else:
        problem = load_flywheel(args.file)
    fly = problem.size()
    data = flywheel_data(problem, fly)
    if args.json:
        print(json.dumps(data, indent=2, ensure_ascii=False))
    else:
        print(format_flywheel(data))
    return 0


def _floats(a) -> list:
    import numpy as np  # here, not at the top: `graphkin` imports this module to build its parser

    return [float(x) for x in np.asarray(a, dtype=float).ravel()]


def _maybe(x):
    x = float(x)
    return x if math.isfinite(x) else None


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
        "driving": {"text": problem.driving_text, "values": _floats(fly.driving)},
        "resisting": {"text": problem.resisting_text, "values": _floats(fly.resisting)},
        "theta": _floats(fly.theta),
        "table": [{"from": p.start, "to": p.end, "area": p.area, "accumulated": p.accumulated} for p in fly.table()],
        "speed": {"max": {"value": speed.omega_max, "at": _maybe(speed.at_max)},
                  "min": {"value": speed.omega_min, "at": _maybe(speed.at_min)}},
        "acceleration": {"values": _floats(fly.acceleration()),
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
