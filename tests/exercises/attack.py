"""An adversary that mines graphkin's feedback for the key: submit, read every word of the feedback, submit again.

It is given more than a student who has not solved anything knows: the question's form, unit and tolerance,
the absolute floor of its slack, and the answer's size within a decade (directions: nothing). It keeps every key
still possible, a fine grid over that prior, and after each submission removes each key for which graphkin's
grader would have said something else: the verdict, the slip named (each undone: a sign, a power of ten, an
angle measured from +y, ...), "close", the vector's size or direction right, the sign or sense, "ten times too
large or small", and every number of "how far off" (inverted into the one or two keys it leaves). The next
submission is the still-possible key that splits the rest best, judged on a sample of them.

A harness runs it against one way a student sees feedback (:class:`Adversary.attack`), with the true key given
to the harness only, to check after each step that the adversary never rules the key out: it loses by
understanding the feedback too little only if that check fails, which is a failure of the test.
"""

from __future__ import annotations

import cmath
import math
import re
from dataclasses import dataclass, field

import numpy as np

CLOSE, CLOSE_PARTS = 2.5, 1.5  # the slacks within which an answer is "close" (graphkin.exercises.grading)

# Labels of what the grader can say (the numbers of "how far off" ride beside them).
CORRECT, NEAR, SIZE_RIGHT, OPAQUE, SLIP, PLAIN = 0, 1, 5, 50, 10, 100


@dataclass
class Question:
    """What the adversary knows of a question: its form, the SI value of its unit, its tolerance, the floor."""

    form: str              # "scalar", "magnitude", "vector" or "direction"
    unit: str              # as typed after the number ("N", "N*m"; "" for a direction)
    factor: float          # SI value of one unit
    tol: float
    floor: float = 0.0     # the absolute slack floor [SI]


def _angle(a):
    return np.abs(np.remainder(a + np.pi, 2 * np.pi) - np.pi)


@dataclass
class Transform:
    """A slip the grader finds by transforming the answer: its phrase, and how to undo and to make it."""

    name: str
    phrase: str
    undo: object
    make: object


def transforms(form: str) -> list[Transform]:
    """The grader's transformation slips for a force's question of this form (graphkin.exercises.grading)."""
    out = []
    if form == "vector":
        out += [Transform("sign", "direction is reversed", lambda a: -a, lambda a: -a),
                Transform("swapped", "components are swapped", lambda a: a.imag + 1j * a.real,
                          lambda a: a.imag + 1j * a.real),
                Transform("angle_from_y", r"the angle is measured from \+y", lambda a: a * 1j, lambda a: a * -1j),
                Transform("clockwise", "the angle is measured clockwise", np.conj, np.conj)]
    elif form == "scalar":
        out += [Transform("sign", r"(?:but the sense is wrong|but the sign is wrong;)", lambda a: -a, lambda a: -a)]
    elif form == "magnitude":
        out += [Transform("sign", "A magnitude is never negative:", lambda a: -a, lambda a: -a)]
    elif form == "direction":
        out += [Transform("opposite", "The direction is off by 180°", lambda a: a + np.pi, lambda a: a + np.pi),
                Transform("swapped", "components are swapped", lambda a: np.pi / 2 - a, lambda a: np.pi / 2 - a),
                Transform("angle_from_y", r"the angle is measured from \+y", lambda a: a + np.pi / 2,
                          lambda a: a - np.pi / 2),
                Transform("clockwise", "the angle is measured clockwise", lambda a: -a, lambda a: -a)]
        for f, wrong, right in ((180 / np.pi, "radians", "degrees"), (np.pi / 180, "degrees", "radians")):
            out.append(Transform("degrees_radians", f"looks like {wrong} read as {right}",
                                 lambda a, f=f: a * f, lambda a, f=f: a / f))
    if form in ("scalar", "magnitude", "vector"):
        for k in (3, -3, 6, -6):
            out.append(Transform("power_of_ten", rf"value is 10\^{abs(k)} too {'large' if k > 0 else 'small'}",
                                 lambda a, k=k: a / 10.0**k, lambda a, k=k: a * 10.0**k))
    return out


