"""The notebook explorer (graphkin.widgets): building, slider and speed callbacks, dead positions, lazy imports."""

from __future__ import annotations

import io
import math
import subprocess
import sys

import numpy as np
import pytest

pytest.importorskip("ipywidgets")
pytest.importorskip("matplotlib")

from graphkin import catalog  # noqa: E402
from graphkin.widgets import Explorer, explore  # noqa: E402

SMALL = 36  # positions of the torque curve: keeps the tests fast


@pytest.fixture(scope="module")
def explorers():
    return {name: explore(catalog.load(name), n=SMALL) for name in catalog.names()}


@pytest.mark.parametrize("name", catalog.names())
def test_builds_for_every_catalog_problem(explorers, name):
    ex = explorers[name]
    assert isinstance(ex, Explorer)
    assert ex.construction is not None and ex.construction.valid
    assert ex.image.value[:8] == b"\x89PNG\r\n\x1a\n"
    assert ex.widget.children and ex.figure.axes
    ends = {q for load in ex.problem.mechanism.loads if load.active is not None for q in (load.active.start, load.active.stop)}
    # A sample either side of each angle where a load switches on or off: an active window's ends, and each
    # reversal of the motion a load's sense follows.
    switches = 2 * (len(ends) + _reversals(ex.problem))
    assert len(ex.cycle.torque) == SMALL + (switches if ex.problem.mechanism.driver.kind == "crank" else 0)
    crank = ex.problem.mechanism.driver.kind == "crank"
    assert ("deg" in ex.slider.description) == crank
    assert ("rpm" in ex.speed.description) == crank


def _reversals(problem):
    """How often over a turn the points of the loads whose sense follows the motion reverse along the load's line.

    Counted here from the sign of the velocity on 720 crank angles, independently of graphkin's own search.
    """
    followers = [load for load in problem.mechanism.loads if getattr(load, "sense", "fixed") != "fixed"]
    if not followers or problem.mechanism.driver.kind != "crank":
        return 0
    kin = problem.kinematics(at=np.linspace(0.0, 2 * np.pi, 720, endpoint=False))
    count = 0
    for load in followers:
        if hasattr(load, "force"):
            u = np.asarray(load.force, float) / np.hypot(*load.force)  # the line of the load (its fixed direction)
            v = kin.velocity(load.link, load.point) @ u
        else:  # a torque follows its link's turning
            v = kin.w(load.link)
        count += int(np.count_nonzero(np.sign(v) != np.sign(np.roll(v, 1))))
    return count


@pytest.mark.parametrize("name,value", [("strip_cutter", 140.0), ("slider_crank_friction", 75.0), ("double_slider", -120.0),
                                        ("gearset", 33.0), ("single_link", 210.0)])
def test_slider_redraws_and_matches_solve(explorers, name, value):
    ex = explorers[name]
    before = len(ex.timings)
    ex.slider.value = value
    assert len(ex.timings) == before + 1  # the observer ran update()
    p = ex.problem
    q = math.radians(value) if p.mechanism.driver.kind == "crank" else value * 1e-3
    ref = p.solve(at=[q])
    c = ex.construction
    assert c.valid
    assert c.q == pytest.approx(q)
    assert ex.analytical.effort[0] == pytest.approx(ref.effort[0])
    assert c.effort == pytest.approx(ref.effort[0], rel=1e-6, abs=1e-9)
    for (i, j) in c.forces:
        np.testing.assert_allclose(c.force(i, j), ref.force(i, j)[0], rtol=1e-6, atol=1e-6)
    x, y = ex.marker.get_data()
    assert x[0] == pytest.approx(value) and y[0] == pytest.approx(ref.effort[0])


def test_update_returns_the_construction(explorers):
    ex = explorers["strip_cutter"]
    ex.slider.value = 130.0
    c = ex.update()
    assert c is ex.construction and c.valid


def test_speed_change_recomputes_the_torque_curve():
    ex = explore(catalog.load("strip_cutter"), n=SMALL)
    ex.slider.value = 100.0
    old = ex.cycle.torque.copy()
    ex.speed.value = 450.0  # rpm
    assert ex.problem.q_dot[0] == pytest.approx(450 * math.pi / 30)
    assert not np.allclose(ex.cycle.torque, old)
    ref = ex.problem.solve(at=[math.radians(100.0)])
    assert ex.cycle.q_dot[0] == pytest.approx(450 * math.pi / 30)
    x, y = ex.marker.get_data()
    assert y[0] == pytest.approx(ref.effort[0])
    assert y[0] == pytest.approx(ex.analytical.effort[0])
    assert ex.curve.get_ydata() == pytest.approx(np.where(ex.cycle.valid, ex.cycle.torque, np.nan), nan_ok=True)


