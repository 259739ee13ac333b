"""Static force analysis and the book's numbering of the frame (issue 13, items 1 and 2).

- ``analysis = "static"``: no masses needed, no inertia loads by either route, the report says so and has no
  "Inertia loads" section; a dynamic problem without its input speed is an error naming the field;
- ``[frame] number = 0``: every printed name (F01, F03, T01), the JSON, the figures' labels, the graphical
  construction and an exercise's ``find`` follow the book's numbering;
- hypothesis, on random linkages of every family solved statically (half of them with the frame numbered 0):
  every link balances without inertia loads, F_ij = −F_ji, the graphical route equals the analytical one.
"""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphkin import catalog
from graphkin.analytical import solve_forces
from graphkin.cli import main
from graphkin.graphical import construct_forces
from graphkin.kinematics import solve_kinematics
from graphkin.model import Prismatic
from graphkin.problem import parse_problem
from graphkin.report import constructions, format_solution, solution
from tests.physics import active, close, joint_point, load_value
from tests.strategies import families, length_scale

STATIC_FOURBAR = """
title = "Static four-bar, frame numbered 0"
analysis = "static"

[frame]
number = 0
points = { A0 = ["0 mm", "0 mm"], B0 = ["300 mm", "0 mm"] }

[[links]]
number = 1
points = { A0 = ["0 mm", "0 mm"], A = ["100 mm", "0 mm"] }

[[links]]
number = 2
points = { A = ["0 mm", "0 mm"], B = ["250 mm", "0 mm"], C = ["125 mm", "50 mm"] }
mass = "3 kg"
I_G = "0.02 kg*m^2"

[[links]]
number = 3
points = { B0 = ["0 mm", "0 mm"], B = ["200 mm", "0 mm"], D = ["100 mm", "0 mm"] }

[[joints]]
type = "revolute"
links = [0, 1]
point = "A0"

[[joints]]
type = "revolute"
links = [1, 2]
point = "A"

[[joints]]
type = "revolute"
links = [2, 3]
point = "B"

[[joints]]
type = "revolute"
links = [3, 0]
point = "B0"

[driver]
link = 1
theta = "60 deg"

[[loads]]
type = "force"
name = "P"
link = 2
point = "C"
force = ["0 N", "-100 N"]

[[loads]]
type = "force"
name = "Q"
link = 3
point = "D"
force = ["40 N", "0 N"]
"""


@pytest.fixture(scope="module")
def static_problem():
    return parse_problem(STATIC_FOURBAR, file="static.toml")


def test_static_needs_no_mass_and_has_no_inertia(static_problem):
    p = static_problem
    assert p.static and p.mechanism.frame == 0
    r = p.solve()
    # Link 2 has a mass and I_G, but a static analysis leaves inertia out: it balances its external load alone.
    inn = r.inertia(2)
    assert not np.any(inn.F) and not np.any(inn.T)
    F_ext = np.array([0.0, -100.0])
    np.testing.assert_allclose(r.force(1, 2)[0] + r.force(3, 2)[0] + F_ext, 0.0, atol=1e-12)
    c = construct_forces(r.kinematics, 0)
    assert c.valid and not c.inertia
    assert not any("inertia" in s.caption for s in c.steps)


def test_static_report(static_problem):
    r = static_problem.solve()
    text = format_solution(static_problem, r, constructions(r))
    assert "analysis: static" in text and "link 0 is the frame" in text
    assert "Inertia loads" not in text and "Kinematics" not in text and "ω =" not in text
    for name in ("F01", "F12", "F23", "F03", "T01", "F10 = −F01", "F30 = −F03"):
        assert name in text, name
    data = solution(static_problem, r, constructions(r))
    assert data["analysis"] == "static" and data["frame"] == 0 and data["driver"]["name"] == "T01"
    pos = data["positions"][0]
    assert set(pos["forces"]) >= {"F01", "F10", "F03", "F30", "F12", "F21"}
    assert set(pos["links"]) == {"1", "2", "3"}
    g = pos["graphical"]
    assert g["driver"]["name"] == "T01" and max(g["relative_difference"].values()) < 1e-12


