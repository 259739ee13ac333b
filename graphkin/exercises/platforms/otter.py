"""Export an exercise to otter-grader: one master notebook that ``otter assign`` splits.

otter-grader (https://otter-grader.readthedocs.io) works from a *master
notebook*: question cells, solutions between markers and tests.
``otter assign`` turns it into the student notebook (solutions replaced by
``...``, hidden tests removed) and an autograder zip for Gradescope (or for
``otter run`` on the teacher's machine).

Otter has one seed per class, not one per student, so nothing here asks it
for random data. Each student's data comes from their id, as in
``graphkin exercise make``: the notebook asks for the id (``STUDENT``) and
prints the student's sheet; the hidden tests hand the id, the answer and the
course secret to :mod:`graphkin.exercises.platforms.runtime`, which recomputes
the student's reference and grades with graphkin's own grader. A failing test
therefore carries graphkin's feedback sentence, not otter's bare "test failed".

Otter's test cases score all or nothing, and graphkin's grader gives partial
credit for a diagnosed slip. A question becomes one hidden test case per
*credit level*: the distinct scores a slip can earn and the full score (see
:func:`credit_levels`). The case for a level passes when graphkin's score
reaches it, and is worth the step from the level below, so the cases that
pass add up to exactly graphkin's score.

What the test functions call (:func:`check` and :func:`readable`) is in this
module, so a test cell stays a few lines: otter keeps only the function
definition of a test cell, and passes the function's arguments by name from
the student's namespace (``STUDENT`` and the answer's variable).
"""

from __future__ import annotations

import json
import keyword
from functools import lru_cache
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.exercises.answers import Unreadable, read_answer
from graphkin.exercises.exercise import dimension_of
from graphkin.exercises.grading import MESSAGES
from graphkin.exercises.platforms import requirements, runtime, vendor_files
from graphkin.optional import require

GRADESCOPE_METADATA = "/autograder/submission_metadata.json"
"""Where Gradescope puts the submission's metadata (who handed it in) on its grading machine."""

VENDOR = "vendor"
"""The folder of the export (and of the student's and the autograder's folders) holding graphkin itself."""

# Names the notebook itself uses: a question's answer variable must not take one of them.
_RESERVED = {"STUDENT", "grader", "otter", "runtime", "sys"}


# ---------------------------------------------------------------------------------------------------------
# What the exported tests call on the platform
# ---------------------------------------------------------------------------------------------------------

def check(exercise_file, student, qid: str, answer, secret: str = "", *, level: float, sheets=None,
          metadata=GRADESCOPE_METADATA) -> None:
    """One hidden test case: pass when graphkin gives ``answer`` at least ``level`` points.

    Parameters
    ----------
    exercise_file : str or Path
        The exercise file that travelled with the export (relative to the working folder).
    student : str
        The id the student typed in the notebook (``STUDENT``).
    qid : str
        The question's id.
    answer
        What the student's answer variable holds (text, a number, or ``...`` if unanswered).
    secret : str
        The course secret (only the autograder's copy of the tests carries it).
    level : float
        The points this test case asks for (one of :func:`credit_levels`).
    sheets : str or Path, optional
        The roster's sheets (JSON): an id that is not on the roster scores nothing.
    metadata : str or Path
        Gradescope's submission metadata; when it names who handed the notebook in,
        an id that is not theirs scores nothing. Absent when grading locally.

    Raises
    ------
    AssertionError
        When the answer earns less than ``level``: the message is graphkin's
        feedback line for the question (verdict, points and the sentence).
    """
    problem = _student_problem(exercise_file, student, sheets, metadata)
    if problem:
        raise AssertionError(f"{qid}: 0 points — {problem}")
    result = _graded(exercise_file, student, qid, answer, secret)
    if result["score"] < level * (1 - 1e-9):
        raise AssertionError(runtime.feedback_line(result))


