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
# # Lesson 01 — The Newtonian method
#
# In this lesson you find the forces in a linkage whose **motion is already known**: *kinetostatics*,
# a dynamics problem turned into a statics problem. You will
#
# 1. see why inertia loads turn every moving link into a body in equilibrium;
# 2. draw the free body of a single rotating link, write its three equations and solve them;
# 3. do the same for a four-link double slider (9 unknowns) and compare with the textbook;
# 4. solve both problems with **your own data**, by hand first, and have your answers checked.
#
# Inside `graphkin` every number is SI (m, kg, s, N, rad); the printouts use mm, degrees and N·mm
# to match the books.

# %%
# %matplotlib inline
import numpy as np

import graphkin as gk

# %% [markdown]
# ## 1. The idea: d'Alembert's principle
#
# Newton's second law for a rigid link moving in the plane reads
#
# $$\sum \vec F = m\,\vec a_G, \qquad \sum M_G = I_G\,\alpha ,$$
#
# with $G$ the centre of mass, $I_G$ the moment of inertia about $G$ and $\alpha$ the angular
# acceleration. When the input motion is **known**, the kinematics gives $\vec a_G$ and $\alpha$ of
# every link before any force is known, so we may move them to the left:
#
# $$\sum \vec F + \underbrace{(-m\,\vec a_G)}_{\vec F_i} = 0, \qquad
#   \sum M_G + \underbrace{(-I_G\,\alpha)}_{T_i} = 0 .$$
#
# This is **d'Alembert's principle**: add an *inertia force* $\vec F_i = -m\vec a_G$ at $G$ and an
# *inertia torque* $T_i = -I_G\alpha$ as if they were ordinary loads, and each moving link is in
# **static equilibrium**: 3 equations per link ($\Sigma F_x = 0$, $\Sigma F_y = 0$, $\Sigma M_G = 0$).
#
# **Sign convention** (everywhere in `graphkin`): link 1 is the frame; $\vec F_{ij}$ is the force of
# link $i$ **on** link $j$, and $\vec F_{ji} = -\vec F_{ij}$; angles, $\omega$, $\alpha$ and torques
# are positive **counter-clockwise**; $T_{12}$ is the torque of the frame (the motor) on link 2.

# %% [markdown]
# ## 2. A single link in pure rotation
#
# One bar $O_2P$ (250 mm, 2 kg, a thin rod: $I_G = mL^2/12$) pivoted to the frame at $O_2$, driven by
# a motor torque $T_{12}$, with a known force $\vec F_P$ at its tip; the problem follows Norton,
# *Design of Machinery*, §11.2 (the numbers are our own): the catalog problem `single_link`.

# %%
p = gk.load("single_link")
bar_result = p.solve()

# %% [markdown]
# ### The free body and its equations
#
# Cut the bar free from the frame and draw every force **on** it: the pin force $\vec F_{12}$ at
# $O_2$, the motor torque $T_{12}$, the tip force $\vec F_P$, and the inertia force, drawn as one
# resultant $\vec R_{2i}$ offset from $G_2$ by $h = |T_i|/|\vec F_i|$ so that it also carries $T_i$.

# %%
gk.draw.draw_free_body(gk.construct_forces(p.kinematics(), 0), 2).figure

# %% [markdown]
# Reading the picture, with moments about $G$ (a 2-D cross product is $a_x b_y - a_y b_x$):
#
# $$\begin{aligned}
# F_{12x} + F_{Px} + F_{ix} &= 0\\
# F_{12y} + F_{Py} + F_{iy} &= 0\\
# (\vec r_{O_2} - \vec r_G)\times\vec F_{12} + T_{12} + (\vec r_P - \vec r_G)\times\vec F_P + T_i &= 0
# \end{aligned}$$
#
# Three unknowns, $F_{12x}$, $F_{12y}$, $T_{12}$, on the left, everything known on the right:
# $[A]\{x\} = \{b\}$, for position 0 of the problem:

# %%
print(gk.assemble(bar_result).format(0))

# %% [markdown]
# ### The same by hand, in one line
#
# Take moments about the **fixed pivot** $O_2$ instead: the pin force drops out. For a link turning
# about $O_2$ the inertia force and torque together have the moment $-(I_G + m r_G^2)\,\alpha = -I_O\alpha$
# (the centripetal part of $\vec a_G$ points at $O_2$), so
#
# $$T_{12} = I_O\,\alpha - \vec r_P\times\vec F_P, \qquad I_O = I_G + m\,r_G^2 = \tfrac13 m L^2 ,$$
#
# and the two force equations give $\vec F_{12} = m\vec a_G - \vec F_P$. The solution:

