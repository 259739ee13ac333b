"""The practice page of drawn answers (issue 38) in Chromium: the student draws with the mouse — the right
construction and each slip the task's targets name, and a wrong one — and the page shows the verdict, the words and
the element at fault, saying that no grade is recorded; undo and the keyboard draw as the mouse does.

The page holds three hand-written tasks (tests/scene/drawn_fixtures.py) and every drawn question of the catalog's
drawn exercises for one student (``task_of(..., practice=True)``, as ``graphkin exercise practice`` writes them). The
clicks go where the targets' own coordinates are on screen (the view's ``toScreen``): what the page reads back
(``drawing()``) must be those coordinates to within a pixel at the task's scale, so that the test checks the
drawing's scale as well as the verdict; and the page's verdict on each drawing must be the grader's
(:func:`graphkin.exercises.drawn_grading.grade_drawing`) on the same drawing.
"""

from __future__ import annotations

import math

import pytest

from graphkin import exercises
from graphkin.exercises.drawn_grading import grade_drawing
from graphkin.exercises.drawn_tasks import task_of
from graphkin.scene.practice import write_practice
from tests.scene.drawn_fixtures import CORNER, I3, TIP, P, on_line, reachable, tasks

PX_MM = 25.4 / 96  # one CSS pixel, in millimetres of drawing
DRAWN = ("draw_strip_cutter", "draw_shaper_polygons")  # the catalog's exercises with drawn questions
STUDENT = "s002"  # a variant whose slips (scale aside) all fit their boxes


def catalog_tasks():
    """(variant, task) of every drawn question of :data:`DRAWN` for :data:`STUDENT`."""
    out = []
    for name in DRAWN:
        v = exercises.variant(exercises.load(name), STUDENT, "")
        out += [(v, task_of(v, q.id, practice=True)) for q in v.exercise.questions if q.kind == "drawing"]
    return out


CATALOG = catalog_tasks()
ALL = tasks() + [t for _, t in CATALOG]


@pytest.fixture(scope="module")
def page(browser, out):
    path = write_practice(ALL, out / "practice.html", title="Practice: drawn answers")
    context = browser.new_context(viewport={"width": 1200, "height": 1000}, device_scale_factor=1)
    pg = context.new_page()
    errors = []
    pg.on("pageerror", lambda e: errors.append(str(e)))
    pg.goto(path.as_uri())
    pg.wait_for_function("() => window.graphkin && window.graphkin.views.length === " + str(len(ALL)))
    yield pg
    assert not errors
    context.close()


def screen(page, k, p):
    page.locator("section").nth(k).locator("svg.gk-draw-svg").scroll_into_view_if_needed()
    return page.evaluate("([k, p]) => window.graphkin.views[k].toScreen(p)", [k, list(p)])


def click(page, k, p):
    x, y = screen(page, k, p)
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.up()


def drag(page, k, p, q):
    a, b = screen(page, k, p), screen(page, k, q)
    page.mouse.move(*a)
    page.mouse.down()
    page.mouse.move(*b, steps=5)
    page.mouse.up()


def draw(page, k, element, by_drag=False):
    task = ALL[k]
    if element["kind"] == "point":
        click(page, k, element["at"])
    else:
        a, b = element["through"] if element["kind"] == "line" else (element["from"], element["to"])
        if element["kind"] == "line":
            a, b = on_line(task, a, b)
        if by_drag:
            drag(page, k, a, b)
        else:
            click(page, k, a)
            click(page, k, b)


def check(page, k):
    section = page.locator("section").nth(k)
    section.locator("[data-do=check]").click()
    verdict = section.locator(".gk-verdict")
    return verdict.get_attribute("data-verdict"), section.locator(".gk-draw-feedback").inner_text()


def drawn(page, k):
    return page.evaluate("(k) => window.graphkin.views[k].drawing()", k)


def clear(page, k):
    page.locator("section").nth(k).locator("[data-do=clear]").click()
    assert drawn(page, k)["elements"] == []