def readable(exercise_file, qid: str, answer) -> None:
    """The public test case: the answer is given and can be read (its value is not checked).

    It needs neither the student's key nor the secret, so it leaks nothing;
    students run it with ``grader.check``.

    Raises
    ------
    AssertionError
        With the sentence ``graphkin exercise grade`` gives a missing or an unreadable answer.
    """
    value = runtime.answer_value(answer)
    if value is None or (isinstance(value, str) and not value.strip()):
        raise AssertionError(MESSAGES["missing"].format(name=qid))
    q = runtime.exercise(exercise_file).question(qid)
    try:
        read_answer(value, dimension=dimension_of(q.kind, q.part), unit=q.unit)
    except Unreadable as exc:
        raise AssertionError(str(exc)) from None


def _student_problem(exercise_file, student, sheets, metadata) -> str | None:
    """Why this notebook cannot be graded under the id it carries (a sentence), or None."""
    if not isinstance(student, str) or not student.strip():
        return ("this notebook carries no student id: type yours in the STUDENT cell, in quotes, "
                "as your teacher gave it")
    try:
        if sheets is not None:
            runtime.sheet(exercise_file, student, sheets)  # refuses an id that is not on the roster
    except GraphkinError as exc:
        return str(exc)
    # Gradescope names who handed the notebook in (several for a group): the id must be one of theirs.
    ids = _submitters(metadata)
    if ids and all(runtime.identity_error(student, who) for who in ids):
        return runtime.identity_error(student, ids[0])
    return None


def _submitters(metadata) -> list[str]:
    """Who handed the submission in, by Gradescope's metadata (student id, else email); [] if unknown."""
    try:
        data = json.loads(Path(metadata).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return []
    users = data.get("users") if isinstance(data, dict) else None
    ids = []
    for user in users if isinstance(users, list) else []:
        if isinstance(user, dict):
            who = user.get("sid") or user.get("email")
            if isinstance(who, str) and who.strip():
                ids.append(who)
    return ids


def _graded(exercise_file, student, qid, answer, secret) -> dict:
    """graphkin's result for one answer; the credit-level cases of a question share one grading."""
    if isinstance(answer, (str, int, float)) and not isinstance(answer, bool):
        return _graded_cached(str(Path(exercise_file).resolve()), student, qid, type(answer), answer, secret)

    return runtime.grade_question(exercise_file, student, qid, answer, secret)


@lru_cache(maxsize=256)
def _graded_cached(exercise_file, student, qid, _type, answer, secret) -> dict:
    return runtime.grade_question(exercise_file, student, qid, answer, secret)


# ---------------------------------------------------------------------------------------------------------
# Building the export
# ---------------------------------------------------------------------------------------------------------

def credit_levels(points: float, partial: dict) -> list[float]:
    """The scores a question can earn above 0, lowest first: each slip's share of ``points``, and ``points``.

    Examples
    --------
    >>> credit_levels(1.0, {"sign": 0.5, "rpm_as_rad_s": 0.25, "dimension": 0.0})
    [0.25, 0.5, 1.0]
    >>> credit_levels(0.0, {"sign": 0.5})
    []
    """
    if points <= 0:
        return []
    levels = {_tidy(points * share) for share in partial.values() if 0 < share < 1}
    return sorted(levels | {_tidy(points)})


def _tidy(x: float) -> float:
    """A point value without float dust (0.30000000000000004 → 0.3), so otter's sums come out exact."""
    return float(f"{x:.12g}")


def variable(qid: str) -> str:
    """The notebook variable that holds the answer to question ``qid``.

    The id itself when it is a Python name the notebook does not use already;
    otherwise ``answer_`` and the id with ``.`` written as ``_``.

    Examples
    --------
    >>> variable("F23"), variable("peak.at"), variable("STUDENT")
    ('F23', 'answer_peak_at', 'answer_STUDENT')
    """
    if qid.isidentifier() and not keyword.iskeyword(qid) and qid not in _RESERVED:
        return qid
    return "answer_" + qid.replace(".", "_")


def _variables(bundle) -> dict[str, str]:
    """Question id → answer variable, checked to be distinct."""
    names = {qid: variable(qid) for qid in bundle.question_ids()}
    seen = {}
    for qid, name in names.items():
        if name in seen:
            raise GraphkinError(f"otter: questions {seen[name]!r} and {qid!r} would both be answered in the "
                                f"notebook variable {name}; rename one of them in the exercise file")
        seen[name] = qid
    return names


def build(bundle) -> dict:
    """The export for otter-grader: the master notebook, the files it lists, graphkin and a README.

    Raises
    ------
    GraphkinError
        With a course secret but no roster: the student notebook would have
        to draw each student's data, and so carry the secret.
    """
    require("nbformat", "an export to otter")
    if bundle.secret and bundle.students is None:
        raise GraphkinError(
            "otter: a course secret needs --roster: the student notebook prints each student's data, so it would "
            "have to carry the secret to draw it; with a roster the notebook carries each student's data (never "
            "the secret), and only the autograder's hidden tests carry the secret")
    tree = dict(bundle.files)
    if bundle.students is not None:
        tree[_sheets_file(bundle)] = json.dumps(bundle.sheets, ensure_ascii=False, indent=1) + "\n"
    tree["requirements.txt"] = "\n".join(requirements()) + "\n"
    for rel, data in vendor_files().items():
        tree[f"{VENDOR}/{rel}"] = data
    tree[f"{bundle.name}.ipynb"] = _notebook(bundle)
    tree["README.md"] = _readme(bundle)
    return tree


def _sheets_file(bundle) -> str | None:
    return f"{bundle.name}-sheets.json" if bundle.students is not None else None


def _notebook(bundle) -> str:
    """The master notebook (nbformat 4 JSON)."""
    import nbformat
    from nbformat import v4

    cells = [v4.new_raw_cell(_config(bundle)), *_front_cells(bundle)]
    names = _variables(bundle)
    key = {a["id"]: a["answer"]["text"] for a in bundle.sample_key()["questions"]}
    for q in bundle.exercise.questions:
        cells += _question_cells(bundle, q, names[q.id], key[q.id])
    nb = v4.new_notebook(cells=cells, metadata={
        "kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"},
        "language_info": {"name": "python"},
    })
    return nbformat.writes(nb) + "\n"


