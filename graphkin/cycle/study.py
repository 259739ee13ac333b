"""A design study: one problem solved over its cycle for every combination of some of its fields' values.

A designer's choice (the crank's length, the coupler's mass, a counterweight) is judged by what it costs over
the whole cycle: the peak and RMS driving torque, the flywheel it needs, the peak force at each joint, the
shaking force and moment on the frame, the smallest transmission angle (Norton, *Design of Machinery*, ch. 11).
:func:`study` varies fields of a problem file, named by their paths as exercises name them
(:mod:`graphkin.problem.fields`: ``"links[0].points.A"``, ``"links[1].mass"``), over the grid of every
combination of their values, and reads those figures of merit off each design's cycle.

Each design is the problem file with the values put in, as :func:`graphkin.problem.build_problem` reads it, so it
keeps the branch its file states (``[assembly]``); a design that cannot be assembled at some position of its
cycle is marked with the first such position and the reason, and its figures of merit are nan (a peak over part
of a cycle would look better than the design is). The file is read once with each field's value alone: where
each field changes a part of the linkage no other field changes (a link's points, a link's mass, I_G and G, a
load, the speed: :func:`_changes`), a design's numbers are the file's with each field's changes put in, and no
file is read per design; else each design is read from its own file.

The designs are solved together, designs × positions as one batch (:func:`graphkin.analytical.designs.solve_designs`):
designs that differ only in numbers the plan of the linkage holds -- a point's place on its link, a mass, I_G,
G, a load's value or a counterweight's, the speed -- are laid end to end, each such number an array with the
design's value at each of its positions, and the kinematic and force steps run once over them all, BATCH
design-positions at a time; the figures of merit are read off the (designs, positions) arrays at once. Each design's
numbers are those of a sweep of it alone, to rounding (:mod:`graphkin.analytical.designs`). A design that cannot
share a batch -- a gear train, a load that varies over the cycle (a table, a spring), values given at one
position -- is swept on its own, and :attr:`Study.why_not_vectorised` says how many and why.
"""

from __future__ import annotations

import itertools
import math
import tomllib
from dataclasses import dataclass
from pathlib import Path
from types import SimpleNamespace
from typing import Any, Mapping

import numpy as np

from graphkin import catalog
from graphkin.analytical.designs import Batch, batch_key, numbers, solve_designs
from graphkin.cycle._sampling import sweep_positions
from graphkin.cycle.choice import best
from graphkin.cycle.flywheel import check_Cs
from graphkin.cycle.sweep import Cycle, sweep
from graphkin.cycle.turn import TURN, closing_step, steps, weights
from graphkin.errors import GraphkinError, ProblemFileError
from graphkin.files import read_text
from graphkin.geometry import zcross
from graphkin.kinematics.solver import CHUNK
from graphkin.model import Prismatic, Revolute
from graphkin.model.names import force_name
from graphkin.notation import position_text
from graphkin.problem import build_problem
from graphkin.problem.fields import missing, set_field

__all__ = ["MAX_DESIGNS", "Design", "Study", "VaryError", "merit", "study"]

MAX_DESIGNS = 100_000
"""The most designs one study solves (the product of the numbers of values of its fields)."""

BATCH = CHUNK
"""Design-positions solved together: as many whole designs as fit (at least one). Their arrays (about 40 MB, 1.3 kB a
design-position) are freed before the next batch, so a study's memory does not grow with its designs beyond their
figures of merit; a batch's Python (its plan's steps compiled for its designs' numbers, the figures' set-up) is
paid once per 90 designs of 360 positions, not 22."""


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
        True if every design was solved in a batch over designs and positions (see the module).
    why_not_vectorised : str or None
        How many designs were swept one by one, and why; None when none was.
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

    def best(self, minimise: str, require=()):
        """The design with the least ``minimise`` among those that meet ``require``
        (:func:`graphkin.cycle.choice.best`): ``s.best("torque_peak", ["transmission_angle_min >= 40 deg"])``."""
        return best(self, minimise, require)


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


