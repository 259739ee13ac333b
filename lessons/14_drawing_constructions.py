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
# # Lesson 14 — You draw the construction, and it is graded
#
# Lesson 02 showed every step of the graphical method and lesson 08 the velocity and acceleration
# polygons. Reading a number off someone else's drawing teaches little: the method is a **drawing
# skill**. In this lesson *you* draw each step on the mechanism or in the polygon, at the stated
# scale, with your own data, and graphkin grades **what you drew**, not a number read off it:
#
# 1. how to draw in a box;
# 2. the strip cutter during the cut: the inertia resultant's line, a two-force member's line, the
#    point where three forces meet, the force polygon closed tip to tail;
# 3. the shaper's block in its turning slot: one step of the velocity and of the acceleration polygon,
#    with its Coriolis component;
# 4. the drawing as data, and a page to practise on.
#
# Draw first, press **Check**, and only then run the cell that shows graphkin's construction.

# %%
# %matplotlib inline
import json

import graphkin as gk

# %% [markdown]
# ## 1. Drawing in a box
#
# Each box shows what you are given at its scale (`1 mm = 10 mm` means one millimetre on your screen is
# ten on the machine) and says, under the buttons, what to draw next:
#
# | to draw | with the mouse | with the keys |
# |---|---|---|
# | a line | click two of its points (or press, drag, release) | arrows move the cross (Shift: 10 mm), Enter places |
# | a point | click it | Tab jumps to the next named point, Enter places |
# | a vector | click its tail, then its tip | as a line |
#
# A click near a named point ($G_3$, a pin, the polygon's pole $o$) **snaps** to it, and a line drawn
# nearly parallel to a direction the drawing states (a link, a known force) snaps to that direction:
# a ring shows the snap. Hold Alt to place a point without snapping. **Undo** (or Ctrl+Z) takes back
# the last point; **Clear** starts again. **Check** grades the drawing: the elements at fault turn red,
# and the feedback names the slip when it is one the grader knows.
#
# ## 2. The strip cutter during the cut
#
# Type the id your teacher gave you in place of `"your-id"` and run the cell: you get your own crank
# angle, speed and cutting force for the four-bar of Söylemez §6.4.1 (lesson 02 solved it at 140°).

# %%
student = "your-id"  # ← type your own id here
mine = gk.exercises.variant("draw_strip_cutter", student)
for given in mine.sheet()["data"]:
    print(given["shown"], f"({given['label']})")

# %% [markdown]
# **(a) The inertia resultant.** The coupler's inertia force $-m_3\vec a_{G_3}$ acts at $G_3$ and its
# inertia torque $-I_{G_3}\alpha_3$ turns it: together they are **one** force $\vec R_{3i}$ of the same
# size and direction, on a line offset from $G_3$ by $h = |T_{3i}|/|F_{3i}|$, on the side whose moment
# about $G_3$ has the torque's sense. Draw that line (the box gives $\vec F_{3i}$ at $G_3$, and the
# torque in its question):

# %%
gk.draw_answer("draw_strip_cutter", "R3i", student)

# %% [markdown]
# **(b) A two-force member.** Superposition (lesson 02) takes the coupler's loads alone first: the
# rocker then carries two forces only, at its two pins, so they act along the line through the pins.
# Draw the line of action of $\vec F'_{43}$:

# %%
gk.draw_answer("draw_strip_cutter", "F43", student)

# %% [markdown]
# **(c) A three-force member.** The coupler then carries three forces: $\vec R_3$ (its inertia
# resultant and the cut), $\vec F'_{43}$ along the line you drew, and $\vec F'_{23}$ through $A$.
# Three forces in equilibrium meet at one point $I_3$; the box draws the two known lines. Place $I_3$:

# %%
gk.draw_answer("draw_strip_cutter", "I3", student)

# %% [markdown]
# **(d) The force polygon.** $\vec R_3$ is drawn from the pole $o$. Close the polygon tip to tail:
# $\vec F'_{43}$ along its line from the tip of $\vec R_3$, then $\vec F'_{23}$ back to $o$ along the
# line through $A$ and $I_3$. Their order and their senses matter:

# %%
gk.draw_answer("draw_strip_cutter", "polygon3", student)

# %% [markdown]
# ### Check your answer
#
# Only once you have checked all four, run the next cell: graphkin's construction for your data,
# every step with its caption. Compare it with yours, step by step.

# %%
gk.draw.draw_step_grid(mine.construction)