def test_slider_driver_speed_in_m_per_s():
    ex = explore(catalog.load("double_slider"), n=SMALL)
    ex.speed.value = 4.0
    assert ex.problem.q_dot[0] == pytest.approx(4.0)
    ex.slider.value = 200.0
    assert ex.analytical.effort[0] == pytest.approx(ex.problem.solve(at=[0.2]).effort[0])


def test_dead_position_shows_a_message():
    ex = explore(catalog.load("double_slider"), n=SMALL)
    assert ex.slider.min <= 500.0 <= ex.slider.max
    ex.slider.value = 500.0
    assert ex.construction is not None and not ex.construction.valid
    assert "dead point" in ex.message
    assert "No solution" in ex.status.value
    assert ex.image.value[:4] == b"\x89PNG"
    assert np.isnan(ex.marker.get_ydata()[0])
    ex.slider.value = 200.0  # and it recovers
    assert ex.construction.valid and not ex.message


def test_import_graphkin_does_not_load_widgets_or_matplotlib():
    code = ("import sys, graphkin, graphkin.problem, graphkin.catalog; "
            "bad = [m for m in ('ipywidgets', 'matplotlib', 'graphkin.widgets') if m in sys.modules]; "
            "import graphkin.widgets; "  # the module itself imports them only when an explorer is built
            "bad += [m for m in ('ipywidgets', 'matplotlib', 'anywidget') if m in sys.modules]; "
            "print(bad); sys.exit(1 if bad else 0)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


def test_bad_n():
    from graphkin.errors import GraphkinError

    with pytest.raises(GraphkinError):
        explore(catalog.load("strip_cutter"), n=1)


def test_figure_grows_when_a_position_needs_more_polygons():
    ex = explore(catalog.load("strip_cutter"), n=SMALL)
    ex._layout(1)
    ex._draw_curve()
    ex.slider.value = 140.0  # the cutting force is on: six polygons
    polys = [s for s in ex.construction.steps if s.polygon]
    assert len(ex.ax_polygons) >= len(polys) > 1
    assert sum(1 for ax in ex.ax_polygons if ax.texts) == len(polys)
    assert ex.marker.get_ydata()[0] == pytest.approx(ex.analytical.effort[0])


def test_display_parts():
    import ipywidgets

    ex = explore(catalog.load("single_link"), n=SMALL)
    assert isinstance(ex.widget, ipywidgets.VBox)
    assert ex.image in ex.widget.children and callable(ex._ipython_display_)


def test_table_shows_both_routes_at_the_slider_position(explorers):
    """The numbers left out of the explorer's polygons are in its table: every joint force, both routes."""
    import re

    ex = explorers["strip_cutter"]
    ex.slider.value = 140.0
    ref = ex.problem.solve(at=[math.radians(140.0)])
    html = ex.table.value
    rows = re.findall(r"<tr><td[^>]*><i>(\w+)</i></td>(.*?)</tr>", html)
    assert [r[0] for r in rows] == ["analytical", "graphical"]
    heads = re.findall(r"<th[^>]*>(\w)<sub>(\d+)</sub></th>", html)
    names = [a + b for a, b in heads]
    assert set(names) == {"F12", "F23", "F34", "F14", "T12"}
    for _, cells in rows:
        values = re.findall(r"<td[^>]*>([^<]*)</td>", cells)
        for name, text in zip(names, values):
            number = float(text.split()[0].replace("−", "-"))
            expected = ref.effort[0] if name == "T12" else float(np.hypot(*ref[name][0]))
            assert number == pytest.approx(expected, rel=1e-3)


def test_no_table_where_there_is_no_solution():
    ex = explore(catalog.load("double_slider"), n=SMALL)
    ex.slider.value = ex.slider.max
    assert ex.message and ex.table.value == ""


def test_stamped_text_looks_like_drawn_text():
    """StampCanvas pastes a label's pixels from its second drawing on: the same picture, whole-pixel placed."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from graphkin.draw.stamps import StampCanvas

    def picture(canvas_class, draws):
        fig = Figure(figsize=(3, 2), dpi=72)
        canvas_class(fig)
        ax = fig.add_axes([0, 0, 1, 1])
        ax.set_axis_off()
        ax.text(0.1, 0.5, "F₂₃ = 1972 N", fontsize=9, color="#D55E00")
        ax.text(0.6, 0.2, "A₀ (G₂)", fontsize=8, rotation=30, ha="center", va="center")
        ax.text(0.5, 0.8, "h = 33 mm", ha="right", va="top")
        for _ in range(draws):
            fig.canvas.draw()
        return np.asarray(fig.canvas.buffer_rgba())[..., :3].astype(int), fig.canvas

    plain, _ = picture(FigureCanvasAgg, 1)
    stamped, canvas = picture(StampCanvas, 3)
    assert sum(1 for v in canvas._stamp_cache.values() if isinstance(v, tuple)) == 3  # pasted, not drawn
    ink = plain.sum(-1) < 3 * 255
    assert ink.sum() > 200
    # Same ink within one pixel: every inked pixel of one picture has ink next to it in the other.
    def near(a, b):
        grown = np.zeros_like(b)
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                grown |= np.roll(np.roll(b, dy, 0), dx, 1)
        return a & ~grown
    stamped_ink = stamped.sum(-1) < 3 * 255
    assert not near(ink, stamped_ink).any() and not near(stamped_ink, ink).any()
    # and the colours are the same: the darkest pixels of the orange label match.
    assert np.abs(plain.min(axis=(0, 1)) - stamped.min(axis=(0, 1))).max() <= 8


# -- what a browser does: echoes, bursts, the screen ---------------------------------------------------------------


def test_a_late_echo_does_not_move_the_explorer_back():
    """Shift+Enter in a browser: the kernel sets 60…330°, then the browser's echo of 150 arrives (issue 14)."""
    ex = explore(catalog.load("slider_crank_friction"), n=SMALL)
    for angle in (60.0, 150.0, 240.0, 330.0):
        ex.slider.value = angle
    drawn = len(ex.timings)
    ex.slider.set_state({"value": 150.00000000000003})  # the path of a message from the browser
    assert ex.value == 330 and ex.slider.value == 330 and ex.box.value == 330
    assert len(ex.timings) == drawn  # nothing redrawn
    assert ex.construction.q == pytest.approx(math.radians(330))
    ref = ex.problem.solve(at=[math.radians(330)])
    assert ex.analytical.effort[0] == pytest.approx(ref.effort[0], rel=1e-12)
    assert f"{ref.effort[0]:.5g}" in ex.status.value


def test_a_slider_drivers_echo_of_its_own_value_changes_nothing():
    """A float slider's value comes back from the browser a rounding off; an older one is put back."""
    ex = explore(catalog.load("double_slider"), n=SMALL)
    for s in (200.0, -120.0, 100.0):
        ex.slider.value = s
    drawn = len(ex.timings)
    assert ex.from_browser(100.00000000000001) is False  # the value drawn, after a floating-point round trip
    ex.slider.set_state({"value": -120.00000000000003})  # an older value, late
    assert ex.value == 100.0 and ex.slider.value == 100.0 and len(ex.timings) == drawn
    assert ex.analytical.effort[0] == pytest.approx(ex.problem.solve(at=[0.1]).effort[0], rel=1e-12)


def test_a_person_moving_the_slider_moves_the_explorer():
    ex = explore(catalog.load("strip_cutter"), n=SMALL)
    ex.slider.value = 140
    ex.slider.set_state({"value": 141})  # an arrow key in the browser
    assert ex.value == 141 and ex.box.value == 141
    assert ex.construction.q == pytest.approx(math.radians(141))
    ex.slider.set_state({"value": 140})  # back to a value the kernel set: a person may do that too
    assert ex.value == 140 and ex.construction.q == pytest.approx(math.radians(140))


def test_values_set_from_code_snap_to_the_step():
    ex = explore(catalog.load("strip_cutter"), n=SMALL)
    ex.slider.value = 139.99999999  # a whole degree: rounded, not truncated
    assert ex.value == 140 and ex.slider.value == 140
    ex.slider.value = math.degrees(math.radians(150.0))
    assert ex.value == 150 and ex.construction.q == pytest.approx(math.radians(150))
    ex.box.value = 45.6  # the box, set from code, moves the slider and redraws
    assert ex.value == 46 and ex.slider.value == 46 and ex.construction.q == pytest.approx(math.radians(46))
    ds = explore(catalog.load("double_slider"), n=SMALL)
    step = ds.step
    assert step in (1, 2, 5, 10, 20, 50) and ds.limits[0] % step == 0 and ds.limits[1] % step == 0
    ds.slider.value = 200.0 + 0.3 * step
    assert ds.value == 200.0 and ds.slider.value == 200.0


def test_a_number_typed_in_the_box_stands():
    """Typed by a person, a value stands even when it equals one the kernel set earlier."""
    ex = explore(catalog.load("strip_cutter"), n=SMALL)
    for angle in (100, 200):
        ex.slider.value = angle
    ex.box.set_state({"value": 100})
    assert ex.value == 100 and ex.slider.value == 100 and ex.construction.q == pytest.approx(math.radians(100))


def test_a_burst_from_the_browser_is_drawn_once_at_its_last_value():
    """Ten key presses reach the kernel before it is free again: one drawing, of the last."""
    import asyncio

    from graphkin import widgets

    ex = explore(catalog.load("strip_cutter"), n=SMALL)
    ex.slider.value = 100
    before = len(ex.timings)

    async def burst():
        for angle in range(101, 111):
            ex.slider.set_state({"value": angle})
        waiting = len(ex.timings) - before
        await asyncio.sleep(widgets.SETTLE + 0.2)
        return waiting

    assert asyncio.run(burst()) == 0  # nothing drawn while the values came
    assert len(ex.timings) == before + 1
    assert ex.value == 110 and ex.construction.q == pytest.approx(math.radians(110))
    ex.slider.value = 50  # code draws at once, loop or not
    assert len(ex.timings) == before + 2 and ex.construction.q == pytest.approx(math.radians(50))


def _grey(png: bytes):
    import io

    from PIL import Image

    with Image.open(io.BytesIO(png)) as im:
        return np.asarray(im.convert("RGBA").convert("L"), float)


def test_positions_next_to_the_one_shown_are_drawn_ahead_and_a_key_press_shows_one_at_once():
    """Idle in a kernel, the explorer draws θ ± 1 and ± 2 steps, the way it last moved first (issue 15)."""
    import asyncio

    from graphkin import widgets

    ex = explore(catalog.load("strip_cutter"), n=SMALL)

    async def session():
        ex.slider.value = 100  # code draws at once, then, idle, the neighbours
        for _ in range(200):
            if {98.0, 99.0, 101.0, 102.0} <= set(ex._frames):
                break
            await asyncio.sleep(0.05)
        order = [v for v in ex._frames if v in (98.0, 99.0, 101.0, 102.0)]
        drawn = len(ex.timings)
        ex.slider.set_state({"value": 101})  # an arrow key in the browser
        shown_at_once = (len(ex.timings) == drawn, ex.value, ex.construction.q, ex.table.value, ex.status.value,
                         ex.image.value == ex._frames[101.0].png)
        await asyncio.sleep(widgets.IDLE + 2.0)  # 103 is drawn next: 101's other neighbours are done
        return order, shown_at_once, list(ex._frames)

    order, (nothing_redrawn, value, q, table, status, image), frames = asyncio.run(session())
    assert order == [101.0, 99.0, 102.0, 98.0]  # up first: the slider came up from its start at 0°
    assert nothing_redrawn and value == 101 and image
    assert q == pytest.approx(math.radians(101))
    ref = ex.problem.solve(at=[math.radians(101)])
    assert "θ = 101°" in table and f"{ref.effort[0]:.5g}" in status
    assert frames[-1] == 103.0
    # The figure is the position shown when code asks for it, drawn again if the neighbours were drawn since.
    x, y = ex.marker.get_data()
    assert x[0] == 101 and y[0] == pytest.approx(ref.effort[0], rel=1e-12)
    got, shown, last = _grey(ex.png()), _grey(ex._frames[101.0].png), _grey(ex._frames[103.0].png)
    assert np.abs(got - shown).mean() < 0.2 * np.abs(last - shown).mean()  # 101's picture, not 103's


def test_a_frame_drawn_ahead_is_the_frame_drawn_when_asked():
    import asyncio

    ahead = explore(catalog.load("slider_crank_friction"), n=SMALL)
    plain = explore(catalog.load("slider_crank_friction"), n=SMALL, ahead=0)

    async def idle():
        ahead.slider.value = 60
        plain.slider.value = 60
        for _ in range(200):
            if 61.0 in ahead._frames:
                break
            await asyncio.sleep(0.05)
        await asyncio.sleep(0.3)
        return sorted(plain._frames)

    assert asyncio.run(idle()) == []  # ahead=0: nothing kept, each position drawn when asked
    frame = ahead._frames[61.0]
    plain.slider.set_state({"value": 61})  # drawn when asked
    assert (frame.status, frame.table, frame.message) == (plain.status.value, plain.table.value, plain.message)
    assert frame.construction.effort == plain.construction.effort
    got, want, before = _grey(frame.png), _grey(plain.image.value), _grey(ahead._frames[60.0].png)
    # The same picture: text stamped to whole pixels and the palette may differ by a shade here and there,
    # far below what one degree of crank changes.
    assert got.shape == want.shape
    assert np.abs(got - want).mean() < 0.2 * np.abs(before - want).mean()


async def _until(condition, seconds=10.0):
    """Wait in the event loop until ``condition()`` holds (drawing ahead goes on meanwhile)."""
    import asyncio
    import time

    end = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > end:
            raise AssertionError("timed out")
        await asyncio.sleep(0.001)


def test_a_key_press_for_the_frame_being_drawn_ahead_finishes_it_and_any_other_stops_it():
    """Drawing ahead goes a panel at a time, the kernel free between steps."""
    import asyncio

    from graphkin import widgets

    ex = explore(catalog.load("strip_cutter"), n=SMALL)

    async def session():
        ex.slider.value = 100
        await _until(lambda: ex._ahead_job is not None)
        value, job = ex._ahead_job  # 101: up first
        drawn = len(ex.timings)
        ex.slider.set_state({"value": value})  # a key press for the frame on the way
        first = (len(ex.timings) == drawn, ex.value, ex.construction.q, ex._ahead_job, job.gi_frame)
        await _until(lambda: ex._ahead_job is not None)
        other, job = ex._ahead_job  # the next neighbour, begun
        ex.slider.set_state({"value": 140})  # a jump elsewhere: the job stops at its next step
        await _until(lambda: ex._ahead_job is None or ex._ahead_job[1] is not job, seconds=1.0)
        stopped = (job.gi_frame is None, other in ex._frames, len(ex.timings) - drawn)
        await asyncio.sleep(widgets.SETTLE + 0.3)
        return first, stopped, ex.value, ex.construction.q, len(ex.timings) - drawn

    (nothing_redrawn, shown, q, job_after, frame_after), stopped, value, q140, redrawn = asyncio.run(session())
    assert nothing_redrawn and shown == 101 and job_after is None and frame_after is None  # finished, not redrawn
    assert q == pytest.approx(math.radians(101))
    closed, kept, drawn_meanwhile = stopped
    assert closed and not kept and drawn_meanwhile == 0  # stopped half way, before 140 was drawn
    assert value == 140 and q140 == pytest.approx(math.radians(140)) and redrawn == 1
    x, _ = ex.marker.get_data()
    assert x[0] == 140


def test_outside_an_event_loop_or_with_ahead_0_every_position_is_drawn_when_asked():
    """As before drawing ahead: nothing kept, a position the browser sends again is drawn again."""
    import asyncio

    ex = explore(catalog.load("strip_cutter"), n=SMALL)
    before = len(ex.timings)
    for v in (60, 0, 60):
        ex.slider.set_state({"value": v})
    assert len(ex.timings) == before + 3 and not ex._frames

    plain = explore(catalog.load("strip_cutter"), n=SMALL, ahead=0)

    async def in_a_loop():
        plain.slider.value = 100
        await asyncio.sleep(0.8)
        drawn = len(plain.timings)
        plain.slider.set_state({"value": 101})
        await asyncio.sleep(0.3)
        return len(plain.timings) - drawn

    assert asyncio.run(in_a_loop()) == 1 and not plain._frames


def test_the_neighbours_go_the_way_the_slider_moved_and_stay_in_its_range():
    import asyncio

    ex = explore(catalog.load("strip_cutter"), n=SMALL)

    async def session():
        ex.slider.value = 120
        ex.slider.value = 100  # down
        await _until(lambda: {98.0, 99.0, 101.0, 102.0} <= set(ex._frames))
        order = [v for v in ex._frames if v in (98.0, 99.0, 101.0, 102.0)]
        ex.slider.value = 360
        await _until(lambda: {358.0, 359.0} <= set(ex._frames))
        await asyncio.sleep(0.3)
        return order, ex._neighbours(), sorted(ex._frames)

    order, at_360, frames = asyncio.run(session())
    assert order == [99.0, 101.0, 98.0, 102.0]
    assert at_360 == [359.0, 358.0] and max(frames) == 360.0


def test_a_late_echo_and_a_typed_value_with_frames_drawn_ahead():
    import asyncio

    ex = explore(catalog.load("slider_crank_friction"), n=SMALL)

    async def session():
        ex.slider.value = 60
        ex.slider.value = 100  # two values set by code
        await _until(lambda: {99.0, 101.0} <= set(ex._frames))
        drawn = len(ex.timings)
        ex.slider.set_state({"value": 60})  # the browser's late echo of 60: 60 has a frame, and is still ignored
        echo = (ex.value, ex.slider.value, len(ex.timings) == drawn)
        ex.box.set_state({"value": 101})  # typed in the box: shown from its frame
        typed = (len(ex.timings) == drawn, ex.value, ex.slider.value, ex.image.value == ex._frames[101.0].png)
        return echo, typed

    (value, slider, nothing_redrawn), typed = asyncio.run(session())
    assert value == 100 and slider == 100 and nothing_redrawn
    nothing_redrawn, value, slider, image = typed
    assert nothing_redrawn and value == 101 and slider == 101 and image
    assert ex.construction.q == pytest.approx(math.radians(101))


def test_a_new_speed_or_screen_while_drawing_ahead_leaves_no_frame_of_the_old_one():
    import asyncio
    import json

    from PIL import Image

    ex = explore(catalog.load("strip_cutter"), n=SMALL)

    async def session():
        ex.slider.value = 100
        await _until(lambda: 101.0 in ex._frames)
        ex.speed.value = 450.0  # the torque curve and every frame change
        await _until(lambda: {99.0, 101.0} <= set(ex._frames))
        ex.slider.set_state({"value": 101})
        status = ex.status.value
        await _until(lambda: ex._ahead_job is not None)
        job = ex._ahead_job[1]
        ex._screen.screen = json.dumps({"ratio": 2, "width": 1200})  # what the page reports
        closed = job.gi_frame is None
        await _until(lambda: {100.0, 102.0} <= set(ex._frames) and ex._figure_at == 101.0 or
                     len(ex._frames) >= 3, seconds=20.0)
        await asyncio.sleep(0.5)
        return status, closed, dict(ex._frames)

    status, closed, frames = asyncio.run(session())
    want = ex.problem.solve(at=[math.radians(101)]).effort[0]
    assert f"{want:.5g}" in status and ex.problem.q_dot[0] == pytest.approx(450 * math.pi / 30)
    assert closed
    size = ex._canvas.figure.canvas.get_width_height(physical=True)
    for frame in frames.values():
        with Image.open(io.BytesIO(frame.png)) as im:
            assert im.size == size  # every frame kept is of the new screen


def test_a_position_that_cannot_be_drawn_ahead_does_not_stop_the_others(monkeypatch):
    import asyncio

    from graphkin import draw, widgets

    ex = explore(catalog.load("strip_cutter"), n=SMALL)
    real = draw.draw_free_body

    def failing(c, link, **kwargs):
        if abs(c.q - math.radians(101)) < 1e-9:
            raise RuntimeError("a drawing fault at 101°")
        return real(c, link, **kwargs)

    monkeypatch.setattr(draw, "draw_free_body", failing)

    async def session():
        ex.slider.value = 100
        await _until(lambda: {98.0, 99.0, 102.0} <= set(ex._frames))
        ex.slider.set_state({"value": 101})  # drawn when asked: its error shows
        await asyncio.sleep(widgets.SETTLE + 0.3)
        return sorted(ex._frames), ex.status.value

    frames, status = asyncio.run(session())
    assert 101.0 not in frames and {98.0, 99.0, 102.0} <= set(frames)
    assert "Could not draw 101" in status and "a drawing fault at 101°" in status


def test_an_error_in_answering_the_browser_is_shown_in_the_status_line_and_one_from_code_raises(monkeypatch):
    """A comm message's handler runs outside any cell: its error would reach only the kernel's log."""
    ex = explore(catalog.load("strip_cutter"), n=SMALL)

    def failing():
        raise RuntimeError("a fault in the sweep")

    monkeypatch.setattr(ex, "_sweep", failing)
    ex.speed.set_state({"value": 450.0})  # typed in the browser
    assert "Could not draw" in ex.status.value and "a new speed from the browser" in ex.status.value
    assert "RuntimeError: a fault in the sweep" in ex.status.value
    with pytest.raises(RuntimeError, match="a fault in the sweep"):
        ex.speed.value = 600.0  # set by code: the cell sees it
    monkeypatch.setattr(ex, "_take", lambda v: failing())
    ex.slider.set_state({"value": 120})
    assert "a new position from the browser" in ex.status.value and "a fault in the sweep" in ex.status.value


@pytest.mark.slow
def test_messages_handled_on_another_thread_are_answered_on_the_explorers_own():
    """ipykernel 7 runs a comm's handler on a subshell's thread: JupyterLab's key presses came there while the
    main thread drew ahead, and a new speed on the main thread then met "generator already executing"."""
    import asyncio
    import threading

    from graphkin import widgets

    ex = explore(catalog.load("strip_cutter"), n=SMALL)
    rendered_on = set()
    render = ex._canvas.render

    def recording():
        rendered_on.add(threading.get_ident())
        render()

    ex._canvas.render = recording

    def subshell(values):  # what a subshell's thread does with a burst of key presses
        for v in values:
            ex.slider.set_state({"value": v})

    async def session():
        ex.slider.value = 100
        await _until(lambda: ex._ahead_job is not None)  # a frame is being drawn ahead, a step at a time
        worker = threading.Thread(target=subshell, args=(range(101, 131),))
        worker.start()
        while worker.is_alive():  # the main thread keeps drawing ahead meanwhile
            await asyncio.sleep(0.001)
        worker.join()
        ex.speed.set_state({"value": 450.0})  # then a new speed, on the main thread
        await asyncio.sleep(widgets.SETTLE + 0.5)
        return ex.value, ex.status.value

    value, status = asyncio.run(session())
    assert rendered_on == {threading.get_ident()}  # nothing drawn on the subshell's thread
    assert value == 130 and "Could not draw" not in status
    want = ex.problem.solve(at=[math.radians(130)]).effort[0]
    assert ex.problem.q_dot[0] == pytest.approx(450 * math.pi / 30) and f"{want:.5g}" in status


def test_a_figure_code_holds_is_put_back_at_the_position_shown_before_a_cell_runs():
    """fig = ex.figure in one cell, fig.savefig(...) in the next: the position shown, not a neighbour."""
    import asyncio

    from IPython.core.interactiveshell import InteractiveShell

    shell = InteractiveShell.instance()
    try:
        ex = explore(catalog.load("strip_cutter"), n=SMALL)

        async def session():
            ex.slider.value = 100
            fig = ex.figure  # the first cell
            await _until(lambda: {99.0, 101.0} <= set(ex._frames))
            moved = ex._figure_at
            shell.events.trigger("pre_run_cell", None)  # the next cell is about to run
            # What that cell sees (the loop waits while a cell runs: nothing is drawn ahead meanwhile).
            return fig, moved, ex._figure_at, ex._ahead_job, ex._canvas.marker.get_xdata()[0]

        fig, moved, at, job, marker = asyncio.run(session())
        assert moved != 100.0  # drawing ahead had drawn a neighbour on it
        assert at == 100.0 and job is None and marker == 100.0 and fig is ex._canvas.figure
    finally:
        InteractiveShell.clear_instance()


def widgets_most_ahead():
    from graphkin import widgets

    return widgets.MOST_AHEAD


def test_bad_ahead():
    for bad in (-1, 1.5, True, widgets_most_ahead() + 1):
        with pytest.raises(Exception, match="ahead must be a whole number"):
            explore(catalog.load("strip_cutter"), n=SMALL, ahead=bad)


def test_the_figure_is_rendered_for_the_screen_the_browser_reports():
    import io
    import json

    from PIL import Image

    from graphkin import widgets

    ex = explore(catalog.load("strip_cutter"), n=SMALL)
    assert ex.figure.dpi == widgets.CSS_DPI  # before a browser reports: 100 dpi
    ex._screen.set_state({"screen": json.dumps({"ratio": 2, "width": 1000})})
    width_in, height_in = ex.figure.get_size_inches()
    assert width_in == pytest.approx(10.0) and ex.figure.dpi == 200
    assert ex.image.layout.width == "1000px"  # 100 screen pixels per inch, 200 image pixels per inch
    png = Image.open(io.BytesIO(ex.image.value))
    assert png.size[0] == round(width_in * 200) and png.info["dpi"] == pytest.approx((200, 200), abs=0.01)
    ex._screen.set_state({"screen": "not what the probe writes"})  # ignored
    assert ex.figure.dpi == 200


def test_every_text_is_at_least_11_screen_pixels():
    """8 pt (the smallest text) at 100 screen pixels per inch is 11.1 px; subscripts are smaller glyphs of it."""
    from matplotlib.text import Text

    from graphkin import widgets

    assert widgets.MIN_PT * widgets.CSS_DPI / 72 >= 11
    ex = explore(catalog.load("strip_cutter"), n=SMALL)
    ex.slider.value = 140  # the cut: the most labels
    texts = [t for t in ex.figure.findobj(Text) if t.get_text().strip() and t.get_visible()]
    assert len(texts) > 20
    assert min(t.get_fontsize() for t in texts) >= widgets.MIN_PT


def test_the_slider_takes_most_of_the_row_with_the_box_beside_it():
    ex = explore(catalog.load("strip_cutter"), n=SMALL)
    row = ex.widget.children[0]
    assert list(row.children) == [ex.slider, ex.box]
    assert ex.slider.layout.min_width == "60%" and ex.slider.readout is False


def test_graphkin_explore_with_a_bad_problem_is_one_line_and_exit_2():
    """Reported before Voilà starts (the browser test serves a real page and stops it with Ctrl-C)."""
    r = subprocess.run([sys.executable, "-m", "graphkin", "explore", "no_such_problem", "--no-browser"],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr.count("\n") == 1 and r.stderr.startswith("graphkin: error:") and "no_such_problem" in r.stderr


def test_graphkin_explore_page_holds_the_problem_and_nothing_else():
    from graphkin.cli.explore import notebook

    nb = notebook("strip_cutter", "Four-bar strip cutter")
    code = [c["source"] for c in nb["cells"] if c["cell_type"] == "code"]
    assert code == ["from graphkin import catalog\nfrom graphkin.widgets import explore\n\n"
                    "explore(catalog.load('strip_cutter'))"]
    assert nb["metadata"]["kernelspec"]["name"] == "python3" and nb["nbformat"] == 4


@pytest.mark.parametrize("name", catalog.names())
def test_the_torque_panel_keeps_its_labels_inside_its_cell(name):
    """The panel's pixels are cached by cell (Canvas.render): a tick or axis label outside it would be cut off."""
    ex = explore(catalog.load(name))  # the whole curve: the double slider's reaches ±50000 N near its dead ends
    fig = ex.figure
    renderer = fig.canvas.get_renderer()
    cell = ex._canvas.torque_cell.transformed(fig.transFigure)
    ax = ex.ax_torque
    assert ax.yaxis.label.get_text() and ax.xaxis.label.get_text() and ax.title.get_text()
    box = ax.get_tightbbox(renderer)  # what is drawn: labels, title, the tick labels inside the limits
    assert cell.x0 - 0.5 <= box.x0 and box.x1 <= cell.x1 + 0.5 and cell.y0 - 0.5 <= box.y0 and box.y1 <= cell.y1 + 0.5


def test_the_torque_curve_follows_the_frame_number_and_keeps_a_flat_curve_inside():
    """A book that numbers the frame 0 reads T01 on the curve; a gear pair's constant torque sits off the edge."""
    from graphkin.problem import parse_problem
    from tests.handout.test_numbering import DYNAMIC_CYCLE

    ex = Explorer(parse_problem(DYNAMIC_CYCLE, file="frame0.toml"))
    assert ex.ax_torque.get_ylabel().startswith("T01") and "T01" in ex.ax_torque.get_title()
    gears = Explorer(catalog.load("gearset"))
    T = gears.cycle.torque[np.isfinite(gears.cycle.torque)]
    lo, hi = gears.ax_torque.get_ylim()
    span = hi - lo
    assert lo + 0.05 * span < T.min() and T.max() < hi - 0.05 * span


def test_the_motion_polygons_toggle_on_and_off():
    ex = explore(catalog.load("strip_cutter"), n=SMALL, ahead=0)
    assert not ex.motion.value and ex.motion_construction is None and ex._canvas.ax_motion == []
    ex.motion.value = True
    ex.slider.value = 140
    mc = ex.motion_construction
    assert mc is not None and mc.valid and len(ex._canvas.ax_motion) == 2
    # The polygons' ω of every link are the analytical solver's at the slider's position.
    kin = ex.problem.kinematics(at=[math.radians(140)])
    for link, w in mc.omega.items():
        assert w == pytest.approx(float(kin.omega[link][0]) if link in kin.omega else 0.0, rel=1e-9, abs=1e-12)
    drawn = {a.get_gid() for ax in ex._canvas.ax_motion for a in ax.patches if a.get_gid()}
    assert any(g.startswith("velocity:") for g in drawn) and any(g.startswith("acceleration:") for g in drawn)
    ex.motion.value = False
    ex.slider.value = 141
    assert ex.motion_construction is None and ex._canvas.ax_motion == []
