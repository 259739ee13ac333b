"""The velocity and acceleration polygons drawn to scale: arrows where the polygon puts them, the scale stated."""

import dataclasses
import math
import re

import numpy as np
import pytest

from graphkin import catalog, draw
from graphkin.cli import main
from graphkin.draw import text as draw_text
from graphkin.errors import GraphkinError
from graphkin.graphical import construct_kinematics


@pytest.fixture(scope="module")
def shaper():
    return construct_kinematics(catalog.load("shaper_six_bar").kinematics(), 0)


@pytest.mark.parametrize("polygon", ["velocity", "acceleration"])
def test_every_arrow_is_its_vector_over_the_scale(shaper, polygon):
    drawn = draw.draw_motion_polygon(shaper, polygon, scale=0.05 if polygon == "velocity" else 1.0)
    vectors = {v.name: v for v in shaper.vectors(polygon)}
    assert drawn.ends
    for name, (tail, tip) in drawn.ends.items():
        v = vectors[name]
        assert np.allclose(tail, np.divide(v.tail, drawn.scale)) and np.allclose(tip, np.divide(v.tip, drawn.scale))


def test_the_scale_is_stated(shaper):
    drawn = draw.draw_motion_polygon(shaper, "acceleration")
    texts = [t.get_text() for t in drawn.ax.texts]
    assert any(f"1 mm = {shaper.acceleration_scale:g} m/s²" in t for t in texts)
    assert drawn.scale == shaper.acceleration_scale


def test_the_coriolis_arrow_is_drawn_known_and_the_sliding_one_found(shaper):
    drawn = draw.draw_motion_polygon(shaper, "acceleration")
    coriolis = next(name for name in drawn.arrows if name.startswith("a^c_"))
    sliding = next(name for name in drawn.arrows if name.startswith("a^r_") and "B3" in name)
    assert drawn.arrows[coriolis].get_linewidth() != drawn.arrows[sliding].get_linewidth()


def test_every_image_point_is_labelled(shaper):
    drawn = draw.draw_motion_polygon(shaper, "velocity")
    assert set(drawn.labels) == set(shaper.images["velocity"])


def test_no_polygon_at_a_position_without_one():
    kin = catalog.load("double_slider").kinematics()
    bad = construct_kinematics(dataclasses.replace(kin, valid=np.zeros(1, bool)), 0)
    with pytest.raises(GraphkinError, match="no polygons"):
        draw.draw_motion_polygon(bad)


@pytest.mark.parametrize("scale", [0, -1.0, math.nan, "1"])
def test_a_bad_scale_is_one_clear_line(shaper, scale):
    with pytest.raises(GraphkinError, match="scale must be a positive number"):
        draw.draw_motion_polygon(shaper, scale=scale)


def test_solve_figure_with_polygons_writes_them(tmp_path, capsys):
    out = tmp_path / "shaper.png"
    assert main(["solve", "shaper_six_bar", "--figure", str(out), "--motion-polygons"]) == 0
    assert (tmp_path / "shaper_polygons.png").stat().st_size > 0
    assert "1 mm = " in capsys.readouterr().err


def test_polygons_without_a_figure_is_one_clear_line(capsys):
    code = main(["solve", "shaper_six_bar", "--motion-polygons"])
    err = capsys.readouterr().err
    assert code != 0 and "-o FILE" in err and err.count("\n") == 1


def test_one_frame_per_step_each_with_its_caption(shaper):
    frames = draw.draw_motion_steps(shaper)
    assert len(frames) == len(shaper.steps)
    for fig, step in zip(frames, shaper.steps):
        texts = " ".join(t.get_text() for t in fig.texts).replace("\n", " ")
        assert step.caption.split(":")[0] in texts


def test_a_frame_draws_only_what_its_step_has_reached(shaper):
    first_dyad = next(k for k, s in enumerate(shaper.steps) if s.kind == "dyad")
    before = draw.draw_motion_polygon(shaper, "velocity", upto=first_dyad - 1)
    after = draw.draw_motion_polygon(shaper, "velocity", upto=first_dyad)
    (found,) = shaper.steps[first_dyad].points
    assert found not in before.labels and found in after.labels
    assert before.ax.get_xlim() == pytest.approx(after.ax.get_xlim())


def test_solve_steps_with_polygons_writes_their_frames_first(tmp_path, capsys):
    assert main(["solve", "double_slider", "--steps", str(tmp_path), "--motion-polygons"]) == 0
    names = sorted(p.name for p in tmp_path.iterdir())
    polygons = [n for n in names if "_polygons" in n]
    assert polygons and len(polygons) == len(construct_kinematics(catalog.load("double_slider").kinematics(), 0).steps)
    assert f"({polygons[0]} …" in capsys.readouterr().err


@pytest.mark.parametrize("polygon", ["velocity", "acceleration"])
def test_labels_are_typeset_not_raw_names(shaper, polygon):
    """A book prints a^t_BA with t above and BA below, g3 as g₃: no raw ``^`` or ``_`` reaches the page."""
    drawn = draw.draw_motion_polygon(shaper, polygon, values=True)
    texts = [t.get_text() for t in drawn.ax.texts]
    names = [v.name for v in shaper.vectors(polygon)]
    assert any("^{" in t for t in texts) == (polygon == "acceleration")
    for t in texts:
        outside = re.sub(r"\$[^$]*\$", "", t)
        assert "^" not in outside and "_" not in outside, t
    assert not any(re.search(r"(?<![\\$])\b[a-z]\d", t) for t in texts), texts  # g3 is g₃
    assert len(names) and all(any(draw_text.plain(draw_text.motion_name(n)) in draw_text.plain(t) for t in texts)
                              for n in names if n in drawn.ends)