def _config(bundle) -> str:
    """The ``# ASSIGNMENT CONFIG`` raw cell (YAML)."""
    files = [*bundle.files] + ([_sheets_file(bundle)] if bundle.students is not None else []) + [VENDOR]
    lines = [
        "# ASSIGNMENT CONFIG",
        f"name: {json.dumps(bundle.name)}",
        "requirements: requirements.txt",
        # STUDENT = "..." lies outside any question: strip the "# SOLUTION" marker in every code cell.
        "strip_solutions_from_all_cells: true",
        "files:",
        *(f"  - {json.dumps(f)}" for f in files),
        "tests:",
        "  ok_format: false",  # one Python function per test case, its arguments taken from the notebook
        "export_cell:",
        "  pdf: false",        # students need no LaTeX to hand in
        "generate:",
        # Per-question scores and graphkin's feedback reach students once the teacher publishes the grades.
        "  show_hidden: true",
    ]
    return "\n".join(lines)


def _front_cells(bundle) -> list:
    """Title, the student's id and their sheet."""
    from nbformat import v4

    ex = bundle.exercise
    sheets = _sheets_file(bundle)
    intro = [f"# {ex.title}", ""]
    if ex.source:
        intro += [f"*{ex.source}*", ""]
    intro += [
        "Every student gets their own data. Type your student id in the cell below, run the cells in order, "
        "and read your data from the sheet it prints. Then answer each question by typing the answer as text, "
        "in quotes, with its unit, e.g. `\"12.3 N ∠ −45°\"`, `\"(7.56, -25.98) N\"`, `\"120.5 N·m CCW\"` "
        "or `\"62.16 N\"`.",
        "",
        "`grader.check(...)` only tells you whether your answer can be read; your teacher's autograder "
        "grades it.",
    ]
    setup = ("# graphkin prints your data and reads your answers; a copy of it comes with this notebook.\n"
             "import sys\n"
             f"if {VENDOR!r} not in sys.path:\n"
             f"    sys.path.append({VENDOR!r})\n"
             "from graphkin.exercises.platforms import runtime")
    args = f"{bundle.exercise_file!r}, STUDENT" + (f", {sheets!r}" if sheets else "")
    return [
        v4.new_markdown_cell("\n".join(intro)),
        v4.new_code_cell(setup),
        v4.new_markdown_cell("Your student id, in quotes, as your teacher gave it:"),
        v4.new_code_cell(f"STUDENT = {bundle.sample!r}  # SOLUTION"),
        v4.new_code_cell(f"print(runtime.sheet_text({args}))"),
    ]


