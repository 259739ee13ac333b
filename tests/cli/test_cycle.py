"""``graphkin cycle``: the summary equals the analysis API's numbers, --json, --figure, bad input."""

import io
import json
import math
import re
import sys

import numpy as np
import pytest

from graphkin import catalog
from graphkin.cli import main
from graphkin.cli._common import Progress as _Progress
from graphkin.cycle import joint_force_index, sweep
from graphkin.report import DISK_THICKNESS, STEEL


def run(capsys, *argv):
    code = main(["cycle", *argv])
    out, err = capsys.readouterr()
    return code, out, err


def number(text, pattern):
    m = re.search(pattern, text)
    assert m, f"{pattern!r} not in\n{text}"
    return [float(g) for g in m.groups()]


@pytest.fixture(scope="module")
def cycle():
    return sweep(catalog.load("strip_cutter"), 90)


def test_summary_equals_the_analysis(capsys, cycle):
    code, out, err = run(capsys, "strip_cutter", "--n", "90", "--cs", "0.05")
    assert code == 0 and err == ""
    assert "94 positions" in out and "loads switch on or off at 124°, 156°" in out
    peaks = cycle.peaks()
    value, at = number(out, r"peak\s+(\S+) N·m at θ12 = (\S+)°")
    assert value == pytest.approx(peaks.effort_max.value, rel=1e-5)
    assert at == pytest.approx(math.degrees(peaks.effort_max.at), abs=1e-4)
    value, at = number(out, r"lowest\s+(\S+) N·m at θ12 = (\S+)°")
    assert value == pytest.approx(peaks.effort_min.value, rel=1e-5)
    assert number(out, r"average\s+(\S+) N·m")[0] == pytest.approx(cycle.average, rel=1e-5)
    assert number(out, r"average\s+(\S+) W")[0] == pytest.approx(cycle.average * 30 * math.pi, rel=1e-5)
    for name, pk in peaks.forces.items():
        value, at = number(out, rf"\n  {name}\s+(\S+) N at θ12 = (\S+)°")
        assert value == pytest.approx(pk.value, rel=1e-5)
        assert at == pytest.approx(math.degrees(pk.at), abs=1e-4)
    f = cycle.flywheel(0.05)
    assert number(out, r"E\s+(\S+) J")[0] == pytest.approx(f.E, rel=1e-5)
    assert number(out, r"I_s\s+(\S+) kg·m²")[0] == pytest.approx(f.I_s, rel=1e-5)
    disk = f.disk(STEEL, DISK_THICKNESS)
    assert number(out, r"radius (\S+) mm")[0] == pytest.approx(disk.radius * 1e3, rel=1e-3)
    assert "steel" in out and "25 mm thick" in out  # the assumption is stated
    jfi = joint_force_index(catalog.load("strip_cutter"), 90)
    value, at = number(out, r"Joint-force index.*\n\s+peak\s+(\S+) at θ12 = (\S+)°")
    assert value == pytest.approx(jfi.peak.value, rel=1e-5)
    assert at == pytest.approx(math.degrees(jfi.peak.at), abs=1e-4)
    assert "immovable positions: none" in out


def test_prismatic_pairs_are_named_g(capsys):
    code, out, _ = run(capsys, "double_slider")
    assert code == 0
    assert re.search(r"\n  G14\s", out) and re.search(r"\n  F23\s", out)
    assert "undefined" in out  # no external load: no joint-force index


def test_json_arrays_have_n_entries(capsys, cycle):
    code, out, _ = run(capsys, "strip_cutter", "--n", "90", "--cs", "0.05", "--json")
    assert code == 0
    data = json.loads(out)
    # 90 equally spaced angles and a sample either side of 124° and of 156°, where the cut starts and ends.
    assert data["n"] == 94 and data["closed"] and data["driver"]["name"] == "T12"
    for values in (data["input"]["values"], data["valid"], data["effort"]["values"], data["power"]["values"],
                   data["shaking"]["moment"], data["shaking"]["force"]["x"], data["transmission_angle"],
                   data["flywheel"]["energy"], data["joint_force_index"]["values"]):
        assert len(values) == 94
    for name, f in data["forces"].items():
        assert all(len(f[k]) == 94 for k in ("x", "y", "magnitude", "angle"))
        np.testing.assert_allclose(f["magnitude"], cycle.polar(name)[0], rtol=1e-12)
    np.testing.assert_allclose(data["effort"]["values"], cycle.torque, rtol=1e-12)
    assert data["flywheel"]["E"] == pytest.approx(cycle.flywheel(0.05).E, rel=1e-12)
    assert data["joint_force_index"]["values"][0] is None  # no cutting force at θ = 0: null, not NaN


def test_figure_is_written(capsys, tmp_path):
    path = tmp_path / "out" / "cycle.png"
    code, out, err = run(capsys, "strip_cutter", "--n", "36", "--cs", "0.05", "--figure", str(path))
    assert code == 0 and path.stat().st_size > 10_000
    assert f"figure written to {path}" in err and "written" not in out  # a message, not data: on stderr


@pytest.mark.parametrize("argv, message", [
    (["double_slider", "--n", "36"], "the driver is a slider"),
    (["double_slider", "--cs", "0.05"], "the driver is a slider"),
    (["strip_cutter", "--n", "1"], "n must be a whole number"),
    (["strip_cutter", "--cs", "-1"], "--cs must be > 0"),
    (["strip_cutter", "--cs", "5"], "--cs 5: the coefficient of speed fluctuation must be below 2"),
    (["strip_cutter", "--n", "1000000000"], "from 2 to 1,000,000"),
    (["strip_cutter", "--figure", "cycle.gif"], ".png, .svg or .pdf"),
    (["no_such_problem"], "neither a catalog problem"),
])
def test_bad_input_is_one_line_and_exit_2(capsys, argv, message):
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith("graphkin: error: ") and message in err


class _Terminal(io.StringIO):
    def isatty(self):
        return True


def test_progress_line_only_after_the_delay():
    quick = _Terminal()
    with _Progress("quick", stream=quick):
        pass
    assert quick.getvalue() == ""
    slow = _Terminal()
    with _Progress("slow", delay=0.0, every=0.01, stream=slow) as p:
        import time

        time.sleep(0.05)
    assert p.shown and slow.getvalue().startswith("\rgraphkin: slow…") and slow.getvalue().endswith(" s\n")


def test_no_progress_line_in_a_log_file():
    """Issue 12: a log (stderr not a terminal) gets no "\r" updates, however long the work."""
    log = io.StringIO()
    with _Progress("slow", delay=0.0, every=0.01, stream=log) as p:
        import time

        time.sleep(0.05)
    assert not p.shown and log.getvalue() == ""


def test_a_batch_of_figures_shows_a_progress_bar_on_a_terminal(monkeypatch, tmp_path):
    """One tick per position drawn, on stderr, when it is a terminal and the batch outlasts the delay."""
    import graphkin.cli._common as cli

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    err = Terminal()
    monkeypatch.setattr(cli, "PROGRESS_DELAY", 0.0)
    monkeypatch.setattr(sys, "stderr", err)
    assert main(["solve", "strip_cutter", "--at", "124 deg,140 deg", "--figure", str(tmp_path / "f.png")]) == 0
    assert "graphkin: drawing" in err.getvalue() and "2/2" in err.getvalue()
    assert (tmp_path / "f_1.png").exists() and (tmp_path / "f_2.png").exists()
