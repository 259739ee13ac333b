# ---
# jupyter:
#   jupytext:
#     formats: ipynb,py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
#       format_version: '1.3'
#       jupytext_version: 1.19.6
#   kernelspec:
#     display_name: Python 3 (ipykernel)
#     language: python
#     name: python3
# ---

# %% [markdown]
# # Lesson 04 — Sizing a flywheel, and the joint-force index
#
# Lesson 03 followed the strip cutter's driving torque over a whole turn: it swings far above and
# below its average, because the links store kinetic energy and give it back twice a turn. A
# **flywheel** on the crank shaft soaks up those swings, so that a motor sized for the *average*
# torque drives the machine at a nearly steady speed. This lesson sizes one after Norton, *Design of
# Machinery*, §11.11, and then judges the linkage with Holte and Chase's joint-force index (§11.12).

# %%
# %matplotlib inline
import math

import numpy as np

import graphkin as gk

# %% [markdown]
# ## 1. The idea: energy in and out of the shaft
#
# Let $T(\theta)$ be the driving torque at crank angle $\theta$ (computed at constant speed) and
# $T_{avg} = \frac{1}{2\pi}\oint T\,d\theta$. A motor that supplies only $T_{avg}$ gives the shaft
# $T_{avg}\,d\theta$ while the linkage takes $T\,d\theta$; the difference comes out of the kinetic
# energy of everything on the shaft, of moment of inertia $I_s$:
#
# $$d\left(\tfrac12 I_s\,\omega^2\right) = -\,(T - T_{avg})\,d\theta .$$
#
# Where $T > T_{avg}$ (a *positive pulse*) the shaft slows down; where $T < T_{avg}$ it speeds up.
# Between the slowest and the fastest instant it gives up
#
# $$E = \tfrac12 I_s\left(\omega_{max}^2 - \omega_{min}^2\right) = I_s\,C_s\,\omega_{avg}^2,
# \qquad C_s = \frac{\omega_{max}-\omega_{min}}{\omega_{avg}},$$
#
# the **coefficient of speed fluctuation** (Norton suggests 0.01 to 0.05). Choose $C_s$, find $E$
# from the torque curve, and
#
# $$\boxed{I_s = \frac{E}{C_s\,\omega_{avg}^2}}$$
#
# $E$ is the largest swing of $U(\theta) = \int (T - T_{avg})\,d\theta$. Its extremes are where $T$
# crosses $T_{avg}$, so Norton integrates $T - T_{avg}$ **pulse by pulse, from one crossing to the
# next**, and adds the areas up in a table (his Table 11-1). The largest and the smallest running sum
# (the start, 0, counts too) are the slowest and the fastest instants; $E$ is their difference.
# Norton's own table has +200.73 in·lb as the largest and −60.32 in·lb as the smallest running sum,
# so $E = 200.73 - (-60.32) = 261.05$ in·lb, as he prints.

# %% [markdown]
# ## 2. Crossings, pulses and the energy table of the strip cutter
#
# The strip cutter at 900 rpm (lesson 03): the motor must push with up to 256 N·m and hold back with
# up to 325 N·m, although on average it supplies only about 8 N·m. `c.flywheel(Cs)` does Norton's
# procedure on the sweep's samples — trapezoidal average, crossings by linear interpolation, pulse
# areas. (The average is only right because the sweep samples both sides of the cut's jumps: lesson
# 03, section 3.) We take $C_s = 0.05$, Norton's upper value. Positive areas are energy the linkage
# takes from the shaft.

# %%
p = gk.load("strip_cutter")
c = gk.sweep(p)
f = c.flywheel(0.05)
for row, name in zip(f.table(), ["A to B", "B to C", "C to D", "D to A"]):
    print(f"{name}: {math.degrees(row.start):6.1f}° to {math.degrees(row.end):6.1f}°   ΔE = {row.area:7.1f} J"
          f"   accumulated {row.accumulated:7.1f} J")

# %% [markdown]
# Read the table as Norton reads his. From crossing A (9.6°) the linkage first *returns* 237.2 J to the
# shaft, which speeds up; the running sum is lowest, −237.2 J, at B (75.8°): the shaft is **fastest**
# there. It is highest, 0, at A itself — after the last pulse (D to A) has taken 211.8 J — so the shaft
# is **slowest** at A. The swing is $E = 237.2$ J, whichever crossing the table starts from. The pulses
# shaded on the torque curve, and the energy $U(\theta)$ with the swing marked:

# %%
gk.draw.draw_torque_curve(c, flywheel=f).figure

# %%
gk.draw.draw_energy(f).figure

