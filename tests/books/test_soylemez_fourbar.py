"""Self-checks of the textbook oracle ``tests/books/soylemez_fourbar_solver.py``.

The oracle transcribes Söylemez §6.4.1 (with typos corrected, see its module
docstring).  Here it is checked three independent ways:

1. kinematics against central finite differences of the position solution;
2. forces against (a) the nine equilibrium equations (1)-(9) as printed (with
   the f4 -> f3 correction in (6)), and (b) an independent d'Alembert
   equilibrium of every link built from point coordinates, with vector sums
   of forces and moments about each link's centre of gravity;
3. a power balance: input + external power = rate of change of kinetic energy.

Plus the strip-cutter example of the seed and tests showing that each
printed typo really is wrong (the printed variant fails a check).
Nothing from graphkin is imported.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from tests.books.soylemez_fourbar_solver import RESULT_KEYS, soylemez_fourbar

RTOL = 1e-9  # equilibrium / power balance / closed-form identities
# Finite differences: five-point central stencils in time, with the step
# expressed as a crank-angle increment δ = 1e-3 (h = δ / max(|ω12|, √|α12|)).
#   truncation: δ⁴/30·|q⁽⁵⁾| (1st) and δ⁴/90·|q⁽⁶⁾| (2nd)  ~ 1e-14 × the
#               magnification of higher derivatives near poor transmission
#               angles (bounded: the generated linkages keep a margin from
#               the dead positions);
#   round-off:  ≈ 1.5·ε|q|/δ ≈ 1e-12 (1st), ≈ 5·ε|q|/δ² ≈ 5e-9 (2nd),
#               with |q| ~ 4 rad or ~ one link length.
# FD_RTOL = 1e-6 is ~170× the largest error seen in 10000 random linkages
# (≈ 6e-9, round-off dominated) and far below the O(1) relative errors the
# typos cause.
FD_STEP = 1e-3
FD_RTOL = 1e-6

I = 1j  # imaginary unit: planar vectors are complex numbers x + iy


# --------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------
def wrap(x):
    """Angle difference mapped to (-π, π]."""
    return np.angle(np.exp(1j * x))


def points(theta12, theta13, theta14, p):
    """Complex coordinates of all points of interest (not using book algebra)."""
    A0 = np.zeros_like(theta12, dtype=complex)
    B0 = p["a1"] + 0j
    A = A0 + p["a2"] * np.exp(I * theta12)
    B = A + p["a3"] * np.exp(I * theta13)          # via the coupler
    B_rocker = B0 + p["a4"] * np.exp(I * theta14)  # via the rocker
    G2 = A0 + p["g2"] * np.exp(I * (theta12 + p["beta2"]))
    G3 = A + p["g3"] * np.exp(I * (theta13 + p["beta3"]))
    G4 = B0 + p["g4"] * np.exp(I * (theta14 + p["beta4"]))
    P3 = A + p["f3"] * np.exp(I * (theta13 + p["gamma3"]))
    P4 = B0 + p["f4"] * np.exp(I * (theta14 + p["gamma4"]))
    return dict(A0=A0, B0=B0, A=A, B=B, B_rocker=B_rocker,
                G2=G2, G3=G3, G4=G4, P3=P3, P4=P4)


def cross(r, F):
    """z-component of r × F for complex 2-vectors."""
    return (np.conj(r) * F).imag


def dot(u, v):
    return (np.conj(u) * v).real


def vec(x, y):
    return x + I * y


def _stack(terms):
    shape = np.broadcast_shapes(*(np.shape(t) for t in terms))
    return [np.broadcast_to(t, shape) for t in terms]


def load_scale(*equations):
    """max over the crank cycle of Σ|term| over all terms of all equations."""
    return np.max(sum(np.abs(t) for terms in equations for t in _stack(terms)))


def sum_is_zero(terms, rtol=RTOL, scale=None):
    """Σ terms == 0 to rtol × scale (default: load_scale(terms)).

    The scale is a maximum over the crank cycle, not pointwise: pointwise
    Σ|terms| would be too strict where every term happens to be ~0 (e.g.
    sin(π − θ12) evaluates to 1.2e-16, not 0, at θ12 = 0).
    """
    if scale is None:
        scale = load_scale(terms)
    return np.all(np.abs(sum(_stack(terms))) <= rtol * scale)


def all_sums_are_zero(equations, rtol=RTOL):
    """Names of the equations in {name: terms} that do not sum to zero.

    All equations of the group share one scale, the load level of the whole
    group.  This matters because the joint forces come from one coupled
    solve: when link 3 carries loads 1e5× larger than link 4, F34 is a small
    difference of large numbers and is known only to ≈ ε × (link-3 loads),
    so link 4's balance can be checked only relative to the system's loads.
    """
    scale = load_scale(*equations.values())
    return [name for name, terms in equations.items()
            if not sum_is_zero(terms, rtol, scale)]


def solve(theta12, omega12, alpha12, p):
    return soylemez_fourbar(theta12, omega12, alpha12, **p)


def kinematic_state(theta12, omega12, alpha12, p, R):
    """Points, velocities and accelerations by rigid-body vector kinematics."""
    P = points(theta12, R["theta13"], R["theta14"], p)
    w2, w3, w4 = omega12, R["omega13"], R["omega14"]
    al2, al3, al4 = alpha12, R["alpha13"], R["alpha14"]
    vA = I * w2 * (P["A"] - P["A0"])
    aA = (I * al2 - w2**2) * (P["A"] - P["A0"])
    v = dict(
        G2=I * w2 * (P["G2"] - P["A0"]),
        G3=vA + I * w3 * (P["G3"] - P["A"]),
        G4=I * w4 * (P["G4"] - P["B0"]),
        P3=vA + I * w3 * (P["P3"] - P["A"]),
        P4=I * w4 * (P["P4"] - P["B0"]),
    )
    a = dict(
        G2=(I * al2 - w2**2) * (P["G2"] - P["A0"]),
        G3=aA + (I * al3 - w3**2) * (P["G3"] - P["A"]),
        G4=(I * al4 - w4**2) * (P["G4"] - P["B0"]),
    )
    return P, v, a


# --------------------------------------------------------------------------
# hypothesis strategy: random Grashof crank-rockers
# --------------------------------------------------------------------------
angles = st.floats(-np.pi, np.pi)


def up_to(hi):
    """0, or a value in [hi/1000, hi] (no subnormal lengths or loads)."""
    return st.one_of(st.just(0.0), st.floats(hi / 1000, hi))


@st.composite
def crank_rockers(draw):
    a1 = draw(st.floats(1.0, 3.0))
    a3 = draw(st.floats(1.0, 3.0))
    a4 = draw(st.floats(1.0, 3.0))
    # r = |B0A| ranges over [a1 - a2, a1 + a2]; the loop closes for every θ12
    # iff |a3 - a4| < a1 - a2 and a1 + a2 < a3 + a4 (crank-rocker, a2 cranks).
    gap = min(a1 - abs(a3 - a4), a3 + a4 - a1)
    assume(gap > 0.3)
    a2 = draw(st.floats(0.1, 0.7)) * gap   # keeps a margin from dead points
    p = dict(a1=a1, a2=a2, a3=a3, a4=a4, sigma=draw(st.sampled_from([1, -1])))
    for i, L in ((2, a2), (3, a3), (4, a4)):
        m = draw(st.floats(0.1, 10.0))
        k = draw(st.floats(0.05, 2.0))
        p[f"m{i}"] = m
        p[f"I{i}"] = m * k**2
        p[f"g{i}"] = draw(up_to(1.5)) * L
        p[f"beta{i}"] = draw(angles)
    for i, L in ((3, a3), (4, a4)):
        p[f"F1{i}"] = draw(up_to(100.0)) * draw(st.sampled_from([1, -1]))
        p[f"phi{i}"] = draw(angles)
        p[f"f{i}"] = draw(up_to(2.0)) * L
        p[f"gamma{i}"] = draw(angles)
    omega12 = draw(st.floats(0.5, 200.0)) * draw(st.sampled_from([1, -1]))
    alpha12 = draw(up_to(1e4)) * draw(st.sampled_from([1, -1]))
    theta12 = draw(st.floats(0, 2 * np.pi)) + np.linspace(0, 2 * np.pi, 72, endpoint=False)
    return theta12, omega12, alpha12, p


SETTINGS = settings(max_examples=200, deadline=None)


# --------------------------------------------------------------------------
# 0. positions close the loop
# --------------------------------------------------------------------------
@SETTINGS
@given(crank_rockers())
def test_position_solution_closes_loop(case):
    theta12, omega12, alpha12, p = case
    R = solve(theta12, omega12, alpha12, p)
    assert set(R) == set(RESULT_KEYS)
    P = points(theta12, R["theta13"], R["theta14"], p)
    L = max(p["a1"], p["a2"], p["a3"], p["a4"])
    np.testing.assert_allclose(np.abs(P["B"] - P["B_rocker"]), 0, atol=RTOL * L)


# --------------------------------------------------------------------------
# 1. kinematics vs central finite differences in time
# --------------------------------------------------------------------------
def positions_at(theta12, p):
    R = soylemez_fourbar(theta12, 0.0, 0.0, **p)
    P = points(theta12, R["theta13"], R["theta14"], p)
    return R["theta13"], R["theta14"], P["G2"], P["G3"], P["G4"]


def time_derivatives(theta12, omega12, alpha12, p):
    """d/dt and d²/dt² of (θ13, θ14, G2, G3, G4) by five-point central
    differences, the crank moving as θ12(t) = θ12 + ω12 t + α12 t²/2."""
    s = max(abs(omega12), np.sqrt(abs(alpha12)))  # crank-angle rate scale, 1/s
    h = FD_STEP / s
    samples = [positions_at(theta12 + omega12 * t + alpha12 * t**2 / 2, p)
               for t in (-2 * h, -h, 0.0, h, 2 * h)]
    first, second = [], []
    for k in range(5):
        q0 = samples[2][k]
        # increments from t = 0; angles wrapped to (-π, π] against 2π jumps
        d = [(wrap(q[k] - q0) if k < 2 else q[k] - q0) for q in samples]
        first.append((d[0] - 8 * d[1] + 8 * d[3] - d[4]) / (12 * h))
        second.append((-d[0] + 16 * d[1] + 16 * d[3] - d[4]) / (12 * h**2))
    return first, second, s


@SETTINGS
@given(crank_rockers())
def test_kinematics_match_finite_differences(case):
    theta12, omega12, alpha12, p = case
    R = solve(theta12, omega12, alpha12, p)
    first, second, s = time_derivatives(theta12, omega12, alpha12, p)

    for k, name in ((0, "13"), (1, "14")):
        np.testing.assert_allclose(first[k], R["omega" + name], rtol=FD_RTOL,
                                   atol=FD_RTOL * s, err_msg="omega" + name)
        np.testing.assert_allclose(second[k], R["alpha" + name], rtol=FD_RTOL,
                                   atol=FD_RTOL * s**2, err_msg="alpha" + name)
    L = max(p["a1"], p["a2"], p["a3"], p["a4"], p["g2"], p["g3"], p["g4"])
    for k, i in ((2, 2), (3, 3), (4, 4)):
        aG = vec(R[f"aG{i}x"], R[f"aG{i}y"])
        np.testing.assert_allclose(np.abs(second[k] - aG), 0,
                                   atol=FD_RTOL * (s**2 * L + np.abs(aG)).max(),
                                   err_msg=f"aG{i}")


@SETTINGS
@given(crank_rockers())
def test_cg_accelerations_match_rigid_body_kinematics(case):
    """Book's aG formulas == a_J + (iα − ω²)(G − J), built from points."""
    theta12, omega12, alpha12, p = case
    R = solve(theta12, omega12, alpha12, p)
    _, _, a = kinematic_state(theta12, omega12, alpha12, p, R)
    for i, J in ((2, 0.0), (3, p["a2"]), (4, 0.0)):
        book = vec(R[f"aG{i}x"], R[f"aG{i}y"])
        # |a_G| ≤ (ω² + |α|)·distance, maximised over the cycle
        w = np.abs(R[f"omega1{i}"] if i > 2 else omega12)
        al = np.abs(R[f"alpha1{i}"] if i > 2 else alpha12)
        scale = np.max(omega12**2 * J + np.abs(alpha12) * J + (w**2 + al) * p[f"g{i}"])
        np.testing.assert_allclose(np.abs(book - a[f"G{i}"]), 0, atol=RTOL * scale)


