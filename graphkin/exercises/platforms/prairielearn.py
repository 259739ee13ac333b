"""PrairieLearn: one question folder per exercise, graded on PrairieLearn's server by graphkin.

The export is laid out as a PrairieLearn course repository is::

    questions/<name>/info.json        the question's metadata (uuid, title, topic, tags, type "v3")
    questions/<name>/question.html    the statement and one ``pl-string-input`` per question
    questions/<name>/server.py        generate(), parse(), grade() (and file() for a figure); holds the secret
    questions/<name>/<name>.toml      the exercise file (and its base problem when not a catalog one)
    serverFilesCourse/graphkin/...    graphkin itself, which server.py imports
    check_question.py                 runs server.py as PrairieLearn does, on the teacher's machine
    README.md

PrairieLearn draws a *variant* per student and attempt; it does not tell
``server.py`` who the student is. So the variant's seed stands in for the
student id: ``generate`` draws graphkin's variant for the key
``pl-<variant_seed>`` (with the course secret), stores the sheet in
``data["params"]`` for the template and the key's answer texts in
``data["correct_answers"]``. ``grade`` grades the submitted texts with the
same grader as ``graphkin exercise grade`` and writes each question's score,
weight (its points) and feedback sentence where PrairieLearn reads them. A
roster plays no part: PrairieLearn hands out the variants.

The functions :func:`generate`, :func:`parse`, :func:`grade` and
:func:`figure` are what the exported ``server.py`` calls, on PrairieLearn's
server, from the copy of graphkin in ``serverFilesCourse``; :func:`build`
writes the export on the teacher's machine.
"""

from __future__ import annotations

import html
import json
import re
import uuid

from graphkin.errors import GraphkinError
from graphkin.exercises.drawn_tasks import task_of
from graphkin.exercises.platforms import requirements, runtime, vendor_files
from graphkin.notation import unit_text
from graphkin.scene.page import asset, module

TOPIC = "Kinetostatics"
"""The PrairieLearn topic of every exported question (listed in the course's ``infoCourse.json``)."""

UUID_NAMESPACE = uuid.UUID("6f1d3a52-5b8e-4c0e-9d57-3c1f0a6b2e41")
"""Fixed namespace of the questions' uuids: uuid5(namespace, exercise id) is the same at every export."""

FIGURE = "given.png"
"""Name under which ``server.py``'s ``file()`` serves the figure of a drawn exercise."""

STUDENT_PREFIX = "pl-"
"""The variant ``pl-<variant_seed>`` is graphkin's variant of that student key."""

DRAWING_FILES = "graphkin"
"""The folder of ``clientFilesCourse`` that holds the drawing's module and styles, for drawn questions."""

DRAWING_MODULES = ("dom.js", "match.js", "draw.js", "pldrawing.js")
"""The ES modules joined into ``clientFilesCourse/graphkin/drawing.mjs``: the student's drawing and the bridge
that puts each drawn question's box on PrairieLearn's page (``graphkin/scene/js/pldrawing.js``)."""

DRAWN_FEEDBACK = "__drawn"
"""Appended to a drawn question's answer name: ``feedback[name + DRAWN_FEEDBACK]`` is what the submission panel draws
back on the student's drawing (docs/json.md, "Drawn answers": Feedback), as JSON."""


# --- On PrairieLearn's server: what server.py calls -------------------------------------------------------------


def variant_student(data: dict) -> str:
    """The student key a PrairieLearn variant is drawn for: ``pl-<variant_seed>``.

    PrairieLearn passes every ``server.py`` function the variant's seed, never
    the student: the same seed gives the same data again, and a new variant a
    new draw.
    """
    seed = data.get("variant_seed")
    if seed is None or str(seed).strip() == "":
        raise GraphkinError("PrairieLearn passed no variant_seed: cannot draw a variant")
    return f"{STUDENT_PREFIX}{seed}"


