"""The notebook explorer (graphkin.widgets): ``gk.explore`` is the browser-drawn one; what it shows at a position is
the matrix solution there; a slider driver that a file gives at one position is explored where it assembles; lazy
imports; ``graphkin explore``'s served notebook."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from dataclasses import replace

import numpy as np
import pytest

pytest.importorskip("anywidget")

import graphkin as gk  # noqa: E402
from graphkin import catalog  # noqa: E402
from graphkin.errors import GraphkinError  # noqa: E402
from graphkin.widgets import BrowserExplorer, explore  # noqa: E402
from graphkin.widgets.browser import nearest  # noqa: E402
from graphkin.widgets.positions import assembling_span, spread  # noqa: E402

SMALL = 36  # crank angles over the turn: keeps the tests fast


def _at(ex, i: int, xy) -> np.ndarray:
    return np.array(xy[2 * i:2 * i + 2], float)


@pytest.mark.parametrize("name,value", [("strip_cutter", 140.0), ("slider_crank_friction", 75.0),
                                        ("double_slider", -120.0), ("gearset", 30.0), ("single_link", 210.0)])
def test_the_position_set_from_python_shows_the_matrix_solution_there(name, value):
    """Norton's matrix method at the presolved position nearest the one asked for: what the browser draws there."""
    ex = explore(catalog.load(name), n=SMALL)
    assert isinstance(ex, BrowserExplorer)
    ex.position = value
    s, i = json.loads(ex.widget.scene), ex.widget.index
    q = s["input"]["values"][i]
    step = (360.0 / SMALL) if ex.crank else float(np.ptp(s["input"]["values"])) * 1e3 / (s["n"] - 1)
    assert abs(ex.position - value) <= step / 2 + 1e-9
    assert ex.position == pytest.approx(math.degrees(q) if ex.crank else q * 1e3)
    ref = ex.problem.solve(at=[q])
    # The scene rounds each value to its precision of its kind's scale (docs/json.md): forces of the largest force
    # of the cycle, torques of that force times the mechanism's size; one unit of rounding either way.
    force = max(float(np.nanmax(np.abs(np.array(f["analytical"], float)))) for f in s["forces"])
    tol = s["precision"] * force
    assert abs(s["effort"]["analytical"][i] - float(ref.effort[0])) <= tol * (1.0 if not ex.crank else s["size"])
    for f in s["forces"]:
        np.testing.assert_allclose(_at(ex, i, f["analytical"]), ref.force(f["of"], f["on"])[0], rtol=0, atol=tol)


def test_a_slider_driver_given_at_one_position_is_explored_where_it_assembles():
    p = catalog.load("double_slider")
    assert len(p.q) == 1
    ex = explore(p, n=SMALL)
    q = np.array(ex.scene["input"]["values"])
    lo, hi = assembling_span(p.at_speed(float(p.q_dot[0])), float(p.q[0]), SMALL)
    assert ex.scene["n"] == SMALL and q[0] == pytest.approx(lo) and q[-1] == pytest.approx(hi)
    assert ex.position == pytest.approx(q[np.argmin(abs(q - p.q[0]))] * 1e3)  # first shown: the file's position
    valid = np.array(ex.scene["valid"], bool)
    assert valid.any() and not valid.all()  # its dead ends are inside the span, with one step of margin
    assert all(r["reason"] for r in ex.scene["invalid"])
    limited = spread(p, 11, limits=(100.0, 300.0))
    assert limited.q == pytest.approx(np.linspace(0.1, 0.3, 11)) and np.all(limited.q_dot == p.q_dot[0])
    with pytest.raises(GraphkinError, match="high > low"):
        spread(p, 11, limits=(300.0, 100.0))
    with pytest.raises(GraphkinError, match="crank"):
        spread(catalog.load("strip_cutter"), 11, limits=(0.0, 1.0))


def test_a_crank_is_drawn_as_the_scene_draws_it():
    p = catalog.load("strip_cutter")
    assert spread(p, SMALL) is p


def test_the_nearest_position_goes_round_the_turn():
    s = {"input": {"name": "theta", "values": list(np.radians(np.arange(0, 360, 10.0)))}}
    assert [nearest(s, v) for v in (0, 4, 6, 356, 359.9, -10, 725)] == [0, 0, 1, 0, 0, 35, 0]
    with pytest.raises(GraphkinError, match="not a number"):
        nearest(s, float("nan"))


def test_the_kernel_drawn_explorer_is_retired_with_one_message():
    with pytest.raises(GraphkinError, match="retired"):
        explore(catalog.load("strip_cutter"), browser=False)


def test_the_speed_the_motion_polygons_and_a_new_problem_from_python():
    ex = gk.explore(catalog.load("strip_cutter"), n=SMALL, motion=True)
    assert ex.scene["motion"] is not None and json.loads(ex.widget.scene)["motion"] is not None
    ex.set("speed", 450 * math.pi / 30)
    assert ex.problem.q_dot[0] == pytest.approx(450 * math.pi / 30)
    ex.position = 100
    i = ex.index
    ref = ex.problem.solve(at=[ex.scene["input"]["values"][i]])
    force = max(float(np.nanmax(np.abs(np.array(f["analytical"], float)))) for f in ex.scene["forces"])
    assert abs(ex.scene["effort"]["analytical"][i] - float(ref.effort[0])) <= 1e-9 * force * ex.scene["size"]


def test_import_graphkin_does_not_load_widgets_or_matplotlib():
    code = ("import sys, graphkin, graphkin.problem, graphkin.catalog; "
            "bad = [m for m in ('ipywidgets', 'matplotlib', 'graphkin.widgets') if m in sys.modules]; "
            "import graphkin.widgets; "  # the module itself imports them only when an explorer is built
            "bad += [m for m in ('ipywidgets', 'matplotlib', 'anywidget') if m in sys.modules]; "
            "print(bad); sys.exit(1 if bad else 0)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


@pytest.mark.parametrize("n", [1, 2.5, True, "36"])
def test_bad_n(n):
    with pytest.raises(GraphkinError, match="n must be"):
        explore(catalog.load("strip_cutter"), n=n)


def test_graphkin_explore_with_a_bad_problem_is_one_line_and_exit_2():
    """Reported before Voilà starts (the browser test serves a real page and stops it with Ctrl-C)."""
    r = subprocess.run([sys.executable, "-m", "graphkin", "explore", "no_such_problem", "--no-browser"],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr.count("\n") == 1 and r.stderr.startswith("graphkin: error:") and "no_such_problem" in r.stderr


def test_graphkin_explore_page_holds_the_problem_and_nothing_else():
    from graphkin.cli.explore import notebook

    nb = notebook("strip_cutter", "Four-bar strip cutter")
    code = [c["source"] for c in nb["cells"] if c["cell_type"] == "code"]
    assert code == ["from graphkin import catalog\nfrom graphkin.widgets import explore\n\n"
                    "explore(catalog.load('strip_cutter'))"]
    assert nb["metadata"]["kernelspec"]["name"] == "python3" and nb["nbformat"] == 4


def test_a_new_scene_is_shown_at_the_position_set_from_python():
    """A change that adds positions (a load that switches on adds samples either side of each switch) keeps the
    angle shown, not the index."""
    p = catalog.load("strip_cutter")
    ex = explore(replace(p, mechanism=replace(p.mechanism, loads=())), n=SMALL)
    assert ex.scene["n"] == SMALL
    ex.position = 130
    ex.problem = p  # the cut switches on and off: four more positions
    assert ex.scene["n"] == SMALL + 4 and ex.position == pytest.approx(130)