# %% [markdown]
# An exact route gives the same $E$ with no torque and no integration: the motor's work equals the
# links' gain of kinetic energy $K = \sum_j \tfrac12 m_j v_{Gj}^2 + \tfrac12 I_{Gj}\omega_j^2$ minus the
# work of the cut. On a 0.05° grid it agrees with the 2° table to 0.1 %. It also shows why the flywheel
# is there: $K$ swings by about 230 J while the cut takes only 50 J per turn — the flywheel absorbs the
# links' own energy, not the cut.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
assert round(f.E, 1) == 237.2 and round(f.areas[0], 1) == -237.2 and round(f.areas[-1], 1) == 211.8
assert np.allclose(np.degrees(f.crossings[:2]), [9.6, 75.8], atol=0.05) and np.argmin(f.accumulated) == 0
assert round(c.peaks().effort_max.value) == 256 and round(-c.peaks().effort_min.value) == 325 and round(c.average) == 8
for first in range(len(f.areas)):
    running = np.cumsum(np.roll(f.areas, -first))
    assert math.isclose(max(running.max(), 0) - min(running.min(), 0), f.E, rel_tol=1e-12)

# %% [markdown]
# ## 3. The system inertia: a disk or a rim
#
# $I_s = E/(C_s\,\omega_{avg}^2)$ is required of *everything* on the crank shaft (if the motor's rotor
# already provides some, the flywheel can be that much smaller). For the same torque curve, halving
# $C_s$ doubles $I_s$, and half the speed needs four times the inertia (it stores $\tfrac12 I\omega^2$).
#
# A **solid disk** of radius $r$, thickness $t$ and density $\rho$ has $I = \tfrac12\rho\pi t\,r^4$, so
# $r = \left(2 I_s/(\pi\rho t)\right)^{1/4}$. A **rim** (an annulus of mean radius $R$) puts the mass far
# out, where it counts most. Steel 7850 kg/m³, cast iron 7200 kg/m³ (our values):

# %%
disk, rim = f.disk(density=7850, thickness=0.050), f.rim(density=7200, mean_radius=0.250, thickness=0.050)
print(f"I_s = {f.I_s:.4f} kg·m²:  steel disk 50 mm thick, r = {disk.radius * 1e3:.0f} mm, m = {disk.mass:.1f} kg;"
      f"  cast-iron rim R = 250 mm, m = {rim.mass:.1f} kg")

# %% [markdown]
# Norton's advice, in numbers: since $I \propto m r^2$, a thin disk of large diameter needs less
# material than a thick small one — for a disk $m \propto \sqrt t$ at a given $I$ — and a rim less still.
#
# ## 4. Before and after
#
# With the flywheel and a motor delivering $T_{avg}$, the energy balance gives the speed at every
# angle (`f.speed()`): it fluctuates by $C_s$, as designed. A flywheel helps only if the motor lets its
# speed droop under load: `graphkin` models it by a straight speed–torque line through its operating
# point, as for an induction motor with slip $s = 0.05$, and `f.smoothed_torque()` solves
# $I_s\,\omega\,d\omega/d\theta = T_m(\omega) - T(\theta)$ for a periodic turn (a simulation of the
# shaft, turn after turn, agrees to 2 %). The green curve on the torque plot above is that motor
# torque: between about 5 and 12.7 N·m instead of −325 and +256 N·m.

# %%
w = f.speed()
print(f"crank speed with the flywheel: {w.min() * 30 / math.pi:.1f} to {w.max() * 30 / math.pi:.1f} rpm"
      f"  (fluctuation {np.ptp(w) / f.omega_avg:.3f})")

# %% [markdown]
# One assumption runs through this, in Norton as here: $T(\theta)$ was computed at a *constant*
# 900 rpm. With the flywheel the speed varies by ±2.5 %, the inertia torques by about ±5 %: a small
# correction.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
assert abs(np.ptp(w) / f.omega_avg - 0.05) < 0.01 * 0.05
Tm = f.smoothed_torque(0.05)
assert round(Tm.min()) == 5 and round(Tm.max(), 1) == 12.7 and rim.mass < disk.mass
assert math.isclose(f.disk(7850, 0.1).mass / f.disk(7850, 0.025).mass, 2.0)

# %% [markdown]
# ## 5. The joint-force index (Norton §11.12)
#
# The transmission angle judges a four-bar only when the load is on the rocker. Holte and Chase's
# **joint-force index** works for any linkage and load: at each position, the largest joint force
# divided by the external load, $\text{JFI} = \max_{ij}|\vec F_{ij}| / |\vec F_{ext}|$, from a
# **static** analysis (no inertia: a linkage bad without the dynamic forces is worse at speed). Keep it
# below about 2; where the input can no longer move the linkage (an *immovable* position) it grows
# without bound. Outside the cut there is no load and the index is undefined.

