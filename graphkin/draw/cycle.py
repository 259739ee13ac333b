"""Plots of a whole cycle: driving torque, joint forces in polar form, shaking, flywheel energy, joint-force index.

Each function plots a result of :mod:`graphkin.cycle` (compute there,
draw here) with matplotlib's object API only. Functions that draw on one
axes take ``ax=None`` (a new headless figure when omitted) and return a
:class:`Drawn`; its ``curves`` dict gives the main lines by role
(``"torque"``, ``"average"``, ``"F23"``, ...). :func:`draw_cycle` and
:func:`draw_shaking` (without ``ax``) return a Figure.

The input position is plotted in degrees for a crank (θ₁₂) and in mm for a
slider driver (s); forces in N, torques in N·m, energy in J.

Examples
--------
>>> from graphkin import catalog
>>> from graphkin.cycle import sweep
>>> from graphkin.draw.cycle import draw_cycle
>>> fig = draw_cycle(sweep(catalog.load("strip_cutter")), Cs=0.05)
>>> len(fig.axes)
3
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.artist import Artist
from matplotlib.figure import Figure
from matplotlib.ticker import Formatter, MaxNLocator

from graphkin.cycle.turn import TURN
from graphkin.draw import style as _style
from graphkin.draw.axes import Drawn, PanelAxes, line, markers, new_axes
from graphkin.draw.text import halo, sub, subscript
from graphkin.errors import GraphkinError
from graphkin.notation import num

SERIES = (_style.BLUE, _style.VERMILLION, _style.GREEN, _style.PURPLE, _style.ORANGE, _style.SKY_BLUE, _style.BLACK)
"""Colours of successive curves (Okabe–Ito, yellow left out: too faint on white)."""
DASHES = ("-", (0, (6, 2)), (0, (1.5, 1.5)), (0, (8, 2, 2, 2)))
"""Dash patterns of successive curves: colour is never the only cue (forces that coincide stay visible)."""
COINCIDE = 0.03
"""Two polar curves closer than this fraction of the plot's radius everywhere (within a band's half width) are
drawn as one line on a wide pale band."""


# -- helpers ---------------------------------------------------------------------------------------

def _is_crank(mechanism) -> bool:
    return mechanism.driver.crank


def _x(q, crank: bool) -> np.ndarray:
    """Input positions as plotted: degrees for a crank, mm for a slider."""
    q = np.asarray(q, float)
    return np.degrees(q) if crank else q * 1e3


def _theta(mechanism) -> str:
    """The crank angle's name as the problem numbers its links: ``θ₁₂``, or ``θ₀₁`` with the frame numbered 0."""
    d = mechanism.driver
    return "θ" + subscript(f"{d.frame}{d.link}")


def _input_axis(ax, crank: bool, symbol: str = "θ₁₂"):
    if crank:
        ax.set_xlabel(f"crank angle {symbol} [°]")
        ax.set_xlim(0, 360)
        ax.set_xticks(np.arange(0, 361, 60))
    else:
        ax.set_xlabel("slider position s [mm]")


def _rect_axes(ax, figsize=(6.4, 4.2)):
    ax = new_axes(ax, figsize=figsize)
    ax.grid(True, color=_style.LIGHT, lw=0.6)
    ax.set_axisbelow(True)
    return ax


def _polar_axes(ax, figsize=(5.0, 5.0)):
    if ax is None:
        return Figure(figsize=figsize, dpi=100).add_subplot(projection="polar")
    if getattr(ax, "name", "") != "polar":
        raise GraphkinError("a polar plot needs a polar axes: fig.add_subplot(projection='polar')")
    return ax


def _radial_labels(ax, curves, s):
    """Put the radial tick labels of a polar plot on the ray where they cross the fewest curves.

    Where the labels go is decided when the plot is drawn, once its layout
    is final (:class:`_RadialLabels`). ``curves`` is a list of (angle [rad],
    radius) arrays; a single point stands for a marker.
    """
    ax.tick_params(labelsize=s.small_size)
    ax.yaxis.set_major_locator(MaxNLocator(5))
    # Tick labels made later copy the first tick's properties, path effects included.
    for tick in ax.yaxis.get_major_ticks():
        tick.label1.set_path_effects([halo(2.2)])
    ax.add_artist(_RadialLabels(curves))


