"""Export an exercise to otter-grader: one master notebook that ``otter assign`` splits, and a plugin that grades.

otter-grader (https://otter-grader.readthedocs.io) works from a *master notebook*: question cells,
solutions between markers and tests. ``otter assign`` turns it into the student notebook (solutions
replaced by ``...``, hidden tests removed) and an autograder zip for ``otter run`` (or Gradescope).

Otter has one seed per class, not one per student, so nothing here asks it for random data. Each
student's data come from their id, as in ``graphkin exercise make``: the notebook asks for the id
(``STUDENT``) and prints the student's sheet from the roster's sheets.

**Only the answers a student typed count, whatever else they hand in.** Otter grades by running the notebook
and its tests in one kernel, where a notebook can replace any function a test calls; its runner unpickles a
hand-in's ``.OTTER_LOG`` and the results the kernel sends back; and the kernel, started in the submission
folder, imports modules from it first. The export registers :class:`Plugin` with otter instead, whose
first hook runs before otter reads ``.OTTER_LOG`` or starts a kernel:

1. it reads the hand-in as data (:func:`graphkin.exercises.handins.read_handin`: the literal assigned to
   ``STUDENT`` and to each answer's variable, never run), and names everything else handed in;
2. it grades those answers in a separate, isolated Python process that holds the precomputed keys and
   not the course secret (:mod:`graphkin.exercises.platforms.isolated`), importing graphkin from the
   autograder's own copy;
3. it deletes the keys, empties the submission folder of all but the autograder's own files, and puts a
   notebook of those literals in place of the student's, so the kernel otter starts runs nothing the
   student wrote and imports nothing they handed in;

and after otter's tests, it writes graphkin's score and feedback into otter's results, question by
question (partial credit as it is; the hidden test case itself, in the kernel, never passes: a grade
comes from the plugin or not at all). ``otter run`` gives each notebook a time limit (the plugin
stops it with otter's own error after ``timeout`` seconds), and ``graphkin exercise collect`` makes
one class table of the ``results.json`` files.

Otter opens a submission before any plugin: it refuses a zip of two notebooks and stops on a notebook it
cannot parse. :func:`strip` makes of each hand-in a notebook it can read, for ``otter run``; on Gradescope
that stays open (:data:`NOT_CLOSED`).
"""

from __future__ import annotations

import html
import json
import signal
import threading
import tomllib
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.exercises import load
from graphkin.exercises.grading import echo
from graphkin.exercises.handins import (
    HandIn,
    clear_folder,
    literal,
    notebook_text,
    own_files,
    read_handin,
    stripped_notebook,
)
from graphkin.exercises.keys import keys_text
from graphkin.exercises.notebooks import STUDENT_VARIABLE, answer_variables
from graphkin.exercises.platforms import requirements, runtime, vendor_files
from graphkin.exercises.platforms.isolated import grade_submissions, submission
from graphkin.files import write_text
from graphkin.optional import require

VENDOR = "vendor"
"""The folder of the export (and of the student's and the autograder's folders) holding graphkin itself."""

TIMEOUT = 120
"""Seconds ``otter run`` may spend on one notebook before the plugin stops it."""

PLUGIN = "graphkin.exercises.platforms.otter.Plugin"
"""The plugin's importable name, as the assignment's configuration lists it."""

NOT_CLOSED = (
    "on Gradescope, otter opens an upload before graphkin's plugin runs: a zip of two notebooks, or a notebook "
    "otter cannot parse (not JSON, nested too deeply), gets otter's own error and no grade, where graphkin gives "
    "that student's row with a sentence. Grade the submissions you download from Gradescope with the README's "
    "steps 3 and 4 (graphkin exercise strip, then otter run; or the regrade). And otter imports the plugin once "
    "it is in the submission folder: run otter as its commands do (otter run), never from a Python whose "
    "sys.path starts with the current folder (python -c, a notebook), where a graphkin/ handed in would be "
    "imported in its place.")
