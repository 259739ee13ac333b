"""nbgrader: a source notebook for a course directory.

``build(bundle)`` writes ``source/<name>/``, which the teacher copies into
their nbgrader course directory, then runs ``nbgrader generate_assignment``
and, once the submissions are collected, ``nbgrader autograde``. The
notebook is made of nbgrader's own cell types:

- the student types their id into ``STUDENT`` (a solution cell, so it stays
  editable) and a locked cell prints their sheet from the roster's sheets
  that travel with the notebook, so the student's copy needs no secret;
- each answer is a solution cell (``F23 = "3226 N ∠ −114.32°"`` between
  ``### BEGIN SOLUTION`` and ``### END SOLUTION``, the sample student's key);
- each question has an autograder test cell worth the question's points.
  Its visible part only checks that the answer can be read. Its hidden part
  checks the id nbgrader grades under against ``STUDENT``, grades the answer
  with :func:`graphkin.exercises.platforms.runtime.grade_question`, prints
  the feedback line and ends with the score: nbgrader takes a test cell's
  last value as its score (partial credit).

The course secret is not written into the notebook at all, not even into
the hidden tests: nbgrader puts the hidden tests back into the autograded
notebook, and ``nbgrader generate_feedback`` shows them to the student (an
open nbgrader issue, jupyter/nbgrader#917). The hidden tests read it from
``$GRAPHKIN_SECRET`` while ``nbgrader autograde`` runs, and check it
against the roster's sheets (:func:`course_secret`).

The three functions above :func:`build` run inside the notebook's kernel.
"""

from __future__ import annotations

import json
import keyword
import os
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.exercises.answers import Unreadable, read_answer
from graphkin.exercises.exercise import dimension_of
from graphkin.exercises.grading import MESSAGES, answer_example
from graphkin.exercises.platforms import requirements, runtime
from graphkin.optional import require

SECRET_VARIABLE = "GRAPHKIN_SECRET"
"""The environment variable the hidden tests read the course secret from while ``nbgrader autograde`` runs."""

STUDENT_VARIABLE = "STUDENT"
"""The notebook variable that holds the id the student typed."""

SCHEMA_VERSION = 3
"""The version of nbgrader's cell metadata (nbgrader 0.6 to 0.9)."""

_BEGIN, _END = "### BEGIN SOLUTION", "### END SOLUTION"
_BEGIN_HIDDEN, _END_HIDDEN = "### BEGIN HIDDEN TESTS", "### END HIDDEN TESTS"


# ---------------------------------------------------------------------------
# Run by the notebook's cells, on the students' and the grader's machines


def graded_as(claimed):
    """The student id nbgrader grades this notebook under; outside ``nbgrader autograde``, ``claimed``.

    nbgrader does not hand the student's id to the kernel, but it runs the
    notebook in ``autograded/<student>/<assignment>/`` (its default
    ``CourseDirectory.directory_structure``) and sets ``NBGRADER_EXECUTION``
    to ``"autograde"``; the folder above the working directory is the
    student. ``$NBGRADER_STUDENT``, when set, takes precedence (for a course
    with another directory structure, graded one student at a time).

    Parameters
    ----------
    claimed : object
        What the notebook's ``STUDENT`` holds: returned as it is when the
        notebook is not being autograded (a student's own run, or ``nbgrader
        validate``), so the identity check passes there.
    """
    explicit = os.environ.get("NBGRADER_STUDENT", "").strip()
    if explicit:
        return explicit
    if os.environ.get("NBGRADER_EXECUTION") == "autograde":
        return Path.cwd().parent.name
    return claimed


def course_secret(exercise_file, student: str, sheets) -> str:
    """The course secret for grading ``student``: ``$GRAPHKIN_SECRET``, checked against the roster's sheet.

    The variant drawn with the secret must give the data the student was
    shown (their sheet in ``sheets``). Otherwise every answer would be graded
    against data the student never saw, and nbgrader records an erroring
    test cell as 0 without a word; so under ``nbgrader autograde`` the kernel
    is stopped after writing the reason to the terminal: nbgrader then
    reports the submission as failed and keeps no grade for it. Elsewhere
    (``nbgrader validate`` of the source notebook) it raises.

    Raises
    ------
    GraphkinError
        If ``student`` is not on the roster (the sentence says so), or the
        secret does not give the student's sheet (outside autograde).
    """
    secret = os.environ.get(SECRET_VARIABLE, "")
    shown = runtime.sheet(exercise_file, student, sheets)["data"]
    if runtime.variant(exercise_file, student, secret).sheet()["data"] == shown:
        return secret
    why = (f"{SECRET_VARIABLE} is not set" if not secret else
           f"${SECRET_VARIABLE} is not the secret this assignment was exported with")
    message = (f"graphkin: cannot grade {student!r}: {why}, so the data it draws differs from the student's sheet; "
               f"run {SECRET_VARIABLE}=<the course secret> nbgrader autograde <assignment>")
    if os.environ.get("NBGRADER_EXECUTION") == "autograde":
        # The kernel's own stderr reaches the terminal that runs nbgrader; the cell's output would not.
        os.write(2, (message + "\n").encode("utf-8"))
        os._exit(3)
    raise GraphkinError(message)


