"""An interactive explorer for notebooks: move the crank (or slider), watch the forces.

:func:`explore` builds an :class:`Explorer`: a slider for the input position
(crank angle in whole degrees, or slider position in mm) with a numeric box
beside it, a speed input (rpm, or m/s for a slider driver), and one figure
that shows the mechanism, each moving link's free-body diagram, every force
polygon of the graphical construction and the driving torque (or force) over
the cycle with a marker at the current position. Moving the slider redraws
the position; changing the speed recomputes the torque curve (once per speed,
by :func:`graphkin.cycle.sweep.sweep`).

The figure is one persistent headless :class:`matplotlib.figure.Figure` whose
axes are cleared and redrawn on each update with the ``graphkin.draw``
functions, rendered to PNG bytes (Agg) into an ``ipywidgets.Image``. No
interactive matplotlib backend (ipympl) is needed.

What a person sees in a browser, and what code sees, agree:

* A value the kernel sets stands. It is snapped to the slider's step (whole
  degrees for a crank: an integer slider, which the browser never sends back
  changed), and a value the browser sends back late, from before the kernel
  set a newer one, is recognised and ignored (:meth:`Explorer.from_browser`).
* Values that arrive from the browser in a burst (key presses, a drag) are
  drawn once, at the latest value, after the burst settles (:data:`SETTLE`).
  Values set from code are drawn at once, so a cell can read the result.
* While the kernel is idle, the positions next to the one shown are drawn
  ahead (:data:`AHEAD` steps either side, the way the slider last moved
  first): an arrow key that reaches one shows that finished frame at once,
  well under a millisecond where drawing it takes 30–200 ms. The figure and
  the marker that code reads are always those of the position shown.
* The explorer belongs to the thread that made it (the kernel's main
  thread). A message from the browser that ipykernel hands to another
  thread (a subshell's) is answered on the explorer's own thread, never
  alongside what it draws there; an error in answering is shown in the
  status line.
* The figure is rendered for the screen: the browser reports its pixel ratio
  and the width it gives the explorer, and the PNG is drawn at
  ``CSS_DPI × pixel ratio`` (text of 8 pt is then at least 11 screen pixels
  high and sharp on a HiDPI screen), at most as wide as the page.

ipywidgets and matplotlib are imported here only, when an explorer is built:
``import graphkin`` does not load them.

Examples
--------
>>> from graphkin import catalog
>>> from graphkin.widgets import explore
>>> ex = explore(catalog.load("strip_cutter"))   # doctest: +SKIP
>>> ex                                            # in a notebook cell: the explorer  # doctest: +SKIP
>>> ex.slider.value = 140                         # θ12 = 140°: redraws  # doctest: +SKIP
>>> ex.analytical["T12"], ex.construction.effort  # doctest: +SKIP
"""

from __future__ import annotations

import collections
import contextlib
import dataclasses
import functools
import io
import json
import logging
import math
import threading
import time
import weakref

import numpy as np

from graphkin import exercises
from graphkin.analytical import solve_forces
from graphkin.cycle.sweep import Cycle, sweep
from graphkin.errors import GraphkinError
from graphkin.exercises.grading import grade_variant
from graphkin.graphical import construct_forces
from graphkin.notation import polar_text

_log = logging.getLogger(__name__)

NCOLS = 4
"""Panels per row of the explorer's figure."""

RC = {"text.hinting": "no_hinting"}
"""matplotlib settings while the explorer draws and renders."""

CELL_ASPECT = 0.9
"""Height of a panel over its width."""

CSS_DPI = 100.0
"""Screen (CSS) pixels per inch of the figure, at least: its smallest text (:data:`MIN_PT`) is then 11 px high."""

MIN_PT = 8.0
"""The smallest text in the explorer's figure [pt]."""

FIGURE_WIDTH = (8.0, 13.0)
"""Narrowest and widest figure [in]: between them it fills the width the page gives the explorer."""

PAGE_WIDTH = 1100.0
"""The width the explorer is given [CSS px] until a browser reports it (and where there is none)."""

SETTLE = 0.03
"""Seconds without a new value from the browser before it is drawn: a burst of key presses is drawn once."""

LIVE = 0.15
"""While values keep coming from the browser (a drag), one is drawn at least this often [s]."""

ECHOES = 64
"""Values set by the kernel that are remembered to recognise their late echoes."""

AHEAD = 2
"""Positions drawn ahead on either side of the one shown, while the kernel is idle (the way it moves first)."""

MOST_AHEAD = 8
"""The most positions drawn ahead on either side: more is idle work nobody waits for."""

IDLE = 0.05
"""Seconds without a new value before the explorer draws ahead, and between two frames drawn ahead."""

SHOWN = 0.5
"""Seconds after a new layout (the explorer shown, or the page's width or pixel ratio reported) before drawing ahead.

The page may still be settling (a second report of its width would throw the frames away), and a person
looks at the figure before pressing a key: a key pressed meanwhile is drawn, not kept waiting behind a frame
drawn ahead."""

