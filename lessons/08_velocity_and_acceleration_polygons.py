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
# # Lesson 08 — From the input motion to the driving torque, all by drawing
#
# Lesson 02 drew the force polygons from accelerations that the solver had worked out. A course goes
# one step further back: it starts from the crank's **ω2 and α2** only, draws the **velocity polygon**
# and the **acceleration polygon**, reads every ω, α and a_G off them, turns those into inertia loads, and
# only then draws the force polygons. This lesson walks that route on the strip cutter of lessons 02–04
# (Söylemez §6.4.1) at θ12 = 140°, 900 rpm, and ends with your own four-bar to solve by hand.
#
# 1. the input motion and the mechanism;
# 2. the velocity polygon, and ω3, ω4 read off it;
# 3. the acceleration polygon: normal, tangential and Coriolis components, the images and the G points;
# 4. the inertia loads from the polygons, and the force polygons to the driving torque T12;
# 5. the explorer with the polygons switched on;
# 6. your turn.

# %%
# %matplotlib inline
import math

import graphkin as gk

problem = gk.load("strip_cutter")
kin = problem.kinematics(at=[math.radians(140)])

# %% [markdown]
# ## 1. The input motion
#
# All the polygons need is the mechanism's **position** (drawn to scale) and the crank's motion:
# ω2 = 900 rpm = 94.25 rad/s counter-clockwise, α2 = 0. Every other velocity and acceleration is
# constructed from these two numbers.

# %%
gk.draw.draw_mechanism(gk.construct_forces(kin, 0))

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
assert math.isclose(float(kin.q_dot[0]), 900 * 2 * math.pi / 60, rel_tol=1e-12)
assert float(kin.q_ddot[0]) == 0.0

# %% [markdown]
# ## 2. The velocity polygon
#
# Pick a pole **o**: every point's velocity is drawn from it. The crank pin A turns about A0, so
# v_A = ω2 × A0A, perpendicular to A0A, in the sense of ω2: one vector, known in size and direction.
#
# B belongs to the coupler and to the rocker. Seen from A (the coupler), v_BA is perpendicular to AB;
# seen from B0 (the rocker, pivoted on the frame), v_B is perpendicular to B0B. Draw a line through
# **a** perpendicular to AB and a line through **o** perpendicular to B0B: they meet at **b**. Then
# the coupler turns at ω3 = v_BA / AB, and the rocker at ω4 = v_B / B0B, each in the sense its vector
# turns the link.
#
# The triangle **abc** is the coupler's *velocity image*: the coupler's shape, turned 90° and scaled
# by ω3. Every other point of the link, and its centre of mass G, sits on the image just as it sits on
# the link.

# %%
motion = gk.construct_kinematics(kin, 0)
gk.draw.draw_motion_polygon(motion, "velocity")

# %% [markdown]
# Each step of the construction says what is known, what is perpendicular to what, and what it
# found. The velocity polygon's steps:

# %%
for step in motion.steps:
    if step.polygon == "velocity":
        print("•", step.caption)

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
for link in (3, 4):
    assert math.isclose(motion.omega[link], float(kin.omega[link][0]), rel_tol=1e-9)

# %% [markdown]
# ## 3. The acceleration polygon
#
# The acceleration of B relative to A has two parts. The **normal** one, ω3² AB, points from B
# towards A: known in size and direction the moment ω3 is known, so draw it first. The **tangential**
# one, α3 × AB, is perpendicular to AB: only its line is known. Do the same from B0 on the rocker,
# and the two tangential lines meet at **b′**.
#
# Where a block slides on a *turning* guide (a shaper's slotted lever) a third part appears, the
# **Coriolis** component 2ω v: the sliding velocity turned 90° in the sense of the guide's ω. The
# four-bar has no such pair; the catalog's `shaper_polygons` exercise asks for one.
#
# The acceleration image is the link's shape again, this time turned by atan2(α, −ω²) and scaled
# by √(ω⁴ + α²); **g′** on it gives a_G, the vector from **o′** to **g′**.

