"""The bad-input catalogue (issue 12): problem files, every command and flag, and the Python API.

Each case is input a careless or unlucky user could give. Every one must end
the same way: exit code 2 (a GraphkinError in Python), exactly one line on
stderr that names the file and the field (or the flag, or the argument), no
traceback, and nothing left behind in the working folder — no stray output,
no temporary file.

Cases are grouped by kind (missing, wrong type, wrong unit, negative, out of
range, unknown, duplicate, malformed, encoding, structure, ...). The CLI runs
in-process through :func:`graphkin.cli.main`; a few cases at the end run the
real ``graphkin`` entry point in a subprocess.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from graphkin import catalog
from graphkin.cli import main
from graphkin.errors import GraphkinError

SLIDER = catalog.path("double_slider").read_text(encoding="utf-8")
CUTTER = catalog.path("strip_cutter").read_text(encoding="utf-8")
GEARS = catalog.path("gearset").read_text(encoding="utf-8")
FRICTION = catalog.path("slider_crank_friction").read_text(encoding="utf-8")
BASES = {"slider": SLIDER, "cutter": CUTTER, "gears": GEARS, "friction": FRICTION}
GRAPHKIN = Path(sys.executable).with_name("graphkin")


def snapshot(root: Path) -> set[str]:
    """Every file and folder under ``root``, hidden ones (temporary files) included."""
    found = set()
    for folder, dirs, files in os.walk(root):
        for name in dirs + files:
            found.add(os.path.relpath(os.path.join(folder, name), root))
    return found


@pytest.fixture
def work(tmp_path, monkeypatch):
    """A fresh working folder, made the current one: relative outputs would land here."""
    folder = tmp_path / "work"
    folder.mkdir()
    monkeypatch.chdir(folder)
    return folder


def run(capsys, root, *args):
    """``graphkin ARGS`` in-process; asserts that nothing appeared or vanished under ``root``."""
    before = snapshot(root)
    code = main([str(a) for a in args])
    out, err = capsys.readouterr()
    assert snapshot(root) == before, f"files left behind: {snapshot(root) ^ before}"
    return code, out, err


def one_error_line(err: str, *named: str) -> None:
    """Exactly one line, graphkin's own, no traceback, naming everything in ``named``."""
    assert err.endswith("\n") and err.count("\n") == 1, f"not one line: {err!r}"
    assert err.startswith("graphkin: error: "), err
    assert "Traceback" not in err
    for text in named:
        assert text in err, f"{text!r} not in {err!r}"


def solve_refuses(capsys, tmp_path, text: str, *named: str) -> None:
    """``graphkin solve`` on ``text`` written to a file: exit 2, nothing on stdout, one error line naming the file
    and everything in ``named``."""
    path = tmp_path / "p.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["solve", str(path)]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    one_error_line(err, str(path), *named)


def edit(text: str, old: str, new: str) -> str:
    """``text`` with the first ``old`` replaced; ``old`` must be there (so a case never tests nothing)."""
    assert old in text, old
    return text.replace(old, new, 1)


# ---------------------------------------------------------------------------------------------------------------
# Problem files: (base, old, new, what the message must name besides the file)