def _question_cells(bundle, q, name: str, solution: str) -> list:
    """One otter question: its prompt, the answer cell (``solution``, the sample's key) and its tests."""
    from nbformat import v4

    levels = credit_levels(q.points, bundle.exercise.partial)
    steps = [_tidy(b - a) for a, b in zip([0.0, *levels], levels)]
    # The public test case is worth nothing; each hidden case the step up to its level.
    config = ["# BEGIN QUESTION", f"name: {json.dumps(q.id)}", f"points: {json.dumps([0, *steps])}"]
    prompt = f"**{q.id}** ({_points(q.points)}): {q.ask}\n\nType your answer in `{name}`, as text in quotes."
    cells = [
        v4.new_raw_cell("\n".join(config)),
        v4.new_markdown_cell(prompt),
        v4.new_raw_cell("# BEGIN SOLUTION"),
        v4.new_code_cell(f"{name} = {solution!r}  # SOLUTION"),
        v4.new_raw_cell("# END SOLUTION"),
        v4.new_raw_cell("# BEGIN TESTS"),
        v4.new_code_cell(_public_test(bundle, q, name)),
        *(v4.new_code_cell(_hidden_test(bundle, q, name, i, level)) for i, level in enumerate(levels, 1)),
        v4.new_raw_cell("# END TESTS"),
        v4.new_raw_cell("# END QUESTION"),
    ]
    return cells


def _points(points: float) -> str:
    return f"{points:g} point" + ("" if points == 1 else "s")


def _import_lines() -> list[str]:
    """How a test function reaches graphkin: installed, else the copy that travelled with the assignment."""
    return ["    import sys",
            f"    if {VENDOR!r} not in sys.path:",
            f"        sys.path.append({VENDOR!r})",
            "    from graphkin.exercises.platforms import otter as graphkin_otter"]


def _test_name(q, suffix: str) -> str:
    return f"test_{q.id.replace('.', '_')}_{suffix}"


def _public_test(bundle, q, name: str) -> str:
    fn = _test_name(q, "readable")
    return "\n".join([
        f"def {fn}({name}):",
        *_import_lines(),
        f"    graphkin_otter.readable({bundle.exercise_file!r}, {q.id!r}, {name})",
        "",
        f"{fn}({name})",
    ])


def _hidden_test(bundle, q, name: str, i: int, level: float) -> str:
    """A hidden test case for one credit level. The secret sits on a line of its own: otter shows the
    line a failing test stopped at, and that line must never be the secret."""
    fn = _test_name(q, f"credit_{i}")
    sheets = _sheets_file(bundle)
    return "\n".join([
        "# HIDDEN",
        f"def {fn}(STUDENT, {name}):",
        *_import_lines(),
        f"    secret = {bundle.secret!r}",
        f"    graphkin_otter.check({bundle.exercise_file!r}, STUDENT, {q.id!r}, {name}, secret, "
        f"level={level!r}, sheets={sheets!r})",
        "",
        f"{fn}(STUDENT, {name})",
    ])


