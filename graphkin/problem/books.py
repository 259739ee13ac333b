"""Loads and inputs as books give them: a pressure on a piston, a power at a speed, a crank angle from a dead centre
in the sense of rotation, a crank placed by its piston's travel, a slider placed by another link's angle, and a
forward step (``[forward]``).

Each becomes what graphkin's core solves — a force, a torque, an input position, a :class:`Forward` — at the
boundary, with every error naming the file and the field (``docs/problem-files.md``).
"""

from __future__ import annotations

import math
import re
from collections import OrderedDict
from dataclasses import dataclass, replace

import numpy as np

from graphkin.errors import ModelError
from graphkin.kinematics import decompose, solve_kinematics
from graphkin.kinematics.plan import kept_plan
from graphkin.kinematics.structure import Dyad
from graphkin.model import GearMesh, PointForce, Prismatic, Revolute, StrokeForce, Table, Torque, spring
from graphkin.model.names import force_name
from graphkin.notation import num
from graphkin.problem.placement import placements
from graphkin.problem.problem import Forward
from graphkin.problem.reader import shown
from graphkin.problem.tables import load_table, parse_table
from graphkin.problem.unknown import Unknown

DEAD_CENTRES = {"inner dead centre": 1, "top dead centre": 1, "outer dead centre": -1, "bottom dead centre": -1}
"""A crank angle's origin in an engine: the crank pointing at the piston (+1) or away from it (−1)."""
SENSES_OF_ROTATION = {"counter-clockwise": 1.0, "clockwise": -1.0}
"""A crank's sense of rotation as a book names it, and the sign it gives ω and α."""
SIDES = ("cover", "crank")
"""The faces of a piston a pressure acts on: the cover end (no rod) and the crank end (the rod's side)."""
ROLES = ("resisting", "driving")
"""What a power does to its link's rotation: a load taken off it, or a drive."""


def forward(rd, value, kind, q_dot):
    """``[forward]``: the shaft's moment of inertia (I, or mass and k) and the resisting torque (or power)."""
    t = rd.table(value, "forward", {"I", "mass", "k", "torque", "power"})
    if kind != "crank":
        raise rd.fail("forward", "a forward step finds a crank shaft's angular acceleration: the driver must be a crank")
    if "I" in t:
        for key in ("mass", "k"):
            if key in t:
                raise rd.fail(f"forward.{key}", "give I, or the mass and its radius of gyration k, not both")
        I = rd.si(t["I"], "moment_of_inertia", "forward.I")
    elif "mass" in t or "k" in t:
        m = rd.si(rd.need(t, "mass", "forward"), "mass", "forward.mass")
        k = rd.si(rd.need(t, "k", "forward"), "length", "forward.k", "length")
        I = m * k * k
    else:
        raise rd.fail("forward.I", "is missing: the moment of inertia of the parts on the crank shaft, e.g. "
                      "I = \"21.6 kg*m^2\", or their mass and radius of gyration (mass = \"60 kg\", k = \"0.6 m\")")
    if not I > 0:
        raise rd.fail("forward.I" if "I" in t else "forward.mass", "must be > 0: a shaft with no inertia has no "
                      "angular acceleration to find")
    given = [key for key in ("torque", "power") if key in t]
    if len(given) != 1:
        raise rd.fail("forward.torque", "give the resisting load once: torque = \"1591 N*m\" (its size; it opposes "
                      "the rotation) or power = \"20 kW\" (taken off at the crank's speed)"
                      + (", not both" if given else ""))
    if "torque" in t:
        T = rd.si(t["torque"], "torque", "forward.torque")
        if T < 0:
            raise rd.fail("forward.torque", f"is the resisting torque's size (it opposes the rotation): give it ≥ 0, "
                          f"got {t['torque']!r}")
    else:
        P = rd.si(t["power"], "power", "forward.power")
        if P < 0:
            raise rd.fail("forward.power", f"is the power taken off the shaft: give it ≥ 0, got {t['power']!r}")
        if len(set(np.abs(q_dot))) != 1 or q_dot[0] == 0:
            raise rd.fail("forward.power", "a power becomes a torque at the crank's speed (T = P/ω): the driver needs "
                          "one constant, non-zero omega")
        T = P / abs(float(q_dot[0]))
    return Forward(I, T)


