# ---
# jupyter:
#   jupytext:
#     formats: ipynb,py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
#       format_version: '1.3'
#       jupytext_version: 1.19.6
#   kernelspec:
#     display_name: Python 3 (ipykernel)
#     language: python
#     name: python3
# ---

# %% [markdown]
# # Lesson 06 — Exercises for a course (for teachers)
#
# The other lessons are for students. This one is for you, the teacher: how to give each student
# **their own numbers** for an exercise, grade what they type, and see which slips the class made. Every
# result is plain data (dicts, strings, numbers) to save as CSV or JSON. The weekly loop: choose or write an exercise (section 1); make every
# student's sheet and your key from the roster and a **course secret** (2), also from the command line
# (3); grade the answers and read the class's slips (4); set partial credit, reveal the answers and keep
# the secret (5). Lesson 07 puts the same on Gradescope, otter-grader, nbgrader and PrairieLearn.
#
# Everything happens in a temporary folder; the class of section 4 is simulated with a fixed seed.

# %%
# %matplotlib inline
import math
import tempfile
from pathlib import Path

import graphkin as gk

NAME = "strip_cutter_cut"     # the exercise of this lesson
SECRET = "mech-2025-autumn"   # a demo secret; a real one never goes in a notebook (section 5)
folder = Path((workdir := tempfile.TemporaryDirectory(prefix="graphkin-course-")).name)

# %% [markdown]
# ## 1. What an exercise is
#
# The catalog's exercises, each on a problem the lessons solve:

# %%
for name in gk.exercises.names():
    print(f"{name:<26}{gk.exercises.load(name).title}")

# %% [markdown]
# Each is a TOML file shipped inside the package; `gk.exercises.path` finds it whether graphkin
# was installed from a wheel or from a checkout. Here is the one we use in this lesson, the strip
# cutter of lessons 02–03 during the cut:

# %%
print(gk.exercises.path(NAME).read_text(encoding="utf-8"))

# %% [markdown]
# How to read it:
#
# * `problem` is the **base problem** (here the catalog's `strip_cutter`); everything the exercise
#   doesn't vary is taken from it. `intro` is the statement; `{θ12}`, `{ω}`, `{Fc}` become the student's values.
# * Each `[vary.SYMBOL]` is one value that changes from student to student: `field` says where it goes
#   in the problem file (a list: several places); `from`, `to` and `step` make a grid, so students get
#   round numbers like the book's, never 131.4729°. A list `values = [...]` works too.
# * Each `[[questions]]` has an `id` (the answers CSV's column), `find` (`F23`, `T12`, …), the `part`
#   asked, and optionally a `unit`, a `tolerance` (default 1 %) and `points` (default 1).
#
# What the file allows, once read:

# %%
ex = gk.exercises.load(NAME)
for v in ex.vary:
    print(f"{v.symbol:>4} ({v.label}): {len(v.values)} values, {v.values[0]}, {v.values[1]}, …, {v.values[-1]}")
print(f"     {math.prod(len(v.values) for v in ex.vary)} different data sets")
for q in ex.questions:
    print(f"{q.id}: {q.part} in {q.unit}, within {q.tolerance:.0%}, {q.points:g} point")

# %% [markdown]
# ### Writing your own
#
# Write the TOML in a file, or in a string while you try it out, and read it with
# `gk.exercises.parse_exercise`. Reading it checks everything: graphkin builds the base problem with
# the first, middle and last value of every range, so a mistake shows up now, not when the first
# student asks. Here is a short exercise on the same machine, with the speed from a list, two points
# for the torque and the rocker force in kN within 2 %:

# %%
MY_EXERCISE = """
title = "Strip cutter: how fast may it cut?"
problem = "strip_cutter"
intro = "The strip cutter of lesson 03 cuts with 2000 N. At θ12 = {θ12}, with the crank at {ω}, find:"

[vary."θ12"]
field = "driver.theta"
from = "130 deg"
to = "150 deg"
step = "5 deg"

[vary."ω"]
field = "driver.omega"
values = ["600 rpm", "900 rpm", "1200 rpm"]

[[questions]]
id = "T12"
find = "T12"
ask = "T12, the motor torque, with its sense"
points = 2

[[questions]]
id = "F34"
find = "F34"
part = "magnitude"
unit = "kN"
tolerance = "2 %"
ask = "|F34|, the force of the coupler on the rocker at B [kN]"
"""
mine = gk.exercises.parse_exercise(MY_EXERCISE, id="cutter_speed")
my_key = gk.exercises.key(mine, "s001", secret=SECRET)
print(my_key["intro"])
for q in my_key["questions"]:
    print(f"  {q['id']}: {q['ask']}  →  key: {q['answer']['text']}")