def check_answer(exercise_file, qid: str, answer) -> None:
    """The visible test: an answer is given and can be read (whether it is right is not told).

    Raises ``AssertionError`` (what nbgrader's *Validate* reports) with the
    grader's own sentence for an answer that would be graded missing or
    unreadable, which earn nothing whatever the data; anything else passes,
    and the hidden test grades it. The answer is read as data, never run.
    """
    q = runtime.exercise(exercise_file).question(qid)
    value = runtime.answer_value(answer)
    if value is None or (isinstance(value, str) and not value.strip()):
        raise AssertionError(MESSAGES["missing"].format(name=qid))
    try:
        read_answer(value, dimension=dimension_of(q.kind, q.part), unit=q.unit)
    except Unreadable as exc:
        raise AssertionError(str(exc)) from None
    print(f"{qid}: your answer can be read; it is graded after you hand in.")


# ---------------------------------------------------------------------------
# The export


def build(bundle) -> dict:
    """The course-directory fragment for an exercise: ``{relative path: text}``.

    ``source/<name>/`` holds the source notebook, the exercise file (and a
    base problem file beside it) and, with a roster, ``<name>-sheets.json``;
    ``nbgrader_config.example.py`` and ``README.md`` sit at the top.

    Raises
    ------
    GraphkinError
        With a course secret but no roster: the student's notebook would
        need the secret to draw the student's data.
    """
    require("nbformat", "an export to nbgrader")
    if bundle.secret and not bundle.sheets:
        raise GraphkinError("nbgrader with a course secret needs a roster (--roster CSV): the student's notebook "
                            "prints the student's data from the roster's sheets; without them it would need the "
                            "secret, which students must not see")
    name = bundle.name
    folder = f"source/{name}"
    tree = {f"{folder}/{file}": text for file, text in bundle.files.items()}
    if bundle.sheets:
        tree[f"{folder}/{_sheets_file(bundle)}"] = json.dumps(bundle.sheets, ensure_ascii=False, indent=1) + "\n"
    tree[f"{folder}/{name}.ipynb"] = _notebook(bundle)
    tree["nbgrader_config.example.py"] = _config_example()
    tree["README.md"] = _readme(bundle)
    return tree


def _sheets_file(bundle) -> str | None:
    return f"{bundle.name}-sheets.json" if bundle.sheets else None


_TAKEN = {STUDENT_VARIABLE, "runtime", "check_answer", "course_secret", "graded_as"}
"""Names the notebook's own cells use: no answer may be typed into one of them."""


def variables(bundle) -> dict[str, str]:
    """Question id → the notebook variable the student types the answer into.

    The id itself when it is a Python name the notebook does not use
    (``F23``); else ``answer_`` and the id with dots as underscores
    (``peak.at`` → ``answer_peak_at``, ``runtime`` → ``answer_runtime``).
    """
    names = {}
    for qid in bundle.question_ids():
        ok = qid.isidentifier() and not keyword.iskeyword(qid) and qid not in _TAKEN and not qid.startswith("_")
        names[qid] = qid if ok else "answer_" + qid.replace(".", "_")
    clash = sorted({v for v in names.values() if list(names.values()).count(v) > 1})
    if clash:
        raise GraphkinError(f"{bundle.name}: question ids give the same notebook variable {', '.join(clash)}; "
                            "rename one of them")
    return names


def _grade_id(prefix: str, qid: str) -> str:
    """An nbgrader grade id (letters, digits, ``_`` and ``-``): a question id may hold dots."""
    return f"{prefix}_{qid.replace('.', '-')}"


def _cell(kind: str, source: str, grade_id: str, *, solution=False, grade=False, points=None):
    """A notebook cell with nbgrader's metadata; every cell graphkin writes is locked unless students type in it."""
    import nbformat

    make = nbformat.v4.new_markdown_cell if kind == "markdown" else nbformat.v4.new_code_cell
    cell = make(source)
    meta = {"grade": grade, "grade_id": grade_id, "locked": not solution, "schema_version": SCHEMA_VERSION,
            "solution": solution}
    if grade:
        meta["points"] = points
    cell.metadata["nbgrader"] = meta
    return cell


