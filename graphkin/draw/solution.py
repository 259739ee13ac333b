"""The side-by-side figure: mechanism, free bodies, force polygons and both routes' numbers."""

from __future__ import annotations

import math

import numpy as np
from matplotlib.figure import Figure

from graphkin.draw import style as _style
from graphkin.draw.axes import PanelAxes
from graphkin.draw.convention import draw_sign_convention
from graphkin.draw.fbd import draw_free_body
from graphkin.draw.mechanism import draw_mechanism
from graphkin.draw.polygon import draw_force_polygon, step_title
from graphkin.draw.text import input_text, sub
from graphkin.notation import num, polar_text

NCOLS = 4


def _effort_text(value: float, kind: str) -> str:
    if not math.isfinite(value):
        return "—"
    if kind == "crank":
        return f"{num(abs(value))} N·m {'CCW' if value > 0 else 'CW' if value < 0 else ''}".strip()
    return f"{num(value)} N along the guide"


def comparison_rows(construction, analytical=None) -> list[tuple[str, str, str, str]]:
    """The table's rows: (force name, analytical value, graphical value, relative difference) as text.

    Joint forces in polar form (``27.06 N ∠ −73.78°``), the driver last. The
    relative difference is |graphical − analytical| / |analytical| (relative
    to the largest force where a force is about zero); "—" without an
    analytical result.
    """
    c = construction
    mech = c.mechanism
    idx = c.index
    rows = []
    keys = list(analytical.forces) if analytical is not None else list(c.forces)
    if analytical is not None:
        scale = max([float(np.hypot(*analytical.force(*k)[idx])) for k in keys] + [1e-300])
    for i, j in keys:
        letter = mech.joint_between(i, j).force_letter
        name = f"{letter}{i}{j}" if i < 10 and j < 10 else f"{letter}{i},{j}"
        G = c.force(i, j) if (min(i, j), max(i, j)) in c.forces else np.array([np.nan, np.nan])
        if analytical is not None:
            A = analytical.force(i, j)[idx]
            d = float(np.hypot(*(G - A)) / max(float(np.hypot(*A)), 1e-12 * scale))
            rows.append((name, polar_text(A), polar_text(G), _diff(d)))
        else:
            rows.append((name, "—", polar_text(G), "—"))
    kind = mech.driver.kind
    if analytical is not None:
        e = float(analytical.effort[idx])
        d = abs(c.effort - e) / abs(e) if e else abs(c.effort)
        rows.append((c.driver_name, _effort_text(e, kind), _effort_text(c.effort, kind), _diff(d)))
    else:
        rows.append((c.driver_name, "—", _effort_text(c.effort, kind), "—"))
    return rows


def _diff(d: float) -> str:
    if not math.isfinite(d):
        return "—"
    if d == 0:
        return "0"
    return f"{d:.1e}".replace("-", "−")


def draw_table(construction, analytical=None, *, ax, **style):
    """The comparison table on ``ax``; returns the matplotlib Table."""
    s = _style.resolve(**style)
    ax.set_axis_off()
    rows = comparison_rows(construction, analytical)
    header = ["Force", "Analytical", "Graphical", "Rel. difference"]
    cells = [[sub(r[0]), r[1], r[2], r[3]] for r in rows]
    table = ax.table(cellText=cells, colLabels=header, loc="upper center", cellLoc="center",
                     colWidths=[0.14, 0.33, 0.33, 0.2])
    table.auto_set_font_size(False)
    table.set_fontsize(s.label_size)
    table.scale(1.0, 1.55)
    for (r, col), cell in table.get_celld().items():
        cell.set_edgecolor("#9A9A9A")
        cell.set_linewidth(0.6)
        if r == 0:
            cell.set_facecolor("#EDEDED")
            cell.get_text().set_fontweight("bold")
        elif r == len(rows):
            cell.set_facecolor("#F7EEF4")  # the driver's row
    ax.set_title("Both routes", fontsize=s.title_size, color=s.ink)
    c = construction
    if c.warnings:
        ax.text(0.5, 0.02, "\n".join(f"warning: {w}" for w in c.warnings), transform=ax.transAxes, ha="center",
                va="bottom", fontsize=s.small_size, color=s.unknown, wrap=True)
    return table


def draw_solution(construction, analytical=None, *, figsize=None, **style) -> Figure:
    """The whole graphical solution of one position, with the analytical one beside it.

    Top row: the mechanism at the position and a table of every joint force
    and the driving effort by both routes with their relative difference.
    Then, four to a row in reading order, the free-body diagram of each
    moving link, the sign convention, and every force polygon of the
    construction in the order it is built (its scale bar also gives the
    drawing scale, 1 mm = … N).

    Parameters
    ----------
    construction : graphkin.graphical.Construction
    analytical : graphkin.analytical.ForceAnalysis, optional
        The matrix solution of the same kinematics; compared at ``construction.index``.
    figsize : (float, float), optional
        Inches; by default 4 panels wide and as tall as the content needs.
    **style
        Overrides of :class:`graphkin.draw.style.Style` fields.

    Returns
    -------
    matplotlib.figure.Figure
    """
    s = _style.resolve(**style)
    c = construction
    mech = c.mechanism
    title = f"{mech.title or 'Mechanism'} — {input_text(c)}"
    if not c.valid:
        fig = Figure(figsize=figsize or (8, 3))
        fig.suptitle(title, fontsize=s.suptitle_size)
        fig.text(0.5, 0.5, f"No solution at this position: {c.reason}", ha="center", va="center",
                 fontsize=s.label_size, color=s.unknown, wrap=True)
        return fig
    polys = [st for st in c.steps if st.polygon]
    moving = list(mech.moving)
    # Free bodies, the sign convention and the polygons in reading order, four to a row: no half-empty rows.
    cells = len(moving) + 1 + len(polys)
    nrows = 1 + math.ceil(cells / NCOLS)
    if figsize is None:
        figsize = (4.3 * NCOLS, 4.1 * nrows + 0.9)
    fig = Figure(figsize=figsize, dpi=100)
    top = 1 - 1.3 / figsize[1]
    gs = fig.add_gridspec(nrows, NCOLS, left=0.02, right=0.98, top=top, bottom=0.02, hspace=0.28, wspace=0.12)
    fig.suptitle(title, fontsize=s.suptitle_size, y=1 - 0.25 / figsize[1], va="top")
    fig.text(0.5, 1 - 0.62 / figsize[1],
             "Graphical route (free bodies, force polygons) beside the analytical one ([A]{x} = {b});  "
             "blue: known loads,  vermillion: unknown forces,  purple: the driver",
             ha="center", va="top", fontsize=s.caption_size, color="#444444")
    ax = fig.add_subplot(gs[0, 0:2], axes_class=PanelAxes)
    draw_mechanism(c, ax=ax, **style)
    ax.set_title(f"Mechanism at {input_text(c)} (lengths in mm)", fontsize=s.title_size, color=s.ink)
    ax = fig.add_subplot(gs[0, 2:4], axes_class=PanelAxes)
    draw_table(c, analytical, ax=ax, **style)

    def cell(k):
        r, col = divmod(k, NCOLS)
        return fig.add_subplot(gs[1 + r, col], axes_class=PanelAxes)

    for k, link in enumerate(moving):
        draw_free_body(c, link, ax=cell(k), **style)
    draw_sign_convention(ax=cell(len(moving)), **style)
    for k, step in enumerate(polys, start=len(moving) + 1):
        draw_force_polygon(step, scale=c.force_scale, ax=cell(k), title=step_title(step), driver_name=c.driver_name,
                           scale_note=True, **style)
    return fig
