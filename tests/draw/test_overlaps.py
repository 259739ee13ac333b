"""Nothing written on anything: labels measured in the rendered figure, over a sweep of positions.

For every catalog problem, at 12 positions over its range, the side-by-side
solution figure (``draw_solution``: mechanism, free bodies, force polygons,
table) and the step frames are laid out by matplotlib, and then
measured in display coordinates from the artists themselves:

* every text's box (``Text.get_window_extent``; a table or legend as one box);
* every drawn outline: force and couple arrows (their drawn path, head
  included), link bars (the stroked band), plates, slider blocks, gears and
  ground symbols (patch edges), rails and scale bars (solid lines), pins and
  centres of mass (their markers), each as wide as it is stroked, and the
  hatched areas of ground and rails.

No two texts may overlap, and no text may cover an outline, by more than
:data:`TOL` pixels. Dashed lines (lines of action, centre lines, the guide's
normal) are not outlines: a label may cross one, over its white halo.

The measurement knows nothing of how the labels were placed (it does not use
:class:`graphkin.draw.labels.Labeler` or its obstacle lists), so it catches a
label the Labeler was not told about, an obstacle it missed, or a placement
bug.
"""

from __future__ import annotations

import contextlib
import math

import numpy as np
import pytest

pytest.importorskip("matplotlib")
shapely = pytest.importorskip("shapely")

from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import FancyArrowPatch  # noqa: E402

from graphkin import catalog, draw  # noqa: E402
from graphkin.graphical import construct_forces  # noqa: E402

# Lays out every catalog figure at 12 positions (the longest file of the suite): make test runs it, make check does not.
pytestmark = pytest.mark.slow

TOL = 1.5
"""How far [px, at the figures' 100 dpi] a text's box may run into another box or onto an outline.

A text's box runs from the font's descender to above its capitals, and its
edges are rounded out to whole pixels: for the 8–9.5 pt labels at 100 dpi the
top 1–2 px and the bottom 2–3 px of the box are blank unless a subscript or a
descender reaches them, and the labels' white halo (2.6 pt) paints over a thin
line there anyway. 1.5 px (about 1 pt) is within that blank: an overlap the
eye cannot see passes, anything that touches a letter fails.
"""

POSITIONS = 12
"""Positions per problem: every 30° of a crank, or 12 steps over a slider's range."""


# -- what the figure shows, in display coordinates -----------------------------------------------


def _solid(style) -> bool:
    return style in ("-", "solid") or style is None


def _px(fig, points: float) -> float:
    return points * fig.dpi / 72.0


def _lines_of(path, transform):
    """The polylines of a path in display coordinates (curves flattened, NaN breaks split)."""
    out = []
    for poly in path.to_polygons(transform=transform, closed_only=False):
        poly = np.asarray(poly, float)
        pieces = np.split(poly, np.flatnonzero(~np.isfinite(poly).all(axis=1)))
        for piece in pieces:
            piece = piece[np.isfinite(piece).all(axis=1)]
            if len(piece) >= 2:
                out.append(piece)
            elif len(piece) == 1:
                out.append(np.vstack([piece, piece]))
    return out


def _clipped(artist, geom, ax):
    """The part of ``geom`` that is drawn: inside the axes when the artist is clipped to them."""
    if artist.get_clip_on() and (artist.get_clip_path() is not None or artist.get_clip_box() is not None):
        return geom.intersection(shapely.box(*ax.bbox.extents))
    return geom


