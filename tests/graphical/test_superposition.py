"""Superposition as books write it: sub-problems announced, solved, read and added; captions that never contradict.

The graphical route superposes when a dyad has both links loaded: one sub-problem per loaded link, the
others unloaded (Söylemez §6.4.1, the strip cutter; Uicker, Pennock and Shigley §15). Checked here:

- on every catalog problem over a sweep of input positions, the steps in order: each sub-problem is
  announced before its steps and its steps are contiguous, a link called a two-force member carries no load
  in that (sub-)problem, the sums come after every sub-problem, and the sub-problems' forces and driving
  efforts add up to the whole problem's;
- on random mechanisms of every family (hypothesis), the same, and each sub-problem equals the analytical
  solution of the mechanism with only that link's loads (where the equations are linear: no friction, no
  gear flank to choose);
- the strip cutter at 140° (Söylemez), in words.
"""

from __future__ import annotations

import dataclasses
import json
import math
import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphkin import catalog
from graphkin.analytical import solve_forces
from graphkin.graphical import construct_forces
from graphkin.kinematics import solve_kinematics
from graphkin.model import GearMesh, Prismatic
from tests.strategies import families, friction_families

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])

REL = 1e-9
"""Relative tolerance of a sum against the whole problem: the graphical route reads values off exactly."""


def _scopes(sub: str) -> list[str]:
    """``"I.a"`` → ``["I", "I.a"]``: a step's sub-problem and every one enclosing it."""
    parts = sub.split(".") if sub else []
    return [".".join(parts[: k + 1]) for k in range(len(parts))]


def check_steps(c) -> None:
    """The order and the words of a construction's steps; the sub-problems' sums."""
    steps = c.steps
    announced: dict[str, tuple[int, int]] = {}  # sub -> (step index, loaded link)
    finished: set[str] = set()
    current: list[str] = []
    for k, s in enumerate(steps):
        if s.kind == "sub-problem":
            assert s.sub and s.sub not in announced, (k, s.caption)
            assert s.caption.lower().startswith(("sub-problem", "part")), s.caption
            announced[s.sub] = (k, s.link)
        for scope in _scopes(s.sub):
            # Announced before its steps, and never resumed once another sub-problem began.
            assert scope in announced and announced[scope][0] <= k, (k, s.sub, s.caption)
            assert scope not in finished, (k, s.sub, s.caption)
        for scope in current:
            if scope not in _scopes(s.sub):
                finished.add(scope)
        current = _scopes(s.sub)
    top = {sub for sub in announced if "." not in sub}
    assert {sp.label for sp in c.subproblems} == top
    assert not any(s.kind == "readings" and "." in s.sub for s in steps)
    for k, s in enumerate(steps):
        if s.kind != "two-force":
            continue
        M, chain = s.link, _scopes(s.sub)
        assert "carries no load" in s.caption and "two-force member" in s.caption, s.caption
        # Not the loaded link of its sub-problem, nor of any enclosing one, and the announcement says so ...
        for scope in chain:
            k0, loaded = announced[scope]
            assert loaded != M, (k, s.caption)
            unloaded = re.search(r"links? ([\d, and]+?) (?:are|is) unloaded", steps[k0].caption)
            assert unloaded and str(M) in re.findall(r"\d+", unloaded[1]), (steps[k0].caption, M)
        # ... and nothing listed as acting on it in its own (sub-)problem before it; a load listed in an enclosing
        # one (the whole problem's own loads, a reaction passed on in a sub-problem split once more) must be
        # followed by the announcement of a sub-problem or part that leaves it out.
        for j, p in enumerate(steps[:k]):
            if p.kind == "resultant" and p.link == M and p.sub in [""] + chain:
                assert p.sub != s.sub, (k, s.caption, p.caption)
                assert any(announced[sc][0] > j for sc in chain if sc not in _scopes(p.sub)), (k, s.caption, p.caption)
        if len(chain) == 1:
            # Physics: the two forces on a two-force member balance in its sub-problem.
            sp = next(sp for sp in c.subproblems if sp.label == chain[0])
            total = sum(sp.force(other, M) for other in _neighbours(c.mechanism, M))
            size = max(np.hypot(*sp.force(other, M)) for other in _neighbours(c.mechanism, M))
            assert np.hypot(*total) <= 1e-9 * max(size, 1e-300), (k, s.caption)
    if not c.subproblems:
        assert not any(s.sub for s in steps)
        assert not any(s.kind in ("sub-problem", "readings") for s in steps)
        return
    last = max(k for k, s in enumerate(steps) if s.sub)
    sums = [k for k, s in enumerate(steps) if s.kind == "superpose" and not s.sub]
    # Parts that are zero in every sub-problem need no polygon: a note says so, after the sub-problems too.
    sums += [k for k, s in enumerate(steps) if s.kind == "note" and not s.sub and "zero in every sub-problem" in s.caption]
    drivers = [k for k, s in enumerate(steps) if s.kind == "driver" and not s.sub]
    assert sums and min(sums) > last, "the sums come after every sub-problem"
    assert len(drivers) == 1 and drivers[0] > last and drivers[0] == len(steps) - 1
    intro = [k for k, s in enumerate(steps) if s.kind == "note" and s.caption.startswith("Superposition")]
    assert intro and intro[0] < min(announced[sub][0] for sub in top)
    for sp in c.subproblems:
        (readings,) = [s for s in steps if s.kind == "readings" and s.sub == sp.label]
        assert f"Sub-problem {sp.label} gives" in readings.caption
        assert c.driver_name + sp.mark in readings.values
        (driver,) = [s for s in steps if s.kind == "driver" and s.sub == sp.label]
        assert c.driver_name + sp.mark in driver.caption
    check_sums(c)


