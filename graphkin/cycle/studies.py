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
design-positions at a time, and designs that differ only in masses, I_G, G and loads (the same points and speed)
share one kinematic pass (:func:`batch_order`); the figures of merit are read off the (designs, positions) arrays
at once. Each design's
numbers are those of a sweep of it alone, to rounding (:mod:`graphkin.analytical.designs`). A design that cannot
share a batch -- a gear train, a load that varies over the cycle (a table, a spring), values given at one
position -- is swept on its own, and :attr:`Study.why_not_vectorised` says how many and why.

A file's ``[study]`` table (:mod:`graphkin.problem.study_table`) is read when no ``vary`` is given; a design is a
problem (:meth:`Study.design`); :meth:`Study.optimum` searches between the grid's values (:mod:`graphkin.cycle.optimum`).
"""

from __future__ import annotations

import copy
import dataclasses
import itertools
import math
import tomllib
from dataclasses import dataclass
from operator import getitem
from pathlib import Path
from typing import Any, Mapping

import numpy as np

from graphkin import catalog
from graphkin.analytical.designs import batch_key, numbers
from graphkin.cycle._sampling import sweep_positions
from graphkin.cycle.choice import best
from graphkin.cycle.flywheel import check_Cs
from graphkin.cycle.merit import Design, Shared, batch_merits, merit, unbuilt
from graphkin.cycle.optimum import optimum as find_optimum
from graphkin.cycle.sweep import sweep
from graphkin.errors import GraphkinError, ProblemFileError
from graphkin.files import read_text, write_text
from graphkin.kinematics.solver import CHUNK
from graphkin.problem import FieldReader, Problem, build_problem
from graphkin.problem.fields import missing, set_field
from graphkin.problem.study_table import MAX_DESIGNS, StudyTable, read_study
from graphkin.problem.toml_text import toml_text

__all__ = ["MAX_DESIGNS", "Design", "Study", "VaryError", "merit", "solve_grid", "stated", "study"]

BATCH = CHUNK
"""Design-positions solved together: as many whole designs as fit (at least one). Their arrays (about 40 MB, 1.3 kB a
design-position) are freed before the next batch, so a study's memory does not grow with its designs beyond their
figures of merit; a batch's Python (its plan's steps compiled for its designs' numbers, the figures' set-up) is
paid once per 90 designs of 360 positions, not 22."""

GROUP = 2 * BATCH
"""Design-positions of a group of designs that share their kinematics solved together at most: its kinematic
pass is over one design's positions, its force pass over all of theirs."""

SHARED = 4 * BATCH
"""Design-positions of a batch of groups of more than one design that share their kinematics: their kinematic
pass is over one design's positions of each group (a 25th of the batch's, in a study of 25 masses), so a batch of
four times BATCH pays a batch's Python (its plan and load specs compiled for its numbers, the figures' set-up, the
kinematic steps) a quarter as often for arrays of the force pass of a few hundred kB (measured on the benchmark,
benchmarks/README.md: 1 to 6 times BATCH, 4 the least time; the peak memory of its study did not change)."""