def crank_from_dead_centre(rd, d, mech, q):
    """``driver.from``: crank angles measured from a dead centre in the sense of rotation, as angles from +x.

    The dead centres are where the crank and the connecting rod lie in line: the piston's pin, on its guide, is
    r + l (inner, the crank pointing at the piston) or l − r (outer) from the crank's pivot. Of the two such points
    on the guide line, the one the mechanism assembles into is taken.
    """
    which = d["from"]
    if which not in DEAD_CENTRES:
        raise rd.fail("driver.from", f"must be one of {', '.join(repr(k) for k in DEAD_CENTRES)}, got {which!r}")
    theta, _ = dead_centre(rd, mech, which, "driver.from")
    return theta + SENSES_OF_ROTATION[d.get("sense", "counter-clockwise")] * q


MOVING = ("away", "towards")
"""Which of the two crank angles at a piston's travel ``driver.moving`` names: the piston moving away from the dead
centre the travel is measured from (on the stroke that begins there), or back towards it."""
_FRACTION = re.compile(r"^\s*(\d+(?:\.\d*)?|\.\d+)\s*(?:/\s*(\d+(?:\.\d*)?|\.\d+)\s*)?$")


def read_travel(rd, value) -> tuple[np.ndarray, np.ndarray]:
    """``driver.travel`` as written: each value a length [m] or a fraction of the stroke, and which are fractions.

    A length carries its unit (``"80 mm"``); a fraction is a bare number (``0.25``) or a ratio of two
    (``"1/3"``), since a third has no exact decimal. A range is of lengths, or of bare numbers.
    """
    field = "driver.travel"
    if isinstance(value, dict):
        fraction = isinstance(value.get("start"), (int, float)) and not isinstance(value.get("start"), bool)
        x = rd.array(value, "dimensionless" if fraction else "length", field)
        return x, np.full(len(x), fraction)
    items = value if isinstance(value, list) else [value]
    if not items:
        raise rd.fail(field, "the list is empty; give at least one travel")
    x, fraction = np.empty(len(items)), np.zeros(len(items), bool)
    for i, raw in enumerate(items):
        where = f"{field}[{i}]" if isinstance(value, list) else field
        if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
            raise rd.fail(where, f"must be a length (\"80 mm\") or a fraction of the stroke (0.25, \"1/3\"), got "
                          f"{raw!r}")
        ratio = _FRACTION.match(raw) if isinstance(raw, str) else None
        if isinstance(raw, (int, float)) or ratio:
            top, bottom = (float(raw), 1.0) if not ratio else (float(ratio[1]), float(ratio[2] or 1.0))
            if bottom == 0:
                raise rd.fail(where, f"\"{raw}\" divides by zero: a fraction of the stroke is p/q with q > 0")
            x[i], fraction[i] = top / bottom, True
            if not 0 <= x[i] <= 1:
                raise rd.fail(where, f"{raw!r} is not a fraction of the stroke: give one from 0 to 1, or a length "
                              "with its unit (\"80 mm\")")
        else:
            x[i] = rd.si(raw, "length", where, None)
            if not x[i] >= 0:
                raise rd.fail(where, f"\"{raw}\" is the piston's distance from the dead centre: give it ≥ 0 (the "
                              "stroke it is on is driver.moving)")
            rd.ranged(x[i], raw, "coordinate", where)
    return x, fraction


