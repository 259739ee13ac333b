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
# # Lesson 02 — The graphical method
#
# Lesson 01 wrote three equilibrium equations per link and solved them as a matrix. Before
# computers, engineers found the same forces **with a ruler and a pencil**: every force is drawn as
# an arrow, and equilibrium means that the arrows, placed tip to tail, close into a polygon. It shows
# *why* each force points where it does. `graphkin` does each construction exactly (it computes where
# a draftsman would measure), so the graphical and analytical answers agree to rounding error.

# %%
# %matplotlib inline
import numpy as np

import graphkin as gk

# %% [markdown]
# ## 1. The idea
#
# **One force instead of a force and a torque.** d'Alembert gives each moving link an inertia force
# $\vec F_i = -m\vec a_G$ at $G$ and an inertia torque $T_i = -I_G\alpha$. A force and a couple in the
# plane can always be replaced by **one force**: the same vector $\vec F_i$, moved sideways from $G$ by
#
# $$h = \frac{|T_i|}{|\vec F_i|}$$
#
# so that its moment about $G$ is exactly $T_i$ — to the side that turns the link the same way as
# $T_i$: the *inertia resultant* $\vec R_i$. Other known loads join it through the point where their
# lines cross.
#
# **Two-force members.** A link with no load of its own, touched at only two points, is held by two
# forces; they balance only if equal, opposite and **on the line through the two joints**. So we know
# the direction of the force it passes on before we know its size.
#
# **Three-force members.** A link held by three forces is in equilibrium only if the three lines of
# action meet in **one point**, and the three vectors drawn **tip to tail** close a triangle (the
# *force polygon*). So: cross the known resultant with the line fixed by a two-force neighbour — the
# *point of concurrency* $I$ — and the third force passes through $I$ and its own joint. All three
# directions and one size are then known; the polygon gives the rest.
#
# **Superposition.** If **both** links of a pair carry loads, neither is a two-force member: load one
# link at a time (one *sub-problem* each), solve each as above, and **add** their joint forces.
#
# The sign convention is lesson 01's, drawn once: $\vec F_{ij}$ is the force of link $i$ **on** link
# $j$; a free body of link $j$ shows the forces $\vec F_{ij}$ of its neighbours.

# %%
gk.draw.draw_sign_convention().figure

# %% [markdown]
# ## 2. The double slider, step by step (Söylemez §6.4)
#
# The mechanism of lesson 01: slider 2 moves along $x$ at 2 m/s, slider 4 along $y$, and the rod 3
# (500 mm, 5 kg) joins them; only the rod has mass. `gk.construct_forces` builds the construction at
# one position as data — a list of steps, each with a caption, the lines and points it draws, and its
# force polygon — and `gk.draw.draw_steps` draws one frame per step.

# %%
p = gk.load("double_slider")
c = gk.construct_forces(p.kinematics(), 0)
frames = gk.draw.draw_steps(c)

# %% [markdown]
# ### Step 1 — the inertia resultant of the rod
#
# The rod's inertia force points straight up (25.98 N) and its inertia torque is clockwise (866 N·mm).
# An upward force turns the rod clockwise about $G_3$ if it passes **to the left** of $G_3$: so
# $\vec R_{3i}$ is drawn vertical, $h = 33.33$ mm to the left of $G_3$ (the book: 33.31 mm).

# %%
frames[0]

# %% [markdown]
# ### Step 2 — slider 4 is a two-force member
#
# Slider 4 is massless and its guide frictionless: it is touched by the rod's pin at $B$ and by the
# guide, which pushes only horizontally. So $\vec F_{43}$ is **horizontal, through $B$**.

# %%
frames[1]

# %% [markdown]
# ### Step 3 — the rod is a three-force member
#
# The rod carries $\vec R_{3i}$ (line known), $\vec F_{43}$ (line known from step 2) and $\vec F_{23}$
# at $A$ (line unknown). The first two lines cross at $I_3$; the third force must pass through $I_3$
# too, so its line is $AI_3$.

# %%
frames[2]

