"""What a book asks for besides the joint forces and the driving effort, as it asks it: the net force on an engine's
piston, the forces on its crank pin and the turning moment (Khurmi and Gupta, §15.10), the flywheel's angular
acceleration (§15.12), a tooth force's tangential and radial components (Wentzell, §12), and the torque that holds a
gear meshing with the frame (an epicyclic train's annulus). Each section states its own sign convention where it differs from the
driving torque's, and is printed only where it fits the mechanism and the book asks for it (the problem file's
``asked``; a file that does not say gets the crank pin of a plain crank).
"""

from __future__ import annotations

import numpy as np

from graphkin.analytical.meshes import contact, pitch, power_flow
from graphkin.geometry import as_xy, as_z
from graphkin.geometry import zdot as dot
from graphkin.handout import maths as M
from graphkin.handout.document import Doc, Subject
from graphkin.kinematics import GearGroup
from graphkin.model import GearMesh, Prismatic, Revolute

CRANK_PIN = {"F_B", "F_T", "T"}
"""The names ``asked`` gives the crank pin's quantities."""
TOOTH = {"W_t", "W_r"}
"""The names ``asked`` gives a tooth force's components."""


def asked(doc: Doc, s: Subject, entry: dict, i: int):
    """The sections of position ``i`` that answer what the book asks beyond the joint forces and the effort."""
    wanted = set(s.problem.asked)
    if "F_P" in wanted:
        piston(doc, s, entry, i)
    if CRANK_PIN & wanted or not wanted and s.variant is None:
        crank_pin(doc, s, entry, i)
    if "alpha" in wanted and "forward" in entry:
        flywheel(doc, s, entry, i)
    if TOOTH & wanted:
        for joint in s.mech.joints:
            if isinstance(joint, GearMesh) and s.mech.frame not in joint.links:
                tooth(doc, s, joint, i)
    if "T_hold" in wanted or not wanted:
        for joint in s.mech.joints:
            if isinstance(joint, GearMesh) and s.mech.frame in joint.links:
                held(doc, s, joint, i)


def _sense(T: float) -> str:
    return " (CCW)" if T > 0 else " (CW)" if T < 0 else ""


def piston(doc: Doc, s: Subject, entry: dict, i: int):
    """The net force on the piston along the line of stroke, F_P (Khurmi and Gupta, §15.10): what the piston passes
    to the connecting rod at the gudgeon pin along the stroke, the gas load less the inertia force (and plus the
    weight of a vertical engine's parts), which the rod's force on the piston balances."""
    mech, kin = s.mech, s.result.kinematics
    d = mech.driver
    slides = [j for j in mech.joints if isinstance(j, Prismatic) and j.guide == mech.frame]
    pivot = mech.joint_between(mech.frame, d.link) if d.crank else None
    if len(slides) != 1 or pivot is None:
        return
    guide = slides[0]
    pins = [j for j in mech.joints_of(guide.slider) if isinstance(j, Revolute) and mech.frame not in j.links]
    if len(pins) != 1:
        return
    rod = (set(pins[0].links) - {guide.slider}).pop()
    name = s.result.name_of(rod, guide.slider)
    P = kin.position(guide.slider, pins[0].point)[i]
    O = kin.position(d.link, pivot.point)[i]
    u = np.asarray(kin.guide_direction(guide)[i], float)
    if float((O - P) @ u) < 0:
        u = -u  # along the stroke towards the crank shaft
    F = np.asarray(entry["forces"][name], float)
    F_P = float(-F @ u)
    doc.heading(2, "The net force on the piston")
    doc.text("The net force on the piston ", M.sym("F", "P"), " is what it passes to the connecting rod at ", pins[0].point,
             ", along the line of stroke, counted positive towards the crank shaft: the gas load less the inertia "
             "force (with the weight where the stroke is vertical). The rod's force ", M.name(name),
             " on the piston balances it along the stroke:")
    doc.equation(M.row(M.sym("F", "P"), M.op("="), M.op("−"), M.vec(M.name(name)), M.op("·"), M.i("u"), M.op("="),
                       s.qty(F_P, "force"), M.t(" (towards the crank shaft)" if F_P > 0 else
                                                " (away from the crank shaft)" if F_P < 0 else "")))


