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
# # Lesson 09 — The engine: gas pressure and the inertia of the reciprocating parts
#
# A reciprocating engine is a slider-crank run backwards: the gas pushes the piston, and the crank
# shaft takes the work off. Two forces act on the piston along the line of stroke — the **gas load**
# and the **inertia force of the reciprocating parts** — and the connecting rod carries what is left
# of them to the crank pin, at an angle. This lesson follows that force from the piston to the shaft
# the way Khurmi & Gupta (*Theory of Machines*, ch. 15) do, checks it against graphkin's matrix
# method, and then follows it round a whole turn:
#
# 1. the forces on the piston, and how the rod turns them into a torque;
# 2. Khurmi & Gupta's Example 15.7 by hand and by graphkin;
# 3. the driving torque over a turn: why a constant gas force does no work in a turn;
# 4. your turn: an engine with your own numbers, worked by hand first.

# %%
# %matplotlib inline
import numpy as np

import graphkin as gk

# %% [markdown]
# ## 1. From the piston to the crank shaft
#
# Take the crank $OC$ of radius $r$ at an angle $\theta$ from the **inner dead centre** (I.D.C., the
# crank pointing at the piston), the connecting rod $CP$ of length $l = n\,r$, the piston $P$ on the
# line of stroke through $O$. The rod leans at the angle $\varphi$ with
#
# $$\sin\varphi = \frac{\sin\theta}{n}.$$
#
# **The gas load.** A net pressure $p$ on a bore $D$ pushes the piston with
# $F_L = p\,\dfrac{\pi D^2}{4}$ (less the back pressure on the other face, if any).
#
# **The inertia force.** The reciprocating parts of mass $m_R$ (piston, rings, gudgeon pin, a share
# of the rod) move with the piston. Differentiating the piston's distance from the crank shaft,
# $x = r\cos\theta + \sqrt{l^2 - r^2\sin^2\theta}$, twice at constant $\omega$ gives its acceleration
# towards the crank,
#
# $$a_P = \omega^2 r\left(\cos\theta + \frac{n^2\cos 2\theta + \sin^4\theta}{(n^2 - \sin^2\theta)^{3/2}}\right)
#       \approx \omega^2 r\left(\cos\theta + \frac{\cos 2\theta}{n}\right),$$
#
# the books' two-term approximation on the right (good for long rods; with $n = 4$ it can be 3 % off
# near $\theta = 90^\circ$). d'Alembert's inertia force $F_I = m_R\,a_P$ acts the other way. What
# drives the rod is the **piston effort**
#
# $$F_P = F_L - F_I \qquad(\text{horizontal engine, no friction}).$$
#
# **Through the rod.** The piston is in equilibrium under $F_P$, the rod's thrust $F_Q$ along $CP$
# and the cylinder wall's normal force $F_N$ (the *side thrust*). Resolving along and across the
# stroke:
#
# $$F_Q = \frac{F_P}{\cos\varphi}, \qquad F_N = F_P\tan\varphi .$$
#
# At the crank pin the thrust splits into a part along the crank (into the bearings) and a part
# across it, the **crank effort** $F_T$, whose moment $F_T\,r$ about $O$ turns the crank (the book's
# *turning moment*). graphkin names one torque, the **driving torque** $T_{12}$: the torque of the
# frame (link 1) on the crank (link 2) that keeps the motion, counter-clockwise positive like every
# torque in graphkin. In an engine it is the shaft's load, holding the crank against $F_T$; with the
# crank turning counter-clockwise:
#
# $$F_T = F_Q\,\sin(\theta + \varphi), \qquad T_{12} = -F_T\, r ,$$
#
# so $T_{12}$ is clockwise (negative) while the gas drives the crank.
#
# The picture below is the engine of Example 15.7 at $\theta = 60^\circ$ and the free body of its
# piston, with the two known loads drawn (the rod's thrust and the wall's push are the unknowns).

# %%
engine = gk.load("engine_gas_force")
gk.draw.draw_given(gk.construct_forces(engine.kinematics(), 0), [4])

