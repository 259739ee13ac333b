"""``graphkin`` on the command line: ``graphkin list``, ``graphkin solve PROBLEM``.

Bad input ends with a one-line message on stderr and exit code 2, never a
traceback.
"""

from __future__ import annotations

import argparse
import json
import math
import sys

import numpy as np

from .errors import GraphkinError


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="graphkin", description="Kinetostatics of planar machinery.")
    sub = p.add_subparsers(dest="command", required=True)
    sub.add_parser("list", help="list the catalog problems")
    s = sub.add_parser("solve", help="solve a problem: a catalog name or a TOML file")
    s.add_argument("problem", help="catalog name (see 'graphkin list') or path to a problem file")
    s.add_argument("--at", help="input position(s) with units, comma-separated, e.g. '124 deg,140 deg' or '200 mm'")
    s.add_argument("--json", action="store_true", help="print the result as JSON in SI units (schema: docs/json.md)")
    s.add_argument("--figure", metavar="FILE", help="write the side-by-side figure (.png, .svg or .pdf); "
                   "with several positions, one file each, numbered")
    s.add_argument("--steps", metavar="DIR", help="write the construction step by step, one PNG frame per step")
    return p


def _positions(problem, text: str):
    from .units import to_si

    dim = "angle" if problem.mechanism.driver.kind == "crank" else "length"
    return np.array([to_si(part.strip(), dim, field="--at", file="command line") for part in text.split(",")])


def _list() -> int:
    from . import catalog

    for name in catalog.names():
        problem = catalog.load(name)
        print(f"{name:<24}{problem.title}")
        print(f"{'':<24}{problem.source}")
    return 0


def _solve(args) -> int:
    from . import catalog, report

    problem = catalog.load(args.problem)
    result = problem.solve(_positions(problem, args.at) if args.at else None)
    graphical = report.constructions(result)
    if args.json:
        print(json.dumps(report.solution(problem, result, graphical), indent=2, ensure_ascii=False))
    else:
        print(report.format_solution(problem, result, graphical))
    if args.figure or args.steps:
        _figures(problem, result, graphical, args.figure, args.steps, sys.stderr if args.json else sys.stdout)
    bad = np.flatnonzero(~result.valid)
    for i in bad:
        q = result.kinematics.q[i]
        where = f"θ = {math.degrees(q):.6g}°" if problem.mechanism.driver.kind == "crank" else f"s = {q * 1e3:.6g} mm"
        print(f"graphkin: error: {problem.name}: {where}: {result.reason(i)}", file=sys.stderr)
    return 2 if len(bad) else 0


def _figures(problem, result, graphical, figure, steps, say):
    """Write the side-by-side figure(s) and the step frames; say where they went."""
    from pathlib import Path

    from . import draw

    many = result.n > 1
    for i, c in enumerate(graphical):
        if c is None or not c.valid:
            continue
        tag = f"_{i + 1}" if many else ""
        if figure:
            path = Path(figure)
            path = path.with_name(f"{path.stem}{tag}{path.suffix}")
            if path.suffix.lower() not in (".png", ".svg", ".pdf"):
                raise GraphkinError(f"--figure {figure}: the file must end in .png, .svg or .pdf")
            path.parent.mkdir(parents=True, exist_ok=True)
            draw.save(draw.draw_solution(c, result), path)
            print(f"figure written to {path}", file=say)
        if steps:
            folder = Path(steps)
            folder.mkdir(parents=True, exist_ok=True)
            for k, fig in enumerate(draw.draw_steps(c), start=1):
                draw.save(fig, folder / f"{Path(problem.name).stem}{tag}_step{k:02d}.png")
            print(f"{len(c.steps)} construction steps written to {folder}/", file=say)


def main(argv=None) -> int:
    """Entry point of the ``graphkin`` command."""
    args = _parser().parse_args(argv)
    try:
        return _list() if args.command == "list" else _solve(args)
    except GraphkinError as exc:
        print(f"graphkin: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # output piped into `head`: not an error of ours
        sys.stderr.close()
        return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
