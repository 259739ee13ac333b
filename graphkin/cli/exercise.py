"""``graphkin exercise ...``: list, make, key and grade exercises, for one student or a roster.

``make`` gives a student's data and questions (no answers), ``key`` the same
with the answers, ``grade`` reads a student's answers (JSON, question id →
text as typed) and prints the verdict and feedback per question. With
``--roster FILE.csv`` each command runs for every student of the roster (a
``student`` column) and writes one CSV row per student; ``grade --answers
FILE.csv`` grades a CSV with a ``student`` column and one column per question.

The course secret comes from ``--secret`` or the ``GRAPHKIN_SECRET``
environment variable; without one, students can compute their own keys.
"""

from __future__ import annotations

import csv
import io
import json
import os
import sys
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.files import check_destination, json_text, read_text, write_text


def add_parser(sub) -> None:
    """Add ``exercise`` and its subcommands to the ``graphkin`` parser."""
    e = sub.add_parser("exercise", help="exercises with per-student data: list, make, key, grade, practice, collect, "
                       "strip, export")
    esub = e.add_subparsers(dest="action", required=True)
    esub.add_parser("list", help="list the catalog exercises")
    for action, text in (("make", "a student's data and questions (no answers)"),
                         ("key", "a student's data, questions and answers"),
                         ("grade", "grade a student's answers, with feedback")):
        a = esub.add_parser(action, help=text)
        a.add_argument("exercise", help="catalog name (see 'graphkin exercise list') or path to an exercise file")
        who = a.add_mutually_exclusive_group(required=action != "grade")
        who.add_argument("--student", help="the student's id")
        who.add_argument("--roster", metavar="CSV", help="a CSV with a 'student' column: one row out per student")
        a.add_argument("--secret", help="the course secret (default: $GRAPHKIN_SECRET)")
        a.add_argument("--json", action="store_true", help="print plain data as JSON")
        a.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of standard output")
        if action == "make":
            a.add_argument("--figure", metavar="FILE", help="with --student: write what the student is given to "
                           "draw on (the mechanism and the free bodies to scale, without the forces to find) as "
                           ".png, .svg or .pdf")
        if action == "grade":
            a.add_argument("--answers", required=True, metavar="FILE", nargs="+",
                           help="JSON {question id: answer} for --student ('-' reads stdin); a CSV with a "
                                "'student' column and one column per question; or handed-in notebooks (.ipynb), "
                                "read as data, never run")
            a.add_argument("--keys", metavar="FILE", help="grade with the precomputed keys an export wrote (no secret "
                           "needed): the grade the platform gave")
            a.add_argument("--student-from", choices=("notebook", "folder"), default="notebook",
                           help="for notebooks: the id in the notebook's STUDENT (default), or the folder above the "
                                "assignment's, as nbgrader lays out submitted/<student>/<assignment>/ (then the "
                                "notebook's STUDENT must match it)")
            a.add_argument("--reveal", action="store_true", help="show the expected value of every question")
            a.add_argument("--feedback", choices=("parts", "distance"),
                           help="what a wrong answer is told (default: the exercise's feedback): 'distance' adds how "
                                "far off it is, which gives the answer away (e.g. for a regrade after the due date)")
    pr = esub.add_parser("practice", help="a practice page: the student draws each drawn question and checks it in "
                         "the page (no grade recorded)")
    pr.add_argument("exercise", help="catalog name or path to an exercise file with drawn questions")
    pr.add_argument("--student", required=True, help="the student's id: the page draws their variant")
    pr.add_argument("--secret", help="the course secret (default: $GRAPHKIN_SECRET)")
    pr.add_argument("-o", "--output", required=True, metavar="FILE", help="the HTML page to write")
    c = esub.add_parser("collect", help="one class table from the results.json files of otter run (or Gradescope)")
    c.add_argument("results", nargs="+", metavar="PATH", help="results.json files, or folders holding them")
    c.add_argument("--json", action="store_true", help="print plain data as JSON")
    c.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of standard output")
    s = esub.add_parser("strip", help="for otter run: each hand-in (a notebook, or otter's zip) as a notebook of "
                        "its code cells' text only, nothing that was beside it; what else it held is named")
    s.add_argument("exercise", help="catalog name or path to the exercise file the export carried")
    s.add_argument("handins", nargs="+", metavar="HANDIN", help="the hand-ins: notebooks, otter's zips, or folders")
    s.add_argument("-o", "--output", required=True, metavar="DIR",
                   help="the folder to write <hand-in>.ipynb into (made if missing)")
    x = esub.add_parser("export", help="everything a grading platform needs: otter-grader, nbgrader, "
                        "PrairieLearn or Gradescope")
    x.add_argument("exercise", help="catalog name (see 'graphkin exercise list') or path to an exercise file")
    x.add_argument("--to", required=True, metavar="PLATFORM",
                   help="otter, nbgrader, prairielearn or gradescope")
    x.add_argument("-o", "--output", required=True, metavar="DIR", help="the folder to write (made if missing)")
    x.add_argument("--roster", metavar="CSV", help="a CSV with a 'student' column; the notebook platforms carry "
                   "each student's data (never the answers), so the student notebook needs no secret")
    x.add_argument("--secret", help="the course secret (default: $GRAPHKIN_SECRET); it goes only into the parts "
                   "students never see")


