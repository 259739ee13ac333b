"""An interactive explorer for notebooks: move the crank (or slider), watch the forces.

:func:`explore` builds an :class:`Explorer`: a slider for the input position
(crank angle in degrees, or slider position in mm), a speed input (rpm, or
m/s for a slider driver), and one figure that shows the mechanism, each moving
link's free-body diagram, every force polygon of the graphical construction
and the driving torque (or force) over the cycle with a marker at the current
position. Moving the slider redraws the position; changing the speed
recomputes the torque curve (once per speed, by :func:`graphkin.analysis.cycle.sweep`).

The figure is one persistent headless :class:`matplotlib.figure.Figure` whose
axes are cleared and redrawn on each update with the ``graphkin.draw``
functions, rendered to PNG bytes (Agg, small dpi) into an
``ipywidgets.Image``. No interactive matplotlib backend (ipympl) is needed.

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

import io
import math
import time

import numpy as np

from .errors import GraphkinError

NCOLS = 4
"""Panels per row of the explorer's figure."""

RC = {"text.hinting": "no_hinting"}
"""matplotlib settings while the explorer draws and renders."""

CELL = (3.0, 2.7)
"""Size of one panel [in]."""


def explore(problem, *, n: int = 360, limits=None, dpi: int = 72, halo: bool = False):
    """An interactive explorer of a problem, for a Jupyter notebook.

    Parameters
    ----------
    problem : graphkin.problem.Problem
    n : int
        Number of positions of the torque curve over the cycle (and steps of the slider).
    limits : (float, float), optional
        Slider range for a slider driver [mm]; by default the problem's own
        positions if they span a range, else its position ± the total length of
        its links. A crank always turns 0–360°.
    dpi : int
        Resolution of the rendered figure (small is fast).
    halo : bool
        Keep the white outline behind labels (legible over lines, but drawing
        outlined text costs about a third of the rendering time).

    Returns
    -------
    Explorer
    """
    return Explorer(problem, n=n, limits=limits, dpi=dpi, halo=halo)


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
    ax.set_autoscale_on(True)


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


def _cell(v) -> str:
    """A force for the table, with a true minus: ``1972 N ∠ −73.78°`` (``0 N`` when there is none)."""
    from .report import polar_text

    return polar_text(v).replace("-", "−") if np.any(v) else "0 N"


