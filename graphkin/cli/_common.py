"""What every command shares: the parser class, input positions, output checks, progress and the process set-up."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from graphkin.errors import GraphkinError

DOCS = "https://graphkin.github.io/graphkin/docs"
"""The guide on the documentation site (``make docs``): docs/X.md is ``DOCS/X.html``; the help points into it."""


class Parser(argparse.ArgumentParser):
    """argparse, but a mistake on the command line is one line on stderr like every other error."""

    def error(self, message):
        # argparse's own error prints the usage (several lines) first; the usage is one --help away.
        self.exit(2, f"graphkin: error: {message}; see '{self.prog} --help'\n")


def positions(problem, text: str):
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


def check_outputs(figure=None, steps=None) -> None:
    """Refuse a figure or step folder that cannot be written, before any work is done."""
    from graphkin.files import check_destination, check_folder

    if figure:
        if Path(figure).suffix.lower() not in (".png", ".svg", ".pdf"):
            raise GraphkinError(f"-o {figure}: the figure's file must end in .png, .svg or .pdf")
        check_destination(figure, "-o")
    if steps:
        check_folder(steps, "--steps")


def position_text(problem, q) -> str:
    """``θ = 89.99999999999°`` or ``s = 499.99 mm``: as many digits as name the position (a dead point's neighbour)."""
    from graphkin.notation import position_text as text

    return text(q, problem.mechanism.driver.crank)


PROGRESS_DELAY = 1.0
"""Work that takes longer than this [s] shows its progress on stderr."""


def batch_note(written) -> str:
    """``"3 files were written before it stopped, the last build/out_3.png"``, or that none were."""
    if not written:
        return "no file was written"
    return (f"{len(written)} file{'s' * (len(written) != 1)} {'were' if len(written) != 1 else 'was'} written "
            f"before it stopped, the last {written[-1]}")


class Progress:
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


def one_line_warnings() -> None:
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


def single_threaded_blas() -> None:
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
