"""A design study drawn: what each choice costs, and the chosen design marked.

The picture follows the number of fields that take more than one value (Norton, *Design of Machinery*, ch. 11,
draws a design's cost against one parameter; two need a map):

* one: each figure of merit against it, a small panel each, the designs that cannot be assembled a gap;
* two: a contour map of one figure of merit over both, the designs that cannot be assembled crossed out;
* more: parallel coordinates, each design a line through its fields' values and its figures, coloured by one
  figure of merit.

The chosen design of the grid (:func:`graphkin.cycle.choice.best`) is a black star, or a black line, in each; the
optimum between the grid's values (:func:`graphkin.cycle.optimum.optimum`) a red diamond, or a red line. The
figures of merit are drawn in the units asked for (:class:`graphkin.units.systems.UnitSystem`, ``--units``; SI
by default, μ in degrees), the fields' values in the unit the study writes them in, as its table and CSV show them.

>>> from graphkin.cycle import study
>>> from graphkin.draw.study import draw_study
>>> s = study("strip_cutter", {"links[1].mass": ["2 kg", "3 kg", "4 kg"]}, n=36)
>>> fig = draw_study(s, s.best("torque_peak"))
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
from matplotlib.figure import Figure

from graphkin.cycle.choice import field_axis, figure_values, figures
from graphkin.errors import GraphkinError
from graphkin.units.systems import SI, UnitSystem

__all__ = ["OPTIMUM", "draw_study"]

_NAMES = {"torque_peak": "peak driving effort", "torque_rms": "RMS driving effort", "I_s": "flywheel I_s",
          "shaking_force_peak": "peak shaking force", "shaking_moment_peak": "peak shaking moment",
          "transmission_angle_min": "least transmission angle μ"}

OPTIMUM = "tab:red"
"""The colour of the optimum between the grid's values (a diamond, or a line), the grid's chosen design black."""


def _shown(study, name: str, units: UnitSystem = SI, designs=None) -> tuple[np.ndarray, str]:
    """A figure of merit of every design (or of ``designs``) as drawn, in ``units``, and its axis label."""
    x = figure_values(study if designs is None else dataclasses.replace(study, designs=tuple(designs)), name, "merit")
    dim = figures(study)[name]
    words = _NAMES.get(name, f"peak |{name.removesuffix('_peak')}|")
    return units.show(x, dim), f"{words} [{units.symbol(dim)}]"


def _axis(study, k: int) -> tuple[np.ndarray, str, list | None]:
    """Field k's values as positions on an axis, its label, and tick labels where they are not numbers."""
    values = study.grid[k]
    numbers = field_axis(values)
    if numbers is None:  # points or tables: one tick each, labelled as the file writes them
        written = [f"({', '.join(map(str, v))})" if isinstance(v, (list, tuple)) else str(v) for v in values]
        return np.arange(len(values), dtype=float), study.fields[k], written
    unit, x = numbers
    return x, f"{study.fields[k]} [{unit}]" if unit else study.fields[k], None


def _design_axes(study, varied: list) -> list[np.ndarray]:
    """Each design's position on each varied field's axis (the grid's order: the last field fastest)."""
    mesh = np.meshgrid(*(_axis(study, k)[0] for k in range(len(study.fields))), indexing="ij")
    return [m.ravel() for m in (mesh[k] for k in varied)]


def _optimum_at(study, optimum, k: int) -> float:
    """The optimum's position on field k's axis: its value in the grid's unit, or the tick of a value as written."""
    if field_axis(study.grid[k]) is not None:
        return float(optimum.x[k])
    return float(list(study.grid[k]).index(optimum.values[k]))


def _ticks(ax, which: str, labels: list | None) -> None:
    if labels is not None:
        getattr(ax, f"set_{which}ticks")(range(len(labels)), labels, rotation=30 if which == "x" else 0, fontsize=7)


