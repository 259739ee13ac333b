r"""Reference implementation of Söylemez, *Mechanisms*, §6.4.1
"Dynamic Force Analysis of a Four-Bar Mechanism" (seed
``/work/shared/seeds/000_6a5b8db2377b79fc.txt``).

This module is deliberately independent of :mod:`graphkin` (numpy only).  It
transcribes the book's closed-form solution literally, formula by formula,
vectorised over arrays of crank angles, so that graphkin can be checked
against a textbook oracle.  Every formula of the section was re-derived here;
the printed text contains the typos listed below, which are corrected in the
code.

Conventions (the book's)
------------------------
* Ground pivots: A0 at the origin, B0 at (a1, 0).  Crank A0A = a2 at θ12,
  coupler AB = a3 at θ13, rocker B0B = a4 at θ14; all angles measured CCW
  from +x.  Loop equation: a2 e^{iθ12} + a3 e^{iθ13} = a1 + a4 e^{iθ14}.
* Centre of mass of link i at distance g_i from its first joint (A0 for 2,
  A for 3, B0 for 4), at angle β_i measured CCW from the link line
  (so "∠BAG3 = 1° CW" means β3 = −1°).
* External force F13 (magnitude F13, direction ϕ3) acts on link 3 at P3,
  |AP3| = f3, at angle γ3 from AB; F14 (F14, ϕ4) acts on link 4 at P4,
  |B0P4| = f4, at angle γ4 from B0B.
* F_ij is the force of link i on link j (F34: of 3 on 4, F23: of 2 on 3);
  G14, G12 are the forces of the ground (link 1) on links 4 and 2; T12 is the
  (CCW positive) input torque applied to link 2.  I_i are centroidal moments
  of inertia.  d'Alembert inertia: F_ii = −m_i a_Gi, T_ii = −I_i α_1i.
* σ = ±1 selects the assembly branch (the book's open / cross configuration;
  σ = +1 puts B clockwise of the line B0→A, σ = −1 counter-clockwise).
* Units: any consistent set (the seed's example uses mm and kg; SI gives N
  and N·m directly).

Typos found in the printed text and corrected here
--------------------------------------------------
1. Position analysis, printed ``r cosϕ = a1 cosθ12 − a1`` and
   ``r sinϕ = a1 sinθ12``.  r e^{iϕ} is the vector from B0 to A, i.e.
   a2 e^{iθ12} − a1, so both lines must read a2 (the crank length), not a1:
   ``r cosϕ = a2 cosθ12 − a1``, ``r sinϕ = a2 sinθ12``.  With a1 the
   "solution" does not close the loop (|B − A| ≠ a3 or no assembly at all);
   evidence: ``test_typo_position_a1_instead_of_a2``.
   The remaining position formulas (λ, μ by the cosine rule, θ14 = ϕ − σλ,
   θ13 = θ14 − σμ) were re-derived from triangle A B0 B and are correct: for
   σ = +1, B lies clockwise of B0A by λ, the triangle B0→A→B is clockwise,
   so at B the direction to A is the direction to B0 turned clockwise by μ.
2. Angular acceleration of the coupler, printed::

       α13 = [a2 α12 sin(θ12−θ14) + a2 ω12² cos(θ12−θ14)
              + a3 ω13² cos(θ13−θ14) − a4 ω12²] / [a3 sin(θ14−θ13)]

   The last numerator term must be ``a4 ω14²``.  Derivation: differentiate
   the velocity loop a2ω12 i e^{iθ12} + a3ω13 i e^{iθ13} = a4ω14 i e^{iθ14},
   multiply by e^{−iθ14} and take the real part; the rocker term becomes
   −a4 ω14² (centripetal acceleration of B about B0).  The printed version
   is off by a4 (ω14² − ω12²) / [a3 sin(θ14 − θ13)] and fails the
   finite-difference test of α13 (``test_typo_alpha13_a4_omega12_squared``;
   it also breaks the zero cycle-average of dT/dt in the strip-cutter test).
   Note that it is α13, not α14, that carries this typo: α14 as printed,
   [a2α12 sin(θ12−θ13) + a2ω12² cos(θ12−θ13) + a3ω13² − a4ω14² cos(θ13−θ14)]
   / [a4 sin(θ14−θ13)], is correct (real part after multiplying by
   e^{−iθ13}) and passes the finite-difference test.
3. Equation (6), moment equilibrium of link 3 about A, printed
   ``... + F13 f4 sin(ϕ3 − θ13 − γ3) ...``.  The lever arm of F13 is
   |AP3| = f3, not f4 (f4 belongs to link 4).  The book's own closed-form
   B term uses f3, so (6) as printed is inconsistent with the book's
   solution: the returned forces violate printed (6) when F13 ≠ 0 and
   f3 ≠ f4 (``test_typo_eq6_f4_instead_of_f3``), and a B term built with f4
   fails the independent vector-sum equilibrium of link 3 and the power
   balance.
4. Input torque, printed::

       T12 = F23y a2 cosθ12 − F23x a2 sinθ12 + I2 α12
             + m2 g2 [aG2y sin(θ12+β2) − aG2x sin(θ12+β2)]

   The aG2y term must have cos: ``m2 g2 [aG2y cos(θ12+β2) − aG2x sin(θ12+β2)]``.
   This is the moment about A0 of the inertia force −m2 a_G2 applied at
   G2 = g2 e^{i(θ12+β2)}, i.e. −m2 g2 [cos(θ12+β2) aG2y − sin(θ12+β2) aG2x],
   and it is exactly what equation (9) (correctly printed) gives when solved
   for T12; it also has the same form as the A and B terms of links 4 and 3.
   With the printed sin, equation (9), the vector equilibrium of link 2 and
   the power balance fail as soon as g2 ≠ 0 (``test_typo_T12_sin_instead_of_cos``);
   the typo is invisible in the strip-cutter example, where g2 = 0.
5. Minor notation: "T3i = −IG3 αG3" means −I3 α13 (a link has one angular
   acceleration).

Everything else was re-derived and found correct: ω13, ω14; the six
centre-of-mass accelerations; equations (1)–(5) and (7)–(9); the solution of
(3) and (6) for F34x, F34y (Cramer's rule, determinant a3 a4 sin(θ14 − θ13));
and the back-substitutions for G14, F23, G12.

How this module is verified (``tests/books/test_soylemez_fourbar.py``)
---------------------------------------------------------------------------
Hypothesis draws random crank-rockers (both σ), masses, inertias, CG offsets,
external forces, ω12 and α12, over a full crank cycle, and checks:
loop closure; ω, α and a_G against five-point central differences in time
(rtol 1e-6, see the test module for the error budget); a_G against
rigid-body vector kinematics; equations (1)–(9) (with (6) corrected);
d'Alembert equilibrium of every link from point coordinates (ΣF = 0 and
ΣM about the CG = 0, without the book's algebra); and the power balance
T12 ω12 + F13·v_P3 + F14·v_P4 = Σ (m_i a_Gi·v_Gi + I_i α_1i ω_1i)
(all to 1e-9 relative to the load level).  Plus the strip cutter below.

Notes on the strip-cutter example of the seed
---------------------------------------------
The ground link |A0B0| is not given in the text (the figure and MathCad sheet
are missing); the tests assume a1 = 500 mm.  The data for point C are
slightly inconsistent: |AB| = 235, |BC| = 238, |AC| = 467 mm give
∠BAC = 9.19° by the cosine rule, not the printed 7.6° (triangle B0BC is
consistent: 25.62° vs 25.6°).  With the assumed a1 = 500 mm the point C of
link 3 (|AC| = 467 mm, 7.6° either side of AB) and the point C of link 4
(|B0C| = 487 mm, 25.6° either side of B0B) never come closer than about
66 mm over the cycle, for either σ, so if the blades are meant to meet at C
the book's ground link is probably longer (about 555–575 mm with σ = −1
brings the two C points to within 2 mm of each other near the cutting
interval 124° < θ12 < 156°).  This is only a plausibility remark; the tests
use 500 mm as instructed.

The external-force arguments (F13, phi3, ..., gamma4) may be arrays that
broadcast against θ12, e.g. to switch a cutting force on over part of the
cycle.
"""

