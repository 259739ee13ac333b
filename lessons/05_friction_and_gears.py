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
# # Lesson 05 — Friction and gears
#
# In lessons 01–04 a pin force may point anywhere and a frictionless guide pushes normal to itself.
# Two common joints add **one extra relation between the components of a joint force**:
#
# * a slider with **Coulomb friction**: the force along the guide is $\mu$ times the normal force,
#   against the sliding;
# * a pair of **spur gears**: the tooth force lies on the pressure line, at the pressure angle $\phi$
#   to the common tangent.
#
# Both come from ME 370 lecture 22 (*Dynamic force analysis 3*; the numbers are our own). In both the
# coefficient carries a **sign that depends on the answer** (the side the normal force pushes on, the
# flank the tooth pushes with), and the way round it is the same: **assume the sign, solve the linear
# system, check the sign.**

# %%
# %matplotlib inline
import math

import numpy as np

import graphkin as gk

# %% [markdown]
# ## 1. The slider-crank with friction at the slider
#
# Crank 2 ($O_2A$ = 60 mm) turns at a constant 300 rpm; the rod 3 ($AB$ = 200 mm, 1.2 kg) drives
# slider 4 (0.8 kg) along a horizontal guide 20 mm above $O_2$. A gas force of 500 N pushes the slider
# to the left, and the guide has friction $\mu = 0.2$.
#
# **The friction law, and the sign it needs.** While the slider slides, the guide pushes on it with a
# normal force $N$ and a friction force $\mu|N|$ against the sliding velocity $V_4$:
#
# $$F_{14x} = -\operatorname{sign}(V_4)\;\mu\,|F_{14y}| .$$
#
# The notes write $-\operatorname{sign}(V_4)\,\mu F_{14y}$: the same **as long as $F_{14y} > 0$**. Here the
# normal force changes side twice a turn, and where $F_{14y} < 0$ the unsigned form would turn friction
# round so that it *helps* the motion. The absolute value makes the equations non-linear; write
# $|N| = \sigma N$: once $\sigma$ is **assumed**, friction is a fixed multiple of $N$ and the system is
# linear again. Solve it, **check** that $N$ came out with the sign $\sigma$, else take the other sign.
#
# **The matrix at θ₁₂ = 60°.** Per unit of $N_{14}$ the guide pushes with $(-\mu\sigma\operatorname{sign}V_4,\ 1)$,
# so in the row *link 4: ΣFx* the column $N_{14}$ holds $-\mu\sigma\operatorname{sign}V_4$ — the lecture's
# $\pm\mu F_{14y}$ with the $\pm$ written out. $C_{14}$ is the couple the guide can pass; its row reads
# $C_{14} = 0$ (dropping it gives the lecture's 8 × 8).

# %%
p = gk.load("slider_crank_friction")
r = p.solve(at=[math.radians(60)])
print(gk.assemble(r).format(0))

# %% [markdown]
# Of the two assumptions $\sigma = \pm 1$ exactly one is confirmed by its answer; `graphkin` keeps it.
#
# **The graphical route: a guide reaction tilted by the friction angle.** With friction the guide force
# $\vec G_{14}$ is the normal force plus $\mu|N|$ along the guide, so it leans away from the normal by the
# **friction angle** $\rho = \arctan\mu$ = 11.31°, against the sliding. Once the side of $N$ is assumed,
# the direction of $\vec G_{14}$ is known before its size — what a force polygon needs. On the slider's
# free body (link 4) the dashed line through $B$ is the guide's normal and the arc is $\rho$:

# %%
gk.draw.draw_solution(gk.construct_forces(r.kinematics, 0), r)

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
c = gk.construct_forces(r.kinematics, 0)
G14 = c.force(1, 4)
assert c.valid and round(math.degrees(math.atan2(abs(G14[0]), abs(G14[1]))), 2) == 11.31
assert np.sign(G14[0]) == -np.sign(r.kinematics.velocity(4, "B")[0][0])
for name in r.names():
    assert np.allclose(c[name], r[name][0], rtol=1e-9, atol=1e-9)

