"""nbgrader: a source notebook for a course directory, and the exporter and preprocessors that grade it as data.

``build(bundle)`` writes ``source/<name>/``, which the teacher copies into their nbgrader course
directory, then runs ``nbgrader generate_assignment`` and, once the submissions are collected,
``nbgrader autograde``. The notebook is made of nbgrader's own cell types:

- the student types their id into ``STUDENT`` (a solution cell, so it stays editable) and a locked
  cell prints their sheet from the roster's sheets that travel with the notebook;
- each answer is a solution cell (``F23 = "3226 N ∠ −114.32°"`` between ``### BEGIN SOLUTION`` and
  ``### END SOLUTION``, the sample student's key);
- each question has an autograder test cell worth the question's points. Its visible part only checks
  that the answer can be read.

**Only the answers a student typed count, whatever else they hand in.** nbgrader grades by running the
notebook in a kernel, where the student's code runs beside the tests; before that it parses the submitted
notebook and copies the submission's other files (and what its links point to) into the folder the kernel
starts in, where Python imports them first, and which ``generate_feedback`` copies back to the student. The
export's ``nbgrader_config.example.py`` names three hooks, each in nbgrader's own process:

- ``HandInExporter`` (``Autograde.exporter_class``) reads each submission of an assignment with keys before
  nbgrader does (:func:`graphkin.exercises.handins.read_handin`: the literals assigned to ``STUDENT`` and to
  each answer's variable) and hands nbgrader :func:`reduced_notebook`: graphkin's cells, the answers as
  literals, nothing else of the student's; what else was handed in, and a notebook that cannot be read, are
  named in nbgrader's log;
- :func:`read_as_data`, first among ``Autograde.autograde_preprocessors``, before nbgrader's ``Execute``,
  grades the submission read as data in a separate, isolated Python process with the precomputed keys
  (``graphkin-keys/<name>.json`` in the course directory, beside ``source/``; never the secret), empties the
  kernel's folder of what nbgrader copied of the submission, and writes each test cell as the feedback line
  and the score;
- :func:`write_grades`, after ``Execute``, sets each test cell's output to graphkin's feedback line and
  score, whatever the kernel printed: nbgrader records that number (its partial credit).

The student's id is the one nbgrader grades under; a notebook carrying another's scores 0.

A test cell's hidden part fails loudly when the preprocessor was not configured: under ``nbgrader
autograde`` it stops the kernel, so nbgrader keeps no grade rather than one the notebook decided.
"""

from __future__ import annotations

import datetime
import json
import math
import os
import time
import tomllib
from functools import cache
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.exercises.grading import answer_example, echo
from graphkin.exercises.handins import METADATA, HandIn, clear_folder, literal, own_files, read_handin
from graphkin.exercises.keys import Keys, keys_text
from graphkin.exercises.notebooks import STUDENT_VARIABLE, answer_variables
from graphkin.exercises.platforms import requirements, runtime
from graphkin.exercises.platforms.isolated import grade_submissions, submission
from graphkin.optional import require

KEYS_FOLDER = "graphkin-keys"
"""The folder of the course directory (beside ``source/``) holding each assignment's keys, ``<assignment>.json``."""

PREPROCESSOR = "graphkin.exercises.platforms.nbgrader.read_as_data"
"""The importable name of :func:`read_as_data`, as ``nbgrader_config.py`` lists it."""

GRADE_WRITER = "graphkin.exercises.platforms.nbgrader.write_grades"
"""The importable name of :func:`write_grades`, as ``nbgrader_config.py`` lists it (after ``Execute``)."""

EXPORTER = "graphkin.exercises.platforms.nbgrader.HandInExporter"
"""The importable name of the exporter ``nbgrader autograde`` reads submissions with (``HandInExporter``)."""

CLASSMATES = (
    "the folder released to students lets any student compute any classmate's answers with graphkin: its sheets "
    "hold every roster student's data. A classmate's answers handed in score 0.")
"""What the released folder lets every student do."""

NOT_CLOSED = (
    "nbgrader autograde copies the files of a submission folder, and what its links point to, as you, before "
    "graphkin's exporter runs: graphkin reads none of it and removes the copies before the kernel starts, so "
    "generate_feedback hands none of it back. To keep nbgrader from reading through links at all, remove them "
    "from submitted/ before you autograde: find submitted -type l -delete")