P = pytest.param
DISK_MASS = 'mass = "3 kg"\nG = ["0 mm", "0 mm"]\nk = "100 mm"'
PROBLEM_CASES = [
    # -- missing ----------------------------------------------------------------------------------------------
    P("slider", "[driver]\ntype = \"slider\"\nlink = 2\ns = \"200 mm\"\nv = \"2 m/s\"\na = \"0 m/s^2\"\n", "",
      ["driver", "missing"], id="missing-driver"),
    P("slider", "link = 2\ns = \"200 mm\"", "s = \"200 mm\"", ["driver.link", "missing"], id="missing-driver-link"),
    P("slider", "s = \"200 mm\"\n", "", ["driver.s", "missing"], id="missing-driver-s"),
    P("cutter", "theta = { start", "thetas = { start", ["driver.thetas"], id="missing-driver-theta-typo"),
    P("slider", "mass = \"5 kg\"\nshape", "shape", ["links[1].mass", "missing"], id="missing-rod-mass"),
    P("slider", "number = 2\n", "", ["links[0].number", "missing"], id="missing-link-number"),
    P("slider", "points = { B = [\"0 mm\", \"0 mm\"] }\n", "", ["links[2].points", "missing"],
      id="missing-link-points"),
    P("slider", "links = [2, 3]\npoint = \"A\"\n", "links = [2, 3]\n", ["joints[1].point", "missing"],
      id="missing-revolute-point"),
    P("slider", "guide = 1\nslider = 2\n", "slider = 2\n", ["joints[0].guide", "missing"], id="missing-guide"),
    P("slider", "through = \"O\"\ndirection = \"0 deg\"", "direction = \"0 deg\"", ["joints[0].through", "missing"],
      id="missing-through"),
    P("gears", "radii = [\"100 mm\", \"40 mm\"]\n", "", ["joints[2].radii", "missing"], id="missing-gear-radii"),
    P("gears", "centers = [\"O2\", \"O3\"]\n", "", ["joints[2].centers", "missing"], id="missing-gear-centers"),
    P("cutter", "link = 3\npoint = \"C\"\n", "link = 3\n", ["loads[0].point", "missing"], id="missing-load-point"),
    P("cutter", "force = { magnitude = \"2000 N\", angle = \"90 deg\" }\n", "", ["loads[0].force", "missing"],
      id="missing-load-force"),
    P("cutter", "name = \"Fc3 (cutting)\"\nlink = 3\n", "name = \"Fc3 (cutting)\"\n", ["loads[0].link", "missing"],
      id="missing-load-link"),
    P("cutter", "active = { from = \"124 deg\", to", "active = { to", ["loads[0].active.from", "missing"],
      id="missing-active-from"),
    P("slider", "shape = { type = \"rod\", from = \"A\", to = \"B\" }",
      "shape = { type = \"rod\", to = \"B\" }", ["links[1].shape.from", "missing"], id="missing-rod-from"),
    P("cutter", DISK_MASS,
      "shape = { type = \"disk\", center = \"A0\", radius = \"100 mm\", thickness = \"10 mm\" }",
      ["links[0].shape.density", "missing"], id="missing-disk-density"),
    P("slider", "type = \"revolute\"\nlinks = [2, 3]", "links = [2, 3]", ["joints[1].type", "missing"],
      id="missing-joint-type"),
    P("slider", "[frame]\npoints = { O = [\"0 mm\", \"0 mm\"] }\n", "", ["joints[0].through", "no point 'O'"],
      id="missing-frame"),
    P("cutter", "theta = { start = \"0 deg\", stop = \"360 deg\", step = \"2 deg\" }",
      "theta = { start = \"0 deg\", step = \"2 deg\" }", ["driver.theta", "stop"], id="missing-range-stop"),
    P("cutter", "force = { magnitude = \"2000 N\", angle = \"90 deg\" }", "force = { magnitude = \"2000 N\" }",
      ["loads[0].force", "angle"], id="missing-polar-angle"),
    P("cutter", "C = { r = \"467 mm\", angle = \"-7.6 deg\" }", "C = { r = \"467 mm\" }",
      ["links[1].points.C.angle", "missing"], id="missing-point-angle"),
    # -- wrong type -------------------------------------------------------------------------------------------
    P("slider", "number = 2", "number = \"two\"", ["links[0].number", "whole number"], id="type-number-string"),
    P("slider", "number = 2", "number = 2.5", ["links[0].number", "whole number"], id="type-number-float"),
    P("slider", "points = { A = [\"0 mm\", \"0 mm\"] }\nmass = \"0 kg\"", "points = \"A\"\nmass = \"0 kg\"",
      ["links[0].points", "table"], id="type-points-string"),
    P("slider", "mass = \"5 kg\"", "mass = 5", ["links[1].mass", "units"], id="type-mass-bare-number"),
    P("slider", "mass = \"5 kg\"", "mass = true", ["links[1].mass"], id="type-mass-bool"),
    P("slider", "mass = \"5 kg\"", "mass = [\"5 kg\"]", ["links[1].mass", "single value"], id="type-mass-list"),
    P("slider", "links = [2, 3]", "links = 3", ["joints[1].links", "two link numbers"], id="type-joint-links-int"),
    P("slider", "links = [2, 3]", "links = [2, 3, 4]", ["joints[1].links", "two link numbers"],
      id="type-joint-links-three"),
    P("slider", "links = [2, 3]", "links = [\"2\", 3]", ["joints[1].links[0]", "whole number"],
      id="type-joint-link-string"),
    P("slider", "links = [2, 3]\npoint = \"A\"", "links = [2, 3]\npoint = 5", ["joints[1].point", "string"],
      id="type-joint-point-int"),
    P("slider", "link = 2\ns", "link = \"2\"\ns", ["driver.link", "whole number"], id="type-driver-link-string"),
    P("slider", "s = \"200 mm\"", "s = true", ["driver.s"], id="type-driver-s-bool"),
    P("slider", "[[links]]\nnumber = 2", "links = \"many\"\n[[linkz]]\nnumber = 2", ["linkz"],
      id="type-links-not-array"),
    P("slider", "A = [\"0 mm\", \"0 mm\"] }\nmass = \"0 kg\"", "A = \"0 mm\" }\nmass = \"0 kg\"",
      ["links[0].points.A", "vector"], id="type-point-scalar"),
    P("cutter", "force = { magnitude = \"2000 N\", angle = \"90 deg\" }", "force = \"2000 N\"",
      ["loads[0].force", "vector"], id="type-force-scalar"),
    P("cutter", "active = { from = \"124 deg\", to = \"156 deg\" }", "active = \"124 deg\"",
      ["loads[0].active", "table"], id="type-active-string"),
    P("cutter", "B = 1", "B = 2", ["assembly.B", "1 or -1"], id="type-assembly-two"),
    P("cutter", "B = 1", "B = true", ["assembly.B", "1 or -1"], id="type-assembly-bool"),
    P("slider", "shape = { type = \"rod\", from = \"A\", to = \"B\" }", "shape = \"rod\"",
      ["links[1].shape", "table"], id="type-shape-string"),
    P("slider", "title = ", "gravity = 9.81\ntitle = ", ["gravity", "units"], id="type-gravity-bare"),
    P("cutter", "step = \"2 deg\" }", "num = 2.5 }", ["driver.theta.num", "integer"], id="type-range-num-float"),
    P("cutter", "step = \"2 deg\" }", "step = \"0 deg\" }", ["driver.theta.step", "nonzero"], id="type-range-step-zero"),
    P("friction", "mu = 0.2", "mu = \"lots\"", ["joints[3].mu"], id="type-mu-word"),
    P("slider", "[driver]", "[given]\n3 = 5\n\n[driver]", ["given.3", "table"], id="type-given-not-table"),
    P("slider", "title = ", "loads = 5\ntitle = ", ["loads", "array of tables"], id="type-loads-int"),
    P("slider", "s = \"200 mm\"", "s = []", ["driver.s", "empty"], id="type-positions-empty-list"),
    P("slider", "s = \"200 mm\"", "s = { start = \"1 mm\", stop = \"9 mm\", step = \"1 mm\", every = 2 }",
      ["driver.s", "every"], id="type-range-unknown-key"),
    # -- wrong unit -------------------------------------------------------------------------------------------
    P("slider", "mass = \"5 kg\"", "mass = \"5 m\"", ["links[1].mass", "mass"], id="unit-mass-metres"),
    P("cutter", "omega = \"900 rpm\"", "omega = \"900 Hz\"", ["driver.omega"], id="unit-omega-hertz"),
    P("cutter", "omega = \"900 rpm\"", "omega = \"900 rmp\"", ["driver.omega"], id="unit-omega-misspelt"),
    P("cutter", "start = \"0 deg\"", "start = \"0\"", ["driver.theta.start", "degrees or radians"],
      id="unit-angle-bare"),
    P("gears", "torque = \"8 N*m\"", "torque = \"8 Nm\"", ["loads[0].torque", "N*m"], id="unit-torque-glued"),
    P("gears", "torque = \"8 N*m\"", "torque = \"8 J\"", ["loads[0].torque", "energy"], id="unit-torque-joule"),
    P("cutter", "magnitude = \"2000 N\", angle = \"90 deg\"", "magnitude = \"2000 kg\", angle = \"90 deg\"",
      ["loads[0].force.magnitude"], id="unit-force-kg"),
    P("gears", "I_G = \"0.015 kg*m^2\"", "I_G = \"0.015 kg*m\"", ["links[0].I_G"], id="unit-inertia"),
    P("cutter", "k = \"100 mm\"", "k = \"100 kg\"", ["links[0].k"], id="unit-k-mass"),
    P("slider", "direction = \"90 deg\"", "direction = \"90 N\"", ["joints[3].direction"], id="unit-direction-force"),
    P("slider", "title = ", "gravity = \"9.81 m/s\"\ntitle = ", ["gravity"], id="unit-gravity-velocity"),
    P("friction", "mu = 0.2", "mu = \"0.2 deg\"", ["joints[3].mu"], id="unit-mu-angle"),
    P("cutter", "from = \"124 deg\"", "from = \"124 mm\"", ["loads[0].active.from"], id="unit-active-length"),
    P("slider", "[driver]", "[given.3]\nomega = \"4 m/s\"\n\n[driver]", ["given.3.omega"], id="unit-given-omega"),
    P("slider", "B = [\"500 mm\", \"0 mm\"]", "B = [\"500 mm\", \"0 deg\"]", ["links[1].points.B[1]"],
      id="unit-point-angle"),
    P("slider", "s = \"200 mm\"", "s = \"2,5 mm\"", ["driver.s", "decimal point"], id="unit-decimal-comma"),
    P("slider", "v = \"2 m/s\"", "v = \"2 m/s^2\"", ["driver.v"], id="unit-velocity-acceleration"),
    P("cutter", "alpha = \"0 rad/s^2\"", "alpha = \"0 rad/s\"", ["driver.alpha"], id="unit-alpha-velocity"),
    P("slider", "s = \"200 mm\"", "s = \"200 mm^2\"", ["driver.s"], id="unit-area"),
    P("gears", "radii = [\"100 mm\", \"40 mm\"]", "radii = [\"100 mm\", \"40 kg\"]", ["joints[2].radii[1]"],
      id="unit-gear-radius"),
    P("gears", "pressure_angle = \"20 deg\"", "pressure_angle = \"20\"", ["joints[2].pressure_angle"],
      id="unit-pressure-angle-bare"),
    P("slider", "s = \"200 mm\"", "s = \"nan mm\"", ["driver.s", "finite"], id="unit-nan"),
    P("slider", "s = \"200 mm\"", "s = \"inf mm\"", ["driver.s", "finite"], id="unit-inf"),
    # -- negative ---------------------------------------------------------------------------------------------
    P("slider", "mass = \"5 kg\"", "mass = \"-5 kg\"", ["links[1].mass", "≥ 0"], id="negative-mass"),
    P("gears", "I_G = \"0.015 kg*m^2\"", "I_G = \"-0.015 kg*m^2\"", ["links[0].I_G", "≥ 0"], id="negative-inertia"),
    P("cutter", "k = \"100 mm\"", "k = \"-100 mm\"", ["links[0].k", "≥ 0"], id="negative-k"),
    P("friction", "mu = 0.2", "mu = -0.2", ["joints[3].mu", "≥ 0"], id="negative-mu"),
    P("gears", "radii = [\"100 mm\", \"40 mm\"]", "radii = [\"100 mm\", \"-40 mm\"]", ["joints[2].radii[1]",
      "negative"], id="negative-gear-radius"),
    P("slider", "title = ", "gravity = \"-9.81 m/s^2\"\ntitle = ", ["gravity", "≥ 0"], id="negative-gravity"),
    P("cutter", DISK_MASS,
      "shape = { type = \"disk\", center = \"A0\", radius = \"-100 mm\", thickness = \"10 mm\", "
      "density = \"7800 kg/m^3\" }", ["links[0].shape.radius", "negative"], id="negative-disk-radius"),
    P("cutter", DISK_MASS,
      "shape = { type = \"disk\", center = \"A0\", radius = \"100 mm\", thickness = \"-10 mm\", "
      "density = \"7800 kg/m^3\" }", ["links[0].shape.thickness", "negative"], id="negative-thickness"),
    P("cutter", DISK_MASS,
      "shape = { type = \"disk\", center = \"A0\", radius = \"100 mm\", thickness = \"10 mm\", "
      "density = \"-7800 kg/m^3\" }", ["links[0].shape.density", "negative"], id="negative-density"),
    P("cutter", DISK_MASS,
      "shape = { type = \"outline\", through = [\"A0\", \"A\"], width = \"-20 mm\", thickness = \"10 mm\", "
      "density = \"7800 kg/m^3\" }", ["links[0].shape.width", "negative"], id="negative-outline-width"),
    P("cutter", DISK_MASS,
      "shape = { type = \"outline\", through = [\"A0\", \"A\"], width = \"20 mm\", thickness = \"10 mm\", "
      "density = \"7800 kg/m^3\", hole_diameter = \"-5 mm\" }", ["links[0].shape.hole_diameter", "negative"],
      id="negative-hole"),
    # -- out of range -----------------------------------------------------------------------------------------
    P("slider", "mass = \"5 kg\"", "mass = \"1e-200 kg\"", ["links[1].mass", "too small", "1e-9 kg"],
      id="range-mass-tiny"),
    P("slider", "mass = \"5 kg\"", "mass = \"1e308 kg\"", ["links[1].mass", "too large"], id="range-mass-huge"),
    P("cutter", "mass = \"5.1 kg\"", "mass = \"2e6 kg\"", ["links[2].mass", "too large"], id="range-mass-2e6"),
    P("slider", "B = [\"500 mm\", \"0 mm\"]", "B = [\"1e200 mm\", \"0 mm\"]", ["links[1].points.B[0]", "1 km"],
      id="range-length-huge"),
    P("cutter", "B0 = [\"565 mm\", \"0 mm\"]", "B0 = [\"2 km\", \"0 mm\"]", ["frame.points.B0[0]", "1 km"],
      id="range-frame-2km"),
    P("cutter", "omega = \"900 rpm\"", "omega = \"1e200 rpm\"", ["driver.omega", "too large"], id="range-omega-huge"),
    P("cutter", "omega = \"900 rpm\"", "omega = \"2e6 rpm\"", ["driver.omega", "1,000,000 rpm"], id="range-omega-2e6"),
    P("cutter", "omega = \"900 rpm\"", "omega = \"1e-300 rad/s\"", ["driver.omega", "too small"],
      id="range-omega-tiny"),
    P("cutter", "alpha = \"0 rad/s^2\"", "alpha = \"1e11 rad/s^2\"", ["driver.alpha", "too large"],
      id="range-alpha"),
    P("slider", "v = \"2 m/s\"", "v = \"1e5 m/s\"", ["driver.v", "10 km/s"], id="range-velocity"),
    P("slider", "v = \"2 m/s\"", "v = \"1e-160 m/s\"", ["driver.v", "too small"], id="range-velocity-tiny"),
    P("slider", "a = \"0 m/s^2\"", "a = \"1e11 m/s^2\"", ["driver.a", "too large"], id="range-acceleration"),
    P("cutter", "magnitude = \"2000 N\", angle = \"90 deg\"", "magnitude = \"1e11 N\", angle = \"90 deg\"",
      ["loads[0].force.magnitude", "too large"], id="range-force"),
    P("friction", "force = [\"-500 N\", \"0 N\"]", "force = [\"-5e300 N\", \"0 N\"]", ["loads[0].force[0]",
      "too large"], id="range-force-component"),
    P("gears", "torque = \"8 N*m\"", "torque = \"1e11 N*m\"", ["loads[0].torque", "too large"], id="range-torque"),
    P("gears", "I_G = \"0.015 kg*m^2\"", "I_G = \"1e13 kg*m^2\"", ["links[0].I_G", "too large"], id="range-inertia"),
    P("cutter", "k = \"100 mm\"", "k = \"1e-6 mm\"", ["links[0].k", "too small"], id="range-k-tiny"),
    P("friction", "mu = 0.2", "mu = 11", ["joints[3].mu", "too large"], id="range-mu"),
    P("slider", "title = ", "gravity = \"1e11 m/s^2\"\ntitle = ", ["gravity", "too large"], id="range-gravity"),
    P("cutter", DISK_MASS,
      "shape = { type = \"disk\", center = \"A0\", radius = \"100 mm\", thickness = \"10 mm\", "
      "density = \"1e7 kg/m^3\" }", ["links[0].shape.density", "too large"], id="range-density"),
    P("cutter", DISK_MASS,
      "shape = { type = \"disk\", center = \"A0\", radius = \"100 mm\", thickness = \"1e-9 mm\", "
      "density = \"7800 kg/m^3\" }", ["links[0].shape.thickness", "too small"], id="range-thickness-tiny"),
    P("cutter", "start = \"0 deg\"", "start = \"1e9 deg\"", ["driver.theta.start", "turns"], id="range-angle"),
    P("slider", "direction = \"90 deg\"", "direction = \"1e12 deg\"", ["joints[3].direction", "turns"],
      id="range-direction"),
    P("gears", "radii = [\"100 mm\", \"40 mm\"]", "radii = [\"100 mm\", \"1e-9 mm\"]", ["joints[2].radii[1]",
      "too small"], id="range-gear-radius"),
    P("gears", "pressure_angle = \"20 deg\"", "pressure_angle = \"60 deg\"", ["joints[2].pressure_angle", "45°"],
      id="range-pressure-angle"),
    P("slider", "B = [\"500 mm\", \"0 mm\"]", "B = [\"0.0001 mm\", \"0 mm\"]", ["links[1]", "1 µm"],
      id="range-pins-too-close"),
    P("slider", "B = [\"500 mm\", \"0 mm\"] }\nmass = \"5 kg\"\nshape = { type = \"rod\", from = \"A\", to = \"B\" }",
      "B = [\"0 mm\", \"0 mm\"] }\nmass = \"5 kg\"", ["links[1].points", "coincide"], id="range-pins-coincide"),
    P("cutter", "step = \"2 deg\" }", "num = 2000000 }", ["driver.theta.num", "too many"], id="range-num"),
    P("cutter", "step = \"2 deg\" }", "step = \"1e-9 deg\" }", ["driver.theta.step", "too many"],
      id="range-step-tiny"),
    P("cutter", "to = \"156 deg\"", "to = \"124 deg\"", ["loads[0].active", "zero width"], id="range-active-zero"),
    # -- unknown key, link, point, joint, type ------------------------------------------------------------------
    P("slider", "mass = \"5 kg\"", "mas = \"5 kg\"", ["links[1].mas", "did you mean 'mass'"], id="unknown-key-mass"),
    P("slider", "[driver]", "[driverr]\n[driver]", ["driverr", "did you mean 'driver'"], id="unknown-top-table"),
    P("slider", "links = [2, 3]\npoint = \"A\"", "links = [2, 3]\npont = \"A\"", ["joints[1].pont"],
      id="unknown-key-joint"),
    P("cutter", "name = \"Fc3 (cutting)\"", "nmae = \"Fc3 (cutting)\"", ["loads[0].nmae"], id="unknown-key-load"),
    P("slider", "from = \"A\"", "form = \"A\"", ["links[1].shape.form"], id="unknown-key-shape"),
    P("cutter", "omega = \"900 rpm\"", "omega = \"900 rpm\"\nv = \"2 m/s\"", ["driver.v"],
      id="unknown-key-driver-slider-rate-on-crank"),
    P("slider", "[driver]", "[given.3]\nomegaa = \"4 rad/s\"\n\n[driver]", ["given.3.omegaa"],
      id="unknown-key-given"),
    P("cutter", "[assembly]\nB = 1", "[assembly]\nQ = 1", ["assembly.Q", "joint point"], id="unknown-assembly-point"),
    P("cutter", "[assembly]\nB = 1", "[assembly]\nA = 1", ["assembly.A", "B"], id="unknown-assembly-not-middle"),
    P("slider", "links = [3, 4]", "links = [3, 7]", ["joints[2].links[1]", "unknown link 7"],
      id="unknown-link-joint"),
    P("slider", "slider = 4", "slider = 9", ["joints[3].slider", "unknown link 9"], id="unknown-link-slider"),
    P("cutter", "link = 3\npoint = \"C\"", "link = 9\npoint = \"C\"", ["loads[0].link", "not a moving link"],
      id="unknown-link-load"),
    P("cutter", "link = 3\npoint = \"C\"", "link = 1\npoint = \"C\"", ["loads[0].link", "not a moving link"],
      id="unknown-load-on-frame"),
    P("slider", "link = 2\ns", "link = 9\ns", ["driver.link", "unknown link 9"], id="unknown-link-driver"),
    P("slider", "link = 2\ns", "link = 1\ns", ["driver.link", "frame"], id="unknown-driver-frame"),
    P("slider", "[driver]", "[given.9]\nomega = \"1 rad/s\"\n\n[driver]", ["given.9"], id="unknown-given-link"),
    P("slider", "links = [3, 4]\npoint = \"B\"", "links = [3, 4]\npoint = \"Q\"", ["joints[2].point", "no point 'Q'"],
      id="unknown-point-revolute"),
    P("slider", "point = \"A\"\nthrough = \"O\"", "point = \"X\"\nthrough = \"O\"", ["joints[0].point", "'X'"],
      id="unknown-point-slider"),
    P("slider", "through = \"O\"\ndirection = \"0 deg\"", "through = \"Z\"\ndirection = \"0 deg\"",
      ["joints[0].through", "'Z'"], id="unknown-point-through"),
    P("gears", "centers = [\"O2\", \"O3\"]", "centers = [\"O2\", \"O4\"]", ["joints[2].centers[1]", "'O4'"],
      id="unknown-gear-centre"),
    P("cutter", "link = 3\npoint = \"C\"", "link = 3\npoint = \"X\"", ["loads[0].point", "'X'"],
      id="unknown-load-point"),
    P("slider", "from = \"A\"", "from = \"Q\"", ["links[1].shape.from", "names no point"], id="unknown-rod-point"),
    P("cutter", DISK_MASS,
      "shape = { type = \"disk\", center = \"Q\", radius = \"100 mm\", thickness = \"10 mm\", "
      "density = \"7800 kg/m^3\" }", ["links[0].shape.center", "names no point"], id="unknown-disk-centre"),
    P("slider", "type = \"revolute\"\nlinks = [2, 3]", "type = \"hinge\"\nlinks = [2, 3]", ["joints[1].type",
      "hinge"], id="unknown-joint-type"),
    P("cutter", "type = \"force\"", "type = \"moment\"", ["loads[0].type", "moment"], id="unknown-load-type"),
    P("slider", "type = \"slider\"", "type = \"rocket\"", ["driver.type", "rocket"], id="unknown-driver-type"),
    P("slider", "type = \"rod\"", "type = \"sphere\"", ["links[1].shape.type", "sphere"], id="unknown-shape-type"),
    # -- duplicate --------------------------------------------------------------------------------------------
    P("slider", "number = 4", "number = 3", ["links[2].number", "defined twice"], id="duplicate-link-number"),
    P("slider", "[[joints]]\ntype = \"revolute\"\nlinks = [3, 4]\npoint = \"B\"",
      "[[joints]]\ntype = \"revolute\"\nlinks = [2, 3]\npoint = \"A\"", ["joints[2].links", "joined twice"],
      id="duplicate-joint"),
    P("slider", "mass = \"5 kg\"", "mass = \"5 kg\"\nmass = \"6 kg\"", ["not valid TOML"], id="duplicate-toml-key"),
    P("slider", "[driver]", "[driver]\ntype = \"slider\"\n[driver]", ["not valid TOML"], id="duplicate-table"),
    P("gears", "I_G = \"0.015 kg*m^2\"", "I_G = \"0.015 kg*m^2\"\nk = \"50 mm\"", ["links[0].k", "not both"],
      id="duplicate-IG-and-k"),
    P("slider", "mass = \"5 kg\"\nshape", "mass = \"5 kg\"\nG = [\"1 mm\", \"0 mm\"]\nshape", ["links[1].G",
      "not both"], id="duplicate-shape-and-G"),
    P("cutter", "G = [\"0 mm\", \"0 mm\"]\nk = \"100 mm\"",
      "shape = { type = \"disk\", center = \"A0\", radius = \"100 mm\", thickness = \"10 mm\", "
      "density = \"7800 kg/m^3\" }", ["links[0].mass", "leave mass out"], id="duplicate-disk-and-mass"),
    # -- malformed TOML ---------------------------------------------------------------------------------------
    P("slider", "[driver]", "[driver", ["not valid TOML"], id="toml-bracket"),
    P("slider", "mass = \"5 kg\"", "mass = \"5 kg", ["not valid TOML"], id="toml-unterminated"),
    P("slider", "mass = \"5 kg\"", "mass = 5 kg", ["not valid TOML"], id="toml-bare-words"),
    P("slider", "mass = \"5 kg\"", "= \"5 kg\"", ["not valid TOML"], id="toml-no-key"),
    P("slider", "points = { A", "points = { A = [\"0 mm\", \"0 mm\"], A", ["not valid TOML"],
      id="toml-inline-duplicate"),
    # -- structure --------------------------------------------------------------------------------------------
    P("slider", "[[joints]]\ntype = \"revolute\"\nlinks = [3, 4]\npoint = \"B\"\n", "", ["joints",
      "degrees of freedom"], id="structure-dof"),
    P("gears", "radii = [\"100 mm\", \"40 mm\"]", "radii = [\"100 mm\", \"50 mm\"]", ["joints[2].radii",
      "centre distance"], id="structure-gear-radii-sum"),
    P("slider", "type = \"slider\"\nlink = 2\ns = \"200 mm\"\nv = \"2 m/s\"\na = \"0 m/s^2\"",
      "type = \"crank\"\nlink = 2\ntheta = \"1 deg\"", ["driver.type", "revolute joint"],
      id="structure-crank-on-slider"),
    P("cutter", "type = \"force\"\nname = \"Fc3 (cutting)\"", "name = \"Fc3 (cutting)\"",
      ["loads[0].type", "missing"], id="missing-load-type"),
    P("slider", "type = \"rod\", from", "from", ["links[1].shape.type", "missing"], id="missing-shape-type"),
    P("slider", "links = [2, 3]", "links = [2, 2]", ["joints[1].links", "itself"], id="structure-self-joint"),
    P("slider", "number = 2", "number = 1", ["links[0].number", "frame"], id="structure-link-one"),
    P("cutter", "[assembly]", "[given.3]\nomega = \"1 rad/s\"\n\n[assembly]", ["given", "single input position"],
      id="structure-given-many-positions"),
    # -- issue 13: static analysis, the frame's number, given angles and points ------------------------------------
    P("slider", "title =", "analysis = \"statics\"\ntitle =", ["analysis", "static"], id="analysis-unknown"),
    P("slider", "title =", "analysis = 1\ntitle =", ["analysis", "dynamic"], id="analysis-not-text"),
    P("slider", "v = \"2 m/s\"\n", "", ["driver.v", "missing", "static"], id="dynamic-missing-v"),
    P("cutter", "omega = \"900 rpm\"\n", "", ["driver.omega", "missing", "static"], id="dynamic-missing-omega"),
    P("slider", "title =", "analysis = \"static\"\ntitle =", ["driver.a", "static"], id="static-with-a"),
    P("cutter", "title =", "analysis = \"static\"\ntitle =", ["driver.alpha", "static"], id="static-with-alpha"),
    P("slider", "[frame]\n", "[frame]\nnumber = 2\n", ["frame.number", "0"], id="frame-number-two"),
    P("slider", "[frame]\n", "[frame]\nnumber = \"0\"\n", ["frame.number", "whole number"], id="frame-number-text"),
    P("slider", "[frame]\n", "[frame]\nnumber = 0\n", ["joints[0].guide", "unknown link 1", "links are 0, 2"],
      id="frame-zero-joint-to-link-one"),
    P("slider", "number = 2\n", "number = 0\n", ["links[0].number", "numbered from 2"], id="link-zero-with-frame-one"),
    P("slider", "a = \"0 m/s^2\"\n", "a = \"0 m/s^2\"\n\n[given.3]\ntheta = \"114\"\n",
      ["given.3.theta", "deg"], id="given-theta-no-unit"),
    P("gears", "alpha = \"50 rad/s^2\"\n", "alpha = \"50 rad/s^2\"\n\n[given.2]\ntheta = \"30 deg\"\n",
      ["given.2.theta", "crank"], id="given-theta-of-crank"),
    P("slider", "a = \"0 m/s^2\"\n", "a = \"0 m/s^2\"\n\n[given.3]\npoints = { C = [\"0 mm\", \"1 mm\"] }\n",
      ["given.3.points.C", "no point"], id="given-point-unknown"),
    P("slider", "a = \"0 m/s^2\"\n", "a = \"0 m/s^2\"\n\n[given.3]\npoints = { B = [\"0 mm\"] }\n",
      ["given.3.points.B", "2 components"], id="given-point-one-component"),
    P("slider", "a = \"0 m/s^2\"\n", "a = \"0 m/s^2\"\n\n[given.3]\npoints = \"B\"\n",
      ["given.3.points", "table"], id="given-points-not-table"),
    P("slider", "a = \"0 m/s^2\"\n", "a = \"0 m/s^2\"\n\n[given.3]\npoints = { B = [\"1e9 mm\", \"0 mm\"] }\n",
      ["given.3.points.B[0]", "too large"], id="given-point-out-of-range"),
]