def run(args) -> int:
    """Run ``graphkin exercise ACTION``; returns the exit code."""
    code = _run(args)
    if code == 0 and args.action in ("key", "grade", "export") and not _secret(args) and \
            not getattr(args, "keys", None):
        # Said once the work is done: a command that fails prints its one error line and nothing else.
        print("graphkin: note: no course secret (--secret or GRAPHKIN_SECRET): students can compute these keys "
              "themselves", file=sys.stderr)
    return code


def _secret(args) -> str:
    return args.secret if args.secret is not None else os.environ.get("GRAPHKIN_SECRET", "")


def _run(args) -> int:
    # Imported here, not at the top: `graphkin` builds every subcommand's parser, and the exercise machinery
    # (numpy, shapely, the problem reader) is ~0.1 s that `graphkin solve` and `graphkin list` never use.
    from graphkin import exercises
    from graphkin.exercises.batch import run_roster
    from graphkin.exercises.roster import read_roster
    from graphkin.exercises.sheets import format_sheet

    if args.action == "list":
        for name in exercises.names():
            ex = exercises.load(name)
            print(f"{name:<26}{ex.title}")
        return 0
    if args.action == "export":
        return _export(args)
    if args.action == "collect":
        return _collect(args)
    if args.action == "strip":
        return _strip(args)
    if args.action == "practice":
        return _practice(args)
    if args.output:
        check_destination(args.output, "-o")
    figure = getattr(args, "figure", None)
    if figure:
        if args.roster:
            raise GraphkinError("--figure draws one student's exercise: use it with --student, not --roster")
        check_destination(figure, "--figure")
        if Path(figure).suffix.lower() not in (".png", ".svg", ".pdf"):
            raise GraphkinError(f"--figure {figure}: the file must end in .png, .svg or .pdf")
    secret = _secret(args)
    ex = exercises.load(args.exercise)
    if args.action == "grade":
        return _grade(ex, args, secret)
    if args.roster:
        students = read_roster(args.roster)
        with _progress(len(students), args.action) as bar:
            rows = run_roster(ex, args.action, students, secret, progress=bar.update)
        text = json_text(rows) if args.json else _csv(_flat(rows))
    else:
        v = exercises.variant(ex, args.student, secret)
        sheet = v.key() if args.action == "key" else v.sheet()
        if figure:
            _given_figure(v, figure)
        text = json_text(sheet) if args.json else format_sheet(sheet)
    _emit(text, args.output)
    return 0