"""What nbgrader's own design leaves open that graphkin cannot close from its side."""

NOTES = (NOT_CLOSED, CLASSMATES)
"""Said when the export is made (``graphkin exercise export`` prints them) and in its README."""

GRADES = "graphkin_grades"
"""The key of nbgrader's resources under which :func:`read_as_data` leaves the grades for :func:`write_grades`."""

TIMEOUT = 120
"""Seconds nbgrader's ``Execute`` may spend on one notebook, its cells together (:class:`TimeLimit`)."""

SCHEMA_VERSION = 3
"""The version of nbgrader's cell metadata (nbgrader 0.6 to 0.9)."""

_BEGIN, _END = "### BEGIN SOLUTION", "### END SOLUTION"
_BEGIN_HIDDEN, _END_HIDDEN = "### BEGIN HIDDEN TESTS", "### END HIDDEN TESTS"
_READ = "  # read from your notebook as data"
_KERNEL = {"kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"},
           "language_info": {"name": "python"}}
# nbgrader's course layout (its default CourseDirectory settings, which graphkin's lines assume).
_SUBMITTED, _AUTOGRADED, _TIMESTAMP = "submitted", "autograded", "timestamp.txt"
_LAYOUT = "{nbgrader_step}/{student_id}/{assignment_id}"
_IGNORED_BY_NBGRADER = (".ipynb_checkpoints", "__pycache__", "feedback")


# ---------------------------------------------------------------------------
# Run by nbgrader autograde, in nbgrader's own process (never in the kernel)


class TimeLimit:
    """A time limit per notebook for nbgrader's ``Execute``: each cell gets what is left of the notebook's.

    nbgrader limits each cell (``c.Execute.timeout``), so a notebook of n cells may hold up the class n times
    as long, and a file handed in beside the notebook can hang the kernel at every cell. nbclient, which
    ``Execute`` is made of, calls ``on_notebook_start`` as each notebook starts and asks ``timeout_func`` for
    each cell's limit: :meth:`start` notes the time, :meth:`cell_timeout` gives the rest of the budget (at
    least one second, which nbclient needs to interrupt the kernel and go on). nbgrader autogrades one
    notebook at a time, so one object serves a whole run. The grade never waits on the kernel: it was made
    from the notebook read as data before ``Execute`` (:func:`read_as_data`).

    Parameters
    ----------
    seconds : float
        The budget of one notebook [s].
    clock : callable, optional
        The clock [s]; ``time.monotonic`` unless a test gives its own.
    """

    def __init__(self, seconds: float = TIMEOUT, clock=time.monotonic):
        if not seconds > 0:
            raise GraphkinError(f"an nbgrader time limit must be a positive number of seconds, not {seconds!r}")
        self.seconds, self.clock = float(seconds), clock
        self.started = clock()

    def start(self, **_):
        """nbclient's ``on_notebook_start`` hook: the notebook's clock starts."""
        self.started = self.clock()

    def cell_timeout(self, cell) -> int:
        """nbclient's ``timeout_func``: what is left of the notebook's budget [s], at least 1."""
        return max(1, math.ceil(self.seconds - (self.clock() - self.started)))


def course_root(resources) -> Path:
    """The course directory of the notebook nbgrader is autograding.

    nbgrader runs it in ``autograded/<student>/<assignment>/`` (its default
    ``CourseDirectory.directory_structure``), three folders below the course directory.
    """
    path = Path((resources.get("metadata") or {}).get("path") or ".").resolve()
    return path.parents[2] if len(path.parents) > 2 else Path.cwd()


def assignment_files(root: Path, assignment: str) -> dict[str, Path]:
    """The assignment's own files, as nbgrader copies them into a student's folders: those of
    ``source/<assignment>/`` but its notebooks (which hold the solutions) and what nbgrader ignores."""
    files = own_files(root / "source" / assignment, skip=_IGNORED_BY_NBGRADER)
    return {rel: path for rel, path in files.items() if not rel.lower().endswith(".ipynb")}


