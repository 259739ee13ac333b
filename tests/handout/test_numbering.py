"""Handouts of a static problem and of a problem whose frame is numbered 0 (issues 11 and 13).

A book that numbers the frame 0 prints F01, F03, T01 and θ01; a static
problem has no speed, no masses and no inertia loads. The handout must
follow both: the same names as ``graphkin solve --json``, the same numbers,
and no section that only a dynamic analysis has.
"""

from __future__ import annotations

import json
import math
import re

import pytest

pypdf = pytest.importorskip("pypdf")

from graphkin import handout  # noqa: E402
from graphkin.cli import main  # noqa: E402
from graphkin.handout import maths as M  # noqa: E402
from tests.analytical.test_static_and_numbering import STATIC_FOURBAR  # noqa: E402
from tests.handout.test_handout import _kinematics_blocks, _printed_results  # noqa: E402

DYNAMIC_CYCLE = (STATIC_FOURBAR.replace('analysis = "static"', "")
                 .replace('theta = "60 deg"', 'theta = { start = "0 deg", stop = "360 deg", step = "10 deg" }\n'
                                              'omega = "300 rpm"')
                 .replace('number = 3\n', 'number = 3\nmass = "1.5 kg"\n')
                 .replace('number = 1\n', 'number = 1\nmass = "1 kg"\n', 1))


def _solve_json(path, capsys) -> dict:
    assert main(["solve", str(path), "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def _pdf_text(path) -> str:
    return "\n".join(page.extract_text() for page in pypdf.PdfReader(path).pages)


def _handout(tmp_path_factory, name: str, text: str, suffix: str, detail: str = "full"):
    """A problem file written from ``text``, its key built and written as ``suffix``: (file, doc, output)."""
    folder = tmp_path_factory.mktemp(name)
    path = folder / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    doc = handout.build(str(path), detail=detail)
    out = folder / f"{name}{suffix}"
    handout.write(doc, out)
    return path, doc, out


@pytest.fixture(scope="module")
def static_key(tmp_path_factory):
    path, doc, pdf = _handout(tmp_path_factory, "static0", STATIC_FOURBAR, ".pdf")
    return path, doc, _pdf_text(pdf)


@pytest.fixture(scope="module")
def static_compact(tmp_path_factory):
    path, doc, pdf = _handout(tmp_path_factory, "static0c", STATIC_FOURBAR, ".pdf", detail="compact")
    return path, doc, _pdf_text(pdf)


def test_static_frame_zero_compact_key_names_the_frame_and_has_no_inertia(static_compact):
    _, doc, text = static_compact
    assert doc["worked"][0]["label"] == "θ01 = 60°"
    assert "Link 0 is the frame" in text and "frame (link 0)" in text and "static force analysis" in text
    for absent in ("Inertia loads", "inertia included", "inertia resultant", "Mass properties used", "Link 1 is the frame"):
        assert absent not in text, absent


def test_static_frame_zero_key_names_forces_as_the_book_does(static_key):
    _, doc, text = static_key
    assert doc["worked"][0]["label"] == "θ01 = 60°"
    assert "Link 0 is the frame" in text and "frame (link 0)" in text
    assert "static force analysis" in text
    # No inertia anywhere: no section, no d'Alembert statement, no offset h, no mass table.
    for absent in ("Inertia loads", "inertia included", "inertia resultant", "Mass properties used", "Link 1 is the frame"):
        assert absent not in text, absent
    headings = [b["text"] for b in doc["blocks"] if b["kind"] == "heading"]
    assert "Position of every link" in headings and "Kinematics" not in headings


@pytest.mark.parametrize("key", ["static_key", "static_compact"])
def test_static_frame_zero_key_carries_the_numbers_of_solve_json(key, request, capsys):
    path, doc, text = request.getfixturevalue(key)
    data = _solve_json(path, capsys)
    assert data["analysis"] == "static" and data["frame"] == 0
    entry = data["positions"][0]
    want = {}
    for name, F in entry["forces"].items():
        assert name[1] in "0123"
        want[f"|{name}|"] = M.fmt(M.size_of(F))
        i, j = (int(c) for c in re.findall(r"\d", name)[:2])
        if i < j:  # the table prints F_ij with i < j
            want[f"∠{name}"] = M.fmt_fixed(M.angle_of(F))
    assert {"F01", "F12", "F23", "F03"} <= set(entry["forces"])
    want[entry["driver"]["name"]] = M.fmt(entry["driver"]["value"])
    assert entry["driver"]["name"] == "T01"
    for name, F in entry["graphical"]["forces"].items():
        want[f"graphical |{name}|"] = M.fmt(M.size_of(F))
    for link, d in entry["links"].items():
        want[f"θ{link}"] = M.fmt_fixed(math.degrees(d["theta"]))
    assert {k: v for k, v in want.items() if v not in text} == {}
    # The names as the book writes them: in the PDF's text, or set as mathematics (F₀₁ reads as 𝐹01 there).
    maths = " ".join(M.to_text(r) for b in doc["blocks"] for r in b.get("runs", []) + b.get("lines", [])
                     + [x for row in b.get("rows", []) for cell in row for x in cell] if isinstance(r, list))
    for name in ("F01", "F03", "T01"):
        assert name in text or name in maths


def test_static_kinematics_are_positions_only(static_key):
    """The groups print each link's angle as the solver found it, and no rate at all."""
    from graphkin.handout.document import subject

    path, doc, _ = static_key
    kin = subject(str(path)).result.kinematics
    blocks = doc["blocks"]
    start = next(k for k, b in enumerate(blocks) if b["kind"] == "heading" and b["text"] == "Position of every link")
    end = next(k for k in range(start + 1, len(blocks)) if blocks[k]["kind"] == "heading" and blocks[k]["level"] <= 2)
    printed = dict(_printed_results(blocks[start + 1:end]))
    for link in kin.mechanism.moving:
        assert printed[f"θ{link}"] == M.fmt_fixed(math.degrees(kin.theta[link][0])) + "°"
        assert f"ω{link}" not in printed and f"α{link}" not in printed


@pytest.fixture(scope="module")
def dynamic_doc(tmp_path_factory):
    path, doc, md = _handout(tmp_path_factory, "dynamic0", DYNAMIC_CYCLE, ".md")
    return path, doc, md.read_text(encoding="utf-8")


def test_a_whole_cycle_with_the_frame_numbered_zero(dynamic_doc, capsys):
    path, doc, text = dynamic_doc
    assert doc["worked"][0]["label"].startswith("θ01 = ")
    # Over the cycle the extremes are placed by θ01, never by a frame-1 name.
    cycle = text[text.index("Over the whole cycle"):]
    assert "θ01 = " in cycle and "θ12" not in cycle and "T12" not in cycle
    assert "Inertia loads" in text and "Link 0 is the frame" in text
    # The worked position carries the kinematics and forces of solve --json at that angle.
    q = doc["worked"][0]["q"]
    assert main(["solve", str(path), "--at", f"{math.degrees(q)!r} deg", "--json"]) == 0
    entry = json.loads(capsys.readouterr().out)["positions"][0]
    kin_text = "\n".join(str(b) for b in _kinematics_blocks(doc))
    for link, d in entry["links"].items():
        assert M.fmt(d["omega"]) in kin_text
    for name, F in entry["forces"].items():
        assert M.fmt(M.size_of(F)) in text, name
    assert M.fmt(entry["driver"]["value"]) in text
