"""Drawings printed at a stated scale: the free bodies at one force scale, the force polygons at one scale, a
construction step beside its polygon; each figure sized so that it prints at the scales it states.

A handout places these figures at their own size (never scaled to a share of the text width), so a length
measured on the printed page with a ruler is the length the scale says: a true length of k mm prints 1 mm
long at 1:k, and a force of X N prints 1 mm long at 1 mm = X N. Each figure ends with a scale bar for each of
its scales, each stating its scale beside it (:func:`scale_strip`).

Panels at the mechanism's scale (free bodies, lines of action) are drawn first, each on an axes of its own with
its labels left unplaced, then laid out in rows (:func:`arrange`) and given their printed size, and only then
are the labels placed: where a label goes depends on how large the drawing prints. Polygons (of forces, of
velocities and accelerations) are drawn in millimetres of paper already, so their size is known before they are
drawn: their panels are laid out first (:func:`layout`), then each polygon is drawn from its place on one axes
over the whole figure, and its labels are placed in its panel's box.
"""

from __future__ import annotations

import numpy as np
from matplotlib import rcParams
from matplotlib.figure import Figure
from matplotlib.transforms import Affine2D

from graphkin.draw import style as _style
from graphkin.draw.axes import BareAxes, setup_axes
from graphkin.draw.fbd import draw_free_body
from graphkin.draw.labels import ASTRAY_COST, _offset, measuring_renderer
from graphkin.draw.mechanism import draw_mechanism
from graphkin.draw.motion import draw_motion_polygon, motion_extent
from graphkin.draw.polygon import draw_force_polygon, polygon_vertices, step_title
from graphkin.draw.scales import nice_round, scale_bar
from graphkin.draw.steps import draw_step_geometry
from graphkin.draw.text import sub, text_extent
from graphkin.graphical.paper import FIGURE_WIDTH, force_text, length_text
from graphkin.notation import num

GAP = 5.0
"""Room between two panels of a figure [mm]."""
STRIP = 9.0
"""Height of the strip of scale bars under a figure [mm]."""


def _new_figure(width: float) -> Figure:
    # 100 dpi, as every drawing of this package: the labels' sizes are measured at it.
    return Figure(figsize=(width / 25.4, 100 / 25.4), dpi=100)


def _box(ax, mm_per_unit: float) -> tuple[float, float]:
    """Width and height [mm] the axes take on paper at ``mm_per_unit``."""
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    return abs(x1 - x0) * mm_per_unit, abs(y1 - y0) * mm_per_unit


def _title_size(t) -> tuple[float, float]:
    """Width and height [mm] a panel's title takes as printed, with the room under it (0, 0 without one)."""
    if not t.get_text().strip():
        return 0.0, 0.0
    fig = t.get_figure(root=True)
    bb = text_extent(t, measuring_renderer(fig))
    return bb.width / fig.dpi * 25.4, bb.height / fig.dpi * 25.4 + 1.5


def layout(sizes, *, width: float = FIGURE_WIDTH, strip: float = 0.0, gap: float = GAP):
    """Where panels go in rows: as many as fit the width in each row, each row centred, each panel below its title.

    Parameters
    ----------
    sizes : list of (float, float, float, float)
        Each panel's width and height [mm], and the width and height it takes with its title over it.
    width : float
        The figure's width [mm].
    strip : float
        Height [mm] left free under the rows (for :func:`scale_strip`).

    Returns
    -------
    height : float
        The figure's height [mm].
    boxes : list of (float, float)
        The lower left corner [mm from the figure's lower left] of each panel (without its title).
    """
    rows, row, used = [], [], 0.0
    for k, (_, _, pw, _) in enumerate(sizes):
        if row and used + gap + pw > width:
            rows.append(row)
            row, used = [], 0.0
        used += (gap if row else 0.0) + pw
        row.append(k)
    if row:
        rows.append(row)
    heights = [max(sizes[k][3] for k in r) for r in rows]
    height = sum(heights) + gap * (len(rows) - 1) + strip + 2.0
    corners = [(0.0, 0.0)] * len(sizes)
    top = height - 1.0
    for r, rh in zip(rows, heights):
        used = sum(sizes[k][2] for k in r) + gap * (len(r) - 1)
        x = max(0.0, (width - used) / 2)
        for k in r:
            w, h, pw, ph = sizes[k]
            # Below its title, centred in its column; the tallest panel of the row sets the row's height.
            corners[k] = (x + (pw - w) / 2, top - (ph - h) - h)
            x += pw + gap
        top -= rh + gap
    return height, corners


