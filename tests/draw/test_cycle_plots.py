"""Plots of a whole cycle (graphkin.draw.cycle) on the strip cutter: the artists carry the analysis' numbers."""

import math

import numpy as np
import pytest
from matplotlib.figure import Figure

from graphkin import catalog, draw
from graphkin.cycle import joint_force_index, sweep
from graphkin.draw.cycle import crossing_energy
from graphkin.errors import GraphkinError


@pytest.fixture(scope="module")
def cutter():
    return catalog.load("strip_cutter")


@pytest.fixture(scope="module")
def cycle(cutter):
    return sweep(cutter, 72)


@pytest.fixture(scope="module")
def flywheel(cycle):
    return cycle.flywheel(0.05)


def test_torque_curve(cycle, flywheel):
    d = draw.draw_torque_curve(cycle, flywheel=flywheel)
    T = d.curves["torque"]
    assert len(T.get_xdata()) == cycle.n
    np.testing.assert_allclose(T.get_xdata(), np.degrees(cycle.q))
    np.testing.assert_array_equal(T.get_ydata(), cycle.torque)
    np.testing.assert_allclose(d.curves["average"].get_ydata(), [cycle.average] * 2)
    np.testing.assert_allclose(d.curves["smoothed"].get_ydata(), flywheel.smoothed_torque())
    assert len(d.pulses) == len(flywheel.crossings)
    assert "T₁₂" in d.ax.get_ylabel() and "N·m" in d.ax.get_ylabel() and "°" in d.ax.get_xlabel()
    assert d.ax.get_legend() is not None


def test_torque_curve_without_flywheel(cycle):
    d = draw.draw_torque_curve(cycle)
    assert set(d.curves) == {"torque", "average"} and d.pulses == []


def test_polar_forces_are_cycle_polar(cycle):
    d = draw.draw_polar_forces(cycle)
    assert d.ax.name == "polar"
    assert set(d.curves) == {"F12", "F23", "F34", "F14"}
    for name, curve in d.curves.items():
        size, angle = cycle.polar(name)
        assert len(curve.get_xdata()) == cycle.n
        np.testing.assert_array_equal(curve.get_xdata(), angle)
        np.testing.assert_array_equal(curve.get_ydata(), size)
        assert curve.get_label().startswith(draw.cycle.sub(name))
    assert d.ax.get_ylim()[1] >= max(cycle.peaks().forces.values(), key=lambda p: p.value).value
    one = draw.draw_polar_forces(cycle, ["F32"])
    np.testing.assert_array_equal(one.curves["F32"].get_ydata(), cycle.polar("F32")[0])


def test_polar_needs_polar_axes(cycle):
    ax = Figure().add_subplot()
    with pytest.raises(GraphkinError, match="polar"):
        draw.draw_polar_forces(cycle, ax=ax)


def test_shaking(cycle):
    fig = draw.draw_shaking(cycle)
    assert isinstance(fig, Figure) and len(fig.axes) == 2 and fig.axes[0].name == "polar"
    S = cycle.shaking_force()
    d = draw.draw_shaking(cycle, ax=Figure().add_subplot(projection="polar"))
    np.testing.assert_allclose(d.curves["shaking force"].get_ydata(), np.hypot(*S.T))
    d = draw.draw_shaking(cycle, ax=Figure().add_subplot())
    np.testing.assert_array_equal(d.curves["shaking moment"].get_ydata(), cycle.shaking_moment())
    assert "N·m" in d.ax.get_ylabel()


def test_energy(flywheel):
    d = draw.draw_energy(flywheel)
    np.testing.assert_array_equal(d.curves["energy"].get_ydata(), flywheel.U)
    Uc = crossing_energy(flywheel)
    assert Uc.max() - Uc.min() == pytest.approx(flywheel.E, rel=1e-12)
    lo, hi = sorted(d.curves["E"].get_ydata())
    assert hi - lo == pytest.approx(flywheel.E, rel=1e-12)
    # the energy at the crossings lies on the curve (the curve is sampled, so to the step's accuracy)
    on_curve = np.interp(flywheel.crossings, flywheel.theta, flywheel.U, period=2 * math.pi)
    np.testing.assert_allclose(Uc, on_curve, atol=0.02 * flywheel.E)
    assert "E = " in d.labels["E"].get_text() and "J" in d.labels["E"].get_text()