def answer_names(question_ids) -> dict[str, str]:
    """PrairieLearn's answer name of each question (name → question id).

    A question id is the name when it is a plain identifier; a ``.`` (which
    graphkin allows in an id) would split a Mustache name such as
    ``{{feedback.peak.at}}``, so it becomes ``_``, with a number added if
    that name is taken.
    """
    names: dict[str, str] = {}
    for qid in question_ids:
        base = re.sub(r"[^A-Za-z0-9_]", "_", qid)
        name, n = base, 2
        while name in names:
            name, n = f"{base}_{n}", n + 1
        names[name] = qid
    return names


def marks(q: dict) -> str:
    """The bracket printed after a question: unit, slack and points (as ``graphkin exercise make`` prints it)."""
    unit = unit_text(q["unit"]) or "no unit"
    return f"{unit}, within {q['within']}, {q['points']:g} point{'s' if q['points'] != 1 else ''}"


def generate(data: dict, exercise_file: str, secret: str = "") -> None:
    """PrairieLearn's ``generate(data)``: draw the variant, fill ``params`` and ``correct_answers``.

    ``params`` holds what ``question.html`` shows (title, intro with the
    values filled in, the data, each question's ask and marks, the student
    key); ``correct_answers`` holds the key's answer texts, which
    PrairieLearn's answer panel shows. Neither holds the secret.
    """
    student = variant_student(data)
    key = runtime.variant(exercise_file, student, secret).key()
    names = {qid: name for name, qid in answer_names([q["id"] for q in key["questions"]]).items()}
    data["params"].update({
        "student": key["student"],
        "exercise": key["exercise"],
        "title": key["title"],
        "intro": key["intro"].strip(),
        "data": [{"symbol": g["symbol"], "shown": g["shown"], "label": g["label"]} for g in key["data"]],
        "asks": {names[q["id"]]: q["ask"] for q in key["questions"]},
        "marks": {names[q["id"]]: marks(q) for q in key["questions"]},
    })
    for q in key["questions"]:
        # A drawn question's correct answer is what a right submission holds: the right drawing, as data.
        data["correct_answers"][names[q["id"]]] = q["answer"].get("drawing") or q["answer"]["text"]
    drawn = [q["id"] for q in key["questions"] if q.get("form") == "drawing"]
    if drawn:
        v = runtime.variant(exercise_file, student, secret)
        # The task as data, shown in an attribute (Mustache escapes it); it carries no targets (never 'check').
        data["params"]["tasks"] = {names[qid]: json.dumps(task_of(v, qid), ensure_ascii=False) for qid in drawn}


def parse(data: dict, exercise_file: str, secret: str = "") -> None:
    """PrairieLearn's ``parse(data)``: an answer graphkin cannot read is a format error, not a wrong answer.

    PrairieLearn does not grade a submission with format errors, nor count it
    as an attempt; the student sees the sentence that says how to write the
    answer (``Could not read "12,5 N": ... (use a decimal point).``). Blank
    answers are left to ``pl-string-input`` (blank is its own format error
    unless ``allow-blank`` is set; then graphkin grades it as missing).
    """
    student = _student_of(data)
    ex = runtime.exercise(exercise_file)
    for name, qid in answer_names([q.id for q in ex.questions]).items():
        value = data["submitted_answers"].get(name)
        if name in data["format_errors"] or value is None or str(value).strip() == "":
            continue
        result = runtime.grade_question(ex, student, qid, value, secret)
        if result["verdict"] == "unreadable":
            # PrairieLearn shows a format error as HTML: the sentence quotes what the student typed.
            data["format_errors"][name] = html.escape(result["feedback"])


