"""``graphkin exercise``: list, make, key, grade, for one student and for a roster; bad input in one line, exit 2."""

import csv
import io
import json
import os
import sys

import pytest

from graphkin import exercises
from graphkin.cli import main


def run(capsys, *args, stdin=None, monkeypatch=None):
    if stdin is not None:
        monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(stdin.encode()), encoding="utf-8"))
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def test_list(capsys):
    code, out, _ = run(capsys, "exercise", "list")
    assert code == 0
    assert [line.split()[0] for line in out.splitlines()] == exercises.names()


def test_make_shows_data_and_questions_but_no_answers(capsys):
    code, out, err = run(capsys, "exercise", "make", "strip_cutter_cut", "--student", "s001")
    assert code == 0 and not err
    assert "θ12 = 132°" in out and "ω = 1150 rpm" in out and "Fc = 2500 N" in out
    assert "answer" not in out
    code, out, _ = run(capsys, "exercise", "make", "strip_cutter_cut", "--student", "s001", "--json")
    assert json.loads(out) == exercises.make("strip_cutter_cut", "s001")


def test_key_and_grade_round_trip(capsys, monkeypatch, tmp_path):
    code, out, err = run(capsys, "exercise", "key", "strip_cutter_cut", "--student", "s001", "--json",
                         "--secret", "k")
    assert code == 0 and "secret" not in err
    key = json.loads(out)
    answers = {q["id"]: q["answer"]["text"] for q in key["questions"]}
    path = tmp_path / "a.json"
    path.write_text(json.dumps(answers, ensure_ascii=False), encoding="utf-8")
    code, out, _ = run(capsys, "exercise", "grade", "strip_cutter_cut", "--student", "s001", "--secret", "k",
                       "--answers", str(path), "--json")
    report = json.loads(out)
    assert code == 0 and report["score"] == report["max"] == 3
    # The same answers for another secret's data are wrong.
    code, out, _ = run(capsys, "exercise", "grade", "strip_cutter_cut", "--student", "s001", "--answers", str(path),
                       "--json")
    assert json.loads(out)["score"] < 3
    # From standard input, printed as text with the feedback.
    code, out, err = run(capsys, "exercise", "grade", "strip_cutter_cut", "--student", "s001", "--secret", "k",
                         "--answers", "-", stdin=json.dumps({"T12": key["questions"][2]["answer"]["text"]
                                                             .replace("CCW", "CW")}), monkeypatch=monkeypatch)
    assert code == 0
    assert "T12" in out and "slip (sign)" in out and "counter-clockwise" in out
    assert "F23" in out and "missing" in out


def test_no_secret_is_noted(capsys):
    code, _, err = run(capsys, "exercise", "key", "single_link", "--student", "s1")
    assert code == 0 and "no course secret" in err


def write_roster(tmp_path, n=12, name="roster.csv", header="student,name"):
    path = tmp_path / name
    lines = [header] + [f"s{i:03d},Student {i}" for i in range(n)]
    path.write_text("\ufeff" + "\n".join(lines) + "\n", encoding="utf-8")  # a spreadsheet's BOM is fine
    return path


