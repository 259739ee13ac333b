"""The force route fed from the polygons: inertia loads from values read off them (:func:`kinematics_from_polygons`)."""

from __future__ import annotations

import numpy as np

from graphkin.errors import GraphkinError
from graphkin.graphical.polygons import construct_kinematics
from graphkin.kinematics import Kinematics


def kinematics_from_polygons(kin: Kinematics) -> Kinematics:
    """These kinematics with ω, α, v_G and a_G of every moving link as read off the polygons.

    The force route (:func:`graphkin.analytical.solve_forces`, :func:`graphkin.graphical.construct_forces`)
    takes its inertia loads −m a_G and −I_G α from what it is given, so with these kinematics a handout goes
    from the input motion to the driving effort by construction alone. The numbers are the polygons' own
    (they equal the analytical ones to rounding, which the tests check).

    Parameters
    ----------
    kin : Kinematics
        The mechanism's motion over n positions (its positions and input rates are what the polygons read).

    Returns
    -------
    Kinematics
        With ``given`` values ``(link, "omega" | "alpha")`` [rad/s, rad/s²] and ``(link, "v_G" | "a_G")``
        [m/s, m/s²], nan where a position has no polygons.
    """
    if not isinstance(kin, Kinematics):
        raise GraphkinError(f"kinematics_from_polygons takes the Kinematics of a problem, got {type(kin).__name__}")
    if kin.given:
        raise GraphkinError("kinematics_from_polygons: these kinematics already carry given values "
                            f"({', '.join(sorted({str(k[1]) for k in kin.given}))}); start from the derived ones")
    moving = kin.mechanism.moving
    n = kin.n
    w, al = {l: np.full(n, np.nan) for l in moving}, {l: np.full(n, np.nan) for l in moving}
    v_G, a_G = {l: np.full((n, 2), np.nan) for l in moving}, {l: np.full((n, 2), np.nan) for l in moving}
    for i in range(n):
        c = construct_kinematics(kin, i)
        if not c.valid:
            continue
        for l in moving:
            w[l][i], al[l][i] = c.omega[l], c.alpha[l]
            v_G[l][i], a_G[l][i] = c.v_G[l], c.a_G[l]
    given = {}
    for l in moving:
        given.update({(l, "omega"): w[l], (l, "alpha"): al[l], (l, "v_G"): v_G[l], (l, "a_G"): a_G[l]})
    return kin.with_given(given)