def test_joint_force_index(cutter):
    jfi = joint_force_index(cutter, 72)
    d = draw.draw_joint_force_index(jfi)
    assert len(d.curves["index"].get_ydata()) == 72 + 4  # and a sample either side of 124° and 156°
    np.testing.assert_array_equal(d.curves["limit"].get_ydata(), [2.0, 2.0])
    assert d.curves["peak"].get_ydata()[0] == jfi.peak.value
    assert "immovable" not in d.curves  # the strip cutter has no toggle
    assert d.ax.get_ylim()[1] > 2.0


def test_joint_force_index_marks_immovable(cutter):
    jfi = joint_force_index(cutter, 8)
    fake = type(jfi)(**{**jfi.__dict__, "immovable": ((1.0, "dead point"),)})
    d = draw.draw_joint_force_index(fake)
    np.testing.assert_allclose(d.curves["immovable"].get_xdata(), [math.degrees(1.0)])


def test_draw_cycle(cycle, tmp_path):
    fig = draw.draw_cycle(cycle)
    assert len(fig.axes) == 2
    fig = draw.draw_cycle(cycle, Cs=0.05)
    assert [ax.name for ax in fig.axes] == ["rectilinear", "polar", "rectilinear"]
    assert draw.save(fig, tmp_path / "cycle.png").stat().st_size > 10_000


def test_slider_driver_in_mm():
    c = sweep(catalog.load("double_slider"))
    d = draw.draw_torque_curve(c)
    assert "mm" in d.ax.get_xlabel() and "F₁₂" in d.ax.get_ylabel()
    np.testing.assert_allclose(d.curves["torque"].get_xdata(), c.q * 1e3)


def _shows(ax, y):
    """The y range of the axes holds every finite value of y (as drawn, after the figure is rendered)."""
    ax.figure.canvas.draw() if hasattr(ax.figure.canvas, "draw") else None
    lo, hi = ax.get_ylim()
    y = np.asarray(y, float)
    y = y[np.isfinite(y)]
    return lo <= y.min() and y.max() <= hi