def grade(data: dict, exercise_file: str, secret: str = "") -> dict:
    """PrairieLearn's ``grade(data)``: grade every answer with graphkin and write scores and feedback.

    For each question ``data["partial_scores"][name]`` becomes ``{"score":
    points earned / points, "weight": points, "feedback": sentence}`` and
    ``data["feedback"][name]`` the same sentence (``question.html`` shows it
    under the answer); ``data["score"]`` is the points earned over the
    points, from 0 to 1. Every sentence is HTML-escaped (PrairieLearn renders
    feedback as HTML, and a sentence may quote what the student typed), and
    ``question.html`` shows it with triple braces, so it is escaped once.
    Returns graphkin's report.
    """
    ex = runtime.exercise(exercise_file)
    names = answer_names([q.id for q in ex.questions])
    answers = {qid: data["submitted_answers"].get(name) for name, qid in names.items()}
    report = runtime.grade(ex, _student_of(data), answers, secret)
    results = {r["id"]: r for r in report["questions"]}
    # With every question worth 0 points, each counts the same (PrairieLearn divides by the total weight).
    unweighted = not any(r["max"] for r in report["questions"])
    earned = total = 0.0
    for name, qid in names.items():
        r = results[qid]
        part = r["score"] / r["max"] if r["max"] else float(r["verdict"] == "correct")
        weight = 1 if unweighted else _number(r["max"])
        sentence = html.escape(feedback(r))
        data["partial_scores"][name] = {"score": part, "weight": weight, "feedback": sentence}
        data["feedback"][name] = sentence
        if "fault" in r:  # a drawn question: what the submission panel marks on the student's own drawing
            shown = {k: r.get(k) for k in ("verdict", "slip", "score", "max", "feedback", "fault", "right")}
            data["feedback"][name + DRAWN_FEEDBACK] = json.dumps(shown, ensure_ascii=False)
        earned, total = earned + part * weight, total + weight
    data["score"] = earned / total if total else 0.0
    return report


def feedback(result: dict) -> str:
    """The sentence shown under an answer: graphkin's feedback, and the expected answer if the exercise reveals it."""
    text = result["feedback"]
    if "expected" in result and result["verdict"] != "correct":
        text += f" Expected: {result['expected']}."
    return text


def figure(data: dict, exercise_file: str, secret: str = "") -> bytes:
    """PNG of what the student is given to scale (``graphkin exercise make --figure``), for ``file(data)``."""
    import io

    from graphkin import draw

    c = runtime.variant(exercise_file, _student_of(data), secret).construction
    if not c.valid:
        raise GraphkinError("this exercise has no single position to draw (a whole-cycle exercise)")
    buf = io.BytesIO()
    draw.draw_given(c).savefig(buf, format="png")
    return buf.getvalue()


def _student_of(data: dict) -> str:
    """The student key of the variant being graded: the one generate() stored, else drawn from the seed again."""
    return (data.get("params") or {}).get("student") or variant_student(data)


def _number(x: float):
    """An integral number of points as an int (PrairieLearn's weights are integers in its own elements)."""
    return int(x) if float(x).is_integer() else float(x)


# --- On the teacher's machine: the export -----------------------------------------------------------------------


def build(bundle) -> dict:
    """The export's files (relative path → text or bytes): one question folder, graphkin, a check, a README."""
    folder = f"questions/{bundle.name}"
    tree: dict = {
        f"{folder}/info.json": info_json(bundle),
        f"{folder}/question.html": question_html(bundle),
        f"{folder}/server.py": server_py(bundle),
        "check_question.py": check_question_py(bundle),
        "README.md": readme(bundle),
    }
    for file_name, text in bundle.files.items():
        tree[f"{folder}/{file_name}"] = text
    for rel, content in vendor_files().items():
        tree[f"serverFilesCourse/{rel}"] = content
    if _drawn(bundle):
        tree[f"clientFilesCourse/{DRAWING_FILES}/drawing.mjs"] = module(DRAWING_MODULES)
        tree[f"clientFilesCourse/{DRAWING_FILES}/drawing.css"] = asset("draw.css")
    return tree


def _drawn(bundle) -> list[str]:
    """The ids of the exercise's drawn questions."""
    return [q.id for q in bundle.exercise.questions if q.kind == "drawing"]


def question_uuid(exercise_id: str) -> str:
    """The question's uuid: the same at every export of the exercise (PrairieLearn keeps its statistics by it)."""
    return str(uuid.uuid5(UUID_NAMESPACE, f"graphkin:{exercise_id}"))


def info_json(bundle) -> str:
    """``info.json``: the fields PrairieLearn requires (uuid, type, title, topic) and a few more."""
    ex = bundle.exercise
    info = {
        "uuid": question_uuid(bundle.name),
        "title": ex.title,
        "topic": TOPIC,
        "tags": ["graphkin", bundle.name],
        "type": "v3",
        "singleVariant": False,
        "comment": f"Written by 'graphkin exercise export {bundle.name} --to prairielearn'; export again rather "
                   "than edit server.py. The course secret is in server.py, which PrairieLearn never sends to "
                   "students.",
    }
    return json.dumps(info, ensure_ascii=False, indent=2) + "\n"