# %% [markdown]
# ## 3. A block in a turning slot: the Coriolis component
#
# In the shaper (lesson 08's polygons, Marghitu's Example 6.1) the crank's block $B_2$ slides in the
# slotted lever 3, which turns. $B_3$ is the lever's point under the block. Its velocity is
# $\vec v_{B_3} = \vec v_{B_2} + \vec v_{B_3B_2}$ (the sliding, along the slot) and also
# $\vec v_{B_3} = \omega_3 \times \vec r_{DB}$ (turning about $D$, perpendicular to $DB$): draw both
# from what the polygon gives. For the acceleration add the Coriolis component
# $2\,\vec\omega_3 \times \vec v_{B_3B_2}$: perpendicular to the slot, its sense the sliding velocity's
# turned by 90° in the sense of $\omega_3$. Reversing it is the classic slip; the grader names it.

# %%
shaper = gk.exercises.variant("draw_shaper_polygons", student)
for given in shaper.sheet()["data"]:
    print(given["shown"], f"({given['label']})")
gk.draw_answer("draw_shaper_polygons", "vB3", student)

# %%
gk.draw_answer("draw_shaper_polygons", "aB3", student)

# %% [markdown]
# Then, and only then, graphkin's polygons for your crank angle:

# %%
gk.draw.draw_motion_polygons(gk.construct_kinematics(shaper.problem.kinematics(), 0))

# %% [markdown]
# ## 4. Your drawing is data
#
# What you drew is kept as numbers, not as a picture: each line by two of its points, each point and
# each vector's tail and tip, in the mechanism's coordinates (metres) or the polygon's (newtons, m/s,
# m/s²). The box writes it, with the answer's name, in an output under itself: it is saved with the
# notebook and is what your teacher's grader reads. Nothing you type is run to grade it.
#
# The grader compares each element with the right construction within what a careful drawing allows
# at the box's scale, and then with the drawings of the usual slips, which it names:
#
# | slip | what was drawn |
# |---|---|
# | `wrong_side` | the resultant offset by $h$ on the wrong side of $G$ |
# | `through_G` | the resultant through $G$, the inertia torque left out |
# | `scale_factor` | a length or a force read off at ten times (or a tenth of) the scale |
# | `wrong_member` | a member with three forces taken as a two-force member |
# | `wrong_order`, `sense_reversed` | a polygon closed in the wrong order, or an arrow reversed |
# | `coriolis_reversed`, `normal_outward` | the Coriolis component reversed; a normal component away from the centre |
#
# Here is a drawing as the grader reads it: the right line of (a) for the sample student `s001`, as
# the teacher's key holds it (made from the construction itself), and graded.

# %%
sample = gk.exercises.variant("draw_strip_cutter", "s001")
key = {q["id"]: q["answer"] for q in sample.key()["questions"]}
right = key["R3i"]["drawing"]
print(right[:160], "…")
print(sample.grade({"R3i": right})["questions"][0]["verdict"])

# %% [markdown]
# To practise away from the course, `graphkin exercise practice draw_strip_cutter --student ID -o
# practice.html` writes one page that works offline: draw, press Check, and the page says which
# construction your drawing matches. It records no grade and sends nothing.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
_kinds = {q.id: q.draw for q in sample.exercise.questions}
assert _kinds == {"R3i": "inertia-line", "F43": "two-force-line", "I3": "concurrency", "polygon3": "force-polygon"}
assert {q.draw for q in shaper.exercise.questions} == {"velocity-step", "acceleration-step"}
for _v in (sample, gk.exercises.variant("draw_shaper_polygons", "s001")):
    for _k in _v.key()["questions"]:
        _r = {r["id"]: r for r in _v.grade({_k["id"]: _k["answer"]["drawing"]})["questions"]}[_k["id"]]
        assert _r["verdict"] == "correct", (_v.exercise.id, _k["id"], _r)
# A line through G (the inertia torque left out) is named as that slip, as the table says.
_through = next(t for t in gk.exercises.task_of(sample, "R3i", practice=True)["check"]["targets"]
                if t["slip"] == "through_G")
_r = sample.grade({"R3i": json.dumps({**json.loads(right), "elements": _through["elements"]})})["questions"][0]
assert (_r["verdict"], _r["slip"]) == ("slip", "through_G"), _r
_box = gk.draw_answer("draw_strip_cutter", "R3i", "s001", drawing=right)
assert _box.check()["verdict"] == "correct"
assert mine.construction.valid