def _handin(root: Path, student: str, assignment: str, notebook: str, names: dict) -> HandIn:
    """A student's submission folder (``submitted/<student>/<assignment>/``) read as data."""
    submitted = root / _SUBMITTED / student / assignment
    # nbgrader's own record of when it was handed in sits beside the notebook: not the student's to name.
    own = {**assignment_files(root, assignment), _TIMESTAMP: submitted / _TIMESTAMP}
    return read_handin(submitted, names, notebook=f"{notebook}.ipynb", own=own)


def reduced_notebook(exercise, handin: HandIn):
    """The notebook nbgrader gets in place of a submission: graphkin's cells, the id and each answer as literals.

    Each cell is one of the source notebook's, with its nbgrader metadata, in its order; a locked cell is
    left empty (nbgrader's ``OverwriteCells`` writes it back from the gradebook), a cell the student
    types in holds the literal read. A cell the student added (an extra grade cell), a cell's outputs and
    the student's metadata are not carried.
    """
    import nbformat

    names = answer_variables([q.id for q in exercise.questions])
    cells = [_cell("markdown", "", "intro"),
             _cell("code", f"{STUDENT_VARIABLE} = {literal(handin.claimed)}{_READ}", "student", solution=True),
             _cell("code", "", "sheet")]
    for q in exercise.questions:
        value = handin.answers.get(q.id)
        cells += [_cell("markdown", "", _grade_id("question", q.id)),
                  _cell("code", f"{names[q.id]} = {literal(value)}{_READ}", _grade_id("answer", q.id), solution=True),
                  _cell("code", "", _grade_id("test", q.id), grade=True, points=q.points)]
    for i, cell in enumerate(cells):
        cell["id"] = f"graphkin-{i:02d}"
    return nbformat.v4.new_notebook(cells=cells, metadata={**_KERNEL, METADATA: {"reduced": True}})


@cache
def _exporter_class():
    # nbconvert is imported only when nbgrader asks for the class (importing graphkin never loads it).
    from nbconvert.exporters import NotebookExporter

    class HandInExporter(NotebookExporter):
        """nbgrader's exporter for ``nbgrader autograde``: a submission of a graphkin assignment is read as data.

        nbgrader reads a submitted notebook (``nbformat.read``) before any preprocessor runs, so a
        notebook nested 100 000 deep or not JSON would stop that student's autograde with a traceback,
        and an extra grade cell could stop the gradebook for the students after. This exporter comes
        first: a submitted notebook of an assignment with keys in ``graphkin-keys/`` is read as data
        (:func:`graphkin.exercises.handins.read_handin`, within its limits), and nbgrader gets
        :func:`reduced_notebook` in its place; what else the submission folder holds is named in
        nbgrader's log. Every other notebook (another assignment's, and nbgrader's own autograded copy) is
        read as nbgrader reads it.
        """

        def from_filename(self, filename, resources=None, **kw):
            reduced = _reduce_submission(self, filename, resources)
            if reduced is None:
                return super().from_filename(filename, resources, **kw)
            nb, resources = reduced
            return self.from_notebook_node(nb, resources, **kw)

    HandInExporter.__module__, HandInExporter.__qualname__ = __name__, "HandInExporter"  # where nbgrader finds it
    return HandInExporter