# %%
print(gk.format_solution(p, bar_result))

# %% [markdown]
# The motor must hold the bar back (a clockwise $T_{12}$): the tip force pushes harder than the
# bar's inertia resists.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
m, L = 2.0, 0.250
k = p.kinematics()
rP, FP = k.position(2, "P")[0], np.array(p.mechanism.loads[0].force)
T12_hand = m * L**2 / 3 * k.alpha[2][0] - gk.cross(rP, FP)
assert np.isclose(T12_hand, bar_result["T12"][0], rtol=1e-12)
assert np.allclose(bar_result["F12"][0], m * k.a_G(2)[0] - FP)
assert bar_result["T12"][0] < 0

# %% [markdown]
# ## 3. The double slider (Söylemez, §6.4)
#
# Three moving links: slider 2 moves along the $x$-axis at a constant 2 m/s, slider 4 along the
# $y$-axis, and the rod 3 (500 mm, 5 kg) joins them with pins at $A$ and $B$. The sliders are
# massless; no friction, no gravity. At a **pin** the force has two unknown components. At a
# **guide** the reaction $\vec G_{ij}$ is normal to the guide: its size $N$ and where it acts (a
# couple $C$) are unknown. Slider 2's driver pushes it **along** its guide with $\vec F_{12}$.
# Count: 2 + 2 (pins) + 2 + 2 (guides) + 1 (driver) = 9 unknowns, 3 links × 3 = 9 equations.
#
# ### The free bodies and their equations
#
# Every link cut free, at one length scale and one force scale; $\vec F_{32} = -\vec F_{23}$ appears
# on two free bodies, once on each:

# %%
p = gk.load("double_slider")
result = p.solve()
gk.draw.draw_free_bodies(gk.construct_forces(p.kinematics(), 0), length_scale=5, force_scale=2)

# %% [markdown]
# Each free body gives its equations (forces, then moments about the link's pin or $G$):
#
# * **slider 2** (massless, at $A$): $\vec F_{12} + \vec G_{12} + \vec F_{32} = 0$; every force passes
#   through the pin, so $C_{12} = 0$;
# * **rod 3**: $\vec F_{23} + \vec F_{43} + \vec F_{3i} = 0$ and
#   $(\vec r_A - \vec r_G)\times\vec F_{23} + (\vec r_B - \vec r_G)\times\vec F_{43} + T_{3i} = 0$;
# * **slider 4** (massless, at $B$): $\vec F_{34} + \vec G_{14} = 0$ and $C_{14} = 0$.
#
# $G_3$ is the middle of $AB$ and $x_A$ has no acceleration, so $\vec a_{G3}$ and $\vec F_{3i}$ are
# vertical. Slider 4 can push only horizontally, so $\vec F_{43}$ is horizontal, and on slider 2 the
# guide takes the vertical part, $\vec G_{12} = -\vec F_{3i}$, the driver the horizontal part,
# $\vec F_{12} = -\vec F_{43}$. The same nine equations as a matrix (rows: links 2, 3, 4; $N$ is
# measured along the guide turned by +90°):

# %%
print(gk.assemble(result).format(0))

# %%
print(gk.format_solution(p, result))

# %% [markdown]
# The book prints $F_{23} = 27.04$ N ∠ −73.78°, $F_{43} = 7.555$ N ∠ 180°, $G_{12} = 25.97$ N ∠ 270°,
# $T_{3i} = 865$ N·mm CW and $h = 33.31$ mm: the same to within 0.3 %, the rounding of its
# intermediate values (it divides the rounded 865 N·mm by the rounded 25.97 N to get $h$).

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
i3 = result.inertia(3)
assert np.allclose(result["G12"][0], -i3.F[0]) and np.allclose(result["F12"][0], -result["F43"][0])
for name, book, ours in [("F23", 27.04 * np.exp(1j * np.radians(-73.78)), result["F23"][0]),
                         ("F43", -7.555, result["F43"][0]), ("G12", -25.97j, result["G12"][0])]:
    assert abs(complex(*ours) - book) / abs(book) < 3e-3, name
assert abs(i3.T[0] * 1e3 + 865) / 865 < 3e-3 and abs(i3.h[0] * 1e3 - 33.31) / 33.31 < 3e-3

# %% [markdown]
# ## 4. Other positions: nothing is typed in by hand
#
# `p.solve(at=[...])` takes other values of the input coordinate in SI units (metres for a slider);
# every result then has one row per position. The driving force from 50 mm to 450 mm:

