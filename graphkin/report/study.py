"""What ``graphkin study`` reports, as plain data in SI units (:func:`study_data`), as text (:func:`format_study`)
and as a table of rows for a spreadsheet (:func:`study_rows`, :func:`study_csv`).

The data is the JSON of ``graphkin study --json`` (schema: ``docs/json.md``); with ``--units``, :func:`study_in`
converts it as ``graphkin cycle --units`` converts a cycle's, and the table and the CSV show those units.
"""

from __future__ import annotations

import csv
import io
import math

from graphkin.cycle.choice import field_axis
from graphkin.report.in_units import _apply
from graphkin.report.plain import number
from graphkin.units.systems import UnitSystem


def _choice_data(choice) -> dict:
    """The best design's choice as plain data: what is minimised, under which limits, and the design's index."""
    return {"minimise": choice.minimise, "require": [r.text for r in choice.require], "index": choice.index,
            "why": choice.why}


def _design_data(d) -> dict:
    return {
        "values": list(d.values), "ok": d.ok, "failure": d.failure, "failed_at": number(d.failed_at),
        "torque_peak": number(d.torque_peak), "torque_rms": number(d.torque_rms),
        "I_s": number(d.I_s), "no_flywheel": d.no_flywheel,
        "shaking_force_peak": number(d.shaking_force_peak), "shaking_moment_peak": number(d.shaking_moment_peak),
        "transmission_angle_min": number(d.transmission_angle_min),
        "joint_peaks": {k: number(v) for k, v in d.joint_peaks.items()},
    }


def optimum_data(o) -> dict:
    """An optimum (:meth:`Study.optimum`) as plain data, SI: ``"optimum"`` of :func:`study_data`."""
    return {"objective": o.objective, "sense": o.sense, "require": [r.text for r in o.require],
            "fields": list(o.fields), "x": list(o.x), "field_units": list(o.units), "values": list(o.values),
            "design": _design_data(o.design), "start": o.start, "converged": o.converged, "message": o.message,
            "method": o.method, "iterations": o.iterations, "evaluations": o.evaluations}


def study_data(study, choice=None, optimum=None) -> dict:
    """Every design of a study and its figures of merit, as plain data in SI units (schema: docs/json.md).

    Parameters
    ----------
    study : graphkin.cycle.study.Study
        The study (:func:`graphkin.cycle.study`).
    choice : graphkin.cycle.choice.Choice, optional
        The best design under stated limits (:meth:`Study.best`), reported as ``"best"``.
    optimum : graphkin.cycle.optimum.Optimum, optional
        The optimum between the grid's values (:meth:`Study.optimum`), reported as ``"optimum"``.

    Returns
    -------
    dict
        ``{"problem", "fields", "grid", "n", "Cs", "vectorised", "why_not_vectorised", "driver", "units", "designs"}``
        (and ``"best": {"minimise", "require", "index", "why"}`` with a choice, ``index`` into ``designs``;
        ``"optimum"`` with an optimum, :func:`optimum_data`);
        each design ``{"values", "ok", "failure", "failed_at", "torque_peak", "torque_rms", "I_s", "no_flywheel",
        "shaking_force_peak", "shaking_moment_peak", "transmission_angle_min", "joint_peaks"}``, a figure that
        is not defined (or of a design that fails) null.
    """
    data = {
        "problem": study.problem, "fields": list(study.fields), "grid": [list(v) for v in study.grid],
        "n": study.n, "Cs": study.Cs, "vectorised": study.vectorised, "why_not_vectorised": study.why_not_vectorised,
        "driver": "crank" if study.crank else "slider",
        # A slider's driving effort is a force: torque_peak and torque_rms are then in N.
        "units": {"torque": "N*m" if study.crank else "N", "force": "N", "moment": "N*m", "inertia": "kg*m^2",
                  "angle": "rad"},
        "designs": [_design_data(d) for d in study.designs],
    }
    if choice is not None:
        data["best"] = _choice_data(choice)
    if optimum is not None:
        data["optimum"] = optimum_data(optimum)
    return data


def _kinds(crank: bool) -> dict[str, str]:
    """Each figure of a design's data and its kind of quantity (:data:`graphkin.units.systems.KINDS`)."""
    effort = "torque" if crank else "force"
    return {"torque_peak": effort, "torque_rms": effort, "I_s": "moment_of_inertia", "shaking_force_peak": "force",
            "shaking_moment_peak": "torque", "transmission_angle_min": "angle", "joint_peaks.*": "force",
            "failed_at": "angle" if crank else "length"}


