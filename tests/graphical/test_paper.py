"""A worksheet's scales, worked out once per construction and never answering for another one."""

from __future__ import annotations

import gc
from dataclasses import replace

from graphkin import catalog
from graphkin.graphical import construct_forces, construct_kinematics, paper
from graphkin.graphical.construction import Arrow, Step
from graphkin.graphical.paper import POLYGON_ROOM, motion_scales, sheet_scales


def test_sheet_scales_are_the_constructions_own_and_kept():
    c = construct_forces(catalog.load("strip_cutter").kinematics(), 0)
    first = sheet_scales(c)
    assert first == paper._sheet_scales(c)  # what a fresh computation gives
    assert sheet_scales(c) is first  # kept: the sheet, its key and the grader ask again and again
    # A construction whose polygons are ten times larger (another one, though equal in everything else) has its own.
    bigger = replace(c, steps=tuple(
        Step(s.kind, s.caption, s.link, s.lines, s.points,
             tuple(Arrow(a.name, (10 * a.vector[0], 10 * a.vector[1]), a.known, a.at) for a in s.polygon),
             s.values, s.sub) for s in c.steps))
    assert sheet_scales(bigger) == paper._sheet_scales(bigger)
    assert sheet_scales(bigger).polygon > first.polygon
    assert sheet_scales(c) is first


def test_motion_scales_by_room_and_forgotten_with_the_construction():
    kin = catalog.load("strip_cutter").kinematics()
    mc = construct_kinematics(kin, 0)
    small = motion_scales(mc, (10.0, 10.0))
    assert small == paper._motion_scales(mc, (10.0, 10.0))
    assert motion_scales(mc, POLYGON_ROOM) == paper._motion_scales(mc, POLYGON_ROOM) != small  # each room its own
    key = id(mc)
    assert key in paper._KEPT
    del mc
    gc.collect()
    assert key not in paper._KEPT  # the entry goes with the construction: nothing is kept alive or stale
