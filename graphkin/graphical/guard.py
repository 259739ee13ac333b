"""One guard for everything graphical: each value a construction yields, checked against the analytical route.

A construction is other arithmetic on the same positions: resultants and concurrency points, polygons closed tip
to tail, Kennedy's lines. It agrees with the analytical route (the matrix solution, the closed-form kinematics) to
rounding, about 1e-13 on textbook problems and at most about 1e-10 on random linkages near their transmission
limits; a wrong term in either route (a pitch point on the wrong side of an internal mesh, a sign, a reaction not
passed on) is a difference of order one. Whatever differs by more than :data:`AGREEMENT` of the position's scale
is not a number anyone may see: the construction is returned not valid, its reason naming the quantity and both
values, and every reader (the report and its JSON, the figures, the handouts, the exercises' keys, the widgets)
already refuses an invalid construction. Its ``disagreement`` flag tells this fault of graphkin's apart from a
position the linkage cannot take (an exercise refuses to be made from it, rather than drawing other data).

What is compared, position by position:

- **Force polygons** (:func:`check_forces`): every joint force and the driving effort, against the
  :class:`~graphkin.analytical.ForceAnalysis`; the scale is the largest joint force (a torque is divided by the
  mechanism's size to be measured as a force).
- **Velocity and acceleration polygons** (:func:`motion_disagreement`): ω and α of every link (times the
  mechanism's size, to be measured as a speed), the velocity and acceleration of every named point and centre of
  mass, every image point of both polygons (each is a point of a link, so its value follows from the link's
  motion) and every Coriolis component 2 ω v_rel, against the kinematics; the scale is the largest speed (or
  acceleration) of the position. Every other vector of a polygon (a relative velocity, a normal or tangential
  component) joins two image points, so it is right when they are.
- **Instant centres** (:func:`centres_disagreement`): each centre found must be a point with no velocity of one
  link relative to the other (the relative velocity there, against the largest speed), each centre at infinity a
  direction across which the two links only translate; the ω and velocities the centres give are compared as the
  polygons' are.
"""

from __future__ import annotations

import math
import weakref
from dataclasses import replace
from functools import partial
from itertools import starmap
from operator import itemgetter
from operator import sub as _sub

import numpy as np

from graphkin.kinematics import solve_kinematics
from graphkin.kinematics.plan import plan_of, plan_solved
from graphkin.notation import largest, num, polar_text

AGREEMENT = 1e-9
"""How far a graphical value may differ from the analytical one, relative to the largest value of its kind at the
position, before the position's construction is not valid (issue 35). The routes differ by rounding, ~1e-13 on
textbook problems and at most ~1e-10 on the property tests' random linkages; any wrong term is O(1)."""


def mechanism_size(mech) -> float:
    """The mechanism's size [m]: the largest distance between two points of one link (1 m for a point-sized one)."""
    size = 0.0
    for link in mech.links:
        pts = [complex(*p) for p in link.points.values()]
        size = max([size] + [abs(a - b) for a in pts for b in pts])
    return size or 1.0


# -- forces ---------------------------------------------------------------------------------------------------
def forces_disagreement(result, c, i: int, size: float | None = None) -> str:
    """Why the force construction ``c`` of position ``i`` disagrees with the analytical ``result`` ('' if not).

    Every difference is measured as a force: a joint force's as it is, the driving torque's divided by the
    mechanism's size (``size`` [m], :func:`mechanism_size` when not given); the largest, against
    :data:`AGREEMENT` of the largest force (or effort) at the position.
    """
    if not c.valid:
        return f"the graphical route cannot close ({c.reason}) where the analytical one finds a solution"
    size = _shape_of(plan_of(result.mechanism), result.mechanism).size if size is None else size
    # Each pair once, as the lower-numbered link's force on the higher (how both routes keep them), in plain
    # floats: the differences are numpy's to the bit, and only the worst is put in words, once it is known.
    known = c.forces
    rows = [(key, F[i].tolist()) for key, F in result.forces.items()]
    scale = largest(A for _, A in rows)
    worst, found = 0.0, None
    for key, (ax, ay) in rows:
        gx, gy = known[key] if key in known else c.force(*key)
        gap = float(np.hypot(gx - ax, gy - ay))
        if gap > worst or gap != gap:  # a nan is the worst, and stays so
            worst, found = gap, key
    crank = result.mechanism.driver.crank
    arm = size if crank else 1.0  # a torque [N·m] per metre of the mechanism is a force
    effort = float(result.effort[i])
    gap = abs(c.effort - effort) / arm
    if (gap > worst or gap != gap) and worst == worst:
        worst, found = gap, None
    if worst <= AGREEMENT * max(scale, abs(effort) / arm):
        return ""
    if found is None:
        unit = "N·m" if crank else "N"
        what = (f"{result.driver_name} is {num(c.effort, 6, minus='-')} {unit} graphically, "
                f"{num(effort, 6, minus='-')} {unit} analytically")
    else:
        A, G = result.force(*found)[i], c.force(*found)
        what = (f"{result.name_of(*found)} is {polar_text(G, scale=scale)} graphically, "
                f"{polar_text(A, scale=scale)} analytically")
    return f"the graphical and analytical routes disagree: {what}"


