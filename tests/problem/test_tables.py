"""Tables as spreadsheets export them: read with Python's csv (delimiter found, quotes, trailing delimiter,
a decimal comma where the file declares it); every error still one line naming the file, field and line."""

from __future__ import annotations

import numpy as np
import pytest

from graphkin.errors import ProblemFileError
from graphkin.problem.tables import parse_table

COLUMNS = {"angle": "angle", "torque": "torque"}
EXPECTED_DEG = [0.0, 15.0, 30.0]
EXPECTED_NM = [0.0, 2800.5, 2090.0]


def _read(text, decimal="."):
    cols = parse_table(text, COLUMNS, file="engine.toml", field="driving.csv", shown="engine.csv", decimal=decimal)
    return np.degrees(cols["angle"]).tolist(), cols["torque"].tolist()


@pytest.mark.parametrize("text, decimal", [
    ("angle [deg], torque [N*m]\n0, 0\n15, 2800.5\n30, 2090\n", "."),
    ('"angle [deg]","torque [N*m]"\n"0","0"\n"15","2800.5"\n"30","2090"\n', "."),  # every field quoted
    ("angle [deg];torque [N*m]\n0;0\n15;2800,5\n30;2090\n", ","),  # a European spreadsheet's export
    ("angle [deg]\ttorque [N*m]\n0\t0\n15\t2800.5\n30\t2090\n", "."),  # tabs
    ("angle [deg],torque [N*m],\n0,0,\n15,2800.5,\n30,2090,\n", "."),  # a trailing comma on every line
    ("# cylinder 1\nangle [deg], torque [N*m]\n\n0, 0\n15, 2800.5\n# the peak\n30, 2090\n", "."),
    ("angle [deg]\ttorque [N*m]\n0\t0\n15\t2800,5\n30\t2090\n", ","),  # tabs and a decimal comma
])
def test_a_table_as_spreadsheets_write_it(text, decimal):
    angle, torque = _read(text, decimal)
    np.testing.assert_allclose(angle, EXPECTED_DEG, rtol=1e-15)
    assert torque == EXPECTED_NM


@pytest.mark.parametrize("text, decimal, words", [
    ("angle [deg];torque [N*m]\n0;0\n15;2800,5\n30;2090\n", ".", ["engine.csv line 3", "'2800,5'", 'decimal = ","']),
    ("angle [deg], torque [N*m]\n0, 0\n15, 2800.5, 7\n30, 2090\n", ".", ["line 3", "3 cells, the header 2"]),
    ("angle, torque\n0, 0\n15, 1\n", ".", ["line 1", "units in brackets"]),
    ("angle [deg], torque [N*m]\n0, 0\n", ".", ["1 row", "at least two"]),
    ("angle [deg], torque [N*m]\n0, 0\n15, x\n", ".", ["line 3", "torque 'x' is not a number"]),
    ("angle [deg], torque [N*m]\n0, 0\n15, inf\n", ".", ["line 3", "not a finite number"]),
])
def test_a_bad_table_is_one_line_naming_the_place(text, decimal, words):
    with pytest.raises(ProblemFileError) as info:
        _read(text, decimal)
    message = str(info.value)
    assert "\n" not in message and "engine.toml" in message and "driving.csv" in message
    for w in words:
        assert w in message, message


def test_the_decimal_field_is_read_and_checked(tmp_path):
    """``decimal = ","`` beside a load's csv reads the file's decimal commas; any other value is refused."""
    from graphkin import catalog
    from graphkin.problem import load_problem

    text = catalog.path("strip_cutter").read_text(encoding="utf-8")
    assert "[[loads]]" in text
    (tmp_path / "cut.csv").write_text("angle [deg];force [N]\n0;0\n124;0\n124,5;2000,0\n155,5;2000,0\n156;0\n359;0\n",
                                      encoding="utf-8")
    problem = tmp_path / "p.toml"
    base = text.split("[[loads]]")[0]
    load = ('[[loads]]\ntype = "force"\nlink = 3\npoint = "C"\ndirection = "90 deg"\ncsv = "cut.csv"\n'
            'decimal = "{}"\n')
    problem.write_text(base + load.format(","), encoding="utf-8")
    p = load_problem(problem)
    table = p.mechanism.loads[0].table
    assert np.degrees(table.q).tolist()[2] == pytest.approx(124.5) and table.value.tolist()[2] == 2000.0
    problem.write_text(base + load.format(";"), encoding="utf-8")
    with pytest.raises(ProblemFileError, match=r'loads\[0\]\.decimal: must be "\." or ","'):
        load_problem(problem)