_PLACEHOLDERS = {
    "vector": "e.g. 12.3 {u} ∠ −45° or (8.7, −8.7) {u}",
    "point": "e.g. (120.5, 80.2) {u}",
    "direction": "an angle, e.g. −45°",
    "scalar": "e.g. 12.3 {u}",
    "magnitude": "e.g. 12.3 {u}",
    "drawing": "the drawing as the drawing page gives it (JSON text)",  # a drawn question (docs/json.md)
}


def _placeholder(q: dict) -> str:
    unit = unit_text(q["unit"])
    if not unit and q["form"] in ("scalar", "magnitude"):
        return "a number, e.g. 1.23"
    text = _PLACEHOLDERS[q["form"]].format(u=unit)
    if q["answer"]["text"].endswith(("CCW", "CW")):
        text += " CCW"  # a torque is answered with its sense, as the key prints it
    return text


def question_html(bundle) -> str:
    """``question.html``: the statement from ``params``, one ``pl-string-input`` per question, the feedback.

    Everything that varies comes from ``{{params...}}`` (Mustache escapes
    it); the file itself is the same for every variant and holds no answer
    and no secret (PrairieLearn may serve it to the browser).
    """
    sheet = bundle.sample_key()
    names = {qid: name for name, qid in answer_names(bundle.question_ids()).items()}
    figure_html = (f'\n  <pl-figure file-name="{FIGURE}" type="dynamic" width="100%"></pl-figure>'
                   if bundle.exercise.draw else "")
    parts = [
        "{{! Written by graphkin exercise export; the values come from server.py's generate(). }}",
        "<pl-question-panel>",
        '  <div class="mathjax_ignore">',
        "  <p>{{params.intro}}</p>",
        "  <p><strong>Your data</strong> <small class=\"text-muted\">(variant {{params.student}})</small></p>",
        "  <ul>",
        "    {{#params.data}}<li>{{shown}}{{#label}} <span class=\"text-muted\">({{label}})</span>{{/label}}</li>"
        "{{/params.data}}",
        "  </ul>" + figure_html,
        "  <p class=\"small text-muted\">Type each answer as text with its unit: a force as magnitude and angle "
        "(\"27.06 N ∠ −73.78°\") or components (\"(7.56, −25.98) N\"), a torque with its sense "
        "(\"108.9 N·m CCW\"). Use a decimal point; write N·m as \"N*m\" or \"N·m\".</p>",
        "  </div>",
        "</pl-question-panel>",
        "",
    ]
    for q in sheet["questions"]:
        name = names[q["id"]]
        if q["form"] == "drawing":
            parts += _drawn_html(name)
            continue
        attrs = {
            "answers-name": name,
            "label": q["id"],
            "placeholder": _placeholder(q),
            "size": "40",
            # graphkin reads the text as typed: spaces inside it matter ("12 13 N" is two numbers).
            "remove-leading-trailing": "true",
            # graphkin's own note above says how to write answers; PrairieLearn's generic one would not.
            "show-help-text": "false",
        }
        attr_text = " ".join(f'{k}="{html.escape(v, quote=True)}"' for k, v in attrs.items())
        parts += [
            '<div class="mb-3 mathjax_ignore">',
            f'  <p class="mb-1">{{{{params.asks.{name}}}}} <small class="text-muted">[{{{{params.marks.{name}}}}}]'
            "</small></p>",
            f"  <pl-string-input {attr_text}></pl-string-input>",
            # Triple braces: grade() escaped the sentence already (it may quote the student's text).
            f"  <pl-submission-panel><p class=\"mt-1\">{{{{{{feedback.{name}}}}}}}</p></pl-submission-panel>",
            "</div>",
        ]
    if any(q["form"] == "drawing" for q in sheet["questions"]):
        url = f"{{{{options.client_files_course_url}}}}/{DRAWING_FILES}"
        parts += [f'<link rel="stylesheet" href="{url}/drawing.css">',
                  f'<script type="module" src="{url}/drawing.mjs"></script>']
    return "\n".join(parts) + "\n"


