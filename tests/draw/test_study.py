"""draw_study: what a study's picture shows is the study's numbers, the chosen design marked where it is.

One varied field: a panel per defined figure of merit, its line the figure against the field; two: a contour map
with the designs that cannot be assembled crossed out; more: parallel coordinates, a line per design that
assembles. The chosen design (Study.best) is the black star or line in each, the optimum (Study.optimum) the red
diamond or dashed line; the figures of merit are drawn in the units asked for (--units).
"""

import dataclasses
import subprocess
import sys

import numpy as np
import pytest
from matplotlib.collections import LineCollection
from matplotlib.contour import ContourSet

from graphkin.cycle import study
from graphkin.cycle.choice import figure_values, figures
from graphkin.draw import draw_study, save
from graphkin.errors import GraphkinError

CRANK = ["60 mm", "100 mm", "140 mm", "180 mm", "240 mm"]  # the 240 mm crank cannot turn


@pytest.fixture(scope="module")
def one():
    return study("strip_cutter", {"links[0].points.A[0]": CRANK}, n=36)


@pytest.fixture(scope="module")
def two():
    return study("strip_cutter", {"links[0].points.A[0]": CRANK, "links[1].mass": ["1 kg", "2.5 kg", "4 kg"]}, n=36)


def stars(ax):
    return [line for line in ax.lines if line.get_marker() == "*"]


def test_one_field_each_figure_against_it(one):
    choice = one.best("shaking_moment_peak", ["transmission_angle_min >= 45 deg"])
    fig = draw_study(one, choice)
    panels = [ax for ax in fig.axes if ax.get_visible()]
    names = [n for n in figures(one) if not np.isnan(figure_values(one, n)).all()]
    assert len(panels) == len(names) == 10  # six figures and four joints
    x = np.array([60, 100, 140, 180, 240], float)
    for ax, name in zip(panels, names):
        y = figure_values(one, name)
        if name == "transmission_angle_min":
            y = np.degrees(y)
        (curve,) = [line for line in ax.lines if line.get_marker() == "."]
        np.testing.assert_array_equal(curve.get_xdata(), x)
        np.testing.assert_array_equal(curve.get_ydata(), y)  # nan: the crank that cannot turn is a gap
        (star,) = stars(ax)
        assert (star.get_xdata()[0], star.get_ydata()[0]) == (x[choice.index], y[choice.index])
        assert ax.get_xlabel() == "links[0].points.A[0] [mm]"


def test_two_fields_a_contour_map_failures_crossed_out(two):
    choice = two.best("torque_rms")
    fig = draw_study(two, choice, merit="I_s")
    ax = fig.axes[0]
    assert any(isinstance(c, ContourSet) for c in ax.collections)
    assert ax.get_xlabel() == "links[1].mass [kg]" and ax.get_ylabel() == "links[0].points.A[0] [mm]"
    mass, crank = np.meshgrid([60, 100, 140, 180, 240], [1, 2.5, 4], indexing="ij")
    (crosses,) = [line for line in ax.lines if line.get_marker() == "x"]
    bad = np.array([not d.ok for d in two.designs])
    assert bad.sum() == 3
    np.testing.assert_array_equal(crosses.get_xdata(), crank.ravel()[bad])
    np.testing.assert_array_equal(crosses.get_ydata(), mass.ravel()[bad])
    (star,) = stars(ax)
    assert (star.get_xdata()[0], star.get_ydata()[0]) == (crank.ravel()[choice.index], mass.ravel()[choice.index])
    assert "flywheel I_s" in fig.axes[1].get_ylabel()  # the colour bar names the merit drawn