STEP = 0.002
"""Seconds between two steps of a frame drawn ahead: the kernel reads what came meanwhile."""

FRAMES = 48
"""Finished frames kept while drawing ahead (least recently shown dropped first): 2–12 MB of PNG (the six-bar at
pixel ratio 2 the most), and at least every neighbour of the position shown (``2 × MOST_AHEAD + 1``)."""


@dataclasses.dataclass(frozen=True, slots=True)
class Frame:
    """One position, drawn: what the explorer's widgets show there.

    Attributes
    ----------
    value : float
        The position [deg or mm].
    png : bytes
        The figure.
    construction, analytical
        The graphical and the matrix solution (None where there is none).
    message : str
        Why there is no solution here ("" where there is one).
    status, table : str
        The HTML of the status line and of the force table.
    """

    value: float
    png: bytes
    construction: object
    analytical: object
    message: str
    status: str
    table: str


def explore(problem, *, n: int = 360, limits=None, dpi: int | None = None, halo: bool = False,
            ahead: int = AHEAD):
    """An interactive explorer of a problem, for a Jupyter notebook.

    Parameters
    ----------
    problem : graphkin.problem.Problem
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

    Returns
    -------
    Explorer
    """
    return Explorer(problem, n=n, limits=limits, dpi=dpi, halo=halo, ahead=ahead)


def _link_size(link) -> float:
    pts = np.array(list(link.points.values()), float).reshape(-1, 2)
    if len(pts) < 2:
        return 0.0
    return float(np.max(np.hypot(*(pts[:, None, :] - pts[None, :, :]).transpose(2, 0, 1))))


def _empty(ax):
    """Remove what was drawn on a panel: cheaper than ``ax.cla()``, which rebuilds the axis machinery."""
    for artist in list(ax._children):
        artist.remove()
    for title in (ax.title, ax._left_title, ax._right_title):
        title.set_text("")
    ax.ignore_existing_data_limits = True
    ax.dataLim.set_points(np.array([[np.inf, np.inf], [-np.inf, -np.inf]]))
    # Every drawing sets its panel's view itself: with autoscaling off, matplotlib neither keeps the
    # data limits (graphkin.draw.axes.follows_data) nor fits a view that is then replaced.
    ax.set_autoscale_on(False)


def _assembling_span(problem, q0: float, n: int) -> tuple[float, float]:
    """Where a slider-driven linkage assembles around q0 [m], with one step of margin (its dead ends included).

    Searched over q0 ± twice the total length of the moving links.
    """
    L = 2.0 * (sum(_link_size(link) for link in problem.mechanism.links if link.number != 1) or 0.5)
    q = np.linspace(q0 - L, q0 + L, 4 * n + 1)
    try:
        ok = np.flatnonzero(problem.kinematics(q).valid)
    except GraphkinError:
        ok = np.zeros(0, int)
    if not len(ok):
        return q0 - L / 2, q0 + L / 2
    step = q[1] - q[0]
    return float(q[ok[0]] - step), float(q[ok[-1]] + step)


def _nice_step(x: float) -> float:
    """The largest 1, 2 or 5 × 10^k not above ``x`` (a slider step a person reads at a glance)."""
    base = 10.0 ** math.floor(math.log10(x))
    for m in (5.0, 2.0, 1.0):
        if m * base <= x * (1 + 1e-9):
            return float(f"{m * base:.12g}")
    return float(f"{base:.12g}")  # pragma: no cover  (1 × base ≤ x always)


@functools.cache
def _degree_controls():
    """An integer slider and box whose value, set from code, is rounded to the nearest degree.

    ipywidgets' integer traits truncate (``int(139.9999)`` is 139); a crank
    angle computed in radians and converted must land on the nearest degree.
    The browser's integer slider rounds what it shows in the same way, so a
    value the kernel sets comes back unchanged and is never echoed.
    """
    import ipywidgets as W
    import traitlets

    class RoundedInt(traitlets.CInt):
        def validate(self, obj, value):
            if isinstance(value, (float, np.floating)) and math.isfinite(value):
                value = round(float(value))
            return super().validate(obj, value)

    class DegreeSlider(W.IntSlider):
        value = RoundedInt(0, help="Crank angle [deg]").tag(sync=True)

    class DegreeBox(W.BoundedIntText):
        value = RoundedInt(0, help="Crank angle [deg]").tag(sync=True)

    return DegreeSlider, DegreeBox


# A hidden image that fails to load runs its onerror handler, standard ipywidgets' only way to run
# a line of JavaScript: it writes the screen's pixel ratio and the width the page gives the explorer
# into the explorer's hidden text box, as if typed, and again when that width changes.
_PROBE = ("<img src='data:,' alt='' style='display:none' onerror=\"(function probe(img, tries) {"
          "var root = img.closest('.graphkin-explorer');"
          "var box = root && root.querySelector('.graphkin-screen input');"
          "if (!box || !root.parentElement) { if (tries < 100) setTimeout(probe, 100, img, tries + 1); return; }"
          "var host = root.parentElement;"
          "function report() {"
          "var width = Math.round(host.getBoundingClientRect().width);"
          "var said = JSON.stringify({ratio: window.devicePixelRatio || 1, width: width});"
          "if (width > 0 && box.value !== said) {"
          "box.value = said; box.dispatchEvent(new Event('input', {bubbles: true})); } }"
          "report();"
          "if (window.ResizeObserver) { var wait;"
          "new ResizeObserver(function () { clearTimeout(wait); wait = setTimeout(report, 250); }).observe(host); }"
          "})(this, 0)\">")