def check_forces(result, c, i: int):
    """The force construction ``c`` of position ``i``, or a copy not valid where it disagrees with ``result``.

    Parameters
    ----------
    result : graphkin.analytical.ForceAnalysis
        The analytical solution the construction was built beside (the same kinematics).
    c : graphkin.graphical.Construction or None
        :func:`graphkin.graphical.construct_forces` at position ``i`` (None passes through).
    i : int
        The position's index in ``result``.

    Returns
    -------
    Construction or None
        ``c`` itself where both routes agree (or where the analytical route has no solution, whose reason the
        construction already gives); else a copy whose ``valid`` is False, whose ``disagreement`` is True and whose
        ``reason`` names the force and both values.
    """
    if c is None or not c.valid or not result.valid[i]:
        return c
    why = forces_disagreement(result, c, i)
    return replace(c, valid=False, reason=why, disagreement=True) if why else c


# -- motion -----------------------------------------------------------------------------------------------------
class _Shape:
    """What the guard reads of a mechanism at every position, made once per mechanism (its plan's cache).

    ``keys``: every named point of every moving link, ``(link, name)``, then each centre of mass, ``(link, None)``;
    ``local``: where each is in its link's own frame [m]; ``index``: each key's place in ``keys``. ``column``: each
    link's place in a row of link values, the moving links in order, then the frame.
    """

    def __init__(self, mech):
        self.size = mechanism_size(mech)
        self.frame = mech.frame
        self.moving = tuple(mech.moving)
        points = plan_of(mech).points  # (link, name): the point in its link's own frame [m], complex
        self.keys = [(n, name) for n in self.moving for name in mech.link(n).points] + [(n, None) for n in self.moving]
        self.local = np.array([points[key] if key[1] is not None else complex(*mech.link(key[0]).G)
                               for key in self.keys], dtype=complex)
        self.index = {key: k for k, key in enumerate(self.keys)}
        self.column = {n: j for j, n in enumerate(self.moving + (self.frame,))}
        self.columns = tuple(self.column[n] for n, _ in self.keys)  # each key's link's place in a row
        self.local_list = self.local.tolist()
        self.pickers: dict = {}  # (what, the keys a construction names, in its order): where they are in a row


def _plan(kin):
    return plan_solved(kin.mechanism, kin.groups)


def plan(kin):
    """The plan of ``kin``'s mechanism, the one it was solved with (:func:`~graphkin.kinematics.plan.plan_solved`),
    found once per kinematics while it lives (:func:`kept`): what the guard, the polygons and the instant centres
    read of the mechanism is kept in it."""
    return kept(kin, "plan", _plan)


def _shape(kin) -> _Shape:
    return _shape_of(plan(kin), kin.mechanism)


def _shape_of(plan, mech) -> _Shape:
    shape = plan.compiled.get("guard")
    if shape is None:
        shape = plan.compiled["guard"] = _Shape(mech)
    return shape


FEW = 4
"""Positions of one kinematics whose analytical motion the guard works out one at a time, in plain Python (a few
microseconds each), before it works out all the positions at once with numpy (about 100 µs, whatever their
number, and a microsecond a position): a one-position problem, or one position asked of a cycle, never pays for
the whole table."""


class _Table:
    """The analytical motion of one kinematics, a :class:`_Truth` per position asked for, kept.

    The first :data:`FEW` positions asked for are worked out one at a time (:func:`_row`: the velocities, and the
    accelerations only once asked for), the rest all at once, numpy over the positions (:func:`_rows`): a row per
    position, of Python numbers, read as a :class:`_Truth`.
    """

    __slots__ = ("shape", "truths", "rows")

    def __init__(self, kin):
        self.shape = _shape(kin)
        self.truths: dict = {}
        self.rows = None  # every position's row, once more than FEW were asked for

    def truth(self, kin, i: int, accelerations: bool = True) -> _Truth:
        """The :class:`_Truth` of position ``i`` of ``kin`` (the kinematics this table was made for); its
        accelerations too where ``accelerations`` (the instant centres need none)."""
        truth = self.truths.get(i)
        if truth is None:
            if self.rows is None and (len(self.truths) < FEW or kin.n <= FEW):
                truth = _row(self.shape, kin, i)
            else:
                if self.rows is None:
                    self.rows = _rows(self.shape, kin)
                truth = _Truth(self.shape, self.rows[0][i], self.rows[1][i])
            self.truths[i] = truth
        if accelerations and truth.a is None:
            _accelerate(truth, kin, i)
        return truth