def _readme(bundle) -> str:
    """README.md of the export: the files, then otter's commands step by step."""
    name = bundle.name
    sheets = _sheets_file(bundle)
    others = "".join(f", `{f}`" for f in bundle.files if f != bundle.exercise_file)
    files = [
        f"- `{name}.ipynb`: the **master notebook** for `otter assign`: the assignment's configuration, one "
        f"question per exercise question with the answers of student `{bundle.sample}` as the solutions, and "
        "the tests" + (" (the hidden ones carry the course secret)" if bundle.secret else "") + ". Teachers only.",
        f"- `{bundle.exercise_file}`{others}: the exercise, so that the notebook and the autograder draw the same "
        "data as `graphkin exercise make`.",
    ]
    if sheets:
        files.append(f"- `{sheets}`: each roster student's sheet (their data and the questions; no answers, "
                     "no secret). The student notebook prints the sheet of the id typed in it; an id that is "
                     "not on the roster gets a sentence saying so, and scores nothing.")
    files += [
        "- `requirements.txt`: what graphkin needs; `otter assign` puts it into the autograder, and Gradescope "
        "installs it in the grading image.",
        f"- `{VENDOR}/graphkin/`: graphkin itself. `otter assign` copies it into the student folder and the "
        f"autograder; the notebook and the tests append `{VENDOR}` to `sys.path`, so an installed graphkin "
        "comes first and this copy serves where there is none (Gradescope's image, a student's laptop).",
    ]
    if bundle.secret:
        secret = ("The course secret is in the master notebook and in `dist/autograder/` only: give students "
                  "`dist/student/` and nothing else.")
    else:
        secret = "There is no course secret: anyone with graphkin can compute any student's key."
    return f"""\
# {bundle.exercise.title}: otter-grader

Made by `graphkin exercise export {name} --to otter`. Each student types their id into the notebook and gets
their own data. The hidden tests recompute that student's answers and grade them with graphkin's grader, so a
wrong answer gets graphkin's feedback sentence and a slip its partial credit (each question has one test case
per credit level, worth the step from the level below: the cases that pass add up to graphkin's score).

## Files

{chr(10).join(files)}

{secret}

## Next steps

1. Make the student notebook and the autograder (otter runs the tests on the solutions as it goes):

   ```sh
   otter assign {name}.ipynb dist
   ```

   `dist/student/` is what students get: `{name}.ipynb` (the answers are `...`; only the public tests,
   which say whether an answer can be read) and the files it needs. The autograder is
   `dist/autograder/{name}-autograder_<date>.zip`.

2. Grade the handed-in notebooks on your own machine (no Docker, a few seconds each). `otter run` takes one
   notebook and writes `results.json` (Gradescope's format: per question `score`, `max_score` and `output`,
   with graphkin's feedback line for each credit level not reached):

   ```sh
   for nb in submissions/*.ipynb; do
       out=results/$(basename "$nb" .ipynb); mkdir -p "$out"
       otter run -a dist/autograder/{name}-autograder_*.zip -o "$out" "$nb"
   done
   ```

3. Or grade on Gradescope: create a programming assignment and upload the zip as its autograder; Gradescope
   builds the image (otter's conda environment plus `requirements.txt`). Students hand in `{name}.ipynb`.
   The tests compare the id in the notebook with who handed it in (Gradescope's Student ID, else the email):
   the roster's ids must be those. Per-question scores and feedback become visible when you publish the grades.

## What the machines need

Your machine: Python 3.11 or newer with `otter-grader` and `ipykernel`, and graphkin's requirements. Students
and the grading image: graphkin's requirements (`{' '.join(requirements())}`) and `otter-grader`.
"""


__all__ = ["GRADESCOPE_METADATA", "VENDOR", "build", "check", "credit_levels", "readable", "variable"]
