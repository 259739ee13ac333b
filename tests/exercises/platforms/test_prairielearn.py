"""The PrairieLearn export: server.py run as PrairieLearn runs it, info.json and question.html checked.

PrairieLearn itself (a Node service in Docker) cannot run here. What it does
with a question is documented and small: it runs ``server.py`` in the
question's folder with ``serverFilesCourse`` on the path (exec'd, without
``__file__``) and calls ``generate(data)``, then ``parse(data)`` and
``grade(data)``, with the data dictionary below. The export's own
``check_question.py`` does exactly that; the tests drive it in a fresh
Python process (so the copy of graphkin in ``serverFilesCourse`` is the one
imported) and compare every score and sentence with ``exercises.grade`` for
the same variant key and secret.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import uuid
from html.parser import HTMLParser
from pathlib import Path

import jsonschema
import pytest

from graphkin import exercises
from graphkin.exercises import platforms
from graphkin.exercises.platforms import prairielearn

pytestmark = pytest.mark.slow  # runs the real platform

NAME = "strip_cutter_cut"
DRAWN = "double_slider_graphical"
SECRET = "pl-course-secret-2025"
MARKER = "pl-env-marker-5c3e"
# Answers that name what sits on the server: its environment, its files, format fields (issue 23, item 2).
PROBES = ["$GRAPHKIN_SECRET", "${GRAPHKIN_MARKER}", "%GRAPHKIN_MARKER%", "$(cat server.py)", "`cat server.py`",
          "@server.py", "file://./server.py", "../../serverFilesCourse/graphkin/__init__.py", "{{secret}}",
          "{{{params}}}", "{0.__class__.__mro__}", "%(secret)s"]

# The parts of PrairieLearn's schema of info.json that an export must meet
# (apps/prairielearn/src/schemas/schemas/infoQuestion.json: required fields,
# the uuid pattern, the question types, no unknown keys), restated here.
INFO_SCHEMA = {
    "type": "object",
    "additionalProperties": False,
    "required": ["uuid", "type", "title", "topic"],
    "properties": {
        "comment": {},
        "uuid": {"type": "string",
                 "pattern": "^[0-9a-fA-F]{8}-[0-9a-fA-F]{4}-[0-9a-fA-F]{4}-[0-9a-fA-F]{4}-[0-9a-fA-F]{12}$"},
        "type": {"enum": ["Calculation", "MultipleChoice", "Checkbox", "File", "MultipleTrueFalse", "v3"]},
        "title": {"type": "string"},
        "topic": {"type": "string"},
        "tags": {"type": "array", "items": {"type": "string"}},
        "clientFiles": {"type": "array"}, "clientTemplates": {"type": "array"}, "template": {"type": "string"},
        "gradingMethod": {"enum": ["Internal", "External", "Manual"]},
        "singleVariant": {"type": "boolean"}, "showCorrectAnswer": {"type": "boolean"},
        "partialCredit": {"type": "boolean"}, "options": {"type": "object"},
        "externalGradingOptions": {"type": "object"}, "dependencies": {"type": "object"},
        "workspaceOptions": {"type": "object"}, "sharingSets": {"type": "array"},
        "sharePublicly": {"type": "boolean"}, "shareSourcePublicly": {"type": "boolean"},
    },
}

# Run in a fresh process from the export's folder: the server's functions, called as PrairieLearn calls them.
DRIVER = r'''
import json, sys
root, scenarios = sys.argv[1], json.loads(open(sys.argv[2], encoding="utf-8").read())
sys.path.insert(0, root)
import check_question as cq

server = cq.load_server()

def generated(seed):
    data = cq.pl_data(seed)
    server["generate"](data)
    return data

def submitted(seed, answers):
    data = generated(seed)
    data["submitted_answers"] = dict(answers)
    data["raw_submitted_answers"] = dict(answers)
    # What pl-string-input's own grade() leaves before server.py's: an exact text match, weight 1.
    for name, text in answers.items():
        data["partial_scores"][name] = {"score": float(text == data["correct_answers"][name]), "weight": 1}
    server["parse"](data)
    if not data["format_errors"]:  # PrairieLearn grades only a submission without format errors
        server["grade"](data)
    json.dumps(data, allow_nan=False)  # PrairieLearn keeps data as JSON
    return {k: data[k] for k in ("score", "partial_scores", "feedback", "format_errors")}

first, again = generated(1), generated(1)
out = {
    "graphkin_file": sys.modules["graphkin"].__file__,
    "first": {"params": first["params"], "correct_answers": first["correct_answers"]},
    "same": [first[k] == again[k] for k in ("params", "correct_answers")],
    "others": [generated(seed)["params"]["data"] for seed in range(2, 8)],
    "graded": {label: submitted(1, answers) for label, answers in scenarios.get("graded", {}).items()},
}
if "file" in server:
    data = generated(3)
    data["filename"] = scenarios["figure"]
    png = server["file"](data)
    out["figure"] = {"bytes": len(png), "head": png[:8].hex(), "draw_params": data["params"]["data"]}
json.dump(out, sys.stdout, ensure_ascii=False)
'''


def run_driver(root: Path, scenarios: dict) -> dict:
    spec = root / "scenarios.json"
    spec.write_text(json.dumps(scenarios, ensure_ascii=False), encoding="utf-8")
    driver = root / "driver.py"
    driver.write_text(DRIVER, encoding="utf-8")
    # The server's environment holds a marker: no answer may bring it back.
    env = dict(os.environ, GRAPHKIN_SECRET=SECRET, GRAPHKIN_MARKER=MARKER)
    done = subprocess.run([sys.executable, str(driver), str(root), str(spec)], capture_output=True, text=True,
                          encoding="utf-8", timeout=120, cwd=root, env=env)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def key_answers(student: str, exercise: str = NAME) -> dict:
    return {q["id"]: q["answer"]["text"] for q in exercises.key(exercise, student, secret=SECRET)["questions"]}


def flip_sense(text: str) -> str:
    return text[:-3] + "CW" if text.endswith("CCW") else text[:-2] + "CCW"


@pytest.fixture(scope="module")
def export(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("prairielearn") / "export"
    platforms.export(NAME, "prairielearn", out, secret=SECRET, students=["s001", "s002"])
    return out


@pytest.fixture(scope="module")
def served(export) -> dict:
    key = key_answers("pl-1")
    scenarios = {"graded": {
        "key": key,
        "sign": {**key, "T12": flip_sense(key["T12"])},
        "blank": {**key, "F14": ""},
        "unreadable": {**key, "F14": "1,352 N"},
        # HTML and script in answers: PrairieLearn renders format errors and feedback as HTML.
        "html": {**key, "F14": '<img src=x onerror="alert(1)">', "T12": "<script>alert('x')</script> N*m"},
        "html_graded": {**key, "F14": "1 N <b>", "T12": "12 N*m <i>"},
    }}
    ids = list(key)
    for k in range(0, len(PROBES), len(ids)):
        scenarios["graded"][f"probe{k}"] = dict(zip(ids, PROBES[k:k + len(ids)]))
    return run_driver(export, scenarios)


def question(export: Path, name: str = NAME) -> Path:
    return export / "questions" / name


def test_tree(export):
    q = question(export)
    for f in ("info.json", "question.html", "server.py", f"{NAME}.toml"):
        assert (q / f).is_file(), f
    assert (export / "serverFilesCourse" / "graphkin" / "exercises" / "platforms" / "prairielearn.py").is_file()
    assert (export / "README.md").is_file() and (export / "check_question.py").is_file()
    readme = (export / "README.md").read_text(encoding="utf-8")
    assert "python check_question.py 1" in readme and "serverFilesCourse" in readme
    for r in platforms.requirements():
        assert r in readme
    assert "roster" in readme  # said to play no part


def test_generate_draws_the_variant_of_the_seed(served):
    # The vendored copy is what server.py imported, not the graphkin of this environment.
    assert "serverFilesCourse" in Path(served["graphkin_file"]).parts
    params, correct = served["first"]["params"], served["first"]["correct_answers"]
    assert params["student"] == "pl-1"
    sheet = exercises.make(NAME, "pl-1", secret=SECRET)
    assert params["intro"] == sheet["intro"].strip()
    assert [g["shown"] for g in params["data"]] == [g["shown"] for g in sheet["data"]]
    assert params["asks"] == {q["id"]: q["ask"] for q in sheet["questions"]}
    assert params["marks"]["F23"] == "N, within 1 %, 1 point"
    # The key of student "pl-1" with the course secret, as graphkin prints it (PrairieLearn's answer panel).
    assert correct == key_answers("pl-1")
    assert correct != {q["id"]: q["answer"]["text"] for q in exercises.key(NAME, "pl-1")["questions"]}
    assert SECRET not in json.dumps(served["first"], ensure_ascii=False)


def test_same_seed_same_data_other_seeds_other_data(served):
    assert served["same"] == [True, True]
    shown = [tuple(g["shown"] for g in data) for data in served["others"]]
    first = tuple(g["shown"] for g in served["first"]["params"]["data"])
    assert len(set(shown + [first])) >= 4  # 7 seeds over 15 × 13 × 11 values


def test_grade_key_answers_score_one(served):
    g = served["graded"]["key"]
    assert g["score"] == 1.0 and not g["format_errors"]
    assert g["partial_scores"] == {qid: {"score": 1.0, "weight": 1, "feedback": "Correct."}
                                   for qid in ("F23", "F14", "T12")}
    assert g["feedback"] == {"F23": "Correct.", "F14": "Correct.", "T12": "Correct."}


def test_grade_sign_slip_is_graphkins_partial_credit_and_sentence(served):
    g = served["graded"]["sign"]
    answers = {**key_answers("pl-1"), "T12": flip_sense(key_answers("pl-1")["T12"])}
    expected = {q["id"]: q for q in exercises.grade(NAME, "pl-1", answers, secret=SECRET)["questions"]}
    assert expected["T12"]["verdict"] == "slip" and expected["T12"]["slip"] == "sign"
    assert g["partial_scores"]["T12"] == {"score": 0.5, "weight": 1, "feedback": expected["T12"]["feedback"]}
    assert g["feedback"]["T12"].startswith("The size is right but the sense is wrong: T12 is counter-clockwise")
    assert g["score"] == pytest.approx(2.5 / 3)


def test_blank_is_left_to_pl_string_input_and_graded_missing_if_it_gets_through(served, export):
    # pl-string-input refuses a blank box itself (allow-blank is false by default): question.html must not
    # change that. Should a blank reach grade(), graphkin's verdict is "missing", 0 points.
    html = (question(export) / "question.html").read_text(encoding="utf-8")
    assert "allow-blank" not in html and "remove-spaces" not in html and "normalize-to-ascii" not in html
    g = served["graded"]["blank"]
    assert not g["format_errors"]
    assert g["partial_scores"]["F14"] == {"score": 0.0, "weight": 1, "feedback": "No answer was given for F14."}
    assert g["score"] == pytest.approx(2 / 3)


def test_unreadable_answer_is_a_format_error_not_a_grade(served):
    g = served["graded"]["unreadable"]
    # A comma that could be a decimal comma or a thousands separator is neither guessed nor graded.
    assert g["format_errors"] == {"F14": 'Could not read &quot;1,352 N&quot;: &quot;1,352&quot; could be 1.352 or '
                                         "1352: write 1.352 (a decimal point) or 1352 (no separator)."}
    # Not graded: PrairieLearn keeps what the element left (and does not count the attempt).
    assert g["partial_scores"]["F14"] == {"score": 0.0, "weight": 1}


def test_check_question_is_the_readmes_command(export):
    done = subprocess.run([sys.executable, "check_question.py", "1"], capture_output=True, text=True,
                          encoding="utf-8", timeout=120, cwd=export)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[-1] == "score 1"
    assert "F23: " + key_answers("pl-1")["F23"] + "  ->  1 x 1  Correct." in done.stdout


def test_info_json_meets_prairielearns_schema_and_uuid_is_stable(export, tmp_path):
    info = json.loads((question(export) / "info.json").read_text(encoding="utf-8"))
    jsonschema.validate(info, INFO_SCHEMA)
    assert info["type"] == "v3" and info["topic"] == "Kinetostatics" and info["singleVariant"] is False
    assert info["title"] == exercises.load(NAME).title
    assert str(uuid.UUID(info["uuid"])) == info["uuid"]
    # Another export, another secret: the same uuid (PrairieLearn keeps the question's history by it).
    again = tmp_path / "again"
    platforms.export(NAME, "prairielearn", again, secret="another-secret")
    assert json.loads((question(again) / "info.json").read_text(encoding="utf-8"))["uuid"] == info["uuid"]
    assert prairielearn.question_uuid(DRAWN) != info["uuid"]


class _Inputs(HTMLParser):
    def __init__(self):
        super().__init__()
        self.inputs, self.tags = [], []

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        if tag == "pl-string-input":
            self.inputs.append(dict(attrs))


def test_question_html_names_one_input_per_question(export, served):
    text = (question(export) / "question.html").read_text(encoding="utf-8")
    parser = _Inputs()
    parser.feed(text)
    parser.close()
    assert [i["answers-name"] for i in parser.inputs] == ["F23", "F14", "T12"]
    assert {"pl-question-panel", "pl-submission-panel"} <= set(parser.tags)
    for name in ("F23", "F14", "T12"):
        assert f"{{{{feedback.{name}}}}}" in text
    # Every {{params...}} the template names is filled in by generate().
    params = served["first"]["params"]
    for ref in set(re.findall(r"\{\{[#/^]?params\.([\w.]+)\}\}", text)):
        node = params
        for part in ref.split("."):
            node = node[part]


def test_secret_only_in_server_py(export):
    q = question(export)
    assert SECRET in (q / "server.py").read_text(encoding="utf-8")
    for f in ("question.html", "info.json", f"{NAME}.toml"):
        assert SECRET not in (q / f).read_text(encoding="utf-8"), f
    assert SECRET not in (export / "README.md").read_text(encoding="utf-8")


def test_answer_names_stay_mustache_names():
    assert prairielearn.answer_names(["F23", "peak.at", "peak_at"]) == {
        "F23": "F23", "peak_at": "peak.at", "peak_at_2": "peak_at"}


def test_drawn_exercise_serves_its_figure(tmp_path):
    out = tmp_path / "drawn"
    platforms.export(DRAWN, "prairielearn", out, secret=SECRET)
    text = (question(out, DRAWN) / "question.html").read_text(encoding="utf-8")
    assert f'<pl-figure file-name="{prairielearn.FIGURE}" type="dynamic"' in text
    served = run_driver(out, {"figure": prairielearn.FIGURE,
                              "graded": {"key": key_answers("pl-1", DRAWN)}})
    assert served["figure"]["head"] == "89504e470d0a1a0a" and served["figure"]["bytes"] > 10_000
    assert served["graded"]["key"]["score"] == 1.0


def test_html_in_an_answer_is_escaped_in_format_errors_and_feedback(served):
    """A tag a student types comes back as text: escaped once, never as markup."""
    errors = served["graded"]["html"]["format_errors"]
    assert set(errors) == {"F14", "T12"}
    assert "&lt;img src=x onerror=&quot;alert(1)&quot;&gt;" in errors["F14"]
    assert "&lt;script&gt;alert(&#x27;x&#x27;)&lt;/script&gt;" in errors["T12"]
    graded = served["graded"]["html_graded"]
    shown = json.dumps(graded, ensure_ascii=False)
    for raw in ("<img", "<script", "<b>", "<i>"):
        assert raw not in json.dumps(errors, ensure_ascii=False) and raw not in shown
    assert "&lt;b&gt;" in graded["format_errors"].get("F14", "") + graded["feedback"].get("F14", "")


def test_nothing_secret_in_what_the_student_gets_back(served):
    """params, correct answers shown after grading, scores, feedback and format errors: no secret in any."""
    for label, data in served["graded"].items():
        assert SECRET not in json.dumps(data, ensure_ascii=False), label
    assert SECRET not in json.dumps(served["first"], ensure_ascii=False)


def test_answers_naming_the_environment_or_the_server_files_bring_nothing_back(served, export):
    """Each probe is its own question's format error, quoted as typed; nothing of server.py (where the
    secret is), of the vendored graphkin or of the environment comes back."""
    server = (question(export) / "server.py").read_text(encoding="utf-8")
    lines = {line.strip() for line in server.splitlines() if len(line.strip()) >= 12}
    probes = {label: data for label, data in served["graded"].items() if label.startswith("probe")}
    assert len(probes) == -(-len(PROBES) // len(key_answers("pl-1")))
    for label, data in probes.items():
        shown = json.dumps(data, ensure_ascii=False)
        assert SECRET not in shown and MARKER not in shown, label
        for line in lines:
            if not any(line in p for p in PROBES):
                assert line not in shown, (label, line)
        assert set(data["format_errors"]) == set(key_answers("pl-1")), label