def _row(shape: _Shape, kin, i: int) -> _Truth:
    """The :class:`_Truth` of position ``i`` alone, in plain Python (as :func:`_rows` and :class:`_Truth` make it):
    its velocities; its accelerations are :func:`_accelerate`'s, once asked for."""
    moving = shape.moving
    O = [kin.O[n].item(i) for n in moving]  # .item: a Python number, no numpy scalar made
    O.append(0j)
    e = [kin.e[n].item(i) for n in moving]
    e.append(1 + 0j)
    v_O = [kin.v_O[n].item(i) for n in moving]
    v_O.append(0j)
    w = [kin.omega[n].item(i) for n in moving]
    w.append(0.0)
    iw = [1j * x for x in w]
    v = [v_O[j] + iw[j] * e[j] * p for j, p in zip(shape.columns, shape.local_list)]  # e p: from its link's origin
    size = shape.size
    truth = _Truth.__new__(_Truth)
    truth.shape, truth.size, truth.index, truth.column = shape, size, shape.index, shape.column
    truth.v, truth.O, truth.v_O, truth.iw, truth.w, truth.e = v, O, v_O, iw, w, e
    truth.a = None
    truth.v_scale = max(max(map(abs, v), default=0.0), max(map(abs, w)) * size)
    return truth


def _accelerate(truth: _Truth, kin, i: int) -> None:
    """The accelerations of :func:`_row`'s ``truth`` of position ``i``, added to it."""
    moving = truth.shape.moving
    a_O = [kin.a_O[n].item(i) for n in moving]
    a_O.append(0j)
    al = [kin.alpha[n].item(i) for n in moving]
    al.append(0.0)
    turn = [1j * y - x * x for x, y in zip(truth.w, al)]
    e = truth.e
    a = [a_O[j] + turn[j] * e[j] * p for j, p in zip(truth.shape.columns, truth.shape.local_list)]
    truth.a, truth.a_O, truth.turn, truth.al = a, a_O, turn, al
    truth.a_scale = max(max(map(abs, a), default=0.0), max(map(abs, al)) * truth.size)


def _rows(shape: _Shape, kin) -> tuple[list, list]:
    """Every position's row at once (numpy over the positions), as lists of Python numbers: ``values`` (complex)
    holds the velocity and acceleration of every key of the :class:`_Shape`, then each link's origin O, v_O, a_O,
    iω, iα − ω² and e^iθ (the moving links, then the frame's: 0, and e^iθ 1); ``rates`` (real) holds ω and α of each link (the
    same order), then the position's scales: the largest speed (acceleration) of a named point or centre of mass,
    or of a link's ω (α) times the mechanism's size."""
    moving = shape.moving
    column = list(shape.columns)

    def links(arrays, kind, frame=0):  # (positions, links), the frame's value (0; its e^iθ: 1) last
        return np.stack([np.asarray(arrays[m], dtype=kind) for m in moving] + [np.full(kin.n, frame, kind)], axis=1)

    O, v_O, a_O = (links(x, complex) for x in (kin.O, kin.v_O, kin.a_O))
    e = links(kin.e, complex, 1)
    w, al = links(kin.omega, float), links(kin.alpha, float)
    iw, turn = 1j * w, 1j * al - w * w
    e_c = e[:, column]  # each point from its link's origin is e p [m]
    v = v_O[:, column] + iw[:, column] * e_c * shape.local
    a = a_O[:, column] + turn[:, column] * e_c * shape.local
    with np.errstate(invalid="ignore"):  # positions that cannot be assembled are nan, and never asked for
        v_top = np.maximum(np.abs(v).max(axis=1), np.abs(w).max(axis=1) * shape.size)
        a_top = np.maximum(np.abs(a).max(axis=1), np.abs(al).max(axis=1) * shape.size)
    # As Python numbers, all at once: a position's few dozen values are too few for numpy to pay.
    return (np.concatenate([v, a, O, v_O, a_O, iw, turn, e], axis=1).tolist(),
            np.concatenate([w, al, v_top[:, None], a_top[:, None]], axis=1).tolist())


