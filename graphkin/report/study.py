"""What ``graphkin study`` reports, as plain data in SI units (:func:`study_data`), as text (:func:`format_study`)
and as a table of rows for a spreadsheet (:func:`study_rows`, :func:`study_csv`).

The data is the JSON of ``graphkin study --json`` (schema: ``docs/json.md``).
"""

from __future__ import annotations

import csv
import io
import math

from graphkin.cycle.choice import field_axis
from graphkin.report.plain import number


def _choice_data(choice) -> dict:
    """The best design's choice as plain data: what is minimised, under which limits, and the design's index."""
    return {"minimise": choice.minimise, "require": [r.text for r in choice.require], "index": choice.index,
            "why": choice.why}


def study_data(study, choice=None) -> dict:
    """Every design of a study and its figures of merit, as plain data in SI units (schema: docs/json.md).

    Parameters
    ----------
    study : graphkin.cycle.study.Study
        The study (:func:`graphkin.cycle.study`).
    choice : graphkin.cycle.choice.Choice, optional
        The best design under stated limits (:meth:`Study.best`), reported as ``"best"``.

    Returns
    -------
    dict
        ``{"problem", "fields", "grid", "n", "Cs", "vectorised", "why_not_vectorised", "driver", "units", "designs"}``
        (and ``"best": {"minimise", "require", "index", "why"}`` with a choice, ``index`` into ``designs``);
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
        "designs": [{
            "values": list(d.values), "ok": d.ok, "failure": d.failure, "failed_at": number(d.failed_at),
            "torque_peak": number(d.torque_peak), "torque_rms": number(d.torque_rms),
            "I_s": number(d.I_s), "no_flywheel": d.no_flywheel,
            "shaking_force_peak": number(d.shaking_force_peak), "shaking_moment_peak": number(d.shaking_moment_peak),
            "transmission_angle_min": number(d.transmission_angle_min),
            "joint_peaks": {k: number(v) for k, v in d.joint_peaks.items()},
        } for d in study.designs],
    }
    if choice is not None:
        data["best"] = _choice_data(choice)
    return data


def _value(v) -> str:
    """A field's value as the file writes it, in one cell: ``85 mm`` or ``(85 mm, 0 mm)``."""
    return f"({', '.join(map(str, v))})" if isinstance(v, (list, tuple)) else str(v)


def _cell(x, scale: float = 1.0) -> str:
    return "—" if x is None else f"{x * scale:.6g}"


_FIGURES = ("torque_peak", "torque_rms", "I_s", "shaking_force_peak", "shaking_moment_peak", "transmission_angle_min")


def study_rows(data: dict) -> list[list]:
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

    Returns
    -------
    list of list
        The header (str), then a row per design: numbers as floats, text as str, None for an empty cell.
    """
    designs = data["designs"]
    u = data["units"]
    axes = [field_axis(values) for values in data["grid"]]
    joints = next((list(d["joint_peaks"]) for d in designs if d["joint_peaks"]), [])
    units = (u["torque"], u["torque"], u["inertia"], u["force"], u["moment"], "deg")
    head = ["design"] + [f if a is None else f"{f} [{a[0]}]" if a[0] else f for f, a in zip(data["fields"], axes)]
    head += ["ok"] + [f"{name} [{unit}]" for name, unit in zip(_FIGURES, units)]
    head += [f"{j}_peak [{u['force']}]" for j in joints]
    head += [f"failed_at [{'rad' if data['driver'] == 'crank' else 'm'}]", "failure"]
    best = data.get("best")
    if best is not None:
        head.append("best")
    rows = [head]
    for k, d in enumerate(designs):
        row = [k + 1] + [_value(v) if a is None else float(field_axis([v])[1][0]) for v, a in zip(d["values"], axes)]
        row += [d["ok"]] + [d[name] for name in _FIGURES[:-1]]
        mu = d["transmission_angle_min"]
        row += [None if mu is None else math.degrees(mu)] + [d["joint_peaks"].get(j) for j in joints]
        row += [d["failed_at"], d["failure"]]
        if best is not None:
            row.append(k == best["index"])
        rows.append(row)
    return rows


def study_csv(data: dict) -> str:
    """:func:`study_rows` as CSV text (numbers at full precision, empty where not defined)."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    for row in study_rows(data):
        writer.writerow(["" if x is None else repr(x) if isinstance(x, float) else x for x in row])
    return out.getvalue()


def format_study(data: dict) -> str:
    """The text report of ``graphkin study``: one row per design, SI units (μ in degrees).

    Parameters
    ----------
    data : dict
        :func:`study_data` of the study.

    Returns
    -------
    str
        The table, then where and why each design that fails cannot be assembled.
    """
    designs = data["designs"]
    joints = next((list(d["joint_peaks"]) for d in designs if d["joint_peaks"]), [])
    effort = "T [N·m]" if data["driver"] == "crank" else "F [N]"
    heads = (list(data["fields"]) + [effort.replace(" ", "_peak "), effort.replace(" ", "_rms "),
                                     f"I_s (C_s={data['Cs']:g}) [kg·m²]",
                                     "shaking F [N]", "shaking M [N·m]", "μ_min [°]"]
             + [f"|{j}| peak [N]" for j in joints])
    rows, notes = [], []
    best = data.get("best")
    chosen = None if best is None else best["index"]
    for k, d in enumerate(designs, 1):
        cells = [_value(v) for v in d["values"]]
        cells += [_cell(d[key]) for key in ("torque_peak", "torque_rms", "I_s", "shaking_force_peak",
                                            "shaking_moment_peak")]
        cells.append(_cell(d["transmission_angle_min"], 180 / math.pi))
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
        out += ["", _best_text(best, designs, data["driver"] == "crank")]
    return "\n".join(out)


def _best_text(best: dict, designs: list, crank: bool) -> str:
    """The line naming the best design (marked * in the table), or why there is none."""
    limits = f" with {' and '.join(best['require'])}" if best["require"] else ""
    if best["index"] is None:
        return f"best: none: {best['why']}"
    name = best["minimise"]
    d = designs[best["index"]]
    if name == "transmission_angle_min":
        x, unit = math.degrees(d[name]), "°"
    else:
        x = d[name] if name in d else d["joint_peaks"][name.removesuffix("_peak")]  # else a joint's peak force
        effort = "N·m" if crank else "N"  # a slider's driving effort is a force
        unit = {"torque_peak": effort, "torque_rms": effort, "I_s": "kg·m²", "shaking_moment_peak": "N·m"}.get(name, "N")
    values = ", ".join(_value(v) for v in d["values"])
    return f"best (*): design {best['index'] + 1} ({values}), least {name} = {x:.6g} {unit}{limits}"
