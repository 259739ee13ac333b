"""``graphkin cycle PROBLEM``: a whole cycle's torque, peak joint forces, flywheel and joint-force index."""

from __future__ import annotations

import sys
from pathlib import Path

from graphkin.cli._common import DOCS, Progress, check_outputs, position_text
from graphkin.errors import GraphkinError


def add_parser(sub) -> None:
    """Add ``cycle`` to the ``graphkin`` subcommands."""
    c = sub.add_parser("cycle", help="a whole cycle: torque, peak joint forces, flywheel, joint-force index")
    c.add_argument("problem", help="catalog name (see 'graphkin list') or path to a problem file")
    c.add_argument("--n", type=int, help="number of equally spaced crank angles over one turn (crank drivers only; "
                   "default: the problem's own positions); a load that switches on and off adds a sample either side "
                   "of each switching angle")
    c.add_argument("--cs", type=float, metavar="CS", help="coefficient of speed fluctuation: size a flywheel, e.g. 0.05")
    c.add_argument("--json", action="store_true", help=f"print every array as JSON in SI units (schema: {DOCS}/json.html)")
    c.add_argument("--units", metavar="SI|US|FILE",
                   help="print in these units: SI (default), US (in, lbf, lbf·ft, rpm, hp) or a units file (TOML); "
                   f"with --json, the JSON states each field's unit ({DOCS}/problem-files.html#units-of-a-report)")
    c.add_argument("-o", "--output", "--figure", dest="figure", metavar="FILE",
                   help="write the cycle figure (.png, .svg or .pdf) (--figure is the older name)")


def run(args) -> int:
    """Carry out ``graphkin cycle``; returns the exit code (2 if a position has no solution)."""
    import numpy as np

    from graphkin import catalog
    from graphkin.cycle import sweep
    from graphkin.cycle.flywheel import check_Cs
    from graphkin.files import json_text
    from graphkin.ranges import MAX_POSITIONS
    from graphkin.report import cycle_data, format_cycle
    from graphkin.report.in_units import cycle_in
    from graphkin.units.systems import unit_system

    check_outputs(args.figure)
    if args.cs is not None:
        check_Cs(args.cs, "--cs")
    if args.n is not None and not 2 <= args.n <= MAX_POSITIONS:
        raise GraphkinError(f"--n {args.n}: n must be a whole number of positions from 2 to {MAX_POSITIONS:,} "
                            "(1° steps need 360, 0.01° steps 36,000)")
    units = unit_system(args.units)
    problem = catalog.load(args.problem)
    if args.n is not None and not problem.mechanism.driver.crank:
        raise GraphkinError(f"{problem.name}: --n: the driver is a slider, so there is no turn to divide into "
                            "positions; leave out --n to sweep the problem's own positions")
    with Progress(f"sweeping {problem.name}"):
        cycle = sweep(problem, args.n)
        why = cycle.why_no_flywheel() if args.cs is not None else None
        if why:
            raise GraphkinError(f"{problem.name}: --cs {args.cs:g}: {why}")
        data = cycle_data(cycle, args.cs)
    if args.json:
        print(json_text(data if units is None else cycle_in(data, units)))
    else:
        print(format_cycle(cycle, data, units))
    if args.figure:
        from graphkin import draw

        path = Path(args.figure)
        with Progress(f"drawing {path.name}"):
            path.parent.mkdir(parents=True, exist_ok=True)
            draw.save(draw.draw_cycle(cycle, Cs=args.cs), path)
        print(f"figure written to {path}", file=sys.stderr)
    bad = np.flatnonzero(~cycle.valid)
    if len(bad):
        i = bad[0]
        print(f"graphkin: error: {problem.name}: {len(bad)} of {cycle.n} positions have no solution, the first at"
              f" {position_text(problem, cycle.q[i])}: {cycle.analysis.reason(i)}", file=sys.stderr)
        return 2
    return 0