class _Truth:
    """The analytical motion of one position, as lists of Python numbers (a row of the :class:`_Table`).

    ``v``, ``a``: the velocity and acceleration of each key of the :class:`_Shape` [m/s, m/s²], in its order
    (``index``); ``O``, ``v_O``, ``a_O``, ``iw``, ``turn``: each link's origin [m], its velocity and acceleration and
    the factors iω and iα − ω² that carry them to a point r = P − O away (v = v_O + iω r, a = a_O + (iα − ω²) r);
    ``w``, ``al``: each link's ω and α; ``e``: its turn e^iθ (where its points are: O + e^iθ p, p in its own
    frame; the instant centres place the links with them); all of these in the order of ``column``. A position
    worked out alone (:func:`_row`) has its accelerations (``a`` … ``a_scale``) once asked for (``a`` None until
    then).
    """

    __slots__ = ("shape", "size", "index", "column", "v", "a", "O", "v_O", "a_O", "iw", "turn", "w", "al", "v_scale",
                 "a_scale", "e")

    def __init__(self, shape: _Shape, z: list, x: list):
        K, L = len(shape.keys), len(shape.column)
        self.shape, self.size, self.index, self.column = shape, shape.size, shape.index, shape.column
        self.v, self.a = z[:K], z[K:2 * K]
        self.O, self.v_O, self.a_O, self.iw, self.turn, self.e = (z[2 * K + k * L:2 * K + (k + 1) * L]
                                                                  for k in range(6))
        self.w, self.al = x[:L], x[L:2 * L]
        self.v_scale, self.a_scale = x[2 * L], x[2 * L + 1]

    def at(self, link: int, P: complex) -> complex:
        """Velocity [m/s] of the point at ``P`` [m] moving with ``link``."""
        j = self.column[link]
        return self.v_O[j] + self.iw[j] * (P - self.O[j])


_KEPT: dict = {}
"""What was worked out for each of the last few kinematics, ``id of the kinematics: (weakref to it, {what:
value})``, the oldest first: the guard's :class:`_Table`, the kinematics solved again without a problem's given
values (:func:`derived`), what the polygons and the instant centres read of its mechanism. Every position of one
kinematics shares them."""

KEPT = 16
"""How many kinematics :func:`kept` keeps what it worked out for (the most recent)."""


def kept(kin, what: str, make):
    """``make(kin)``, worked out once for the kinematics ``kin`` while it lives (one of the last :data:`KEPT`).

    A :class:`~graphkin.kinematics.Kinematics` is frozen, so what is made of it (and of its mechanism) holds as
    long as it does; finding it here is two dicts' lookups, where a mechanism's plan (:func:`plan_of`) checks every
    part of the mechanism for a change on each call. Everything kept for one kinematics is one entry, so a new
    kinematics costs one weak reference however much is made of it.
    """
    key = id(kin)
    entry = _KEPT.get(key)
    if entry is not None and entry[0]() is kin:  # (an id is reused once its object is gone: the reference tells)
        values = entry[1]
        if what in values:
            return values[what]
    else:
        values = {}
        _KEPT.pop(key, None)
        while len(_KEPT) >= KEPT:
            del _KEPT[next(iter(_KEPT))]
        _KEPT[key] = (weakref.ref(kin), values)
    value = values[what] = make(kin)
    return value


def motion_at(kin, i: int, accelerations: bool = True) -> _Truth:
    """The analytical motion of position ``i`` of ``kin``, as the guard compares a construction with it: each
    link's place (O, e^iθ), ω, the velocity of every named point and centre of mass, and their accelerations where
    ``accelerations`` (the instant centres need none). Worked out once per position and kept with the kinematics'
    table (:func:`kept`), so that a construction reading the links' places from it reads them once."""
    return kept(kin, "table", _Table).truth(kin, i, accelerations)