def crank_from_travel(rd, d, mech, q_dot) -> np.ndarray:
    """``driver.travel``: the crank angles [rad] at which the piston has travelled a length from a dead centre.

    The piston's pin is then at X = X_dc + s u on its guide (u from that dead centre towards the other, s the travel
    or its fraction of the stroke |X_other − X_dc|), and the crank pin is where the crank's circle about its pivot
    O (radius r) meets the connecting rod's about X (radius l): two points, one on each stroke, in closed form. Of
    the two, ``driver.moving`` takes the one where the piston moves away from the dead centre as the crank turns in
    its sense of rotation (``driver.sense``; the default) or back towards it. Each angle is checked by solving the
    linkage there: the pin is at X on the file's assembly branch.
    """
    which = d.get("from", "inner dead centre")
    if which not in DEAD_CENTRES:
        raise rd.fail("driver.from", f"must be one of {', '.join(repr(k) for k in DEAD_CENTRES)}, got {which!r}")
    moving = d.get("moving", "away")
    if moving not in MOVING:
        raise rd.fail("driver.moving", f"must be \"away\" (the piston moving away from the {which}, on the stroke "
                      f"that begins there: the default) or \"towards\" (coming back to it), got {moving!r}")
    sense = SENSES_OF_ROTATION[d.get("sense", "counter-clockwise")]
    if "sense" not in d and (q_dot < 0).any():
        raise rd.fail("driver.omega", f"is negative ({float(q_dot[q_dot < 0][0]):.6g} rad/s, clockwise) but driver."
                      "sense is not given: the piston's travel is on the stroke it makes in the crank's sense of "
                      "rotation, so write sense = \"clockwise\" and omega as its size")
    field = "driver.travel"
    s, fraction = read_travel(rd, d["travel"])
    theta_a, X_a = dead_centre(rd, mech, which, field)
    other = "outer dead centre" if DEAD_CENTRES[which] > 0 else "inner dead centre"
    theta_b, X_b = dead_centre(rd, mech, other, field)
    stroke = abs(X_b - X_a)
    s = np.where(fraction, s * stroke, s)
    beyond = np.flatnonzero(s > stroke * (1 + 1e-12))
    if len(beyond):
        k = beyond[0]
        raw = d["travel"][k] if isinstance(d["travel"], list) else d["travel"]
        raw = shown(raw) if not isinstance(raw, dict) else f"{s[k] * 1e3:.6g} mm"
        raise rd.fail(f"{field}[{k}]" if isinstance(d["travel"], list) else field,
                      f"{raw} is beyond the stroke: the piston travels {stroke * 1e3:.6g} mm from the {which} to "
                      f"the {other}")
    # The stroke is the distance between two computed points: a travel of the whole stroke, as written, may exceed
    # or fall short of it by rounding, which at a dead centre (where the piston stands still) would turn the crank
    # by ~1e-8 rad. Within rounding of either end the piston is at that dead centre.
    s = np.where(s >= stroke * (1 - 1e-13), stroke, np.where(s <= stroke * 1e-13, 0.0, s))
    pivot, C, rod, P, _ = piston(rd, mech, field)
    link_c = mech.link(mech.driver.link)
    (ox, oy), (cx, cy) = link_c.point(pivot.point), link_c.point(C.point)
    r, beta = math.hypot(cx - ox, cy - oy), math.atan2(cy - oy, cx - ox)
    (ax, ay), (bx, by) = mech.link(rod).point(C.point), mech.link(rod).point(P.point)
    l = math.hypot(bx - ax, by - ay)
    O = complex(*mech.link(mech.frame).point(pivot.point))
    X = X_a + s * (X_b - X_a) / stroke
    # The crank pin: on the circle |C − O| = r and on |C − X| = l, a from O along OX and h either side of it.
    D = np.abs(X - O)
    a = (r * r - l * l + D * D) / (2 * D)
    h = np.sqrt(np.maximum(r * r - a * a, 0.0))
    along = (X - O) / D
    turned = np.stack([np.angle((a + side * 1j * h) * along) - beta for side in (1.0, -1.0)])
    # Each candidate's angle from the dead centre in the sense of rotation: the piston moves away from it until
    # the crank has turned as far as the other dead centre, and comes back after.
    phi = np.mod(sense * (turned - theta_a), 2 * math.pi)
    phi = phi.min(axis=0) if moving == "away" else phi.max(axis=0)
    phi = np.where(s == 0, 0.0, np.where(s == stroke, np.mod(sense * (theta_b - theta_a), 2 * math.pi), phi))
    theta = theta_a + sense * phi
    kin = solve_kinematics(mech, theta, 0.0, 0.0)
    at = kin.position(rod, P.point)[:, 0] + 1j * kin.position(rod, P.point)[:, 1]
    wrong = np.flatnonzero(~kin.valid | ~(np.abs(at - X) <= 1e-9 * (r + l)))
    if len(wrong):
        raise rd.fail(field, f"the mechanism cannot be assembled with the piston {s[wrong[0]] * 1e3:.6g} mm from "
                      f"its {which} (on the file's assembly branch)")
    return theta


