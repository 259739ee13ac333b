"""What the stated precision of a careful drawing makes of each graphical answer.

A force read off a polygon carries the errors of every line drawn before it: the lines of action in the
mechanism, the point where two of them meet, the sides laid off in this polygon and in the polygons whose
results it takes over; a value read off the velocity or acceleration polygon, those of the vectors laid off
and the lines drawn before it. :func:`careful` replays the drawing as careful students draw it
(:mod:`graphkin.exercises.drawn_forces`, :mod:`graphkin.exercises.drawn_motion`), each line with its own
error within the stated precision (:mod:`graphkin.exercises.precision`), for many sets of errors at once.
:func:`drawing_slack` finds each error's effect on the answer from that replay; each error taken as uniform
within its stated bound (standard deviation bound/√3), the slack is the bound of their sum that holds
:data:`~graphkin.exercises.precision.HELD` of careful constructions.
"""

from __future__ import annotations

import math

import numpy as np

from graphkin.exercises.drawn_forces import drawn, measured
from graphkin.exercises.drawn_motion import motion_answer
from graphkin.exercises.precision import COVERAGE, Errors


def drawing_slack(solved, q, exact) -> float | None:
    """The slack of a graphical answer that the stated precision gives [SI; rad for a direction].

    Each error's effect on the answer is found by replaying the construction (or the velocity and acceleration
    polygons) with that error alone; the slack is :data:`~graphkin.exercises.precision.COVERAGE` times the root
    sum of squares of the effects at the stated bounds. None when the answer is not measured off a drawing this
    module replays.

    Parameters
    ----------
    solved : graphkin.exercises.variants.Solved
        The student's solved draw (its construction and polygons, at the position asked about).
    q : Question
    exact : float or complex
        The key's value (SI).

    Returns
    -------
    float or None
    """
    errors = Errors(1)
    m = careful(solved, q, exact, errors)
    # A replay that does not give the key's value back without errors is not this construction's: not used.
    if m is None or not abs(_off(q, m[0], exact)) <= 1e-9 * max(abs(exact), 1e-300):
        return None
    small = 1e-6  # of each bound: the effects are linear this near
    m = careful(solved, q, exact, Errors(1 + errors.count, probe=small))
    effects = np.abs(_off(q, m[1:], m[0])) / small
    return float(COVERAGE * np.sqrt(np.sum(effects**2)))


def careful(solved, q, exact, errors: Errors):
    """What careful students measure for ``q`` with ``errors`` (an array over the drawings; SI, angles in rad),
    or None where the answer is not measured off a drawing this module replays."""
    if q.kind in ("omega", "alpha", "a_G", "coriolis"):
        mc = solved.motion
        return motion_answer(mc, q, exact, errors) if mc.valid else None
    c = solved.construction
    if not c.valid:
        return None
    d = drawn(c, errors)
    return None if d is None else measured(d, q, exact)


def _off(q, a, b):
    """a − b, an angle's wrapped to (−π, π]."""
    if q.part == "direction":
        return np.remainder(a - b + math.pi, 2 * math.pi) - math.pi
    return a - b
