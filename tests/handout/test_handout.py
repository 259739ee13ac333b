"""Worked-solution handouts (issue 11): the numbers of ``solve --json`` in every format, figures, layout, errors.

The handouts are built once per module (a few seconds: every figure is
drawn) and each test reads the rendered PDF, HTML or Markdown.
"""

from __future__ import annotations

import html.parser
import io
import json
import math
import os
import re
import subprocess
import sys
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import numpy as np
import pytest

pypdf = pytest.importorskip("pypdf")
pdfium = pytest.importorskip("pypdfium2")

from graphkin import handout  # noqa: E402
from graphkin.handout import maths as M  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
BASELINES = ROOT / "baseline"
PROBLEMS = ("double_slider", "strip_cutter")


# -- the handouts and the JSON they must agree with ------------------------------------------------
def _main(argv) -> tuple[int, str, str]:
    """``graphkin ARGV`` in this process: exit code, stdout, stderr."""
    from graphkin import cli

    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        code = cli.main(argv)
    return code, out.getvalue(), err.getvalue()


DETAILS = ("compact", "full")


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    """Each problem's key, compact (the default) and full: the document, its PDF, HTML and Markdown, and the
    ``solve --json`` of the problem. ``built[name]`` is the compact key, ``built[name, "full"]`` the full one."""
    folder = tmp_path_factory.mktemp("handouts")
    out = {}
    for name in PROBLEMS:
        code, stdout, _ = _main(["solve", name, "--json"])
        assert code == 0
        data = json.loads(stdout)
        for detail in DETAILS:
            doc = handout.build(name, detail=detail)
            paths = {fmt: folder / f"{name}_{detail}.{fmt}" for fmt in ("pdf", "html", "md")}
            for p in paths.values():
                handout.write(doc, p)
            entry = {"doc": doc, "paths": paths, "json": data,
                     "pdf_text": "\n".join(page.extract_text() for page in pypdf.PdfReader(paths["pdf"]).pages)}
            out[name, detail] = entry
            if detail == "compact":
                out[name] = entry
    return out


def _expected(entry: dict) -> dict[str, str]:
    """What the handout must print for one position of ``solve --json``, formatted as the handout formats.

    Keys say where a number comes from (for the failure message); the values
    are derived from the JSON's SI values with the handout's own formatter.
    """
    want = {}
    for link, d in entry["links"].items():
        want[f"θ{link}"] = M.fmt_fixed(math.degrees(d["theta"]))
        want[f"ω{link}"] = M.fmt(d["omega"])
        want[f"α{link}"] = M.fmt(d["alpha"])
        if any(d["inertia_force"]):
            want[f"|a_G{link}|"] = M.fmt(M.size_of(d["a_G"]))
            want[f"∠a_G{link}"] = M.fmt_fixed(M.angle_of(d["a_G"]))
            want[f"|F{link}i|"] = M.fmt(M.size_of(d["inertia_force"]))
            want[f"∠F{link}i"] = M.fmt_fixed(M.angle_of(d["inertia_force"]))
        if d["inertia_torque"]:
            want[f"T{link}i"] = M.fmt(d["inertia_torque"])
        if d["h"] is not None:
            want[f"h{link} [mm]"] = M.fmt(d["h"] * 1e3)
    for name, F in entry["forces"].items():
        want[f"|{name}|"] = M.fmt(M.size_of(F))
        i, j = (int(c) for c in re.findall(r"\d", name)[:2])
        if i < j:  # the table prints F_ij with i < j; F_ji = −F_ij
            want[f"∠{name}"] = M.fmt_fixed(M.angle_of(F))
            for axis, value in zip("xy", F):
                if abs(value) > 1e-9 * M.size_of(F):
                    want[f"{name}{axis}"] = M.fmt(value)
    want[entry["driver"]["name"]] = M.fmt(entry["driver"]["value"])
    g = entry["graphical"]
    for name, F in g["forces"].items():
        want[f"graphical |{name}|"] = M.fmt(M.size_of(F))
    return want


def _worked(b) -> dict:
    """The ``solve --json`` position the handout works out."""
    return b["json"]["positions"][b["doc"]["worked"][0]["index"]]


def _missing(text: str, want: dict) -> dict:
    return {k: v for k, v in want.items() if v not in text}


@pytest.mark.parametrize("detail", DETAILS)
@pytest.mark.parametrize("name", PROBLEMS)
def test_pdf_text_carries_the_numbers_of_solve_json(built, name, detail):
    b = built[name, detail]
    want = _expected(_worked(b))
    assert len(want) > 20
    assert _missing(b["pdf_text"], want) == {}


def test_the_worked_position_of_a_cycle_is_where_the_driving_effort_peaks(built):
    b = built["strip_cutter"]
    efforts = [abs(p["driver"]["value"]) if p["valid"] else -1 for p in b["json"]["positions"]]
    assert b["doc"]["worked"][0]["index"] == int(np.argmax(efforts))
    assert len(built["double_slider"]["doc"]["worked"]) == 1 and built["double_slider"]["doc"]["worked"][0]["index"] == 0