class _Check:
    """Every comparison of a construction with the analytical route, of speeds (kind 0) or accelerations (kind 1).

    Each difference is measured against the largest value of its kind at the position: the named points', the
    links' ω (α) times the mechanism's size, and every analytical value compared (a pitch point that is no named
    point may be the only thing that moves). The values come a list at a time, join one list per kind, and are
    judged all at once, at the end; only where the routes disagree is the worst found and put in words.
    """

    __slots__ = ("scale", "zs", "ts", "seen")

    def __init__(self, truth: _Truth):
        self.scale = [truth.v_scale, truth.a_scale if truth.a is not None else math.nan]  # (none: centres)
        self.zs: tuple = ([], [])
        self.ts: tuple = ([], [])
        self.seen: list = []  # (kind, where its values start in zs[kind], say, names): to put one in words

    def see(self, kind: int, zs: list, ts: list, say: tuple, names, sized: bool = False):
        """The construction's values ``zs`` against the analytical ``ts`` [m/s or m/s²], in step.

        ``say`` is a function and its first arguments, the j-th of ``names`` the next ones (a tuple, or one value),
        to put the j-th difference in words. ``sized``: the ``ts`` may be larger than the position's scale (a point
        that is not a named one), so they join it.
        """
        if zs:
            self.seen.append((kind, len(self.zs[kind]), say, names))
            self.zs[kind].extend(zs)
            self.ts[kind].extend(ts)
            if sized:
                top = max(map(abs, ts))
                if top > self.scale[kind]:
                    self.scale[kind] = top

    def reason(self, route: str) -> str:
        """'' where every difference is within :data:`AGREEMENT` of its scale, else the worst one in words."""
        scale = self.scale
        for kind in (0, 1):
            if self.zs[kind]:
                gaps = [abs(z - t) for z, t in zip(self.zs[kind], self.ts[kind])]
                total, top = sum(gaps), scale[kind]  # a nan anywhere makes the sum nan (max() passes over one)
                if total != total or not top > 0 or max(gaps) / top > AGREEMENT:
                    break
        else:
            return ""
        worst, found, at = 0.0, None, 0.0
        for kind in (0, 1):
            if not self.zs[kind]:
                continue
            gap, j = self._worst(kind)
            ratio = gap / scale[kind] if scale[kind] > 0 else (0.0 if gap == 0 else math.inf)
            if ratio != ratio or ratio > worst:
                worst, found, at = ratio, (kind, j), scale[kind]
                if ratio != ratio:
                    break
        if worst <= AGREEMENT:
            return ""
        kind, j = found
        start, (say, *args), names = next((start, say, names) for k, start, say, names in reversed(self.seen)
                                          if k == kind and start <= j)
        name = list(names)[j - start]
        name = name if type(name) is tuple else (name,)
        z, t = self.zs[kind][j], self.ts[kind][j]
        return f"the {route} and the analytical route disagree: {say(*args, *name, z, t, at)}"

    def _worst(self, kind: int) -> tuple[float, int]:
        """The largest difference of a kind (a nan is the largest there is; of equal ones, the first) and where it
        is in ``zs[kind]``."""
        gaps = [abs(z - t) for z, t in zip(self.zs[kind], self.ts[kind])]
        if sum(gaps) != sum(gaps):
            return math.nan, next(j for j, g in enumerate(gaps) if g != g)
        top = max(gaps)
        return top, gaps.index(top)


_UNIT = ("m/s", "m/s²")


def _vec(z: complex, unit: str, scale: float) -> str:
    return polar_text((z.real, z.imag), unit, scale=scale, minus="-")


def _rate(x: float, unit: str) -> str:
    return f"{num(x, 6, minus='-')} {unit}"


def _vectors(name: str, kind: int, z: complex, t: complex, scale: float) -> str:
    unit = _UNIT[kind]
    return f"{name} is {_vec(z, unit, scale)} graphically, {_vec(t, unit, scale)} analytically"


def _point(kind: int, link: int, point: str | None, z: complex, t: complex, scale: float) -> str:
    name = f"{'va'[kind]}_G{link}" if point is None else f"{'va'[kind]}_{point} of link {link}"
    return _vectors(name, kind, z, t, scale)


def _centre_of_mass(kind: int, link: int, z: complex, t: complex, scale: float) -> str:
    return _point(kind, link, None, z, t, scale)


def _rates(symbol: str, unit: str, size: float, link: int, z: float, t: float, scale: float) -> str:
    return f"{symbol}{link} is {_rate(z / size, unit)} graphically, {_rate(t / size, unit)} analytically"


def _motion_values(check: _Check, truth: _Truth, kind: int, rates: dict, points: dict, centres_of_mass: dict):
    """Compare a construction's ω (kind 0; α, kind 1) of each link and the velocity (acceleration) of each named
    point and G (``points`` by ``(link, name)``, ``centres_of_mass`` by link)."""
    size, index, column = truth.size, truth.index, truth.column
    true, symbol, unit = (truth.w, "ω", "rad/s") if kind == 0 else (truth.al, "α", "rad/s²")
    # ω and α times the mechanism's size: measured as the speed (acceleration) they give its farthest point.
    check.see(kind, [x * size for x in rates.values()], [true[column[link]] * size for link in rates],
              (_rates, symbol, unit, size), rates)
    true = truth.v if kind == 0 else truth.a
    check.see(kind, [complex(x, y) for x, y in points.values()], [true[index[key]] for key in points], (_point, kind),
              points)
    check.see(kind, [complex(x, y) for x, y in centres_of_mass.values()],
              [true[index[link, None]] for link in centres_of_mass], (_centre_of_mass, kind), centres_of_mass)


def _image(polygon: str, kind: int, name: str, z: complex, t: complex, scale: float) -> str:
    return _vectors(f"the {polygon} image {name}", kind, z, t, scale)


