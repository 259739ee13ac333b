"""Notebook widgets: the explorer, drawn by the browser, and the exercise box.

:func:`explore` builds a :class:`BrowserExplorer` (issue 37): the kernel solves the problem's whole cycle once
(:func:`graphkin.scene.scene`: every position's mechanism, forces of both routes, free bodies, force polygons and
torque curve, and on request the velocity and acceleration polygons) and sends it to the browser as JSON in an
anywidget; the browser draws every position with the module that draws ``graphkin explore PROBLEM -o page.html``
(graphkin/scene/js): the crank dragged on the drawing, the slider and the arrow keys, play, the toggles, the force
table and the speed box. The kernel is asked again only when something the scene cannot express changes — a length,
a mass, a load, the friction (:meth:`BrowserExplorer.set`) — and answers with a new scene. It works the same in
JupyterLab, Notebook 7 and Voilà.

ipywidgets and anywidget are imported only when a widget is built: ``import graphkin`` and
``import graphkin.widgets`` do not load them.

:func:`exercise` builds an :class:`ExerciseBox`: a box for the student's id, their data, a text box per question
and a Check button. :func:`draw_answer` builds a :class:`DrawingBox`: a drawn question the student draws with the
mouse or the keys and checks.

The package, one module per concern:

``browser``
    :func:`explore`, :class:`BrowserExplorer` (the scene in an anywidget), and ``set``'s fields.
``positions``
    Where a slider-driven problem whose file gives one position is explored: where its linkage assembles.
``exercise_box``
    :func:`exercise` and :class:`ExerciseBox`.
``drawing``
    :func:`draw_answer` and :class:`DrawingBox`: a drawn question answered by drawing (issue 38), checked in the
    kernel, the drawing kept as the answer output.

Examples
--------
>>> import graphkin as gk
>>> ex = gk.explore(gk.load("strip_cutter"))   # doctest: +SKIP
>>> ex                                          # in a notebook cell: the explorer  # doctest: +SKIP
>>> ex.position = 140                           # θ12 = 140° shown from Python  # doctest: +SKIP
>>> ex.set("mass.3", 4.0)                       # a new mass: a new scene  # doctest: +SKIP
"""

from graphkin.widgets.browser import BrowserExplorer, explore
from graphkin.widgets.drawing import DrawingBox, draw_answer
from graphkin.widgets.exercise_box import ExerciseBox, exercise

__all__ = ["BrowserExplorer", "DrawingBox", "ExerciseBox", "draw_answer", "exercise", "explore"]