# %% [markdown]
# The `id` is part of every student's data (section 2): save the file as `cutter_speed.toml`, so
# the command line, which takes the id from the file name, gives the same data.
#
# A slip in the file is named with its field, as in problem files:

# %%
try:
    gk.exercises.parse_exercise(MY_EXERCISE.replace('tolerance = "2 %"', 'tolerence = "2 %"'), id="cutter_speed")
except gk.ProblemFileError as err:
    typo = str(err)
print(typo)

# %% tags=["remove-input"] jupyter={"source_hidden": true}
toml_file = gk.exercises.path(NAME)
assert len(gk.exercises.names()) >= 10 and NAME in gk.exercises.names()
assert [len(v.values) for v in ex.vary] == [15, 13, 11] and math.prod(len(v.values) for v in ex.vary) == 2145
assert ex.vary[0].values[:2] == ("126 deg", "128 deg") and ex.vary[0].values[-1] == "154 deg"
assert all(q.tolerance == 0.01 and q.points == 1 for q in ex.questions)
assert [(q.id, q.part, q.unit) for q in ex.questions] == [("F23", "vector", "N"), ("F14", "magnitude", "N"),
                                                          ("T12", "value", "N*m")]
assert gk.exercises.load(str(toml_file)).vary == ex.vary   # the file found is the catalog's
assert [v.values for v in mine.vary] == [("130 deg", "135 deg", "140 deg", "145 deg", "150 deg"),
                                         ("600 rpm", "900 rpm", "1200 rpm")]
assert [(q.points, q.unit, q.tolerance) for q in mine.questions] == [(2, "N*m", 0.01), (1, "kN", 0.02)]
assert my_key["questions"][1]["answer"]["text"].endswith(" kN")
assert "tolerence" in typo and "did you mean 'tolerance'" in typo
# The id is the seed: the file saved as cutter_speed.toml gives the same data.
(folder / "cutter_speed.toml").write_text(MY_EXERCISE, encoding="utf-8")
assert gk.exercises.make(str(folder / "cutter_speed.toml"), "s001", SECRET)["data"] == my_key["data"]

# %% [markdown]
# ## 2. A roster, the sheets and the key
#
# Your platform exports the class list as a CSV. graphkin needs one column, `student`; the others
# are ignored. Here is a made-up class of 30 in two lab groups:

# %%
roster = folder / "roster.csv"
roster.write_text("student,group\n" + "".join(f"s{n:03d},{'AB'[n % 2]}\n" for n in range(1, 31)), encoding="utf-8")
students = gk.exercises.read_roster(roster)
print(len(students), "students:", ", ".join(students[:5]), "…")

# %% [markdown]
# A student's **sheet** (`gk.exercises.make`) is the statement with their data and the questions, no
# answers: that is what you hand out. The **key** (`gk.exercises.key`) adds every answer, in SI and as
# the book prints it. Both depend on the course secret:

# %%
sheets = {s: gk.exercises.make(NAME, s, secret=SECRET) for s in students}
keys = {s: gk.exercises.key(NAME, s, secret=SECRET) for s in students}

print(sheets["s001"]["intro"])

# %%
for s in students[:8]:
    data = ", ".join(g["shown"] for g in keys[s]["data"])
    print(f"{s}  {data:<40}" + "   ".join(q["answer"]["text"] for q in keys[s]["questions"]))

# %% [markdown]
# Each student's data come from a hash of (exercise, student id, secret) and nothing else: the same
# id always gives the same data, on any machine; a late student changes nobody's data, nor does the
# roster's order; stray spaces around an id don't matter, but the case does (`S001` is not `s001`);
# another secret (next year's course) gives other data.