def test_roster_make_key_grade(capsys, tmp_path):
    roster = write_roster(tmp_path)
    code, _, err = run(capsys, "exercise", "key", "gear_pair", "--roster", str(roster), "--secret", "k",
                       "-o", str(tmp_path / "keys.csv"))
    assert code == 0 and "written to" in err
    keys = list(csv.DictReader(open(tmp_path / "keys.csv", encoding="utf-8")))
    assert [r["student"] for r in keys] == [f"s{i:03d}" for i in range(12)]
    assert set(keys[0]) == {"student", "ω2", "α2", "T13", "F23", "F12", "T12"}
    with open(tmp_path / "answers.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=["student", "F23", "F12", "T12"])
        w.writeheader()
        for i, r in enumerate(keys):
            w.writerow({"student": r["student"], "F23": r["F23"], "F12": r["F12"] if i % 2 else "",
                        "T12": r["T12"]})
    code, out, _ = run(capsys, "exercise", "grade", "gear_pair", "--answers", str(tmp_path / "answers.csv"),
                       "--secret", "k")
    grades = list(csv.DictReader(io.StringIO(out)))
    assert [float(g["score"]) for g in grades] == [2.0 if i % 2 == 0 else 3.0 for i in range(12)]
    assert grades[0]["F12 verdict"] == "missing"
    code, out, _ = run(capsys, "exercise", "make", "gear_pair", "--roster", str(roster), "--json")
    assert [s["student"] for s in json.loads(out)] == [f"s{i:03d}" for i in range(12)]
    assert not [p for p in os.listdir(tmp_path) if p.endswith(".tmp")]


@pytest.mark.parametrize("setup, args, expected", [
    (None, ["exercise", "make", "no_such", "--student", "s"], "neither a catalog exercise"),
    (None, ["exercise", "make", "single_link", "--student", ""], "student id"),
    ("a.json:{not json", ["exercise", "grade", "single_link", "--student", "s", "--answers", "A"], "not valid JSON"),
    ("a.json:[1, 2]", ["exercise", "grade", "single_link", "--student", "s", "--answers", "A"], "JSON object"),
    ("a.json:\xff\xfe", ["exercise", "grade", "single_link", "--student", "s", "--answers", "A"], "is UTF-16 text"),
    ("a.json:{\"T12\": \"1 N\xb7m\"}", ["exercise", "grade", "single_link", "--student", "s", "--answers", "A"],
     "not UTF-8 text (line 1, byte 0xb7"),
    (None, ["exercise", "grade", "single_link", "--student", "s", "--answers", "missing.json"], "cannot be read"),
    ("r.csv:name\nx", ["exercise", "key", "single_link", "--roster", "A"], "'student' column"),
    ("r.csv:student\n\n,", ["exercise", "key", "single_link", "--roster", "A"], "student id is empty"),
    ("a.json:{}", ["exercise", "grade", "single_link", "--student", "s", "--answers", "A", "-o", "DIR"], "is a folder"),
    ("a.json:{}", ["exercise", "make", "single_link", "--student", "s", "-o", "FILE/x.txt"], "is a file"),
    ("bad.toml:title = 'x'\nproblem = 'single_link'\n", ["exercise", "make", "A", "--student", "s"], "questions"),
    ("r.csv:student\ns1\ns2\x00x\ns3\n", ["exercise", "key", "single_link", "--roster", "A"], "line 3: a NUL byte"),
    ("r.csv:student\ns1\ns2\ns1 \n", ["exercise", "key", "single_link", "--roster", "A"],
     "line 4: student 's1' is already on line 2"),
    ("r.csv:student\ns1\n\"s2\n", ["exercise", "key", "single_link", "--roster", "A"],
     "line 2: not readable as CSV (unexpected end of data)"),
    ("r.csv:student\ns1\n" + "x" * 101 + "\n", ["exercise", "key", "single_link", "--roster", "A"],
     "line 3: student id must be printable text of at most 100 characters"),
    ("a.csv:student,T12\ns1,1 N*m\ns1,2 N*m\n", ["exercise", "grade", "single_link", "--answers", "A"],
     "answers A: line 3: student 's1' is already on line 2"),
    ("k.json:{}", ["exercise", "grade", "single_link", "--keys", "A", "--answers", "x.csv"], "not graphkin keys"),
    (None, ["exercise", "grade", "single_link", "--answers", "missing.ipynb"], "missing.ipynb: no such file"),
])
def test_bad_input_is_one_line_and_exit_2(capsys, tmp_path, setup, args, expected):
    target = None
    if setup:
        name, text = setup.split(":", 1)
        target = tmp_path / name
        target.write_bytes(text.encode("latin-1") if ("\xff" in text or "\xb7" in text) else text.encode("utf-8"))
    (tmp_path / "DIR").mkdir()
    (tmp_path / "FILE").write_text("x")
    args = [str(target) if a == "A" else str(tmp_path / a) if a in ("DIR", "FILE/x.txt", "missing.json",
                                                                     "missing.ipynb") else a
            for a in args]
    expected = expected.replace("answers A", f"answers {target}")
    code, out, err = run(capsys, *args)
    assert code == 2, (out, err)
    lines = [l for l in err.splitlines() if not l.startswith("graphkin: note")]
    assert len(lines) == 1 and lines[0].startswith("graphkin: error:") and expected in lines[0], err
    assert "Traceback" not in err


def test_a_failed_write_is_checked_before_the_work(capsys, tmp_path, monkeypatch):
    calls = []
    monkeypatch.setattr(exercises, "variant", lambda *a, **k: calls.append(a))
    (tmp_path / "FILE").write_text("x")
    code, _, err = run(capsys, "exercise", "key", "single_link", "--student", "s", "-o", str(tmp_path / "FILE" / "k"))
    assert code == 2 and not calls


def test_make_figure_draws_what_the_student_is_given(capsys, tmp_path):
    out = tmp_path / "given.svg"
    code, _, err = run(capsys, "exercise", "make", "double_slider_graphical", "--student", "s1", "--figure", str(out))
    assert code == 0 and "figure written" in err
    svg = out.read_text(encoding="utf-8")
    assert "fbd3:R3i" in svg and "fbd3:F23" not in svg and "fbd3:F43" not in svg
    code, _, err = run(capsys, "exercise", "make", "torque_curve", "--student", "s1", "--figure", str(tmp_path / "x.jpg"))
    assert code == 2 and ".png, .svg or .pdf" in err


def test_a_5000_digit_answer_is_that_answers_problem_not_a_traceback(capsys, tmp_path):
    key = {q["id"]: q["answer"]["text"] for q in exercises.key("single_link", "s1")["questions"]}
    (tmp_path / "a.json").write_text('{"F12": 1' + "0" * 5000 + ', "T12": "' + key["T12"] + '"}', encoding="utf-8")
    code, out, err = run(capsys, "exercise", "grade", "single_link", "--student", "s1", "--answers",
                         str(tmp_path / "a.json"), "--json")
    assert code == 0 and "Traceback" not in err
    verdicts = {q["id"]: q["verdict"] for q in json.loads(out)["questions"]}
    assert verdicts == {"F12": "unreadable", "T12": "correct"}


def test_ids_are_trimmed_unknown_ids_are_reported_and_absent_ones_too(capsys, tmp_path):
    (tmp_path / "roster.csv").write_text("student\ns1\ns2\ns3\n", encoding="utf-8")
    (tmp_path / "a.csv").write_text("student,T12\n s1 ,1 N*m\ns9,2 N*m\ns2\u00a0,3 N*m\n", encoding="utf-8")
    code, out, err = run(capsys, "exercise", "grade", "single_link", "--answers", str(tmp_path / "a.csv"),
                         "--roster", str(tmp_path / "roster.csv"))
    assert code == 0
    assert [g["student"] for g in csv.DictReader(io.StringIO(out))] == ["s1", "s2"]
    assert "1 student is not on the roster and was not graded: s9 (line 3)" in err
    assert "no answers from 1 roster student: s3" in err


def _notebook(tmp_path, name, cells):
    import nbformat

    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in cells])
    path = tmp_path / name
    path.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(nb, path)
    return path


