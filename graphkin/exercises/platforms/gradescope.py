"""Gradescope: an autograder zip that grades an answers file with graphkin.

Gradescope builds a Docker image from the zip a teacher uploads (its
``setup.sh`` runs once, as root), then, for every submission, unpacks the
student's files into ``/autograder/submission/``, writes
``/autograder/submission_metadata.json`` (who submitted) and runs
``run_autograder``, which must leave ``/autograder/results/results.json``.

What the export writes (``build``):

- ``autograder.zip``, for *Configure Autograder*: ``setup.sh`` (a Python of at
  least 3.11 in a virtual environment, with graphkin's requirements),
  ``run_autograder``, ``grade.py``, ``config.json`` (the exercise's name and the
  roster, if any), ``keys.json`` (the roster's precomputed keys, never the course
  secret), the exercise file and graphkin itself under ``vendor/`` (the grade
  comes from the version that was exported);
- ``student_template/answers.toml``, the file students fill in and upload;
- ``sample_submission/``, the first roster student's key answers and a
  metadata file, to try the autograder on the teacher's machine;
- ``README.md``, the steps.

What runs on Gradescope (:func:`run`, called by ``grade.py``): find the one
answers file (TOML or JSON, read as data, never run), take the submitter's
id from the metadata (``sid``, else ``email``), refuse a file that carries
another student's id, grade with the keys and write one Gradescope test per
question (every output marked ``"output_format": "text"``, so Gradescope shows
what a student typed as text, never as HTML). Whatever goes wrong, a ``results.json`` is
written: 0 points and a sentence the student can act on.
"""

from __future__ import annotations

import io
import json
import os
import re
import stat
import traceback
import zipfile
from pathlib import Path

import graphkin
from graphkin import __version__
from graphkin.errors import GraphkinError
from graphkin.exercises.answer_files import json_answers, toml_answers
from graphkin.exercises.keys import Keys, keys_text
from graphkin.exercises.platforms import requirements, runtime, vendor_files
from graphkin.exercises.variants import check_student
from graphkin.files import write_text

ROOT_ENV = "GRAPHKIN_AUTOGRADER_ROOT"
"""Environment variable naming the autograder's root folder (Gradescope's is ``/autograder``)."""

DEFAULT_ROOT = "/autograder"

VENV = "/opt/graphkin-venv"
"""Where ``setup.sh`` makes the Python environment that ``run_autograder`` uses."""

CONFIG = "config.json"
"""The file in the zip that carries the exercise's name and the roster."""

KEYS = "keys.json"
"""The file in the zip that carries the precomputed keys (:mod:`graphkin.exercises.keys`)."""

ANSWER_SUFFIXES = (".toml", ".json")
MAX_ANSWERS_BYTES = 20_000_000
"""Largest answers file read. One over-long answer is that answer's problem (it is refused with a sentence,
the others are graded); only a file larger than this is refused whole."""

EXAMPLE_LINE = 'F23 = "27.06 N ∠ −73.78°"'
"""How one answer is written in answers.toml, quoted in the messages students read."""

_ZIP_TIME = (1980, 1, 1, 0, 0, 0)  # the earliest time a zip can hold: the same export gives the same bytes
_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


class SubmissionError(Exception):
    """A submission that cannot be graded; the message is the sentence the student reads."""


# --------------------------------------------------------------------------------------------------
# The scripts that travel in the zip
# --------------------------------------------------------------------------------------------------

