"""The polygons or the instant centres of a catalog problem, as instructions: a count that no neighbour's load moves.

For ``bench_guard.py``'s question (issue 35, "Keep") on a machine too busy for CPU time to settle: run under
valgrind's callgrind, once with 0 repetitions and once with 3, for each checkout; the difference over
3 × 180 positions is the instructions a position costs::

    OPENBLAS_NUM_THREADS=1 PYTHONHASHSEED=0 PYTHONPATH=/tmp/base setarch -R \\
        valgrind --tool=callgrind --callgrind-out-file=/dev/null \\
        .venv/bin/python benchmarks/guard_instructions.py 3 polygons   # or: 0 polygons, 3 centres

(about two minutes a run; OpenBLAS's spinning threads would otherwise add a few million instructions that vary
from run to run; a third argument names another catalog problem, e.g. ``3 centres gearset``). Both
are made once for every position before the repetitions, so that the
counts leave out the imports, the problem and its kinematics, and every cache filled on first use.

A fourth argument ``cold`` times the first call instead: each repetition goes once over the positions of a new
kinematics (the problem's ``kinematics()`` again: the same mechanism, whose plan the solver keeps; :data:`COPIES`
are made before the repetitions in every run, so that the difference leaves them out), so that what is worked out
once per kinematics is counted too, as ``graphkin solve`` meets it (e.g. ``40 centres gearset cold`` against
``0 centres gearset cold``, divided by 40 × its positions).

One hash seed is one layout of the heap (which dict slots collide, which objects sit together), and a small call's
count moves by a few thousand instructions from one layout to another: compare the median over several seeds
(``PYTHONHASHSEED`` 0 to 5), each run as above, rather than one seed's count (benchmarks/README.md, "Met").
"""

from __future__ import annotations

import sys

from graphkin import catalog
from graphkin.graphical import construct_kinematics, instant_centres

COPIES = 400
"""New kinematics objects made in every ``cold`` run (the most repetitions it can count)."""

repetitions, what = int(sys.argv[1]), sys.argv[2]
problem = catalog.load(sys.argv[3] if len(sys.argv) > 3 else "strip_cutter")
kin = problem.kinematics()
cold = len(sys.argv) > 4 and sys.argv[4] == "cold"
for i in range(kin.n):
    construct_kinematics(kin, i), instant_centres(kin, i)
make = {"polygons": construct_kinematics, "centres": instant_centres}[what]
if cold:
    if repetitions > COPIES:
        sys.exit(f"guard_instructions: at most {COPIES} repetitions of a cold run")
    copies = [problem.kinematics() for _ in range(COPIES)]
    for one in copies[:repetitions]:
        for i in range(one.n):
            make(one, i)
else:
    for _ in range(repetitions):
        for i in range(kin.n):
            make(kin, i)
