"""The engine's cached plans, its chunks and the memory its results keep (behaviour, not speed).

A mechanism's decomposition and constants are worked out once and reused
(:mod:`graphkin.kinematics.plan`): a cached plan must never answer for
another mechanism, or for one that has changed. Large batches are solved a
chunk at a time, which must not change a digit. And the result of
:func:`graphkin.analytical.solve` keeps the forces, not the solver's
intermediates: its kinematics are worked out again, identically, when read.
Timings are in ``benchmarks/``.
"""

import dataclasses
import gc
import math
import tracemalloc
import weakref
from types import MappingProxyType

import numpy as np
import pytest

import graphkin.analytical.kinetostatics as kinetostatics
import graphkin.kinematics.solver as dyads
from graphkin.analytical import solve, solve_forces
from graphkin.catalog import load as load_problem
from graphkin.catalog import names as catalog_names
from graphkin.kinematics import decompose, solve_kinematics
from graphkin.kinematics.plan import cached_plans, kept_plan, plan_of
from graphkin.model import Active, Driver, Link, Mechanism, PointForce, Revolute, Torque

FIELDS = ("theta", "omega", "alpha", "e", "O", "v_O", "a_O")


def polar(r, deg):
    return (r * math.cos(math.radians(deg)), r * math.sin(math.radians(deg)))


def fourbar(a2=0.085, a3=0.235, m3=2.0, sigma=1, loads=()):
    """A crank-rocker with masses on every moving link (the benchmark's)."""
    links = [
        Link(1, {"A0": (0.0, 0.0), "B0": (0.5, 0.0)}),
        Link(2, {"A0": (0.0, 0.0), "A": (a2, 0.0)}, mass=3.0, I_G=0.03),
        Link(3, {"A": (0.0, 0.0), "B": (a3, 0.0), "C": (0.1, 0.05)}, mass=m3, G=polar(0.231, -1.0), I_G=0.14),
        Link(4, {"B0": (0.0, 0.0), "B": (0.55, 0.0)}, mass=5.1, G=polar(0.305, -7.0), I_G=0.92),
    ]
    joints = [Revolute((1, 2), "A0"), Revolute((2, 3), "A"), Revolute((3, 4), "B"), Revolute((1, 4), "B0")]
    return Mechanism(links, joints, Driver(2), loads, assembly={"B": sigma})


THETA = np.linspace(0.0, 2 * math.pi, 37)


def answer(mech, theta=THETA, **kw):
    r = solve(mech, theta, 94.0, 3.0, **kw)
    return np.column_stack([r.effort, *(r.forces[key] for key in sorted(r.forces))])


def same(a, b):
    np.testing.assert_array_equal(a, b)


# -- plans ----------------------------------------------------------------------------------------------
def test_two_mechanisms_solved_alternately_each_get_their_own_answer():
    m1, m2 = fourbar(), fourbar(a2=0.1, m3=4.0)
    alone1, alone2 = answer(fourbar()), answer(fourbar(a2=0.1, m3=4.0))  # fresh objects, fresh plans
    for _ in range(3):
        same(answer(m1), alone1)
        same(answer(m2), alone2)
    assert not np.allclose(alone1, alone2)
    assert plan_of(m1) is plan_of(m1) and plan_of(m1) is not plan_of(m2)


def test_an_equal_mechanism_is_a_different_object_with_its_own_plan():
    m1, m2 = fourbar(), fourbar()
    assert m1 == m2 and plan_of(m1) is not plan_of(m2)
    same(answer(m1), answer(m2))


def test_replacing_a_link_or_the_branch_gives_a_new_plan_and_a_new_answer():
    m = fourbar()
    before = answer(m)
    heavier = dataclasses.replace(m, links=(*m.links[:2], dataclasses.replace(m.links[2], mass=7.0), m.links[3]))
    crossed = dataclasses.replace(m, assembly={"B": -1})
    assert plan_of(heavier) is not plan_of(m)
    same(answer(heavier), answer(fourbar(m3=7.0)))
    same(answer(crossed), answer(fourbar(sigma=-1)))
    assert not np.allclose(answer(heavier), before) and not np.allclose(answer(crossed), before)
    same(answer(m), before)  # the original is untouched


@pytest.mark.parametrize("change", ["link mass", "link points", "mechanism links", "branch", "joint", "load",
                                    "load window", "gravity"])