def arrange(fig, panels, *, width: float = FIGURE_WIDTH, strip: float = 0.0, gap: float = GAP,
            fenced: bool = False) -> float:
    """Lay panels out in rows at their printed size (:func:`layout`), size the figure to them, and place their
    labels.

    Parameters
    ----------
    fig : Figure
    panels : list of (Axes, float)
        Each axes, its limits final, and the millimetres of paper per data unit it prints at.
    width : float
        The figure's width [mm]; a row holds the panels that fit it, each row centred.
    strip : float
        Height [mm] left free under the rows (for :func:`scale_strip`).
    fenced : bool
        A label with no clean spot in its panel may stand in the figure's free space beside it, off the other
        panels, their titles and the strip (:attr:`graphkin.draw.labels.Labeler.fence`), as a polygon's may.

    Returns
    -------
    float
        The figure's height [mm].
    """
    sizes = []
    for ax, mm in panels:
        w, h = _box(ax, mm)
        tw, th = _title_size(ax.title)
        sizes.append((w, h, max(w, tw), h + th))
    height, corners = layout(sizes, width=width, strip=strip, gap=gap)
    fig.set_size_inches(width / 25.4, height / 25.4)
    for (ax, _), (x, y), (w, h, _, _) in zip(panels, corners, sizes):
        ax.set_position([x / width, y / height, w / width, h / height])
    renderer = measuring_renderer(fig)
    taken = [tuple(text_extent(ax.title, renderer).extents) for ax, _ in panels if ax.title.get_text().strip()]
    for ax, _ in panels:
        lab = getattr(ax, "_graphkin_labeler", None)
        if lab is not None and fenced:
            # The other panels and the strip, in this panel's data units.
            back = ax.transData.inverted().transform
            px = fig.dpi / 25.4
            boxes = [other.get_position().transformed(fig.transFigure).extents for other, _ in panels
                     if other is not ax] + [np.array([0.0, 0.0, width * px, strip * px])]
            lab.fence = [tuple(back(np.reshape(b, (2, 2))).ravel()) for b in boxes]
            lab.taken = [b for b in taken if tuple(b) != tuple(text_extent(ax.title, renderer).extents)]
            lab.room = tuple(back(ax.bbox.extents.reshape(2, 2)).ravel())
        if lab is not None:
            lab.place()
            if fenced:
                taken += lab.placed  # the panels placed after keep off its labels
            drawn = getattr(ax, "_graphkin_drawn", None)
            if drawn is not None:
                drawn += lab.leaders
    return height


