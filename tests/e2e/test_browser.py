"""Every lesson in JupyterLab (cell by cell, Shift+Enter, as a student runs it) and in Voilà; ``graphkin explore``.

Each explorer (``gk.explore``) is drawn by the browser from the scene the kernel sent (issue 37). For each page: no
error output and no "Error displaying widget"; every explorer draws its mechanism as SVG and no image comes from the
kernel; what is drawn is read back from the SVG and compared with the scene to 1e-6 of the mechanism's size
(tests/e2e/test_scene_page.py's read-back) after each of: the position first shown, an arrow key, the slider, and a
drag of the crank's handle across a third of the turn; a toggle hides what it names and the position stays. In
JupyterLab, cells typed after the lesson set each explorer's angle from Python (shown, and still shown after a
pause) and double a link's mass: the kernel sends a new scene, whose inertia force of that link is twice the old one,
drawn as the new scene says. The time from an input event to the SVG updated is printed and written to
``build/e2e/timings.json`` with the screenshots.
"""

from __future__ import annotations

import json
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from graphkin.widgets.browser import nearest
from tests.e2e.test_scene_page import READ_BACK, check_drawn

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "build" / "e2e"

LESSONS = sorted(p.name for p in (ROOT / "lessons").glob("*.ipynb"))
CELL_TIMEOUT = 180_000  # ms: the longest lesson cell (07's class of autograder runs) takes up to ~30 s here

EXPLORER = ".gk-scene"  # the element an explorer's module draws in (graphkin/scene/js/widget.js)

# The page's read-back (tests/e2e/test_scene_page.py), from one explorer's element: anywidget's element holds its
# view as the page's window does.
READ = (READ_BACK.replace("() => {", "(root) => {", 1)
        .replace('document.querySelector("svg.gk-mechanism")', 'root.querySelector("svg.gk-mechanism")')
        .replace("window.graphkin.view.index", "root.parentElement.graphkin.index")
        .replace('document.querySelectorAll("svg[data-polygon]")', 'root.querySelectorAll("svg[data-polygon]")'))
assert "document." not in READ and "window." not in READ, "the page's read-back changed: read it from the explorer's element"

VIEW = "(r) => r.parentElement.graphkin"
SCENE = "(r) => r.parentElement.graphkin.scene"
INDEX = "(r) => r.parentElement.graphkin.index"
TIMES = "(r) => { const v = r.parentElement.graphkin; return [v.timings.slice(), v.work.slice()]; }"
RESET = "(r) => { const v = r.parentElement.graphkin; v.timings.length = 0; v.work.length = 0; v.frames.length = 0; }"


def _xy(flat, i: int) -> np.ndarray:
    return np.array(flat[2 * i:2 * i + 2], float)


def _wait_index(page, root, i: int):
    page.wait_for_function(f"([r, i]) => ({INDEX})(r) === i", arg=[root.element_handle(), i], timeout=30_000)


