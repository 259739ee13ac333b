"""Problem files: a mechanism, its input motion and loads, written in TOML with units.

This is the boundary where textbook units (mm, rpm, degrees, N·mm) become SI;
the field-by-field format is documented in ``docs/problem-files.md``. Every
error names the file, the field and what is wrong.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import replace
from pathlib import Path
from typing import Any, Mapping

import numpy as np

from graphkin.errors import GraphkinError, GraphkinWarning, ModelError, ProblemFileError
from graphkin.files import read_text
from graphkin.kinematics.plan import plan_of
from graphkin.kinematics.structure import Dyad
from graphkin.model import SENSES, Active, Driver, GearMesh, Link, PointForce, Prismatic, Revolute, Torque
from graphkin.model import mass as massprops
from graphkin.problem import books
from graphkin.problem.problem import Problem
from graphkin.problem.reader import FieldReader
from graphkin.problem.shared import mechanism_once, read_once
from graphkin.problem.stated import check_stated
from graphkin.problem.study_table import read_study
from graphkin.problem.tables import load_table

_TOP = {"title", "source", "cite", "notes", "analysis", "gravity", "frame", "links", "joints", "driver", "loads", "assembly",
        "given", "forward", "unknown", "asked", "study"}
_ANALYSES = ("dynamic", "static")
_LINK = {"number", "name", "points", "mass", "G", "I_G", "k", "shape"}
_JOINT = {
    "revolute": {"type", "links", "point"},
    "prismatic": {"type", "guide", "slider", "point", "through", "direction", "slider_direction", "mu"},
    "gear": {"type", "links", "centers", "radii", "pressure_angle", "internal", "efficiency"},
}
_DRIVER = {
    "crank": {"type", "link", "theta", "travel", "moving", "omega", "alpha", "from", "sense"},
    "slider": {"type", "link", "s", "v", "a", "place"},
}
_LOAD = {"force": {"type", "link", "point", "force", "direction", "table", "csv", "decimal", "sense", "active", "name"},
         "torque": {"type", "link", "torque", "table", "csv", "decimal", "sense", "active", "name"},
         "pressure": {"type", "link", "point", "bore", "rod", "pressure", "back_pressure", "side", "direction", "table",
                      "csv", "decimal", "active", "name", "from"},
         "power": {"type", "link", "power", "speed", "role", "active", "name"},
         "spring": {"type", "links", "points", "rate", "free_length", "name"}}
_GIVEN = {"omega", "alpha", "a_G", "v_G", "theta", "points"}
_SHAPES = {
    "rod": {"type", "from", "to"},
    "outline": {"type", "through", "width", "thickness", "density", "hole_diameter"},
    "disk": {"type", "center", "radius", "thickness", "density"},
}


def _field_of(at: tuple) -> str:
    """The field path in a problem file of a place in the mechanism (:attr:`graphkin.errors.ModelError.at`).

    The file's ``[frame]`` is the mechanism's first link, so ``links[k]`` of
    the mechanism is ``links[k-1]`` of the file.
    """
    if not at:
        return ""
    head, rest = at[0], [str(x) for x in at[1:]]
    if head == "links" and rest:
        k = int(rest[0])
        return ".".join(["frame" if k == 0 else f"links[{k - 1}]"] + rest[1:])
    if head in ("joints", "loads") and rest:
        return ".".join([f"{head}[{rest[0]}]"] + rest[1:])
    return ".".join([head] + rest)


def load_problem(source: str | Path, *, name: str | None = None) -> Problem:
    """Read a problem file (a path, or a catalog name via :func:`graphkin.catalog.load`).

    Parameters
    ----------
    source : str or Path
        The file.
    name : str, optional
        The name messages and reports show (default: the path).

    Returns
    -------
    Problem
        The mechanism, its input motion and loads, in SI units.

    Raises
    ------
    ProblemFileError
        With the file, the field and what is wrong.
    """
    if not isinstance(source, (str, Path)) or not str(source):
        raise GraphkinError(f"load_problem takes the path of a problem file (a str or Path), got "
                            f"{type(source).__name__} {source!r}"
                            + ("; for the file's text use parse_problem(text)" if isinstance(source, bytes) else ""))
    if name is not None and not isinstance(name, str):
        raise GraphkinError(f"load_problem: name must be a str, got {type(name).__name__} {name!r}")
    path = Path(source)
    file = name or str(path)
    return parse_problem(read_text(path, "problem", shown=file), file=file, base=path)


def parse_problem(text: str, *, file: str = "<problem>", base: str | Path | None = None) -> Problem:
    """Build a :class:`Problem` from TOML text.

    Parameters
    ----------
    text : str
        The file's text (not bytes: decode them first, or use :func:`load_problem` on the path).
    file : str, optional
        The name shown in messages.
    base : str or Path, optional
        The problem file's path: a load's ``csv`` table is read from its folder.

    Returns
    -------
    Problem
        The mechanism, its input motion and loads, in SI units.

    Raises
    ------
    ProblemFileError
        With the file, the field and what is wrong.
    GraphkinError
        If ``text`` is not a str.
    """
    if not isinstance(file, str):
        raise GraphkinError(f"parse_problem: file must be a str (the name shown in messages), got {file!r}")
    if isinstance(text, (bytes, bytearray)):
        raise GraphkinError(f"parse_problem takes the file's text as a str, got {type(text).__name__}: decode it first "
                            "(text = data.decode('utf-8')) or give the path to load_problem")
    if not isinstance(text, str):
        raise GraphkinError(f"parse_problem takes the file's text as a str, got {type(text).__name__} {text!r:.60}")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ProblemFileError(file, "", f"is not valid TOML ({exc})") from None
    return build_problem(data, file=file, base=base)


def build_problem(data: Mapping[str, Any], *, file: str = "<problem>", base: str | Path | None = None) -> Problem:
    """Build a :class:`Problem` from a problem file's TOML already read into a dict.

    Exercises use it to solve a variant: the base file's data with some
    values replaced by the strings the student is shown.

    Parameters
    ----------
    data : mapping
        The file's tables and values, as ``tomllib`` reads them (units in strings).
    file : str, optional
        The name shown in messages.
    base : str or Path, optional
        The problem file's path: a load's ``csv`` table is read from its folder.

    Returns
    -------
    Problem
        The mechanism, its input motion and loads, in SI units.

    Raises
    ------
    ProblemFileError
        With the file, the field and what is wrong.
    """
    rd = FieldReader(file)
    rd.base = base
    if not isinstance(data, Mapping):
        raise GraphkinError(f"build_problem takes a problem file's tables as a dict, got {type(data).__name__}")
    rd.table(dict(data), "", _TOP)
    analysis = data.get("analysis", "dynamic")
    if analysis not in _ANALYSES:
        raise rd.fail("analysis", f"must be \"dynamic\" (inertia loads included, the default) or \"static\" (no inertia "
                      f"loads), got {analysis!r}")
    static = analysis == "static"
    frame = read_once(_frame, rd, data.get("frame", {}), "frame")
    links = [frame] + [read_once(_link, rd, t, f"links[{i}]", frame.number, static)
                       for i, t in enumerate(_list(rd, data, "links"))]
    joints = [_joint_once(rd, t, f"joints[{i}]") for i, t in enumerate(_list(rd, data, "joints"))]
    d = rd.table(rd.need(data, "driver", ""), "driver", _DRIVER["crank"] | _DRIVER["slider"])
    kind = d.get("type", "crank")
    if kind not in _DRIVER:
        raise rd.fail("driver.type", f"must be 'crank' or 'slider', got {kind!r}")
    if kind == "slider" and "travel" in d:
        raise rd.fail("driver.travel", "places a crank by its piston's travel from a dead centre; a slider driver's "
                      "position is s itself (along the guide from its through point)")
    rd.table(d, "driver", _DRIVER[kind])
    driver = Driver(rd.whole(rd.need(d, "link", "driver"), "driver.link"), kind)
    q, q_dot, q_ddot = _motion(rd, d, kind, static)
    motion = (driver.link, q_dot) if kind == "crank" else None
    loads, origin = [], []  # a spring puts a load on each moving end: origin[k] is the file's index of loads[k]
    for i, t in enumerate(_list(rd, data, "loads")):
        found = _load_once(rd, t, f"loads[{i}]", kind, motion, frame.number)
        found = found if isinstance(found, list) else [found]
        loads += found
        origin += [i] * len(found)
    gravity = rd.si(data["gravity"], "acceleration", "gravity", None) if "gravity" in data else 0.0
    if gravity < 0:
        raise rd.fail("gravity", f"must be ≥ 0 (g acts along −y; write its size), got {data['gravity']!r}")
    rd.ranged(gravity, data.get("gravity"), "acceleration", "gravity")
    assembly = {}
    for key, sigma in rd.table(data.get("assembly", {}), "assembly", set(data.get("assembly", {}))).items():
        if sigma not in (1, -1) or isinstance(sigma, bool):
            raise rd.fail(f"assembly.{key}", f"must be 1 or -1, got {sigma!r}")
        assembly[key] = sigma
    # A pressure against the stroke needs the mechanism's dead centres: it joins the loads once they are known.
    plain = [k for k, ld in enumerate(loads) if not isinstance(ld, books.PendingStroke)]
    try:
        mech = mechanism_once(links, joints, driver, [loads[k] for k in plain], gravity, assembly,
                               str(data.get("title", "")), str(data.get("source", "")), frame.number)
        if len(plain) < len(loads):
            plain = list(range(len(loads)))
            mech = replace(mech, loads=tuple(books.resolve_strokes(rd, mech, loads, bool(np.any(q_dot)))))
            loads = list(mech.loads)
    except ModelError as exc:
        at = exc.at
        if at and at[0] == "loads" and len(at) > 1:
            at = ("loads", origin[plain[at[1]]], *at[2:])
        raise rd.fail(_field_of(at), str(exc)) from None
    for key in assembly:
        points = {j.point for j in joints if not isinstance(j, GearMesh)}
        if key not in points:
            raise rd.fail(f"assembly.{key}", f"names no joint point (joints are at {', '.join(sorted(points))})")
    speed = "omega" if kind == "crank" else "v"
    if not static and speed not in d:
        # Checked once the mechanism is known to be sound, so that a wrong driver type is named first.
        raise rd.fail(f"driver.{speed}", f"is missing: a dynamic analysis needs the input speed, e.g. {speed} = "
                      + ('"900 rpm"' if kind == "crank" else '"2 m/s"')
                      + ' (for a linkage at rest or at negligible speed write analysis = "static")')
    for k, joint in enumerate(joints):
        if isinstance(joint, GearMesh) and joint.efficiency < 1 and not np.all(q_dot):
            raise rd.fail(f"joints[{k}].efficiency", "a mesh efficiency takes power off the driven gear, and which gear "
                          f"drives depends on the motion: give driver.{speed} at every position (a static analysis "
                          "uses it only for that)")
    for k, load in enumerate(loads):
        if load.sense != "fixed" and not np.any(q_dot):
            raise rd.fail(f"loads[{origin[k]}].sense", f"{load.sense!r} follows the motion, but the input does not move: give "
                          f"driver.{speed} (a static analysis uses it only to set such senses)")
    given = _given(rd, data.get("given", {}), mech, len(q), static)
    try:
        # The plan the kinematics will use: decomposed once, here, for the mechanism's solvers too.
        groups = plan_of(mech).groups
    except ModelError as exc:
        raise rd.fail(_field_of(exc.at) or "joints", str(exc)) from None
    if "travel" in d:
        q = books.crank_from_travel(rd, d, mech, q_dot)
    elif "from" in d:
        q = books.crank_from_dead_centre(rd, d, mech, q)
    if "place" in d:
        q = books.placed(rd, d, mech)
    branches = sorted({g.key for g in groups if isinstance(g, Dyad)})
    for key in assembly:
        if key not in branches:
            raise rd.fail(f"assembly.{key}", f"{key} is not the middle joint of a dyad, so it chooses no branch; "
                          + (f"this mechanism's branches are chosen at {', '.join(branches)}" if branches else
                             "this mechanism has no dyad, so no branch to choose: leave out [assembly]"))
    # Once the mechanism, its positions and rates are known: what the file states twice must agree with itself.
    check_stated(rd, data, mech, q, q_dot, q_ddot, loads, origin)
    forward = books.forward(rd, data["forward"], kind, q_dot) if "forward" in data else None
    unknown = books.unknown(rd, data["unknown"], mech) if "unknown" in data else None
    if unknown is not None and forward is not None:
        raise rd.fail("unknown", "a forward step needs the driver's effort; with [unknown] the driver carries none")
    effort = unknown.label(mech) if unknown is not None else mech.driver.symbol
    asked = books.asked(rd, data["asked"], mech, effort, forward is not None) if "asked" in data else ()
    if "study" in data:  # read by a study (graphkin.cycle.study); checked here, so a bad entry is named at once
        read_study(rd, data["study"], data)
    return Problem(file, mech, q, q_dot, q_ddot, given, str(data.get("title", "")), str(data.get("source", "")),
                   str(data.get("notes", "")), analysis, str(data.get("cite", "")), forward, unknown, asked)


def _list(rd, data, key):
    value = data.get(key, [])
    if not isinstance(value, list):
        raise rd.fail(key, f"must be an array of tables ([[{key}]]), got {type(value).__name__}")
    return value


def _frame(rd, value, where):
    t = rd.table(value, where, {"points", "number"})
    number = rd.whole(t.get("number", 1), "frame.number")
    if number not in (0, 1):
        raise rd.fail("frame.number", f"the frame is numbered 1 (as in Norton and Söylemez) or 0 (books that write F01, "
                      f"T01), got {number!r}")
    return Link(number, _points(rd, t.get("points", {}), "frame.points"), name="frame")


def _points(rd, value, where):
    if not isinstance(value, dict):
        raise rd.fail(where, "must be a table of named points, e.g. { A = [\"0 mm\", \"0 mm\"] }")
    return {name: rd.point(p, f"{where}.{name}") for name, p in value.items()}


def _link(rd, t, where, frame=1, static=False):
    rd.table(t, where, _LINK)
    number = rd.whole(rd.need(t, "number", where), f"{where}.number")
    if number == frame:
        raise rd.fail(f"{where}.number", f"link {frame} is the frame: describe it in [frame]")
    if number < frame:
        raise rd.fail(f"{where}.number", f"with the frame numbered {frame}, the moving links are numbered from {frame + 1}"
                      f" up, got {number!r}" + (" (number the frame 0 with [frame] number = 0)" if number == 0 else ""))
    points = _points(rd, rd.need(t, "points", where), f"{where}.points")
    name = str(t.get("name", ""))
    if "shape" in t:
        for key in ("mass", "G", "I_G", "k"):
            if key in t and key != "mass":
                raise rd.fail(f"{where}.{key}", "give either a shape or the mass properties, not both")
        props = _shape(rd, t, points, f"{where}.shape", static)
    else:
        # A static analysis has no inertia loads: a mass matters only for a weight, so it may be left out (0 kg).
        m = rd.si(t.get("mass", "0 kg") if static else rd.need(t, "mass", where), "mass", f"{where}.mass", None)
        if m < 0:
            raise rd.fail(f"{where}.mass", f"must be ≥ 0 kg, got {t['mass']!r}")
        rd.ranged(m, t.get("mass"), "mass", f"{where}.mass")
        G = rd.point(t["G"], f"{where}.G") if "G" in t else (0.0, 0.0)
        if "I_G" in t and "k" in t:
            raise rd.fail(f"{where}.k", "give I_G or the radius of gyration k, not both")
        if "k" in t:
            k = rd.si(t["k"], "length", f"{where}.k", None)
            if k < 0:
                raise rd.fail(f"{where}.k", f"must be ≥ 0, got {t['k']!r}")
            rd.ranged(k, t["k"], "length0", f"{where}.k")
            I_G = m * k * k
        else:
            I_G = rd.si(t.get("I_G", "0 kg*m^2"), "moment_of_inertia", f"{where}.I_G", None)
            if I_G < 0:
                raise rd.fail(f"{where}.I_G", f"must be ≥ 0, got {t['I_G']!r}")
            rd.ranged(I_G, t.get("I_G"), "moment_of_inertia", f"{where}.I_G")
        props = massprops.MassProperties(m, G, I_G)
    try:
        return Link(number, points, props.m, props.G, props.I_G, name)
    except GraphkinError as exc:
        # Only a shape's mass properties can fail here: everything else was checked as it was read.
        raise rd.fail(f"{where}.shape" if "shape" in t else where, str(exc)) from None


def _shape(rd, t, points, where, static=False):
    s = t["shape"]
    kind = rd.table(s, where, set(s) if isinstance(s, dict) else set()).get("type")
    if kind is None:
        raise rd.fail(f"{where}.type", f"is missing: write type = one of {', '.join(sorted(_SHAPES))}")
    if kind not in _SHAPES:
        raise rd.fail(f"{where}.type", f"must be one of {', '.join(sorted(_SHAPES))}, got {kind!r}")
    rd.table(s, where, _SHAPES[kind])

    def pt(name, key):
        if name not in points:
            raise rd.fail(f"{where}.{key}", f"names no point of this link ({', '.join(points)})")
        return points[name]

    try:
        if kind == "rod":
            m = rd.si(t.get("mass", "0 kg") if static else rd.need(t, "mass", where[:-6]), "mass", f"{where[:-6]}.mass",
                      None)
            if m < 0:
                raise rd.fail(f"{where[:-6]}.mass", f"must be ≥ 0 kg, got {t['mass']!r}")
            rd.ranged(m, t.get("mass"), "mass", f"{where[:-6]}.mass")
            (x0, y0), (x1, y1) = pt(rd.need(s, "from", where), "from"), pt(rd.need(s, "to", where), "to")
            return massprops.thin_rod(math.hypot(x1 - x0, y1 - y0), m, start=(x0, y0), angle=math.atan2(y1 - y0, x1 - x0))
        if "mass" in t:
            raise rd.fail(f"{where[:-6]}.mass", f"a {kind} shape gets its mass from density and size: leave mass out")
        thickness = rd.si(rd.need(s, "thickness", where), "length", f"{where}.thickness", "length")
        density = rd.si(rd.need(s, "density", where), "density", f"{where}.density")
        if kind == "disk":
            radius = rd.si(rd.need(s, "radius", where), "length", f"{where}.radius", "length")
            return massprops.disk(radius, thickness, density, center=pt(rd.need(s, "center", where), "center"))
        through = rd.need(s, "through", where)
        centers = [pt(p, "through") for p in through]
        width = rd.si(rd.need(s, "width", where), "length", f"{where}.width", "length")
        hole = rd.si(s.get("hole_diameter", "0 mm"), "length", f"{where}.hole_diameter", "length0")
        return massprops.from_shape(massprops.link_outline(centers, width, hole), thickness, density)
    except GraphkinError as exc:
        if isinstance(exc, ProblemFileError):
            raise
        raise rd.fail(where, str(exc)) from None


def _joint_once(rd, t, where):
    """A joint read from its table, or the one read before from an equal table
    (:func:`~graphkin.problem.shared.read_once`); an unusually high friction coefficient is warned of every time."""
    joint = read_once(_joint, rd, t, where)
    if isinstance(joint, Prismatic) and joint.mu > 1:
        import warnings

        # Rubber on dry concrete reaches about 1; above it is more often a typing slip than a material.
        warnings.warn(f"{rd.file}: {where}.mu: a friction coefficient of {joint.mu:g} is unusually high "
                      "(dry metals on metals: 0.15 to 0.6); solving with it", GraphkinWarning, stacklevel=2)
    return joint


def _joint(rd, t, where):
    kind = rd.table(t, where, set().union(*_JOINT.values())).get("type")
    if kind is None:
        raise rd.fail(f"{where}.type", "is missing: write type = \"revolute\", \"prismatic\" or \"gear\"")
    if kind not in _JOINT:
        raise rd.fail(f"{where}.type", f"must be one of revolute, prismatic, gear; got {kind!r}")
    rd.table(t, where, _JOINT[kind])
    try:
        if kind == "revolute":
            return Revolute(_pair(rd, rd.need(t, "links", where), f"{where}.links"),
                            rd.text(rd.need(t, "point", where), f"{where}.point"))
        if kind == "prismatic":
            mu = rd.si(t.get("mu", 0.0), "dimensionless", f"{where}.mu")
            if mu < 0:
                raise rd.fail(f"{where}.mu", f"friction coefficient must be ≥ 0, got {t['mu']!r}")
            rd.ranged(mu, t.get("mu"), "friction", f"{where}.mu")
            return Prismatic(
                rd.whole(rd.need(t, "guide", where), f"{where}.guide"), rd.whole(rd.need(t, "slider", where), f"{where}.slider"),
                rd.text(rd.need(t, "point", where), f"{where}.point"), rd.text(rd.need(t, "through", where), f"{where}.through"),
                rd.si(t.get("direction", "0 deg"), "angle", f"{where}.direction"),
                rd.si(t.get("slider_direction", "0 deg"), "angle", f"{where}.slider_direction"), mu)
        radii = rd.need(t, "radii", where)
        if not isinstance(radii, list) or len(radii) != 2:
            raise rd.fail(f"{where}.radii", "must be two pitch radii, e.g. [\"100 mm\", \"50 mm\"]")
        centers = rd.need(t, "centers", where)
        if not isinstance(centers, list) or len(centers) != 2:
            raise rd.fail(f"{where}.centers", "must name the two gear centres, e.g. [\"O2\", \"O3\"]")
        internal = t.get("internal", False)
        if not isinstance(internal, bool):
            raise rd.fail(f"{where}.internal", f"must be true (an annulus with teeth inside, and a pinion) or false, got "
                          f"{internal!r}")
        return GearMesh(_pair(rd, rd.need(t, "links", where), f"{where}.links"), tuple(centers),
                        tuple(rd.si(r, "length", f"{where}.radii[{i}]", "length") for i, r in enumerate(radii)),
                        rd.si(t.get("pressure_angle", "20 deg"), "angle", f"{where}.pressure_angle"), internal,
                        rd.si(t.get("efficiency", 1.0), "dimensionless", f"{where}.efficiency", None))
    except ProblemFileError:
        raise
    except ModelError as exc:
        # The joint's constructor says which of its fields is at fault (``at``, relative to the joint).
        raise rd.fail(".".join([where, *map(str, exc.at)]), str(exc)) from None


def _pair(rd, value, where):
    if not isinstance(value, list) or len(value) != 2:
        raise rd.fail(where, f"must be two link numbers, e.g. [2, 3], got {value!r}")
    return tuple(rd.whole(v, f"{where}[{i}]") for i, v in enumerate(value))


def _motion(rd, d, kind, static=False):
    names = ("theta", "omega", "alpha") if kind == "crank" else ("s", "v", "a")
    dims = ("angle", "angular_velocity", "angular_acceleration") if kind == "crank" else ("length", "velocity", "acceleration")
    if "place" in d:
        if "s" in d:
            raise rd.fail("driver.place", "places the slider by another link's angle: give it or s, not both")
        q = np.zeros(1)  # found once the mechanism is known (books.placed)
    elif "travel" in d:
        if "theta" in d:
            raise rd.fail("driver.travel", "places the crank by its piston's travel: give it or theta, not both")
        q = np.zeros(len(books.read_travel(rd, d["travel"])[0]))  # the angles need the mechanism (books.crank_from_travel)
    else:
        if "moving" in d:
            raise rd.fail("driver.moving", "chooses the stroke on which the piston has travelled driver.travel: "
                          "give it with travel, not with theta")
        q = rd.array(rd.need(d, names[0], "driver"), dims[0], f"driver.{names[0]}")
    accel = names[2]
    if static and accel in d:
        raise rd.fail(f"driver.{accel}", f"a static analysis has no inertia loads, so {accel} is not used: leave it out "
                      f"(or write analysis = \"dynamic\")")
    rates = []
    for name, dim in zip(names[1:], dims[1:]):
        none = f"0 {'rad/s' if kind == 'crank' else 'm/s'}{'^2' if name in ('alpha', 'a') else ''}"  # at rest
        r = rd.array(d.get(name, none), dim, f"driver.{name}")
        if len(r) not in (1, len(q)):
            raise rd.fail(f"driver.{name}", f"has {len(r)} values for {len(q)} positions: give one value or one per position")
        rates.append(np.broadcast_to(r, q.shape).astype(float))
    if "sense" in d:
        # A book gives the speed's size and the sense of rotation: a clockwise engine turns at ω < 0.
        sense = d["sense"]
        if sense not in books.SENSES_OF_ROTATION:
            raise rd.fail("driver.sense", f"must be \"counter-clockwise\" (the default) or \"clockwise\", got {sense!r}")
        if kind != "crank":
            raise rd.fail("driver.sense", "is a crank's sense of rotation; a slider's v and a carry their own signs")
        if (rates[0] < 0).any():
            raise rd.fail("driver.omega", f"with driver.sense = {sense!r}, omega is the speed in that sense: give it "
                          "≥ 0")
        # alpha too is measured in the sense of rotation (negative: slowing down).
        rates = [books.SENSES_OF_ROTATION[sense] * r + 0.0 for r in rates]
    return q, rates[0], rates[1]


def _load_once(rd, t, where, driver_kind, motion, frame):
    """A force, torque or pressure read from its table, or the one read before from an equal table (see
    :func:`~graphkin.problem.shared.read_once`: a draw of an exercise changes one load and reads the others again,
    and shares the mechanism of the draws before whose loads are the same objects). A load that reads a CSV file
    beside the problem, a pressure against the stroke (resolved once the mechanism's dead centres are known), a
    spring or a power is read every time."""
    if isinstance(t, dict) and "csv" not in t and (t.get("type") in ("force", "torque") or
                                                   t.get("type") == "pressure" and not books.stroke_table(t)):
        return read_once(_load, rd, t, where, driver_kind, None, frame)  # none of them uses the motion
    return _load(rd, t, where, driver_kind, motion, frame)


def _load(rd, t, where, driver_kind, motion=None, frame=1):
    kind = rd.table(t, where, set().union(*_LOAD.values())).get("type")
    kinds = ", ".join(repr(k) for k in _LOAD)
    if kind is None:
        raise rd.fail(f"{where}.type", f"is missing: write type = one of {kinds}")
    if kind not in _LOAD:
        raise rd.fail(f"{where}.type", f"must be one of {kinds}, got {kind!r}")
    rd.table(t, where, _LOAD[kind])
    if kind == "spring":
        return books.spring_loads(rd, t, where, frame)
    link = rd.whole(rd.need(t, "link", where), f"{where}.link")
    active = None
    if "active" in t:
        a = rd.table(t["active"], f"{where}.active", {"from", "to"})
        dim = "angle" if driver_kind == "crank" else "length"
        active = Active(rd.si(rd.need(a, "from", f"{where}.active"), dim, f"{where}.active.from"),
                        rd.si(rd.need(a, "to", f"{where}.active"), dim, f"{where}.active.to"), periodic=driver_kind == "crank")
        if not active.mask(np.array([active.start + 0.5 * active.width])).all():
            raise rd.fail(f"{where}.active", f"from {a['from']!r} to {a['to']!r} is a window of zero width, so the load "
                          "would never act" + (" (angles are taken modulo 360°)" if active.periodic else
                                               "; 'to' must lie above 'from'") +
                          "; leave out 'active' for a load that always acts")
    name = str(t.get("name", ""))
    if kind == "pressure":
        return books.pressure(rd, t, where, link, driver_kind, active, name)
    if kind == "power":
        return books.power(rd, t, where, link, active, name, motion)
    sense = t.get("sense", "fixed")
    if sense not in SENSES:
        raise rd.fail(f"{where}.sense", f"must be one of {', '.join(repr(x) for x in SENSES)}, got {sense!r}")
    table = load_table(rd, t, where, kind, driver_kind)
    if kind == "force":
        point = rd.text(rd.need(t, "point", where), f"{where}.point")
        if table is None:
            if "direction" in t:
                raise rd.fail(f"{where}.direction", "is for a force given by a table; a constant force is "
                              'force = ["Fx", "Fy"] (or {magnitude = "…", angle = "…"})')
            force = rd.vec(rd.need(t, "force", where), "force", f"{where}.force")
        else:
            if "force" in t:
                raise rd.fail(f"{where}.force", "a force given by a table takes its size from the table: give its line "
                              'and positive sense with direction = "180 deg" instead')
            a = rd.si(rd.need(t, "direction", where), "angle", f"{where}.direction")
            force = (math.cos(a), math.sin(a))
        return PointForce(link, point, force, active, name, table, sense)
    if table is None:
        return Torque(link, rd.si(rd.need(t, "torque", where), "torque", f"{where}.torque"), active, name, None, sense)
    if "torque" in t:
        raise rd.fail(f"{where}.torque", "a torque given by a table takes its values from the table: leave torque out")
    return Torque(link, 1.0, active, name, table, sense)


def _given(rd, value, mech, n, static=False):
    out = {}
    if not isinstance(value, dict):
        raise rd.fail("given", "must be a table of links, e.g. [given.3]")
    if value and n != 1:
        raise rd.fail("given", f"given kinematics need a single input position, the file has {n}")
    dims = {"omega": "angular_velocity", "alpha": "angular_acceleration", "a_G": "acceleration", "v_G": "velocity",
            "theta": "angle"}
    for key, t in value.items():
        where = f"given.{key}"
        try:
            link = int(key)
        except ValueError:
            raise rd.fail(where, "must be a link number") from None
        if link not in mech.moving:
            raise rd.fail(where, f"names no moving link (moving links are {', '.join(map(str, mech.moving))})")
        rd.table(t, where, _GIVEN)
        for name, v in t.items():
            if static and name in ("alpha", "a_G"):
                raise rd.fail(f"{where}.{name}", "a static analysis has no inertia loads, so it is not used: leave it out "
                              "(or write analysis = \"dynamic\")")
            if name == "theta" and link == mech.driver.link and mech.driver.crank:
                raise rd.fail(f"{where}.theta", f"link {link} is the crank: its angle is the input, driver.theta")
            if name == "points":
                if not isinstance(v, dict) or not v:
                    raise rd.fail(f"{where}.points", 'must be a table of named points in global coordinates, e.g. '
                                  '{ B = ["-200 mm", "458 mm"] }')
                own = mech.link(link).points
                for point, xy in v.items():
                    if point not in own:
                        raise rd.fail(f"{where}.points.{point}", f"names no point of link {link} "
                                      f"({', '.join(own) or 'it has none'})")
                    out[(link, "at", point)] = rd.vec(xy, "length", f"{where}.points.{point}")
                continue
            read = rd.vec if name in ("a_G", "v_G") else rd.si
            out[(link, name)] = read(v, dims[name], f"{where}.{name}")
    return out