# %%
print("s001 again:        ", gk.exercises.make(NAME, "s001", secret=SECRET) == sheets["s001"])
print("' s001 ' (spaces): ", gk.exercises.make(NAME, " s001 ", secret=SECRET)["data"] == sheets["s001"]["data"])
print("'S001':            ", gk.exercises.make(NAME, "S001", secret=SECRET)["data"] == sheets["s001"]["data"])
next_year = {s: gk.exercises.make(NAME, s, secret="mech-2026-autumn")["data"] for s in students}
changed = sum(next_year[s] != sheets[s]["data"] for s in students)
print(f"another secret: {changed} of {len(students)} students get other data")

# %% [markdown]
# 2145 data sets is plenty, but two students out of 30 may still draw the same (the birthday
# problem: the chance is $1 - \prod_{k<30} (1 - k/2145) \approx 18\,\%$). Does it happen here?

# %%
by_data = {}
for s in students:
    by_data.setdefault(tuple(g["value"] for g in sheets[s]["data"]), []).append(s)
twins = [group for group in by_data.values() if len(group) > 1]
print(f"{len(by_data)} different data sets for {len(students)} students; the same data: {twins}")

# %% [markdown]
# It does: s013 and s025 have the same numbers. If that matters (they sit side by side), vary one
# more value or take a finer step; every student's data change with the file, so do it before
# you hand out the sheets.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
assert len(students) == 30 and len(set(students)) == 30
assert all(keys[s]["data"] == sheets[s]["data"] for s in students)
assert all("answer" not in q for s in students for q in sheets[s]["questions"])
assert gk.exercises.make(NAME, "s001", secret=SECRET) == sheets["s001"]
assert gk.exercises.make(NAME, " s001 ", secret=SECRET)["data"] == sheets["s001"]["data"]
assert gk.exercises.make(NAME, "S001", secret=SECRET)["data"] != sheets["s001"]["data"]
assert changed == len(students)
# A late student changes nobody's data; the roster's order doesn't matter.
late = {s: gk.exercises.make(NAME, s, secret=SECRET) for s in reversed(students + ["s031"])}
assert all(late[s] == sheets[s] for s in students)
assert twins == [["s013", "s025"]] and len(by_data) == 29
assert round(100 * (1 - math.prod(1 - k / 2145 for k in range(30)))) == 18


# %% [markdown]
# ## 3. The same from the command line
#
# The `graphkin exercise` command does the same for a whole roster and writes one CSV row per
# student. Here we run it from the notebook, exactly as you would type it in a terminal in the course
# folder (a hidden helper, `graphkin(...)`, runs `python -m graphkin`, which is the `graphkin`
# command, and prints the command line). From a few hundred students on, the command spreads the
# work over all your cores.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
import subprocess
import sys


def graphkin(*args, env=None):
    """Run `graphkin ARGS...` in the course folder and return what it printed."""
    print("$ graphkin", " ".join(args))
    done = subprocess.run([sys.executable, "-m", "graphkin", *args], cwd=folder, env=env,
                          capture_output=True, text=True, encoding="utf-8", check=True)
    if done.stderr:
        print(done.stderr.strip())
    return done.stdout


# %%
graphkin("exercise", "make", NAME, "--roster", "roster.csv", "--secret", SECRET, "-o", "sheets.csv")
graphkin("exercise", "key", NAME, "--roster", "roster.csv", "--secret", SECRET, "-o", "keys.csv")
print("".join((folder / "keys.csv").read_text(encoding="utf-8").splitlines(keepends=True)[:4]))

# %% [markdown]
# One student's sheet, as text to print or mail (`--json` gives the same as plain data):

# %%
print(graphkin("exercise", "make", NAME, "--student", "s001", "--secret", SECRET))

# %% [markdown]
# ## 4. Collecting and grading the answers
#
# Students hand in a CSV (or a form your platform turns into one): a `student` column and one column
# per question id, the answers as typed. We make a class **honestly from the keys**: each answer is
# right, or carries one of the classic slips made on purpose, or is wrong, blank or unreadable:
#
# * **sign**: the force of the other link (F32 for F23), or the torque with the wrong sense;
# * **power of ten**: the torque worked out in N·mm and written as N·m;
# * **no inertia torque**: the variant solved again without $-I_G\alpha$ (`variant.altered(...)`).
#
# A wrong answer is 5 to 15 % off; an unreadable one is "see my drawing", "?", or a comma that could be
# a decimal comma or a thousands separator (`2,643 N`). Answers are
# typed as students type them: `2643 N ∠ -126.57°`, `(-1575, -2123) N`, `216.6 N·m CCW`, `0.2166 kN·m`.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The class, made from the keys: each answer right, a slip, wrong, blank or unreadable (see above).
import csv
import re