def __getattr__(name):
    # ``c.Autograde.exporter_class = "graphkin.exercises.platforms.nbgrader.HandInExporter"``: the class is
    # made when nbgrader imports it (PEP 562), so that importing this module does not load nbconvert.
    if name == "HandInExporter":
        return _exporter_class()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def _reduce_submission(exporter, filename, resources):
    """(reduced notebook, resources) for a submitted notebook of a graphkin assignment; None for any other."""
    coursedir = getattr(exporter.parent, "coursedir", None)
    info = (resources or {}).get("nbgrader") or {}
    if coursedir is None or not info:
        return None
    root = Path(coursedir.root)
    student, assignment, notebook = info.get("student"), info.get("assignment"), info.get("notebook")
    keys = root / KEYS_FOLDER / f"{assignment}.json"
    if not keys.is_file():
        return None
    if (coursedir.submitted_directory, coursedir.autograded_directory) != (_SUBMITTED, _AUTOGRADED) or \
            coursedir.directory_structure != _LAYOUT:
        raise GraphkinError("graphkin's nbgrader lines need nbgrader's default course layout "
                            f"(c.CourseDirectory.directory_structure = {_LAYOUT!r}, submitted/ and autograded/)")
    if os.path.abspath(Path(filename).parent) != os.path.abspath(root / _SUBMITTED / str(student) / str(assignment)):
        return None  # nbgrader's own autograded copy, which it reads in its second pass
    exercise = Keys(keys).exercise
    handin = _handin(root, student, assignment, notebook, answer_variables([q.id for q in exercise.questions]))
    if handin.ignored:
        exporter.log.warning("%s: handed in beside the notebook, not read (graphkin): %s", student,
                             ", ".join(handin.ignored))
    added = _cells_added(exercise, handin.grade_ids)
    if added:
        exporter.log.warning("%s: cells of the student's own, not given to nbgrader (graphkin): %s", student,
                             ", ".join(added))
    if handin.refused:
        exporter.log.warning("%s: not graded (graphkin): %s", student, handin.reason)
    path, name = os.path.split(filename)
    changed = datetime.datetime.fromtimestamp(os.lstat(filename).st_mtime, tz=datetime.timezone.utc)
    meta = {"name": os.path.splitext(name)[0], "path": path,  # as nbconvert's own from_filename sets them
            "modified_date": f"{changed:%B} {changed.day}, {changed.year}"}
    resources = dict(resources)
    resources["metadata"] = {**(resources.get("metadata") or {}), **meta}
    return reduced_notebook(exercise, handin), resources


def _cells_added(exercise, grade_ids) -> list[str]:
    """The grade ids of a submission's cells that are not the source notebook's, or are there twice, for the log."""
    ours = {"intro", "student", "sheet"} | {_grade_id(kind, q.id) for q in exercise.questions
                                             for kind in ("question", "answer", "test")}
    seen, added = set(), []
    for gid in grade_ids:
        if gid not in ours or gid in seen:
            added.append(repr(echo(gid, 40)) + (" (again)" if gid in seen else ""))
        seen.add(gid)
    return added


def read_as_data(nb, resources):
    """nbgrader preprocessor: grade the submission read as data, and leave the kernel nothing of the student's.

    Before nbgrader's ``Execute``: the student's submission folder is read as data again (the notebook's
    answers; :func:`graphkin.exercises.handins.read_handin`) and graded in a separate, isolated process
    with the precomputed keys; the folder the kernel starts in (``autograded/<student>/<assignment>/``)
    is emptied of everything but the assignment's own files (what nbgrader copied of the student's, and
    what their links pointed to), so the kernel imports nothing of theirs and ``generate_feedback`` hands
    back nothing of it; and each cell becomes the id, an answer as a literal, or a test cell that prints
    graphkin's feedback line and ends in the score. A cell that is not one of graphkin's is dropped.

    Parameters
    ----------
    nb : nbformat.NotebookNode
        The notebook :class:`HandInExporter` made of the submission, after nbgrader's sanitizing (locked
        cells restored).
    resources : dict
        nbgrader's resources; ``resources["nbgrader"]`` names the student and the assignment.

    Returns
    -------
    nb, resources
        A notebook of an assignment without keys (not graphkin's) is returned as it is.

    Raises
    ------
    GraphkinError
        The notebook was not made by :class:`HandInExporter` (``nbgrader_config.py`` lacks its line).
    """
    info = resources.get("nbgrader") or {}
    root = course_root(resources)
    assignment, student = str(info.get("assignment")), str(info.get("student"))
    keys = root / KEYS_FOLDER / f"{assignment}.json"
    if not keys.is_file():
        return nb, resources
    if not ((nb.get("metadata") or {}).get(METADATA) or {}).get("reduced"):
        raise GraphkinError(f"graphkin: {assignment!r} must be read as data before nbgrader reads it: add "
                            f"c.Autograde.exporter_class = {EXPORTER!r} to nbgrader_config.py (see the export's "
                            "nbgrader_config.example.py), then run nbgrader autograde again")
    qids = [q["id"] for q in tomllib.loads(json.loads(keys.read_text(encoding="utf-8"))["exercise"]["text"])
            ["questions"]]
    names = answer_variables(qids)
    kernel_folder = Path(resources["metadata"]["path"])
    if os.path.abspath(kernel_folder) != os.path.abspath(root / _AUTOGRADED / student / assignment):
        raise GraphkinError(f"graphkin: {kernel_folder} is not {_AUTOGRADED}/{student}/{assignment}/ of the course "
                            "directory: graphkin's nbgrader lines need nbgrader's default course layout")
    handin = _handin(root, student, assignment, str(info.get("notebook")), names)
    report = grade_submissions(keys, [submission(student, handin.answers, handin.claimed,
                                                 refused=handin.refused)])[0]
    clear_folder(kernel_folder, assignment_files(root, assignment), leave={f"{info.get('notebook')}.ipynb", _TIMESTAMP})
    results = {r["id"]: r for r in report["questions"]}
    resources[GRADES] = {"tests": {_grade_id("test", r["id"]): (runtime.feedback_line(r), float(r["score"]))
                                   for r in report["questions"]},
                         "sheet": runtime.summary(report)}
    answer_ids = {_grade_id("answer", q): q for q in qids}
    tests = {_grade_id("test", q): q for q in qids}
    fixed = {"intro", "sheet", *(_grade_id("question", q) for q in qids)}
    kept, seen = [], set()
    for cell in nb.cells:
        gid = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id", "")
        if gid in seen or gid not in {"student", *fixed, *answer_ids, *tests}:
            continue
        seen.add(gid)
        if gid == "student":
            cell.source = f"{STUDENT_VARIABLE} = {literal(handin.claimed)}{_READ}"
        elif gid in answer_ids:
            qid = answer_ids[gid]
            cell.source = f"{names[qid]} = {literal(handin.answers.get(qid))}{_READ}"
        elif gid in tests:
            r = results[tests[gid]]
            cell.source = ("# graded by graphkin from your notebook read as data\n"
                           f"print({runtime.feedback_line(r)!r})\n{float(r['score'])!r}")
        kept.append(cell)
    nb.cells = kept
    return nb, resources