def _failed(values: tuple, names: list, count: int, q: np.ndarray, i: int, crank: bool, reason: str) -> Design:
    """A design that has no solution at ``count`` of the positions ``q``, the first ``q[i]``, for ``reason``."""
    nan = math.nan
    return Design(values, nan, nan, dict.fromkeys(names, nan), nan, nan, nan, nan,
                  f"no solution at {count} of the {len(q)} positions, the first at {position_text(q[i], crank)}: "
                  f"{reason}", float(q[i]), "the design cannot be assembled over the whole cycle")


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
        return _failed(values, names, len(bad), cycle.q, i, cycle.problem.mechanism.driver.crank,
                       cycle.analysis.reason(i))
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
    singles = [[_single(data, field, value, file, base) for value in values] for field, values in zip(fields, grid)]
    first = build_problem(data, file=file, base=base)
    positions: dict = {}
    changes = _changes(first, singles, n, positions)
    designs, batches, alone = {}, {}, {}
    for index, at in enumerate(itertools.product(*(range(len(v)) for v in grid))):
        values = tuple(v[i] for v, i in zip(grid, at))
        if changes is not None:  # the file's numbers with each field's own put in (see _changes)
            own = dict(changes[0])
            for field, i in enumerate(at):
                own.update(changes[1][field][i])
            shape, (key, q), member = first, changes[2], (own, *own.pop(RATES))
        else:
            try:
                shape = _design_problem(data, fields, values, file, base)
            except GraphkinError as exc:  # each value builds alone: together these do not
                designs[index] = _unbuilt(values, str(exc))
                continue
            key, q = _batch_key(shape, n, positions)
            if q is None:
                alone[index] = (values, shape, key)
                continue
            member = (numbers(shape.mechanism), shape.q_dot[0], shape.q_ddot[0])
        shape, q, members = batches.setdefault(key, (shape, q, []))
        members.append((index, values, *member))
        if len(members) * len(q) >= BATCH:  # solved as soon as it is full: a study holds one batch at a time
            designs.update(_merits(shape, members, q, Cs))
            members.clear()
    for shape, q, members in batches.values():
        if members:
            designs.update(_merits(shape, members, q, Cs))
    for index, (values, p, _) in alone.items():
        designs[index] = merit(sweep(p, n), values, Cs)
    why = None
    if alone:
        reasons = sorted({key for _, _, key in alone.values()})
        why = (f"{len(alone)} of the {len(designs)} designs were swept one after another, not in a batch over "
               f"designs: {'; '.join(reasons)}")
    crank = first.mechanism.driver.crank
    return Study(file, fields, grid, tuple(designs[i] for i in range(len(designs))), n, Cs, not alone, why, crank)


def _single(data: dict, field: str, value, file: str, base):
    """The problem with one field's value put in; a fault is named by the field."""
    try:
        return _design_problem(data, (field,), (value,), file, base)
    except ProblemFileError as exc:  # the file's words for the fault, less the design's name
        raise VaryError(field, f"{value!r}: " + (exc.message if exc.field == field else str(exc))) from None
    except GraphkinError as exc:
        raise VaryError(field, f"{value!r}: {exc}") from None


RATES = ("rates",)
"""The key of a design's input speed and acceleration among its numbers (:func:`_changes`)."""


def _part(key: tuple) -> tuple:
    """The part of a linkage a number belongs to, as the model checks it: a link's points (its pins' distances), a
    link's body (mass, I_G, G), a load, the input's rates."""
    return ("link", key[1]) if key[0] == "point" else ("body", key[1]) if key[0] in ("mass", "I_G", "G") else key


def _changes(first, singles: list, n: int | None, positions: dict):
    """How each field's values change the file's numbers, if the designs need not be read from the file one by one.

    They need not when each value alone gives a linkage of the file's batch (:func:`_batch_key`: the same links,
    joints, loads, branch and positions) and no two fields change the same part (:func:`_part`): then a design is
    the file's numbers with each field's changes put in, the numbers its own file would give, and it builds as
    each of its values alone builds (the model's checks of numbers are of one part at a time: a link's pins). Two
    fields that change one part (a mass and the radius of gyration of one link, two points of one link) are read
    design by design.

    Returns
    -------
    tuple or None
        The file's numbers (:func:`graphkin.analytical.designs.numbers`, the rates under :data:`RATES`); for each
        field and value, the numbers of the parts the field changes; and the file's batch key and positions.
        None if the designs are to be read one by one.
    """
    key, q = _batch_key(first, n, positions)
    if q is None:
        return None
    own = numbers(first.mechanism) | {RATES: (first.q_dot[0], first.q_ddot[0])}
    out, taken = [], set()
    for problems in singles:
        theirs = []
        for p in problems:
            if _batch_key(p, n, positions)[0] != key:
                return None
            theirs.append(numbers(p.mechanism) | {RATES: (p.q_dot[0], p.q_ddot[0])})
        parts = {_part(x) for x in own for mine in theirs if mine[x] != own[x]}
        if parts & taken:
            return None
        taken |= parts
        out.append([{x: mine[x] for x in own if _part(x) in parts} for mine in theirs])
    return own, out, (key, q)