def _unknown_image(polygon: str, name: str, z, t, scale) -> str:
    return f"the {polygon} polygon's image {name} is no point of a link the check knows"


# -- the quick look: whether everything agrees, in as few Python steps as there can be -------------------------
# The same values, the same differences and the same scales as :class:`_Check` (so the same answer), gathered with
# C loops (map, itemgetter) where a construction names its values in its usual order, every difference of a kind in
# one list, judged at once (every value of a kind is measured against the same scale); only where something
# disagrees does :class:`_Check` go over them all again to find the worst and put it in words.
def _agree(gaps: list, scale: float) -> bool:
    """Whether the largest of ``gaps`` (each |z − t|) is within :data:`AGREEMENT` of ``scale``, as
    :meth:`_Check.reason` judges it: a nan never is; against a scale of 0, only 0 is; no gaps always are."""
    if not gaps:
        return True
    total = sum(gaps)  # a nan anywhere makes the sum nan (max() passes over one)
    if total != total:
        return False
    top = max(gaps)
    return top / scale <= AGREEMENT if scale > 0 else top == 0


def _picker(shape: _Shape, what: str, keys: tuple, places: dict):
    """A function that picks the values of ``keys`` (in their order) out of a row list, by their ``places``: made
    once per mechanism and order of keys (an itemgetter: a C loop). ``what`` "G": the keys are links, each
    standing for its centre of mass, ``(link, None)``."""
    pick = shape.pickers.get((what, keys))
    if pick is None:
        at = [places[key] for key in keys] if what != "G" else [places[key, None] for key in keys]
        pick = shape.pickers[what, keys] = itemgetter(*at) if len(at) > 1 else partial(_one, at[0])
    return pick


def _one(k: int, row: list) -> tuple:
    return (row[k],)


def _link_gaps(gaps: list, truth: _Truth, rates: dict, true: list) -> None:
    """Add to ``gaps`` the differences of a construction's ω (α) of each link from ``true`` (the truth's, by
    column), both times the size."""
    if rates:
        size = truth.size
        ts = _picker(truth.shape, "link", tuple(rates), truth.column)(true)
        gaps.extend(map(abs, map(_sub, [x * size for x in rates.values()], [t * size for t in ts])))


def _point_gaps(gaps: list, truth: _Truth, points: dict, true: list, what: str) -> None:
    """Add to ``gaps`` the differences of a construction's ``(x, y)`` of named points (``what`` "point": keyed
    ``(link, name)``) or of centres of mass (``what`` "G": keyed by link) from ``true`` (the truth's, by key)."""
    if points:
        ts = _picker(truth.shape, what, tuple(points), truth.index)(true)
        gaps.extend(map(abs, map(_sub, starmap(complex, points.values()), ts)))


def _motion_agrees(truth: _Truth, c, where: dict, coriolis: dict) -> bool:
    """Whether :func:`motion_disagreement` finds nothing: every value of the polygons ``c`` within
    :data:`AGREEMENT` of its scale (a nan, or an image the check cannot place, never is)."""
    index, column, O = truth.index, truth.column, truth.O
    scale = [truth.v_scale, truth.a_scale]
    gaps: tuple = ([], [])
    # The images: each against its named point's value (or, a point that is no named one, the link's motion there).
    for kind, polygon, true, base, factor in ((0, "velocity", truth.v, truth.v_O, truth.iw),
                                              (1, "acceleration", truth.a, truth.a_O, truth.turn)):
        images = c.images[polygon]
        zs, ts = [], []
        for name, z in images.items():
            place = where.get(name)
            if place is None:
                if name != "o" and name != "o′":
                    return False  # an image whose point the check does not know: not shown
                t = 0j
            elif place[2] is None:
                j = column[place[0]]
                t = base[j] + factor[j] * (place[1] - O[j])
            else:
                t = true[index[place[2]]]
            zs.append(z)
            ts.append(t)
        if ts:
            top = max(map(abs, ts))
            if top > scale[kind]:
                scale[kind] = top
            gaps[kind].extend(map(abs, map(_sub, starmap(complex, zs), ts)))
    if coriolis:
        w, at = truth.w, truth.at
        vectors = [v for v in c.vectors("acceleration") if v.name in coriolis]
        zs = [complex(*v.vector) for v in vectors]
        ts = [2j * w[column[m]] * (at(k, X) - at(b, X)) for m, k, b, X in (coriolis[v.name] for v in vectors)]
        if ts:
            top = max(map(abs, ts))
            if top > scale[1]:
                scale[1] = top
            gaps[1].extend(map(abs, map(_sub, zs, ts)))
    v, a = gaps
    _link_gaps(v, truth, c.omega, truth.w)
    _link_gaps(a, truth, c.alpha, truth.al)
    _point_gaps(v, truth, c.velocity, truth.v, "point")
    _point_gaps(a, truth, c.acceleration, truth.a, "point")
    _point_gaps(v, truth, c.v_G, truth.v, "G")
    _point_gaps(a, truth, c.a_G, truth.a, "G")
    return _agree(v, scale[0]) and _agree(a, scale[1])


