"""The explorer: its controls, what the browser says, and when a position is drawn.

:class:`Explorer` holds the widgets (a slider and a numeric box for the input
position, a speed input, a status line, the force table and the image), and
answers them: a value the kernel sets stands and is drawn at once; values from
the browser are told from their late echoes and drawn once a burst of them
settles (:data:`SETTLE`); a message handed to another thread is answered on the
explorer's own. What it draws is the canvas's (:mod:`graphkin.widgets.canvas`);
the frames it keeps and draws ahead are :mod:`graphkin.widgets.frames`'.
"""

from __future__ import annotations

import contextlib
import json
import logging
import math
import threading
import time
import weakref
from html import escape

import numpy as np

from graphkin.analytical import solve_forces
from graphkin.cycle.sweep import Cycle, sweep
from graphkin.errors import GraphkinError
from graphkin.graphical import construct_forces, construct_kinematics
from graphkin.graphical.guard import check_forces
from graphkin.optional import require
from graphkin.widgets.browser import BrowserExplorer
from graphkin.widgets.canvas import PAGE_WIDTH, Canvas, force_table
from graphkin.widgets.controls import make_controls, snap
from graphkin.widgets.frames import AHEAD, MOST_AHEAD, DrawingAhead, Frame, to_the_end
from graphkin.widgets.threads import answers_the_browser, running_loop

_log = logging.getLogger(__name__)

SETTLE = 0.03
"""Seconds without a new value from the browser before it is drawn: a burst of key presses is drawn once."""

LIVE = 0.15
"""While values keep coming from the browser (a drag), one is drawn at least this often [s]."""

ECHOES = 64
"""Values set by the kernel that are remembered to recognise their late echoes."""


def explore(problem, *, n: int = 360, limits=None, dpi: int | None = None, halo: bool = False,
            ahead: int = AHEAD, browser: bool = False):
    """An interactive explorer of a problem, for a Jupyter notebook.

    By default the kernel draws each position as a PNG (:class:`Explorer`). With ``browser=True`` the browser draws
    every position of a presolved cycle (:class:`graphkin.widgets.browser.BrowserExplorer`, issue 37): the kernel is
    asked again only for a new length, mass, load or friction (``set``); ``limits``, ``dpi``, ``halo`` and ``ahead``
    are the PNG explorer's and do not apply.

    Parameters
    ----------
    problem : graphkin.problem.Problem
        The problem to explore: a catalog problem or one read from a file.
    n : int
        Number of positions of the torque curve over the cycle. A crank's
        slider moves in whole degrees; a slider driver's in a round step
        (1, 2 or 5 × 10^k mm) of about ``range / n``.
    limits : (float, float), optional
        Slider range for a slider driver [mm]; by default the problem's own
        positions if they span a range, else its position ± the total length of
        its links (rounded out to the step). A crank always turns 0–360°.
    dpi : int, optional
        Resolution of the rendered PNG [pixels per inch of the figure]. By
        default ``CSS_DPI`` times the screen's pixel ratio, as the browser
        reports it (100 until it does).
    halo : bool
        Keep the white outline behind labels (legible over lines, but drawing
        outlined text costs about a third of the rendering time).
    ahead : int
        While the kernel is idle, the positions this many steps either side of
        the one shown are drawn ahead, the way the slider last moved first: a
        key press (or a typed value) that reaches one of them shows it at once.
        0 draws only what is asked for.
    browser : bool
        Draw in the browser from a presolved cycle of ``n`` crank angles (a slider driver: its own positions).

    Returns
    -------
    Explorer or graphkin.widgets.browser.BrowserExplorer
        The widgets and the figure; display it in a cell.
    """
    if browser:
        return BrowserExplorer(problem, n)
    return Explorer(problem, n=n, limits=limits, dpi=dpi, halo=halo, ahead=ahead)


def _canvas_part(name: str, doc: str) -> property:
    """A read-only attribute of the explorer: its canvas's ``name`` (see :class:`~graphkin.widgets.canvas.Canvas`)."""
    return property(lambda self: getattr(self._canvas, name), doc=doc)


