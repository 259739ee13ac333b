"""Instant centres by Kennedy's theorem, and the velocities they give (:func:`instant_centres`).

The second graphical route to a point's velocity. The primary centres come from the joints: a pin is the
centre of its two links, a sliding pair's centre is at infinity perpendicular to its guide, two gears in
mesh have theirs at the pitch point. Kennedy's theorem (the three centres of any three links lie on one
line) gives the others: I_ik lies on the line I_ij I_jk for every third link j, so two such lines meet at
it. Then, link by link, a centre I_mk shared with a link m whose motion is known is a point with the same
velocity on both links, and link k turns about I_1k: v_P = ω_k × (P − I_1k).

Points are homogeneous, (x, y, w) with x, y divided by the mechanism's size, so that a centre at infinity
(w = 0: a link in translation, two sliders) is a point like any other and the velocity formulas never
divide by w.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass, field
from itertools import combinations

import numpy as np

from graphkin.analytical.meshes import pitch as pitch_point
from graphkin.errors import GraphkinError
from graphkin.graphical.captions import Captions, Later, number
from graphkin.graphical.guard import centres_disagreement, derived, kept, motion_at
from graphkin.graphical.guard import plan as kept_plan
from graphkin.kinematics import DriverGroup, Kinematics
from graphkin.model import GearMesh, Prismatic, Revolute

SAME = 1e-9
"""|sin| of the angle between two homogeneous points (or lines) below which they are the same one."""


@dataclass(frozen=True)
class InstantCentres:
    """The instant centres of one position and the velocities they give.

    Attributes
    ----------
    mechanism : Mechanism
    index : int
        Position index in the kinematics.
    centres : dict of (int, int) to (float, float)
        Each centre found at a finite point [m], keyed by the two links (lower first).
    at_infinity : dict of (int, int) to (float, float)
        Each centre at infinity, as the unit direction it lies in (perpendicular to the relative sliding).
    steps : tuple of str
        How each centre was found, in order: from a joint, or from the two Kennedy lines that meet at it.
    missing : tuple of (int, int)
        Pairs of links whose centre Kennedy's theorem does not reach (each needs two lines through known
        centres that are not the same line).
    omega : dict of int to float
        Angular velocity of each link whose motion the centres give [rad/s].
    velocity : dict of (int, str) to (float, float)
        Every named point of those links [m/s].
    v_G : dict of int to (float, float)
        Their centres of mass [m/s].
    valid : bool
    reason : str
    disagreement : bool
        True where the centres are not valid because a value they yield disagrees with the analytical route
        (:mod:`graphkin.graphical.guard`): a fault in graphkin's arithmetic, to be reported, not a position the
        linkage cannot take (the ``reason`` names the quantity and both values).
    """

    mechanism: object
    index: int
    centres: dict = field(default_factory=dict)
    at_infinity: dict = field(default_factory=dict)
    steps: tuple[str, ...] = Captions()  # may be written when first read (graphical.captions.Later)
    missing: tuple = ()
    omega: dict = field(default_factory=dict)
    velocity: dict = field(default_factory=dict)
    v_G: dict = field(default_factory=dict)
    valid: bool = True
    reason: str = ""
    disagreement: bool = False

    def __getstate__(self):
        # Steps not yet written are written before the result is copied or pickled.
        return {**self.__dict__, "steps": self.steps}


# Homogeneous points and lines are plain 3-tuples: a mechanism has a few dozen pairs, and tuples are several
# times faster than small numpy arrays here.
def _cross(p, q) -> tuple[float, float, float]:
    return (p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0])


def _norm(p) -> float:
    return math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])


def _unit(p) -> tuple[float, float, float]:
    size = _norm(p)
    return (p[0] / size, p[1] / size, p[2] / size)


def _line(p, q):
    """The line through two homogeneous points, or None where they are the same point."""
    line = _cross(p, q)
    return None if _norm(line) <= SAME else _unit(line)


def _where(P, size: float) -> str:
    if abs(P[2]) <= SAME:
        return f"at infinity, in the direction ({number(P[0])}, {number(P[1])})"
    return f"at ({number(P[0] / P[2] * size * 1e3)}, {number(P[1] / P[2] * size * 1e3)}) mm"


# The steps are written when first read (most centres are made to be checked): these take all they print.
def _primary(lo: int, hi: int, how: str, P, size: float) -> str:
    return f"I{lo}{hi}: {how} ({_where(P, size)})."


def _kennedy(a: int, b: int, j: int, via: int, P, size: float) -> str:
    return (f"I{min(a, b)}{max(a, b)}: on the line I{min(a, j)}{max(a, j)} I{min(j, b)}{max(j, b)} and "
            f"on the line I{min(a, via)}{max(a, via)} I{min(via, b)}{max(via, b)} (Kennedy), which meet "
            f"{_where(P, size)}.")


def _shape(kin: Kinematics) -> tuple[dict, dict, dict]:
    """What the centres read of a kinematics' mechanism, made once per mechanism (its plan's cache) and found once
    per kinematics (:func:`graphkin.graphical.guard.kept`): every named point in its link's own frame [m] by
    ``(link, name)``, each moving link's point names, and its centre of mass [m]."""
    mech = kin.mechanism
    plan = kept_plan(kin)
    shape = plan.compiled.get("centres")
    if shape is None:
        shape = plan.compiled["centres"] = (plan.points, {n: list(mech.link(n).points) for n in mech.moving},
                                            {n: complex(*mech.link(n).G) for n in mech.moving})
    return shape


