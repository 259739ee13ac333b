"""Free bodies a student can read (issue 36, item 4): no link of two or more points prints shorter than 15 mm.

An engine's free bodies at one scale printed a 3 mm crank beside its connecting rod, four labels on one point. A
link too short to read at its figure's scale is enlarged, at a scale of its own that its panel and the caption
state; a figure that would be taller than its room is split. Checked over every catalog problem's worked
position and every exercise for a few students, on the plan; and on a drawn figure, in millimetres of paper.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin import catalog, exercises
from graphkin.handout import scaled
from graphkin.handout.document import subject
from tests.handout.worked import exercise_constructions

STUDENTS = ["s00", "s01", "s02"]


def _short(label: str, c, links) -> list[str]:
    out = []
    for k, X, group, own in scaled.free_body_plan(c, links):
        for n in group:
            pts = [np.asarray(p, float) * 1e3 for p in c.points[n].values()]
            if len(pts) < 2:
                continue
            longest = max(math.dist(p, q) for p in pts for q in pts)
            printed = longest / own.get(n, k)
            if printed < scaled.SHORTEST_LINK - 1e-6:
                out.append(f"{label}: link {n} prints {printed:.1f} mm at 1:{own.get(n, k):g}")
        w = scaled._rows_height([scaled.free_body_size(c, n, own.get(n, k), X) for n in group],
                                scaled.FREE_BODY_ROOM[0])
        if len(group) > 1 and w > scaled.FREE_BODY_ROOM[1]:
            out.append(f"{label}: a figure of links {group} is {w:.0f} mm tall")
    return out


@pytest.mark.parametrize("name", catalog.names())
def test_no_link_of_a_problem_s_free_bodies_prints_shorter_than_15_mm(name):
    s = subject(name)
    bad = []
    for i in s.worked():
        c = s.construction(i)
        if c is not None and c.valid:
            bad += _short(f"{name} at {s.where(i)}", c, list(s.mech.moving))
    assert not bad, "\n".join(bad)


@pytest.mark.parametrize("name", exercises.names())
def test_no_link_of_an_exercise_s_free_bodies_prints_shorter_than_15_mm(name):
    bad = [line for label, c in exercise_constructions(name, STUDENTS, "readable")
           for line in _short(label, c, list(c.mechanism.moving))]
    assert not bad, "\n".join(bad)


def test_the_engine_s_crank_is_enlarged_and_measured_15_mm_or_more_on_paper():
    """The engine whose crank printed 3 mm at 1:100: drawn, each panel's crank measured in mm of paper."""
    from graphkin.draw import paper

    s = subject("engine_gas_force")
    c = s.construction(s.worked()[0])
    links = list(s.mech.moving)
    (k, X, group, own), *_ = scaled.free_body_plan(c, links)
    assert 2 in own and own[2] < k  # the crank, enlarged
    fig = paper.draw_free_bodies(c, group, length_scale=k, force_scale=X, enlarged=own)
    for n, ax in zip(group, fig.axes):
        pts = [np.asarray(p, float) * 1e3 for p in c.points[n].values()]
        if len(pts) < 2:
            continue
        bbox = ax.get_position()
        mm_per_unit = bbox.width * fig.get_figwidth() * 25.4 / abs(np.diff(ax.get_xlim())[0])
        assert mm_per_unit == pytest.approx(1 / own.get(n, k), rel=1e-6)  # printed at the scale it states
        assert max(math.dist(p, q) for p in pts for q in pts) * mm_per_unit >= scaled.SHORTEST_LINK - 1e-6
        if n in own:
            assert f"1:{own[n]:g}" in ax.get_title()


def test_each_pitch_point_of_the_epicyclic_train_has_its_own_name():
    """Issue 36: "P" named both pitch points of the epicyclic train. Each is named by its mesh, as the drawing of
    the mechanism labels it (P34), and one name is never two points."""
    s = subject("epicyclic_khurmi")
    c = s.construction(s.worked()[0])
    where: dict = {}
    for step in c.steps:
        for name, X in step.points.items():
            where.setdefault(name, []).append(np.asarray(X, float))
    for name, points in where.items():
        assert all(np.allclose(points[0], X) for X in points), f"{name} names {len(points)} points"
    pitch = {name for name in where if name.startswith("P")}
    assert pitch == {"P" + "".join(map(str, sorted(key))) for key in c.pitch_points}