def test_changing_a_mechanism_in_place_is_never_answered_from_a_stale_plan(change):
    """Frozen dataclasses can still be changed with object.__setattr__: the plan notices."""
    active = Active(0.5, 2.0)
    loads = (PointForce(3, "C", (100.0, -50.0), active=active), Torque(4, 20.0))
    m = fourbar(loads=loads)
    answer(m)
    old_plan = plan_of(m)
    link3 = m.links[2]
    if change == "link mass":
        object.__setattr__(link3, "mass", 9.0)
        want = fourbar(m3=9.0, loads=loads)
    elif change == "link points":
        object.__setattr__(link3, "points", MappingProxyType({**link3.points, "B": (0.25, 0.0)}))
        want = fourbar(a3=0.25, loads=loads)
    elif change == "mechanism links":
        object.__setattr__(m, "links", (*m.links[:2], dataclasses.replace(link3, mass=9.0), m.links[3]))
        want = fourbar(m3=9.0, loads=loads)
    elif change == "branch":
        object.__setattr__(m, "assembly", MappingProxyType({"B": -1}))
        want = fourbar(sigma=-1, loads=loads)
    elif change == "joint":  # the coupler pinned to the crank at another point of the crank
        crank = dataclasses.replace(m.links[1], points={**m.links[1].points, "A": (0.07, 0.0)})
        object.__setattr__(m, "links", (m.links[0], crank, *m.links[2:]))
        want = fourbar(a2=0.07, loads=loads)
    elif change == "load":
        object.__setattr__(loads[0], "force", (-80.0, 10.0))
        want = fourbar(loads=(PointForce(3, "C", (-80.0, 10.0), active=active), loads[1]))
    elif change == "load window":
        object.__setattr__(active, "stop", 3.0)
        want = fourbar(loads=(PointForce(3, "C", (100.0, -50.0), active=Active(0.5, 3.0)), loads[1]))
    else:
        object.__setattr__(m, "gravity", 9.81)
        want = dataclasses.replace(fourbar(loads=loads), gravity=9.81)
    assert plan_of(m) is not old_plan
    same(answer(m), answer(want))
    same(answer(m, static=True), answer(want, static=True))


def test_the_cache_does_not_keep_a_mechanism_alive():
    gc.collect()
    before = cached_plans()
    m = fourbar(a2=0.0912)
    answer(m)
    assert cached_plans() == before + 1
    ref = weakref.ref(m)
    del m
    gc.collect()
    assert ref() is None and cached_plans() == before


# -- chunks ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("name", catalog_names() + ["fourbar"])
def test_solving_a_chunk_at_a_time_changes_no_digit(name, monkeypatch):
    if name == "fourbar":
        mech, rates = fourbar(), (94.0, 3.0)
    else:
        p = load_problem(name)
        mech, rates = p.mechanism, (float(p.q_dot[0]), float(p.q_ddot[0]))
    crank = mech.driver.kind == "crank"
    q = np.linspace(0.0, 2 * math.pi, 1000, endpoint=False) if crank else np.linspace(-0.6, 0.6, 1000)
    whole = solve(mech, q, *rates)
    kin = solve_kinematics(mech, q, *rates)
    by_kin = solve_forces(kin)
    monkeypatch.setattr(dyads, "CHUNK", 97)
    monkeypatch.setattr(kinetostatics, "CHUNK", 97)
    for r in (solve(mech, q, *rates), solve_forces(solve_kinematics(mech, q, *rates))):
        same(r.effort, whole.effort)
        same(r.valid, whole.valid)
        assert r.forces.keys() == whole.forces.keys() and r.failures.keys() == whole.failures.keys()
        for key in whole.forces:
            same(r.forces[key], whole.forces[key])
        for key in whole.normal:
            same(r.normal[key], whole.normal[key])
            same(r.couple[key], whole.couple[key])
        for why in whole.failures:
            same(r.failures[why], whole.failures[why])
    chunked = solve_kinematics(mech, q, *rates)
    for name_ in FIELDS:
        for link, x in getattr(kin, name_).items():
            same(getattr(chunked, name_)[link], x)
    same(chunked.valid, kin.valid)
    same(by_kin.effort, whole.effort)


# -- what a result keeps ------------------------------------------------------------------------------------
def _owned(x) -> int:
    """Bytes of the buffer an array keeps alive (its base's, if it is a view)."""
    while isinstance(x.base, np.ndarray):
        x = x.base
    return x.nbytes


