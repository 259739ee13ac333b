"""What a book asks for besides the joint forces and the driving effort, as it asks it: the forces on an engine's
crank pin and the turning moment (Khurmi and Gupta, §15.10), and the torque that holds a gear meshing with the
frame (an epicyclic train's annulus). Each section states its own sign convention where it differs from the
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
from graphkin.model import GearMesh, Revolute

CRANK_PIN = {"F_B", "F_T", "T"}
"""The names ``asked`` gives the crank pin's quantities."""


def asked(doc: Doc, s: Subject, entry: dict, i: int):
    """The sections of position ``i`` that answer what the book asks beyond the joint forces and the effort."""
    wanted = set(s.problem.asked)
    if CRANK_PIN & wanted or not wanted and s.variant is None:
        crank_pin(doc, s, entry, i)
    if "T_hold" in wanted or not wanted:
        for joint in s.mech.joints:
            if isinstance(joint, GearMesh) and s.mech.frame in joint.links:
                held(doc, s, joint, i)


def _sense(T: float) -> str:
    return " (CCW)" if T > 0 else " (CW)" if T < 0 else ""


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
