"""The physics every correct solver satisfies, as checks the property tests share: each link's equilibrium with its
inertia loads, action and reaction, the power balance, the loads a mechanism applies at a position, and the
graphical route against the analytical one."""

from __future__ import annotations

import dataclasses
import math
import os

import numpy as np
from hypothesis import HealthCheck, settings

from graphkin.analytical import solve_forces
from graphkin.graphical import construct_forces, construct_kinematics, instant_centres, kinematics_from_polygons
from graphkin.kinematics import solve_kinematics
from graphkin.model import GearMesh, Mechanism, PointForce, Prismatic, Revolute, SpringForce
from tests.strategies import length_scale
from tests.vectors import cross, dot, perp

RTOL = 1e-9


BATCH_RTOL = 1e-12  # same arithmetic on the same numbers: only rounding-order noise allowed


SETTINGS = settings(
    # GRAPHKIN_EXAMPLES=500 for a thorough run; the default keeps the file fast.
    max_examples=int(os.environ.get("GRAPHKIN_EXAMPLES", 20)),
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)


# --------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------
def _solve(case, mech=None):
    mech = case.mechanism if mech is None else mech
    kin = solve_kinematics(mech, case.q, case.q_dot, case.q_ddot)
    assert kin.valid.all(), [kin.reason(i) for i in range(kin.n)]
    r = solve_forces(kin)
    assert r.valid.all(), [r.reason(i) for i in range(r.n)]
    return kin, r


def _lohi(joint):
    i, j = joint.links
    return (min(i, j), max(i, j))


def pitch_point(kin, mesh: GearMesh, link: int):
    """Pitch point of a mesh: on the line of centres where the pitch circles touch.

    External: between the centres, r_link from link's centre. Internal: on the far side of the pinion's centre
    from the annulus's, the annulus's pitch radius from its centre.
    """
    k = mesh.links.index(link)
    Ck = kin.position(link, mesh.centers[k])
    Cj = kin.position(mesh.links[1 - k], mesh.centers[1 - k])
    if mesh.internal:
        ring = int(np.argmax(mesh.radii))
        C_ring, C_pinion = (Ck, Cj) if ring == k else (Cj, Ck)
        u = (C_pinion - C_ring) / np.linalg.norm(C_pinion - C_ring, axis=-1)[:, None]
        return C_ring + max(mesh.radii) * u
    e = (Cj - Ck) / np.linalg.norm(Cj - Ck, axis=-1)[:, None]
    return Ck + mesh.radii[k] * e


def joint_point(kin, joint, link):
    """Where a joint's force acts on ``link``: pin, slider point or pitch point."""
    if isinstance(joint, Revolute):
        return kin.position(link, joint.point)
    if isinstance(joint, Prismatic):
        return kin.position(joint.slider, joint.point)
    return pitch_point(kin, joint, link)


def active(kin, load):
    return np.ones(kin.n) if load.active is None else load.active.mask(kin.q).astype(float)


def table_value(table, q):
    """A load table's value at each q, from its rows by the straight line between them (written here, not np.interp).

    At a jump (two rows at one input) the second row's value holds from the jump on.
    """
    xp, fp = list(table.q), list(table.value)
    if table.periodic:
        xp.append(xp[0] + 2 * math.pi)
        fp.append(fp[0])
    out = []
    for x in np.atleast_1d(q):
        if table.periodic:
            x = xp[0] + math.fmod(math.fmod(x - xp[0], 2 * math.pi) + 2 * math.pi, 2 * math.pi)
        k = max(j for j in range(len(xp)) if xp[j] <= x) if x >= xp[0] else 0
        if k == len(xp) - 1:
            out.append(fp[-1])
        else:
            t = (x - xp[k]) / (xp[k + 1] - xp[k])
            out.append(fp[k] + t * (fp[k + 1] - fp[k]))
    return np.array(out)


