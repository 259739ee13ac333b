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
# # Lesson 07 — Exercises on your grading platform (for teachers)
#
# Lesson 06 graded a class on your own machine. A course usually grades somewhere else: in
# **Gradescope**, **PrairieLearn**, **otter-grader** or **nbgrader**, which already run thousands of
# submissions at once. graphkin does not replace them; `graphkin exercise export` writes what you
# upload to one of them, and the code that runs there calls graphkin's grader, so each student still
# gets their own data and feedback that names the slip.
#
# This lesson takes one exercise through Gradescope, end to end, on this machine:
#
# 1. a roster and the course secret, each student's data;
# 2. the export: `autograder.zip` and what is in it;
# 3. a folder of submissions, as Gradescope stores them (here simulated, honestly, from the keys);
# 4. each submission graded by the real `run_autograder`, in a folder laid out as Gradescope lays
#    out `/autograder`;
# 5. the spread of scores and the most frequent slips, from the `results.json` files;
# 6. the other three platforms, in one paragraph each, and why a notebook cannot grade itself.
#
# Everything happens in a temporary folder, deleted when the kernel stops. The simulated class uses
# a fixed random seed, so the numbers are the same every time; the checks at the end make sure the
# text says what the code does.

# %%
# %matplotlib inline

import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import zipfile
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

import graphkin as gk

NAME = "strip_cutter_cut"     # the exercise of this lesson (lesson 06 shows how to write your own)
SECRET = "mech-2025-autumn"   # a demo secret; a real one lives in $GRAPHKIN_SECRET, never in a notebook
workdir = tempfile.TemporaryDirectory(prefix="graphkin-platform-")
folder = Path(workdir.name)
GRAPHKIN = str(Path(sys.executable).with_name("graphkin"))


def graphkin(*args):
    """Run the `graphkin` command and return what it printed (stop with its message if it fails)."""
    done = subprocess.run([GRAPHKIN, *args], capture_output=True, text=True, cwd=folder)
    if done.returncode != 0:
        raise RuntimeError(done.stderr.strip())
    return done.stdout


# %% [markdown]
# ## 1. The roster and each student's data
#
# Gradescope knows a student by the **Student ID** of the course roster (its `sid`), or by the
# email where there is none. Draw each student's data from **that** id, so that the autograder,
# which reads the id from Gradescope's metadata, grades the variant the student was given.

# %%
students = [f"2025{n:04d}" for n in range(1, 25)]   # the SIDs of 24 students
roster = folder / "roster.csv"
roster.write_text("student\n" + "\n".join(students) + "\n", encoding="utf-8")
sheets = folder / "sheets.csv"
graphkin("exercise", "make", NAME, "--roster", "roster.csv", "--secret", SECRET, "-o", "sheets.csv")
print("".join(sheets.read_text(encoding="utf-8").splitlines(keepends=True)[:4]))

# %% [markdown]
# You hand these out as you like: a mail merge of `sheets.csv`, one sheet per student
# (`graphkin exercise make NAME --student ID`), or the student's own notebook (lesson 06).

# %% [markdown]
# ## 2. The export
#
# One command writes everything Gradescope needs. With `--roster`, the autograder grades only ids on
# the roster and says so to anyone else.

# %%
graphkin("exercise", "export", NAME, "--to", "gradescope", "-o", "export", "--roster", "roster.csv", "--secret", SECRET)
export = folder / "export"
for p in sorted(export.rglob("*")):
    if p.is_file():
        print(f"{p.relative_to(export)!s:<48}{p.stat().st_size:>9,} bytes")
with zipfile.ZipFile(export / "autograder.zip") as z:
    top = sorted({n.split("/")[0] for n in z.namelist()})
print("\nautograder.zip holds:", ", ".join(top))

# %% [markdown]
# * `autograder.zip` is what you upload under *Configure Autograder*. Its `setup.sh` installs a Python
#   with graphkin's requirements when Gradescope builds the image; `run_autograder` grades one
#   submission; graphkin itself travels in `vendor/`, so the grade comes from the version you
#   exported. `keys.json` holds the roster's **keys**, each student's answers computed here with the
#   secret; the secret itself is in no file of the export. **The zip never goes to students.**
# * `student_template/answers.toml` is what students fill in and upload, one line per question:

# %%
print((export / "student_template" / "answers.toml").read_text(encoding="utf-8"))