def piston(rd, mech, field):
    """The slider-crank of a crank driver: (the piston's pin joint, its guide, the rod's link, r, l, β)."""
    crank = mech.driver.link
    frame = mech.frame
    why = ("a dead centre belongs to a slider-crank: the crank pinned to the frame and to a connecting rod, whose "
           "other pin is the point of a piston that runs on a guide of the frame")
    if not mech.driver.crank:
        raise rd.fail(field, why + " (here the driver is a slider)")
    pivot = mech.joint_between(frame, crank)
    rods = [j for j in mech.joints_of(crank) if isinstance(j, Revolute) and frame not in j.links]
    if not isinstance(pivot, Revolute) or len(rods) != 1:
        raise rd.fail(field, why)
    C = rods[0]
    rod = C.links[0] if C.links[1] == crank else C.links[1]
    pins = [j for j in mech.joints_of(rod) if isinstance(j, Revolute) and crank not in j.links]
    guides = [(j, g) for j in pins for g in mech.joints_of(j.links[0] if j.links[1] == rod else j.links[1])
              if isinstance(g, Prismatic) and g.guide == frame and g.point == j.point]
    if len(guides) != 1:
        raise rd.fail(field, why)
    P, guide = guides[0]
    return pivot, C, rod, P, guide


_DEAD_CENTRES: OrderedDict = OrderedDict()
"""Dead centres found, by the geometry that decides them (an exercise asks again for every draw)."""


def dead_centre(rd, mech, which, field):
    """A dead centre of the crank driver's slider-crank: (the crank angle θ there, the piston pin's position).

    Found once per geometry: the links, joints, driver and branches decide it (the loads and the motion do
    not), and finding it solves the linkage's position. A geometry that has none raises each time, naming the
    caller's file.
    """
    key = (which, *_geometry(mech))
    found = _DEAD_CENTRES.get(key)
    if found is None:
        found = _DEAD_CENTRES[key] = _dead_centre(rd, mech, which, field)
        if len(_DEAD_CENTRES) > 64:
            _DEAD_CENTRES.popitem(last=False)
    return found


def _geometry(mech) -> tuple:
    """What decides a mechanism's dead centres, as text: made once per mechanism, kept in its plan (a mechanism
    changed in place gets a new one), or each time for one that has no plan yet."""
    plan = kept_plan(mech)
    compiled = plan.compiled if plan is not None else {}
    geometry = compiled.get("dead centre")
    if geometry is None:
        geometry = compiled["dead centre"] = (mech.frame, mech.driver.link, repr(mech.links), repr(mech.joints),
                                              repr(sorted(mech.assembly.items())))
    return geometry


def _dead_centre(rd, mech, which, field):
    crank = mech.driver.link
    pivot, C, rod, P, guide = piston(rd, mech, field)
    link_c, link_r = mech.link(crank), mech.link(rod)
    (ox, oy), (cx, cy) = link_c.point(pivot.point), link_c.point(C.point)
    r, beta = math.hypot(cx - ox, cy - oy), math.atan2(cy - oy, cx - ox)
    (ax, ay), (bx, by) = link_r.point(C.point), link_r.point(P.point)
    l = math.hypot(bx - ax, by - ay)
    f = mech.link(mech.frame)
    O, T = complex(*f.point(pivot.point)), complex(*f.point(guide.through))
    u = complex(math.cos(guide.direction), math.sin(guide.direction))
    reach = r + l if DEAD_CENTRES[which] > 0 else l - r
    w = T - O
    b = (w * u.conjugate()).real
    disc = b * b - abs(w) ** 2 + reach * reach
    if disc < 0:
        raise rd.fail(field, f"the piston's guide passes {abs((w * u.conjugate()).imag) * 1e3:.6g} mm from the "
                      f"crank's pivot, farther than {reach * 1e3:.6g} mm: this slider-crank has no {which}")
    for t in (-b + math.sqrt(disc), -b - math.sqrt(disc)):
        X = T + t * u
        # The crank points at the piston at the inner dead centre, away from it at the outer one.
        theta = float(np.angle((X - O) * DEAD_CENTRES[which])) - beta
        kin = solve_kinematics(mech, [theta], 0.0, 0.0)
        # The slider-crank alone decides: a linkage that goes on from it may not assemble there (its row says so
        # when solved), and the piston's pin is then still placed (nan only where the slider-crank is not).
        if abs(complex(*kin.position(rod, P.point)[0]) - X) <= 1e-6 * (r + l):
            return theta, X
    raise rd.fail(field, f"the mechanism cannot be assembled at its {which}")


