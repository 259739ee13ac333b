"""The explorer's figure: its panels, the torque curve, a position drawn on it, the PNG; and the force table.

One persistent headless :class:`matplotlib.figure.Figure` (:class:`Canvas`)
holds a row with the mechanism and the driving torque (or force) over the
cycle, a row of free-body diagrams, and rows of slots for the force polygons.
At each position its panels are emptied and drawn again with the
``graphkin.draw`` functions, rendered (Agg) and encoded as PNG bytes; the
torque curve changes only with the speed, and its pixels are pasted.

The figure is sized for the screen (:func:`geometry`): as wide as the page
gives the explorer, between the :data:`FIGURE_WIDTH` limits, and drawn at
:data:`CSS_DPI` × the screen's pixel ratio, so that its smallest text
(:data:`MIN_PT`) is at least 11 screen pixels high and sharp on a HiDPI screen.

The numbers the force polygons leave out are in an HTML table (:func:`force_table`).

matplotlib and PIL are imported inside the functions that use them: importing
this module does not load them.
"""

from __future__ import annotations

import io
import math

import numpy as np

from graphkin.notation import polar_text

NCOLS = 4
"""Panels per row of the explorer's figure."""

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


def geometry(page_width: float, pixel_ratio: float, dpi: int | None = None) -> tuple[float, float, float]:
    """Figure width [in], screen pixels per inch of it, and the PNG's pixels per inch.

    Parameters
    ----------
    page_width : float
        The width the page gives the explorer [CSS px].
    pixel_ratio : float
        The screen's pixel ratio.
    dpi : int, optional
        A resolution fixed by the caller [pixels per inch of the figure]; by default the screen's.
    """
    lo, hi = FIGURE_WIDTH
    width = min(hi, max(lo, page_width / CSS_DPI))
    css_dpi = max(CSS_DPI, min(page_width / width, 1.5 * CSS_DPI))
    if dpi:
        return width, css_dpi, float(dpi)
    dpi = round(css_dpi * pixel_ratio)  # whole: one PNG pixel per screen pixel exactly
    return width, dpi / pixel_ratio, float(dpi)


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