def outlines(ax, dashed=False):
    """(what, shapely geometry in display px) of everything drawn on ``ax`` that a text must not cover.

    Dashed lines count only with ``dashed`` (the curves of a plot, where a dash
    pattern tells one curve from another).
    """
    fig = ax.figure
    out = []

    def add(what, artist, geom):
        geom = _clipped(artist, geom, ax)
        if not geom.is_empty:
            out.append((what, geom))

    for p in ax.patches:
        if not p.get_visible():
            continue
        lw = p.get_linewidth()
        if isinstance(p, FancyArrowPatch):
            what = f"arrow {p.get_gid() or ''}".strip()
        elif p.get_hatch():
            # Hatching (ground, rails): the whole area is drawn on.
            for ring in _lines_of(p.get_path(), p.get_transform()):
                if len(ring) >= 3:
                    add("hatching", p, shapely.Polygon(ring).buffer(0))
            continue
        elif lw <= 0 or p.get_edgecolor()[3] == 0 or not (dashed or _solid(p.get_linestyle())):
            continue  # hatching only, or a dashed reference circle
        else:
            what = f"outline {type(p).__name__}"
        half = max(_px(fig, lw) / 2, 0.5)
        for line in _lines_of(p.get_path(), p.get_transform()):
            add(what, p, shapely.LineString(line).buffer(half, cap_style="flat"))
    for ln in ax.lines:
        if not ln.get_visible() or type(ln) is not Line2D:
            continue  # an axline is a line of action drawn across the view
        xy = ln.get_transform().transform(np.column_stack([ln.get_xdata(orig=False), ln.get_ydata(orig=False)]))
        if (dashed or _solid(ln.get_linestyle())) and ln.get_linestyle() not in ("None", "none", "", " ") \
                and ln.get_linewidth() > 0 and len(xy) > 1:
            half = max(_px(fig, ln.get_linewidth()) / 2, 0.5)
            for piece in np.split(xy, np.flatnonzero(~np.isfinite(xy).all(axis=1))):
                piece = piece[np.isfinite(piece).all(axis=1)]
                if len(piece) >= 2:
                    shape = shapely.LineString(piece).buffer(half, cap_style="flat")
                    add(f"line {ln.get_gid() or ''}".strip(), ln, shape)
        marker = ln.get_marker()
        if marker not in (None, "None", "none", "", " "):
            r = _px(fig, ln.get_markersize() + ln.get_markeredgewidth()) / 2
            for x, y in xy[np.isfinite(xy).all(axis=1)]:
                add("marker", ln, shapely.Point(x, y).buffer(r))
    return out


def texts(fig, renderer):
    """(what, box (x0, y0, x1, y1) [px]) of every text drawn: labels, titles, figure texts, tables, legends, and
    the tick labels and axis labels of axes that show them."""
    out = []
    for t in fig.texts:
        if t.get_visible() and t.get_text().strip():
            out.append((f"figure text {t.get_text()!r}", t.get_window_extent(renderer)))
    for k, ax in enumerate(fig.axes):
        if not ax.get_visible():
            continue
        shown = [ax.title, *ax.texts]
        if ax.axison:
            for axis in ax._axis_map.values():
                shown.append(axis.label)
                shown += [tick.label1 for tick in axis._update_ticks() if tick.label1.get_visible()]
        for t in shown:
            if t.get_visible() and t.get_text().strip():
                out.append((f"axes {k} {t.get_text()!r}", t.get_window_extent(renderer)))
        for table in ax.tables:
            out.append((f"axes {k} table", table.get_window_extent(renderer)))
        if ax.get_legend() is not None:
            out.append((f"axes {k} legend", ax.get_legend().get_window_extent(renderer)))
    return [(w, tuple(map(float, b.extents))) for w, b in out]


def _shrunk(box, by):
    x0, y0, x1, y1 = box
    return shapely.box(x0 + by, y0 + by, max(x0 + by, x1 - by), max(y0 + by, y1 - by))


def _depth(a, b) -> float:
    """How far two geometries overlap [px]: the smaller side of their intersection's bounds."""
    inter = a.intersection(b)
    if inter.is_empty:
        return 0.0
    x0, y0, x1, y1 = inter.bounds
    return float(min(x1 - x0, y1 - y0))


def laid_out(fig):
    """Lay ``fig`` out as matplotlib draws it, and a renderer to measure it with.

    A figure left unchanged since its last drawing (matplotlib's ``stale`` unset) is as it was laid out then, and
    is not drawn again: a figure measured twice (:func:`overlaps`, then
    :func:`tests.draw.test_polygon_labels.astray`) is drawn once, most of a measure's time.
    """
    if fig.stale:
        with _path_effects_not_drawn():
            fig.draw_without_rendering()
    return fig.canvas.get_renderer()


