"""Feedback that teaches without giving the key away (issue 34).

"yours is +73885.2 % off" gave the key in one more submission (key = answer / (1 + p)). An adversary that reads
every word of the feedback and inverts or bisects on it (:mod:`tests.exercises.attack`) now needs more than 10
submissions on every question kind, on every way a student sees feedback (the notebook check and the exercise
box, Gradescope, PrairieLearn); with ``feedback = "distance"`` it needs three at most, which is what the docs say
that choice gives away.
"""

from __future__ import annotations

import html
import json
import re
import statistics
import zipfile

import numpy as np
import pytest

from graphkin import exercises
from graphkin.exercises import platforms
from graphkin.exercises.exercise import dimension_of
from graphkin.exercises.grading import grade_question
from graphkin.exercises.platforms import gradescope, prairielearn, runtime
from graphkin.exercises.quantities import unit_factor
from tests.exercises.attack import Adversary, Question, prior

# strip_cutter_cut, and two more questions on F23: every question kind.
EXERCISE = exercises.path("strip_cutter_cut").read_text(encoding="utf-8") + """
[[questions]]
id = "F23dir"
find = "F23"
part = "direction"

[[questions]]
id = "F23x"
find = "F23"
part = "x"
"""
KINDS = {"scalar": "T12", "magnitude": "F14", "component": "F23x", "direction": "F23dir", "vector": "F23"}
LIMIT = 10  # the attempts a platform typically allows
SECRET = "attack-course-secret"
STUDENTS = [f"s{i:03d}" for i in range(12)]


def load(tmp_path=None):
    if tmp_path is None:
        return exercises.parse_exercise(EXERCISE, id="attack")
    path = tmp_path / "attack.toml"
    path.write_text(EXERCISE, encoding="utf-8")
    return exercises.load(path)


def adversary(v, q, seed: int, distance: bool):
    """The adversary for ``q`` of variant ``v`` (its prior placed by ``seed``), and the true key and grid step."""
    e = v.expected(q)
    floor = e.slack if e.form != "direction" and e.slack > q.tolerance * abs(e.value) * (1 + 1e-9) else 0.0
    aq = Question(e.form, q.unit if e.form != "direction" else "", unit_factor(q.unit, dimension_of(q.kind, q.part)),
                  q.tolerance, floor)
    rng = np.random.default_rng(seed)
    grid, step = prior(aq, e.value, rng)
    return Adversary(aq, grid, rng, distance=distance), e.value, step


def core(v, q, feedback):
    """The feedback line of graphkin's grader, as Gradescope and the notebook platforms print it."""
    return lambda text: runtime.feedback_line(grade_question(v, q, text, feedback=feedback))


@pytest.mark.parametrize("kind", KINDS)
def test_the_default_feedback_needs_more_than_ten_submissions_on_every_kind(kind):
    ex = load()
    q = ex.question(KINDS[kind])
    attempts = []
    for seed, student in enumerate(STUDENTS):
        v = exercises.variant(ex, student)
        adv, key, step = adversary(v, q, seed, distance=False)
        attempts.append(adv.attack(core(v, q, None), key, step, LIMIT))
    found = [n for n in attempts if n is not None]
    # Blind luck finds a few (a first guess in the right few per cent of a decade); the feedback adds no more.
    assert len(found) <= len(STUDENTS) // 4, attempts
    assert statistics.median(n or LIMIT + 1 for n in attempts) > LIMIT


@pytest.mark.parametrize("kind", KINDS)
def test_distance_feedback_gives_the_key_in_three_submissions(kind):
    """What feedback = "distance" gives away: the same adversary, on the same questions, needs three at most."""
    ex = load()
    q = ex.question(KINDS[kind])
    for seed, student in enumerate(STUDENTS):
        v = exercises.variant(ex, student)
        adv, key, step = adversary(v, q, seed, distance=True)
        assert adv.attack(core(v, q, "distance"), key, step, LIMIT) <= 3


# --- every way a student sees feedback ---------------------------------------------------------------------------


def notebook_check(ex, student, qid):
    """``graphkin.exercises.check``, the line a notebook cell prints."""
    def submit(text):
        lines = exercises.check(ex, student, {qid: text}, SECRET).splitlines()
        return next(line for line in lines if line.startswith(f"{qid}:"))
    return submit


