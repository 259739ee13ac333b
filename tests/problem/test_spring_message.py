"""A spring whose ends meet (with a free length > 0) has no line of action: the position says which spring."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from graphkin import catalog
from graphkin.cli import main
from tests.bad_input.test_catalogue import one_error_line

FILE = Path(__file__).parent / "files" / "spring_ends_meet.toml"


def test_the_message_names_the_spring_and_its_ends(capsys):
    r = catalog.load(str(FILE)).solve()
    assert not r.valid[0] and r.valid[1]
    why = r.reason(0)
    assert "spring k" in why and "S and Q" in why and "50 mm" in why and "singular" not in why
    # At 30° the spring is 51.76 mm long: 1.76 mm stretched at 2 N/mm, a pull towards Q, balanced by T12.
    assert np.isfinite(r.effort[1]) and r.effort[1] > 0
    assert main(["solve", str(FILE)]) == 2
    one_error_line(capsys.readouterr().err, "θ = 0°", "spring k")
