"""A dead centre (``driver.from``) is found once per geometry: an exercise builds a problem for every draw."""

from __future__ import annotations

import copy
import tomllib

from graphkin import catalog
from graphkin.problem import books
from graphkin.problem.file import build_problem


def _tables():
    return tomllib.loads(catalog.path("gas_engine_khurmi").read_text(encoding="utf-8"))


def test_draws_of_one_engine_find_its_dead_centre_once(monkeypatch):
    calls = []
    real = books._dead_centre
    monkeypatch.setattr(books, "_dead_centre", lambda *a: calls.append(a[2]) or real(*a))
    books._DEAD_CENTRES.clear()
    angles = []
    for theta in ("20 deg", "45 deg", "160 deg"):
        t = _tables()
        t["driver"]["theta"] = theta
        t["driver"]["omega"] = "900 rpm"
        angles.append(float(build_problem(t, file=theta).q[0]))
    assert len(calls) == 1
    # Measured from the same dead centre: the angles differ by what the file's angles differ by.
    assert abs((angles[1] - angles[0]) - (25 * 3.141592653589793 / 180)) < 1e-12
    longer = _tables()
    crank = next(link for link in longer["links"] if link["number"] == longer["driver"]["link"])
    far = max(crank["points"], key=lambda p: abs(float(crank["points"][p][0].split()[0])))
    crank["points"][far] = [f"{float(crank['points'][far][0].split()[0]) * 1.1} mm", crank["points"][far][1]]
    build_problem(copy.deepcopy(longer), file="longer crank")
    assert len(calls) == 2  # another geometry: found again
