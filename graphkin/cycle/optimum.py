"""The optimum between a study's grid values: ``scipy.optimize`` over the designs, started from the grid's best.

A grid says which region is good; the designer then asks for the best design in it to the last millimetre: the
least peak torque, say, with a transmission angle of at least 40° (Norton, *Design of Machinery*, §4.10 and
ch. 11). :func:`optimum` finds it with ``scipy.optimize.minimize`` (SLSQP: bounds and inequality limits), each
varied field bounded by its grid's smallest and largest value and scaled to [0, 1], starting from the grid's best
design under the same limits. Each evaluation solves, as one batch over designs and positions
(:func:`graphkin.cycle.studies.solve_grid`), the design and its neighbours a small step along each field: the
objective's and the limits' values and their gradients (central differences) come from one batch. A design that
cannot be assembled over its cycle counts as far worse than any that can (and as breaking every limit).

The figures of merit are maxima over the sampled positions, so they are smooth only piecewise: scipy may stop at a
kink without saying it converged, and :attr:`Optimum.converged` and :attr:`Optimum.message` pass on what it said.
The optimum is never worse than the grid's best: if scipy's last design is, or breaks a limit, the grid's best is
kept and the message says so. scipy is an optional extra (``pip install 'graphkin[study]'``).
"""

from __future__ import annotations

import dataclasses
import re
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.cycle.choice import Requirement, field_axis, figure_values, figures, requirement
from graphkin.cycle.merit import Design
from graphkin.errors import GraphkinError
from graphkin.optional import require as require_module

__all__ = ["Optimum", "objective_of", "optimum"]

STEP = 1e-6
"""The step of the central differences, in a field's range scaled to [0, 1]."""

FAILED = 1e6
"""The scaled objective of a design that cannot be assembled over its cycle (the grid's best is 1 in magnitude)."""

_OBJECTIVE = re.compile(r"\s*(?:(?P<sense>minimi[sz]e|maximi[sz]e)\s+)?(?P<name>[A-Za-z_]\w*)\s*")


@dataclass(frozen=True)
class Optimum:
    """The design that scipy found best between a study's grid values, and what scipy said.

    Attributes
    ----------
    objective : str
        The figure of merit optimised (:func:`graphkin.cycle.choice.figures`).
    sense : str
        ``"minimise"`` or ``"maximise"``.
    require : tuple of Requirement
        The limits it meets.
    fields : tuple of str
        The study's varied fields.
    x : tuple of float
        The optimum's value of each field, a number in the unit its grid is written in (``units``).
    units : tuple of str
        That unit of each field (``"mm"``; ``""`` for a plain number).
    values : tuple
        The same values as the problem file writes them (``"93.25 mm"``): :meth:`Study.design` takes them.
    design : Design
        Its figures of merit (SI).
    start : int
        The grid's best design under the limits, where scipy started (its index in :attr:`Study.designs`).
    converged : bool
        Whether scipy said it converged.
    message : str
        scipy's message (and, if the grid's best was kept, why).
    method : str
        scipy's method.
    iterations : int
        scipy's iterations.
    evaluations : int
        Designs solved, neighbours for the gradients included.
    """

    objective: str
    sense: str
    require: tuple
    fields: tuple
    x: tuple
    units: tuple
    values: tuple
    design: Design
    start: int
    converged: bool
    message: str
    method: str
    iterations: int
    evaluations: int
    study: Any = dataclasses.field(default=None, repr=False, compare=False)

    @property
    def value(self) -> float:
        """The objective's value at the optimum, SI."""
        return float(figure_values(dataclasses.replace(self.study, designs=(self.design,)), self.objective)[0])

    @property
    def problem(self):
        """The optimum as an ordinary :class:`~graphkin.problem.Problem` (:meth:`Study.design`)."""
        return self.study.design(self.values)

    @property
    def data(self) -> dict:
        """The optimum's problem file data (:meth:`Study.design_data`)."""
        return self.study.design_data(self.values)