def load_value(kin, load):
    """What an external load applies at each position: force (n, 2) [N] or torque (n,) [N·m].

    From the load's own definition (window, table, sense), independently of
    :func:`graphkin.analytical.loads.applied`: a table along the unit vector of
    ``force``; "opposes motion" reverses the load where it would help the
    motion (F·v > 0, a torque's T ω > 0) and drops it at a standstill;
    "working stroke" keeps it only where it resists (F·v < 0).
    """
    on = active(kin, load)
    if isinstance(load, SpringForce):
        # Hooke's law along the spring: k (L − L0) towards the other end.
        d = kin.position(load.anchor_link, load.anchor_point) - kin.position(load.link, load.point)
        L = np.hypot(d[:, 0], d[:, 1])
        return on[:, None] * load.rate * (L - load.free_length)[:, None] * d / L[:, None]
    if isinstance(load, PointForce):
        u = np.asarray(load.force, dtype=float)
        if load.table is not None:
            f = table_value(load.table, kin.q)[:, None] * (u / np.hypot(*u))
        else:
            f = np.tile(u, (kin.n, 1))
        power = dot(f, kin.velocity(load.link, load.point))
    else:
        f = table_value(load.table, kin.q) if load.table is not None else np.full(kin.n, load.torque)
        power = f * kin.omega[load.link]
    if load.sense == "opposes motion":
        keep = np.where(power < 0, 1.0, np.where(power > 0, -1.0, 0.0))
    elif load.sense == "working stroke":
        keep = (power < 0).astype(float)
    else:
        keep = np.ones(kin.n)
    return (on * keep)[:, None] * f if isinstance(load, PointForce) else on * keep * f


def loads_on(kin, r, link):
    """Every load on ``link`` as (force (n,2) or None, point (n,2) or None, couple (n,) or None, what)."""
    mech = kin.mechanism
    body = mech.link(link)
    out = []
    for joint in mech.joints_of(link):
        lo, hi = _lohi(joint)
        other = lo if link == hi else hi
        out.append((r.force(other, link), joint_point(kin, joint, link), None, f"{joint.label}"))
        if isinstance(joint, Prismatic):
            # r.couple[(lo, hi)]: couple of the lower-numbered link on the higher.
            out.append((None, None, (1.0 if link == hi else -1.0) * r.couple[(lo, hi)], f"couple of {joint.label}"))
    d = mech.driver
    if link == d.link:
        if d.kind == "crank":
            out.append((None, None, r.effort, "driving torque"))
        else:
            J = mech.joint_between(mech.frame, link)
            out.append((r.effort[:, None] * kin.guide_direction(J), kin.position(link, J.point), None, "driving force"))
    for load in mech.loads:
        if load.link != link:
            continue
        if isinstance(load, PointForce):
            out.append((load_value(kin, load), kin.position(link, load.point), None, load.name))
        else:
            out.append((None, None, load_value(kin, load), load.name))
    G = kin.G(link)
    if mech.gravity:
        out.append((np.broadcast_to([0.0, -body.mass * mech.gravity], (kin.n, 2)), G, None, "weight"))
    out.append((-body.mass * kin.a_G(link), G, None, "inertia force"))
    out.append((None, None, -body.I_G * kin.alpha[link], "inertia torque"))
    return out


def balance(kin, r, link):
    """Residual force (n, 2) and moment about G (n,) of a link."""
    G = kin.G(link)
    F = np.zeros((kin.n, 2))
    M = np.zeros(kin.n)
    for force, X, couple, _ in loads_on(kin, r, link):
        if force is not None:
            F = F + force
            M = M + cross(X - G, force)
        if couple is not None:
            M = M + couple
    return F, M


def frictionless(mech: Mechanism) -> Mechanism:
    joints = [dataclasses.replace(j, mu=0.0) if isinstance(j, Prismatic) else j for j in mech.joints]
    return dataclasses.replace(mech, joints=tuple(joints))