def _batch_key(p, n: int | None, positions: dict) -> tuple:
    """What a design shares with the designs it can be solved with, and its positions; or why it is swept alone
    and None. ``positions`` keeps the positions found for each key: a batch's loads switch at the same angles."""
    driver = p.mechanism.joint_between(p.mechanism.frame, p.mechanism.driver.link)
    if not p.mechanism.driver.crank and driver.guide != p.mechanism.frame:
        return "the driver slides on a guide of its own, not the frame's", None
    if p.given:
        return "the problem gives kinematic values ([given]) that hold at one position", None
    if p.unknown is not None:
        return "the effort is asked of a link other than the driver", None
    key, why = batch_key(p.mechanism)
    if key is None:
        return f"the linkage has {why}", None
    # With n, the positions follow from the key (the driver, the loads' windows); else from the file's own too.
    at = (key, n) if n is not None else (key, p.q.tobytes(), len(set(p.q_dot)) == 1 and len(set(p.q_ddot)) == 1)
    if at not in positions:
        positions[at] = sweep_positions(p, n)
    q = positions[at]
    if q is None:
        return "the input rates vary with position", None
    return (key, q.tobytes(), p.static), q


def _means(q: np.ndarray, f: np.ndarray) -> np.ndarray:
    """:meth:`Cycle.mean` of each row of ``f`` (designs, positions), by the same rule."""
    gap = closing_step(q)
    if gap is not None:
        return np.sum(weights(q, gap) * f, axis=1) / TURN
    if len(q) < 2 or q[-1] == q[0]:
        return f[:, 0] if len(q) == 1 else np.full(len(f), math.nan)
    return np.sum(0.5 * (f[:, 1:] + f[:, :-1]) * np.diff(q), axis=1) / (q[-1] - q[0])


def _four_bar(mech) -> tuple | None:
    """The pins (link, point) of a crank-driven four-bar's transmission angle: A and B on the coupler, B0 on the
    frame (:meth:`Cycle.transmission_angle`); None for another linkage."""
    if not (len(mech.links) == 4 and len(mech.joints) == 4 and mech.driver.crank
            and all(isinstance(j, Revolute) for j in mech.joints)):
        return None
    crank = mech.driver.link
    coupler = [j for j in mech.moving if j != crank and any(set(J.links) == {crank, j} for J in mech.joints)]
    if len(coupler) != 1:
        return None
    (coupler,) = coupler
    (rocker,) = [j for j in mech.moving if j not in (crank, coupler)]
    return ((coupler, mech.joint_between(crank, coupler).point), (coupler, mech.joint_between(coupler, rocker).point),
            (mech.frame, mech.joint_between(mech.frame, rocker).point))


def _frame_pins(mech, forces) -> list:
    """Each joint with the frame, in the order of ``forces`` (pairs of links): (joint, moving link, the point its
    force acts at)."""
    out = []
    for i, j in forces:
        if mech.frame in (i, j):
            joint = mech.joint_between(i, j)
            at = (joint.slider, joint.point) if isinstance(joint, Prismatic) else (mech.frame, joint.point)
            out.append((joint, j if i == mech.frame else i, at))
    return out


def _shaking(b: Batch, mech, pins) -> tuple[np.ndarray, np.ndarray]:
    """The shaking force (complex) and moment of each design at each position, as :class:`Cycle` sums them."""
    S = np.zeros(b.effort.shape, complex)
    M = np.zeros(b.effort.shape)
    for joint, j, at in pins:  # in place: arrays of every design-position of the batch
        F = b.forces[(mech.frame, j)]
        S -= F
        M -= (np.conjugate(b.points[at]) * F).imag  # zcross(at, F) as one complex product
        if isinstance(joint, Prismatic):
            M -= b.couple[(mech.frame, j)]
    if mech.driver.crank:
        M -= b.effort
        return S, M
    # A slider driver's actuator pushes along the frame's guide: F1j = effort u, at the slider's point.
    joint = mech.joint_between(mech.frame, mech.driver.link)
    F = b.effort * np.exp(1j * joint.direction)
    return S - F, M + zcross(b.points[joint.slider, joint.point], -F)


