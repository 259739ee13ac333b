"""``graphkin`` on the command line: ``list``, ``solve PROBLEM``, ``cycle PROBLEM``, ``flywheel FILE``, ``exercise ...``.

Bad input ends with a one-line message on stderr and exit code 2, never a
traceback.

A command imports only what it runs: numpy, the engine, matplotlib and pint
are imported inside the functions that need them, so that ``graphkin solve``
starts in about a tenth of a second (benchmarks/bench_cli.py).
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from graphkin.errors import GraphkinError


class _Parser(argparse.ArgumentParser):
    """argparse, but a mistake on the command line is one line on stderr like every other error."""

    def error(self, message):
        # argparse's own error prints the usage (several lines) first; the usage is one --help away.
        self.exit(2, f"graphkin: error: {message}; see '{self.prog} --help'\n")


def _parser() -> argparse.ArgumentParser:
    p = _Parser(prog="graphkin", description="Kinetostatics of planar machinery.")
    sub = p.add_subparsers(dest="command", required=True)
    sub.add_parser("list", help="list the catalog problems")
    s = sub.add_parser("solve", help="solve a problem: a catalog name or a TOML file")
    s.add_argument("problem", help="catalog name (see 'graphkin list') or path to a problem file")
    s.add_argument("--at", help="input position(s) with units, comma-separated, e.g. '124 deg,140 deg' or '200 mm'")
    s.add_argument("--json", action="store_true", help="print the result as JSON in SI units (schema: docs/json.md)")
    s.add_argument("--figure", metavar="FILE", help="write the side-by-side figure (.png, .svg or .pdf); "
                   "with several positions, one file each, numbered")
    s.add_argument("--steps", metavar="DIR", help="write the construction step by step, one PNG frame per step")
    c = sub.add_parser("cycle", help="a whole cycle: torque, peak joint forces, flywheel, joint-force index")
    c.add_argument("problem", help="catalog name (see 'graphkin list') or path to a problem file")
    c.add_argument("--n", type=int, help="number of equally spaced crank angles over one turn (crank drivers only; "
                   "default: the problem's own positions); a load that switches on and off adds a sample either side "
                   "of each switching angle")
    c.add_argument("--cs", type=float, metavar="CS", help="coefficient of speed fluctuation: size a flywheel, e.g. 0.05")
    c.add_argument("--json", action="store_true", help="print every array as JSON in SI units (schema: docs/json.md)")
    c.add_argument("--figure", metavar="FILE", help="write the cycle figure (.png, .svg or .pdf)")
    from graphkin.cli.exercise import add_parser
    from graphkin.cli.explore import add_parser as add_explore
    from graphkin.cli.flywheel import add_parser as add_flywheel
    from graphkin.cli.handout import add_parser as add_handout

    add_parser(sub)
    add_explore(sub)
    add_handout(sub)
    add_flywheel(sub)
    return p


def _positions(problem, text: str):
    import numpy as np

    from graphkin.units import to_si

    crank = problem.mechanism.driver.crank
    dim = "angle" if crank else "length"
    parts = text.split(",")
    if not text.strip() or any(not part.strip() for part in parts):
        raise GraphkinError(f"--at {text!r}: give one or more positions with units, separated by commas, e.g. "
                            + ("'124 deg,140 deg'" if crank else "'200 mm,250 mm'"))
    from graphkin.ranges import complaint

    q = np.array([to_si(part.strip(), dim, field="--at", file="command line") for part in parts])
    for x, part in zip(q, parts):
        why = complaint(x, "angle" if crank else "coordinate")
        if why:
            raise GraphkinError(f"--at: {part.strip()!r} {why}")
    return q


def _check_outputs(figure=None, steps=None) -> None:
    """Refuse a figure or step folder that cannot be written, before any work is done."""
    from graphkin.files import check_destination, check_folder

    if figure:
        if Path(figure).suffix.lower() not in (".png", ".svg", ".pdf"):
            raise GraphkinError(f"--figure {figure}: the file must end in .png, .svg or .pdf")
        check_destination(figure, "--figure")
    if steps:
        check_folder(steps, "--steps")


def _list() -> int:
    from graphkin import catalog

    for name in catalog.names():
        problem = catalog.load(name)
        print(f"{name:<24}{problem.title}")
        print(f"{'':<24}family: {catalog.family(name)}")
        print(f"{'':<24}{problem.source}")
    print("\nflywheels (graphkin flywheel NAME):")
    for name in catalog.flywheel_names():
        from graphkin.cycle.flywheel_file import load_flywheel

        fly = load_flywheel(catalog.flywheel_path(name), name=name)
        print(f"{name:<24}{fly.title}")
        print(f"{'':<24}{fly.source}")
    return 0


def _solve(args) -> int:
    import numpy as np

    from graphkin import catalog, report
    from graphkin.files import json_text

    _check_outputs(args.figure, args.steps)
    problem = catalog.load(args.problem)
    result = problem.solve(_positions(problem, args.at) if args.at is not None else None)
    graphical = report.constructions(result)
    if args.json:
        print(json_text(report.solution(problem, result, graphical)))
    else:
        print(report.format_solution(problem, result, graphical))
    if args.figure or args.steps:
        _figures(problem, result, graphical, args.figure, args.steps, sys.stderr if args.json else sys.stdout)
    bad = np.flatnonzero(~result.valid)
    if len(bad):
        # One line, however many positions fail: the first names the position and the reason.
        i = bad[0]
        more = f" (and {len(bad) - 1} more of the {result.n} positions)" if len(bad) > 1 else ""
        print(f"graphkin: error: {problem.name}: {position_text(problem, result.kinematics.q[i])}: "
              f"{result.reason(i)}{more}", file=sys.stderr)
    return 2 if len(bad) else 0


def position_text(problem, q) -> str:
    """``θ = 89.99999999999°`` or ``s = 499.99 mm``: as many digits as name the position (a dead point's neighbour)."""
    from graphkin.notation import position_text as text

    return text(q, problem.mechanism.driver.crank)


PROGRESS_DELAY = 1.0
"""Work that takes longer than this [s] shows its progress on stderr."""


def _figures(problem, result, graphical, figure, steps, say):
    """Write the side-by-side figure(s) and the step frames; say which files went where.

    A batch that takes more than a second shows a tqdm progress bar on stderr,
    one tick per position drawn. Each file is written whole or not at all
    (:func:`graphkin.draw.save`); if the batch stops part-way (Ctrl-C, a full
    disk), the one-line message says how many files were written and the last.
    """
    from pathlib import Path

    from tqdm import tqdm

    from graphkin import draw

    many = result.n > 1
    drawn = [(i, c) for i, c in enumerate(graphical) if c is not None and c.valid]
    written: list[Path] = []
    try:
        for i, c in tqdm(drawn, desc="graphkin: drawing", unit="position", delay=PROGRESS_DELAY, file=sys.stderr,
                          leave=False, disable=None):  # disable=None: no bar when stderr is not a terminal
            tag = f"_{i + 1}" if many else ""
            if figure:
                path = Path(figure)
                path = path.with_name(f"{path.stem}{tag}{path.suffix}")
                path.parent.mkdir(parents=True, exist_ok=True)
                written.append(draw.save(draw.draw_solution(c, result), path))
                tqdm.write(f"figure written to {path}", file=say)
            if steps:
                folder = Path(steps)
                folder.mkdir(parents=True, exist_ok=True)
                frames = []
                for k, fig in enumerate(draw.draw_steps(c), start=1):
                    frames.append(draw.save(fig, folder / f"{Path(problem.name).stem}{tag}_step{k:02d}.png"))
                    written.append(frames[-1])
                tqdm.write(f"{len(frames)} construction steps written to {folder}/ "
                           f"({frames[0].name} … {frames[-1].name})" if frames else
                           f"no construction steps to write for position {i + 1}", file=say)
    except KeyboardInterrupt:
        raise KeyboardInterrupt(_batch_note(written)) from None
    except OSError as exc:
        where = exc.filename or (figure or steps)
        raise GraphkinError(f"{where}: cannot be written ({exc.strerror or exc}); {_batch_note(written)}") from None
    except GraphkinError as exc:
        raise GraphkinError(f"{exc}; {_batch_note(written)}") from None


def _batch_note(written) -> str:
    """``"3 files were written before it stopped, the last build/out_3.png"``, or that none were."""
    if not written:
        return "no file was written"
    return (f"{len(written)} file{'s' * (len(written) != 1)} {'were' if len(written) != 1 else 'was'} written "
            f"before it stopped, the last {written[-1]}")


def _cycle(args) -> int:
    import numpy as np

    from graphkin import catalog
    from graphkin.cycle import sweep
    from graphkin.cycle.flywheel import check_Cs
    from graphkin.files import json_text
    from graphkin.ranges import MAX_POSITIONS
    from graphkin.report import cycle_data, format_cycle

    _check_outputs(args.figure)
    if args.cs is not None:
        check_Cs(args.cs, "--cs")
    if args.n is not None and not 2 <= args.n <= MAX_POSITIONS:
        raise GraphkinError(f"--n {args.n}: n must be a whole number of positions from 2 to {MAX_POSITIONS:,} "
                            "(1° steps need 360, 0.01° steps 36,000)")
    problem = catalog.load(args.problem)
    if args.n is not None and not problem.mechanism.driver.crank:
        raise GraphkinError(f"{problem.name}: --n: the driver is a slider, so there is no turn to divide into "
                            "positions; leave out --n to sweep the problem's own positions")
    with _Progress(f"sweeping {problem.name}"):
        cycle = sweep(problem, args.n)
        why = cycle.why_no_flywheel() if args.cs is not None else None
        if why:
            raise GraphkinError(f"{problem.name}: --cs {args.cs:g}: {why}")
        data = cycle_data(cycle, args.cs)
    if args.json:
        print(json_text(data))
    else:
        print(format_cycle(cycle, data))
    if args.figure:
        from graphkin import draw

        path = Path(args.figure)
        with _Progress(f"drawing {path.name}"):
            path.parent.mkdir(parents=True, exist_ok=True)
            draw.save(draw.draw_cycle(cycle, Cs=args.cs), path)
        print(f"figure written to {path}", file=sys.stderr if args.json else sys.stdout)
    bad = np.flatnonzero(~cycle.valid)
    if len(bad):
        i = bad[0]
        print(f"graphkin: error: {problem.name}: {len(bad)} of {cycle.n} positions have no solution, the first at"
              f" {position_text(problem, cycle.q[i])}: {cycle.analysis.reason(i)}", file=sys.stderr)
        return 2
    return 0


class _Progress:
    """A one-line elapsed-time report on stderr for one call that takes more than a second.

    A sweep is one vectorised call with no iterations to count, so tqdm (used
    for batches of figures, :func:`_figures`) has nothing to tick; this shows
    the time instead.

    A background thread writes ``graphkin: LABEL… 1.2 s`` over itself until the
    work is done, then ends the line with the total time; nothing at all is
    written if the work is done within ``delay`` seconds.
    """

    def __init__(self, label: str, delay: float | None = None, every: float = 0.25, stream=None):
        self.label, self.every = label, every
        self.delay = PROGRESS_DELAY if delay is None else delay
        self.stream = stream or sys.stderr
        self.shown = False

    def __enter__(self):
        import threading
        import time

        self._time = time.perf_counter
        self._start = self._time()
        self._done = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()
        return self

    def _run(self):
        if self._done.wait(self.delay):
            return
        try:
            # A log file gets no "\r" updates four times a second: the bar is for a person at a terminal.
            if not self.stream.isatty():
                return
        except (AttributeError, ValueError):
            return
        while not self._done.is_set():
            self._write(f"\rgraphkin: {self.label}… {self._time() - self._start:.1f} s")
            self._done.wait(self.every)

    def _write(self, text):
        try:
            self.stream.write(text)
            self.stream.flush()
            self.shown = True
        except (OSError, ValueError):  # stderr closed: no progress, no error
            pass

    def __exit__(self, *exc):
        self._done.set()
        self._thread.join()
        if self.shown:
            self._write(f"\rgraphkin: {self.label}: {self._time() - self._start:.1f} s\n")
        return False


def _one_line_warnings() -> None:
    """Print graphkin's warnings as ``graphkin: warning: ...``, one line each, not Python's two-line form."""
    import warnings

    from graphkin.errors import GraphkinWarning

    default = warnings.showwarning

    def show(message, category, filename, lineno, file=None, line=None):
        if issubclass(category, GraphkinWarning):
            print(f"graphkin: warning: {message}", file=sys.stderr)
        else:
            default(message, category, filename, lineno, file, line)

    warnings.showwarning = show


def _single_threaded_blas() -> None:
    """Load numpy with one OpenBLAS thread, unless numpy is loaded already or the user chose a number.

    OpenBLAS starts a thread per core and allocates its buffers when numpy is
    imported: ~0.1 s of a command's start on a busy 2-core machine, for
    linear algebra on 9 x 9 matrices that never uses a second thread. The
    variable is put back afterwards, so programs the command starts (a
    notebook server, the exercise workers) get the user's environment.
    """
    key = "OPENBLAS_NUM_THREADS"
    if "numpy" in sys.modules or any(k in os.environ for k in (key, "GOTO_NUM_THREADS", "OMP_NUM_THREADS")):
        return
    os.environ[key] = "1"
    try:
        import numpy  # noqa: F401
    except ImportError:  # pragma: no cover - numpy is a dependency; the command itself will say what is missing
        pass
    finally:
        os.environ.pop(key, None)


def main(argv=None) -> int:
    """Entry point of the ``graphkin`` command; returns the exit code (2 for bad input, 130 for Ctrl-C)."""
    try:
        args = _parser().parse_args(argv)
    except SystemExit as exc:  # --help, or a mistake argparse caught: its message is already printed
        return exc.code if isinstance(exc.code, int) else 2
    except KeyboardInterrupt:
        print("graphkin: interrupted", file=sys.stderr)
        return 130
    _single_threaded_blas()  # after parsing: --help and a mistyped option need no numpy
    _one_line_warnings()
    try:
        if args.command == "cycle":
            return _cycle(args)
        if args.command == "exercise":
            from graphkin.cli.exercise import run

            return run(args)
        if args.command == "handout":
            from graphkin.cli.handout import run as handout

            return handout(args)
        if args.command == "explore":
            from graphkin.cli.explore import run as explore

            return explore(args)
        if args.command == "flywheel":
            from graphkin.cli.flywheel import run as flywheel

            return flywheel(args)
        return _list() if args.command == "list" else _solve(args)
    except GraphkinError as exc:
        print(f"graphkin: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # output piped into `head`: not an error of ours
        sys.stderr.close()
        return 0
    except KeyboardInterrupt as exc:
        # Every file is written to a temporary file and moved into place, so Ctrl-C leaves none half-written;
        # a batch adds which files it had written (:func:`_figures`).
        print("graphkin: interrupted" + (f": {exc.args[0]}" if exc.args and exc.args[0] else ""), file=sys.stderr)
        return 130
    except OSError as exc:
        # A write that passed the checks made before the work (a full disk, a folder removed meanwhile).
        where = f"{exc.filename}: " if exc.filename else ""
        print(f"graphkin: error: {where}{exc.strerror or exc}", file=sys.stderr)
        return 2