def placed(rd, d, mech):
    """``driver.place``: the slider's position s [m] at which a named link stands at a given angle.

    Every position the linkage reaches counts, its dead centres too (:mod:`.placement`); an angle it never
    reaches is refused with the angles it does.
    """
    t = rd.table(d["place"], "driver.place", {"link", "theta"})
    link = rd.whole(rd.need(t, "link", "driver.place"), "driver.place.link")
    if link not in mech.moving or link == mech.driver.link:
        raise rd.fail("driver.place.link", f"must be a moving link other than the slider "
                      f"({', '.join(str(n) for n in mech.moving if n != mech.driver.link)}), got {link!r}")
    target = rd.si(rd.need(t, "theta", "driver.place"), "angle", "driver.place.theta")
    found = placements(mech, link, target)
    if not found.s:
        reach = _reach(found)
        # Not on the file's branch: say which other branch has it, so the book's figure can be matched.
        for key in sorted({g.key for g in decompose(mech) if isinstance(g, Dyad)}):
            other = replace(mech, assembly={**mech.assembly, key: -mech.assembly.get(key, 1)})
            there = placements(other, link, target).s
            if there:
                raise rd.fail("driver.place.theta", f"link {link} never stands at {t['theta']!r} on the branch the "
                              f"file assembles (there {reach}), but does on the other branch at {key} (s = "
                              + ", ".join(f"{x} mm" for x in _apart(there))
                              + f"): add [assembly] {key} = {-mech.assembly.get(key, 1)} if the book's figure is that one")
        raise rd.fail("driver.place.theta", f"link {link} never stands at {t['theta']!r} as the slider moves: {reach}")
    if len(found.s) > 1:
        raise rd.fail("driver.place.theta", f"link {link} stands at {t['theta']!r} at more than one slider position ("
                      + ", ".join(f"s = {x} mm" for x in _apart(found.s)) + "): give the one the book means as s")
    return np.array(found.s)


def _apart(s) -> list[str]:
    """Slider positions [m] in mm, with 6 significant digits or as many more as tell them apart."""
    for digits in range(6, 18):
        shown = [f"{x * 1e3:.{digits}g}" for x in s]
        if len(set(shown)) == len(shown):
            return shown
    return shown


def _reach(found) -> str:
    """Where a link stands, stretch by stretch of the slider's travel, for a message: "it stands from … to …"."""
    if not found.reach:
        return "the linkage cannot be assembled anywhere along the guide"

    def deg(r, x):
        return num(math.degrees(x), 6, minus="-", zero=math.degrees(r.rounding))

    def mm(x):
        return num(x * 1e3, 6, minus="-")

    return "it stands " + "; ".join(
        ("at every angle" if r.every_angle else f"from {deg(r, r.theta[0])}° to {deg(r, r.theta[1])}°")
        + f" for s = {mm(r.s[0])} mm to {mm(r.s[1])} mm" for r in found.reach)