def _neighbours(mech, link):
    return [(set(j.links) - {link}).pop() for j in mech.joints_of(link)]


def check_sums(c) -> None:
    """The sub-problems' joint forces and driving efforts add up to the whole problem's."""
    subs = c.subproblems
    scale = max([np.hypot(*F) for F in c.forces.values()]
                + [np.hypot(*F) for sp in subs for F in sp.forces.values()] + [1e-300])
    for key in c.forces:
        total = sum(np.asarray(sp.forces[key]) for sp in subs)
        np.testing.assert_allclose(total, c.forces[key], rtol=0, atol=REL * scale, err_msg=str(key))
    # A couple that is zero in the whole problem sums its parts' rounding (1e-16 of the problem's couples), so each
    # is compared at the size of the largest couple anywhere in the construction, as forces are at the largest force.
    lever = max([abs(v) for v in c.couple.values()] + [abs(v) for sp in subs for v in sp.couple.values()] + [1e-300])
    for key in c.couple:
        total = sum(sp.couple[key] for sp in subs)
        assert total == pytest.approx(c.couple[key], rel=0, abs=REL * max(lever, scale * 1e-3))
    # A driving effort that is zero in the whole problem (a load that the frame holds alone) sums its parts'
    # rounding too: it is compared as a couple is, at the construction's largest couple or force, not at its own 0.
    efforts = [sp.effort for sp in subs]
    size = max([abs(c.effort)] + [abs(e) for e in efforts] + [lever, scale * 1e-3])
    assert sum(efforts) == pytest.approx(c.effort, rel=0, abs=REL * size)
    if c.driver_vector is not None:
        np.testing.assert_allclose(sum(np.asarray(sp.driver_vector) for sp in subs), c.driver_vector, rtol=0,
                                   atol=REL * max(size, scale))


def only_loads_of(kin, link):
    """The same kinematics on a mechanism whose only loads are those of ``link`` (the others massless, unloaded)."""
    mech = kin.mechanism
    links = tuple(l if l.number in (link, mech.frame) else dataclasses.replace(l, mass=0.0, I_G=0.0) for l in mech.links)
    loads = tuple(ld for ld in mech.loads if ld.link == link)
    return dataclasses.replace(kin, mechanism=dataclasses.replace(mech, links=links, loads=loads))


