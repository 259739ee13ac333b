"""A drawn answer in a notebook (issue 38): ``gk.draw_answer(exercise, question_id, student)``.

The student draws the construction a drawn question asks for (the task of
:func:`graphkin.exercises.drawn_tasks.task_of`, drawn by the browser's ``draw.js`` in an anywidget) and presses
Check: the kernel grades the drawing with the exercise's grader
(:func:`graphkin.exercises.grading.grade_question`) and the browser draws the feedback back on the student's own
drawing (the element at fault in red, the right one dashed where the exercise reveals answers).

Where the drawing is kept. The platforms' notebook reader (:mod:`graphkin.exercises.notebooks`) reads answer
variables assigned a string literal in code cells. A widget cannot write a code cell's source (the notebook's
editor belongs to JupyterLab; neither the kernel nor an anywidget's module may change it), so the drawing is kept
two ways, both tried in JupyterLab 4.6 in Chromium (tests/e2e/test_drawing_widget.py):

- **The answer output.** Displaying the box displays, under the drawing, one more output with a ``display_id``:
  its ``text/plain`` is the answer line (``line3 = '{"drawing": 1, ...}'``) and its
  ``application/vnd.graphkin.drawing+json`` the drawing as data. Every change of the drawing (a comm message from
  the browser) updates it with ``IPython.display.update_display``. JupyterLab routes that ``update_display_data``
  to the cell's output area by its display id although its parent is the comm message, not the cell's execution
  (the kernel connection keeps each display id's parent executions, and a cell's execution is not disposed when it
  ends); the notebook saved then holds the drawing in that output, and it is there after a reload. The notebook
  reader (:func:`graphkin.exercises.notebooks.code_sources`) reads the answer line of every output of that MIME
  type after its cell's own text, as data: a saved notebook's drawing is graded on every notebook platform.
- **The answer line in a cell.** The widget shows the same line with a Copy button: pasted into the answer cell it
  is a string literal the reader reads. ``gk.draw_answer(..., drawing=line3)`` puts a drawing back in the
  widget (after a kernel restart, say).

A kernel that still runs keeps the widget's drawing itself: a reloaded page shows it again.

anywidget and traitlets are imported only when a box is built.
"""

from __future__ import annotations

import functools
import json

from graphkin import exercises
from graphkin.errors import GraphkinError
from graphkin.exercises.drawn_tasks import task_of
from graphkin.exercises.grading import grade_question
from graphkin.exercises.notebooks import DRAWING_MIME, answer_variables
from graphkin.optional import require
from graphkin.scene.page import DRAW_MODULES, asset, module

MIME = DRAWING_MIME
"""The answer output's MIME type: the drawing as data (docs/json.md, "Drawn answers"); the notebook reader reads the
answer line of each output that carries it (:func:`graphkin.exercises.notebooks.code_sources`)."""

FEEDBACK = ("verdict", "slip", "score", "max", "feedback", "fault", "right")
"""What of a grading the browser draws back (docs/json.md, "Drawn answers": Feedback)."""


@functools.cache
def drawing_widget():
    """The class of the widget: anywidget's, with the drawing's module as its ``_esm``; ``task`` (JSON, from the
    kernel), ``drawing`` (JSON, from the browser), ``asked`` (counts the Check presses), ``feedback`` (JSON, from the
    kernel) and ``line`` (the answer line, from the kernel)."""
    anywidget = require("anywidget", "gk.draw_answer(...)")
    import traitlets

    class DrawingWidget(anywidget.AnyWidget):
        _esm = module(DRAW_MODULES)
        _css = asset("draw.css")
        task = traitlets.Unicode("").tag(sync=True)
        drawing = traitlets.Unicode("").tag(sync=True)
        asked = traitlets.Int(0).tag(sync=True)
        feedback = traitlets.Unicode("").tag(sync=True)
        line = traitlets.Unicode("").tag(sync=True)

    return DrawingWidget