SETUP_SH = f"""\
#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image.
# graphkin needs Python 3.11 or newer (Ubuntu 22.04's python3 is 3.10): use a python3 that is
# new enough, else install python3.11 from apt. Its requirements go into a virtual environment,
# which newer Ubuntus require for pip (PEP 668) and which keeps the grader's packages apart.
set -euo pipefail
ROOT="${{{ROOT_ENV}:-{DEFAULT_ROOT}}}"
VENV="${{GRAPHKIN_VENV:-{VENV}}}"

new_enough() {{ "$1" -c 'import sys; sys.exit(sys.version_info < (3, 11))' 2>/dev/null; }}

PY=""
for candidate in python3 python3.13 python3.12 python3.11; do
  if command -v "$candidate" >/dev/null && new_enough "$candidate"; then PY="$candidate"; break; fi
done
if [ -z "$PY" ]; then
  apt-get update
  if ! apt-get install -y python3.11 python3.11-venv; then
    # Older Ubuntus (20.04) have no python3.11 of their own: the deadsnakes archive has it.
    apt-get install -y software-properties-common
    add-apt-repository -y ppa:deadsnakes/ppa
    apt-get update
    apt-get install -y python3.11 python3.11-venv
  fi
  PY=python3.11
fi
if ! "$PY" -m venv "$VENV"; then
  # Debian and Ubuntu ship the venv module apart from Python itself.
  apt-get update
  apt-get install -y "$(basename "$PY")-venv"
  "$PY" -m venv "$VENV"
fi
"$VENV/bin/python" -m pip install --upgrade pip
"$VENV/bin/python" -m pip install -r "$ROOT/source/requirements.txt"
# graphkin's bytecode, compiled once into the image: each submission's Python reads it instead of
# compiling the vendored package again (about half a second of CPU a submission).
"$VENV/bin/python" -m compileall -q "$ROOT/source/vendor"
"$VENV/bin/python" --version
"""

RUN_AUTOGRADER = f"""\
#!/usr/bin/env bash
# Gradescope runs this once per submission. It grades with grade.py, and makes sure a
# results.json exists even if Python itself could not start (the student then reads why).
# {ROOT_ENV} (default {DEFAULT_ROOT}) and GRAPHKIN_PYTHON let a teacher run it in a
# folder of their own: see the README that came with the zip.
ROOT="${{{ROOT_ENV}:-{DEFAULT_ROOT}}}"
export {ROOT_ENV}="$ROOT"
PYTHON="${{GRAPHKIN_PYTHON:-}}"
if [ -z "$PYTHON" ]; then
  if [ -x "${{GRAPHKIN_VENV:-{VENV}}}/bin/python" ]; then PYTHON="${{GRAPHKIN_VENV:-{VENV}}}/bin/python"; else PYTHON=python3; fi
fi
mkdir -p "$ROOT/results"
rm -f "$ROOT/results/results.json"
"$PYTHON" "$ROOT/source/grade.py"
if [ ! -s "$ROOT/results/results.json" ]; then
  echo "graphkin: grade.py wrote no results.json (Python: $PYTHON)" >&2
  cat > "$ROOT/results/results.json" <<'EOF'
{{"score": 0.0, "output": "The autograder could not start, so this submission was not graded. Your teacher can see why in the autograder's output; submit again once they have fixed it.", "output_format": "text", "visibility": "visible", "stdout_visibility": "hidden", "tests": []}}
EOF
fi
exit 0
"""

GRADE_PY = f'''\
"""Gradescope runs this, through run_autograder, once per submission: graphkin grades the answers file.

Everything it needs travelled in the autograder zip: the exercise file, {CONFIG} (the roster),
{KEYS} (the roster's keys; never the course secret) and graphkin itself under vendor/. vendor/ goes first on the path, so the
grade comes from the graphkin that was exported, whatever else the image has installed.
"""

import json
import os
import sys
import traceback
from pathlib import Path

SOURCE = Path(__file__).resolve().parent
sys.path.insert(0, str(SOURCE / "vendor"))


def cannot_start(root, exc):
    """0 points and a sentence, when graphkin itself cannot be imported (a broken image)."""
    results = {{
        "score": 0.0,
        "output": "The autograder could not start, so this submission was not graded. Your teacher can see "
                  "why in the autograder's output; submit again once they have fixed it.",
        "visibility": "visible",
        "stdout_visibility": "hidden",
        "output_format": "text",
        "tests": [],
    }}
    print(f"graphkin could not be imported: {{type(exc).__name__}}: {{exc}}")
    out = root / "results" / "results.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = out.with_name(".results.json.tmp")
    tmp.write_text(json.dumps(results, indent=2), encoding="utf-8")
    os.replace(tmp, out)


if __name__ == "__main__":
    root = Path(os.environ.get("{ROOT_ENV}") or SOURCE.parent)
    try:
        from graphkin.exercises.platforms import gradescope
    except Exception as exc:  # numpy missing, a Python older than 3.11: say so rather than leave no result
        traceback.print_exc()
        cannot_start(root, exc)
        sys.exit(1)
    gradescope.run(root)
'''


