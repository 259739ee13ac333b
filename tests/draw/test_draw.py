"""graphkin.draw: the drawings carry what they show — arrows at their points, closed polygons, every label.

Every catalog problem at its first position. Assertions are on the artists
(paths in data coordinates, texts), so they hold whatever the look.
"""

import math
import re
import subprocess
import sys

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from matplotlib.figure import Figure  # noqa: E402
from matplotlib.testing.compare import compare_images  # noqa: E402

from graphkin import catalog, draw  # noqa: E402
from graphkin.graphical import construct_forces  # noqa: E402
from graphkin.graphical.construction import Construction  # noqa: E402
from graphkin.model import FRAME  # noqa: E402

NAMES = ["double_slider", "strip_cutter", "slider_crank_friction", "gearset", "single_link"]
MM = 1e3
_CACHE = {}


class Case:
    def __init__(self, name):
        p = catalog.load(name)
        self.name = name
        self.problem = p
        self.result = p.solve()
        self.c = construct_forces(self.result.kinematics, 0)
        self.fbd = {link: draw.draw_free_body(self.c, link) for link in self.c.mechanism.moving}


@pytest.fixture(params=NAMES)
def case(request):
    if request.param not in _CACHE:
        _CACHE[request.param] = Case(request.param)
    return _CACHE[request.param]


_UNSUB = dict(zip("₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ", "0123456789aehijklmnoprstuvx"))


def plain(text: str) -> str:
    """Text with subscripts as plain characters and no mathtext markup: ``F₂₃ = 2 N`` → ``F23 = 2 N``."""
    text = "".join(_UNSUB.get(ch, ch) for ch in text)
    return re.sub(r"\\mathregular|[${}]", "", text).replace("_", "")


def texts_of(ax) -> list[str]:
    return [plain(t.get_text()) for t in ax.texts]


def names_in(ax) -> set:
    """Every word-like token of every text on the axes."""
    out = set()
    for t in texts_of(ax):
        out.update(re.findall(r"[A-Za-z]+\d*[a-z]?", t))
    return out


def shows(ax, name: str) -> bool:
    return any(re.search(rf"(^|[^\w]){re.escape(name)}($|[^\w])", t) for t in texts_of(ax))


def tail_tip(artist):
    """Tail and tip of a force arrow, from its drawn path (data coordinates)."""
    from matplotlib.path import Path

    path = artist.get_path()
    v = path.vertices
    if path.codes is not None:
        v = v[path.codes != Path.CLOSEPOLY]  # a CLOSEPOLY vertex is a placeholder, not a point
    v = v[np.all(np.isfinite(v), axis=1)]
    tail = v[0]
    tip = v[np.argmax(np.hypot(*(v - tail).T))]
    return tail, tip


def data_per_point(ax) -> float:
    """Data units per typographic point along x (the axes are equal-scale)."""
    ax.apply_aspect()
    return np.ptp(ax.get_xlim()) / (ax.bbox.width * 72 / ax.figure.dpi)


def expected_forces(c, link):
    """(name, vector [N], point of application [mm]) of every force on a link, from the construction alone."""
    out = [(a.name, np.array(a.vector), np.array(a.at) * MM) for a in c.forces_on(link)]
    out += [(a.name, np.array(a.vector), np.array(a.at) * MM) for a in c.external.get(link, [])]
    inert = c.inertia.get(link)
    if inert and math.hypot(*inert["F"]) > 0:
        out.append((f"R{link}i", np.array(inert["F"]), np.array(inert["line_point"]) * MM))
    d = c.mechanism.driver
    if d.link == link and d.kind == "slider":
        joint = c.mechanism.joint_between(FRAME, link)
        X = np.array(c.points[link][joint.point]) * MM
        driver_arrow = next(a for s in c.steps for a in s.polygon if a.name == d.symbol)
        out.append((d.symbol, np.array(driver_arrow.vector), X))
    return out


# -- import hygiene ------------------------------------------------------------------