def scale_strip(fig, height: float, *, length_scale=None, force_scale=None, width: float = FIGURE_WIDTH,
                velocity_scale=None, acceleration_scale=None, ax=None, **style) -> list:
    """Scale bars along the foot of a figure: one per scale the figure is drawn at, each stating its scale.

    A length bar reads ``0 — 100 mm  (scale 1:5)``, a force bar ``0 — 400 N  (1 mm = 20 N)``, a velocity bar
    ``0 — 2 m/s  (1 mm = 0.05 m/s)`` (``velocity_scale`` [m/s per mm]; ``acceleration_scale`` [m/s² per mm]
    likewise); each is as long on paper as what it reads at its scale. ``ax``: an axes over the whole figure
    whose data units are millimetres of paper, to draw the bars on; by default they go on the figure's first
    panel, placed in millimetres of paper from the figure's lower left (``height`` [mm] is the figure's).
    Returns the artists.
    """
    s = _style.resolve(**style)
    paper = None
    if ax is None and fig.axes:
        # No axes of their own (making one cost as much as drawing the bars): the strip's artists belong to a panel
        # but stand in millimetres of paper, outside it.
        ax, paper = fig.axes[0], Affine2D().scale(1 / 25.4) + fig.dpi_scale_trans
    elif ax is None:
        ax = fig.add_axes([0, 0, 1, 1], axes_class=BareAxes)
        setup_axes(ax)
        ax.set_xlim(0, width)
        ax.set_ylim(0, height)
    y = 0.5 + (STRIP - 1.0) / 2
    scales = [(k, X, unit) for k, X, unit in ((length_scale, None, "mm"), (None, force_scale, "N"),
                                              (None, velocity_scale, "m/s"), (None, acceleration_scale, "m/s²"))
              if k is not None or X is not None]
    # Each bar about 30 mm long; where the bars and their readings do not fit the width so, shorter bars.
    for reach in (30.0, 20.0):
        out, fits = _bars(ax, scales, reach, y, s, paper, width)
        if fits:
            return out
        for artist in out:
            artist.remove()
    return _bars(ax, scales, 12.0, y, s, paper, width)[0]


STRIP_GAP = 5.0
"""The least room [mm] between a bar's reading and the next bar's "0" in a strip of scale bars."""


def _bars(ax, scales, reach: float, y: float, s, paper, width: float) -> tuple[list, bool]:
    """The bars of :func:`scale_strip`, each about ``reach`` [mm] long, from the left, 12 mm apart, the last moved
    left (down to :data:`STRIP_GAP` from the one before) where its reading would run past the figure's edge.
    Returns the artists and whether every reading ends within the figure."""
    out, x, least, fits = [], 4.0, 4.0, True
    for k, X, unit in scales:
        if k is not None:
            value = nice_round(reach * k)
            length, note = value / k, f"scale {length_text(k)}"
        else:
            value = nice_round(reach * X)
            length, note = value / X, force_text(X) if unit == "N" else f"1 mm = {num(X, 4)} {unit}"
        bar = scale_bar(ax, (x, y), length, value, s=s, unit_text=unit, tick=1.0, note=note, transform=paper)
        over = _right(bar[-1]) - (width - 1.0)
        if over > 0:
            # Its reading would run past the figure's edge (and the page's margin): the bar moves left to fit, but
            # not onto the reading before it.
            fits = over <= x - least
            for artist in bar:
                artist.remove()
            bar = scale_bar(ax, (max(x - over, least), y), length, value, s=s, unit_text=unit, tick=1.0, note=note,
                            transform=paper)
        out += bar
        x = _right(bar[-1]) + 12.0
        least = _right(bar[-1]) + STRIP_GAP + 3.0  # the next bar's "0" stands 3 mm left of its start
    return out, fits


def _right(text) -> float:
    """Where a text of a figure ends [mm from the figure's left edge]."""
    fig = text.get_figure(root=True)
    return text_extent(text, measuring_renderer(fig)).x1 / fig.dpi * 25.4


def _names(text: str) -> str:
    """A title with every force or point name in it subscripted (``R3 = R3i + Fc3`` → R₃ = R₃ᵢ + F_c3)."""
    return " ".join(sub(word) for word in text.split(" "))


