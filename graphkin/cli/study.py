"""``graphkin study PROBLEM --vary "FIELD=FROM..TO UNIT:N"``: a problem's figures of merit over a grid of designs.

``--best FIGURE [--require "FIGURE OP VALUE UNIT"]...`` marks the design with the least FIGURE among those that meet
the limits; ``--csv FILE`` writes a row per design, ``--figure FILE`` draws the study (:func:`graphkin.draw.draw_study`).
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

from graphkin.cli._common import DOCS, Progress
from graphkin.errors import GraphkinError

_RANGE = re.compile(r"\s*(?P<a>[-+]?[\d.]+(?:[eE][-+]?\d+)?)\s*\.\.\s*(?P<b>[-+]?[\d.]+(?:[eE][-+]?\d+)?)"
                    r"\s+(?P<unit>\S(?:.*\S)?)\s*:\s*(?P<n>\d+)\s*")
"""``FROM..TO UNIT:N``: two numbers, the unit they are in, and how many equally spaced values from one to the other."""


def add_parser(sub) -> None:
    """Add ``study`` to the ``graphkin`` subcommands."""
    c = sub.add_parser("study", help="a design study: torque, flywheel, joint and shaking forces over a grid of designs")
    c.add_argument("problem", help="catalog name (see 'graphkin list') or path to a problem file")
    c.add_argument("--vary", action="append", required=True, metavar="FIELD=FROM..TO UNIT:N",
                   help="a field of the problem file (links[0].mass, links[0].points.A[0], ...) and N equally spaced "
                   "values from FROM to TO in UNIT, e.g. \"links[0].points.A[0]=60..100 mm:41\"; give --vary again "
                   "for another field (the designs are every combination)")
    c.add_argument("--n", type=int, help="equally spaced crank angles per design (default: the problem's own)")
    c.add_argument("--cs", type=float, default=0.05, metavar="CS",
                   help="coefficient of speed fluctuation the flywheels are sized for (default 0.05)")
    c.add_argument("--json", action="store_true", help=f"print the study as JSON in SI units (schema: {DOCS}/json.html)")
    c.add_argument("--best", metavar="FIGURE", help="mark the design with the least FIGURE (torque_peak, torque_rms, "
                   "I_s, shaking_force_peak, shaking_moment_peak, transmission_angle_min, F12_peak, ...)")
    c.add_argument("--require", action="append", default=[], metavar="\"FIGURE OP VALUE UNIT\"",
                   help="with --best: a limit the best design must meet, e.g. \"transmission_angle_min >= 40 deg\" "
                   "(OP one of <=, >=, <, >); give --require again for another")
    c.add_argument("--csv", metavar="FILE", help="write a row per design (the fields' values, each figure of merit "
                   "with its unit, where and why a design cannot be assembled) to FILE")
    c.add_argument("--figure", metavar="FILE", help="draw the study (.png, .svg or .pdf): each figure of merit against "
                   "one varied field, a contour map over two, parallel coordinates over more")
    c.add_argument("--merit", metavar="FIGURE", help="with --figure: the figure of merit a contour map or parallel "
                   "coordinates colour by (default: --best's, else torque_peak)")


def vary_values(text: str) -> tuple[str, list[str]]:
    """A ``--vary`` argument's field and its values as a problem file writes them (``"62.5 mm"``).

    Raises
    ------
    GraphkinError
        Naming the ``--vary`` if it is not ``FIELD=FROM..TO UNIT:N`` with N ≥ 1 (N = 1 only when FROM = TO).
    """
    import numpy as np

    from graphkin.cycle.study import MAX_DESIGNS

    field, eq, rng = text.partition("=")
    m = _RANGE.fullmatch(rng)
    why = ("write it FIELD=FROM..TO UNIT:N, e.g. \"links[0].mass=2..4 kg:11\"" if not (eq and field.strip() and m)
           else None)
    if why is None:
        try:
            a, b = float(m["a"]), float(m["b"])
        except ValueError:
            a = b = None
        n = int(m["n"])
        if a is None:
            why = f"{m['a']}..{m['b']} is not a range of two numbers"
        elif not 1 <= n <= MAX_DESIGNS:
            why = f"N = {n}: give from 1 to {MAX_DESIGNS:,} values"
        elif n == 1 and a != b:
            why = f"N = 1 value cannot span {m['a']}..{m['b']}; give N ≥ 2"
        elif n > 1 and a == b:
            why = f"{n} values from {m['a']} to {m['b']} would all be equal; give N = 1 or two different ends"
    if why:
        raise GraphkinError(f"--vary {text!r}: {why}")
    return field.strip(), [f"{x!r} {m['unit']}" for x in np.linspace(a, b, n).tolist()]


def run(args) -> int:
    """Carry out ``graphkin study``; returns the exit code (0, also when some designs cannot be assembled)."""
    from graphkin.cycle.choice import best, figure_values, requirement
    from graphkin.cycle.flywheel import check_Cs
    from graphkin.cycle.study import VaryError, study
    from graphkin.files import check_destination, json_text, write_text
    from graphkin.report.study import format_study, study_csv, study_data

    check_Cs(args.cs, "--cs")
    if args.require and not args.best:
        raise GraphkinError(f"--require {args.require[0]!r}: a limit goes with --best FIGURE (the figure to minimise)")
    if args.merit and not args.figure:
        raise GraphkinError(f"--merit {args.merit}: goes with --figure FILE")
    if args.figure:  # a figure or table that cannot be written is refused before the solve, as every command does
        if Path(args.figure).suffix.lower() not in (".png", ".svg", ".pdf"):
            raise GraphkinError(f"--figure {args.figure}: the figure's file must end in .png, .svg or .pdf")
        check_destination(args.figure, "--figure")
    if args.csv:
        check_destination(args.csv, "--csv")
    if args.n is not None and args.n < 2:
        raise GraphkinError(f"--n {args.n}: give at least 2 crank angles")
    given, vary = {}, {}
    for text in args.vary:
        field, values = vary_values(text)
        if field in vary:
            raise GraphkinError(f"--vary {text!r}: {field} is varied twice")
        given[field], vary[field] = text, values

    def solved(grid):
        try:
            return study(args.problem, grid, n=args.n, Cs=args.cs)
        except VaryError as exc:  # the field's fault, named by the --vary the user wrote
            raise GraphkinError(f"--vary {given[exc.field]!r}: "
                                + str(exc).removeprefix(f"vary {exc.field}: ")) from None

    def chosen(s):
        """The best design of ``s`` under the limits (None without --best), each name and unit checked."""
        limits = [requirement(s, r, "--require") for r in args.require]
        if args.merit:
            figure_values(s, args.merit, label="--merit")
        return best(s, args.best, limits, label="--best") if args.best else None

    if args.best or args.merit:
        # One design has every figure the grid has (its joints' names too, once it is built): a figure or a unit
        # named wrong is told before the whole grid is solved.
        probe = solved({field: values[:1] for field, values in vary.items()})
        if probe.designs[0].joint_peaks:
            chosen(probe)
    with Progress(f"studying {args.problem}"):
        s = solved(vary)
    choice = chosen(s)
    data = study_data(s, choice)
    if args.figure:  # drawn before anything is written: a figure that cannot be drawn leaves no table behind
        from graphkin import draw

        with Progress(f"drawing {Path(args.figure).name}"):
            figure = draw.draw_study(s, choice, merit=args.merit)
    if args.csv:
        write_text(args.csv, study_csv(data), "--csv")
        print(f"table written to {args.csv}", file=sys.stderr)
    if args.figure:
        draw.save(figure, args.figure)
        print(f"figure written to {args.figure}", file=sys.stderr)
    print(json_text(data) if args.json else format_study(data))
    return 0