@contextlib.contextmanager
def _path_effects_not_drawn():
    """matplotlib's drawing without rendering, for path effects too.

    ``draw_without_rendering`` makes every drawing call of its renderer a no-op, but a text or patch with a path
    effect (the labels' white halo) draws through a ``PathEffectRenderer``, which first turns the text into its
    outline (about 40 % of laying a figure of labels out) and then hands it to those no-ops. Its drawing calls
    are no-ops here too: what is laid out (positions, limits, ticks, boxes) is the same, only nothing is drawn.
    """
    from matplotlib.patheffects import PathEffectRenderer

    names = ("draw_path", "draw_markers", "draw_path_collection", "draw_text")
    own = {name: PathEffectRenderer.__dict__[name] for name in names if name in PathEffectRenderer.__dict__}
    for name in names:
        setattr(PathEffectRenderer, name, lambda *args, **kwargs: None)
    try:
        yield
    finally:
        for name in names:
            if name in own:
                setattr(PathEffectRenderer, name, own[name])
            else:
                delattr(PathEffectRenderer, name)


def overlaps(fig, panels=None, tol=TOL, dashed=False, page=False):
    """Every text on a text and every text on an outline in ``fig`` deeper than ``tol`` px: list of (what, what, px).

    ``panels``: the axes whose outlines count (all by default). ``page``: a
    text must also lie wholly inside the figure (an image cut to the figure,
    as the explorer shows it).
    """
    renderer = laid_out(fig)
    boxes = texts(fig, renderer)
    found = []
    # Text on text: each box shrunk by tol/2 on every side, so two boxes meet only if they overlap by more than tol.
    shrunk = [_shrunk(b, tol / 2) for _, b in boxes]
    tree = shapely.STRtree(shrunk)
    for i, j in zip(*tree.query(shrunk, predicate="intersects")):
        if i < j:
            found.append((boxes[i][0], boxes[j][0], round(_depth(shrunk[i], shrunk[j]) + tol, 1)))
    # Text on outline: the box shrunk by tol on every side.
    inner = [_shrunk(b, tol) for _, b in boxes]
    for ax in panels if panels is not None else fig.axes:
        shapes = outlines(ax, dashed)
        if not shapes:
            continue
        tree = shapely.STRtree([g for _, g in shapes])
        for i, j in zip(*tree.query(inner, predicate="intersects")):
            found.append((boxes[i][0], shapes[j][0], round(_depth(inner[i], shapes[j][1]) + tol, 1)))
    if page:
        x0, y0, x1, y1 = fig.bbox.extents
        for what, b in boxes:
            out = max(x0 - b[0], y0 - b[1], b[2] - x1, b[3] - y1)
            if out > tol:
                found.append((what, "the figure's edge", round(out, 1)))
    return found


# -- the sweep -----------------------------------------------------------------------------------------


def _positions(problem, count=POSITIONS):
    """``count`` input positions [rad or m] over the problem's range: a turn of a crank, or the span where a
    slider-driven linkage assembles (as the explorer finds it)."""
    if problem.mechanism.driver.kind == "crank":
        return np.radians(np.arange(count) * 360.0 / count)
    from graphkin.widgets.positions import assembling_span

    lo, hi = assembling_span(problem, float(problem.q[0]), 360)
    return np.linspace(lo, hi, count + 2)[1:-1]


def _figure_position(name, problem):
    """The position figures/ draws the problem at (figures/build.py)."""
    import importlib.util
    from pathlib import Path

    spec = importlib.util.spec_from_file_location("_figures_build", Path(__file__).parents[2] / "figures" / "build.py")
    build = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(build)
    return build.AT.get(name, float(problem.q[0]))


def _where(c) -> str:
    return f"{math.degrees(c.q):.0f}°" if c.mechanism.driver.kind == "crank" else f"s = {c.q * 1e3:.0f} mm"


NAMES = catalog.names()


@pytest.mark.parametrize("name", NAMES)
def test_no_label_on_a_label_or_an_outline_in_the_solution_figure(name):
    """The side-by-side figure of figures/ and ``graphkin solve --figure``: at figures/' position and 6 others."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    problem = catalog.load(name)
    at = np.concatenate([[_figure_position(name, problem)], _positions(problem, POSITIONS // 2)])
    # A book's [given] values hold at its own position only (the step frames below draw that one with them).
    result = problem.without_given().solve(at=at)
    bad = []
    for i in range(len(at)):
        c = construct_forces(result.kinematics, i)
        if not c.valid:
            continue
        fig = draw.draw_solution(c, result)
        FigureCanvasAgg(fig)
        bad += [(_where(c), *o) for o in overlaps(fig)]
    assert not bad, "\n".join(map(str, bad))


@pytest.mark.parametrize("name", NAMES)
def test_no_label_on_a_label_or_an_outline_in_the_step_frames(name):
    """The construction's frames (figures/<problem>/stepNN.png) and the exercise's given figure, at figures/'
    position."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    problem = catalog.load(name)
    c = construct_forces(problem.kinematics(at=[_figure_position(name, problem)]), 0)
    bad = []
    for k, fig in enumerate(draw.draw_steps(c), start=1):
        FigureCanvasAgg(fig)
        bad += [(f"step {k}", *o) for o in overlaps(fig)]
    # And what a student is given for an exercise (the mechanism and the free bodies without the unknowns).
    fig = draw.draw_given(c)
    FigureCanvasAgg(fig)
    bad += [("given", *o) for o in overlaps(fig)]
    assert not bad, "\n".join(map(str, bad))