def _step(steps):
    """One step of a drawing (a generator), with the explorer's matplotlib settings around it only."""
    import matplotlib

    # Unhinted glyphs lay out and render about a quarter faster, and look the same at this size.
    with matplotlib.rc_context(RC):
        next(steps)


def _to_the_end(steps):
    """The rest of a drawing (a generator) at once, with the explorer's matplotlib settings; returns its frame."""
    import matplotlib

    with matplotlib.rc_context(RC):
        while True:
            try:
                next(steps)
            except StopIteration as done:
                return done.value


def _running_loop():
    """The event loop a kernel dispatches messages from, or None (plain Python, a test)."""
    import asyncio

    try:
        return asyncio.get_running_loop()
    except RuntimeError:
        return None


def _answers_the_browser(name: str, what: str):
    """Decorate the observer of the control ``name`` (``what`` it holds, for people).

    The observer is called as ``observer(self, change, by_browser)``, where
    ``by_browser`` tells a value the browser sent from one that code set
    (ipywidgets locks the property while it applies a browser's value: the lock
    is read here, while it is held).

    The explorer belongs to the thread it was made in, the kernel's main thread:
    its figure, its timers and its drawing ahead are never touched from two
    threads. ipykernel 7 may run a comm message's handler on another thread (a
    subshell's: a comm's messages go to the subshell that last sent on it),
    where it would close or step a drawing that the main thread is stepping. On
    another thread, the observer's work is handed to the main thread's event
    loop, and the handler returns at once.

    An error in answering the browser is shown in the status line: run from a
    comm message, outside any cell, it would otherwise reach only the kernel's
    log, and the explorer would silently stop answering. A value set by code
    on the explorer's own thread raises in the cell that set it.
    """

    def decorate(observer):
        @functools.wraps(observer)
        def observe(self, change):
            by_browser = "value" in getattr(self, name)._property_lock
            home = self._home_loop if threading.get_ident() != self._home else None
            if home is not None and home.is_running():
                home.call_soon_threadsafe(self._answer, observer, change, by_browser, what, True)
            else:
                self._answer(observer, change, by_browser, what, False)

        return observe

    return decorate


def _cell(v) -> str:
    """A force for the table, with a true minus: ``1972 N ∠ −73.78°`` (``0 N`` when there is none)."""
    return polar_text(v)


def _table(construction, analytical, where: str = "") -> str:
    """The joint forces and the driving effort at one position, both routes, as an HTML table.

    The explorer's force polygons carry names only: the numbers are here, where
    they can be read and copied (and a new value costs the figure no text to lay out).
    ``where`` (the position, e.g. ``"θ = 150°"``) heads the table, so that a copy
    of it says where it holds.
    """
    c, a = construction, analytical
    names = [n for n in (a.names() if a is not None else []) if n != c.driver_name]
    head = "".join(f"<th style='padding:0 8px'>{n[0]}<sub>{n[1:]}</sub></th>" for n in [*names, c.driver_name])
    unit = "N·m" if c.driver_name.startswith("T") else "N"
    rows = []
    for label, source in (("analytical", a), ("graphical", c)):
        if source is None:
            continue
        cells = [_cell(np.asarray(source[n], float).reshape(-1, 2)[0]) for n in names]
        effort = float(np.ravel(source.effort)[0])
        cells.append(f"{effort:.5g} {unit}".replace("-", "−"))
        rows.append(f"<tr><td style='padding:0 8px'><i>{label}</i></td>"
                    + "".join(f"<td style='padding:0 8px'>{x}</td>" for x in cells) + "</tr>")
    return (f"<table style='font-size:90%'><tr><th style='padding:0 8px;text-align:left'>{where}</th>{head}</tr>"
            f"{''.join(rows)}</table>")