def objective_of(study, text: str, label: str = "optimize") -> tuple[str, str]:
    """``"minimise FIGURE"``, ``"maximise FIGURE"`` or ``"FIGURE"`` (minimised) as (figure, sense).

    Raises
    ------
    GraphkinError
        Naming ``label`` if the text is not of that form or names no figure of the study.
    """
    m = _OBJECTIVE.fullmatch(text) if isinstance(text, str) else None
    if m is None:
        raise GraphkinError(f"{label} {text!r}: write it \"minimise FIGURE\" or \"maximise FIGURE\", e.g. "
                            "\"minimise torque_peak\"")
    if m["name"] not in figures(study):
        raise GraphkinError(f"{label} {text!r}: no such figure of merit; the study has {', '.join(figures(study))}")
    return m["name"], "maximise" if (m["sense"] or "").startswith("maxim") else "minimise"


def _value(x: float, unit: str):
    return f"{x!r} {unit}" if unit else x


def optimum(study, objective: str, require=(), *, maxiter: int = 100, tol: float = 1e-9,
            label: str = "optimize") -> Optimum:
    """The design between the grid's values with the least (or greatest) figure of merit that meets the limits.

    Parameters
    ----------
    study : Study
        A study whose varied fields are numbers of one unit each (a coordinate ``links[0].points.A[0]``, not a
        point); a field of one value stays at it.
    objective : str
        ``"minimise FIGURE"``, ``"maximise FIGURE"`` or ``"FIGURE"`` (minimised), e.g. ``"torque_peak"``.
    require : iterable of str or Requirement
        Limits ``"FIGURE OP VALUE UNIT"`` (:func:`graphkin.cycle.choice.requirement`).
    maxiter : int, optional
        scipy's iterations at most.
    tol : float, optional
        scipy's ``ftol`` on the objective scaled by its value at the start.
    label : str, optional
        What messages call the objective (``--optimize`` on the command line).

    Returns
    -------
    Optimum

    Raises
    ------
    GraphkinError
        scipy is not installed (naming the extra), the objective or a limit is at fault, a field is not a number
        of one unit, or no design of the grid meets the limits (there is nowhere to start).

    Examples
    --------
    >>> from graphkin.cycle import study
    >>> s = study("strip_cutter", {"links[1].mass": ["1 kg", "2 kg", "3 kg", "4 kg"]}, n=72)
    >>> o = optimum(s, "minimise torque_peak")   # doctest: +SKIP
    >>> o.design.torque_peak <= min(d.torque_peak for d in s.designs)   # doctest: +SKIP
    True
    """
    name, sense = objective_of(study, objective, label)
    limits = tuple(r if isinstance(r, Requirement) else requirement(study, r) for r in require)
    axes = [field_axis(values) for values in study.grid]
    for f, values, axis in zip(study.fields, study.grid, axes):
        if axis is None:
            raise GraphkinError(f"{label}: {f}'s values are not numbers of one unit ({values[0]!r}, ...); scipy "
                                "varies numbers: vary one coordinate of a point, e.g. links[0].points.A[0]")
    units = tuple(a[0] for a in axes)
    lo = np.array([a[1].min() for a in axes])
    hi = np.array([a[1].max() for a in axes])
    free = np.flatnonzero(hi > lo)
    if not len(free):
        raise GraphkinError(f"{label}: every varied field has a single value; give a range to optimise over")
    sign = -1.0 if sense == "maximise" else 1.0
    ok = np.array([d.ok for d in study.designs], bool)
    for r in limits:
        ok &= r.met(study)
    score = np.where(ok, sign * figure_values(study, name), np.nan)
    if np.isnan(score).all():
        meets = f" meets {' and '.join(r.text for r in limits)} and" if limits else ""
        raise GraphkinError(f"{label} {objective!r}: no design of the grid that assembles over its cycle{meets} has "
                            f"a {name}: there is nowhere to start")
    start = int(np.nanargmin(score))
    x0 = np.array([a[1][list(study.grid[k]).index(study.designs[start].values[k])] for k, a in enumerate(axes)])
    optimize = require_module("scipy.optimize", "a study's optimum (scipy.optimize)")

    span = hi[free] - lo[free]
    scale = abs(score[start]) or 1.0
    bounds_of = [abs(r.bound) or 1.0 for r in limits]
    cache: dict[bytes, tuple] = {}
    solved = [0]

    def x_of(u):
        x = x0.copy()
        x[free] = lo[free] + np.clip(u, 0.0, 1.0) * span
        return x

    def solve(xs: list) -> list:
        """The designs at the points ``xs`` (each a value of every field), as one batch."""
        designs = study.solve_values([tuple(_value(float(v), units[k]) for k, v in enumerate(x)) for x in xs])
        solved[0] += len(designs)
        return list(designs)

    def scores(designs: list) -> tuple[np.ndarray, np.ndarray]:
        """The scaled objective and limits (≥ 0 where met) of each design; a design that fails: far worse."""
        sub = dataclasses.replace(study, designs=tuple(designs))
        f = sign * figure_values(sub, name) / scale
        g = np.array([(figure_values(sub, r.figure) - r.bound) * (1.0 if r.op in (">=", ">") else -1.0) / b
                      for r, b in zip(limits, bounds_of)]).reshape(len(limits), len(designs))
        bad = ~np.array([d.ok for d in designs]) | ~np.isfinite(f)
        return np.where(bad, FAILED, f), np.where(bad | ~np.isfinite(g), -FAILED, g)

    def evaluate(u):
        u = np.clip(np.asarray(u, float), 0.0, 1.0)
        key = u.tobytes()
        if key not in cache:
            ups, downs = np.minimum(u + STEP, 1.0), np.maximum(u - STEP, 0.0)
            points = [u]
            for i in range(len(u)):
                for end in (ups[i], downs[i]):
                    v = u.copy()
                    v[i] = end
                    points.append(v)
            designs = solve([x_of(v) for v in points])
            f, g = scores(designs)
            width = ups - downs
            df = (f[1::2] - f[2::2]) / width
            dg = (g[:, 1::2] - g[:, 2::2]) / width
            failed = f[0] >= FAILED
            cache[key] = (f[0], np.where(failed, 0.0, df), g[:, 0], np.where(failed, 0.0, dg), designs[0])
        return cache[key]

    u0 = (x0[free] - lo[free]) / span
    constraints = [{"type": "ineq", "fun": (lambda u, k=k: evaluate(u)[2][k]),
                    "jac": (lambda u, k=k: evaluate(u)[3][k][None, :])} for k in range(len(limits))]
    res = optimize.minimize(lambda u: evaluate(u)[0], u0, jac=lambda u: evaluate(u)[1], method="SLSQP",
                            bounds=[(0.0, 1.0)] * len(free), constraints=constraints,
                            options={"maxiter": maxiter, "ftol": tol})
    f, _, g, _, design = evaluate(res.x)
    x = x_of(np.clip(res.x, 0.0, 1.0))
    message = str(res.message)
    if not (f < FAILED and (g >= -1e-9).all() and f <= score[start] / scale):
        x, design = x0, study.designs[start]
        message += "; scipy's last design was no better than the grid's best (or broke a limit): the grid's best is kept"
    values = tuple(_value(float(v), u) if k in free else study.designs[start].values[k]
                   for k, (v, u) in enumerate(zip(x, units)))
    design = dataclasses.replace(design, values=values)
    return Optimum(name, sense, limits, tuple(study.fields), tuple(float(v) for v in x), units, values, design, start,
                   bool(res.success), message, "SLSQP", int(getattr(res, "nit", 0)), solved[0], study)
