"""The mechanism moving over one turn of its crank with its joint forces: the frames, and the film that holds them.

:func:`animate` solves a problem at ``frames`` equally spaced crank angles (one
turn at the problem's constant speed, so equal steps of angle are equal steps
of time), constructs each position graphically
(:func:`graphkin.graphical.construct_forces`) and draws it: the mechanism to
scale (:func:`~graphkin.draw.draw_mechanism`), the force of each joint as an
arrow from the joint, each known load (a cutting force, a weight) as an arrow
from where it acts, and, with ``polygons=True``, each moving link's force
polygon beside it. The caption gives the crank angle and the driving torque.
It is the one drawing that solves: an animation shows a problem over a turn,
not a result someone already has.

Nothing jumps from one frame to the next: every frame has the same view (the
union of every frame's own, found before any frame is drawn), one force
scale for the whole turn (the largest force of the turn drawn
:data:`LONGEST` of the mechanism's size long), and its length and force scale
bars in one place. Positions where the linkage cannot be assembled are frames
that say so.

The frames are kept as PNG; :class:`Animation` writes them
(:mod:`graphkin.draw.films`) as a GIF, an MP4 (ffmpeg) or one self-contained
web page, and shows itself in a notebook.

Examples
--------
>>> from graphkin import catalog, draw
>>> film = draw.animate(catalog.load("strip_cutter"), frames=4, dpi=30)
>>> len(film.frames), film.fps
(4, 24.0)
>>> film.save("strip_cutter.gif")  # doctest: +SKIP
"""

from __future__ import annotations

import io
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from graphkin.analytical import solve_forces
from graphkin.draw import films
from graphkin.draw import style as _style
from graphkin.draw.arrows import arrow, unit
from graphkin.draw.axes import MM, Drawn, PanelAxes, markers, points_per_unit
from graphkin.draw.fbd import loads_on
from graphkin.draw.geometry import Geometry
from graphkin.draw.labels import offset_text
from graphkin.draw.mechanism import draw_mechanism
from graphkin.draw.scales import nice_round, scale_bar
from graphkin.draw.text import input_text, sub
from graphkin.errors import GraphkinError
from graphkin.graphical import construct_forces
from graphkin.graphical.construction import nice_scale
from graphkin.graphical.guard import check_forces
from graphkin.model import GearMesh, Prismatic
from graphkin.model.names import force_name
from graphkin.notation import num

LONGEST = 0.35
"""The largest force of the turn (joint force or known load) is drawn this fraction of the mechanism's size long."""

MAX_FRAMES = 3600
"""The most frames an animation has (0.1° steps)."""

WIDTH = 6.4
"""Width of a frame [in] (640 pixels at 100 dpi)."""


@dataclass(frozen=True)
class Animation:
    """The frames of an animation and how fast they play.

    Attributes
    ----------
    frames : tuple of bytes
        Each frame as PNG, all of one size.
    fps : float
        Frames per second.
    size : (int, int)
        Width and height of a frame [px].
    title : str
        What it shows (the web page's title).
    scale : float
        The force scale [N per mm of the drawing] of every frame.
    gaps : tuple of (float, str)
        The frames with no solution, which say so: the crank angle [rad] and why.
    """

    frames: tuple
    fps: float
    size: tuple
    title: str = ""
    scale: float = math.nan
    gaps: tuple = ()

    def save(self, path) -> Path:
        """Write the animation as ``.gif``, ``.mp4`` or ``.html``, chosen by the suffix, whole or not at all.

        Raises
        ------
        GraphkinError
            If the suffix is another, the file cannot be written, or an MP4 is
            asked for and ffmpeg is not installed.
        """
        return films.write(self, path)

    def to_html(self) -> str:
        """The animation as one web page: the frames inline, a small player, nothing loaded from the network."""
        return films.html_page(self)

    def _repr_html_(self):
        return films.html_player(self)