# %% [markdown]
# The export's `README.md` lists the steps on Gradescope and how to try the autograder on your
# machine first; section 4 below does exactly that, for a whole class.

# %% [markdown]
# ## 3. A folder of submissions
#
# Gradescope keeps each submission as the files the student uploaded plus
# `submission_metadata.json`, which says who submitted (name, email, `sid`). We have no real class,
# so we make one from the keys: most answers are copied right (typed as students type them), the
# others carry a classic slip made on purpose: the **sign** (the torque's sense reversed, or the
# force of the other link: the vector turned by 180°), a **power of ten** (the torque worked in
# N·mm and written as N·m), a **wrong** value (8 % off), a **blank**, or text the grader cannot read.
# One student uploads a friend's file.

# %%
rng = np.random.default_rng(7)
KINDS = ["correct", "sign", "power_of_ten", "wrong", "missing", "unreadable"]


def typed(q, si, kind):
    """The answer to question `q` whose right value (SI) is `si`, made as `kind`."""
    if q["form"] == "vector":
        x, y = si
        if kind == "sign":
            x, y = -x, -y
        elif kind == "wrong":
            x, y = 1.08 * x, 1.08 * y
        return f"({x:.4g}, {y:.4g}) N"
    value = {"sign": -si, "power_of_ten": 1e3 * si, "wrong": 1.08 * si}.get(kind, si)
    if q["unit"] == "N*m":
        return f"{abs(value):.4g} N·m {'CCW' if value > 0 else 'CW'}"
    return f"{value:.4g} N"


made = {}          # (student, question) → the kind of answer we made
submissions = folder / "submissions"
for s in students:
    key = gk.exercises.key(NAME, s, secret=SECRET)
    lines = []
    for q in key["questions"]:
        kind = str(rng.choice(KINDS, p=[0.7, 0.1, 0.06, 0.06, 0.04, 0.04]))
        if kind == "power_of_ten" and q["unit"] != "N*m":
            kind = "correct"       # a force has no N·mm to slip into
        made[s, q["id"]] = kind
        if kind == "missing":
            continue
        text = "see my drawing" if kind == "unreadable" else typed(q, q["answer"]["si"], kind)
        lines.append(f"{q['id']} = {json.dumps(text, ensure_ascii=False)}")
    own = submissions / s
    own.mkdir(parents=True)
    (own / "answers.toml").write_text("\n".join(lines) + "\n", encoding="utf-8")
    meta = {"users": [{"name": f"Student {s}", "email": f"{s}@uni.example", "sid": s}],
            "assignment": {"title": "Strip cutter, week 6"}}
    (own / "submission_metadata.json").write_text(json.dumps(meta), encoding="utf-8")

# The friend's file: the last student uploads the first one's answers, with the first one's id in it.
copier, friend = students[-1], students[0]
answers_of_friend = (submissions / friend / "answers.toml").read_text(encoding="utf-8")
(submissions / copier / "answers.toml").write_text(f'student = "{friend}"\n' + answers_of_friend, encoding="utf-8")
print(f"{len(students)} submissions; {copier}'s answers.toml:\n")
print((submissions / copier / "answers.toml").read_text(encoding="utf-8"))

# %% [markdown]
# ## 4. Grading every submission with the real autograder
#
# For each submission we lay out a folder as Gradescope lays out `/autograder` — the unpacked zip in
# `source/`, the student's files in `submission/`, the metadata beside them, an empty `results/` —
# and run `run_autograder`. `GRAPHKIN_AUTOGRADER_ROOT` points it at that folder instead of
# `/autograder`, and `GRAPHKIN_PYTHON` at this notebook's Python instead of the one `setup.sh` would
# have installed. Two at a time, one per core.

# %%
source = folder / "autograder-source"
with zipfile.ZipFile(export / "autograder.zip") as z:
    z.extractall(source)
os.chmod(source / "run_autograder", 0o755)


def autograde(student):
    """Grade one submission as Gradescope would; return its results.json as data."""
    root = folder / "runs" / student
    (root / "results").mkdir(parents=True)
    shutil.copytree(source, root / "source")
    shutil.copytree(submissions / student, root / "submission")
    shutil.move(root / "submission" / "submission_metadata.json", root / "submission_metadata.json")
    env = dict(os.environ, GRAPHKIN_AUTOGRADER_ROOT=str(root), GRAPHKIN_PYTHON=sys.executable)
    subprocess.run(["bash", str(root / "source" / "run_autograder")], env=env, capture_output=True, check=True)
    return json.loads((root / "results" / "results.json").read_text(encoding="utf-8"))


