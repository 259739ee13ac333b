"""The explorer's widgets: the position's slider and box, the speed, the status line, the force table, the image.

A crank's slider and box move in whole degrees over 0–360°
(:func:`degree_controls`); a slider driver's in a round step (:func:`nice_step`)
over the problem's own positions, or where its linkage assembles
(:func:`assembling_span`). The numeric box beside the slider is its readout.

Each widget carries a CSS class (``graphkin-explorer``, ``graphkin-position``,
``graphkin-position-box``, ``graphkin-speed``, ``graphkin-status``,
``graphkin-table``, ``graphkin-image``, ``graphkin-screen``) for the browser
test. The hidden probe ``graphkin-screen`` (:func:`screen_probe`, an
anywidget) reports the screen's pixel ratio and the width the page gives the
explorer through its own widget messages (no script is injected into the
page).

ipywidgets and anywidget are imported inside the functions that make
widgets: importing this module does not load them.
"""

from __future__ import annotations

import dataclasses
import functools
import math

import numpy as np

from graphkin.errors import GraphkinError


def _link_size(link) -> float:
    pts = np.array(list(link.points.values()), float).reshape(-1, 2)
    if len(pts) < 2:
        return 0.0
    return float(np.max(np.hypot(*(pts[:, None, :] - pts[None, :, :]).transpose(2, 0, 1))))


def assembling_span(problem, q0: float, n: int) -> tuple[float, float]:
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


def nice_step(x: float) -> float:
    """The largest 1, 2 or 5 × 10^k not above ``x`` (a slider step a person reads at a glance)."""
    base = 10.0 ** math.floor(math.log10(x))
    for m in (5.0, 2.0, 1.0):
        if m * base <= x * (1 + 1e-9):
            return float(f"{m * base:.12g}")
    return float(f"{base:.12g}")  # pragma: no cover  (1 × base ≤ x always)


@functools.cache
def degree_controls():
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


PROBE_ESM = """
function render({ model, el }) {
  // The screen's pixel ratio and the width the page gives the explorer (the parent of its box), told to
  // the kernel as the probe's own state, and again when that width changes.
  let tries = 0, wait = null, observer = null;
  function report(host) {
    const width = Math.round(host.getBoundingClientRect().width);
    const said = JSON.stringify({ ratio: window.devicePixelRatio || 1, width: width });
    el.dataset.said = said;
    if (width > 0 && model.get("screen") !== said) {
      model.set("screen", said);
      model.save_changes();
    }
  }
  function start() {
    const root = el.closest(".graphkin-explorer");
    const host = root && root.parentElement;
    if (!host) {
      if (tries++ < 100) setTimeout(start, 100);  // not in the page yet
      return;
    }
    report(host);
    if (window.ResizeObserver) {
      observer = new ResizeObserver(() => { clearTimeout(wait); wait = setTimeout(() => report(host), 250); });
      observer.observe(host);
    }
  }
  start();
  return () => { if (observer) observer.disconnect(); clearTimeout(wait); };
}
export default { render };
"""
"""The probe's script: an anywidget module that reports the screen through the widget's own state."""


@functools.cache
def screen_probe():
    """The class of the explorer's screen probe: a widget with a ``screen`` trait its script writes.

    Its script (:data:`PROBE_ESM`) runs in the browser as the widget's own
    module (anywidget): the screen's pixel ratio and the width the page gives
    the explorer reach the kernel as a change of ``screen`` (JSON text), by the
    widget's own messages.
    """
    import anywidget
    import traitlets

    class ScreenProbe(anywidget.AnyWidget):
        _esm = PROBE_ESM
        screen = traitlets.Unicode("").tag(sync=True)

    return ScreenProbe


def snap(value: float, limits: tuple[float, float], step: float) -> float:
    """``value`` on the slider's step, inside its range (whole degrees for a crank)."""
    lo, hi = limits
    value = min(max(float(value), lo), hi)
    k = round((value - lo) / step)
    return float(f"{min(lo + k * step, hi):.12g}")