class _RadialLabels(Artist):
    """Chooses the ray of a polar plot's radial tick labels as the plot is drawn (an artist that draws nothing).

    Each of 36 rays (every 10°) is tried: the tick labels are laid out along
    it as matplotlib lays them out, and the curves' segments and markers
    that run through their boxes, and labels that cover each other, are
    counted. The ray with the fewest wins, the one nearest 112.5° (upper
    left, clear of the angle labels) among equals. A label that still
    crosses a curve there is left blank, while two others remain: its ring
    is read from its neighbours. Drawn first (lowest zorder), so the tick
    labels are drawn where it put them.
    """

    zorder = -100

    def __init__(self, curves):
        super().__init__()
        self.curves = [(np.ravel(a), np.ravel(r)) for a, r in curves]

    def draw(self, renderer):
        from graphkin.draw.labels import _hits_many

        ax = self.axes
        axis = ax.yaxis
        if not isinstance(axis.get_major_formatter(), _Hide):
            axis.set_major_formatter(_Hide(axis.get_major_formatter(), ()))
        formatter = axis.get_major_formatter()
        formatter.hidden = set()
        P, Q, W = [], [], []
        for a, r in self.curves:
            xy = ax.transData.transform(np.column_stack([a, r]))
            xy = xy[np.isfinite(xy).all(axis=1)]
            if len(xy) == 1:  # a marker
                P.append(xy), Q.append(xy), W.append([4.0])
            elif len(xy) > 1:
                P.append(xy[:-1]), Q.append(xy[1:]), W.append(np.full(len(xy) - 1, 2.0))
        if not P:
            return
        P, Q, W = np.concatenate(P), np.concatenate(Q), np.concatenate(W)
        r0, r1 = ax.get_ylim()
        rays = np.arange(0.0, 360.0, 10.0)
        results = []
        for ray in rays:
            ax.set_rlabel_position(float(ray))
            labels = [(tick.get_loc(), tick.label1) for tick in axis._update_ticks()
                      if r0 < tick.get_loc() <= r1 and tick.label1.get_text()]
            boxes = np.array([t.get_window_extent(renderer).extents for _, t in labels]).reshape(-1, 4)
            boxes = boxes + [-4.0, -4.0, 4.0, 4.0]
            hits = _hits_many(P, Q, W, np.ones(len(P)), boxes)
            a, b = boxes[:-1], boxes[1:]
            stacked = int(np.sum((np.minimum(a[:, 2], b[:, 2]) > np.maximum(a[:, 0], b[:, 0]))
                                 & (np.minimum(a[:, 3], b[:, 3]) > np.maximum(a[:, 1], b[:, 1]))))
            results.append((int(np.count_nonzero(hits)) + 10 * stacked, [v for (v, _), n in zip(labels, hits) if n],
                            len(labels)))
        crossed = np.array([c for c, _, _ in results])
        off = np.abs((rays - 112.5 + 180.0) % 360.0 - 180.0)
        k = int(np.lexsort((off, crossed))[0])
        ax.set_rlabel_position(float(rays[k]))
        _, hidden, count = results[k]
        if hidden and count - len(hidden) >= 2:
            formatter.hidden = set(hidden)
        self.stale = False


class _Hide(Formatter):
    """A tick formatter that leaves some ticks unlabelled and formats the others as ``base`` does."""

    def __init__(self, base, hidden):
        super().__init__()
        self.base, self.hidden = base, set(hidden)

    def set_axis(self, axis):
        super().set_axis(axis)
        self.base.set_axis(axis)

    def set_locs(self, locs):
        self.base.set_locs(locs)

    def __call__(self, x, pos=None):
        return "" if x in self.hidden else self.base(x, pos)