def linear(mech) -> bool:
    """Whether each sub-problem is a problem of its own: no friction side, no tooth flank taken from the whole."""
    return not any(isinstance(j, GearMesh) or (isinstance(j, Prismatic) and j.mu > 0) for j in mech.joints)


def check_against_analytical(c, kin, i) -> None:
    """Each sub-problem equals the analytical solution with only its link's loads."""
    for sp in c.subproblems:
        r = solve_forces(only_loads_of(kin, sp.link))
        assert r.valid[i], r.reason(i)
        scale = max([np.hypot(*r.force(*k)[i]) for k in r.forces] + [1e-300])
        for key in r.forces:
            np.testing.assert_allclose(sp.force(*key), r.force(*key)[i], rtol=0, atol=REL * scale,
                                       err_msg=f"sub-problem {sp.label}, {key}")
        size = max(abs(r.effort[i]), scale * 1e-3)
        assert sp.effort == pytest.approx(r.effort[i], rel=0, abs=REL * size * 10), sp.label


# -- every catalog problem over a sweep ------------------------------------------------------------


def _sweep(problem):
    """Input positions to walk: a crank every 10° and three inside the strip cutter's cut; a slider over its range."""
    if problem.given or len(set(problem.q_dot)) > 1 or len(set(problem.q_ddot)) > 1:
        return None  # its own positions only
    if problem.mechanism.driver.kind == "crank":
        return np.radians(np.concatenate([np.arange(0.0, 360.0, 10.0), [125.0, 140.0, 155.0]]))
    lo, hi = float(np.min(problem.q)), float(np.max(problem.q))
    span = max(hi - lo, 0.1 * max(abs(lo), abs(hi), 1e-3))
    return np.linspace(lo - span, hi + span, 25)


@pytest.mark.parametrize("name", catalog.names())
def test_catalog_steps_never_contradict_and_the_sub_problems_add_up(name):
    problem = catalog.load(name)
    kin = problem.kinematics(_sweep(problem))
    checked = 0
    for i in np.flatnonzero(kin.valid):
        c = construct_forces(kin, int(i))
        if not c.valid:
            continue
        check_steps(c)
        if c.subproblems and linear(kin.mechanism):
            check_against_analytical(c, kin, int(i))
        checked += 1
    assert checked


def test_strip_cutter_at_140_deg_in_the_books_order():
    """Söylemez §6.4.1 at θ12 = 140°, inside the cut: sub-problem I (link 3 loaded), II (link 4), then the sum."""
    c = construct_forces(catalog.load("strip_cutter").kinematics([math.radians(140.0)]), 0)
    kinds = [(s.kind, s.sub, s.link) for s in c.steps]
    assert kinds == [
        ("resultant", "", 3), ("resultant", "", 4), ("note", "", None),
        ("sub-problem", "I", 3), ("two-force", "I", 4), ("three-force", "I", 3), ("polygon", "I", 3),
        ("resultant", "I", 2), ("driver", "I", 2), ("readings", "I", 3),
        ("sub-problem", "II", 4), ("two-force", "II", 3), ("three-force", "II", 4), ("polygon", "II", 4),
        ("resultant", "II", 2), ("driver", "II", 2), ("readings", "II", 4),
        ("superpose", "", 3), ("superpose", "", 4), ("superpose", "", 4), ("resultant", "", 2), ("driver", "", 2),
    ]
    words = [s.caption for s in c.steps]
    assert words[1].startswith("Link 4: its inertia force")  # link 4's loads are listed ...
    assert words[3].startswith("Sub-problem I: only the loads on link 3 (R3 = 2268 N); links 2 and 4 are unloaded")
    # ... so link 4 is a two-force member only in sub-problem I, and the caption says so.
    assert words[4].startswith("In sub-problem I, link 4 carries no load, so it is a two-force member: F43′")
    assert words[11].startswith("In sub-problem II, link 3 carries no load, so it is a two-force member: F34″")
    assert [a.name for a in c.steps[6].polygon] == ["R3", "F43′", "F23′"]
    assert [a.name for a in c.steps[17].polygon] == ["F23′", "F23″", "−F23"]
    I, II = c.subproblems
    assert (I.label, I.link, I.mark, II.label, II.link, II.mark) == ("I", 3, "′", "II", 4, "″")
    assert "T12′ = " in words[9] and "T12″ = " in words[16]
    assert I.effort + II.effort == pytest.approx(c.effort, rel=1e-12)
    assert "T12 = T12′ + T12″" in words[-1]
    r = catalog.load("strip_cutter").solve([math.radians(140.0)])
    assert c.effort == pytest.approx(r.effort[0], rel=1e-12)
    check_steps(c)