def power_terms(kin, r):
    """(input + external + gravity + joint powers, Σ dT/dt, scale) per position.

    Joint powers are the powers of the pair's force on both links: zero at
    pins and gear meshes (equal velocities at the point of contact), the
    friction power F·u ṡ at sliders (the couple does no work: both links of
    a prismatic pair turn together).
    """
    mech = kin.mechanism
    n = kin.n
    P = r.effort * kin.q_dot
    scale = np.abs(P)
    for load in mech.loads:
        if isinstance(load, PointForce):
            p = dot(load_value(kin, load), kin.velocity(load.link, load.point))
        else:
            p = load_value(kin, load) * kin.omega[load.link]
        P, scale = P + p, scale + np.abs(p)
    dT = np.zeros(n)
    for link in mech.moving:
        body = mech.link(link)
        p = -body.mass * mech.gravity * kin.v_G(link)[:, 1]
        k = body.mass * dot(kin.a_G(link), kin.v_G(link)) + body.I_G * kin.alpha[link] * kin.omega[link]
        P, dT = P + p, dT + k
        scale = scale + np.abs(p) + np.abs(body.mass * kin.a_G(link)).sum(-1) * np.linalg.norm(kin.v_G(link), axis=-1)
        scale = scale + np.abs(body.I_G * kin.alpha[link] * kin.omega[link])
    v_max = np.zeros(n)
    f_max = np.zeros(n)
    for joint in mech.joints:
        lo, hi = _lohi(joint)
        for link in (lo, hi):
            if link != mech.frame:
                X = joint_point(kin, joint, link)
                v_max = np.maximum(v_max, np.linalg.norm(_velocity_at(kin, link, X), axis=-1))
        f_max = np.maximum(f_max, np.linalg.norm(r.force(lo, hi), axis=-1))
        if isinstance(joint, Prismatic):
            p = dot(r.force(lo, hi), kin.guide_direction(joint)) * kin.slide_rate(joint, hi)
            P, scale = P + p, scale + np.abs(p)
    return P, dT, scale + f_max * v_max


def _velocity_at(kin, link, X):
    """Velocity of the point of ``link`` that is at X (n, 2): v_P + ω k × (X − P)."""
    P = next(iter(kin.mechanism.link(link).points))
    return kin.velocity(link, P) + kin.omega[link][:, None] * perp(X - kin.position(link, P))


def close(a, b, tol):
    a, b = np.asarray(a, float), np.asarray(b, float)
    err = np.abs(a - b)
    tol = tol + 1e-300  # an absolute floor: tolerances scaled by subnormal loads underflow to 0
    if err.ndim == 2:
        err = err.max(axis=-1)
    return bool(np.all(err <= tol)), float(np.max(err - tol))


def load_scales(kin, r):
    """The largest load in the mechanism: (force scale [N], moment scale [N·m]) per position.

    Every load on every moving link counts: joint forces and couples, the
    driving effort, external forces and torques, weights, inertia forces and
    torques. Force scale: the largest force, or the largest couple divided by
    the mechanism's size L. Moment scale: the force scale times (L + the
    mechanism's extent from the origin -- the solver takes moments about the
    origin, so its rounding grows with |X|), plus the largest couple.

    Judged against the whole mechanism, not link by link: a link that carries
    almost nothing (a force of 1e-16 N from rounding elsewhere) is balanced
    to the precision of the loads around it, not to its own.
    """
    mech = kin.mechanism
    L = length_scale(mech)
    f = np.zeros(kin.n)
    c = np.zeros(kin.n)
    ext = np.zeros(kin.n)
    for link in mech.moving:
        for force, X, couple, _ in loads_on(kin, r, link):
            if force is not None:
                f = np.maximum(f, np.linalg.norm(force, axis=-1))
                ext = np.maximum(ext, np.linalg.norm(X, axis=-1))
            if couple is not None:
                c = np.maximum(c, np.abs(couple))
        for name in mech.link(link).points:
            ext = np.maximum(ext, np.linalg.norm(kin.position(link, name), axis=-1))
    f = np.maximum(f, c / L)
    return f, f * (L + ext) + c


def agree(what, graphical, analytical, tol):
    """Assert that a value the graphical route gives equals the analytical one within ``tol`` (absolute).

    The message names the value and gives both, so that a failing example says what disagrees and by how much.
    """
    graphical, analytical = np.asarray(graphical, float), np.asarray(analytical, float)
    off = float(np.max(np.abs(graphical - analytical)))
    assert off <= tol, (f"{what}: graphical {graphical.tolist()} ≠ analytical {analytical.tolist()} "
                        f"(off by {off:.3g}, allowed {tol:.3g})")


