"""The catalog, the plain-data report and the command line."""

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from graphkin import catalog
from graphkin.analytical.matrix import assemble, solve_matrix
from graphkin.cli import main


@pytest.mark.parametrize("name", catalog.names())
def test_every_catalog_problem_solves_and_matches_the_matrix(name):
    problem = catalog.load(name)
    assert problem.source, "every catalog problem cites its source"
    r = problem.solve()
    assert r.valid.all(), r.reason(int(np.argmin(r.valid)))
    m = solve_matrix(r)
    scale = max(np.abs(F).max() for F in r.forces.values())
    for key, F in r.forces.items():
        np.testing.assert_allclose(m.forces[key], F, rtol=0, atol=1e-9 * scale)
    np.testing.assert_allclose(m.effort, r.effort, rtol=1e-9, atol=1e-9 * scale)
    system = assemble(r)
    assert system.A.shape == (r.n, 3 * len(r.mechanism.moving), 3 * len(r.mechanism.moving))


def test_single_link_by_hand():
    """Norton §11.2: T12 = I_O α − r_P × F_P and F12 = m a_G − F_P (numbers of our catalog file)."""
    r = catalog.load("single_link").solve()
    m, L, theta, omega, alpha = 2.0, 0.25, math.radians(30), 20.0, 15.0
    I_O = m * L**2 / 12 + m * (L / 2) ** 2
    F_P = 40 * np.array([math.cos(math.radians(60)), math.sin(math.radians(60))])
    r_P = L * np.array([math.cos(theta), math.sin(theta)])
    T12 = I_O * alpha - (r_P[0] * F_P[1] - r_P[1] * F_P[0])
    e, n = np.array([math.cos(theta), math.sin(theta)]), np.array([-math.sin(theta), math.cos(theta)])
    a_G = (L / 2) * (alpha * n - omega**2 * e)
    assert r["T12"][0] == pytest.approx(T12, rel=1e-12)
    np.testing.assert_allclose(r["F12"][0], m * a_G - F_P, rtol=1e-12)


def test_gear_tooth_force_lies_on_the_pressure_line():
    r = catalog.load("gearset").solve()
    F = r["F23"][0]
    k = r.kinematics
    centre_line = k.position(3, "O3")[0] - k.position(2, "O2")[0]
    tangent = np.array([-centre_line[1], centre_line[0]])
    # The angle between the tooth force and the common tangent is the pressure angle.
    cos = abs(F @ tangent) / (np.linalg.norm(F) * np.linalg.norm(tangent))
    assert math.degrees(math.acos(cos)) == pytest.approx(20.0, abs=1e-9)
    # Its radial part pushes the pinion away from the gear.
    assert F @ centre_line > 0
    # Moment balance of the pinion about its fixed centre: r × F + T13 = I α3,
    # with the pitch point at r = −r3 ê from the pinion's centre.
    I3, alpha3 = 0.0005, k.alpha[3][0]
    assert -0.040 * (F @ tangent / np.linalg.norm(tangent)) + 8.0 == pytest.approx(I3 * alpha3, rel=1e-12)


def test_friction_opposes_sliding_with_mu_times_normal():
    r = catalog.load("slider_crank_friction").solve()
    k = r.kinematics
    joint = r.mechanism.joint_between(1, 4)
    u = k.guide_direction(joint)
    friction = np.sum(r["G14"] * u, axis=1)
    v = k.slide_rate(joint, 4)
    moving = np.abs(v) > 1e-9
    assert np.all(np.sign(friction[moving]) == -np.sign(v[moving]))
    np.testing.assert_allclose(np.abs(friction), 0.2 * np.abs(r.normal[(1, 4)]), rtol=1e-12)


def test_cutting_force_switches_on_and_off():
    problem = catalog.load("strip_cutter")
    on = problem.solve(at=np.radians([130.0]))
    off = problem.solve(at=np.radians([160.0]))
    from graphkin.analytical import external_loads

    assert external_loads(on.kinematics, 3)[0][0] == pytest.approx([0.0, 2000.0], abs=1e-9)
    assert external_loads(off.kinematics, 3)[0][0] == pytest.approx([0.0, 0.0])