def _drawn_html(name: str) -> list[str]:
    """A drawn question's part of ``question.html``: the box the student draws in, with the hidden input that
    PrairieLearn submits (the drawing's JSON, graded on the server by graphkin), and in the submission panel the
    drawing submitted with the grader's feedback drawn back on it.

    Every value is in an attribute written with double braces: Mustache escapes it, the browser reads it back
    unescaped, and nothing a student submitted can close the attribute or the element.
    """
    task = f"{{{{params.tasks.{name}}}}}"
    return [
        '<div class="mb-3 mathjax_ignore">',
        f'  <p class="mb-1">{{{{params.asks.{name}}}}} <small class="text-muted">[{{{{params.marks.{name}}}}}]'
        "</small></p>",
        "  <pl-question-panel>",
        f'  <div class="graphkin-drawing" data-answer="{name}" data-task="{task}"'
        f' data-drawing="{{{{raw_submitted_answers.{name}}}}}">',
        f'    <input type="hidden" name="{name}" value="{{{{raw_submitted_answers.{name}}}}}">',
        "  </div>",
        "  </pl-question-panel>",
        "  <pl-submission-panel>",  # the box says the feedback's words itself, under the drawing
        f'  <div class="graphkin-drawing" data-answer="{name}" data-task="{task}"'
        f' data-drawing="{{{{submitted_answers.{name}}}}}" data-feedback="{{{{feedback.{name}{DRAWN_FEEDBACK}}}}}">'
        "</div>",
        "  </pl-submission-panel>",
        "</div>",
    ]


_SERVER_PY = '''\
"""PrairieLearn question code for graphkin's exercise {name!r}.

Written by `graphkin exercise export {name} --to prairielearn`: export again
rather than edit it. PrairieLearn runs this file on its server and never
sends it to students, which is why the course secret lives here (and only
here): with it, nobody can compute another variant's answers.

generate() draws the variant (student key "pl-<variant_seed>") and grade()
grades the answers with graphkin's grader; both are in
graphkin/exercises/platforms/prairielearn.py, in the copy of graphkin in
the course's serverFilesCourse/.
"""

import importlib
import os
import sys

EXERCISE_FILE = {exercise_file!r}
SECRET = {secret!r}


def _graphkin(data):
    """graphkin's PrairieLearn module, always from serverFilesCourse/.

    That copy is the version the question was exported with, so a variant
    shows the same data and gets the same key as on the teacher's machine.
    PrairieLearn puts serverFilesCourse/ on the path already; putting it
    first, and dropping a graphkin loaded from elsewhere, makes sure.
    """
    course_files = (data.get("options") or {{}}).get("server_files_course_path")
    if course_files:
        course_files = os.path.abspath(course_files)
        if sys.path[:1] != [course_files]:
            sys.path.insert(0, course_files)
        loaded = getattr(sys.modules.get("graphkin"), "__file__", None) or ""
        if loaded and not os.path.abspath(loaded).startswith(course_files + os.sep):
            for module in [m for m in sys.modules if m == "graphkin" or m.startswith("graphkin.")]:
                del sys.modules[module]
    return importlib.import_module("graphkin.exercises.platforms.prairielearn")


def _exercise_file(data):
    """The exercise file beside this one (PrairieLearn runs server.py in the question's folder)."""
    folder = (data.get("options") or {{}}).get("question_path") or os.getcwd()
    return os.path.join(folder, EXERCISE_FILE)


def generate(data):
    _graphkin(data).generate(data, _exercise_file(data), SECRET)


def parse(data):
    _graphkin(data).parse(data, _exercise_file(data), SECRET)


def grade(data):
    _graphkin(data).grade(data, _exercise_file(data), SECRET)
'''

_SERVER_FILE = '''

def file(data):
    """The figure the student measures on ({figure!r}, shown by pl-figure in question.html)."""
    if data.get("filename") == {figure!r}:
        return _graphkin(data).figure(data, _exercise_file(data), SECRET)
    return None
'''