start = time.perf_counter()
with ThreadPoolExecutor(max_workers=2) as pool:
    results = dict(zip(students, pool.map(autograde, students)))
elapsed = time.perf_counter() - start
print(f"{len(results)} submissions graded in {elapsed:.1f} s "
      f"({elapsed / len(results):.2f} s each, on {min(2, os.cpu_count() or 1)} cores)")

# %% [markdown]
# What one student reads on Gradescope: the summary, then one test per question with graphkin's
# verdict and feedback sentence. Here the first student who made a slip:

# %%
slipper = next(s for s in students if any(made[s, q.id] in ("sign", "power_of_ten")
                                          for q in gk.exercises.load(NAME).questions) and s != copier)
r = results[slipper]
print(r["output"], "\n")
for t in r["tests"]:
    print(f"[{t['score']:g} / {t['max_score']:g}] {t['output']}")

# %% [markdown]
# And the student who uploaded a friend's file:

# %%
print(results[copier]["output"])

# %% [markdown]
# ## 5. The class at a glance
#
# Gradescope shows each score; for a class's slips you want the verdicts as data. Each
# `results.json` carries graphkin's whole report under `extra_data` (Gradescope stores it with the
# submission and does not show it), the same report `graphkin exercise grade --json` prints.
# Gradescope's *Export Submissions* gives you these files for a real class.

# %%
scores = np.array([results[s]["score"] for s in students])
reports = {s: results[s]["extra_data"]["graphkin"] for s in students if "extra_data" in results[s]}
counts = Counter((q["id"], q["slip"] or q["verdict"]) for rep in reports.values() for q in rep["questions"]
                 if q["verdict"] != "correct")

fig = Figure(figsize=(10, 3.6), layout="constrained")
ax1, ax2 = fig.subplots(1, 2, width_ratios=[1, 1.4])
ax1.hist(scores, bins=np.arange(-0.25, 3.5, 0.5), color="#4c72b0", edgecolor="white")
ax1.set(xlabel="score (of 3 points)", ylabel="students", title=f"Scores, mean {scores.mean():.2f}")
labels = [f"{qid}: {what.replace('_', ' ')}" for (qid, what), n in counts.most_common()]
ax2.barh(labels[::-1], [n for _, n in counts.most_common()][::-1], color="#dd8452")
ax2.set(xlabel="answers", title="What went wrong, by question")
ax2.xaxis.get_major_locator().set_params(integer=True)
fig

# %% [markdown]
# Read it as a teacher: a sign slip on T12 means the torque's sense is not settled (go back to the
# sign convention); a power of ten means a unit was carried wrong; "wrong" answers are the ones to
# look at by hand. The student who copied scored 0, with a sentence saying why.

# %% [markdown]
# ## 6. The other platforms
#
# The same command writes for the other three; each export has a README with that platform's
# next commands, and `docs/platforms/` has each one step by step.
#
# * **otter-grader** (`--to otter`): an assignment notebook with the student's id, a cell that
#   prints their data and one answer cell per question. `otter assign` makes the student notebook
#   and the autograder; `otter run` grades, through graphkin's otter plugin (below), and
#   `graphkin exercise collect` makes one class table of the `results.json` files.
# * **nbgrader** (`--to nbgrader`): a source notebook for your course directory and two lines for
#   `nbgrader_config.py`; `nbgrader generate_assignment`, then `nbgrader autograde`. Each question's
#   test cell shows graphkin's feedback and ends in the score (nbgrader's partial credit); a notebook
#   carrying another student's id than the one nbgrader grades it under scores 0.
# * **PrairieLearn** (`--to prairielearn`): a question folder (`info.json`, `question.html`,
#   `server.py`) and graphkin under `serverFilesCourse/`. `generate` draws a variant per
#   PrairieLearn variant; `grade` writes graphkin's feedback per answer box.
#
# With a course secret, the notebook platforms need `--roster`: the student notebook then carries
# each student's data (never the answers), and grading carries the roster's keys, never the secret.
#
# **Why a notebook cannot grade itself.** otter and nbgrader grade by running the student's notebook,
# and code in a notebook can replace any function a test calls. So graphkin never lets it: otter's
# plugin and nbgrader's preprocessor read the handed-in notebook **as a file**, take the text
# assigned to `STUDENT` and to each answer (literals only; nothing is run), grade those answers in a
# separate Python process that holds the keys, and write the grade themselves. You can do the same
# on your own machine with `graphkin exercise grade --keys`. Here is a notebook that tries to give
# itself full marks, graded as the platforms grade it (the otter export writes the keys file):

