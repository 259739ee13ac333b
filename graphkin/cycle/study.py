"""A design study: one problem solved over its cycle for every combination of some of its fields' values.

A designer's choice (the crank's length, the coupler's mass, a counterweight) is judged by what it costs over
the whole cycle: the peak and RMS driving torque, the flywheel it needs, the peak force at each joint, the
shaking force and moment on the frame, the smallest transmission angle (Norton, *Design of Machinery*, ch. 11).
:func:`study` varies fields of a problem file, named by their paths as exercises name them
(:mod:`graphkin.problem.fields`: ``"links[0].points.A"``, ``"links[1].mass"``), over the grid of every
combination of their values, and reads those figures of merit off each design's :class:`~graphkin.cycle.Cycle`.

Each design is the problem file with the values put in, built by :func:`graphkin.problem.build_problem`, so it
keeps the branch its file states (``[assembly]``); a design that cannot be assembled at some position of its
cycle is marked with the first such position and the reason, and its figures of merit are nan (a peak over part
of a cycle would look better than the design is).

The designs are solved one after another, each a sweep vectorised over its positions. A broadcast over designs
(designs × positions as one batch) needs every per-mechanism constant as an array, one value per
design-position: :func:`graphkin.kinematics.plan.plan_of` works out each point as a complex number and each bar's
length once per mechanism, and the compiled steps of :mod:`graphkin.kinematics.solver` (``_crank_step``,
``_rrr_step``) close over them as Python scalars (``abs(dj)``, ``if p == 0``); the force analysis's compiled groups
(``_crank``, ``_rrr`` in :mod:`graphkin.analytical.kinetostatics`) take G, m and I_G the same way, and the loads
(:mod:`graphkin.analytical.loads`) and ``Kinematics.position`` read points from the mechanism's links. Until
those take arrays, :attr:`Study.vectorised` is False and :attr:`Study.why_not_vectorised` says so.
"""

from __future__ import annotations

import itertools
import math
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Mapping

import numpy as np

from graphkin import catalog
from graphkin.cycle.flywheel import check_Cs
from graphkin.cycle.sweep import Cycle, sweep
from graphkin.errors import GraphkinError, ProblemFileError
from graphkin.files import read_text
from graphkin.notation import position_text
from graphkin.problem import build_problem
from graphkin.problem.fields import missing, set_field

__all__ = ["MAX_DESIGNS", "Design", "Study", "VaryError", "merit", "study"]

MAX_DESIGNS = 100_000
"""The most designs one study solves (the product of the numbers of values of its fields)."""

NOT_VECTORISED = ("the designs are solved one after another (each over its positions at once): the compiled "
                  "kinematic and force steps take each mechanism's points, lengths, masses and I_G as scalars")
"""Why :attr:`Study.vectorised` is False (the module's docstring says what a broadcast over designs needs)."""


class VaryError(GraphkinError):
    """A field a study varies, or one of its values, is at fault; ``field`` names it as the study was given it."""

    def __init__(self, field: str, message: str):
        self.field = field
        super().__init__(f"vary {field}: {message}")


@dataclass(frozen=True)
class Design:
    """One design of a study and its figures of merit over the cycle (SI units; nan where not defined).

    Attributes
    ----------
    values : tuple
        The value of each varied field, in the order of :attr:`Study.fields`, as given (problem-file values).
    torque_peak : float
        Largest |T1j| over the cycle [N·m] (a slider driver: |F1j| [N]).
    torque_rms : float
        Root mean square of the driving effort, √(mean T²) by the cycle's trapezoidal rule
        (:meth:`Cycle.mean`) [N·m] (or [N]).
    joint_peaks : dict of str to float
        Largest |F| at each joint over the cycle [N], by the force's name (``"F12"``, ``"F23"``, ...).
    I_s : float
        The flywheel's system inertia for the study's C_s [kg·m²] (:meth:`Cycle.flywheel`); nan where none can
        be sized, and :attr:`no_flywheel` says why.
    shaking_force_peak : float
        Largest |Σ F_j1| on the frame [N] (:meth:`Cycle.shaking_force`).
    shaking_moment_peak : float
        Largest |M| of the mechanism on the frame about the origin [N·m] (:meth:`Cycle.shaking_moment`).
    transmission_angle_min : float
        Smallest transmission angle μ over the cycle [rad] (folded to [0, π/2]); nan for a linkage that is not
        a crank-driven four-bar of revolutes.
    failure : str or None
        Where and why the design cannot be assembled over the whole cycle (its first such position); None if it
        can.
    failed_at : float
        That position, θ [rad] or s [m]; nan if the design assembles everywhere.
    no_flywheel : str or None
        Why no flywheel can be sized (:meth:`Cycle.why_no_flywheel`); None if one can.
    """

    values: tuple
    torque_peak: float
    torque_rms: float
    joint_peaks: Mapping[str, float]
    I_s: float
    shaking_force_peak: float
    shaking_moment_peak: float
    transmission_angle_min: float
    failure: str | None = None
    failed_at: float = math.nan
    no_flywheel: str | None = None

    @property
    def ok(self) -> bool:
        """True if the design assembles at every position of its cycle."""
        return self.failure is None


