"""``graphkin study PROBLEM [--vary "FIELD=FROM..TO UNIT:N"]``: a problem's figures of merit over a grid of designs.

Without ``--vary`` the problem file's ``[study]`` table says what to vary (and, unless the flags say otherwise,
the number of positions, C_s, ``best``, ``require`` and ``optimize``). ``--best FIGURE [--require "FIGURE OP VALUE
UNIT"]...`` marks the design with the least FIGURE among those that meet the limits; ``--optimize "minimise
FIGURE"`` runs scipy.optimize between the grid's values from there; ``-o FILE.toml`` writes the chosen design as a
problem file; ``--csv FILE`` writes a row per design, ``--figure FILE`` draws the study
(:func:`graphkin.draw.draw_study`, the chosen design marked); ``--units`` prints and draws them in SI, US or a
units file's units.
"""

from __future__ import annotations

import sys
from pathlib import Path

from graphkin.cli._common import DOCS, Progress
from graphkin.errors import GraphkinError, ProblemFileError


def add_parser(sub) -> None:
    """Add ``study`` to the ``graphkin`` subcommands."""
    c = sub.add_parser("study", help="a design study: torque, flywheel, joint and shaking forces over a grid of designs")
    c.add_argument("problem", help="catalog name (see 'graphkin list') or path to a problem file")
    c.add_argument("--vary", action="append", default=[], metavar="FIELD=FROM..TO UNIT:N",
                   help="a field of the problem file (links[0].mass, links[0].points.A[0], ...) and N equally spaced "
                   "values from FROM to TO in UNIT, e.g. \"links[0].points.A[0]=60..100 mm:41\", or a list, "
                   "\"links[1].mass=2 kg, 3 kg, 5 kg\"; give --vary again for another field (the designs are every "
                   "combination); default: the problem file's [study] table")
    c.add_argument("--n", type=int, help="equally spaced crank angles per design (default: the problem's own)")
    c.add_argument("--cs", type=float, metavar="CS",
                   help="coefficient of speed fluctuation the flywheels are sized for (default: [study]'s, else 0.05)")
    c.add_argument("--json", action="store_true", help=f"print the study as JSON in SI units (schema: {DOCS}/json.html)")
    c.add_argument("--best", metavar="FIGURE", help="mark the design with the least FIGURE (torque_peak, torque_rms, "
                   "I_s, shaking_force_peak, shaking_moment_peak, transmission_angle_min, F12_peak, ...)")
    c.add_argument("--require", action="append", default=[], metavar="\"FIGURE OP VALUE UNIT\"",
                   help="with --best or --optimize: a limit the chosen design must meet, e.g. \"transmission_angle_min "
                   ">= 40 deg\" (OP one of <=, >=, <, >); give --require again for another")
    c.add_argument("--optimize", metavar="\"minimise FIGURE\"",
                   help="scipy.optimize (pip install 'graphkin[study]') between the grid's values, from the grid's "
                   "best design: \"minimise FIGURE\" or \"maximise FIGURE\", under the --require limits")
    c.add_argument("-o", "--output", metavar="FILE.toml", help="write the chosen design (the optimum with "
                   "--optimize, else the best with --best) as a problem file that graphkin solve, cycle, handout and "
                   "explore read")
    c.add_argument("--units", metavar="SI|US|FILE",
                   help="print in these units: SI (default), US (in, lbf, lbf·ft, rpm, hp) or a units file (TOML); "
                   f"the CSV's headers and --json's \"units\" state them ({DOCS}/problem-files.html#units-of-a-report)")
    c.add_argument("--csv", metavar="FILE", help="write a row per design (the fields' values, each figure of merit "
                   "with its unit, where and why a design cannot be assembled) to FILE")
    c.add_argument("--figure", metavar="FILE", help="draw the study (.png, .svg or .pdf): each figure of merit against "
                   "one varied field, a contour map over two, parallel coordinates over more; the best design marked (a black "
                   "star or line), the optimum too (a red diamond or line), the figures in the --units")
    c.add_argument("--merit", metavar="FIGURE", help="with --figure: the figure of merit a contour map or parallel "
                   "coordinates colour by (default: --best's, else --optimize's, else torque_peak)")


def vary_values(text: str) -> tuple[str, list[str]]:
    """A ``--vary`` argument's field and its values as a problem file writes them (``"62.5 mm"``).

    Raises
    ------
    GraphkinError
        Naming the ``--vary`` if it is not ``FIELD=FROM..TO UNIT:N`` (N ≥ 1; N = 1 only when FROM = TO) nor
        ``FIELD=V1, V2, ...``.
    """
    from graphkin.problem.study_table import parse_values

    field, eq, rng = text.partition("=")
    try:
        values = parse_values(rng) if eq and field.strip() else None
    except GraphkinError as exc:
        raise GraphkinError(f"--vary {text!r}: {exc}") from None
    if values is None:
        raise GraphkinError(f"--vary {text!r}: write it FIELD=FROM..TO UNIT:N, e.g. \"links[0].mass=2..4 kg:11\", "
                            "or FIELD=V1, V2, ..., e.g. \"links[0].mass=2 kg, 3 kg\"")
    return field.strip(), values


