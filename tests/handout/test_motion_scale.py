"""The velocity and acceleration polygons of a handout print at the scales their caption states (issue 26).

Each arrow of the polygons' figure is measured in the PDF (``pdfgeometry``), tail to the point of its ink;
times the stated velocity scale it must be the size of a vector of the velocity polygon, or times the stated
acceleration scale one of the acceleration polygon, to 1 %. The crank pin's velocity, ω2 × O2B from the
analytical kinematics, must be among them at the velocity scale.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

pypdf = pytest.importorskip("pypdf")

from graphkin import catalog, handout  # noqa: E402
from graphkin.draw import style  # noqa: E402
from graphkin.graphical import construct_kinematics  # noqa: E402
from tests.handout.pdfgeometry import arrows, figures  # noqa: E402

pytestmark = pytest.mark.slow

COLOURS = [tuple(int(c[k:k + 2], 16) / 255 for k in (1, 3, 5)) for c in (style.BLUE, style.VERMILLION)]
STATED = re.compile(r"velocity polygon \(1 mm = ([0-9.]+) m/s\) and the acceleration polygon \(1 mm = ([0-9.]+) m/s²\)")
CASES = {"fourbar_compact": dict(source="fourbar_dynamic_makdin"),
         "strip_cutter_full": dict(source="strip_cutter", at="140 deg", detail="full")}


@pytest.fixture(scope="module", params=list(CASES))
def printed(request, tmp_path_factory):
    kw = dict(CASES[request.param])
    name = kw.pop("source")
    doc = handout.build(name, **kw)
    path = tmp_path_factory.mktemp("motion") / f"{request.param}.pdf"
    handout.write(doc, path)
    problem = catalog.load(name)
    kin = problem.solve(np.array([doc["worked"][0]["q"]])).kinematics
    return {"path": path, "kin": kin, "i": 0, "problem": problem}


def _matches(value: float, wanted, rel: float = 0.01) -> bool:
    return any(abs(value - w) <= rel * w for w in wanted)


def test_the_motion_polygons_print_at_their_stated_scales(printed):
    kin, i = printed["kin"], printed["i"]
    mc = construct_kinematics(kin, i)
    speeds = [math.hypot(*v.vector) for v in mc.vectors("velocity") if math.hypot(*v.vector) > 0]
    accels = [math.hypot(*v.vector) for v in mc.vectors("acceleration") if math.hypot(*v.vector) > 0]
    stated = [(f, STATED.search(f.caption)) for f in figures(printed["path"])]
    stated = [(f, float(m[1]), float(m[2])) for f, m in stated if m]
    assert len(stated) == 1, "one figure states the polygons' two scales"
    fig, Xv, Xa = stated[0]
    lengths = arrows(fig, COLOURS)
    on_v = [mm for mm in lengths if _matches(mm * Xv, speeds)]
    on_a = [mm for mm in lengths if _matches(mm * Xa, accels)]
    wrong = [round(mm, 2) for mm in lengths if mm not in on_v and mm not in on_a]
    assert wrong == [], f"printed arrows [mm] that are no vector at either stated scale ({Xv} m/s, {Xa} m/s² per mm)"
    assert len(on_v) >= 3 and len(on_a) >= 4
    # The crank pin's velocity from the analytical solver, independent of the construction.
    d = printed["problem"].mechanism.driver
    pin = [j.point for j in printed["problem"].mechanism.joints_of(d.link)
           if printed["problem"].mechanism.frame not in j.links][0]
    v_pin = math.hypot(*kin.velocity(d.link, pin)[i])
    assert _matches(v_pin / Xv, on_v), f"v_{pin} = {v_pin:.4g} m/s is {v_pin / Xv:.2f} mm at {Xv} m/s per mm; none printed"
