"""Drawn to the stated scale on paper (issue 24): lengths measured in the PDF against what the page states.

Each figure's caption states its scales ("Scale 1:10; forces 1 mm = 20 N."). The PDF's drawing operators are
read (``pdfgeometry``) and each force arrow is measured as printed, tail to the point of its ink, and each
link drawn as a bar end to end: times the stated scale, every one must be a force of ``graphkin solve --json``
(or a link's true length) to 1 %. A figure drawn for one size and placed at another fails: every length on the
page changes with it.
"""

from __future__ import annotations

import io
import json
import math
import re
from contextlib import redirect_stderr, redirect_stdout

import numpy as np
import pytest

pypdf = pytest.importorskip("pypdf")

from graphkin import catalog, handout  # noqa: E402
from graphkin.draw import style  # noqa: E402
from tests.handout.pdfgeometry import MM, arrows, bars, figures  # noqa: E402

# Typesets PDFs and measures them (every catalog key, at print size): make test runs it, make check does not.
pytestmark = pytest.mark.slow

FORCE_COLOURS = [tuple(int(c[k:k + 2], 16) / 255 for k in (1, 3, 5)) for c in (style.BLUE, style.VERMILLION, style.PURPLE)]
INK = tuple(int(style.STYLE.ink[k:k + 2], 16) / 255 for k in (1, 3, 5))
CASES = {
    "double_slider": dict(source="double_slider"),
    "strip_cutter_140": dict(source="strip_cutter", at="140 deg"),
    "strip_cutter_140_full": dict(source="strip_cutter", at="140 deg", detail="full"),
    "strip_cutter_140_blank": dict(source="strip_cutter", at="140 deg", version="blank"),
    "slider_crank_friction": dict(source="slider_crank_friction"),
}


def _solve_json(name: str, at: str | None) -> dict:
    from graphkin import cli

    out = io.StringIO()
    with redirect_stdout(out), redirect_stderr(io.StringIO()):
        assert cli.main(["solve", name, "--json"] + (["--at", at] if at else [])) == 0
    return json.loads(out.getvalue())


@pytest.fixture(scope="module")
def printed(tmp_path_factory):
    folder = tmp_path_factory.mktemp("scale")
    out = {}
    for case, kw in CASES.items():
        kw = dict(kw)
        name, at = kw.pop("source"), kw.get("at")
        doc = handout.build(name, **kw)
        path = folder / f"{case}.pdf"
        handout.write(doc, path)
        out[case] = {"doc": doc, "path": path, "json": _solve_json(name, at), "problem": catalog.load(name)}
    return out


def _forces(entry: dict) -> list[float]:
    """Every force of the position [N]: joint forces, inertia forces, external loads, the driver's force, and
    those of the graphical route (sub-problems, resultants, polygon sides)."""
    out = [math.hypot(*F) for F in entry["forces"].values()]
    out += [math.hypot(*d["inertia_force"]) for d in entry["links"].values()]
    out += [math.hypot(*ld["force"]) for ld in entry["loads"] if "force" in ld]
    if "vector" in entry["driver"]:
        out.append(math.hypot(*entry["driver"]["vector"]))
    g = entry["graphical"]
    for step in g["steps"]:
        out += [math.hypot(*a["vector"]) for a in step.get("polygon", [])]
        out += [math.hypot(*v) for v in step.get("values", {}).values() if isinstance(v, list) and len(v) == 2]
    for sp in g.get("subproblems", []):
        out += [math.hypot(*F) for F in sp["forces"].values()]
    return [f for f in out if f > 0]


def _lengths(problem) -> list[float]:
    """True distances [mm] between the points of each moving link: what a link drawn as a bar may measure."""
    mech = problem.mechanism
    out = []
    for n in mech.moving:
        pts = list(mech.link(n).points.values())
        out += [math.dist(p, q) * 1e3 for k, p in enumerate(pts) for q in pts[k + 1:]]
    return out


def _figures(p: dict) -> list:
    """The figures of a case's PDF (:func:`tests.handout.pdfgeometry.figures`), read from the page once: the force
    arrows' test and the bars' read the same pages."""
    if "figures" not in p:
        p["figures"] = figures(p["path"])
    return p["figures"]


def _matches(value: float, wanted: list[float], rel: float = 0.01) -> bool:
    return any(abs(value - w) <= rel * w for w in wanted)


@pytest.mark.parametrize("case", CASES)
def test_every_force_arrow_prints_at_the_stated_force_scale(printed, case):
    p = printed[case]
    entry = p["json"]["positions"][p["doc"]["worked"][0]["index"]]
    wanted = _forces(entry)
    stated = [f for f in _figures(p) if f.X is not None]
    assert stated, "no figure states a force scale"
    measured = 0
    for fig in stated:
        lengths = arrows(fig, FORCE_COLOURS)
        assert lengths, f"figure {fig.number} states {fig.X} N per mm but has no force arrow"
        wrong = [(round(mm, 2), round(mm * fig.X, 1)) for mm in lengths if not _matches(mm * fig.X, wanted)]
        assert wrong == [], f"figure {fig.number} ({fig.caption[:60]}…): printed mm, and N at its scale"
        measured += len(lengths)
    assert measured >= 4  # a worksheet's known loads, at least


