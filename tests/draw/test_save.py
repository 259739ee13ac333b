"""``graphkin.draw.save`` draws a PNG once, with the pixels matplotlib's ``bbox_inches="tight"`` gives."""

from __future__ import annotations

import io

import numpy as np
import pytest


def _solved(name):
    from graphkin import catalog, report

    r = catalog.load(name).solve()
    return r, report.constructions(r)[0]


def _pixels(source):
    from PIL import Image

    with Image.open(source) as im:
        return np.asarray(im.convert("RGBA")), im.info


# The double slider's solution, small; and a figure whose box is 3487.99... pixels wide at 200 dpi, which Agg
# makes 3488: the canvas's size is read from the canvas, never recomputed.
@pytest.mark.parametrize("name, what, dpi", [("double_slider", "solution", 40), ("slider_crank_friction", "given", 200)])
def test_a_png_is_drawn_once_with_the_pixels_of_matplotlibs_tight_box(tmp_path, name, what, dpi):
    from graphkin import draw

    r, c = _solved(name)

    def make():
        return draw.draw_solution(c, r) if what == "solution" else draw.draw_given(c)

    fig = make()
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi, bbox_inches="tight", pad_inches=0.08, facecolor="white")
    buf.seek(0)
    expected, _ = _pixels(buf)
    fig = make()
    dpi_before, canvas_before = fig.dpi, fig.canvas
    draws = []
    original = type(fig).draw

    def counting(self, renderer):
        draws.append(renderer)
        return original(self, renderer)

    type(fig).draw = counting
    try:
        path = draw.save(fig, tmp_path / "s.png", dpi=dpi)
    finally:
        type(fig).draw = original
    got, info = _pixels(path)
    assert len(draws) == 1
    assert got.shape == expected.shape and np.array_equal(got, expected)
    assert round(info["dpi"][0]) == dpi and info["Software"].startswith("Matplotlib")
    assert fig.dpi == dpi_before and fig.canvas is canvas_before


def test_a_transparent_figure_keeps_its_alpha_and_other_options_go_to_matplotlib(tmp_path):
    from matplotlib.figure import Figure

    from graphkin import draw

    fig = Figure(figsize=(2, 1))
    fig.add_subplot().plot([0, 1], [0, 1])
    got, _ = _pixels(draw.save(fig, tmp_path / "t.png", dpi=30, facecolor="none"))
    assert got[..., 3].min() == 0  # see-through where nothing is drawn
    path = draw.save(fig, tmp_path / "m.png", dpi=30, metadata={"Title": "a line"})
    assert _pixels(path)[1]["Title"] == "a line"
    fig = Figure(figsize=(2, 1), layout="constrained")
    fig.add_subplot().set_title("constrained")
    assert _pixels(draw.save(fig, tmp_path / "c.png", dpi=30))[0].shape[2] == 4
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c.png", "m.png", "t.png"]  # no temporary file left