def _centres_agree(truth: _Truth, ic) -> bool:
    """Whether :func:`centres_disagreement` finds nothing (as :func:`_motion_agrees` for the polygons)."""
    column, O, v_O, iw, w, size = truth.column, truth.O, truth.v_O, truth.iw, truth.w, truth.size
    gaps = []
    for (a, b), (x, y) in ic.centres.items():  # v_b(P) − v_a(P), against 0
        P, j, k = complex(x, y), column[a], column[b]
        gaps.append(abs((v_O[k] + iw[k] * (P - O[k])) - (v_O[j] + iw[j] * (P - O[j]))))
    pairs = ic.at_infinity
    if pairs:
        gaps.extend([abs((w[column[b]] - w[column[a]]) * size) for a, b in pairs])
        d = [truth.at(b, 0j) - truth.at(a, 0j) for a, b in pairs]
        gaps.extend([abs(z.real * u[0] + z.imag * u[1]) for z, u in zip(d, pairs.values())])
    # The centres give a few values (a link's ω, its named points and G): plain loops, where the polygons' dozens
    # pay for :func:`_picker`'s C loops. The same differences as theirs, so the same answer.
    index, v = truth.index, truth.v
    gaps.extend([abs(x * size - w[column[link]] * size) for link, x in ic.omega.items()])
    gaps.extend([abs(complex(x, y) - v[index[key]]) for key, (x, y) in ic.velocity.items()])
    gaps.extend([abs(complex(x, y) - v[index[link, None]]) for link, (x, y) in ic.v_G.items()])
    return _agree(gaps, truth.v_scale)


def motion_disagreement(kin, i: int, c, where: dict, coriolis: dict) -> str:
    """Why the velocity and acceleration polygons ``c`` of position ``i`` disagree with ``kin`` ('' if they agree).

    Parameters
    ----------
    kin : graphkin.kinematics.Kinematics
        The analytical kinematics (its derived motion: values a problem gives off its drawing are not the route).
    i : int
        The position's index.
    c : graphkin.graphical.MotionConstruction
        The polygons built from the input motion.
    where : dict of str to (int, complex, tuple or None)
        Each image point of both polygons, by its name (``"b"``, ``"g3′"``): the link it is a point of, where that
        point is [m], and its key in ``c.velocity`` (``(link, name)``; ``(link, None)``: G of the link) where it is
        a named point or a centre of mass, else None. The pole (``"o"``, ``"o′"``) is the frame's. An image whose
        value is its named point's in ``c`` is compared once, as that point.
    coriolis : dict of str to (int, int, int, complex)
        Each Coriolis vector by its name: the guide's link m, the sliding link k, the link b whose point the
        relative velocity is measured from, and the point X [m]; it must equal 2 ω_m × (v_X on k − v_X on b).

    Returns
    -------
    str
        '' where every value agrees to :data:`AGREEMENT` of its scale; else the reason, naming the worst quantity
        and both values.
    """
    truth = motion_at(kin, i)
    if _motion_agrees(truth, c, where, coriolis):
        return ""
    # Only where a value disagrees (or is not a number): every difference again, the worst one put in words.
    check = _Check(truth)
    _motion_values(check, truth, 0, c.omega, c.velocity, c.v_G)
    _motion_values(check, truth, 1, c.alpha, c.acceleration, c.a_G)
    index, column = truth.index, truth.column
    for kind, polygon, table, true, base, factor in ((0, "velocity", (c.velocity, c.v_G), truth.v, truth.v_O, truth.iw),
                                                     (1, "acceleration", (c.acceleration, c.a_G), truth.a, truth.a_O,
                                                      truth.turn)):
        zs, ts, names, unknown = [], [], [], []
        for name, z in c.images[polygon].items():
            if name in where:
                link, P, key = where[name]
                if key is None:  # a point that is no named one (a pitch point, a slider's coincident point)
                    j = column[link]
                    ts.append(base[j] + factor[j] * (P - truth.O[j]))
                elif z == (table[0].get(key) if key[1] is not None else table[1].get(link)):
                    continue  # the very value compared above, as the named point's (or G's)
                else:
                    ts.append(true[index[key]])
            elif name in ("o", "o′"):  # the pole is the frame's image: 0
                ts.append(0j)
            else:  # an image a construction added without saying whose point it is cannot be checked: not shown
                unknown.append(name)
                continue
            zs.append(complex(*z))
            names.append(name)
        check.see(kind, zs, ts, (_image, polygon, kind), names, sized=True)
        check.see(kind, [complex(math.inf)] * len(unknown), [0j] * len(unknown), (_unknown_image, polygon), unknown)
    if coriolis:
        found = [v for v in c.vectors("acceleration") if v.name in coriolis]
        w, at = truth.w, truth.at
        check.see(1, [complex(*v.vector) for v in found],
                  [2j * w[column[m]] * (at(k, X) - at(b, X)) for m, k, b, X in (coriolis[v.name] for v in found)],
                  (_vectors,), [(v.name, 1) for v in found], sized=True)
    return check.reason("velocity and acceleration polygons")