# %%
import nbformat  # noqa: E402  (here, because only this cell writes a notebook)

graphkin("exercise", "export", NAME, "--to", "otter", "-o", "otter", "--roster", "roster.csv", "--secret", SECRET)
forger = students[1]
forged = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in [
    f"STUDENT = {forger!r}",
    # Replace graphkin's grader with one that says "correct" to everything...
    "import graphkin.exercises.grading as g\n"
    "g.grade_question = lambda *a, **k: {'verdict': 'correct', 'score': 1.0}",
    # ... and answer anything at all, or compute the answer from the course's files.
    'F23 = "1 N ∠ 0°"', 'F14 = "1 N"', 'T12 = open("otter/strip_cutter_cut-keys.json").read()',
]])
nbformat.write(forged, folder / "forged.ipynb")
print(graphkin("exercise", "grade", NAME, "--keys", "otter/strip_cutter_cut-keys.json", "--answers", "forged.ipynb"))

# %% [markdown]
# It scores what its answers earn: nothing. The line that replaced the grader never ran, and the
# answer written as code was not read (its feedback says to type the answer as text). The tests of
# `tests/exercises/platforms/` hand in a dozen such notebooks to the real otter and nbgrader, and
# `docs/platforms/` says, for each platform, what a student can and cannot learn or do.
#
# PrairieLearn's export is a question folder:

# %%
graphkin("exercise", "export", NAME, "--to", "prairielearn", "-o", "pl", "--secret", SECRET)
print("\n".join(sorted(str(p.relative_to(folder / "pl")) for p in (folder / "pl").rglob("*")
                       if p.is_file() and "serverFilesCourse" not in p.parts)))

# %% tags=["remove-input"] jupyter={"source_hidden": true}
import tomllib  # noqa: E402  (here, because only the checks read the answers files back)

for s in students:
    answers = tomllib.loads((submissions / s / "answers.toml").read_text(encoding="utf-8"))
    answers.pop("student", None)
    if s == copier:
        assert results[s]["score"] == 0 and "each student answers their own variant" in results[s]["output"]
        continue
    report = gk.exercises.grade(NAME, s, answers, secret=SECRET, classmates=students)   # as the autograder does
    assert abs(results[s]["score"] - report["score"]) < 1e-12, s
    assert results[s]["extra_data"]["graphkin"] == json.loads(json.dumps(report)), s
    for q in report["questions"]:
        want = {"correct": "correct", "missing": "missing", "unreadable": "unreadable", "wrong": "wrong"}.get(
            made[s, q["id"]], made[s, q["id"]])
        assert (q["slip"] or q["verdict"]) == want, (s, q["id"], q["verdict"], q["slip"], made[s, q["id"]])
assert sum(counts.values()) == sum(kind != "correct" for (s, _), kind in made.items() if s != copier)
assert (source / "keys.json").is_file() and "secret" not in json.loads((source / "config.json").read_text())
assert not [p for p in source.rglob("*") if p.is_file() and SECRET.encode() in p.read_bytes()]
forged_grade = next(csv.DictReader(graphkin("exercise", "grade", NAME, "--keys", "otter/strip_cutter_cut-keys.json",
                                            "--answers", "forged.ipynb").splitlines()))
assert (forged_grade["student"], float(forged_grade["score"])) == (forger, 0.0)
assert forged_grade["T12 verdict"] == "unreadable" and "as text" in forged_grade["T12 feedback"]
for p in (export / "student_template", export / "README.md"):
    files = [p] if p.is_file() else list(p.rglob("*"))
    assert all(SECRET not in f.read_text(encoding="utf-8") for f in files if f.is_file())
assert SECRET not in (folder / "pl" / "questions" / NAME / "question.html").read_text(encoding="utf-8")
print("checks passed:", len(students), "submissions, mean score", round(float(scores.mean()), 3))
