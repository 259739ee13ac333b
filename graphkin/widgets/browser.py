"""The explorer, drawn by the browser (issue 37): ``gk.explore(problem)``.

The kernel solves the cycle once (:func:`graphkin.scene.scene`) and sends the scene to the browser as JSON in one
trait of an anywidget; the browser's module (:func:`graphkin.scene.page.module`, the same that draws
``graphkin explore PROBLEM -o page.html``) draws every position, the crank dragged, the keys, play, the toggles and
the speed box included. The kernel is asked again only when something the scene cannot express changes — a length,
a mass, a load, the friction (:meth:`BrowserExplorer.set`), or a new problem — and answers with a new scene. Nothing
is drawn ahead, kept or timed in Python, and the browser sends nothing back while a student moves the mechanism.

A slider-driven problem whose file gives one position (``double_slider``) is explored over where its linkage
assembles (:func:`graphkin.widgets.positions.spread`), as the kernel-drawn explorer this one replaced did.

anywidget and traitlets are imported only when an explorer is built.
"""

from __future__ import annotations

import functools
import math
from dataclasses import replace

import numpy as np

from graphkin.errors import GraphkinError
from graphkin.model import SpringForce, StrokeForce, Torque
from graphkin.optional import require
from graphkin.scene import scene, scene_json
from graphkin.scene.build import drawn
from graphkin.scene.page import asset, module
from graphkin.widgets.positions import spread

FIELDS = ("speed", "mu", "gravity", "mass.K", "I_G.K", "G.K", "point.K.P", "load.NAME")
"""What :meth:`BrowserExplorer.set` changes: K a link's number, P one of its points, NAME an external load's."""


@functools.cache
def scene_widget():
    """The class of the widget: anywidget's, with the drawing module as its ``_esm`` and the scene's JSON in
    ``scene``; ``index`` is the position shown when set from Python."""
    anywidget = require("anywidget", "gk.explore(problem)")
    import traitlets

    class SceneWidget(anywidget.AnyWidget):
        _esm = module()
        _css = asset("scene.css")
        scene = traitlets.Unicode("").tag(sync=True)
        index = traitlets.Int(0).tag(sync=True)

    return SceneWidget


def explore(problem, *, n: int = 360, polygons: bool = True, motion: bool = False, units=None, limits=None,
            browser: bool = True):
    """An interactive explorer of a problem for a notebook (JupyterLab, Voilà): the browser draws every position.

    Parameters
    ----------
    problem : graphkin.Problem
        A catalog problem or one read from a file.
    n : int
        Crank angles over one turn; for a slider driver whose file gives one position, positions over where its
        linkage assembles (or over ``limits``).
    polygons : bool
        The graphical route and its force polygons at every position.
    motion : bool
        The velocity and acceleration polygons at every position (a toggle shows them).
    units : graphkin.units.systems.UnitSystem, optional
        The book's units, offered beside SI for reading a value.
    limits : (float, float), optional
        A slider driver's range [mm], where its file gives one position.
    browser : bool
        Kept for code written while the kernel-drawn explorer was the default: only True is accepted.

    Returns
    -------
    BrowserExplorer
        Display it in a cell.

    Examples
    --------
    >>> import graphkin as gk
    >>> ex = gk.explore(gk.load("strip_cutter"))     # doctest: +SKIP
    >>> ex.position = 140                             # θ12 = 140°, the nearest presolved angle  # doctest: +SKIP
    >>> ex.set("mass.3", 4.0)                         # a new scene from Python  # doctest: +SKIP
    """
    if browser is not True:
        raise GraphkinError("explore: browser=False asked for the explorer drawn by the kernel as PNG images, which "
                            "is retired; the browser draws every position (gk.draw.draw_solution draws one in Python)")
    return BrowserExplorer(problem, n, polygons=polygons, motion=motion, units=units, limits=limits)


