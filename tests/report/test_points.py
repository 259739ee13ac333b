"""Every named point's position, velocity and acceleration in the JSON (issue 13, item 6).

``graphkin solve --json`` gives them per position under ``links[n]["points"]``; ``graphkin cycle --json`` gives
them as arrays over the cycle under ``links``. Checked against:

- finite differences of the positions over the input (the cycle's own arrays, and a five-point stencil around
  random positions of random mechanisms of every family, hypothesis): v = r′(q) q̇, a = r″(q) q̇² + r′(q) q̈;
- the rigid-body formula between two points of one link: v_P − v_A = ω × r_AP, a_P − a_A = α × r_AP − ω² r_AP;
- values given in the problem file ([given.N] ω, α, v_G, a_G): the points follow them.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphkin import catalog
from graphkin.analytical import solve_forces
from graphkin.cli import main
from graphkin.cycle import sweep
from graphkin.kinematics import solve_kinematics
from graphkin.kinematics.points import link_points, point_motion, rigid_body
from graphkin.report import cycle_data, cycle_links, solution
from tests.strategies import families, length_scale

SETTINGS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _cross_w(w, r):
    """ω × r for a plane vector r and a scalar ω (k × r scaled)."""
    return np.array([-w * r[1], w * r[0]])


def check_rigid(entry):
    """Every pair of points of every link obeys the rigid-body formula, G included."""
    for link, s in entry["links"].items():
        pts = dict(s["points"])
        pts["G"] = {"position": s["G"], "velocity": s["v_G"], "acceleration": s["a_G"]}
        w, al = s["omega"], s["alpha"]
        size = max(np.hypot(*p["position"]) for p in pts.values()) + 1e-300
        vscale = max([np.hypot(*p["velocity"]) for p in pts.values()] + [abs(w) * size, 1e-300])
        ascale = max([np.hypot(*p["acceleration"]) for p in pts.values()] + [(abs(al) + w * w) * size, 1e-300])
        A = pts["G"]
        for name, P in pts.items():
            r = np.subtract(P["position"], A["position"])
            v = np.add(A["velocity"], _cross_w(w, r))
            a = np.add(A["acceleration"], _cross_w(al, r)) - w * w * r
            np.testing.assert_allclose(P["velocity"], v, rtol=0, atol=1e-12 * vscale, err_msg=f"v of {name} on {link}")
            np.testing.assert_allclose(P["acceleration"], a, rtol=0, atol=1e-12 * ascale, err_msg=f"a of {name} on {link}")


def test_solve_json_has_every_point_of_every_link(capsys):
    """The strip cutter at two crank angles (--at), the cut's C on links 3 and 4 apart: every point, SI."""
    assert main(["solve", "strip_cutter", "--at", "100 deg,140 deg", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    problem = catalog.load("strip_cutter")
    kin = problem.kinematics(np.radians([100.0, 140.0]))
    assert len(data["positions"]) == 2
    for i, entry in enumerate(data["positions"]):
        for link in problem.mechanism.moving:
            s = entry["links"][str(link)]
            assert set(s["points"]) == set(problem.mechanism.link(link).points)
            for name, p in s["points"].items():
                assert set(p) == {"position", "velocity", "acceleration"}
                np.testing.assert_allclose(p["position"], kin.position(link, name)[i], rtol=1e-14, atol=1e-15)
                np.testing.assert_allclose(p["velocity"], kin.velocity(link, name)[i], rtol=1e-12, atol=1e-12)
                np.testing.assert_allclose(p["acceleration"], kin.acceleration(link, name)[i], rtol=1e-11, atol=1e-9)
            np.testing.assert_allclose(s["v_G"], kin.v_G(link)[i], rtol=1e-12, atol=1e-12)
        check_rigid(entry)
        # C of the coupler and C of the rocker are two points, not one.
        c3, c4 = entry["links"]["3"]["points"]["C"], entry["links"]["4"]["points"]["C"]
        assert np.hypot(*np.subtract(c3["velocity"], c4["velocity"])) > 0.1


@pytest.mark.parametrize("name", catalog.names())
def test_every_catalog_problem_obeys_the_rigid_body_formula(name):
    problem = catalog.load(name)
    data = solution(problem, problem.solve())
    for entry in data["positions"]:
        if entry["valid"]:
            check_rigid(entry)


def test_given_kinematics_move_the_points_with_them():
    """With ω, α, v_G, a_G given for link 3 (read off a drawing), its points follow the given values, not the derived."""
    kin = catalog.load("strip_cutter").kinematics([math.radians(140.0)])
    given = {(3, "omega"): np.array([-8.0]), (3, "alpha"): np.array([2600.0]),
             (3, "v_G"): np.array([[-3.6, -7.3]]), (3, "a_G"): np.array([[81.0, -131.0]])}
    g = kin.with_given(given)
    G = g.G(3)[0]
    for name in ("A", "B", "C"):
        m = point_motion(g, 3, name)
        r = m.position[0] - G
        np.testing.assert_allclose(m.velocity[0], given[(3, "v_G")][0] + _cross_w(-8.0, r), rtol=1e-14, atol=1e-13)
        np.testing.assert_allclose(m.acceleration[0], given[(3, "a_G")][0] + _cross_w(2600.0, r) - 64.0 * r,
                                   rtol=1e-14, atol=1e-11)


def test_rigid_body_helper():
    """v_P = v_A + ω × r_AP, a_P = a_A + α × r_AP − ω² r_AP, over a batch."""
    rA = np.array([[0.0, 0.0], [1.0, 1.0]])
    rP = rA + [[0.2, 0.0], [0.0, 0.5]]
    v, a = rigid_body(rA, [[1.0, 0.0], [0.0, 0.0]], [[0.0, 0.0], [0.0, -9.81]], [3.0, -2.0], [10.0, 0.0], rP)
    np.testing.assert_allclose(v, [[1.0, 0.6], [1.0, 0.0]])
    np.testing.assert_allclose(a, [[-1.8, 2.0], [0.0, -9.81 - 2.0]])


# -- the cycle's arrays against finite differences ----------------------------------------------------


def _uniform(q, n):
    """Indices of the equally spaced angles of a cycle (without the samples either side of a switching angle)."""
    k = q / (2 * math.pi / n)
    return np.flatnonzero(np.abs(k - np.round(k)) < 1e-10)


CRANKS = [name for name in catalog.names() if catalog.load(name).mechanism.driver.kind == "crank"
          and not catalog.load(name).given and len(set(catalog.load(name).q_dot)) == 1
          and len(set(catalog.load(name).q_ddot)) == 1]


@pytest.mark.parametrize("name", CRANKS)
def test_cycle_json_points_match_finite_differences(name):
    """Central differences over 720 crank angles: v = dr/dθ ω and a = d²r/dθ² ω² + dr/dθ α (ω, α constant)."""
    n = 720
    problem = catalog.load(name)
    data = json.loads(json.dumps(cycle_data(sweep(problem, n))))
    q = np.asarray(data["input"]["values"])
    keep = _uniform(q, n)
    assert len(keep) == n
    h = 2 * math.pi / n
    w, al = float(problem.q_dot[0]), float(problem.q_ddot[0])

    def largest(kind):
        return max(max(np.abs(m[kind]["x"]).max(), np.abs(m[kind]["y"]).max())
                   for s in data["links"].values() for m in [s["G"], *s["points"].values()])

    # The mechanism's fastest point sets the scale: a pivot's zero velocity is checked to that scale too.
    vscale, ascale = largest("velocity"), largest("acceleration")
    for link, s in data["links"].items():
        motions = dict(s["points"], G=s["G"])
        assert set(s["points"]) == set(problem.mechanism.link(int(link)).points)
        for pname, m in motions.items():
            r = np.column_stack([m["position"]["x"], m["position"]["y"]])[keep]
            v = np.column_stack([m["velocity"]["x"], m["velocity"]["y"]])[keep]
            a = np.column_stack([m["acceleration"]["x"], m["acceleration"]["y"]])[keep]
            d1, d2 = _d1(r, h), _d2(r, h)
            np.testing.assert_allclose(d1 * w, v, rtol=0, atol=2e-4 * vscale, err_msg=f"v of {pname} on {link}")
            np.testing.assert_allclose(d2 * w * w + d1 * al, a, rtol=0, atol=2e-4 * ascale,
                                       err_msg=f"a of {pname} on {link}")
            # And the velocity's own differences give the acceleration (ω is the same at every sample, so α
            # enters through dr/dθ).
            np.testing.assert_allclose(_d1(v, h) * w + d1 * al, a, rtol=0, atol=2e-4 * ascale,
                                       err_msg=f"dv/dt of {pname} on {link}")


def _d1(f, h):
    """df/dθ of samples h apart round a closed cycle: central differences at h and 2h, Richardson-extrapolated.

    The plain central difference errs by about h²/6 of the third derivative, which is 3e-4 of the largest
    acceleration where a quick return's lever swings back sharply; the extrapolation leaves an error of order
    h⁴ (about 1e-7 of the size here), so the tolerance below keeps its meaning for every mechanism.
    """
    D = lambda k: (np.roll(f, -k, 0) - np.roll(f, k, 0)) / (2 * k * h)  # noqa: E731
    return (4 * D(1) - D(2)) / 3


def _d2(f, h):
    """d²f/dθ², the same way: second differences at h and 2h, Richardson-extrapolated."""
    D = lambda k: (np.roll(f, -k, 0) - 2 * f + np.roll(f, k, 0)) / (k * h) ** 2  # noqa: E731
    return (4 * D(1) - D(2)) / 3


def test_cycle_json_links_have_one_value_per_position_and_null_where_invalid():
    problem = catalog.load("double_slider")
    # Past the dead point at s = 500 mm the linkage cannot be assembled.
    cycle = sweep(problem, at=np.array([0.1, 0.2, 0.3, 0.6]))
    data = cycle_data(cycle)
    s = data["links"]["3"]
    assert len(s["theta"]) == data["n"] == 4
    assert s["theta"][3] is None and s["points"]["B"]["velocity"]["x"][3] is None
    assert all(x is not None for x in s["points"]["B"]["velocity"]["x"][:3])


# -- random mechanisms: a five-point stencil around each drawn position -------------------------------


@SETTINGS
@pytest.mark.parametrize("family", sorted(families))
@given(data=st.data())
def test_points_match_finite_differences_on_random_mechanisms(family, data):
    mech, q, q_dot, q_ddot = data.draw(families[family])
    L = length_scale(mech)
    crank = mech.driver.kind == "crank"
    # A slider's step is finer: a crank driven by its piston turns by dθ/ds ~ 1/(r sin θ) per metre, and a planet on
    # it by several times that, so a step of 1e-3 L leaves a truncation error (∝ h⁴) of the stencil's second
    # difference near the tolerance; at 1e-4 L it is 1e-4 of that, and rounding (ε r / h² ~ 2e-8 r/L²) far below.
    h = 1e-3 if crank else 1e-4 * L
    for q0, w, al in zip(q, q_dot, q_ddot):
        kin = solve_kinematics(mech, q0 + np.arange(-2, 3) * h, np.full(5, w), np.full(5, al))
        if not kin.valid.all():
            continue
        # The sizes of v and a the input's rates make, for a crank (r′ ~ L) and for a slider (r′ ~ 1, r″ ~ 1/L).
        v_ref = abs(w) * (L if crank else 1.0) + 1e-300
        a_ref = (w * w + abs(al)) * L if crank else w * w / L + abs(al) + 1e-300
        links = cycle_links(solve_forces(kin))
        for link in mech.moving:
            assert set(links[str(link)]["points"]) == set(mech.link(link).points)
            for pname, m in link_points(kin, link).items():
                r, v, a = m.position, m.velocity, m.acceleration
                d1 = (r[0] - 8 * r[1] + 8 * r[3] - r[4]) / (12 * h)
                d2 = (-r[0] + 16 * r[1] - 30 * r[2] + 16 * r[3] - r[4]) / (12 * h * h)
                np.testing.assert_allclose(d1 * w, v[2], rtol=0, atol=1e-6 * v_ref, err_msg=f"v of {pname} on {link}")
                np.testing.assert_allclose(d2 * w * w + d1 * al, a[2], rtol=0, atol=1e-5 * a_ref,
                                           err_msg=f"a of {pname} on {link}")
                series = links[str(link)]["points"][pname]
                assert [series["velocity"]["x"][2], series["velocity"]["y"][2]] == [float(v[2, 0]), float(v[2, 1])]
                assert [series["acceleration"]["x"][2], series["acceleration"]["y"][2]] == [float(a[2, 0]),
                                                                                          float(a[2, 1])]