@pytest.mark.parametrize("base, old, new, named", PROBLEM_CASES)
def test_problem_file(work, capsys, base, old, new, named):
    path = work / "problem.toml"
    path.write_text(edit(BASES[base], old, new), encoding="utf-8")
    code, out, err = run(capsys, work, "solve", path)
    assert code == 2
    assert out == ""
    one_error_line(err, str(path), *named)


# -- encodings and files that are not problem files --------------------------------------------------------------

ENCODED = [
    P(lambda: SLIDER.replace("rod AB", "rod AB (Söylemez)").encode("latin-1", errors="replace"), ["not UTF-8", "line"],
      id="latin-1"),
    P(lambda: SLIDER.encode("utf-16"), ["UTF-16"], id="utf-16"),
    P(lambda: b"\x00\x01\x02binary\x00" * 10, ["not a text file"], id="binary"),
    P(lambda: b"", ["driver", "missing"], id="empty"),
    P(lambda: b"# only a comment\n", ["driver", "missing"], id="comment-only"),
    P(lambda: b"x" * 10_000_001, ["larger than 10 MB"], id="too-large"),
    P(lambda: SLIDER.encode("utf-8").replace(b"rod AB", b"rod \xe9 AB"), ["not UTF-8", "0xe9"], id="stray-byte"),
]


