"""The explorer's frames: a position drawn, the frames kept, and the positions next to the one shown drawn ahead.

A :class:`Frame` is what the explorer's widgets show at one position: the
PNG, both solutions, the status line and the force table. While the kernel is
idle, :class:`DrawingAhead` draws the positions next to the one shown
(``ahead`` steps either side, the way the slider last moved first) and keeps
the frames (:data:`FRAMES` at most): an arrow key that reaches one shows that
finished frame at once, well under a millisecond where drawing it takes
30–200 ms.

A drawing is a generator (:meth:`~graphkin.widgets.explorer.Explorer._drawing`):
one step draws one panel, the rendering or the PNG. Drawn ahead, one step runs
at a time, and the kernel's event loop runs between two (:data:`STEP`), so a
key press is read and answered before the next step; drawn when asked, the
steps run to the end at once (:func:`to_the_end`).

:class:`DrawingAhead` is a mixin of :class:`~graphkin.widgets.explorer.Explorer`
rather than a helper object: it runs on the explorer's own event loop and
thread, it gives way to a value from the browser that is waiting to be drawn
(the explorer's pending timer), it draws on the explorer's one figure (whose
position, ``_figure_at``, it leaves unknown when it stops half way), and its
loop callback is looked up on the explorer each time it is scheduled
(``benchmarks/bench_explorer.py`` times ``ex._draw_ahead``).
"""

from __future__ import annotations

import collections
import dataclasses
import logging

_log = logging.getLogger(__name__)

RC = {"text.hinting": "no_hinting"}
"""matplotlib settings while the explorer draws and renders."""

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
    motion : MotionConstruction or None
        The velocity and acceleration polygons drawn (None when they are not shown).
    """

    value: float
    png: bytes
    construction: object
    analytical: object
    message: str
    status: str
    table: str
    motion: object = None


def _step(steps):
    """One step of a drawing (a generator), with the explorer's matplotlib settings around it only."""
    import matplotlib

    # Unhinted glyphs lay out and render about a quarter faster, and look the same at this size.
    with matplotlib.rc_context(RC):
        next(steps)


def to_the_end(steps):
    """The rest of a drawing (a generator) at once, with the explorer's matplotlib settings; returns its frame."""
    import matplotlib

    with matplotlib.rc_context(RC):
        while True:
            try:
                next(steps)
            except StopIteration as done:
                return done.value


class DrawingAhead:
    """The frames an :class:`~graphkin.widgets.explorer.Explorer` keeps, and its drawing ahead (a mixin).

    The explorer calls :meth:`_init_drawing_ahead` once, :meth:`_keep` with
    each frame it draws, :meth:`_take` with a position from the browser,
    :meth:`_plan_ahead` after it shows a position, :meth:`_abandon` before it
    draws on the figure itself, and :meth:`_on_new_layout` when it lays the
    figure out anew.

    The explorer provides: ``value``, ``step`` and ``ahead`` (see
    :func:`~graphkin.widgets.explorer.explore`); ``_heading`` (the way the
    slider last moved: +1 or -1); ``_snap`` and ``_same`` (a position on the
    slider's step; two positions the same); ``_loop()`` (the running event
    loop, or None); ``_timer`` (the pending draw of a value from the browser, or
    None); ``_drawing(value)`` (a position's drawing, a generator that returns
    its :class:`Frame`); ``_present(frame)``; ``_cancel()`` and ``_later()``
    (drop, or set, the pending draw); and ``_figure_at``, the position the
    figure shows (None: none, or half drawn).
    """

    def _init_drawing_ahead(self):
        self._frames: collections.OrderedDict = collections.OrderedDict()  # position -> Frame, drawn
        self._ahead_handle = None  # the pending step of drawing ahead
        self._ahead_job = None  # (position, its drawing's steps) being drawn ahead
        self._new_layout = True  # no frame drawn ahead since the layout was made (see SHOWN)
        self._failed: set = set()  # positions whose drawing ahead failed (drawn when asked, the error shown then)

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

    def _on_new_layout(self):
        """The figure is laid out anew: its frames are dropped, and drawing ahead waits :data:`SHOWN`."""
        job = self._ahead_job
        if job is not None and not job[1].gi_running:
            self._abandon()  # it draws on the old axes (unless it is what needs the new layout)
            if self._ahead_handle is not None:
                self._ahead_handle.cancel()
                self._ahead_handle = None
        self._failed.clear()
        self._frames.clear()  # drawn for the old layout
        self._figure_at = None
        self._new_layout = True

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
            return to_the_end(steps)
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
