"""Bad input in the fields issue 25 added (gears on an arm, springs, pressures, powers, the unknown effort, the
book's input conventions, the forward step, --units): one line on stderr naming the file and the field, exit 2.

Each case edits a small valid problem file; :func:`edit` asserts that the text it replaces is there, so no case
can pass by testing an unchanged file.
"""

from __future__ import annotations

from importlib.resources import files

import pytest

from graphkin.cli import main
from tests.bad_input.test_catalogue import edit, solve_refuses

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

ENGINE = (files("graphkin.catalog") / "engine_double_acting_khurmi.toml").read_text(encoding="utf-8")
"""Pressures on both faces, θ from the inner dead centre, a clockwise crank, a forward step (Khurmi Ex. 15.12)."""

SLIDER_PLACED = """title = "Slider-crank driven by its piston, placed by the crank's angle"
analysis = "static"
[frame]
points = { O = ["0 mm", "0 mm"] }
[[links]]
number = 2
points = { O = ["0 mm", "0 mm"], C = ["51 mm", "0 mm"] }
[[links]]
number = 3
points = { C = ["0 mm", "0 mm"], P = ["200 mm", "0 mm"] }
[[links]]
number = 4
points = { P = ["0 mm", "0 mm"] }
[[joints]]
type = "revolute"
links = [1, 2]
point = "O"
[[joints]]
type = "revolute"
links = [2, 3]
point = "C"
[[joints]]
type = "revolute"
links = [3, 4]
point = "P"
[[joints]]
type = "prismatic"
guide = 1
slider = 4
point = "P"
through = "O"
direction = "0 deg"
[driver]
type = "slider"
link = 4
place = { link = 2, theta = "60 deg" }
[assembly]
C = -1
[[loads]]
type = "power"
link = 2
power = "1 kW"
speed = "100 rpm"
"""

SPRING = SLIDER_PLACED.replace("""[[loads]]
type = "power"
link = 2
power = "1 kW"
speed = "100 rpm"
""", """[[loads]]
type = "spring"
links = [1, 2]
points = ["O", "C"]
rate = "2 N/mm"
free_length = "40 mm"
""")
"""A spring from the crank pin to the crank's pivot on the frame."""

BASES = {"epicyclic": EPICYCLIC, "engine": ENGINE, "slider": SLIDER_PLACED, "spring": SPRING}