@pytest.mark.parametrize("data, named", ENCODED)
def test_file_encoding(work, capsys, data, named):
    path = work / "problem.toml"
    path.write_bytes(data())
    code, out, err = run(capsys, work, "solve", path)
    assert code == 2 and out == ""
    one_error_line(err, str(path), *named)


def test_byte_order_mark_is_fine(work, capsys):
    path = work / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + SLIDER.encode("utf-8"))
    code, out, err = run(capsys, work, "solve", path)
    assert code == 0 and err == "" and "F23" in out


@pytest.mark.parametrize("target, named", [
    P("missing.toml", ["missing.toml", "cannot be read"], id="missing-file"),
    P("folder.toml", ["folder.toml", "cannot be read"], id="a-folder"),
    P("no_such_problem", ["no_such_problem", "double_slider"], id="unknown-catalog-name"),
])
def test_problem_that_is_no_file(work, capsys, target, named):
    (work / "folder.toml").mkdir()
    code, out, err = run(capsys, work, "solve", target)
    assert code == 2 and out == ""
    one_error_line(err, *named)


# ---------------------------------------------------------------------------------------------------------------
# The command line: every command and flag

CLI_CASES = [
    # -- argparse: usage mistakes are one line too ----------------------------------------------------------------
    P(["solv", "double_slider"], ["invalid choice", "solv"], id="unknown-command"),
    P([], ["required", "command"], id="no-command"),
    P(["list", "extra"], ["unrecognized arguments", "extra"], id="list-extra-argument"),
    P(["solve"], ["required", "problem"], id="solve-no-problem"),
    P(["solve", "double_slider", "--at"], ["--at", "expected one argument"], id="solve-at-no-value"),
    P(["solve", "double_slider", "--colour", "red"], ["--colour"], id="solve-unknown-flag"),
    P(["cycle", "strip_cutter", "--n", "abc"], ["--n", "abc"], id="cycle-n-word"),
    P(["cycle", "strip_cutter", "--n", "2.5"], ["--n", "2.5"], id="cycle-n-fraction"),
    P(["cycle", "strip_cutter", "--cs", "abc"], ["--cs", "abc"], id="cycle-cs-word"),
    P(["exercise"], ["required", "action"], id="exercise-no-action"),
    P(["exercise", "mak", "single_link"], ["invalid choice", "mak"], id="exercise-unknown-action"),
    P(["exercise", "make", "single_link"], ["--student", "--roster"], id="make-no-student"),
    P(["exercise", "make", "single_link", "--student", "a", "--roster", "r.csv"], ["--roster", "--student"],
      id="make-student-and-roster"),
    P(["exercise", "grade", "single_link", "--student", "a"], ["--answers"], id="grade-no-answers"),
    P(["exercise", "export", "single_link", "-o", "out"], ["--to"], id="export-no-platform"),
    P(["exercise", "export", "single_link", "--to", "otter"], ["--output"], id="export-no-output"),
    # -- solve --------------------------------------------------------------------------------------------------
    P(["solve", "double_slider", "--at", ""], ["--at", "positions with units"], id="solve-at-empty"),
    P(["solve", "double_slider", "--at", "200 mm,"], ["--at", "positions with units"], id="solve-at-trailing-comma"),
    P(["solve", "double_slider", "--at", "200"], ["--at", "units"], id="solve-at-no-unit"),
    P(["solve", "double_slider", "--at", "30 deg"], ["--at", "length"], id="solve-at-angle-for-slider"),
    P(["solve", "strip_cutter", "--at", "30 mm"], ["--at", "angle"], id="solve-at-length-for-crank"),
    P(["solve", "double_slider", "--at", "fast"], ["--at", "fast"], id="solve-at-word"),
    P(["solve", "double_slider", "--at", "5 km"], ["--at", "1 km"], id="solve-at-out-of-range"),
    P(["solve", "strip_cutter", "--at", "1e9 deg"], ["--at", "turns"], id="solve-at-angle-out-of-range"),
    P(["solve", "double_slider", "--at", "nan mm"], ["--at", "finite"], id="solve-at-nan"),
    P(["solve", "double_slider", "-o", "out.jpg"], ["-o", "out.jpg", ".png"], id="solve-figure-jpg"),
    P(["solve", "double_slider", "-o", "out"], ["-o", "out", ".png"], id="solve-figure-no-suffix"),
    P(["solve", "double_slider", "-o", "{png_dir}"], ["-o", "folder"], id="solve-figure-onto-folder"),
    P(["solve", "double_slider", "-o", "{file}/x.png"], ["-o", "is a file"],
      id="solve-figure-under-file"),
    P(["solve", "double_slider", "--steps", "{file}/steps"], ["--steps", "is a file"], id="solve-steps-under-file"),
    P(["solve", "double_slider", "--steps", "{file}"], ["--steps", "is a file"], id="solve-steps-onto-file"),
    P(["solve", "double_slider", "--json", "-o", "x.gif"], ["-o", "x.gif"], id="solve-json-figure-gif"),
    P(["solve", "strip_cutter", "--every-position"], ["--every-position", "-o FILE"], id="solve-every-position-alone"),
    P(["solve", "double_slider", "--at", "500 mm"], ["double_slider", "s = 500 mm", "dead point"],
      id="solve-dead-point"),
    P(["solve", "double_slider", "--at", "600 mm"], ["double_slider", "s = 600 mm", "cannot be assembled"],
      id="solve-cannot-assemble"),
    P(["solve", "double_slider", "--at", "499.9999999999999 mm"], ["s = 499.9999999999999 mm", "dead point"],
      id="solve-near-dead-point-digits"),
    P(["solve", "double_slider", "--at", "550 mm,600 mm,700 mm"], ["s = 550 mm", "2 more"],
      id="solve-several-bad-positions-one-line"),
    P(["solve", "double_slider", "--json", "--at", "600 mm"], ["double_slider", "s = 600 mm"],
      id="solve-json-cannot-assemble"),
    # -- cycle --------------------------------------------------------------------------------------------------
    P(["cycle", "strip_cutter", "--n", "0"], ["--n", "from 2"], id="cycle-n-zero"),
    P(["cycle", "strip_cutter", "--n", "1"], ["--n", "from 2"], id="cycle-n-one"),
    P(["cycle", "strip_cutter", "--n", "-36"], ["--n", "from 2"], id="cycle-n-negative"),
    P(["cycle", "strip_cutter", "--n", "1000000000"], ["--n", "1,000,000"], id="cycle-n-huge"),
    P(["cycle", "double_slider", "--n", "36"], ["--n", "slider"], id="cycle-n-slider"),
    P(["cycle", "strip_cutter", "--cs", "0"], ["--cs", "> 0"], id="cycle-cs-zero"),
    P(["cycle", "strip_cutter", "--cs", "-0.05"], ["--cs", "> 0"], id="cycle-cs-negative"),
    P(["cycle", "strip_cutter", "--cs", "2"], ["--cs", "below 2"], id="cycle-cs-two"),
    P(["cycle", "strip_cutter", "--cs", "nan"], ["--cs"], id="cycle-cs-nan"),
    P(["cycle", "strip_cutter", "--cs", "inf"], ["--cs"], id="cycle-cs-inf"),
    P(["cycle", "double_slider", "--cs", "0.05"], ["--cs", "slider"], id="cycle-cs-slider"),
    P(["cycle", "single_link", "--cs", "0.05"], ["--cs", "full turn"], id="cycle-cs-one-position"),
    P(["cycle", "engine_inch_bevan", "--n", "72", "--cs", "0.02", "--units", "US"],
      ["--cs", "the crank does not turn", "a static analysis", "driver.omega"], id="cycle-cs-static-no-speed"),
    P(["cycle", "strip_cutter", "-o", "cycle.bmp"], ["-o", "cycle.bmp"], id="cycle-figure-bmp"),
    P(["cycle", "strip_cutter", "-o", "{png_dir}"], ["-o", "folder"], id="cycle-figure-onto-folder"),
    P(["cycle", "strip_cutter", "-o", "{file}/c.svg"], ["-o", "is a file"], id="cycle-figure-under-file"),
    P(["cycle", "no_such_problem"], ["no_such_problem"], id="cycle-unknown-problem"),
    P(["cycle", "{bad_toml}"], ["bad.toml", "not valid TOML"], id="cycle-bad-file"),
    P(["cycle", "{no_turn}", "--cs", "0.05"], ["no_turn.toml", "--cs", "no flywheel can be sized", "θ = 0°",
                                               "cannot be assembled"], id="cycle-cs-linkage-cannot-turn"),
    P(["cycle", "{no_turn}", "--n", "36", "--json"], ["no_turn.toml", "positions have no solution", "θ = 0°"],
      id="cycle-linkage-cannot-turn"),
    # -- exercise list / make / key / grade -------------------------------------------------------------------------
    P(["exercise", "list", "extra"], ["unrecognized arguments", "extra"], id="exercise-list-extra"),
    P(["exercise", "make", "no_such_exercise", "--student", "a"], ["no_such_exercise"], id="make-unknown-exercise"),
    P(["exercise", "key", "no_such_exercise", "--student", "a", "--secret", "k"], ["no_such_exercise"],
      id="key-unknown-exercise"),
    P(["exercise", "make", "{bad_exercise}", "--student", "a"], ["bad_exercise.toml", "questions[0].tolerence"],
      id="make-bad-exercise-file"),
    P(["exercise", "make", "{latin1_exercise}", "--student", "a"], ["latin1.toml", "not UTF-8"],
      id="make-latin1-exercise-file"),
    P(["exercise", "make", "single_link", "--student", "a", "--figure", "given.jpg"], ["--figure", "given.jpg"],
      id="make-figure-jpg"),
    P(["exercise", "make", "single_link", "--roster", "{roster}", "--figure", "g.png"], ["--figure", "--roster"],
      id="make-figure-with-roster"),
    P(["exercise", "make", "single_link", "--student", "a", "-o", "{dir}"], ["-o", "{dir}", "folder"],
      id="make-output-onto-folder"),
    P(["exercise", "make", "single_link", "--student", "a", "-o", "{file}/sheet.txt"], ["-o", "sheet.txt", "is a file"],
      id="make-output-under-file"),
    P(["exercise", "make", "single_link", "--roster", "missing.csv"], ["roster", "missing.csv", "cannot be read"],
      id="make-roster-missing"),
    P(["exercise", "make", "single_link", "--roster", "{no_student_column}"], ["roster", "'student' column"],
      id="make-roster-no-student-column"),
    P(["exercise", "make", "single_link", "--roster", "{empty_id}"], ["roster", "line 3", "empty"],
      id="make-roster-empty-id"),
    P(["exercise", "key", "single_link", "--roster", "{binary}", "--secret", "k"], ["roster", "not a text file"],
      id="key-roster-binary"),
    P(["exercise", "key", "single_link", "--roster", "{utf16_roster}", "--secret", "k"], ["roster", "UTF-16"],
      id="key-roster-utf16"),
    P(["exercise", "grade", "single_link", "--student", "a", "--answers", "missing.json", "--secret", "k"],
      ["answers", "missing.json", "cannot be read"], id="grade-answers-missing"),
    P(["exercise", "grade", "single_link", "--student", "a", "--answers", "{not_json}", "--secret", "k"],
      ["answers", "not valid JSON"], id="grade-answers-not-json"),
    P(["exercise", "grade", "single_link", "--student", "a", "--answers", "{json_list}", "--secret", "k"],
      ["answers", "JSON object"], id="grade-answers-json-list"),
    P(["exercise", "grade", "single_link", "--answers", "{no_student_column}", "--secret", "k"],
      ["answers", "'student' column"], id="grade-csv-no-student-column"),
    P(["exercise", "grade", "single_link", "--student", "a", "--answers", "{binary}", "--secret", "k"],
      ["answers", "not a text file"], id="grade-answers-binary"),
    P(["exercise", "grade", "single_link", "--student", "a", "--answers", "{answers}", "--secret", "k", "-o",
       "{file}/g.csv"], ["-o", "g.csv", "is a file"], id="grade-output-under-file"),
    # -- exercise export ----------------------------------------------------------------------------------------
    P(["exercise", "export", "single_link", "--to", "moodle", "-o", "out"], ["moodle", "otter"],
      id="export-unknown-platform"),
    P(["exercise", "export", "single_link", "--to", "otter", "-o", "{file}"], ["-o", "is a file"],
      id="export-onto-file"),
    P(["exercise", "export", "single_link", "--to", "otter", "-o", "{file}/out"], ["-o", "is a file"],
      id="export-under-file"),
    P(["exercise", "export", "no_such_exercise", "--to", "otter", "-o", "out"], ["no_such_exercise"],
      id="export-unknown-exercise"),
    P(["exercise", "export", "single_link", "--to", "gradescope", "-o", "out", "--roster", "missing.csv"],
      ["roster", "missing.csv"], id="export-roster-missing"),
]