def test_grade_handed_in_notebooks_read_as_data(capsys, tmp_path):
    key = {q["id"]: q["answer"]["text"] for q in exercises.key("single_link", "s1", "k")["questions"]}
    good = _notebook(tmp_path, "good.ipynb", ['STUDENT = "s1"', f"F12 = {key['F12']!r}",
                                              "import graphkin.exercises.grading as g; g.grade_question = None",
                                              f"T12 = {key['T12']!r}"])
    sly = _notebook(tmp_path, "sly.ipynb", ['STUDENT = "s2"', "F12 = open('keys.json').read()",
                                            f"T12 = {key['T12']!r}"])
    anon = _notebook(tmp_path, "anon.ipynb", ["STUDENT = ...", f"T12 = {key['T12']!r}"])
    code, out, err = run(capsys, "exercise", "grade", "single_link", "--secret", "k", "--json", "--answers",
                         str(good), str(sly), str(anon))
    assert code == 0, err
    reports = json.loads(out)
    assert [r["student"] for r in reports] == ["s1", "s2", ""]
    assert reports[0]["score"] == 2
    f12 = reports[1]["questions"][0]
    assert f12["verdict"] == "unreadable" and "must be typed as text in quotes" in f12["feedback"]
    assert reports[2]["refused"].startswith("This notebook carries no student id")