def _export(args) -> int:
    from graphkin.exercises import platforms
    from graphkin.exercises.roster import read_roster

    module = platforms.platform(args.to)
    secret = _secret(args)
    students = read_roster(args.roster) if args.roster else None
    with _progress(len(students or ()), "export") as bar:
        written = platforms.export(args.exercise, args.to, args.output, secret=secret, students=students,
                                   progress=bar.update)
    print(f"{len(written)} files written to {args.output}; next: see {Path(args.output) / 'README.md'}",
          file=sys.stderr)
    for note in getattr(module, "NOTES", ()):
        _note(f"{args.to}: {note}")
    return 0


def _practice(args) -> int:
    """``graphkin exercise practice``: the drawn questions of one student's variant on one self-contained page, each
    with the targets it is matched against in the page (docs/exercises.md, "Drawing in the browser")."""
    from graphkin import exercises
    from graphkin.exercises.drawn_tasks import task_of
    from graphkin.scene.practice import write_practice

    check_destination(args.output, "-o")
    ex = exercises.load(args.exercise)
    drawn = [q.id for q in ex.questions if q.kind == "drawing"]
    if not drawn:
        raise GraphkinError(f"practice: {ex.id} has no drawn questions (find = \"drawing\")")
    v = exercises.variant(ex, args.student, _secret(args))
    tasks = [task_of(v, qid, practice=True) for qid in drawn]
    write_practice(tasks, args.output, title=f"{ex.title} — practice ({args.student})")
    print(f"practice page of {len(tasks)} drawn question{'s' if len(tasks) != 1 else ''} written to "
          f"{args.output}", file=sys.stderr)
    return 0


def _given_figure(v, figure) -> None:
    from graphkin import draw

    c = v.construction
    if not c.valid:
        raise GraphkinError(f"--figure: {v.exercise.id} has no single position to draw (a whole-cycle exercise)")
    Path(figure).parent.mkdir(parents=True, exist_ok=True)  # checked writable before any work: check_destination
    draw.save(draw.draw_given(c), figure)
    print(f"figure written to {figure}", file=sys.stderr)


def _progress(total: int, label: str):
    """A progress bar on stderr for a batch that takes more than a second (none when stderr is not a terminal)."""
    from tqdm import tqdm

    from graphkin.cli import _common

    return tqdm(total=total, desc=f"graphkin: {label}", unit="student", delay=_common.PROGRESS_DELAY, file=sys.stderr,
                leave=False, disable=None)


def _emit(text: str, output) -> None:
    if output:
        write_text(output, text if text.endswith("\n") else text + "\n", "-o")
        print(f"written to {output}", file=sys.stderr)
    else:
        print(text)


def _flat(sheets: list[dict]) -> list[dict]:
    """One CSV row per student: the data (by symbol) and, for a key, each answer as printed."""
    rows = []
    for s in sheets:
        if "error" in s:
            rows.append(s)
            continue
        row = {"student": s["student"]}
        row.update({g["symbol"]: g["value"] for g in s["data"]})
        for q in s["questions"]:
            if "answer" in q:
                row[q["id"]] = q["answer"]["text"]
        rows.append(row)
    return rows


def _csv(rows: list[dict]) -> str:
    from graphkin.exercises.roster import spreadsheet_rows

    out = io.StringIO()
    fields = list(dict.fromkeys(k for row in rows for k in row))
    w = csv.DictWriter(out, fieldnames=fields, lineterminator="\n")
    w.writeheader()
    w.writerows(spreadsheet_rows(rows))  # a student's text that begins as a formula stays text
    return out.getvalue()


def _answers_json(path) -> dict:
    from graphkin.exercises.answer_files import json_answers

    text = read_text(path, "answers")
    name = "standard input" if str(path) == "-" else path
    try:
        data = json_answers(text)
    except json.JSONDecodeError as exc:
        raise GraphkinError(f"answers {name}: not valid JSON ({exc.msg} at line {exc.lineno}, column {exc.colno}); "
                            'write {"F23": "27.06 N ∠ -73.78°", ...}') from None
    except ValueError as exc:
        raise GraphkinError(f"answers {name}: cannot be read ({exc})") from None
    if not isinstance(data, dict):
        raise GraphkinError(f'answers {name}: must be a JSON object of question id to answer, e.g. {{"F23": "27.06 N"}}')
    return data