def draw_free_bodies(construction, links=None, *, length_scale: float, force_scale: float, unknowns=True,
                     width: float = FIGURE_WIDTH, enlarged=None, **style) -> Figure:
    """Every free body of ``links`` at one length scale and one force scale, side by side, printed at them.

    Parameters
    ----------
    construction : graphkin.graphical.Construction
    links : sequence of int, optional
        Default: every moving link.
    length_scale : float
        k: the links are printed at 1:k.
    force_scale : float
        X: every force is printed 1 mm long per X N, on every free body alike.
    unknowns : bool
        Draw the joint forces and the driver's effort (False: only the known loads, for a worksheet).
    width : float
        The figure's width [mm].
    enlarged : dict of int to float, optional
        A link drawn at a length scale of its own, k (a crank too short to read beside a long rod): its title and a
        length bar under it state its scale.

    Returns
    -------
    Figure
        Sized to print at the scales; its scale bars state them.
    """
    c = construction
    links = list(c.mechanism.moving if links is None else links)
    enlarged = enlarged or {}
    s = _style.resolve(**style)
    fig = _new_figure(width)
    panels = []
    for link in links:
        k = enlarged.get(link, length_scale)
        ax = fig.add_axes([0, 0, 0.2, 0.2], axes_class=BareAxes)
        title = c.mechanism.link(link).label + (f", {length_text(k)}" if link in enlarged else "")
        # In the drawing's units (mm of the mechanism), X N per printed mm is X / k N per mm drawn.
        drawn = draw_free_body(c, link, ax=ax, force_scale=force_scale / k, title=title, unknowns=unknowns,
                               paper=1.0 / k, bar=False, place=False, **style)
        if link in enlarged:
            _own_length_bar(ax, drawn, k, s)
        panels.append((ax, 1.0 / k))
    height = arrange(fig, panels, width=width, strip=STRIP, fenced=True)
    scale_strip(fig, height, length_scale=length_scale, force_scale=force_scale, width=width, **style)
    return fig


def _own_length_bar(ax, drawn, k: float, s) -> None:
    """A length bar under a panel drawn at a scale of its own (about 15 mm on paper), reading its scale."""
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    value = nice_round(15.0 * k)
    note = length_text(k)
    at = (x0 + 3.0 * k, y0 - 6.0 * k)
    drawn += scale_bar(ax, at, value, value, s=s, unit_text="mm", tick=1.0 * k, note=note,
                       labeler=getattr(drawn, "labeler", None))
    # Room in the panel for the bar and its reading (about 1.8 mm a character at its size), so that the reading
    # keeps off the next panel.
    reading = len(f"{num(value)} mm   ({note})")
    ax.set_xlim(x0, max(x1, at[0] + value + (3.0 + 1.8 * reading) * k))
    ax.set_ylim(y0 - 10.0 * k, y1)


def _one_axes(fig):
    """An axes over the whole figure whose data units are millimetres of paper, for panels drawn at their printed
    size (:func:`_lay_out_on`): one axes rather than one per panel, which cost as much again as drawing a polygon."""
    ax = fig.add_axes([0, 0, 1, 1], axes_class=BareAxes)
    setup_axes(ax)
    return ax


def _lay_out_on(ax, extents, titles, s, *, width: float, strip: float) -> tuple[float, list]:
    """Lay out panels drawn on one axes in millimetres of paper (:func:`_one_axes`), each under its title.

    Parameters
    ----------
    extents : list of (ndarray, ndarray)
        Each panel's lower left and upper right corners [mm] as drawn from the origin, its margins included.
    titles : list of str
    s : graphkin.draw.style.Style

    Returns
    -------
    height : float
        The figure's height [mm]; the figure and the view are sized to it.
    panels : list of (ndarray, tuple, Text)
        For each panel, the origin to draw it from, its box (x0, y0, x1, y1) [mm] for its labels
        (:attr:`graphkin.draw.labels.Labeler.room`), and its title.
    """
    fig = ax.get_figure(root=True)
    texts, sizes = [], []
    for (lo, hi), title in zip(extents, titles):
        w, h = np.asarray(hi, float) - lo
        # The title as set_title places it: centred 6 pt over the panel, on its baseline.
        t = ax.text(0.0, 0.0, title, fontsize=s.title_size, color=s.ink, ha="center", va="baseline", clip_on=False)
        tw, th = _title_size(t)
        texts.append(t)
        sizes.append((float(w), float(h), max(float(w), tw), float(h) + th))
    height, corners = layout(sizes, width=width, strip=strip)
    fig.set_size_inches(width / 25.4, height / 25.4)
    ax.set_xlim(0.0, width)
    ax.set_ylim(0.0, height)
    panels = []
    for t, (x, y), (w, h, _, _), (lo, _) in zip(texts, corners, sizes, extents):
        t.set_position((x + w / 2, y + h))
        t.set_transform(_offset(ax, (0.0, rcParams["axes.titlepad"])))
        panels.append((np.array([x, y]) - lo, (x, y, x + w, y + h), t))
    return height, panels