# --------------------------------------------------------------------------------------------------
# The export (on the teacher's machine)
# --------------------------------------------------------------------------------------------------

def build(bundle) -> dict:
    """Everything the Gradescope export writes, as ``{relative path: text or bytes}``.

    Parameters
    ----------
    bundle : graphkin.exercises.platforms.Bundle

    Returns
    -------
    dict
        ``autograder.zip`` (bytes), ``README.md``, ``student_template/answers.toml``,
        ``sample_submission/answers.toml`` and ``sample_submission/submission_metadata.json``.
    """
    if bundle.secret and bundle.students is None:
        raise GraphkinError("gradescope: a course secret needs --roster: the autograder grades with the roster's "
                            "precomputed keys, so that the zip never carries the secret")
    sample = bundle.sample_key()
    # A drawn question's right answer is its drawing (JSON text), not the words the key prints.
    answers = {q["id"]: q["answer"].get("drawing", q["answer"]["text"]) for q in sample["questions"]}
    return {
        **bundle.files,
        "autograder.zip": autograder_zip(zip_members(bundle)),
        "README.md": readme(bundle),
        "student_template/answers.toml": answers_toml(bundle, None, None),
        "sample_submission/answers.toml": answers_toml(bundle, answers, bundle.sample),
        "sample_submission/submission_metadata.json": json.dumps(sample_metadata(bundle), indent=2,
                                                                 ensure_ascii=False) + "\n",
    }


def zip_members(bundle) -> dict[str, bytes]:
    """The files of the autograder zip, by their path inside it."""
    members = {
        "setup.sh": SETUP_SH,
        "run_autograder": RUN_AUTOGRADER,
        "grade.py": GRADE_PY,
        "requirements.txt": "\n".join(requirements()) + "\n",
        CONFIG: json.dumps(config(bundle), indent=2, ensure_ascii=False, sort_keys=True) + "\n",
        KEYS: keys_text(bundle.keys()),
    }
    for name, text in bundle.files.items():
        if name in members:
            raise GraphkinError(f"{name}: the Gradescope export uses this name itself; rename the problem file")
        members[name] = text
    members.update({f"vendor/{rel}": data for rel, data in vendor_files().items()})
    return {k: v.encode("utf-8") if isinstance(v, str) else v for k, v in members.items()}


def config(bundle) -> dict:
    """What ``grade.py`` reads besides the keys: the exercise and the roster (``None`` without one)."""
    return {
        "exercise": bundle.name,
        "exercise_file": bundle.exercise_file,
        "title": bundle.exercise.title,
        "roster": list(bundle.students) if bundle.students else None,
        "graphkin": __version__,
    }


def autograder_zip(members: dict[str, bytes]) -> bytes:
    """A zip of ``members``, files at its root, in name order, with fixed times: the same input, the same bytes.

    The scripts get execute bits (Unix permissions in ``external_attr``):
    Gradescope runs ``run_autograder`` as a program.
    """
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        for name in sorted(members):
            info = zipfile.ZipInfo(name, date_time=_ZIP_TIME)
            info.create_system = 3  # Unix, so unzip reads the permissions below
            mode = 0o755 if name in ("setup.sh", "run_autograder") else 0o644
            info.external_attr = (stat.S_IFREG | mode) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            zf.writestr(info, members[name])
    return buf.getvalue()


def _toml_key(key: str) -> str:
    return key if _BARE_KEY.fullmatch(key) else json.dumps(key, ensure_ascii=False)


def _toml_string(text: str) -> str:
    # A JSON string is a TOML basic string: the same escapes (\", \\, \n, \uXXXX).
    return json.dumps(text, ensure_ascii=False)


def answers_toml(bundle, answers: dict | None, student: str | None) -> str:
    """An answers file: blank for students (``answers=None``), or filled in (the sample's key).

    Each question comes with its words and unit as comments, so the file is
    its own instructions.
    """
    ex = bundle.exercise
    if answers is None:
        head = [f"# {ex.title}",
                "# Your answers, to upload to Gradescope as answers.toml. Type each answer between the",
                f"# double quotes, with its unit, as on your sheet: {EXAMPLE_LINE}",
                "# An answer left as \"\" is not answered. Put your student id (as on your sheet) in `student`.",
                ""]
    else:
        head = [f"# {ex.title}",
                f"# THE KEY ANSWERS of student {student!r}, to test the autograder. Do not give this file to students.",
                ""]
    lines = head + [f"student = {_toml_string(student or '')}", ""]
    for q in ex.questions:
        ask = " ".join(q.ask.split())  # one comment line, whatever the exercise file's line breaks
        lines.append(f"# {ask}  [{q.unit}, {q.points:g} point{'s' if q.points != 1 else ''}]")
        lines.append(f"{_toml_key(q.id)} = {_toml_string((answers or {}).get(q.id, ''))}")
    return "\n".join(lines) + "\n"


