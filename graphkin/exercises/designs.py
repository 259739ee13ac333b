"""Questions whose answer is a design: one field's value, chosen from a grid, that meets stated limits at least cost.

A design exercise (its ``[design]`` table, ``docs/exercises.md``) names one field of the problem file, the grid of
values the student chooses from, the limits a design must meet (``"shaking_force_peak <= 1500 N"``: figures of
merit of :mod:`graphkin.cycle.choice`) and what it minimises: ``"value"``, the field's own value (the lightest
counterweight, the shortest crank), or a figure of merit (``"torque_peak"``). Its question ``find = "design"``
asks for that value. The key is the study of the student's own data (:func:`graphkin.cycle.study`): every value of
the grid solved over the cycle, the cheapest that meets every limit (the first of equal ones, in the grid's order).

The key is a value of the grid, and the grid is all the study knows: the true boundary of a limit lies within one
step of the grid of the key (on the side that fails), so the grader allows **one step of the grid** either side
(:func:`slack`): a student who solves the same grid gets the key itself, and one who finds the boundary
continuously (a finer grid, a root-finder) lands within that step.

Two slips are keyed as values, found by the same study (:data:`SLIPS`): ``unconstrained``, the design that is
cheapest when the limits are left out, and ``best_for_limit``, the design that is best for the first limit's
figure (the counterweight that balances best, heavier than needed). With ``feedback = "distance"`` any other wrong
design is also told whether it meets the limits (:func:`design_part`); not by default, since "meets" and "does not
meet" part at the key itself and a search would bisect its way there without a study.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np

from graphkin.cycle.choice import figure_values, figures, requirement
from graphkin.cycle.studies import study
from graphkin.errors import GraphkinError, ProblemFileError
from graphkin.units import to_si

__all__ = ["DESIGN_KINDS", "DIMENSIONS", "SLIPS", "Chosen", "DesignTable", "choose", "design_part", "design_words",
           "dimension", "read_design", "slack"]

DIMENSIONS = {"mass": "kg", "length": "mm", "angle": "deg", "moment_of_inertia": "kg*m^2", "force": "N",
              "torque": "N*m", "angular_velocity": "rpm"}
"""What a designed field may measure, and the unit its answer is read in by default."""

DESIGN_KINDS = frozenset(f"design_{d}" for d in DIMENSIONS)
"""The kinds of a design question (:class:`graphkin.exercises.Question`), one per dimension of the field."""

SLIPS = {"unconstrained": 0.25, "best_for_limit": 0.25}
"""The design slips and the share of the question's points each earns by default."""

TABLE = {"field", "from", "to", "step", "values", "label", "minimise", "require"}
"""The keys of an exercise file's ``[design]`` table."""


@dataclass(frozen=True)
class DesignTable:
    """An exercise's ``[design]`` table, read.

    Attributes
    ----------
    field : str
        The field the student chooses (a path of :mod:`graphkin.problem.fields`, e.g. ``"links[0].mass"``).
    label : str
        Words for it (``"the counterweight B"``).
    values : tuple of str
        The grid, as the file writes it (``"0.35 kg"``).
    si : tuple of float
        The same values in SI units.
    dimension : str
        What the field measures (a key of :data:`DIMENSIONS`).
    minimise : str
        ``"value"`` (the field's own value) or a figure of merit's name.
    require : tuple of str
        The limits, as written (``"shaking_force_peak <= 1500 N"``).
    """

    field: str
    label: str
    values: tuple
    si: tuple
    dimension: str
    minimise: str
    require: tuple

    @property
    def step(self) -> float:
        """The grid's resolution: its largest step between neighbouring values [SI] (0 for one value)."""
        s = np.sort(np.asarray(self.si))
        return float(np.max(np.diff(s))) if len(s) > 1 else 0.0


WORDS = {"torque_peak": "the peak driving torque", "torque_rms": "the RMS driving torque", "I_s": "the flywheel's I_s",
         "shaking_force_peak": "the peak shaking force", "shaking_moment_peak": "the peak shaking moment",
         "transmission_angle_min": "the least transmission angle"}