def value_limits(*values, include=(0.0,), margin=0.08) -> tuple[float, float]:
    """Limits of a value axis that show every finite value of ``values`` and ``include`` with room around them.

    The margin is ``margin`` of the span, and never less than ``margin`` of
    the largest magnitude: a flat curve (a gear pair's steady torque) then
    sits well inside the plot instead of on its edge, where its line and a
    marker on it would be cut in half. (−1, 1) when there is nothing to show.

    Examples
    --------
    >>> value_limits([20.91, 20.91])
    (-1.6728, 22.5828)
    """
    finite = [np.asarray(v, float).ravel() for v in values] + [np.asarray(include, float).ravel()]
    finite = np.concatenate(finite)
    finite = finite[np.isfinite(finite)]
    if not finite.size:
        return -1.0, 1.0
    lo, hi = float(finite.min()), float(finite.max())
    pad = margin * max(hi - lo, float(np.max(np.abs(finite))))
    if pad == 0:
        return -1.0, 1.0
    return round(lo - pad, 12), round(hi + pad, 12)


def _drawn(ax) -> Drawn:
    d = Drawn(ax)
    d.curves = {}
    return d


def _closed(cycle_or_q, crank: bool) -> bool:
    return crank and getattr(cycle_or_q, "closed", False)


def _interp_turn(x, theta, T):
    """T at angles x [rad], from samples over one turn (periodic linear interpolation)."""
    return np.interp(x, theta, T, period=TURN)


def _pieces(a: float, b: float, theta0: float):
    """The interval [a, b] [rad] split where it leaves the plotted turn [θ0, θ0 + 2π)."""
    end = theta0 + TURN
    if b <= end:
        return [(a, b)]
    return [(a, end), (theta0, b - TURN)]


# -- the driving torque ----------------------------------------------------------------------------

def draw_torque_curve(cycle, *, ax=None, flywheel=None, **style) -> Drawn:
    """Driving torque T₁₂ (or force F₁₂ of a slider driver) against the input, with its average.

    Parameters
    ----------
    cycle : Cycle
        From :func:`graphkin.cycle.sweep`.
    ax : Axes, optional
    flywheel : Flywheel, optional
        From ``cycle.flywheel(Cs)``: the pulses of T − T_avg between its
        crossings are shaded (energy taken from the shaft: vermillion; given
        back: blue) with their areas in J, and the motor's torque with the
        flywheel (:meth:`Flywheel.smoothed_torque`) is drawn too.

    Returns
    -------
    Drawn
        ``curves``: ``"torque"`` (n points), ``"average"`` (a horizontal
        line at ``cycle.average``), ``"smoothed"`` (with a flywheel);
        ``pulses``: one list of filled areas per pulse.
    """
    s = _style.resolve(**style)
    ax = _rect_axes(ax)
    d = _drawn(ax)
    d.pulses = []
    mech = cycle.problem.mechanism
    crank = _is_crank(mech)
    name = mech.driver.symbol
    unit = "N·m" if crank else "N"
    x = _x(cycle.q, crank)
    T = cycle.torque
    d.curves["torque"] = d.add(line(ax, x, T, color=s.driver, lw=1.8, label=f"{sub(name)} (kinetostatic)", zorder=3))
    avg = cycle.average
    lo, hi = (0.0, 360.0) if _closed(cycle, crank) else (float(np.nanmin(x)), float(np.nanmax(x)))
    if math.isfinite(avg):
        d.curves["average"] = d.add(line(ax, [lo, hi], [avg, avg], color=s.ink, lw=1.1, linestyle=(0, (6, 3)),
                                         label=f"average {num(avg)} {unit}", zorder=2))
    ax.axhline(0.0, color=s.ink, lw=0.6, zorder=1)
    if flywheel is not None:
        _pulses(ax, d, flywheel, s)
        try:
            Tm = flywheel.smoothed_torque()
        except GraphkinError:
            Tm = None
        if Tm is not None:
            d.curves["smoothed"] = d.add(line(ax, np.degrees(flywheel.theta), Tm, color=s.found, lw=1.6,
                                              label=f"motor with flywheel (Cₛ = {num(flywheel.Cs, 3)})", zorder=3))
    _input_axis(ax, crank, _theta(mech))
    ax.set_ylim(*value_limits(*[c.get_ydata() for c in d.curves.values()]))
    ax.set_ylabel(f"driving {'torque' if crank else 'force'} {sub(name)} [{unit}]")
    ax.set_title(f"{'Driving torque' if crank else 'Driving force'} over the cycle", fontsize=s.title_size)
    ax.legend(loc="best", fontsize=s.small_size, framealpha=0.9)
    return d


