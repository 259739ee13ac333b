"""``graphkin flywheel FILE``: size a flywheel from a turning-moment diagram alone (no mechanism).

::

    graphkin flywheel engine.toml           # the energy table, E, I_s (or C_s), speed and acceleration extremes
    graphkin flywheel engine.toml --json    # the same as JSON, SI units (docs/json.md)

The file format is in ``docs/problem-files.md`` ("Flywheel files"). Bad input
is a :class:`graphkin.errors.GraphkinError`, which ``graphkin``'s ``main``
prints as one line with exit code 2.
"""

from __future__ import annotations

from graphkin.cli._common import DOCS


def add_parser(sub) -> None:
    """Add ``flywheel`` to the ``graphkin`` subcommands."""
    f = sub.add_parser("flywheel", help="size a flywheel from a turning-moment diagram (engine torque against angle), "
                       "no mechanism needed")
    f.add_argument("file", help=f"a flywheel file (TOML; see {DOCS}/problem-files.html, 'Flywheel files'), or a catalog "
                   "flywheel's name (graphkin list)")
    f.add_argument("--units", metavar="SI|US|FILE",
                   help="print in these units: SI (default), US (in, lbf, lbf·ft, rpm, hp) or a units file (TOML); "
                   f"with --json, the JSON states each field's unit ({DOCS}/problem-files.html#units-of-a-report)")
    f.add_argument("--json", action="store_true", help=f"print the result as JSON in SI units (schema: {DOCS}/json.html)")


def run(args) -> int:
    """Carry out ``graphkin flywheel``; returns the exit code."""
    from pathlib import Path

    from graphkin import catalog
    from graphkin.cycle.flywheel_file import load_flywheel
    from graphkin.files import json_text
    from graphkin.report import flywheel_data, format_flywheel
    from graphkin.report.in_units import flywheel_in
    from graphkin.units.systems import unit_system

    # A catalog name, unless a file of that name is here.
    units = unit_system(args.units)
    if not Path(args.file).exists() and args.file in catalog.flywheel_names():
        problem = load_flywheel(catalog.flywheel_path(args.file), name=args.file)
    else:
        problem = load_flywheel(args.file)
    fly = problem.size()
    data = flywheel_data(problem, fly)
    if args.json:
        print(json_text(data if units is None else flywheel_in(data, units)))
    else:
        print(format_flywheel(data, units))
    return 0