@dataclass(frozen=True)
class Study:
    """The designs of a study, as plain data.

    Attributes
    ----------
    problem : str
        The problem's name (catalog name or file path).
    fields : tuple of str
        The varied fields' paths.
    grid : tuple of tuple
        Each field's values; the designs are every combination, the last field varying fastest.
    designs : tuple of Design
        One per combination, in that order.
    n : int or None
        Equally spaced crank angles per design (None: the problem's own positions).
    Cs : float
        The coefficient of speed fluctuation the flywheels are sized for.
    vectorised : bool
        True if the designs were solved as one batch over designs and positions.
    why_not_vectorised : str or None
        Why not, when they were not.
    crank : bool
        True if the driver is a crank (the effort is a torque [N·m]); False for a slider (a force [N]).
    """

    problem: str
    fields: tuple
    grid: tuple
    designs: tuple
    n: int | None
    Cs: float
    vectorised: bool
    why_not_vectorised: str | None
    crank: bool = True

    @property
    def shape(self) -> tuple:
        """The grid's shape: the number of values of each field."""
        return tuple(len(v) for v in self.grid)


def _problem_data(problem) -> tuple[dict, str, Path | None]:
    """A problem file's data, the name messages show and the file's path, from a catalog name, a path or data."""
    if isinstance(problem, Mapping):
        return dict(problem), "<problem>", None
    if not isinstance(problem, (str, Path)):
        raise GraphkinError(f"study takes a catalog name ({', '.join(catalog.names())}), a problem file's path or "
                            f"its data (a dict), got {type(problem).__name__} {problem!r:.60}")
    name = str(problem)
    path = catalog.path(name) if name in catalog.names() else Path(name)
    if name not in catalog.names() and not path.is_file():
        raise GraphkinError(f"{name!r} is neither a catalog problem ({', '.join(catalog.names())}) nor a file")
    try:
        return tomllib.loads(read_text(path, "problem", shown=name)), name, path
    except tomllib.TOMLDecodeError as exc:
        raise GraphkinError(f"{name}: is not valid TOML ({exc})") from None


def _grid(data: dict, vary) -> tuple[tuple, tuple]:
    """The varied fields and their values, each field checked against the problem's data."""
    if not isinstance(vary, Mapping) or not vary:
        raise GraphkinError("study: vary must be a dict of at least one field path to its values, e.g. "
                            '{"links[0].points.A": [["80 mm", "0 mm"], ["90 mm", "0 mm"]]}')
    fields, grid = [], []
    for field, values in vary.items():
        try:
            gap = missing(data, field) if isinstance(field, str) else "?"
        except KeyError:
            raise VaryError(str(field), "is not a field path (tables and keys joined by dots, list items by "
                                        "[index], e.g. links[1].mass)") from None
        if gap is not None:
            raise VaryError(str(field), f"the problem has no {gap}")
        if isinstance(values, (str, bytes)) or not hasattr(values, "__len__") or not len(values):
            raise VaryError(field, f"give a list of one or more values, got {values!r:.60}")
        fields.append(field)
        grid.append(tuple(values))
    count = math.prod(len(v) for v in grid)
    if count > MAX_DESIGNS:
        raise GraphkinError(f"study: {count:,} designs is more than {MAX_DESIGNS:,}; take fewer values")
    return tuple(fields), tuple(grid)


def _design_problem(data: dict, fields: tuple, values: tuple, file: str, base):
    """The problem of one design: the file's data with each field's value put in (the data is not changed)."""
    trial = dict(data)
    for field, value in zip(fields, values):
        set_field(trial, field, value, copy=True)
    shown = ", ".join(f"{f}={v}" for f, v in zip(fields, values))
    return build_problem(trial, file=f"{file} ({shown})", base=base)