def animate(problem, path=None, *, frames: int = 72, fps: float = 24.0, polygons: bool = False, dpi: float = 100,
            progress=None, **style) -> Animation:
    """The mechanism moving over one turn of its crank with its joint forces, as an animation.

    Parameters
    ----------
    problem : graphkin.problem.Problem
        A crank-driven problem at a constant speed.
    path : str or Path, optional
        Also write the animation there (``.gif``, ``.mp4`` or ``.html``, see :meth:`Animation.save`).
    frames : int
        Frames over the turn: crank angles θ = 360°·k/frames, k = 0 … frames − 1.
    fps : float
        Frames per second, above 0 and at most :data:`graphkin.draw.films.MAX_FPS`.
    polygons : bool
        Draw each moving link's force polygon beside the mechanism.
    dpi : float
        Pixels per inch of a frame (a frame is :data:`WIDTH` inches wide, 1.45 times that with polygons).
    progress : callable, optional
        Called with 1 after each frame is drawn (a tqdm bar's ``update``).
    **style
        Overrides of :class:`graphkin.draw.style.Style` fields.

    Returns
    -------
    Animation

    Raises
    ------
    GraphkinError
        If the problem has no crank to turn, its speed varies, it gives
        measured kinematics ([given]) or no crank angle has a solution; or
        ``frames``, ``fps``, ``dpi`` or ``path`` is out of range.
    """
    check_frames(frames)
    films.check_fps(fps)
    if path is not None:
        films.check_path(path)
    if not (isinstance(dpi, (int, float)) and 10 <= dpi <= 600):
        raise GraphkinError(f"--dpi {dpi}: the resolution must be from 10 to 600 pixels per inch")
    kin = _kinematics(problem, frames)
    result = solve_forces(kin)
    # Each frame's construction checked against the analytical route before it is drawn (graphical/guard.py).
    cs = [check_forces(result, construct_forces(kin, i), i) for i in range(frames)]
    gaps = tuple((c.q, c.reason) for c in cs if not (c.valid and c.points))
    if len(gaps) == frames:
        raise GraphkinError(f"{problem.name}: no crank angle of the turn has a solution, so there is nothing to "
                            f"animate ({input_text(cs[0])}: {gaps[0][1]})")
    film = Film(cs, polygons=polygons, dpi=dpi, **style)
    pngs = []
    for c in cs:
        pngs.append(film.png(c))
        if progress is not None:
            progress(1)
    title = f"{getattr(problem, 'title', '') or problem.name}: one turn of the crank"
    anim = Animation(tuple(pngs), float(fps), film.pixels, title, film.scale, gaps)
    if path is not None:
        anim.save(path)
    return anim


def check_frames(frames) -> int:
    """``frames`` if it is a whole number from 1 to :data:`MAX_FRAMES`; an error naming ``--frames`` if not."""
    if isinstance(frames, bool) or not isinstance(frames, (int, np.integer)) or not 1 <= frames <= MAX_FRAMES:
        raise GraphkinError(f"--frames {frames}: give a whole number of frames from 1 to {MAX_FRAMES}")
    return int(frames)


def _kinematics(problem, frames: int):
    """The problem's motion at ``frames`` crank angles over one turn; an error if it has no turn to show."""
    name = getattr(problem, "name", type(problem).__name__)
    mech = getattr(problem, "mechanism", None)
    if mech is None or not hasattr(problem, "kinematics"):
        raise GraphkinError(f"animate takes a Problem (graphkin.catalog.load(name)), got {type(problem).__name__}")
    if not mech.driver.crank:
        raise GraphkinError(f"{name}: the driver is a slider, so there is no turn of a crank to animate")
    if problem.given:
        raise GraphkinError(f"{name}: it gives kinematic values ([given] in the file) that hold at its own position "
                            "only, so there is no cycle to animate")
    return problem.kinematics(at=np.linspace(0.0, 2 * math.pi, frames, endpoint=False))


def joint_forces(c):
    """Each joint's force at a construction's position: (name, force [N], point [mm]), the lower link's on the higher.

    ``F23`` is the force of link 2 on link 3 at their joint, as the reports
    name it; a sliding pair's force is at its slider point, a mesh's at its
    pitch point (off it, on the line of centres, with a mesh efficiency).
    """
    out = []
    for joint in c.mechanism.joints:
        lo, hi = sorted(joint.links)
        if isinstance(joint, Prismatic):
            at = c.points[joint.slider][joint.point]
        elif isinstance(joint, GearMesh):
            at = c.contacts[(lo, hi)]
        else:
            at = c.points[hi][joint.point]
        out.append((force_name(c.mechanism, lo, hi), np.asarray(c.force(lo, hi), float), np.asarray(at, float) * MM))
    return out


def loads(c):
    """The known loads at a construction's position: (name, force [N], point [mm]) of each external force and weight.

    The cutting force of the strip cutter, a gas force, a weight: what the
    joint forces answer. Named without their note (``Fc3``, not ``Fc3 (cutting)``).
    """
    return [(a.name.split(" ")[0], np.asarray(a.vector, float), np.asarray(a.at, float) * MM)
            for link in c.mechanism.moving for a in c.external.get(link, []) if a.at is not None]