def test_the_whole_cycle_carries_the_numbers_of_cycle_json(built):
    from graphkin import catalog
    from graphkin.cycle import sweep
    from graphkin.report import cycle_data

    data = cycle_data(sweep(catalog.load("strip_cutter")), handout.document.DEFAULT_CS)
    fw, jfi, e = data["flywheel"], data["joint_force_index"], data["effort"]
    want = {"E": M.fmt(fw["E"]), "I_s": M.fmt(fw["I_s"]), "T_avg": M.fmt(fw["T_avg"]),
            "peak": M.fmt(e["max"]["value"]), "lowest": M.fmt(e["min"]["value"]),
            "disk radius": M.fmt(fw["disk"]["radius"] * 1e3), "JFI": M.fmt(jfi["peak"]["value"])}
    want |= {f"ΔE{k}": M.fmt(a) for k, a in enumerate(fw["areas"])}
    want |= {f"peak {k}": M.fmt(v["peak"]["value"]) for k, v in data["forces"].items()}
    for detail in DETAILS:
        assert _missing(built["strip_cutter", detail]["pdf_text"], want) == {}


@pytest.mark.parametrize("detail", DETAILS)
@pytest.mark.parametrize("name", PROBLEMS)
def test_every_figure_named_in_the_text_is_present(built, name, detail):
    b = built[name, detail]
    text = b["pdf_text"]
    figures = [blk for blk in b["doc"]["blocks"] if blk["kind"] == "figure"]
    named = set(re.findall(r"Figure (\d+)", text))
    captions = set(re.findall(r"Figure (\d+)\. ", text))
    assert named and named <= captions
    assert captions == {str(k) for k in range(1, len(figures) + 1)}
    # Each picture is one vector drawing in the PDF: typst turns an SVG into a form XObject.
    forms = 0
    for page in pypdf.PdfReader(b["paths"]["pdf"]).pages:
        xobjects = page["/Resources"].get("/XObject", {})
        forms += sum(1 for x in xobjects.values() if x.get_object().get("/Subtype") == "/Form")
    pictures = sum(len(blk["pictures"]) for blk in figures)
    assert forms >= pictures
    # No raster image: the figures stay vector.
    assert not any(x.get_object().get("/Subtype") == "/Image" for page in pypdf.PdfReader(b["paths"]["pdf"]).pages
                   for x in page["/Resources"].get("/XObject", {}).values())


# -- the kinematics, group by group, as the solver solved it -------------------------------------------------
class _Collect:
    """Collects what :func:`graphkin.handout.loops.groups` writes, as the handout's document would."""

    def __init__(self):
        self.blocks = []

    def heading(self, level, text):
        self.blocks.append({"kind": "heading", "level": level, "text": text})

    def text(self, *runs):
        self.blocks.append({"kind": "text", "runs": list(runs)})

    def equation(self, *lines, small=False):
        self.blocks.append({"kind": "equation", "lines": list(lines)})


def _kinematics_blocks(doc: dict) -> list:
    """The blocks of the key's section "Kinematics" (up to the next heading of its level)."""
    blocks = doc["blocks"]
    start = next(k for k, b in enumerate(blocks) if b["kind"] == "heading" and b["text"] == "Kinematics")
    end = next(k for k in range(start + 1, len(blocks)) if blocks[k]["kind"] == "heading" and blocks[k]["level"] <= 2)
    return blocks[start + 1:end]


def _printed_results(blocks) -> list[tuple[str, str]]:
    """Every ``symbol = … = value`` the equations print: (symbol, value) as text.

    A line that starts with "=" continues the one before; results on one
    line are separated by semicolons (:mod:`graphkin.handout.loops`).
    """
    out = []
    for b in blocks:
        if b["kind"] != "equation":
            continue
        texts = []
        for line in b["lines"]:
            t = M.to_text(line)
            if t.startswith("= ") and texts:
                texts[-1] += " " + t
            else:
                texts.append(t)
        for t in texts:
            for part in t.split(" ; "):
                symbol, _, _ = part.partition(" = ")
                out.append((symbol, part.rsplit(" = ", 1)[-1]))
    return out


class _Wanted(dict):
    def __init__(self):
        super().__init__()
        self.rounding = {}