"""What otter's own design leaves open that graphkin cannot close from its side."""

CLASSMATES = (
    "the folder students are given lets any student compute any classmate's answers with graphkin: it holds "
    "graphkin and the sheets, every roster student's data. A classmate's answers handed in score 0.")
"""What the student folder lets every student do."""

NOTES = (NOT_CLOSED, CLASSMATES)
"""Said when the export is made (``graphkin exercise export`` prints them) and in its README."""


# ---------------------------------------------------------------------------------------------------------
# What the exported tests call, in the student's kernel (they decide nothing)
# ---------------------------------------------------------------------------------------------------------

def readable(exercise_file, qid: str, answer, variable: str | None = None) -> None:
    """The public test case: the answer is given, typed as text, and can be read (its value is not checked).

    It needs neither the student's key nor the secret, so it leaks nothing; students run it with
    ``grader.check``.

    Raises
    ------
    AssertionError
        With the sentence the grader gives a missing or unreadable answer.
    """
    problem = runtime.readable_problem(exercise_file, qid, answer, variable)
    if problem:
        raise AssertionError(problem)


def graded_by_plugin(qid: str) -> None:
    """The hidden test case in the kernel: it never passes. graphkin's :class:`Plugin` writes the grade.

    Otter runs hidden tests in the same kernel as the student's notebook; a grade decided there could
    be forged. So this case fails, and the plugin, which graded the notebook read as data in a process
    of its own, overwrites its result and score. An autograder without the plugin gives 0, never a
    grade the student's code decided.
    """
    raise AssertionError(f"{qid} is graded by graphkin's otter plugin, from the notebook read as data")


# ---------------------------------------------------------------------------------------------------------
# The plugin, run by otter in its own process (never in the kernel)
# ---------------------------------------------------------------------------------------------------------

def _submitters(metadata) -> list[str]:
    """Who handed the submission in, by Gradescope's metadata (student id, else email); [] if unknown."""
    users = metadata.get("users") if isinstance(metadata, dict) else None
    ids = []
    for user in users if isinstance(users, list) else []:
        if isinstance(user, dict):
            who = user.get("sid") or user.get("email")
            if isinstance(who, str) and who.strip():
                ids.append(who)
    return ids