from __future__ import annotations

import numpy as np

__all__ = ["soylemez_fourbar", "RESULT_KEYS"]

RESULT_KEYS = (
    "theta13", "theta14", "omega13", "omega14", "alpha13", "alpha14",
    "aG2x", "aG2y", "aG3x", "aG3y", "aG4x", "aG4y",
    "G14x", "G14y", "F34x", "F34y", "F23x", "F23y", "G12x", "G12y", "T12",
)


def soylemez_fourbar(theta12, omega12, alpha12, *, a1, a2, a3, a4, sigma,
                     m2, g2, beta2, I2, m3, g3, beta3, I3, m4, g4, beta4, I4,
                     F13=0.0, phi3=0.0, f3=0.0, gamma3=0.0,
                     F14=0.0, phi4=0.0, f4=0.0, gamma4=0.0
                     ) -> dict[str, np.ndarray]:
    """Kinematics and kinetostatics of a four-bar, Söylemez §6.4.1.

    ``theta12``, ``omega12``, ``alpha12`` (crank angle, angular velocity and
    acceleration) are broadcast against each other; all angles in radians.
    Returns a dict with the keys in :data:`RESULT_KEYS`, each an array of the
    broadcast shape.  Raises ``ValueError`` if the linkage cannot be assembled
    at some crank angle.
    """
    theta12, omega12, alpha12 = np.broadcast_arrays(
        np.asarray(theta12, dtype=float),
        np.asarray(omega12, dtype=float),
        np.asarray(alpha12, dtype=float),
    )
    sin, cos = np.sin, np.cos

    # ---- Position analysis --------------------------------------------------
    # Book: r cosϕ = a1 cosθ12 − a1, r sinϕ = a1 sinθ12   (typo 1: a1 → a2)
    r_cos_phi = a2 * cos(theta12) - a1
    r_sin_phi = a2 * sin(theta12)
    r = np.hypot(r_cos_phi, r_sin_phi)
    phi = np.arctan2(r_sin_phi, r_cos_phi)          # correct quadrant
    cos_lam = (a4**2 + r**2 - a3**2) / (2 * a4 * r)
    cos_mu = (a3**2 + a4**2 - r**2) / (2 * a3 * a4)
    bad = (np.abs(cos_lam) > 1) | (np.abs(cos_mu) > 1)
    if np.any(bad):
        raise ValueError(
            "four-bar cannot be assembled at theta12 = "
            f"{np.degrees(theta12[bad]).ravel()[:5]} deg"
        )
    lam = np.arccos(cos_lam)
    mu = np.arccos(cos_mu)
    theta14 = phi - sigma * lam
    theta13 = theta14 - sigma * mu

    # ---- Velocity analysis --------------------------------------------------
    omega13 = a2 / a3 * sin(theta12 - theta14) / sin(theta14 - theta13) * omega12
    omega14 = a2 / a4 * sin(theta12 - theta13) / sin(theta14 - theta13) * omega12

    # ---- Acceleration analysis ----------------------------------------------
    # Book prints the last numerator term of α13 as a4 ω12²   (typo 2: → a4 ω14²)
    alpha13 = (a2 * alpha12 * sin(theta12 - theta14)
               + a2 * omega12**2 * cos(theta12 - theta14)
               + a3 * omega13**2 * cos(theta13 - theta14)
               - a4 * omega14**2) / (a3 * sin(theta14 - theta13))
    alpha14 = (a2 * alpha12 * sin(theta12 - theta13)
               + a2 * omega12**2 * cos(theta12 - theta13)
               + a3 * omega13**2
               - a4 * omega14**2 * cos(theta13 - theta14)) / (a4 * sin(theta14 - theta13))

    # ---- Accelerations of the centres of gravity ----------------------------
    aG2x = -g2 * omega12**2 * cos(theta12 + beta2) - g2 * alpha12 * sin(theta12 + beta2)
    aG2y = -g2 * omega12**2 * sin(theta12 + beta2) + g2 * alpha12 * cos(theta12 + beta2)
    aG3x = (-a2 * omega12**2 * cos(theta12) - a2 * alpha12 * sin(theta12)
            - g3 * omega13**2 * cos(theta13 + beta3) - g3 * alpha13 * sin(theta13 + beta3))
    aG3y = (-a2 * omega12**2 * sin(theta12) + a2 * alpha12 * cos(theta12)
            - g3 * omega13**2 * sin(theta13 + beta3) + g3 * alpha13 * cos(theta13 + beta3))
    aG4x = -g4 * omega14**2 * cos(theta14 + beta4) - g4 * alpha14 * sin(theta14 + beta4)
    aG4y = -g4 * omega14**2 * sin(theta14 + beta4) + g4 * alpha14 * cos(theta14 + beta4)

    # ---- Dynamic force analysis: closed-form solution of (1)-(9) ------------
    A = (I4 * alpha14
         + m4 * g4 * (aG4y * cos(theta14 + beta4) - aG4x * sin(theta14 + beta4))
         - F14 * f4 * sin(phi4 - theta14 - gamma4))
    B = (I3 * alpha13
         + m3 * g3 * (aG3y * cos(theta13 + beta3) - aG3x * sin(theta13 + beta3))
         - F13 * f3 * sin(phi3 - theta13 - gamma3))
    F34x = (A * a3 * cos(theta13) + B * a4 * cos(theta14)) / (a3 * a4 * sin(theta13 - theta14))
    F34y = (A * a3 * sin(theta13) + B * a4 * sin(theta14)) / (a3 * a4 * sin(theta13 - theta14))
    G14x = -F34x + m4 * aG4x - F14 * cos(phi4)
    G14y = -F34y + m4 * aG4y - F14 * sin(phi4)
    F23x = F34x + m3 * aG3x - F13 * cos(phi3)
    F23y = F34y + m3 * aG3y - F13 * sin(phi3)
    G12x = F23x + m2 * aG2x
    G12y = F23y + m2 * aG2y
    # Book prints m2 g2 [aG2y sin(θ12+β2) − aG2x sin(θ12+β2)]   (typo 4: first sin → cos)
    T12 = (F23y * a2 * cos(theta12) - F23x * a2 * sin(theta12) + I2 * alpha12
           + m2 * g2 * (aG2y * cos(theta12 + beta2) - aG2x * sin(theta12 + beta2)))

    return {
        "theta13": theta13, "theta14": theta14,
        "omega13": omega13, "omega14": omega14,
        "alpha13": alpha13, "alpha14": alpha14,
        "aG2x": aG2x, "aG2y": aG2y, "aG3x": aG3x, "aG3y": aG3y,
        "aG4x": aG4x, "aG4y": aG4y,
        "G14x": G14x, "G14y": G14y, "F34x": F34x, "F34y": F34y,
        "F23x": F23x, "F23y": F23y, "G12x": G12x, "G12y": G12y,
        "T12": T12,
    }
