"""An exercise in a notebook: the student's id, their own data, a text box per question, and a Check button.

:func:`exercise` builds an :class:`ExerciseBox` for a catalog exercise or an
exercise file: the student types their id, reads the data of their own
variant (:func:`graphkin.exercises.variant`), types an answer per question
and checks them; the grading (:func:`graphkin.exercises.grading.grade_variant`)
is shown as feedback and kept as plain data.

ipywidgets is imported only when a box is built.
"""

from __future__ import annotations

from html import escape

from graphkin import exercises
from graphkin.errors import GraphkinError
from graphkin.exercises.grading import grade_variant
from graphkin.notation import citation, symbols_in
from graphkin.optional import require


def exercise(name, student: str = "", *, secret: str = ""):
    """An exercise in a notebook: a box for the student id, their data, one text box per question, a Check button.

    Parameters
    ----------
    name : str or graphkin.exercises.Exercise
        A catalog exercise (``graphkin exercise list``) or an exercise file.
    student : str
        The student's id (they can also type it in the box).
    secret : str
        The course secret, if the teacher set one.

    Returns
    -------
    ExerciseBox
        Display it in a cell; ``box.answers`` (question id → text box), ``box.check()``
        and ``box.report`` (the last grading as plain data) are there for tests.
    """
    return ExerciseBox(exercises.load(name), student, secret)


def html_text(text: str) -> str:
    """Plain exercise text as HTML, each symbol with its subscript as a handout sets it (F_ij: F, subscript ij).

    Examples
    --------
    >>> html_text("F_ij is the force of link i on link j; a_G3 < 1")
    '<i>F</i><sub>ij</sub> is the force of link i on link j; <i>a</i><sub>G3</sub> &lt; 1'
    """
    return "".join(escape(part) if isinstance(part, str) else
                   f"<i>{escape(part[0])}</i><sub>{escape(part[1])}</sub>{escape(part[2])}" for part in symbols_in(text))


class ExerciseBox:
    """The widgets of :func:`exercise`: the student types an id, reads their data, answers, and checks."""

    def __init__(self, exercise, student: str, secret: str):
        w = require("ipywidgets", "the exercise box")

        self.exercise, self.secret, self.report = exercise, secret, None
        self.student = w.Text(value=student, description="Your id", placeholder="e.g. your student number")
        self.data = w.HTML()
        self.answers = {q.id: w.Text(description=q.id, placeholder=q.unit or "number",
                                     layout=w.Layout(width="60%"), style={"description_width": "80px"})
                        for q in exercise.questions}
        self.asks = {q.id: w.HTML(f"<b>{q.id}</b>: {html_text(q.ask)}") for q in exercise.questions}
        self.button = w.Button(description="Check", button_style="primary")
        self.feedback = w.HTML()
        self.button.on_click(lambda _: self.check())
        self.student.observe(lambda _: self._show_data(), names="value")
        rows = [x for pair in zip(self.asks.values(), self.answers.values()) for x in pair]
        # The source in one line, as a sheet cites it: where the catalog read the book is the teacher's.
        cite = f"<div><i>{escape(citation(exercise.source))}</i></div>" if exercise.source else ""
        self.widget = w.VBox([w.HTML(f"<h4>{escape(exercise.title)}</h4>{cite}"), self.student, self.data, *rows,
                              self.button, self.feedback])
        self._show_data()

    def _ipython_display_(self):
        from IPython.display import display

        display(self.widget)

    def _show_data(self):
        student = self.student.value.strip()
        if not student:
            self.data.value = "<i>Type your id to get your own data.</i>"
            return
        try:
            sheet = exercises.variant(self.exercise, student, self.secret).sheet()
        except GraphkinError as exc:
            self.data.value = f"<span style='color:#b00'>{escape(str(exc))}</span>"
            return
        items = "".join(f"<li>{escape(g['shown'])}" + (f" ({escape(g['label'])})" if g["label"] else "")
                        for g in sheet["data"])
        self.data.value = f"<p>{html_text(sheet['intro'])}</p><p>Your data:</p><ul>{items}</ul>"
        # Each question as the student's sheet asks it, with how close an answer must be (as a sheet states it).
        for q in sheet["questions"]:
            self.asks[q["id"]].value = (f"<b>{escape(q['id'])}</b>: {html_text(q['ask'])} "
                                        f"<i>(within {escape(q['within'])})</i>")

    def check(self) -> dict | None:
        """Grade what is in the boxes and show the feedback; returns the report (plain data)."""
        student = self.student.value.strip()
        if not student:
            self.feedback.value = "<span style='color:#b00'>Type your id first.</span>"
            return None
        variant = exercises.variant(self.exercise, student, self.secret)
        self.report = grade_variant(variant, {k: box.value for k, box in self.answers.items()})
        colour = {"correct": "#070", "slip": "#a60"}
        rows = "".join(f"<li><b>{q['id']}</b> <span style='color:{colour.get(q['verdict'], '#b00')}'>{q['verdict']}"
                       f"</span> ({q['score']:g}/{q['max']:g}): {escape(q['feedback'])}</li>"
                       for q in self.report["questions"])
        self.feedback.value = f"<p>Score: {self.report['score']:g} / {self.report['max']:g}</p><ul>{rows}</ul>"
        return self.report
