"""The polygons or the instant centres of the strip cutter, as instructions: a count that no neighbour's load moves.

For ``bench_guard.py``'s question (issue 35, "Keep") on a machine too busy for CPU time to settle: run under
valgrind's callgrind, once with 0 repetitions and once with 3, for each checkout; the difference over
3 × 180 positions is the instructions a position costs::

    PYTHONPATH=/tmp/base valgrind --tool=callgrind --callgrind-out-file=/dev/null \\
        .venv/bin/python benchmarks/guard_instructions.py 3 polygons   # or: 0 polygons, 3 centres

(about two minutes a run; a third argument names another catalog problem, e.g. ``3 centres gearset``). Both
are made once for every position before the repetitions, so that the
counts leave out the imports, the problem and its kinematics, and every cache filled on first use.
"""

from __future__ import annotations

import sys

from graphkin import catalog
from graphkin.graphical import construct_kinematics, instant_centres

repetitions, what = int(sys.argv[1]), sys.argv[2]
kin = catalog.load(sys.argv[3] if len(sys.argv) > 3 else "strip_cutter").kinematics()
for i in range(kin.n):
    construct_kinematics(kin, i), instant_centres(kin, i)
make = {"polygons": construct_kinematics, "centres": instant_centres}[what]
for _ in range(repetitions):
    for i in range(kin.n):
        make(kin, i)