def draw_study(study, choice=None, *, merit: str | None = None, optimum=None,
               units: UnitSystem | None = None) -> Figure:
    """Draw a study: each figure of merit against one field, a contour map over two, parallel coordinates over more.

    Parameters
    ----------
    study : graphkin.cycle.studies.Study
        The designs (:func:`graphkin.cycle.study`).
    choice : graphkin.cycle.choice.Choice, optional
        The best design of the grid (:meth:`Study.best`), marked in black.
    merit : str, optional
        The figure of merit a contour map shows or parallel coordinates colour by (a name of
        :func:`graphkin.cycle.choice.figures`); default the choice's, else the optimum's, else ``"torque_peak"``.
    optimum : graphkin.cycle.optimum.Optimum, optional
        The optimum between the grid's values (:meth:`Study.optimum`), marked in red (:data:`OPTIMUM`).
    units : UnitSystem, optional
        The units of the figures of merit (``--units``); default SI (μ in degrees). The fields' values are drawn
        in the unit the study writes them in.

    Returns
    -------
    matplotlib.figure.Figure
        The figure; :func:`graphkin.draw.save` writes it.

    Raises
    ------
    GraphkinError
        If ``merit`` names no figure of the study or one no design has, or no design can be assembled (there is
        nothing to draw).
    """
    units = SI if units is None else units
    merit = merit or (choice.minimise if choice is not None else
                      optimum.objective if optimum is not None else "torque_peak")
    z = figure_values(study, merit, "merit")
    if not any(d.ok for d in study.designs):
        raise GraphkinError(f"{study.problem}: no design of the study can be assembled over its cycle; "
                            "there is nothing to draw")
    if np.isnan(z).all():  # e.g. μ of a linkage that is not a four-bar: an empty map would say nothing
        raise GraphkinError(f"merit {merit!r}: not defined for any design of {study.problem}; choose another")
    varied = [k for k, v in enumerate(study.grid) if len(v) > 1] or [0]
    chosen = None if choice is None else choice.index
    if len(varied) == 1:
        return _against_one(study, varied[0], chosen, optimum, units)
    if len(varied) == 2:
        return _contours(study, varied, merit, chosen, optimum, units)
    return _parallel(study, varied, merit, chosen, optimum, units)


def _failed_note(study) -> str:
    bad = sum(not d.ok for d in study.designs)
    return f"; {bad} of {len(study.designs)} designs cannot be assembled (not drawn)" if bad else ""