class Canvas:
    """The explorer's figure and its panels.

    Parameters
    ----------
    dpi : int, optional
        Resolution of the PNG [pixels per inch of the figure], fixed; by
        default ``CSS_DPI`` times the screen's pixel ratio (see :meth:`layout`).

    Attributes
    ----------
    figure : matplotlib.figure.Figure
    ax_mechanism : matplotlib.axes.Axes
        The mechanism's panel.
    ax_torque : matplotlib.axes.Axes
        The driving torque (or force) over the cycle.
    ax_fbd : dict of int to matplotlib.axes.Axes
        The free-body diagram's panel of each moving link (by number).
    ax_polygons : list of matplotlib.axes.Axes
        The force polygons' panels (``polygon_slots`` of them, the unused left empty).
    ax_motion : list of matplotlib.axes.Axes
        The velocity and the acceleration polygon's panels (empty when the layout leaves them out).
    panels : list of matplotlib.axes.Axes
        The panels drawn again at each position: all but the torque curve's.
    curve, marker : matplotlib.lines.Line2D
        The torque curve and the marker on it (None between :meth:`layout` and :meth:`draw_curve`).
    torque_cell : matplotlib.transforms.Bbox
        The torque curve's cell of the grid [figure fraction]: its pixels are rendered once and pasted.
    background
        Those pixels (None until the next :meth:`render`).
    polygon_slots : int
    """

    def __init__(self, dpi: int | None = None):
        from matplotlib.figure import Figure

        from graphkin.draw.stamps import StampCanvas

        self.dpi = dpi
        self.figure = Figure(dpi=dpi or CSS_DPI)
        StampCanvas(self.figure)  # each distinct label is rendered once, then pasted
        self.polygon_slots = 0
        self.ax_motion = []

    def layout(self, moving, polygons: int, page_width: float, pixel_ratio: float, motion: bool = False) -> float:
        """(Re)create the persistent axes: mechanism and torque curve, free bodies, polygon slots.

        Parameters
        ----------
        moving : sequence of int
            The moving links, one free-body panel each.
        polygons : int
            Force polygons to make room for.
        page_width, pixel_ratio : float
            The width the page gives the explorer [CSS px] and the screen's pixel ratio (see :func:`geometry`).
        motion : bool
            Add a row for the velocity and acceleration polygons (two panels of two cells each).

        Returns
        -------
        float
            The width to show the PNG at [CSS px].
        """
        from matplotlib.gridspec import GridSpec

        from graphkin.draw.axes import PanelAxes

        fig = self.figure
        fig.clear()
        fbd_rows = math.ceil(len(moving) / NCOLS)
        poly_rows = math.ceil(polygons / NCOLS)
        motion_rows = 1 if motion else 0
        nrows = 1 + fbd_rows + poly_rows + motion_rows
        width, css_dpi, dpi = geometry(page_width, pixel_ratio, self.dpi)
        cell_h = CELL_ASPECT * width / NCOLS
        fig.set_size_inches(width, cell_h * nrows)
        fig.set_dpi(dpi)
        gs = GridSpec(nrows, NCOLS, figure=fig, left=0.01, right=0.99, top=1 - 0.3 / (cell_h * nrows),
                      bottom=0.01, hspace=0.3, wspace=0.08)
        self.ax_mechanism = fig.add_subplot(gs[0, 0:2], axes_class=PanelAxes)
        self.ax_torque = fig.add_subplot(gs[0, 2:4])
        # Inside its cell with room for its tick labels, so the cell can be cached as pixels (see render()).
        cell = gs[0, 2:4].get_position(fig)
        w, h = fig.get_size_inches()
        # 0.8 in on the left: room for "−50000" and the axis label at 8-9 pt.
        self.ax_torque.set_position([cell.x0 + 0.8 / w, cell.y0 + 0.45 / h,
                                     cell.width - 0.9 / w, cell.height - 0.75 / h])
        self.torque_cell = cell
        self.background = None
        self.ax_fbd = {}
        for k, link in enumerate(moving):
            r, col = divmod(k, NCOLS)
            self.ax_fbd[link] = fig.add_subplot(gs[1 + r, col], axes_class=PanelAxes)
        self.ax_polygons = []
        for k in range(poly_rows * NCOLS):
            r, col = divmod(k, NCOLS)
            self.ax_polygons.append(fig.add_subplot(gs[1 + fbd_rows + r, col], axes_class=PanelAxes))
        self.polygon_slots = len(self.ax_polygons)
        row = 1 + fbd_rows + poly_rows
        self.ax_motion = [fig.add_subplot(gs[row, 0:2], axes_class=PanelAxes),
                          fig.add_subplot(gs[row, 2:4], axes_class=PanelAxes)] if motion else []
        self.panels = [self.ax_mechanism, *self.ax_fbd.values(), *self.ax_polygons, *self.ax_motion]
        for ax in self.panels:
            ax.set_axis_off()
        # The torque curve's axes keep their position: no per-draw title layout.
        self.ax_torque._autotitlepos = False
        self.curve = None
        self.marker = None
        # Shown at css_dpi screen pixels per inch whatever the PNG's own resolution: sharp on a HiDPI screen.
        return width * css_dpi

    def draw_curve(self, x, y, limits, *, xlabel: str, ylabel: str, title: str):
        """Draw the torque (or force) curve, and a marker on it at no position yet.

        Parameters
        ----------
        x, y : numpy.ndarray
            The positions [deg or mm] and the driving effort there [N·m or N]; NaN where there is none.
        limits : (float, float)
            The positions' range [deg or mm].
        xlabel, ylabel, title : str
        """
        self.background = None
        ax = self.ax_torque
        ax.cla()
        ax._autotitlepos = False
        (self.curve,) = ax.plot(x, y, color="#0072B2", lw=1.4)
        (self.marker,) = ax.plot([np.nan], [np.nan], "o", color="#CC79A7", ms=7, zorder=5)
        ax.axhline(0.0, color="#999999", lw=0.6)
        ax.set_xlim(*limits)
        finite = y[np.isfinite(y)]
        if finite.size:
            from graphkin.draw.cycle import value_limits

            lo, hi = np.percentile(finite, [0.5, 99.5]) if finite.size > 20 else (finite.min(), finite.max())
            # A flat curve (a gear pair's steady torque) keeps a margin: not on the plot's edge, its marker whole.
            ylim = value_limits([lo, hi])
            ax.set_ylim(*ylim)
        ax.set_xlabel(xlabel, fontsize=MIN_PT + 1, labelpad=1)
        ax.set_ylabel(ylabel, fontsize=MIN_PT + 1, labelpad=1)
        ax.tick_params(labelsize=MIN_PT, pad=1.5)
        ax.set_title(title, fontsize=MIN_PT + 2)
        # Fixed ticks: no locator runs on each render.
        ax.set_xticks(ax.get_xticks())
        ax.set_yticks(ax.get_yticks())
        ax.set_xlim(*limits)
        if finite.size:
            ax.set_ylim(*ylim)

    def drawing(self, construction, polygons, marker: tuple[float, float], message: str = "", halo: bool = False,
                motion=None):
        """Draw a position on the panels and render the figure, in steps (a generator: one panel, or the rendering,
        each); the PNG is then :meth:`encode`'s.

        Parameters
        ----------
        construction : graphkin.graphical.Construction
            The graphical solution to draw (not read when there is a ``message``).
        polygons : list of graphkin.graphical.Step
            Its steps that draw a force polygon, one slot each.
        marker : (float, float)
            Where the marker sits on the torque curve: the position [deg or mm] and the effort [N·m or N].
        message : str
            Why there is no solution here, said in the mechanism's panel instead ("" where there is one).
        halo : bool
            Keep the white outline behind labels.
        motion : graphkin.graphical.MotionConstruction, optional
            The velocity and acceleration polygons to draw in :attr:`ax_motion` (laid out with ``motion=True``);
            one that is not valid says why instead.
        """
        from graphkin import draw

        c = construction
        for ax in self.panels:
            _empty(ax)
        yield
        if message:
            self.ax_mechanism.text(0.5, 0.5, message, ha="center", va="center",
                                   wrap=True, fontsize=10, color="#D55E00", transform=self.ax_mechanism.transAxes)
            self.marker.set_data([marker[0]], [marker[1]])
        else:
            draw.draw_mechanism(c, ax=self.ax_mechanism)
            yield
            for link, ax in self.ax_fbd.items():
                draw.draw_free_body(c, link, ax=ax)
                yield
            for step, ax in zip(polygons, self.ax_polygons):
                draw.draw_force_polygon(step, scale=c.force_scale, ax=ax, driver_name=c.driver_name, values=False)
                yield
            if motion is not None and self.ax_motion:
                if motion.valid:
                    for polygon, ax in zip(("velocity", "acceleration"), self.ax_motion):
                        draw.draw_motion_polygon(motion, polygon, ax=ax, values=False)
                        yield
                else:
                    self.ax_motion[0].text(0.5, 0.5, f"No polygons here: {motion.reason}", ha="center", va="center",
                                           wrap=True, fontsize=MIN_PT + 1, color="#D55E00",
                                           transform=self.ax_motion[0].transAxes)
            self.marker.set_data([marker[0]], [marker[1]])
        for ax in self.panels:
            ax._autotitlepos = False
            if not halo:
                for t in ax.texts:
                    if t.get_path_effects():
                        t.set_path_effects([])
        self.render()
        yield

    def render(self):
        """Render the figure into the canvas (Agg)."""
        from matplotlib.transforms import TransformedBbox

        canvas = self.figure.canvas
        fig, ax = self.figure, self.ax_torque
        # The torque curve changes only with the speed: its pixels are rendered once and pasted,
        # and only the marker is drawn on each update.
        if self.background is None:
            for panel in self.panels:
                panel.set_visible(False)
            self.marker.set_visible(False)
            canvas.draw()
            self.background = canvas.copy_from_bbox(TransformedBbox(self.torque_cell, fig.transFigure))
            self.marker.set_visible(True)
            for panel in self.panels:
                panel.set_visible(True)
        ax.set_visible(False)
        try:
            canvas.draw()
        finally:
            ax.set_visible(True)
        canvas.restore_region(self.background)
        ax.draw_artist(self.marker)

    def encode(self) -> bytes:
        """The canvas as PNG bytes (fast zlib setting)."""
        from PIL import Image

        canvas = self.figure.canvas
        w, h = canvas.get_width_height(physical=True)
        # Line art on white has few colours: a 256-colour palette (octree, no dithering visible at
        # this size) makes a PNG a third the size, and quantising + encoding costs half of what
        # encoding the full-colour pixels did.
        image = Image.frombuffer("RGBA", (w, h), canvas.buffer_rgba(), "raw", "RGBA", 0, 1)
        buf = io.BytesIO()
        dpi = round(float(self.figure.dpi))  # in the file (pHYs), so what shows it can tell its resolution
        image.quantize(256, method=Image.Quantize.FASTOCTREE).save(buf, format="png", compress_level=1, dpi=(dpi, dpi))
        return buf.getvalue()


def _cell(v) -> str:
    """A force for the table, with a true minus: ``1972 N ∠ −73.78°`` (``0 N`` when there is none)."""
    return polar_text(v)


def force_table(construction, analytical, where: str = "") -> str:
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
