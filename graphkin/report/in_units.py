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
    units["positions[].graphical.relative_difference"] = "(ratio)"
    return {**data, "units": units, "given": given, "positions": positions}