import numpy as np

from graphkin.exercises.quantities import value_of   # the raw answer of a solved variant, for the made-up class


def fmt(x):
    """A number as a student writes it: 4 significant figures, no powers of ten."""
    return f"{x:.4g}" if abs(x) < 1e4 else f"{x:.0f}"


def typed(q, value, style):
    """An answer (SI value) typed in one of three styles."""
    if q.part == "vector":
        size, angle = abs(value), math.degrees(math.atan2(value.imag, value.real))
        return [f"{fmt(size)} N ∠ {angle:.2f}°", f"({fmt(value.real)}, {fmt(value.imag)}) N",
                f"{fmt(size / 1e3)} kN at {angle:.1f} deg"][style]
    if q.part == "magnitude":
        return [f"{fmt(value)} N", f"{fmt(value / 1e3)} kN", fmt(value)][style]
    return [f"{fmt(abs(value))} N·m {'CCW' if value > 0 else 'CW'}", f"{fmt(value)} N*m",
            f"{fmt(value / 1e3)} kN·m"][style]


def slipped(variant, q, slip):
    """The value (SI) of a student who made `slip`."""
    right = value_of(variant.solved, q)
    if slip == "sign":
        return -right
    if slip == "power_of_ten":   # N·mm written as N·m
        return right * 1e3
    return value_of(variant.altered(slip), q)


SLIPS_MADE = {"F23": ["sign", "no_inertia_torque"], "F14": ["no_inertia_torque"],
              "T12": ["sign", "power_of_ten", "no_inertia_torque"]}
GARBAGE = ["see my drawing", "?", "comma"]   # "comma": the right answer as "2,643" (2.643 or 2643?)


rng = np.random.default_rng(2025)
made = {}   # (student, question) → what we made: "correct", a slip, "wrong", "missing", "unreadable"
rows = []
for s in students:
    v = gk.exercises.variant(NAME, s, secret=SECRET)
    row = {"student": s}
    for q in ex.questions:
        right, style = value_of(v.solved, q), int(rng.integers(3))
        what = str(rng.choice(["correct", "slip", "wrong", "missing", "unreadable"], p=[.75, .13, .04, .04, .04]))
        if what == "correct":
            answer = typed(q, right, style)
        elif what == "slip":   # one that changes the answer: at some angles T12 hardly feels the inertia torques
            what = str(rng.choice([sl for sl in SLIPS_MADE[q.id]
                                   if abs(slipped(v, q, sl) - right) > 3 * q.tolerance * abs(right)]))
            answer = typed(q, slipped(v, q, what), style)
        elif what == "wrong":   # 5 to 15 % off: an arm measured badly
            answer = typed(q, right * (1 + rng.choice([-1, 1]) * rng.uniform(0.05, 0.15)), style)
        elif what == "missing":
            answer = ""
        else:
            answer = str(rng.choice(GARBAGE))
            if answer == "comma":   # a thousands comma in the first number of four digits or more, else "?"
                four = [t for t in (typed(q, right, k) for k in range(3)) if re.search(r"(?<![\d.])\d{4}", t)]
                answer = re.sub(r"(?<![\d.])(\d)(\d{3})(?!\d)", r"\1,\2", four[0], count=1) if four else "?"
        made[s, q.id] = what
        row[q.id] = answer
    rows.append(row)

answers_csv = folder / "answers.csv"
with answers_csv.open("w", newline="", encoding="utf-8") as f:
    out = csv.DictWriter(f, fieldnames=["student"] + [q.id for q in ex.questions])
    out.writeheader()
    out.writerows(rows)
print("".join(answers_csv.read_text(encoding="utf-8").splitlines(keepends=True)[:8]))

# %% [markdown]
# Grading a row is one call, `gk.exercises.grade(exercise, student, answers, secret=...)`, where
# `answers` maps each question id to the text typed. It returns the score and, per question, the
# verdict (`correct`, `slip`, `wrong`, `unreadable`, `missing`), the slip it diagnosed, the points
# and a sentence of feedback.

# %%
with answers_csv.open(encoding="utf-8") as f:
    handed_in = {row.pop("student"): row for row in csv.DictReader(f)}