def draw_answer(exercise, question_id: str, student: str, *, secret: str = "", drawing=None):
    """A drawn question of an exercise in a notebook: the student draws, checks, and keeps the drawing as the answer.

    Parameters
    ----------
    exercise : str or graphkin.exercises.Exercise
        A catalog exercise or an exercise file.
    question_id : str
        The drawn question's id (``line3``, …).
    student : str
        The student's id: the variant drawn is theirs.
    secret : str
        The course secret, if the teacher set one.
    drawing : str or dict, optional
        A drawing to start from (the answer line's text, or the drawing as data).

    Returns
    -------
    DrawingBox
        Display it in a cell.
    """
    if not str(student).strip():
        raise GraphkinError("draw_answer: give the student's id (the variant drawn is theirs)")
    variant = exercises.variant(exercises.load(exercise), str(student).strip(), secret)
    qs = [q for q in variant.exercise.questions if q.id == question_id]
    if not qs:
        raise GraphkinError(f"draw_answer: the exercise has no question {question_id!r} "
                            f"({', '.join(q.id for q in variant.exercise.questions)})")
    reveal = variant.exercise.reveal  # the right construction drawn back only where the teacher reveals answers
    variable = answer_variables([q.id for q in variant.exercise.questions])[question_id]
    return DrawingBox(task_of(variant, question_id),
                      lambda text: grade_question(variant, qs[0], text, reveal=reveal), drawing=drawing,
                      variable=variable)


class DrawingBox:
    """The widget of :func:`draw_answer`, and the answer output beneath it.

    Parameters
    ----------
    task : dict
        The drawn task (docs/json.md, "Drawn answers"), without its ``check``.
    grade : callable
        The grader: given the drawing's text, the grading (a dict with at least ``verdict`` and ``feedback``).
    drawing : str or dict, optional
        A drawing to start from.
    variable : str, optional
        The notebook variable the answer line assigns (:func:`graphkin.exercises.notebooks.answer_variables`);
        default the question's id.

    Attributes
    ----------
    widget : anywidget.AnyWidget
    report : dict or None
        The last grading, as the grader gave it.
    """

    def __init__(self, task: dict, grade, *, drawing=None, variable: str | None = None):
        if task.get("check"):
            raise GraphkinError("draw_answer: a graded task must not carry its targets ('check' is for practice)")
        self.task, self.grade, self.report = task, grade, None
        self.question = task["question"]
        self.variable = variable or task["question"]
        self.widget = drawing_widget()(task=json.dumps(task))
        self._handle = None
        if drawing is not None:
            self.widget.drawing = drawing if isinstance(drawing, str) else json.dumps(drawing)
        self._changed()
        self.widget.observe(lambda _: self._changed(), names="drawing")
        self.widget.observe(lambda _: self.check(), names="asked")

    @property
    def text(self) -> str:
        """The drawing as the answer's text (compact JSON), or ``""`` before anything is drawn."""
        return self.widget.drawing

    @property
    def line(self) -> str:
        """The answer line for the answer cell: ``variable = '<the drawing as JSON>'``."""
        return f"{self.variable} = {self.text!r}"

    def _bundle(self) -> dict:
        data = {"text/plain": self.line}
        if self.text:
            data[MIME] = json.loads(self.text)
        return data

    def _changed(self) -> None:
        self.widget.feedback = ""  # a grading is of the drawing it graded
        self.widget.line = self.line
        if self._handle is not None:
            self._handle.update(self._bundle(), raw=True)

    def check(self) -> dict:
        """Grade the drawing and send the feedback to the browser; returns the grading."""
        self.report = self.grade(self.text)
        shown = {k: self.report.get(k) for k in FEEDBACK if k in self.report}
        self.widget.feedback = json.dumps(shown)
        return self.report

    def _ipython_display_(self):
        from IPython.display import display

        display(self.widget)
        self._handle = display(self._bundle(), raw=True, display_id=True)