def write_grades(nb, resources):
    """nbgrader preprocessor, after ``Execute``: each test cell's output is graphkin's feedback line and score.

    nbgrader scores a test cell by its output (the number it ends with). :func:`read_as_data` left the
    kernel only literals to run, but the kernel starts in the folder nbgrader copied the submission into,
    where a student can hand in extra files (a ``json.py`` that Python imports before the real one).
    Whatever the kernel printed, the outputs of graphkin's test cells are set here from the report of the
    isolated grading, so the grade nbgrader saves never depends on the kernel; the sheet cell shows whom
    the notebook was graded as and their data; every other output is dropped, so nothing the kernel
    printed reaches the feedback students get back.

    Parameters
    ----------
    nb : nbformat.NotebookNode
        The notebook as ``Execute`` left it.
    resources : dict
        nbgrader's resources, carrying :func:`read_as_data`'s grades (absent for other assignments,
        whose notebooks pass through unchanged).

    Returns
    -------
    nb, resources
    """
    import nbformat

    grades = resources.get(GRADES)
    if not grades:
        return nb, resources
    tests = grades["tests"]
    for cell in nb.cells:
        if cell.get("cell_type") != "code":
            continue
        gid = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id", "")
        if gid in tests:
            line, score = tests[gid]
            cell.outputs = [nbformat.v4.new_output("stream", name="stdout", text=line + "\n"),
                            nbformat.v4.new_output("execute_result", data={"text/plain": repr(score)},
                                                   execution_count=cell.get("execution_count"))]
        elif gid == "sheet":
            cell.outputs = [nbformat.v4.new_output("stream", name="stdout", text=grades["sheet"] + "\n")]
        else:
            # Nothing the kernel printed reaches the feedback students get back (it ran in a folder holding
            # their files, beside the course's keys).
            cell.outputs = []
    return nb, resources


def not_read_as_data() -> None:
    """The hidden part of a test cell: reached only when :func:`read_as_data` did not rewrite the notebook.

    Under ``nbgrader autograde`` the grade would come from a kernel that ran the student's code, so the
    kernel is stopped after a sentence on the terminal: nbgrader reports the submission as failed and
    keeps no grade. Elsewhere (``nbgrader validate`` of the source notebook) it does nothing.
    """
    if os.environ.get("NBGRADER_EXECUTION") == "autograde":
        message = (f"graphkin: this notebook must be graded read as data: add {PREPROCESSOR!r} first to "
                   "c.Autograde.autograde_preprocessors in nbgrader_config.py (see the export's "
                   "nbgrader_config.example.py), then run nbgrader autograde again")
        os.write(2, (message + "\n").encode("utf-8"))
        os._exit(3)