class VaryError(GraphkinError):
    """A field a study varies, or one of its values, is at fault; ``field`` names it as the study was given it."""

    def __init__(self, field: str, message: str):
        self.field = field
        super().__init__(f"vary {field}: {message}")


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
    data : dict or None
        The problem file's data, without its ``[study]`` table: each design is it with its values put in
        (:meth:`design_data`).
    base : Path or None
        The problem file's path (a load's ``csv`` table is read from its folder).
    stated : StudyTable or None
        The file's ``[study]`` table, if it has one (its ``best``, ``require`` and ``optimize``).
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
    data: Mapping | None = dataclasses.field(default=None, repr=False, compare=False)
    base: Any = dataclasses.field(default=None, repr=False, compare=False)
    stated: StudyTable | None = dataclasses.field(default=None, repr=False, compare=False)

    @property
    def shape(self) -> tuple:
        """The grid's shape: the number of values of each field."""
        return tuple(len(v) for v in self.grid)

    def best(self, minimise: str, require=()):
        """The design with the least ``minimise`` among those that meet ``require``
        (:func:`graphkin.cycle.choice.best`): ``s.best("torque_peak", ["transmission_angle_min >= 40 deg"])``."""
        return best(self, minimise, require)

    def design_data(self, which) -> dict:
        """The problem file's data of one design: the file (less its ``[study]``) with the design's values put in.

        Parameters
        ----------
        which : int or tuple
            The design's index in :attr:`designs`, or the value of each field (as the file writes them).
        """
        values = self.designs[which].values if isinstance(which, (int, np.integer)) else tuple(which)
        if len(values) != len(self.fields):
            raise GraphkinError(f"design: give one value for each of the {len(self.fields)} fields "
                                f"({', '.join(self.fields)}), got {values!r:.80}")
        out = copy.deepcopy(dict(self.data))
        for f, v in zip(self.fields, values):
            set_field(out, f, copy.deepcopy(v))
        return out

    def design(self, which) -> Problem:
        """One design as an ordinary :class:`~graphkin.problem.Problem`: ``gk.solve``, ``gk.sweep``,
        ``gk.handout`` and ``gk.explore`` take it (``which`` as for :meth:`design_data`).

        >>> s = study("strip_cutter", {"links[1].mass": ["2 kg", "4 kg"]}, n=36)
        >>> s.design(1).mechanism.link(3).mass
        4.0
        """
        values = self.designs[which].values if isinstance(which, (int, np.integer)) else tuple(which)
        shown = ", ".join(f"{f}={v}" for f, v in zip(self.fields, values))
        return build_problem(self.design_data(values), file=f"{self.problem} ({shown})", base=self.base)

    def write_design(self, which, path, comment: str | None = None) -> Path:
        """Write one design as a problem file (atomically) that ``graphkin solve``, ``cycle``, ``handout`` and
        ``explore`` read, and return its path: ``gk.handout.build(s.write_design(3, "design.toml"))``.

        Parameters
        ----------
        which : int or tuple
            As for :meth:`design_data`.
        path : str or Path
            The file (``.toml``); a load's ``csv`` table is named as the study's file names it, so write the design
            beside that file if it has one.
        comment : str, optional
            Lines written first as ``#`` comments (default: the study and the design's values).
        """
        values = self.designs[which].values if isinstance(which, (int, np.integer)) else tuple(which)
        if comment is None:
            comment = f"a design of the study of {self.problem}: " + ", ".join(
                f"{f} = {v}" for f, v in zip(self.fields, values))
        return write_text(path, toml_text(self.design_data(values), comment), "design")

    def optimum(self, objective: str, require=(), **options):
        """The design between the grid's values that minimises (or maximises) one figure of merit under limits,
        by ``scipy.optimize`` started from the best design of the grid (:func:`graphkin.cycle.optimum.optimum`).

        ``s.optimum("torque_peak", ["transmission_angle_min >= 40 deg"])``; ``"maximise transmission_angle_min"``.
        """
        return find_optimum(self, objective, require, **options)

    def solve_values(self, rows) -> tuple:
        """The designs with these values of the fields (each row one value per field, as the file writes them),
        solved together as one batch, each as :func:`study` solves its grid's: :class:`Design` s, in order."""
        rows = [tuple(r) for r in rows]
        grid = tuple(list(dict.fromkeys(map(_hashable, (r[k] for r in rows)))) for k in range(len(self.fields)))
        combos = [tuple(grid[k].index(_hashable(r[k])) for k in range(len(self.fields))) for r in rows]
        values = tuple(tuple(_unhashable(v) for v in g) for g in grid)
        return solve_grid(self.data, self.problem, self.base, self.fields, values, combos, self.n, self.Cs)[0]


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


def _hashable(v):
    return tuple(_hashable(x) for x in v) if isinstance(v, list) else v


def _unhashable(v):
    return [_unhashable(x) for x in v] if isinstance(v, tuple) else v


def stated(problem) -> StudyTable | None:
    """The ``[study]`` table of a problem (a catalog name, a file or its data), read and checked; None if it has none.

    Raises
    ------
    ProblemFileError
        An entry of the table at fault, named ``study.FIELD``.
    """
    data, file, _ = _problem_data(problem)
    return read_study(FieldReader(file), data["study"], data) if "study" in data else None


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


