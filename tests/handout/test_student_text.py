"""What a student reads cites its source in one line and carries no catalog provenance (issue 24, item 4).

Every catalog problem's compact key and worksheet, and every catalog exercise's sheet and key, read as the
text the renderers print (the blocks' runs, tables, captions and equations; no PDF needed): no seed file, no
"NOT FROM THE SOURCE", no web address or companion the catalog read the book in, no raw file key
(``pressure_angle``, ``strip_cutter``), no unrounded number (``35342.917353``) and no e-notation. The teacher's
full key keeps the problem's notes on its source.
"""

from __future__ import annotations

import re

import pytest

from graphkin import catalog, exercises, handout
from graphkin.handout import maths as M

SECRET = "course-secret"
PROVENANCE = re.compile(r"(?i)\bseeds?\b|NOT FROM THE SOURCE|scribd|github|\.txt\b|FOSSEE|companion|catalog file")
FILE_KEY = re.compile(r"\b[a-z]+_[a-z]+\w*\b")
UNDERSCORE = re.compile(r"[A-Za-zΣ]_[A-Za-z]")
POWER = re.compile(r"(?<![\w.])\d+(?:\.\d+)?[eE][-−+]?\d")
NUMBER = re.compile(r"(?<![\w.])\d+(?:\.\d+)?(?![\w.])")


def _runs(runs) -> str:
    return "".join(r if isinstance(r, str) else M.to_text(r) for r in runs)


def lines(doc: dict) -> list[str]:
    """Everything a handout prints, as lines of text (the pictures' own labels are drawn from the same names)."""
    out = [doc["title"], doc["subtitle"], doc["source"]]
    for b in doc["blocks"]:
        kind = b["kind"]
        if kind == "heading":
            out.append(b["text"])
        elif kind == "text":
            out.append(_runs(b["runs"]))
        elif kind == "list":
            out += [_runs(item) for item in b["items"]]
        elif kind == "table":
            out += [_runs(h) for h in b["header"]] + [_runs(c) for row in b["rows"] for c in row]
            out.append(b.get("caption") or "")
        elif kind == "equation":
            out += [M.to_text(line) for line in b["lines"]]
        elif kind == "figure":
            out.append(b["caption"])
        elif kind == "space":
            out.append(b["label"] + (M.to_text(b["math"]) if b.get("math") else ""))
    return out


def _significant(number: str) -> int:
    return len(number.replace(".", "").lstrip("0"))


def faults(text_lines) -> list[tuple[str, str]]:
    """(what, the line) for each fault a student's page must not have."""
    out = []
    for line in text_lines:
        for what, pattern in (("provenance", PROVENANCE), ("file key", FILE_KEY), ("e-notation", POWER)):
            if pattern.search(line):
                out.append((what, line[:160]))
        # An unrounded number: more than 6 significant figures (4 are printed; a position may need 6).
        if any(_significant(m[0]) > 6 for m in NUMBER.finditer(line)):
            out.append(("unrounded", line[:160]))
    return out


PROBLEMS = [(name, version) for name in catalog.names() for version in ("key", "blank")]
EXERCISES = [(name, version) for name in exercises.names() for version in ("sheet", "key")]


@pytest.mark.parametrize("name, version", PROBLEMS)
def test_a_problem_s_compact_key_and_worksheet_carry_no_provenance(name, version):
    doc = handout.build(name, version=version)
    assert faults(lines(doc)) == []
    assert "\n" not in doc["source"] and doc["source"]
    # Nor a symbol's underscore in plain text (T_avg, I_G): the handout sets those as mathematics.
    assert [line for line in lines(doc) if UNDERSCORE.search(line)] == []


@pytest.mark.parametrize("name, version", EXERCISES)
def test_an_exercise_s_sheet_and_key_carry_no_provenance(name, version):
    doc = handout.build(name, student="alice", secret=SECRET, version=version)
    assert faults(lines(doc)) == []
    assert "\n" not in doc["source"] and doc["source"]


def test_the_check_catches_what_the_catalog_holds_for_the_teacher():
    """The catalog's own source lines and notes (what students were shown before) fail the check; the teacher's
    full key still carries the notes."""
    assert [w for w, _ in faults([catalog.load("gas_engine_khurmi").source])] == ["provenance"]
    assert "unrounded" in [w for w, _ in faults(["F = 35342.917353 N"])]
    assert "file key" in [w for w, _ in faults(["radii = (100 mm, 40 mm); pressure_angle = 20°"])]
    assert "e-notation" in [w for w, _ in faults(["T2i = −5.871e-05 N·m"])]
    shaper = catalog.load("shaper_six_bar")
    assert faults(shaper.notes.split("\n\n")) != []
    full = lines(handout.build("shaper_six_bar", detail="full"))
    assert any(" ".join(shaper.notes.split()[:12]) in line for line in full)