def _solver_values(kin, i: int) -> tuple[dict, dict]:
    """What the solver found at position ``i``, printed as the handout prints it.

    θ, ω, α of every link; each sliding pair's relative speed and acceleration
    along its guide, both ways round (v4/1, a4/1); and, by point name, the
    position of that point on every link that carries it. A sliding
    acceleration recomputed here from the links' motion may differ from the
    solver's by rounding where it is zero (1e-17 m/s² against the solver's 0):
    ``want.rounding`` keeps, for those, the value and the acceleration it is
    rounding beside.
    """
    from graphkin.model import Prismatic

    mech = kin.mechanism
    want = _Wanted()
    for link in mech.moving:
        want[f"θ{link}"] = M.fmt_fixed(math.degrees(kin.theta[link][i])) + "°"
        want[f"ω{link}"] = M.fmt(kin.omega[link][i]) + " rad/s"
        want[f"α{link}"] = M.fmt(kin.alpha[link][i]) + " rad/s²"
    for joint in mech.joints:
        if not isinstance(joint, Prismatic):
            continue
        u = kin.z_guide(joint)[i]
        X = kin.z(joint.slider, joint.point)[i]

        def acc(link):  # the acceleration of the point of ``link`` at the slider point
            return kin.a_O[link][i] + (1j * kin.alpha[link][i] - kin.omega[link][i] ** 2) * (X - kin.O[link][i])

        for on, other in ((joint.slider, joint.guide), (joint.guide, joint.slider)):
            want[f"v{on}/{other}"] = M.fmt(kin.slide_rate(joint, on)[i]) + " m/s"
            a = acc(on) - acc(other)
            along = a.real * u.real + a.imag * u.imag
            want[f"a{on}/{other}"] = M.fmt(along) + " m/s²"
            want.rounding[f"a{on}/{other}"] = (along, max(abs(acc(link)) for link in mech.moving))
    positions = {}
    for body in mech.links:
        for name in body.points:
            z = kin.z(body.number, name)[i] * 1e3
            positions.setdefault(f"r{name}", set()).add(M.to_text(M.pair((z.real, z.imag), "mm")))
    return want, positions


def _check_groups(kin, i: int, blocks) -> set:
    """Assert every result the equations print is the solver's, to the printed digits; returns the symbols seen."""
    want, positions = _solver_values(kin, i)
    seen, wrong = set(), []
    for symbol, value in _printed_results(blocks):
        if symbol in want:
            seen.add(symbol)
            raw, scale = want.rounding.get(symbol, (None, 0.0))
            if value != want[symbol] and not (value.startswith("0 ") and abs(raw or 0.0) <= 1e-12 * scale):
                wrong.append((symbol, value, want[symbol]))
        elif symbol in positions:
            seen.add(symbol)
            if value not in positions[symbol]:
                wrong.append((symbol, value, positions[symbol]))
    assert wrong == []
    # Each link's angle, angular velocity and angular acceleration is a result of some group.
    assert {f"{q}{link}" for link in kin.mechanism.moving for q in "θωα"} <= seen
    return seen


@pytest.mark.parametrize("name, at", [("double_slider", None), ("strip_cutter", None),
                                      ("slider_crank_friction", "60 deg")])
def test_each_group_s_equations_print_what_the_solver_computed(name, at):
    doc = handout.build(name, at=at, detail="full")
    s = handout.document.subject(name, at=at)
    kin, i = s.result.kinematics, doc["worked"][0]["index"]
    blocks = _kinematics_blocks(doc)
    seen = _check_groups(kin, i, blocks)
    # One section per group, in the order the solver locates them.
    headings = [b["text"] for b in blocks if b["kind"] == "heading"]
    assert len(headings) == len(kin.groups)
    for heading, g in zip(headings, kin.groups):
        assert all(f"{n}" in heading for n in g.links)
    dyad = kin.groups[1]
    assert dyad.type in headings[1]
    # The dyad's middle joint is located, and a sliding pair's rates are printed.
    assert f"r{dyad.J2.point}" in seen
    if dyad.type == "RRP":
        assert {f"v{dyad.k}/{dyad.b}", f"a{dyad.k}/{dyad.b}"} <= seen


def test_the_double_slider_s_kinematics_are_the_book_s():
    """Söylemez's double slider: ω13 = 4.364 rad/s, α13 = 8.312 rad/s², B at y = 458.258 mm (the book rounds)."""
    printed = dict(_printed_results(_kinematics_blocks(handout.build("double_slider", detail="full"))))
    assert printed["ω3"] == "4.364 rad/s" and printed["rB"] == "(0, 458.3) mm"
    assert float(printed["α3"].split()[0]) == pytest.approx(8.312, abs=1.5e-3)


@pytest.mark.parametrize("name", PROBLEMS)
def test_pdf_text_carries_each_group_s_results(built, name):
    b = built[name, "full"]
    numbers = {n for _, value in _printed_results(_kinematics_blocks(b["doc"]))
               for n in re.findall(r"−?[0-9][0-9.]*(?:e−?[0-9]+)?", value)}
    assert len(numbers) > 10
    assert {n for n in numbers if n not in b["pdf_text"]} == set()


def _families():
    from tests.strategies import families

    return families


@pytest.mark.parametrize("family", sorted(_families()))
def test_every_dyad_type_prints_the_solver_s_numbers(family):
    """Random linkages of every family (RRR, RRP, RPR, RPP, gears, six-bars): each group's results are the solver's."""
    from hypothesis import HealthCheck, given, settings
    from hypothesis import strategies as st

    from graphkin.handout.loops import groups
    from graphkin.kinematics import solve_kinematics

    @settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
    @given(data=st.data())
    def check(data):
        mech, q, q_dot, q_ddot = data.draw(_families()[family])
        kin = solve_kinematics(mech, q, q_dot, q_ddot)
        for i in np.flatnonzero(kin.valid):
            out = _Collect()
            groups(out, kin, int(i))
            _check_groups(kin, int(i), out.blocks)

    check()


