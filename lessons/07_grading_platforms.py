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
# a fixed random seed, so the numbers are the same every time; graphkin's tests run this lesson and
# check that the text says what the code does.

# %%
# %matplotlib inline
import tempfile
from pathlib import Path

import graphkin as gk

NAME = "strip_cutter_cut"     # the exercise of this lesson (lesson 06 shows how to write your own)
SECRET = "mech-2025-autumn"   # a demo secret; a real one lives in $GRAPHKIN_SECRET, never in a notebook
folder = Path((workdir := tempfile.TemporaryDirectory(prefix="graphkin-platform-")).name)

# %% [markdown]
# The commands below are typed as in a terminal in the course folder: a hidden helper, `graphkin(...)`,
# runs the `graphkin` command there and returns what it printed.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
import subprocess
import sys

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
for p in sorted(p for p in export.rglob("*") if p.is_file()):
    print(f"{p.relative_to(export)!s:<48}{p.stat().st_size:>9,} bytes")

# %%
import zipfile

with zipfile.ZipFile(export / "autograder.zip") as z:
    print("autograder.zip holds:", ", ".join(sorted({n.split("/")[0] for n in z.namelist()})))

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

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The class, made from the keys as the text above says.
import json

import numpy as np

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

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# Gradescope's /autograder, laid out for each submission (as the text above says).
import compileall
import os
import shutil

source = folder / "autograder-source"
with zipfile.ZipFile(export / "autograder.zip") as z:
    z.extractall(source)
os.chmod(source / "run_autograder", 0o755)
compileall.compile_dir(source / "vendor", quiet=1)   # as setup.sh does when Gradescope builds the image


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


# %%
import time
from concurrent.futures import ThreadPoolExecutor

start = time.perf_counter()
with ThreadPoolExecutor(max_workers=2) as pool:
    results = dict(zip(students, pool.map(autograde, students)))
elapsed = time.perf_counter() - start
print(f"{len(results)} submissions graded in {elapsed:.1f} s ({elapsed / len(results):.2f} s each, two at a time)")

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
# Gradescope shows this at once, and a student may submit again: so a wrong answer is told its slip, or
# which part is wrong (the sign or sense, the size or the direction), never how far off, which would give
# the key away in one more try. Lesson 06 shows the exercise file's `feedback = "distance"` for after the
# deadline; `docs/exercises.md` says what each choice gives away.
#
# And the student who uploaded a friend's file:

# %%
print(results[copier]["output"])

# %% [markdown]
# ## 5. The class at a glance
#
# Gradescope shows each score; for a class's slips you want the verdicts as data. Each
# `results.json` carries under `extra_data` (Gradescope stores it with the submission and does not show
# it) the score and each question's verdict and slip of the report `graphkin exercise grade --json` prints.
# Gradescope's *Export Submissions* gives you these files for a real class.

# %%
reports = {s: r["extra_data"]["graphkin"] for s, r in results.items() if "extra_data" in r}
gk.draw.draw_grades(reports)

# %% [markdown]
# Read it as a teacher: a sign slip on T12 means the torque's sense is not settled (go back to the
# sign convention); a power of ten means a unit was carried wrong; "wrong" answers are the ones to
# look at by hand. The student who copied scored 0, with a sentence saying why; their `results.json`
# carries no report (nothing of theirs was graded), so the charts leave them out. A student who copies a
# friend's answers into a file of their own is graded against the class too: where the friend's data
# explain two or more of the answers, each of those earns nothing ("This is the answer for another
# student's data"); one such answer alone is graded as the student's own.

# %% [markdown]
# ## 6. The other platforms
#
# The same command writes for the other three; each export has a README with that platform's
# next commands, and `docs/platforms/` has each one step by step.
#
# * **otter-grader** (`--to otter`): an assignment notebook with the student's id, a cell that
#   prints their data and one answer cell per question. `otter assign` makes the student notebook
#   and the autograder; `graphkin exercise strip` makes of each hand-in a notebook otter can read,
#   `otter run` grades it through graphkin's otter plugin (below), and `graphkin exercise collect`
#   makes one class table of the `results.json` files.
# * **nbgrader** (`--to nbgrader`): a source notebook for your course directory and the lines for
#   `nbgrader_config.py` (graphkin's exporter and preprocessors); `nbgrader generate_assignment`, then
#   `nbgrader autograde`. Each question's test cell shows graphkin's feedback and ends in the score
#   (nbgrader's partial credit); a notebook carrying another student's id than the one nbgrader grades
#   it under scores 0.
# * **PrairieLearn** (`--to prairielearn`): a question folder (`info.json`, `question.html`,
#   `server.py`) and graphkin under `serverFilesCourse/`. `generate` draws a variant per
#   PrairieLearn variant; `grade` writes graphkin's feedback per answer box.
#
# With a course secret, the notebook platforms need `--roster`: the student notebook then carries
# each student's data (never the answers), and grading carries the roster's keys, never the secret.
# **On otter and nbgrader, the folder students are given lets any student compute any classmate's
# answers with graphkin**: its sheets hold every roster student's data, and graphkin solves the
# exercise. What protects the grade is that a classmate's answers, handed in, score 0.
#
# **Why a notebook cannot grade itself.** otter and nbgrader grade by running the student's notebook,
# and code in a notebook can replace any function a test calls; they also load more of a hand-in than
# its notebook (otter unpickles the `.OTTER_LOG` in the zip; both start the kernel in a folder where
# modules handed in beside the notebook are imported first). So graphkin never lets them: before the
# platform loads anything of a hand-in, otter's plugin and nbgrader's exporter read the notebook
# **as a file**, take the text assigned to `STUDENT` and to each answer (literals only; nothing is
# run), remove everything else that was handed in, grade those answers in a separate Python process
# that holds the keys, and write the grade themselves. You can do the same on your own machine with
# `graphkin exercise grade --keys`. Here is a notebook that tries to give itself full marks, graded as
# the platforms grade it (the otter export writes the keys file):

# %%
graphkin("exercise", "export", NAME, "--to", "otter", "-o", "otter", "--roster", "roster.csv", "--secret", SECRET)

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The forger's notebook, cell by cell, as nbformat writes it.
import nbformat

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
print("forged.ipynb:\n\n" + "\n\n".join(f"[{k + 1}] {c.source}" for k, c in enumerate(forged.cells)))

# %%
print(graphkin("exercise", "grade", NAME, "--keys", "otter/strip_cutter_cut-keys.json", "--answers", "forged.ipynb"))

# %% [markdown]
# It scores what its answers earn: nothing. The line that replaced the grader never ran, and the
# answer written as code was not read (its feedback says to type the answer as text). The tests of
# `tests/exercises/platforms/` hand in dozens of such notebooks, zips and folders to the real otter
# and nbgrader (shadow packages, pickles, links to the keys, notebooks too big or too deep to read),
# and `docs/platforms/` says, for each platform, what a student can and cannot learn or do, and what
# the platform leaves open that graphkin cannot close.
#
# PrairieLearn's export is a question folder:

# %%
graphkin("exercise", "export", NAME, "--to", "prairielearn", "-o", "pl", "--secret", SECRET)
print("\n".join(sorted(str(p.relative_to(folder / "pl")) for p in (folder / "pl").rglob("*")
                       if p.is_file() and "serverFilesCourse" not in p.parts)))
