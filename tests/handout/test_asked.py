"""Each catalog problem's key prints the answers its book asks for (issue 36, item 6), and a page that uses two
sign conventions for one torque says so.

What a book asks is the problem file's own ``asked`` (joint forces, the driving effort, the piston's net force F_P,
the crank pin's F_T, F_B and T, the flywheel's α, a tooth force's W_t and W_r, the holding torque of a gear of the
frame). Each value is worked out here from the solver's result on its own, not from the handout's code, and looked
for, to the printed digits, on a line that names it. Where the book's printed answer is known (:data:`BOOK`), that
value is checked too, within its last digit and the deviation of the book's own method that tests/books measures.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin import catalog, handout
from graphkin.handout import maths as M
from graphkin.handout.document import subject
from graphkin.model import GearMesh, Prismatic, Revolute
from tests.books import test_khurmi_double_acting as khurmi_15_12
from tests.books import test_khurmi_engines as khurmi_15
from tests.books import test_khurmi_static as khurmi_15_10
from tests.books import test_soylemez_double_slider as soylemez
from tests.books import test_wentzell_gears as wentzell

NOT_ASKED = {
    # Khurmi & Gupta ch. 22 asks for the unbalanced (shaking) force, which `graphkin balance` reports, not a key.
    "engine_balancing": "shaking force",
    # Hibbeler asks for the equilibrium angle θ: the file is written at it, and the key solves the forces there.
    "spring_link_hibbeler": "equilibrium angle",
}


def _lines(doc: dict) -> list[str]:
    """The key's text, a line per paragraph, list item, table row and displayed equation line."""
    def text(runs):
        return "".join(r if isinstance(r, str) else M.to_text(r) for r in runs)

    out = []
    for b in doc["blocks"]:
        if b["kind"] == "text":
            out.append(text(b["runs"]))
        elif b["kind"] == "list":
            out += [text(item) for item in b["items"]]
        elif b["kind"] == "table":
            out += [" ".join(text(c) for c in row) for row in b["rows"]]
        elif b["kind"] == "equation":
            out += [M.to_text(line) for line in b["lines"]]
    return out


def _crank_pin(s, i: int) -> dict:
    """F_T, F_B and T of the rod's force on the crank pin (Khurmi and Gupta §15.10), from the solver's force."""
    mech, kin = s.mech, s.result.kinematics
    d = mech.driver
    pivot = mech.joint_between(mech.frame, d.link)
    pin = next(j for j in mech.joints_of(d.link) if isinstance(j, Revolute) and mech.frame not in j.links)
    rod = (set(pin.links) - {d.link}).pop()
    O, P = kin.position(d.link, pivot.point)[i], kin.position(d.link, pin.point)[i]
    r = float(np.hypot(*(P - O)))
    u = (P - O) / r
    F = s.result.force(rod, d.link)[i]
    F_T = float(F @ np.array([-u[1], u[0]]))
    return {"F_B": float(-F @ u), "F_T": F_T, "T": r * F_T}


def _holding(s, i: int) -> float:
    """The torque that holds the frame's gear about its centre: minus the moment of the tooth force on it, taken at
    the pitch point (on the line of centres, the frame gear's pitch radius from its centre)."""
    mech, kin = s.mech, s.result.kinematics
    mesh = next(j for j in mech.joints if isinstance(j, GearMesh) and mech.frame in j.links)
    k = (set(mesh.links) - {mech.frame}).pop()
    O = kin.position(mech.frame, mesh.centers[mesh.links.index(mech.frame)])[i]
    C = kin.position(k, mesh.centers[mesh.links.index(k)])[i]
    X = O + mesh.radius(mech.frame) * (C - O) / np.hypot(*(C - O))
    F = s.result.force(k, mech.frame)[i]
    return -float((X - O)[0] * F[1] - (X - O)[1] * F[0])


def _piston(s, i: int) -> float:
    """The net force on the piston F_P (Khurmi and Gupta §15.10): the piston's force on the connecting rod along
    the line of stroke, positive towards the crank shaft."""
    mech, kin = s.mech, s.result.kinematics
    guide = next(j for j in mech.joints if isinstance(j, Prismatic) and j.guide == mech.frame)
    pin = next(j for j in mech.joints_of(guide.slider) if isinstance(j, Revolute))
    rod = (set(pin.links) - {guide.slider}).pop()
    u = kin.guide_direction(guide)[i]
    towards = kin.position(mech.driver.link, mech.joint_between(mech.frame, mech.driver.link).point)[i] - \
        kin.position(guide.slider, pin.point)[i]
    return float(s.result.force(guide.slider, rod)[i] @ (u if towards @ u > 0 else -u))