# --------------------------------------------------------------------------
# 2a. the nine equations (1)-(9) as printed (with (6): f4 -> f3)
# --------------------------------------------------------------------------
def printed_equations(theta12, omega12, alpha12, p, R, *, f_in_eq6=None):
    """Terms of equations (1)-(9), each a list whose sum must vanish."""
    sin, cos, pi = np.sin, np.cos, np.pi
    th12, th13, th14 = theta12, R["theta13"], R["theta14"]
    a2, a3, a4 = p["a2"], p["a3"], p["a4"]
    m2, m3, m4, I2, I3, I4 = (p[k] for k in ("m2", "m3", "m4", "I2", "I3", "I4"))
    g2, g3, g4, b2, b3, b4 = (p[k] for k in ("g2", "g3", "g4", "beta2", "beta3", "beta4"))
    F13, phi3, f3, gam3 = p["F13"], p["phi3"], p["f3"], p["gamma3"]
    F14, phi4, f4, gam4 = p["F14"], p["phi4"], p["f4"], p["gamma4"]
    al12, al13, al14 = alpha12, R["alpha13"], R["alpha14"]
    aG2x, aG2y, aG3x, aG3y, aG4x, aG4y = (R[k] for k in
                                          ("aG2x", "aG2y", "aG3x", "aG3y", "aG4x", "aG4y"))
    G14x, G14y, F34x, F34y = R["G14x"], R["G14y"], R["F34x"], R["F34y"]
    F23x, F23y, G12x, G12y, T12 = R["F23x"], R["F23y"], R["G12x"], R["G12y"], R["T12"]
    f_6 = f3 if f_in_eq6 is None else f_in_eq6
    return {
        1: [F34x, G14x, F14 * cos(phi4), -m4 * aG4x],
        2: [F34y, G14y, F14 * sin(phi4), -m4 * aG4y],
        3: [F34y * a4 * sin(pi / 2 - th14), F34x * a4 * sin(-th14),
            F14 * f4 * sin(phi4 - th14 - gam4), -I4 * al14,
            -m4 * aG4x * g4 * sin(-th14 - b4), -m4 * aG4y * g4 * sin(pi / 2 - th14 - b4)],
        4: [F23x, -F34x, F13 * cos(phi3), -m3 * aG3x],
        5: [F23y, -F34y, F13 * sin(phi3), -m3 * aG3y],
        6: [F34x * a3 * sin(pi - th13), F34y * a3 * sin(-pi / 2 - th13),
            F13 * f_6 * sin(phi3 - th13 - gam3), -I3 * al13,
            -m3 * aG3x * g3 * sin(-th13 - b3), -m3 * aG3y * g3 * sin(pi / 2 - th13 - b3)],
        7: [-F23x, G12x, -m2 * aG2x],
        8: [-F23y, G12y, -m2 * aG2y],
        9: [F23x * a2 * sin(pi - th12), F23y * a2 * sin(-pi / 2 - th12), T12, -I2 * al12,
            -m2 * aG2x * g2 * sin(-th12 - b2), -m2 * aG2y * g2 * sin(pi / 2 - th12 - b2)],
    }