def test_the_free_bodies_show_every_force_at_one_scale(printed):
    """Every force on every link of the double slider, each measured once on the page, at the one stated scale."""
    p = printed["double_slider"]
    entry = p["json"]["positions"][0]
    fig = next(f for f in _figures(p) if f.caption.split(". ", 1)[1].startswith("Every force on each"))
    want = []
    for link in entry["links"]:
        want += [math.hypot(*F) for name, F in entry["forces"].items() if name[2] == link]
        want += [math.hypot(*entry["links"][link]["inertia_force"])]
    want.append(math.hypot(*entry["driver"]["vector"]))
    want = sorted(w for w in want if w > 0)
    got = sorted(mm * fig.X for mm in arrows(fig, FORCE_COLOURS))
    assert len(got) == len(want)
    assert np.allclose(got, want, rtol=0.01)


@pytest.mark.parametrize("case", CASES)
def test_every_link_drawn_as_a_bar_prints_at_the_stated_length_scale(printed, case):
    p = printed[case]
    wanted = _lengths(p["problem"])
    stated = [f for f in _figures(p) if f.k is not None]
    assert stated, "no figure states a length scale"
    seen = 0
    for fig in stated:
        # A link too short to read at the figure's scale is enlarged, at a scale its caption states too.
        ks = [fig.k] + [float(b) / float(a) for a, b in re.findall(r"at (\d+(?:\.\d+)?):(\d+(?:\.\d+)?), enlarged",
                                                                   fig.caption)]
        for mm in bars(fig, style.STYLE.link_lw, INK):
            assert any(_matches(mm * k, wanted) for k in ks), (fig.number, round(mm, 2), round(mm * fig.k, 1))
            seen += 1
    assert seen >= 1


@pytest.mark.parametrize("case", CASES)
def test_every_drawing_states_its_scales_and_fits_the_page(printed, case):
    """Each drawing of the mechanism or of forces states its length scale and (with forces) its force scale, in
    its caption, and is no wider than the text (so it is printed at its own size)."""
    from graphkin.graphical.paper import TEXT_WIDTH

    p = printed[case]
    for b in p["doc"]["blocks"]:
        if b["kind"] != "figure" or b["pictures"][0].key.startswith(("convention", "torque", "energy", "jfi")):
            continue
        assert all(pic.natural for pic in b["pictures"]), b["caption"]
        assert "Scale 1:" in b["caption"] or "scale 1:" in b["caption"] or "1 mm = " in b["caption"], b["caption"]
        assert sum(pic.size()[0] for pic in b["pictures"]) <= TEXT_WIDTH * MM, b["caption"]


def test_the_test_catches_a_figure_shrunk_to_the_text_width(printed, tmp_path, monkeypatch):
    """Placed at 90 % of its size, as handouts used to place their figures, the arrows no longer match."""
    from graphkin.handout import typst as T

    source = T.source
    monkeypatch.setattr(T, "source", lambda d, **kw: source(d, **kw).replace("pt, alt:", "pt * 0.9, alt:"))
    p = printed["double_slider"]
    path = tmp_path / "shrunk.pdf"
    path.write_bytes(T.render(p["doc"]))
    entry = p["json"]["positions"][0]
    fig = next(f for f in figures(path) if f.X is not None)
    assert not all(_matches(mm * fig.X, _forces(entry)) for mm in arrows(fig, FORCE_COLOURS))


@pytest.mark.parametrize("case, pages", [("double_slider", 3), ("strip_cutter_140", 4)])
def test_a_compact_key_is_as_long_as_a_textbook_s(printed, case, pages):
    assert len(pypdf.PdfReader(printed[case]["path"]).pages) <= pages


LABEL_CASES = {
    "strip_cutter": dict(),  # a whole cycle, compact: the torque curve, energy and joint-force index plots too
    "strip_cutter_140_full": dict(at="140 deg", detail="full"),  # every step, the sign convention
    "strip_cutter_140_blank": dict(at="140 deg", version="blank"),
}


@pytest.mark.parametrize("case", LABEL_CASES)
def test_every_label_prints_at_8_pt_or_more(case, monkeypatch):
    """Every picture prints at its own size (a drawing at its scales, a plot at the size it was drawn), so a
    label's font size is its printed size: none below 8 pt. A figure shrunk to a share of the text width, as the
    cycle's plots were (labels at 5–6 pt), is not printed at its own size and fails the first check."""
    from matplotlib.text import Text

    from graphkin.handout import sections

    # The sign convention is drawn once a process and kept as SVG: a fresh one, to read its labels.
    monkeypatch.setattr(sections, "_CONVENTION", [])
    doc = handout.build("strip_cutter", **LABEL_CASES[case])
    pictures = [p for b in doc["blocks"] if b["kind"] == "figure" for p in b["pictures"]]
    assert pictures
    small = []
    for pic in pictures:
        assert pic.natural, pic.key
        texts = [t for t in pic.figure().findobj(Text) if t.get_visible() and t.get_text().strip()]
        assert texts, pic.key
        small += [(pic.key, t.get_text(), t.get_fontsize()) for t in texts if t.get_fontsize() < 8.0]
    assert small == []


@pytest.mark.parametrize("name", catalog.names())
def test_every_picture_of_a_compact_key_fits_the_page(name):
    """Printed at its own size, a picture must fit the text block: the gear pair's free bodies, sized from the
    gears' centres alone, were drawn at 5:1 and ran off two pages."""
    from graphkin.graphical.paper import PAGE_HEIGHT, TEXT_WIDTH

    room = (TEXT_WIDTH * MM, (PAGE_HEIGHT - 18.0 - 20.0 - 15.0) * MM)  # the text block less a caption's lines
    doc = handout.build(name)
    sizes = [(p.key, p.size()) for b in doc["blocks"] if b["kind"] == "figure" for p in b["pictures"]]
    assert sizes
    assert [(key, w / MM, h / MM) for key, (w, h) in sizes if w > room[0] or h > room[1]] == []