P = pytest.param
CASES = [
    P("epicyclic", "internal = true", "internal = \"yes\"", ["joints[2].internal", "true"], id="internal-not-bool"),
    P("epicyclic", "radii = [\"150 mm\", \"60 mm\"]", "radii = [\"150 mm\", \"50 mm\"]",
      ["joints[2].radii", "centre distance"], id="internal-radii-distance"),
    P("epicyclic", "radii = [\"150 mm\", \"60 mm\"]", "radii = [\"60 mm\", \"60 mm\"]",
      ["joints[2].radii", "annulus larger"], id="internal-equal-radii"),
    P("epicyclic", "centers = [\"O\", \"C\"]", "centers = [\"O\", \"Q\"]", ["joints[2]", "Q"], id="gear-centre-unknown"),
    # -- a pressure on a piston --------------------------------------------------------------------------------
    P("engine", 'bore = "250 mm"\n', '', ["loads[0].bore", "missing"], id="pressure-no-bore"),
    P("engine", 'rod = "50 mm"', 'rod = "300 mm"', ["loads[0].rod", "thinner than the bore"], id="pressure-rod-too-thick"),
    P("engine", 'pressure = "550 kN/m^2"', 'pressure = "550 kN"', ["loads[0].pressure", "pressure"],
      id="pressure-wrong-dimension"),
    P("engine", 'pressure = "550 kN/m^2"\n', '', ["loads[0].pressure", "give the pressure once"], id="pressure-missing"),
    P("engine", 'back_pressure = "70 kN/m^2"', 'back_pressure = "70 kN/m^2"\nside = "head"',
      ["loads[0].side", "cover"], id="pressure-side-unknown"),
    P("engine", 'direction = "180 deg"\n', '', ["loads[0].direction", "missing"], id="pressure-no-direction"),
    P("engine", 'back_pressure = "70 kN/m^2"', 'back_pressure = "70 kN"', ["loads[0].back_pressure", "pressure"],
      id="back-pressure-wrong-dimension"),
    P("engine", 'pressure = "550 kN/m^2"', 'table = """\nangle [deg], pressure [N]\n0, 1\n180, 0\n"""',
      ["loads[0].table", "pressure"], id="pressure-table-wrong-unit"),
    P("engine", 'pressure = "550 kN/m^2"', 'table = """\nangle [deg], force [MPa]\n0, 1\n180, 0\n"""',
      ["loads[0].table", "pressure"], id="pressure-table-wrong-column"),
    P("engine", 'pressure = "550 kN/m^2"', 'pressure = "550 kN/m^2"\ntable = """\nangle [deg], pressure [MPa]\n0, 1\n180, 0\n"""',
      ["loads[0].pressure", "not pressure and table"], id="pressure-and-table"),
    P("engine", 'name = "FL (steam)"', 'name = "FL (steam)"\nsense = "opposes motion"', ["loads[0].sense", "unknown"],
      id="pressure-field-of-another-type"),
    # -- a power at a speed ------------------------------------------------------------------------------------
    P("slider", 'power = "1 kW"', 'power = "-1 kW"', ["loads[0].power", "≥ 0"], id="power-negative"),
    P("slider", 'power = "1 kW"', 'power = "1 N*m"', ["loads[0].power", "power"], id="power-wrong-dimension"),
    P("slider", 'speed = "100 rpm"\n', '', ["loads[0].speed", "missing"], id="power-no-speed"),
    P("slider", 'speed = "100 rpm"', 'speed = "0 rpm"', ["loads[0].speed", "not be zero"], id="power-zero-speed"),
    P("slider", 'speed = "100 rpm"', 'speed = "100 rpm"\nrole = "braking"', ["loads[0].role", "resisting"],
      id="power-role-unknown"),
    # -- the crank angle from a dead centre, the sense of rotation ---------------------------------------------
    P("engine", 'from = "inner dead centre"', 'from = "IDC"', ["driver.from", "inner dead centre"], id="from-unknown"),
    P("engine", 'sense = "clockwise"', 'sense = "cw"', ["driver.sense", "clockwise"], id="sense-unknown"),
    P("engine", 'omega = "120 rpm"', 'omega = "-120 rpm"', ["driver.omega", "≥ 0"], id="sense-and-negative-omega"),
    P("epicyclic", 'theta = "30 deg"', 'theta = "30 deg"\nfrom = "inner dead centre"', ["driver.from", "slider-crank"],
      id="from-without-a-slider-crank"),
    # -- a slider placed by a link's angle ---------------------------------------------------------------------
    P("slider", 'place = { link = 2, theta = "60 deg" }', 'place = { link = 2, theta = "60 deg" }\ns = "100 mm"',
      ["driver.place", "not both"], id="place-and-s"),
    P("slider", 'place = { link = 2, theta = "60 deg" }', 'place = { link = 7, theta = "60 deg" }',
      ["driver.place.link", "moving link"], id="place-link-unknown"),
    P("slider", 'place = { link = 2, theta = "60 deg" }', 'place = { link = 3, theta = "60 deg" }',
      ["driver.place.theta", "never stands at"], id="place-angle-never-reached"),
    P("slider", 'place = { link = 2, theta = "60 deg" }', 'place = { link = 2, angle = "60 deg" }',
      ["driver.place", "angle"], id="place-field-unknown"),
    # -- a spring ----------------------------------------------------------------------------------------------
    P("spring", 'links = [1, 2]\npoints', 'links = [2]\npoints', ["loads[0].links", "two links"], id="spring-one-link"),
    P("spring", 'links = [1, 2]\npoints', 'links = [2, 2]\npoints', ["loads[0].links", "both ends"], id="spring-same-link"),
    P("spring", 'links = [1, 2]\npoints', 'links = [1, 9]\npoints', ["loads[0]", "9"], id="spring-unknown-link"),
    P("spring", 'points = ["O", "C"]', 'points = ["O", "Z"]', ["loads[0].point", "Z"], id="spring-unknown-point"),
    P("spring", 'points = ["O", "C"]', 'points = ["Z", "C"]', ["loads[0].points", "Z"], id="spring-unknown-anchor"),
    P("spring", 'points = ["O", "C"]', 'points = "OC"', ["loads[0].points", "point of each link"],
      id="spring-points-not-a-list"),
    P("spring", 'rate = "2 N/mm"', 'rate = "2 N"', ["loads[0].rate", "stiffness"], id="spring-rate-wrong-dimension"),
    P("spring", 'rate = "2 N/mm"', 'rate = "-2 N/mm"', ["loads[0].rate", "negative"], id="spring-negative-rate"),
    P("spring", 'free_length = "40 mm"\n', '', ["loads[0].free_length", "missing"], id="spring-no-free-length"),
    P("spring", 'free_length = "40 mm"', 'free_length = "-40 mm"', ["loads[0].free_length", "negative"],
      id="spring-negative-free-length"),
    P("spring", 'free_length = "40 mm"', 'free_length = "40 mm"\nsense = "opposes motion"', ["loads[0].sense", "unknown"],
      id="spring-sense"),
    # -- the forward step --------------------------------------------------------------------------------------
    P("engine", 'mass = "60 kg"\nk = "0.6 m"', 'k = "0.6 m"', ["forward.mass", "missing"], id="forward-no-mass"),
    P("engine", 'mass = "60 kg"\nk = "0.6 m"', 'I = "0 kg*m^2"', ["forward.I", "> 0"], id="forward-zero-inertia"),
    P("engine", 'mass = "60 kg"\nk = "0.6 m"', 'I = "2 kg*m^2"\nk = "0.6 m"', ["forward.k", "not both"],
      id="forward-I-and-k"),
    P("engine", 'power = "20 kW"', 'power = "20 kW"\ntorque = "5 N*m"', ["forward.torque", "not both"],
      id="forward-power-and-torque"),
    P("engine", 'power = "20 kW"', 'torque = "-5 N*m"', ["forward.torque", "≥ 0"], id="forward-negative-torque"),
    P("engine", 'power = "20 kW"', 'power = "20 kg"', ["forward.power", "power"], id="forward-power-wrong-dimension"),
    P("slider", 'C = -1', 'C = -1\n[forward]\nI = "1 kg*m^2"\ntorque = "1 N*m"', ["forward", "crank"],
      id="forward-on-a-slider"),
]


@pytest.mark.parametrize("base, old, new, named", CASES)
def test_problem_file(tmp_path, capsys, base, old, new, named):
    solve_refuses(capsys, tmp_path, edit(BASES[base], old, new), *named)


def test_the_base_files_solve(tmp_path, capsys):
    for name, text in BASES.items():
        path = tmp_path / f"{name}.toml"
        path.write_text(text, encoding="utf-8")
        assert main(["solve", str(path)]) == 0, capsys.readouterr().err
        capsys.readouterr()