def sample_metadata(bundle) -> dict:
    """A ``submission_metadata.json`` as Gradescope writes it, for the sample student (to try the zip locally)."""
    return {
        "id": 1,
        "created_at": "2025-01-01T12:00:00.000000+00:00",
        "assignment": {"id": 1, "title": bundle.exercise.title, "group_submission": False, "group_size": None,
                       "total_points": f"{sum(q.points for q in bundle.exercise.questions):g}"},
        "submission_method": "upload",
        "users": [{"email": "", "id": 1, "name": "Sample Student", "sid": bundle.sample}],
        "previous_submissions": [],
    }


def readme_commands(bundle) -> dict[str, str]:
    """The README's shell commands, by step, exactly as printed (the tests run them as they are)."""
    return {"make": f"graphkin exercise make {bundle.exercise_file} --roster roster.csv -o sheets.csv\n",
            "try": local_try_commands()}


def _indent(text: str, spaces: int) -> str:
    return "".join(" " * spaces + line + "\n" for line in text.splitlines())


def local_try_commands() -> str:
    """The shell commands that run the autograder on the sample submission, in a folder laid out as Gradescope's.

    The README prints them and the tests run them as they are.
    """
    return f"""\
mkdir -p try/submission try/results
python3 -m zipfile -e autograder.zip try/source
cp sample_submission/answers.toml try/submission/
cp sample_submission/submission_metadata.json try/
{ROOT_ENV}="$PWD/try" GRAPHKIN_PYTHON=python3 bash try/source/run_autograder
python3 -m json.tool --no-ensure-ascii try/results/results.json
"""


