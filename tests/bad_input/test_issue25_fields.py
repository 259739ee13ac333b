"""Bad input in the fields issue 25 added (gears on an arm, springs, pressures, powers, the unknown effort, the
book's input conventions, the forward step, --units): one line on stderr naming the file and the field, exit 2.

Each case edits a small valid problem file; :func:`edit` asserts that the text it replaces is there, so no case
can pass by testing an unchanged file.
"""

from __future__ import annotations

import pytest

from graphkin.cli import main
from tests.bad_input.test_catalogue import edit, one_error_line

EPICYCLIC = '''title = "Planet on an arm in a fixed annulus"
[frame]
points = { O = ["0 mm", "0 mm"] }
[[links]]
number = 2
points = { O = ["0 mm", "0 mm"], C = ["90 mm", "0 mm"] }
mass = "0 kg"
[[links]]
number = 3
points = { C = ["0 mm", "0 mm"] }
mass = "0 kg"
[[joints]]
type = "revolute"
links = [1, 2]
point = "O"
[[joints]]
type = "revolute"
links = [2, 3]
point = "C"
[[joints]]
type = "gear"
links = [1, 3]
centers = ["O", "C"]
radii = ["150 mm", "60 mm"]
internal = true
[driver]
type = "crank"
link = 2
theta = "30 deg"
omega = "100 rpm"
[[loads]]
type = "torque"
link = 3
torque = "10 N*m"
'''

BASES = {"epicyclic": EPICYCLIC}

P = pytest.param
CASES = [
    P("epicyclic", "internal = true", "internal = \"yes\"", ["joints[2].internal", "true"], id="internal-not-bool"),
    P("epicyclic", "radii = [\"150 mm\", \"60 mm\"]", "radii = [\"150 mm\", \"50 mm\"]",
      ["joints[2].radii", "centre distance"], id="internal-radii-distance"),
    P("epicyclic", "radii = [\"150 mm\", \"60 mm\"]", "radii = [\"60 mm\", \"60 mm\"]",
      ["joints[2].radii", "annulus larger"], id="internal-equal-radii"),
    P("epicyclic", "centers = [\"O\", \"C\"]", "centers = [\"O\", \"Q\"]", ["joints[2]", "Q"], id="gear-centre-unknown"),
]


@pytest.mark.parametrize("base, old, new, named", CASES)
def test_problem_file(tmp_path, capsys, base, old, new, named):
    path = tmp_path / "bad.toml"
    path.write_text(edit(BASES[base], old, new), encoding="utf-8")
    code = main(["solve", str(path)])
    out, err = capsys.readouterr()
    assert code == 2
    one_error_line(err, str(path), *named)


def test_the_base_files_solve(tmp_path, capsys):
    for name, text in BASES.items():
        path = tmp_path / f"{name}.toml"
        path.write_text(text, encoding="utf-8")
        assert main(["solve", str(path)]) == 0, capsys.readouterr().err
        capsys.readouterr()