def assert_printed_equations_hold(theta12, omega12, alpha12, p, R):
    eqs = printed_equations(theta12, omega12, alpha12, p, R)
    forces = {n: eqs[n] for n in (1, 2, 4, 5, 7, 8)}
    moments = {n: eqs[n] for n in (3, 6, 9)}
    assert all_sums_are_zero(forces) == [], "force equation(s) violated"
    assert all_sums_are_zero(moments) == [], "moment equation(s) violated"


@SETTINGS
@given(crank_rockers())
def test_printed_equilibrium_equations_hold(case):
    theta12, omega12, alpha12, p = case
    R = solve(theta12, omega12, alpha12, p)
    assert_printed_equations_hold(theta12, omega12, alpha12, p, R)


# --------------------------------------------------------------------------
# 2b. independent vector equilibrium of each link about its CG
# --------------------------------------------------------------------------
def link_loads(theta12, omega12, alpha12, p, R):
    """Per link: list of (force, point) and list of pure couples, d'Alembert."""
    P, _, a = kinematic_state(theta12, omega12, alpha12, p, R)
    F34 = vec(R["F34x"], R["F34y"])
    F23 = vec(R["F23x"], R["F23y"])
    G12 = vec(R["G12x"], R["G12y"])
    G14 = vec(R["G14x"], R["G14y"])
    F13 = p["F13"] * np.exp(I * p["phi3"])
    F14 = p["F14"] * np.exp(I * p["phi4"])
    return {
        2: ("G2", [(G12, "A0"), (-F23, "A"), (-p["m2"] * a["G2"], "G2")],
            [R["T12"], -p["I2"] * alpha12]),
        3: ("G3", [(F23, "A"), (-F34, "B"), (F13, "P3"), (-p["m3"] * a["G3"], "G3")],
            [-p["I3"] * R["alpha13"]]),
        4: ("G4", [(G14, "B0"), (F34, "B"), (F14, "P4"), (-p["m4"] * a["G4"], "G4")],
            [-p["I4"] * R["alpha14"]]),
    }, P