def check_explorer(page, root, name: str) -> dict:
    """Drive one explorer as a person does, reading back what is drawn; returns what was measured."""
    root.scroll_into_view_if_needed()
    page.wait_for_function("r => !!r.querySelector('svg.gk-mechanism') && !!r.parentElement.graphkin",
                           arg=root.element_handle(), timeout=60_000)
    assert root.locator("img").count() == 0  # nothing drawn by the kernel
    s = root.evaluate(SCENE)
    n = s["n"]
    found = {"positions": n}
    i0 = root.evaluate(INDEX)
    check_drawn(root.evaluate(READ), s, i0)

    # An arrow key steps one presolved position, the widget's own once it has the focus.
    root.focus()
    root.evaluate(RESET)
    page.keyboard.press("ArrowRight")
    _wait_index(page, root, (i0 + 1) % n)
    check_drawn(root.evaluate(READ), s, (i0 + 1) % n)
    for _ in range(9):
        page.keyboard.press("ArrowRight")
    _wait_index(page, root, (i0 + 10) % n)
    check_drawn(root.evaluate(READ), s, (i0 + 10) % n)
    keys = root.evaluate(TIMES)

    # The slider.
    target = (i0 + n // 2) % n
    root.locator("[data-do=position]").fill(str(target))
    _wait_index(page, root, target)
    check_drawn(root.evaluate(READ), s, target)

    # Dragging the crank (or the driving slider) by its handle on the drawing, over a third of the cycle.
    handle = next(lk for lk in s["links"] if lk["number"] == s["driver"]["link"])["points"][s["driver"]["handle"]]
    svg = root.locator("svg.gk-mechanism")
    svg.scroll_into_view_if_needed()

    def screen(i):
        x, y = _xy(handle, i)
        return root.evaluate("(r, [x, y]) => { const svg = r.querySelector('svg.gk-mechanism'); "
                             "const p = new DOMPoint(x, -y).matrixTransform(svg.getScreenCTM()); return [p.x, p.y]; }",
                             [x, y])

    start = root.evaluate(INDEX)
    page.mouse.move(*screen(start))
    page.mouse.down()
    root.evaluate(RESET)
    goal = (start + n // 3) % n
    for j in range(start + 1, start + n // 3 + 1):
        page.mouse.move(*screen(j % n))
    page.mouse.up()
    drag = root.evaluate(TIMES)
    drawn = root.evaluate(READ)
    assert drawn["index"] != start, "the drag did not move the mechanism"
    # The nearest presolved handle to the pointer: the goal, or one whose handle is as near (a drawn pixel).
    assert np.hypot(*(_xy(handle, drawn["index"]) - _xy(handle, goal))) < 1e-3 * s["size"]
    check_drawn(drawn, s, drawn["index"])

    # A toggle hides what it names; the position stays and is drawn again as the scene says when shown.
    box = root.locator("[data-toggle=forces]")
    box.uncheck()
    assert root.locator("svg.gk-mechanism g.gk-forces").is_hidden()
    assert root.evaluate(INDEX) == drawn["index"]
    box.check()
    check_drawn(root.evaluate(READ), s, drawn["index"])

    for what, (update, work) in (("key", keys), ("drag", drag)):
        if update:
            found[f"{what}_update_ms_median"] = round(float(np.median(update)), 2)
            found[f"{what}_update_ms_p99"] = round(float(np.percentile(update, 99)), 2)
            found[f"{what}_drawing_ms_median"] = round(float(np.median(work)), 2)
    root.screenshot(path=str(OUT / f"{name}.png"))
    return found


def _explorer_names(nb_path) -> list[str]:
    cells = json.loads(nb_path.read_text(encoding="utf-8"))["cells"]
    code = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")
    return re.findall(r"^(\w+) = (?:gk\.)?explore\(", code, re.M)


def _explorers_in(nb_path) -> int:
    return len(_explorer_names(nb_path))


def _type_cell(page, code: str, count: int) -> int:
    """Add a code cell at the end of the notebook, run it with Shift+Enter, wait for it; returns its number."""
    page.keyboard.press("Escape")
    page.keyboard.press("Control+End")  # the last cell
    page.keyboard.press("b")  # a new cell below it
    page.keyboard.press("Enter")  # edit it
    page.keyboard.insert_text(code)  # as pasted: no auto-closed brackets
    page.keyboard.press("Shift+Enter")
    _wait_ran(page, count + 1)
    return count + 1


def _largest(s: dict) -> float:
    """The largest force of a scene's cycle [N]: its forces are rounded to its precision of this (docs/json.md)."""
    arrays = [f["analytical"] for f in s["forces"]] + [k["force"] for k in s["inertia"]]
    arrays += [ld["force"] for ld in s["loads"] if "force" in ld]
    return max(float(np.nanmax(np.abs(np.array(a, float)))) for a in arrays if len(a))


def _from_python(page, root, name: str, count: int) -> int:
    """Cells typed after the lesson, as a student would: the angle set from Python is shown, and stays; a doubled
    mass is a new scene from the kernel, its link's inertia force twice the old, drawn as the new scene says."""
    s = root.evaluate(SCENE)
    angle = 200.0 if s["input"]["name"] == "theta" else float(np.mean(s["input"]["values"])) * 1e3
    count = _type_cell(page, f"{name}.position = {angle!r}", count)
    shown = nearest(s, angle)  # the presolved position nearest to it, as Python finds it
    _wait_index(page, root, shown)
    time.sleep(1.0)
    assert root.evaluate(INDEX) == shown  # nothing comes back from the browser to move it
    check_drawn(root.evaluate(READ), s, shown)
    # The link whose inertia force is largest (a gear pivoted at its centre has none: its mass changes no force).
    sizes = {k["link"]: float(np.nanmax(np.abs(np.array(k["force"], float)))) for k in s["inertia"]}
    link = max(sizes, key=sizes.get, default=None)
    if link is None or sizes[link] < 1e-3 * _largest(s):
        return count
    el = root.element_handle().evaluate_handle("r => r.parentElement")  # anywidget's element: it stays
    el.evaluate("el => { el.graphkin.__old = true; }")
    # What the student chose on the drawing stays across the new scene: here the force table hidden.
    table = root.locator("[data-toggle=table]")
    if table.count():
        table.uncheck()
    count = _type_cell(page, f"{name}.set('mass.{link}', 2 * {name}.problem.mechanism.link({link}).mass); "
                             f"{name}.index = {shown}", count)
    page.wait_for_function("el => !el.graphkin.__old && !!el.querySelector('svg.gk-mechanism')", arg=el,
                           timeout=60_000)
    new_root = root  # found again: the new scene's element, in the same place
    new = new_root.evaluate(SCENE)
    assert new["n"] == s["n"] and new["links"] == s["links"]  # the same motion
    (old_R,) = [np.array(k["force"], float) for k in s["inertia"] if k["link"] == link]
    (new_R,) = [np.array(k["force"], float) for k in new["inertia"] if k["link"] == link]
    tol = 2 * s["precision"] * max(_largest(s), _largest(new))  # each scene rounds to its largest force
    np.testing.assert_allclose(new_R, 2 * old_R, rtol=0, atol=3 * tol)
    _wait_index(page, new_root, shown)
    check_drawn(new_root.evaluate(READ), new, shown)
    if table.count():
        assert not new_root.locator("[data-toggle=table]").is_checked(), "a new scene showed the table again"
        assert not new_root.locator(".gk-tablebox").is_visible()
    return count


def _no_widget_errors(page):
    assert page.get_by_text("Error displaying widget").count() == 0
    assert page.get_by_text("Traceback (most recent call last)").count() == 0


def _report(where: str, lesson: str, found: list, timings: dict, seconds: float):
    timings.setdefault(where, {})[lesson] = {"seconds": round(seconds, 1), "explorers": found}
    for k, f in enumerate(found):
        times = "; ".join(f"{what}: event → SVG median {f[f'{what}_update_ms_median']:.1f} ms, 99th "
                          f"{f[f'{what}_update_ms_p99']:.1f} ms (drawing {f[f'{what}_drawing_ms_median']:.2f} ms)"
                          for what in ("key", "drag") if f"{what}_update_ms_median" in f)
        print(f"\n{where} {lesson} explorer {k + 1}: {f['positions']} positions; {times}")


# The server wants its _xsrf cookie back in a header on a DELETE.
SHUT_DOWN = """async (id) => {
  const xsrf = decodeURIComponent((document.cookie.match(/(?:^|; )_xsrf=([^;]*)/) || [, ''])[1]);
  const r = await fetch('/api/sessions/' + id, {method: 'DELETE', headers: {'X-XSRFToken': xsrf}});
  return r.status;
}"""

PROMPT = "n => [...document.querySelectorAll('.jp-Notebook .jp-InputPrompt')].some(e => e.textContent.trim() === n)"


def _wait_ran(page, n: int):
    """Until the n-th code cell of a fresh kernel has run: its prompt shows [n].

    Shift+Enter pressed while the notebook is still connecting to its new kernel can pass
    without running the cell (its prompt stays [ ] and the selection moves on): the cell
    is then run again, once it is sure that it never started.
    """
    for _ in range(3):
        try:
            page.wait_for_function(f"() => ({PROMPT})('[{n}]:') || ({PROMPT})('[*]:')", timeout=10_000)
            break
        except Exception:
            page.keyboard.press("ArrowUp")
            page.keyboard.press("Shift+Enter")
    page.wait_for_function(PROMPT, arg=f"[{n}]:", timeout=CELL_TIMEOUT)


def _saved_cells(path, before: float, timeout: float = 30.0) -> list:
    """The cells of the notebook at ``path`` once JupyterLab has finished saving it.

    jupyter_server's "atomic" save copies the notebook to ``.~<name>``, then truncates and
    rewrites the notebook in place, and removes the copy last. The file's mtime therefore
    changes before its text is written: reading it then can find it empty (CI, stop 32).
    The save is over when the copy is gone and the text is one whole JSON document.
    """
    backup = path.with_name(".~" + path.name)
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if path.stat().st_mtime != before and not backup.exists():
            try:
                return json.loads(path.read_text(encoding="utf-8"))["cells"]
            except json.JSONDecodeError:
                pass  # a new save began between the two looks
        time.sleep(0.2)
    pytest.fail(f"the notebook was not saved within {timeout:.0f} s: {path.name}")


@pytest.fixture(scope="module")
def lab_page(browser, jupyterlab):
    context = browser.new_context(viewport={"width": 1400, "height": 900}, device_scale_factor=1)
    page = context.new_page()
    yield page
    context.close()


@pytest.mark.parametrize("lesson", LESSONS)
def test_lesson_cell_by_cell_in_jupyterlab(lab_page, jupyterlab, workdir, timings, lesson):
    page, path = lab_page, workdir / lesson
    t0 = time.monotonic()
    page.goto(f"{jupyterlab}/lab/tree/{lesson}?reset", wait_until="domcontentloaded")  # this notebook alone
    page.wait_for_selector(".jp-Notebook .jp-Cell", timeout=60_000)
    page.wait_for_selector(".jp-Notebook-ExecutionIndicator[data-status='idle']", timeout=60_000)
    page.get_by_text(re.compile(r"\| Idle$")).first.wait_for(timeout=60_000)  # the status bar: kernel connected
    time.sleep(1.0)  # the kernel's connection settles after its first idle
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    page.locator(".jp-Notebook .jp-Cell").first.click()
    page.keyboard.press("Escape")  # command mode: Shift+Enter runs the cell and selects the next
    count = 0
    for i, cell in enumerate(cells):
        page.keyboard.press("Shift+Enter")
        if cell["cell_type"] == "code":
            count += 1
            try:
                _wait_ran(page, count)
            except Exception:
                page.screenshot(path=str(OUT / f"FAILED-lab-{path.stem}.png"))
                prompts = page.evaluate("() => [...document.querySelectorAll('.jp-InputPrompt')]"
                                        ".map(e => e.textContent)")
                pytest.fail(f"cell {i} (code cell {count}) did not finish: {''.join(cell['source'])[:200]!r}; "
                            f"prompts: {[p for p in prompts if p.strip()][-5:]}")
    page.wait_for_selector(".jp-Notebook-ExecutionIndicator[data-status='idle']", timeout=60_000)
    explorers = page.locator(f".jp-Notebook {EXPLORER}")
    names = _explorer_names(path)
    # Save what the browser ran and read its outputs: no cell raised (the lessons' checks are assertions).
    saved = path.stat().st_mtime
    page.locator(".jp-Notebook").first.click(position={"x": 5, "y": 5})
    page.keyboard.press("Escape")
    page.keyboard.press("Control+s")
    ran = _saved_cells(path, saved)
    errors = [f"cell {i}: {o['ename']}: {o['evalue']}" for i, c in enumerate(ran) for o in c.get("outputs", [])
              if o["output_type"] == "error"]
    assert not errors, errors
    assert sum(1 for c in ran if c["cell_type"] == "code" and c.get("execution_count")) == count
    _no_widget_errors(page)
    assert explorers.count() == len(names)
    found = [check_explorer(page, explorers.nth(k), f"lab-{path.stem}-{k + 1}") for k in range(len(names))]
    for k, name in enumerate(names):  # the explorers in the order their cells made them
        count = _from_python(page, explorers.nth(k), name, count)
    _no_widget_errors(page)
    page.screenshot(path=str(OUT / f"lab-{path.stem}.png"))
    _report("jupyterlab, cell by cell", lesson, found, timings, time.monotonic() - t0)
    # Shut the kernel down before the next lesson (two cores: one kernel at a time).
    for s in json.loads(page.evaluate("() => fetch('/api/sessions').then(r => r.text())")):
        status = page.evaluate(SHUT_DOWN, s["id"])
        assert status == 204, f"the lesson's kernel was not shut down: HTTP {status}"


@pytest.fixture(scope="module")
def voila_page(browser, voila):
    # A HiDPI screen: the SVG is drawn in CSS pixels, whatever the pixel ratio.
    context = browser.new_context(viewport={"width": 1280, "height": 900}, device_scale_factor=2)
    page = context.new_page()
    yield page
    context.close()


@pytest.mark.parametrize("lesson", LESSONS)
def test_lesson_in_voila(voila_page, voila, workdir, timings, lesson):
    page, path = voila_page, workdir / lesson
    t0 = time.monotonic()
    page.goto(f"{voila}/voila/render/{lesson}", wait_until="load", timeout=CELL_TIMEOUT)
    expected = _explorers_in(path)
    page.wait_for_function(f"n => document.querySelectorAll('{EXPLORER}').length >= n", arg=expected,
                           timeout=60_000)
    _no_widget_errors(page)
    assert page.get_by_text("There was an error when executing cell").count() == 0
    assert page.locator("[data-mime-type='application/vnd.jupyter.error']").count() == 0
    explorers = page.locator(EXPLORER)
    assert explorers.count() == expected
    found = [check_explorer(page, explorers.nth(k), f"voila-{path.stem}-{k + 1}") for k in range(expected)]
    page.screenshot(path=str(OUT / f"voila-{path.stem}.png"))
    _report("voila, pixel ratio 2", lesson, found, timings, time.monotonic() - t0)
    page.goto("about:blank")  # Voilà shuts the page's kernel down


def _explore(problem: str, *options: str) -> subprocess.Popen:
    """`graphkin explore PROBLEM --no-browser OPTIONS` started as a child that a Ctrl-C (SIGINT) reaches.

    Ctrl-C as at a terminal. A shell without job control starts a background job (`.ci/run &`) with SIGINT
    ignored, and a child inherits that: Python then never raises KeyboardInterrupt and the explorer runs on. With a
    handler of the test's own, the child starts with the default disposition (exec resets a handler; preexec_fn is
    not safe beside Playwright's threads)."""
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        return subprocess.Popen([sys.executable, "-m", "graphkin", "explore", problem, "--no-browser", *options],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    finally:
        signal.signal(signal.SIGINT, before)


@pytest.mark.parametrize("problem", ["strip_cutter", "double_slider"])  # a crank (degrees) and a slider (mm)
def test_graphkin_explore_serves_the_explorer_and_stops_on_ctrl_c(browser, timings, problem):
    """`graphkin explore PROBLEM`: one URL line, a working explorer, Ctrl-C → one line, exit 130, Voilà gone."""
    proc = _explore(problem)
    try:
        line = proc.stdout.readline()
        url = re.search(r"http://127\.0\.0\.1:\d+/", line)
        assert url, line + proc.stderr.read()
        context = browser.new_context(viewport={"width": 1920, "height": 1080}, device_scale_factor=1)  # a projector
        page = context.new_page()
        page.goto(url.group(0), wait_until="load", timeout=120_000)
        page.wait_for_selector(EXPLORER, timeout=60_000)
        _no_widget_errors(page)
        t0 = time.monotonic()
        found = check_explorer(page, page.locator(EXPLORER).first, f"explore-{problem}")
        page.screenshot(path=str(OUT / f"explore-{problem}-page.png"))
        context.close()
        _report("graphkin explore, 1920 × 1080", problem, [found], timings, time.monotonic() - t0)
    finally:
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=60)
    assert proc.returncode == 130
    assert err.strip().splitlines() == ["graphkin: explorer stopped"] and "Traceback" not in out + err
    port = int(url.group(0).rsplit(":", 1)[1].strip("/"))
    import socket

    with pytest.raises(OSError), socket.create_connection(("127.0.0.1", port), timeout=2):
        pass  # nothing listens any more


def test_graphkin_explore_serves_under_a_hub_proxy_s_path(browser):
    """`--base-url /user/NAME/proxy/absolute/{port}/`: the page, its widgets' assets and its kernel all under the
    path a JupyterHub's jupyter-server-proxy forwards whole (docs/hub.md); nothing answers at the root."""
    proc = _explore("strip_cutter", "--base-url", "/user/ada/proxy/absolute/{port}/")
    try:
        line = proc.stdout.readline()
        url = re.search(r"http://127\.0\.0\.1:(\d+)/user/ada/proxy/absolute/(\d+)/", line)
        assert url and url[1] == url[2], line + proc.stderr.read()
        context = browser.new_context(viewport={"width": 1280, "height": 900})
        page = context.new_page()
        requests = []
        page.on("request", lambda r: requests.append(r.url))
        page.goto(url.group(0), wait_until="load", timeout=120_000)
        page.wait_for_selector(f"{EXPLORER} svg.gk-mechanism", timeout=60_000)
        _no_widget_errors(page)
        local = [r for r in requests if r.startswith("http://127.0.0.1")]
        assert local and all(r.startswith(url.group(0)) for r in local), local
        assert page.goto(f"http://127.0.0.1:{url[1]}/", timeout=30_000).status == 404
        context.close()
    finally:
        proc.send_signal(signal.SIGINT)
        proc.communicate(timeout=60)
    assert proc.returncode == 130


def test_graphkin_explore_bad_problem_is_one_line():
    r = subprocess.run([sys.executable, "-m", "graphkin", "explore", "no_such_problem", "--no-browser"],
                       capture_output=True, text=True, cwd=ROOT, timeout=60)
    assert r.returncode == 2 and r.stdout == ""
    assert len(r.stderr.strip().splitlines()) == 1 and "no_such_problem" in r.stderr