def test_a_notebook_that_cannot_be_read_is_its_row_and_never_stops_the_class(capsys, tmp_path):
    """Issue 34: one student's notebook of 58 MB, or of JSON nested 100 000 deep, stopped the whole regrade."""
    key = {q["id"]: q["answer"]["text"] for q in exercises.key("single_link", "s1", "k")["questions"]}
    good = _notebook(tmp_path, "good.ipynb", ['STUDENT = "s1"', f"F12 = {key['F12']!r}", f"T12 = {key['T12']!r}"])
    deep = tmp_path / "deep.ipynb"
    deep.write_bytes(b'{"cells": ' + b"[" * 100_000 + b"]" * 100_000 + b"}")
    big = tmp_path / "big.ipynb"
    with open(big, "wb") as f:
        f.truncate(60_000_000)
    (tmp_path / "not.ipynb").write_bytes(b"\xff\xfe not a notebook")
    code, out, err = run(capsys, "exercise", "grade", "single_link", "--secret", "k", "--json", "--answers",
                         str(deep), str(good), str(big), str(tmp_path / "not.ipynb"))
    assert code == 0, err
    reports = json.loads(out)
    assert [(r["student"], r["score"]) for r in reports] == [("", 0.0), ("s1", 2.0), ("", 0.0), ("", 0.0)]
    assert [r.get("refused", "").split(",")[0] for r in reports] == [
        "This file is nested too deeply to be a notebook: hand in the notebook as Jupyter saved it.", "",
        "This notebook is larger than 50 MB", "This file is not UTF-8 text"]
    assert f"graphkin: note: {deep}: not graded: This file is nested too deeply" in err
    assert "Traceback" not in err


def test_grade_nbgrader_folders_checks_the_notebooks_id(capsys, tmp_path):
    key = {q["id"]: q["answer"]["text"] for q in exercises.key("single_link", "alice")["questions"]}
    for student, claimed in (("alice", "alice"), ("carol", "alice")):
        _notebook(tmp_path, f"submitted/{student}/hw/hw.ipynb", [f"STUDENT = {claimed!r}",
                                                                 f"T12 = {key['T12']!r}"])
    (tmp_path / "roster.csv").write_text("student\nalice\ncarol\n", encoding="utf-8")
    code, out, err = run(capsys, "exercise", "grade", "single_link", "--json", "--student-from", "folder",
                         "--roster", str(tmp_path / "roster.csv"), "--answers",
                         *sorted(str(p) for p in tmp_path.glob("submitted/*/hw/hw.ipynb")))
    alice, carol = json.loads(out)
    assert alice["student"] == "alice" and alice["questions"][1]["verdict"] == "correct"
    assert carol["score"] == 0 and "carries the student id 'alice' but was handed in by 'carol'" in carol["refused"]