def assert_links_in_equilibrium(theta12, omega12, alpha12, p, R):
    loads, P = link_loads(theta12, omega12, alpha12, p, R)
    force_sums, moment_sums = {}, {}
    for link, (cg, forces, couples) in loads.items():
        force_sums[f"link {link}: ΣFx"] = [F.real for F, _ in forces]
        force_sums[f"link {link}: ΣFy"] = [F.imag for F, _ in forces]
        moment_sums[f"link {link}: ΣM_G"] = (
            [cross(P[pt] - P[cg], F) for F, pt in forces] + list(couples))
    assert all_sums_are_zero(force_sums) == []
    assert all_sums_are_zero(moment_sums) == []


@SETTINGS
@given(crank_rockers())
def test_each_link_in_dynamic_equilibrium(case):
    theta12, omega12, alpha12, p = case
    R = solve(theta12, omega12, alpha12, p)
    assert_links_in_equilibrium(theta12, omega12, alpha12, p, R)


# --------------------------------------------------------------------------
# 3. power balance
# --------------------------------------------------------------------------
def power_terms(theta12, omega12, alpha12, p, R):
    """Input/external power and dT/dt terms (their difference must vanish)."""
    _, v, a = kinematic_state(theta12, omega12, alpha12, p, R)
    F13 = p["F13"] * np.exp(I * p["phi3"])
    F14 = p["F14"] * np.exp(I * p["phi4"])
    supplied = [R["T12"] * omega12, dot(F13, v["P3"]), dot(F14, v["P4"])]
    dT_dt = [p["m2"] * dot(a["G2"], v["G2"]), p["I2"] * alpha12 * omega12,
             p["m3"] * dot(a["G3"], v["G3"]), p["I3"] * R["alpha13"] * R["omega13"],
             p["m4"] * dot(a["G4"], v["G4"]), p["I4"] * R["alpha14"] * R["omega14"]]
    return supplied, dT_dt


