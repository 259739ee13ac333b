"""A value that is not a number is the worst disagreement there is (issue 35's guard).

The guard kept the worst difference with ``if not gap <= worst``: a nan became the worst, and the next value,
``not gap <= nan``, took its place, so a nan anywhere but last passed as agreement. Each test puts a nan in one
value of a construction that agrees, in turn at every place, and checks that the guard names it.
"""

from __future__ import annotations

import dataclasses
import math
import sys

import pytest

from graphkin import catalog
from graphkin.graphical import construct_forces, construct_kinematics, guard, instant_centres, polygons


@pytest.fixture(scope="module")
def strip_cutter():
    return catalog.load("strip_cutter").solve()


def _polygons_and_their_places(kin, monkeypatch):
    """The polygons of position 0 and what the builder told the guard of them (whose point each image is)."""
    seen = []
    monkeypatch.setattr(polygons, "motion_disagreement", lambda *args: seen.append(args) or "")
    construct_kinematics(kin, 0)
    monkeypatch.undo()
    return seen[0]


@pytest.mark.parametrize("field", ["velocity", "acceleration", "v_G", "a_G", "omega", "alpha"])
def test_a_nan_in_the_polygons_is_refused_wherever_it_is(strip_cutter, field, monkeypatch):
    kin, i, c, where, coriolis = _polygons_and_their_places(strip_cutter.kinematics, monkeypatch)
    assert guard.motion_disagreement(kin, i, c, where, coriolis) == ""
    table = getattr(c, field)
    for key in table:
        nan = math.nan if field in ("omega", "alpha") else (math.nan, 0.0)
        bad = dataclasses.replace(c, **{field: {**table, key: nan}})
        why = guard.motion_disagreement(kin, i, bad, where, coriolis)
        assert why.startswith("the velocity and acceleration polygons and the analytical route disagree: ")
        assert "nan" in why, (field, key)


def test_a_nan_image_is_refused(strip_cutter, monkeypatch):
    kin, i, c, where, coriolis = _polygons_and_their_places(strip_cutter.kinematics, monkeypatch)
    for polygon, images in c.images.items():
        for name in images:
            bad = dataclasses.replace(c, images={**c.images, polygon: {**images, name: (math.nan, 0.0)}})
            why = guard.motion_disagreement(kin, i, bad, where, coriolis)
            assert f"image {name} is nan" in why, (polygon, name)


def test_a_nan_from_the_instant_centres_is_refused(strip_cutter):
    kin = strip_cutter.kinematics
    ic = instant_centres(kin, 0)
    assert ic.valid and guard.centres_disagreement(kin, 0, ic) == ""
    for field in ("centres", "velocity", "v_G", "omega"):
        table = getattr(ic, field)
        for key in table:
            bad = dataclasses.replace(ic, **{field: {**table, key: math.nan if field == "omega" else (math.nan, 0.0)}})
            assert "nan" in guard.centres_disagreement(kin, 0, bad), (field, key)


def test_a_nan_force_is_refused_wherever_it_is(strip_cutter):
    c = construct_forces(strip_cutter.kinematics, 0)
    assert guard.check_forces(strip_cutter, c, 0) is c
    for key in c.forces:
        bad = dataclasses.replace(c, forces={**c.forces, key: (math.nan, 0.0)})
        checked = guard.check_forces(strip_cutter, bad, 0)
        assert not checked.valid and checked.disagreement, key


def test_the_truth_is_the_same_worked_out_alone_or_with_every_position(strip_cutter):
    """The guard works out the first FEW positions it is asked for one at a time, the rest all at once (numpy):
    both ways it refuses a value nudged by 100 × AGREEMENT of the position's largest speed, and passes it unnudged."""
    kin = dataclasses.replace(strip_cutter.kinematics)  # a new kinematics: nothing kept for it yet
    for i in [*range(guard.FEW + 3), kin.n - 1]:  # alone, then from the table
        c = instant_centres(kin, i)
        assert c.valid and guard.centres_disagreement(kin, i, c) == ""
        top = max(math.hypot(*v) for v in c.velocity.values())
        key = next(iter(c.velocity))
        x, y = c.velocity[key]
        for factor, ok in ((0.01, True), (100.0, False)):
            nudged = dataclasses.replace(c, velocity={**c.velocity, key: (x + factor * guard.AGREEMENT * top, y)})
            assert (guard.centres_disagreement(kin, i, nudged) == "") is ok, (i, factor)


def test_a_position_alone_and_from_the_table_gives_the_same_numbers(strip_cutter):
    """The instant centres place the links with the guard's O and e^iθ (:func:`guard.motion_at`): a position worked
    out alone and the same position read from the table of every position read the same numbers of the kinematics
    (each link's O, e^iθ and rates, to the bit), the frame's e^iθ 1 in both; what is worked out of them (a point's
    velocity) may differ in the last bit (numpy's complex product against Python's), which the guard's tolerance is
    far above."""
    i = strip_cutter.kinematics.n - 1
    alone = dataclasses.replace(strip_cutter.kinematics)  # new kinematics: nothing kept for them yet
    by_table = dataclasses.replace(strip_cutter.kinematics)
    for j in range(guard.FEW):
        guard.motion_at(by_table, j)
    a, b = guard.motion_at(alone, i), guard.motion_at(by_table, i)
    assert guard.kept(by_table, "table", None).rows is not None and guard.kept(alone, "table", None).rows is None
    for name in ("O", "e", "v_O", "w", "a_O", "al"):
        assert getattr(a, name) == getattr(b, name), name
    # a few units of the last bit (ε = 2.2e-16) of the largest speed: rounding, not a term worked out otherwise
    assert max(abs(x - y) for x, y in zip(a.v, b.v)) <= 4 * sys.float_info.epsilon * a.v_scale
    assert a.e[a.column[strip_cutter.mechanism.frame]] == 1
