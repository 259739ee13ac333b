"""``graphkin solve PROBLEM``: both routes at the problem's positions (or ``--at``), as text or JSON, and figures."""

from __future__ import annotations

import sys

from graphkin.cli import _common
from graphkin.cli._common import DOCS, batch_note, check_outputs, position_text, positions
from graphkin.errors import GraphkinError


def add_parser(sub) -> None:
    """Add ``solve`` to the ``graphkin`` subcommands."""
    s = sub.add_parser("solve", help="solve a problem: a catalog name or a TOML file")
    s.add_argument("problem", help="catalog name (see 'graphkin list') or path to a problem file")
    s.add_argument("--at", help="input position(s) with units, comma-separated, e.g. '124 deg,140 deg' or '200 mm'")
    s.add_argument("--json", action="store_true", help=f"print the result as JSON in SI units (schema: {DOCS}/json.html)")
    s.add_argument("--units", metavar="SI|US|FILE",
                   help="print in these units: SI (default: mm, deg, N, N·m, rad/s), US (in, deg, lbf, lbf·ft, rpm) or a "
                   f"units file (TOML, e.g. torque = \"lbf*in\"); with --json, the JSON states each field's unit "
                   f"({DOCS}/problem-files.html#units-of-a-report)")
    s.add_argument("-o", "--output", "--figure", dest="figure", metavar="FILE",
                   help="write the side-by-side figure (.png, .svg or .pdf); over the problem's own positions, one "
                   "figure, at the position where the driving torque or force is largest in size (named as it is "
                   "written); with --at or --every-position, one file per position, numbered (--figure is the older "
                   "name)")
    s.add_argument("--steps", metavar="DIR", help="write the construction step by step, one PNG frame per step, at the "
                   "positions -o draws")
    s.add_argument("--every-position", dest="every", action="store_true",
                   help="with -o or --steps over the problem's own positions (a whole cycle: 180 figures for the "
                   "strip cutter), draw every position, not only the one of largest driving effort")
    s.add_argument("--motion-polygons", dest="polygons", action="store_true",
                   help="with -o/--figure, also write the velocity and acceleration polygons to scale "
                        "(1 mm = X m/s, 1 mm = Y m/s²), as FILE_polygons; with --steps, their steps too; with "
                        "--json, each position's polygons and instant centres as graphical_kinematics, every step in full")


def run(args) -> int:
    """Carry out ``graphkin solve``; returns the exit code (2 if a position has no solution)."""
    import numpy as np

    from graphkin import catalog, report
    from graphkin.files import json_text
    from graphkin.report.in_units import solution_in
    from graphkin.units.systems import unit_system

    check_outputs(args.figure, args.steps)
    if args.polygons and not (args.figure or args.steps or args.json):
        raise GraphkinError("--motion-polygons draws beside the figure or the steps, or details the JSON: give "
                            "-o FILE, --steps DIR or --json too")
    if args.every and not (args.figure or args.steps):
        raise GraphkinError("--every-position chooses the positions -o or --steps draws: give -o FILE or --steps DIR "
                            "too")
    units = unit_system(args.units)
    problem = catalog.load(args.problem)
    result = problem.solve(positions(problem, args.at) if args.at is not None else None)
    graphical = report.constructions(result)
    # A position where the two routes disagree is not valid: neither answer can be trusted there.
    result = report.cross_check(result, graphical)
    if args.json:
        # The velocity and acceleration polygons of every position cost a quarter of `solve --json` again (the
        # strip cutter's 180 positions: benchmarks/README.md) and nearly double its size: only --motion-polygons
        # asks for them, with every step in full.
        kinematic = report.kinematic_constructions(result.kinematics) if args.polygons else None
        data = report.solution(problem, result, graphical, kinematic, kinematic_steps=True)
        print(json_text(data if units is None else solution_in(data, units)))
    else:
        print(report.format_solution(problem, result, graphical, units))
    if args.figure or args.steps:
        every = args.every or args.at is not None
        _figures(problem, result, graphical, args.figure, args.steps, polygons=args.polygons, every=every)
    bad = np.flatnonzero(~result.valid)
    if len(bad):
        # One line, however many positions fail: the first names the position and the reason.
        i = bad[0]
        more = f" (and {len(bad) - 1} more of the {result.n} positions)" if len(bad) > 1 else ""
        print(f"graphkin: error: {problem.name}: {position_text(problem, result.kinematics.q[i])}: "
              f"{result.reason(i)}{more}", file=sys.stderr)
    return 2 if len(bad) else 0