reports = {s: gk.exercises.grade(NAME, s, answers, secret=SECRET) for s, answers in handed_in.items()}
as_made = sum((q["slip"] or q["verdict"]) == made[s, q["id"]] for s in students for q in reports[s]["questions"])
print(f"the grader named what we made in {as_made} of {len(made)} answers")

# %% [markdown]
# The grader named every answer as we made it: right, the slip we put in, wrong, blank or
# unreadable. It can only judge the number, though: a wrong answer that happens to land within the
# tolerance of a slip's value is named as that slip. That happens now and then, because some slips
# change the answer only a little: at some crank angles the inertia torques add only a few percent to T12.

# %%
gk.draw.draw_grades(reports)

# %% [markdown]
# The right-hand chart is your plan for the next class: the tallest bars are what to go over again.
# A **slip** earns part of the points (by default half for a sign or a power of ten, a quarter for a
# missing inertia torque); a **wrong** or **unreadable** answer earns none, but an unreadable one's
# feedback says how to write it. What a student sees (`gk.exercises.check` gives the report as text):

# %%
shown = next(s for s in students if len({q["verdict"] for q in reports[s]["questions"]}) == 3)  # 3 verdicts
print(gk.exercises.check(NAME, shown, handed_in[shown], secret=SECRET))

# %% [markdown]
# The command line grades the whole CSV at once and writes one row per student: the score, and per
# question the points, the verdict and the feedback, ready to import into your gradebook.

# %%
graphkin("exercise", "grade", NAME, "--answers", "answers.csv", "--secret", SECRET, "-o", "grades.csv")
print("".join((folder / "grades.csv").read_text(encoding="utf-8").splitlines(keepends=True)[:3]))

# %% [markdown]
# ## 5. Partial credit, revealing answers, and the secret
#
# ### How much a slip is worth
#
# The default shares of a question's points for each slip the grader can diagnose:

# %%
for slip, share in gk.exercises.SLIPS.items():
    print(f"{slip:<20}{share:g}")

# %% [markdown]
# You change them in the exercise file, with a `[partial]` table. Say you want the sign to cost more,
# a power of ten less, and no credit at all for a forgotten inertia torque (the point of the exercise!).
# Keep the same `id`, and the students keep their data; then grade the same CSV again:

# %%
STRICT = gk.exercises.path(NAME).read_text(encoding="utf-8") + """
[partial]
sign = 0.25
power_of_ten = 0.75
no_inertia_torque = 0
"""
strict = gk.exercises.parse_exercise("reveal = true\n" + STRICT, id=NAME)
strict_reports = {s: gk.exercises.grade(strict, s, handed_in[s], secret=SECRET) for s in handed_in}
mean = {name: sum(r["score"] for r in rs.values()) / len(rs) for name, rs in [("default", reports), ("strict", strict_reports)]}
print(f"mean score, default shares: {mean['default']:.3f}; with this [partial]: {mean['strict']:.3f}")

# %% [markdown]
# ### Revealing the answers
#
# By default the report never shows the expected value, so that a student can try again. Put
# `reveal = true` at the top of the file (as in `strict` above) once the deadline has passed, or
# pass `reveal=True` to `gk.exercises.grade` (`--reveal` on the command line) for one run. Each
# question of the report then has an `expected` entry:

# %%
for q in strict_reports[shown]["questions"]:
    print(f"{q['id']}: {q['verdict']:<10} {q['score']:g}/{q['max']:g}   typed {q['answer']!r:<24} expected {q['expected']}")

# %% [markdown]
# ### How far off? What the feedback gives away
#
# A wrong answer is told its slip, or which part is wrong (sign, size, direction, a factor of ten), never
# how far off: "+19.5 % off" gives the key in one more try. After the deadline, `feedback = "distance"` in
# the exercise file (`feedback="distance"` in Python, `--feedback distance`) says how far. Both ways:

# %%
s_wrong, q_wrong = next((s, q.id) for s in students for q in ex.questions if made[s, q.id] == "wrong")
told = {}
for feedback in ("parts", "distance"):
    report = gk.exercises.grade(NAME, s_wrong, handed_in[s_wrong], secret=SECRET, feedback=feedback)
    told[feedback] = next(q for q in report["questions"] if q["id"] == q_wrong)
    print(f"{feedback:<9} {told[feedback]['feedback']}")

