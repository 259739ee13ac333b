"""Free bodies a student can read (issue 36, item 4): no two labels on one point, measured in the drawn figures.

At a slider every force starts at its one point, on one line: the engine's piston printed "P (G₄)", "R₄ᵢ" and
"G₁₄" on its point, G₁₄'s name nearer the gas load's arrow than its own. For every catalog problem's worked
position (and the strip cutter at 140°, whose offset "h = 1228 mm (not to scale)" ran into the next panel) and
every exercise for a few students, each figure of free bodies the handout prints (the key's, with every force;
the sheet's, with the given loads only) is laid out as printed and measured from its artists:

* no text on another text or on an outline, and none outside the figure (:func:`tests.draw.test_overlaps.overlaps`);
* each force's label nearer its own arrow than any other arrow of its panel, or tied to it by a leader line
  (:func:`tests.draw.test_polygon_labels.astray`, over the arrows with gid ``fbd<link>:<force>``, couples' arcs
  included).

The measure does not use the Labeler (:class:`graphkin.draw.labels.Labeler`): it reads the figure only.
"""

from __future__ import annotations

import pytest

pytest.importorskip("matplotlib")
shapely = pytest.importorskip("shapely")

from graphkin import catalog, exercises  # noqa: E402
from graphkin.handout import scaled  # noqa: E402
from graphkin.handout.document import subject  # noqa: E402
from tests.draw.test_overlaps import overlaps  # noqa: E402
from tests.draw.test_polygon_labels import arrows, astray  # noqa: E402
from tests.handout.worked import exercise_constructions  # noqa: E402

STUDENTS = ["s00", "s01", "s02"]


def _figures(label, c):
    """(what, figure) of each figure of free bodies the handout prints of construction ``c``: the key's and the
    sheet's, as :func:`graphkin.handout.scaled.free_body_figures` plans and draws them."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from graphkin.draw import paper

    for k, X, group, own in scaled.free_body_plan(c, list(c.mechanism.moving)):
        for unknowns, which in ((True, "key"), (False, "sheet")):
            fig = paper.draw_free_bodies(c, group, length_scale=k, force_scale=X, unknowns=unknowns, enlarged=own)
            FigureCanvasAgg(fig)
            yield f"{label}, {which}, links {group}", fig


def unreadable(fig) -> list:
    """Everything wrong with a figure of free bodies' labels and arrows (see the module's docstring)."""
    return [("overlap", *o) for o in overlaps(fig, page=True)] + [("astray", *a) for a in astray(fig, kinds=("fbd",))]


def _problem_constructions(name, at=None):
    s = subject(name, at=at) if at else subject(name)
    for i in s.worked():
        c = s.construction(i)
        if c is not None and c.valid:
            yield f"{name} at {s.where(i)}", c


@pytest.mark.parametrize("name, at", [(n, None) for n in catalog.names()] + [("strip_cutter", "140 deg")])
def test_no_two_labels_on_one_point_in_a_problem_s_free_bodies(name, at):
    bad = [(what, *m) for label, c in _problem_constructions(name, at) for what, fig in _figures(label, c)
           for m in unreadable(fig)]
    assert not bad, "\n".join(map(str, bad))


@pytest.mark.parametrize("name", exercises.names())
def test_no_two_labels_on_one_point_in_an_exercise_s_free_bodies(name):
    bad = [(what, *m) for label, c in exercise_constructions(name, STUDENTS, "readable")
           for what, fig in _figures(label, c) for m in unreadable(fig)]
    assert not bad, "\n".join(map(str, bad))


def _piston():
    """The key's figure of the engine's piston (link 4 of engine_gas_force at its worked position)."""
    label, c = next(_problem_constructions("engine_gas_force"))
    return next(fig for what, fig in _figures(label, c) if "key" in what and "[4]" in what)


def test_the_piston_s_labels_are_each_by_their_own_force():
    """The figure of issue 36: each of the piston's forces named, each name by its own arrow, none on another."""
    fig = _piston()
    assert not unreadable(fig)
    named = {(t.get_gid() or "")[len("label:"):] for ax in fig.axes for t in ax.texts}
    drawn = {gid for ax in fig.axes for gid, _ in arrows(ax, ("fbd",))}
    assert {"fbd4:G14", "fbd4:F34", "fbd4:R4i"} <= drawn <= named


def test_the_measure_sees_labels_left_at_their_first_spot(monkeypatch):
    """With placing switched off (every label at its first candidate spot), the measure finds the piston's labels
    on one another: G₁₄'s on "P (G₄)"."""
    from graphkin.draw.labels import Labeler

    monkeypatch.setattr(Labeler, "place", lambda self: None)
    found = unreadable(_piston())
    assert any(kind == "overlap" and "G₁₄" in a and "P (G₄)" in b for kind, a, b, *_ in found), found


def test_the_measure_sees_a_label_nearer_another_force(monkeypatch):
    """With the Labeler blind to which arrow a label names (as it was for free bodies), the measure finds labels of
    the shaper's free bodies nearer another force's arrow than their own."""
    import numpy as np

    from graphkin.draw import labels

    monkeypatch.setattr(labels, "_astray", lambda boxes, P, Q, R, own: np.zeros(len(boxes)))
    label, c = next(_problem_constructions("shaper_six_bar"))
    found = [m for what, fig in _figures(label, c) for m in unreadable(fig)]
    assert "astray" in {kind for kind, *_ in found}, found