@SETTINGS
@given(crank_rockers())
def test_power_balance(case):
    theta12, omega12, alpha12, p = case
    R = solve(theta12, omega12, alpha12, p)
    supplied, dT_dt = power_terms(theta12, omega12, alpha12, p, R)
    assert sum_is_zero(supplied + [-t for t in dT_dt])


# --------------------------------------------------------------------------
# strip cutter of the seed (SI units)
# --------------------------------------------------------------------------
deg = np.radians
STRIP_CUTTER = dict(
    a1=0.500,  # ASSUMPTION: |A0B0| is not given in the text
    a2=0.085, a3=0.235, a4=0.550,
    m2=3.0, g2=0.0, beta2=0.0, I2=3.0 * 0.100**2,          # G2 at A0
    m3=2.0, g3=0.231, beta3=deg(-1.0), I3=2.0 * 0.268**2,   # ∠BAG3 = 1° CW
    m4=5.1, g4=0.305, beta4=deg(-7.0), I4=5.1 * 0.424**2,   # ∠BB0G4 = 7° CW
    F13=0.0, phi3=0.0, f3=0.0, gamma3=0.0, F14=0.0, phi4=0.0, f4=0.0, gamma4=0.0,
)
OMEGA_900_RPM = 900 * 2 * np.pi / 60