def _pulses(ax, d, flywheel, s):
    theta, T, avg = flywheel.theta, flywheel.T, flywheel.T_avg
    grid = np.concatenate([theta - TURN, theta, theta + TURN])
    theta0 = float(theta[0])
    for pulse in flywheel.table():
        taken = pulse.area > 0
        color = s.unknown if taken else s.known
        made = []
        for a, b in _pieces(pulse.start, pulse.end, theta0):
            inside = grid[(grid > a) & (grid < b)]
            xs = np.concatenate([[a], inside, [b]])
            ys = _interp_turn(xs, theta, T)
            made.append(d.add(ax.fill_between(np.degrees(xs), ys, avg, color=color, alpha=0.22, lw=0, zorder=1)))
        d.pulses.append(made)
        width = pulse.end - pulse.start
        if width > math.radians(25):
            mid = 0.5 * (pulse.start + pulse.end)
            mid = mid - TURN if mid >= theta0 + TURN else mid
            y = avg + 0.5 * (_interp_turn(mid, theta, T) - avg)
            d.labels[f"pulse {len(d.pulses)}"] = d.add(ax.text(
                math.degrees(mid), y, f"{'+' if taken else '−'}{num(abs(pulse.area), 3)} J", ha="center",
                va="center", fontsize=s.small_size, color=color, zorder=4))


# -- joint forces in polar form --------------------------------------------------------------------

def draw_polar_forces(cycle, names=None, *, ax=None, **style) -> Drawn:
    """Joint forces over the cycle in polar form: magnitude ``|F|`` [N] against direction (Söylemez §6.4.1).

    Each curve is the locus of the tip of the force vector drawn from the
    origin, one point per position: its angle is the force's direction from
    +x (CCW), its radius the magnitude. The peak of each force is marked.

    Parameters
    ----------
    cycle : Cycle
    names : sequence of str, optional
        Joint forces to plot (``"F23"``, ``"F32"``, ``"G14"``, ...); every
        joint force of the analysis (one order each) by default.
    ax : polar Axes, optional

    Returns
    -------
    Drawn
        ``curves[name]``: the Line2D with xdata = angle [rad] and ydata =
        magnitude [N], exactly ``cycle.polar(name)``.
    """
    s = _style.resolve(**style)
    ax = _polar_axes(ax)
    d = _drawn(ax)
    r = cycle.analysis
    if names is None:
        names = [r.name_of(i, j) for i, j in r.forces]
    crank = _is_crank(cycle.problem.mechanism)
    polar = {name: cycle.polar(name) for name in names}
    tops = [float(np.nanmax(size)) for size, _ in polar.values() if np.isfinite(size).any()]
    top = max(tops + [0.0])
    tips = {name: size * np.exp(1j * angle) for name, (size, angle) in polar.items()}
    bands: dict = {}
    for k, name in enumerate(names):
        size, angle = polar[name]
        color = SERIES[k % len(SERIES)]
        # A force that stays within a line's width of one drawn before (F₁₂ of a light crank and F₂₃) is drawn as
        # a wide pale band under that one: otherwise the curve on top hides it.
        same = next((other for other in names[:k] if top > 0
                     and np.nanmax(np.abs(tips[name] - tips[other]), initial=0.0) < COINCIDE * top), None)
        label = sub(name) + (f" ≈ {sub(same)} (wide band)" if same else "")
        if np.isfinite(size).any():
            i = int(np.nanargmax(size))
            where = f"{num(math.degrees(cycle.q[i]), 4)}°" if crank else f"s = {num(cycle.q[i] * 1e3, 4)} mm"
            label += f": max {num(size[i])} N at {where}"
        if same:
            k_band = bands[same] = bands.get(same, 0) + 1  # a second band under the same curve is wider, beneath
            curve = line(ax, angle, size, color=color, lw=2.0 + 4.0 * k_band, alpha=0.35, solid_capstyle="round",
                         label=label, zorder=2 - 0.01 * k_band)
        else:
            curve = line(ax, angle, size, color=color, lw=1.5, linestyle=DASHES[k % len(DASHES)], label=label,
                         zorder=3)
        d.curves[name] = d.add(curve)
        if np.isfinite(size).any():
            d.add(markers(ax, [angle[i]], [size[i]], color=color, ms=5, zorder=4))
    ax.set_ylim(0, 1.05 * top if top > 0 else 1.0)
    _radial_labels(ax, [(c.get_xdata(), c.get_ydata()) for c in d.curves.values()]
                   + [(m.get_xdata(), m.get_ydata()) for m in d if m.get_marker() not in (None, "None", "")
                      and m not in d.curves.values()], s)
    ax.set_title("Joint forces |F| [N] against direction", fontsize=s.title_size, pad=14)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.08), ncols=2, fontsize=s.small_size, framealpha=0.9)
    return d