def _energy_swings(theta: np.ndarray, T: np.ndarray) -> np.ndarray:
    """The energy swing E [J] of :func:`graphkin.cycle.flywheel.size_flywheel` for each row of ``T`` (designs, one
    closed turn ``theta``), driven at its mean, by the same steps row by row; rows with nan give nan.

    The pulses' areas, accumulated from the first crossing of T with its mean, are the energies at the crossings
    less that at the first (the last accumulated sum, the whole turn's, is U at the turn's end); so E is the larger
    of their largest and U's end less the smaller of their smallest and U's end (0 without a crossing). The first
    crossing is the first by index, or the last interval's where it lies past the turn's end (it is then one turn
    back, first of all). Rows with a crossing past the turn's end elsewhere (a turn whose last angle repeats the
    first), or angles that decrease, take :func:`_energy_swings_sorted`.
    """
    k, n = T.shape
    h = steps(theta, closing_step(theta))
    T_avg = np.sum(0.5 * (T + np.roll(T, -1, axis=1)) * h, axis=1) / TURN
    D = T - T_avg[:, None]
    D_next = np.roll(D, -1, axis=1)
    step = D + D_next
    step *= 0.5 * h
    U = np.cumsum(step, axis=1)  # U[:, i] the energy at sample i + 1; at sample 0 it is 0
    U_end = U[:, -1].copy()
    cross = (D >= 0) != (D_next >= 0)
    frac = D / (D - D_next)
    at = theta + frac * h
    wrap = at >= theta[0] + TURN * (1 - 1e-12)
    wrap &= cross
    # The energy at each crossing: U at the interval's start plus the trapezoid up to it.
    V = D * frac
    V *= 0.5 * h
    V[:, 1:] += U[:, :-1]
    V[:, -1] = np.where(wrap[:, -1], V[:, -1] - U_end, V[:, -1])
    rows = np.arange(k)
    first = np.where(wrap[:, -1], n - 1, np.argmax(cross, axis=1))
    V0 = V[rows, first]
    top = np.max(np.where(cross, V, -np.inf), axis=1) - V0
    low = np.min(np.where(cross, V, np.inf), axis=1) - V0
    E = np.maximum(np.maximum(top, U_end), 0.0) - np.minimum(np.minimum(low, U_end), 0.0)
    E[~cross.any(axis=1)] = 0.0
    odd = wrap[:, :-1].any(axis=1) | (not np.all(np.diff(theta) > 0))
    if odd.any():
        E[odd] = _energy_swings_sorted(theta, T[odd])
    return np.where(np.isfinite(T).all(axis=1), E, np.nan)


def _energy_swings_sorted(theta: np.ndarray, T: np.ndarray) -> np.ndarray:
    """:func:`_energy_swings` with the crossings sorted by angle and their pulses' areas summed, for any closed turn.

    With m crossings of T and its mean in a row, the pulses' areas are padded with zeros to the row's length:
    their running sum then stays at its last value, which changes neither its largest nor its smallest value.
    """
    k, n = T.shape
    h = steps(theta, closing_step(theta))
    T_avg = np.sum(0.5 * (T + np.roll(T, -1, axis=1)) * h, axis=1) / TURN
    D = T - T_avg[:, None]
    D_next = np.roll(D, -1, axis=1)
    U = np.concatenate([np.zeros((k, 1)), np.cumsum(0.5 * (D + D_next) * h, axis=1)], axis=1)
    cross = (D >= 0) != (D_next >= 0)
    frac = D / (D - D_next)
    at = theta + frac * h
    U_c = U[:, :-1] + 0.5 * D * frac * h
    wrap = at >= theta[0] + TURN * (1 - 1e-12)
    at = np.where(wrap, at - TURN, at)
    U_c = np.where(wrap, U_c - U[:, -1:], U_c)
    # Each row's crossings in order of angle (the others after them), then the areas between them.
    order = np.argsort(np.where(cross, at, np.inf), axis=1, kind="stable")
    U_c = np.take_along_axis(np.where(cross, U_c, np.nan), order, axis=1)
    m = cross.sum(axis=1)
    rows = np.arange(k)
    ends = np.append(U_c[:, 1:], np.full((k, 1), np.nan), axis=1)
    ends[rows[m > 0], m[m > 0] - 1] = U_c[m > 0, 0] + U[m > 0, -1]
    areas = np.where(np.arange(n) < m[:, None], ends - U_c, 0.0)
    accumulated = np.cumsum(areas, axis=1)
    E = np.maximum(accumulated.max(axis=1, initial=0.0), 0.0) - np.minimum(accumulated.min(axis=1, initial=0.0), 0.0)
    return np.where(np.isfinite(T).all(axis=1), E, np.nan)