# %% [markdown]
# ## 2. Khurmi & Gupta, Example 15.7
#
# *A horizontal engine: crank radius 300 mm, connecting rod 1.2 m, bore 0.5 m, reciprocating parts
# 250 kg, 250 rpm. At 60° from the I.D.C. the net pressure on the piston is 0.35 N/mm². Find the
# thrust in the connecting rod, the tangential force on the crank pin and the turning moment.*
# The book prints 50.62 kN, 48.28 kN and 14.484 kN·m.
#
# By hand, with $n = 4$ and $\omega = 2\pi \cdot 250/60 = 26.18$ rad/s:
#
# | step | value |
# |---|---|
# | $F_L = 0.35 \times \pi\,500^2/4$ | 68.72 kN |
# | $F_I = 250 \times 26.18^2 \times 0.3\,(\cos 60^\circ + \cos 120^\circ/4)$ | 19.28 kN |
# | $F_P = F_L - F_I$ | 49.44 kN |
# | $\varphi = \arcsin(\sin 60^\circ/4)$ | 12.50° |
# | $F_Q = F_P/\cos\varphi$ | 50.64 kN |
# | $F_T = F_Q \sin(72.50^\circ)$ | 48.30 kN |
# | $T_{12} = -F_T \times 0.3$ m | −14.49 kN·m |
#
# graphkin does not use these formulas: it writes the three equilibrium equations of every moving
# link with the piston's exact acceleration and solves them together (lesson 01). The rod's force
# on the piston is $\vec F_{34}$, the wall's is $\vec G_{14}$, and $T_{12}$ is section 1's driving
# torque. The crank effort is the moment of the rod's push on the crank pin, $\vec F_{32}$, about $O$,
# divided by $r$.

# %%
solved = engine.solve()
(F34,) = solved.force(3, 4)  # one position: one row
(G14,) = solved.force(1, 4)
(F32,) = solved.force(3, 2)
(T12,) = solved.effort
OC = np.array([0.3 * np.cos(np.pi / 3), 0.3 * np.sin(np.pi / 3)])  # the crank, 300 mm at 60°

# %%
print(f"thrust in the rod   F_Q = |F34|      = {np.hypot(*F34) / 1e3:.2f} kN   (book 50.62 kN)")
print(f"side thrust         F_N = |G14|      = {np.hypot(*G14) / 1e3:.2f} kN")
print(f"crank effort        F_T = OC × F32/r = {gk.cross(OC, F32) / 0.3 / 1e3:.2f} kN   (book 48.28 kN)")
print(f"driving torque      T12 = −F_T r     = {T12 / 1e3:.3f} kN·m (book 14.484 kN·m, its size)")

# %% [markdown]
# The book's figures lie 0.04 % below graphkin's: it rounds $\omega$ to 26.2 rad/s and $\varphi$ to
# 12.5° on the way, and its two-term formula for $a_P$ is 0.03 % short of the exact acceleration
# (77.11 against 77.13 m/s²). The reference test `tests/books/test_khurmi_engine.py` reproduces
# every printed digit from those roundings.
#
# Two things to notice. The inertia force *takes away* 28 % of the gas load here: early in the
# out-stroke the piston is still speeding up, so part of the gas load goes into accelerating the
# 250 kg rather than into the rod. And the side thrust, 11 kN, is what wears cylinders oval: it is
# the price of a rod that leans.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
n, omega, m_R, p_gas = 4.0, 250 * 2 * np.pi / 60, 250.0, 0.35e6 * np.pi * 0.5**2 / 4
phi = np.arcsin(np.sin(np.pi / 3) / n)
a_P = -solved.kinematics.acceleration(4, "P")[0, 0]  # towards the crank, exact
s60 = np.sin(np.pi / 3)
assert np.isclose(a_P, omega**2 * 0.3 * (0.5 + (n**2 * np.cos(2 * np.pi / 3) + s60**4) / (n**2 - s60**2) ** 1.5))
assert 0.03 < ((n**2 - 1) / (n**2 - 1) ** 1.5) / (1 / n) - 1 < 0.035  # the series "3 % off near 90°" at n = 4
F_P = p_gas - m_R * a_P
assert np.isclose(np.hypot(*F34), F_P / np.cos(phi), rtol=1e-9)
assert np.isclose(np.hypot(*G14), F_P * np.tan(phi), rtol=1e-9)
assert np.isclose(gk.cross(OC, F32), F_P / np.cos(phi) * np.sin(np.pi / 3 + phi) * 0.3, rtol=1e-9)
assert np.isclose(-T12, gk.cross(OC, F32), rtol=1e-9)
assert abs(-T12 / 14484 - 1) < 1e-3 and abs(np.hypot(*F34) / 50620 - 1) < 1e-3  # the book, to its rounding
assert 0.27 < m_R * a_P / p_gas < 0.29  # "28 % of the gas load"
assert 10.9e3 < np.hypot(*G14) < 11.05e3  # "11 kN"