def server_py(bundle) -> str:
    """``server.py``: constants (the exercise file, the secret) and thin calls into this module."""
    text = _SERVER_PY.format(name=bundle.name, exercise_file=bundle.exercise_file, secret=bundle.secret)
    if bundle.exercise.draw:
        text += _SERVER_FILE.format(figure=FIGURE)
    return text


_CHECK_PY = '''\
"""Run questions/{name}/server.py as PrairieLearn does, before you commit it.

    python check_question.py [VARIANT_SEED]

Like PrairieLearn, it runs server.py in the question's folder with
serverFilesCourse/ on the path, calls generate(data) for the variant, then
parse(data) and grade(data) with the key's answers typed in, and prints the
data and the score (1 when all is well). Needs a Python with graphkin's
requirements (numpy, shapely, pint).
"""

import json
import os
import sys

NAME = {name!r}
HERE = os.path.dirname(os.path.abspath(__file__))
QUESTION = os.path.join(HERE, "questions", NAME)
SERVER_FILES = os.path.join(HERE, "serverFilesCourse")


def load_server():
    """server.py's functions, loaded as PrairieLearn loads them (exec in the question folder, no __file__)."""
    os.chdir(QUESTION)
    sys.path[:0] = [QUESTION, SERVER_FILES]
    path = os.path.join(QUESTION, "server.py")
    with open(path, encoding="utf-8") as f:
        code = compile(f.read(), path, "exec")
    functions = {{}}
    exec(code, functions)  # the question's own server code, as PrairieLearn runs it
    return functions


def pl_data(variant_seed):
    """The data dictionary PrairieLearn passes, for a new variant."""
    return {{
        "params": {{}}, "correct_answers": {{}}, "submitted_answers": {{}}, "raw_submitted_answers": {{}},
        "format_errors": {{}}, "partial_scores": {{}}, "score": 0, "feedback": {{}},
        "variant_seed": variant_seed, "answers_names": {{}},
        "options": {{"question_path": QUESTION, "server_files_course_path": SERVER_FILES}},
    }}


def main(variant_seed=1):
    server = load_server()
    data = pl_data(variant_seed)
    server["generate"](data)
    p = data["params"]
    print(f"{{NAME}}, variant {{p['student']}}: " + ", ".join(g["shown"] for g in p["data"]))
    data["submitted_answers"] = dict(data["correct_answers"])
    server["parse"](data)
    if data["format_errors"]:
        sys.exit(f"format errors: {{data['format_errors']}}")
    server["grade"](data)
    json.dumps(data, allow_nan=False)  # PrairieLearn keeps data as JSON
    for name, part in data["partial_scores"].items():
        print(f"  {{name}}: {{data['correct_answers'][name]}}  ->  {{part['score']:g}} x {{part['weight']:g}}  "
              f"{{part['feedback']}}")
    print(f"score {{data['score']:g}}")
    return 0 if data["score"] == 1 else 1


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else 1))
'''


def check_question_py(bundle) -> str:
    """``check_question.py``: the teacher's local run of server.py, as PrairieLearn calls it."""
    return _CHECK_PY.format(name=bundle.name)


def readme_commands(bundle) -> dict[str, str]:
    """The README's shell commands, by step, exactly as printed (the tests run them as they are).

    (The README's one other command, which installs shapely into the course with PrairieLearn's Docker
    image, needs Docker and the course repository, and is not among them.)
    """
    return {"check": "python check_question.py 1\n",
            "key": f"graphkin exercise key questions/{bundle.name}/{bundle.exercise_file} --student pl-1\n"}


def _indent(text: str, spaces: int) -> str:
    return "".join(" " * spaces + line + "\n" for line in text.splitlines())