def test_without_a_dyad_loaded_twice_there_is_no_superposition():
    """The double slider (Söylemez §6.4): only link 3 has mass, so link 4 is a two-force member of the whole problem."""
    c = construct_forces(catalog.load("double_slider").kinematics(), 0)
    assert not c.subproblems and not any(s.sub for s in c.steps)
    step = next(s for s in c.steps if s.kind == "two-force")
    assert step.caption.startswith("Link 4 carries no load, so it is a two-force member")
    check_steps(c)


def test_friction_keeps_the_whole_problems_side_in_every_sub_problem():
    """With friction the sub-problems take the side of the normal force from the whole problem, and still add up."""
    problem = catalog.load("slider_crank_friction")
    kin = problem.kinematics(np.radians(np.arange(0.0, 360.0, 15.0)))
    seen = 0
    for i in np.flatnonzero(kin.valid):
        c = construct_forces(kin, int(i))
        if c.subproblems:
            assert any(s.kind == "note" and s.caption.startswith("Friction") for s in c.steps)
            check_steps(c)
            seen += 1
    assert seen


# -- random mechanisms -------------------------------------------------------------------------------


def check_case(case):
    mech, q, q_dot, q_ddot = case
    kin = solve_kinematics(mech, q, q_dot, q_ddot)
    r = solve_forces(kin)
    for i in np.flatnonzero(r.valid):
        c = construct_forces(kin, int(i))
        assert c.valid, c.reason
        check_steps(c)
        if c.subproblems and linear(mech):
            check_against_analytical(c, kin, int(i))


@SETTINGS
@pytest.mark.parametrize("family", sorted(families))
@given(data=st.data())
def test_sub_problems_add_up_and_equal_the_analytical_route(family, data):
    check_case(data.draw(families[family]))


@SETTINGS
@pytest.mark.parametrize("family", sorted(friction_families))
@given(data=st.data())
def test_sub_problems_add_up_with_friction(family, data):
    check_case(data.draw(friction_families[family]))


# -- a sub-problem split once more; the frame numbered 0; the JSON and the text ---------------------------


def double_dyad():
    """A four-bar 2-3-4 with a second dyad 5-6 hung from its coupler (C) and its rocker (D).

    With links 3, 5 and 6 loaded, sub-problems II (link 5) and III (link 6) pass reactions to both links 3
    and 4 of the first dyad, so each is split once more into parts (a) and (b).
    """
    from graphkin.model import Driver, Link, Mechanism, PointForce, Revolute

    P = {"A0": (0.0, 0.0), "A": (0.05, 0.1 * math.sin(math.radians(60))), "B0": (0.5, 0.0), "B": (0.45, 0.3),
         "C": (0.25, 0.35), "D": (0.475, 0.15), "E": (0.38, 0.45)}

    def pts(*names):
        return {n: P[n] for n in names}

    def mid(a, b):
        return tuple((np.array(P[a]) + np.array(P[b])) / 2)

    links = [Link(1, pts("A0", "B0")), Link(2, pts("A0", "A")), Link(3, pts("A", "B", "C"), 2.0, mid("A", "B"), 0.03),
             Link(4, pts("B0", "B", "D")), Link(5, pts("C", "E"), 1.0, mid("C", "E"), 0.01),
             Link(6, pts("E", "D"), 1.5, mid("E", "D"), 0.01)]
    joints = [Revolute((1, 2), "A0"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), Revolute((1, 4), "B0"),
              Revolute((3, 5), "C"), Revolute((5, 6), "E"), Revolute((4, 6), "D")]
    return Mechanism(links, joints, Driver(2, "crank"), [PointForce(5, "E", (0.0, -30.0), name="P")],
                     assembly={"B": 1, "E": -1})