def _note(text: str) -> None:
    print(f"graphkin: note: {text}", file=sys.stderr)


def _ids_and_lines(items, limit: int = 10) -> str:
    shown = ", ".join(items[:limit])
    return shown + (f" and {len(items) - limit} more" if len(items) > limit else "")


def _grade(ex, args, secret) -> int:
    from graphkin import exercises
    from graphkin.exercises.grading import grade_variant
    from graphkin.exercises.handins import class_notes
    from graphkin.exercises.keys import Keys
    from graphkin.exercises.roster import read_roster
    from graphkin.exercises.sheets import format_report

    reveal = True if args.reveal else None
    feedback = args.feedback
    keys = _keys(ex, args.keys) if args.keys else None
    files = args.answers
    if args.student:
        if len(files) != 1:
            raise GraphkinError("--answers: with --student, give one JSON file of that student's answers")
        answers = _answers_json(files[0])
        v = keys.variant(args.student) if keys else exercises.variant(ex, args.student, secret)
        report = grade_variant(v, answers, reveal=reveal, classmates=keys.classmates() if keys else None,
                               feedback=feedback)
        text = json_text(report) if args.json else format_report(report)
        _emit(text, args.output)
        return 0
    roster = read_roster(args.roster) if args.roster else None
    if all(str(f).lower().endswith((".ipynb", ".zip")) for f in files):
        subs = _notebook_submissions(ex, files, args.student_from)
        for text in class_notes(subs, roster):  # one id in two files; roster students with no hand-in
            _note(text)
    elif len(files) == 1:
        subs = _csv_submissions(files[0], roster)
    else:
        raise GraphkinError("--answers: give one CSV of the class's answers, or handed-in notebooks (.ipynb, or "
                            "otter's .zip)")
    class_ids = roster if roster is not None else list(dict.fromkeys(s["student"] for s in subs))
    if keys is None:
        # The class's keys, made here with the secret: the same grade as the platform's, which carried them.
        from graphkin.exercises.batch import run_roster
        from graphkin.exercises.keys import make_keys

        usable = [r for r in run_roster(ex, "entry", class_ids, secret) if "entry" in r]
        keys = Keys(make_keys(ex, [r["student"] for r in usable], secret, entries=[r["entry"] for r in usable]))
    with _progress(len(subs), "grading") as bar:
        reports = []
        for sub in subs:
            reports.append(_graded(keys, sub, reveal, feedback))
            bar.update(1)
    text = json_text(reports) if args.json else _csv(_report_rows(reports))
    _emit(text, args.output)
    return 0


def _keys(ex, path):
    from graphkin.exercises.keys import Keys

    keys = Keys(path)
    if keys.exercise.id != ex.id or keys.exercise.text != ex.text:
        raise GraphkinError(f"--keys {path}: these are the keys of {keys.exercise.id!r} as exported, not of "
                            f"{ex.file}; give the exercise file the export carried")
    return keys


def _graded(keys, sub: dict, reveal, feedback) -> dict:
    from graphkin.exercises.grading import grade_variant
    from graphkin.exercises.handins import REFUSALS
    from graphkin.exercises.platforms.isolated import grade_one, refused

    if sub.get("refused"):  # a hand-in that cannot be read: its row, with why
        return refused(keys.exercise, sub["student"], REFUSALS[sub["refused"]])
    if "claimed" in sub:  # a notebook: refused, with a sentence, if its id is not usable or not the graded one's
        return grade_one(keys, sub["student"], sub["answers"], sub["claimed"], reveal=reveal, feedback=feedback)
    try:
        variant = keys.variant(sub["student"])
    except GraphkinError as exc:
        return {"student": sub["student"], "error": str(exc)}
    return grade_variant(variant, sub["answers"], reveal=reveal, classmates=keys.classmates(), feedback=feedback)