# %% [markdown]
# ## 2. Friction over a whole turn
#
# **It flips with the velocity — not with the normal force.** The slider stops and turns back at the
# **dead centres**, where crank and rod are in line: with offset $e$, crank $r$ and rod $l$, at
# $\sin\theta = e/(r+l)$ and $\theta = 180° + \arcsin\big(e/(l-r)\big)$ — near 4° and 188°. There the
# friction force jumps to the opposite sense. At the exact dead centre the slider is at rest and
# Coulomb's law only bounds the friction (static friction, which kinetostatics cannot size):
# `graphkin` takes it as zero there, so the solution is exactly the frictionless one. The unsigned
# form of the notes gets the sense wrong wherever $N < 0$ — here most of the turn.
#
# **The work lost to friction.** Compare with the frictionless solution (`p.with_friction(0.0)`) at the
# same crank angle: the kinematics, the inertia loads and the gas force are the same, the pin forces do
# no net work, so the **only** difference is the friction force, of power $-\mu|N||V_4|$:
#
# $$\big(T_{12} - T_{12}^{\mu=0}\big)\,\omega_2 = \mu\,|N|\,|V_4| ,
# \qquad W_f = \oint \big(T_{12} - T_{12}^{\mu=0}\big)\,d\theta > 0 .$$
#
# Without friction the motor does no net work over a turn: the gas force gives back on one stroke what
# it takes on the other. With it, the average torque is the work lost per turn over $2\pi$:

# %%
cyc = gk.sweep(p, 360)
print(f"work lost to friction per turn: {2 * math.pi * (cyc.average - gk.sweep(p.with_friction(0.0), 360).average):.3f} J")
gk.draw.draw_torque_curve(cyc).figure

# %% [markdown]
# A power balance of the whole linkage — motor, inertia loads, gas force and guide force take zero power
# together — holds at every crank angle. In the explorer, watch $\vec G_{14}$ lean the other way as the crank
# passes the dead centres near 4° and 188°:

# %%
ex = gk.explore(p)
ex

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
res, kin = cyc.analysis, cyc.analysis.kinematics
V4, N, G = kin.velocity(4, "B")[:, 0], res.normal[(1, 4)], res["G14"]
assert np.all(np.sign(G[:, 0]) == -np.sign(V4)) and np.allclose(np.abs(G[:, 0]), 0.2 * np.abs(N))
assert np.sum(N < 0) > 180 and cyc.average > 0
dead = np.array([math.asin(0.02 / 0.26), math.pi + math.asin(0.02 / 0.14)])
assert np.array_equal(np.round(np.degrees(dead)), [4, 188]) and np.all(p.solve(at=dead)["G14"][:, 0] == 0)

# %% [markdown]
# ## 3. The gearset
#
# Gear 2 (pitch radius $r_2$ = 100 mm, $I_{G2}$ = 0.015 kg·m²) drives pinion 3 ($r_3$ = 40 mm,
# $I_{G3}$ = 0.0005 kg·m²), both pivoted at their centres, $O_3$ 140 mm to the right of $O_2$; pressure
# angle $\phi$ = 20°. The gear turns at 120 rpm CCW and speeds up at 50 rad/s²; a resisting torque
# $T_{13}$ = 8 N·m acts on the pinion. The pitch circles roll on each other, so
# $\omega_3 = -(r_2/r_3)\,\omega_2$ and $\alpha_3 = -(r_2/r_3)\,\alpha_2$; the centres of mass are on the
# pivots, so there are only inertia torques $-I_G\alpha$.
#
# **The pressure-angle constraint.** Each gear gives three equations; the unknowns are $\vec F_{12}$,
# $\vec F_{13}$, $\vec F_{32}$ and $T_{12}$ — seven for six equations. The seventh relation is the tooth
# geometry: with the centres on the $x$-axis the tangent at the pitch point $P$ is vertical, and
#
# $$F_{32x} = c\,F_{32y}, \qquad |c| = \tan\phi .$$
#
# The radial part always **pushes the gears apart**. The notes' $c = \tan\phi\,\operatorname{sign}(F_{32y})$
# assumes the pinion on the $-x$ side; ours is on the $+x$ side, so $c = -\tan\phi\,\operatorname{sign}(F_{32y})$.
# Either way $c$ depends on the answer: assume, solve, check. `graphkin` uses the relation the other way
# round — its one mesh unknown $F_{23}$ is the size of the tooth force *along the pressure line*, so that
# column holds the line's direction $(\sin\phi, \cos\phi)$:

# %%
g = gk.load("gearset")
rg = g.solve()
print(gk.assemble(rg).format(0))