def test_graphkin_and_the_construction_do_not_import_matplotlib():
    code = (
        "import sys, graphkin, graphkin.graphical\n"
        "from graphkin import catalog\n"
        "from graphkin.graphical import construct_forces\n"
        "p = catalog.load('double_slider'); construct_forces(p.kinematics(), 0); p.solve()\n"
        "bad = sorted(m for m in sys.modules if m == 'matplotlib' or m.startswith('matplotlib.'))\n"
        "assert not bad, bad\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


# -- free-body diagrams -----------------------------------------------------------------


def test_every_fbd_arrow_starts_or_ends_at_its_point_of_application(case):
    c = case.c
    for link, d in case.fbd.items():
        ax = d.ax
        slack = 6 * data_per_point(ax)  # a head's point is pulled back by its stroke, a few points
        for name, F, X in expected_forces(c, link):
            size = math.hypot(*F)
            if size == 0:
                assert shows(ax, name)
                continue
            tail, tip = tail_tip(d.arrows[name])
            length = math.hypot(*(tip - tail))
            tol = 0.02 * length + slack
            if name.endswith("i") and "h" in d.labels and "not to scale" in d.labels["h"].get_text():
                # A far line of action drawn nearer G (a broken dimension): on the way from G to the true line.
                G = np.array(c.G[link]) * MM
                ends = (tail, tip) if math.hypot(*(tail - X)) < math.hypot(*(tip - X)) else (tip, tail)
                t = float(np.dot(ends[0] - G, X - G) / np.dot(X - G, X - G))
                assert 0 < t < 1 and math.hypot(*(G + t * (X - G) - ends[0])) < tol, (case.name, link, name)
                X = G + t * (X - G)
            assert min(math.hypot(*(tail - X)), math.hypot(*(tip - X))) < tol, (case.name, link, name)
            if size / d.scale < 2 * slack:
                continue  # a few points long: its head is all there is to see
            # Along the force, and as long as the scale says.
            assert np.dot(tip - tail, F) / (length * size) > 0.999, (case.name, link, name)
            assert abs(length - size / d.scale) < tol, (case.name, link, name)


def test_every_force_and_couple_on_each_link_is_labelled(case):
    c = case.c
    for link, d in case.fbd.items():
        for name, _, _ in expected_forces(c, link):
            assert shows(d.ax, name), (case.name, link, name, texts_of(d.ax))
        if c.mechanism.driver.link == link:
            assert shows(d.ax, c.driver_name)
        for ld in c.mechanism.loads:
            if getattr(ld, "torque", None) is not None and ld.link == link:
                assert shows(d.ax, ld.name)
        # The link's own points are named too.
        for point in c.points[link]:
            assert point in names_in(d.ax) or any(t.startswith(point) for t in texts_of(d.ax))


def test_labels_keep_clear_of_their_own_arrows(case):
    from graphkin.draw.labels import measuring_renderer as renderer_of
    from graphkin.draw.labels import segment_hits_box as _seg_hits_box

    for link, d in case.fbd.items():
        r = renderer_of(d.ax.figure)
        to = d.ax.transData.transform
        for name, arrow in d.arrows.items():
            if name not in d.labels or not hasattr(arrow, "get_path"):
                continue
            if name.startswith("T") or name.startswith("C"):  # couples: curved arrows
                continue
            tail, tip = tail_tip(arrow)
            bb = d.labels[name].get_window_extent(r)
            assert not _seg_hits_box(to(tail), to(tip), (bb.x0, bb.y0, bb.x1, bb.y1)), (case.name, link, name)


def test_h_is_dimensioned_where_the_inertia_force_is_offset(case):
    c = case.c
    for link, d in case.fbd.items():
        inert = c.inertia.get(link)
        if not inert or inert["h"] is None or math.hypot(*inert["F"]) == 0:
            continue
        h_texts = [t for t in texts_of(d.ax) if "h =" in t]
        if inert["h"] == 0 and len(c.points[link]) == 1:
            # A slider never turns: no "h = 0" crowding its one point (issue 36).
            assert not h_texts, (case.name, link)
            continue
        assert h_texts, (case.name, link)
        if inert["h"] > 0:
            assert any(t.startswith(f"h = {inert['h'] * MM:.4g} mm".replace("-", "−")) for t in h_texts), h_texts


def test_double_slider_fbd_shows_the_books_offset():
    """Söylemez §6.4: F3i acts 33.3 mm from G3 (the book's rounding gives 33.31)."""
    c = construct_forces(catalog.load("double_slider").kinematics(), 0)
    d = draw.draw_free_body(c, 3)
    assert "h = 33.33 mm" in texts_of(d.ax)
    tail, _ = tail_tip(d.arrows["R3i"])
    assert math.hypot(*(tail - np.array(c.G[3]) * MM)) == pytest.approx(33.33, abs=0.01)


def test_a_fixed_link_has_no_free_body():
    c = construct_forces(catalog.load("single_link").kinematics(), 0)
    with pytest.raises(ValueError, match="not a moving link"):
        draw.draw_free_body(c, FRAME)


# -- force polygons ------------------------------------------------------------------------


def test_every_force_polygon_closes_tip_to_tail(case):
    c = case.c
    steps = [s for s in c.steps if s.polygon]
    assert steps
    for step in steps:
        d = draw.draw_force_polygon(step, scale=c.force_scale)
        arrows = [d.arrows[a.name] for a in step.polygon if math.hypot(*a.vector) > 0]
        ends = [tail_tip(a) for a in arrows]
        longest = max(math.hypot(*(t - s)) for s, t in ends)
        tol = 0.01 * longest + 6 * data_per_point(d.ax)
        for (_, tip), (tail, _) in zip(ends[:-1], ends[1:]):
            assert math.hypot(*(tail - tip)) < tol, (case.name, step.caption)  # tip to tail
        first_tail, last_tip = ends[0][0], ends[-1][1]
        assert math.hypot(*(last_tip - first_tail)) < tol, (case.name, step.caption)  # it closes
        for a in step.polygon:
            assert shows(d.ax, a.name), (a.name, texts_of(d.ax))
        # A scale bar reading 0 — N.
        assert "0" in texts_of(d.ax) and any(re.fullmatch(r"[\d.]+ N", t) for t in texts_of(d.ax))


def test_known_loads_and_unknowns_look_different():
    c = construct_forces(catalog.load("double_slider").kinematics(), 0)
    step = next(s for s in c.steps if s.kind == "polygon")
    d = draw.draw_force_polygon(step, scale=c.force_scale)
    known = [d.arrows[a.name] for a in step.polygon if a.known]
    unknown = [d.arrows[a.name] for a in step.polygon if not a.known]
    assert known and unknown
    for k in known:
        for u in unknown:
            assert k.get_edgecolor() != u.get_edgecolor()
            assert k.get_facecolor() != u.get_facecolor()  # solid heads vs open heads


def _scale_bar_box(d, renderer):
    """Display box (x0, y0, x1, y1) around a drawing's scale bar: the bar, its end ticks and both numbers."""
    from matplotlib.lines import Line2D

    zero = next(t for t in d.ax.texts if t.get_text() == "0")
    x, y = zero.get_position()
    value = next(t for t in d.ax.texts if re.fullmatch(r"[\d.]+ N", t.get_text()))
    bar = [a for a in d.ax.lines if isinstance(a, Line2D) and len(a.get_xdata()) in (2, 5)
           and a.get_xdata()[0] == x and (a.get_ydata()[0] == y or np.isnan(a.get_ydata()).any())]
    boxes = [a.get_window_extent(renderer) for a in [zero, value, *bar]]
    return (min(b.x0 for b in boxes), min(b.y0 for b in boxes), max(b.x1 for b in boxes), max(b.y1 for b in boxes))


def _overlap_px(a, b) -> float:
    """How far two display boxes (x0, y0, x1, y1) overlap [px]: the smaller of the two overlaps, 0 if apart."""
    ox = min(a[2], b[2]) - max(a[0], b[0])
    oy = min(a[3], b[3]) - max(a[1], b[1])
    return max(0.0, min(ox, oy))


def _panel(size, dpi):
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from graphkin.draw.axes import PanelAxes

    fig = Figure(figsize=size, dpi=dpi)
    FigureCanvasAgg(fig)
    return fig.add_subplot(axes_class=PanelAxes)


# Panels where a label used to sit on the scale bar (overlap before the fix, in px): small axes, where the
# bar's numbers reached past the segment that stood for them, and a crossing cost no more than an arrow's.
_BAR_CASES = {
    # The superposition polygon of G14 at θ = 0: "G₁₄ (4 loaded) = 45.83 N" over "0 ⊢⊣ 10 N" (11 px).
    "slider_crank_G14_parts": ("slider_crank_friction", 0.0, "superpose:G14", (2.5, 2.5), 100, True),
    # The double slider at its book position, the explorer's size (values off): "F₁₂" on the bar (5 px).
    "double_slider_input": ("double_slider", None, "driver", (2.82, 2.2), 72, False),
    # The strip cutter at θ = 240°: "F₃₄ (3 loaded)" (8 px).
    "strip_cutter_F34_parts": ("strip_cutter", math.radians(240), "superpose:F34", (2.82, 2.2), 72, False),
    # A free body: the crank's driving torque "T₁₂ = 29.49 N·m CW" at θ = 80° (8 px).
    "slider_crank_fbd2": ("slider_crank_friction", math.radians(80), "fbd:2", (2.82, 2.2), 72, False),
}


@pytest.mark.parametrize("key", sorted(_BAR_CASES))
def test_labels_keep_off_the_scale_bar(key):
    from graphkin.draw.labels import measuring_renderer as renderer_of

    name, at, panel, size, dpi, values = _BAR_CASES[key]
    p = catalog.load(name)
    c = construct_forces(p.kinematics(None if at is None else [at]), 0)
    ax = _panel(size, dpi)
    kind, _, which = panel.partition(":")
    if kind == "fbd":
        d = draw.draw_free_body(c, int(which), ax=ax)
    else:
        step = next(s for s in c.steps if s.kind == kind and (not which or s.polygon[-1].name == f"−{which}"))
        d = draw.draw_force_polygon(step, scale=c.force_scale, ax=ax, values=values, driver_name=c.driver_name)
    r = renderer_of(ax.figure)
    bar = _scale_bar_box(d, r)
    for label, t in d.labels.items():
        over = _overlap_px(tuple(t.get_window_extent(r).extents), bar)
        assert over <= 0.5, (key, label, t.get_text(), f"{over:.1f} px over the scale bar")


def test_scale_bar_is_a_box_the_labeler_keeps_off():
    """The bar's numbers are measured by arithmetic (no text layout per draw): the box is where the text is drawn."""
    from graphkin.draw.labels import Labeler
    from graphkin.draw.labels import measuring_renderer as renderer_of
    from graphkin.draw.labels import text_box as _text_box
    from graphkin.draw.scales import scale_bar
    from graphkin.draw.style import resolve

    ax = _panel((3, 3), 100)
    ax.set_xlim(0, 100)
    ax.set_ylim(0, 100)
    ax.set_aspect("equal")
    lab = Labeler(ax, resolve())
    bar = scale_bar(ax, (20, 20), 30, 500, s=resolve(), labeler=lab)
    ax.apply_aspect()
    r = renderer_of(ax.figure)
    for t in bar[2:]:
        np.testing.assert_allclose(_text_box(t, r), tuple(t.get_window_extent(r).extents), atol=1.0)
    # A label whose first spot is on the bar's reading goes to its next spot.
    t = lab.label("F23", [((35, 20), (0, 1), 0.0), ((35, 80), (0, 1), 0.0)])
    lab.place()
    assert t.get_position() == (35, 80)


# -- names as typeset ---------------------------------------------------------------------------


def test_negated_names_are_subscripted_like_the_names():
    from graphkin.draw.text import sub

    assert sub("F23") == "F₂₃"
    assert sub("−F23") == "−F₂₃"
    assert sub("-F23") == "−F₂₃"  # a hyphen becomes a true minus, as in every number drawn
    assert sub("−G14 (4 loaded)") == "−G₁₄ (4 loaded)"
    assert sub("−R3i") == "−R₃ᵢ"
    assert sub("−FP") == "−FP" and sub("-") == "-"  # not a name with a subscript: as it is


def test_superposition_polygon_shows_the_negated_total_subscripted():
    """The strip cutter at 140°: each superposition polygon closes with −F₂₃, −F₃₄ or −F₁₄."""
    p = catalog.load("strip_cutter")
    c = construct_forces(p.kinematics([math.radians(140)]), 0)
    steps = [s for s in c.steps if s.kind == "superpose"]
    assert {s.polygon[-1].name for s in steps} == {"−F23", "−F34", "−F14"}
    for step in steps:
        total = step.polygon[-1].name
        d = draw.draw_force_polygon(step, scale=c.force_scale)
        shown = d.labels[total].get_text()
        assert shown.startswith("−F") and shown[2] in "₁₂₃₄" and shown[3] in "₁₂₃₄", shown
        assert "−F" + "".join("₁₂₃₄"["1234".index(ch)] for ch in total[2:]) in draw.polygon.step_title(step)


def test_named_loads_with_a_note_subscript_the_name_and_keep_the_note():
    from matplotlib import cbook

    from graphkin.draw.text import plain as unsub
    from graphkin.draw.text import sub

    # There is no Unicode subscript c: the name alone goes to upright mathtext, the note stays text.
    assert sub("Fc3 (cutting)") == r"$\mathregular{F_{c3}}$ (cutting)"
    assert sub("Fc3") == r"$\mathregular{F_{c3}}$" and sub("−Fc4") == r"−$\mathregular{F_{c4}}$"
    assert sub("F14 (cutting)") == "F₁₄ (cutting)"
    assert unsub(sub("Fc3 (cutting)")) == "Fc3 (cutting)" and unsub(sub("−F23")) == "−F23"
    # The strip cutter at 140°, cutting: its free bodies label the cutting forces so.
    p = catalog.load("strip_cutter")
    c = construct_forces(p.kinematics([math.radians(140)]), 0)
    for link, name in ((3, "Fc3 (cutting)"), (4, "Fc4 (cutting)")):
        d = draw.draw_free_body(c, link)
        t = d.labels[name]
        assert cbook.is_math_text(t.get_text()) and t.get_text().endswith("$ (cutting)"), t.get_text()
        assert shows(d.ax, name)
        # It renders: the subscript sits below the F's baseline, so the label is taller than plain "Fc3".
        from graphkin.draw.labels import measuring_renderer as renderer_of

        r = renderer_of(d.ax.figure)
        flat = d.ax.text(0, 0, name, fontsize=t.get_fontsize())
        assert t.get_window_extent(r).height > flat.get_window_extent(r).height


# -- mechanism, convention, steps ------------------------------------------------------------


def test_mechanism_names_its_points_and_is_to_scale(case):
    c = case.c
    d = draw.draw_mechanism(c)
    assert d.ax.get_aspect() == 1.0
    for link, pts in c.points.items():
        for name in pts:
            assert any(t.startswith(name) or f" {name}" in t for t in texts_of(d.ax)), name
    for link in c.mechanism.moving:
        if c.mechanism.link(link).mass > 0:
            assert any(f"G{link}" in t for t in texts_of(d.ax))


def test_sign_convention_legend():
    d = draw.draw_sign_convention()
    text = " ".join(texts_of(d.ax))
    assert "force of link i on link j" in text
    assert {"x", "y", "CCW", "F23", "F32"} <= set(d.arrows)
    tail23, tip23 = tail_tip(d.arrows["F23"])
    tail32, tip32 = tail_tip(d.arrows["F32"])
    np.testing.assert_allclose(tip23 - tail23, -(tip32 - tail32), rtol=0.03)  # action and reaction


def test_one_frame_per_step_with_its_caption():
    c = construct_forces(catalog.load("double_slider").kinematics(), 0)
    figs = draw.draw_steps(c)
    assert len(figs) == len(c.steps)
    for fig, step in zip(figs, c.steps):
        assert isinstance(fig, Figure)
        words = " ".join(" ".join(t.get_text().split()) for t in fig.texts)
        assert " ".join(step.caption.split()) in words
    grid = draw.draw_step_grid(c)
    assert isinstance(grid, Figure)
    assert len(grid.get_axes()) >= len(c.steps)


# -- the side-by-side figure -----------------------------------------------------------------


def test_solution_table_has_every_joint_force_and_the_driver(case):
    fig = draw.draw_solution(case.c, case.result)
    tables = [t for ax in fig.axes for t in ax.tables]
    assert len(tables) == 1
    cells = [plain(cell.get_text().get_text()) for cell in tables[0].get_celld().values()]
    for name in case.result.names():
        assert name in cells, (name, cells)
    assert case.result.driver_name in cells
    # One free body per moving link, and a polygon per polygon step.
    titles = [ax.get_title() for ax in fig.axes]
    for link in case.c.mechanism.moving:
        assert any(t.startswith(f"Free body: link {link}") for t in titles)
    assert sum(1 for ax in fig.axes for p in ax.patches if (p.get_gid() or "").startswith("polygon:")) >= 2
    assert case.problem.title in fig.get_suptitle()


def test_table_relative_differences_are_tiny(case):
    rows = draw.comparison_rows(case.c, case.result)
    assert [r[0] for r in rows] == case.result.names()
    for name, analytical, graphical, diff in rows:
        assert analytical == graphical, name
        assert diff == "0" or float(diff.replace("−", "-")) < 1e-9, (name, diff)


def test_solution_without_analytical_and_at_an_invalid_position():
    c = construct_forces(catalog.load("single_link").kinematics(), 0)
    fig = draw.draw_solution(c)
    cells = [plain(cell.get_text().get_text()) for ax in fig.axes for t in ax.tables for cell in t.get_celld().values()]
    assert "F12" in cells and "T12" in cells
    bad = Construction(c.mechanism, 0, 0.0, valid=False, reason="the linkage cannot be assembled")
    fig = draw.draw_solution(bad)
    assert any("cannot be assembled" in t.get_text() for t in fig.texts)


@pytest.fixture(scope="module")
def figures():
    p = catalog.load("slider_crank_friction")
    c = construct_forces(p.kinematics(), 0)
    small = construct_forces(catalog.load("double_slider").kinematics(), 0)
    return {"solution": draw.draw_solution(c, p.solve()), "fbd": draw.draw_free_body(c, 3),
            "grid": draw.draw_step_grid(small), "step": draw.draw_steps(small)[2]}


@pytest.mark.parametrize("fmt", ["png", "svg", "pdf"])
def test_figures_save_to_png_svg_and_pdf(tmp_path, fmt, figures):
    magic = {"png": b"\x89PNG", "svg": b"<?xml", "pdf": b"%PDF"}[fmt]
    for what, fig in figures.items():
        path = draw.save(fig, tmp_path / f"{what}.{fmt}", dpi=50)
        assert path.read_bytes().startswith(magic), what


def test_save_refuses_other_formats(tmp_path):
    with pytest.raises(ValueError, match=r"\.png, \.svg, \.pdf"):
        draw.save(Figure(), tmp_path / "x.jpg")


def test_style_overrides_are_checked():
    c = construct_forces(catalog.load("single_link").kinematics(), 0)
    d = draw.draw_free_body(c, 2, unknown="#000000")
    assert d.arrows["F12"].get_edgecolor()[:3] == (0.0, 0.0, 0.0)
    with pytest.raises(TypeError, match="unknown style option"):
        draw.draw_mechanism(c, colour="red")


# -- image baseline ------------------------------------------------------------------------------


def _baseline_drawings():
    c = construct_forces(catalog.load("double_slider").kinematics(), 0)
    polygon = next(s for s in c.steps if s.kind == "polygon" and s.link == 3)
    gears = construct_forces(catalog.load("gearset").kinematics(at=[math.radians(30)]), 0)
    friction = construct_forces(catalog.load("slider_crank_friction").kinematics(at=[math.radians(60)]), 0)
    return {
        "double_slider_fbd3": lambda: draw.draw_free_body(c, 3),
        "double_slider_polygon3": lambda: draw.draw_force_polygon(polygon, scale=c.force_scale),
        "double_slider_mechanism": lambda: draw.draw_mechanism(c),
        "sign_convention": lambda: draw.draw_sign_convention(),
        "gearset_mechanism": lambda: draw.draw_mechanism(gears),  # teeth and marks that turn
        "slider_crank_friction_fbd4": lambda: draw.draw_free_body(friction, 4),  # the normal and ρ
    }


@pytest.mark.parametrize("name", sorted(_baseline_drawings()))
def test_figures_users_see_most_look_as_before(tmp_path, name):
    """Small PNG baselines in tests/baseline; after a deliberate change, regenerate with
    ``GRAPHKIN_NEW_BASELINES=1 python -m pytest tests/draw/test_draw.py -k look_as_before``."""
    import os
    from pathlib import Path

    baseline = Path(__file__).parents[1] / "baseline" / f"{name}.png"
    actual = tmp_path / f"{name}.png"
    draw.save(_baseline_drawings()[name](), actual, dpi=60)
    if os.environ.get("GRAPHKIN_NEW_BASELINES"):
        baseline.write_bytes(actual.read_bytes())
    assert baseline.exists(), f"missing baseline {baseline}"
    assert compare_images(str(baseline), str(actual), tol=12) is None


def test_a_name_two_links_use_for_different_points_is_told_apart():
    """The strip cutter's blades are both called C (on links 3 and 4), a few mm apart: C₃ and C₄, in one label
    (two would sit on top of each other), as G₃ a few mm from B shares B's."""
    problem = catalog.load("strip_cutter")
    c = construct_forces(problem.kinematics(at=[math.radians(140.0)]), 0)
    d = draw.draw_mechanism(c)
    assert d.labels["C"] is d.labels["C@4"] and d.labels["C"].get_text() == "C₃, C₄"
    assert d.labels["G3"] is d.labels["B"] and d.labels["B"].get_text() == "B, G₃"
    assert "C" not in [t.get_text() for t in d.ax.texts]
    # Each free body names its own C alone, plainly.
    for link in (3, 4):
        assert "C" in texts_of(draw.draw_free_body(c, link).ax)


# -- figures that show what they say (issue 14) ----------------------------------------------------


def _gear_bodies(d):
    """The toothed outlines on a drawing, largest first: (N×2 vertices [mm]) per gear."""
    from matplotlib.patches import Polygon

    bodies = [p.get_xy()[:-1] for p in d.ax.patches if isinstance(p, Polygon) and len(p.get_xy()) > 40]
    return sorted(bodies, key=lambda v: -np.ptp(v[:, 0]))


def test_gear_teeth_and_mark_turn_with_the_gear_and_mesh():
    """Lesson 05 says "turn the gear with the slider: the teeth move". They do, by θ₂ on the gear and by
    −(r₂/r₃)θ₂ on the pinion, with a mark on each gear's x-axis, and the teeth never run into each other."""
    shapely = pytest.importorskip("shapely")
    p = catalog.load("gearset")
    at = np.radians([0.0, 7.0, 30.0, 200.0])
    kin = p.kinematics(at=at)
    drawn = [draw.draw_mechanism(construct_forces(kin, i), labels=False) for i in range(len(at))]
    (gear0, pinion0), centres = _gear_bodies(drawn[0]), (np.array([0.0, 0.0]), np.array([140.0, 0.0]))
    r2, r3 = p.mechanism.joints[-1].radii
    for i, d in enumerate(drawn):
        gear, pinion = _gear_bodies(d)
        c = construct_forces(kin, i)
        for body, body0, centre, turn, teeth in ((gear, gear0, centres[0], at[i], 40),
                                                  (pinion, pinion0, centres[1], -r2 / r3 * at[i], 16)):
            assert len(body) % teeth == 0
            a = np.angle(complex(*(body[0] - centre))) - np.angle(complex(*(body0[0] - centre)))
            pitch = 2 * np.pi / teeth  # a turn by a whole tooth looks the same
            assert abs((a - turn + pitch / 2) % pitch - pitch / 2) < 1e-6, (i, teeth)
        assert shapely.Polygon(gear).intersection(shapely.Polygon(pinion)).area < 1e-9  # in mesh, clear
        # The reference marks: a spoke from each centre along its link's x-axis.
        spokes = [ln for ln in d.ax.lines if ln.get_linewidth() == 2.4]
        assert len(spokes) == 2
        for spoke, link, centre, r in zip(spokes, (2, 3), centres, (r2, r3)):
            x, y = spoke.get_data()
            direction = np.arctan2(y[1] - y[0], x[1] - x[0])
            assert abs((direction - c.angles[link] + np.pi) % (2 * np.pi) - np.pi) < 1e-9
            assert math.hypot(x[0] - centre[0], y[0] - centre[1]) < 0.2 * r * MM


def test_friction_angle_is_drawn_on_the_slider():
    """The friction lesson's main idea on the slider's free body: the guide's normal, dashed, and ρ between it and
    G14, with tan ρ = μ while the slider slides; at a dead centre, the normal alone."""
    p = catalog.load("slider_crank_friction")
    mu = next(j.mu for j in p.mechanism.joints if getattr(j, "mu", 0) > 0)
    c = construct_forces(p.kinematics(at=[math.radians(60)]), 0)
    d = draw.draw_free_body(c, 4)
    assert d.labels["rho"].get_text() == f"ρ = {math.degrees(math.atan(mu)):.2f}°"
    assert d.labels["normal"].get_text() == "normal"
    normal = next(ln for ln in d.ax.lines if ln.get_linestyle() == "--" and ln.get_color() == draw.style.STYLE.ink)
    x, y = normal.get_data()
    assert abs(x[1] - x[0]) < 1e-9 * abs(y[1] - y[0])  # the guide runs along x: its normal is vertical
    assert abs(x[0] - c.points[4]["B"][0] * MM) < 1e-9  # through the slider's point
    # The arc between the normal and G14, as wide as ρ.
    arc = next(ln for ln in d.ax.lines if len(ln.get_xdata()) == 24)
    ax_, ay_ = arc.get_data()
    ends = np.arctan2(ay_[[0, -1]] - c.points[4]["B"][1] * MM, ax_[[0, -1]] - c.points[4]["B"][0] * MM)
    assert abs(abs(ends[1] - ends[0]) - math.atan(mu)) < 1e-9
    # A frictionless slider (the double slider's) has neither.
    d = draw.draw_free_body(construct_forces(catalog.load("double_slider").kinematics(), 0), 4)
    assert "rho" not in d.labels and "normal" not in d.labels


def test_far_inertia_line_is_drawn_nearer_with_a_broken_dimension():
    """The strip cutter's coupler at 140°: its resultant acts 1228 mm from G₃, eight times the link's size. Drawn
    true, the link was a speck beside it; now the line is drawn nearer and the dimension says so."""
    c = construct_forces(catalog.load("strip_cutter").kinematics(at=[math.radians(140)]), 0)
    d = draw.draw_free_body(c, 3)
    h = c.inertia[3]["h"] * MM
    assert d.labels["h"].get_text() == f"h = {h:.4g} mm (not to scale)"
    G = np.array(c.G[3]) * MM
    tail, tip = tail_tip(d.arrows["R3i"])
    F = np.array(c.inertia[3]["F"])
    e = F / np.hypot(*F)
    drawn_h = abs(float(e[0] * (tail - G)[1] - e[1] * (tail - G)[0]))
    size = max(math.dist(a, b) for a in c.points[3].values() for b in c.points[3].values()) * MM
    assert drawn_h < 0.8 * size < h
    zigzag = [ln for ln in d.ax.lines if len(ln.get_xdata()) == 4]
    assert zigzag  # the break mark
    # A near line is drawn true: the double slider's h = 33.33 mm.
    d = draw.draw_free_body(construct_forces(catalog.load("double_slider").kinematics(), 0), 3)
    assert d.labels["h"].get_text() == "h = 33.33 mm"


def test_a_polygon_on_one_line_is_drawn_in_two_lanes():
    """The pinion's two-force polygon F₂₃ + F₁₃ = 0 used to be one line with both labels on it."""
    from graphkin.draw.polygon import LANE

    c = construct_forces(catalog.load("gearset").kinematics(), 0)
    step = next(s for s in c.steps if s.polygon and [a.name for a in s.polygon] == ["F23", "F13"])
    d = draw.draw_force_polygon(step, scale=c.force_scale)
    (t1, h1), (t2, h2) = (np.array(d.ends[n]) for n in ("F23", "F13"))
    u = (h1 - t1) / np.hypot(*(h1 - t1))
    gap = abs(float(u[0] * (t2 - t1)[1] - u[1] * (t2 - t1)[0]))  # [mm of drawing] between the two arrows
    assert gap == pytest.approx(2 * LANE * data_per_point(d.ax), rel=0.2)
    r = draw.measuring_renderer(d.ax.figure)
    b1, b2 = (d.labels[n].get_window_extent(r) for n in ("F23", "F13"))
    assert not b1.overlaps(b2)


def test_mechanism_has_a_length_scale_and_polygons_their_drawing_scale():
    c = construct_forces(catalog.load("double_slider").kinematics(), 0)
    assert any(re.fullmatch(r"\d+ mm", t) for t in texts_of(draw.draw_mechanism(c).ax))
    fig = draw.draw_solution(c)
    polygons = [ax for ax in fig.axes if any((p.get_gid() or "").startswith("polygon:") for p in ax.patches)]
    assert polygons
    for ax in polygons:
        assert any(t.endswith(f"(1 mm = {c.force_scale:g} N)") for t in texts_of(ax)), texts_of(ax)
    table = next(ax for ax in fig.axes if ax.tables)
    assert not any("force scale" in t for t in texts_of(table))  # with the polygons now, not under the table


@pytest.mark.parametrize("name", NAMES)
def test_solution_figure_has_no_empty_row(name):
    """single_link.png was half blank: a row for one free body, another for one polygon."""
    c = construct_forces(catalog.load(name).kinematics(), 0)
    fig = draw.draw_solution(c)
    panels = [ax for ax in fig.axes if ax.get_subplotspec() is not None]
    rows = {ax.get_subplotspec().rowspan.start for ax in panels}
    nrows = panels[0].get_subplotspec().get_gridspec().nrows
    assert rows == set(range(nrows))
    cells = len(c.mechanism.moving) + 1 + sum(1 for s in c.steps if s.polygon)
    assert nrows == 1 + math.ceil(cells / 4)


@pytest.mark.parametrize("name, shown", [("gearset", {"P"}), ("epicyclic_khurmi", None)])
def test_pitch_points_are_told_apart_where_there_are_several(name, shown):
    """One mesh's pitch point is P, as the books write it; a train's several are named by their gears (P23, P34)."""
    c = construct_forces(catalog.load(name).kinematics(), 0)
    d = draw.draw_mechanism(c)
    keys = {f"P{i}{j}" for i, j in c.pitch_points}
    texts = {plain(d.labels[k].get_text()) for k in keys}
    labelled = {p for t in texts for p in re.split(r",\s*", t) if p.startswith("P")}
    assert labelled == (shown if shown is not None else keys)