def _table(construction, analytical) -> str:
    """The joint forces and the driving effort at one position, both routes, as an HTML table.

    The explorer's force polygons carry names only: the numbers are here, where
    they can be read and copied (and a new value costs the figure no text to lay out).
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
    return (f"<table style='font-size:90%'><tr><th></th>{head}</tr>{''.join(rows)}</table>")


class Explorer:
    """The widgets and figure of :func:`explore`.

    Attributes
    ----------
    problem : Problem
        The problem at the current speed (the original's input rate replaced).
    slider : ipywidgets.FloatSlider
        Crank angle θ [deg] or slider position s [mm].
    speed : ipywidgets.FloatText
        Crank speed [rpm] or slider speed [m/s].
    figure : matplotlib.figure.Figure
    image : ipywidgets.Image
        The rendered figure (PNG).
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
    timings : list of float
        Seconds taken by each update (construction + redraw + PNG).
    """

    def __init__(self, problem, *, n: int = 360, limits=None, dpi: int = 72, halo: bool = False):
        import ipywidgets as W
        from matplotlib.figure import Figure

        from .draw._stamps import StampCanvas

        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 2:
            raise GraphkinError(f"n must be a whole number of positions ≥ 2, got {n!r}")
        self.n = int(n)
        self.halo = halo
        self.crank = problem.mechanism.driver.kind == "crank"
        self._original = problem
        q_dot0 = float(problem.q_dot[0])
        # A problem that gives ω, α or a_G itself holds at its own speed only: the speed box is then fixed.
        self.problem = problem if problem.given else problem.at_speed(q_dot0)
        self.timings: list[float] = []
        self.construction = None
        self.analytical = None
        self.message = ""

        q0 = float(problem.q[0])
        if self.crank:
            self.slider = W.FloatSlider(value=math.degrees(q0) % 360.0, min=0.0, max=360.0, step=360.0 / self.n,
                                        description="θ (deg)", continuous_update=True, readout_format=".1f")
            self.speed = W.FloatText(value=round(q_dot0 * 30.0 / math.pi, 6), description="speed (rpm)")
        else:
            if limits is None:
                lo, hi = float(np.min(problem.q)), float(np.max(problem.q))
                if hi - lo < 1e-9:
                    lo, hi = _assembling_span(self.problem, q0, self.n)
                lo, hi = lo * 1e3, hi * 1e3
            else:
                lo, hi = map(float, limits)
            self.limits = (lo, hi)
            self.slider = W.FloatSlider(value=q0 * 1e3, min=lo, max=hi, step=(hi - lo) / self.n,
                                        description="s (mm)", continuous_update=True, readout_format=".1f")
            self.speed = W.FloatText(value=q_dot0, description="speed (m/s)")
        if self.crank:
            self.limits = (0.0, 360.0)
        self.slider.style.description_width = "initial"
        self.speed.style.description_width = "initial"
        self.speed.disabled = bool(problem.given)

        self.figure = Figure(dpi=dpi)
        StampCanvas(self.figure)  # each distinct label is rendered once, then pasted
        self.image = W.Image(format="png")
        self.status = W.HTML()
        self.table = W.HTML()
        self.widget = W.VBox([W.HBox([self.slider, self.speed]), self.status, self.table, self.image])
        self._polygon_slots = 0
        self._layout(self._polygons_needed())
        self._sweep()
        self.slider.observe(self._on_position, names="value")
        self.speed.observe(self._on_speed, names="value")
        self.update()

    # -- the problem at the chosen speed ---------------------------------------
    def _si(self, value: float) -> float:
        """The slider's value in SI (rad or m)."""
        return math.radians(value) if self.crank else value * 1e-3

    def _q_dot(self) -> float:
        v = float(self.speed.value)
        return v * math.pi / 30.0 if self.crank else v

    # -- layout -----------------------------------------------------------------
    def _polygons_needed(self) -> int:
        """The most force polygons a construction draws, over a few positions of the range."""
        from .graphic import construct_forces

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

        from .draw._common import PanelAxes

        fig = self.figure
        fig.clear()
        moving = list(self.problem.mechanism.moving)
        fbd_rows = math.ceil(len(moving) / NCOLS)
        poly_rows = math.ceil(polygons / NCOLS)
        nrows = 1 + fbd_rows + poly_rows
        fig.set_size_inches(CELL[0] * NCOLS, CELL[1] * nrows)
        gs = GridSpec(nrows, NCOLS, figure=fig, left=0.01, right=0.99, top=1 - 0.3 / (CELL[1] * nrows),
                      bottom=0.01, hspace=0.3, wspace=0.08)
        self.ax_mechanism = fig.add_subplot(gs[0, 0:2], axes_class=PanelAxes)
        self.ax_torque = fig.add_subplot(gs[0, 2:4])
        # Inside its cell with room for its tick labels, so the cell can be cached as pixels (see png()).
        cell = gs[0, 2:4].get_position(fig)
        w, h = fig.get_size_inches()
        self.ax_torque.set_position([cell.x0 + 0.6 / w, cell.y0 + 0.45 / h, cell.width - 0.7 / w, cell.height - 0.75 / h])
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
        self.marker = None

    # -- the torque curve ---------------------------------------------------------
    def _sweep(self):
        """Solve the whole cycle at the current speed and draw the torque curve (once per speed)."""
        from .analysis.cycle import Cycle, sweep

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
        ax = self.ax_torque
        ax.cla()
        ax._autotitlepos = False
        x = np.degrees(self.cycle.q) if self.crank else self.cycle.q * 1e3
        y = np.where(self.cycle.valid, self.cycle.torque, np.nan)
        effort = self.problem.mechanism.driver
        name = f"T1{effort.link}" if self.crank else f"F1{effort.link}"
        unit = "N·m" if self.crank else "N"
        speed = f"{self.speed.value:g} {'rpm' if self.crank else 'm/s'}"
        (self.curve,) = ax.plot(x, y, color="#0072B2", lw=1.4)
        (self.marker,) = ax.plot([np.nan], [np.nan], "o", color="#CC79A7", ms=7, zorder=5)
        ax.axhline(0.0, color="#999999", lw=0.6)
        ax.set_xlim(*self.limits)
        finite = y[np.isfinite(y)]
        if finite.size:
            lo, hi = np.percentile(finite, [0.5, 99.5]) if finite.size > 20 else (finite.min(), finite.max())
            pad = 0.08 * max(hi - lo, 1e-9)
            ax.set_ylim(min(lo, 0.0) - pad, max(hi, 0.0) + pad)
        ax.set_xlabel("θ (deg)" if self.crank else "s (mm)", fontsize=8, labelpad=1)
        ax.set_ylabel(f"{name} ({unit})", fontsize=8, labelpad=1)
        ax.tick_params(labelsize=7, pad=1.5)
        ax.set_title(f"Driving {'torque' if self.crank else 'force'} {name} at {speed}", fontsize=9)
        # Fixed ticks: no locator runs on each render.
        ax.set_xticks(ax.get_xticks())
        ax.set_yticks(ax.get_yticks())
        ax.set_xlim(*self.limits)
        if finite.size:
            ax.set_ylim(min(lo, 0.0) - pad, max(hi, 0.0) + pad)

    # -- callbacks ------------------------------------------------------------------
    def _on_position(self, change):
        self.update()

    def _on_speed(self, change):
        try:
            self._sweep()
        except GraphkinError as exc:
            self.message = f"No torque curve at this speed: {exc}"
        self.update()

    # -- one update -----------------------------------------------------------------
    def update(self):
        """Solve and redraw at the slider's current value; returns the Construction drawn (None if none)."""
        import matplotlib

        # Unhinted glyphs lay out and render about a quarter faster, and look the same at this size.
        with matplotlib.rc_context(RC):
            return self._update()

    def _update(self):
        from . import draw
        from .graphic import construct_forces

        t0 = time.perf_counter()
        q = self._si(float(self.slider.value))
        c = a = None
        self.message = ""
        try:
            kin = self.problem.kinematics(at=[q])
            c = construct_forces(kin, 0)
            from .solve import solve_forces

            a = solve_forces(kin)
        except GraphkinError as exc:
            self.message = str(exc)
        if c is not None and not c.valid:
            self.message = c.reason or "the linkage cannot be assembled here"
        self.construction, self.analytical = c, a
        polys = [s for s in c.steps if s.polygon] if (c is not None and c.valid) else []
        if len(polys) > self._polygon_slots:
            self._layout(len(polys))
            self._draw_curve()
        for ax in self._panels:
            _empty(ax)
        here = f"{float(self.slider.value):.1f}{'°' if self.crank else ' mm'}"
        if self.message:
            self.ax_mechanism.text(0.5, 0.5, f"No solution at {here}:\n{self.message}", ha="center", va="center",
                                   wrap=True, fontsize=10, color="#D55E00", transform=self.ax_mechanism.transAxes)
            self.marker.set_data([np.nan], [np.nan])
            self.status.value = f"<b>No solution at {here}</b>: {self.message}"
        else:
            draw.draw_mechanism(c, ax=self.ax_mechanism)
            for link, ax in self.ax_fbd.items():
                draw.draw_free_body(c, link, ax=ax)
            for step, ax in zip(polys, self.ax_polygons):
                draw.draw_force_polygon(step, scale=c.force_scale, ax=ax, driver_name=c.driver_name, values=False)
            effort = float(a.effort[0]) if a is not None else float(c.effort)
            x = math.degrees(q) if self.crank else q * 1e3
            self.marker.set_data([x], [effort])
            name = c.driver_name
            unit = "N·m" if self.crank else "N"
            warn = "".join(f"<br>warning: {w}" for w in c.warnings)
            self.status.value = (f"{here}: {name} = {effort:.5g} {unit} (analytical), "
                                 f"{float(c.effort):.5g} {unit} (graphical){warn}")
        self.table.value = _table(c, a) if not self.message else ""
        for ax in self._panels:
            ax._autotitlepos = False
            if not self.halo:
                for t in ax.texts:
                    if t.get_path_effects():
                        t.set_path_effects([])
        self.image.value = self.png()
        self.timings.append(time.perf_counter() - t0)
        return c

    def png(self) -> bytes:
        """The figure as PNG bytes (fast zlib setting)."""
        from PIL import Image

        from matplotlib.transforms import TransformedBbox

        canvas = self.figure.canvas
        fig, ax = self.figure, self.ax_torque
        # The torque curve changes only with the speed: its pixels are rendered once and pasted,
        # and only the marker is drawn on each update.
        if self._background is None:
            for panel in self._panels:
                panel.set_visible(False)
            self.marker.set_visible(False)
            canvas.draw()
            self._background = canvas.copy_from_bbox(TransformedBbox(self._torque_cell, fig.transFigure))
            self.marker.set_visible(True)
            for panel in self._panels:
                panel.set_visible(True)
        ax.set_visible(False)
        try:
            canvas.draw()
        finally:
            ax.set_visible(True)
        canvas.restore_region(self._background)
        ax.draw_artist(self.marker)
        w, h = canvas.get_width_height(physical=True)
        # Line art on white has few colours: a 256-colour palette (octree, no dithering visible at
        # this size) makes a PNG a third the size, and quantising + encoding costs half of what
        # encoding the full-colour pixels did.
        image = Image.frombuffer("RGBA", (w, h), canvas.buffer_rgba(), "raw", "RGBA", 0, 1)
        buf = io.BytesIO()
        image.quantize(256, method=Image.Quantize.FASTOCTREE).save(buf, format="png", compress_level=1)
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
    from . import exercises

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
            sheet = self.exercise.variant(student, self.secret).sheet()
        except GraphkinError as exc:
            self.data.value = f"<span style='color:#b00'>{_escape(str(exc))}</span>"
            return
        items = "".join(f"<li>{_escape(g['shown'])}" + (f" ({_escape(g['label'])})" if g["label"] else "")
                        for g in sheet["data"])
        self.data.value = f"<p>{_escape(sheet['intro'])}</p><p>Your data:</p><ul>{items}</ul>"

    def check(self) -> dict | None:
        """Grade what is in the boxes and show the feedback; returns the report (plain data)."""
        from .exercises.grading import grade_variant

        student = self.student.value.strip()
        if not student:
            self.feedback.value = "<span style='color:#b00'>Type your id first.</span>"
            return None
        variant = self.exercise.variant(student, self.secret)
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