def _tooth(s, i: int) -> dict:
    """W_t and W_r: the sizes of the tooth force across and along the line of centres (Wentzell §12)."""
    mech, kin = s.mech, s.result.kinematics
    mesh = next(j for j in mech.joints if isinstance(j, GearMesh) and mech.frame not in j.links)
    a, b = mesh.links
    e = kin.position(b, mesh.centers[1])[i] - kin.position(a, mesh.centers[0])[i]
    e = e / np.hypot(*e)
    F = s.result.force(a, b)[i]
    return {"W_t": abs(float(F[0] * e[1] - F[1] * e[0])), "W_r": abs(float(F @ e))}


def _expected(s, name: str, i: int) -> tuple[str, float]:
    """The text that names ``name`` on a line, and its value."""
    if name in ("F_T", "F_B", "T"):
        return ({"F_T": "FT =", "F_B": "FB =", "T": "T = rFT"}[name], _crank_pin(s, i)[name])
    if name == "T_hold":
        return "Thold =", _holding(s, i)
    if name == "F_P":
        return "FP =", _piston(s, i)
    if name in ("W_t", "W_r"):
        return {"W_t": "Wt =", "W_r": "Wr ="}[name], _tooth(s, i)[name]
    if name == "alpha":
        return "α =", float(s.problem.forward.step(s.result.effort, s.result.kinematics.q_dot)["alpha"][i])
    if name == s.mech.driver.symbol:
        return name, float(s.result.effort[i])
    return name, math.hypot(*s.result[name][i])


@pytest.mark.parametrize("name", catalog.names())
def test_a_key_prints_every_answer_its_book_asks_for(name):
    s = subject(name)
    problem = s.problem
    if name in NOT_ASKED:
        assert not problem.asked, f"{name} lists what its book asks: take it out of NOT_ASKED"
        return
    assert problem.asked, f"{name}: say what its book asks for (asked = [...] in the problem file)"
    lines = _lines(handout.build(s))
    i = s.worked()[0]
    for asked in problem.asked:
        token, value = _expected(s, asked, i)
        printed = M.fmt(value)
        assert any(token in line and printed in line for line in lines), (name, asked, token, printed)


LBF = wentzell.LBF


def _from_the_method(book, exact, printed, half_unit):
    """How far a printed answer may lie from graphkin's: half a unit of its last digit, the distance of the book's
    own chain (its series for the piston's acceleration, its rounded constants) from the exact one, and the
    distance of the printed digit from the book's chain (its rounded intermediates), each as tests/books
    measures it."""
    return lambda: abs(printed - book()) + abs(book() - exact()) + half_unit


def _khurmi_15_11(key):
    chain = khurmi_15.book_method
    return (lambda: chain(**khurmi_15.DATA_1511, F_L=khurmi_15.F_L_1511)[key],
            lambda: chain(**khurmi_15.DATA_1511, F_L=khurmi_15.F_L_1511, exact=True)[key])


