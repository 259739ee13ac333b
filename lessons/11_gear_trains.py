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
# # Lesson 11 — Gear trains and their mesh forces
#
# Lesson 05 solved one pair of spur gears with its inertia. This lesson is about what a gear tooth
# carries and how torque travels through a train, including the train that puzzles most students at
# first sight: the **epicyclic** train, whose gears ride on a rotating arm.
#
# 1. the force on a tooth: tangential and radial components (Wentzell, Example 12.1);
# 2. an epicyclic train: speeds, torques and the free body of the planet (Khurmi & Gupta,
#    Example 13.20);
# 3. your turn.

# %%
# %matplotlib inline
import numpy as np

import graphkin as gk

# %% [markdown]
# ## 1. The force on a tooth
#
# Two involute teeth touch along the **line of action**, a line through the pitch point tilted by the
# **pressure angle** $\phi$ from the common tangent of the pitch circles. Without friction the tooth
# force $W$ lies on that line. Its two components have names:
#
# $$W_t = \frac{T}{r} \quad(\text{tangential: it carries the torque}), \qquad
#   W_r = W_t\tan\phi \quad(\text{radial: it pushes the gears apart}), \qquad
#   W = \frac{W_t}{\cos\phi}.$$
#
# Only $W_t$ does any work. $W_r$ is the price of the involute profile: the bearings carry it for
# nothing. And since the same $W_t$ acts on both pitch circles, a pair changes torque in the ratio of
# its radii, $T_3/T_2 = r_3/r_2$, the inverse of the speed ratio — the power goes through unchanged.
#
# **Wentzell, Example 12.1.** *A 20-tooth pinion of diametral pitch 8 and 20° pressure angle transmits
# 5 hp at 1725 rpm. Find the transmitted force, the separating force and the resultant.* The book
# prints 146.09 lb, 53.17 lb and 155.46 lb. By hand: the pitch radius is $20/8/2 = 1.25$ in, the torque
# $T = 63\,025 \times 5/1725 = 182.7$ lb·in, so $W_t = 182.7/1.25 = 146.1$ lb, $W_r = 53.2$ lb,
# $W = 155.5$ lb.
#
# graphkin works in SI inside; here is the tooth force of the pinion on the gear, $\vec F_{23}$. The
# gears' centres lie on the $x$ axis, so its $y$ component is the tangential one and its $x$
# component the radial one:

# %%
pair = gk.load("spur_pair_wentzell")
(F23,) = pair.solve().force(2, 3)  # one position: one row
lbf = 4.4482216152605  # N
print(f"tangential W_t = {F23[1] / lbf:.2f} lb   (book 146.09 lb)")
print(f"radial     W_r = {F23[0] / lbf:.2f} lb   (book 53.17 lb)")
print(f"resultant  W   = {np.hypot(*F23) / lbf:.2f} lb   (book 155.46 lb)")

# %% [markdown]
# graphkin's forces are 0.04 % above the book's, and all of that is the book's constant: it writes
# 63 000 for 63 025 in $T = 63\,000\,\text{hp}/n$.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
W_t = 63025.0 * 5 / 1725 / 1.25  # lb, 1 hp = 6600 lb·in/s exactly gives 63 025 (to 0.002 %)
assert np.isclose(F23[1] / lbf, W_t, rtol=5e-5)
assert np.isclose(F23[0] / F23[1], np.tan(np.radians(20)), rtol=1e-12)
for ours, book in ((F23[1] / lbf, 146.09), (F23[0] / lbf, 53.17), (np.hypot(*F23) / lbf, 155.46)):
    assert 0.0003 < ours / book - 1 < 0.0006  # "0.04 % above"

# %% [markdown]
# ## 2. An epicyclic train: Khurmi & Gupta, Example 13.20
#
# *An epicyclic train has a sun S, planets P on an arm C and an internal gear (annulus) E. The sun is
# driven with a torque of 100 N·m; the annulus is held; the speed ratio is $N_S/N_C = 5$. Find the
# teeth and the torque needed to hold the annulus.* The book's train: $T_S = 16$, $T_P = 24$,
# $T_E = 64$ teeth; it prints 400 N·m. graphkin's file gives the gears a module of 5 mm (pitch radii 40,
# 60 and 160 mm) and one planet; with the arm at 30°:

# %%
train = gk.load("epicyclic_khurmi")
at_30 = gk.construct_forces(train.kinematics(), 0)
gk.draw.draw_mechanism(at_30)