class Plugin:
    """otter-grader's plugin: grades the hand-in read as data, in an isolated process, and writes the result.

    otter makes one per submission, with its path, Gradescope's submission metadata (``{}`` under
    ``otter run``) and this plugin's configuration from ``otter_config.json``: ``keys`` (the keys file,
    in the autograder's ``files/``) and ``timeout`` (seconds per notebook).
    """

    def __init__(self, submission_path, submission_metadata, plugin_config):
        self.submission_path = Path(submission_path) if submission_path else None
        self.metadata = submission_metadata if isinstance(submission_metadata, dict) else {}
        self.config = plugin_config if isinstance(plugin_config, dict) else {}
        self.handin = HandIn()
        self.names: dict = {}
        self.report = None

    def _source(self) -> Path:
        # The autograder's own folder (source/: the zip's files/, tests/), which the upload cannot replace.
        return self.submission_path.parent.parent / "source"

    def _own(self) -> dict:
        """The files otter itself puts in the submission folder: the assignment's, its tests, a blank package."""
        source = self._source()
        return {**own_files(source / "files"), **own_files(source / "tests", prefix="tests/"), "__init__.py": b""}

    def before_grading(self, config) -> None:
        """The first of graphkin's code that otter runs: grade the hand-in read as data, then leave it nothing.

        It comes before otter reads the submission's ``.OTTER_LOG`` (a pickle otter loads whenever it is
        there) and before the kernel starts in the submission folder (importing from it first). So here,
        in otter's process: the notebook is read as data (:func:`graphkin.exercises.handins.read_handin`)
        and graded in an isolated process; the keys are then deleted from the autograder's folders; every
        other file of the student's is removed from the submission folder and named in otter's log
        (:meth:`generate_report`); and the notebook is replaced by one of the answers' literals, which
        is all the kernel runs. A time limit starts (otter stops with its own error when it runs out).
        """
        from otter.run.run_autograder.utils import OtterRuntimeError

        limit = int(self.config.get("timeout") or 0)
        if limit > 0 and threading.current_thread() is threading.main_thread():
            signal.signal(signal.SIGALRM, _out_of_time(limit))
            signal.alarm(limit)
        try:
            self._grade_and_clear()
        except GraphkinError as exc:
            raise OtterRuntimeError(f"graphkin could not grade this notebook: {exc}") from None

    def _grade_and_clear(self) -> None:
        files = self._source() / "files"
        keys_name = self.config.get("keys", "")
        keys_path = files / keys_name
        names = answer_variables([q["id"] for q in _questions(keys_path)])
        folder = self.submission_path.parent
        own = self._own()
        handin = read_handin(folder, names, notebook=self.submission_path.name, own=own)
        ids = _submitters(self.metadata)
        claimed = handin.claimed
        # On Gradescope the notebook's id must be the submitter's (any member of a group); locally, it is.
        if ids:
            student = claimed if isinstance(claimed, str) and claimed.strip() in ids else ids[0]
        else:
            student = claimed if isinstance(claimed, str) else ""
        vendor = files / VENDOR if (files / VENDOR / "graphkin").is_dir() else None
        sub = submission(student, handin.answers, claimed, refused=handin.refused)
        self.report = grade_submissions(keys_path, [sub], vendor=vendor)[0]
        self.handin, self.names = handin, names
        # Graded: the keys leave every folder of this machine's autograder before anything runs in a kernel.
        for path in (keys_path, folder / keys_name):
            path.unlink(missing_ok=True)
        own.pop(keys_name, None)
        clear_folder(folder, own, leave={self.submission_path.name})
        write_text(self.submission_path, notebook_text(_literal_notebook(handin, names)))

    def before_execution(self, submission_nb):
        """The notebook otter runs: the id and the answers as literals (:meth:`before_grading` wrote it)."""
        import nbformat

        return nbformat.from_dict(_literal_notebook(self.handin, self.names))

    def after_grading(self, results) -> None:
        """graphkin's score and feedback, question by question, in place of what the kernel's tests said."""
        signal.alarm(0)
        report = self.report
        if report is None:
            return
        by_id = {r["id"]: r for r in report["questions"]}
        for name, test_file in results.results.items():
            r = by_id.get(name)
            if r is None:
                continue
            right = r["verdict"] == "correct"
            readable_ = r["verdict"] not in ("missing", "unreadable", "refused")
            for tcr in test_file.test_case_results:
                passed = right if tcr.test_case.hidden else readable_
                tcr.passed = passed
                text = runtime.feedback_line(r) if tcr.test_case.hidden else r["feedback"]
                # Gradescope may render an output as HTML: what the student typed is quoted escaped.
                tcr.message = None if passed else html.escape(text, quote=False)
            test_file.update_score(r["score"])
        results.set_output(html.escape(runtime.summary(report), quote=False))
        results.set_plugin_data("graphkin", report)

    def generate_report(self) -> str:
        """The teacher's log (otter prints it after grading; Gradescope keeps it from students): what else was
        handed in, removed unread, and why a hand-in was not graded."""
        lines = []
        if self.handin.ignored:
            lines.append("graphkin: handed in beside the notebook, removed unread: " + ", ".join(self.handin.ignored))
        if self.handin.grade_ids:
            lines.append("graphkin: grade cells of the student's own, not run: " + grade_cells(self.handin))
        if self.handin.refused:
            lines.append(f"graphkin: not graded: {self.handin.reason}")
        return "\n".join(lines)