def test_a_prp_dyad_prints_the_solver_s_numbers():
    """No family has a PRP dyad: slider 2 driven along x carries a slot for block 3, pinned to slider 4 on a guide."""
    from graphkin.handout.loops import groups
    from graphkin.kinematics import solve_kinematics
    from graphkin.model import Driver, Link, Mechanism, Prismatic, Revolute

    links = [Link(1, {"O": (0.0, 0.0), "S": (0.1, 0.3)}),
             Link(2, {"P": (0.0, 0.0), "T": (0.05, 0.02)}, mass=1.0, G=(0.0, 0.0), I_G=0.01),
             Link(3, {"Q": (0.0, 0.0), "C": (0.1, 0.05)}, mass=1.0, G=(0.02, 0.0), I_G=0.01),
             Link(4, {"C": (0.0, 0.0), "R": (0.0, 0.04)}, mass=1.0, G=(0.0, 0.0), I_G=0.01)]
    joints = [Prismatic(1, 2, "P", "O", 0.0, 0.0), Prismatic(2, 3, "Q", "T", math.radians(60), math.radians(10)),
              Revolute((3, 4), "C"), Prismatic(1, 4, "R", "S", math.radians(100), math.radians(20))]
    kin = solve_kinematics(Mechanism(links, joints, Driver(2, "slider")), [0.05, 0.1], [1.0, -0.5], [2.0, 0.7])
    assert [g.type for g in kin.groups[1:]] == ["PRP"] and kin.valid.all()
    for i in range(kin.n):
        out = _Collect()
        groups(out, kin, i)
        seen = _check_groups(kin, i, out.blocks)
        assert {"rC", "v3/2", "v4/1", "a3/2", "a4/1"} <= seen
    # The same equations typeset by each renderer: typst compiles them and the PDF shows the results.
    doc = {"title": "PRP", "subtitle": "", "source": "", "blocks": out.blocks}
    text = "".join(p.extract_text() for p in pypdf.PdfReader(io.BytesIO(handout.render(doc, "pdf")[0])).pages)
    want, positions = _solver_values(kin, kin.n - 1)
    numbers = {n for symbol, value in _printed_results(out.blocks) if symbol in want or symbol in positions
               for n in re.findall(r"−?[0-9][0-9.]*", value)}
    assert len(numbers) > 5 and {n for n in numbers if n not in text} == set()
    assert "<msqrt>" not in handout.render(doc, "html")[0].decode() and "$$" in handout.render(doc, "md")[0].decode()


def test_a_planet_on_a_rocker_is_written_from_the_angles_it_was_found_from():
    """The planet of tests/kinematics (test_a_planet_on_a_rocker_turns_without_a_jump), where its rocker stands
    beyond ±180°: the key's θ5 = θ4 + ρ(θ1 − θ4) is written with the rocker's angle on the solver's branch, so its
    result is the planet's angle the solver found and the drawing shows (issue 35)."""
    from graphkin.handout.loops import groups
    from graphkin.kinematics import solve_kinematics
    from tests.strategies import planet_on_a_rocker

    mech = planet_on_a_rocker()
    kin = solve_kinematics(mech, np.radians([100.0, 160.0, 250.0, 330.0]), 1.0, 0.0)
    assert np.ptp(np.sign(kin.theta[4])) == 2  # the rocker stands on both sides of ±180°
    for i in range(kin.n):
        out = _Collect()
        groups(out, kin, i)
        printed = dict(_printed_results(out.blocks))
        assert printed["θ5"] == M.fmt_fixed(math.degrees(kin.theta[5][i])) + "°"


# -- page layout ------------------------------------------------------------------------------------------------
def _heading_and_figure_pages(doc: dict, pdf) -> list[tuple[str, int, int]]:
    """For each heading whose section opens with a figure (only paragraphs between): its page and the figure's."""
    pages = [p.extract_text() for p in pypdf.PdfReader(io.BytesIO(pdf) if isinstance(pdf, bytes) else pdf).pages]
    lines = [{line.strip() for line in p.splitlines()} for p in pages]
    blocks = doc["blocks"]
    out = []
    for k, b in enumerate(blocks):
        if b["kind"] != "heading":
            continue
        nxt = next((n for n in range(k + 1, len(blocks)) if blocks[n]["kind"] != "text"), None)
        if nxt is not None and blocks[nxt]["kind"] == "figure":
            heading = next(p for p, ls in enumerate(lines) if b["text"] in ls)
            caption = next(p for p, text in enumerate(pages) if f"{blocks[nxt]['label']}. " in text)
            out.append((b["text"], heading, caption))
    return out