def _printed_polygons(name):
    """The handout's figure of force polygons (every polygon on one axes in paper mm, at one force scale) at
    figures/' position; None where there is no polygon there."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from graphkin.draw import paper
    from graphkin.handout.scaled import polygon_scale

    problem = catalog.load(name)
    c = construct_forces(problem.kinematics(at=[_figure_position(name, problem)]), 0)
    steps = [st for st in c.steps if st.polygon] if c.valid else []
    if not steps:
        return None
    fig = paper.draw_polygons(steps, force_scale=polygon_scale(steps), driver_name=c.driver_name)
    FigureCanvasAgg(fig)
    return fig


@pytest.mark.parametrize("name", NAMES)
def test_no_label_on_a_label_or_an_outline_in_a_printed_figure_of_polygons(name):
    """The polygons share one axes: each panel's labels keep off every title and the labels of the panels placed
    before them, not only off their own polygon."""
    fig = _printed_polygons(name)
    if fig is None:
        pytest.skip(f"{name} has no force polygon at figures/' position")
    bad = overlaps(fig)
    assert not bad, "\n".join(map(str, bad))


def test_the_measure_sees_a_label_on_another_panel_s_title():
    """The polygons share one axes, their titles are texts on it: a force's label put on the title of a panel other
    than its own (as the vertical engine's G₁₄ was, before the labels kept off the boxes other panels' titles take,
    ``Labeler.taken``) is found by the test above."""
    fig = _printed_polygons("engine_vertical_khurmi")
    ax = fig.axes[0]
    title = next(t for t in ax.texts if t.get_text().startswith("Link 2"))
    label = next(t for t in ax.texts if (t.get_gid() or "") == "label:polygon:G14")
    label.set_transform(title.get_transform())
    label.set_position(title.get_position())
    found = overlaps(fig)
    assert any("Link 2" in a and "G₁₄" in b or "G₁₄" in a and "Link 2" in b for a, b, _ in found), found


@pytest.mark.parametrize("name", [n for n in NAMES if catalog.load(n).mechanism.driver.kind == "crank"])
def test_no_label_on_a_label_or_a_curve_in_the_cycle_figure(name):
    """The whole-cycle figure (torque, polar joint forces; figures/<problem>_cycle.png): texts, tick labels and
    legends keep off each other, and the polar plot's radial tick labels keep off every curve."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from graphkin.cycle import sweep

    fig = draw.draw_cycle(sweep(catalog.load(name).without_given(), 120))
    FigureCanvasAgg(fig)
    polar = [ax for ax in fig.axes if ax.name == "polar"]
    bad = [o for o in overlaps(fig, panels=polar, dashed=True)
           if "text" not in o[0] or "'" not in o[0]]  # every text but a curve's own marker label
    assert not bad, "\n".join(map(str, bad))


def test_the_measure_sees_labels_left_where_they_were_first_put(monkeypatch):
    """The measurement does not rely on the Labeler: with placing switched off (every label at its first
    candidate spot), it finds labels on arrows, links and each other in the figure of figures/strip_cutter.png."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from graphkin.draw.labels import Labeler

    monkeypatch.setattr(Labeler, "place", lambda self: None)
    problem = catalog.load("strip_cutter")
    c = construct_forces(problem.kinematics(at=[_figure_position("strip_cutter", problem)]), 0)
    fig = draw.draw_solution(c)
    FigureCanvasAgg(fig)
    found = overlaps(fig)
    kinds = {what.split()[0] for _, what, _ in found}
    assert {"arrow", "line", "axes"} <= kinds, found
