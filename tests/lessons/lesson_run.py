"""Run a lesson's cells as a student's Run All does, and keep what they computed, for the tests to read."""

from __future__ import annotations

import re
from pathlib import Path

import jupytext

LESSONS = Path(__file__).resolve().parents[2] / "lessons"


def run_lesson(stem: str) -> dict:
    """Every code cell of ``lessons/<stem>.py``, hidden ones too, in order, in one namespace; returns it.

    IPython's magics (``%matplotlib inline``) are the only lines that are not Python; they are skipped.
    """
    nb = jupytext.read(LESSONS / f"{stem}.py")
    ns: dict = {"__name__": f"lesson_{stem}"}
    for k, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        source = "\n".join("" if re.match(r"\s*%", line) else line for line in cell.source.splitlines())
        exec(compile(source, f"{stem}.py, cell {k + 1}", "exec"), ns)  # noqa: S102 - the lesson's own code
    return ns