@pytest.mark.parametrize("detail", DETAILS)
@pytest.mark.parametrize("name", PROBLEMS)
def test_a_heading_is_on_the_page_of_its_figure(built, name, detail):
    pairs = _heading_and_figure_pages(built[name, detail]["doc"], built[name, detail]["paths"]["pdf"])
    # A compact key floats its drawings as captioned figures, none opening a section of its own (its sections open
    # with their steps' text): what it must keep in order is its answers after the polygons (the test below).
    assert len(pairs) > (5 if detail == "full" else -1)
    assert [p for p in pairs if p[1] != p[2]] == []


def _where(pdf: bytes, text: str) -> tuple[int, float]:
    """(page, distance from the page's top [pt]) of the last place ``text`` is printed."""
    doc = pdfium.PdfDocument(pdf)
    found = None
    for k in range(len(doc)):
        page = doc[k]
        textpage = page.get_textpage()
        search = textpage.search(text)
        while (hit := search.get_next()) is not None:
            top = textpage.get_charbox(hit[0])[3]
            found = (k, page.get_height() - top)
    assert found is not None, text
    return found


@pytest.mark.parametrize("name", PROBLEMS)
def test_a_compact_key_prints_its_answers_after_the_polygons_that_find_them(built, name):
    """Issue 36: the answers were boxed before the polygons (floated below them). Now they follow the last figure
    of polygons on the page, in reading order; floating it as the other drawings are puts them back before."""
    from graphkin.handout import typst as T

    doc = built[name]["doc"]
    last = [b for b in doc["blocks"] if b["kind"] == "figure" and b["caption"].startswith(f"{b['label']}. The force "
                                                                                          "polygons")][-1]
    pdf = built[name]["paths"]["pdf"].read_bytes()
    assert _where(pdf, f"{last['label']}. The force polygons") < _where(pdf, "Both routes give these")
    floated = dict(doc, blocks=[dict(b, inline=False) if b is last else b for b in doc["blocks"]])
    if name == "double_slider":  # where the page leaves the polygons room below the answers
        pdf = T.render(floated)
        assert _where(pdf, f"{last['label']}. The force polygons") > _where(pdf, "Both routes give these")


def test_the_heading_check_catches_a_heading_left_at_the_foot_of_a_page(built, monkeypatch):
    """Without keeping headings and the paragraphs that lead to a figure with it, some heading is left behind."""
    from graphkin.handout import typst as T

    source = T.source
    loose = "#show heading: set block(sticky: false)\n"
    monkeypatch.setattr(T, "source", lambda d, **kw: loose + source(d, **kw).replace("sticky: true", "sticky: false"))
    doc = built["strip_cutter", "full"]["doc"]
    pairs = _heading_and_figure_pages(doc, T.render(doc))
    assert [p for p in pairs if p[1] != p[2]] != []


# -- the page image ----------------------------------------------------------------------------------------
BASELINE_PAGE = 4           # the fifth page: the inertia resultant, the matrix [A]{x} = {b}, the joint forces
DPI = 100
DOWNSAMPLE = 8              # average over 8×8 pixel blocks (2 mm): antialiasing and hinting wash out
TOLERANCE = 1.5             # mean absolute difference allowed, grey levels out of 255
# Measured: the same PDF with text antialiasing switched off differs by 1.2; the text block moved by
# 2 mm (margins) by 2.6, the text 5 % larger by 9.6, the page's table of unknowns left out by 3.3. (The page
# has no figure: only typst and the fonts it carries draw it, the same on every machine.)