def centres_disagreement(kin, i: int, ic) -> str:
    """Why the instant centres ``ic`` of position ``i`` disagree with ``kin`` ('' if they agree).

    A centre I_ab found at P must be where links a and b have the same velocity: the relative velocity
    v_b(P) − v_a(P) [m/s] is compared with the position's largest speed. A centre at infinity in the direction u
    must leave a and b only translating relative to each other (ω_a = ω_b), and across u (the relative velocity
    perpendicular to u). The ω and the velocities the centres give are compared as the polygons' are.
    """
    truth = motion_at(kin, i, False)
    if _centres_agree(truth, ic):
        return ""
    check = _Check(truth)
    size, column, O, v_O, iw, w = truth.size, truth.column, truth.O, truth.v_O, truth.iw, truth.w
    pairs = ic.centres
    # v_b(P) − v_a(P), each v = v_O + iω (P − O) of its link
    check.see(0, [(v_O[b] + iw[b] * (P - O[b])) - (v_O[a] + iw[a] * (P - O[a]))
                  for (a, b), P in zip([(column[a], column[b]) for a, b in pairs],
                                       [complex(x, y) for x, y in pairs.values()])],
              [0j] * len(pairs), (_moving_centre, pairs), pairs)
    pairs = ic.at_infinity
    if pairs:
        check.see(0, [(w[column[b]] - w[column[a]]) * size for a, b in pairs], [0.0] * len(pairs), (_turning_apart,),
                  [(a, b, size) for a, b in pairs])
        d = [truth.at(b, 0j) - truth.at(a, 0j) for a, b in pairs]  # where ω_a = ω_b, the same at every point
        check.see(0, [z.real * u[0] + z.imag * u[1] for z, u in zip(d, pairs.values())], [0.0] * len(pairs),
                  (_sliding_apart,), pairs)
    _motion_values(check, truth, 0, ic.omega, ic.velocity, ic.v_G)
    return check.reason("instant centres")


def _moving_centre(centres: dict, a: int, b: int, z, t, scale) -> str:
    P = complex(*centres[a, b])
    return (f"I{a}{b} at ({num(P.real * 1e3, 6, minus='-')}, {num(P.imag * 1e3, 6, minus='-')}) mm moves at "
            f"{num(abs(z), 6)} m/s relative to link {a} as a point of link {b} (an instant centre has no relative "
            "velocity)")


def _turning_apart(a: int, b: int, size: float, z, t, scale) -> str:
    return (f"I{a}{b} is at infinity graphically, but links {a} and {b} turn relative to each other at "
            f"{_rate(z / size, 'rad/s')} analytically")


def _sliding_apart(a: int, b: int, z, t, scale) -> str:
    return (f"I{a}{b} is at infinity across the sliding graphically, but links {a} and {b} move "
            f"{num(abs(z), 6)} m/s apart along it analytically")


def _input_motion(kin):
    return solve_kinematics(kin.mechanism, kin.q, kin.q_dot, kin.q_ddot)


def derived(kin, i: int):
    """The kinematics the motion constructions draw and are checked against at position ``i``: ``(kin, i)``.

    A problem may give values measured off its book's drawing (a link's angle θ, α, a_G: ``[given]``); the force
    route uses them, but they are not a motion the input produces (an angle read to the degree leaves a pin slightly
    apart on its two links), so no analytical route shares them. The polygons and instant centres are constructed
    from the input motion alone: the kinematics the given values were put in (``kin.derived``), or, where that is
    not known, the kinematics solved again without them (once for all the positions, kept while ``kin`` is).
    """
    if not kin.given:
        return kin, i
    own = kin.derived
    if own is None or own.mechanism is not kin.mechanism or own.q is not kin.q or own.q_dot is not kin.q_dot or (
            own.q_ddot is not kin.q_ddot):
        own = kept(kin, "derived", _input_motion)  # (not the same input: solved again)
    return own, i