BOOK = {
    # Söylemez §6.4, the double slider: it rounds its intermediate values (h = 33.31 mm, θ3 = 113.578°) and prints
    # four digits, 0.2 % as tests/books/test_soylemez_double_slider.py checks each of them.
    "double_slider": {name: (printed, 1.0, lambda printed=printed: soylemez.REL * printed) for name, printed in
                      (("F12", 7.555), ("F23", 27.04), ("F34", 7.555), ("G14", 7.555), ("G12", 25.97))},
    # Khurmi & Gupta Ex. 15.10: F_B = 22.9 kN and T = 5.06 kN·m, within half their last digit (its F_N = "3 kN" is
    # a slip of the companion's, tests/books/test_khurmi_static.py).
    "engine_static_khurmi": {key: (value, 1.0, lambda half=half: half)
                             for key, (value, half) in khurmi_15_10.PRINTED.items()},
    # Khurmi & Gupta Ex. 15.11: F_P = 2255.6 N, the series with F_I rounded to the newton (the printed value's
    # distance from the chain).
    "petrol_vertical_khurmi": {"F_P": (2255.6, 1.0, _from_the_method(*_khurmi_15_11("F_P"), 2255.6, 0.05))},
    # Wentzell Ex. 12.1 in lb: its 63000 for 63 025 lb·in per hp and rpm.
    "spur_pair_wentzell": {key: (wentzell.PRINTED[w], LBF, _from_the_method(
        lambda w=w: wentzell.method(63000.0)[w], lambda w=w: wentzell.method(wentzell.EXACT)[w], wentzell.PRINTED[w],
        wentzell.HALF_UNIT[w])) for key, w in (("W_t", "W_t"), ("W_r", "W_r"), ("F23", "W"))},
    # Khurmi & Gupta Ex. 15.12, in the sense of rotation: the book's 3920 N·m lies below its own chain, and its
    # 107.8 rad/s² follows from the 3920.
    "engine_double_acting_khurmi": {key: (khurmi_15_12.BOOK[key], 1.0, _from_the_method(
        lambda key=key: khurmi_15_12.series()[key], lambda key=key: khurmi_15_12.exact()[key], khurmi_15_12.BOOK[key],
        half)) for key, half in (("T", 5.0), ("F_B", 5.0), ("alpha", 0.05))},
}
"""Per problem, the book's printed answers: name as ``asked`` gives it -> (printed value, SI per printed unit, how
far graphkin's may lie from it [printed unit])."""


@pytest.mark.parametrize("name", sorted(BOOK))
def test_a_key_prints_the_book_s_own_values(name):
    """Each answer of :data:`BOOK` is on the key (the test above) and within the book's rounding of the value
    printed in the book, the book taken in its own sense (a size, or a torque and α in the sense of rotation)."""
    s = subject(name)
    i = s.worked()[0]
    lines = _lines(handout.build(s))
    assert set(BOOK[name]) <= set(s.problem.asked)
    for asked, (printed, si, allowed) in BOOK[name].items():
        token, value = _expected(s, asked, i)
        assert any(token in line and M.fmt(value) in line for line in lines), (name, asked)
        assert abs(abs(value) / si - printed) <= allowed(), (name, asked, abs(value) / si, printed, allowed())


def test_the_double_acting_key_says_which_way_its_alpha_turns():
    """Its α (CCW positive) is negative, the crank turning clockwise: the page gives the book's reading too."""
    s = subject("engine_double_acting_khurmi")
    lines = _lines(handout.build(s))
    alpha = _expected(s, "alpha", s.worked()[0])[1]
    assert alpha < 0 and s.result.kinematics.q_dot[0] < 0
    said = [line for line in lines if "in the sense of rotation prints" in line]
    assert said and M.fmt(-alpha) in said[0] and "speeds up" in said[0]


def test_the_epicyclic_key_prints_the_book_s_holding_torque():
    """Khurmi & Gupta Ex. 13.20: "torque necessary to keep the internal gear stationary = 400 N-m"."""
    lines = _lines(handout.build("epicyclic_khurmi"))
    assert any("Thold =" in line and "= 400 N·m" in line for line in lines)
    # A gear arm is not a crank with a connecting rod: no section of the crank pin's forces.
    assert not any("FT =" in line for line in lines)


def test_the_turning_moment_and_the_driving_torque_are_told_apart():
    """The crank pin's T (the rod's turning moment on the crank) and T12 (what holds the crank) have opposite
    signs: the page says so, with both numbers, where it prints them."""
    s = subject("engine_static_khurmi")
    i = s.worked()[0]
    lines = _lines(handout.build(s))
    T, T12 = _crank_pin(s, i)["T"], float(s.result.effort[i])
    assert T * T12 < 0
    said = [line for line in lines if "turning moment the connecting rod exerts" in line]
    assert said and M.fmt(T12) in said[0] and "opposite sign" in said[0]


def test_asked_names_only_what_a_handout_prints(tmp_path):
    from graphkin.errors import ProblemFileError

    text = catalog.path("single_link").read_text(encoding="utf-8")
    path = tmp_path / "single.toml"
    path.write_text(text.replace('asked = ["F12", "T12"]', 'asked = ["F12", "F99"]'), encoding="utf-8")
    with pytest.raises(ProblemFileError, match=r"asked\[1\].*'F99'"):
        catalog.load(str(path))
    path.write_text(text.replace('asked = ["F12", "T12"]', 'asked = ["F12", "alpha"]'), encoding="utf-8")
    with pytest.raises(ProblemFileError, match=r"asked\[1\].*needs \[forward\]"):
        catalog.load(str(path))