def check_answer(exercise_file, qid: str, answer, variable: str | None = None) -> None:
    """The visible test: an answer is given, typed as text, and can be read (whether it is right is not told).

    Raises ``AssertionError`` (what nbgrader's *Validate* reports) with the grader's own sentence for an
    answer that would be graded missing or unreadable, which earn nothing whatever the data; anything else
    passes. The answer is read as data, never run.
    """
    problem = runtime.readable_problem(exercise_file, qid, answer, variable)
    if problem:
        raise AssertionError(problem)
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
                            "prints the student's data from the roster's sheets, and grading uses the roster's "
                            "precomputed keys; neither carries the secret")
    name = bundle.name
    folder = f"source/{name}"
    tree = {f"{folder}/{file}": text for file, text in bundle.files.items()}
    if bundle.sheets:
        tree[f"{folder}/{_sheets_file(bundle)}"] = json.dumps(bundle.sheets, ensure_ascii=False, indent=1) + "\n"
    tree[f"{folder}/{name}.ipynb"] = _notebook(bundle)
    tree[f"{KEYS_FOLDER}/{name}.json"] = keys_text(bundle.keys())
    tree["nbgrader_config.example.py"] = _config_example()
    tree["README.md"] = _readme(bundle)
    return tree


def _sheets_file(bundle) -> str | None:
    return f"{bundle.name}-sheets.json" if bundle.sheets else None


