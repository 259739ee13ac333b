"""Known loads on each link: d'Alembert inertia, gravity and external loads."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from graphkin.geometry import as_xy
from graphkin.kinematics import Kinematics
from graphkin.model import PointForce, SpringForce, StrokeForce, Torque


def cross(a, b):
    """z-component of a × b for complex plane vectors, Im(ā b) (:func:`graphkin.geometry.zcross`), as one complex
    product: on arrays three times as fast as the four products of their strided real and imaginary parts."""
    return (np.conjugate(a) * b).imag


@dataclass(frozen=True)
class Inertia:
    """d'Alembert inertia loads of one link over n positions.

    Attributes
    ----------
    F : ndarray, shape (n, 2)
        Inertia force −m a_G [N], acting at G.
    T : ndarray, shape (n,)
        Inertia torque −I_G α [N·m], CCW positive.
    h : ndarray, shape (n,)
        Offset |T|/|F| [m] of the single equivalent resultant from G (nan where F = 0).
    line_point : ndarray, shape (n, 2)
        A point of the resultant's line: G shifted by h to the side that
        reproduces the torque's sense (moment of F about G equals T).
    """

    F: np.ndarray
    T: np.ndarray
    h: np.ndarray
    line_point: np.ndarray


def inertia(kin: Kinematics, link: int) -> Inertia:
    """Inertia force and torque of a link and their single equivalent resultant (zero in a static analysis).

    Parameters
    ----------
    kin : Kinematics
        The motion (a_G and α of the link at every position).
    link : int
        The moving link.

    Returns
    -------
    Inertia
        ``F = −m a_G`` [N], ``T = −I_G α`` [N·m], the offset ``h = |T|/|F|`` [m] of the resultant's line from
        G and a point on it, at every position.
    """
    body = kin.mechanism.link(link)
    m, I_G = (0.0, 0.0) if kin.static else (body.mass, body.I_G)
    F = -m * kin.z_a_G(link) + 0.0
    T = -I_G * kin.al(link) + 0.0
    size = np.abs(F)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        # r × F = T with r ⟂ F gives r = −i T F / |F|² = −i T / conj(F) (no |F|² to underflow or overflow).
        shift = -1j * T / np.conj(F)
        h = np.abs(T) / size
    # No force, or one so small beside the torque that its line lies beyond any float: a pure couple.
    couple = ~np.isfinite(shift) | ~(size > 0)
    h = np.where(couple, np.nan, h)
    shift = np.where(couple, np.nan, shift)
    return Inertia(as_xy(F), T, h, as_xy(kin.z_G(link) + shift))


def applied(kin: Kinematics, load) -> np.ndarray:
    """What an external load applies at each position, active window, table and sense included.

    Parameters
    ----------
    kin : Kinematics
    load : PointForce or Torque

    Returns
    -------
    ndarray, shape (n,)
        A force as complex Fx + i Fy [N]; a torque as float [N·m], CCW positive.
        Zero where the load does not act.

    Notes
    -----
    A tabulated load is ``table(q)`` along the unit vector of its ``force``
    (a torque: ``table(q)`` itself). A load whose sense follows the motion
    reads the velocity of its point along its line (a torque: its link's ω);
    the sign of that velocity sets the sense, so at a standstill along the
    line the load is zero (Coulomb's sign(v), as lecture 22's friction).
    """
    q = kin.q
    if isinstance(load, SpringForce):
        f = spring_force(kin, load)
    elif isinstance(load, StrokeForce):
        f = stroke_force(kin, load)
    elif isinstance(load, PointForce):
        f = complex(*load.force)
        if load.table is not None:
            f = f / abs(f) * load.table(q)
        else:
            f = np.full(kin.n, f)
        if load.sense != "fixed":
            v = kin.z_velocity(load.link, load.point)
            with np.errstate(invalid="ignore"):  # a dead point's infinite velocity across the line: 0 · ∞
                along = v.real * f.real + v.imag * f.imag     # v · F: negative while the point moves against F
            f = _by_sense(load.sense, f, along)
    else:
        f = load.table(q) if load.table is not None else np.full(kin.n, float(load.torque))
        if load.sense != "fixed":
            with np.errstate(invalid="ignore"):  # a dead point's infinite ω times a torque of 0
                power = kin.w(load.link) * f
            f = _by_sense(load.sense, f, power)
    if load.active is not None:
        f = np.where(load.active.mask(q), f, 0.0 * f)
    return f + 0.0


def stroke_force(kin: Kinematics, load: StrokeForce) -> np.ndarray:
    """A force against the piston's displacement from a dead centre, out or back with its motion (complex, N)."""
    away = complex(*load.away)
    z = kin.z(load.link, load.point)
    # Rounding puts a dead centre a hair outside the stroke: the tables are defined on [0, length] only.
    s = np.clip(((z - complex(*load.dead_centre)) * away.conjugate()).real, 0.0, load.length)
    v = (kin.z_velocity(load.link, load.point) * away.conjugate()).real
    # At a dead centre the piston stands still but for rounding (1e-17 m/s): the stroke that begins there is taken.
    still = np.abs(v) <= 1e-9 * np.abs(kin.q_dot) * load.length
    out = np.where(still, s < load.length / 2, v > 0)
    size = load.out(s) if load.back is None else np.where(out, load.out(s), load.back(s))
    u = complex(*load.force)
    return size * (u / abs(u))


def springs_without_a_line(kin, mech, kin_valid) -> dict[str, np.ndarray]:
    """Where a spring's ends meet although its free length is not 0: its force has no direction (named, per spring)."""
    out, seen = {}, set()
    for load in mech.loads:
        # Only a spring has two ends (a torque has not even one point): look at nothing else.
        if not (isinstance(load, SpringForce) and load.free_length and load.rate):
            continue
        ends = frozenset([(load.link, load.point), (load.anchor_link, load.anchor_point)])
        if ends in seen:
            continue
        seen.add(ends)  # a spring between two moving links puts a load on each: one message
        d = kin.z(load.anchor_link, load.anchor_point) - kin.z(load.link, load.point)
        where = kin_valid & (np.abs(d) == 0)
        if where.any():
            name = load.name if load.name.startswith("spring") else f"spring {load.name}".rstrip()
            out[f"the {name} has its ends {load.point} and {load.anchor_point} at one point, where a spring of "
                f"free length {load.free_length * 1e3:.6g} mm has no line: its force has no direction"] = where
    return out


def spring_force(kin: Kinematics, load: SpringForce) -> np.ndarray:
    """A spring's force on its end, k (L − L0) towards the other end, at every position (complex, N).

    Where the two ends meet (L = 0) the spring has no line: its force is 0 if it is also free there (L0 = 0),
    else nan (a compressed spring of no length has no direction).
    """
    d = kin.z(load.anchor_link, load.anchor_point) - kin.z(load.link, load.point)
    if not load.rate:
        return np.zeros(kin.n, complex)
    L = np.abs(d)
    with np.errstate(divide="ignore", invalid="ignore"):
        u = np.where(L > 0, d / np.where(L > 0, L, 1.0), np.nan if load.free_length else 0.0)
    return load.rate * (L - load.free_length) * u + 0.0


def applied_at(kin: Kinematics, load, i: int):
    """What a load applies at position ``i`` alone: complex force [N] or torque [N·m], 0 where it does not act."""
    if load.varies:
        return applied(kin, load)[i].item()
    if load.active is not None and not load.active.mask(kin.q[i:i + 1])[0]:
        return 0j if isinstance(load, PointForce) else 0.0
    return complex(*load.force) if isinstance(load, PointForce) else float(load.torque)


def _by_sense(sense: str, f, power):
    """The load with its sense set by the sign of its power ``power`` = F · v (or T ω) as given."""
    if sense == "opposes motion":
        # Reversed where it would help the motion, kept where it resists; zero at a standstill.
        return np.where(power > 0, -f, np.where(power < 0, f, 0.0 * f))
    # "working stroke": as given while it resists the motion, nothing on the return.
    return np.where(power < 0, f, 0.0 * f)


def _external(kin: Kinematics, link: int):
    """Sum of external forces and weight (complex) and their moment about the origin."""
    mech = kin.mechanism
    n = kin.n
    F = np.zeros(n, complex)
    M = np.zeros(n)
    body = mech.link(link)
    if mech.gravity and body.mass:
        W = -1j * body.mass * mech.gravity
        F = F + W
        M = M + cross(kin.z_G(link), W)
    for load in mech.loads:
        if load.link != link:
            continue
        if not load.varies:
            on = 1.0 if load.active is None else load.active.mask(kin.q)
            value = on * (complex(*load.force) if isinstance(load, PointForce) else load.torque)
        else:
            value = applied(kin, load)
        if isinstance(load, PointForce):
            F = F + value
            M = M + cross(kin.z(link, load.point), value)
        elif isinstance(load, Torque):
            M = M + value
    return F, M


def _known(kin: Kinematics, link: int):
    """External plus inertia loads: complex force (n,) and moment about the origin (n,)."""
    F, M = _external(kin, link)
    body = kin.mechanism.link(link)
    if kin.static:
        return F, M
    if body.mass:
        Fi = -body.mass * kin.z_a_G(link)
        F = F + Fi
        M = M + cross(kin.z_G(link), Fi)
    if body.I_G:
        M = M - body.I_G * kin.al(link)
    return F, M


def external_loads(kin: Kinematics, link: int):
    """Resultant of the external loads on a link (weight included) and its moment about the origin.

    Returns
    -------
    F : ndarray, shape (n, 2)
        Sum of external forces and weight [N].
    M : ndarray, shape (n,)
        Their moment about the global origin plus applied torques [N·m].
    """
    F, M = _external(kin, link)
    return as_xy(np.broadcast_to(F, (kin.n,))), np.broadcast_to(M, (kin.n,)).astype(float)


def known_loads(kin: Kinematics, link: int):
    """External loads plus inertia loads: force (n, 2) [N] and moment about the origin (n,) [N·m]."""
    F, M = _known(kin, link)
    return as_xy(np.broadcast_to(F, (kin.n,))), np.broadcast_to(M, (kin.n,)).astype(float)


def load_specs(plan, mech) -> dict:
    """Per moving link, what its known loads are made of, as constants (compiled once per plan).

    ``(m, I_G, G, W, forces, torques)``: mass, moment of inertia, G in the link's frame (complex), the
    weight (complex, 0 without gravity), the point forces ``(point, force, active)`` and the torques
    ``(torque, active)`` on the link (local point and force as complex numbers).
    """
    specs = plan.compiled.get("loads")
    if specs is None:
        specs = {}
        for link in plan.moving:
            body = mech.link(link)
            W = -1j * body.mass * mech.gravity if mech.gravity and body.mass else 0j
            forces = [(plan.points[link, load.point], complex(*load.force), load.active)
                      for load in mech.loads if load.link == link and isinstance(load, PointForce) and not load.varies]
            torques = [(load.torque, load.active)
                       for load in mech.loads if load.link == link and isinstance(load, Torque) and not load.varies]
            # A table's or a motion's load is worked out at each call (applied); the solver then hands a Kinematics.
            varying = [load for load in mech.loads if load.link == link and load.varies]
            specs[link] = (body.mass, body.I_G, complex(*body.G), W, forces, torques, varying)
        plan.compiled["loads"] = specs
    return specs


def _external_fast(kin, link: int, spec, L, M) -> None:
    """Add a link's external loads and weight to ``L`` (force) and ``M`` (moment about the origin).

    For kinematics without given values (``kin`` a Kinematics or the solver's own state), from a compiled
    spec (:func:`load_specs`); a link with no external load gets no entry.
    """
    m, I_G, pG, W, forces, torques, varying = spec
    if some(W):
        zG = kin.O[link] + kin.e[link] * pG
        _accumulate(L, M, link, W, cross(zG, W))
    for p, f, active in forces:
        f = f if active is None else active.mask(kin.q) * f
        _accumulate(L, M, link, f, cross(kin.O[link] + kin.e[link] * p, f))
    for T, active in torques:
        _accumulate(L, M, link, None, T if active is None else active.mask(kin.q) * T)
    for load in varying:
        value = applied(kin, load)
        if isinstance(load, PointForce):
            _accumulate(L, M, link, value, cross(kin.z(link, load.point), value))
        else:
            _accumulate(L, M, link, None, value)


def _inertia_fast(kin, link: int, spec, L, M) -> None:
    """Add a link's inertia force −m a_G and torque −I_G α to ``L`` and ``M`` (about the origin), unless static."""
    m, I_G, pG, W, forces, torques, varying = spec
    if kin.static:
        return
    if some(m):
        r = kin.e[link] * pG
        w = kin.omega[link]
        F = (kin.a_O[link] + (1j * kin.alpha[link] - w * w) * r) * -m
        _accumulate(L, M, link, F, cross(kin.O[link] + r, F))
    if some(I_G):
        _accumulate(L, M, link, None, kin.alpha[link] * -I_G)


def some(x) -> bool:
    """Whether a constant of a load spec is not 0: a number, or one value per position of a batch of designs."""
    return bool(x.any()) if isinstance(x, np.ndarray) else bool(x)


def _accumulate(L, M, link, F, T):
    if F is not None:
        L[link] = F if link not in L else L[link] + F
    M[link] = T if link not in M else M[link] + T
