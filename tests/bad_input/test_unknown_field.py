"""Bad ``[unknown]`` (the link whose effort the book asks for): one line naming the file and the field, exit 2."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.bad_input.test_catalogue import solve_refuses

GOOD = (Path(__file__).parents[1] / "problem" / "files" / "fourbar_unknown.toml").read_text(encoding="utf-8")
CASES = [
    pytest.param("[unknown]\nlink = 4", "[unknown]\nlink = 7", ["unknown.link", "no moving link", "2, 3, 4"],
                 id="no-such-link"),
    pytest.param("[unknown]\nlink = 4", "[unknown]\nlink = 1", ["unknown.link", "no moving link"], id="frame"),
    pytest.param("[unknown]\nlink = 4", "[unknown]\nlink = 2", ["unknown.link", "is the driver"], id="driver"),
    pytest.param("[unknown]\nlink = 4", "[unknown]\nlink = \"4\"", ["unknown.link"], id="link-text"),
    pytest.param("[unknown]\nlink = 4", "[unknown]\nname = \"T4\"", ["unknown", "link"], id="no-link"),
    pytest.param("[unknown]\nlink = 4", "[unknown]\nlink = 4\ntorque = \"5 N*m\"", ["unknown", "torque"],
                 id="unknown-key"),
    pytest.param("[unknown]\nlink = 4", "[unknown]\nlink = 4\nname = 4", ["unknown.name", "string"], id="name-number"),
    pytest.param("[unknown]\nlink = 4", "[unknown]\nlink = 4\nname = \"T2\"", ["unknown.name", "already"],
                 id="name-taken"),
    pytest.param("[unknown]\nlink = 4", "unknown = 4", ["unknown"], id="not-a-table"),
    pytest.param('[unknown]\nlink = 4', '[unknown]\nlink = 4\n[forward]\nI = "1 kg*m^2"\ntorque = "1 N*m"',
                 ["unknown", "forward step"], id="with-forward"),
]


@pytest.mark.parametrize("old, new, named", CASES)
def test_bad_unknown(capsys, tmp_path, old, new, named):
    assert GOOD.count(old) == 1
    solve_refuses(capsys, tmp_path, GOOD.replace(old, new), *named)