class BrowserExplorer:
    """A problem's cycle drawn in the notebook by the browser; display it in a cell.

    Parameters
    ----------
    problem : graphkin.Problem
    n : int
        Crank angles over one turn (:func:`graphkin.scene.scene`).
    polygons : bool
        Build the graphical route and its force polygons at every position.
    motion : bool
        Build the velocity and acceleration polygons at every position.
    units : graphkin.units.systems.UnitSystem, optional
        The book's units, offered beside SI for reading a value (:func:`graphkin.scene.scene`).
    limits : (float, float), optional
        A slider driver's range [mm] where its file gives one position (:func:`graphkin.widgets.positions.spread`).

    Attributes
    ----------
    widget : anywidget.AnyWidget
        The widget the browser draws: its ``scene`` is :func:`graphkin.scene.scene_json` of :attr:`scene`.
    scene : dict
        The scene drawn (docs/json.md).
    """

    def __init__(self, problem, n: int = 360, polygons: bool = True, motion: bool = False, units=None,
                 limits=None):
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 2:
            raise GraphkinError(f"explore: n must be a whole number of positions ≥ 2, got {n!r}")
        self.n, self.polygons, self.motion, self.units = int(n), polygons, motion, units
        self.widget = scene_widget()()
        self.scene = None
        self.problem = spread(problem, self.n, limits)
        q0 = float(problem.q[0])  # first shown: the file's own position, as presolved
        self.position = math.degrees(q0) if self.crank else q0 * 1e3

    @property
    def problem(self):
        """The problem drawn; setting it sends the browser its new scene."""
        return self._problem

    @problem.setter
    def problem(self, problem) -> None:
        data = scene(problem, self.n, polygons=self.polygons, motion=self.motion, units=self.units)
        shown = self.position if getattr(self, "scene", None) is not None else None
        self._problem, self.scene = problem, data
        with self.widget.hold_sync():  # one message: the new scene and where it is shown
            if shown is not None:  # at the position set from Python (or the nearest the new scene has)
                self.widget.index = nearest(data, shown)
            self.widget.scene = scene_json(data)

    @property
    def index(self) -> int:
        """The position last shown from Python (the browser's own moves are not sent back: no message a frame)."""
        return self.widget.index

    @index.setter
    def index(self, i: int) -> None:
        if not 0 <= int(i) < self.scene["n"]:
            raise GraphkinError(f"explorer index: {i} is not a position of the scene (0 to {self.scene['n'] - 1})")
        self.widget.index = int(i)

    @property
    def position(self) -> float:
        """The position last shown from Python: θ [deg] of a crank, s [mm] of a slider; setting it shows the
        presolved position nearest to it (the index of the scene)."""
        return float(self.scene["input"]["values"][self.index]) * (180.0 / math.pi if self.crank else 1e3)

    @position.setter
    def position(self, value: float) -> None:
        self.index = nearest(self.scene, value)

    @property
    def crank(self) -> bool:
        """Whether the input is a crank (positions in degrees) rather than a slider (mm)."""
        return self.scene["input"]["name"] == "theta"

    def set(self, field: str, value) -> None:
        """Change one thing of the problem the scene cannot express, and draw the new scene.

        Parameters
        ----------
        field : str
            One of :data:`FIELDS`: ``"speed"`` (the input's rate, rad/s or m/s), ``"mu"`` (Coulomb friction at every
            sliding pair), ``"gravity"`` (m/s²), ``"mass.3"`` (kg), ``"I_G.3"`` (kg·m²), ``"G.3"`` ((x, y) m in the
            link's frame), ``"point.3.C"`` (a point of link 3 in its frame, (x, y) m: a length), ``"load.Fc"`` (an
            external force (Fx, Fy) N, or a torque N·m).
        value : float or (float, float)
            The new value, SI.
        """
        self.problem = changed(self.problem, field, value)

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)


def nearest(data: dict, value: float) -> int:
    """The index of the scene's position nearest ``value`` (θ [deg], any turn, or s [mm]).

    Examples
    --------
    >>> nearest({"input": {"name": "theta", "values": [0.0, 1.5, 3.0, 4.5]}}, 350)
    0
    """
    q = np.asarray(data["input"]["values"], float)
    if not math.isfinite(float(value)):
        raise GraphkinError(f"explorer position: {value!r} is not a number")
    if data["input"]["name"] == "theta":
        gap = np.angle(np.exp(1j * (q - math.radians(value))))
    else:
        gap = q - value * 1e-3
    return int(np.argmin(np.abs(gap)))


def changed(problem, field: str, value):
    """The problem with one field changed (:meth:`BrowserExplorer.set`); a field it has not is a plain error.

    Parameters
    ----------
    problem : graphkin.Problem
    field : str
        One of :data:`FIELDS`.
    value : float or (float, float)
        SI.

    Returns
    -------
    graphkin.Problem
    """
    what = f"explorer field {field!r}"
    head, _, rest = field.partition(".")
    problem = drawn(problem)  # as the scene draws it: a crank's cycle without a book's [given] values
    if field == "speed":
        return problem.at_speed(value)
    if field == "mu":
        return problem.with_friction(value)
    mech = problem.mechanism
    if field == "gravity":
        return replace(problem, mechanism=replace(mech, gravity=value))
    if head == "load" and rest:
        loads = [ld for ld in mech.loads if ld.name == rest]
        if not loads:
            raise GraphkinError(f"{what}: no external load is named {rest!r} (loads: "
                                f"{', '.join(ld.name for ld in mech.loads if ld.name) or 'none named'})")
        load = loads[0]
        if isinstance(load, (SpringForce, StrokeForce)):
            raise GraphkinError(f"{what}: a spring's or a stroke's force follows the motion; change it in the file")
        new = replace(load, torque=value) if isinstance(load, Torque) else replace(load, force=tuple(value))
        return replace(problem, mechanism=replace(mech, loads=tuple(new if ld is load else ld for ld in mech.loads)))
    if head in ("mass", "I_G", "G", "point") and rest:
        number, _, point = rest.partition(".")
        links = {str(link.number): link for link in mech.links}
        if number not in links or (head == "point") != bool(point):
            raise GraphkinError(f"{what}: give {head}.K{'.P' if head == 'point' else ''} with K a link's number "
                                f"({', '.join(links)})")
        link = links[number]
        if head in ("G", "point") and problem.given:  # a slider-driven problem, drawn at its own positions
            raise GraphkinError(f"{what}: the file gives kinematic values ([given]) that hold for its own geometry "
                                "only; remove them to change it")
        if head == "point":
            if point not in link.points:
                raise GraphkinError(f"{what}: link {number} has no point {point!r} ({', '.join(link.points)})")
            new = replace(link, points={**link.points, point: tuple(value)})
        else:
            new = replace(link, **{head: tuple(value) if head == "G" else value})
        return replace(problem, mechanism=replace(mech, links=tuple(new if k is link else k for k in mech.links)))
    raise GraphkinError(f"{what}: not one the explorer changes ({', '.join(FIELDS)})")