def _page_image(pdf_bytes: bytes, page: int, **render) -> np.ndarray:
    """A page rendered at DPI in grey, averaged over DOWNSAMPLE² blocks."""
    doc = pdfium.PdfDocument(pdf_bytes)
    img = doc[page].render(scale=DPI / 72, grayscale=True, **render).to_pil().convert("L")
    img = np.asarray(img, dtype=float)
    h, w = (s // DOWNSAMPLE * DOWNSAMPLE for s in img.shape)
    return img[:h, :w].reshape(h // DOWNSAMPLE, DOWNSAMPLE, w // DOWNSAMPLE, DOWNSAMPLE).mean(axis=(1, 3))


def _baseline(name: str, image: np.ndarray) -> np.ndarray:
    from PIL import Image

    path = BASELINES / f"handout_{name}_p{BASELINE_PAGE + 1}.png"
    if os.environ.get("GRAPHKIN_UPDATE_BASELINES") or not path.exists():
        if not os.environ.get("GRAPHKIN_UPDATE_BASELINES"):
            pytest.fail(f"no baseline {path}: run with GRAPHKIN_UPDATE_BASELINES=1 to make it, and look at it")
        path.parent.mkdir(exist_ok=True)
        Image.fromarray(np.round(image).astype(np.uint8)).save(path)
    return np.asarray(Image.open(path).convert("L"), dtype=float)


def _difference(a: np.ndarray, b: np.ndarray) -> float:
    if a.shape != b.shape:
        return math.inf
    return float(np.mean(np.abs(a - b)))


def test_a_page_matches_its_baseline(built):
    pdf = built["double_slider", "full"]["paths"]["pdf"].read_bytes()
    image = _page_image(pdf, BASELINE_PAGE)
    assert _difference(image, _baseline("double_slider", image)) < TOLERANCE
    # Robust to how the glyphs are smoothed: without any text antialiasing the page still matches.
    rough = _page_image(pdf, BASELINE_PAGE, no_smoothtext=True, no_smoothpath=True)
    assert _difference(rough, _baseline("double_slider", image)) < TOLERANCE


@pytest.mark.parametrize("break_it", ["margins", "larger text", "a block left out"])
def test_a_broken_layout_fails_the_page_comparison(built, monkeypatch, break_it):
    from graphkin.handout import typst as T

    doc = dict(built["double_slider", "full"]["doc"])
    if break_it == "margins":
        source = T.source
        monkeypatch.setattr(T, "source", lambda d, **kw: source(d, **kw).replace("margin: (x: 18mm", "margin: (x: 20mm"))
    elif break_it == "larger text":
        source = T.source
        monkeypatch.setattr(T, "source", lambda d, **kw: source(d, **kw).replace("size: 10pt", "size: 10.5pt"))
    else:
        # The table of the solved unknowns, on the page itself: a table left out before it may leave the page as it
        # is, when the float that follows it takes a page of its own either way.
        solved = next(k for k, blk in enumerate(doc["blocks"])
                      if blk["kind"] == "table" and blk.get("header") == [["unknown"], ["value"]])
        doc["blocks"] = doc["blocks"][:solved] + doc["blocks"][solved + 1:]
    image = _page_image(T.render(doc), BASELINE_PAGE)
    reference = _baseline("double_slider", image)
    assert _difference(image, reference) > TOLERANCE


# -- HTML ----------------------------------------------------------------------------------------------------
class _Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.text, self.refs, self.tags, self.styles = [], [], [], []
        self._style = False

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        self._style = tag == "style"
        for k, v in attrs:
            if k in ("src", "href", "xlink:href", "action", "data", "poster", "srcset") and v:
                self.refs.append(v)
            if k == "style" and v:
                self.styles.append(v)

    def handle_endtag(self, tag):
        self._style = False

    def handle_data(self, data):
        (self.styles if self._style else self.text).append(data)


@pytest.mark.parametrize("detail", DETAILS)
@pytest.mark.parametrize("name", PROBLEMS)
def test_html_is_one_self_contained_file_with_the_same_numbers(built, name, detail):
    b = built[name, detail]
    page = b["paths"]["html"].read_text(encoding="utf-8")
    parsed = _Page()
    parsed.feed(page)
    parsed.close()
    assert parsed.tags.count("svg") == sum(len(blk["pictures"]) for blk in b["doc"]["blocks"] if blk["kind"] == "figure")
    assert "math" in parsed.tags
    assert not {"script", "link", "iframe", "img", "object", "embed"} & set(parsed.tags)
    # Every reference stays inside the file (#id); nothing names a network address, not even a namespace.
    assert all(ref.startswith("#") for ref in parsed.refs), [r for r in parsed.refs if not r.startswith("#")][:3]
    for css in parsed.styles:
        assert "@import" not in css
        assert all(u.strip(" '\"").startswith("#") for u in re.findall(r"url\(([^)]*)\)", css))
    assert not re.search(r"https?:|//[a-z0-9]", page.replace("// ", ""), re.I)
    text = "".join(parsed.text)
    assert _missing(text, _expected(_worked(b))) == {}


def test_html_ids_are_unique_across_figures(built):
    page = built["strip_cutter"]["paths"]["html"].read_text(encoding="utf-8")
    ids = re.findall(r'\bid="([^"]+)"', page)
    assert len(ids) == len(set(ids)) > 0


def test_the_same_handout_gives_the_same_bytes(built):
    """Drawn afresh (every figure again), the HTML is byte for byte the same: no date, no random SVG ids."""
    again = handout.render(handout.build("double_slider"), "html")[0]
    assert again == built["double_slider"]["paths"]["html"].read_bytes()


# -- Markdown ----------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("detail", DETAILS)
@pytest.mark.parametrize("name", PROBLEMS)
def test_markdown_has_the_numbers_and_its_figures(built, name, detail):
    b = built[name, detail]
    path = b["paths"]["md"]
    text = path.read_text(encoding="utf-8")
    # In $…$ a number is LaTeX (-73.78, a negative one braced); in prose it has the true minus sign.
    plain = text.replace("{-", "-").replace(M.MINUS, "-")
    want = {k: v.replace(M.MINUS, "-") for k, v in _expected(_worked(b)).items()}
    assert _missing(plain, want) == {}
    links = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", text)
    assert len(links) == sum(len(blk["pictures"]) for blk in b["doc"]["blocks"] if blk["kind"] == "figure")
    for link in links:
        assert (path.parent / link).read_text(encoding="utf-8").lstrip().startswith("<?xml")
    assert "$$" in text


# -- versions --------------------------------------------------------------------------------------------------------
def test_an_exercise_sheet_has_no_answers_and_its_key_has_them(tmp_path):
    from graphkin import exercises

    key = exercises.key("strip_cutter_cut", "s007", "course")
    answers = [q["answer"]["text"] for q in key["questions"]]
    sheet = handout.build("strip_cutter_cut", student="s007", secret="course")
    keydoc = handout.build("strip_cutter_cut", student="s007", secret="course", version="key")
    assert sheet["version"] == "sheet" and keydoc["version"] == "key"
    sheet_html, _ = handout.render(sheet, "html")
    key_html, _ = handout.render(keydoc, "html")
    for g in key["data"]:
        assert g["shown"].split(" = ")[1] in sheet_html.decode()
    for text in answers:
        assert text not in sheet_html.decode()
        assert text in key_html.decode()
    kinds = {b["kind"] for b in sheet["blocks"]}
    assert "equation" not in kinds  # no working shown


def test_blank_gives_the_free_bodies_to_scale_and_room_for_every_polygon():
    from graphkin.graphical.paper import force_text, sheet_scales

    doc = handout.build("double_slider", version="blank")
    c = handout.document.subject("double_slider").construction(0)
    every = [b for b in doc["blocks"] if b["kind"] == "space"]
    spaces = [b for b in every if b["label"].startswith("Polygon")]
    assert len(spaces) == sum(1 for s in c.steps if s.polygon) > 0
    # and none for the velocity and acceleration polygons: this sheet gives the motion (--from-motion asks for
    # them, tests/handout/test_from_motion.py); the others are the analytical part's (tests/handout/test_proportionate.py)
    assert [b for b in every if not b["label"].startswith("Step ")] == spaces
    assert all(b["height"] >= 80 for b in spaces)
    figures = [b for b in doc["blocks"] if b["kind"] == "figure"]
    keys = {p.key for b in figures for p in b["pictures"]}
    assert {"sheet-mechanism-0", "free-bodies-0-given"} <= keys
    text = json.dumps([b.get("runs", "") for b in doc["blocks"]] + [b.get("label", "") for b in spaces],
                      ensure_ascii=False, default=str)
    assert force_text(sheet_scales(c).polygon) in text
    # No answer: neither a joint force nor the driver's effort.
    assert M.fmt(abs(c.effort)) not in text
    assert not any(b["kind"] == "equation" for b in doc["blocks"])


# -- errors: one line, exit code 2 -------------------------------------------------------------------------------------
def _one_error_line(err: str) -> str:
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("graphkin: error: ") and "Traceback" not in err
    return lines[0]


def test_an_unknown_suffix_is_refused_before_anything_is_computed(tmp_path, monkeypatch):
    def boom(*a, **k):
        raise AssertionError("computed before checking the destination")

    monkeypatch.setattr(handout, "build", boom)
    code, _, err = _main(["handout", "double_slider", "-o", str(tmp_path / "out.docx")])
    assert code == 2 and ".pdf, .html or .md" in _one_error_line(err)
    assert not (tmp_path / "out.docx").exists()


def test_an_unwritable_output_gives_one_line(tmp_path, monkeypatch):
    monkeypatch.setattr(handout, "build", lambda *a, **k: pytest.fail("computed before checking the destination"))
    blocker = tmp_path / "a_file"
    blocker.write_text("x")
    code, _, err = _main(["handout", "double_slider", "-o", str(blocker / "out.pdf")])
    assert code == 2 and "is a file, not a folder" in _one_error_line(err)


def test_a_typst_error_gives_one_line(tmp_path, monkeypatch):
    from graphkin.handout import typst as T

    monkeypatch.setattr(T, "source", lambda doc, **kw: "#let broken = (\n")
    code, _, err = _main(["handout", "single_link", "-o", str(tmp_path / "x.pdf")])
    assert code == 2 and "typst:" in _one_error_line(err)
    assert not (tmp_path / "x.pdf").exists()


def test_a_missing_font_gives_one_line(tmp_path, monkeypatch):
    from graphkin.handout import typst as T

    monkeypatch.setattr(T, "FONT", "No Such Font Sans")
    code, _, err = _main(["handout", "single_link", "-o", str(tmp_path / "x.pdf")])
    line = _one_error_line(err)
    assert code == 2 and "no such font sans" in line.lower() and "Libertinus Serif" in line


@pytest.mark.parametrize("argv, words", [
    (["handout", "strip_cutter_cut", "-o", "OUT/x.pdf"], "--student"),
    (["handout", "double_slider", "--at", "nonsense", "-o", "OUT/x.pdf"], "--at"),
    (["handout", "strip_cutter_cut", "--student", "s1", "--at", "130 deg", "-o", "OUT/x.pdf"], "--at"),
    (["handout", "strip_cutter_cut", "--roster", "ROSTER", "-o", "OUT/a_file"], "folder"),
    (["handout", "double_slider", "--format", "html", "-o", "OUT/x.pdf"], "--roster"),
])
def test_bad_requests_give_one_line(tmp_path, argv, words):
    (tmp_path / "a_file").write_text("x")
    (tmp_path / "roster.csv").write_text("student\ns1\n")
    argv = [a.replace("OUT", str(tmp_path)).replace("ROSTER", str(tmp_path / "roster.csv")) for a in argv]
    code, _, err = _main(argv)
    assert code == 2 and words in _one_error_line(err)


# -- a class at once ----------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("workers", [1, 2])
def test_a_roster_gives_a_sheet_and_a_key_per_student(built, tmp_path, workers):
    """In this process, and on two worker processes started after typst has run here (``built``): workers
    forked from such a process could wait for ever on a lock held by one of typst's threads."""
    from graphkin.handout.batch import CHUNK, file_stem, make_roster

    students = ["s001", "s002", "Ana María", "s004"] + [f"t{k}" for k in range(CHUNK)]  # two tasks
    done = []
    rows = make_roster("double_slider_forces", students, tmp_path, secret="k", fmt="html", workers=workers,
                       progress=done.append)
    assert [r[0] for r in rows] == students and all(not r[2] for r in rows)
    assert sum(done) == len(students)
    for st in students:
        for version in ("sheet", "key"):
            page = (tmp_path / f"{file_stem(st)}_{version}.html").read_text(encoding="utf-8")
            assert f"student {st}" in page
    assert not list(tmp_path.glob(".*"))  # atomic writes leave no temporary file behind
    assert len(list(tmp_path.iterdir())) == 2 * len(students)


_MAKE = """
import sys
from graphkin.handout.batch import write_chunk, worker_start
worker_start()
for student in sys.argv[2:]:
    (row,) = write_chunk(("strip_cutter_cut", [student], "k", ("sheet", "key"), "pdf", sys.argv[1], None))
    assert not row[2], row
"""


@pytest.mark.slow
def test_a_student_s_pdfs_are_the_same_whatever_their_worker_made_before(tmp_path):
    """A worker keeps what it laid out (texts, formulas, fonts, typst's memo) and settles after its first task:
    a student's sheet and key come out byte for byte the same made first in a fresh process or after others."""
    first, later = tmp_path / "first", tmp_path / "later"
    for folder, students in ((first, ["s9"]), (later, ["s1", "s2", "s3", "s9"])):
        folder.mkdir()
        subprocess.run([sys.executable, "-c", _MAKE, str(folder), *students], check=True, timeout=300)
    for name in ("s9_sheet.pdf", "s9_key.pdf"):
        assert (first / name).read_bytes() == (later / name).read_bytes(), name


def test_the_roster_command(tmp_path):
    (tmp_path / "roster.csv").write_text("student\ns1\ns2\n")
    code, _, err = _main(["handout", "double_slider_forces", "--roster", str(tmp_path / "roster.csv"),
                          "--secret", "k", "--key", "-o", str(tmp_path / "class")])
    assert code == 0, err
    assert sorted(p.name for p in (tmp_path / "class").iterdir()) == ["s1_key.pdf", "s2_key.pdf"]
    assert "2 files written" in err


# -- the maths, and what importing costs --------------------------------------------------------------------------------------
def test_every_math_node_compiles_in_typst_and_converts_to_mathml():
    import typst
    from latex2mathml.converter import convert

    node = M.row(M.sub(M.i("F"), M.t("23")), M.op("="), M.frac(M.absval(M.i("T")), M.vec(M.i("F"))), M.op("+"),
                 M.sup(M.paren(M.n(-4.364)), "2"), M.pair((7.5586, -25.978), "N"), M.op("∠"), M.n("−73.78"),
                 M.sqrt(M.row(M.sup(M.n(500), "2"), M.op("−"), M.n(200))),
                 M.op("°"), M.op("·"), M.op("×"), M.i("θ"), M.SP, M.mat([[M.n(1), M.n(-2)], [M.n(0), M.t("x")]]),
                 M.column([M.t("a, b")]), M.i("ab"))
    pdf = typst.compile(f"$ {M.to_typst(node)} $".encode(), format="pdf", ignore_system_fonts=True)
    text = pypdf.PdfReader(io.BytesIO(pdf)).pages[0].extract_text()
    for number in ("23", "7.559", "−25.98", "−73.78", "−4.364"):
        assert number in text
    mathml = convert(M.to_latex(node))
    assert "<mfrac>" in mathml and "<mtable>" in mathml and "<msqrt>" in mathml and "25.98" in mathml
    assert M.to_text(node).startswith("F23 = (|T|)/(F)")


def test_fmt_prints_as_the_books_do():
    assert [M.fmt(x) for x in (27.0597, -73.7812, 0.86594, 7580.38, 1.0, -0.0)] == \
        ["27.06", "−73.78", "0.8659", "7580", "1", "0"]
    assert M.fmt_fixed(-0.001) == "0.00" and M.fmt_fixed(180.0) == "180.00"


def test_importing_the_handouts_loads_neither_matplotlib_nor_typst():
    code = ("import sys, graphkin, graphkin.handout, graphkin.cli.handout; "
            "print(sorted(m for m in ('matplotlib', 'typst', 'pint', 'latex2mathml') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT.parent)
    assert out.stdout.strip() == "[]"
