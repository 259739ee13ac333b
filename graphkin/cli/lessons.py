"""``graphkin lessons DIR``: copy the lesson notebooks into a folder, for a course to hand out.

::

    graphkin lessons course/lessons           # the lessons, 01_... to 12_..., without outputs
    graphkin lessons course/lessons --force   # replace the lessons already there (other files stay)

docs/hub.md shows how a class gets them on a JupyterHub (nbgitpuller). A folder that is a file, lies under
a file, cannot be written or already holds the lessons is refused in one line before anything is written.
"""

from __future__ import annotations

import sys

from graphkin.cli._common import DOCS


def add_parser(sub) -> None:
    """Add ``lessons`` to the ``graphkin`` subcommands."""
    p = sub.add_parser("lessons", help="copy the lesson notebooks into a folder, for a course")
    p.add_argument("folder", metavar="DIR", help="the folder to copy them into (made if missing)")
    p.add_argument("--force", action="store_true",
                   help="replace lessons of the same names already in DIR (other files there are left alone)")


def run(args) -> int:
    """Carry out ``graphkin lessons``; returns the exit code."""
    from graphkin.catalog.lessons import copy_lessons

    written = copy_lessons(args.folder, force=args.force)
    print(f"{len(written)} lessons written to {args.folder} ({written[0].name} to {written[-1].name}); "
          f"next: jupyter lab {args.folder}, or for a JupyterHub {DOCS}/hub.html", file=sys.stderr)
    return 0
