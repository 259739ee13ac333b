"""``gk.explore(problem)`` in JupyterLab (issue 37): the browser draws the scene the kernel sent, with
no image from the kernel; a change the scene cannot express (a mass) is a new scene, drawn as Python built it; the
position set from Python is shown; the widget's keys are its own.

What is drawn is read back from the SVG and compared with the scene to 1e-6 of the mechanism's size, as
tests/e2e/test_scene_page.py does for the page.
"""

from __future__ import annotations

import json
import re
import time

import pytest

from graphkin import catalog
from graphkin.scene import scene, scene_json
from graphkin.widgets.browser import changed
from tests.e2e.test_browser import SHUT_DOWN, _no_widget_errors, _type_cell, _wait_ran
from tests.e2e.test_scene_page import READ_BACK, check_drawn

N = 36
NAME = "scene_widget.ipynb"
CELLS = ["import graphkin as gk\nex = gk.explore(gk.load('strip_cutter'), n=36)\nex"]
# The page's read-back, from the widget's own view (anywidget's element holds it, as the page's window does).
READ = READ_BACK.replace("window.graphkin.view.index", "document.querySelector('.gk-scene').parentElement.graphkin.index")
INDEX = "() => document.querySelector('.gk-scene').parentElement.graphkin.index"


def _notebook(cells) -> str:
    return json.dumps({"nbformat": 4, "nbformat_minor": 5, "metadata": {"kernelspec": {
        "name": "python3", "display_name": "Python 3", "language": "python"}},
        "cells": [{"cell_type": "code", "id": f"c{k}", "metadata": {}, "execution_count": None, "outputs": [],
                   "source": code} for k, code in enumerate(cells)]})


def _read(problem) -> dict:
    return json.loads(scene_json(scene(problem, N)))


def test_the_browser_draws_the_scene_and_the_kernel_answers_a_new_mass(browser, jupyterlab, workdir):
    (workdir / NAME).write_text(_notebook(CELLS), encoding="utf-8")
    context = browser.new_context(viewport={"width": 1400, "height": 900}, device_scale_factor=1)
    page = context.new_page()
    logs = []
    page.on("console", lambda m: logs.append(f"{m.type}: {m.text}"))
    page.on("pageerror", lambda e: logs.append(f"pageerror: {e}"))
    try:
        page.goto(f"{jupyterlab}/lab/tree/{NAME}?reset", wait_until="domcontentloaded")
        page.wait_for_selector(".jp-Notebook .jp-Cell", timeout=60_000)
        page.get_by_text(re.compile(r"\| Idle$")).first.wait_for(timeout=60_000)
        time.sleep(1.0)  # the kernel's connection settles after its first idle
        page.locator(".jp-Notebook .jp-Cell").first.click()
        page.keyboard.press("Escape")
        page.keyboard.press("Shift+Enter")
        _wait_ran(page, 1)
        try:
            page.wait_for_selector(".gk-scene svg.gk-mechanism", timeout=60_000)
        except Exception:
            page.screenshot(path=str(workdir.parent / "FAILED-lab-scene-widget.png"))
            output = page.locator(".jp-OutputArea").first.inner_text()
            pytest.fail(f"no scene drawn; the cell's output: {output[:500]!r}; the console: {logs[-10:]}")
        _no_widget_errors(page)
        assert page.locator(".jp-Notebook img").count() == 0  # no PNG from the kernel
        problem = catalog.load("strip_cutter")
        s = _read(problem)
        slider = page.locator(".gk-scene [data-do=position]")
        for i in (0, 9, N // 2):
            slider.fill(str(i))
            check_drawn(page.evaluate(READ), s, i)
        # A new mass: the kernel sends a new scene, drawn as Python builds it; the position comes from Python.
        count = _type_cell(page, "ex.set('mass.3', 4.0); ex.index = 7", 1)
        page.wait_for_function(INDEX + " === 7", timeout=30_000)
        check_drawn(page.evaluate(READ), _read(changed(problem, "mass.3", 4.0)), 7)
        # The arrow keys are the widget's once it has the focus; typed in a cell they are the cell's.
        page.evaluate("() => document.querySelector('.gk-scene').focus()")
        page.keyboard.press("ArrowRight")
        assert page.evaluate(INDEX) == 8
        _type_cell(page, "x = 1", count)
        page.keyboard.press("ArrowRight")
        assert page.evaluate(INDEX) == 8
        _no_widget_errors(page)
        page.screenshot(path=str(workdir.parent / "lab-scene-widget.png"))
        for session in json.loads(page.evaluate("() => fetch('/api/sessions').then(r => r.text())")):
            assert page.evaluate(SHUT_DOWN, session["id"]) == 204
    finally:
        context.close()
