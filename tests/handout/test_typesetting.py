"""The typesetting faults issue 24 found, each checked where it can be (the typst source, the PDF's text and
drawing, the HTML), and the checks shown to catch the fault they guard against."""

from __future__ import annotations

import io
import re

import pytest

pypdf = pytest.importorskip("pypdf")
pytest.importorskip("pypdfium2")

from graphkin import handout  # noqa: E402
from graphkin.handout import maths as M  # noqa: E402
from tests.handout.pdfgeometry import text_across_rules  # noqa: E402

# Typesets PDFs and measures them (every catalog key, at print size): make test runs it, make check does not.
pytestmark = pytest.mark.slow


def _text(path) -> str:
    return "\n".join(page.extract_text() for page in pypdf.PdfReader(path).pages)


CASES = {
    "shaper_six_bar": ("shaper_six_bar", {"detail": "full"}),  # five sub-problems
    "strip_cutter": ("strip_cutter", {"detail": "full"}),  # a whole cycle, worked at 40° (no cut)
    "slider_crank_friction": ("slider_crank_friction", {"detail": "full"}),  # a sliding pair's N and C
    "strip_cutter_140": ("strip_cutter", {"at": "140 deg"}),  # mid-cut: R3 = R3i + Fc3, compact
    "strip_cutter_140_full": ("strip_cutter", {"at": "140 deg", "detail": "full"}),
}


@pytest.fixture(scope="module")
def keys(tmp_path_factory):
    """The keys of :data:`CASES`, built and printed once: their documents, PDFs and the PDFs' text."""
    folder = tmp_path_factory.mktemp("typeset")
    out = {}
    for name, (source, kw) in CASES.items():
        doc = handout.build(source, **kw)
        path = folder / f"{name}.pdf"
        handout.write(doc, path)
        out[name] = {"doc": doc, "path": path, "text": _text(path)}
    return out


def test_a_wide_table_stays_in_its_cells(keys, tmp_path, monkeypatch):
    """The shaper's superposition table (five sub-problems and the sum) keeps each force in its own cell; set on
    one line each, as before, the forces run over the rules into the next cells, and the check sees it."""
    assert any("Superposition: each sub-problem" in (b.get("caption") or "") for b in keys["shaper_six_bar"]["doc"]
               ["blocks"] if b["kind"] == "table")
    assert text_across_rules(keys["shaper_six_bar"]["path"]) == []
    from graphkin.handout import solution

    monkeypatch.setattr(solution, "_stacked", lambda F: M.polar(M.size_of(F), M.angle_of(F), "N"))
    doc = handout.build("shaper_six_bar", detail="full")
    for b in doc["blocks"]:
        b["small"] = False
    path = tmp_path / "one_line.pdf"
    handout.write(doc, path)
    assert text_across_rules(path) != []


@pytest.mark.parametrize("name, typst, latex", [
    ("F43′", 'attach(F, b: "43", t: prime)', r"{F}_{\text{43}}^{\prime}"),
    ("F23″", 'attach(F, b: "23", t: prime.double)', r"^{\prime\prime}"),
    ("F14‴", 'attach(F, b: "14", t: prime.triple)', r"^{\prime\prime\prime}"),
    ("F23⁗", 'attach(F, b: "23", t: prime.quad)', r"^{\prime\prime\prime\prime}"),
    ("F23⁽⁵⁾", 'attach(F, b: "23", t: "(5)")', r"^{\text{(5)}}"),
])
def test_every_sub_problem_s_mark_is_a_superscript_snug_to_its_letter(name, typst, latex):
    """The 4th and 5th marks were set upright, the name not subscripted; a prime sat detached after the
    subscript (F43 ′). Now each is the letter with its subscript and its mark over it: F′₄₃, F⁗₂₃, F⁽⁵⁾₂₃."""
    import typst as T

    node = M.name(name)
    assert M.to_typst(node) == typst
    assert latex in M.to_latex(node)
    assert M.to_text(node) == name
    pdf = T.compile(f"$ {M.to_typst(node)} $".encode(), format="pdf", ignore_system_fonts=True)
    assert re.search(r"\d\d", name)[0] in pypdf.PdfReader(io.BytesIO(pdf)).pages[0].extract_text()


def test_a_reversed_force_in_a_polygon_s_equation_is_subtracted():
    from graphkin import catalog
    from graphkin.graphical import construct_forces
    from graphkin.handout.compact import polygon_equation

    c = construct_forces(catalog.load("strip_cutter").solve(__import__("numpy").radians([140.0])).kinematics, 0)
    superpose = next(st for st in c.steps if st.kind == "superpose")
    text = M.to_text(polygon_equation(superpose))
    assert text == "F23′ + F23″ − F23 = 0"
    assert "+ −" not in text


def test_the_resultant_the_later_steps_use_is_drawn(keys):
    """R3 = R3i + Fc3 is stated in step 1 and used from then on: both keys draw the sum, tip to tail."""
    for name, key in (("strip_cutter_140", "polygons"), ("strip_cutter_140_full", "step")):
        pictures = [p for b in keys[name]["doc"]["blocks"] if b["kind"] == "figure" for p in b["pictures"]
                    if p.key.startswith(key)]
        svg = "".join(p.svg() for p in pictures)
        assert 'id="polygon:R3i"' in svg and 'id="polygon:−R3"' in svg, name