# -- shaking force and moment ----------------------------------------------------------------------

def draw_shaking(cycle, *, ax=None, **style):
    """Shaking force on the frame in polar form and shaking moment against the input.

    Parameters
    ----------
    cycle : Cycle
    ax : Axes, optional
        None: a Figure with both plots (returned). A polar axes: only the
        shaking force there; any other axes: only the moment there (a
        :class:`Drawn` is returned in both cases).

    Returns
    -------
    Figure or Drawn
        Drawn ``curves``: ``"shaking force"`` (angle [rad], magnitude [N]) or
        ``"shaking moment"`` (input, moment [N·m] about the origin).
    """
    if ax is None:
        # Constrained layout: the polar axes' title sits higher than a rectangular one's (above the 90° label),
        # and fixed margins put it under the suptitle.
        fig = Figure(figsize=(11.0, 4.6), dpi=100, layout="constrained")
        _shaking_force(cycle, fig.add_subplot(1, 2, 1, projection="polar"), **style)
        _shaking_moment(cycle, fig.add_subplot(1, 2, 2, axes_class=PanelAxes), **style)
        fig.suptitle(f"Shaking of the frame: {cycle.problem.title}", fontsize=_style.resolve(**style).suptitle_size)
        fig.get_layout_engine().set(wspace=0.08)
        return fig
    if getattr(ax, "name", "") == "polar":
        return _shaking_force(cycle, ax, **style)
    return _shaking_moment(cycle, ax, **style)


def _shaking_force(cycle, ax, **style) -> Drawn:
    s = _style.resolve(**style)
    d = _drawn(ax)
    S = cycle.shaking_force()
    size, angle = np.hypot(S[:, 0], S[:, 1]), np.arctan2(S[:, 1], S[:, 0])
    d.curves["shaking force"] = d.add(line(ax, angle, size, color=s.unknown, lw=1.5, label="shaking force"))
    top = float(np.nanmax(size)) if np.isfinite(size).any() else 0.0
    ax.set_ylim(0, 1.05 * top if top > 0 else 1.0)
    _radial_labels(ax, [(angle, size)], s)
    ax.set_title("Shaking force on the frame [N]", fontsize=s.title_size, pad=14)
    return d


def _shaking_moment(cycle, ax, **style) -> Drawn:
    s = _style.resolve(**style)
    ax = _rect_axes(ax)
    d = _drawn(ax)
    crank = _is_crank(cycle.problem.mechanism)
    d.curves["shaking moment"] = d.add(line(ax, _x(cycle.q, crank), cycle.shaking_moment(), color=s.known, lw=1.6,
                                            label="shaking moment"))
    ax.axhline(0.0, color=s.ink, lw=0.6)
    _input_axis(ax, crank, _theta(cycle.problem.mechanism))
    ax.set_ylabel("shaking moment about the origin [N·m]")
    ax.set_title("Shaking moment on the frame (CCW +)", fontsize=s.title_size)
    return d


