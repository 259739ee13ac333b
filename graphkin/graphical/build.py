"""The graphical route: resultants, two- and three-force members, force polygons (:func:`construct_forces`).

For one position, the groups of the kinematic decomposition are taken in
reverse order, as in the analytical solver, but each is solved the way it is
drawn:

1. each loaded link's known loads are combined into one resultant R — for
   inertia alone, −m a_G on a line offset from G by h = |T|/|F|;
2. in a dyad with one link loaded, the unloaded link is a two-force member,
   which fixes the line of the force it passes on (along its two pins;
   through its pin, normal to its guide; or through its pin, normal to a slot
   in the loaded link);
3. the loaded link is then a three-force member: its resultant, that line and
   the reaction at its other joint meet in one point, found with shapely; the
   force polygon closes tip to tail (a guide reaction has a known direction
   instead, so the polygon alone gives both sizes); reactions found are loads
   on the links of the groups before;
4. the driver: the crank's pivot force and the resultant on the crank form a
   couple T = F·d, or the slider's polygon gives the driving force.

When a dyad has both links loaded, the steps are a superposition as books
write it (docs/graphical.md): one sub-problem per loaded link, with every
other link unloaded, each announced, solved through to its own driving
effort and read off; then the sum of every joint force and the driver with
the summed reactions. The whole problem is solved first, unshown, for the
side of each guide's friction and each tooth's flank, which the
sub-problems keep so that they add up; a sub-problem that loads both links
of a dyad again is split once more into parts.

Magnitudes are read off exactly: a force along a known line is found from
moments about the other joint (the polygon's closing side, computed rather
than measured), so the construction agrees with the matrix solution to
rounding. Friction at a guide tilts its reaction by atan μ against the
sliding; the sense of the tilt depends on the side the normal force pushes,
so the construction assumes a side, checks it, and redoes the polygon if the
assumption was wrong.
"""


from __future__ import annotations

import cmath
import math

import numpy as np

from graphkin.analytical.loads import inertia
from graphkin.analytical.meshes import pitch as pitch_point
from graphkin.errors import GraphkinError
from graphkin.graphical.builder import Builder, DeadPoint, xy
from graphkin.graphical.construction import Arrow, Construction, nice_scale
from graphkin.graphical.superposition import superposition
from graphkin.kinematics import Kinematics
from graphkin.model import GearMesh, PointForce, Prismatic, Torque


def construct_forces(kin: Kinematics, index: int = 0) -> Construction:
    """The graphical solution of position ``index``, step by step.

    Parameters
    ----------
    kin : Kinematics
        The motion of every link (``problem.kinematics()`` or ``result.kinematics``).
    index : int
        Which of the kinematics' positions to construct.

    Returns
    -------
    Construction
        Not ``valid`` (with the reason) where the position cannot be assembled,
        is a dead point, or friction locks it.
    """
    if not isinstance(kin, Kinematics):
        raise GraphkinError(f"construct_forces takes the Kinematics of a problem (problem.kinematics()), "
                            f"got {type(kin).__name__}")
    if isinstance(index, (bool, np.bool_)) or not isinstance(index, (int, np.integer)) or not -kin.n <= index < kin.n:
        raise GraphkinError(f"construct_forces: index must be a whole number from 0 to {kin.n - 1} (one of the "
                            f"{kin.n} positions), got {index!r}")
    index = int(index) % kin.n
    mech = kin.mechanism
    q = float(kin.q[index])
    if not kin.valid[index]:
        return Construction(mech, index, q, valid=False, reason=kin.reason(index))
    b = Builder(kin, index)
    try:
        b.run(b.own_loads)
    except DeadPoint as exc:
        return Construction(mech, index, q, tuple(b.steps), valid=False, reason=str(exc))
    steps, warnings, subproblems = b.steps, b.warnings, ()
    if b.superposed:
        # The whole problem, solved first, gives every force and the sides of friction; the steps shown are the
        # books' superposition, one sub-problem per loaded link.
        try:
            steps, subproblems, more = superposition(kin, index, b)
        except DeadPoint as exc:
            return Construction(mech, index, q, tuple(b.steps), valid=False, reason=str(exc))
        warnings = list(dict.fromkeys(warnings + more))
    largest = max([abs(complex(*F)) for F in b.forces.values()] + [0.0])
    return Construction(mech, index, q, tuple(steps), b.forces, b.normal, b.couple, b.effort,
                        nice_scale(largest), True, "", tuple(warnings), driver_vector=b.driver_vector,
                        subproblems=subproblems, **_geometry(b))


