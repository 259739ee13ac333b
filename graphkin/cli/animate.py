"""``graphkin animate PROBLEM -o FILE``: the mechanism moving over one turn with its joint forces, as GIF, MP4 or HTML."""

from __future__ import annotations

import sys

from graphkin.cli import _common


def add_parser(sub) -> None:
    """Add ``animate`` to the ``graphkin`` subcommands."""
    a = sub.add_parser("animate", help="the mechanism moving over one turn with its joint forces (GIF, MP4, HTML)")
    a.add_argument("problem", help="catalog name (see 'graphkin list') or path to a problem file")
    a.add_argument("-o", "--output", metavar="FILE", required=True,
                   help="the animation: .gif, .mp4 (needs ffmpeg) or .html (one file, plays with no network); "
                   f"see {_common.DOCS}/graphical.html#animations")
    a.add_argument("--frames", type=_number(int), default=72, metavar="N",
                   help="frames over one turn of the crank (default 72: a frame every 5°)")
    a.add_argument("--fps", type=_number(float), default=24.0, metavar="F", help="frames per second (default 24)")
    a.add_argument("--polygons", action="store_true", help="draw each link's force polygon beside the mechanism")
    a.add_argument("--dpi", type=_number(float), default=100.0,
                   help="pixels per inch of a frame, 6.4 in wide (default 100: 640 px)")


def _number(kind):
    """argparse's type for a number; its error names the option (argparse adds which one)."""
    def convert(text):
        try:
            return kind(text)
        except ValueError:
            raise ValueError(text) from None

    convert.__name__ = "whole number" if kind is int else "number"
    return convert


def run(args) -> int:
    """Carry out ``graphkin animate``; returns the exit code."""
    from tqdm import tqdm

    from graphkin import catalog, draw
    from graphkin.draw.animation import check_frames
    from graphkin.draw.films import check_fps, check_path, write

    # Every option is checked before the problem is solved or a frame drawn.
    check_path(args.output, "-o")
    check_frames(args.frames)
    check_fps(args.fps)
    problem = catalog.load(args.problem)
    bar = tqdm(total=args.frames, desc="graphkin: drawing", unit="frame", delay=_common.PROGRESS_DELAY,
               file=sys.stderr, leave=False, disable=None)  # disable=None: no bar when stderr is not a terminal
    with bar:
        film = draw.animate(problem, frames=args.frames, fps=args.fps, polygons=args.polygons, dpi=args.dpi,
                            progress=bar.update)
    path = write(film, args.output, "-o")
    if film.gaps:
        # Written all the same: the frames that say where the linkage cannot close are worth showing.
        q, why = film.gaps[0]
        print(f"graphkin: warning: {problem.name}: {len(film.gaps)} of {len(film.frames)} frames have no solution, "
              f"the first at {_common.position_text(problem, q)}: {why}", file=sys.stderr)
    w, h = film.size
    print(f"{len(film.frames)} frames ({w} × {h} px, {film.fps:g} fps, forces at 1 mm = {film.scale:g} N) "
          f"written to {path}", file=sys.stderr)
    return 0