OPAQUE_PHRASES = ("This is the answer for", "This is what the acceleration polygon", "another point of the link",
                  "another student's data", "wrong side of G", "is a unit of", "without the inertia")


@dataclass
class Seen:
    """What one feedback text says, as the adversary reads it."""

    label: int
    numbers: tuple = ()


@dataclass
class Adversary:
    q: Question
    grid: object           # grid(fineness) -> the keys it starts from, at a spacing divided by fineness
    rng: np.random.Generator
    distance: bool = False  # the exercise's feedback is "distance" (its file says so; so do the texts)
    sample: int = 3000
    options: int = 24
    slips: list = field(default_factory=list)

    def __post_init__(self):
        self.slips = transforms(self.q.form)
        self.fineness = 1
        self.candidates = self.grid(self.fineness)
        self.history = []

    # --- the grader as the adversary models it ------------------------------------------------------------

    def slack(self, c):
        if self.q.form == "direction":
            return np.full(np.shape(c), math.atan(self.q.tol))
        return np.maximum(self.q.tol * np.abs(c), self.q.floor)

    def dist(self, a, b):
        return _angle(a - b) if self.q.form == "direction" else np.abs(a - b)

    def predict(self, p, c):
        """What the grader says to the answer ``p`` if the key were each of ``c``: (label, numbers)."""
        c = np.asarray(c)
        s = self.slack(c)
        d = self.dist(p, c)
        label = np.full(c.shape, PLAIN, dtype=np.int64)
        best = np.full(c.shape, np.inf)
        for i, t in enumerate(self.slips):
            undone = self.dist(t.undo(p), c)
            fits = np.flatnonzero(undone <= s)
            # A slip that leaves the key where it is cannot be told from it: the grader does not try it.
            fits = fits[self.dist(t.make(c[fits]), c[fits]) > s[fits]]
            ratio = undone[fits] / s[fits]
            nearer = ratio < best[fits]
            label[fits[nearer]] = SLIP + i
            best[fits[nearer]] = ratio[nearer]
        undecided = label == PLAIN
        if self.q.form == "vector":
            size_right = np.abs(np.abs(p) - np.abs(c)) <= s
            label = np.where(undecided & size_right, SIZE_RIGHT, label)
            undecided &= ~size_right
        near = d <= (CLOSE if self.distance else CLOSE_PARTS) * s
        label = np.where(undecided & near, NEAR, label)
        undecided &= ~near
        label = np.where(undecided, PLAIN + (0 if self.distance else self.parts(p, c, s)), label)
        label = np.where(d <= s, CORRECT, label)
        return label, self.distance_numbers(p, c)

    def parts(self, p, c, s):
        """The code of "which part is wrong" (graphkin.exercises.grading._parts)."""
        form = self.q.form
        sign = direction = negative = np.zeros(c.shape, dtype=np.int64)
        if form == "scalar" and p != 0:
            sign = np.where(np.abs(c) > s, np.where((p > 0) == (c > 0), 1, 2), 0)
        if form == "vector":
            right = (p != 0) & (np.abs(np.angle(p / c)) <= np.arctan(s / np.abs(c)))
            direction = np.where(right, 1, 2)
        if form == "magnitude" and p < 0:
            negative = np.ones(c.shape, dtype=np.int64)
        decade = np.zeros(c.shape, dtype=np.int64)
        if form in ("scalar", "magnitude", "vector") and p != 0:
            f = self.q.factor
            diff = math.floor(math.log10(abs(p) / f)) - np.floor(np.log10(np.abs(c) / f))
            decade = np.where(diff >= 2, 1, np.where(diff <= -2, 2, 0))
        return ((sign * 3 + direction) * 3 + decade) * 2 + negative

    def distance_numbers(self, p, c):
        """The numbers "how far off" would print (feedback = "distance"), unrounded."""
        form = self.q.form
        if form in ("scalar", "magnitude"):
            return (100 * (p - c) / np.abs(c),)
        if form == "vector":
            return (100 * (abs(p) - np.abs(c)) / np.abs(c), np.degrees(np.abs(np.angle(p / c))))
        return (np.degrees(_angle(p - c)),)

    # --- reading the feedback ------------------------------------------------------------------------------

    def read(self, text: str) -> Seen:
        """The label and the numbers of a feedback text; a text it cannot place fails the test."""
        text = text.replace("−", "-")
        main = text.split(" It fits ")[0]
        numbers = tuple(float(x) for x in re.findall(r"yours is ([+-]?\d+\.\d) % off", main))
        m = re.search(r"the size is ([+-]?\d+\.\d) % off, the direction (\d+\.\d)° off", main)
        if m:
            numbers = (float(m[1]), float(m[2]))
        numbers += tuple(float(x) for x in re.findall(r"yours is (\d+\.\d)° off", main))
        if re.search(r"(?:^|— )Correct\.", main):
            return Seen(CORRECT)
        for i, t in enumerate(self.slips):
            if re.search(t.phrase, main):
                return Seen(SLIP + i)
        m = re.search(r"The size is right but the direction is (not|(\d+\.\d)° off)", main)
        if m:
            return Seen(SIZE_RIGHT, (float(m[2]),) if m[2] else ())
        if any(phrase in main for phrase in OPAQUE_PHRASES):
            return Seen(OPAQUE)
        if "Close, but not within" in main:
            return Seen(NEAR, numbers)
        if "Not within" in main:
            sign = 1 if re.search(r"the (sign|sense \(CCW or CW\)) is right", main) else \
                2 if re.search(r"the (sign|sense \(CCW or CW\)) is wrong", main) else 0
            direction = 1 if "the direction is right" in main else 2 if "the direction is wrong" in main else 0
            decade = 1 if "ten times too large" in main else 2 if "ten times too small" in main else 0
            negative = 1 if "a magnitude is never negative" in main else 0
            return Seen(PLAIN + ((sign * 3 + direction) * 3 + decade) * 2 + negative, numbers)
        raise AssertionError(f"the adversary cannot read this feedback: {text!r}")

    def consistent(self, p, c, seen: Seen, step: float):
        """Which of the keys ``c`` would have given what was seen (``step``: the grid's spacing, in the units of the
        numbers printed, which the rounding of a printed number is widened by)."""
        if seen.label == OPAQUE:
            return self.dist(p, c) > self.slack(c)
        label, numbers = self.predict(p, c)
        ok = label == seen.label
        if seen.label == SIZE_RIGHT and seen.numbers:
            ok &= np.abs(numbers[1] - seen.numbers[0]) <= 0.05 + step
        elif seen.numbers:
            for x, printed in zip(numbers, seen.numbers):
                ok &= np.abs(x - printed) <= 0.05 + step
        return ok

    def inverted(self, p, seen: Seen) -> np.ndarray:
        """The keys "how far off" leaves, computed from its numbers (empty when it printed none)."""
        form, n = self.q.form, seen.numbers
        if not n:
            return np.empty(0, dtype=self.candidates.dtype)
        if form in ("scalar", "magnitude"):
            # p − c = x |c| / 100: c = p / (1 + x/100) if c > 0, p / (1 − x/100) if c < 0.
            return np.array([p / (1 + n[0] / 100), p / (1 - n[0] / 100)])
        if form == "vector":
            if seen.label == SIZE_RIGHT:
                size, turn = abs(p), n[0]
            else:
                size, turn = abs(p) / (1 + n[0] / 100), n[1]
            return np.array([size * cmath.exp(1j * (cmath.phase(p) + s * math.radians(turn))) for s in (1, -1)])
        return np.array([p + math.radians(n[0]), p - math.radians(n[0])])

    # --- choosing the next submission ----------------------------------------------------------------------

    def choose(self):
        if len(self.extra):  # the keys "how far off" leaves: exact, so tried first
            return self.extra[0]
        c = self.candidates
        pick = self.rng.choice(len(c), size=min(self.sample, len(c)), replace=False)
        sample = c[pick]
        options = list(sample[:: max(1, len(sample) // self.options)][: self.options])
        best, score = None, math.inf
        for p in options:
            label, numbers = self.predict(p, sample)
            key = label.astype(float)
            for x in numbers:
                key = key * 1e4 + np.round(x, 1)
            _, counts = np.unique(key, return_counts=True)
            s = float(np.sum(counts.astype(float) ** 2))
            if s < score:
                best, score = p, s
        return best

    # --- the attack ----------------------------------------------------------------------------------------

    def attack(self, submit, key, step: float, limit: int) -> int | None:
        """Submit until graded correct; the number of submissions, or None after ``limit``.

        ``submit(text) -> feedback text``; ``key`` is the true key (SI), for the harness's soundness check only.
        """
        self.extra = np.empty(0, dtype=self.candidates.dtype)
        for n in range(1, limit + 1):
            text, p = self.typed(self.choose())
            seen = self.read(submit(text))
            if seen.label == CORRECT:
                return n
            self.distance |= bool(seen.numbers)  # a text that says how far off is "distance" feedback
            assert self.consistent(p, np.array([key]), seen, step)[0], (text, seen)
            self.history.append((p, seen))
            self.candidates = self.candidates[self.consistent(p, self.candidates, seen, step)]
            inv = self.inverted(p, seen)
            self.extra = np.concatenate([self.extra, inv])
            self.extra = self.extra[self.consistent(p, self.extra, seen, 0.0)] if len(self.extra) else self.extra
            while len(self.candidates) == 0 and self.fineness < 4:
                # The keys left lie between the grid's points: a finer grid, read against all that was seen.
                self.fineness *= 2
                self.candidates = self.grid(self.fineness)
                for probe, was in self.history:
                    self.candidates = self.candidates[self.consistent(probe, self.candidates, was, step)]
            assert len(self.candidates) or len(self.extra), "every key ruled out"
            if len(self.candidates) == 0:
                self.candidates = self.extra
        return None

    def typed(self, p):
        """The answer ``p`` as typed, and the value typed (rounded as the text is)."""
        u = f" {self.q.unit}" if self.q.unit else ""
        if self.q.form == "vector":
            size, angle = f"{abs(p) / self.q.factor:.6g}", f"{math.degrees(cmath.phase(p)):.4f}"
            return f"{size}{u} ∠ {angle}°", float(size) * self.q.factor * cmath.exp(1j * math.radians(float(angle)))
        if self.q.form == "direction":
            angle = f"{math.degrees(math.remainder(float(p), 2 * math.pi)):.4f}"
            return f"{angle}°", math.radians(float(angle))
        number = f"{float(p) / self.q.factor:.6g}"
        return f"{number}{u}", float(number) * self.q.factor


def prior(q: Question, key, rng: np.random.Generator):
    """The keys the adversary starts from, as ``grid(fineness)``, and the grid's spacing in the units of the
    printed numbers (which widen a printed number's rounding).

    A decade of sizes around the key, placed at random (both signs for a signed value); any direction.
    """
    if q.form == "direction":
        return (lambda k: np.radians(np.arange(-180, 180, 0.05 / k))), 0.05
    size = abs(key)
    u = rng.uniform(0.05, 0.95)
    if q.form == "vector":
        def vectors(k):
            sizes = size * 10 ** np.arange(-u, 1 - u, 0.004 / k)
            angles = np.radians(np.arange(-180, 180, 0.5 / k))
            return (sizes[:, None] * np.exp(1j * angles)[None, :]).ravel()
        return vectors, 0.5 + 0.95

    def scalars(k):
        sizes = size * 10 ** np.arange(-u, 1 - u, 0.0004 / k)
        return np.concatenate([sizes, -sizes]) if q.form == "scalar" else sizes
    return scalars, 0.1
