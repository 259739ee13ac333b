"""A drawn exercise exported to PrairieLearn, drawn with the mouse in Chromium and graded by its own server.py.

PrairieLearn itself does not run here. What it does with the export is done as its documentation says: server.py's
``generate`` fills ``data`` (through the export's own ``check_question.py``, which loads server.py as PrairieLearn
does, in a process of its own); ``question.html`` is rendered with Mustache (chevron, the Python implementation of
the template language
PrairieLearn renders questions with) — the question panel without the ``pl-submission-panel`` parts, the submission
panel with those parts only — and served over HTTP with the export's ``clientFilesCourse`` at
``options.client_files_course_url``. The student draws with the mouse; the page's form fields are what PrairieLearn
would post (``raw_submitted_answers``); server.py's ``parse`` and ``grade`` grade them; the submission panel is
rendered with the feedback and must draw it back on the submitted drawing: the verdict, and the element at fault.
"""

from __future__ import annotations

import functools
import http.server
import json
import re
import subprocess
import sys
import threading

import pytest

from graphkin.exercises import task_of, variant
from graphkin.exercises.platforms import export

chevron = pytest.importorskip("chevron", reason="make e2e installs it (the e2e extra)")

NAME = "draw_strip_cutter"
SEED = 7
PANEL = re.compile(r"<pl-submission-panel>.*?</pl-submission-panel>", re.S)


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):  # the test's output is its own lines, not one per request
        pass


SERVER = """
import json, sys
sys.path.insert(0, sys.argv[1])
import check_question
fn, data = json.load(sys.stdin)
if fn == "pl_data":
    data = check_question.pl_data(data)
else:
    check_question.load_server()[fn](data)
json.dump(data, sys.stdout)
"""


def call(root, fn: str, data):
    """server.py's ``fn(data)`` in a process of its own, as PrairieLearn runs it: the export's ``check_question``
    puts the course's copy of graphkin first on that process's path, never on the tests'."""
    out = subprocess.run([sys.executable, "-c", SERVER, str(root)], input=json.dumps([fn, data]), text=True,
                         capture_output=True, cwd=root, timeout=300)
    assert out.returncode == 0, out.stderr[-2000:]
    return json.loads(out.stdout)


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    """The export and an HTTP server for its pages."""
    root = tmp_path_factory.mktemp("pl")
    export(NAME, "prairielearn", root)
    handler = functools.partial(_Quiet, directory=str(root))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    yield root, f"http://127.0.0.1:{httpd.server_address[1]}"
    httpd.shutdown()


def render(root, data, url, panel):
    """question.html as PrairieLearn renders one panel of it, in a page with the question's form."""
    template = (root / "questions" / NAME / "question.html").read_text(encoding="utf-8")
    if panel == "question":
        template = PANEL.sub("", template)
    else:  # the submission panel: its parts only, with the module that draws them
        template = "\n".join(PANEL.findall(template) + re.findall(r"<(?:link|script) [^>]*(?:></script>|>)", template))
    context = {**data, "options": {**data["options"], "client_files_course_url": f"{url}/clientFilesCourse"}}
    body = chevron.render(template, context)
    page = f'<!doctype html><meta charset="utf-8"><form id="question-form">{body}</form>'
    path = root / f"{panel}.html"
    path.write_text(page, encoding="utf-8")
    return f"{url}/{path.name}"


def draw(page, box, element):
    """Click the element's points where the box's view puts them on screen."""
    points = element.get("through") or ([element["at"]] if "at" in element else [element["from"], element["to"]])
    for p in points:
        x, y = box.evaluate("(b, p) => b.graphkin.toScreen(p)", list(p))
        page.mouse.click(x, y)


def test_a_drawn_question_is_drawn_submitted_and_graded_by_server_py(browser, course, out):
    root, url = course
    data = call(root, "generate", call(root, "pl_data", SEED))
    # A graded page's tasks carry no targets: the page cannot tell right from wrong.
    assert all(json.loads(t)["check"] is None for t in data["params"]["tasks"].values())
    v = variant(NAME, data["params"]["student"])
    right = {q.id: task_of(v, q.id, practice=True)["check"]["targets"] for q in v.exercise.questions}
    page = browser.new_page(viewport={"width": 1200, "height": 1000}, device_scale_factor=1)
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(render(root, data, url, "question"))
    page.wait_for_function("() => document.querySelectorAll('.graphkin-drawing[data-mounted]').length === 4")
    # R3i drawn through G3 (the slip the grader names), the three others right, each with the mouse.
    drawn = {"R3i": next(t for t in right["R3i"] if t["slip"] == "through_G")}
    drawn |= {qid: targets[0] for qid, targets in right.items() if qid != "R3i"}
    for qid, target in drawn.items():
        box = page.locator(f'.graphkin-drawing[data-answer="{qid}"]')
        box.scroll_into_view_if_needed()
        for element in target["elements"]:
            draw(page, box, element)
    # What the form posts: one hidden field per drawn question, the drawing as JSON.
    posted = page.evaluate("() => Object.fromEntries(new FormData(document.getElementById('question-form')))")
    assert set(posted) == set(drawn)
    page.close()
    assert not errors
    data["raw_submitted_answers"] = dict(posted)
    data["submitted_answers"] = dict(posted)
    data = call(root, "parse", data)
    assert not data["format_errors"]
    data = call(root, "grade", data)
    verdicts = {qid: json.loads(data["feedback"][f"{qid}__drawn"])["verdict"] for qid in drawn}
    assert verdicts == {"R3i": "slip", "F43": "correct", "I3": "correct", "polygon3": "correct"}
    assert 0 < data["score"] < 1
    # The submission panel draws the grading back on the student's own drawing.
    page = browser.new_page(viewport={"width": 1200, "height": 1000}, device_scale_factor=1)
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(render(root, data, url, "submission"))
    page.wait_for_function("() => document.querySelectorAll('.graphkin-drawing[data-mounted]').length === 4")
    r3i = page.locator('.graphkin-drawing[data-answer="R3i"]')
    assert r3i.locator(".gk-verdict").get_attribute("data-verdict") == "slip"
    assert "through G" in r3i.locator(".gk-verdict").inner_text()
    assert r3i.locator(".gk-fault").count() == len(json.loads(data["feedback"]["R3i__drawn"])["fault"])
    for qid in ("F43", "I3", "polygon3"):
        box = page.locator(f'.graphkin-drawing[data-answer="{qid}"]')
        assert box.locator(".gk-verdict").get_attribute("data-verdict") == "correct"
        assert box.locator(".gk-fault").count() == 0
    page.screenshot(path=str(out / "prairielearn-submission.png"), full_page=True)
    page.close()
    assert not errors
