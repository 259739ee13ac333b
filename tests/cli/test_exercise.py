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
])
def test_bad_input_is_one_line_and_exit_2(capsys, tmp_path, setup, args, expected):
    target = None
    if setup:
        name, text = setup.split(":", 1)
        target = tmp_path / name
        target.write_bytes(text.encode("latin-1") if ("\xff" in text or "\xb7" in text) else text.encode("utf-8"))
    (tmp_path / "DIR").mkdir()
    (tmp_path / "FILE").write_text("x")
    args = [str(target) if a == "A" else str(tmp_path / a) if a in ("DIR", "FILE/x.txt", "missing.json") else a
            for a in args]
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