def study_in(data: dict, u: UnitSystem) -> dict:
    """The data of :func:`study_data` in the units of ``u`` (``--units``), with ``"units"`` per field.

    Every figure of every design (and of the optimum's design) is converted; ``"units"`` maps each field, a path
    with ``*`` for any key and ``[]`` for any item (``"designs[].torque_peak"``), to its unit, and ``"system"``
    to the system's name. The varied fields' values stay as the file writes them.

    Parameters
    ----------
    data : dict
        :func:`study_data`'s data (SI).
    u : UnitSystem
        The system to convert to.

    Returns
    -------
    dict
        A new dict; ``data`` is not changed.
    """
    table = _kinds(data["driver"] == "crank")
    units: dict[str, str] = {"system": u.name}
    out = _apply(data, {f"designs[].{k}": kind for k, kind in table.items()}, "", u, units)
    if "optimum" in out:
        units_o: dict[str, str] = {}
        design = _apply({"design": out["optimum"]["design"]}, {f"design.{k}": kind for k, kind in table.items()},
                        "optimum.", u, units_o)["design"]
        out = {**out, "optimum": {**out["optimum"], "design": design}}
        units.update(units_o)
    return {**out, "units": units}


def _view(data: dict, units: UnitSystem | None):
    """The data to show, the unit of each figure as a table prints it and as a CSV header writes it, and the
    factor from the data's transmission angle to the one shown: SI (μ in degrees, θ in rad) without ``units``."""
    crank = data["driver"] == "crank"
    kinds = _kinds(crank)
    if units is None:
        u = data["units"]
        printed = {"torque_peak": "N·m" if crank else "N", "I_s": "kg·m²", "shaking_force_peak": "N",
                   "shaking_moment_peak": "N·m", "transmission_angle_min": "°", "joint_peaks.*": "N"}
        written = {"torque_peak": u["torque"], "I_s": u["inertia"], "shaking_force_peak": u["force"],
                   "shaking_moment_peak": u["moment"], "transmission_angle_min": "deg", "joint_peaks.*": u["force"],
                   "failed_at": "rad" if crank else "m"}
        return data, printed, written, 180 / math.pi
    shown = study_in(data, units)
    return (shown, {k: units.symbol(kind) for k, kind in kinds.items()},
            {k: units.units[kind] for k, kind in kinds.items()}, 1.0)


def _value(v) -> str:
    """A field's value as the file writes it, in one cell: ``85 mm`` or ``(85 mm, 0 mm)``."""
    return f"({', '.join(map(str, v))})" if isinstance(v, (list, tuple)) else str(v)


def _cell(x, scale: float = 1.0) -> str:
    return "—" if x is None else f"{x * scale:.6g}"


_FIGURES = ("torque_peak", "torque_rms", "I_s", "shaking_force_peak", "shaking_moment_peak", "transmission_angle_min")

_UNIT_OF = {"torque_rms": "torque_peak"}
"""A figure whose unit is another's (the RMS effort's is the peak's)."""


def study_rows(data: dict, units: UnitSystem | None = None) -> list[list]:
    """The study as a table, one row per design after a header row: what ``graphkin study --csv`` writes.

    Each varied field is a column of numbers in the unit its values are written in (``links[1].mass [kg]``), or
    of the values as the file writes them where they are not numbers of one unit (a point); then whether the
    design assembles, each figure of merit in the unit its header states (SI, the transmission angle in degrees),
    where (θ [rad] or s [m]) and why a design cannot be assembled, and, when a best design was asked for, which.
    A figure that is not defined is an empty cell.

    Parameters
    ----------
    data : dict
        :func:`study_data` of the study.
    units : UnitSystem, optional
        The units of the figures (``--units``; :func:`study_in`); default SI, μ in degrees, θ in rad.

    Returns
    -------
    list of list
        The header (str), then a row per design: numbers as floats, text as str, None for an empty cell.
    """
    data, _, written, mu = _view(data, units)
    designs = data["designs"]
    axes = [field_axis(values) for values in data["grid"]]
    joints = next((list(d["joint_peaks"]) for d in designs if d["joint_peaks"]), [])
    head = ["design"] + [f if a is None else f"{f} [{a[0]}]" if a[0] else f for f, a in zip(data["fields"], axes)]
    head += ["ok"] + [f"{name} [{written[_UNIT_OF.get(name, name)]}]" for name in _FIGURES]
    head += [f"{j}_peak [{written['joint_peaks.*']}]" for j in joints]
    head += [f"failed_at [{written['failed_at']}]", "failure"]
    best = data.get("best")
    if best is not None:
        head.append("best")
    rows = [head]
    for k, d in enumerate(designs):
        row = [k + 1] + [_value(v) if a is None else float(field_axis([v])[1][0]) for v, a in zip(d["values"], axes)]
        row += [d["ok"]] + [d[name] for name in _FIGURES[:-1]]
        m = d["transmission_angle_min"]
        row += [None if m is None else m * mu] + [d["joint_peaks"].get(j) for j in joints]
        row += [d["failed_at"], d["failure"]]
        if best is not None:
            row.append(k == best["index"])
        rows.append(row)
    return rows