@pytest.mark.parametrize("sigma", [1, -1])
@pytest.mark.parametrize("cutting", [False, True], ids=["no-cut", "cut"])
def test_strip_cutter(sigma, cutting):
    theta12 = deg(np.arange(0.0, 360.0, 0.5))
    p = dict(STRIP_CUTTER, sigma=sigma)
    if cutting:
        # 2000 N, vertical, opposite on links 3 and 4 at C for 124° < θ12 < 156°.
        # ASSUMPTIONS (figure missing): downward on link 3, upward on link 4;
        # C3 at |AC| = 467 mm, 7.6° CCW of AB; C4 at |B0C| = 487 mm, 25.6° CCW
        # of B0B.
        on = (theta12 > deg(124)) & (theta12 < deg(156))
        p.update(F13=np.where(on, 2000.0, 0.0), phi3=deg(-90), f3=0.467, gamma3=deg(7.6),
                 F14=np.where(on, 2000.0, 0.0), phi4=deg(90), f4=0.487, gamma4=deg(25.6))
    # assembles over the whole cycle: r = |B0A| ∈ [a1 − a2, a1 + a2] lies inside
    # (|a3 − a4|, a3 + a4), and the solver does not raise
    assert abs(p["a3"] - p["a4"]) < p["a1"] - p["a2"]
    assert p["a1"] + p["a2"] < p["a3"] + p["a4"]
    R = solve(theta12, OMEGA_900_RPM, 0.0, p)
    P = points(theta12, R["theta13"], R["theta14"], p)
    np.testing.assert_allclose(np.abs(P["B"] - P["B_rocker"]), 0, atol=1e-12)
    assert all(np.all(np.isfinite(R[k])) for k in RESULT_KEYS)

    assert_printed_equations_hold(theta12, OMEGA_900_RPM, 0.0, p, R)
    assert_links_in_equilibrium(theta12, OMEGA_900_RPM, 0.0, p, R)
    supplied, dT_dt = power_terms(theta12, OMEGA_900_RPM, 0.0, p, R)
    assert sum_is_zero(supplied + [-t for t in dT_dt])
    # The kinetic energy is periodic, so over a full cycle at constant speed
    # the supplied power averages to zero: without the cut ∮T12 dθ12 = 0,
    # with it the input work equals the work done against the cutting force.
    # (Uniform sampling of the smooth periodic dT/dt makes the mean exact to
    # round-off.)  This also ties the α's to the ω's over the whole cycle.
    mean_supplied = np.mean(sum(np.broadcast_to(t, theta12.shape) for t in supplied))
    assert abs(mean_supplied) < RTOL * np.max(sum(np.abs(t) for t in supplied))


# --------------------------------------------------------------------------
# evidence for the typo corrections: each printed variant fails a check
# --------------------------------------------------------------------------
EXAMPLE = dict(a1=2.0, a2=0.5, a3=1.8, a4=1.4, sigma=1,
               m2=1.5, g2=0.3, beta2=0.4, I2=0.05,
               m3=2.0, g3=0.9, beta3=-0.3, I3=0.4,
               m4=3.0, g4=0.8, beta4=0.2, I4=0.6,
               F13=40.0, phi3=1.0, f3=1.2, gamma3=0.5,
               F14=-25.0, phi4=-2.0, f4=0.6, gamma4=-0.7)