def crank_pin(doc: Doc, s: Subject, entry: dict, i: int):
    """The force of the coupler (or connecting rod) on the crank pin, along the crank and across it.

    Books on engines ask for these: the thrust on the crank-shaft bearing F_B (along the crank, towards
    the shaft) and the tangential force F_T that turns the crank, T = r F_T (Khurmi and Gupta, §15.10).
    Not for a gear arm: what its pin carries is a planet, not a connecting rod.
    """
    d = s.mech.driver
    if not d.crank:
        return
    pivot = s.mech.joint_between(s.mech.frame, d.link)
    pins = [j for j in s.mech.joints_of(d.link) if isinstance(j, Revolute) and s.mech.frame not in j.links]
    if pivot is None or len(pins) != 1:
        return
    pin = pins[0]
    other = (set(pin.links) - {d.link}).pop()
    if any(isinstance(j, GearMesh) for j in s.mech.joints_of(other)):
        return
    kin = s.result.kinematics
    O = kin.position(d.link, pivot.point)[i]
    P = kin.position(d.link, pin.point)[i]
    r = float(np.hypot(*(P - O)))
    if r <= 0:
        return
    u = (P - O) / r
    name = s.result.name_of(other, d.link)
    F = np.asarray(entry["forces"][name], float)
    F_B = float(-F @ u)
    F_T = float(F @ np.array([-u[1], u[0]]))
    T, T12 = r * F_T, float(entry["driver"]["value"])
    doc.heading(2, "At the crank pin")
    doc.text("The force ", M.name(name), f" of link {other} on the crank, resolved along the crank "
             f"{pivot.point}{pin.point} (unit vector u) and across it (k × u, the sense of positive θ):")
    doc.equation(
        M.row(M.sym("F", "B"), M.op("="), M.op("−"), M.vec(M.name(name)), M.op("·"), M.i("u"), M.op("="),
              s.qty(F_B, "force"), M.t(" (towards the shaft: a thrust on its bearing)" if F_B > 0 else
                                   " (away from the shaft: a pull on its bearing)" if F_B < 0 else "")),
        M.row(M.sym("F", "T"), M.op("="), M.vec(M.name(name)), M.op("·"), M.paren(M.i("k"), M.op("×"), M.i("u")),
              M.op("="), s.qty(F_T, "force"), M.op(";"), M.SP, M.i("T"), M.op("="), M.i("r"), M.sym("F", "T"),
              M.op("="), M.paren(s.qty(r, "length")), M.paren(s.qty(F_T, "force")), M.op("="),
              s.qty(T, "torque"), M.t(_sense(T))))
    # T and the driving torque are two torques on one crank, of opposite signs: say so, in the numbers.
    rest = T12 + T
    own = (" (they differ by the crank's own inertia and weight, " + M.fmt(-rest) + " N·m)"
           if abs(rest) > 1e-6 * max(abs(T), abs(T12), 1e-300) else "")
    doc.text("T is the turning moment the connecting rod exerts on the crank (", M.name(name), " about the shaft, "
             "counter-clockwise positive); the driving torque ", M.name(d.symbol), " = ", s.qty(T12, "torque"),
             f" found above is what holds the crank against it, so it has the opposite sign{own}: a book that asks "
             "for the turning moment on the crank shaft means T.")


def flywheel(doc: Doc, s: Subject, entry: dict, i: int):
    """The flywheel's angular acceleration from the torque the crank shaft gets and the torque taken off
    (the problem file's ``[forward]``): I α = T_driving + T_resisting."""
    f, T12 = entry["forward"], entry["driver"]
    alpha = f["alpha"]
    omega = float(s.result.kinematics.q_dot[i])
    doc.heading(2, "The flywheel")
    doc.text("The crank shaft gets the torque −", M.name(T12["name"]), " from the engine (the driving torque found "
             "above is what holds the crank against it) and loses the torque the load takes off, against its "
             "rotation; their sum accelerates the flywheel and shaft, of moment of inertia I:")
    doc.equation(M.row(M.i("I"), M.i("α"), M.op("="), M.op("−"), M.name(T12["name"]), M.op("+"),
                       M.sym("T", "resisting"), M.op("="), s.qty(f["T_driving"], "torque"), M.op("+"),
                       M.paren(s.qty(f["T_resisting"], "torque")), M.op("="),
                       s.qty(f["T_driving"] + f["T_resisting"], "torque")),
                 M.row(M.i("α"), M.op("="), M.frac(s.qty(f["T_driving"] + f["T_resisting"], "torque"),
                                                  s.qty(f["I"], "moment_of_inertia")), M.op("="),
                       s.qty(alpha, "angular_acceleration"), M.t(_sense(alpha))))
    if omega * alpha != 0:
        doc.text("α is counter-clockwise positive, as every angle here; the crank turns "
                 f"{'counter-clockwise' if omega > 0 else 'clockwise'}, so the flywheel "
                 f"{'speeds up' if omega * alpha > 0 else 'slows down'}: a book that gives the acceleration in the "
                 "sense of rotation prints ", s.qty(abs(alpha) if omega * alpha > 0 else -abs(alpha),
                                                   "angular_acceleration"), ".")


