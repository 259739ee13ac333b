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

``explore(problem, browser=True)`` builds a
:class:`~graphkin.widgets.browser.BrowserExplorer` instead: the browser draws every position of a presolved cycle
with the module of ``graphkin explore -o page.html`` (an anywidget), and the kernel answers only a change the scene
cannot express (``set("mass.3", 4.0)``) with a new scene. It is not yet the default: the lessons and their browser
tests read the PNG explorer's widgets.

ipywidgets, anywidget, matplotlib and PIL are imported only when an explorer is built:
``import graphkin`` and ``import graphkin.widgets`` do not load them.

:func:`exercise` builds an :class:`ExerciseBox`: a box for the student's id,
their data, a text box per question and a Check button.

The package, one module per concern:

``explorer``
    :func:`explore` and :class:`Explorer`: the controls' behaviour, what the
    browser sends (echoes, bursts, the thread a message is answered on) and
    each update.
``browser``
    :class:`BrowserExplorer`: the scene in an anywidget, and ``set``'s fields.
``controls``
    The widgets: the position's slider and box (whole degrees, or a round
    step over the span where a slider-driven linkage assembles), the speed,
    the status line, the force table, the image, and the probe of the screen.
``canvas``
    The figure (:class:`~graphkin.widgets.canvas.Canvas`): its layout for the
    screen, the torque curve, a position drawn panel by panel, the rendering
    and the PNG; and the HTML force table.
``frames``
    :class:`Frame` (one position drawn) and the drawing ahead: the frames
    kept, the neighbours of the position shown, and the step-at-a-time
    drawing while the kernel is idle.
``threads``
    The explorer's thread: a message ipykernel handles on another thread is
    answered on the explorer's own.
``exercise_box``
    :func:`exercise` and :class:`ExerciseBox`.

The settings (:data:`SETTLE`, :data:`AHEAD`, :data:`CSS_DPI`, ...) are
importable from here and are read in the module that defines them: to change
one, set it there (``graphkin.widgets.explorer.SETTLE``).

Examples
--------
>>> from graphkin import catalog
>>> from graphkin.widgets import explore
>>> ex = explore(catalog.load("strip_cutter"))   # doctest: +SKIP
>>> ex                                            # in a notebook cell: the explorer  # doctest: +SKIP
>>> ex.slider.value = 140                         # θ12 = 140°: redraws  # doctest: +SKIP
>>> ex.analytical["T12"], ex.construction.effort  # doctest: +SKIP
"""

from graphkin.widgets.browser import BrowserExplorer
from graphkin.widgets.canvas import CELL_ASPECT, CSS_DPI, FIGURE_WIDTH, MIN_PT, NCOLS, PAGE_WIDTH
from graphkin.widgets.exercise_box import ExerciseBox, exercise
from graphkin.widgets.explorer import ECHOES, LIVE, SETTLE, Explorer, explore
from graphkin.widgets.frames import AHEAD, FRAMES, IDLE, MOST_AHEAD, RC, SHOWN, STEP, Frame

__all__ = ["AHEAD", "BrowserExplorer", "CELL_ASPECT", "CSS_DPI", "ECHOES", "FIGURE_WIDTH", "FRAMES", "IDLE", "LIVE", "MIN_PT",
           "MOST_AHEAD", "NCOLS", "PAGE_WIDTH", "RC", "SETTLE", "SHOWN", "STEP", "ExerciseBox", "Explorer", "Frame",
           "exercise", "explore"]