def grade_cells(handin: HandIn) -> str:
    """The nbgrader grade ids a notebook's cells carry (none of otter's own notebooks has one), for the log."""
    return ", ".join(repr(echo(gid, 40)) for gid in handin.grade_ids)


def _out_of_time(limit: int):
    def stop(signum, frame):
        from otter.run.run_autograder.utils import OtterRuntimeError

        raise OtterRuntimeError(f"grading this notebook took more than {limit} s, so it was stopped")

    return stop


def _questions(path: Path) -> list[dict]:
    """The questions of the keys' exercise (ids), read from the keys file as data."""
    try:
        data = json.loads(Path(path).read_text(encoding="utf-8"))
        return tomllib.loads(data["exercise"]["text"])["questions"]
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise GraphkinError(f"the keys file {path} cannot be read ({exc})") from None


_KERNEL = {"kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"},
           "language_info": {"name": "python"}}


def _literal_notebook(handin: HandIn, names: dict) -> dict:
    """The notebook otter's kernel runs: the id and each answer as a literal, nothing else of the student's."""
    lines = [f"{STUDENT_VARIABLE} = {literal(handin.claimed)}",
             *(f"{names[qid]} = {literal(value)}" for qid, value in handin.answers.items())]
    cells = [{"cell_type": "code", "id": f"c{i}", "metadata": {}, "execution_count": None, "outputs": [],
              "source": f"{line}  # read from the notebook as data"} for i, line in enumerate(lines)]
    return {"cells": cells, "metadata": dict(_KERNEL), "nbformat": 4, "nbformat_minor": 5}


def strip(exercise, handins, dest) -> list[tuple[Path, HandIn]]:
    """Each hand-in as a notebook for ``otter run``: its code cells' text only, and nothing that was beside it.

    ``otter run`` reads a submission before graphkin's plugin can: it refuses a zip of two notebooks and
    stops on a notebook it cannot parse. Stripped first, every hand-in reaches it as a well-formed notebook
    of one file, and one that cannot be read carries why, so that otter's row and graphkin's regrade give
    the same verdict (:func:`graphkin.exercises.handins.stripped_notebook`).

    Parameters
    ----------
    exercise : str, Path or Exercise
    handins : iterable of str or Path
        Notebooks, otter's zips (``grader.export()``), or folders.
    dest : str or Path
        The folder to write ``<hand-in name>.ipynb`` into.

    Returns
    -------
    list of (Path, HandIn)
        Each notebook written, with what was read of its hand-in (for the teacher's log).

    Raises
    ------
    GraphkinError
        Two hand-ins of one name (``alice.zip`` and ``alice.ipynb``), or a hand-in that is not there.
    """
    ex = load(exercise)
    names = answer_variables([q.id for q in ex.questions])
    paths = [Path(p) for p in handins]
    stems: dict[str, Path] = {}
    for p in paths:
        stem = p.stem if p.suffix.lower() in (".ipynb", ".zip") else p.name
        if stem in stems:
            raise GraphkinError(f"{stems[stem]} and {p} would both be {stem}.ipynb: rename one of them")
        stems[stem] = p
    meta = {**_KERNEL, "otter": {"assignment_name": ex.id}}
    out = []
    for stem, p in stems.items():
        handin = read_handin(p, names, notebook=f"{ex.id}.ipynb")
        out.append((write_text(Path(dest) / f"{stem}.ipynb", notebook_text(stripped_notebook(handin, meta)), "-o"),
                    handin))
    return out


# ---------------------------------------------------------------------------------------------------------
# Building the export
# ---------------------------------------------------------------------------------------------------------

def variable(qid: str) -> str:
    """The notebook variable that holds the answer to question ``qid``.

    Examples
    --------
    >>> variable("F23"), variable("peak.at"), variable("STUDENT")
    ('F23', 'answer_peak_at', 'answer_STUDENT')
    """
    return answer_variables([qid])[qid]