"""Each figure of merit in the words a student's sheet and feedback print (no file keys)."""

_OPS = {"<=": "≤", ">=": "≥", "<": "<", ">": ">"}


def figure_words(name: str) -> str:
    """A figure of merit in words: ``"the peak shaking force"``, ``"the peak |F23|"``."""
    return WORDS.get(name, f"the peak |{name.removesuffix('_peak')}|")


def limit_words(table: DesignTable) -> str:
    """The limits in words: ``"the peak shaking force ≤ 1500 N"``, joined by "and"."""
    out = []
    for text in table.require:
        r = requirement(SimpleNamespace(crank=True, designs=()), text, label="limit")
        value = text.split(r.op, 1)[1].strip()
        out.append(f"{figure_words(r.figure)} {_OPS[r.op]} {value}")
    return " and ".join(out)


def cost_words(table: DesignTable) -> str:
    """What the design minimises in words: ``"counterweight B"``, ``"the flywheel's I_s"``."""
    return table.label if table.minimise == "value" else figure_words(table.minimise)


def _figures() -> dict:
    """The figures of merit a design has by itself (no study needed to name them), and their dimensions."""
    return figures(SimpleNamespace(crank=True, designs=()))


def dimension(values, fail) -> tuple[str, tuple]:
    """What a grid's values measure (the first of :data:`DIMENSIONS` they all read in) and the values in SI.

    ``fail(message)`` makes the error to raise (the exercise file's reader names the file and field).
    """
    for dim in DIMENSIONS:
        try:
            return dim, tuple(to_si(v, dim, field="design", file="design") for v in values)
        except ProblemFileError:
            continue
    raise fail(f"the values must be one of: {', '.join(d.replace('_', ' ') for d in DIMENSIONS)}; "
               f"got {values[0]!r}")


def read_design(t: dict, values: tuple, fail) -> DesignTable:
    """Read a ``[design]`` table whose grid ``values`` are already read (its field is checked by the caller).

    Parameters
    ----------
    t : dict
        The table.
    values : tuple of str
        Its grid (``from``/``to``/``step`` or ``values``).
    fail : callable
        ``fail(where, message)`` makes the error naming the file and the field ``design.<where>``.
    """
    dim, si = dimension(values, lambda m: fail("design", m))
    known = _figures()
    minimise = t.get("minimise", "value")
    if minimise != "value" and minimise not in known:
        raise fail("design.minimise", f"must be \"value\" (the field's own) or one of {', '.join(known)}, "
                                      f"got {minimise!r}")
    require = t.get("require", [])
    if not isinstance(require, list) or not require or not all(isinstance(r, str) for r in require):
        raise fail("design.require", "must be a non-empty list of limits such as [\"shaking_force_peak <= 1500 N\"]")
    for i, text in enumerate(require):
        try:
            requirement(SimpleNamespace(crank=True, designs=()), text, label="limit")
        except GraphkinError as exc:
            raise fail(f"design.require[{i}]", str(exc)) from None
    label = t.get("label", t["field"])
    if not isinstance(label, str) or not label.strip():
        raise fail("design.label", f"must be a non-empty string, got {label!r}")
    return DesignTable(t["field"], label.strip(), tuple(values), si, dim, minimise, tuple(r.strip() for r in require))


@dataclass(frozen=True)
class Chosen:
    """The designs of one student's data: the key and the keyed slips, each a value of the grid [SI] or None.

    Attributes
    ----------
    key : float or None
        The cheapest design that meets every limit; None if none does (the draw is not handed out).
    slips : dict of str to float or None
        Each of :data:`SLIPS`: the value a student who made it chooses.
    feasible : tuple of (float, float)
        The runs of neighbouring grid values that meet every limit, each (least, greatest) [SI].
    why : str or None
        Why there is no key.
    """

    key: float | None
    slips: dict
    feasible: tuple
    why: str | None = None