# %%
jfi = gk.joint_force_index(p)
gk.draw.draw_joint_force_index(jfi).figure

# %% [markdown]
# The static index stays near 1.4 over the whole cut: the cutter transmits its cutting force well. At
# the peak, the matrix of lesson 01 on the massless linkage gives the same largest pin force. At
# 900 rpm, though, the *dynamic* joint forces reach 3.8 times the cut: as Norton warns, the index says
# nothing about speed.
#
# **What a bad linkage looks like.** Lengthen the crank from 85 mm to 245 mm. The crank can no longer
# turn all the way round: coupler and rocker line up — a toggle — when $|AB_0| = a_3 + a_4$, at
# $\cos\theta_t = \left(a_2^2 + a_1^2 - (a_3 + a_4)^2\right)/(2 a_2 a_1)$, and the index climbs through 2
# and blows up as the transmission angle goes to zero:

# %%
long_crank = gk.parse_problem(gk.catalog.path("strip_cutter").read_text().replace('A = ["85 mm", "0 mm"]',
                                                                                   'A = ["245 mm", "0 mm"]'))
gk.draw.draw_joint_force_index(gk.joint_force_index(long_crank)).figure

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
defined = np.isfinite(jfi.index)
assert np.all(abs(jfi.index[defined] - 1.4) < 0.05) and not jfi.immovable
assert round(c.peaks().forces["F23"].value / 2000, 1) == 3.8
assert gk.joint_force_index(long_crank).immovable and gk.joint_force_index(long_crank).peak.value > 5

# %% [markdown]
# ## 6. The interactive explorer
#
# `gk.explore(problem)` puts the whole cycle behind the crank (drag it, or use the slider) and a **speed**
# box. Type 600 rpm: the torque curve is redrawn at once. Predict first: the inertia part of the torque
# scales with $\omega^2$, the cutting part not at all — so at 600 rpm, where is the largest torque, and
# does the average move? (That scaling is how the browser redraws it: the two parts, solved once.)

# %%
ex = gk.explore(p)
ex

# %% [markdown]
# The worked solution is on the last pages of the handout
# [`strip_cutter.pdf`](../figures/handouts/strip_cutter.pdf): `graphkin handout strip_cutter --cs 0.02`.
#
# ## 7. Your turn
#
# Two exercises with **your own numbers**: every id gets its own speed, $C_s$ and crank length, and the
# box grades your answers; a recognised slip (kJ written as J, a sign) is named and earns part of the
# points. **Type your own id** between the quotes, then run the cells below.

# %%
student = "your-id"  # ← type your own id here

# %% [markdown]
# ### Exercise 1: size the flywheel of your cutter
#
# **Reason first.** Your speed and $C_s$ differ from the lesson's. Before any computing, estimate your
# $I_s$ from the lesson's 0.534 kg·m²: how does $I_s$ scale with $C_s$ if the torque curve stayed the
# same, and why does the curve *not* stay the same at another speed? Then find $E$ and $I_s$ with the
# tools of sections 2–3, on your own problem (`gk.exercises.variant("flywheel", student).problem`,
# with your $C_s$ from your data), in the empty cell, and type them in the box.

# %%
# your work here

# %%
gk.exercise("flywheel", student)

# %% [markdown]
# #### Check your answer
#
# Your cutter's energy curve, with the swing $E$ and $I_s$, as `graphkin` finds them:

# %%
mine = gk.exercises.variant("flywheel", student)
gk.draw.draw_energy(gk.sweep(mine.problem, 360).flywheel(mine.Cs)).figure

# %% [markdown]
# ### Exercise 2: the joint-force index of your cutter
#
# **Reason first.** Your crank has its own length. Is it longer or shorter than 85 mm, and so, from
# section 5, will your index be higher or lower than 1.4, and where in the cut will it peak? Then
# compute it at 1° steps in the empty cell and type the peak and its angle in the box.

# %%
# your work here

# %%
gk.exercise("joint_force_index", student)

# %% [markdown]
# #### Check your answer

# %%
gk.draw.draw_joint_force_index(gk.joint_force_index(gk.exercises.variant("joint_force_index", student).problem,
                                                    360)).figure

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
for name in ("flywheel", "joint_force_index"):
    key = {q["id"]: q["answer"]["text"] for q in gk.exercises.key(name, student)["questions"]}
    assert all(q["verdict"] == "correct" for q in gk.exercises.grade(name, student, key)["questions"]), name