class Film:
    """One figure, drawn again for each position, with the view and the force scale of the whole turn fixed first.

    Parameters
    ----------
    constructions : sequence of graphkin.graphical.Construction
        The positions to draw, in order.
    polygons : bool
        Draw each moving link's force polygon beside the mechanism, in a column of panels.
    dpi : float
        Pixels per inch.
    **style
        Overrides of :class:`graphkin.draw.style.Style` fields.

    Attributes
    ----------
    figure : matplotlib.figure.Figure
    ax : matplotlib.axes.Axes
        The mechanism's panel.
    ax_polygons : dict of int to matplotlib.axes.Axes
        Each moving link's force-polygon panel (empty without ``polygons``).
    view : ((float, float), (float, float))
        The mechanism panel's x and y limits in every frame [mm].
    scale : float
        The force scale of every frame [N per mm of the drawing].
    pixels : (int, int)
        A frame's width and height [px].
    drawn : Drawn
        The force arrows of the frame drawn last: ``.arrows`` and ``.ends`` (tail, tip [mm]) by name, the
        mechanism's as ``"F23"`` (a known load ``"Fc3"``), the polygons' as ``"polygon3:F23"``.
    """

    def __init__(self, constructions, *, polygons: bool = False, dpi: float = 100, **style):
        from matplotlib.figure import Figure

        from graphkin.draw.stamps import StampCanvas

        self.s = _style.resolve(**style)
        good = [c for c in constructions if c.valid and c.points]
        largest = max([float(np.hypot(*F)) for c in good for _, F, _ in joint_forces(c) + loads(c)] + [0.0])
        self.size = max([Geometry(c).size for c in good] + [1.0])
        self.scale = nice_scale(largest, LONGEST * self.size)
        links = list(good[0].mechanism.moving) if good and polygons else []
        width = WIDTH * (1.45 if links else 1.0)
        self.figure = Figure(figsize=(width, 0.75 * WIDTH), dpi=dpi)
        StampCanvas(self.figure)  # the names and scale readings, the same in every frame, are rendered once
        share = WIDTH / width
        self.ax = self.figure.add_axes((0.0, 0.0, share, 0.92), axes_class=PanelAxes)
        self.ax_polygons = {}
        for k, link in enumerate(links):
            tall = 0.86 / len(links)
            pax = self.figure.add_axes((share + 0.01, 0.08 + (len(links) - 1 - k) * tall, 0.98 - share, tall - 0.045),
                                       axes_class=PanelAxes)
            pax.set_axis_off()
            pax.set_aspect("equal", adjustable="box")
            self.ax_polygons[link] = pax
        # The polygons' force scale, under their column: an axes of its own, its x in the panels' mm.
        self.ax_bar = self.figure.add_axes((share + 0.01, 0.0, 0.98 - share, 0.06), axes_class=PanelAxes) \
            if links else None
        self.view = self._view(good)
        (x0, x1), (y0, y1) = self.view
        # As tall as the view needs at this width (the caption above it), within reason.
        self.figure.set_size_inches(width, min(max(WIDTH * (y1 - y0) / max(x1 - x0, 1e-9) / 0.92, 0.45 * WIDTH),
                                               1.1 * WIDTH))
        self.polygon_views = _polygon_views(good, links, self.scale)
        if self.ax_bar is not None:
            self.ax_bar.set_axis_off()
            (px0, px1), _ = next(iter(self.polygon_views.values()))
            box = next(iter(self.ax_polygons.values())).get_position()
            w, h = self.figure.get_size_inches()
            # The panels are square in mm and shrink to fit: pixels per mm are those of their shorter side.
            per_mm = min(box.width * w, box.height * h) / (px1 - px0)
            self.bar_span = box.width * w / per_mm
        w, h = self.figure.canvas.get_width_height(physical=True)
        self.pixels = (int(w), int(h))

    def _view(self, good):
        """The union of every frame's view (the mechanism as :func:`draw_mechanism` frames it, and the arrows)."""
        lo, hi = np.full(2, np.inf), np.full(2, -np.inf)
        for c in good:
            _empty(self.ax)
            draw_mechanism(c, ax=self.ax, labels=False, bar=False, **vars(self.s))
            (x0, x1), (y0, y1) = self.ax.get_xlim(), self.ax.get_ylim()
            tips = [X + F / self.scale for _, F, X in joint_forces(c) + loads(c)]
            pts = np.array([[x0, y0], [x1, y1], *tips]).reshape(-1, 2)
            lo, hi = np.minimum(lo, pts.min(axis=0)), np.maximum(hi, pts.max(axis=0))
        if not np.all(np.isfinite([*lo, *hi])):
            return (-1.0, 1.0), (-1.0, 1.0)
        pad = 0.05 * float(np.max(hi - lo))
        lo, hi = lo - pad, hi + pad
        lo[1] -= 0.08 * float(np.max(hi - lo))  # room for the scale bars, below the lowest point of the turn
        return (float(lo[0]), float(hi[0])), (float(lo[1]), float(hi[1]))

    def draw(self, c):
        """Draw one position on the figure (not rendered); returns the figure."""
        s, ax = self.s, self.ax
        for a in (ax, *self.ax_polygons.values(), *([self.ax_bar] if self.ax_bar else [])):
            _empty(a)
        self.drawn = Drawn(ax)
        self.figure.texts.clear()
        if c.valid and c.points:
            draw_mechanism(c, ax=ax, labels=False, bar=False, **vars(s))
            for name, F, X in joint_forces(c):
                self._force(ax, name, F, X)
            for name, F, X in loads(c):
                self._force(ax, name, F, X, known=True)
            torque = f"   {sub(c.driver_name)} = {num(c.effort)} {'N·m' if c.mechanism.driver.crank else 'N'}"
            for link, pax in self.ax_polygons.items():
                _polygon(pax, link, loads_on(c, link)["forces"], self.scale, s, self.drawn)
        else:
            torque = ""
            ax.text(0.5, 0.5, f"no solution here: {c.reason}", transform=ax.transAxes, ha="center", va="center",
                    fontsize=s.label_size, color=s.unknown, wrap=True)
        self._bars()
        self.figure.text(0.02, 0.975, f"{input_text(c)}{torque}", fontsize=s.title_size, color=s.ink, va="top")
        return self.figure

    def png(self, c) -> bytes:
        """One position drawn and rendered, as PNG."""
        self.draw(c)
        self.figure.canvas.draw()
        return _png(self.figure)

    def _force(self, ax, name, F, X, known=False):
        """An arrow from the point the force acts at, in the colour of a found force (or of a known load)."""
        s = self.s
        if not float(np.hypot(*F)) > 1e-9 * self.scale:  # a joint that carries nothing here: no arrow, no name
            return
        tip = X + F / self.scale
        ppu = points_per_unit(ax, max(np.ptp(self.view[0]), np.ptp(self.view[1])))
        color = s.known if known else s.unknown
        self.drawn.arrows[name] = arrow(ax, X, tip, color=color, lw=s.known_lw if known else s.unknown_lw, s=s,
                                        zorder=6, gid=f"force:{name}", pt_per_unit=ppu)
        self.drawn.ends[name] = (tuple(X), tuple(tip))
        _name(ax, sub(name), tip, unit(F), s.label_size, color)

    def _bars(self):
        """The length and force scales, in the same place on every frame; every panel's view, fixed."""
        s, ax = self.s, self.ax
        (x0, x1), (y0, y1) = self.view
        span = max(x1 - x0, y1 - y0)
        y = y0 + 0.03 * span
        length = nice_round(0.2 * self.size)
        scale_bar(ax, (x0 + 0.04 * span, y), length, length, s=s, unit_text="mm", tick=0.01 * span)
        force = nice_round(0.15 * self.size * self.scale)
        scale_bar(ax, (x0 + 0.5 * (x1 - x0), y), force / self.scale, force, s=s, tick=0.01 * span,
                  note=f"1 mm = {num(self.scale)} N")
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
        for link, pax in self.ax_polygons.items():
            (px0, px1), (py0, py1) = self.polygon_views[link]
            pax.set_xlim(px0, px1)
            pax.set_ylim(py0, py1)
        if self.ax_bar is not None:
            bar = nice_round(0.25 * self.bar_span * self.scale)
            scale_bar(self.ax_bar, (0.1 * self.bar_span, 0.0), bar / self.scale, bar, s=s, tick=0.2)
            self.ax_bar.set_xlim(0.0, self.bar_span)
            self.ax_bar.set_ylim(-1.0, 1.0)