def exercise_box(ex, student, qid):
    """The exercise box's feedback, as the student reads it (HTML to text)."""
    from graphkin.widgets import exercise

    box = exercise(ex, student, secret=SECRET)

    def submit(text):
        box.answers[qid].value = text
        box.check()
        row = re.search(rf"<li><b>{re.escape(qid)}</b>(.*?)</li>", box.feedback.value)[1]
        return html.unescape(re.sub(r"<[^>]+>", "", row))
    return submit


def on_gradescope(tmp_path, ex_file, student, qid):
    """Gradescope's autograder (run as on Gradescope, in this process): the test's output and the summary."""
    export = tmp_path / "gs"
    platforms.export(ex_file, "gradescope", export, secret=SECRET, students=STUDENTS)
    root = tmp_path / "autograder"
    with zipfile.ZipFile(export / "autograder.zip") as zf:
        zf.extractall(root / "source")
    (root / "submission").mkdir(parents=True)
    meta = {"users": [{"sid": student, "email": "", "name": "A Student"}], "assignment": {"title": "HW"}}
    (root / "submission_metadata.json").write_text(json.dumps(meta), encoding="utf-8")

    def submit(text):
        (root / "submission" / "answers.toml").write_text(f"{qid} = {json.dumps(text, ensure_ascii=False)}\n",
                                                          encoding="utf-8")
        results = gradescope.run(root)
        test = next(t for t in results["tests"] if t["name"].startswith(f"{qid}:"))
        return results["output"] + "\n" + test["output"]
    return submit


def on_prairielearn(tmp_path, ex_file, seed, qid):
    """PrairieLearn's grade(data) for one variant (its seed), as server.py calls it: the feedback under the box."""
    name = prairielearn.answer_names([qid]).popitem()[0]

    def submit(text):
        data = {"params": {}, "correct_answers": {}, "submitted_answers": {name: text}, "format_errors": {},
                "partial_scores": {}, "score": 0, "feedback": {}, "variant_seed": seed}
        prairielearn.generate(data, str(ex_file), SECRET)
        prairielearn.parse(data, str(ex_file), SECRET)
        assert not data["format_errors"], data["format_errors"]
        prairielearn.grade(data, str(ex_file), SECRET)
        return html.unescape(data["feedback"][name])
    return submit


PATHS = ("notebook check", "exercise box", "gradescope", "prairielearn")


@pytest.mark.parametrize("path", PATHS)
@pytest.mark.parametrize("kind", ["scalar", "direction", "vector"])
def test_every_platform_tells_the_adversary_no_more_than_the_grader(path, kind, tmp_path, capsys):
    """Through each platform the adversary reads the same thing at each step as from the grader itself: the same
    submissions, the same number of them (the statistics above hold there too); and "how far off" is said only
    with feedback = "distance" (here the grader's own, after the platform's texts said nothing of it)."""
    if path == "exercise box":
        pytest.importorskip("ipywidgets")
    ex_file = tmp_path / "attack.toml"
    ex_file.write_text(EXERCISE, encoding="utf-8")
    ex = exercises.load(ex_file)
    qid = KINDS[kind]
    q = ex.question(qid)
    seed = 3
    student = f"pl-{seed}" if path == "prairielearn" else STUDENTS[seed]
    submit = {"notebook check": lambda: notebook_check(ex, student, qid),
              "exercise box": lambda: exercise_box(ex, student, qid),
              "gradescope": lambda: on_gradescope(tmp_path, ex_file, student, qid),
              "prairielearn": lambda: on_prairielearn(tmp_path, ex_file, seed, qid)}[path]()
    v = exercises.variant(ex, student, SECRET)
    seen = {}
    for where, send in (("platform", submit), ("grader", core(v, q, None))):
        adv, key, step = adversary(v, q, seed, distance=False)
        texts = []
        n = adv.attack(lambda text, send=send, texts=texts: texts.append(send(text)) or texts[-1], key, step, LIMIT)
        seen[where] = (n, [adv.read(t) for t in texts])
        for text in texts:
            assert not re.search(r"% off|° off|mm away", text), text
    capsys.readouterr()  # the autograder's log
    assert seen["platform"] == seen["grader"]