def _at(kin, i):
    return f"position {i} (q = {float(kin.q[i])!r})"


def graphical_equals_analytical(case):
    """The force polygons give the analytical joint forces, normal forces, couples and driving effort.

    Each to 1e-9 of the position's largest load or joint force (couples: of the loads' moment scale, or the largest
    couple; the effort: of itself, or of the forces); every polygon closes. Returns how many positions were checked.
    The scale is the loads' as well as the joint forces': where the driver alone balances the loads (a spring on
    the driven slider), the joint forces are rounding noise (1e-17 N) beside a load of 1 N, and so are they in both
    routes.
    """
    mech, q, q_dot, q_ddot = case
    r = solve_forces(solve_kinematics(mech, q, q_dot, q_ddot))
    load, moment = load_scales(r.kinematics, r)
    checked = 0
    for i in np.flatnonzero(r.valid):
        at = _at(r.kinematics, i)
        c = construct_forces(r.kinematics, int(i))
        assert c.valid, f"{at}: {c.reason}"
        assert not c.warnings, f"{at}: {c.warnings}"
        scale = max(max(np.abs(r.force(*k)[i]).max() for k in r.forces), load[i])
        if scale == 0:
            continue
        for key in r.forces:
            agree(f"{at}: force of {key[0]} on {key[1]}", c.force(*key), r.force(*key)[i], RTOL * scale)
        for key in r.normal:
            agree(f"{at}: normal force N{key[0]}{key[1]}", c.normal[key], r.normal[key][i], RTOL * scale)
        lever = max(np.abs(r.couple[k][i]) for k in r.couple) if r.couple else 0.0
        for key in r.couple:
            agree(f"{at}: couple C{key[0]}{key[1]}", c.couple[key], r.couple[key][i],
                  RTOL * max(lever, moment[i], scale * 1e-3))
        effort_scale = max(abs(r.effort[i]), scale * 1e-3)
        agree(f"{at}: driving effort {mech.driver.symbol}", c.effort, r.effort[i], 10 * RTOL * effort_scale)
        for step in c.steps:
            assert step.closure() < RTOL, f"{at}: the polygon of {step.caption!r} does not close"
        checked += 1
    return checked


def motion_scales(kin, i):
    """The scales of position ``i``'s motion: (ω [rad/s], α [rad/s²], v [m/s], a [m/s²]).

    The largest ω; the largest |α| + ω²; the largest speed and acceleration of a named point or a G, plus what the
    links' turning gives across the mechanism (a pitch point is no named point; a gear's named points may all sit
    on its pivot, where they stand still).
    """
    mech = kin.mechanism
    links = mech.moving
    size = length_scale(mech)
    points = [(l, n) for l in links for n in (*mech.link(l).points, mech.link(l).G)]
    w_scale = max(abs(kin.omega[l][i]) for l in links)
    al_scale = max(abs(kin.alpha[l][i]) + kin.omega[l][i] ** 2 for l in links)
    v_scale = max(np.hypot(*kin.velocity(l, n)[i]) for l, n in points) + w_scale * size
    a_scale = max(np.hypot(*kin.acceleration(l, n)[i]) for l, n in points) + al_scale * size
    return w_scale, al_scale, v_scale, a_scale