def _csv_submissions(path, roster) -> list[dict]:
    from graphkin.exercises.roster import read_class_csv

    rows = read_class_csv(path, "answers")
    if roster is not None:
        wanted = set(roster)
        off = [f"{r['student']} (line {r['#line']})" for r in rows if r["student"] not in wanted]
        if off:
            _note(f"answers {path}: {len(off)} student{'s are' if len(off) > 1 else ' is'} not on the roster and "
                  f"{'were' if len(off) > 1 else 'was'} not graded: {_ids_and_lines(off)}")
        have = {r["student"] for r in rows}
        absent = [s for s in roster if s not in have]
        if absent:
            _note(f"answers {path}: no answers from {len(absent)} roster student{'s' if len(absent) > 1 else ''}: "
                  f"{_ids_and_lines(absent)}")
        rows = [r for r in rows if r["student"] in wanted]
    return [{"student": r["student"],
             "answers": {k: v for k, v in r.items() if k not in ("student", "#line") and k is not None}}
            for r in rows]


def _notebook_submissions(ex, files, student_from: str) -> list[dict]:
    """Each hand-in (a notebook, or otter's zip) read as data: whom it is graded as, the id it carries, its
    answers; or why it cannot be read. What else a zip holds is named, never opened."""
    from graphkin.exercises.handins import read_handin
    from graphkin.exercises.notebooks import answer_variables

    names = answer_variables([q.id for q in ex.questions])
    subs = []
    for f in files:
        handin = read_handin(f, names, notebook=f"{ex.id}.ipynb")
        if handin.ignored:
            _note(f"{f}: not read: {', '.join(handin.ignored)}")
        if handin.refused:
            _note(f"{f}: not graded: {handin.reason}")
        claimed = handin.claimed
        if student_from == "folder":
            # nbgrader's submitted/<student>/<assignment>/<notebook>.ipynb (not resolved: the file may be a link)
            parts = Path(os.path.abspath(f)).parts
            if len(parts) < 3:
                raise GraphkinError(f"--student-from folder: {f} is not in <student>/<assignment>/")
            student = parts[-3]
        else:
            student = claimed if isinstance(claimed, str) else ""
        subs.append({"student": student, "claimed": claimed, "answers": handin.answers, "file": str(f),
                     "refused": handin.refused})
    return subs


def _report_rows(reports) -> list[dict]:
    flat = []
    for r in reports:
        if "error" in r:
            flat.append(r)
            continue
        row = {"student": r["student"], "score": r["score"], "max": r["max"]}
        for q in r["questions"]:
            row[q["id"]] = q["score"]
            row[f"{q['id']} verdict"] = q["verdict"] + (f" ({q['slip']})" if q["slip"] else "")
            row[f"{q['id']} feedback"] = q["feedback"]
            if "expected" in q:
                row[f"{q['id']} expected"] = q["expected"]
        flat.append(row)
    return flat


def _strip(args) -> int:
    from graphkin.exercises.platforms import otter

    done = otter.strip(args.exercise, args.handins, args.output)
    for path, handin in done:
        if handin.ignored:
            _note(f"{path.name}: handed in beside the notebook, not carried: {', '.join(handin.ignored)}")
        if handin.grade_ids:
            _note(f"{path.name}: grade cells of the student's own, carried as text only: {otter.grade_cells(handin)}")
        if handin.refused:
            _note(f"{path.name}: not graded: {handin.reason}")
    print(f"{len(done)} notebook{'s' if len(done) != 1 else ''} written to {args.output}", file=sys.stderr)
    return 0


def _collect(args) -> int:
    from graphkin.exercises.platforms.collect import class_table, find_results, repeated

    if args.output:
        check_destination(args.output, "-o")
    rows = class_table(find_results(args.results))
    for student, files in repeated(rows).items():
        _note(f"student {student!r} was graded in {len(files)} files ({', '.join(files)}): the id typed in a "
              "notebook decides whom it is graded as, so check who handed each one in")
    text = json_text(rows) if args.json else _csv(rows)
    _emit(text, args.output)
    return 0
