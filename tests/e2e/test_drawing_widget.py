"""The drawn answer widget in JupyterLab (issue 38): ``gk.draw_answer`` of a catalog exercise's drawn question; the
student draws with the mouse, presses Check, the kernel grades (the exercise's grader) and the browser shows the
verdict and marks the element at fault on the drawing; the drawing is the answer output beneath the widget (updated
from the widget's comm messages by display id), saved with the notebook, and there again after a reload.
"""

from __future__ import annotations

import json
import math
import re
import time

import pytest

from graphkin import exercises
from graphkin.exercises.drawn_tasks import task_of
from tests.e2e.conftest import ROOT
from tests.e2e.test_browser import SHUT_DOWN, _no_widget_errors, _wait_ran
from tests.e2e.test_scene_widget import _notebook
from tests.scene.drawn_fixtures import on_line

NAME = "drawing_widget.ipynb"
EXERCISE, QUESTION, STUDENT = "draw_strip_cutter", "R3i", "s001"
CELL = (f"import sys\nsys.path.insert(0, {str(ROOT)!r})  # this tree's graphkin\nimport graphkin as gk\n"
        f"box = gk.draw_answer({EXERCISE!r}, {QUESTION!r}, {STUDENT!r})\nbox")
VIEW = "document.querySelector('.gk-draw').parentElement.parentElement.graphkin"
MIME = "application/vnd.graphkin.drawing+json"
TEXT = ".jp-RenderedText[data-mime-type='text/plain']"  # the answer output (the widget shows its line too)


def _open(page, url):
    page.goto(url, wait_until="domcontentloaded")
    page.wait_for_selector(".jp-Notebook .jp-Cell", timeout=60_000)
    page.get_by_text(re.compile(r"\| Idle$")).first.wait_for(timeout=60_000)