def test_each_target_drawn_with_the_mouse_gets_the_graders_verdict(page, out):
    graders = [None] * len(tasks()) + [v for v, _ in CATALOG]
    seen = 0
    missed = []
    for k, task in enumerate(ALL):
        s = task["scale"]["si_per_mm"]
        for n, target in enumerate(task["check"]["targets"]):
            if not reachable(task, target):
                missed.append(f"{task['question']} {target['slip']}")
                continue
            for element in target["elements"]:
                draw(page, k, element, by_drag=n % 2 == 1)
            d = drawn(page, k)
            assert d["question"] == task["question"] and d["space"] == task["space"]
            assert len(d["elements"]) == len(target["elements"]), (task["question"], n, d, target)
            for e, t in zip(d["elements"], target["elements"], strict=True):
                assert e["kind"] == t["kind"]
                got = e.get("through") or ([e["at"]] if "at" in e else [e["from"], e["to"]])
                want = t.get("through") or ([t["at"]] if "at" in t else [t["from"], t["to"]])
                if t["kind"] == "line":  # the points the test clicked along it
                    want = list(on_line(task, *want))
                for p, q in zip(got, want, strict=True):  # where the mouse went, to a pixel at the task's scale
                    assert math.dist(p, q) <= 1.0 * PX_MM * s, (task["question"], n, p, q)
            verdict, text = check(page, k)
            shown = page.evaluate("(k) => window.graphkin.views[k].check()", k)
            # The first target the drawing matches: this one, or an earlier one it also lies within tolerance of.
            first = next(t for t in task["check"]["targets"] if t["slip"] == shown["slip"])
            assert task["check"]["targets"].index(first) <= n, (task["question"], n, shown)
            if graders[k] is not None:  # the grader's verdict on the same drawing
                graded = grade_drawing(graders[k], task["question"], d)
                assert (graded["verdict"], graded["slip"], graded["fault"]) == (
                    shown["verdict"], shown["slip"], shown["fault"]), (task["question"], n)
            slip = target["slip"]
            if first is target:
                assert verdict == ("correct" if slip is None else "slip"), (task["question"], slip, text)
                words = task["check"]["words"].get(slip if slip else "right")
                if words:
                    assert words[1:].rstrip(".") in text
            assert "no grade is recorded" in text
            assert page.locator("section").nth(k).locator(".gk-fault").count() == len(shown["fault"])
            clear(page, k)
            seen += 1
    print(f"\npractice page: {seen} targets of {len(ALL)} tasks drawn with the mouse, each verdict the grader's; "
          f"not in the view, so not drawn: {', '.join(missed) or 'none'}")
    assert seen >= len(ALL) * 2  # the right construction and at least one slip of each task, on average
    page.screenshot(path=str(out / "practice-page.png"), full_page=True)


def test_a_wrong_drawing_is_marked_and_undo_takes_back_one_point(page):
    k = 2  # the polygon: F43 right, F23 drawn from the wrong place
    click(page, k, TIP)
    click(page, k, CORNER)
    click(page, k, (40.0, 20.0))
    page.keyboard.press("Control+z")  # takes back F23's tail only
    assert len(drawn(page, k)["elements"]) == 1
    assert page.locator("section").nth(k).locator(".gk-placed").count() == 0
    click(page, k, (40.0, 20.0))
    click(page, k, (0.0, 0.0))
    verdict, text = check(page, k)
    assert verdict == "wrong" and "no grade is recorded" in text
    faults = page.locator("section").nth(k).locator(".gk-fault")
    assert faults.count() == 1 and faults.first.get_attribute("data-index") == "1"
    page.locator("section").nth(k).locator("[data-do=undo]").click()  # F23's tip
    page.locator("section").nth(k).locator("[data-do=undo]").click()  # F23's tail
    assert [e["name"] for e in drawn(page, k)["elements"]] == ["F43"]
    clear(page, k)


def test_the_keyboard_draws_the_point_from_a_snap_point(page):
    k = 1
    svg = page.locator("section").nth(k).locator("svg.gk-draw-svg")
    svg.focus()
    page.keyboard.press("Tab")  # the cursor goes to the task's first snap point, P
    assert "snaps to P" in page.locator("section").nth(k).locator(".gk-draw-status").inner_text()
    s = tasks()[k]["scale"]["si_per_mm"]
    right = round((I3[0] - P[0]) / s)  # whole millimetres of drawing, as the fixture places I3
    down = round((P[1] - I3[1]) / s)
    for _ in range(right // 10):
        page.keyboard.press("Shift+ArrowRight")
    for _ in range(right % 10):
        page.keyboard.press("ArrowRight")
    for _ in range(down):
        page.keyboard.press("ArrowDown")
    page.keyboard.press("Enter")
    (at,) = [e["at"] for e in drawn(page, k)["elements"]]
    assert math.dist(at, I3) < 1e-9
    verdict, _ = check(page, k)
    assert verdict == "correct"
    assert svg.get_attribute("aria-label").startswith("Drawing area for point3")
