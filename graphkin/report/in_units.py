"""A report's plain data in the units ``--units`` asks for, each field's unit stated (``docs/json.md``).

The data of :func:`graphkin.report.solution`, :func:`graphkin.report.cycle_data` and
:func:`graphkin.report.flywheel_data` is in SI. With ``--units``, ``--json`` prints it converted: every number
of a kind of quantity in the system's unit of that kind, and ``"units"`` mapping each field (a path with ``*``
for any key and ``[]`` for any item, e.g. ``"positions[].forces.*"``) to its unit. A field the table does not
list keeps its SI value, and ``"units"`` says so (``"positions[].graphical.steps": "SI (m, N)"``).
"""

from __future__ import annotations

from graphkin.units.systems import UnitSystem

_SOLUTION_POSITION: dict[str, str] = {
    "links.*.theta": "angle", "links.*.omega": "angular_velocity", "links.*.alpha": "angular_acceleration",
    "links.*.G": "length", "links.*.v_G": "velocity", "links.*.a_G": "acceleration",
    "links.*.inertia_force": "force", "links.*.inertia_torque": "torque", "links.*.h": "length",
    "links.*.points.*.position": "length", "links.*.points.*.velocity": "velocity",
    "links.*.points.*.acceleration": "acceleration",
    "forces.*": "force",
    "prismatic.*.normal": "force", "prismatic.*.friction": "force", "prismatic.*.couple": "torque",
    "prismatic.*.offset": "length",
    "loads[].force": "force", "loads[].torque": "torque",
    "sliding[].velocity": "velocity", "sliding[].acceleration": "acceleration", "sliding[].coriolis": "acceleration",
    "driver.vector": "force",
    "forward.I": "moment_of_inertia", "forward.T_driving": "torque", "forward.T_resisting": "torque",
    "forward.alpha": "angular_acceleration",
    "graphical.forces.*": "force",
}


def _convert(node, path: list[str], k: float):
    """``node`` with the value at ``path`` (keys, ``*`` any key, ``[]`` every item) multiplied by ``k``."""
    if node is None:
        return None
    if not path:
        if isinstance(node, list):
            return [None if x is None else k * x for x in node]
        return k * node
    head, rest = path[0], path[1:]
    if head.endswith("[]"):
        key = head[:-2]
        if key not in node or node[key] is None:
            return node
        return {**node, key: [_convert(item, rest, k) for item in node[key]]} if rest else \
            {**node, key: _convert(node[key], [], k)}
    if head == "*":
        return {name: _convert(value, rest, k) for name, value in node.items()}
    if not isinstance(node, dict) or head not in node:
        return node
    return {**node, head: _convert(node[head], rest, k)}


def _apply(data: dict, table: dict[str, str], prefix: str, u: UnitSystem, units: dict) -> dict:
    for field, kind in table.items():
        data = _convert(data, _split(field), u.scales[kind])
        units[prefix + field] = u.units[kind]
    return data


def _split(field: str) -> list[str]:
    """``"loads[].force"`` -> ``["loads[]", "force"]``."""
    return field.split(".")


def solution_in(data: dict, u: UnitSystem) -> dict:
    """The data of :func:`graphkin.report.solution` in the units of ``u``, with ``"units"`` per field.

    Parameters
    ----------
    data : dict
        :func:`graphkin.report.solution`'s data (SI).
    u : UnitSystem
        The system to convert to (``--units``).

    Returns
    -------
    dict
        A new dict; ``data`` is not changed.
    """
    crank = data["driver"]["kind"] == "crank"
    units: dict[str, str] = {"system": u.name}
    table = dict(_SOLUTION_POSITION)
    table["input.value"] = "angle" if crank else "length"
    table["input.rate"] = "angular_velocity" if crank else "velocity"
    table["input.rate2"] = "angular_acceleration" if crank else "acceleration"
    table["driver.value"] = "torque" if crank else "force"
    table["graphical.driver.value"] = "torque" if crank else "force"
    kinds = {p["unknown"]["kind"] for p in data["positions"] if "unknown" in p}
    if kinds:
        table["unknown.value"] = kinds.pop()
    positions = [_apply(p, table, "positions[].", u, units) for p in data["positions"]]
    given = []
    for g in data["given"]:
        kind = {"theta": "angle", "point": "length", "omega": "angular_velocity", "alpha": "angular_acceleration",
                "a_G": "acceleration", "v_G": "velocity"}[g["name"]]
        given.append(_convert(g, ["value"], u.scales[kind]))
        units[f"given[name={g['name']}].value"] = u.units[kind]
    for path in ("positions[].graphical.steps", "positions[].graphical.subproblems",
                 "positions[].graphical_kinematics"):
        units[path] = "SI (m, rad, N, N*m, s)"
    units["positions[].graphical.force_scale_N_per_mm"] = "N/mm"
    units["positions[].prismatic.*.guide_direction"] = "(unit vector)"
    units["positions[].sliding[].guide_direction"] = "(unit vector)"
    units["positions[].graphical.relative_difference"] = "(ratio)"
    return {**data, "units": units, "given": given, "positions": positions}