def _against_one(study, k: int, chosen: int | None, optimum, units: UnitSystem) -> Figure:
    """Small multiples: each defined figure of merit against field k, the chosen design a star in each and the
    optimum a diamond."""
    (x,) = _design_axes(study, [k])
    _, label, ticks = _axis(study, k)
    names = [n for n in figures(study) if not np.isnan(figure_values(study, n)).all()]
    ncols = min(4, len(names))
    nrows = math.ceil(len(names) / ncols)
    fig = Figure(figsize=(3.3 * ncols, 2.7 * nrows), dpi=100, layout="constrained")
    axes = fig.subplots(nrows, ncols, squeeze=False).ravel()
    for ax, name in zip(axes, names):
        y, ylabel = _shown(study, name, units)
        ax.plot(x, y, ".-", color="tab:blue", lw=1.2, ms=3)
        if chosen is not None:
            ax.plot(x[chosen], y[chosen], "*", color="black", ms=11, zorder=3, clip_on=False)
        if optimum is not None:
            ax.plot(_optimum_at(study, optimum, k), _shown(study, name, units, [optimum.design])[0][0], "D",
                    mfc="none", mec=OPTIMUM, mew=1.6, ms=9, zorder=4, clip_on=False)  # hollow: a star shows through
        ax.set_ylabel(ylabel, fontsize=8)
        ax.set_xlabel(label, fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(alpha=0.3)
        _ticks(ax, "x", ticks)
    for ax in axes[len(names):]:
        ax.set_visible(False)
    fig.suptitle(f"{study.problem}: {len(study.designs)} designs{_failed_note(study)}"
                 + ("" if chosen is None else "; ★ the chosen design")
                 + ("" if optimum is None else f"; ◇ the optimum of {optimum.objective}"), fontsize=9)
    return fig


def _contours(study, varied: list, merit: str, chosen: int | None, optimum, units: UnitSystem) -> Figure:
    """A contour map of one figure of merit over two fields, the designs that cannot be assembled crossed out."""
    j, i = varied  # the later field across, the earlier up
    x, y = _design_axes(study, [i, j])
    z, zlabel = _shown(study, merit, units)
    Z = z.reshape(len(study.grid[j]), len(study.grid[i]))  # the fields not varied have one value
    X, Y = x.reshape(Z.shape), y.reshape(Z.shape)
    fig = Figure(figsize=(6.4, 5.0), dpi=100, layout="constrained")
    ax = fig.subplots()
    if np.isfinite(Z).sum() >= 4 and np.nanmax(Z) > np.nanmin(Z):
        filled = ax.contourf(X, Y, np.ma.masked_invalid(Z), levels=14, cmap="viridis")
        lines = ax.contour(X, Y, np.ma.masked_invalid(Z), levels=filled.levels, colors="white", linewidths=0.5)
        ax.clabel(lines, lines.levels[::2], fontsize=7, fmt="%.4g")
        fig.colorbar(filled, ax=ax, label=zlabel)
    else:  # too few or equal values for contours: the designs as coloured dots
        dots = ax.scatter(x, y, c=z, cmap="viridis", s=40)
        fig.colorbar(dots, ax=ax, label=zlabel)
    bad = ~np.isfinite(z)
    if bad.any():
        ax.plot(x[bad], y[bad], "x", color="0.45", ms=5, clip_on=False, label="cannot be assembled" if any(
            not d.ok for d in study.designs) else f"{merit} not defined")
    if chosen is not None:
        ax.plot(x[chosen], y[chosen], "*", color="black", mec="white", ms=16, clip_on=False, zorder=3,
                label="the chosen design")
    if optimum is not None:
        ax.plot(_optimum_at(study, optimum, i), _optimum_at(study, optimum, j), "D", mfc="none", mec=OPTIMUM,
                mew=2.0, ms=11, clip_on=False, zorder=4, label=f"the optimum of {optimum.objective}")
    if bad.any() or chosen is not None or optimum is not None:
        ax.legend(fontsize=8, loc="best")
    _, xlabel, xticks = _axis(study, i)
    _, ylabel, yticks = _axis(study, j)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    _ticks(ax, "x", xticks)
    _ticks(ax, "y", yticks)
    ax.set_title(f"{study.problem}: {zlabel}", fontsize=9)
    return fig


def _parallel(study, varied: list, merit: str, chosen: int | None, optimum, units: UnitSystem) -> Figure:
    """Parallel coordinates: each design that assembles a line through its fields and its figures of merit, each
    axis scaled from its least to its largest value, coloured by ``merit``; the chosen design in black, the
    optimum in red."""
    from matplotlib import colormaps
    from matplotlib.cm import ScalarMappable
    from matplotlib.collections import LineCollection
    from matplotlib.colors import Normalize

    ok = np.array([d.ok for d in study.designs])
    columns = [(c, _axis(study, k)[1]) for c, k in zip(_design_axes(study, varied), varied)]
    shown = [n for n in figures(study) if n in _NAMES and np.isfinite(figure_values(study, n)[ok]).any()]
    columns += [_shown(study, n, units) for n in shown]
    V = np.array([c for c, _ in columns])[:, ok]
    low, high = np.nanmin(V, axis=1), np.nanmax(V, axis=1)
    span = np.where(high > low, high - low, 1.0)
    U = (V - low[:, None]) / span[:, None]
    colour, clabel = _shown(study, merit, units)
    norm = Normalize(np.nanmin(colour[ok]), np.nanmax(colour[ok]))
    cmap = colormaps["viridis"]
    fig = Figure(figsize=(1.6 * len(columns) + 2, 4.8), dpi=100, layout="constrained")
    ax = fig.subplots()
    at = np.arange(len(columns))
    # One collection for all the designs: a study may have thousands, and a line each would take minutes to save.
    lines = LineCollection([np.column_stack([at, d]) for d in U.T], colors=[
        cmap(norm(c)) if np.isfinite(c) else "0.6" for c in colour[ok]], linewidths=0.8, alpha=0.6)
    ax.add_collection(lines)
    if chosen is not None:
        ax.plot(at, U[:, int(np.flatnonzero(ok).tolist().index(chosen))], color="black", lw=2.4,
                label="the chosen design")
    if optimum is not None:  # on the grid's scales: between its values, its figures maybe beyond the grid's
        mine = [_optimum_at(study, optimum, k) for k in varied]
        mine += [_shown(study, n, units, [optimum.design])[0][0] for n in shown]
        ax.plot(at, (np.array(mine) - low) / span, color=OPTIMUM, lw=2.0, ls="--", marker="D", ms=5, zorder=4,
                label=f"the optimum of {optimum.objective}")
    if chosen is not None or optimum is not None:
        ax.legend(fontsize=8, loc="lower right", bbox_to_anchor=(1.0, 1.06))
    for a, lo, hi in zip(at, low, high):
        ax.axvline(a, color="0.3", lw=0.8)
        ax.text(a, -0.04, f"{lo:.4g}", ha="center", va="top", fontsize=7)
        ax.text(a, 1.04, f"{hi:.4g}", ha="center", va="bottom", fontsize=7)
    ax.set_xticks(at, [label for _, label in columns], rotation=20, ha="right", fontsize=7)
    ax.set_yticks([])
    ax.set_xlim(-0.3, len(columns) - 0.7)  # a collection does not widen the axes
    ax.set_ylim(-0.12, 1.12)
    for side in ("top", "right", "left"):
        ax.spines[side].set_visible(False)
    fig.colorbar(ScalarMappable(norm, cmap), ax=ax, label=clabel)
    ax.set_title(f"{study.problem}: {int(ok.sum())} designs{_failed_note(study)}", fontsize=9)
    return fig