EX_THETA12 = np.linspace(0, 2 * np.pi, 36, endpoint=False)
EX_OMEGA12, EX_ALPHA12 = 10.0, 30.0


def test_typo_position_a1_instead_of_a2():
    """Printed r cosϕ = a1 cosθ12 − a1, r sinϕ = a1 sinθ12: loop does not close."""
    p = EXAMPLE
    th = EX_THETA12
    r_cos_phi, r_sin_phi = p["a1"] * np.cos(th) - p["a1"], p["a1"] * np.sin(th)
    r, phi = np.hypot(r_cos_phi, r_sin_phi), np.arctan2(r_sin_phi, r_cos_phi)
    with np.errstate(invalid="ignore", divide="ignore"):
        lam = np.arccos((p["a4"]**2 + r**2 - p["a3"]**2) / (2 * p["a4"] * r))
        mu = np.arccos((p["a3"]**2 + p["a4"]**2 - r**2) / (2 * p["a3"] * p["a4"]))
    theta14 = phi - lam
    theta13 = theta14 - mu
    P = points(th, theta13, theta14, p)
    closure = np.abs(P["B"] - P["B_rocker"])
    # either unassemblable (nan) or a clearly open loop
    assert np.all(np.isnan(closure) | (closure > 1e-3))


def test_typo_alpha13_a4_omega12_squared():
    """Printed last term −a4 ω12² in α13 disagrees with finite differences."""
    p, th, w, al = EXAMPLE, EX_THETA12, EX_OMEGA12, EX_ALPHA12
    R = solve(th, w, al, p)
    s = np.sin
    printed = (p["a2"] * al * s(th - R["theta14"])
               + p["a2"] * w**2 * np.cos(th - R["theta14"])
               + p["a3"] * R["omega13"]**2 * np.cos(R["theta13"] - R["theta14"])
               - p["a4"] * w**2) / (p["a3"] * s(R["theta14"] - R["theta13"]))
    alpha13_fd = time_derivatives(th, w, al, p)[1][0]
    np.testing.assert_allclose(alpha13_fd, R["alpha13"], rtol=FD_RTOL, atol=FD_RTOL * w**2)
    assert np.max(np.abs(printed - alpha13_fd)) > 1e3 * FD_RTOL * w**2


def test_typo_eq6_f4_instead_of_f3():
    """Equation (6) with f4 (as printed) is violated by the equilibrium solution."""
    p = EXAMPLE
    R = solve(EX_THETA12, EX_OMEGA12, EX_ALPHA12, p)
    eqs = printed_equations(EX_THETA12, EX_OMEGA12, EX_ALPHA12, p, R, f_in_eq6=p["f4"])
    assert sum_is_zero(printed_equations(EX_THETA12, EX_OMEGA12, EX_ALPHA12, p, R)[6])
    assert not sum_is_zero(eqs[6], rtol=1e-3)


def test_typo_T12_sin_instead_of_cos():
    """Printed m2 g2 [aG2y sin − aG2x sin] breaks the power balance when g2 ≠ 0."""
    p, th, w, al = EXAMPLE, EX_THETA12, EX_OMEGA12, EX_ALPHA12
    R = solve(th, w, al, p)
    c = th + p["beta2"]
    printed_T12 = (R["F23y"] * p["a2"] * np.cos(th) - R["F23x"] * p["a2"] * np.sin(th)
                   + p["I2"] * al
                   + p["m2"] * p["g2"] * (R["aG2y"] * np.sin(c) - R["aG2x"] * np.sin(c)))
    supplied, dT_dt = power_terms(th, w, al, p, R)
    assert sum_is_zero(supplied + [-t for t in dT_dt])
    supplied[0] = printed_T12 * w
    assert not sum_is_zero(supplied + [-t for t in dT_dt], rtol=1e-3)