def build(bundle) -> dict:
    """The export for otter-grader: the master notebook, the files it lists, the keys, graphkin and a README.

    Raises
    ------
    GraphkinError
        With a course secret but no roster: the student notebook would have to draw each student's
        data, and the autograder grade any id; both need the secret.
    """
    require("nbformat", "an export to otter")
    if bundle.secret and bundle.students is None:
        raise GraphkinError(
            "otter: a course secret needs --roster: the student notebook prints each student's data from the "
            "roster's sheets, and the autograder grades with the roster's precomputed keys; neither carries the "
            "secret")
    answer_variables(bundle.question_ids())  # two ids on one variable: said now, not when grading
    tree = dict(bundle.files)
    if bundle.students is not None:
        tree[_sheets_file(bundle)] = json.dumps(bundle.sheets, ensure_ascii=False, indent=1) + "\n"
    tree[keys_file(bundle)] = keys_text(bundle.keys())
    # The grading image installs the copy of graphkin that travels in the zip (otter imports the plugin
    # before any notebook runs): a line of requirements.txt, and a pyproject.toml that makes vendor/ a project.
    tree["requirements.txt"] = "\n".join(requirements() + [f"/autograder/source/files/{VENDOR}"]) + "\n"
    for rel, data in vendor_files().items():
        tree[f"{VENDOR}/{rel}"] = data
    tree[f"{VENDOR}/pyproject.toml"] = _VENDOR_PYPROJECT
    tree[f"{bundle.name}.ipynb"] = _notebook(bundle)
    tree["README.md"] = _readme(bundle)
    return tree


_VENDOR_PYPROJECT = """\
# The copy of graphkin an export carries, installable as it is (otter's grading image installs it).
[build-system]
requires = ["setuptools>=61"]
build-backend = "setuptools.build_meta"

[project]
name = "graphkin"
version = "0.0.0+vendored"

[tool.setuptools.packages.find]
include = ["graphkin*"]

[tool.setuptools.package-data]
"*" = ["*.toml"]
"""


def keys_file(bundle) -> str:
    return f"{bundle.name}-keys.json"


def _sheets_file(bundle) -> str | None:
    return f"{bundle.name}-sheets.json" if bundle.students is not None else None


def _notebook(bundle) -> str:
    """The master notebook (nbformat 4 JSON)."""
    import nbformat
    from nbformat import v4

    cells = [v4.new_raw_cell(_config(bundle)), *_front_cells(bundle)]
    names = answer_variables(bundle.question_ids())
    key = {a["id"]: a["answer"].get("drawing", a["answer"]["text"]) for a in bundle.sample_key()["questions"]}
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
        # The keys go to the autograder only, never to the student folder.
        "autograder_files:",
        f"  - {json.dumps(keys_file(bundle))}",
        # The grade comes from graphkin's plugin (the notebook read as data, graded in a process of its own).
        "plugins:",
        f"  - {PLUGIN}:",
        f"      keys: {json.dumps(keys_file(bundle))}",
        f"      timeout: {TIMEOUT}",
        # The hidden tests never pass in a kernel (the plugin grades): there is nothing for assign to run.
        "run_tests: false",
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
        "Your answers are read from the notebook as text, not run: type each one as a literal in quotes, "
        "not as a calculation. `grader.check(...)` only tells you whether your answer can be read; your "
        "teacher's autograder grades it.",
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

    # The public test case is worth nothing; the hidden one the question's points (the plugin sets its score).
    config = ["# BEGIN QUESTION", f"name: {json.dumps(q.id)}", f"points: {json.dumps([0, q.points])}"]
    prompt = f"**{q.id}** ({_points(q.points)}): {q.ask}\n\nType your answer in `{name}`, as text in quotes."
    return [
        v4.new_raw_cell("\n".join(config)),
        v4.new_markdown_cell(prompt),
        v4.new_raw_cell("# BEGIN SOLUTION"),
        v4.new_code_cell(f"{name} = {solution!r}  # SOLUTION"),
        v4.new_raw_cell("# END SOLUTION"),
        v4.new_raw_cell("# BEGIN TESTS"),
        v4.new_code_cell(_public_test(bundle, q, name)),
        v4.new_code_cell(_hidden_test(q)),
        v4.new_raw_cell("# END TESTS"),
        v4.new_raw_cell("# END QUESTION"),
    ]