def study(problem, vary: Mapping[str, Any] | None = None, *, n: int | None = None, Cs: float | None = None) -> Study:
    """Solve a problem over its cycle for every combination of the values of some of its fields.

    Parameters
    ----------
    problem : str, Path or dict
        A catalog name, a problem file, or a problem file's data as ``tomllib`` reads it.
    vary : dict of str to list, optional
        Each field's path (:mod:`graphkin.problem.fields`; ``links[0]`` is the file's first ``[[links]]``) and
        its values as the problem file writes them, with units: ``{"links[0].mass": ["2 kg", "3 kg"],
        "links[0].points.A": [["80 mm", "0 mm"], ["90 mm", "0 mm"]]}``. Default: the file's ``[study]`` table
        (:mod:`graphkin.problem.study_table`).
    n : int, optional
        Equally spaced crank angles per design (:func:`graphkin.cycle.sweep`); default the ``[study]`` table's,
        else the file's positions.
    Cs : float, optional
        Coefficient of speed fluctuation the flywheel of each design is sized for; default the ``[study]``
        table's, else 0.05.

    Returns
    -------
    Study
        Every design's values and its figures of merit, in the order of the grid (the last field fastest).

    Raises
    ------
    VaryError
        A varied field the problem does not have, or a value it rejects (naming the field).
    ProblemFileError
        The same of a field the file's ``[study]`` table varies, naming it ``study.vary.FIELD``.
    GraphkinError
        Any other input at fault.

    Examples
    --------
    >>> s = study("strip_cutter", {"links[1].mass": ["2 kg", "4 kg"]}, n=90)
    >>> [round(d.torque_peak, 1) for d in s.designs]
    [324.6, 392.6]
    """
    data, file, base = _problem_data(problem)
    stated = None
    if "study" in data:
        rd = FieldReader(file)
        stated = read_study(rd, data["study"], data)
        data = {k: v for k, v in data.items() if k != "study"}  # each design is the file without its study
    if vary is None and stated is None:
        raise GraphkinError(f"study {file}: give the fields to vary (vary=..., --vary) or a [study] table in the "
                            "problem file (docs/problem-files.md)")
    own = vary is None
    n = stated.n if n is None and stated is not None else n
    Cs = check_Cs((stated.Cs if stated is not None and stated.Cs is not None else 0.05) if Cs is None else Cs)
    try:
        fields, grid = _grid(data, stated.vary if own else vary)
        designs, why, crank = solve_grid(data, file, base, fields, grid,
                                         itertools.product(*(range(len(v)) for v in grid)), n, Cs)
    except VaryError as exc:
        if not own:
            raise
        raise ProblemFileError(file, f"study.vary.{exc.field}", str(exc).removeprefix(f"vary {exc.field}: ")) from None
    return Study(file, fields, grid, designs, n, Cs, why is None, why, crank, data, base, stated)


def solve_grid(data: dict, file: str, base, fields: tuple, grid: tuple, combos, n: int | None, Cs: float):
    """The designs ``combos`` (for each, the index of its value of each field in ``grid``), solved in batches.

    Returns
    -------
    designs : tuple of Design
        In the order of ``combos``.
    why : str or None
        How many designs were swept one by one, and why (:attr:`Study.why_not_vectorised`).
    crank : bool
        True if the driver is a crank.
    """
    singles = [[_single(data, field, value, file, base) for value in values] for field, values in zip(fields, grid)]
    first = build_problem(data, file=file, base=base)
    positions: dict = {}
    changes = _changes(first, singles, n, positions)
    combos = list(combos)
    designs, batches, alone = {}, {}, {}
    if changes is not None:  # the file's numbers with each field's own put in (see _changes), a batch at a time
        designs = _grid_batches(first, changes, grid, combos, Cs)
        combos = ()
    for index, at in enumerate(combos):
        values = tuple(v[i] for v, i in zip(grid, at))
        try:
            shape = _design_problem(data, fields, values, file, base)
        except GraphkinError as exc:  # each value builds alone: together these do not
            designs[index] = unbuilt(values, str(exc))
            continue
        key, q = _batch_key(shape, n, positions)
        if q is None:
            alone[index] = (values, shape, key)
            continue
        member = (index, values, numbers(shape.mechanism), shape.q_dot[0], shape.q_ddot[0])
        if key not in batches:
            batches[key] = (shape, q, [], Shared(shape, q, Cs))
        shape, q, members, shared = batches[key]
        members.append(member)
        if len(members) * len(q) >= BATCH:  # solved as soon as it is full: a study holds one batch at a time
            designs.update(batch_merits(shape, members, q, Cs, shared))
            members.clear()
    for shape, q, members, shared in batches.values():
        if members:
            designs.update(batch_merits(shape, members, q, Cs, shared))
    for index, (values, p, _) in alone.items():
        designs[index] = merit(sweep(p, n), values, Cs)
    why = None
    if alone:
        reasons = sorted({key for _, _, key in alone.values()})
        why = (f"{len(alone)} of the {len(designs)} designs were swept one after another, not in a batch over "
               f"designs: {'; '.join(reasons)}")
    return tuple(designs[i] for i in range(len(designs))), why, first.mechanism.driver.crank