def _inertia(b: Builder, link: int, body) -> dict:
    """The inertia loads of ``link`` at the builder's position: ``{"F": (x, y) [N], "T": N·m, "h": m or None,
    "line_point": (x, y) or None}``, as :func:`graphkin.analytical.loads.inertia` finds them."""
    a_G, alpha = b.motion(link)
    found = _inertia_at(body.mass, body.I_G, complex(a_G), float(alpha), b.z(link, body.G))
    if found is None:
        inn, i = inertia(b.kin, link), b.i
        h = float(inn.h[i])
        found = {"F": tuple(map(float, inn.F[i])), "T": float(inn.T[i]), "h": None if math.isnan(h) else h,
                 "line_point": None if math.isnan(h) else tuple(map(float, inn.line_point[i]))}
    return found


def _inertia_at(m: float, I_G: float, a_G: complex, alpha: float, G: complex) -> dict | None:
    """:func:`graphkin.analytical.loads.inertia` at one position, from plain numbers, bit for bit.

    ``inertia`` works on arrays of every position; on arrays of one it costs ~40 µs a link, most of the
    geometry of an exercise's draw. The same formulas on numpy scalars take a tenth of that and give the
    same bits (numpy's scalar arithmetic is its array arithmetic; a test compares them).

    Parameters
    ----------
    m : float
        Mass [kg].
    I_G : float
        Moment of inertia about G [kg·m²].
    a_G : complex
        Acceleration of G [m/s²].
    alpha : float
        Angular acceleration [rad/s²].
    G : complex
        Position of G [m].

    Returns
    -------
    dict or None
        ``{"F": (x, y) [N], "T": N·m, "h": m or None, "line_point": (x, y) [m] or None}`` (None for h and the
        point where the loads are a pure couple); None where an input is not finite.
    """
    if not (cmath.isfinite(a_G) and math.isfinite(alpha) and cmath.isfinite(G)):
        return None
    F = -m * np.complex128(a_G) + 0.0
    T = -I_G * np.float64(alpha) + 0.0
    size = np.abs(F)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        # As inertia does: r × F = T with r ⟂ F gives r = −i T / conj(F).
        shift = -1j * T / np.conj(F)
    force = (float(F.real), float(F.imag))
    if not (size > 0 and np.isfinite(shift)):  # no force, or one so small beside the torque: a pure couple
        return {"F": force, "T": float(T), "h": None, "line_point": None}
    with np.errstate(over="ignore"):
        h = np.abs(T) / size
    z = G + shift
    return {"F": force, "T": float(T), "h": float(h), "line_point": (float(z.real), float(z.imag))}


def _geometry(b: Builder) -> dict:
    """Plain-data geometry of the builder's position, for drawing and handouts.

    Points, guides and loads come from the builder, which has found most of them already (the same values:
    a point is ``complex(kin.z(link, name)[i])`` either way).
    """
    kin, i = b.kin, b.i
    mech = kin.mechanism
    points = {link.number: {name: xy(b.z(link.number, name)) for name in link.points} for link in mech.links}
    G = {link: xy(b.z(link, mech.link(link).G)) for link in mech.moving}
    inert, external = {}, {}
    for link in mech.moving:
        body = mech.link(link)
        if (body.mass or body.I_G) and not kin.static:
            inert[link] = _inertia(b, link, body)
        arrows = []
        if mech.gravity and body.mass:
            arrows.append(Arrow(f"W{link}", (0.0, -body.mass * mech.gravity), True, G[link]))
        for ld in mech.loads:
            if isinstance(ld, PointForce) and ld.link == link:
                F = b.applied(ld)
                if F:
                    arrows.append(Arrow(ld.name or f"P{link}", xy(F), True, points[link][ld.point]))
        external[link] = arrows
    torques = {link: [(ld.name or f"T{link}", T) for ld in mech.loads
                      if isinstance(ld, Torque) and ld.link == link and (T := b.applied(ld))]
               for link in mech.moving}
    guides = {tuple(sorted(j.links)): xy(b.u(j)) for j in mech.joints if isinstance(j, Prismatic)}
    angles = {link.number: float(kin.theta[link.number][i]) for link in mech.links}
    pitch = {}
    for joint in mech.joints:
        if isinstance(joint, GearMesh):
            (m, n), (cm, cn) = joint.links, joint.centers
            A, B = complex(kin.z(m, cm)[i]), complex(kin.z(n, cn)[i])
            pitch[tuple(sorted(joint.links))] = xy(pitch_point(joint, m, A, B)[0])
    return {"points": points, "G": G, "inertia": inert, "external": external, "pitch_points": pitch,
            "contacts": {key: b.contacts.get(key, P) for key, P in pitch.items()},
            "torques": torques, "guides": guides, "angles": angles}