def tooth(doc: Doc, s: Subject, joint: GearMesh, i: int):
    """A tooth force resolved across and along the line of centres (Wentzell, §12): the transmitted (tangential)
    force W_t that carries the torque, and the separating (radial) force W_r that pushes the gears apart."""
    kin, r = s.result.kinematics, s.result
    a, b = joint.links
    name = r.name_of(a, b)
    F = np.asarray(r.force(a, b)[i], float)
    Ca = kin.position(a, joint.centers[0])[i]
    Cb = kin.position(b, joint.centers[1])[i]
    e = (Cb - Ca) / np.hypot(*(Cb - Ca))
    W_t, W_r = float(abs(F[0] * -e[1] + F[1] * e[0])), float(abs(F @ e))
    doc.heading(2, "The tooth force's components")
    doc.text(*M.prose(f"The tooth force {name} of gear {a} on gear {b}, resolved across the line of centres "
                      f"{joint.centers[0]}{joint.centers[1]} (unit vector e) and along it: the transmitted (tangential) "
                      "force that carries the torque, and the separating (radial) force that pushes the gears apart "
                      "(sizes; the pressure angle φ sets their ratio, W_r = W_t tan φ):"))
    doc.equation(M.row(M.sym("W", "t"), M.op("="), M.absval(M.row(M.vec(M.name(name)), M.op("×"), M.i("e"))),
                       M.op("="), s.qty(W_t, "force"), M.op(";"), M.SP, M.sym("W", "r"), M.op("="),
                       M.absval(M.row(M.vec(M.name(name)), M.op("·"), M.i("e"))), M.op("="), s.qty(W_r, "force")))


def held(doc: Doc, s: Subject, joint: GearMesh, i: int):
    """The torque that holds a gear of the frame (an annulus held still) against its mesh's tooth force."""
    mech, kin, r = s.mech, s.result.kinematics, s.result
    frame = mech.frame
    k = (set(joint.links) - {frame}).pop()
    centre = joint.centers[joint.links.index(frame)]
    O = kin.position(frame, centre)[i]
    # The tooth force's line, where the matrix method and the construction put it (assemble, analytical/matrix.py).
    g = next(g for g in kin.groups if isinstance(g, GearGroup) and g.mesh is joint)
    Ck, Cj = kin.z(g.b, g.ck), kin.z(g.b, g.cj)
    on_k = as_z(r.force(g.j, g.k))
    X = as_xy(contact(joint, g.k, Ck, Cj, power_flow(kin, g, dot(on_k, pitch(joint, g.k, Ck, Cj)[1])))[0])[i]
    name = r.name_of(k, frame)
    F = np.asarray(r.force(k, frame)[i], float)
    arm = X - O
    T = -float(arm[0] * F[1] - arm[1] * F[0])
    what = joint.label if hasattr(joint, "label") else "the mesh"
    doc.heading(2, "The held gear")
    doc.text(*M.prose(f"Gear {frame} is the frame here, held still. Gear {k} pushes on it with the tooth force {name} "
                      f"at the point X where its line crosses the line of centres ({what}); the torque that holds gear "
                      f"{frame} about its centre {centre} balances that force's moment (counter-clockwise positive, as "
                      "every torque here):"))
    doc.equation(M.row(M.sym("T", "hold"), M.op("="), M.op("−"), M.sym("r", f"{centre}X"), M.op("×"),
                       M.vec(M.name(name)), M.op("="), M.op("−"), M.pair(arm, "m"), M.op("×"), M.pair(F, "N"),
                       M.op("="), s.qty(T, "torque"), M.t(_sense(T))))