def readme(bundle) -> str:
    """The teacher's README: the files, the steps on Gradescope, what the machines need."""
    name = bundle.name
    total = sum(q.points for q in bundle.exercise.questions)
    questions = ", ".join(bundle.question_ids())
    roster = (f"the roster given to the export ({len(bundle.students)} students; the autograder refuses an id "
              "that is not on it)" if bundle.students else
              "no roster and no course secret (any id is graded, and anyone with graphkin can compute any key; "
              "give `--roster` and a secret to the export for graded work)")
    reqs = "\n".join(f"- `{r}`" for r in requirements())
    if bundle.students:
        test_on_gradescope = (f"To test on Gradescope, upload `sample_submission/answers.toml` as a submission of "
                              f"student `{bundle.sample}` (instructors can upload a submission for a student): "
                              f"it should score {total:g} / {total:g}. A submission of your own is refused, as "
                              "you are not on the roster.")
    else:
        test_on_gradescope = (f"To test on Gradescope, submit as yourself: the data are drawn from your own id "
                              f"(your SID, else your email), so type the answers of "
                              f"`graphkin exercise key {bundle.exercise_file} --student YOUR_ID` into "
                              "`student_template/answers.toml` (or leave some wrong, to see the feedback).")
    return f"""\
# {bundle.exercise.title}: Gradescope autograder

Exported by graphkin for the exercise `{name}` (questions {questions}; {total:g} points), with {roster}.

## The files

| file | what it is | who sees it |
|---|---|---|
| `autograder.zip` | the autograder: `setup.sh`, `run_autograder`, `grade.py`, `config.json` (the roster), `keys.json` (every roster student's answers, computed here; never the course secret), `{bundle.exercise_file}`, `requirements.txt` and graphkin itself under `vendor/` | you and Gradescope only: it holds the keys |
| `{bundle.exercise_file}`{''.join(f', `{f}`' for f in bundle.files if f != bundle.exercise_file)} | the exercise, for the commands below | you |
| `student_template/answers.toml` | the file students fill in and upload: one line per question, `{EXAMPLE_LINE}` | students |
| `sample_submission/answers.toml` | the key answers of student `{bundle.sample}`, to test the autograder | you only: it holds answers |
| `sample_submission/submission_metadata.json` | Gradescope's metadata for that student, to run the autograder on your machine | you |

## On Gradescope

1. Create a **Programming Assignment** whose autograder is worth **{total:g} points** (the exercise's total).
2. *Configure Autograder*: upload `autograder.zip` (the files are at the root of the zip, as Gradescope
   wants them) on an Ubuntu base image. `setup.sh` uses the image's `python3` if it is 3.11 or newer
   (Ubuntu 22.04's is 3.10), else installs `python3.11` with apt, makes a virtual environment in
   `{VENV}` and installs the requirements below with pip. Wait until the image is built.
3. Give each student their data, drawn from the **same ids Gradescope has for them**: the *Student ID*
   (SID) of the course roster, or the email where a student has no SID. With a CSV whose `student` column
   holds those ids, this prints every student's data (`--student ID` prints one student's sheet):

{_indent(readme_commands(bundle)['make'], 7)}
   (with `GRAPHKIN_SECRET` set to the secret of the export, or the data will not match). A student uploads
   `student_template/answers.toml`, filled in; `answers.json` (`{{"F23": "27.06 N ∠ −73.78°"}}`) works too.
4. {test_on_gradescope}

## Try it on your machine first

In this folder, with a Python (3.11 or newer) that has graphkin's requirements installed:

```sh
{local_try_commands()}```

This lays out `try/` as Gradescope lays out `/autograder` and grades the sample submission: the score
should be {total:g} / {total:g}. Put another `answers.toml` in `try/submission/` to see other feedback.

## What students get

One test per question, with graphkin's verdict and feedback sentence (`F23: slip (sign), 0.5 / 1 — The
size is right but the direction is reversed: ...`), and the total as the score. The summary names the id the
submission was graded as and that student's data, so a student who used someone else's sheet sees it.

- **The id check.** The id comes from Gradescope's metadata (`sid`, else `email`; with a roster, the first of
  the two that is on it). If `answers.toml` carries a `student` that is not the submitter's, it scores 0 with
  the sentence: "this submission carries the student id ... but was handed in by ...".
- **Group submissions** are graded on the variant of the member the file's `student` names, else the first
  member; the output says so. Every member gets that score.
- A file that cannot be read (bad TOML or JSON, two answers files, none) scores 0 and the output says what to fix.

## What the autograder's machine needs

Python 3.11 or newer and (installed by `setup.sh` from `requirements.txt`):

{reqs}
"""


# --------------------------------------------------------------------------------------------------
# Grading (on Gradescope's machine, called by grade.py)
# --------------------------------------------------------------------------------------------------

def run(root=None) -> dict:
    """Grade the submission under ``root`` and write ``root/results/results.json``; return the results.

    Parameters
    ----------
    root : path, optional
        The autograder's root: ``$GRAPHKIN_AUTOGRADER_ROOT``, else ``/autograder``. It holds
        ``source/`` (the unpacked zip), ``submission/``, ``submission_metadata.json`` and ``results/``.

    Never raises for a bad submission: the student gets 0 points and a sentence.
    Anything unexpected is reported the same way, with the traceback on stdout,
    which Gradescope shows to the teacher only.
    """
    root = Path(root or os.environ.get(ROOT_ENV) or DEFAULT_ROOT)
    source = root / "source"
    cfg = json.loads((source / CONFIG).read_text(encoding="utf-8"))
    exercise_file = source / cfg["exercise_file"]
    _log_version()
    try:
        results = grade_submission(root, exercise_file, cfg)
    except Exception as exc:
        traceback.print_exc()
        why = str(exc) if isinstance(exc, GraphkinError) else "the autograder failed"
        results = not_graded(exercise_file, f"This submission could not be graded ({why}). Your teacher can "
                                            "see the details in the autograder's output.")
    write_results(root / "results" / "results.json", results)
    print(f"score: {results['score']:g}")
    return results


def _log_version() -> None:
    # The teacher reads this in Gradescope's output: the graded version is the exported one.
    print(f"graphkin {graphkin.__version__} from {Path(graphkin.__file__).parent}")