def instant_centres(kin: Kinematics, index: int = 0) -> InstantCentres:
    """Every instant centre Kennedy's theorem reaches at position ``index``, and the velocities they give.

    Parameters
    ----------
    kin : Kinematics
        The mechanism's motion; the centres read its positions and the input's rate only.
    index : int
        Which of the kinematics' positions.

    Returns
    -------
    InstantCentres
        Links whose centres are not all reached have no velocities here (see ``missing``). Not ``valid``, with
        the reason, where a centre or a velocity it gives differs from the analytical kinematics
        (:mod:`graphkin.graphical.guard`).
    """
    if not isinstance(kin, Kinematics):
        raise GraphkinError(f"instant_centres takes the Kinematics of a problem, got {type(kin).__name__}")
    if isinstance(index, (bool, np.bool_)) or not isinstance(index, (int, np.integer)) or not -kin.n <= index < kin.n:
        raise GraphkinError(f"instant_centres: index must be a whole number from 0 to {kin.n - 1}, got {index!r}")
    i = int(index) % kin.n
    mech = kin.mechanism
    if not kin.valid[i]:
        return InstantCentres(mech, i, valid=False, reason=kin.reason(i))
    frame = mech.frame
    kin, at = derived(kin, i)  # placed by the input motion alone, a problem's given values left out

    points, names, G_local = kept(kin, "centres", _shape)
    # Where each link is (its origin O [m] and turn e^iθ, by its column): read once, from the analytical motion of
    # the position the guard compares the centres with (the kinematics' own numbers, which both routes share).
    truth = motion_at(kin, at, accelerations=False)
    col, O, e = truth.column, truth.O, truth.e
    pos = {(link, name): p if link == frame else O[col[link]] + e[col[link]] * p  # where each point is [m]
           for (link, name), p in points.items()}
    size = max(map(abs, pos.values())) or 1.0

    def hom(z: complex):
        return _unit((z.real / size, z.imag / size, 1.0))

    # Each centre found, under both orders of its links: (a, b) and (b, a).
    known: dict[tuple[int, int], tuple] = {}
    steps = []
    for joint in mech.joints:
        a, b = joint.links
        if isinstance(joint, Revolute):
            P = hom(pos[a, joint.point])
            how = f"the pin {joint.point}"
        elif isinstance(joint, Prismatic):
            u = (1 + 0j if joint.guide == frame else e[col[joint.guide]]) * cmath.exp(1j * joint.direction)
            P = (-u.imag, u.real, 0.0)
            how = f"at infinity, perpendicular to the guide at {joint.point}"
        elif isinstance(joint, GearMesh):
            A, B = pos[a, joint.centers[0]], pos[b, joint.centers[1]]
            P = hom(complex(pitch_point(joint, a, A, B)[0]))  # an internal mesh's lies beyond the pinion
            how = "the pitch point"
        else:  # pragma: no cover - the model has these three joints only
            raise AssertionError(joint)
        known[a, b] = known[b, a] = P
        steps.append(Later(_primary, min(a, b), max(a, b), how, P, size))

    links = [link.number for link in mech.links]
    progress = True
    while progress:
        progress = False
        for a, b in combinations(links, 2):
            if (a, b) in known:
                continue
            lines = []
            for j in links:
                if j == a or j == b:
                    continue
                p, q = known.get((a, j)), known.get((j, b))
                if p is None or q is None:
                    continue
                line = _line(p, q)
                if line is None:
                    continue
                for other, via in lines:
                    P = _cross(line, other)
                    if _norm(P) > SAME:
                        P = _unit(P)
                        known[a, b] = known[b, a] = P
                        steps.append(Later(_kennedy, a, b, j, via, P, size))
                        progress = True
                        break
                else:
                    lines.append((line, j))
                    continue
                break

    # Link by link: Ω, X, w with v(P) = iΩ (P w − X) (P in units of ``size``), X/w being the centre I_1k.
    fields = {frame: (0.0, 0j, 1.0)}
    g = next(g for g in kin.groups if isinstance(g, DriverGroup))
    q_dot = kin.q_dot.item(at)  # a Python float, no numpy scalar made
    if isinstance(g.joint, Revolute):
        I12 = known[frame, g.link]
        fields[g.link] = (q_dot * size / I12[2], complex(I12[0], I12[1]), I12[2])
    else:
        # A driving slider translates: w = 0 and X = i v, so that v(P) = -iX is v at every point.
        fields[g.link] = (1.0, 1j * q_dot * cmath.exp(1j * g.joint.direction), 0.0)
    progress = True
    while progress:
        progress = False
        for k in links:
            if k in fields or (frame, k) not in known:
                continue
            I1k = known[frame, k]
            X, w = complex(I1k[0], I1k[1]), I1k[2]
            for m, (Om, Xm, wm) in list(fields.items()):
                Imk = known.get((m, k))
                if Imk is None:
                    continue
                Y, s = complex(Imk[0], Imk[1]), Imk[2]
                D = Y * w - X * s
                if abs(D) <= SAME:
                    continue
                R = Om * (Y * wm - Xm * s)  # s times the velocity of I_mk as a point of m (over i)
                fields[k] = ((R.real * D.real + R.imag * D.imag) / abs(D) ** 2, X, w)
                progress = True
                break

    omega, velocity, v_G = {}, {}, {}
    for link in mech.moving:
        if link not in fields:
            continue
        Om, X, w = fields[link]
        omega[link] = Om * w / size
        G = O[col[link]] + e[col[link]] * G_local[link]
        for name in names[link]:
            v = 1j * Om * (pos[link, name] / size * w - X)
            velocity[link, name] = (v.real, v.imag)
        v = 1j * Om * (G / size * w - X)
        v_G[link] = (v.real, v.imag)
    centres, infinite = {}, {}
    for (lo, hi), P in known.items():
        if lo > hi:
            continue
        if abs(P[2]) <= SAME:
            d = math.hypot(P[0], P[1])
            infinite[lo, hi] = (P[0] / d, P[1] / d)
        else:
            centres[lo, hi] = (P[0] / P[2] * size, P[1] / P[2] * size)
    missing = tuple(sorted((a, b) for a, b in combinations(sorted(links), 2) if (a, b) not in known))
    ic = InstantCentres(mech, i, centres, infinite, tuple(steps), missing, omega, velocity, v_G)
    # Checked against the analytical kinematics before anyone sees them (graphical/guard.py).
    why = centres_disagreement(kin, at, ic)
    if why:
        return InstantCentres(mech, i, steps=tuple(steps) + (f"{why}.",), valid=False, reason=why, disagreement=True)
    return ic