def polygons_equal_analytical(case):
    """The velocity and acceleration polygons (and the instant centres) give the analytical kinematics.

    Every value read off a polygon (ω, α of each link, v and a of each named point and of each G) agrees
    with the solver to 1e-9 of the position's largest value of its kind; each image point a dyad step finds
    lies on both lines it intersects. Returns how many positions were checked.
    """
    mech, q, q_dot, q_ddot = case
    kin = solve_kinematics(mech, q, q_dot, q_ddot)
    checked = 0
    for i in np.flatnonzero(kin.valid):
        at = _at(kin, i)
        c = construct_kinematics(kin, int(i))
        assert c.valid, f"{at}: {c.reason}"
        links = mech.moving
        v = {(l, n): kin.velocity(l, n)[i] for l in links for n in mech.link(l).points}
        a = {(l, n): kin.acceleration(l, n)[i] for l in links for n in mech.link(l).points}
        w_scale, al_scale, v_scale, a_scale = motion_scales(kin, i)
        for l, n in v:
            agree(f"{at}: v_{n} of link {l}", c.velocity[l, n], v[l, n], RTOL * v_scale)
            agree(f"{at}: a_{n} of link {l}", c.acceleration[l, n], a[l, n], RTOL * a_scale)
        for l in links:
            agree(f"{at}: v_G{l}", c.v_G[l], kin.v_G(l)[i], RTOL * v_scale)
            agree(f"{at}: a_G{l}", c.a_G[l], kin.a_G(l)[i], RTOL * a_scale)
            agree(f"{at}: ω{l}", c.omega[l], kin.omega[l][i], RTOL * w_scale)
            agree(f"{at}: α{l}", c.alpha[l], kin.alpha[l][i], RTOL * al_scale)
        for step in c.steps:
            scale = v_scale if step.polygon == "velocity" else a_scale
            for found in step.points.values() if step.lines else ():
                for line in step.lines:
                    off = np.subtract(found, line.point)
                    assert abs(cross(line.direction, off)) <= RTOL * scale, f"{at}: {step.caption}: off {line.name}"

        ic = instant_centres(kin, int(i))
        assert ic.valid, f"{at}: instant centres: {ic.reason}"
        for (l, n), value in ic.velocity.items():
            agree(f"{at}: v_{n} of link {l} from the instant centres", value, v[l, n], RTOL * v_scale)
        for l, w in ic.omega.items():
            agree(f"{at}: ω{l} from the instant centres", w, kin.omega[l][i], RTOL * w_scale)
        if not ic.missing:
            assert set(ic.omega) == set(links), f"{at}: the instant centres give ω of {sorted(ic.omega)} only"
        checked += 1
    return checked


def forces_from_polygons_equal_analytical(case):
    """The force route with its inertia loads from the polygons gives the analytical forces and driving effort.

    To 1e-9 of the position's largest joint force, or of the largest inertia loads the motion's scales give (the
    polygons' a_G and α are the analytical ones to 1e-9 of those scales, :func:`polygons_equal_analytical`):
    where every force is 0 in exact arithmetic (a massive gear whose G is on its pivot, and no other load), the
    analytical route's forces are rounding, ε m ω² |O|, and the polygons' may be exactly 0.
    """
    mech, q, q_dot, q_ddot = case
    kin = solve_kinematics(mech, q, q_dot, q_ddot)
    r = solve_forces(kin)
    p = solve_forces(kinematics_from_polygons(kin))
    size = length_scale(mech)
    m = max(mech.link(l).mass for l in mech.moving)
    I_G = max(mech.link(l).I_G for l in mech.moving)
    checked = 0
    for i in np.flatnonzero(r.valid):
        at = _at(kin, i)
        assert p.valid[i], f"{at}: {p.reason(i)}"
        _, al_scale, _, a_scale = motion_scales(kin, i)
        scale = max(max(np.abs(r.force(*k)[i]).max() for k in r.forces), m * a_scale + I_G * al_scale / size)
        for key in r.forces:
            agree(f"{at}: force of {key[0]} on {key[1]} (inertia loads from the polygons)", p.force(*key)[i],
                  r.force(*key)[i], RTOL * scale + 1e-300)
        effort_scale = max(abs(r.effort[i]), scale * 1e-3)
        agree(f"{at}: driving effort {mech.driver.symbol} (inertia loads from the polygons)", p.effort[i],
              r.effort[i], 10 * RTOL * effort_scale)
        c = construct_forces(p.kinematics, int(i))
        assert c.valid, f"{at}: {c.reason}"
        agree(f"{at}: driving effort {mech.driver.symbol} (force polygons on the polygons' inertia loads)", c.effort,
              r.effort[i], 10 * RTOL * effort_scale)
        checked += 1
    return checked