def test_every_cycle_plot_shows_its_whole_curve(cycle, flywheel, cutter):
    """A regression: curves drawn by draw.axes.line left the view at 0–1 where no limits were set."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    d = draw.draw_torque_curve(cycle, flywheel=flywheel)
    FigureCanvasAgg(d.figure)
    assert _shows(d.ax, cycle.torque) and _shows(d.ax, flywheel.smoothed_torque())
    ax = Figure().add_subplot()
    FigureCanvasAgg(ax.figure)
    d = draw.draw_shaking(cycle, ax=ax)
    assert _shows(d.ax, cycle.shaking_moment())
    ax = Figure().add_subplot()
    FigureCanvasAgg(ax.figure)
    d = draw.draw_energy(flywheel, ax=ax)
    assert _shows(d.ax, flywheel.U)
    fig = draw.draw_cycle(cycle, Cs=0.05)
    FigureCanvasAgg(fig)
    torque_axes = [a for a in fig.axes if "T₁₂" in a.get_ylabel()]
    assert torque_axes and _shows(torque_axes[0], cycle.torque)


# -- no text on text -------------------------------------------------------------------------------


def _rendered(fig):
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = fig.figure if not isinstance(fig, Figure) else fig
    FigureCanvasAgg(fig)
    fig.canvas.draw()
    return fig, fig.canvas.get_renderer()


def _texts(fig):
    """(what, artist) of every text drawn on the figure: suptitle, titles, axis labels, tick labels, texts, legends."""
    out = [("suptitle" if t is fig._suptitle else "figure text", t) for t in fig.texts]
    for k, ax in enumerate(fig.axes):
        out += [(f"axes {k} title", t) for t in (ax.title, ax._left_title, ax._right_title)]
        out += [(f"axes {k} text", t) for t in ax.texts]
        for axis in ax._axis_map.values():
            out += [(f"axes {k} axis label", axis.label), (f"axes {k} offset", axis.offsetText)]
            out += [(f"axes {k} tick", lab) for tick in axis._update_ticks() for lab in (tick.label1, tick.label2)]
        if ax.get_legend() is not None:
            out.append((f"axes {k} legend", ax.get_legend()))
    return [(w, t) for w, t in out if t.get_visible() and (not hasattr(t, "get_text") or t.get_text().strip())]


def overlapping_texts(fig, tol=0.5):
    """Pairs of drawn texts (and legends) whose boxes overlap by more than ``tol`` px, with the overlap."""
    fig, r = _rendered(fig)
    items = _texts(fig)
    boxes = [t.get_window_extent(r) for _, t in items]
    found = []
    for i in range(len(items)):
        for j in range(i):
            a, b = boxes[i], boxes[j]
            over = min(min(a.x1, b.x1) - max(a.x0, b.x0), min(a.y1, b.y1) - max(a.y0, b.y0))
            legend = [t for _, t in (items[i], items[j]) if hasattr(t, "get_texts")]
            if over > tol and not any(t in lg.get_texts() for lg in legend for _, t in (items[i], items[j])):
                name = lambda w, t: f"{w} {t.get_text()!r}" if hasattr(t, "get_text") else w  # noqa: E731
                found.append((name(*items[i]), name(*items[j]), round(float(over), 1)))
    return found


_PLOTS = {
    "shaking": lambda c, f: draw.draw_shaking(c),
    "cycle": lambda c, f: draw.draw_cycle(c),
    "cycle with flywheel": lambda c, f: draw.draw_cycle(c, Cs=0.05),
    "torque": lambda c, f: draw.draw_torque_curve(c, flywheel=f),
    "polar forces": lambda c, f: draw.draw_polar_forces(c),
    "energy": lambda c, f: draw.draw_energy(f),
    "joint-force index": lambda c, f: draw.draw_joint_force_index(c.joint_force_index()),
}


@pytest.mark.parametrize("plot", sorted(_PLOTS))
def test_no_text_overlaps_other_text(plot, cycle, flywheel):
    """The shaking figure's suptitle used to run over the polar axes' title (by some 5 px at 100 dpi)."""
    assert overlapping_texts(_PLOTS[plot](cycle, flywheel)) == []


def test_shaking_suptitle_is_above_both_titles(cycle):
    fig, r = _rendered(draw.draw_shaking(cycle))
    bottom = fig._suptitle.get_window_extent(r).y0
    for ax in fig.axes:
        assert ax.title.get_window_extent(r).y1 <= bottom, ax.get_title()


def test_radial_tick_labels_keep_off_the_curves(cycle):
    """They used to sit on the 112.5° ray whatever the curves: on the strip cutter, 8 label–curve crossings."""
    from graphkin.draw.labels import segment_hits_box as _seg_hits_box

    for d in (draw.draw_polar_forces(cycle), draw.draw_shaking(cycle, ax=Figure().add_subplot(projection="polar"))):
        fig, r = _rendered(d.figure)
        ax = d.ax
        labels = [t.label1 for t in ax.yaxis._update_ticks() if t.label1.get_visible() and t.label1.get_text()]
        crossed = 0
        for t in labels:
            b = t.get_window_extent(r)
            for curve in d.curves.values():
                xy = ax.transData.transform(np.column_stack([curve.get_xdata(), curve.get_ydata()]))
                crossed += any(_seg_hits_box(p, q, (b.x0, b.y0, b.x1, b.y1)) for p, q in zip(xy[:-1], xy[1:]))
        assert labels and crossed <= 1, crossed
        assert all(t.get_path_effects() for t in labels)  # a halo for what still crosses them


def test_energy_of_a_steady_torque():
    """A gear pair under a constant load: T never crosses its average, there is no swing to mark (was an IndexError)."""
    c = sweep(catalog.load("gearset"), 36)
    fw = c.flywheel(0.05)
    assert len(fw.crossings) == 0 and crossing_energy(fw).size == 0
    d = draw.draw_energy(fw)
    assert "E" not in d.curves and fw.E == 0.0
    assert overlapping_texts(d) == []


def test_a_flat_torque_curve_keeps_off_the_plot_edge():
    """The gear pair's steady torque sat on the plot's top edge, its line and marker cut in half."""
    from graphkin.draw.cycle import value_limits

    c = sweep(catalog.load("gearset"), 36)
    d = draw.draw_torque_curve(c)
    lo, hi = d.ax.get_ylim()
    T = float(c.torque[0])
    assert np.ptp(c.torque) < 1e-9 * abs(T)
    assert lo < 0 < T < hi and (hi - T) >= 0.05 * (hi - lo)
    assert value_limits([T, T]) == (lo, hi)
    assert value_limits([]) == (-1.0, 1.0) and value_limits([0.0, 0.0]) == (-1.0, 1.0)


def test_forces_that_coincide_are_both_seen_on_the_polar_plot(cycle):
    """The strip cutter's crank has no inertia: F₁₂ = F₂₃ all round, and the second curve hid under the first.
    It is drawn as a wide pale band under it, and the legend says so."""
    d = draw.draw_polar_forces(cycle)
    band, line = d.curves["F12"], d.curves["F23"]
    assert band.get_linewidth() > 2 * line.get_linewidth() and band.get_zorder() < line.get_zorder()
    assert "≈ F₂₃" in band.get_label()
    assert d.curves["F34"].get_linewidth() == line.get_linewidth()  # a force of its own is a line of its own