# %% [markdown]
# ### Step 4 — the force polygon of the rod
#
# Draw $\vec R_{3i}$ to scale, from its tip a line parallel to $\vec F_{43}$, from its tail a line
# parallel to $AI_3$. Where they cross closes the triangle $\vec R_{3i} + \vec F_{43} + \vec F_{23} = 0$.

# %%
frames[3]

# %% [markdown]
# ### Steps 5 and 6 — slider 2 and the driving force
#
# Slider 2 carries $\vec F_{32} = -\vec F_{23}$. The frame holds it with the guide force $\vec G_{12}$
# (vertical) and the driving force $\vec F_{12}$ (horizontal): one known force and two known
# directions, so the polygon gives both sizes.

# %%
frames[4]

# %%
frames[5]

# %% [markdown]
# The book reads two results straight off the polygons: $\vec G_{12} = -\vec R_{3i}$ and
# $\vec F_{12} = -\vec F_{43}$ — the guide takes the vertical part of $\vec F_{32}$, the driver the
# horizontal part. Everything on one sheet — the mechanism, both routes side by side, each free body
# and each polygon; graphical and analytical agree to rounding error, the book to 0.3 %:

# %%
gk.draw.draw_solution(c, p.solve())

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
r = p.solve()
assert len(frames) == len(c.steps) == 6
assert np.allclose(c.force(1, 2), -np.array(c.inertia[3]["F"])) and np.allclose(c.force(2, 1), c.inertia[3]["F"])
assert round(c.inertia[3]["h"] * 1e3, 2) == 33.33 and c.inertia[3]["T"] < 0 and round(-c.inertia[3]["T"] * 1e3) == 866
assert round(float(np.linalg.norm(c.inertia[3]["F"])), 2) == 25.98
for name in ("F23", "F34", "G12", "G14"):
    assert np.allclose(c[name], r[name][0], rtol=1e-12, atol=1e-12)

# %% [markdown]
# ## 3. A four-bar by superposition: the strip cutter (Söylemez §6.4.1)
#
# Crank 2 ($A_0A$) turns at 900 rpm; the coupler 3 and the rocker 4 both carry a blade at $C$. While
# $124° < \theta_{12} < 156°$ the strip pushes the blades apart with 2000 N (up on link 3, down on
# link 4). We take $\theta_{12} = 140°$, in the middle of the cut. **Both** links of the dyad 3–4
# carry loads, so neither is a two-force member.
#
# **Why superposition is allowed.** Once the position is fixed, every equilibrium equation is
# **linear in the loads**: the lever arms and directions come from the geometry, and the unknown
# joint forces appear to the first power. So we solve
#
# * **sub-problem I**: only link 3 loaded — link 4 is a two-force member (force along $B_0B$);
# * **sub-problem II**: only link 4 loaded — link 3 is a two-force member (force along $AB$);
#
# and add the joint forces of the two sub-problems at $A$, $B$ and $B_0$. The figures mark sub-problem
# I's forces with one prime, II's with two: in II, link 3 is a two-force member, so
# $\vec F_{23}'' = \vec F_{34}''$. Every step, in the order it is built:

# %%
p2 = gk.load("strip_cutter")
r2 = p2.solve(at=[np.radians(140)])
c2 = gk.construct_forces(r2.kinematics, 0)
gk.draw.draw_step_grid(c2)

# %% [markdown]
# **The crank is held by a couple.** The crank has no inertia loads (its centre of mass is on the
# pivot and it turns at constant speed), so it carries only $\vec F_{32}$ at $A$, and the pivot force
# $\vec F_{12} = -\vec F_{32}$ at $A_0$: equal, opposite, parallel — a couple of arm $d$, the distance
# from $A_0$ to the line of $\vec F_{32}$. The motor's torque cancels it: $|T_{12}| = |\vec F_{32}|\,d$.
# Both routes, side by side:

# %%
gk.draw.draw_solution(c2, r2)

# %% [markdown]
# **Friction breaks superposition**: Coulomb friction $\mu|N|$ opposes the sliding, and its direction
# depends on the sign of the *total* normal force. So **assume** that sign, solve (linear again), and
# check it at the end (lesson 05). `graphkin` says so in a note; the slider-crank with $\mu = 0.2$:

# %%
p3 = gk.load("slider_crank_friction")
c3 = gk.construct_forces(p3.kinematics(at=[np.radians(60)]), 0)
print(next(s.caption for s in c3.steps if s.kind == "note" and s.caption.startswith("Friction")))

# %% [markdown]
# Both constructions, each step with its caption and its polygon to scale, are in the handouts
# [`double_slider.pdf`](../figures/handouts/double_slider.pdf) and
# [`strip_cutter.pdf`](../figures/handouts/strip_cutter.pdf); `graphkin handout double_slider --blank`
# gives the free bodies to scale with room for you to draw each polygon.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
assert c2.valid and not c2.warnings
assert [s.values.keys() for s in c2.steps if s.kind == "superpose"] == [{"F23"}, {"F34"}, {"F14"}]
assert [s.caption.split(" (")[0] for s in c2.steps if s.kind == "sub-problem"] == [  # the names the prose uses
    "Sub-problem I: only the loads on link 3", "Sub-problem II: only the loads on link 4"]
for name in r2.names():
    assert np.allclose(c2[name], r2[name][0], rtol=1e-9, atol=1e-9), name
assert not any(c2.inertia[2]["F"]) and not c2.inertia[2]["T"]

# %% [markdown]
# ## 4. Your turn
#
# Two exercises with **your own data**: every student gets different numbers, drawn from their id,
# and the box grades your answers against a key solved from exactly those numbers. A recognised slip
# (a torque with the wrong sense, the resultant on the wrong side of $G$, mm read as m) is named and
# earns part of the points. **Type your own id** between the quotes, then run the cells below.

# %%
student = "your-id"  # ← type your own id here

# %% [markdown]
# ### 4.1 The inertia resultant of the strip cutter's coupler
#
# **Work it out first, on paper.** At your crank angle and speed (outside the cut), find the coupler's
# acceleration of $G_3$ and $\alpha_3$ from the velocity and acceleration loops, then $\vec F_{3i}$,
# $T_{3i}$, the offset $h$ and the foot of the perpendicular from $G_3$ to the resultant's line. Before
# you type the foot, reason: on which side of $G_3$ must it be, for the sense of your $T_{3i}$? Write a
# force as `12.3 N at -45 deg`, a torque with its sense, `4.5 N*m CW`, a point as `(x, y) mm`.

# %%
gk.exercise("inertia_resultant", student)

# %% [markdown]
# #### Check your answer
#
# Once the box has graded you: `graphkin`'s free body of your coupler, the resultant on its offset line
# and $h$ dimensioned.

# %%
gk.draw.draw_free_body(gk.exercises.variant("inertia_resultant", student).construction, 3).figure

# %% [markdown]
# ### 4.2 The double slider with a pencil and a ruler
#
# Section 2 at your own position and speed — but this time *you* do the construction. Below are your
# mechanism and the free bodies to scale, with the rod's inertia resultant $\vec R_{3i}$ on its offset
# line and a force scale bar; the joint forces are left out. Print the figure (or copy it onto
# paper), then draw the line of $\vec F_{43}$ (step 2), find $I_3$ and the line $AI_3$ (step 3), draw the
# polygons of the rod and of slider 2 at the printed force scale (steps 4–6), and measure the sides.
# An answer within 3 %, or what a careful drawing allows (each line to ±0.5 mm and ±0.5°), earns
# full marks: the sheet states both.

# %%
mine = gk.exercises.variant("double_slider_graphical", student)
gk.draw.draw_given(mine.construction)

# %%
gk.exercise("double_slider_graphical", student)

# %% [markdown]
# #### Check your answer
#
# `graphkin`'s construction of your double slider, to lay beside your drawing:

# %%
gk.draw.draw_solution(mine.construction, mine.problem.solve())

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
for name in ("inertia_resultant", "double_slider_graphical"):
    key = {q["id"]: q["answer"]["text"] for q in gk.exercises.key(name, student)["questions"]}
    assert all(q["verdict"] == "correct" for q in gk.exercises.grade(name, student, key)["questions"]), name