class Explorer(DrawingAhead):
    """The widgets and figure of :func:`explore`.

    Attributes
    ----------
    problem : Problem
        The problem at the current speed (the original's input rate replaced).
    value : float
        The position drawn: crank angle θ [deg, whole] or slider position s [mm],
        on the slider's step.
    slider : ipywidgets.IntSlider or ipywidgets.FloatSlider
        Crank angle θ [deg] (whole degrees) or slider position s [mm]. Setting
        its value from code snaps it to the step and redraws at once.
    box : ipywidgets.BoundedIntText or ipywidgets.BoundedFloatText
        The same position as a number, beside the slider (type a value).
    speed : ipywidgets.FloatText
        Crank speed [rpm] or slider speed [m/s].
    figure : matplotlib.figure.Figure
    image : ipywidgets.Image
        The rendered figure (PNG, its resolution in the file).
    status : ipywidgets.HTML
        The driving effort at the position, or why there is no solution there.
    table : ipywidgets.HTML
        Every joint force and the driving effort at the position, analytical and
        graphical (the force polygons in the figure carry the names only).
    widget : ipywidgets.VBox
        Everything, for display.
    construction : Construction
        The graphical solution drawn last.
    motion : ipywidgets.Checkbox
        Show the velocity and acceleration polygons (:func:`graphkin.graphical.construct_kinematics`) in a row
        of their own; off at first.
    motion_construction : MotionConstruction or None
        The polygons drawn last (None while they are hidden).
    analytical : ForceAnalysis
        The matrix solution at the same position (one position).
    cycle : Cycle
        The sweep behind the torque curve, at the current speed.
    marker : matplotlib.lines.Line2D
        The marker on the torque curve.
    curve : matplotlib.lines.Line2D
        The torque curve.
    ax_mechanism, ax_torque, ax_fbd, ax_polygons
        The figure's panels: the mechanism, the torque curve, the free-body
        diagrams (by link number) and the force polygons.
    pixel_ratio, page_width : float
        The screen's pixel ratio and the width the page gives the explorer [CSS px],
        as the browser last reported them (1 and :data:`PAGE_WIDTH` before it does).
    timings : list of float
        Seconds taken by each update (construction + redraw + PNG).
    """

    def __init__(self, problem, *, n: int = 360, limits=None, dpi: int | None = None, halo: bool = False,
                 ahead: int = AHEAD):
        require("ipywidgets", "the explorer")  # one line naming the extra, before anything else
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 2:
            raise GraphkinError(f"n must be a whole number of positions ≥ 2, got {n!r}")
        if dpi is not None and (isinstance(dpi, bool) or not isinstance(dpi, (int, np.integer)) or dpi < 10):
            raise GraphkinError(f"dpi must be a whole number ≥ 10 (or None: the screen's), got {dpi!r}")
        if isinstance(ahead, bool) or not isinstance(ahead, (int, np.integer)) or not 0 <= ahead <= MOST_AHEAD:
            raise GraphkinError(f"ahead must be a whole number of positions from 0 to {MOST_AHEAD}, got {ahead!r}")
        self.n = int(n)
        self._halo = bool(halo)
        self.ahead = int(ahead)
        self.crank = problem.mechanism.driver.crank
        # A book's measured values ([given]) hold at its own position only: the explorer moves the mechanism
        # through the motion its input produces.
        problem = problem.without_given()
        self._original = problem
        q_dot0 = float(problem.q_dot[0])
        self.problem = problem.at_speed(q_dot0)
        self.timings: list[float] = []
        self.construction = None
        self.analytical = None
        self.message = ""
        self.pixel_ratio, self.page_width = 1.0, PAGE_WIDTH
        self._dpi = None if dpi is None else int(dpi)
        self._quiet = False  # True while the explorer itself sets its controls
        self._sent: list[float] = []  # values set by the kernel since the browser last moved the slider
        self._timer = None  # the pending draw of a value from the browser
        self._first_wait = None  # when the values now waiting began to arrive (loop time)
        self._figure_at = None  # the position the figure shows (None: none yet)
        self._heading = 1  # the way the slider last moved: +1 or -1
        self._init_drawing_ahead()  # the frames kept, and the frame being drawn ahead (see DrawingAhead)
        self._handed_out = False  # code has taken the figure: it is put back before each cell runs
        self._home = threading.get_ident()  # the explorer's thread: everything it draws is drawn there
        self._home_loop = None  # that thread's event loop, once seen running (see _loop)

        controls = make_controls(problem, self.problem, self.n, limits)
        self.limits, self.step, self.value = controls.limits, controls.step, controls.value
        self.slider, self.box, self.speed = controls.slider, controls.box, controls.speed
        self.image, self.status, self.table = controls.image, controls.status, controls.table
        self._screen, self.widget = controls.screen, controls.widget
        self.motion = controls.motion
        self.motion_construction = None
        self._canvas = Canvas(self._dpi)
        self._layout(self._polygons_needed())
        self._sweep()
        self.slider.observe(self._on_slider, names="value")
        self.box.observe(self._on_box, names="value")
        self.speed.observe(self._on_speed, names="value")
        self._screen.observe(self._on_screen, names="screen")
        self.motion.observe(self._on_motion, names="value")
        self.update()

    # -- the thread ---------------------------------------------------------------
    def _loop(self):
        """The running event loop (None outside one: plain Python), remembered when it is the explorer's thread's."""
        loop = running_loop()
        if loop is not None and threading.get_ident() == self._home:
            self._home_loop = loop
        return loop

    def _answer(self, observer, change, by_browser: bool, what: str, handed: bool):
        """Run an observer of a control (see :func:`graphkin.widgets.threads.answers_the_browser`)."""
        if not (by_browser or handed):
            observer(self, change, by_browser)  # code's own change: an error reaches its cell
            return
        try:
            observer(self, change, by_browser)
        except Exception as exc:  # noqa: BLE001 - shown to the person, logged with its traceback
            _log.exception("the explorer could not answer a new %s", what)
            self._could_not_draw(exc, f" (a new {what} from the browser)")

    def _could_not_draw(self, exc: Exception, why: str = ""):
        """Say in the status line that the position shown could not be drawn, and the error."""
        self.status.value = f"<b>Could not draw {self.value:g}</b>{why}: {escape(f'{type(exc).__name__}: {exc}')}"

    # -- the position -------------------------------------------------------------
    def _si(self, value: float) -> float:
        """A position in the slider's unit, in SI (rad or m)."""
        return math.radians(value) if self.crank else value * 1e-3

    def _q_dot(self) -> float:
        v = float(self.speed.value)
        return v * math.pi / 30.0 if self.crank else v

    def _snap(self, value: float) -> float:
        """``value`` on the slider's step, inside its range (whole degrees for a crank)."""
        return snap(value, self.limits, self.step)

    def _same(self, a: float, b: float) -> bool:
        """Equal to far below one step: the same position after a browser's floating-point round trip."""
        return abs(a - b) <= 1e-6 * self.step

    @contextlib.contextmanager
    def _hushed(self):
        """Set the controls without their observers answering."""
        self._quiet, quiet = True, self._quiet
        try:
            yield
        finally:
            self._quiet = quiet

    def _show(self, value: float, *, slider: bool = True):
        """Put ``value`` in the box (and the slider)."""
        with self._hushed():
            if slider:
                self.slider.value = value
            self.box.value = value

    @answers_the_browser("slider", "position")
    def _on_slider(self, change, by_browser: bool):
        if self._quiet:
            return
        # A person's move (or the browser's echo), or a value set by code.
        if by_browser:
            self.from_browser(change["new"])
        else:
            self._goto(change["new"])

    @answers_the_browser("box", "position typed")
    def _on_box(self, change, by_browser: bool):
        if self._quiet:
            return
        if by_browser:
            # Typed by a person: it stands, even if it equals a value the kernel set earlier.
            self._sent.clear()
            v = self._snap(change["new"])
            self._move(v)
            self._show(v)
            self._take(v)
        else:
            self._goto(change["new"])

    def _goto(self, value: float):
        """A position set by code: snapped, remembered (to know its echo), drawn at once."""
        v = self._snap(value)
        self._sent.append(v)
        del self._sent[:-ECHOES]
        self._move(v)
        self._show(v)
        self.update()

    def _move(self, v: float):
        """Make ``v`` the position, noting the way the slider moved (drawn ahead first)."""
        if not self._same(v, self.value):
            self._heading = 1 if v > self.value else -1
        self.value = v

    def from_browser(self, value: float) -> bool:
        """Take a value of the slider that came from the browser; returns whether it moved the explorer.

        A browser's slider may send back a value the kernel set, changed by a
        floating-point round trip (``150.00000000000003`` for 150), and it may
        arrive after the kernel has set a newer one. A value within a millionth of
        a step of the position drawn changes nothing; one equal to an earlier value
        the kernel set is such a late echo: the slider is put back to the position
        drawn. Anything else is a person's move: shown at once if that position
        was drawn ahead (see ``ahead`` in :func:`explore`), else drawn once the
        burst of moves settles (:data:`SETTLE`), or at once outside a running
        event loop.

        Parameters
        ----------
        value : float
            The slider's value as the browser sent it.

        Returns
        -------
        bool
        """
        v = self._snap(value)
        if self._same(v, self.value):
            return False
        if any(self._same(v, old) for old in self._sent[:-1]):
            with self._hushed():
                self.slider.value = self.value  # tells the browser where the explorer is
            return False
        self._sent.clear()
        self._move(v)
        self._show(v, slider=False)
        self._take(v)
        return True

    def _later(self):
        """Draw the latest value once the values from the browser stop coming (or every LIVE seconds)."""
        loop = self._loop()
        if loop is None:
            self.update()
            return
        now = loop.time()
        if self._timer is not None:
            self._timer.cancel()
        if self._first_wait is None:
            self._first_wait = now
        delay = SETTLE if now - self._first_wait < LIVE else 0.0
        self._timer = loop.call_later(delay, self._draw_waiting)

    def _draw_waiting(self):
        self._timer = self._first_wait = None
        try:
            self.update()
        except Exception as exc:  # no cell shows what a loop callback raises: the status line does
            self._could_not_draw(exc)

    def _cancel(self):
        if self._timer is not None:
            self._timer.cancel()
        self._timer = self._first_wait = None

    # -- the screen -----------------------------------------------------------------
    @answers_the_browser("_screen", "screen size", trait="screen")
    def _on_screen(self, change, by_browser: bool):
        """The browser reports its pixel ratio and the width it gives the explorer: re-render to fit."""
        try:
            said = json.loads(change["new"])
            ratio = min(max(float(said["ratio"]), 1.0), 4.0)
            width = min(max(float(said["width"]), 200.0), 8000.0)
        except (ValueError, TypeError, KeyError):
            return
        if abs(ratio - self.pixel_ratio) < 0.01 and abs(width - self.page_width) < 8:
            return
        self.pixel_ratio, self.page_width = ratio, width
        self._layout(self._canvas.polygon_slots)
        self._draw_curve()
        self._later()

    # -- layout -----------------------------------------------------------------
    def _polygons_needed(self) -> int:
        """The most force polygons a construction draws, over a few positions of the range."""
        lo, hi = self.limits
        at = np.array([self._si(v) for v in np.linspace(lo, hi, 13)])
        try:
            kin = self.problem.kinematics(at)
        except GraphkinError:
            return 1
        most = 1
        for i in range(len(at)):
            c = construct_forces(kin, i)
            most = max(most, sum(1 for s in c.steps if s.polygon))
        return most

    def _layout(self, polygons: int):
        """(Re)create the persistent axes: mechanism and torque curve, free bodies, polygon slots."""
        self._on_new_layout()  # the frames drawn for the old layout go
        shown = self._canvas.layout(self.problem.mechanism.moving, polygons, self.page_width, self.pixel_ratio,
                                    motion=bool(self.motion.value))
        self.image.layout.width = f"{round(shown)}px"

    # -- the torque curve ---------------------------------------------------------
    def _sweep(self):
        """Solve the whole cycle at the current speed and draw the torque curve (once per speed)."""
        self.problem = self._original.at_speed(self._q_dot())
        if self.crank:
            self.cycle = sweep(self.problem, self.n)
        else:
            lo, hi = self.limits
            self.cycle = Cycle(self.problem, self.problem.solve(at=np.linspace(lo, hi, self.n) * 1e-3))
        self._draw_curve()

    def _draw_curve(self):
        """Draw the torque curve of :attr:`cycle` on the canvas."""
        self._frames.clear()  # their marker sits on the old curve
        self._figure_at = None
        x = np.degrees(self.cycle.q) if self.crank else self.cycle.q * 1e3
        y = np.where(self.cycle.valid, self.cycle.torque, np.nan)
        effort = self.problem.mechanism.driver
        name = effort.symbol  # T12, or T01 in a book that numbers the frame 0
        unit = "N·m" if self.crank else "N"
        speed = f"{self.speed.value:g} {'rpm' if self.crank else 'm/s'}"
        self._canvas.draw_curve(x, y, self.limits, xlabel="θ (deg)" if self.crank else "s (mm)",
                                ylabel=f"{name} ({unit})",
                                title=f"Driving {'torque' if self.crank else 'force'} {name} at {speed}")

    # -- the motion polygons -----------------------------------------------------------
    @answers_the_browser("motion", "polygons toggle")
    def _on_motion(self, change, by_browser: bool):
        """Show or hide the velocity and acceleration polygons: a new layout (the frames drawn ahead go)."""
        self._layout(self._canvas.polygon_slots)
        self._draw_curve()
        self.update()

    # -- the speed ------------------------------------------------------------------
    @answers_the_browser("speed", "speed")
    def _on_speed(self, change, by_browser: bool):
        try:
            self._sweep()
        except GraphkinError as exc:
            self.message = f"No torque curve at this speed: {exc}"
        self.update()

    # -- one update -----------------------------------------------------------------
    def update(self):
        """Solve and redraw at the current position (:attr:`value`); returns the Construction drawn (None if none)."""
        self._cancel()  # what was waiting to be drawn is drawn now
        t0 = time.perf_counter()
        frame = self._draw(self.value)
        self._present(frame)
        self.timings.append(time.perf_counter() - t0)
        self._plan_ahead()
        return frame.construction

    def _draw(self, value: float) -> Frame:
        """Solve and draw the figure at ``value``, keep the frame and return it (the widgets show what they showed)."""
        self._abandon()  # a frame being drawn ahead: the figure is needed now
        return to_the_end(self._drawing(value))

    def _drawing(self, value: float):
        """Solve and draw the figure at ``value`` in steps (a generator: one panel, the rendering, the PNG each),
        keep the frame and return it (the widgets show what they showed).

        Drawn ahead, the kernel reads its messages between two steps (see :meth:`_draw_ahead`).
        """
        q = self._si(value)
        c = a = mc = None
        message = ""
        try:
            kin = self.problem.kinematics(at=[q])
            c = construct_forces(kin, 0)
            # Only when shown: the polygons' construction is a key press's cost otherwise.
            mc = construct_kinematics(kin, 0) if self.motion.value else None

            a = solve_forces(kin)
            c = check_forces(a, c, 0)  # a construction that disagrees with the analytical route is not shown
        except GraphkinError as exc:
            message = str(exc)
        if c is not None and not c.valid:
            message = c.reason or "the linkage cannot be assembled here"
        polys = [s for s in c.steps if s.polygon] if (c is not None and c.valid) else []
        if len(polys) > self._canvas.polygon_slots:
            self._layout(len(polys))
            self._draw_curve()
        self._figure_at = None  # in between: asked for, the figure is drawn again
        here = f"{value:g}{'°' if self.crank else ' mm'}"
        if message:
            yield from self._canvas.drawing(c, polys, (np.nan, np.nan), message=f"No solution at {here}:\n{message}",
                                            halo=self._halo)
            status = f"<b>No solution at {here}</b>: {message}"
        else:
            effort = float(a.effort[0]) if a is not None else float(c.effort)
            yield from self._canvas.drawing(c, polys, (value, effort), halo=self._halo, motion=mc)
            name = c.driver_name
            unit = "N·m" if self.crank else "N"
            warn = "".join(f"<br>warning: {w}" for w in c.warnings)
            status = (f"{here}: {name} = {effort:.5g} {unit} (analytical), "
                      f"{float(c.effort):.5g} {unit} (graphical){warn}")
        where = f"θ = {here}" if self.crank else f"s = {here}"
        forces = force_table(c, a, where) if not message else ""
        return self._keep(Frame(value, self._canvas.encode(), c, a, message, status, forces, mc))

    def _present(self, frame: Frame):
        """Show a drawn frame in the widgets."""
        self.construction, self.analytical, self.message = frame.construction, frame.analytical, frame.message
        self.motion_construction = frame.motion
        self.status.value = frame.status
        self.table.value = frame.table
        self.image.value = frame.png

    # -- the figure -------------------------------------------------------------------
    ax_mechanism = _canvas_part("ax_mechanism", "The mechanism's panel (matplotlib.axes.Axes).")
    ax_torque = _canvas_part("ax_torque", "The torque curve's panel (matplotlib.axes.Axes).")
    ax_fbd = _canvas_part("ax_fbd", "The free-body diagrams' panels (dict: link number -> matplotlib.axes.Axes).")
    ax_polygons = _canvas_part("ax_polygons", "The force polygons' panels (list of matplotlib.axes.Axes).")
    curve = _canvas_part("curve", "The torque curve (matplotlib.lines.Line2D).")
    _panels = _canvas_part("panels", "The panels drawn again at each position: all but the torque curve's.")

    @property
    def figure(self):
        """The figure (matplotlib.figure.Figure), drawn at :attr:`value`.

        Positions are drawn ahead on this figure while the kernel is idle;
        asking for it draws the position shown first, and once code has had
        it, the explorer puts it back at the position shown before each cell
        runs (so ``fig = ex.figure`` in one cell and ``fig.savefig(...)`` in
        the next save what the explorer shows).
        """
        self._sync()
        self._hand_out()
        return self._canvas.figure

    @property
    def marker(self):
        """The marker on the torque curve (matplotlib.lines.Line2D), at :attr:`value` (see :attr:`figure`)."""
        self._sync()
        self._hand_out()
        return self._canvas.marker

    @property
    def halo(self) -> bool:
        """Whether labels keep their white outline (see :func:`explore`); setting it redraws the position shown."""
        return self._halo

    @halo.setter
    def halo(self, on: bool):
        self._halo = bool(on)
        self._frames.clear()  # drawn the other way
        self.update()

    def _sync(self):
        if self._figure_at is None or not self._same(self._figure_at, self.value):
            self._draw(self.value)

    def _hand_out(self):
        """Code has the figure: from now on, put it back at the position shown before each cell runs."""
        if self._handed_out:
            return
        self._handed_out = True
        try:
            from IPython import get_ipython
        except ImportError:  # pragma: no cover - ipywidgets brings IPython
            return
        shell = get_ipython()
        if shell is None:
            return
        ref = weakref.ref(self)

        def before_cell(*_):
            ex = ref()
            if ex is None:
                shell.events.unregister("pre_run_cell", before_cell)
                return
            if threading.get_ident() == ex._home:  # a cell on a subshell's thread leaves it alone
                ex._sync()  # a job half way has left the figure at no position: drawn again

        shell.events.register("pre_run_cell", before_cell)

    def png(self) -> bytes:
        """The figure at :attr:`value` as PNG bytes (fast zlib setting)."""
        self._sync()
        return self._png()

    def _png(self) -> bytes:
        self._canvas.render()
        return self._canvas.encode()

    def _ipython_display_(self):
        from IPython.display import display

        display(self.widget)