# %%
xs = np.linspace(0.05, 0.45, 9)
for x_A, F12 in zip(xs, p.solve(at=xs).effort):
    print(f"x_A = {x_A * 1e3:3.0f} mm    F12 = {F12:8.3f} N")

# %% [markdown]
# $F_{12}$ grows very fast as $x_A$ nears the rod's length (500 mm): the rod lies almost along the
# $x$-axis, slider 4 must move fast for a small motion of slider 2, and $\omega_3$, $\alpha_3$ and the
# inertia loads blow up. At 500 mm the mechanism is at a dead point.
#
# An independent check needs no free body at all: without friction the joint forces do no net work,
# so the driver's power balances the power of the inertia loads,
# $\vec F_{12}\cdot\vec v_A + \vec F_{3i}\cdot\vec v_{G3} + T_{3i}\,\omega_3 = 0$ (lesson 03 uses it).
#
# The worked solutions, written out as a textbook would (data, kinematics, inertia loads, the matrix,
# the graphical route), are the handouts [`single_link.pdf`](../figures/handouts/single_link.pdf) and
# [`double_slider.pdf`](../figures/handouts/double_slider.pdf); make your own with
# `graphkin handout double_slider -o double_slider.pdf`.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
sweep = p.solve(at=xs)
assert sweep.valid.all() and np.all(np.diff(sweep.effort) > 0)
assert np.isclose(sweep.effort[np.argmin(abs(xs - 0.2))], result.effort[0])
r300, k300 = p.solve(at=[0.3]), p.solve(at=[0.3]).kinematics
P = (r300["F12"][0] @ k300.velocity(2, "A")[0] + r300.inertia(3).F[0] @ k300.v_G(3)[0]
     + r300.inertia(3).T[0] * k300.omega[3][0])
assert abs(P) < 1e-9 * abs(r300["F12"][0] @ k300.velocity(2, "A")[0])

# %% [markdown]
# ## 5. Your turn
#
# The two problems with **your own data**: every student gets different numbers, drawn from their
# id, and the box grades your answers against a key solved from exactly those numbers. A wrong answer
# gets a sentence of feedback; a recognised slip (the force of the wrong link, a torque with the wrong
# sense, mm read as m) is named and earns part of the points.
#
# **Type your own id** between the quotes below, then run the cells of this section.

# %%
student = "your-id"  # ← type your own id here

# %% [markdown]
# ### 5.1 The single link, with your mass and angle
#
# **Work it out first, on paper.** Sketch the free body of the bar at your angle, find $\vec a_G$
# (tangential $\alpha\,\hat k\times\vec r_G$ plus centripetal $-\omega^2\vec r_G$), then $T_{12}$ from
# moments about $O_2$ and $\vec F_{12}$ from the two force equations. Type each answer in its box and
# press **Check**, as often as you like: a force as `12.3 N at -45 deg` or `(8.7, -8.7) N`, a torque
# with its sense, `4.5 N*m CW`.

# %%
gk.exercise("single_link", student)

# %% [markdown]
# #### Check your answer
#
# Only once the box has graded you: `graphkin`'s solution of your own bar, with its free body.

# %%
mine = gk.exercises.variant("single_link", student)
print(gk.format_solution(mine.problem, mine.problem.solve()))

# %%
gk.draw.draw_free_body(mine.construction, 2).figure

# %% [markdown]
# ### 5.2 The double slider, at your position and speed
#
# **Work it out first.** Draw the three free bodies at your position. Before any number, reason:
# which of your answers must be horizontal, which vertical, and which two must be equal and opposite?
# Then find $\omega_3$, $\alpha_3$ and $\vec a_{G3}$ from the loop $x_A^2 + y_B^2 = L^2$, the inertia
# loads of the rod, and solve the rod's three equations. Type your answers in the box.

# %%
gk.exercise("double_slider_forces", student)

# %% [markdown]
# #### Check your answer
#
# `graphkin`'s solution of your double slider, and its free bodies to compare with your sketch:

# %%
mine = gk.exercises.variant("double_slider_forces", student)
print(gk.format_solution(mine.problem, mine.problem.solve()))

# %%
gk.draw.draw_free_bodies(mine.construction, length_scale=5, force_scale=2)

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
key = {q["id"]: q["answer"]["text"] for q in gk.exercises.key("double_slider_forces", student)["questions"]}
assert all(q["verdict"] == "correct"
           for q in gk.exercises.grade("double_slider_forces", student, key)["questions"])