def study_csv(data: dict, units: UnitSystem | None = None) -> str:
    """:func:`study_rows` as CSV text (numbers at full precision, empty where not defined)."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    for row in study_rows(data, units):
        writer.writerow(["" if x is None else repr(x) if isinstance(x, float) else x for x in row])
    return out.getvalue()


def format_study(data: dict, units: UnitSystem | None = None) -> str:
    """The text report of ``graphkin study``: one row per design, SI units (μ in degrees) or ``units``.

    Parameters
    ----------
    data : dict
        :func:`study_data` of the study (SI).
    units : UnitSystem, optional
        The units to print the figures in (``--units``); default SI.

    Returns
    -------
    str
        The table, then where and why each design that fails cannot be assembled, the best design and the
        optimum, if asked for.
    """
    data, printed, _, mu = _view(data, units)
    designs = data["designs"]
    joints = next((list(d["joint_peaks"]) for d in designs if d["joint_peaks"]), [])
    T = "T" if data["driver"] == "crank" else "F"
    heads = (list(data["fields"]) + [f"{T}_peak [{printed['torque_peak']}]", f"{T}_rms [{printed['torque_peak']}]",
                                     f"I_s (C_s={data['Cs']:g}) [{printed['I_s']}]",
                                     f"shaking F [{printed['shaking_force_peak']}]",
                                     f"shaking M [{printed['shaking_moment_peak']}]",
                                     f"μ_min [{printed['transmission_angle_min']}]"]
             + [f"|{j}| peak [{printed['joint_peaks.*']}]" for j in joints])
    rows, notes = [], []
    best = data.get("best")
    chosen = None if best is None else best["index"]
    for k, d in enumerate(designs, 1):
        cells = [_value(v) for v in d["values"]]
        cells += [_cell(d[key]) for key in ("torque_peak", "torque_rms", "I_s", "shaking_force_peak",
                                            "shaking_moment_peak")]
        cells.append(_cell(d["transmission_angle_min"], mu))
        cells += [_cell(d["joint_peaks"].get(j)) for j in joints]
        rows.append([f"{k}*" if k - 1 == chosen else str(k)] + cells)
        if d["failure"]:
            notes.append(f"  design {k}: {d['failure']}")
    heads = ["#"] + heads
    width = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(heads)]
    shape = " × ".join(str(len(v)) for v in data["grid"])
    positions = f"{data['n']} crank angles" if data["n"] else "the problem's own positions"
    out = [f"{data['problem']}: {len(designs)} designs ({shape}), each over {positions}"]
    if not data["vectorised"]:
        out.append(f"({data['why_not_vectorised']})")
    out += ["", "  ".join(h.rjust(w) for h, w in zip(heads, width))]
    out += ["  ".join(c.rjust(w) for c, w in zip(r, width)) for r in rows]
    if notes:
        out += ["", f"{len(notes)} of the {len(designs)} designs cannot be assembled over the whole cycle:"] + notes
    if best is not None:
        out += ["", _best_text(best, designs, printed, mu)]
    if "optimum" in data:
        out += ["", _optimum_text(data["optimum"], designs, printed, mu)]
    return "\n".join(out)


def _figure(d: dict, name: str, printed: dict, mu: float) -> str:
    """One figure of a design's data as the table shows it, with its unit: ``141.64 N·m``."""
    if name == "transmission_angle_min":
        x, unit = d[name] * mu, printed[name]
    elif name in d:
        x, unit = d[name], printed[_UNIT_OF.get(name, name)]
    else:  # a joint's peak force
        x, unit = d["joint_peaks"][name.removesuffix("_peak")], printed["joint_peaks.*"]
    return f"{x:.6g} {unit}"


def _best_text(best: dict, designs: list, printed: dict, mu: float) -> str:
    """The line naming the best design (marked * in the table), or why there is none."""
    limits = f" with {' and '.join(best['require'])}" if best["require"] else ""
    if best["index"] is None:
        return f"best: none: {best['why']}"
    name = best["minimise"]
    d = designs[best["index"]]
    values = ", ".join(_value(v) for v in d["values"])
    return f"best (*): design {best['index'] + 1} ({values}), least {name} = {_figure(d, name, printed, mu)}{limits}"


def _optimum_text(o: dict, designs: list, printed: dict, mu: float) -> str:
    """The lines of the optimum between the grid's values: its values, its figure, the grid's best, scipy's word."""
    name = o["objective"]
    limits = f" with {' and '.join(o['require'])}" if o["require"] else ""
    values = ", ".join(f"{f} = {_value(v)}" for f, v in zip(o["fields"], o["values"]))
    least = "least" if o["sense"] == "minimise" else "greatest"
    said = "converged" if o["converged"] else "did not converge"
    return (f"optimum (scipy {o['method']}, {said}: {o['message']}; {o['iterations']} iterations, "
            f"{o['evaluations']} designs solved):\n  {values}: {least} {name} = "
            f"{_figure(o['design'], name, printed, mu)}{limits}\n"
            f"  (from the grid's best, design {o['start'] + 1}: {_figure(designs[o['start']], name, printed, mu)})")