def run(args) -> int:
    """Carry out ``graphkin study``; returns the exit code (0, also when some designs cannot be assembled)."""
    from graphkin.cycle.choice import best, figure_values, requirement
    from graphkin.cycle.flywheel import check_Cs
    from graphkin.cycle.optimum import objective_of, optimum
    from graphkin.cycle.studies import VaryError, stated, study
    from graphkin.files import check_destination, json_text, write_text
    from graphkin.report.study import format_study, study_csv, study_data, study_in
    from graphkin.units.systems import unit_system

    units = unit_system(args.units)
    if args.cs is not None:
        check_Cs(args.cs, "--cs")
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
    table = stated(args.problem)
    own = not vary  # the file's [study] says what to vary
    if own and table is None:
        raise GraphkinError(f"{args.problem}: give the fields to vary, --vary \"FIELD=FROM..TO UNIT:N\", or a [study] "
                            "table in the problem file (docs/problem-files.md)")
    here = f"{args.problem}: study"  # what messages call an entry of the file's table
    # The flags say what to choose by; the file's table where they say nothing.
    best_name, best_label = (args.best, "--best") if args.best or table is None else (table.best, f"{here}.best")
    aim, aim_label = ((args.optimize, "--optimize") if args.optimize or table is None
                      else (table.optimize, f"{here}.optimize"))
    limits_text, limits_label = ((args.require, "--require") if args.require or table is None
                                 else (list(table.require), f"{here}.require"))
    if limits_text and not (best_name or aim):
        raise GraphkinError(f"--require {limits_text[0]!r}: a limit goes with --best FIGURE (the figure to minimise) "
                            "or --optimize \"minimise FIGURE\"")
    if args.output:
        if not (best_name or aim):
            raise GraphkinError(f"-o {args.output}: writes the chosen design: give --best FIGURE or --optimize")
        if Path(args.output).suffix.lower() != ".toml":
            raise GraphkinError(f"-o {args.output}: a problem file's name ends in .toml")
        check_destination(args.output, "-o")
    def solved(grid):
        try:
            return study(args.problem, None if own and grid is None else grid, n=args.n, Cs=args.cs)
        except VaryError as exc:  # the field's fault, named by the --vary the user wrote or the file's entry
            said = str(exc).removeprefix(f"vary {exc.field}: ")
            if own:
                raise ProblemFileError(args.problem, f"study.vary.{exc.field}", said) from None
            raise GraphkinError(f"--vary {given[exc.field]!r}: {said}") from None

    def chosen(s):
        """The best design of ``s`` under the limits (None without --best), each name and unit checked."""
        limits = [requirement(s, r, limits_label) for r in limits_text]
        if args.merit:
            figure_values(s, args.merit, label="--merit")
        if aim:
            objective_of(s, aim, aim_label)
        return best(s, best_name, limits, label=best_label) if best_name else None, limits

    grid = table.vary if own else vary
    if best_name or aim or args.merit:
        # One design has every figure the grid has (its joints' names too, once it is built): a figure or a unit
        # named wrong is told before the whole grid is solved.
        probe = solved({field: list(values[:1]) for field, values in grid.items()})
        if probe.designs[0].joint_peaks:
            chosen(probe)
    if aim:
        from graphkin.optional import missing, require

        if aim_label == "--optimize":
            require("scipy.optimize", f"{aim_label} {aim!r}")
        else:  # the file's table asks for it: without scipy the grid is still studied, and a note says why not more
            try:
                require("scipy.optimize", f"{aim_label} {aim!r}")
            except GraphkinError:
                print(f"note: {missing('scipy', f'{aim_label} {aim!r}')}; studying the grid only", file=sys.stderr)
                aim = None
    with Progress(f"studying {args.problem}"):
        s = solved(None if own else vary)
    choice, limits = chosen(s)
    best_one = None
    if aim:
        with Progress(f"optimising {args.problem}"):
            best_one = optimum(s, aim, limits, label=aim_label)
    data = study_data(s, choice, best_one)
    if args.output and best_one is None and (choice is None or choice.index is None):
        raise GraphkinError(f"-o {args.output}: no design to write: "
                            + (choice.why if choice is not None else "no best design was asked for, and no optimum"))
    if args.figure:  # drawn before anything is written: a figure that cannot be drawn leaves no table behind
        from graphkin import draw

        with Progress(f"drawing {Path(args.figure).name}"):
            figure = draw.draw_study(s, choice, merit=args.merit, optimum=best_one, units=units)
    if args.csv:
        write_text(args.csv, study_csv(data, units), "--csv")
        print(f"table written to {args.csv}", file=sys.stderr)
    if args.figure:
        draw.save(figure, args.figure)
        print(f"figure written to {args.figure}", file=sys.stderr)
    if args.output:
        values = best_one.values if best_one is not None else s.designs[choice.index].values
        what = "the optimum" if best_one is not None else f"design {choice.index + 1}, the best of the grid,"
        shown = ", ".join(f"{f} = {v}" for f, v in zip(s.fields, values))
        s.write_design(values, args.output, f"{what} of graphkin study {args.problem}:\n{shown}")
        print(f"design written to {args.output}", file=sys.stderr)
    print(json_text(data if units is None else study_in(data, units)) if args.json else format_study(data, units))
    return 0
