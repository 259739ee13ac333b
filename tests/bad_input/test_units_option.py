"""Bad ``--units``: one line on stderr naming the option or the units file and its field, exit 2."""

from __future__ import annotations

import pytest

from graphkin.cli import main
from tests.bad_input.test_catalogue import one_error_line

FILES = [
    pytest.param('torque = "lbf"\n', ["torque", "a torque", "a force"], id="dimension"),
    pytest.param('force = "blorp"\n', ["force", "unknown unit", "blorp"], id="unknown-unit"),
    pytest.param('torque = "Nm"\n', ["torque", "N*m"], id="nm"),
    pytest.param('torque = "J"\n', ["torque"], id="energy-for-torque"),
    pytest.param('torc = "N*m"\n', ["torc", "not a kind"], id="unknown-kind"),
    pytest.param('base = "UK"\n', ["base", "SI", "US"], id="unknown-base"),
    pytest.param('torque = 5\n', ["torque", "a unit"], id="number"),
    pytest.param('torque = "5 N*m"\n', ["torque", "without a number"], id="number-in-string"),
    pytest.param('torque = ""\n', ["torque", "a unit"], id="empty"),
    pytest.param('angular_velocity = "Hz"\n', ["angular_velocity"], id="hz-for-speed"),
    pytest.param('torque = \n', ["not valid TOML"], id="not-toml"),
]


@pytest.mark.parametrize("text, named", FILES)
@pytest.mark.parametrize("command", [["solve", "engine_inch_bevan"], ["cycle", "engine_inch_bevan", "--n", "4"],
                                     ["flywheel", "three_cylinder"]])
def test_a_bad_units_file(capsys, tmp_path, text, named, command):
    f = tmp_path / "units.toml"
    f.write_text(text, encoding="utf-8")
    assert main([*command, "--units", str(f)]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    one_error_line(err, str(f), *named)


@pytest.mark.parametrize("value", ["metric", "imperial.toml", ""])
def test_neither_si_us_nor_a_file(capsys, value):
    assert main(["solve", "engine_inch_bevan", "--units", value]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    one_error_line(err, "--units", "SI, US or a units file")


def test_a_handout_checks_its_units_before_any_work(capsys, tmp_path):
    assert main(["handout", "engine_inch_bevan", "--units", "cgs", "-o", str(tmp_path / "h.md")]) == 2
    one_error_line(capsys.readouterr().err, "--units")
    assert not (tmp_path / "h.md").exists()
