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
# # Lesson 03 — A whole cycle: the strip cutter at 900 rpm
#
# Lessons 01 and 02 found the forces at **one** position. A designer needs them at **every**
# position: the motor must drive all the way round, and each pin must survive its largest force.
#
# The machine is the four-bar strip cutter of Söylemez, *Mechanisms*, §6.4.1 (lesson 02 met it at
# 140°). Crank 2 turns at a constant 900 rpm; the coupler 3 and the rocker 4 each carry a blade at
# $C$, and while $124° < \theta_{12} < 156°$ the strip pushes the blades apart with 2000 N. The frame
# length $A_0B_0 = 565$ mm is read off the book's figure.

# %%
# %matplotlib inline
import math

import numpy as np

import graphkin as gk

# %%
p = gk.load("strip_cutter")
gk.draw.draw_mechanism(gk.construct_forces(p.kinematics(at=[math.radians(140)]), 0)).figure

# %% [markdown]
# ## 1. The whole cycle in one call
#
# `gk.sweep(problem)` solves every position of the problem (180 crank angles, 2° apart, as in the
# book) in **one vectorised call** and returns a `Cycle`: the `torque` curve, its `average` and `power`,
# `peaks()`, the joint forces, the shaking force and moment. Each position is exactly what lessons 01
# and 02 give one at a time.
#
# The sweep adds four positions of its own: wherever a load switches on or off (124°, 156°) it also
# solves $\varepsilon = 10^{-9}$ rad before and after, so that the curve is sampled on **both sides of
# each jump**. Section 3 shows why.

# %%
cyc = gk.sweep(p)
print(f"{cyc.n} positions, a closed turn: {cyc.closed}, all valid: {cyc.valid.all()}")

# %% [markdown]
# ## 2. The driving torque
#
# The blades at the start, middle and end of the cut: $C_3$ and $C_4$ close in and almost meet at 156°.

# %%
gk.draw.draw_positions(p, np.radians([124, 140, 156]), between=((3, "C"), (4, "C")))

# %% [markdown]
# **What the cut adds, by virtual work.** Give the crank a small rotation $\delta\theta_{12}$. With the
# inertia loads included the virtual work of all loads is zero. The cutting forces are
# $\vec F_{c3} = (0, F_c)$ at $C_3$ and $\vec F_{c4} = (0, -F_c)$ at $C_4$, so they add to the motor
# torque
#
# $$T_{cut} = -F_c\,\frac{d(y_{C3} - y_{C4})}{d\theta_{12}} = -F_c\,\frac{v_{C3,y} - v_{C4,y}}{\omega_{12}} .$$
#
# Only kinematics enters. The problem is linear in the loads (lesson 02), so the torque with the cut
# is the torque without it plus $T_{cut}$ — exactly, at every position. $T_{cut} > 0$: blade 3 moves
# down relative to blade 4 while the strip pushes it up, so the motor pushes the cutter through the
# strip. The force switches on and off abruptly, so the torque **jumps**, up by about 116 N·m at 124°
# and down by about 58 N·m at 156°:

# %%
gk.draw.draw_torque_curve(cyc).figure

# %% [markdown]
# The torque swings far more than the cut adds: at 900 rpm the coupler and the rocker are accelerated
# and slowed down again every turn. Its largest and smallest values lie outside the cut.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
from dataclasses import replace

kin, loads = cyc.analysis.kinematics, p.mechanism.loads
on = loads[0].active.mask(cyc.q)
T_cut = -sum(kin.velocity(ld.link, ld.point) @ np.asarray(ld.force) for ld in loads) / kin.omega[2]
no_cut = replace(p, mechanism=replace(p.mechanism, loads=()))
assert np.allclose(cyc.torque - no_cut.solve(at=cyc.q).effort, np.where(on, T_cut, 0.0), atol=1e-9)
assert np.all(T_cut[on] > 0) and not on[cyc.peaks().effort_max.index] and not on[cyc.peaks().effort_min.index]
jumps = np.diff(cyc.torque[~np.isin(cyc.q, p.q)])[::2]
assert round(jumps[0]) == 116 and round(-jumps[1]) == 58
blades = p.kinematics(at=np.radians([124, 140, 156]))
gaps = np.hypot(*(blades.position(3, "C") - blades.position(4, "C")).T)
assert np.all(np.diff(gaps) < 0) and gaps[-1] < 2e-3   # "close in ... almost meet at 156°" (< 2 mm)

# %% [markdown]
# ## 3. Average torque, power and the work done on the strip
#
# The crank turns at constant $\omega_{12}$, so the average torque is
# $\bar T_{12} = \frac{1}{2\pi}\oint T_{12}\,d\theta_{12}$. Where does the work go? The inertia loads do
# **no net work** over a turn (every link comes back with the same speed). The cut does: $\vec F_{c3}$ is
# constant, so its work needs only the blade positions at the ends of the cut,
#
# $$W_{cut} = \int_{124°}^{156°} T_{cut}\, d\theta_{12}
#           = -F_c\,\big[(y_{C3} - y_{C4})_{156°} - (y_{C3} - y_{C4})_{124°}\big] ,$$
#
# and $\bar T_{12} = W_{cut}/2\pi$:

# %%
ends = p.kinematics(at=[loads[0].active.start, loads[0].active.stop])
W_cut = -loads[0].force[1] * np.diff(ends.position(3, "C")[:, 1] - ends.position(4, "C")[:, 1])[0]
print(f"W_cut = {W_cut:.2f} J per turn:  W_cut/2π = {W_cut / (2 * math.pi):.4f} N·m;  cycle.average = {cyc.average:.4f} N·m")

# %% [markdown]
# ### Averaging a curve with jumps: the trapezoidal rule
#
# `cycle.average` integrates the samples with the **trapezoidal rule**, which assumes the curve is
# straight between samples — at a jump it is not. On the book's plain 2° grid the samples at 124° and
# 156° have the force off (the interval is open), so the trapezoids beside each jump count only
# **half** of it: the average comes out about 6 % low, and the error is proportional to the step $h$
# (**first order**: half the step, half the error).
#
# The samples at $\pm\varepsilon$ put each jump inside a step only $\varepsilon$ wide; every other step
# lies on one smooth piece, where the rule's error is $\propto h^2$ (**second order**: half the step, a
# quarter of the error). So the sweep's average agrees with $W_{cut}/2\pi$ to 0.01 %:

# %%
plain = p.solve(at=np.radians(np.arange(0, 360, 2.0))).effort.mean()
print(f"plain 2° grid: {plain:.4f} N·m ({plain / cyc.average - 1:+.1%});  sweep: {cyc.average:.4f} N·m")

# %% [markdown]
# **An average or an energy taken from a curve with jumps needs samples on both sides of each jump**
# (lesson 04's flywheel relies on it).
#
# **Input power.** $P = T_{12}\,\omega_{12}$ (`cycle.power`). On average a motor of about 0.76 kW does
# the cutting, but the inertia torques demand from −31 kW to +24 kW **for a moment**, every turn: that
# is why such machines have a flywheel (lesson 04). The energy argument holds at **each** position
# too: with no friction the powers of the motor, the cutting forces and the inertia loads add to zero.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
r = cyc.analysis
P_inertia = sum(np.sum(r.inertia(j).F * kin.v_G(j), axis=1) + r.inertia(j).T * kin.omega[j] for j in p.mechanism.moving)
P_cut = np.where(on, sum(kin.velocity(ld.link, ld.point) @ np.asarray(ld.force) for ld in loads), 0.0)
assert abs(cyc.power + P_cut + P_inertia).max() < 1e-9 * abs(cyc.power).max()
assert round(W_cut) == 50 and round(abs(cyc.average * 2 * math.pi / W_cut - 1), 4) == 0.0001
assert round(plain * 2 * math.pi / W_cut - 1, 2) == -0.06
assert round(cyc.power.min() / 1e3) == -31 and round(cyc.power.max() / 1e3) == 24
assert round(W_cut / (2 * math.pi) * float(p.q_dot[0]) / 1e3, 2) == 0.76

# %% [markdown]
# ## 4. Joint forces: polar plots and peaks
#
# A pin is sized by the **largest** force it carries, and the direction tells where a bushing wears.
# Söylemez draws the joint forces as **polar plots**: each force a vector from the origin, the curve
# the path of its tip over the cycle, each peak marked. ($\vec F_{12}$: the frame on the crank at
# $A_0$; $\vec F_{23}$: the crank on the coupler at $A$; $\vec F_{34}$ at $B$; $\vec F_{14}$ at $B_0$.)

# %%
gk.draw.draw_polar_forces(cyc).figure

# %% [markdown]
# The straight chords are the jumps at 124° and 156°. $\vec F_{12}$ and $\vec F_{23}$ lie on top of each
# other: the crank has no inertia loads (its centre of mass is on the pivot, its speed constant), so it
# is held by two forces, $\vec F_{12} = -\vec F_{32} = \vec F_{23}$. Every peak lies **outside** the cut
# and exceeds twice the 2000 N cutting force: at 900 rpm the inertia of the coupler and the rocker, not
# the strip, sizes the pins.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
assert np.allclose(r["F12"], r["F23"], atol=1e-9)
assert all(not on[pk.index] and pk.value > 4000 for pk in cyc.peaks().forces.values())

