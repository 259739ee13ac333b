"""Gear outlines: spur gears with their teeth out, annuli (internal gears) with their teeth in.

The mechanism drawing (:mod:`graphkin.draw.mechanism`) draws every gear with
these: a gear pair on the frame, the planet of an epicyclic train and the
sun or annulus the train's frame carries.
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.patches import Circle, PathPatch
from matplotlib.path import Path

from graphkin.draw.arrows import arc_points
from graphkin.draw.axes import MM, put


def gear_outline(centre, r, teeth: int, phase: float, module: float, n_root: int = 3) -> np.ndarray:
    """The outline of a spur gear of pitch radius ``r`` [mm]: ``teeth`` trapezoids, one centred at ``phase`` [rad].

    Addendum one module, dedendum 1.25 modules; straight flanks, each tooth
    about 0.4 of the circular pitch thick at the pitch circle (a sketch, not
    an involute: the thin teeth keep clear of each other in mesh). Returns
    the closed polygon's vertices (not repeated at the end).
    """
    tau = 2 * math.pi / teeth
    ra, rr = r + module, max(r - 1.25 * module, 0.3 * r)
    pts = []
    for k in range(teeth):
        c = phase + k * tau
        pts.append((rr, c - 0.28 * tau))
        pts.append((ra, c - 0.12 * tau))
        pts.append((ra, c + 0.12 * tau))
        for t in np.linspace(0.28, 0.72, n_root):
            pts.append((rr, c + t * tau))
    rho, ang = np.asarray(pts).T
    return np.column_stack([centre[0] + rho * np.cos(ang), centre[1] + rho * np.sin(ang)])


def annulus_outline(centre, r, teeth: int, phase: float, module: float) -> tuple[np.ndarray, np.ndarray]:
    """An annulus of pitch radius ``r`` [mm]: its toothed inside (a tooth's middle at ``phase``) and its rim.

    The inside is :func:`gear_outline` mirrored about the pitch circle, at the same angles: the teeth point in,
    their tips 0.75 of a module inside the pitch circle, the roots 1.5 modules outside; the rim is 3.5 modules out.
    """
    inner = gear_outline(centre, r, teeth, phase, module)
    d = inner - np.asarray(centre, float)
    rho, ang = 2 * r + 0.25 * module - np.hypot(*d.T), np.arctan2(d[:, 1], d[:, 0])
    inner = np.column_stack([centre[0] + rho * np.cos(ang), centre[1] + rho * np.sin(ang)])
    return inner, arc_points(centre, r + 3.5 * module, 0.0, 2 * math.pi, 97)


def mesh_phase(geom, mesh, a: int, b: int, placed: tuple, zb: int, psi: float, sa: float) -> float:
    """The angle [rad] of a tooth's middle on gear b, placed to fit gear a's teeth at their pitch point.

    ``placed`` is gear a's (teeth, phase, module); ``psi`` the direction from a's centre to b's and ``sa`` the arc
    from a's nearest tooth to the pitch point there (see :class:`graphkin.draw.mechanism.Geometry`). External: the
    pitch circles run opposite ways, b's gap faces a's tooth across the line of centres. Internal: they run the
    same way and the pitch point lies beyond the pinion's centre, so both angles are measured towards it.
    """
    rb = mesh.radius(b) * MM
    pb = 2 * math.pi * rb / zb
    if not mesh.internal:
        return psi + math.pi - (pb / 2 - sa) / rb
    za, phase_a, _ = placed
    P = np.asarray(geom.c.pitch_points[tuple(sorted(mesh.links))], float) * MM
    ca, cb = (geom.P[n][mesh.centers[mesh.links.index(n)]] for n in (a, b))
    psi_a, psi_b = (math.atan2(*(P - c)[::-1]) for c in (ca, cb))
    sa = mesh.radius(a) * MM * ((psi_a - phase_a) % (2 * math.pi / za))
    return psi_b + (pb / 2 - sa) / rb


def draw_annulus(ax, geom, n: int, centre, r, s, labeler):
    """An annulus: its rim with the teeth pointing in and its dashed pitch circle, turning with link n."""
    teeth, phase, module = geom.teeth[n]
    inner, outer = annulus_outline(centre, r, teeth, phase, module)
    verts = np.concatenate([outer, inner[::-1], inner[-1:]])
    codes = ([Path.MOVETO] + [Path.LINETO] * (len(outer) - 1) + [Path.MOVETO] + [Path.LINETO] * (len(inner) - 1)
             + [Path.CLOSEPOLY])
    body = PathPatch(Path(verts, codes), facecolor=s.plate_fill, edgecolor=s.ink, lw=s.outline_lw, zorder=1.5)
    pitch = Circle(centre, r, fill=False, edgecolor=s.ink, lw=s.thin_lw, linestyle=(0, (10, 3, 2, 3)), zorder=1.55)
    put(ax, body, verts)
    ax.add_patch(pitch)
    if labeler:
        labeler.polyline(inner, closed=True)
        labeler.polyline(outer, closed=True)
    return [body, pitch]


def frame_gears(geom):
    """The gears the frame carries (a held sun or annulus): ``(mesh, centre [mm], pitch radius [mm])`` each."""
    frame = geom.mech.frame
    return [(mesh, geom.P[frame][mesh.centers[mesh.links.index(frame)]], mesh.radius(frame) * MM)
            for mesh in geom.gears if frame in mesh.links]