def _polygon_loads(forces):
    """A link's forces in the order a book adds them: the known loads first, then the joint forces."""
    order = {"inertia": 0, "known": 1, "driver": 2, "unknown": 3}
    return sorted(forces, key=lambda f: order[f[3]])


def _vertices(forces, scale):
    """The polygon's corners [mm of drawing], tip to tail from (0, 0)."""
    return np.cumsum([np.zeros(2)] + [np.asarray(f[1], float) / scale for f in _polygon_loads(forces)], axis=0)


def _polygon_views(good, links, scale):
    """Each polygon panel's limits: around every frame's polygon of its link, all panels the same size.

    Of one size, the panels share one drawing scale, so one force polygon can
    be compared with another at a glance, as with the arrows.
    """
    boxes = {}
    for link in links:
        pts = np.array([v for c in good for v in _vertices(loads_on(c, link)["forces"], scale)]).reshape(-1, 2)
        boxes[link] = (pts.min(axis=0), pts.max(axis=0)) if len(pts) else (np.zeros(2), np.zeros(2))
    half = 0.62 * max([float(np.max(hi - lo)) for lo, hi in boxes.values()] + [1e-9])
    views = {}
    for link, (lo, hi) in boxes.items():
        mid = 0.5 * (lo + hi)
        views[link] = ((mid[0] - half, mid[0] + half), (mid[1] - half, mid[1] + half))
    return views