def test_json_schema(capsys):
    assert main(["solve", "double_slider", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["problem"] == "double_slider" and data["driver"]["name"] == "F12"
    (pos,) = data["positions"]
    assert pos["valid"] and pos["input"] == {"name": "s", "value": 0.2, "rate": 2.0, "rate2": 0.0}
    for name in ("F23", "F32", "F34", "F43", "G14", "G41", "G12", "G21"):
        assert len(pos["forces"][name]) == 2
    assert pos["forces"]["F32"] == [-c for c in pos["forces"]["F23"]]
    assert pos["driver"]["name"] == "F12" and pos["driver"]["vector"][0] == pytest.approx(7.5586, rel=1e-4)
    assert pos["links"]["3"]["h"] == pytest.approx(0.03333, rel=1e-3)
    assert set(pos["prismatic"]["G14"]) >= {"normal", "friction", "couple", "offset"}


def test_text_output_and_at(capsys):
    assert main(["solve", "strip_cutter", "--at", "124 deg, 130 deg"]) == 0
    out = capsys.readouterr().out
    assert "Position 2 of 2: θ = 130°" in out
    assert "T12 =" in out and "F23" in out and "∠" in out and "h =" in out


def _three_positions(tmp_path) -> Path:
    """The strip cutter at its own three positions (0°, 120°, 240°): a cycle's batch, quick to draw."""
    text = catalog.path("strip_cutter").read_text(encoding="utf-8")
    assert 'step = "2 deg"' in text
    path = tmp_path / "cutter3.toml"
    path.write_text(text.replace('step = "2 deg"', 'step = "120 deg"'), encoding="utf-8")
    return path


def test_a_figure_over_the_problems_own_positions_is_one_at_the_largest_effort(tmp_path, capsys):
    # Issue 40: `solve strip_cutter -o sc.png` drew every one of the 180 positions (153 MB, 11 minutes).
    problem = _three_positions(tmp_path)
    effort = np.abs(catalog.load(str(problem)).solve().effort)
    i = int(np.argmax(effort))
    assert np.count_nonzero(effort == effort[i]) == 1  # one position is the largest, or the test means nothing
    assert main(["solve", str(problem), "-o", str(tmp_path / "f.png")]) == 0
    err = capsys.readouterr().err.splitlines()
    assert sorted(p.name for p in tmp_path.glob("*.png")) == ["f.png"]
    assert err[0] == (f"graphkin: drawing position {i + 1} of 3 (θ = {120 * i}°), where |T12| is largest; "
                      "--every-position draws all 3")
    assert err[1:] == [f"figure written to {tmp_path / 'f.png'}"]


def test_every_position_draws_one_figure_each(tmp_path, capsys):
    problem = _three_positions(tmp_path)
    assert main(["solve", str(problem), "-o", str(tmp_path / "f.png"), "--every-position"]) == 0
    assert sorted(p.name for p in tmp_path.glob("*.png")) == ["f_1.png", "f_2.png", "f_3.png"]
    assert "--every-position" not in capsys.readouterr().err


def test_list(capsys):
    assert main(["list"]) == 0
    out = capsys.readouterr().out
    lines = out.splitlines()
    for name in catalog.names():
        assert name in out
        assert f"family: {catalog.family(name)}" in out  # each problem's family of mechanism (issue 13)
        # The name stands apart from its title, however long it is (fourbar_two_loads_makdin ran into "Static").
        assert any(line.startswith(f"{name}  ") for line in lines), name


@pytest.mark.parametrize("command", [["-m", "graphkin"], "console script"])
def test_console_script_and_python_m_run_the_default_example(command):
    script = Path(sys.executable).with_name("graphkin")
    if command == "console script" and not script.exists():
        pytest.skip("graphkin is not installed as a console script beside this Python")
    argv = [str(script)] if command == "console script" else [sys.executable, *command]
    out = subprocess.run([*argv, "solve", catalog.DEFAULT], capture_output=True, text=True)
    assert out.returncode == 0 and "F12 = 7.559 N ∠ 0.00°" in out.stdout


def test_import_loads_no_heavy_layers():
    code = (
        "import sys, graphkin, graphkin.model, graphkin.kinematics, graphkin.analytical, graphkin.problem, graphkin.catalog,"
        " graphkin.graphical, graphkin.cycle, graphkin.report;"
        "print([m for m in ('matplotlib', 'ipywidgets', 'pint', 'IPython') if m in sys.modules])"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"
