"""The constructions a handout works, for the tests that measure what it draws from them: each exercise's for a
few students (its worked positions, each student's numbers)."""

from __future__ import annotations

import warnings

from graphkin.handout.document import subject


def exercise_constructions(name: str, students, secret: str):
    """(label, construction) of exercise ``name`` at each worked position of each student's variant, where it
    solves: ``"double_slider_forces for s01"``."""
    for student in students:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # a variant's own warnings (a load set aside) are not the test's
            s = subject(name, student=student, secret=secret)
        for i in s.worked():
            c = s.construction(i)
            if c is not None and c.valid:
                yield f"{name} for {student}", c