@dataclasses.dataclass(frozen=True, slots=True)
class Controls:
    """The explorer's widgets (see :class:`~graphkin.widgets.explorer.Explorer`), and the position's range.

    Attributes
    ----------
    limits : (float, float)
        The slider's range [deg or mm].
    step : float
        The slider's step [deg or mm].
    value : float
        The problem's own position [deg or mm], on the step.
    slider, box, speed, image, status, table : ipywidgets.DOMWidget
    motion : ipywidgets.Checkbox
        Show the velocity and acceleration polygons (off at first: drawing them costs each position more).
    screen : ScreenProbe
        Hidden: its ``screen`` is the screen's pixel ratio and the page's width, as the browser reports them.
    widget : ipywidgets.VBox
        Everything, for display.
    """

    limits: tuple[float, float]
    step: float
    value: float
    slider: object
    box: object
    speed: object
    image: object
    status: object
    table: object
    screen: object
    widget: object
    motion: object = None


def make_controls(problem, at_speed, n: int, limits=None) -> Controls:
    """The explorer's widgets for a problem, the slider at the problem's own position.

    Parameters
    ----------
    problem : graphkin.problem.Problem
        The problem as given: its position, speed, and whether it gives its own
        kinematics (the speed box is then fixed).
    at_speed : graphkin.problem.Problem
        The same problem at a constant speed: where a slider driver's linkage
        assembles is searched on it.
    n : int
        Positions of the torque curve: a slider driver's step is a round ``range / n``.
    limits : (float, float), optional
        A slider driver's range [mm] (see :func:`~graphkin.widgets.explorer.explore`).

    Returns
    -------
    Controls
    """
    import ipywidgets as W

    q0 = float(problem.q[0])
    q_dot0 = float(problem.q_dot[0])
    if problem.mechanism.driver.crank:
        Slider, Box = degree_controls()
        limits = (0.0, 360.0)
        step = 1.0
        value = float(round(math.degrees(q0) % 360.0))
        slider = Slider(value=value, min=0, max=360, step=1, description="θ (deg)")
        box = Box(value=value, min=0, max=360, step=1)
        speed = W.FloatText(value=round(q_dot0 * 30.0 / math.pi, 6), description="speed (rpm)")
    else:
        if limits is None:
            lo, hi = float(np.min(problem.q)), float(np.max(problem.q))
            if hi - lo < 1e-9:
                lo, hi = assembling_span(at_speed, q0, n)
            step = nice_step((hi - lo) * 1e3 / n)
            # Rounded out to the step, the grid holds the round numbers (200 mm, −120 mm).
            lo = math.floor(round(lo * 1e3 / step, 6)) * step
            hi = math.ceil(round(hi * 1e3 / step, 6)) * step
        else:
            lo, hi = map(float, limits)
            if not hi > lo:
                raise GraphkinError(f"limits must be (low, high) with high > low [mm], got {limits!r}")
            step = nice_step((hi - lo) / n)
        limits = (float(f"{lo:.12g}"), float(f"{hi:.12g}"))
        value = snap(q0 * 1e3, limits, step)
        slider = W.FloatSlider(value=value, min=limits[0], max=limits[1], step=step, description="s (mm)")
        box = W.BoundedFloatText(value=value, min=limits[0], max=limits[1], step=step)
        speed = W.FloatText(value=q_dot0, description="speed (m/s)")
    # The box beside the slider is the readout: large, and a person can type in it.
    slider.readout = False
    slider.continuous_update = True
    slider.layout = W.Layout(flex="1 1 auto", width="auto", min_width="60%")
    box.layout = W.Layout(width="7em")
    slider.style.description_width = "initial"
    speed.style.description_width = "initial"
    speed.layout = W.Layout(width="15em", flex="0 0 auto")
    speed.disabled = bool(problem.given)

    image = W.Image(format="png", layout=W.Layout(max_width="100%", height="auto"))
    status = W.HTML(layout=W.Layout(flex="1 1 auto"))
    table = W.HTML()
    screen = screen_probe()(layout=W.Layout(display="none"))
    motion = W.Checkbox(value=False, description="velocity and acceleration polygons", indent=False,
                        layout=W.Layout(width="auto", flex="0 0 auto"))
    for widget, name in ((slider, "position"), (box, "position-box"), (speed, "speed"),
                         (status, "status"), (table, "table"), (image, "image"),
                         (screen, "screen"), (motion, "motion")):
        widget.add_class(f"graphkin-{name}")  # for the browser test and for the probe
    widget = W.VBox([W.HBox([slider, box], layout=W.Layout(width="100%", align_items="center")),
                     W.HBox([speed, motion, status], layout=W.Layout(width="100%", align_items="center")),
                     table, image, screen])
    widget.add_class("graphkin-explorer")
    return Controls(limits, step, value, slider, box, speed, image, status, table, screen, widget, motion)