def _polygon(ax, link, forces, scale, s, drawn):
    """A link's force polygon at the animation's force scale: the arrows tip to tail and their names (no sizes)."""
    forces = _polygon_loads(forces)
    verts = _vertices(forces, scale)
    centre = verts.mean(axis=0)
    for (name, _, _, kind), tail, tip in zip(forces, verts[:-1], verts[1:]):
        if not np.hypot(*(tip - tail)) > 1e-9:
            continue
        known = kind in ("inertia", "known")
        color = s.driver if kind == "driver" else s.known if known else s.unknown
        key = f"polygon{link}:{name.split(' ')[0]}"
        drawn.arrows[key] = arrow(ax, tail, tip, color=color, lw=s.known_lw if known else s.unknown_lw, s=s, zorder=4.5,
                                  gid=key)
        drawn.ends[key] = (tuple(tail), tuple(tip))
        _name(ax, sub(name.split(" ")[0]), 0.5 * (tail + tip), unit(0.5 * (tail + tip) - centre), s.small_size, color)
    markers(ax, *verts[0], ms=6, mfc="none", mec=s.ink, mew=1.0, zorder=5)
    ax.set_title(f"Link {link}: " + " + ".join(sub(f[0].split(" ")[0]) for f in forces) + " = 0",
                 fontsize=s.small_size, color=s.ink)


def _name(ax, text, at, away, size, color):
    """A force's name 4 pt from ``at`` [mm], on the side ``away`` points to."""
    offset_text(ax, text, at, tuple(4.0 * away), fontsize=size, color=color,
                ha="left" if away[0] > 0.3 else "right" if away[0] < -0.3 else "center",
                va="bottom" if away[1] > 0.3 else "top" if away[1] < -0.3 else "center")


def _fit(points, margin):
    """Equal-aspect limits around points [mm], ``margin`` of their extent added each side."""
    pts = np.asarray(points, float).reshape(-1, 2)
    if not len(pts):
        return (-1.0, 1.0), (-1.0, 1.0)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    pad = margin * max(float(np.max(hi - lo)), 1e-9)
    return (lo[0] - pad, hi[0] + pad), (lo[1] - pad, hi[1] + pad)


def _empty(ax):
    """Remove what was drawn on a panel (cheaper than ``ax.cla()``, which rebuilds the axis machinery)."""
    for artist in list(ax._children):
        artist.remove()
    ax.title.set_text("")
    # The view is set by hand at the end of each frame: nothing drawn needs to join the data limits.
    ax.set_autoscale_on(False)


def _png(fig) -> bytes:
    """The rendered figure as PNG: a 256-colour palette (line art on white) at a fast zlib setting."""
    from PIL import Image

    canvas = fig.canvas
    w, h = canvas.get_width_height(physical=True)
    # Opaque (the figure is white): a palette with transparency would make the GIF writer's frame differences fail.
    image = Image.frombuffer("RGBA", (w, h), canvas.buffer_rgba(), "raw", "RGBA", 0, 1).convert("RGB")
    buf = io.BytesIO()
    image.quantize(256, method=Image.Quantize.FASTOCTREE).save(buf, format="png", compress_level=1)
    return buf.getvalue()
