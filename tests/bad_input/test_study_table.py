"""A bad ``[study]`` table is one line naming the file and the entry (``study.vary.links[1].mass``), exit 2.

The table is checked whenever the file is read, so ``graphkin solve`` names a bad entry as ``graphkin study`` does;
a value that reads but that the problem rejects is named by the entry that gave it.
"""

import pytest

from graphkin import catalog
from graphkin.cli import main

BASE = catalog.path("strip_cutter").read_text(encoding="utf-8")


def write(tmp_path, table: str) -> str:
    path = tmp_path / "cutter.toml"
    path.write_text(BASE + "\n[study]\n" + table + "\n", encoding="utf-8")
    return str(path)


def run(capsys, *args):
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def refused(capsys, tmp_path, table: str, named: str, words: str) -> None:
    """``graphkin study`` on a file with ``table`` stops with exit 2 and one line on stderr that begins with the
    file and ``named`` and says ``words``."""
    path = write(tmp_path, table)
    code, out, err = run(capsys, "study", path, "--n", "36")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert err.startswith(f"graphkin: error: {path}: {named}") and words in err


@pytest.mark.parametrize(("table", "field", "words"), [
    ('vary = { "links[1].mass" = "1..2 kg" }', "study.vary.links[1].mass", "FROM..TO UNIT:N"),
    ('vary = { "links[1].mass" = "1..2 kg:0" }', "study.vary.links[1].mass", "N = 0"),
    ('vary = { "links[1].mass" = "2..2 kg:3" }', "study.vary.links[1].mass", "would all be equal"),
    ('vary = { "links[1].mass" = [] }', "study.vary.links[1].mass", "a list of one or more values"),
    ('vary = { "links[1].mass" = 3 }', "study.vary.links[1].mass", "a list of one or more values"),
    ('vary = { "links[9].mass" = "1..2 kg:2" }', "study.vary.links[9].mass", "the problem has no links[9]"),
    ('vary = { "links[1]..mass" = "1..2 kg:2" }', "study.vary.links[1]..mass", "is not a field path"),
    ('vary = {}', "study.vary", "name one or more fields"),
    ('vary = "links[1].mass"', "study.vary", "must be a table"),
    ('n = 36', "study.vary", "is missing"),
    ('vary = { "links[1].mass" = "1..2 kg:2" }\nn = 1', "study.n", "at least 2"),
    ('vary = { "links[1].mass" = "1..2 kg:2" }\nn = "36"', "study.n", "whole number"),
    ('vary = { "links[1].mass" = "1..2 kg:2" }\nCs = 2', "study.Cs", "below 2"),
    ('vary = { "links[1].mass" = "1..2 kg:2" }\nrequire = ["I_s <= 1 kg*m^2"]', "study.require", "goes with best"),
    ('vary = { "links[1].mass" = "1..2 kg:2" }\nrequire = [3]', "study.require", "a list of limits"),
    ('vary = { "links[1].mass" = "1..2 kg:2" }\nbest = 3', "study.best", "must be a string"),
    ('vary = { "links[1].mass" = "1..2 kg:2" }\nbest_of = "I_s"', "study.best_of", "did you mean 'best'"),
])
@pytest.mark.parametrize("command", ["study", "solve"])
def test_a_bad_entry_is_one_line_naming_it(capsys, tmp_path, table, field, words, command):
    path = write(tmp_path, table)
    code, out, err = run(capsys, command, path)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert err.startswith(f"graphkin: error: {path}: {field}: ") and words in err


@pytest.mark.parametrize(("table", "field", "words"), [
    ('vary = { "links[1].mass" = "-2..2 kg:3" }', "study.vary.links[1].mass", "-2.0 kg"),
    ('vary = { "links[1].mass" = "1..2 m:2" }', "study.vary.links[1].mass", "expected a mass"),
    ('vary = { "links[1].mas" = "1..2 kg:2" }', "study.vary.links[1].mas", "unknown field"),
])
def test_a_value_the_problem_rejects_is_named_by_the_entry(capsys, tmp_path, table, field, words):
    refused(capsys, tmp_path, table, f"{field}: ", words)


@pytest.mark.parametrize(("table", "field", "words"), [
    ('vary = { "links[1].mass" = "1..2 kg:2" }\nbest = "torque"', "study.best", "no such figure of merit"),
    ('vary = { "links[1].mass" = "1..2 kg:2" }\nbest = "I_s"\nrequire = ["I_s <= 1 m"]', "study.require",
     "expected a moment of inertia"),
    ('vary = { "links[1].mass" = "1..2 kg:2" }\noptimize = "lessen I_s"', "study.optimize", "minimise FIGURE"),
])
def test_a_figure_the_study_has_not_is_named_by_the_entry(capsys, tmp_path, table, field, words):
    refused(capsys, tmp_path, table, field, words)
