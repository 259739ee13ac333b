"""What the catalog says and prints cites books, never a file a teacher or a student cannot open (issue 40, item 4).

graphkin was written from notes kept outside the repository (``seed 000_….txt``), and its reference tests
live in ``tests/``, which no install carries. A catalog file's text (its source, citation, notes, title,
questions) is printed by ``graphkin list``, at the top of every report, on the documentation's catalog page
and in the teacher's handout, so none of it may name either.
"""

from __future__ import annotations

import re

import pytest

from graphkin import catalog, exercises
from graphkin.cli import main

INTERNAL = re.compile(r"(?i)\bseeds?\s+\d|\b\d{3}_[0-9a-f]{16}\b|\.txt\b"
                      r"|(?<![\w/.])(?:tests|benchmarks|figures|lessons|docs|graphkin)/[\w./-]+")
"""The notes graphkin was written from (by name, or as "seed 000"), and a path of graphkin's repository."""

FILES = ([catalog.path(n) for n in catalog.names()] + [catalog.flywheel_path(n) for n in catalog.flywheel_names()]
         + [exercises.path(n) for n in exercises.names()])


def test_the_pattern_knows_an_internal_file_from_a_books_reference():
    internal = ["(seed 000_6a5b8db2377b79fc.txt)", "(seeds 000, 002)", "See tests/books/test_makdin.py."]
    assert [bool(INTERNAL.search(t)) for t in internal] == [True] * len(internal)
    books = ["Khurmi & Gupta, Theory of Machines, 14th ed., Example 15.9 (p. 534)", "Norton, Design of Machinery, §11.2",
             "FOSSEE Python Textbook Companion (Theory_Of_Machines/ch16.ipynb)"]
    assert [bool(INTERNAL.search(t)) for t in books] == [False] * len(books)


@pytest.mark.parametrize("path", FILES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_no_catalog_file_names_an_internal_file(path):
    text = path.read_text(encoding="utf-8")
    assert [m[0] for m in INTERNAL.finditer(text)] == []


def test_graphkin_list_cites_books_only(capsys):
    assert main(["list"]) == 0
    out = capsys.readouterr().out
    assert "Söylemez, Mechanisms, §6.4.1" in out
    assert [m[0] for m in INTERNAL.finditer(out)] == []


def test_a_report_and_an_exercise_sheet_cite_the_book(capsys):
    assert main(["solve", "strip_cutter", "--at", "140 deg"]) == 0
    header = capsys.readouterr().out.splitlines()[:3]
    assert header[1] == "source: Söylemez, Mechanisms, §6.4.1, four-bar strip-cutting example"
    assert main(["exercise", "make", "strip_cutter_cut", "--student", "s001", "--secret", "k"]) == 0
    out = capsys.readouterr().out
    assert "source: After Söylemez, Mechanisms, §6.4.1, four-bar strip-cutting example" in out
    assert [m[0] for m in INTERNAL.finditer(out)] == []
