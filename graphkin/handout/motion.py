"""The velocity and acceleration polygons in a handout: the key's figure at stated scales (and, in the full
walk-through, the steps that draw them), and a worksheet's boxes to construct them in.

The polygons are :func:`graphkin.graphical.construct_kinematics`'s, built from the input's ω2 and α2 (or a
driving slider's v and a) and the positions only; each figure prints at 1 mm = X m/s and 1 mm = Y m/s²
(:func:`graphkin.graphical.paper.motion_scales`), with a bar for each scale under it.
"""

from __future__ import annotations

from graphkin.graphical.paper import POLYGON_ROOM, READING, motion_scales, motion_text
from graphkin.handout import maths as M
from graphkin.handout.document import Doc, Subject
from graphkin.handout.figures import Picture

BOX = (POLYGON_ROOM[0] + 14.0, POLYGON_ROOM[1] + 16.0)
"""A motion polygon's box on a worksheet [mm], as large as a force polygon's (its scale is chosen to fit it)."""


def picture(s: Subject, mc, i: int, Xv: float, Xa: float, *, key: str = "motion") -> Picture:
    """Both polygons of position ``i`` printed at 1 mm = ``Xv`` m/s and 1 mm = ``Xa`` m/s²."""
    from graphkin.draw import paper

    return s.picture(f"{key}-{i}", lambda: paper.draw_motion_paper(mc, velocity_scale=Xv, acceleration_scale=Xa),
                     alt=f"the velocity polygon at {motion_text(Xv, 'velocity')} and the acceleration polygon at "
                         f"{motion_text(Xa, 'acceleration')}", natural=True)


def _input_text(s: Subject, mc) -> str:
    """What the polygons start from: ``ω2 = 95 rad/s (CCW), α2 = 0`` (a crank), or the slider's v and a."""
    d = s.mech.driver
    if d.crank:
        w, a = mc.omega[d.link], mc.alpha[d.link]
        return f"ω{d.link} = {M.fmt(w)} rad/s, α{d.link} = {M.fmt(a)} rad/s² (CCW positive)"
    kin = s.result.kinematics
    v, a = float(kin.q_dot[mc.index]), float(kin.q_ddot[mc.index])
    return (f"the driving slider's v = {M.fmt(v)} m/s and a = {M.fmt(a)} m/s² along its guide "
            "(positive in the guide's direction)")


def _unavailable(doc: Doc, mc) -> bool:
    if mc is None or not mc.valid:
        doc.text("The velocity and acceleration polygons cannot be drawn here: "
                 f"{mc.reason if mc is not None else 'no solution'}.")
        return True
    return False


def key(doc: Doc, s: Subject, i: int, *, steps: bool = False, explain: bool = True):
    """The polygons of position ``i`` at stated scales; ``steps``: with every step of the construction, captioned;
    ``explain``: with a sentence on how the polygons give ω, α and a_G (a compact key's caption is enough)."""
    if s.static:
        return
    mc = s.motion(i)
    if _unavailable(doc, mc):
        return
    Xv, Xa = motion_scales(mc)
    label = doc.figure([picture(s, mc, i, Xv, Xa)],
                       f"The velocity polygon ({motion_text(Xv, 'velocity')}) and the acceleration polygon "
                       f"({motion_text(Xa, 'acceleration')}) at {s.where(i)}, constructed from {_input_text(s, mc)}. "
                       "Pole o (o′); each link's image shaded; g the image of its centre of mass.")
    if explain:
        doc.text(f"{label} draws the same motion graphically: each ω and α above is a relative vector of a polygon over "
                 "the length it turns about (", M.row(M.sym("ω", "3"), M.op("="), M.sym("v", "BA"), M.op("/"), M.i("AB")),
                 "), and each ", M.sym("a", "G"), " the vector from o′ to its g′.")
    if not steps:
        return
    doc.text("The construction of the polygons, step by step (each step in the order drawn; measure each found "
             "vector at the figure's scale):")
    doc.items([M.prose(f"{st.polygon.capitalize()} polygon, {st.kind}: {st.caption}") for st in mc.steps],
              ordered=True)


def boxes(doc: Doc, s: Subject, i: int):
    """A worksheet's boxes for the velocity and acceleration polygons of position ``i``, each with its scale."""
    if s.static:
        return
    mc = s.motion(i)
    if mc is None or not mc.valid:
        return
    Xv, Xa = motion_scales(mc, POLYGON_ROOM)
    doc.heading(2, "Velocity and acceleration polygons")
    doc.text(f"Start from the input motion, {_input_text(s, mc)}, and the mechanism's drawing above (measure "
             "each length on it at its scale). Draw the velocity polygon from its pole o at "
             f"{motion_text(Xv, 'velocity')}, then the acceleration polygon from o′ at {motion_text(Xa, 'acceleration')}: "
             "normal components ω² r towards the centre of turning, tangential ones perpendicular to the link, the "
             "Coriolis component 2ωv across a sliding pair; mark each centre of mass's image g on its link's image. "
             f"A reading to ±{READING:g} mm is ±{M.fmt(READING * Xv)} m/s and ±{M.fmt(READING * Xa)} m/s².")
    doc.space(BOX[1], f"Velocity polygon, at {motion_text(Xv, 'velocity')}: ", width=BOX[0])
    doc.space(BOX[1], f"Acceleration polygon, at {motion_text(Xa, 'acceleration')}: ", width=BOX[0])
