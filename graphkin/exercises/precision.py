"""What a careful student's drawing is accurate to.

A graphical answer is only as good as the lines it is measured off. A careful student draws each line of
a construction or polygon within :data:`LENGTH` (a point placed, an offset or a side laid off, a length
measured, on paper) and :data:`ANGLE` (a direction drawn or carried over with set squares), at the
worksheet's printed scales. :mod:`graphkin.exercises.drawn` carries this precision through the drawing to
each answer; :class:`Errors` draws the errors, one source (one drawn line, point or reading) at a time.
"""

from __future__ import annotations

import math
from statistics import NormalDist

import numpy as np

from graphkin.graphical.paper import READING

LENGTH = READING
"""A careful student's error on paper [mm], each way: a point placed, an offset or a side laid off, a length
measured (half the smallest division of a school rule)."""

ANGLE = 0.5
"""A careful student's error in a drawn direction [°], each way: a line drawn at a given angle, or a direction
carried from the mechanism to the polygon with set squares (half a degree of a protractor)."""

HELD = 0.975
"""The share of careful constructions the slack is set to hold. A course promises 95 %; aiming higher leaves room
for what the linear estimate leaves out (a construction is not quite linear in its errors, a sum of a few uniform
errors not quite normal)."""

COVERAGE = NormalDist().inv_cdf(0.5 + HELD / 2) / math.sqrt(3)
"""The slack in units of the root sum of squares of the stated bounds' effects: an error uniform within ±b has
a standard deviation of b/√3, and 2.24 standard deviations hold 97.5 % of a sum of such errors (1.29 bounds)."""


class Errors:
    """The errors of one set of drawings, source by source, as arrays over the ``n`` drawings.

    Parameters
    ----------
    n : int
        How many drawings are replayed at once.
    rng : numpy.random.Generator, optional
        Draws each error uniformly within its bound (a Monte Carlo of careful students).
    probe : float, optional
        Instead of random errors: drawing ``1 + i`` moves source ``i`` alone, by ``probe`` times its bound
        (drawing 0 has no error), to find each source's effect.
    """

    def __init__(self, n: int, *, rng=None, probe: float | None = None):
        self.n, self.rng, self.probe = n, rng, probe
        self.count = 0

    def __call__(self, bound: float) -> np.ndarray:
        """The error of the next source, within ±``bound`` (its unit), one value per drawing."""
        i = self.count
        self.count += 1
        if self.rng is not None:
            return self.rng.uniform(-bound, bound, self.n)
        e = np.zeros(self.n)
        if self.probe is not None and 1 + i < self.n:
            e[1 + i] = self.probe * bound
        return e
