"""What ``graphkin`` loads before it runs a command: building the parser imports nothing heavy, and numpy starts
with one BLAS thread without changing the environment programs it starts see. Timings: ``benchmarks/bench_cli.py``."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]


def _python(code: str, **env) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO,
                          env={**os.environ, **env}, timeout=120)


def test_building_the_parser_imports_nothing_heavy():
    r = _python("import sys\n"
                "from graphkin.cli import parser as _parser\n"
                "_parser()\n"
                "print(sorted(m for m in ('numpy', 'pint', 'matplotlib', 'ipywidgets', 'graphkin.exercises', 'socket',"
                " 'subprocess') if m in sys.modules))")
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]"


def test_numpy_is_loaded_with_one_blas_thread_and_the_environment_is_put_back():
    code = ("import os, sys\n"
            "from graphkin.cli._common import single_threaded_blas as _single_threaded_blas\n"
            "_single_threaded_blas()\n"
            "print('numpy' in sys.modules, os.environ.get('OPENBLAS_NUM_THREADS'))")
    env = {k: v for k, v in os.environ.items() if k not in ("OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS",
                                                           "OMP_NUM_THREADS")}
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, env=env, timeout=60)
    assert r.stdout.split() == ["True", "None"], r.stderr
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, timeout=60,
                       env={**env, "OPENBLAS_NUM_THREADS": "2"})
    assert r.stdout.split()[1] == "2", r.stderr  # the user's choice stands


def test_every_page_the_help_points_to_is_a_page_of_the_guide():
    # `--help` names DOCS/X.html; the site is built from docs/X.md (docs/conf.py), so each must exist.
    import re

    from graphkin.cli import parser as _parser
    from graphkin.cli._common import DOCS

    def helps(p):
        yield p.format_help()
        for action in p._actions:
            if isinstance(action.choices, dict):  # a command's subcommands
                for sub in action.choices.values():
                    yield from helps(sub)

    text = " ".join(" ".join(h.split()) for h in helps(_parser()))
    pages = set(re.findall(re.escape(DOCS) + r"/([\w/-]+)\.html", text.replace(" ", "")))
    assert pages >= {"json", "problem-files"}, pages
    missing = sorted(p for p in pages if not (REPO / "docs" / f"{p}.md").exists())
    assert not missing, f"--help points to pages the site does not have: {missing}"


def test_solve_imports_no_cycle_and_no_other_command():
    # Issue 35 ("Keep"): `graphkin solve` reads no cycle (graphkin.report loads the reports of a cycle, a flywheel
    # and a study when first named), so neither the sweep nor a design study, its figures of merit or optimum; and
    # it imports no other command's module (graphkin.cli builds only the subparser of the command it runs).
    r = _python("import sys\n"
                "from graphkin.cli import main\n"
                "code = main(['solve', 'gearset'])\n"
                "print(code, sorted(m for m in sys.modules if m.startswith(('graphkin.cycle', 'graphkin.cli.', "
                "'graphkin.report.'))))")
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines()[-1] == ("0 ['graphkin.cli._common', 'graphkin.cli.solve', 'graphkin.report.in_units', "
                                         "'graphkin.report.polygons', 'graphkin.report.solution']")
    r = _python("import graphkin.cycle.sweep, graphkin.cycle as c\n"
                "from graphkin.cycle import study, Study\n"
                "print(callable(c.sweep) and not isinstance(c.sweep, type(c)), study.__module__, Study.__name__)")
    assert r.stdout.split() == ["True", "graphkin.cycle.studies", "Study"], r.stderr


def test_a_command_parsed_alone_is_parsed_as_by_the_whole_parser(capsys):
    # graphkin.cli.main builds only the subparser of the command a command line starts with: its help, its
    # defaults and its mistakes must be those of the whole parser.
    from graphkin.cli import COMMANDS, main, parser

    def sub(p, name):
        return next(a for a in p._actions if isinstance(a.choices, dict)).choices[name]

    whole = parser()
    for name in COMMANDS:
        alone = parser(name)
        assert sub(alone, name).format_help() == sub(whole, name).format_help(), name
        assert sub(alone, name).prog == f"graphkin {name}"
    assert vars(parser("solve").parse_args(["solve", "gearset", "--json"])) == vars(
        whole.parse_args(["solve", "gearset", "--json"]))
    assert main(["solve", "gearset", "--no-such-option"]) == 2
    assert capsys.readouterr().err == "graphkin: error: unrecognized arguments: --no-such-option; see 'graphkin --help'\n"
    assert main(["solv"]) == 2  # not a command: the whole parser says which are
    err = capsys.readouterr().err
    assert err.startswith("graphkin: error: argument command: invalid choice: 'solv' (choose from 'list', 'solve',")