def test_grade_with_keys_is_grade_with_the_secret(capsys, tmp_path):
    from graphkin.exercises.keys import keys_text, make_keys

    roster = ["s1", "s2", "s3"]
    (tmp_path / "k.json").write_text(keys_text(make_keys(exercises.load("gear_pair"), roster, "k")), encoding="utf-8")
    (tmp_path / "roster.csv").write_text("student\n" + "\n".join(roster) + "\n", encoding="utf-8")
    keys = {s: {q["id"]: q["answer"]["text"] for q in exercises.key("gear_pair", s, "k")["questions"]} for s in roster}
    rows = [{"student": "s1", **keys["s1"]}, {"student": "s2", **keys["s3"]}, {"student": "s3", "T12": "1 N*m"}]
    with open(tmp_path / "a.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=["student", "F23", "F12", "T12"])
        w.writeheader()
        w.writerows(rows)
    common = ["exercise", "grade", "gear_pair", "--answers", str(tmp_path / "a.csv"), "--json"]
    _, with_keys, _ = run(capsys, *common, "--keys", str(tmp_path / "k.json"))
    _, with_secret, _ = run(capsys, *common, "--secret", "k", "--roster", str(tmp_path / "roster.csv"))
    assert json.loads(with_keys) == json.loads(with_secret)
    s2 = json.loads(with_keys)[1]
    assert {q["slip"] for q in s2["questions"]} == {"other_data"} and s2["score"] == 0


def test_collect_makes_one_class_table(capsys, tmp_path):
    for i, (student, score) in enumerate((("s2", 1.5), ("s1", 3.0))):
        folder = tmp_path / "results" / f"nb{i}"
        folder.mkdir(parents=True)
        tests = [{"name": "Public Tests", "output": "..."},
                 {"name": "F23", "score": score - 1, "max_score": 1}, {"name": "T12: the torque", "score": 1.0,
                                                                      "max_score": 2}]
        output = f"Graded as student {student!r}: {score:g} / 3 points."
        (folder / "results.json").write_text(json.dumps({"tests": tests, "output": output}), encoding="utf-8")
    (tmp_path / "results" / "junk").mkdir()
    (tmp_path / "results" / "junk" / "results.json").write_text('{"tests": []}', encoding="utf-8")
    code, out, err = run(capsys, "exercise", "collect", str(tmp_path / "results"))
    rows = list(csv.DictReader(io.StringIO(out)))
    assert code == 0 and [r["student"] for r in rows] == ["s1", "s2", ""]
    assert (rows[0]["F23"], rows[0]["T12"], rows[0]["max"]) == ("2.0", "1.0", "3")
    assert "no graphkin summary" in rows[2]["error"]
    assert "graded in" not in err
    # A second notebook graded as s1 (its id typed by someone else, say): the table keeps both, with a note.
    (tmp_path / "results" / "nb9").mkdir()
    (tmp_path / "results" / "nb9" / "results.json").write_text(json.dumps(
        {"tests": [], "output": "Graded as student 's1': 0 / 3 points."}), encoding="utf-8")
    code, out, err = run(capsys, "exercise", "collect", str(tmp_path / "results"))
    assert code == 0 and [r["student"] for r in csv.DictReader(io.StringIO(out))] == ["s1", "s1", "s2", ""]
    assert "student 's1' was graded in 2 files" in err and "nb9" in err


def test_one_long_answer_in_a_class_csv_voids_nothing_else(capsys, tmp_path):
    key = {q["id"]: q["answer"]["text"] for q in exercises.key("single_link", "s1")["questions"]}
    with open(tmp_path / "a.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerows([["student", "F12", "T12"], ["s1", "y" * 1_000_000, key["T12"]], ["s2", "1 N", "1 N*m"]])
    code, out, err = run(capsys, "exercise", "grade", "single_link", "--answers", str(tmp_path / "a.csv"), "--json")
    assert code == 0, err
    s1, s2 = json.loads(out)
    verdicts = {q["id"]: q["verdict"] for q in s1["questions"]}
    assert verdicts == {"F12": "unreadable", "T12": "correct"} and s2["student"] == "s2"
    assert "too long (1000000 characters" in s1["questions"][0]["feedback"]


def test_grade_with_distance_feedback_for_a_regrade_after_the_due_date(capsys, tmp_path):
    """--feedback distance tells a wrong answer how far off it is, whatever the exercise file says (issue 34);
    the verdicts and scores are the default's. On handed-in notebooks too (graded as the platforms grade)."""
    v = exercises.variant("single_link", "s1", "k")
    e = v.expected(v.exercise.question("T12")).value
    nb = _notebook(tmp_path, "nb.ipynb", ['STUDENT = "s1"', f'T12 = "{1.3 * e:.6g} N*m"'])
    reports = {}
    for feedback in ([], ["--feedback", "distance"]):
        code, out, err = run(capsys, "exercise", "grade", "single_link", "--secret", "k", "--json", "--answers",
                             str(nb), *feedback)
        assert code == 0, err
        reports[bool(feedback)] = json.loads(out)[0]["questions"][1]
    assert (reports[False]["verdict"], reports[False]["score"]) == (reports[True]["verdict"], reports[True]["score"])
    assert "(yours is +30.0 % off)" in reports[True]["feedback"] and "% off" not in reports[False]["feedback"]
    assert "the sense (CCW or CW) is right; the size is not" in reports[False]["feedback"]


@pytest.mark.parametrize("to", ["otter", "nbgrader"])
def test_an_export_says_what_the_platform_leaves_open(capsys, tmp_path, to):
    """Issue 34: what graphkin cannot close on a platform, and that students can compute any classmate's answers,
    are said when the export is made (and in its README)."""
    pytest.importorskip("nbformat")
    from graphkin.exercises import platforms

    (tmp_path / "roster.csv").write_text("student\ns1\ns2\n", encoding="utf-8")
    code, _, err = run(capsys, "exercise", "export", "single_link", "--to", to, "-o", str(tmp_path / "x"),
                       "--roster", str(tmp_path / "roster.csv"))
    assert code == 0, err
    module = platforms.platform(to)
    readme = (tmp_path / "x" / "README.md").read_text(encoding="utf-8")
    for note in module.NOTES:
        assert f"graphkin: note: {to}: {note}\n" in err
        assert note[1:40] in readme
    assert "any student compute any classmate's answers with graphkin" in err