# %% [markdown]
# **Speeds.** Watch the train from the arm (Willis's method): there the arm stands still and the
# train is an ordinary one. If the sun turns $x$ relative to the arm, the planet turns
# $-x\,T_S/T_P$ and the annulus (teeth inside: the planet's sense) $-x\,T_S/T_E$ relative to it. Add
# the arm's own turn $y$ to everything: the sun turns $y + x$, and the annulus is held, so
# $y - x\,T_S/T_E = 0$:
#
# $$\frac{N_S}{N_C} = 1 + \frac{T_E}{T_S} = 1 + \frac{64}{16} = 5 .$$
#
# **Torques.** Three shafts come out of the train: the sun's, the arm's and the annulus's. The external
# torques on them balance, and (the annulus held, no friction) the power in is the power out:
#
# $$T_S + T_C + T_E = 0, \qquad T_S\,\omega_S + T_C\,\omega_C = 0 .$$
#
# So $T_C = -5\,T_S = -500$ N·m (the arm's load holds it against the sun's drive) and the annulus
# must be held with $T_E = -T_S - T_C = 400$ N·m.
#
# **The planet's free body.** The planet turns freely on its pin, so the moments of its two tooth
# forces about its centre cancel: the sun's and the annulus's tangential components are equal, and
# point the same way. With $W_t = T_S/r_S = 100/0.040 = 2500$ N, each tooth force is
# $W_t/\cos 20^\circ = 2660$ N; their radial parts cancel, and the arm's pin pushes back with
# $2\,W_t = 5000$ N, whose moment about $O$ is $5000 \times 0.100 = 500$ N·m.

# %%
gk.draw.draw_free_body(at_30, 3)

# %% [markdown]
# graphkin solves the same train with its matrix: the arm is the driver, so $T_{12}$ is the arm's
# torque $T_C$; the tooth force of the sun on the planet is $\vec F_{43}$ and the planet's on the
# annulus (the frame) is $\vec F_{31}$.

# %%
solved = train.solve()
(T12,) = solved.effort
(F43,) = solved.force(4, 3)
(F31,) = solved.force(3, 1)
(F23,) = solved.force(2, 3)

# %%
print(f"torque on the arm         T12 = {T12:.1f} N·m")
print(f"sun on planet            |F43| = {np.hypot(*F43):.1f} N")
print(f"planet on annulus        |F31| = {np.hypot(*F31):.1f} N")
print(f"arm's pin on the planet  |F23| = {np.hypot(*F23):.1f} N")
E = 0.160 * np.array([np.cos(np.radians(30)), np.sin(np.radians(30))])  # planet–annulus pitch point
print(f"holding the annulus       T_E = {-gk.cross(E, F31):.1f} N·m   (book 400 N·m)")

# %% [markdown]
# The last line is the moment about $O$ of the planet's push on the annulus, reversed: what the frame
# must supply. The pitch point $E$ of planet and annulus is on the arm's line, 160 mm from $O$.
#
# Give the arm a speed, and the kinematics confirm Willis's ratio — and lesson 10's power check gives
# the arm's torque without a single tooth force:

# %%
turning = gk.solve_kinematics(train.mechanism, train.q, 1.0)  # the arm at 1 rad/s
print(f"ω_sun / ω_arm = {turning.omega[4].item():.3f}")
print(f"T12 by virtual work = {gk.effort_by_virtual_work(train.kinematics()).item():.1f} N·m")

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
assert np.isclose(T12, -500, rtol=1e-12)
assert np.isclose(np.hypot(*F43), 2500 / np.cos(np.radians(20)), rtol=1e-12)
assert np.isclose(np.hypot(*F31), np.hypot(*F43), rtol=1e-12)
assert np.isclose(np.hypot(*F23), 5000, rtol=1e-12)
assert np.isclose(-gk.cross(E, F31), 400, rtol=1e-12)
assert np.isclose(abs(F23 @ E), 0, atol=1e-9 * 5000)  # the pin force has no radial part
assert np.isclose(turning.omega[4].item(), 5, rtol=1e-12)

# %% [markdown]
# A book's figure has three or four planets. They share the tooth forces equally (if the teeth are
# made well enough) but change none of the torques: $T_C$ and $T_E$ are set by the speeds, through
# the power balance, whatever the number of planets.
#
# ## 3. Your turn
#
# The train of section 2 with **your own** torque on the sun and arm angle. Type your id in place of
# `"your-id"` and run the cell.
#
# Work it **by reasoning first**: the arm's torque from the speed ratio and the power balance, the
# tooth forces from the planet's free body. Does the arm's angle change any of them? Then type your
# answers (`"123 N*m CW"`, `"1234 N"`) and press **Check**.

# %%
student = "your-id"  # ← type your own id here
gk.exercise("epicyclic_torques", student)

# %% [markdown]
# Only when you have checked your answers, run the next cell: graphkin's solution of your train.

# %%
mine = gk.exercises.variant("epicyclic_torques", student).problem
print(gk.format_solution(mine, mine.solve()))

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
key = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("epicyclic_torques", student)["questions"]}
T_S = mine.mechanism.loads[0].torque
assert np.isclose(key["T12"], -5 * T_S, rtol=1e-9)
assert np.isclose(key["F43"], T_S / 0.040 / np.cos(np.radians(20)), rtol=1e-9)
assert np.isclose(key["F31"], key["F43"], rtol=1e-9)