def _place_on(ax, drawings, width: float, height: float, reserved=None):
    """Place the labels of panels drawn on one axes (:func:`_lay_out_on`), once they are all drawn.

    ``drawings`` holds each panel's Drawn, its box and its title. Each panel's labels keep to its box, off every
    title and off the labels placed before them (a label may leave its panel when there is no room in it), and off
    the box ``reserved`` holds for the panel, if any (a column kept for its table, :func:`draw_motion_paper`).
    """
    reserved = reserved or [None] * len(drawings)
    # Each drawing merged its limits into the view: the figure's own are the view.
    ax.set_xlim(0.0, width)
    ax.set_ylim(0.0, height)
    renderer = measuring_renderer(ax.get_figure(root=True))
    taken = [tuple(text_extent(title, renderer).extents) for _, _, title in drawings]
    for (drawn, room, _), column in zip(drawings, reserved):
        lab = drawn.labeler
        lab.room = room
        # The other panels and the scale strip under them: a label may use the figure's free space, not theirs.
        lab.fence = [r for _, r, _ in drawings if r is not room] + [(0.0, 0.0, width, STRIP)]
        if column is not None:
            lab.fence.append(column)
        lab.taken = list(taken)
        lab.place()
        drawn += lab.leaders
        taken += lab.placed


def draw_polygons(steps, *, force_scale: float, titles=None, driver_name=None, width: float = FIGURE_WIDTH,
                  **style) -> Figure:
    """Force polygons at one force scale, side by side, printed at it.

    Parameters
    ----------
    steps : sequence of graphkin.graphical.Step
        Steps with a polygon.
    force_scale : float
        X: 1 mm of every polygon is X N.
    titles : sequence of str, optional
        Each polygon's title (default: its equation, :func:`graphkin.draw.polygon.step_title`).
    driver_name : str, optional
        The driving effort's name, drawn in the driver's colour.
    width : float
        The figure's width [mm].

    Returns
    -------
    Figure
        One axes, its data units millimetres of paper: each polygon is drawn at 1 mm = X N, from its own origin.
    """
    s = _style.resolve(**style)
    fig = _new_figure(width)
    ax = _one_axes(fig)
    pad = 9.0  # the margin each polygon keeps for its labels, as draw_force_polygon keeps it on paper [mm]
    extents = []
    for step in steps:
        _, _, verts = polygon_vertices(step, force_scale)
        extents.append((verts.min(axis=0) - pad, verts.max(axis=0) + pad))
    names = [_names(titles[k]) if titles is not None else step_title(step) for k, step in enumerate(steps)]
    height, panels = _lay_out_on(ax, extents, names, s, width=width, strip=STRIP)
    drawings = []
    for step, (origin, room, title) in zip(steps, panels):
        drawn = draw_force_polygon(step, scale=force_scale, ax=ax, origin=origin, title=False,
                                   driver_name=driver_name, paper=1.0, bar=False, place=False, **style)
        drawings.append((drawn, room, title))
    _place_on(ax, drawings, width, height)
    scale_strip(fig, height, force_scale=force_scale, width=width, ax=ax, **style)
    return fig


