"""Values a problem file states that graphkin also computes, checked against what it computes.

A book states some things twice: a power "at 1200 rpm" on a gear whose speed the train already fixes, a gas
pressure along a cylinder whose line the guide already fixes, the crank's ω again among the given values. Where
the two disagree by more than the rounding of the number as written, the file contradicts itself (a sign slip
turns a driving power into a resisting one), and it is refused, naming the field and both values, rather than
solved with one of them. ``docs/problem-files.md`` lists the checks ("Inputs checked against what graphkin
computes").

They are made at the file's own positions, where the book states its values; ``solve --at`` and a cycle apply
the loads made there (a power's torque P/ω, a pressure's force along its direction).
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from graphkin.kinematics import solve_kinematics
from graphkin.model import Prismatic
from graphkin.notation import position_text
from graphkin.problem.reader import shown
from graphkin.units import Written, written

REL = 1e-3
"""How far a stated value may lie from graphkin's, relative, besides the rounding of its written digits: books
round their intermediate values to about 0.1 %. For a direction, the same number in radians (0.06°)."""

SLIP = 0.25
"""A given ω, α, v_G or a_G of a link whose motion graphkin derives is a reading off a drawing, a few per cent from
the exact value (the catalog's Makdin examples: within 3 %); one within this fraction of the exact value's
negative is the exact value with its sign lost."""

_SYMBOL = {"omega": "ω", "alpha": "α", "v_G": "v_G", "a_G": "a_G"}
_DIMENSION = {"omega": "angular_velocity", "alpha": "angular_acceleration", "v_G": "velocity", "a_G": "acceleration",
              "theta": "angle", "v": "velocity", "a": "acceleration"}


class _Motion:
    """The file's mechanism and input motion, with its kinematics solved once, when a check first needs them."""

    def __init__(self, mech, q, q_dot, q_ddot):
        self.mech, self.q, self.q_dot, self.q_ddot = mech, q, q_dot, q_ddot

    @cached_property
    def kin(self):
        return solve_kinematics(self.mech, self.q, self.q_dot, self.q_ddot)

    def at(self, i: int) -> str:
        return position_text(self.q[i], self.mech.driver.crank)


def check_stated(rd, data, mech, q, q_dot, q_ddot, loads, origin) -> None:
    """Refuse a file whose stated values contradict what graphkin computes from its mechanism and input motion.

    Parameters
    ----------
    rd : graphkin.problem.reader.FieldReader
        The file's reader (its messages name the file).
    data : mapping
        The file's tables, as read from TOML.
    mech : Mechanism
    q, q_dot, q_ddot : ndarray, shape (n,)
        The input motion [SI].
    loads, origin : list
        The mechanism's loads, and for each the index of the file's ``[[loads]]`` table it comes from.

    Raises
    ------
    ProblemFileError
        Naming the field, the value as written and graphkin's value in the same unit.
    """
    motion = _Motion(mech, q, q_dot, q_ddot)
    load_of = {i: loads[k] for k, i in enumerate(origin)}
    for i, t in enumerate(data.get("loads", [])):
        if t.get("type") == "power" and "speed" in t:
            _power_speed(rd, t["speed"], f"loads[{i}].speed", load_of[i], motion)
        elif t.get("type") == "pressure":
            _pressure_line(rd, data.get("joints", []), t["direction"], f"loads[{i}]", load_of[i], motion)
    for key, t in data.get("given", {}).items():
        for name, raw in t.items():
            if name != "points":
                _given(rd, data["driver"], raw, f"given.{key}.{name}", int(key), name, motion)


def _close(stated, computed, rounding):
    """Whether a stated value is graphkin's to within the rounding of its digits [SI] or :data:`REL`."""
    return np.abs(stated - computed) <= np.maximum(REL * np.maximum(np.abs(stated), np.abs(computed)), rounding)


def _sense(x: float) -> str:
    return "CCW" if x > 0 else "CW"


@dataclass(frozen=True)
class _Value:
    """A value as the file states it: in SI (a vector as x + iy), its rounding as written [SI], and its unit."""

    si: float | complex
    rounding: float
    raw: object
    unit: Written

    @property
    def shown(self) -> str:
        return self.text(self.si) if isinstance(self.si, complex) else shown(self.raw)

    def text(self, x) -> str:
        """``x`` [SI] in this value's unit, as a vector in its form (polar or components)."""
        u = self.unit
        if not isinstance(self.si, complex):
            return f"{x / u.size:.6g} {u.unit}"
        if isinstance(self.raw, dict):
            return f"{abs(x) / u.size:.6g} {u.unit} ∠ {math.degrees(cmath.phase(x)):.6g}°"
        return f"({x.real / u.size:.6g}, {x.imag / u.size:.6g}) {u.unit}"


def _value(rd, raw, dimension, field, vector=False) -> _Value:
    """A stated value read again with its rounding. A zero rate is exact: a book's "at rest", "at constant speed"."""

    def rounding(text, dim, where):
        if dim != "angle" and rd.si(text, dim, where, None) == 0:
            return 0.0
        return written(text, dim, field=where, file=rd.file).rounding

    if not vector:
        return _Value(rd.si(raw, dimension, field, None), rounding(raw, dimension, field), raw,
                      written(raw, dimension, field=field, file=rd.file))
    z = complex(*rd.vec(raw, dimension, field))
    if isinstance(raw, dict):
        size = rounding(raw["magnitude"], dimension, f"{field}.magnitude") \
            + abs(z) * rounding(raw["angle"], "angle", f"{field}.angle")
        first = raw["magnitude"]
    else:
        size = math.hypot(rounding(raw[0], dimension, f"{field}[0]"), rounding(raw[1], dimension, f"{field}[1]"))
        first = raw[0]
    return _Value(z, size, raw, written(first, dimension, field=field, file=rd.file))


def _power_speed(rd, raw, field, load, motion) -> None:
    """A power's speed is its link's own: T = P/ω at another ω, or the other sign, is another load."""
    mech = motion.mech
    speed = _value(rd, raw, "angular_velocity", field)
    if mech.driver.crank and load.link == mech.driver.link:
        omega, valid = motion.q_dot, np.ones(len(motion.q), bool)  # the input itself: no kinematics to solve
    else:
        omega, valid = motion.kin.omega[load.link], motion.kin.valid
    # Where the input stands still the file gives no motion (a static analysis without driver.omega): no speed to check.
    acts = valid & (motion.q_dot != 0)
    if load.active is not None:
        acts &= load.active.mask(motion.q)
    off = acts & ~_close(speed.si, omega, speed.rounding)
    if off.any():
        i = int(np.argmax(off))
        x = float(omega[i])
        turns = "stands still" if x == 0 else f"turns at {speed.text(x)} ({_sense(x)})"
        raise rd.fail(field, f"is {speed.shown} but link {load.link} {turns} at {motion.at(i)}: a power's speed is its "
                      "link's, sign included (negative clockwise), for T = P/ω")


def _pressure_line(rd, joints, raw, where, load, motion) -> None:
    """A pressure pushes its piston along the line the piston slides on, at every position the file gives."""
    mech = motion.mech
    field = f"{where}.direction"
    lines = [(k, j) for k, j in enumerate(mech.joints) if isinstance(j, Prismatic) and load.link in j.links]
    if not lines:
        raise rd.fail(f"{where}.link", f"link {load.link} slides on no guide: a pressure pushes a piston along its "
                      "cylinder (a link of a prismatic joint); give a load on another link as type = \"force\"")
    a = rd.si(raw, "angle", field)
    rounding = written(raw, "angle", field=field, file=rd.file).rounding

    def tolerance(k, own):
        # The joint's direction is written too, with its own rounding (left out, it is an exact 0).
        text = joints[k].get(own) if own else None
        return max(REL, rounding + (0.0 if text is None else
                                    written(text, "angle", field=f"joints[{k}].{own}", file=rd.file).rounding))

    def refuse(k, j, g, at=""):
        d = math.degrees(g) % 360
        other = j.slider if j.guide == load.link else j.guide
        on = "the frame" if other == mech.frame else f"link {other}"
        raise rd.fail(field, f"is {shown(raw)} but the piston, link {load.link}, slides on {on} along {d:.6g}° "
                      f"(joints[{k}]){at}: a pressure pushes it along that line, direction = \"{d:.6g} deg\" or "
                      f"\"{(d + 180) % 360:.6g} deg\"")

    turning = []
    for k, j in lines:
        if mech.frame not in j.links:
            turning.append((k, j))
            continue
        # A line fixed in the frame: the guide's direction, or the slider's own where the frame is the slider.
        own = "direction" if j.guide == mech.frame else "slider_direction"
        if abs(math.sin(a - getattr(j, own))) <= tolerance(k, own):
            return
    if not turning:
        k, j = lines[0]
        refuse(k, j, j.direction if j.guide == mech.frame else j.slider_direction)
    kin = motion.kin
    ok = np.zeros(len(motion.q), bool)
    for k, j in turning:
        ok |= np.abs(np.sin(a - np.angle(kin.z_guide(j)))) <= tolerance(k, None)
    off = kin.valid & ~ok
    if load.active is not None:
        off &= load.active.mask(motion.q)
    if off.any():
        i = int(np.argmax(off))
        k, j = turning[0]
        refuse(k, j, float(np.angle(kin.z_guide(j))[i]), f" at {motion.at(i)}")


def _on_frame(mech, link):
    """The prismatic joint (index, joint) by which ``link`` slides on the frame, or None."""
    for k, j in enumerate(mech.joints):
        if isinstance(j, Prismatic) and set(j.links) == {mech.frame, link}:
            return k, j
    return None


def _given(rd, driver, raw, field, link, name, motion) -> None:
    """A given value of a link: the crank's ω and α are the driver's; a link sliding on the frame does not turn and
    moves along its guide; on any other link a reading off a drawing may differ from graphkin's, but not in sense."""
    mech = motion.mech
    value = _value(rd, raw, _DIMENSION[name], field, vector=name in ("v_G", "a_G"))
    sliding = _on_frame(mech, link)
    if mech.driver.crank and link == mech.driver.link and name in ("omega", "alpha"):
        _crank_rate(rd, driver, field, link, name, value, motion)
    elif sliding is not None:
        _sliding(rd, driver, field, link, name, value, sliding, motion)
    elif name != "theta":
        _sign(rd, field, link, name, value, motion)


def _crank_rate(rd, driver, field, link, name, value, motion) -> None:
    """The crank's given ω or α is the driver's own."""
    if name not in driver and name == "omega":
        return  # a static analysis without the input's speed: the file gives the crank none to contradict
    driven = float((motion.q_dot if name == "omega" else motion.q_ddot)[0])
    rounding = value.rounding + _rate_rounding(rd, driver, name)
    if _close(value.si, driven, rounding):
        return
    if name == "alpha" and driven == 0:
        how = "at a constant speed (driver.alpha = 0" + (")" if name in driver else ", the default)")
    else:
        how = f"at {_SYMBOL[name]} = {value.text(driven)}" + (f" ({_sense(driven)})" if driven else "") \
            + f" by driver.{name}"
    raise rd.fail(field, f"is {value.shown} but link {link} is the crank, driven {how}: give the input's motion once, "
                  "in [driver]")


def _rate_rounding(rd, driver, key) -> float:
    """The rounding of the driver's rate ``key`` as written (one value, or a list of one: given values are for one
    position); 0 where it is left out (a default of 0 is exact)."""
    if key not in driver:
        return 0.0
    raw = driver[key][0] if isinstance(driver[key], list) else driver[key]
    field = f"driver.{key}" + ("[0]" if isinstance(driver[key], list) else "")
    return _value(rd, raw, _DIMENSION[key], field).rounding


def _sliding(rd, driver, field, link, name, value, sliding, motion) -> None:
    """A link that slides on the frame keeps its angle and moves along the guide (the slider driver: at v and a)."""
    mech = motion.mech
    k, joint = sliding
    guide = f"slides on the frame's guide (joints[{k}])"
    if name in ("omega", "alpha"):
        if not _close(value.si, 0.0, value.rounding):
            raise rd.fail(field, f"is {value.shown} but link {link} {guide} without turning: its {_SYMBOL[name]} is 0")
        return
    # The line's direction from +x, and the link's angle: θ_slider = θ_guide + direction − slider_direction.
    if joint.guide == mech.frame:
        line, theta = joint.direction, joint.direction - joint.slider_direction
    else:
        line, theta = joint.slider_direction, joint.slider_direction - joint.direction
    if name == "theta":
        if abs(cmath.phase(cmath.rect(1.0, value.si - theta))) > max(REL, value.rounding):
            raise rd.fail(field, f"is {value.shown} but link {link} {guide} without turning, at "
                          f"{math.degrees(theta):.6g}°")
        return
    if link == mech.driver.link:
        _slider_rate(rd, driver, field, link, name, value, motion)
        return
    across = (value.si * cmath.rect(1.0, -line)).imag
    if not _close(across, 0.0, max(REL * abs(value.si), value.rounding)):
        raise rd.fail(field, f"is {value.shown} but link {link} {guide} along {math.degrees(line) % 360:.6g}°: its G "
                      f"moves along that line, so {_SYMBOL[name]} has no component across it (here "
                      f"{abs(across) / value.unit.size:.6g} {value.unit.unit})")


def _slider_rate(rd, driver, field, link, name, value, motion) -> None:
    """The slider driver's G moves at the input's own v and a, along its guide."""
    key = "v" if name == "v_G" else "a"
    kin = motion.kin
    if (key == "v" and key not in driver) or not kin.valid[0]:
        return  # a static analysis without the input's speed, or a position where the linkage does not assemble
    c = complex((kin.z_velocity if name == "v_G" else kin.z_acceleration)(link, motion.mech.link(link).G)[0])
    rounding = value.rounding + _rate_rounding(rd, driver, key)
    if not _close(value.si, c, rounding):
        given = f"driver.{key} = {shown(driver[key])}" if key in driver else "constant speed (driver.a = 0, the default)"
        raise rd.fail(field, f"is {value.shown} but link {link} is the slider, driven at {given}: its {_SYMBOL[name]} "
                      f"is {value.text(c)}")


def _sign(rd, field, link, name, value, motion) -> None:
    """A reading off a drawing may differ from graphkin's exact value, but not be its negative."""
    kin = motion.kin
    if not kin.valid[0]:
        return
    if name in ("omega", "alpha"):
        c = float((kin.omega if name == "omega" else kin.alpha)[link][0])
    else:
        G = motion.mech.link(link).G
        c = complex((kin.z_velocity if name == "v_G" else kin.z_acceleration)(link, G)[0])
    if not (abs(c) > 0 and abs(value.si + c) <= SLIP * abs(c)):
        return
    stated, found = value.shown, value.text(c)
    if name in ("omega", "alpha"):
        stated, found = f"{stated} ({_sense(value.si)})", f"{found} ({_sense(c)})"
    raise rd.fail(field, f"is {stated} but graphkin finds {_SYMBOL[name]}{link} = {found} at {motion.at(0)}: the same "
                  "size the other way, a lost sign (ω and α are positive counter-clockwise, vectors in global x, y)")