def _motion(prefix: str) -> dict[str, str]:
    return {f"{prefix}.{key}.{axis}": kind for key, kind in
            (("position", "length"), ("velocity", "velocity"), ("acceleration", "acceleration")) for axis in "xy"}


def cycle_in(data: dict, u: UnitSystem) -> dict:
    """The data of :func:`graphkin.report.cycle_data` in the units of ``u``, with ``"units"`` per field.

    The joint-force index (a ratio, or its own ``units``) and the flywheel disk's density stay as they are.
    """
    crank = data["driver"]["kind"] == "crank"
    q = "angle" if crank else "length"
    effort = "torque" if crank else "force"
    table = {
        "input.values": q, "input.rate": "angular_velocity" if crank else "velocity",
        "links.*.theta": "angle", "links.*.omega": "angular_velocity", "links.*.alpha": "angular_acceleration",
        **_motion("links.*.G"), **_motion("links.*.points.*"),
        "effort.values": effort, "effort.average": effort, "effort.max.value": effort, "effort.min.value": effort,
        "effort.max.at": q, "effort.min.at": q,
        "power.values": "power", "power.average": "power", "power.max.value": "power", "power.min.value": "power",
        "power.max.at": q, "power.min.at": q,
        "forces.*.x": "force", "forces.*.y": "force", "forces.*.magnitude": "force", "forces.*.angle": "angle",
        "forces.*.peak.value": "force", "forces.*.peak.at": q,
        "shaking.force.x": "force", "shaking.force.y": "force", "shaking.moment": "torque",
        "transmission_angle": "angle",
        "flywheel.omega_avg": "angular_velocity", "flywheel.T_avg": "torque", "flywheel.E": "energy",
        "flywheel.I_s": "moment_of_inertia", "flywheel.crossings": q, "flywheel.areas": "energy",
        "flywheel.accumulated": "energy", "flywheel.energy": "energy",
        "flywheel.disk.thickness": "length", "flywheel.disk.radius": "length", "flywheel.disk.mass": "mass",
        "flywheel.disk.I": "moment_of_inertia",
        "joint_force_index.peak.at": q, "joint_force_index.immovable[].at": q,
    }
    units: dict[str, str] = {"system": u.name}
    out = _apply(data, table, "", u, units)
    units["flywheel.disk.density"] = "kg/m^3"
    units["joint_force_index.values"] = "(the index's own units)"
    return {**out, "units": units}


def flywheel_in(data: dict, u: UnitSystem) -> dict:
    """The data of :func:`graphkin.report.flywheel_data` in the units of ``u``, with ``"units"`` per field."""
    table = {
        "omega_avg": "angular_velocity", "I_s": "moment_of_inertia", "E": "energy", "T_avg": "torque",
        "period": "angle", "driving.values": "torque", "resisting.values": "torque", "theta": "angle",
        "table[].from": "angle", "table[].to": "angle", "table[].area": "energy", "table[].accumulated": "energy",
        "speed.max.value": "angular_velocity", "speed.min.value": "angular_velocity",
        "speed.max.at": "angle", "speed.min.at": "angle",
        "acceleration.values": "angular_acceleration", "acceleration.max.value": "angular_acceleration",
        "acceleration.min.value": "angular_acceleration", "acceleration.max.at": "angle", "acceleration.min.at": "angle",
    }
    units: dict[str, str] = {"system": u.name}
    out = _apply(data, table, "", u, units)
    return {**out, "units": units}
