"""A figure's drawn extent (:func:`graphkin.draw.extent.drawn_extent`) is matplotlib's tight box, to the last bit."""

from __future__ import annotations

import numpy as np
import pytest
from matplotlib.figure import Figure

from graphkin import handout
from graphkin.draw import measuring_renderer
from graphkin.draw.extent import drawn_extent
from graphkin.draw.text import halo


def _pictures(doc):
    return [p for b in doc["blocks"] if b["kind"] == "figure" for p in b["pictures"]]


@pytest.mark.parametrize("source, kw", [
    ("strip_cutter_cut", {"student": "s1", "secret": "x", "version": "key"}),
    ("strip_cutter_cut", {"student": "s1", "secret": "x", "version": "sheet"}),
    ("strip_cutter", {"detail": "full"}),  # the torque curve: axes with their axis on
    ("shaper_six_bar", {}),
    ("strip_cutter", {"at": "140 deg", "version": "blank"}),
])
def test_every_handout_figure_s_extent_is_matplotlib_s_tight_box(source, kw, monkeypatch):
    from graphkin.handout import sections

    # The sign convention is drawn once a process and kept as SVG: a fresh one, to measure it.
    monkeypatch.setattr(sections, "_CONVENTION", [])
    pictures = _pictures(handout.build(source, **kw))
    assert pictures
    for p in pictures:
        fig = p.figure()
        expected = fig.get_tightbbox(measuring_renderer(fig)).get_points()
        # Twice: laid out, then from the boxes kept.
        for _ in range(2):
            np.testing.assert_array_equal(drawn_extent(fig).get_points(), expected, err_msg=p.key)


def test_a_text_moved_rotated_or_restyled_is_measured_again():
    """The box kept for a text is its own string's, font's, alignment's and angle's: change one and the
    extent follows (a label that reaches past the axes sets the figure's edge)."""
    fig = Figure(figsize=(3, 2), dpi=100)
    ax = fig.add_axes([0.3, 0.3, 0.4, 0.4])
    ax.set_axis_off()
    t = ax.text(0.5, 0.5, "F₂₃ = 1234 N", transform=ax.transAxes, clip_on=False, path_effects=[halo()])
    boxes = []
    for change in ({}, {"x": 1.4}, {"rotation": 90}, {"fontsize": 20}, {"ha": "right"}, {"va": "top"},
                   {"text": "F₂₃ = 1234 N\nsecond line"}):
        t.set(**change)
        box = drawn_extent(fig).get_points()
        np.testing.assert_array_equal(box, fig.get_tightbbox(measuring_renderer(fig)).get_points(), err_msg=change)
        boxes.append(tuple(box.ravel()))
    assert len(set(boxes)) >= len(boxes) - 1  # all but one change (to a rotated text's va) moved the edge