def test_the_matrix_names_its_rows_and_its_unknowns(keys):
    """N14 and C14 were undefined and the rows unlabelled; ΣM_G printed its underscore."""
    text = " ".join(keys["slider_crank_friction"]["text"].split())
    assert "𝑁14 the normal force of the sliding pair of links 1 and 4" in text
    assert "𝐶14 the couple link 1 applies to link 4 through their sliding pair" in text
    for row in ("link 2 ΣFx", "link 3 ΣFy", "link 4 Σ𝑀G"):
        assert row in text, row
    assert "M_G" not in text and "_ext" not in text


@pytest.mark.parametrize("name", ["strip_cutter", "strip_cutter_140", "shaper_six_bar"])
def test_no_number_is_printed_in_e_notation_and_no_zero_as_a_rounding_residue(keys, name):
    """The energy table's last accumulated energy was 5.684e−14 J (zero but for rounding)."""
    text = keys[name]["text"]
    assert not re.search(r"\de[−-]?\d", text)
    if name == "strip_cutter":
        table = text[text.index("accumulated [J]"):text.index("The energy table")]
        assert table.split()[-1] == "0"


@pytest.mark.parametrize("name", ["strip_cutter_140_full", "shaper_six_bar"])
def test_captions_carry_a_true_minus(keys, name):
    text = keys[name]["text"]
    assert not re.search(r"(?<![\w)\]])-\d", text), re.findall(r".{20}(?<![\w)\]])-\d.{5}", text)[:3]
    if name == "strip_cutter_140_full":
        # Link 3's inertia torque at 140°, in the caption of its figure: a true minus.
        caption = next(b["caption"] for b in keys[name]["doc"]["blocks"] if b["kind"] == "figure"
                       and b["caption"].split(". ", 1)[1].startswith("Link 3: its inertia force"))
        assert "T3i = −I_G α = −379.4 N·m" in caption or "= −379.4 N·m" in caption


def test_html_names_a_math_font_stack_and_prints_with_margins_and_whole_equations():
    page = handout.render(handout.build("slider_crank_friction", detail="full"), "html")[0].decode()
    css = page[page.index("<style>"):page.index("</style>")]
    fonts = re.search(r"math \{ font-family: ([^;]*);", css)[1]
    for font in ("STIX Two Math", "Cambria Math", "Latin Modern Math", "DejaVu Math TeX Gyre", "DejaVu Serif"):
        assert font in fonts
    assert "@page { size: A4; margin: 18mm" in css
    assert re.search(r"\.eq[^{]*\{[^}]*break-inside: avoid", css) or ".eq, table" in css
    # Nothing needs a math font's stretchy glyphs: brackets and roots are drawn with borders.
    assert 'class="bmat"' in page and "<msqrt>" not in page and 'form="prefix">[</mo><mtable' not in page
    assert 'class="radicand"' in page


def _measured(exprs, size=10.0) -> list[float]:
    """Widths [pt] typst gives each piece of maths (typst source between ``$ … $``), set as a displayed line."""
    import json
    import tempfile
    from pathlib import Path

    import typst

    from graphkin.handout.typst import FONT, MATH_FONT

    lines = [f'#set text(font: "{FONT}", size: {size}pt)', f'#show math.equation: set text(font: "{MATH_FONT}")']
    lines += [f"#context [#metadata(measure($ {e} $).width / 1pt) <w{k}>]" for k, e in enumerate(exprs)]
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "measure.typ"
        path.write_text("\n".join(lines), encoding="utf-8")
        compiler = typst.Compiler(str(path), ignore_system_fonts=True)
        return [json.loads(compiler.query(f"<w{k}>", field="value", one=True)) for k in range(len(exprs))]


def test_each_character_s_advance_is_at_least_what_typst_sets():
    """The advances :func:`maths.width_bound` counts are typst's own, in italic and upright, or more."""
    chars = list(M._ADVANCE)
    quoted = [c.replace("\\", "\\\\").replace('"', '\\"') for c in chars]
    widths = _measured([f'italic("{q}")' for q in quoted] + [f'upright("{q}")' for q in quoted])
    for k, ch in enumerate(chars):
        assert max(widths[k], widths[k + len(chars)]) / 10.0 <= M._ADVANCE[ch], ch


def test_an_equation_set_without_measuring_is_narrower_than_its_bound():
    """Every displayed line of every catalog key (compact and full) and exercise key is narrower than
    :func:`maths.width_bound` says, so one whose bound fits the page is set as it is; the widest lines (the
    matrix) are still scaled to the page."""
    from pathlib import Path

    from graphkin import catalog
    from graphkin.handout import typst as T

    docs = [handout.build(name, detail=detail) for name in catalog.names() for detail in ("compact", "full")]
    docs += [handout.build(p.stem, student="s1", secret="x", version="key")
             for p in sorted((Path(catalog.__file__).parent / "exercises").glob("*.toml"))]
    lines = {M.to_typst(line): line for doc in docs for b in doc["blocks"] if b["kind"] == "equation"
             for line in b["lines"]}
    # Each line at the size its block is set at (a key's stacked equilibrium rows at 9 pt, a matrix at 8 pt).
    size = {M.to_typst(line): T.equation_size(b) for doc in docs for b in doc["blocks"] if b["kind"] == "equation"
            for line in b["lines"]}
    widths = _measured(list(lines))
    for (source, line), width in zip(lines.items(), widths):
        assert width <= M.width_bound(line) * 10.0, M.to_text(line)
    fitted = [w for (source, line), w in zip(lines.items(), widths) if "measure(" in T._equation(line, size[source])]
    assert max(widths) > T.TEXT_WIDTH and max(widths) in fitted
    assert len(fitted) < len(lines) / 10