class Explorer:
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
    analytical : ForceAnalysis
        The matrix solution at the same position (one position).
    cycle : Cycle
        The sweep behind the torque curve, at the current speed.
    marker : matplotlib.lines.Line2D
        The marker on the torque curve.
    pixel_ratio, page_width : float
        The screen's pixel ratio and the width the page gives the explorer [CSS px],
        as the browser last reported them (1 and :data:`PAGE_WIDTH` before it does).
    timings : list of float
        Seconds taken by each update (construction + redraw + PNG).
    """

    def __init__(self, problem, *, n: int = 360, limits=None, dpi: int | None = None, halo: bool = False,
                 ahead: int = AHEAD):
        import ipywidgets as W
        from matplotlib.figure import Figure

        from graphkin.draw._stamps import StampCanvas

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
        self._original = problem
        q_dot0 = float(problem.q_dot[0])
        # A problem that gives ω, α or a_G itself holds at its own speed only: the speed box is then fixed.
        self.problem = problem if problem.given else problem.at_speed(q_dot0)
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
        self._frames: collections.OrderedDict = collections.OrderedDict()  # position -> Frame, drawn
        self._figure_at = None  # the position the figure shows (None: none yet)
        self._heading = 1  # the way the slider last moved: +1 or -1
        self._ahead_handle = None  # the pending step of drawing ahead
        self._ahead_job = None  # (position, its drawing's steps) being drawn ahead
        self._new_layout = True  # no frame drawn ahead since the layout was made (see SHOWN)
        self._failed: set = set()  # positions whose drawing ahead failed (drawn when asked, the error shown then)
        self._handed_out = False  # code has taken the figure: it is put back before each cell runs
        self._home = threading.get_ident()  # the explorer's thread: everything it draws is drawn there
        self._home_loop = None  # that thread's event loop, once seen running (see _loop)

        q0 = float(problem.q[0])
        if self.crank:
            Slider, Box = _degree_controls()
            self.limits = (0.0, 360.0)
            self.step = 1.0
            self.value = float(round(math.degrees(q0) % 360.0))
            self.slider = Slider(value=self.value, min=0, max=360, step=1, description="θ (deg)")
            self.box = Box(value=self.value, min=0, max=360, step=1)
            self.speed = W.FloatText(value=round(q_dot0 * 30.0 / math.pi, 6), description="speed (rpm)")
        else:
            if limits is None:
                lo, hi = float(np.min(problem.q)), float(np.max(problem.q))
                if hi - lo < 1e-9:
                    lo, hi = _assembling_span(self.problem, q0, self.n)
                self.step = _nice_step((hi - lo) * 1e3 / self.n)
                # Rounded out to the step, the grid holds the round numbers (200 mm, −120 mm).
                lo = math.floor(round(lo * 1e3 / self.step, 6)) * self.step
                hi = math.ceil(round(hi * 1e3 / self.step, 6)) * self.step
            else:
                lo, hi = map(float, limits)
                if not hi > lo:
                    raise GraphkinError(f"limits must be (low, high) with high > low [mm], got {limits!r}")
                self.step = _nice_step((hi - lo) / self.n)
            self.limits = (float(f"{lo:.12g}"), float(f"{hi:.12g}"))
            self.value = self._snap(q0 * 1e3)
            self.slider = W.FloatSlider(value=self.value, min=self.limits[0], max=self.limits[1], step=self.step,
                                        description="s (mm)")
            self.box = W.BoundedFloatText(value=self.value, min=self.limits[0], max=self.limits[1], step=self.step)
            self.speed = W.FloatText(value=q_dot0, description="speed (m/s)")
        # The box beside the slider is the readout: large, and a person can type in it.
        self.slider.readout = False
        self.slider.continuous_update = True
        self.slider.layout = W.Layout(flex="1 1 auto", width="auto", min_width="60%")
        self.box.layout = W.Layout(width="7em")
        self.slider.style.description_width = "initial"
        self.speed.style.description_width = "initial"
        self.speed.layout = W.Layout(width="15em", flex="0 0 auto")
        self.speed.disabled = bool(problem.given)

        self._figure = Figure(dpi=self._dpi or CSS_DPI)
        StampCanvas(self._figure)  # each distinct label is rendered once, then pasted
        self.image = W.Image(format="png", layout=W.Layout(max_width="100%", height="auto"))
        self.status = W.HTML(layout=W.Layout(flex="1 1 auto"))
        self.table = W.HTML()
        self._screen = W.Text(layout=W.Layout(display="none"))
        probe = W.HTML(_PROBE, layout=W.Layout(display="none"))
        for widget, name in ((self.slider, "position"), (self.box, "position-box"), (self.speed, "speed"),
                             (self.status, "status"), (self.table, "table"), (self.image, "image"),
                             (self._screen, "screen")):
            widget.add_class(f"graphkin-{name}")  # for the browser test and for the probe
        self.widget = W.VBox([W.HBox([self.slider, self.box], layout=W.Layout(width="100%", align_items="center")),
                              W.HBox([self.speed, self.status], layout=W.Layout(width="100%", align_items="center")),
                              self.table, self.image, probe, self._screen])
        self.widget.add_class("graphkin-explorer")
        self._polygon_slots = 0
        self._layout(self._polygons_needed())
        self._sweep()
        self.slider.observe(self._on_slider, names="value")
        self.box.observe(self._on_box, names="value")
        self.speed.observe(self._on_speed, names="value")
        self._screen.observe(self._on_screen, names="value")
        self.update()

    # -- the thread ---------------------------------------------------------------
    def _loop(self):
        """The running event loop (None outside one: plain Python), remembered when it is the explorer's thread's."""
        loop = _running_loop()
        if loop is not None and threading.get_ident() == self._home:
            self._home_loop = loop
        return loop

    def _answer(self, observer, change, by_browser: bool, what: str, handed: bool):
        """Run an observer of a control (see :func:`_answers_the_browser`)."""
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
        self.status.value = f"<b>Could not draw {self.value:g}</b>{why}: {_escape(f'{type(exc).__name__}: {exc}')}"

    # -- the position -------------------------------------------------------------
    def _si(self, value: float) -> float:
        """A position in the slider's unit, in SI (rad or m)."""
        return math.radians(value) if self.crank else value * 1e-3

    def _q_dot(self) -> float:
        v = float(self.speed.value)
        return v * math.pi / 30.0 if self.crank else v

    def _snap(self, value: float) -> float:
        """``value`` on the slider's step, inside its range (whole degrees for a crank)."""
        lo, hi = self.limits
        value = min(max(float(value), lo), hi)
        k = round((value - lo) / self.step)
        return float(f"{min(lo + k * self.step, hi):.12g}")

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

    @_answers_the_browser("slider", "position")
    def _on_slider(self, change, by_browser: bool):
        if self._quiet:
            return
        # A person's move (or the browser's echo), or a value set by code.
        if by_browser:
            self.from_browser(change["new"])
        else:
            self._goto(change["new"])

    @_answers_the_browser("box", "position typed")
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
    @_answers_the_browser("_screen", "screen size")
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
        self._layout(self._polygon_slots)
        self._draw_curve()
        self._later()

    def _geometry(self) -> tuple[float, float, float]:
        """Figure width [in], screen pixels per inch of it, and the PNG's pixels per inch."""
        lo, hi = FIGURE_WIDTH
        width = min(hi, max(lo, self.page_width / CSS_DPI))
        css_dpi = max(CSS_DPI, min(self.page_width / width, 1.5 * CSS_DPI))
        if self._dpi:
            return width, css_dpi, float(self._dpi)
        dpi = round(css_dpi * self.pixel_ratio)  # whole: one PNG pixel per screen pixel exactly
        return width, dpi / self.pixel_ratio, float(dpi)

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
        from matplotlib.gridspec import GridSpec

        from graphkin.draw.axes import PanelAxes

        job = self._ahead_job
        if job is not None and not job[1].gi_running:
            self._abandon()  # it draws on the old axes (unless it is what needs the new layout)
            if self._ahead_handle is not None:
                self._ahead_handle.cancel()
                self._ahead_handle = None
        self._failed.clear()
        fig = self._figure
        fig.clear()
        self._frames.clear()  # drawn for the old layout
        self._figure_at = None
        self._new_layout = True
        moving = list(self.problem.mechanism.moving)
        fbd_rows = math.ceil(len(moving) / NCOLS)
        poly_rows = math.ceil(polygons / NCOLS)
        nrows = 1 + fbd_rows + poly_rows
        width, css_dpi, dpi = self._geometry()
        cell_h = CELL_ASPECT * width / NCOLS
        fig.set_size_inches(width, cell_h * nrows)
        fig.set_dpi(dpi)
        # Shown at css_dpi screen pixels per inch whatever the PNG's own resolution: sharp on a HiDPI screen.
        self.image.layout.width = f"{round(width * css_dpi)}px"
        gs = GridSpec(nrows, NCOLS, figure=fig, left=0.01, right=0.99, top=1 - 0.3 / (cell_h * nrows),
                      bottom=0.01, hspace=0.3, wspace=0.08)
        self.ax_mechanism = fig.add_subplot(gs[0, 0:2], axes_class=PanelAxes)
        self.ax_torque = fig.add_subplot(gs[0, 2:4])
        # Inside its cell with room for its tick labels, so the cell can be cached as pixels (see png()).
        cell = gs[0, 2:4].get_position(fig)
        w, h = fig.get_size_inches()
        # 0.8 in on the left: room for "−50000" and the axis label at 8-9 pt.
        self.ax_torque.set_position([cell.x0 + 0.8 / w, cell.y0 + 0.45 / h,
                                     cell.width - 0.9 / w, cell.height - 0.75 / h])
        self._torque_cell = cell
        self._background = None
        self.ax_fbd = {}
        for k, link in enumerate(moving):
            r, col = divmod(k, NCOLS)
            self.ax_fbd[link] = fig.add_subplot(gs[1 + r, col], axes_class=PanelAxes)
        self.ax_polygons = []
        for k in range(poly_rows * NCOLS):
            r, col = divmod(k, NCOLS)
            self.ax_polygons.append(fig.add_subplot(gs[1 + fbd_rows + r, col], axes_class=PanelAxes))
        self._polygon_slots = len(self.ax_polygons)
        self._panels = [self.ax_mechanism, *self.ax_fbd.values(), *self.ax_polygons]
        for ax in self._panels:
            ax.set_axis_off()
        # The torque curve's axes keep their position: no per-draw title layout.
        self.ax_torque._autotitlepos = False
        self.curve = None
        self._marker = None

    # -- the torque curve ---------------------------------------------------------
    def _sweep(self):
        """Solve the whole cycle at the current speed and draw the torque curve (once per speed)."""
        if not self._original.given:
            self.problem = self._original.at_speed(self._q_dot())
        if self.crank:
            self.cycle = sweep(self.problem, self.n)
        else:
            lo, hi = self.limits
            self.cycle = Cycle(self.problem, self.problem.solve(at=np.linspace(lo, hi, self.n) * 1e-3))
        self._draw_curve()

    def _draw_curve(self):
        self._background = None
        self._frames.clear()  # their marker sits on the old curve
        self._figure_at = None
        ax = self.ax_torque
        ax.cla()
        ax._autotitlepos = False
        x = np.degrees(self.cycle.q) if self.crank else self.cycle.q * 1e3
        y = np.where(self.cycle.valid, self.cycle.torque, np.nan)
        effort = self.problem.mechanism.driver
        name = effort.symbol  # T12, or T01 in a book that numbers the frame 0
        unit = "N·m" if self.crank else "N"
        speed = f"{self.speed.value:g} {'rpm' if self.crank else 'm/s'}"
        (self.curve,) = ax.plot(x, y, color="#0072B2", lw=1.4)
        (self._marker,) = ax.plot([np.nan], [np.nan], "o", color="#CC79A7", ms=7, zorder=5)
        ax.axhline(0.0, color="#999999", lw=0.6)
        ax.set_xlim(*self.limits)
        finite = y[np.isfinite(y)]
        if finite.size:
            from graphkin.draw.cycle import value_limits

            lo, hi = np.percentile(finite, [0.5, 99.5]) if finite.size > 20 else (finite.min(), finite.max())
            # A flat curve (a gear pair's steady torque) keeps a margin: not on the plot's edge, its marker whole.
            ylim = value_limits([lo, hi])
            ax.set_ylim(*ylim)
        ax.set_xlabel("θ (deg)" if self.crank else "s (mm)", fontsize=MIN_PT + 1, labelpad=1)
        ax.set_ylabel(f"{name} ({unit})", fontsize=MIN_PT + 1, labelpad=1)
        ax.tick_params(labelsize=MIN_PT, pad=1.5)
        ax.set_title(f"Driving {'torque' if self.crank else 'force'} {name} at {speed}", fontsize=MIN_PT + 2)
        # Fixed ticks: no locator runs on each render.
        ax.set_xticks(ax.get_xticks())
        ax.set_yticks(ax.get_yticks())
        ax.set_xlim(*self.limits)
        if finite.size:
            ax.set_ylim(*ylim)

    # -- the speed ------------------------------------------------------------------
    @_answers_the_browser("speed", "speed")
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
        return _to_the_end(self._drawing(value))

    def _drawing_ahead(self) -> bool:
        """Whether positions are drawn ahead: ``ahead`` > 0, in a running event loop (a kernel)."""
        return bool(self.ahead) and self._loop() is not None

    def _keep(self, frame: Frame) -> Frame:
        self._figure_at = frame.value
        if not self._drawing_ahead():
            return frame  # no frame is shown again: each position is drawn when asked, as it always was
        self._frames[frame.value] = frame
        self._frames.move_to_end(frame.value)
        while len(self._frames) > FRAMES:
            self._frames.popitem(last=False)
        return frame

    def _drawing(self, value: float):
        """Solve and draw the figure at ``value`` in steps (a generator: one panel, the rendering, the PNG each),
        keep the frame and return it (the widgets show what they showed).

        Drawn ahead, the kernel reads its messages between two steps (see :meth:`_draw_ahead`).
        """
        from graphkin import draw

        q = self._si(value)
        c = a = None
        message = ""
        try:
            kin = self.problem.kinematics(at=[q])
            c = construct_forces(kin, 0)

            a = solve_forces(kin)
        except GraphkinError as exc:
            message = str(exc)
        if c is not None and not c.valid:
            message = c.reason or "the linkage cannot be assembled here"
        polys = [s for s in c.steps if s.polygon] if (c is not None and c.valid) else []
        if len(polys) > self._polygon_slots:
            self._layout(len(polys))
            self._draw_curve()
        self._figure_at = None  # in between: asked for, the figure is drawn again
        for ax in self._panels:
            _empty(ax)
        here = f"{value:g}{'°' if self.crank else ' mm'}"
        yield
        if message:
            self.ax_mechanism.text(0.5, 0.5, f"No solution at {here}:\n{message}", ha="center", va="center",
                                   wrap=True, fontsize=10, color="#D55E00", transform=self.ax_mechanism.transAxes)
            self._marker.set_data([np.nan], [np.nan])
            status = f"<b>No solution at {here}</b>: {message}"
        else:
            draw.draw_mechanism(c, ax=self.ax_mechanism)
            yield
            for link, ax in self.ax_fbd.items():
                draw.draw_free_body(c, link, ax=ax)
                yield
            for step, ax in zip(polys, self.ax_polygons):
                draw.draw_force_polygon(step, scale=c.force_scale, ax=ax, driver_name=c.driver_name, values=False)
                yield
            effort = float(a.effort[0]) if a is not None else float(c.effort)
            self._marker.set_data([value], [effort])
            name = c.driver_name
            unit = "N·m" if self.crank else "N"
            warn = "".join(f"<br>warning: {w}" for w in c.warnings)
            status = (f"{here}: {name} = {effort:.5g} {unit} (analytical), "
                      f"{float(c.effort):.5g} {unit} (graphical){warn}")
        where = f"θ = {here}" if self.crank else f"s = {here}"
        table = _table(c, a, where) if not message else ""
        for ax in self._panels:
            ax._autotitlepos = False
            if not self._halo:
                for t in ax.texts:
                    if t.get_path_effects():
                        t.set_path_effects([])
        self._render()
        yield
        return self._keep(Frame(value, self._encode(), c, a, message, status, table))

    def _present(self, frame: Frame):
        """Show a drawn frame in the widgets."""
        self.construction, self.analytical, self.message = frame.construction, frame.analytical, frame.message
        self.status.value = frame.status
        self.table.value = frame.table
        self.image.value = frame.png

    # -- drawing ahead ----------------------------------------------------------------
    def _take(self, value: float):
        """A position from the browser: shown at once if it was drawn ahead, else drawn once the values settle."""
        frame = self._frames.get(value) if self._drawing_ahead() else None
        if frame is None and self._ahead_job is not None and self._same(self._ahead_job[0], value):
            frame = self._finish_ahead()  # being drawn ahead: its last steps now
        if frame is None:
            self._later()
            return
        self._cancel()  # a value still waiting is superseded by this one
        self._frames.move_to_end(frame.value)
        self._present(frame)
        if self._ahead_job is not None and self._ahead_job[0] not in self._neighbours():
            self._abandon()  # the neighbour of a position left behind
        self._plan_ahead()

    def _neighbours(self) -> list[float]:
        """The positions to draw ahead, nearest first, the way the slider last moved before the other."""
        out = []
        for k in range(1, self.ahead + 1):
            for way in (self._heading, -self._heading):
                v = self._snap(self.value + way * k * self.step)
                if not self._same(v, self.value) and v not in out:
                    out.append(v)
        return out

    def _plan_ahead(self):
        """Draw the neighbours once the kernel has been idle for :data:`IDLE` (:data:`SHOWN` after a new layout);
        in a running event loop only."""
        loop = self._loop()
        if loop is None or not self.ahead:
            return
        if self._ahead_handle is not None:
            self._ahead_handle.cancel()
        self._ahead_handle = loop.call_later(SHOWN if self._new_layout else IDLE, self._draw_ahead)

    def _draw_ahead(self):
        """One step of drawing a neighbour not drawn yet, then the loop back: a message that came meanwhile
        (a key press) is read before the next step, so the kernel is never busy drawing ahead for longer
        than a step (one panel, the rendering, or the PNG)."""
        self._ahead_handle = None
        if self._timer is not None:
            self._abandon()
            return  # a value from the browser is waiting: its drawing plans again
        if self._ahead_job is None:
            todo = [v for v in self._neighbours() if v not in self._frames and v not in self._failed]
            if not todo:
                return
            self._new_layout = False
            self._ahead_job = (todo[0], self._drawing(todo[0]))
        value, steps = self._ahead_job
        try:
            _step(steps)
        except StopIteration:
            self._ahead_job = None
        except Exception:  # noqa: BLE001 - drawn when it is asked for, and the error shown then
            _log.debug("drawing %g ahead failed", value, exc_info=True)
            self._failed.add(value)
            self._abandon()
        # A pause before the next step: a message passes through the kernel's queues in several turns of
        # the loop, and a new value must find it free.
        self._ahead_handle = self._loop().call_later(STEP if self._ahead_job else IDLE, self._draw_ahead)

    def _finish_ahead(self) -> Frame | None:
        """The frame being drawn ahead, drawn to its end now (None if it fails: it is drawn again when asked)."""
        _, steps = self._ahead_job
        self._ahead_job = None
        try:
            return _to_the_end(steps)
        except Exception:  # noqa: BLE001 - drawn again as asked, and the error shown then
            _log.debug("finishing %g, drawn ahead, failed", self.value, exc_info=True)
            self._figure_at = None
            return None

    def _abandon(self):
        """Stop drawing ahead (the figure is needed for something else; what was half drawn is drawn again)."""
        if self._ahead_job is not None:
            self._ahead_job[1].close()
            self._ahead_job = None
            self._figure_at = None

    # -- the figure -------------------------------------------------------------------
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
        return self._figure

    @property
    def marker(self):
        """The marker on the torque curve (matplotlib.lines.Line2D), at :attr:`value` (see :attr:`figure`)."""
        self._sync()
        self._hand_out()
        return self._marker

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
        self._render()
        return self._encode()

    def _render(self):
        """Render the figure into the canvas (Agg)."""
        from matplotlib.transforms import TransformedBbox

        canvas = self._figure.canvas
        fig, ax = self._figure, self.ax_torque
        # The torque curve changes only with the speed: its pixels are rendered once and pasted,
        # and only the marker is drawn on each update.
        if self._background is None:
            for panel in self._panels:
                panel.set_visible(False)
            self._marker.set_visible(False)
            canvas.draw()
            self._background = canvas.copy_from_bbox(TransformedBbox(self._torque_cell, fig.transFigure))
            self._marker.set_visible(True)
            for panel in self._panels:
                panel.set_visible(True)
        ax.set_visible(False)
        try:
            canvas.draw()
        finally:
            ax.set_visible(True)
        canvas.restore_region(self._background)
        ax.draw_artist(self._marker)

    def _encode(self) -> bytes:
        """The canvas as PNG bytes (fast zlib setting)."""
        from PIL import Image

        canvas = self._figure.canvas
        w, h = canvas.get_width_height(physical=True)
        # Line art on white has few colours: a 256-colour palette (octree, no dithering visible at
        # this size) makes a PNG a third the size, and quantising + encoding costs half of what
        # encoding the full-colour pixels did.
        image = Image.frombuffer("RGBA", (w, h), canvas.buffer_rgba(), "raw", "RGBA", 0, 1)
        buf = io.BytesIO()
        dpi = round(float(self._figure.dpi))  # in the file (pHYs), so what shows it can tell its resolution
        image.quantize(256, method=Image.Quantize.FASTOCTREE).save(buf, format="png", compress_level=1, dpi=(dpi, dpi))
        return buf.getvalue()

    def _ipython_display_(self):
        from IPython.display import display

        display(self.widget)