@pytest.fixture
def props(work):
    """Files the CLI cases point at: a plain file, a folder, bad rosters and answers, bad exercise files."""
    (work / "a_file.txt").write_text("not a folder\n")
    (work / "a_dir").mkdir()
    (work / "plot.svg").mkdir()
    (work / "bad.toml").write_text("[driver\n")
    exercise = catalog.path("double_slider").parent / "exercises" / "single_link.toml"
    text = exercise.read_text(encoding="utf-8").replace('problem = "single_link"',
                                                        f'problem = "{catalog.path("single_link")}"')
    (work / "bad_exercise.toml").write_text(edit(text, 'id = "F12"', 'id = "F12"\ntolerence = 0.01'))
    (work / "latin1.toml").write_bytes(text.replace("A single link", "Söylemez's link").encode("latin-1", errors="replace"))
    (work / "no_turn.toml").write_text(edit(CUTTER, 'A = ["85 mm", "0 mm"]', 'A = ["300 mm", "0 mm"]'))
    (work / "roster.csv").write_text("student\na\nb\n")
    (work / "no_student.csv").write_text("name\na\n")
    (work / "empty_id.csv").write_text("student\na\n \n")
    (work / "binary.bin").write_bytes(b"\x00" * 64)
    (work / "roster16.csv").write_bytes("student\na\n".encode("utf-16"))
    (work / "not.json").write_text("{F12: 3}")
    (work / "list.json").write_text('["3 N"]')
    (work / "answers.json").write_text(json.dumps({"F12": "3 N"}))
    return {"file": "a_file.txt", "dir": "a_dir", "png_dir": "plot.svg", "bad_toml": "bad.toml",
            "bad_exercise": "bad_exercise.toml",
            "latin1_exercise": "latin1.toml", "roster": "roster.csv", "no_student_column": "no_student.csv",
            "empty_id": "empty_id.csv", "binary": "binary.bin", "utf16_roster": "roster16.csv",
            "not_json": "not.json", "json_list": "list.json", "answers": "answers.json",
            "no_turn": "no_turn.toml"}


