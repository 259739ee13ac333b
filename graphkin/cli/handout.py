"""``graphkin handout``: a worked-solution handout (PDF, HTML or Markdown) of a problem or a student's exercise.

::

    graphkin handout PROBLEM [--at POS] [--key | --blank [--from-motion]] [--detail compact|full] -o out.pdf|…
    graphkin handout EXERCISE --student ID [--secret S] [--key | --blank] -o out.pdf
    graphkin handout EXERCISE --roster roster.csv [--format pdf|html|md] [--key | --blank] -o DIR/

The destination and the format are checked before anything is computed.
Every failure (a bad file name, a folder that cannot be written, a typst
error, a missing font) is a :class:`graphkin.errors.GraphkinError`, which
``graphkin``'s ``main`` prints as one line with exit code 2.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

from graphkin.errors import GraphkinError


def add_parser(sub) -> None:
    """Add ``handout`` to the ``graphkin`` subcommands."""
    h = sub.add_parser("handout", help="a worked-solution handout (PDF, HTML or Markdown) of a problem, or a "
                       "student's exercise sheet and key")
    h.add_argument("source", metavar="PROBLEM|EXERCISE",
                   help="a catalog problem or problem file; with --student or --roster, an exercise")
    who = h.add_mutually_exclusive_group()
    who.add_argument("--student", metavar="ID", help="the student's id: their own variant of the exercise")
    who.add_argument("--roster", metavar="CSV", help="a CSV with a 'student' column: every student's sheet and key, "
                     "written into the folder -o")
    h.add_argument("--secret", help="the course secret (default: $GRAPHKIN_SECRET)")
    h.add_argument("--at", help="a problem's input position(s) to work out, with units, e.g. '124 deg' or "
                   "'200 mm' (default: the problem's own; over a whole cycle, where the driving effort peaks)")
    version = h.add_mutually_exclusive_group()
    version.add_argument("--key", action="store_true", help="everything: the worked solution (default for a problem)")
    version.add_argument("--blank", action="store_true", help="a worksheet: each link's motion and inertia loads "
                         "given, the free bodies to scale, room to draw the force polygons by hand (no answers); "
                         "with --from-motion, the sheet that starts from the input motion")
    h.add_argument("--from-motion", action="store_true", help="with --blank, for a problem: only the positions, the "
                   "input's motion (ω and α of the driving crank, or the driving slider's v and a), the masses and the "
                   "external "
                   "loads given; boxes for the velocity and acceleration polygons, a table to fill with each link's "
                   "ω, α, a_G and inertia loads, then the force polygons")
    h.add_argument("--detail", choices=("compact", "full"), default="compact",
                   help="a key as a textbook prints it (compact, the default), or every step walked through with "
                        "the problem's notes on its source (full)")
    h.add_argument("--cs", type=float, metavar="CS", help="coefficient of speed fluctuation of a whole cycle's "
                   "flywheel (default: the exercise's, else 0.05)")
    h.add_argument("--units", metavar="SI|US|FILE",
                   help="the answers' units: SI (default: N, N·m, mm), US (lbf, lbf·ft, in) or a units file (TOML); "
                   "the working stays in SI")
    h.add_argument("--format", choices=("pdf", "html", "md"), default=None,
                   help="with --roster: the files' format (default pdf)")
    h.add_argument("-o", "--output", required=True, metavar="FILE|DIR",
                   help="out.pdf, out.html or out.md; with --roster, a folder")


def _version(args) -> str | None:
    return "key" if args.key else "blank" if args.blank else None


def run(args) -> int:
    """Carry out ``graphkin handout``; returns the exit code."""
    from graphkin import handout

    if args.roster:
        if args.units:
            raise GraphkinError("--units is for one handout; a class's sheets and keys are in the exercise's units")
        if args.from_motion:
            raise GraphkinError("--from-motion is for a problem's worksheet; a class's sheets give what their "
                                "exercise's statement says")
        return _roster(args)
    if args.format:
        raise GraphkinError("--format is for --roster; for one handout the suffix of -o says it (.pdf, .html, .md)")
    if args.from_motion and not args.blank:
        raise GraphkinError("--from-motion is for a worksheet (--blank)" + (
            ", not a key: a key draws the polygons from the input motion already" if args.key else ": add --blank"))
    handout.check_output(args.output)
    if args.at and args.student:
        raise GraphkinError("--at: an exercise's position is part of the student's data; leave --at out")
    from graphkin.units.systems import unit_system

    units = unit_system(args.units)
    secret = _secret(args) if args.student else ""
    doc = handout.build(args.source, student=args.student, secret=secret, at=args.at, version=_version(args),
                        Cs=args.cs, detail=args.detail, units=units, from_motion=args.from_motion)
    moving = _moving(args, secret, units)
    written = handout.write({**doc, "scene": moving} if moving else doc, args.output)
    extra = f" and {len(written) - 1} figures beside it" if len(written) > 1 else ""
    print(f"{doc['subtitle'].lower()} written to {written[-1]}{extra}", file=sys.stderr)
    return 0


def _moving(args, secret: str, units):
    """The scene of an HTML key: the figure a student moves, beside the one printed to scale; None otherwise.

    Only a key has it: a worksheet or a student's sheet leaves the forces to be found, and the moving figure
    would show them. PDF and Markdown have no place for it.
    """
    if Path(args.output).suffix.lower() != ".html" or args.blank or (args.student and not args.key):
        return None
    from graphkin import catalog, exercises
    from graphkin.scene import scene

    problem = exercises.variant(args.source, args.student, secret).problem if args.student else \
        catalog.load(args.source)
    return scene(problem, units=units)


def _secret(args) -> str:
    secret = args.secret if args.secret is not None else os.environ.get("GRAPHKIN_SECRET", "")
    if not secret:
        print("graphkin: note: no course secret (--secret or GRAPHKIN_SECRET): students can compute these keys "
              "themselves", file=sys.stderr)
    return secret


def _roster(args) -> int:
    from graphkin.exercises.roster import read_roster
    from graphkin.handout.batch import make_roster

    folder = Path(args.output)
    if folder.exists() and not folder.is_dir():
        raise GraphkinError(f"-o {folder}: with --roster, -o is a folder (one sheet and one key per student), "
                            "but this is a file")
    if folder.suffix.lower() in (".pdf", ".html", ".md") and not folder.exists():
        raise GraphkinError(f"-o {folder}: with --roster, -o is a folder; choose the files' format with --format")
    if args.at:
        raise GraphkinError("--at: an exercise's position is part of each student's data; leave --at out")
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise GraphkinError(f"-o {folder}: cannot make the folder ({exc.strerror})") from None
    if not os.access(folder, os.W_OK):
        raise GraphkinError(f"-o {folder}: the folder cannot be written")
    students = read_roster(args.roster)
    # Read the exercise once here: a missing or malformed one fails now, not in every worker.
    from graphkin import exercises

    exercises.load(args.source)
    secret = _secret(args)
    versions = {"key": ("key",), "blank": ("blank",), None: ("sheet", "key")}[_version(args)]
    with _progress(len(students)) as bar:
        rows = make_roster(args.source, students, folder, secret=secret, versions=versions,
                           fmt=args.format or "pdf", Cs=args.cs, progress=bar.update)
    failed = [(st, err) for st, _, err in rows if err]
    files = sum(len(w) for _, w, _ in rows)
    print(f"{files} files written to {folder}/ for {len(rows) - len(failed)} of {len(rows)} students",
          file=sys.stderr)
    for st, err in failed:
        print(f"graphkin: error: student {st}: {err}", file=sys.stderr)
    return 2 if failed else 0


def _progress(total: int):
    """A progress bar on stderr for a batch that takes more than a second (none when stderr is not a terminal)."""
    from tqdm import tqdm

    from graphkin.cli import _common

    return tqdm(total=total, desc="graphkin: handouts", unit="student", delay=_common.PROGRESS_DELAY, file=sys.stderr,
                leave=False, disable=None)