def test_the_widget_draws_checks_and_keeps_the_drawing_through_save_and_reload(browser, jupyterlab, workdir, out):
    (workdir / NAME).write_text(_notebook([CELL]), encoding="utf-8")
    context = browser.new_context(viewport={"width": 1400, "height": 1000}, device_scale_factor=1)
    page = context.new_page()
    logs = []
    page.on("console", lambda m: logs.append(f"{m.type}: {m.text}"))
    try:
        _open(page, f"{jupyterlab}/lab/tree/{NAME}?reset")
        time.sleep(1.0)  # the kernel's connection settles after its first idle
        page.locator(".jp-Notebook .jp-Cell").first.click()
        page.keyboard.press("Escape")
        page.keyboard.press("Shift+Enter")
        _wait_ran(page, 1)
        try:
            page.wait_for_selector(".gk-draw svg.gk-draw-svg", timeout=60_000)
        except Exception:
            page.screenshot(path=str(out / "FAILED-lab-drawing-widget.png"))
            pytest.fail(f"no drawing; the output: {page.locator('.jp-OutputArea').first.inner_text()[:500]!r}; "
                        f"the console: {logs[-10:]}")
        _no_widget_errors(page)
        # The right line, where the grader's target is (the second click snaps to F3i's direction).
        task = task_of(exercises.variant(exercises.load(EXERCISE), STUDENT, ""), QUESTION, practice=True)
        targets = {t["slip"]: t["elements"][0]["through"] for t in task["check"]["targets"]}
        a, b = on_line(task, *targets[None])
        page.locator(".gk-draw svg").scroll_into_view_if_needed()
        for p in (a, b):
            page.mouse.click(*page.evaluate(f"(p) => {VIEW}.toScreen(p)", list(p)))
        # The answer output under the widget follows the drawing, from the widget's comm message.
        answer = page.locator(TEXT, has_text='"kind":"line"')
        answer.wait_for(timeout=30_000)
        line = answer.inner_text().strip()
        drawn = json.loads(line.split(" = ", 1)[1].strip("'"))
        (e,) = drawn["elements"]
        assert e["kind"] == "line" and math.dist(e["through"][0], a) < 1e-3  # 0.1 mm of drawing at 1:10
        page.locator(".gk-draw [data-do=check]").click()
        page.wait_for_selector(".gk-verdict[data-verdict=correct]", timeout=30_000)
        # A line through G3 is the slip the grader names; the drawn line is marked, and the right one is not shown
        # (the exercise does not reveal answers).
        page.locator(".gk-draw [data-do=clear]").click()
        for p in on_line(task, *targets["through_G"]):
            page.mouse.click(*page.evaluate(f"(p) => {VIEW}.toScreen(p)", list(p)))
        page.locator(".gk-draw [data-do=check]").click()
        page.wait_for_selector(".gk-verdict[data-verdict=slip]", timeout=30_000)
        assert "through g" in page.locator(".gk-draw-feedback").inner_text().lower()
        assert page.locator(".gk-draw .gk-fault").count() == 1
        assert page.locator(".gk-draw .gk-right line").count() == 0
        page.locator(".gk-draw [data-do=undo]").click()  # back to one point of the line...
        page.mouse.click(*page.evaluate(f"(p) => {VIEW}.toScreen(p)", list(b)))  # ...and to a point of the right one
        page.wait_for_function(f"() => {VIEW}.drawing().elements.length === 1")
        kept = page.evaluate(f"() => {VIEW}.drawing()")
        tip = json.dumps(kept["elements"][0]["through"][1], separators=(",", ":"))
        page.wait_for_function("(t) => [...document.querySelectorAll(\"" + TEXT + "\")].some("
                               "e => e.innerText.includes(t))", arg=tip, timeout=30_000)
        # Saved: the notebook on disk holds the drawing in the answer output.
        page.locator(".jp-Notebook").first.click(position={"x": 5, "y": 5})
        page.keyboard.press("Control+s")
        saved = None
        for _ in range(50):
            nb = json.loads((workdir / NAME).read_text(encoding="utf-8"))
            outputs = [o for o in nb["cells"][0]["outputs"] if MIME in o.get("data", {})]
            if outputs and outputs[0]["data"][MIME]["elements"]:
                saved = outputs[0]["data"]
                break
            time.sleep(0.2)
        assert saved is not None, "the saved notebook has no drawing"
        assert saved[MIME]["elements"] == kept["elements"]
        assert "".join(saved["text/plain"]).startswith(QUESTION + " = '{")  # nbformat keeps text as lines
        # ... and the platforms' reader reads it from the file as the answer, graded as the widget graded it.
        from graphkin.exercises.notebooks import answer_variables, notebook_answers

        v = exercises.variant(EXERCISE, STUDENT)
        _, answers = notebook_answers(nb, answer_variables([q.id for q in v.exercise.questions]))
        assert json.loads(answers[QUESTION])["elements"] == kept["elements"]
        # Reloaded (the kernel still runs): the widget shows the same drawing, and the output holds it.
        page.reload(wait_until="domcontentloaded")
        page.wait_for_selector(".gk-draw svg.gk-draw-svg", timeout=60_000)
        assert page.evaluate(f"() => {VIEW}.drawing().elements") == kept["elements"]
        assert page.locator(TEXT, has_text=QUESTION + " = '{").count() == 1
        _no_widget_errors(page)
        # The keys are the drawing's while it has the focus: Ctrl+Z undoes its last point, Tab goes to a snap point
        # and Enter places it; the notebook gets none of them (no cell added, none run, no undo of a cell).
        cells = page.locator(".jp-Notebook .jp-Cell").count()
        page.locator(".gk-draw svg").focus()
        page.keyboard.press("Control+z")
        page.keyboard.press("Tab")
        assert "snaps to" in page.locator(".gk-draw-status").inner_text()
        page.keyboard.press("Enter")
        after = page.evaluate(f"() => {VIEW}.drawing().elements")
        assert len(after) == 1 and after[0]["through"][0] == kept["elements"][0]["through"][0]
        snap = task["snap"]["points"][0]["at"]  # snapped, to the thousandth of a mm of drawing the answer keeps
        assert math.dist(after[0]["through"][1], snap) <= 1e-3 * task["scale"]["si_per_mm"]
        assert page.locator(".jp-Notebook .jp-Cell").count() == cells
        page.screenshot(path=str(out / "lab-drawing-widget.png"))
        for session in json.loads(page.evaluate("() => fetch('/api/sessions').then(r => r.text())")):
            assert page.evaluate(SHUT_DOWN, session["id"]) == 204
    finally:
        context.close()