def draw_step(construction, step, *, length_scale: float, force_scale: float, polygon=None,
              width: float = FIGURE_WIDTH, **style) -> Figure:
    """One step of the construction printed at scale: its lines of action on the mechanism (1:k), and beside it
    its force polygon (1 mm = X N) when it has one, or ``polygon`` (a step whose polygon to draw there: a
    resultant's sum, R3i + Fc3 − R3 = 0)."""
    c = construction
    fig = _new_figure(width)
    paper = 1.0 / length_scale
    ax = fig.add_axes([0, 0, 0.2, 0.2], axes_class=BareAxes)
    draw_mechanism(c, ax=ax, faint=True, emphasis=step.link, place=False, length_scale=length_scale, **style)
    # Its loads to the force scale the figure states (X N per printed mm is X / k per mm drawn).
    draw_step_geometry(c, step, ax=ax, place=False, force_scale=force_scale / length_scale, **style)
    panels = [(ax, paper)]
    shown = polygon if polygon is not None else step if step.polygon else None
    if shown is not None:
        ax2 = fig.add_axes([0, 0, 0.2, 0.2], axes_class=BareAxes)
        draw_force_polygon(shown, scale=force_scale, ax=ax2, title=False, driver_name=c.driver_name, paper=1.0,
                           bar=False, place=False, **style)
        panels.append((ax2, 1.0))
    height = arrange(fig, panels, width=width, strip=STRIP if shown is not None else 0.0)
    if shown is not None:
        scale_strip(fig, height, force_scale=force_scale, width=width, **style)
    return fig


def draw_constructions(construction, steps, *, length_scale: float, titles=None, width: float = FIGURE_WIDTH,
                       **style) -> Figure:
    """The lines of action of several steps, one panel each (the mechanism drawn faint under them), all at 1:k.

    Parameters
    ----------
    construction : graphkin.graphical.Construction
    steps : sequence of graphkin.graphical.Step
        Typically the three-force members of the construction (of each sub-problem of a superposition).
    length_scale : float
        k: every panel is printed at 1:k.
    titles : sequence of str, optional
        A title over each panel.
    width : float
        The figure's width [mm].

    Returns
    -------
    Figure
    """
    c = construction
    fig = _new_figure(width)
    paper = 1.0 / length_scale
    s = _style.resolve(**style)
    panels = []
    for k, step in enumerate(steps):
        ax = fig.add_axes([0, 0, 0.2, 0.2], axes_class=BareAxes)
        draw_mechanism(c, ax=ax, faint=True, emphasis=step.link, place=False, length_scale=length_scale, bar=False,
                       **style)
        if titles is not None:
            ax.set_title(_names(titles[k]), fontsize=s.title_size, color=s.ink)
        draw_step_geometry(c, step, ax=ax, place=False, narrow=True, **style)
        panels.append((ax, paper))
    height = arrange(fig, panels, width=width, strip=STRIP)
    scale_strip(fig, height, length_scale=length_scale, width=width, **style)
    return fig


def plotted(draw, width: float, height: float) -> Figure:
    """A plot (a curve over the cycle) drawn on a figure of the size it prints at, so that its labels print at
    the sizes :mod:`graphkin.draw.style` gives them (never below 8 pt), not shrunk with the figure.

    Parameters
    ----------
    draw : callable
        ``draw(ax=ax)`` draws the plot on the axes it is given (``draw_torque_curve``, ``draw_energy``, …).
    width, height : float
        The figure's printed size [mm].

    Returns
    -------
    Figure
    """
    fig = Figure(figsize=(width / 25.4, height / 25.4), dpi=100, layout="constrained")
    draw(ax=fig.add_subplot())
    # The layout is made now, so that the picture's extent (measured before it is saved) is the laid-out one:
    # a title or a legend laid out only when saving would be cut off.
    fig.draw_without_rendering()
    fig.set_layout_engine("none")
    return fig