@pytest.mark.parametrize("args, named", CLI_CASES)
def test_command_line(work, props, capsys, args, named):
    args = [a.format(**props) for a in args]
    named = [n.format(**props) for n in named]
    code, out, err = run(capsys, work, *args)
    assert code == 2
    one_error_line(err, *named)
    # Output is checked before any work: a bad destination prints no report to go with it.
    if any(a.startswith(("--figure", "--steps", "-o")) for a in args) and "is a file" in err:
        assert out == ""


# ---------------------------------------------------------------------------------------------------------------
# The Python API: plain GraphkinErrors at the public entry points, never numpy's or a backwards TypeError

def _problem():
    return catalog.load("strip_cutter")


def _slider():
    return catalog.load("double_slider")


def _mechanism():
    return _problem().mechanism


def _cycle():
    from graphkin.cycle import sweep

    return sweep(_problem(), 36)


API_CASES = [
    # -- reading problems ---------------------------------------------------------------------------------------
    P(lambda: __import__("graphkin.problem").problem.parse_problem(SLIDER.encode()), ["parse_problem", "bytes"],
      id="parse-bytes"),
    P(lambda: __import__("graphkin.problem").problem.parse_problem(None), ["parse_problem", "str"], id="parse-none"),
    P(lambda: __import__("graphkin.problem").problem.parse_problem(SLIDER, file=3), ["file"], id="parse-file-int"),
    P(lambda: __import__("graphkin.problem").problem.load_problem(42), ["load_problem", "int"], id="load-int"),
    P(lambda: __import__("graphkin.problem").problem.load_problem(b"double_slider.toml"),
      ["load_problem", "bytes"], id="load-bytes"),
    P(lambda: __import__("graphkin.problem").problem.load_problem(""), ["load_problem"], id="load-empty"),
    P(lambda: __import__("graphkin.problem").problem.build_problem(["x"]), ["build_problem", "list"],
      id="build-list"),
    P(lambda: catalog.load(None), ["None"], id="catalog-none"),
    # -- positions and rates ----------------------------------------------------------------------------------
    P(lambda: _problem().solve(at=[[1.0, 2.0], [3.0, 4.0]]), ["at", "shape (2, 2)"], id="solve-at-2d"),
    P(lambda: _problem().solve(at="124 deg"), ["at", "number"], id="solve-at-string"),
    P(lambda: _problem().solve(at=[]), ["at", "empty"], id="solve-at-empty"),
    P(lambda: _problem().solve(at=[0.1, float("nan")]), ["at[1]", "finite"], id="solve-at-nan"),
    P(lambda: _problem().solve(at=1e9), ["at", "turns"], id="solve-at-out-of-range"),
    P(lambda: _problem().solve(at=[1 + 2j]), ["at", "number"], id="solve-at-complex"),
    P(lambda: _problem().solve(at=[0.1, [0.2, 0.3]]), ["at", "flat list"], id="solve-at-ragged"),
    P(lambda: _problem().kinematics(at=[True, False]), ["at", "number"], id="kinematics-at-bool"),
    P(lambda: _slider().solve(at=5000.0), ["at", "1 km"], id="solve-at-slider-out-of-range"),
    P(lambda: __import__("graphkin.kinematics").kinematics.solve_kinematics(_mechanism(), [0.1, 0.2, 0.3],
                                                                          [1.0, 2.0]),
      ["q_dot", "2 values for 3 positions"], id="kinematics-rates-length"),
    P(lambda: __import__("graphkin.kinematics").kinematics.solve_kinematics(_mechanism(), [0.1, 0.2],
                                                                          1.0, np.ones((2, 2))),
      ["q_ddot", "shape (2, 2)"], id="kinematics-acceleration-2d"),
    P(lambda: __import__("graphkin.kinematics").kinematics.solve_kinematics(_mechanism(), 0.1, "fast"),
      ["q_dot", "number"], id="kinematics-rate-string"),
    P(lambda: __import__("graphkin.kinematics").kinematics.solve_kinematics(_mechanism(), 0.1, 1e9),
      ["q_dot", "too large"], id="kinematics-rate-out-of-range"),
    P(lambda: __import__("graphkin.kinematics").kinematics.solve_kinematics(None, 0.1), ["Mechanism"],
      id="kinematics-no-mechanism"),
    # One position as an array of one (an exercise's draw): the one number checked as every other is.
    P(lambda: __import__("graphkin.kinematics").kinematics.solve_kinematics(_mechanism(), np.array([np.nan])),
      ["q (the input positions)", "finite"], id="kinematics-one-position-nan"),
    P(lambda: __import__("graphkin.kinematics").kinematics.solve_kinematics(_mechanism(), np.array([0.1]),
                                                                          np.array([1e-9])),
      ["q_dot", "too small"], id="kinematics-one-rate-tiny"),
    P(lambda: __import__("graphkin.kinematics").kinematics.solve_kinematics(_mechanism(), np.array([0.1]),
                                                                          np.array([1e9])),
      ["q_dot", "too large"], id="kinematics-one-rate-huge"),
    P(lambda: __import__("graphkin.analytical").analytical.solve(_mechanism(), np.zeros((3, 1))), ["q", "shape (3, 1)"],
      id="solve-q-column"),
    P(lambda: __import__("graphkin.analytical").analytical.solve(_mechanism(), np.zeros(2_000_000)), ["q", "1,000,000"],
      id="solve-too-many"),
    # -- sweeps and flywheels ---------------------------------------------------------------------------------
    P(lambda: __import__("graphkin.cycle").cycle.sweep(_problem(), 1), ["n", "from 2"], id="sweep-n-one"),
    P(lambda: __import__("graphkin.cycle").cycle.sweep(_problem(), 2.5), ["n", "whole number"],
      id="sweep-n-float"),
    P(lambda: __import__("graphkin.cycle").cycle.sweep(_problem(), "36"), ["n", "whole number"],
      id="sweep-n-string"),
    P(lambda: __import__("graphkin.cycle").cycle.sweep(_problem(), True), ["n", "whole number"],
      id="sweep-n-bool"),
    P(lambda: __import__("graphkin.cycle").cycle.sweep(_problem(), 36, at=[0.1]), ["either n", "at"],
      id="sweep-n-and-at"),
    P(lambda: __import__("graphkin.cycle").cycle.sweep(_problem(), at=np.zeros((4, 2))),
      ["at", "shape (4, 2)"], id="sweep-at-2d"),
    P(lambda: __import__("graphkin.cycle").cycle.size_flywheel(np.linspace(0, 6, 10), np.ones(9),
                                                                   omega_avg=10.0, Cs=0.05),
      ["theta", "T", "same length"], id="flywheel-lengths"),
    P(lambda: __import__("graphkin.cycle").cycle.size_flywheel(np.zeros((2, 5)), np.zeros((2, 5)),
                                                                   omega_avg=10.0, Cs=0.05),
      ["theta", "1-D"], id="flywheel-2d"),
    P(lambda: __import__("graphkin.cycle").cycle.size_flywheel("0 deg", [1.0], omega_avg=10.0, Cs=0.05),
      ["theta", "numbers"], id="flywheel-theta-string"),
    P(lambda: __import__("graphkin.cycle").cycle.size_flywheel(np.linspace(0, 2 * np.pi, 10, endpoint=False),
                                                                   np.ones(10), omega_avg=0.0, Cs=0.05),
      ["omega_avg", "> 0"], id="flywheel-omega-zero"),
    P(lambda: __import__("graphkin.cycle").cycle.size_flywheel(np.linspace(0, 2 * np.pi, 10, endpoint=False),
                                                                   np.ones(10), omega_avg=1e-300, Cs=0.05),
      ["omega_avg", "too small"], id="flywheel-omega-tiny"),
    P(lambda: __import__("graphkin.cycle").cycle.size_flywheel(np.linspace(0, 2 * np.pi, 10, endpoint=False),
                                                                   np.ones(10), omega_avg=10.0, Cs=5),
      ["Cs", "below 2"], id="flywheel-cs-five"),
    P(lambda: _cycle().flywheel("0.05"), ["Cs", "number"], id="cycle-flywheel-cs-string"),
    P(lambda: __import__("graphkin.cycle").cycle.sweep(catalog.load("double_slider")).flywheel(0.05),
      ["flywheel", "slider"], id="cycle-flywheel-slider"),
    P(lambda: _cycle().mean([1.0, 2.0]), ["mean", "one value per position"], id="cycle-mean-length"),
    P(lambda: __import__("graphkin.cycle").cycle.sweep("strip_cutter", 36), ["sweep", "Problem", "str"],
      id="sweep-name-not-problem"),
    P(lambda: __import__("graphkin.cycle").cycle.joint_force_index(None), ["joint_force_index", "Problem"],
      id="joint-force-index-none"),
    P(lambda: _cycle().joint_force_index(limit="two"), ["limit", "number"], id="joint-force-index-limit-word"),
    P(lambda: __import__("graphkin.analytical").analytical.solve_forces(_problem()), ["solve_forces", "Kinematics"],
      id="solve-forces-problem"),
    P(lambda: __import__("graphkin.graphical").graphical.construct_forces(_problem().solve(), 0),
      ["construct_forces", "Kinematics"], id="construct-from-result"),
    P(lambda: __import__("graphkin.graphical").graphical.construct_forces(_problem().kinematics(), 1.5),
      ["index", "1.5"], id="construct-index-float"),
    # -- changing a problem -----------------------------------------------------------------------------------
    P(lambda: _problem().at_speed("fast"), ["q_dot", "number"], id="at-speed-string"),
    P(lambda: _problem().at_speed(1e12), ["q_dot", "too large"], id="at-speed-out-of-range"),
    P(lambda: catalog.load("slider_crank_friction").with_friction(-0.1), ["mu", "≥ 0"], id="with-friction-negative"),
    P(lambda: catalog.load("slider_crank_friction").with_friction(50), ["mu", "too large"],
      id="with-friction-out-of-range"),
    P(lambda: _problem().with_friction(0.1), ["no sliding pair"], id="with-friction-no-slider"),
    # -- building a mechanism in Python -----------------------------------------------------------------------
    P(lambda: __import__("graphkin.model").model.Link(2, points="A"), ["link 2 points"], id="link-points-string"),
    P(lambda: __import__("graphkin.model").model.Link(2, mass=1e-200), ["link 2 mass", "too small"],
      id="link-mass-tiny"),
    P(lambda: __import__("graphkin.model").model.Link(2, mass="5 kg"), ["link 2 mass", "number"],
      id="link-mass-string"),
    P(lambda: __import__("graphkin.model").model.Link(2, {"A": (0.0, 0.0, 0.0)}), ["link 2 point A", "pair"],
      id="link-point-triple"),
    P(lambda: __import__("graphkin.model").model.Link(2, {"A": (1e9, 0.0)}), ["link 2 point A.x", "1 km"],
      id="link-point-far"),
    P(lambda: __import__("graphkin.model").model.Link(2.5), ["link number"], id="link-number-float"),
    P(lambda: __import__("graphkin.model").model.Revolute((2, "3"), "A"), ["revolute", "by number"],
      id="revolute-link-string"),
    P(lambda: __import__("graphkin.model").model.Revolute((2, 3), 7), ["revolute", "point"],
      id="revolute-point-int"),
    P(lambda: __import__("graphkin.model").model.Prismatic(1, 2, "A", "O", mu=100.0), ["mu", "too large"],
      id="prismatic-mu-huge"),
    P(lambda: __import__("graphkin.model").model.GearMesh((2, 3), ("O2", "O3"), 0.1), ["pitch radii"],
      id="gear-radius-scalar"),
    P(lambda: __import__("graphkin.model").model.GearMesh((2, 3), "O2", (0.1, 0.05)), ["centers"],
      id="gear-centres-string"),
    P(lambda: __import__("graphkin.model").model.PointForce(2, "A", (1e12, 0.0)), ["force on link 2", "too large"],
      id="point-force-huge"),
    P(lambda: __import__("graphkin.model").model.Torque(2, "8 N*m"), ["torque on link 2", "number"],
      id="torque-string"),
    P(lambda: __import__("graphkin.model").model.Driver("2"), ["driver link"], id="driver-link-string"),
    P(lambda: __import__("graphkin.model").model.Mechanism(_mechanism().links[0], (), None),
      ["links", "list"], id="mechanism-links-single"),
    P(lambda: __import__("graphkin.model").model.Mechanism(list(_mechanism().links) + [{"number": 5}],
                                                          _mechanism().joints, _mechanism().driver),
      ["links[4]", "Link"], id="mechanism-link-dict"),
    P(lambda: __import__("graphkin.model").model.Mechanism(_mechanism().links, _mechanism().joints,
                                                          _mechanism().driver, assembly=[("B", 1)]),
      ["assembly"], id="mechanism-assembly-list"),
    P(lambda: __import__("graphkin.model").model.Mechanism(_mechanism().links, _mechanism().joints,
                                                          _mechanism().driver, gravity=1e12),
      ["gravity", "too large"], id="mechanism-gravity-huge"),
    # -- reading results --------------------------------------------------------------------------------------
    P(lambda: __import__("graphkin.graphical").graphical.construct_forces(_problem().kinematics(), 999),
      ["index", "999"], id="construct-index-out-of-range"),
    P(lambda: _problem().solve()["F99"], ["F99"], id="result-unknown-force"),
    P(lambda: _problem().solve().force(2, 9), ["9"], id="result-force-unknown-link"),
]