def _figures(problem, result, graphical, figure, steps, *, polygons=False, every=True):
    """Write the side-by-side figure(s) and the step frames; say which files went where.

    With ``every`` false and several positions (the problem's own: often a
    whole cycle, 180 figures and minutes of drawing), only the position of
    largest driving effort is drawn, to the file asked for, and one line says
    which it is and how to have them all.

    A batch that takes more than a second shows a tqdm progress bar on stderr,
    one tick per position drawn. Each file is written whole or not at all
    (:func:`graphkin.draw.save`); if the batch stops part-way (Ctrl-C, a full
    disk), the one-line message says how many files were written and the last.
    """
    from pathlib import Path

    from tqdm import tqdm

    from graphkin import draw
    from graphkin.graphical import construct_kinematics

    drawn = [(i, c) for i, c in enumerate(graphical) if c is not None and c.valid]
    many = result.n > 1 and every
    if result.n > 1 and not every and drawn:
        drawn = [_largest_effort(problem, result, drawn)]
    written: list[Path] = []
    try:
        for i, c in tqdm(drawn, desc="graphkin: drawing", unit="position", delay=_common.PROGRESS_DELAY, file=sys.stderr,
                          leave=False, disable=None):  # disable=None: no bar when stderr is not a terminal
            tag = f"_{i + 1}" if many else ""
            if figure:
                path = Path(figure)
                path = path.with_name(f"{path.stem}{tag}{path.suffix}")
                path.parent.mkdir(parents=True, exist_ok=True)
                written.append(draw.save(draw.draw_solution(c, result), path))
                tqdm.write(f"figure written to {path}", file=sys.stderr)
                if polygons:
                    motion = construct_kinematics(result.kinematics, i)
                    more = path.with_name(f"{path.stem}_polygons{path.suffix}")
                    written.append(draw.save(draw.draw_motion_polygons(motion), more))
                    tqdm.write(f"velocity and acceleration polygons written to {more} (1 mm = "
                               f"{motion.velocity_scale:g} m/s, 1 mm = {motion.acceleration_scale:g} m/s²)",
                               file=sys.stderr)
            if steps:
                folder = Path(steps)
                folder.mkdir(parents=True, exist_ok=True)
                frames = []
                if polygons:
                    # The polygons come first: they give the inertia loads the force construction starts from.
                    for k, fig in enumerate(draw.draw_motion_steps(construct_kinematics(result.kinematics, i)), 1):
                        frames.append(draw.save(fig, folder / f"{Path(problem.name).stem}{tag}_polygons{k:02d}.png"))
                        written.append(frames[-1])
                for k, fig in enumerate(draw.draw_steps(c), start=1):
                    frames.append(draw.save(fig, folder / f"{Path(problem.name).stem}{tag}_step{k:02d}.png"))
                    written.append(frames[-1])
                tqdm.write(f"{len(frames)} construction steps written to {folder}/ "
                           f"({frames[0].name} … {frames[-1].name})" if frames else
                           f"no construction steps to write for position {i + 1}", file=sys.stderr)
    except KeyboardInterrupt:
        raise KeyboardInterrupt(batch_note(written)) from None
    except OSError as exc:
        where = exc.filename or (figure or steps)
        raise GraphkinError(f"{where}: cannot be written ({exc.strerror or exc}); {batch_note(written)}") from None
    except GraphkinError as exc:
        raise GraphkinError(f"{exc}; {batch_note(written)}") from None


def _largest_effort(problem, result, drawn):
    """The ``(index, construction)`` of ``drawn`` where the driving effort is largest in size; say so on stderr.

    The position a teacher puts in front of a class from a whole cycle: where the
    motor (or the slider's actuator) works hardest, which in a machine that cuts,
    presses or lifts is inside the working stroke.
    """
    i, c = max(drawn, key=lambda pair: abs(result.effort[pair[0]]))
    print(f"graphkin: drawing position {i + 1} of {result.n} ({position_text(problem, result.kinematics.q[i])}), "
          f"where |{result.driver_name}| is largest; --every-position draws all {result.n}", file=sys.stderr)
    return i, c