def readme(bundle) -> str:
    """README.md: what each file is, where it goes in the course repository, what the server needs."""
    name = bundle.name
    reqs = "\n".join(f"       {r}" for r in requirements())
    secret_line = ("The course secret is written into `server.py` (and nowhere else): keep the course repository "
                   "private to course staff." if bundle.secret else
                   "**No course secret was given**: anyone with graphkin can compute a variant's answers from the "
                   "variant key shown on the page (`pl-<seed>`). Export again with `--secret`.")
    roster = ("\nThe roster given to the export plays no part here: PrairieLearn draws a variant for each student "
              "and attempt itself.\n" if bundle.students else "")
    questions = "\n".join(f"- `{q.id}`: {q.ask}" for q in bundle.exercise.questions)
    return f"""# {bundle.exercise.title} — PrairieLearn question

Exported by `graphkin exercise export {name} --to prairielearn`. One PrairieLearn question, graded on
PrairieLearn's server by graphkin's grader.

## Files

| file | what it is | where it goes in the course repository |
|---|---|---|
| `questions/{name}/info.json` | uuid (the same at every export), title, topic `{TOPIC}`, tags, `type: v3` | `questions/{name}/` (any folder under `questions/`) |
| `questions/{name}/question.html` | the statement, your data, one text box per question, the feedback | same folder |
| `questions/{name}/server.py` | `generate`, `parse`, `grade`{', `file` (the figure)' if bundle.exercise.draw else ''}; holds the course secret | same folder |
| `questions/{name}/{bundle.exercise_file}`{''.join(f', `{f}`' for f in bundle.files if f != bundle.exercise_file)} | the exercise (no answers, no secret) | same folder |
| `serverFilesCourse/graphkin/` | graphkin itself, imported by `server.py` | the course's `serverFilesCourse/` |
| `check_question.py` | runs `server.py` as PrairieLearn does, on your machine | not in the course: keep it here |

{secret_line}
{roster}
## Next steps

1. Check the question on your machine (a Python with graphkin's requirements):

{_indent(readme_commands(bundle)["check"], 7)}
   It prints the data of variant `pl-1`, each answer of its key graded (`1 x 1  Correct.`) and `score 1`.

2. Copy `questions/{name}/` into the course repository's `questions/`, and `serverFilesCourse/graphkin/`
   into its `serverFilesCourse/` (create it if needed).

3. graphkin's requirements:

{reqs}

   On PrairieLearn, `server.py` needs numpy, shapely and pint to draw and grade (and matplotlib for a
   figure); the others serve graphkin's command line only. PrairieLearn's question image has numpy, pint
   and matplotlib (pint 0.25 in current images; graphkin needs 0.24 or later); **shapely is not among its
   packages**. Install it into the course as PrairieLearn's documentation describes (from a machine with
   Docker; `--no-deps` keeps PrairieLearn's own numpy):

       docker run -it --rm -v <path-to-course>:/course prairielearn/prairielearn pip3 install --target /course/serverFilesCourse --no-deps "shapely>=2.0"

   and commit the files it writes (including `*.so`).

4. List the topic in `infoCourse.json` (else PrairieLearn makes a placeholder topic):
   `"topics": [{{"name": "{TOPIC}", "color": "blue1", "description": "graphkin exercises"}}]`,
   and the tags `graphkin` and `{name}` under `"tags"` if you want colours for them.

5. Add the question to an assessment's `infoAssessment.json`, in a zone's `"questions"`:
   `{{"id": "{name}", "points": 10}}` (the id is the folder's path under `questions/`). graphkin's points
   weight the parts inside the question; the assessment sets what the question is worth.

6. Commit, push and sync the course; open the question's **Preview** page, type answers and press
   **Save & Grade**. Each new variant is a new draw.

## What the student sees

The statement with their values, the data list and a variant key (`pl-<seed>`), and one text box per
question:

{questions}

Answers are typed as text ("27.06 N ∠ −73.78°", "(7.56, −25.98) N", "108.9 N·m CCW"). After **Save & Grade**
each box shows its score badge (100 %, 50 %, 0 %) and graphkin's sentence under it (the slip it diagnosed,
else which part is wrong, and which step to revisit; how far off only with `feedback = "distance"` in the
exercise file, which gives the answer away in one more try). A blank box or an answer graphkin cannot read
("12,5 N") is marked *invalid* with the sentence saying how to write it, and is not graded (it does not use
an attempt).
PrairieLearn's answer panel shows the key's answers when the assessment lets it.

To see a variant's key on your machine, with `GRAPHKIN_SECRET` set to the export's secret (here variant
`pl-1`; the page shows the variant of each student):

{_indent(readme_commands(bundle)["key"], 4)}
(the seed shown on the page).
"""