def _points(points: float) -> str:
    return f"{points:g} point" + ("" if points == 1 else "s")


def _test_name(q, suffix: str) -> str:
    return f"test_{q.id.replace('.', '_')}_{suffix}"


def _public_test(bundle, q, name: str) -> str:
    fn = _test_name(q, "readable")
    return "\n".join([
        f"def {fn}({name}):",
        "    import sys",
        f"    if {VENDOR!r} not in sys.path:",
        f"        sys.path.append({VENDOR!r})",
        "    from graphkin.exercises.platforms import otter as graphkin_otter",
        f"    graphkin_otter.readable({bundle.exercise_file!r}, {q.id!r}, {name}, {name!r})",
        "",
        f"{fn}({name})",
    ])


def _hidden_test(q) -> str:
    """The hidden test case: it holds nothing secret and never passes in the kernel (the plugin grades)."""
    fn = _test_name(q, "graded")
    return "\n".join([
        "# HIDDEN",
        f"def {fn}():",
        f"    raise AssertionError({(q.id + ' is graded by graphkin' + chr(39) + 's otter plugin')!r})",
        "",
        f"{fn}()",
    ])


def readme_commands(bundle) -> dict[str, str]:
    """The README's shell commands, by step, exactly as printed (the tests run them as they are)."""
    name = bundle.name
    exercise = bundle.exercise_file
    return {
        "assign": f"otter assign {name}.ipynb dist\n",
        "check": (f"mkdir -p check\n"
                  f"timeout {TIMEOUT + 60} otter run -a dist/autograder/{name}-autograder_*.zip -o check "
                  f"dist/autograder/{name}.ipynb\n"),
        "grade": (f"graphkin exercise strip {exercise} submissions/* -o handed-in\n"
                  "for nb in handed-in/*.ipynb; do\n"
                  '    out=results/$(basename "$nb" .ipynb); mkdir -p "$out"\n'
                  f'    timeout {TIMEOUT + 60} otter run -a dist/autograder/{name}-autograder_*.zip -o "$out" "$nb" '
                  '|| echo "otter could not grade $nb" >&2\n'
                  "done\n"
                  f"graphkin exercise collect results -o class.csv\n"),
        "regrade": (f"graphkin exercise grade {exercise} --keys {keys_file(bundle)} --answers submissions/* "
                    f"-o regraded.csv\n"),
    }