def test_more_fields_parallel_coordinates():
    s = study("strip_cutter", {"links[0].points.A[0]": ["60 mm", "240 mm"], "links[1].mass": ["1 kg", "4 kg"],
                               "links[2].mass": ["2 kg", "3 kg", "5 kg"]}, n=36)
    choice = s.best("I_s")
    ax = draw_study(s, choice).axes[0]
    ok = [k for k, d in enumerate(s.designs) if d.ok]
    (designs,) = [c for c in ax.collections if isinstance(c, LineCollection)]
    thick = [line for line in ax.lines if line.get_linewidth() > 2]
    assert len(designs.get_segments()) == len(ok) == 6 and len(thick) == 1
    assert any(np.array_equal(seg[:, 1], thick[0].get_ydata()) for seg in designs.get_segments())
    # the least flywheel: the short crank and the lightest links, each at the bottom of its field's axis
    assert s.designs[choice.index].values == ("60 mm", "1 kg", "2 kg")
    assert thick[0].get_ydata()[:3].tolist() == [0, 0, 0]
    assert thick[0].get_ydata()[5] == 0  # fields, T_peak, T_rms, then I_s: its least
    assert choice.index in ok


def test_a_bad_merit_or_nothing_to_draw_is_named(one):
    with pytest.raises(GraphkinError, match="merit 'mu': no such figure of merit"):
        draw_study(one, merit="mu")
    none = study("strip_cutter", {"links[0].points.A[0]": ["240 mm", "250 mm"]}, n=12)
    with pytest.raises(GraphkinError, match="no design of the study can be assembled"):
        draw_study(none)


@pytest.mark.parametrize("suffix", ["png", "svg", "pdf"])
def test_saved_whole_in_each_format(one, tmp_path, suffix):
    path = save(draw_study(one, one.best("torque_peak")), tmp_path / f"s.{suffix}")
    assert path.stat().st_size > 1000 and [p.name for p in tmp_path.iterdir()] == [f"s.{suffix}"]


def test_a_study_and_its_choice_do_not_load_matplotlib():
    code = ("import sys, graphkin, graphkin.cycle.choice, graphkin.report.study, graphkin.cli.study; "
            "assert 'matplotlib' not in sys.modules")
    assert subprocess.run([sys.executable, "-c", code], capture_output=True).returncode == 0


def test_a_point_field_is_an_axis_of_its_values_as_written():
    s = study("slider_crank_friction", {"links[0].points.A": [["40 mm", "0 mm"], ["60 mm", "0 mm"]],
                                        "links[2].mass": ["0.5 kg", "2 kg"]}, n=24)
    ax = draw_study(s, s.best("torque_peak")).axes[0]
    assert [t.get_text() for t in ax.get_yticklabels()] == ["(40 mm, 0 mm)", "(60 mm, 0 mm)"]
    assert ax.get_ylabel() == "links[0].points.A"


def diamonds(ax):
    return [line for line in ax.lines if line.get_marker() == "D"]


@pytest.fixture(scope="module")
def optimised(two):
    """The least peak torque between the grid's values with μ ≥ 30°: scipy moves the coupler's mass off the grid."""
    return two.optimum("torque_peak", ["transmission_angle_min >= 30 deg"])


def test_the_optimum_is_marked_where_it_is_on_a_map_and_in_parallel_coordinates(two, optimised):
    ax = draw_study(two, two.best("torque_peak", ["transmission_angle_min >= 30 deg"]), optimum=optimised).axes[0]
    (mark,) = diamonds(ax)
    assert (mark.get_xdata()[0], mark.get_ydata()[0]) == (optimised.x[1], optimised.x[0])  # mass across, crank up
    assert mark.get_label() == "the optimum of torque_peak" and "the optimum of torque_peak" in [
        t.get_text() for t in ax.get_legend().get_texts()]
    three = study("strip_cutter", {"links[0].points.A[0]": ["60 mm", "90 mm"], "links[1].mass": ["1 kg", "4 kg"],
                                   "links[2].mass": ["2 kg", "5 kg"]}, n=36)
    best = three.optimum("torque_peak", ["transmission_angle_min >= 30 deg"], maxiter=5)
    ax = draw_study(three, optimum=best).axes[0]
    (line,) = [line for line in ax.lines if line.get_linestyle() == "--"]
    # each axis from its least to its largest value over the designs that assemble (all of them here)
    names = [n for n in figures(three) if n in ("torque_peak", "torque_rms", "I_s", "shaking_force_peak",
                                                 "shaking_moment_peak", "transmission_angle_min")]
    grid = np.array([[float(v.split()[0]) for v in d.values] for d in three.designs]).T
    merits = [figure_values(three, n) for n in names]
    mine = [figure_values(dataclasses.replace(three, designs=(best.design,)), n)[0] for n in names]
    columns = list(grid) + [np.degrees(x) if n == "transmission_angle_min" else x for n, x in zip(names, merits)]
    ends = [np.degrees(x) if n == "transmission_angle_min" else x for n, x in zip(names, mine)]
    at = list(best.x) + ends
    expected = [(a - c.min()) / (c.max() - c.min() if c.max() > c.min() else 1.0) for a, c in zip(at, columns)]
    np.testing.assert_allclose(line.get_ydata(), expected, rtol=1e-12, atol=1e-12)