def test_the_frame_number_reaches_the_figure(static_problem, tmp_path):
    from graphkin import draw

    r = static_problem.solve()
    c = constructions(r)[0]
    fig = draw.draw_solution(c, r)
    texts = " ".join(t.get_text() for ax in fig.axes for t in ax.texts) + " ".join(ax.get_title() for ax in fig.axes)
    assert "F₀₁" in texts or "F01" in texts
    assert "T₀₁" in texts or "T01" in texts
    assert "θ₀₁" in texts
    import matplotlib.pyplot as plt

    plt.close(fig)


def test_cli_static_frame_zero(tmp_path, capsys):
    path = tmp_path / "static.toml"
    path.write_text(STATIC_FOURBAR, encoding="utf-8")
    assert main(["solve", str(path)]) == 0
    out = capsys.readouterr().out
    assert "T01 = " in out and "analysis: static" in out
    assert main(["solve", str(path), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["frame"] == 0


def test_exercise_find_with_the_books_numbering(tmp_path):
    from graphkin.exercises import load_exercise

    (tmp_path / "base.toml").write_text(STATIC_FOURBAR, encoding="utf-8")
    (tmp_path / "ex.toml").write_text('''title = "Static four-bar"
problem = "base.toml"

[vary.P]
field = "loads[0].force[1]"
from = "-150 N"
to = "-50 N"
step = "10 N"

[[questions]]
id = "F03"
find = "F03"
ask = "F03, the force of the frame on the rocker"

[[questions]]
id = "T01"
find = "T01"
ask = "the driving torque T01"
''', encoding="utf-8")
    ex = load_exercise(tmp_path / "ex.toml")
    assert [q.find for q in ex.questions] == ["F03", "T01"]


def test_dynamic_problem_needs_its_speed():
    text = catalog.path("strip_cutter").read_text().replace('omega = "900 rpm"\n', "")
    with pytest.raises(Exception, match="driver.omega: is missing"):
        parse_problem(text, file="cutter.toml")


@pytest.mark.parametrize("name", catalog.names())
def test_every_catalog_problem_loads_as_its_file_says(name):
    """Dynamic unless the file says ``analysis = "static"`` (the default is never static by accident)."""
    p = catalog.load(name)
    static = 'analysis = "static"' in catalog.path(name).read_text(encoding="utf-8")
    assert p.analysis == ("static" if static else "dynamic") and p.static == static


@pytest.mark.parametrize("extra, field", [
    ('\n[given.2]\nalpha = "3 rad/s^2"\n', "given.2.alpha"),
    ('\n[given.2]\na_G = ["1 m/s^2", "0 m/s^2"]\n', "given.2.a_G"),
])
def test_static_refuses_what_it_would_not_use(tmp_path, capsys, extra, field):
    """One line, exit 2, the field named (the bad-input catalogue's rule)."""
    path = tmp_path / "s.toml"
    path.write_text(STATIC_FOURBAR + extra, encoding="utf-8")
    assert main(["solve", str(path)]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and err.startswith("graphkin: error: ")
    assert str(path) in err and field in err and "static" in err


def test_cycle_figure_follows_the_numbering():
    import matplotlib.pyplot as plt

    from graphkin import draw
    from graphkin.cycle import sweep

    dynamic = STATIC_FOURBAR.replace('analysis = "static"', "").replace('theta = "60 deg"',
                                                                     'theta = "60 deg"\nomega = "300 rpm"')
    dynamic = dynamic.replace('number = 3\n', 'number = 3\nmass = "1.5 kg"\n').replace('number = 1\n',
                                                                                           'number = 1\nmass = "1 kg"\n', 1)
    p = parse_problem(dynamic, file="dynamic.toml")
    assert not p.static and p.mechanism.frame == 0
    fig = draw.draw_cycle(sweep(p, 36), Cs=0.05)
    labels = [ax.get_xlabel() for ax in fig.axes]
    assert labels[0] == labels[2] == "crank angle θ₀₁ [°]"
    assert "T₀₁" in fig.axes[0].get_ylabel()
    plt.close(fig)


# -- hypothesis: random linkages solved statically (half of them with the frame numbered 0: tests/strategies.py) --

SETTINGS = settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                             HealthCheck.filter_too_much])


def static_loads(kin, r, link):
    """Every load on ``link`` in a static analysis, as (force (n,2) or None, point or None, couple or None).

    As :func:`tests.properties.test_equilibrium.loads_on`, with the frame's own number and without inertia loads.
    """
    mech = kin.mechanism
    out = []
    for joint in mech.joints_of(link):
        lo, hi = sorted(joint.links)
        other = lo if link == hi else hi
        out.append((r.force(other, link), joint_point(kin, joint, link), None))
        if isinstance(joint, Prismatic):
            out.append((None, None, (1.0 if link == hi else -1.0) * r.couple[(lo, hi)]))
    d = mech.driver
    if link == d.link:
        if d.kind == "crank":
            out.append((None, None, r.effort))
        else:
            J = mech.joint_between(mech.frame, link)
            out.append((r.effort[:, None] * kin.guide_direction(J), kin.position(link, J.point), None))
    for load in mech.loads:
        if load.link == link:
            if hasattr(load, "point"):  # a spring's force follows its length: load_value works it out
                out.append((load_value(kin, load), kin.position(link, load.point), None))
            else:
                out.append((None, None, active(kin, load) * load.torque))
    if mech.gravity:
        out.append((np.broadcast_to([0.0, -mech.link(link).mass * mech.gravity], (kin.n, 2)), kin.G(link), None))
    return out


def _static(data, family):
    case = data.draw(families[family])
    kin = dataclasses.replace(solve_kinematics(*case), static=True)
    r = solve_forces(kin)
    assert r.valid.all(), [r.reason(i) for i in range(r.n)]
    return kin, r


@pytest.mark.parametrize("family", sorted(families))
@SETTINGS
@given(data=st.data())
def test_static_every_link_balances_without_inertia(family, data):
    kin, r = _static(data, family)
    mech = kin.mechanism
    L = length_scale(mech)
    scale = np.zeros(kin.n)
    parts = {}
    for link in mech.moving:
        parts[link] = static_loads(kin, r, link)
        for force, X, couple in parts[link]:
            if force is not None:
                scale = np.maximum(scale, np.linalg.norm(force, axis=-1) * (L + np.linalg.norm(X, axis=-1)))
            if couple is not None:
                scale = np.maximum(scale, np.abs(couple))
    for link in mech.moving:
        G = kin.G(link)
        F, M = np.zeros((kin.n, 2)), np.zeros(kin.n)
        for force, X, couple in parts[link]:
            if force is not None:
                d = X - G
                F, M = F + force, M + d[:, 0] * force[:, 1] - d[:, 1] * force[:, 0]
            if couple is not None:
                M = M + couple
        ok, excess = close(F * L, 0.0, 1e-9 * scale)
        assert ok, f"link {link}: ΣF ≠ 0 ({excess:.3g})"
        ok, excess = close(M, 0.0, 1e-9 * scale)
        assert ok, f"link {link}: ΣM ≠ 0 ({excess:.3g})"


@pytest.mark.parametrize("family", sorted(families))
@SETTINGS
@given(data=st.data())
def test_static_action_equals_minus_reaction_and_names(family, data):
    kin, r = _static(data, family)
    mech = kin.mechanism
    for joint in mech.joints:
        i, j = joint.links
        np.testing.assert_array_equal(r.force(i, j), -r.force(j, i))
        letter = joint.force_letter
        np.testing.assert_array_equal(r[f"{letter}{i}{j}"], -r[f"{letter}{j}{i}"])
    assert r.driver_name == f"{'T' if mech.driver.kind == 'crank' else 'F'}{mech.frame}{mech.driver.link}"


@pytest.mark.parametrize("family", sorted(families))
@SETTINGS
@given(data=st.data())
def test_static_graphical_equals_analytical(family, data):
    kin, r = _static(data, family)
    for i in range(r.n):
        c = construct_forces(kin, i)
        assert c.valid, c.reason
        assert not any(s.caption.find("inertia") >= 0 for s in c.steps)
        scale = max(np.abs(r.force(*k)[i]).max() for k in r.forces)
        if scale == 0:
            continue
        for key in r.forces:
            np.testing.assert_allclose(c.force(*key), r.force(*key)[i], rtol=0, atol=1e-9 * scale)
        effort_scale = max(abs(r.effort[i]), scale * 1e-3 * length_scale(kin.mechanism))
        assert c.effort == pytest.approx(r.effort[i], rel=0, abs=1e-9 * effort_scale * 10)