# %% [markdown]
# ### Keeping the secret out of the students' notebook
#
# Whoever has the secret can compute every key: keep it out of notebooks and repositories, in *your*
# terminal's environment (`export GRAPHKIN_SECRET=...`, then start Jupyter from it). The command line reads
# it when there is no `--secret`; in Python pass `secret=os.environ["GRAPHKIN_SECRET"]`. Choose a new one
# each term. Without a secret anyone can compute any key: fine for practice, not for graded work. The
# command line with the secret in the environment gives the same key as `gk.exercises.key`:

# %%
import os

course_env = {**os.environ, "GRAPHKIN_SECRET": SECRET}   # in a course: set in your terminal, not here
print(graphkin("exercise", "key", NAME, "--student", "s001", env=course_env))
secret = os.environ.get("GRAPHKIN_SECRET", "")   # how your own grading notebook reads it

# %% tags=["remove-input"] jupyter={"source_hidden": true}
import json

assert gk.exercises.SLIPS["sign"] == gk.exercises.SLIPS["power_of_ten"] == 0.5
assert gk.exercises.SLIPS["no_inertia_torque"] == 0.25
assert strict.reveal and not ex.reveal and strict.id == ex.id
assert strict.partial == {**gk.exercises.SLIPS, "sign": 0.25, "power_of_ten": 0.75, "no_inertia_torque": 0}
for s in students:
    assert gk.exercises.make(strict, s, secret=SECRET) == sheets[s]   # the same data
    for q_default, q_strict in zip(reports[s]["questions"], strict_reports[s]["questions"]):
        assert (q_default["verdict"], q_default["slip"]) == (q_strict["verdict"], q_strict["slip"])
        assert "expected" not in q_default and "expected" in q_strict
        share = {"correct": 1, "sign": 0.25, "power_of_ten": 0.75}.get(made[s, q_strict["id"]], 0)
        assert q_strict["score"] == share * q_strict["max"]
assert mean["strict"] < mean["default"]
assert [q["expected"] for q in strict_reports[shown]["questions"]] == \
       [q["answer"]["text"] for q in keys[shown]["questions"]]
assert (told["parts"]["verdict"], told["parts"]["score"]) == (told["distance"]["verdict"], told["distance"]["score"])
assert "% off" in told["distance"]["feedback"] and "% off" not in told["parts"]["feedback"]
assert all("expected" in q for q in gk.exercises.grade(NAME, shown, handed_in[shown], SECRET, reveal=True)["questions"])
# GRAPHKIN_SECRET: the CLI without --secret uses it; the Python functions don't read it.
env_key = subprocess.run([sys.executable, "-m", "graphkin", "exercise", "key", NAME, "--student", "s001",
                          "--json"], env=course_env, capture_output=True, text=True, encoding="utf-8", check=True)
assert json.loads(env_key.stdout) == keys["s001"]
before = os.environ.get("GRAPHKIN_SECRET")
os.environ["GRAPHKIN_SECRET"] = SECRET
try:
    assert gk.exercises.key(NAME, "s001") != keys["s001"]   # the Python default is no secret, whatever the environment
finally:
    if before is None:
        del os.environ["GRAPHKIN_SECRET"]
    else:
        os.environ["GRAPHKIN_SECRET"] = before
assert secret == (before or "")

# %% [markdown]
# ## 6. What next
#
# * `docs/exercises.md` is the reference: every field of an exercise file, what students may type,
#   how a slip is diagnosed, and the commands.
# * Grading on a platform: lesson 07, and `docs/platforms/`. The CSV in and out of section 4 (or
#   `--json`) works with any other tool.
# * Read your own exercise with `gk.exercises.load_exercise("my_exercise.toml")`: it reads the file
#   again after each edit (`gk.exercises.load` reads a path once per session).

# %% tags=["remove-input"] jupyter={"source_hidden": true}
draft = folder / "my_exercise.toml"
draft.write_text(MY_EXERCISE, encoding="utf-8")
assert gk.exercises.load(str(draft)).questions[1].tolerance == 0.02
draft.write_text(MY_EXERCISE.replace('tolerance = "2 %"', 'tolerance = "3 %"'), encoding="utf-8")
assert gk.exercises.load(str(draft)).questions[1].tolerance == 0.02            # the copy read first
assert gk.exercises.load_exercise(draft).questions[1].tolerance == 0.03        # the file as it is now
assert gk.exercises.load_exercise(draft).id == "my_exercise"