def pressure(rd, t, where, link, driver_kind, active, name):
    """A pressure on a piston as the force it makes: p A on the face it acts on, less a back pressure on the other.

    The cover end's area is A = π D²/4 (D the bore); the crank end's, A − π d²/4 (d the piston rod's diameter).
    ``direction`` is the way a pressure on the cover end pushes the piston; one on the crank end pushes it back.
    A pressure given by a table (an indicator diagram against the crank angle, or the slider's position) makes a
    tabulated force.
    """
    point = rd.text(rd.need(t, "point", where), f"{where}.point")
    D = rd.si(rd.need(t, "bore", where), "length", f"{where}.bore", "length")
    d = rd.si(t["rod"], "length", f"{where}.rod", "length0") if "rod" in t else 0.0
    if d >= D:
        raise rd.fail(f"{where}.rod", f"the piston rod ({t['rod']!r}) must be thinner than the bore ({t['bore']!r})")
    side = t.get("side", "cover")
    if side not in SIDES:
        raise rd.fail(f"{where}.side", f"must be \"cover\" (the cylinder's closed end, no rod: the default) or "
                      f"\"crank\" (the rod's side), got {side!r}")
    area = {"cover": math.pi * D * D / 4, "crank": math.pi * (D * D - d * d) / 4}
    other = "crank" if side == "cover" else "cover"
    push = 1.0 if side == "cover" else -1.0  # along direction: the cover side pushes forward, the crank side back
    back = rd.si(t["back_pressure"], "pressure", f"{where}.back_pressure") if "back_pressure" in t else 0.0
    a = rd.si(rd.need(t, "direction", where), "angle", f"{where}.direction")
    u = (math.cos(a), math.sin(a))
    given = [k for k in ("pressure", "table", "csv") if k in t]
    if len(given) != 1:
        raise rd.fail(f"{where}.pressure", "give the pressure once: a value (pressure = \"0.35 MPa\") or a table against "
                      "the input (table = \"\"\"…\"\"\" or csv = \"…\")" + (f", not {' and '.join(given)}" if given else ""))
    if "pressure" in t:
        p = rd.si(t["pressure"], "pressure", f"{where}.pressure")
        F = push * (p * area[side] - back * area[other])
        return PointForce(link, point, (F * u[0], F * u[1]), active, name)
    if stroke_table(t):
        return _stroke_pressure(rd, t, where, link, point, u, active, name, push, area[side], back * area[other],
                                driver_kind)
    if "from" in t:
        raise rd.fail(f"{where}.from", "names the dead centre a stroke table measures the piston's displacement from; "
                      "this table is against the " + ("crank angle" if driver_kind == "crank" else "slider's position"))
    table = load_table(rd, t, where, "pressure", driver_kind)
    value = push * (table.value * area[side] - back * area[other])
    return PointForce(link, point, u, active, name, Table(table.q, value, table.periodic, table.source))