def _grid_batches(first, changes: tuple, grid: tuple, combos: list, Cs: float) -> dict:
    """The designs ``combos`` of one batch key, the file's numbers with each field's changes put in, solved
    about BATCH design-positions at a time, by index.

    Each batch's numbers are columns, one per number (:func:`graphkin.analytical.designs.solve_designs`): a
    number no field changes is the file's, for every design; one a field changes is, for each design, the value
    that field's value gives it, picked out of the field's values by the design's index of its value. The designs
    are taken in the order of the values of the fields that change a point or the speed (their kinematics), then
    of the others' (:func:`batch_order`), so that a batch holds whole groups of designs that share their kinematics,
    which are solved once for each group.
    """
    own, per_field, (_, q) = changes
    at = np.array(combos, dtype=np.intp).reshape(len(combos), len(grid))
    changed = {x: f for f, values in enumerate(per_field) for x in values[0]}
    table = {x: np.array([value[x] for value in per_field[f]]) for x, f in changed.items() if x != RATES}
    rates = {f: np.array([value[RATES] for value in per_field[f]], dtype=float) for f in {changed.get(RATES)}
             if f is not None}
    f_rates = changed.get(RATES)
    moves = sorted({f for x, f in changed.items() if x == RATES or x[0] == "point"})
    shared = Shared(first, q, Cs)
    same = {x: [v] for x, v in own.items() if x != RATES and x not in table}  # a column of one: every design's
    designs = {}
    for rows, per in batch_order(at, moves, len(q)):
        sub = at[rows]
        k = len(rows)
        columns = same | {x: column[sub[:, changed[x]]] for x, column in table.items()}
        if f_rates is None:
            w, al = [own[RATES][0]] * k, [own[RATES][1]] * k
        else:
            picked = rates[f_rates][sub[:, f_rates]]
            w, al = picked[:, 0], picked[:, 1]
        values = [tuple(map(getitem, grid, combos[i])) for i in rows.tolist()]
        designs.update(batch_merits(first, (rows.tolist(), values, columns, w, al), q, Cs, shared, per))
    return designs


def batch_order(at: np.ndarray, moves: list, N: int) -> list:
    """The batches of the designs ``at`` (each design's index of its value of each field): for each, the designs'
    indices (an array) and how many in a row share their kinematics (the size of its groups).

    The designs are sorted by their values of the fields ``moves`` (those that change their kinematics), then of
    the others; a run of designs with the same values of ``moves`` is a group that shares its kinematics. A batch
    is the fewest whole groups of one size that fill BATCH design-positions (SHARED for groups of more than one
    design); a group of more than GROUP design-positions is cut into nearly equal parts. Groups of one design
    (every design its own kinematics) fill a batch as they always have.
    """
    k = len(at)
    others = [f for f in range(at.shape[1]) if f not in moves]
    order = np.lexsort([at[:, f] for f in reversed(others)] + [at[:, f] for f in reversed(moves)])
    if moves:
        key = at[order][:, moves]
        starts = np.flatnonzero(np.concatenate(([True], (key[1:] != key[:-1]).any(axis=1))))
    else:
        starts = np.zeros(1 if k else 0, np.intp)
    sizes = np.diff(np.append(starts, k)).tolist()
    out, batch, size = [], [], 0  # the batch being filled: its groups' starts, and their size
    for start, m in zip(starts.tolist(), sizes):
        if batch and (m != size or len(batch) * m * N >= (SHARED if m > 1 else BATCH)):
            out.append((np.concatenate([order[s:s + size] for s in batch]), size))
            batch = []
        if m * N > GROUP:  # a group of its own, in parts
            parts = -(-m * N // GROUP)
            edges = np.linspace(0, m, parts + 1).round().astype(int).tolist()
            out += [(order[start + a:start + b], b - a) for a, b in zip(edges[:-1], edges[1:])]
            continue
        batch.append(start)
        size = m
    if batch:
        out.append((np.concatenate([order[s:s + size] for s in batch]), size))
    return out


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