def grade_submission(root: Path, exercise_file: Path, cfg: dict) -> dict:
    """The results of one submission (a ``SubmissionError`` becomes 0 points and its sentence)."""
    keys = Keys(root / "source" / KEYS)
    ex = keys.exercise
    try:
        users = read_metadata(root / "submission_metadata.json")
        path = find_answers(root / "submission")
        print(f"answers file: {path.relative_to(root)}")
        answers = read_answers(path)
        claimed = None
        if "student" not in _ids(ex):  # `student` is the id, unless the exercise asks a question by that name
            claimed = answers.pop("student", None)
        if isinstance(claimed, str) and not claimed.strip():
            claimed = None  # the template's blank id: no claim
        student, notes = whom_to_grade(users, claimed, keys.roster)
    except SubmissionError as exc:
        return not_graded(exercise_file, str(exc))
    print(f"graded as: {student!r}")
    if claimed is not None:
        wrong = runtime.identity_error(claimed, student)
        if wrong:
            return not_graded(exercise_file, wrong[0].upper() + wrong[1:] + ".")
    report = keys.grade(student, answers)
    shown = [d["shown"] for d in keys.variant(student).sheet()["data"]]
    if shown:
        notes.insert(0, "Your data: " + ", ".join(shown) + ".")
    if report.get("ignored"):
        notes.append("Not questions of this exercise, so not graded: " + ", ".join(report["ignored"]) + ".")
    return results_from_report(ex, report, notes)


def _ids(ex) -> list[str]:
    return [q.id for q in ex.questions]


def read_metadata(path: Path) -> list[dict]:
    """The submitters (``users``) of Gradescope's ``submission_metadata.json``."""
    try:
        meta = json.loads(path.read_text(encoding="utf-8"))
        users = meta["users"]
        if not isinstance(users, list) or not users or not all(isinstance(u, dict) for u in users):
            raise ValueError("no users")
    except (OSError, ValueError, KeyError, TypeError) as exc:
        print(f"{path}: {exc}")
        raise SubmissionError("Gradescope's submission metadata could not be read, so the autograder does not "
                              "know who submitted: ask your teacher to check the autograder.") from None
    return users


def find_answers(folder: Path) -> Path:
    """The one answers file (``*.toml`` or ``*.json``) anywhere in the submission.

    Hidden files and the ``__MACOSX`` folder a Mac's zip adds are not the
    student's, and are passed over. A link is never followed: an answers file
    that is one, or a linked folder, is refused with a sentence.
    """
    def visible(p: Path) -> bool:
        return not any(part.startswith(".") or part == "__MACOSX" for part in p.relative_to(folder).parts)

    def linked(p: Path) -> bool:
        # A link (a repository or an unzipped upload keeps them) points past the submission, at the autograder's
        # own files: it is never followed, nor is anything under a linked folder.
        rel = p.relative_to(folder).parts
        return any(folder.joinpath(*rel[:k]).is_symlink() for k in range(1, len(rel) + 1))

    entries = sorted(p for p in folder.rglob("*") if visible(p)) if folder.is_dir() else []
    links = [p for p in entries if p.is_symlink() and (p.suffix.lower() in ANSWER_SUFFIXES or p.is_dir())]
    if links:
        names = ", ".join(p.relative_to(folder).as_posix() for p in links[:5])
        raise SubmissionError(f"Your submission holds a link ({names}), not the file itself: upload answers.toml "
                              f"as a file, with one line per question, for example {EXAMPLE_LINE}.")
    files = [p for p in entries if not linked(p) and p.is_file()]
    found = [p for p in files if p.suffix.lower() in ANSWER_SUFFIXES]
    if len(found) == 1:
        return found[0]
    if not found:
        uploaded = ", ".join(p.relative_to(folder).as_posix() for p in files[:5]) or "no files"
        raise SubmissionError(f"No answers file was found in your submission (you uploaded: {uploaded}). Upload "
                              f"answers.toml, with one line per question, for example {EXAMPLE_LINE}.")
    names = ", ".join(p.relative_to(folder).as_posix() for p in found)
    raise SubmissionError(f"Your submission has {len(found)} answers files ({names}): upload only one, "
                          "answers.toml.")