# -- the flywheel's energy -------------------------------------------------------------------------

def crossing_energy(flywheel) -> np.ndarray:
    """Energy U = ∫ (T − T_avg) dθ from θ[0] at each crossing [J] (the extremes of U); empty without crossings."""
    if not len(flywheel.crossings):
        return np.zeros(0)  # a steady torque: U stays 0, and there is no extreme to mark
    before = np.concatenate([[0.0], flywheel.accumulated[:-1]])
    return flywheel.U_min - before.min(initial=0.0) + before


def draw_energy(flywheel, *, ax=None, **style) -> Drawn:
    """Energy taken from the shaft, ∫ (T − T_avg) dθ, against crank angle, with the largest swing E marked.

    Parameters
    ----------
    flywheel : Flywheel
        From ``cycle.flywheel(Cs)`` or :func:`graphkin.cycle.size_flywheel`.
    ax : Axes, optional

    Returns
    -------
    Drawn
        ``curves``: ``"energy"`` (n points, ``flywheel.U``), ``"crossings"``
        (markers at the crossings of T with T_avg), ``"E"`` (the vertical
        span between the lowest and highest energy, E long);
        ``labels["E"]``: its text.
    """
    s = _style.resolve(**style)
    ax = _rect_axes(ax)
    d = _drawn(ax)
    x = np.degrees(flywheel.theta)
    d.curves["energy"] = d.add(line(ax, x, flywheel.U, color=s.driver, lw=1.8, label=r"∫ (T − $\mathregular{T_{avg}}$) dθ"))
    Uc = crossing_energy(flywheel)
    xc = np.degrees(flywheel.crossings)
    d.curves["crossings"] = d.add(markers(ax, xc, Uc, color=s.ink, ms=4.5, zorder=4,
                                          label=r"T = $\mathregular{T_{avg}}$ (crossings)"))
    if len(Uc):
        i_lo, i_hi = int(np.argmin(Uc)), int(np.argmax(Uc))
        lo, hi = float(Uc[i_lo]), float(Uc[i_hi])
        xE = float(xc[i_hi])
        for y in (lo, hi):
            d.add(ax.axhline(y, color=s.found, lw=0.8, linestyle=(0, (4, 3)), zorder=1))
        d.curves["E"] = d.add(line(ax, [xE, xE], [lo, hi], color=s.found, lw=1.6, marker="_", ms=10, zorder=3))
        d.labels["E"] = d.add(ax.text(xE, 0.5 * (lo + hi), f"  E = {num(flywheel.E)} J", color=s.found,
                                      fontsize=s.label_size, va="center", ha="left" if xE < 250 else "right", zorder=5))
        d.labels["E"].set_path_effects([halo()])  # the energy curve often runs through it
    ax.axhline(0.0, color=s.ink, lw=0.6)
    _input_axis(ax, True)
    ax.set_ylabel("energy taken from the shaft [J]")
    ax.set_title(f"Flywheel: E = {num(flywheel.E)} J, Iₛ = {num(flywheel.I_s)} kg·m² "
                 f"(Cₛ = {num(flywheel.Cs, 3)}, ω = {num(flywheel.omega_avg)} rad/s)", fontsize=s.title_size)
    ax.legend(loc="best", fontsize=s.small_size, framealpha=0.9)
    return d


# -- the joint-force index -------------------------------------------------------------------------