def test_a_result_keeps_only_its_own_outputs():
    n = 20_000
    r = solve(fourbar(), np.linspace(0, 2 * math.pi, n), 94.0, 3.0)
    for F in r.forces.values():
        assert F.shape == (n, 2) and _owned(F) == n * 16  # its own complex array, not a slice of a temporary
    assert _owned(r.effort) == n * 8 and _owned(r.valid) == n
    kin = r.kinematics
    held = {id(a): _owned(a) for a in (r.effort, r.valid, kin.q, kin.q_dot, kin.q_ddot, kin.valid, *r.forces.values())}
    assert sum(held.values()) <= 100 * n


def test_bytes_kept_per_position():
    n = 100_000
    theta = np.linspace(0, 2 * math.pi, n)
    mech = fourbar()
    solve(mech, theta[:10], 94.0, 3.0)
    gc.collect()
    tracemalloc.start()
    try:
        start = tracemalloc.get_traced_memory()[0]
        r = solve(mech, theta, 94.0, 3.0)
        gc.collect()
        kept, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert r.valid.all()
    # Four joint forces and T12 need 72 bytes a position; with the inputs and the valid masks, 98.
    assert (kept - start) / n <= 150
    # Chunks bound what the solve needs on the way: not a multiple of n.
    assert (peak - start) / n <= 200


def test_the_kinematics_of_a_result_are_worked_out_again_identically():
    mech = fourbar(loads=(PointForce(3, "C", (100.0, -50.0), active=Active(0.5, 2.0)),))
    q = np.linspace(0, 2 * math.pi, 500)
    r = solve(mech, q, 94.0, 3.0)
    kin = solve_kinematics(mech, q, 94.0, 3.0)
    for name in FIELDS:
        got = getattr(r.kinematics, name)
        assert set(got) == set(getattr(kin, name))
        for link, x in getattr(kin, name).items():
            same(got[link], x)
    same(r.kinematics.valid, kin.valid)
    same(solve_forces(r.kinematics).effort, r.effort)
    same(r.kinematics.position(3, "B"), kin.position(3, "B"))
    # and they are the kinematics the forces were found from
    same(solve_forces(kin).effort, r.effort)


def test_a_failing_position_is_named_the_same_way_in_chunks(monkeypatch):
    """An unreachable crank angle (a crank longer than the ground allows) fails in its own chunk only."""
    mech = fourbar(a2=0.3)  # 0.3 + 0.5 > 0.235 + 0.55: cannot assemble near θ = 180°
    q = np.linspace(0, 2 * math.pi, 400, endpoint=False)
    whole = solve(mech, q, 10.0)
    monkeypatch.setattr(dyads, "CHUNK", 64)
    monkeypatch.setattr(kinetostatics, "CHUNK", 64)
    r = solve(mech, q, 10.0)
    assert not whole.valid.all() and whole.valid.any()
    same(r.valid, whole.valid)
    assert r.failures.keys() == whole.failures.keys()
    assert r.kinematics.failures.keys() == whole.kinematics.failures.keys()
    i = int(np.argmin(whole.valid))
    assert r.reason(i) == whole.reason(i) and "cannot be assembled" in r.reason(i)


def test_a_plan_is_made_once_per_mechanism_whatever_is_asked_of_it_first(monkeypatch):
    """A cached property the plan itself asks for (``moving``) or a solver asks for later (``joint_between``'s
    pairs) is worked out from the fields: it must not make the plan look stale and be built again."""
    from collections import OrderedDict

    from graphkin import catalog
    from graphkin.graphical import construct_forces
    from graphkin.kinematics import plan as plans
    from graphkin.problem import shared

    made = []
    monkeypatch.setattr(plans, "decompose", lambda mech: made.append(mech) or decompose(mech))
    # A new mechanism: one read from the same tables before would be shared, with the plan made for it then.
    monkeypatch.setattr(shared, "_MECHANISMS", OrderedDict())
    p = catalog.load("strip_cutter")  # reading the file checks the decomposition: the plan is made there
    result = p.solve()
    construct_forces(result.kinematics, 0)
    p.mechanism.joint_between(2, 3)
    p.solve()
    assert made == [p.mechanism]


def test_a_kept_plan_is_only_read_never_made():
    m = fourbar()
    assert kept_plan(m) is None  # asking makes none
    assert kept_plan(m) is None
    plan = plan_of(m)
    assert kept_plan(m) is plan
    object.__setattr__(m.links[2], "mass", 9.0)
    assert kept_plan(m) is None  # stale once a part changes in place
    assert plan_of(m) is not plan