# %%
gk.draw.draw_motion_polygons(motion)

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
for link in (3, 4):
    assert math.isclose(motion.alpha[link], float(kin.alpha[link][0]), rel_tol=1e-9)
    aG = kin.a_G(link)[0]
    assert math.dist(motion.a_G[link], aG) <= 1e-9 * math.hypot(*aG)

# %% [markdown]
# ## 4. Inertia loads, and the force polygons
#
# With ω, α and a_G read off the polygons, each link's inertia force is −m a_G and its inertia torque
# −I_G α, combined as in lesson 02 into one resultant offset from G. `kinematics_from_polygons` hands
# those readings to the force route, so everything below comes from the drawing: the force polygons
# and the driving torque T12.

# %%
drawn = gk.kinematics_from_polygons(kin)
forces = gk.construct_forces(drawn, 0)
gk.draw.draw_step_grid(forces)

# %%
print(f"T12 from the polygons: {forces.effort:.2f} N·m (CCW positive)")

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
T12 = float(problem.solve(at=[math.radians(140)]).effort[0])
assert math.isclose(forces.effort, T12, rel_tol=1e-6)

# %% [markdown]
# ## 5. The explorer, with the polygons
#
# `motion=True` adds both polygons at every crank angle, drawn beside the force polygons (the **motion
# polygons** toggle hides them). Drag the crank round: watch ω3 change sign as the coupler swings back,
# and the Coriolis arrow appear on the slotted lever of `gk.load("shaper_six_bar")`.

# %%
ex = gk.explore(problem, motion=True)
ex.position = 140
ex

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
# At 140° the explorer's velocity polygon turns the coupler at the ω3 found above: v_BA = ω3 k × AB.
s, i = ex.scene, ex.index
(vel,) = [poly for poly in s["motion"]["polygons"] if poly["kind"] == "velocity"]
k = 4 * (len(vel["names"]) * i + vel["names"].index("v_BA"))
x0, y0, x1, y1 = vel["vectors"][k:k + 4]
(coupler,) = [link for link in s["links"] if link["number"] == 3]
(ax, ay), (bx, by) = (coupler["points"][name][2 * i:2 * i + 2] for name in "AB")
omega3 = ((bx - ax) * (y1 - y0) - (by - ay) * (x1 - x0)) / ((bx - ax) ** 2 + (by - ay) ** 2)
assert math.isclose(ex.position, 140, abs_tol=1e-9) and s["motion"]["valid"][i]
assert math.isclose(omega3, motion.omega[3], rel_tol=1e-6)

# %% [markdown]
# ## 6. Your turn
#
# Type the id your teacher gave you in place of `"your-id"` and run the cell: you get your own crank
# angle and speed for the same four-bar. **Before you type any answer**, draw the mechanism at your
# angle (AB = 235 mm, B0B = 550 mm, A0B0 = 565 mm), then the velocity polygon on paper at a scale of
# your choosing. Measure v_BA, divide by AB, and that is ω3 (CCW positive). Go on to the acceleration polygon for α3 and a_G. Then type your readings and
# press **Check**: answers within 3 %, or what a careful drawing allows (each line to ±0.5 mm and ±0.5°
# at a worksheet's printed scales), are right, and the feedback names the usual slips (a normal component left out, g′ put at the link's end).

# %%
student = "your-id"  # ← type your own id here
box = gk.exercise("fourbar_polygons", student)
box

# %% [markdown]
# Only once you have checked your own, run the next cell: graphkin's polygons for your variant. Compare
# them with your drawing, step by step.

# %%
mine = gk.exercises.variant("fourbar_polygons", student)
gk.draw.draw_motion_polygons(gk.construct_kinematics(mine.problem.kinematics(), 0))

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
import graphkin.exercises as _ex

_v = _ex.variant("fourbar_polygons", "s001")
_q = _v.exercise.question("omega3")
assert box.exercise.id == "fourbar_polygons"
assert _v.grade({"omega3": _v.expected(_q).text})["questions"][0]["verdict"] == "correct"