def draw_joint_force_index(jfi, *, ax=None, **style) -> Drawn:
    """Holte and Chase's joint-force index against the input, with its limit and the immovable positions.

    Parameters
    ----------
    jfi : JointForceIndex
        From :func:`graphkin.cycle.joint_force_index`.
    ax : Axes, optional

    Returns
    -------
    Drawn
        ``curves``: ``"index"`` (n points; gaps where it is undefined),
        ``"limit"`` (a horizontal line at ``jfi.limit``), ``"peak"``, and
        ``"immovable"`` (markers on the axis, when there are immovable positions).
    """
    s = _style.resolve(**style)
    ax = _rect_axes(ax)
    d = _drawn(ax)
    crank = _is_crank(jfi.analysis.mechanism)
    x = _x(jfi.q, crank)
    unit = f" [{jfi.units}]" if jfi.units else ""
    d.curves["index"] = d.add(line(ax, x, jfi.index, color=s.known, lw=1.8, label="joint-force index"))
    lo, hi = (0.0, 360.0) if crank else (float(np.min(x)), float(np.max(x)))
    d.curves["limit"] = d.add(line(ax, [lo, hi], [jfi.limit, jfi.limit], color=s.unknown, lw=1.2,
                                   linestyle=(0, (6, 3)), label=f"limit {num(jfi.limit)} (Holte and Chase)"))
    if jfi.peak.index >= 0:
        xp = float(_x(jfi.peak.at, crank))
        d.curves["peak"] = d.add(markers(ax, [xp], [jfi.peak.value], color=s.known, ms=6, zorder=4,
                                         label=f"peak {num(jfi.peak.value)}{unit} at "
                                               f"{num(xp, 4)}{'°' if crank else ' mm'}"))
    if jfi.immovable:
        xi = _x([q for q, _ in jfi.immovable], crank)
        d.curves["immovable"] = d.add(markers(ax, xi, np.zeros(len(xi)), marker="x", color=s.unknown, ms=7, mew=1.8,
                                              zorder=5, label=f"immovable ({len(xi)} position{'s' * (len(xi) > 1)})"))
        for xv in xi:
            d.add(ax.axvline(xv, color=s.unknown, lw=0.6, alpha=0.5, zorder=1))
    finite = jfi.index[np.isfinite(jfi.index)]
    ax.set_ylim(0, 1.1 * max(float(finite.max()) if finite.size else 0.0, jfi.limit))
    _input_axis(ax, crank, _theta(jfi.analysis.mechanism))
    ax.set_ylabel(f"joint-force index{unit}")
    ax.set_title("Joint-force index max|Fᵢⱼ| / |Fₑₓₜ| (static)", fontsize=s.title_size)
    ax.legend(loc="best", fontsize=s.small_size, framealpha=0.9)
    return d


# -- all together ------------------------------------------------------------------------------------

def draw_cycle(cycle, *, Cs=None, **style) -> Figure:
    """The cycle at a glance: driving torque, joint forces in polar form and, with C_s, the flywheel energy.

    Parameters
    ----------
    cycle : Cycle
    Cs : float, optional
        Coefficient of speed fluctuation: size a flywheel (``cycle.flywheel(Cs)``),
        shade the torque's pulses and add the energy plot.

    Returns
    -------
    Figure
        Axes in order: torque, polar forces, (energy).
    """
    s = _style.resolve(**style)
    flywheel = cycle.flywheel(Cs) if Cs is not None else None
    ncols = 3 if flywheel is not None else 2
    # Constrained layout, as draw_shaking: titles, the polar legend below its axes and the suptitle all get room.
    fig = Figure(figsize=(6.2 * ncols, 5.6), dpi=100, layout="constrained")
    draw_torque_curve(cycle, ax=fig.add_subplot(1, ncols, 1, axes_class=PanelAxes), flywheel=flywheel, **style)
    draw_polar_forces(cycle, ax=fig.add_subplot(1, ncols, 2, projection="polar"), **style)
    if flywheel is not None:
        energy = draw_energy(flywheel, ax=fig.add_subplot(1, ncols, 3, axes_class=PanelAxes), **style)
        _input_axis(energy.ax, True, _theta(cycle.problem.mechanism))
    fig.suptitle(f"{cycle.problem.title}: {cycle.n} positions", fontsize=s.suptitle_size)
    fig.get_layout_engine().set(wspace=0.06)
    return fig


__all__ = ["crossing_energy", "draw_cycle", "draw_energy", "draw_joint_force_index", "draw_polar_forces",
           "draw_shaking", "draw_torque_curve", "value_limits"]
