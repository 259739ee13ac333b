"""What ``graphkin study`` reports, as plain data in SI units (:func:`study_data`) and as text (:func:`format_study`).

The data is the JSON of ``graphkin study --json`` (schema: ``docs/json.md``).
"""

from __future__ import annotations

import math

from graphkin.report.plain import number


def study_data(study) -> dict:
    """Every design of a study and its figures of merit, as plain data in SI units (schema: docs/json.md).

    Parameters
    ----------
    study : graphkin.cycle.study.Study
        The study (:func:`graphkin.cycle.study`).

    Returns
    -------
    dict
        ``{"problem", "fields", "grid", "n", "Cs", "vectorised", "why_not_vectorised", "driver", "units", "designs"}``;
        each design ``{"values", "ok", "failure", "failed_at", "torque_peak", "torque_rms", "I_s", "no_flywheel",
        "shaking_force_peak", "shaking_moment_peak", "transmission_angle_min", "joint_peaks"}``, a figure that
        is not defined (or of a design that fails) null.
    """
    return {
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


def _value(v) -> str:
    """A field's value as the file writes it, in one cell: ``85 mm`` or ``(85 mm, 0 mm)``."""
    return f"({', '.join(map(str, v))})" if isinstance(v, (list, tuple)) else str(v)


def _cell(x, scale: float = 1.0) -> str:
    return "—" if x is None else f"{x * scale:.6g}"


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
    for k, d in enumerate(designs, 1):
        cells = [_value(v) for v in d["values"]]
        cells += [_cell(d[key]) for key in ("torque_peak", "torque_rms", "I_s", "shaking_force_peak",
                                            "shaking_moment_peak")]
        cells.append(_cell(d["transmission_angle_min"], 180 / math.pi))
        cells += [_cell(d["joint_peaks"].get(j)) for j in joints]
        rows.append([str(k)] + cells)
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
    return "\n".join(out)