@pytest.mark.parametrize("call, named", API_CASES)
def test_python_api(work, call, named):
    before = snapshot(work)
    with pytest.raises(GraphkinError) as info:
        call()
    message = str(info.value)
    assert "\n" not in message and message.strip() == message and message, message
    for text in named:
        assert text in message, f"{text!r} not in {message!r}"
    assert snapshot(work) == before


# ---------------------------------------------------------------------------------------------------------------
# Warnings: accepted, said in one line, never numpy's

def test_high_friction_is_one_warning_line(work, capsys):
    path = work / "grippy.toml"
    path.write_text(edit(FRICTION, "mu = 0.2", "mu = 1.5"), encoding="utf-8")
    code, out, err = run(capsys, work, "solve", path, "--at", "30 deg")
    assert code == 0 and "F14" in out.replace("G14", "F14")
    assert err.count("\n") == 1 and err.startswith("graphkin: warning: ") and "joints[3].mu" in err


@pytest.mark.parametrize("old, new", [
    P('mass = "5.1 kg"', 'mass = "1e6 kg"', id="heaviest"),
    P('mass = "5.1 kg"', 'mass = "1e-9 kg"', id="lightest"),
    P('omega = "900 rpm"', 'omega = "1e6 rpm"', id="fastest"),
    P('omega = "900 rpm"', 'omega = "1e-6 rad/s"', id="slowest"),
    P('magnitude = "2000 N", angle = "90 deg"', 'magnitude = "1e10 N", angle = "90 deg"', id="strongest"),
])
def test_edges_of_the_ranges_solve_quietly(work, capsys, old, new):
    # The largest and smallest values accepted solve with no numpy warning (pytest turns graphkin's into errors).
    path = work / "edge.toml"
    path.write_text(edit(CUTTER, old, new), encoding="utf-8")
    code, out, err = run(capsys, work, "cycle", path, "--n", "72", "--cs", "0.05")
    assert code == 0, err
    assert err == "" and "Flywheel" in out


