"""A long fuzz of the grader: 10⁶ answers, random text and JSON, code-injection strings included.

Run directly: ``.venv/bin/python benchmarks/fuzz_grader.py [examples] [seed]`` (``make bench`` runs it).

The test suite fuzzes 10⁴ answers with hypothesis; this runs far more, with a
plain seeded generator (fast enough for 10⁶ in about a minute): strings made of
the pieces answers are made of (digits, signs, units, ∠, brackets, sense
words, unicode look-alikes), arbitrary unicode, JSON values of every type and
a list of injection strings. Every answer is graded against every question
of three exercises (a force vector, a torque with its sense, a length, a
point, an energy). The grader must return a verdict every time, never raise,
never give more than full marks; a file the injections try to create must
not appear. It prints a table of verdicts and the time per answer.
"""

from __future__ import annotations

import collections
import json
import os
import random
import sys
import time

from graphkin import exercises

PIECES = ["0", "1", "2", "7", "9", ".", "-", "+", "−", "e", "E", "3", " ", "  ", "N", "kN", "mN", "N*m", "N·m",
          "N m", "Nm", "N*mm", "J", "kJ", "kg*m^2", "kg·m²", "m", "mm", "deg", "°", "rad", "rpm", "∠", "at", "@",
          "(", ")", "[", "]", ",", ";", "CW", "CCW", "clockwise", "^", "**", "²", "×", "10", "nan", "inf", "%",
          "/", "s", "\t", "\n", "é", "\u00a0", "\u202e", "١", "½", "'", '"', "\\", "{", "}", "$", "#", "\x00"]
INJECTIONS = ["__import__('os').system('touch /tmp/graphkin_fuzz_pwned')", "eval('1+1')", "exec('x=1')",
              "{{7*7}}", "${7*7}", "1; import os", "().__class__.__bases__[0].__subclasses__()", "lambda: 0",
              "open('/etc/passwd').read()", "1e999 N", "9**9**9", "1 m^2^3", "10**10**10 N", "'; DROP TABLE x; --",
              "1 N" * 400, "(" * 1000, "1" * 5000 + " N", "\x00" * 50]
TARGETS = [("double_slider_forces", "F23"), ("double_slider_forces", "h3"), ("strip_cutter_cut", "T12"),
           ("inertia_resultant", "line3"), ("inertia_resultant", "T3i"), ("flywheel", "E")]


def answer(rng: random.Random):
    kind = rng.random()
    if kind < 0.55:
        return "".join(rng.choice(PIECES) for _ in range(rng.randint(0, 12)))
    if kind < 0.75:
        return "".join(chr(rng.randint(0, 0x2FFF)) for _ in range(rng.randint(0, 20)))
    if kind < 0.80:
        return rng.choice(INJECTIONS)
    if kind < 0.90:
        # A number near a plausible answer, with or without a unit.
        x = rng.choice([1, -1]) * 10 ** rng.uniform(-6, 6)
        return f"{x:.{rng.randint(1, 8)}g}" + rng.choice(["", " N", " N*m", " mm", " J", " deg", " N·m CW"])
    return json.loads(json.dumps(rng.choice([None, True, 1, 1.5, [], {}, [1, 2], {"a": 1}, "x", -0.0, 10**30])))


def main(n: int = 1_000_000, seed: int = 2026) -> int:
    rng = random.Random(seed)
    variants = {name: exercises.variant(name, "fuzz") for name, _ in TARGETS}
    verdicts = collections.Counter()
    start = time.perf_counter()
    for i in range(n):
        name, qid = TARGETS[i % len(TARGETS)]
        text = answer(rng)
        report = variants[name].grade({qid: text})
        (q,) = [q for q in report["questions"] if q["id"] == qid]
        assert 0 <= report["score"] <= report["max"], (text, report)
        assert q["verdict"] in ("correct", "slip", "wrong", "unreadable", "missing") and q["feedback"], (text, q)
        verdicts[q["verdict"]] += 1
    elapsed = time.perf_counter() - start
    assert not os.path.exists("/tmp/graphkin_fuzz_pwned"), "an injection ran"
    print(f"{n} answers graded in {elapsed:.1f} s ({elapsed / n * 1e6:.0f} µs each), seed {seed}; none raised\n")
    print(f"{'verdict':<12}{'count':>10}")
    for verdict, count in verdicts.most_common():
        print(f"{verdict:<12}{count:>10}")
    return 0


if __name__ == "__main__":
    sys.exit(main(*(int(a) for a in sys.argv[1:])))
