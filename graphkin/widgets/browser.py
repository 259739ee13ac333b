"""The explorer drawn by the browser (issue 37): ``gk.explore(problem, browser=True)``.

The kernel solves the cycle once (:func:`graphkin.scene.scene`) and sends the scene to the browser as JSON in one
trait of an anywidget; the browser's module (:func:`graphkin.scene.page.module`, the same that draws
``graphkin explore PROBLEM -o page.html``) draws every position, the crank dragged, the keys, play, the toggles and
the speed box included. The kernel is asked again only when something the scene cannot express changes — a length,
a mass, a load, the friction (:meth:`BrowserExplorer.set`), or a new problem — and answers with a new scene. Nothing
is drawn ahead, kept or timed in Python: none of the PNG explorer's machinery (:mod:`graphkin.widgets.explorer`).

anywidget and traitlets are imported only when an explorer is built.
"""

from __future__ import annotations

import functools
from dataclasses import replace

from graphkin.errors import GraphkinError
from graphkin.model import SpringForce, StrokeForce, Torque
from graphkin.optional import require
from graphkin.scene import scene, scene_json
from graphkin.scene.build import drawn
from graphkin.scene.page import asset, module

FIELDS = ("speed", "mu", "gravity", "mass.K", "I_G.K", "G.K", "point.K.P", "load.NAME")
"""What :meth:`BrowserExplorer.set` changes: K a link's number, P one of its points, NAME an external load's."""


@functools.cache
def scene_widget():
    """The class of the widget: anywidget's, with the drawing module as its ``_esm`` and the scene's JSON in
    ``scene``; ``index`` is the position shown when set from Python."""
    anywidget = require("anywidget", "gk.explore(problem, browser=True)")
    import traitlets

    class SceneWidget(anywidget.AnyWidget):
        _esm = module()
        _css = asset("scene.css")
        scene = traitlets.Unicode("").tag(sync=True)
        index = traitlets.Int(0).tag(sync=True)

    return SceneWidget


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

    Attributes
    ----------
    widget : anywidget.AnyWidget
        The widget the browser draws: its ``scene`` is :func:`graphkin.scene.scene_json` of :attr:`scene`.
    scene : dict
        The scene drawn (docs/json.md).
    """

    def __init__(self, problem, n: int = 360, polygons: bool = True, motion: bool = False, units=None):
        self.n, self.polygons, self.motion, self.units = n, polygons, motion, units
        self.widget = scene_widget()()
        self.problem = problem

    @property
    def problem(self):
        """The problem drawn; setting it sends the browser its new scene."""
        return self._problem

    @problem.setter
    def problem(self, problem) -> None:
        data = scene(problem, self.n, polygons=self.polygons, motion=self.motion, units=self.units)
        self._problem, self.scene = problem, data
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