# ---------------------------------------------------------------------------------------------------------------
# The real entry point: a subprocess proves no traceback escapes past main()

@pytest.mark.parametrize("args, named", [
    P(["solve", "{bad}"], ["bad.toml", "links[1].mass", "too small"], id="solve-tiny-mass"),
    P(["cycle", "strip_cutter", "--n", "abc"], ["--n"], id="cycle-n-word"),
    P(["solve", "{latin1}"], ["latin1.toml", "not UTF-8"], id="latin-1"),
    P(["exercise", "grade", "single_link", "--student", "a", "--answers", "-", "--secret", "k"],
      ["answers", "standard input", "not valid JSON"], id="grade-stdin-not-json"),
    P(["exercise", "export", "single_link", "--to", "blackboard", "-o", "out"], ["blackboard"], id="export-platform"),
])
def test_entry_point(work, args, named):
    (work / "bad.toml").write_text(edit(SLIDER, 'mass = "5 kg"', 'mass = "1e-200 kg"'), encoding="utf-8")
    (work / "latin1.toml").write_bytes(SLIDER.replace("rod AB", "rod AB (Söylemez)").encode("latin-1", errors="replace"))
    args = [a.format(bad="bad.toml", latin1="latin1.toml") for a in args]
    before = snapshot(work)
    env = dict(os.environ, PYTHONWARNINGS="error::RuntimeWarning")
    done = subprocess.run([str(GRAPHKIN), *args], input="not json", capture_output=True, text=True, env=env,
                          timeout=60)
    assert done.returncode == 2
    one_error_line(done.stderr, *named)
    assert snapshot(work) == before