def read_answers(path: Path) -> dict:
    """The answers in a TOML or JSON file, question id → value, read as data (never run).

    A dotted key (``F12.x = "..."`` in TOML makes a table) is flattened back
    to ``"F12.x"``, the question id it names.
    """
    import tomllib

    name = path.name
    try:  # never through a link, never more than the cap
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0))
    except OSError:
        raise SubmissionError(f"{name} cannot be read: upload answers.toml as a file, for example "
                              f"{EXAMPLE_LINE}.") from None
    with os.fdopen(fd, "rb") as f:
        data = f.read(MAX_ANSWERS_BYTES + 1)
    if len(data) > MAX_ANSWERS_BYTES:
        raise SubmissionError(f"{name} is more than {MAX_ANSWERS_BYTES} bytes: an answers file is a few lines "
                              f"of text ({EXAMPLE_LINE}).")
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise SubmissionError(f"{name} is not text in UTF-8: save it as plain text (UTF-8), one line per "
                              f"question, for example {EXAMPLE_LINE}.") from None
    # Read as data; a whole number too long to convert stays text, that one answer's problem.
    if path.suffix.lower() == ".json":
        try:
            answers = json_answers(text)
        except json.JSONDecodeError as exc:
            raise SubmissionError(f"{name} is not valid JSON ({exc.msg} at line {exc.lineno}, column {exc.colno}). "
                                  'Write one object, for example {"F23": "27.06 N ∠ −73.78°"}.') from None
        except ValueError as exc:
            raise SubmissionError(f"{name} cannot be read ({exc}). Write one object, for example "
                                  '{"F23": "27.06 N ∠ −73.78°"}.') from None
    else:
        try:
            answers = toml_answers(text)
        except tomllib.TOMLDecodeError as exc:
            raise SubmissionError(f"{name} is not valid TOML ({exc}). Write one line per question, the answer "
                                  f"between double quotes, for example {EXAMPLE_LINE}.") from None
        except ValueError as exc:
            raise SubmissionError(f"{name} cannot be read ({exc}). Write one line per question, the answer "
                                  f"between double quotes, for example {EXAMPLE_LINE}.") from None
    if not isinstance(answers, dict):
        raise SubmissionError(f"{name} must hold question ids and answers, for example {EXAMPLE_LINE}.")
    return _flatten(answers)


def _flatten(table: dict, prefix: str = "") -> dict:
    out = {}
    for key, value in table.items():
        # A drawn answer held as an object (``{"drawing": 1, ...}``, docs/json.md) is one answer, not a table.
        if isinstance(value, dict) and value and "drawing" not in value:
            out.update(_flatten(value, f"{prefix}{key}."))
        else:
            out[f"{prefix}{key}"] = value
    return out


def _user_ids(user: dict) -> list[str]:
    """A submitter's usable ids, in order of preference: the roster's student id (``sid``), then the email."""
    ids = []
    for key in ("sid", "email"):
        value = user.get(key)
        if value is None or isinstance(value, bool) or not str(value).strip():
            continue
        try:
            ids.append(check_student(str(value)))
        except GraphkinError:
            continue
    return ids


def whom_to_grade(users: list[dict], claimed, roster) -> tuple[str, list[str]]:
    """The student id to grade as, and notes for the student.

    Parameters
    ----------
    users : list of dict
        Gradescope's submitters (several for a group).
    claimed : object or None
        The ``student`` the answers file carries, if any.
    roster : list of str or None
        The roster the export was given.

    The member graded is the one whose id the file carries, else the first.
    Their id is the one the file carries when it is one of theirs (and on the
    roster); else, with a roster, the first of ``sid``, ``email`` on it;
    without one, ``sid``, else ``email``.
    """
    try:
        claim = check_student(claimed) if claimed is not None else None
    except GraphkinError:
        claim = None  # the identity check that follows says what is wrong with it
    members = [_user_ids(u) for u in users]
    chosen = next((i for i, ids in enumerate(members) if claim in ids), 0)
    ids = members[chosen]
    roster_ids = None if roster is None else {check_student(s) for s in roster}
    if not ids:
        raise SubmissionError("Gradescope gives neither a student id nor an email for this submission, so the "
                              "autograder cannot tell whose data to grade: ask your teacher.")
    if claim in ids and (roster_ids is None or claim in roster_ids):
        student = claim
    elif roster_ids is not None:
        on = [i for i in ids if i in roster_ids]
        if not on:
            raise SubmissionError(f"Your Gradescope account ({' / '.join(ids)}) is not on this exercise's roster, "
                                  "so the autograder has no data of yours: ask your teacher to add you.")
        student = on[0]
    else:
        student = ids[0]
    notes = []
    if len(users) > 1:
        names = ", ".join(str(u.get("name") or (m[0] if m else "?")) for u, m in zip(users, members))
        who = users[chosen].get("name") or student
        notes.append(f"Group submission ({names}): graded on the data of {who} (student {student!r}); "
                     "every member gets this score.")
    return student, notes