def choose(table: DesignTable, data: dict, *, n: int | None, Cs: float | None) -> Chosen:
    """The key of a design question for one student's problem data: a study over the grid, then the choice.

    Parameters
    ----------
    table : DesignTable
    data : dict
        The student's problem file's data (the base problem with their values).
    n : int or None
        Positions per cycle (the exercise's ``positions``).
    Cs : float or None
        Coefficient of speed fluctuation, where a limit or the cost is the flywheel's I_s.
    """
    s = study(data, {table.field: list(table.values)}, n=n, Cs=Cs if Cs is not None else 0.05)
    x = np.asarray(table.si, float)
    ok = np.array([d.ok for d in s.designs], bool)
    limits = [requirement(s, r, label="limit") for r in table.require]
    meets = ok.copy()
    for r in limits:
        meets &= r.met(s)
    cost = x if table.minimise == "value" else figure_values(s, table.minimise)

    def cheapest(mask) -> float | None:
        c = np.where(mask & np.isfinite(cost), cost, np.nan)
        return None if np.isnan(c).all() else float(x[int(np.nanargmin(c))])

    first = limits[0]
    limited = figure_values(s, first.figure)
    if first.op in (">", ">="):
        limited = -limited
    limited = np.where(ok & np.isfinite(limited), limited, np.nan)
    slips = {"unconstrained": cheapest(ok),
             "best_for_limit": None if np.isnan(limited).all() else float(x[int(np.nanargmin(limited))])}
    order = np.argsort(x, kind="stable")
    runs, start = [], None
    for k, i in enumerate(order):
        if meets[i] and start is None:
            start = x[i]
        if start is not None and (not meets[i] or k == len(order) - 1):
            runs.append((float(start), float(x[i] if meets[i] else x[order[k - 1]])))
            start = None
    key = cheapest(meets)
    why = None if key is not None else f"no {table.label} of the grid meets {limit_words(table)}"
    return Chosen(key, slips, tuple(runs), why)


def slack(table: DesignTable, tolerance: float, value: float) -> float:
    """What the grader allows either side of a design's key [SI]: one step of the grid (the key is known to the
    grid's step, see the module), or the question's tolerance of the key if that is larger."""
    return max(table.step, tolerance * abs(value))


def design_words(table: DesignTable, chosen: Chosen) -> dict:
    """The words of a design question's messages: the limits, what is minimised, and the runs of the grid that
    meet the limits (as text, for :func:`design_part`; keys carry them as they carry every word)."""
    return {"limit": limit_words(table), "cost": cost_words(table),
            "feasible": ";".join(f"{lo!r}:{hi!r}" for lo, hi in chosen.feasible)}


def design_part(exp, a: float, words: dict, step: float) -> str:
    """Which part of a wrong design is wrong: it does not meet the limits, or it meets them at a greater cost.

    ``step`` is the grid's step [SI]: a design within half a step of a run that meets the limits meets them (the
    grid is all the study knows between its values)."""
    runs = [tuple(map(float, r.split(":"))) for r in words.get("feasible", "").split(";") if r]
    meets = any(lo - step / 2 <= a <= hi + step / 2 for lo, hi in runs)
    if not meets:
        return f"that design does not meet {words['limit']}"
    return f"that design meets {words['limit']}, but it is not the one of least {words['cost']} that does"


def hint(table: DesignTable) -> str:
    """Where a design's answer comes from, for the grader's "revisit"."""
    return (f"a study of every {table.label} of the grid, each design solved over the cycle, then the one with "
            f"the least {cost_words(table)} among those that meet {limit_words(table)}")


def grid_text(table: DesignTable) -> str:
    """The grid's step as a sheet states the tolerance: ``"one step of the grid (0.01 kg)"``."""
    unit = DIMENSIONS[table.dimension]
    step = table.step / to_si(f"1 {unit}", table.dimension, field="design", file="design")
    return f"one step of the grid ({step:.4g} {unit})" if math.isfinite(step) else "one step of the grid"