def _merits(shape, members: list, q: np.ndarray, Cs: float) -> dict:
    """The figures of merit of designs that share a batch (:func:`merit`'s, each design's to rounding), by index.

    ``shape`` is one of the designs' problems (their links, joints, loads, analysis); ``members`` are
    ``(index, values, numbers, q_dot, q_ddot)``.
    """
    mech = shape.mechanism
    four = _four_bar(mech)
    b = solve_designs(mech, [m[2] for m in members], q, [m[3] for m in members], [m[4] for m in members],
                      static=shape.static,
                      points=[at for _, _, at in _frame_pins(mech, [j.links for j in mech.joints])] + list(four or ()))
    pins = _frame_pins(mech, b.forces)  # in the order a Cycle sums them
    names = [force_name(mech, i, j) for (i, j) in b.forces]
    T, N = b.effort, len(q)
    with np.errstate(all="ignore"):  # a design that fails carries nan; its figures are not read
        # Reductions over each design's positions.
        peak, square = np.max(np.abs(T), axis=1), _means(q, T * T)
        joints = [_peak_size(F) for F in b.forces.values()]
        S, M = _shaking(b, mech, pins)
        shaking_force, shaking_moment = _peak_size(S), np.max(np.abs(M), axis=1)
        if four is not None:
            # μ folded to [0, π/2] grows with |u × v| / |u · v|: its least is μ at the position of the least ratio.
            A, B, B0 = (b.points[at] for at in four)
            u, v = A - B, B0 - B
            uv = np.conjugate(u) * v  # u · v + i u × v, one complex product
            size, along = np.abs(uv.imag), uv.real
            at = np.argmin(size / np.abs(along), axis=1)
            rows = np.arange(len(at))
            mu = np.arctan2(size[rows, at], along[rows, at])
            mu_min = np.minimum(mu, np.pi - mu).tolist()
        closed = closing_step(q) is not None
        swing = _energy_swings(q, T).tolist() if closed else None  # T not crossing its mean: 0/0, x/0, not read
    ok = b.valid.all(axis=1).tolist()
    peak, square, shaking_force, shaking_moment = (x.tolist() for x in (peak, square, shaking_force, shaking_moment))
    joints = [x.tolist() for x in joints]
    out, whys = {}, {}
    for d, (index, vals, _, w, _) in enumerate(members):
        if not ok[d]:
            bad = np.flatnonzero(~b.valid[d])
            out[index] = _failed(vals, names, len(bad), q, int(bad[0]), mech.driver.crank, b.reason(d, int(bad[0])))
            continue
        # The design's own cycle's words for a flywheel it cannot have: for a valid design of a crank they follow
        # from its speed (and, at rest, whether its analysis is static, which a batch shares).
        if w not in whys:
            q_dot = np.full(N, w)
            why = Cycle.why_no_flywheel(SimpleNamespace(problem=shape, closed=closed, valid=b.valid[d], q_dot=q_dot))
            whys[w] = why, None if why else Cs * float(np.mean(q_dot)) ** 2
        why, per = whys[w]
        out[index] = Design(
            values=vals, torque_peak=peak[d], torque_rms=math.sqrt(square[d]),
            joint_peaks={name: x[d] for name, x in zip(names, joints)},
            I_s=math.nan if why else swing[d] / per,
            shaking_force_peak=shaking_force[d], shaking_moment_peak=shaking_moment[d],
            transmission_angle_min=mu_min[d] if four is not None else math.nan, no_flywheel=why)
    return out


def _peak_size(F: np.ndarray) -> np.ndarray:
    """The largest |F| of each row of complex ``F`` (designs, positions): np.abs of a complex array is
    np.hypot of its parts, a third of the time of np.hypot on the strided parts."""
    return np.max(np.abs(F), axis=1)