def test_the_optimum_is_marked_on_each_figure_against_one_field(one):
    best = one.optimum("torque_peak", ["transmission_angle_min >= 30 deg"], maxiter=5)
    fig = draw_study(one, one.best("torque_peak", ["transmission_angle_min >= 30 deg"]), optimum=best)
    panels = [ax for ax in fig.axes if ax.get_visible()]
    names = [n for n in figures(one) if not np.isnan(figure_values(one, n)).all()]
    for ax, name in zip(panels, names):
        y = figure_values(dataclasses.replace(one, designs=(best.design,)), name)[0]
        (mark,) = diamonds(ax)
        assert mark.get_xdata()[0] == best.x[0]
        assert mark.get_ydata()[0] == (np.degrees(y) if name == "transmission_angle_min" else y)
    assert "the optimum of torque_peak" in fig.get_suptitle()


def test_the_figures_are_drawn_in_the_units_asked_for(one, two):
    from graphkin.units.systems import SI, unit_system

    US = unit_system("US")

    choice = one.best("torque_peak")
    si, us = draw_study(one, choice), draw_study(one, choice, units=US)
    assert [ax.get_ylabel() for ax in draw_study(one, choice, units=SI).axes] == [ax.get_ylabel() for ax in si.axes]
    for a, b in zip(si.axes, us.axes):
        if not a.get_visible():
            continue
        kind = {"N·m": "torque", "N": "force", "kg·m²": "moment_of_inertia", "°": "angle"}[
            a.get_ylabel().rsplit("[", 1)[1].rstrip("]")]
        assert b.get_ylabel().endswith(f"[{US.symbol(kind)}]")
        assert b.get_xlabel() == a.get_xlabel() == "links[0].points.A[0] [mm]"  # the field as the study writes it
        for la, lb in zip(a.lines, b.lines):
            np.testing.assert_allclose(lb.get_ydata(), np.asarray(la.get_ydata()) * US.scales[kind] /
                                       SI.scales[kind], rtol=1e-12)
    assert any(ax.get_ylabel() == "peak driving effort [lbf·ft]" for ax in us.axes)
    cbar = draw_study(two, two.best("torque_rms"), merit="shaking_force_peak", units=US).axes[1]
    assert cbar.get_ylabel() == "peak shaking force [lbf]"


def test_the_command_draws_the_optimum_in_its_units(monkeypatch, tmp_path, capsys):
    from graphkin import draw
    from graphkin.cli import main

    drawn = []
    monkeypatch.setattr(draw, "save", lambda fig, path: drawn.append(fig))
    code = main(["study", "strip_cutter", "--vary", "links[1].mass=1..4 kg:4", "--n", "36", "--best",
                 "torque_peak", "--optimize", "minimise torque_peak", "--units", "US", "--figure",
                 str(tmp_path / "f.png")])
    assert code == 0
    (fig,) = drawn
    first = fig.axes[0]
    assert first.get_ylabel() == "peak driving effort [lbf·ft]"
    assert len(stars(first)) == 1 and len(diamonds(first)) == 1
    capsys.readouterr()