def _notebook(bundle) -> str:
    """The source notebook as JSON text."""
    import nbformat

    key = {q["id"]: q for q in bundle.sample_key()["questions"]}
    names = variables(bundle)
    cells = [_cell("markdown", _intro(bundle), "intro"),
             _cell("code", _student_cell(bundle), "student", solution=True),
             _cell("code", _sheet_cell(bundle), "sheet")]
    for q in bundle.exercise.questions:
        cells += [_cell("markdown", _question_text(bundle, q, names[q.id]), _grade_id("question", q.id)),
                  _cell("code", _answer_cell(names[q.id], key[q.id]["answer"]["text"]), _grade_id("answer", q.id),
                        solution=True),
                  _cell("code", _test_cell(bundle, q.id, names[q.id]), _grade_id("test", q.id), grade=True,
                        points=q.points)]
    # Ids of our own, in order, so that the same export writes the same notebook.
    for i, cell in enumerate(cells):
        cell["id"] = f"graphkin-{i:02d}"
    nb = nbformat.v4.new_notebook(cells=cells, metadata={
        "kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"},
        "language_info": {"name": "python"}})
    nbformat.validate(nb)
    return nbformat.writes(nb) + "\n"


def _intro(bundle) -> str:
    ex = bundle.exercise
    source = f"\n\n*{ex.source}*" if ex.source else ""
    return f"""# {ex.title}{source}

Each student has their own data. To work:

1. Type your student id in the next cell, exactly as your teacher gave it: `{STUDENT_VARIABLE} = "..."`.
2. Run the cell after it: it prints your data and the questions.
3. Type each answer as text between quotes, with its unit. In each cell you type in, delete the lines
   `# YOUR CODE HERE` and `raise NotImplementedError()`.
4. The cell under each answer checks only that the answer can be read (*Validate* runs them all).
   Your answers are graded after you hand the notebook in, against your own data; a notebook that
   carries another student's id scores 0."""


def _student_cell(bundle) -> str:
    return (f"# Your student id, exactly as your teacher gave it\n{STUDENT_VARIABLE} = ...\n{_BEGIN}\n"
            f"{STUDENT_VARIABLE} = {_literal(bundle.sample)}\n{_END}")


def _sheet_cell(bundle) -> str:
    args = [_literal(bundle.exercise_file), STUDENT_VARIABLE]
    if bundle.sheets:
        args.append(_literal(_sheets_file(bundle)))
    return ("# Your data and the questions\nfrom graphkin.exercises.platforms import runtime\n"
            f"print(runtime.sheet_text({', '.join(args)}))")


def _question_text(bundle, q, variable: str) -> str:
    points = f"{q.points:g} point{'s' if q.points != 1 else ''}"
    return f"**{q.id}** ({points}): {q.ask}\n\nFor example: `{variable} = {_literal(_example_answer(bundle, q))}`"


def _example_answer(bundle, q) -> str:
    """How to write an answer to ``q``: the grader's own example, a made-up number in the question's unit."""
    return answer_example(runtime.variant(bundle.exercise, bundle.sample, bundle.secret).expected(q))


def _answer_cell(variable: str, answer: str) -> str:
    return f"{variable} = ...\n{_BEGIN}\n{variable} = {_literal(answer)}\n{_END}"


def _test_cell(bundle, qid: str, variable: str) -> str:
    """The autograder test: a visible readability check, then the hidden grading that ends in the score."""
    file = _literal(bundle.exercise_file)
    if bundle.secret:  # (an export with a secret always has the roster's sheets: build() sees to it)
        secret = (f"course_secret({file}, _graded, {_literal(_sheets_file(bundle))})  "
                  f"# ${SECRET_VARIABLE}, checked against the sheet")
        imports = "from graphkin.exercises.platforms.nbgrader import course_secret, graded_as"
    else:
        # No secret: every variant is drawn from the id alone, whatever $GRAPHKIN_SECRET holds.
        secret = '""  # this export has no course secret'
        imports = "from graphkin.exercises.platforms.nbgrader import graded_as"
    return f"""# Checks only that {variable} can be read, not whether it is right.
from graphkin.exercises.platforms.nbgrader import check_answer
check_answer({file}, {_literal(qid)}, {variable})
{_BEGIN_HIDDEN}
from graphkin.exercises.platforms import runtime
{imports}
_graded = graded_as({STUDENT_VARIABLE})  # whom nbgrader grades (its folder), whatever the notebook says
_refused = runtime.identity_error({STUDENT_VARIABLE}, _graded)
if _refused:
    print(_refused)
    _score = 0.0
else:
    _secret = {secret}
    _result = runtime.grade_question({file}, _graded, {_literal(qid)}, {variable}, _secret)
    print(runtime.feedback_line(_result))
    _score = _result["score"]
_score  # the last value is the cell's score: nbgrader's partial credit
{_END_HIDDEN}"""


def _literal(text: str) -> str:
    """A Python string literal in double quotes (JSON's escapes are Python's), keeping ∠, ° and − as they are."""
    return json.dumps(text, ensure_ascii=False)