def test_a_sub_problem_split_once_more():
    q = np.radians(np.arange(0.0, 360.0, 30.0))
    kin = solve_kinematics(double_dyad(), q, np.full(len(q), 10.0), np.full(len(q), 3.0))
    assert kin.valid.all()
    for i in range(len(q)):
        c = construct_forces(kin, i)
        assert [sp.link for sp in c.subproblems] == [3, 5, 6]
        subs = {s.sub for s in c.steps}
        assert {"II.a", "II.b", "III.a", "III.b"} <= subs
        part = next(s for s in c.steps if s.kind == "two-force" and s.sub == "II.a")
        assert part.caption.startswith("In part (a) of sub-problem II, link 4 carries no load") and "F43″a" in part.caption
        check_steps(c)
        check_against_analytical(c, kin, i)


def test_frame_numbered_zero_keeps_its_names_in_the_sub_problems():
    """A static four-bar with the frame 0 and two external loads: F01′, T01′, F03″ … and their sums."""
    from graphkin.problem import parse_problem
    from tests.analytical.test_static_and_numbering import STATIC_FOURBAR

    p = parse_problem(STATIC_FOURBAR, file="static.toml")
    c = construct_forces(p.kinematics(), 0)
    assert [(sp.label, sp.link) for sp in c.subproblems] == [("I", 2), ("II", 3)]
    words = " ".join(s.caption for s in c.steps)
    for name in ("F01′", "T01′", "F03′", "F01″", "T01″", "F03″", "T01 = T01′ + T01″"):
        assert name in words, name
    assert not any(name in words for name in ("T12", "F14", "F13"))  # no names of a frame numbered 1
    assert not any(s.kind == "resultant" and ("inertia" in s.caption) for s in c.steps)  # static: no inertia
    check_steps(c)
    check_against_analytical(c, p.kinematics(), 0)


def test_json_and_text_give_each_sub_problem_then_the_sum(capsys):
    from graphkin.cli import main

    assert main(["solve", "strip_cutter", "--at", "140 deg", "--json"]) == 0
    g = json.loads(capsys.readouterr().out)["positions"][0]["graphical"]
    I, II = g["subproblems"]
    assert (I["label"], I["link"], I["mark"], II["label"], II["link"], II["mark"]) == ("I", 3, "′", "II", 4, "″")
    assert I["driver"]["name"] == II["driver"]["name"] == "T12"
    assert I["driver"]["value"] + II["driver"]["value"] == pytest.approx(g["driver"]["value"], rel=1e-12)
    for name, F in g["forces"].items():
        np.testing.assert_allclose(np.add(I["forces"][name], II["forces"][name]), F, rtol=0, atol=1e-9 * 2000)
    assert [s["sub"] for s in g["steps"]][3:5] == ["I", "I"] and g["steps"][3]["kind"] == "sub-problem"
    assert main(["solve", "strip_cutter", "--at", "140 deg"]) == 0
    text = capsys.readouterr().out
    table = text[text.index("Superposition: each sub-problem"):]
    head, *rows = table.splitlines()[1:7]
    assert head.split() == ["force", "I", "(link", "3)", "II", "(link", "4)", "sum"]
    assert [r.split()[0] for r in rows] == ["F23", "F34", "F14", "F12", "T12"]
    T = rows[-1].split()
    assert float(T[1]) + float(T[3]) == pytest.approx(float(T[5]), abs=2e-4)
