"""``graphkin`` on the command line: one module per command, and :func:`main`.

=============  =====================================================================
``list``       the catalog (:mod:`graphkin.cli.listing`)
``solve``      both routes at given positions (:mod:`graphkin.cli.solve`)
``cycle``      a whole cycle (:mod:`graphkin.cli.cycle`)
``exercise``   per-student exercises and platforms (:mod:`graphkin.cli.exercise`)
``explore``    the explorer as a web page (:mod:`graphkin.cli.explore`)
``handout``    worked solutions and worksheets (:mod:`graphkin.cli.handout`)
``flywheel``   a flywheel from a turning-moment diagram (:mod:`graphkin.cli.flywheel`)
``animate``    the mechanism moving with its forces, as GIF, MP4 or HTML (:mod:`graphkin.cli.animate`)
``lessons``    the lesson notebooks copied for a course (:mod:`graphkin.cli.lessons`)
=============  =====================================================================

Each command module has ``add_parser(subparsers)`` and ``run(args) -> exit
code``. Bad input ends with a one-line message on stderr and exit code 2,
never a traceback. :func:`main` runs a command and returns its exit code (so
Python can call it); :func:`command` is the ``graphkin`` program itself, which
also turns a Ctrl-C after the command, while the process ends, into the same
one line and exit code 130.

The command line is the leaf of graphkin's layers: nothing in graphkin
imports it. A command imports only what it runs: numpy, the engine,
matplotlib and pint are imported inside the functions that need them, so
that ``graphkin solve`` starts in about a tenth of a second
(benchmarks/bench_cli.py).
"""

from __future__ import annotations

import argparse
import importlib
import os
import signal
import sys

from graphkin import __version__
from graphkin.cli._common import Parser, one_line_warnings, single_threaded_blas
from graphkin.errors import GraphkinError

COMMANDS = {"list": "listing", "solve": "solve", "cycle": "cycle", "study": "study", "exercise": "exercise",
            "explore": "explore", "handout": "handout", "flywheel": "flywheel", "animate": "animate",
            "lessons": "lessons"}
"""Each command and the module of :mod:`graphkin.cli` that carries it out, in the order ``graphkin --help`` lists
them; :func:`command_module` imports it."""


INTERRUPTED = 130
"""The exit code of a command ended by Ctrl-C (128 + SIGINT, as a shell reports it)."""


def command_module(name: str):
    """The module that carries out command ``name`` (a key of :data:`COMMANDS`), imported when first asked for."""
    return importlib.import_module(f"graphkin.cli.{COMMANDS[name]}")


def parser(command: str | None = None) -> argparse.ArgumentParser:
    """The ``graphkin`` command's parser, with every command's subparser, or only ``command``'s.

    A command line that starts with a command's name is parsed by that command's subparser alone (its options,
    its ``--help`` and its mistakes are the same whatever else the parser holds), so ``graphkin solve`` neither
    imports the other commands' modules nor builds their subparsers (benchmarks/README.md, "The guard's cost").
    """
    p = Parser(prog="graphkin", description="Kinetostatics of planar machinery.")
    p.add_argument("--version", action="version", version=f"graphkin {__version__}")
    sub = p.add_subparsers(dest="command", required=True)
    for name in COMMANDS if command is None else (command,):
        command_module(name).add_parser(sub)
    return p


def main(argv=None) -> int:
    """Entry point of the ``graphkin`` command; returns the exit code (2 for bad input, 130 for Ctrl-C)."""
    argv = sys.argv[1:] if argv is None else list(argv)
    try:
        args = parser(argv[0] if argv and argv[0] in COMMANDS else None).parse_args(argv)
    except SystemExit as exc:  # --help, or a mistake argparse caught: its message is already printed
        return exc.code if isinstance(exc.code, int) else 2
    except KeyboardInterrupt:
        print("graphkin: interrupted", file=sys.stderr)
        return INTERRUPTED
    single_threaded_blas()  # after parsing: --help and a mistyped option need no numpy
    one_line_warnings()
    try:
        return command_module(args.command).run(args)
    except GraphkinError as exc:
        print(f"graphkin: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # output piped into `head`: not an error of ours
        sys.stderr.close()
        return 0
    except KeyboardInterrupt as exc:
        # Every file is written to a temporary file and moved into place, so Ctrl-C leaves none half-written;
        # a batch adds which files it had written (graphkin.cli.solve).
        print("graphkin: interrupted" + (f": {exc.args[0]}" if exc.args and exc.args[0] else ""), file=sys.stderr)
        return INTERRUPTED
    except OSError as exc:
        # A write that passed the checks made before the work (a full disk, a folder removed meanwhile).
        where = f"{exc.filename}: " if exc.filename else ""
        print(f"graphkin: error: {where}{exc.strerror or exc}", file=sys.stderr)
        return 2


def command():
    """The ``graphkin`` program (``python -m graphkin``, the console script): :func:`main`, then exit.

    Ctrl-C is one line on stderr and exit code 130 wherever it lands. Inside a
    command :func:`main` says so; after it, while the process ends (threading
    joins its threads, atexit runs, modules are torn down), Python's own handler
    would print a KeyboardInterrupt traceback and the exit code would stay 0, so
    from the moment the command is done a Ctrl-C ends the process at once.
    Every file is already whole by then (written to a temporary file and moved).

    An interrupted command ends the process at once too. CPython (3.11) marks
    a KeyboardInterrupt raised inside ``exec`` of a string (dataclasses build
    their methods so, while matplotlib is imported) as unhandled, even when
    :func:`main` caught it, and at exit would kill the process by SIGINT
    (exit -2) instead of returning 130.
    """
    ours = signal.getsignal(signal.SIGINT) is signal.default_int_handler  # a background job's SIG_IGN is kept
    try:
        code = main()
    except KeyboardInterrupt:  # on the way out of main, past its own handlers
        code = None
    if ours:
        try:
            signal.signal(signal.SIGINT, _interrupted_late)
        except KeyboardInterrupt:  # one still pending is raised as the handler changes
            code = None
    if code is None:
        _interrupted_late()
    _flush()
    if code == INTERRUPTED:
        os._exit(code)
    sys.exit(code)


def _interrupted_late(signum=None, frame=None):
    """Say "interrupted" and end the process now: what was interrupted is the interpreter's own shutdown."""
    _flush()
    try:
        # A plain write to the descriptor: the signal may land while Python's stderr object is mid-write.
        os.write(2, b"graphkin: interrupted\n")
    except OSError:
        pass
    os._exit(INTERRUPTED)


def _flush():
    """Flush what the command printed (os._exit would drop it); a closed or busy stream is not our error."""
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError, RuntimeError, AttributeError):
            pass