def _config_example() -> str:
    return '''"""An example nbgrader_config.py for a course that grades graphkin's exercises.

Named nbgrader_config.example.py so that it never replaces your own: merge
what you lack into your course's nbgrader_config.py.
"""

c = get_config()  # noqa: F821 (nbgrader defines it)

# Your course's id (the gradebook is gradebook.db in the course directory unless you set
# c.CourseDirectory.db_url).
c.CourseDirectory.course_id = "mechanics"

# graphkin's hidden tests read the student's id from the folder nbgrader grades in,
# autograded/<student>/<assignment>/: keep nbgrader's default directory structure,
#   c.CourseDirectory.directory_structure = "{nbgrader_step}/{student_id}/{assignment_id}"
'''


def _readme(bundle) -> str:
    """The export's README: what each file is, then nbgrader's commands, step by step."""
    name = bundle.name
    files = [f"- `source/{name}/{name}.ipynb`: the source notebook (the sample answers of student "
             f"`{bundle.sample}` in solution regions, the grading in hidden tests).",
             f"- `source/{name}/{bundle.exercise_file}`: the exercise; the notebook reads it, on the students' "
             "machines and when grading."]
    files += [f"- `source/{name}/{f}`: the exercise's base problem." for f in bundle.files if f != bundle.exercise_file]
    if bundle.sheets:
        files.append(f"- `source/{name}/{_sheets_file(bundle)}`: each roster student's sheet (data and questions, "
                     "no answers); the student's notebook prints its own from it.")
    files += ["- `nbgrader_config.example.py`: an example configuration, to merge into your own "
              "`nbgrader_config.py` (named so that it never replaces yours).",
              "- `README.md`: this file."]
    secret_env = f"{SECRET_VARIABLE}=<the course secret> " if bundle.secret else ""
    if bundle.secret:
        secret_note = (f"The course secret is in none of these files. The hidden tests read it from "
                       f"`${SECRET_VARIABLE}` while `nbgrader autograde` runs; without it (or with another one) "
                       "autograde stops with `graphkin: cannot grade ...` and keeps no grade.")
    else:
        secret_note = ("This export has no course secret: anyone with graphkin can compute any student's key "
                       "from their id.")
    reqs = "\n".join(f"    {r}" for r in requirements())
    first = bundle.exercise.questions[0]
    typed = f"{variables(bundle)[first.id]} = {_literal(_example_answer(bundle, first))}"
    return f"""# {bundle.exercise.title}: nbgrader

Exported by graphkin for nbgrader (tried with nbgrader 0.9.6).

## Files

{chr(10).join(files)}

{secret_note}

## Steps

In your nbgrader course directory (the folder with `nbgrader_config.py`). Put your environment's
`bin` folder first on `PATH`: nbgrader runs `alembic` from `PATH` for its gradebook, and without
it `nbgrader generate_assignment` fails with `FileNotFoundError: ... 'alembic'`.

1. Copy `source/{name}/` into the course's `source/` folder (and, if you have no
   `nbgrader_config.py` yet, `nbgrader_config.example.py` as `nbgrader_config.py`).
2. `nbgrader generate_assignment {name}`: writes the students' copy in `release/{name}/`
   (no answers, no hidden tests).
3. Release and collect as usual (`nbgrader release_assignment {name}` and
   `nbgrader collect {name}`, or your hub's or LMS's way): submissions go to
   `submitted/<student>/{name}/{name}.ipynb`.
4. `{secret_env}nbgrader autograde {name}` (students missing from the gradebook are added).
5. `nbgrader export`: `grades.csv`, one row per student and assignment; per-question scores
   are in the formgrader and the gradebook.
6. `nbgrader generate_feedback {name}` if you return feedback: it shows each test cell's
   feedback line, and also the hidden tests' code (no key and no secret are in it).

## What students see

The notebook: they type their id (`{STUDENT_VARIABLE} = "..."`), run the next cell to print their
own data and the questions, type each answer as text (`{typed}`), and the cell
under each answer tells them only whether it can be read. After autograde each test cell prints one
line, e.g. `T12: slip (sign), 0.5 / 1 — The size is right but the sense is wrong: ...`, and scores
that share of the question's points. A notebook whose `{STUDENT_VARIABLE}` is not the student nbgrader
grades it as scores 0 on every question, with the sentence
`this submission carries the student id '...' but was handed in by '...'`.

## What the machines need

The Jupyter kernel students work in, and the one `nbgrader autograde` runs, need graphkin (the
version that made this export) and its requirements:

{reqs}
"""


__all__ = ["SECRET_VARIABLE", "STUDENT_VARIABLE", "build", "check_answer", "course_secret", "graded_as", "variables"]