# %% [markdown]
# ## 5. Shaking force and shaking moment
#
# The **shaking force** on the frame is the resultant of the forces the moving links put on it,
# $-\vec F_{12} - \vec F_{14}$; the **shaking moment** their moment about $A_0$, plus the motor's
# reaction $-T_{12}$. Adding up the equilibrium of all moving links, every pin force between two moving
# links cancels, which leaves
#
# $$\vec F_{shake} = \sum_j (-m_j\vec a_{Gj}) + \vec F_{c3} + \vec F_{c4} .$$
#
# The cutting forces are an equal and opposite pair, so they cancel: the shaking force is inertia only.

# %%
gk.draw.draw_shaking(cyc)

# %% [markdown]
# More than 5 kN at 15 turns a second would shake the floor: balancing the links is the cure.
#
# ## 6. Transmission angle
#
# The transmission angle $\mu$, between the coupler $AB$ and the rocker $B_0B$, says how well the
# coupler can turn the rocker: at 90° all of its force does, near 0° or 180° almost none, and the pin
# forces grow. A rule of thumb asks for $90° \pm 50°$. With $a = A_0A$, $b = AB$, $c = B_0B$,
# $d = A_0B_0$ and the diagonal $s = AB_0$, the law of cosines gives
#
# $$s^2 = a^2 + d^2 - 2ad\cos\theta_{12}, \qquad \cos\mu = \frac{b^2 + c^2 - s^2}{2bc} .$$
#
# $\mu$ is extreme where the crank lines up with the frame (0° and 180°); `cycle.transmission_angle()`
# folds it to $[0°, 90°]$:

# %%
gk.draw.draw_transmission_angle(cyc).figure

# %% [markdown]
# ## 7. The interactive explorer
#
# `gk.explore(problem)` solves the cycle once; your browser draws it. Drag the crank, toggle the free
# bodies and polygons, hover a force. `ex.set("mass.3", 4.0)` asks Python for a new cycle.

# %%
ex = gk.explore(p)
ex

# %% [markdown]
# ## 8. The cycle on a lecture slide
#
# `gk.draw.animate` draws the cutter at equally spaced crank angles, each joint force an arrow at one
# force scale for the whole turn: from 124° to 156° the cutting forces appear on the blades. From a
# terminal, `graphkin animate strip_cutter -o cutter.gif` (or `.html`, or `.mp4` with ffmpeg;
# `--polygons` adds the force polygons) makes a file for a slide. The handout
# [`strip_cutter.pdf`](../figures/handouts/strip_cutter.pdf) works the whole cycle out on paper.

# %%
from IPython.display import HTML

film = gk.draw.animate(p, frames=36, fps=8, dpi=60)
HTML(film.to_html())

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
assert len(film.frames) == 36 and film.fps == 8 and not film.gaps
assert "https:" not in film.to_html() and "http:" not in film.to_html()

# %% [markdown]
# ## 9. Your turn
#
# Two exercises with **your own numbers**: every id gets its own speed, cutting force and crank
# angle, and the box grades your answers; a recognised slip (a torque with the wrong sense, the force
# of the wrong link) is named and earns part of the points. **Type your own id** between the quotes, then run the cells below.

# %%
student = "your-id"  # ← type your own id here

# %% [markdown]
# ### Exercise 1: the forces during your cut
#
# **Work it out first.** One position inside the cut: the force of the crank on the coupler, the
# frame's force on the rocker, and the motor's torque. Solve it as in lesson 01 (three equations per
# link) or by the construction of lesson 02 (superposition: both links 3 and 4 carry a blade). Before
# you type $T_{12}$, reason: inside the cut, is it larger or smaller than without the cut, and by the
# $T_{cut}$ of section 2?

# %%
gk.exercise("strip_cutter_cut", student)

# %% [markdown]
# #### Check your answer
#
# `graphkin`'s solution of your cutter at your angle:

# %%
mine = gk.exercises.variant("strip_cutter_cut", student)
gk.draw.draw_solution(mine.construction, mine.problem.solve())

# %% [markdown]
# ### Exercise 2: the torque curve of your cutter
#
# **Reason first**, then compute. The average torque needs no sweep: find $W_{cut}$ from your blade
# positions at the ends of your cut (section 3) and divide by $2\pi$. For the largest and smallest
# torque and the peak of $F_{23}$ write your own few lines in the empty cell, with the tools of
# sections 1–4, on your own problem (`gk.exercises.variant("torque_curve", student).problem`).
# Before you read the peaks, predict: inside the cut or outside it?

# %%
# your work here

# %%
gk.exercise("torque_curve", student)

# %% [markdown]
# #### Check your answer
#
# Your cutter's torque curve, with its average, as `graphkin` draws it:

# %%
gk.draw.draw_torque_curve(gk.sweep(gk.exercises.variant("torque_curve", student).problem, 360)).figure

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
for name in ("strip_cutter_cut", "torque_curve"):
    key = {q["id"]: q["answer"]["text"] for q in gk.exercises.key(name, student)["questions"]}
    assert all(q["verdict"] == "correct" for q in gk.exercises.grade(name, student, key)["questions"]), name