def stroke_table(t) -> bool:
    """Whether a pressure's table (inline) is against the piston's displacement: its header starts with stroke."""
    text = t.get("table")
    if not isinstance(text, str):
        return False
    head = next((line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")), "")
    return head.lstrip().lower().startswith("stroke")


@dataclass(frozen=True)
class PendingStroke:
    """A pressure against the stroke, read before the mechanism is built: its dead centre is found afterwards
    (:func:`resolve_strokes`)."""

    where: str
    link: int
    point: str
    force: tuple[float, float]
    active: object
    name: str
    which: str
    stroke: np.ndarray
    out: np.ndarray
    back: np.ndarray | None


def _stroke_pressure(rd, t, where, link, point, u, active, name, push, area, back_force, driver_kind):
    """An indicator diagram against the piston's displacement from a dead centre (columns stroke, pressure and an
    optional return: the pressure while the piston comes back)."""
    field = f"{where}.table"
    if driver_kind != "crank":
        raise rd.fail(field, "a table against the stroke belongs to a crank-driven engine; with a slider driver give "
                      "it against the slider's position (position [mm], pressure [...])")
    which = t.get("from", "inner dead centre")
    if which not in DEAD_CENTRES:
        raise rd.fail(f"{where}.from", f"must be one of {', '.join(repr(k) for k in DEAD_CENTRES)}, got {which!r}")
    head = next(line for line in t["table"].splitlines() if line.strip() and not line.lstrip().startswith("#"))
    columns = {"stroke": "length", "pressure": "pressure"}
    if head.count(",") >= 2 or head.count(";") >= 2 or head.count("\t") >= 2:
        columns["return"] = "pressure"
    cols = parse_table(t["table"], columns, file=rd.file, field=field, decimal=rd.decimal(t, where))
    s = cols["stroke"]
    if (np.diff(s) < 0).any() or s[0] < 0:
        raise rd.fail(field, "the stroke column is the piston's displacement from the dead centre: from 0 up, "
                      "ascending")

    def force(p):
        return push * (p * area - back_force)

    return PendingStroke(where, link, point, u, active, name, which, s, force(cols["pressure"]),
                         force(cols["return"]) if "return" in cols else None)


def resolve_strokes(rd, mech, loads, moves):
    """The loads with each pressure against the stroke made a :class:`StrokeForce` on the mechanism's piston."""
    out = []
    for ld in loads:
        if not isinstance(ld, PendingStroke):
            out.append(ld)
            continue
        field = f"{ld.where}.from"
        guide = piston(rd, mech, field)[4]
        slider = guide.slider
        if ld.link != slider:
            raise rd.fail(f"{ld.where}.link", f"a pressure against the stroke acts on the piston, link {slider}, "
                          f"got {ld.link}")
        theta, X = dead_centre(rd, mech, ld.which, field)
        other = "outer dead centre" if DEAD_CENTRES[ld.which] > 0 else "inner dead centre"
        _, Y = dead_centre(rd, mech, other, field)
        length = abs(Y - X)
        away = (Y - X) / length
        # Where the load's own point is at the dead centre (any point of the piston: it only slides).
        kin = solve_kinematics(mech, [theta], 0.0, 0.0)
        Z = complex(*kin.position(ld.link, ld.point)[0])
        if ld.stroke[-1] < length * (1 - 1e-9):
            raise rd.fail(f"{ld.where}.table", f"covers the stroke to {ld.stroke[-1] * 1e3:.6g} mm; the stroke is "
                          f"{length * 1e3:.6g} mm: give rows to the end (the other dead centre)")
        if ld.back is not None and not moves:
            raise rd.fail(f"{ld.where}.table", "a return column needs the sense of the motion: give driver.omega "
                          "(a static analysis uses it only for that)")
        s = np.minimum(ld.stroke, length)
        try:
            load = StrokeForce(ld.link, ld.point, ld.force, ld.active, ld.name, dead_centre=(Z.real, Z.imag),
                               away=(away.real, away.imag), length=length,
                               out=Table(s, ld.out, periodic=False),
                               back=None if ld.back is None else Table(s, ld.back, periodic=False))
        except ModelError as exc:
            raise rd.fail(f"{ld.where}.table", str(exc).split(": ", 1)[-1]) from None
        out.append(load)
    return out


def power(rd, t, where, link, active, name, motion):
    """A power at a speed ("20 kW at 1200 rpm") as the torque it is: T = P/ω, against ω (resisting) or with it."""
    P = rd.si(rd.need(t, "power", where), "power", f"{where}.power")
    if P < 0:
        raise rd.fail(f"{where}.power", f"must be ≥ 0 W (say whether it drives or resists with role), got {t['power']!r}")
    role = t.get("role", "resisting")
    if role not in ROLES:
        raise rd.fail(f"{where}.role", f"must be \"resisting\" (the torque opposes the link's rotation: a load taken "
                      f"off, the default) or \"driving\", got {role!r}")
    if "speed" in t:
        omega = rd.si(t["speed"], "angular_velocity", f"{where}.speed")
    elif motion is not None and motion[0] == link and len(set(motion[1])) == 1:
        omega = float(motion[1][0])
    else:
        raise rd.fail(f"{where}.speed", "is missing: give the link's speed at which the power is transmitted, e.g. "
                      "speed = \"1200 rpm\" (negative for clockwise); it may be left out only on a crank driven at "
                      "one constant speed")
    if omega == 0:
        raise rd.fail(f"{where}.speed", "must not be zero: a power at rest is no torque (T = P/ω)")
    T = (P / omega) * (-1.0 if role == "resisting" else 1.0)
    return Torque(link, T, active, name or f"{P / 1e3:.6g} kW {role}")


def spring_loads(rd, t, where, frame):
    """A linear spring between two points (``type = "spring"``) as the forces on its moving ends."""
    links = t.get("links")
    if not isinstance(links, list) or len(links) != 2:
        raise rd.fail(f"{where}.links", f"must be the two links the spring's ends are fixed to, e.g. [1, 3], got "
                      f"{links!r}")
    links = [rd.whole(n, f"{where}.links[{i}]") for i, n in enumerate(links)]
    if links[0] == links[1]:
        raise rd.fail(f"{where}.links", f"a spring joins two links; both ends are on link {links[0]}")
    points = t.get("points")
    if not isinstance(points, list) or len(points) != 2 or not all(isinstance(p, str) for p in points):
        raise rd.fail(f"{where}.points", f"must name the point of each link the spring is fixed to, e.g. "
                      f"[\"Q\", \"B\"], got {points!r}")
    k = rd.si(rd.need(t, "rate", where), "stiffness", f"{where}.rate")
    L0 = rd.si(rd.need(t, "free_length", where), "length", f"{where}.free_length", "length0")
    return spring(links, points, k, L0, frame=frame, name=str(t.get("name", "")))


def unknown(rd, value, mech):
    """``[unknown]``: the link whose effort the book asks for, instead of the driver's (:mod:`.unknown`)."""
    t = rd.table(value, "unknown", {"link", "name"})
    link = rd.whole(rd.need(t, "link", "unknown"), "unknown.link")
    moving = [lk.number for lk in mech.links if lk.number != mech.frame]
    if link not in moving:
        raise rd.fail("unknown.link", f"names no moving link (the moving links are {', '.join(map(str, moving))}), "
                      f"got {link!r}")
    if link == mech.driver.link:
        raise rd.fail("unknown.link", f"link {link} is the driver, whose effort graphkin finds anyway: leave out "
                      "[unknown], or name the link whose torque (or slider force) the book asks for")
    lossy = [k for k, j in enumerate(mech.joints) if isinstance(j, GearMesh) and j.efficiency < 1]
    if lossy:
        raise rd.fail("unknown", f"is found from two solutions, as loads are linear; the efficiency of joints"
                      f"[{lossy[0]}] makes them not so (which gear loses depends on the way the power flows): drive "
                      f"link {link} instead (its effort is then the driver's) and give the other effort as a load")
    name = t.get("name", "")
    if not isinstance(name, str):
        raise rd.fail("unknown.name", f"must be a string such as \"T4\", got {name!r}")
    if any(ld.name == name for ld in mech.loads if name) or (not name and any(
            ld.name == Unknown(link).label(mech) for ld in mech.loads)):
        raise rd.fail("unknown.name", "a load already has this name: give the unknown another (name = \"T4\")")
    return Unknown(link, name)


ASKED = {"F_P": "the net force on the piston along the line of stroke",
         "F_T": "the tangential force on the crank pin", "F_B": "the thrust on the crank-shaft bearing",
         "T": "the turning moment the connecting rod exerts on the crank", "T_hold": "the torque that holds a gear "
         "meshing with the frame (an annulus held still)", "W_t": "the tangential (transmitted) component of a "
         "tooth force", "W_r": "the radial (separating) component of a tooth force", "alpha": "the flywheel's "
         "angular acceleration ([forward])"}
"""What a book may ask besides the joint forces and the driver's effort, by the name the handout prints."""


def asked(rd, value, mech, effort: str, forward: bool = False) -> tuple[str, ...]:
    """``asked``: the answers the book asks for, by the names a handout prints them under (``["T12", "F23",
    "G14"]``): joint forces, the driver's effort ``effort`` (or ``[unknown]``'s) and the names of :data:`ASKED`
    (``"alpha"`` only with a ``[forward]`` step, ``forward``)."""
    if not isinstance(value, list) or not all(isinstance(x, str) for x in value):
        raise rd.fail("asked", f"must be a list of names such as [\"T12\", \"F23\"], got {value!r}")
    forces = {force_name(mech, i, j) for joint in mech.joints for a, b in [sorted(joint.links)] for i, j in
              ((a, b), (b, a))}
    known = forces | {effort} | set(ASKED)
    for k, name in enumerate(value):
        if name not in known:
            raise rd.fail(f"asked[{k}]", f"{name!r} is not a quantity a handout prints; one of "
                          f"{', '.join(sorted(known))}")
        if name == "alpha" and not forward:
            raise rd.fail(f"asked[{k}]", "the flywheel's angular acceleration needs [forward] (its mass and "
                          "radius of gyration, and the power taken off)")
    return tuple(value)