def variables(bundle) -> dict[str, str]:
    """Question id → the notebook variable the student types the answer into
    (:func:`graphkin.exercises.notebooks.answer_variables`)."""
    return answer_variables(bundle.question_ids())


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
                  _cell("code", _answer_cell(names[q.id], _right(key[q.id])), _grade_id("answer", q.id),
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


def _right(entry: dict) -> str:
    """A key entry's right answer as a student types it: the printed answer, or a drawn question's drawing."""
    return entry["answer"].get("drawing", entry["answer"]["text"])


def _answer_cell(variable: str, answer: str) -> str:
    return f"{variable} = ...\n{_BEGIN}\n{variable} = {_literal(answer)}\n{_END}"


def _test_cell(bundle, qid: str, variable: str) -> str:
    """The autograder test: a visible readability check; the hidden part only stops an autograde that did not
    read the notebook as data (:func:`read_as_data` replaces the whole cell with the grade)."""
    file = _literal(bundle.exercise_file)
    return f"""# Checks only that {variable} can be read, not whether it is right.
from graphkin.exercises.platforms.nbgrader import check_answer
check_answer({file}, {_literal(qid)}, {variable}, {_literal(variable)})
{_BEGIN_HIDDEN}
from graphkin.exercises.platforms.nbgrader import not_read_as_data
not_read_as_data()  # graphkin grades this notebook read as data, before nbgrader runs it
{_END_HIDDEN}"""


def _literal(text: str) -> str:
    """A Python string literal in double quotes (JSON's escapes are Python's), keeping ∠, ° and − as they are."""
    return json.dumps(text, ensure_ascii=False)


def config_lines(seconds: float = TIMEOUT) -> list[str]:
    """The lines a course's ``nbgrader_config.py`` needs for graphkin's notebooks (the tests run them).

    Parameters
    ----------
    seconds : float
        The time limit of one notebook [s] (:class:`TimeLimit`).
    """
    return [
        "# graphkin's notebooks are graded read as data. Its exporter reads each submission before nbgrader does,",
        "# as data, and hands nbgrader graphkin's cells with the answers as literals (nothing else of the",
        "# student's). Its preprocessor, before nbgrader's Execute, grades the answers in a process of its own and",
        "# empties the kernel's folder of the student's files; after Execute, its grade writer sets each test",
        "# cell's output from that grading, whatever the kernel did. (All three pass the notebooks of other",
        "# assignments, which have no graphkin-keys/<assignment>.json, through unchanged.)",
        f"c.Autograde.exporter_class = {EXPORTER!r}",
        "c.Autograde.autograde_preprocessors = [",
        f"    {PREPROCESSOR!r},",
        '    "nbgrader.preprocessors.Execute",',
        f"    {GRADE_WRITER!r},",
        '    "nbgrader.preprocessors.IgnorePattern",',
        '    "nbconvert.preprocessors.ClearMetadataPreprocessor",',
        '    "nbgrader.preprocessors.LimitOutput",',
        '    "nbgrader.preprocessors.SaveAutoGrades",',
        '    "nbgrader.preprocessors.AssignLatePenalties",',
        '    "nbgrader.preprocessors.CheckCellMetadata",',
        "]",
        f"# A time limit per notebook ({seconds:g} s, its cells together), so that no notebook holds up the class:",
        "# each cell gets what is left of its notebook's time.",
        "from graphkin.exercises.platforms.nbgrader import TimeLimit",
        f"_graphkin_time_limit = TimeLimit({seconds!r})",
        "c.Execute.on_notebook_start = _graphkin_time_limit.start",
        "c.Execute.timeout_func = _graphkin_time_limit.cell_timeout",
    ]


def _config_example() -> str:
    lines = "\n".join(config_lines())
    return f'''"""An example nbgrader_config.py for a course that grades graphkin's exercises.

Named nbgrader_config.example.py so that it never replaces your own: merge
what you lack into your course's nbgrader_config.py.
"""

c = get_config()  # noqa: F821 (nbgrader defines it)

# Your course's id (the gradebook is gradebook.db in the course directory unless you set
# c.CourseDirectory.db_url).
c.CourseDirectory.course_id = "mechanics"

{lines}

# graphkin finds an assignment's keys in graphkin-keys/ of the course directory, from the folder nbgrader
# autogrades in, autograded/<student>/<assignment>/: keep nbgrader's default directory structure,
#   c.CourseDirectory.directory_structure = "{{nbgrader_step}}/{{student_id}}/{{assignment_id}}"
'''


def readme_commands(bundle) -> dict[str, str]:
    """The README's shell commands, by step, exactly as printed (the tests run them as they are).

    They run in the course directory, with the export in ``export/`` beside the course's files.
    """
    name = bundle.name
    return {
        "setup": (f"mkdir -p source && cp -r export/source/{name} source/\n"
                  f"mkdir -p {KEYS_FOLDER} && cp export/{KEYS_FOLDER}/{name}.json {KEYS_FOLDER}/\n"),
        "generate": f"nbgrader generate_assignment {name}\n",
        "autograde": f"nbgrader autograde {name}\nnbgrader export\n",
        "feedback": f"nbgrader generate_feedback {name}\n",
        "regrade": (f"graphkin exercise grade export/source/{name}/{bundle.exercise_file} --keys "
                    f"{KEYS_FOLDER}/{name}.json --answers submitted/*/{name}/{name}.ipynb --student-from folder "
                    "-o regraded.csv\n"),
    }


def _readme(bundle) -> str:
    """The export's README: what each file is, then nbgrader's commands, step by step."""
    name = bundle.name
    cmd = readme_commands(bundle)
    files = [f"- `source/{name}/{name}.ipynb`: the source notebook (the sample answers of student "
             f"`{bundle.sample}` in solution regions; the test cells).",
             f"- `source/{name}/{bundle.exercise_file}`: the exercise; the notebook reads it to print the sheet and "
             "to check that an answer can be read."]
    files += [f"- `source/{name}/{f}`: the exercise's base problem." for f in bundle.files if f != bundle.exercise_file]
    if bundle.sheets:
        files.append(f"- `source/{name}/{_sheets_file(bundle)}`: each roster student's sheet (data and questions, "
                     "no answers); the student's notebook prints its own from it.")
    files += [f"- `{KEYS_FOLDER}/{name}.json`: the **keys**: each roster student's answers, computed with the "
              "course secret (which they do not hold). Teachers only: it goes into the course directory, never "
              "into `source/` (whatever is there is released).",
              "- `nbgrader_config.example.py`: the configuration graphkin needs (its exporter and preprocessors, a "
              "time limit per notebook), to merge into your own `nbgrader_config.py` (named so that it never "
              "replaces yours).",
              "- `README.md`: this file."]
    if bundle.secret:
        secret_note = "The course secret is in none of these files: grading uses the keys."
    else:
        secret_note = ("This export has no course secret: anyone with graphkin can compute any student's key "
                       "from their id.")
    reqs = "\n".join(f"    {r}" for r in requirements())
    first = bundle.exercise.questions[0]
    typed = f"{variables(bundle)[first.id]} = {_literal(_example_answer(bundle, first))}"
    config = "\n".join(f"    {line}" for line in config_lines())
    return f"""# {bundle.exercise.title}: nbgrader

Exported by graphkin for nbgrader (tried with nbgrader 0.9.6). **Only the answers a student typed count,
whatever else they hand in.** graphkin's exporter reads each submitted notebook as a file before nbgrader
does (the text assigned to `STUDENT` and to each answer) and hands nbgrader graphkin's own cells with those
answers as literals; what else the submission holds (files, packages, pickles, links, other notebooks,
extra grade cells) is named in nbgrader's log, and a notebook that cannot be read (too big, too deep, not
UTF-8, not JSON) scores 0 with a sentence saying why. graphkin's preprocessor grades the answers in a
separate Python process that holds the keys, and empties the folder the kernel starts in of what nbgrader
copied of the submission, so the kernel runs only the literals and `generate_feedback` hands back nothing of
it; after the kernel, its grade writer sets each test cell's output to graphkin's feedback line and score.

## Files

{chr(10).join(files)}

**What graphkin cannot close from its side:** {NOT_CLOSED.replace("find submitted", "`find submitted")}`.

{secret_note} {CLASSMATES[0].upper() + CLASSMATES[1:]} See `docs/platforms/nbgrader.md` in graphkin for what
students can and cannot learn or do.

## Steps

In your nbgrader course directory (the folder with `nbgrader_config.py`), with this export copied into it
as `export/`. Put your environment's `bin` folder first on `PATH`: nbgrader runs `alembic` from `PATH` for
its gradebook, and without it `nbgrader generate_assignment` fails with `FileNotFoundError: ... 'alembic'`.

1. Add graphkin's lines to `nbgrader_config.py` (they are in `nbgrader_config.example.py`):

{config}

2. Copy the assignment and its keys into the course:

   ```sh
{_indent(cmd['setup'])}   ```

3. Write the students' copy in `release/{name}/` (no answers, no hidden tests):

   ```sh
{_indent(cmd['generate'])}   ```

4. Release and collect as usual (`nbgrader release_assignment {name}` and `nbgrader collect {name}`, or
   your hub's or LMS's way): submissions go to `submitted/<student>/{name}/{name}.ipynb`.

5. Grade, and write `grades.csv` (one row per student and assignment; per-question scores are in the
   formgrader and the gradebook):

   ```sh
{_indent(cmd['autograde'])}   ```

6. If you return feedback (each test cell shows graphkin's feedback line; no key, no secret):

   ```sh
{_indent(cmd['feedback'])}   ```

7. Grade the same notebooks again outside nbgrader, read as data (the scores are those of step 5):

   ```sh
{_indent(cmd['regrade'])}   ```

## What students see

The notebook: they type their id (`{STUDENT_VARIABLE} = "..."`), run the next cell to print their
own data and the questions, type each answer as text (`{typed}`), and the cell
under each answer tells them only whether it can be read (and whether it is typed as text: an answer
written as a calculation is not read). After autograde each test cell prints one line, e.g.
`T12: slip (sign), 0.5 / 1 — The size is right but the sense is wrong: ...`, and scores that share of the
question's points. A notebook whose `{STUDENT_VARIABLE}` is not the student nbgrader grades it as scores 0
on every question, with the sentence `This submission carries the student id '...' but was handed in by '...'`.

## What the machines need

The Jupyter kernel students work in, and the one `nbgrader autograde` runs, need graphkin (the
version that made this export) and its requirements:

{reqs}
"""


def _indent(text: str) -> str:
    return "".join(f"   {line}\n" for line in text.splitlines())


__all__ = ["CLASSMATES", "EXPORTER", "GRADES", "GRADE_WRITER", "KEYS_FOLDER", "NOTES", "NOT_CLOSED", "PREPROCESSOR",
           "STUDENT_VARIABLE", "TIMEOUT", "TimeLimit", "assignment_files", "build", "reduced_notebook",
           "check_answer", "config_lines", "course_root", "not_read_as_data", "read_as_data", "readme_commands",
           "variables", "write_grades"]