# %% [markdown]
# ## 3. The driving torque over a turn
#
# Sweep the same file over a turn and graphkin keeps the gas load at 68.7 kN everywhere — on the
# out-stroke, when the piston moves towards the crank, and on the return, when it moves away. The
# work of a constant force over a closed path is zero, and so is the work of the inertia forces of a
# machine running at constant speed (the kinetic energy comes back to where it started). So the
# **mean of $T_{12}$ over a turn is zero**:

# %%
steady = gk.sweep(engine, 360)
print(f"mean T12, gas load on both strokes: {steady.average:.1e} N·m")

# %% [markdown]
# A real engine does net work only because the pressure on the return stroke is lower. The simplest
# model is a **single-acting engine** with full admission: the gas pushes only on the out-stroke,
# $0 < \theta < 180^\circ$. One more line in the problem file does it — the file's last table is the gas
# load, and an `active` window switches it on for that half-turn only:

# %%
text = gk.catalog.path("engine_gas_force").read_text(encoding="utf-8")
single = gk.parse_problem(text + 'active = { from = "0 deg", to = "180 deg" }\n')
single_cycle = gk.sweep(single, 360)
gk.draw.draw_torque_curve(single_cycle)

# %% [markdown]
# The curve is $T_{12}$, negative while the gas drives the crank and the shaft's load holds it back.
# On the return stroke only the inertia of the reciprocating parts acts: it takes energy from the
# shaft while the piston speeds up and gives it back while it slows down.
#
# Energy says what the mean must be. The gas does work $F_L \times 2r$ per turn (one stroke of
# length $2r$), and the shaft's load takes it out; spread over a turn of $2\pi$ radians,
#
# $$\overline{T_{12}} = -\frac{F_L\,2r}{2\pi} = -\frac{F_L\,r}{\pi}.$$

# %%
print(f"mean T12 from the sweep: {single_cycle.average / 1e3:.3f} kN·m")
print(f"−F_L r / π             : {-68722.3393 * 0.3 / np.pi / 1e3:.3f} kN·m")

# %% [markdown]
# (The last digit differs by the sweep's 1° steps.) The peak is almost four times the mean: this is the fluctuation a flywheel smooths out (lesson 04)
# and the reason engines have several cylinders with their cranks spread round the turn.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
assert abs(steady.average) < 1e-6 * abs(steady.torque).max()
mean_T = 68722.3393 * 0.3 / np.pi
assert abs(-single_cycle.average / mean_T - 1) < 1e-4
assert 3.5 < abs(single_cycle.torque).max() / mean_T < 4.0  # "almost four times"
out = (single_cycle.q > 0.01) & (single_cycle.q < np.pi - 0.01)
assert (single_cycle.torque[out] < 0).mean() > 0.9  # "negative while the gas drives", all but near the dead centres
no_gas = gk.sweep(gk.parse_problem(text.replace('magnitude = "68722.3393 N"', 'magnitude = "0 N"')), 360)
assert abs(no_gas.average) < 1e-6 * abs(no_gas.torque).max()  # inertia alone: no net work

# %% [markdown]
# ## 4. Your turn
#
# A small gas engine (Khurmi & Gupta's Example 15.9: crank 50 mm, rod 200 mm, bore 80 mm, 1 kg of
# reciprocating parts) with **your own** crank angle, speed and gas pressure. Type the id your teacher
# gave you in place of `"your-id"` and run the cell; the box shows your data.
#
# Work it **by hand first**, with the steps of section 2: $F_L$, $F_I$, $F_P$, $\varphi$, then $F_Q$,
# $F_N$ and $T_{12}$. Use the exact $a_P$ of section 1: this engine's rod is short ($n = 4$), and the
# grader allows 1 %. Mind the sense of $T_{12}$ (section 1): the shaft's load holds the crank *against*
# the gas. Type your three answers with their units (`"1234 N"`, `"56.7 N*m CW"`) and press **Check**:
# the grader says which are right and, when one is off, what slip it looks like.

# %%
student = "your-id"  # ← type your own id here
gk.exercise("engine_efforts", student)

# %% [markdown]
# Only when you have checked your answers, run the next cell: graphkin's solution of your engine.
# Compare your $F_I$ with link 4's inertia force there first: most slips start in it.

# %%
mine = gk.exercises.variant("engine_efforts", student).problem
print(gk.format_solution(mine, mine.solve()))

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
key = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("engine_efforts", student)["questions"]}
worked = mine.solve()
assert np.isclose(key["F_Q"], np.hypot(*worked.force(3, 4)[0]), rtol=1e-9)
assert np.isclose(key["T12"], worked.effort[0], rtol=1e-9)