def exercise(name, student: str = "", *, secret: str = ""):
    """An exercise in a notebook: a box for the student id, their data, one text box per question, a Check button.

    Parameters
    ----------
    name : str or graphkin.exercises.Exercise
        A catalog exercise (``graphkin exercise list``) or an exercise file.
    student : str
        The student's id (they can also type it in the box).
    secret : str
        The course secret, if the teacher set one.

    Returns
    -------
    ExerciseBox
        Display it in a cell; ``box.answers`` (question id → text box), ``box.check()``
        and ``box.report`` (the last grading as plain data) are there for tests.
    """
    return ExerciseBox(exercises.load(name), student, secret)


class ExerciseBox:
    """The widgets of :func:`exercise`: the student types an id, reads their data, answers, and checks."""

    def __init__(self, exercise, student: str, secret: str):
        import ipywidgets as w

        self.exercise, self.secret, self.report = exercise, secret, None
        self.student = w.Text(value=student, description="Your id", placeholder="e.g. your student number")
        self.data = w.HTML()
        self.answers = {q.id: w.Text(description=q.id, placeholder=q.unit or "number",
                                     layout=w.Layout(width="60%"), style={"description_width": "80px"})
                        for q in exercise.questions}
        asks = [w.HTML(f"<b>{q.id}</b>: {_escape(q.ask)}") for q in exercise.questions]
        self.button = w.Button(description="Check", button_style="primary")
        self.feedback = w.HTML()
        self.button.on_click(lambda _: self.check())
        self.student.observe(lambda _: self._show_data(), names="value")
        rows = [x for pair in zip(asks, self.answers.values()) for x in pair]
        self.widget = w.VBox([w.HTML(f"<h4>{_escape(exercise.title)}</h4>"), self.student, self.data, *rows,
                              self.button, self.feedback])
        self._show_data()

    def _ipython_display_(self):
        from IPython.display import display

        display(self.widget)

    def _show_data(self):
        student = self.student.value.strip()
        if not student:
            self.data.value = "<i>Type your id to get your own data.</i>"
            return
        try:
            sheet = exercises.variant(self.exercise, student, self.secret).sheet()
        except GraphkinError as exc:
            self.data.value = f"<span style='color:#b00'>{_escape(str(exc))}</span>"
            return
        items = "".join(f"<li>{_escape(g['shown'])}" + (f" ({_escape(g['label'])})" if g["label"] else "")
                        for g in sheet["data"])
        self.data.value = f"<p>{_escape(sheet['intro'])}</p><p>Your data:</p><ul>{items}</ul>"

    def check(self) -> dict | None:
        """Grade what is in the boxes and show the feedback; returns the report (plain data)."""
        student = self.student.value.strip()
        if not student:
            self.feedback.value = "<span style='color:#b00'>Type your id first.</span>"
            return None
        variant = exercises.variant(self.exercise, student, self.secret)
        self.report = grade_variant(variant, {k: box.value for k, box in self.answers.items()})
        colour = {"correct": "#070", "slip": "#a60"}
        rows = "".join(f"<li><b>{q['id']}</b> <span style='color:{colour.get(q['verdict'], '#b00')}'>{q['verdict']}"
                       f"</span> ({q['score']:g}/{q['max']:g}): {_escape(q['feedback'])}</li>"
                       for q in self.report["questions"])
        self.feedback.value = f"<p>Score: {self.report['score']:g} / {self.report['max']:g}</p><ul>{rows}</ul>"
        return self.report


def _escape(text: str) -> str:
    import html

    return html.escape(text)