def _readme(bundle) -> str:
    """README.md of the export: the files, then otter's commands step by step."""
    name = bundle.name
    sheets = _sheets_file(bundle)
    cmd = readme_commands(bundle)
    others = "".join(f", `{f}`" for f in bundle.files if f != bundle.exercise_file)
    files = [
        f"- `{name}.ipynb`: the **master notebook** for `otter assign`: the assignment's configuration, one "
        f"question per exercise question with the answers of student `{bundle.sample}` as the solutions, and "
        "the tests (which hold nothing secret). Teachers only.",
        f"- `{bundle.exercise_file}`{others}: the exercise, so that the notebook prints the same data as "
        "`graphkin exercise make`.",
        f"- `{keys_file(bundle)}`: the **keys**: every roster student's answers, computed here with the course "
        "secret, which they do not hold. `otter assign` puts them in the autograder only. Teachers only.",
    ]
    if sheets:
        files.append(f"- `{sheets}`: each roster student's sheet (their data and the questions; no answers, "
                     "no secret). The student notebook prints the sheet of the id typed in it.")
    files += [
        "- `requirements.txt`: what graphkin needs, and the copy of graphkin below, for the grading image.",
        f"- `{VENDOR}/graphkin/`: graphkin itself, for the student notebook (which prints the sheet and checks "
        "that an answer can be read) and for the grading.",
    ]
    secret = ("This export has a course secret: it is in none of these files. The autograder grades with the keys. "
              if bundle.secret else "There is no course secret: anyone with graphkin can compute any student's key. ")
    return f"""\
# {bundle.exercise.title}: otter-grader

Made by `graphkin exercise export` for the exercise `{name}`. Each student types their id into the notebook
and gets their own data. **Only the answers a student typed count, whatever else they hand in.** Before otter
loads anything of a submission (its `.OTTER_LOG`, the files beside the notebook), graphkin's otter plugin
reads the notebook as a file (the text assigned to `STUDENT` and to each answer), grades those answers in a
separate Python process that holds the keys, deletes the keys, removes everything else the student handed
in (naming it in otter's log), and later writes graphkin's score and feedback into otter's results. Otter's
kernel runs only those answers, typed back as literals.

**What graphkin cannot close from its side:** {NOT_CLOSED}

## Files

{chr(10).join(files)}

{secret}{CLASSMATES[0].upper() + CLASSMATES[1:]} See `docs/platforms/otter.md` in graphkin for what
students can and cannot learn or do.

## Next steps

In this folder, with a Python that has `otter-grader`, `ipykernel` and graphkin.

1. Make the student notebook and the autograder:

   ```sh
{_indent(cmd['assign'])}   ```

   `dist/student/` is what students get: `{name}.ipynb` (the answers are `...`; only the public tests,
   which say whether an answer can be read) and the files it needs. It holds no key and no secret.

2. Check the autograder on the solutions (the first roster student's answers): it should score full marks.

   ```sh
{_indent(cmd['check'])}   ```

3. Put what students handed in (notebooks, or the zips `grader.export()` writes) in `submissions/` and grade
   them. `graphkin exercise strip` makes of each hand-in a notebook otter can read: its code cells' text,
   nothing that was beside it (it names what it left out, and why a hand-in cannot be graded). `otter run`
   grades one notebook in a few seconds and writes its `results.json` (Gradescope's format: per question
   `score`, `max_score` and graphkin's feedback); `timeout` and the plugin stop a notebook that takes too
   long; `graphkin exercise collect` makes one class table (`student`, `score`, `max`, each question's
   points, and `refused`: why a hand-in was not graded):

   ```sh
{_indent(cmd['grade'])}   ```

4. Grade the same hand-ins again on your own machine, outside otter (read as data, never run); the
   scores and verdicts are those of step 3:

   ```sh
{_indent(cmd['regrade'])}   ```

   It grades with the same keys, so it needs no secret.

5. Or grade on Gradescope: upload the zip as a programming assignment's autograder. The grading image
   installs graphkin from the zip; the tests compare the id in the notebook with who handed it in
   (Gradescope's Student ID, else the email), so the roster's ids must be those. A zip of two notebooks, or
   a notebook otter cannot parse, gets otter's own error there (above): grade the download with steps 3
   and 4. Not tried here.

## What the machines need

Your machine: Python 3.11 or newer with `otter-grader` and `ipykernel`, and graphkin. Students and the
grading image: graphkin's requirements (`{' '.join(requirements())}`) and `otter-grader`.
"""


def _indent(text: str) -> str:
    return "".join(f"   {line}\n" for line in text.splitlines())


__all__ = ["CLASSMATES", "NOTES", "NOT_CLOSED", "PLUGIN", "Plugin", "TIMEOUT", "VENDOR", "build", "grade_cells",
           "graded_by_plugin", "keys_file", "readable", "readme_commands", "strip", "variable"]