def _test_name(question, limit: int = 100) -> str:
    """``"<id>: <ask>"``, cut at a word with "…" when longer than ``limit`` (Gradescope shows it as a heading)."""
    name = " ".join(f"{question.id}: {question.ask}".split())
    if len(name) <= limit:
        return name
    return name[:limit - 1].rsplit(" ", 1)[0].rstrip(",;:") + "…"


def results_from_report(ex, report: dict, notes: list[str]) -> dict:
    """Gradescope's ``results.json`` for a graphkin grading report: one test per question."""
    asked = {q.id: q for q in ex.questions}
    tests = [{
        "name": _test_name(asked[r["id"]]),
        "score": r["score"],
        "max_score": r["max"],
        "status": "passed" if r["verdict"] == "correct" else "failed",
        "output": runtime.feedback_line(r),
        "output_format": "text",
        "visibility": "visible",
    } for r in report["questions"]]
    summary = f"{ex.title}\nGraded as student {report['student']!r}: {report['score']:g} / {report['max']:g} points."
    results = _results(report["score"], "\n".join([summary, *notes]), tests)
    results["extra_data"] = {"graphkin": statistics(report)}
    return results


STATISTICS = ("id", "verdict", "slip", "score", "max")
"""What ``results.json`` keeps of each question's result (:func:`statistics`)."""


def statistics(report: dict) -> dict:
    """What ``results.json`` keeps of graphkin's report, under ``extra_data``: the teacher's statistics only.

    Gradescope stores ``extra_data`` with the submission without showing it, and the class's statistics
    (:func:`graphkin.draw.draw_grades`) need only the score and each question's verdict and slip. The rest of the
    report is left out, as ``results.json`` is the submission's own file, written where the submission was
    unpacked: ``other`` names a classmate whose data an answer fits, ``expected`` and a drawing's ``right`` are the
    key's values, ``answer``, ``feedback`` and ``ignored`` repeat what the student typed or was shown.

    Parameters
    ----------
    report : dict
        A report of :meth:`graphkin.exercises.keys.Keys.grade` (points, no unit).

    Returns
    -------
    dict
        ``{"exercise", "student", "score", "max", "questions": [{"id", "verdict", "slip", "score", "max"}]}``
        (``student``: the submitter graded, whom Gradescope already knows).
    """
    return {"exercise": report["exercise"], "student": report["student"], "score": report["score"],
            "max": report["max"], "questions": [{k: r.get(k) for k in STATISTICS} for r in report["questions"]]}


def not_graded(exercise_file, reason: str) -> dict:
    """0 points, the reason as the submission's output, and every question listed at 0."""
    ex = runtime.exercise(exercise_file)
    tests = [{"name": _test_name(q), "score": 0.0, "max_score": q.points, "status": "failed",
              "output": f"{q.id}: not graded (see the message above).", "output_format": "text",
              "visibility": "visible"}
             for q in ex.questions]
    return _results(0.0, f"{ex.title}\nNot graded: {reason}", tests)


def _results(score: float, output: str, tests: list[dict]) -> dict:
    # stdout carries the traceback of a failure and the graded id: for the teacher, not the student.
    # "text": Gradescope shows the output as typed, so what a student typed never becomes HTML on the page.
    return {"score": score, "output": output, "output_format": "text", "visibility": "visible",
            "stdout_visibility": "hidden",
            "tests": tests}


def write_results(path: Path, results: dict) -> None:
    """Write ``results.json`` atomically: Gradescope never reads half a file."""
    write_text(path, json.dumps(results, indent=2, ensure_ascii=False) + "\n", "results")


__all__ = ["STATISTICS", "build", "run", "read_answers", "find_answers", "whom_to_grade", "results_from_report",
           "statistics", "local_try_commands"]
