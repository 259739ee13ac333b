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
    e = sub.add_parser("exercise", help="exercises with per-student data: list, make, key, grade, export")
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
            a.add_argument("--answers", required=True, metavar="FILE",
                           help="JSON {question id: answer} for --student ('-' reads stdin), "
                                "or a CSV with a 'student' column and one column per question")
            a.add_argument("--reveal", action="store_true", help="show the expected value of every question")
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
    if code == 0 and args.action in ("key", "grade", "export") and not _secret(args):
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

    platforms.platform(args.to)
    secret = _secret(args)
    students = read_roster(args.roster) if args.roster else None
    with _progress(len(students or ()), "export") as bar:
        written = platforms.export(args.exercise, args.to, args.output, secret=secret, students=students,
                                   progress=bar.update)
    print(f"{len(written)} files written to {args.output}; next: see {Path(args.output) / 'README.md'}",
          file=sys.stderr)
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
    out = io.StringIO()
    fields = list(dict.fromkeys(k for row in rows for k in row))
    w = csv.DictWriter(out, fieldnames=fields, lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
    return out.getvalue()


def _answers_json(path) -> dict:
    text = read_text(path, "answers")
    name = "standard input" if str(path) == "-" else path
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise GraphkinError(f"answers {name}: not valid JSON ({exc.msg} at line {exc.lineno}, column {exc.colno}); "
                            'write {"F23": "27.06 N ∠ -73.78°", ...}') from None
    if not isinstance(data, dict):
        raise GraphkinError(f'answers {name}: must be a JSON object of question id to answer, e.g. {{"F23": "27.06 N"}}')
    return data


def _grade(ex, args, secret) -> int:
    from graphkin import exercises
    from graphkin.exercises.batch import run_roster
    from graphkin.exercises.grading import grade_variant
    from graphkin.exercises.roster import read_class_csv, read_roster
    from graphkin.exercises.sheets import format_report

    reveal = True if args.reveal else None
    if args.student:
        answers = _answers_json(args.answers)
        report = grade_variant(exercises.variant(ex, args.student, secret), answers, reveal=reveal)
        text = json_text(report) if args.json else format_report(report)
        _emit(text, args.output)
        return 0
    rows = read_class_csv(args.answers, "answers")
    if args.roster:
        wanted = set(read_roster(args.roster))
        rows = [r for r in rows if r["student"] in wanted]
    answers = [{k: v for k, v in row.items() if k != "student" and k is not None} for row in rows]
    with _progress(len(rows), "grading") as bar:
        reports = run_roster(ex, "grade", [row["student"] for row in rows], secret, answers=answers, reveal=reveal,
                             progress=bar.update)
    if args.json:
        text = json_text(reports)
    else:
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
        text = _csv(flat)
    _emit(text, args.output)
    return 0