def _unbuilt(values: tuple, why: str) -> Design:
    """A design whose values, together, make no mechanism (each alone does): marked, its figures nan."""
    nan = math.nan
    return Design(values, nan, nan, {}, nan, nan, nan, nan, why, nan, "the design cannot be built")


def merit(cycle: Cycle, values: tuple, Cs: float) -> Design:
    """The figures of merit of one design's cycle (see :class:`Design`).

    Parameters
    ----------
    cycle : Cycle
        The design swept over its cycle.
    values : tuple
        The design's values of the varied fields.
    Cs : float
        Coefficient of speed fluctuation for the flywheel.
    """
    names = [cycle.analysis.name_of(i, j) for (i, j) in cycle.analysis.forces]
    bad = np.flatnonzero(~cycle.valid)
    if len(bad):
        i = int(bad[0])
        crank = cycle.problem.mechanism.driver.crank
        failure = (f"no solution at {len(bad)} of the {cycle.n} positions, the first at "
                   f"{position_text(cycle.q[i], crank)}: {cycle.analysis.reason(i)}")
        nan = math.nan
        return Design(values, nan, nan, dict.fromkeys(names, nan), nan, nan, nan, nan, failure, float(cycle.q[i]),
                      "the design cannot be assembled over the whole cycle")
    T = cycle.torque
    peaks = cycle.peaks().forces
    why = cycle.why_no_flywheel()
    try:
        mu = float(np.min(cycle.transmission_angle()))
    except GraphkinError:  # not a crank-driven four-bar: μ is not defined (the joint-force index is)
        mu = math.nan
    return Design(
        values=values,
        torque_peak=float(np.max(np.abs(T))),
        torque_rms=math.sqrt(cycle.mean(T * T)),
        joint_peaks={name: peaks[name].value for name in names},
        I_s=math.nan if why else cycle.flywheel(Cs).I_s,
        shaking_force_peak=float(np.max(np.hypot(*cycle.shaking_force().T))),
        shaking_moment_peak=float(np.max(np.abs(cycle.shaking_moment()))),
        transmission_angle_min=mu,
        no_flywheel=why,
    )


def study(problem, vary: Mapping[str, Any], *, n: int | None = None, Cs: float = 0.05) -> Study:
    """Solve a problem over its cycle for every combination of the values of some of its fields.

    Parameters
    ----------
    problem : str, Path or dict
        A catalog name, a problem file, or a problem file's data as ``tomllib`` reads it.
    vary : dict of str to list
        Each field's path (:mod:`graphkin.problem.fields`; ``links[0]`` is the file's first ``[[links]]``) and
        its values as the problem file writes them, with units: ``{"links[0].mass": ["2 kg", "3 kg"],
        "links[0].points.A": [["80 mm", "0 mm"], ["90 mm", "0 mm"]]}``.
    n : int, optional
        Equally spaced crank angles per design (:func:`graphkin.cycle.sweep`); default the file's positions.
    Cs : float, optional
        Coefficient of speed fluctuation the flywheel of each design is sized for.

    Returns
    -------
    Study
        Every design's values and its figures of merit, in the order of the grid (the last field fastest).

    Raises
    ------
    VaryError
        A varied field the problem does not have, or a value it rejects (naming the field).
    GraphkinError
        Any other input at fault.

    Examples
    --------
    >>> s = study("strip_cutter", {"links[1].mass": ["2 kg", "4 kg"]}, n=90)
    >>> [round(d.torque_peak, 1) for d in s.designs]
    [324.6, 392.6]
    """
    Cs = check_Cs(Cs)
    data, file, base = _problem_data(problem)
    fields, grid = _grid(data, vary)
    for field, values in zip(fields, grid):  # each field's values alone in the file: a fault named by its field
        for value in values:
            try:
                _design_problem(data, (field,), (value,), file, base)
            except ProblemFileError as exc:  # the file's words for the fault, less the design's name
                raise VaryError(field, f"{value!r}: " + (exc.message if exc.field == field else str(exc))) from None
            except GraphkinError as exc:
                raise VaryError(field, f"{value!r}: {exc}") from None
    designs, crank = [], build_problem(data, file=file, base=base).mechanism.driver.crank
    for values in itertools.product(*grid):
        try:
            p = _design_problem(data, fields, values, file, base)
        except GraphkinError as exc:  # each value builds alone: together these do not
            designs.append(_unbuilt(values, str(exc)))
            continue
        designs.append(merit(sweep(p, n), values, Cs))
    return Study(file, fields, grid, tuple(designs), n, Cs, False, NOT_VECTORISED, crank)