def draw_motion_paper(construction, *, velocity_scale: float, acceleration_scale: float, upto=None, values=True,
                      titles=None, width: float = FIGURE_WIDTH, **style) -> Figure:
    """The velocity and acceleration polygons of one position side by side, printed at their stated scales.

    Parameters
    ----------
    construction : graphkin.graphical.MotionConstruction
        The polygons of one position (:func:`graphkin.graphical.construct_kinematics`).
    velocity_scale, acceleration_scale : float
        1 mm of the velocity polygon is ``velocity_scale`` m/s, of the acceleration polygon
        ``acceleration_scale`` m/s².
    upto : int, optional
        Draw the polygons as they stand after step ``upto`` of ``construction.steps`` (a step of the
        velocity polygon leaves the acceleration polygon out).
    values : bool
        Write each vector's size beside it.
    titles : (str, str), optional
        The two panels' titles (default: the polygon's name).
    width : float
        The figure's width [mm].

    Returns
    -------
    Figure
        One axes, its data units millimetres of paper: two polygons (one before the acceleration polygon is
        begun), each drawn from its own origin, and a strip of scale bars. A polygon whose table of short vectors
        finds no clean spot beside it is drawn again with a column of its own for the table, to its right.
    """
    shown = ["velocity", "acceleration"]
    if upto is not None and construction.steps[upto].polygon == "velocity":
        shown = ["velocity"]
    scales = {"velocity": velocity_scale, "acceleration": acceleration_scale}
    columns: dict = {}
    for _ in range(3):
        fig, tables = _motion_figure(construction, shown, scales, columns, upto=upto, values=values, titles=titles,
                                     width=width, **style)
        # A table that found no clean spot beside its polygon, or outgrew the column kept for it: a column beside
        # the polygon as large as the table, kept free of the other labels, and the figure drawn again.
        grown = {polygon: size for polygon, (size, crowded) in tables.items()
                 if crowded and size != columns.get(polygon)}
        if not grown:
            break
        columns.update(grown)
    return fig


def _motion_figure(construction, shown, scales, columns, *, upto, values, titles, width, **style):
    """The figure of :func:`draw_motion_paper`, each polygon of ``columns`` with a column (width, height [mm]) to
    its right for its table of short vectors.

    Returns the figure and, by polygon, its table's size as drawn (width, height [mm]) and whether it is crowded:
    placed by the Labeler where it covers something, or larger than its column.
    """
    s = _style.resolve(**style)
    fig = _new_figure(width)
    ax = _one_axes(fig)
    pad = 9.0  # the margin each polygon keeps for its labels, as draw_motion_polygon keeps it on paper [mm]
    extents = []
    for polygon in shown:
        lo, hi = motion_extent(construction, polygon, scales[polygon])
        lo, hi = lo - pad, hi + pad
        if polygon in columns:
            w, h = columns[polygon]
            hi = hi + (2.0 + w, 0.0)  # 2 mm between the polygon's margin and its table's column
            lo = np.minimum(lo, hi - (0.0, h))
        extents.append((lo, hi))
    names = [titles[n] if titles is not None else f"{polygon.capitalize()} polygon" for n, polygon in enumerate(shown)]
    height, panels = _lay_out_on(ax, extents, names, s, width=width, strip=STRIP)
    drawings, reserved = [], []
    for polygon, (origin, room, title) in zip(shown, panels):
        column, at = None, None
        if polygon in columns:
            w, _ = columns[polygon]
            column = (room[2] - w, room[1], room[2], room[3])
            at = (column[0], column[3])
        drawn = draw_motion_polygon(construction, polygon, scale=scales[polygon], ax=ax, values=values, title=False,
                                    upto=upto, paper=1.0, bar=False, place=False, origin=origin, table_at=at,
                                    **style)
        drawings.append((drawn, room, title))
        reserved.append(column)
    _place_on(ax, drawings, width, height, reserved)
    scale_strip(fig, height, velocity_scale=scales["velocity"],
                acceleration_scale=scales["acceleration"] if "acceleration" in shown else None, width=width, ax=ax,
                **style)
    renderer = measuring_renderer(fig)
    tables = {}
    for polygon, (drawn, _, _), column in zip(shown, drawings, reserved):
        table = next((a for a in drawn if (getattr(a, "get_gid", lambda: None)() or "").startswith("table:")), None)
        if table is None or not table.get_text().strip():
            continue
        bb = text_extent(table, renderer)
        size = (round(bb.width / fig.dpi * 25.4 + 0.5, 1), round(bb.height / fig.dpi * 25.4 + 0.5, 1))
        crowded = (drawn.labeler.prices.get(table, 0.0) >= ASTRAY_COST if column is None
                   else size[0] > columns[polygon][0] or size[1] > columns[polygon][1])
        tables[polygon] = (size, crowded)
    return fig, tables