# %% [markdown]
# **Mesh force and torque ratio.** Take moments about each fixed centre, where the pivot force has no
# moment. On the pinion the tangential tooth force is $W_t = (T_{13} - I_{G3}\alpha_3)/r_3$; along the
# pressure line $W = W_t/\cos\phi$, and the radial part $W_t\tan\phi$ loads the bearings but has no moment.
# On the gear, $T_{12} - I_{G2}\alpha_2 = r_2 W_t$, so
#
# $$T_{12} - I_{G2}\alpha_2 = \frac{r_2}{r_3}\,\big(T_{13} - I_{G3}\alpha_3\big),$$
#
# the torque ratio $r_2/r_3 = 2.5$. The pressure angle changes the bearing loads, not the torques.
#
# **The graphical route.** The pinion carries only torques: its loads reduce to a **pure couple**, which
# only a couple can balance. So the pivot force is equal, opposite and parallel to the tooth force, and
# its arm is the distance from $O_3$ to the pressure line — the **base-circle radius** $r_3\cos\phi$ (the
# pressure line is tangent to both base circles). The pinion is not a three-force member: its polygon
# has just two arrows, $\vec F_{23} + \vec F_{13} = 0$.

# %%
gk.draw.draw_solution(gk.construct_forces(rg.kinematics, 0), rg)

# %% [markdown]
# **Power.** The tooth forces act at the pitch point, where both pitch circles have the same velocity, so
# together they take no power: power in = power to the load + $I_{G2}\alpha_2\omega_2 + I_{G3}\alpha_3\omega_3$.
# At steady speed the torque ratio is exactly $r_2/r_3$ and this ideal mesh has no losses. In the
# explorer, drag the crank round: the forces, and so the torque curve, do not change:

# %%
ex_g = gk.explore(g)
ex_g

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
(mesh,) = [j for j in g.mechanism.joints if hasattr(j, "pressure_angle")]
r2, r3 = mesh.radii
(T13,) = [ld.torque for ld in g.mechanism.loads]
I2, I3, k3 = g.mechanism.link(2).I_G, g.mechanism.link(3).I_G, rg.kinematics
W_t = (T13 - I3 * k3.alpha[3][0]) / r3
assert math.isclose(np.linalg.norm(rg["F23"][0]), W_t / math.cos(mesh.pressure_angle))
assert math.isclose(rg["T12"][0], I2 * k3.alpha[2][0] + r2 / r3 * (T13 - I3 * k3.alpha[3][0]))

# %% [markdown]
# The handouts [`slider_crank_friction.pdf`](../figures/handouts/slider_crank_friction.pdf) and
# [`gearset.pdf`](../figures/handouts/gearset.pdf) write both examples out as textbook solutions.
#
# ## 4. Your turn
#
# Two exercises with **your own numbers**: every id gets its own crank angle, speed and $\mu$ for the
# slider-crank, and its own speed, acceleration and load for the gears; the box grades your answers,
# and a recognised slip (a force turned round, a torque with the wrong sense) earns part of the points.
# **Type your own id** between the quotes, then run the cells below.

# %%
student = "your-id"  # ← type your own id here

# %% [markdown]
# ### Exercise 1: your gear pair, by hand
#
# **Work it out first, on paper.** From the kinematics of section 3 find $\alpha_3$, then the tangential
# tooth force from the pinion's moments about $O_3$, the tooth force along the pressure line, the force on
# the gear's bearing (which way does the radial part push?), and $T_{12}$ from the gear's moments about
# $O_2$. Type your answers in the box.

# %%
gk.exercise("gear_pair", student)

# %% [markdown]
# #### Check your answer

# %%
mine = gk.exercises.variant("gear_pair", student)
print(gk.format_solution(mine.problem, mine.problem.solve()))

# %% [markdown]
# ### Exercise 2: your slider-crank with friction
#
# **Work it out first.** At your angle, find the slider's velocity: which way does friction push? Assume
# the side of the normal force, solve (by the matrix or by the polygons with $\vec G_{14}$ tilted by your
# friction angle), and check the assumption. Which force do you give for $\vec G_{14}$ — the guide's on the
# slider, or the slider's on the guide? Type your answers in the box.

# %%
gk.exercise("slider_crank_friction", student)

# %% [markdown]
# #### Check your answer

# %%
mine = gk.exercises.variant("slider_crank_friction", student)
gk.draw.draw_solution(mine.construction, mine.problem.solve())

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
for name in ("gear_pair", "slider_crank_friction"):
    key = {q["id"]: q["answer"]["text"] for q in gk.exercises.key(name, student)["questions"]}
    assert all(q["verdict"] == "correct" for q in gk.exercises.grade(name, student, key)["questions"]), name
