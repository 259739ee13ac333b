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
# # Lesson 10 — The power check: the driving torque from virtual work
#
# The matrix method (lesson 01) finds the driving torque together with every joint force: three
# equations per moving link, solved at once. If all you need is the torque, there is a shorter road,
# and it is also the best check a designer has on the long one: the **principle of virtual work**, or
# in a machine running at speed, the **power balance**. One equation, no joint forces at all.
#
# 1. why the joint forces drop out, and the equation that is left;
# 2. an engine at one position, by hand (Khurmi & Gupta, Example 15.10);
# 3. the strip cutter over a whole turn, inertia included, against the matrix method;
# 4. what virtual work cannot tell you;
# 5. your turn.

# %%
# %matplotlib inline
import numpy as np

import graphkin as gk

# %% [markdown]
# ## 1. Why the joint forces drop out
#
# With d'Alembert's inertia loads added ($\vec F_{ji} = -m_j\,\vec a_{Gj}$ at $G_j$ and
# $T_{ji} = -I_{Gj}\,\alpha_j$), every link of the mechanism is in equilibrium. Multiply each link's
# equilibrium by any motion it can have — its velocity field — and add over the links: the sum of the
# **powers** of all forces on all links is zero.
#
# Now look at the joint forces in that sum. At a **pin** between links $i$ and $j$, $\vec F_{ij}$ on
# $j$ and $\vec F_{ji} = -\vec F_{ij}$ on $i$ act at one point, which has one velocity: their powers
# cancel. At a **frictionless guide** the normal force is across the sliding and the two links turn
# together: no power. At a **gear mesh** the two pitch circles roll on each other, the pitch points
# have one velocity: no power. So in a frictionless mechanism only the driver, the external loads and
# the inertia loads are left:
#
# $$T_{12}\,\omega_2 \;+\; \sum_{\text{loads}} \vec F\cdot\vec v_P \;+\; \sum_{\text{torques}} T\,\omega
#   \;+\; \sum_{j}\Big(\vec F_{ji}\cdot\vec v_{Gj} + T_{ji}\,\omega_j\Big) \;=\; 0 ,$$
#
# with $\vec v_P$ the velocity of the point a load acts at. Divide by $\omega_2$ and $T_{12}$ is found.
# Only the **velocities** enter — the kinematics you already have — and the inertia loads, which need
# the accelerations. A static problem has no motion, but any motion the linkage allows will do: give
# the crank $\omega_2 = 1$ rad/s (a *virtual* velocity) and the velocities are the velocity ratios.

# %% [markdown]
# ## 2. An engine by hand: Khurmi & Gupta, Example 15.10
#
# *A horizontal engine: crank radius $r = 300$ mm, connecting rod $l = 4.5\,r$. At 30° from the inner
# dead centre the piston effort — gas load 35.34 kN less the inertia of the reciprocating parts,
# 6.48 kN, and friction, 0.6 kN — is $F_P = 28.26$ kN towards the crank. Find the turning moment on
# the crank shaft.* The book prints 5.06 kN·m.
#
# The piston is the only link with a load, and it moves along the stroke. Differentiating the piston's
# position $x = r\cos\theta + \sqrt{l^2 - r^2\sin^2\theta}$ gives its speed towards the crank,
#
# $$v_P = \omega\,r\left(\sin\theta + \frac{\sin 2\theta}{2\sqrt{n^2 - \sin^2\theta}}\right),$$
#
# and the power balance is $T\,\omega = F_P\,v_P$, where $T = -T_{12}$ is the engine's turning moment:
#
# $$T = F_P\,r\left(\sin\theta + \frac{\sin 2\theta}{2\sqrt{n^2 - \sin^2\theta}}\right)
#     = 28.26 \times 0.3 \times (0.5 + 0.0969) = 5.06\ \text{kN·m}.$$
#
# The book takes the long road — the rod's thrust, then its component across the crank — and gets
# the same number. graphkin does it both ways:

# %%
static_engine = gk.load("engine_static_khurmi")
by_power = gk.effort_by_virtual_work(static_engine.kinematics())
by_matrix = static_engine.solve().effort
print(f"turning moment by virtual work:  {-by_power.item() / 1e3:.4f} kN·m")
print(f"turning moment by the matrix:    {-by_matrix.item() / 1e3:.4f} kN·m   (book 5.06 kN·m)")

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
theta, r_crank, n = np.radians(30), 0.3, 4.5
F_P = 35342.917353 - 6480 - 600
by_hand = F_P * r_crank * (np.sin(theta) + np.sin(2 * theta) / (2 * np.sqrt(n**2 - np.sin(theta) ** 2)))
assert np.isclose(-by_power.item(), by_hand, rtol=1e-12)
assert np.isclose(by_power.item(), by_matrix.item(), rtol=1e-12)
assert round(by_hand / 1e3, 2) == 5.06  # the book's printed answer, to its digits

# %% [markdown]
# ## 3. The strip cutter over a turn
#
# The strip cutter of lesson 03 at 900 rpm: three moving links with mass, and during the cut
# ($124^\circ < \theta_{12} < 156^\circ$) a 2 kN force on each blade. At one position in the cut,
# here is every power in the balance but the motor's — what each load puts in (+) or takes out (−):

# %%
cutter = gk.load("strip_cutter")
at_140 = cutter.kinematics(at=np.radians(140))
for name, power in gk.load_powers(at_140).items():
    print(f"{name:<22}{power.item():>10.1f} W")
print(f"{'sum':<22}{sum(gk.load_powers(at_140).values()).item():>10.1f} W")

# %% [markdown]
# The motor must supply the opposite of the sum, so $T_{12} = -\Sigma P/\omega_2$ with
# $\omega_2 = 94.25$ rad/s. Both blades cut, but they do not work equally: blade 3 meets the strip
# head-on, while blade 4 is moving the same way as its cutting force and gives some power back.
# The crank turns at a constant speed: its inertia force is centripetal, across the velocity of
# $G_2$, and it has no inertia torque, so it takes no power. The inertia of
# link 3 gives power back as it slows down, link 4 takes it as it speeds up.
#
# Over a whole turn, the two roads give the same curve:

# %%
cycle = gk.sweep(cutter, 360)
from_power = gk.effort_by_virtual_work(cycle.analysis.kinematics)
print(f"largest |T12 by virtual work − T12 by the matrix| over the turn: "
      f"{np.abs(from_power - cycle.torque).max():.1e} N·m (T12 reaches {np.abs(cycle.torque).max():.0f} N·m)")
gk.draw.draw_torque_curve(cycle)

# %% [markdown]
# They agree to the last digits a computer carries: $10^{-13}$ N·m on a torque of 300 N·m. Two
# different calculations — one through every joint force, one through none — cannot agree like that
# by accident. This is why the power balance is the first test run on any new kinetostatics code,
# graphkin's included (`tests/analytical/test_virtual_work.py` runs it on random linkages of every
# kind).
#
# It also explains the **mean** of the torque curve. Over a turn at constant speed the inertia
# loads give back all they take — the kinetic energy ends where it began — so the mean input power is
# the mean power of the cutting forces alone.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
assert np.abs(from_power - cycle.torque).max() < 1e-9 * np.abs(cycle.torque).max()
powers_140 = gk.load_powers(at_140)
assert powers_140["Fc3 (cutting)"].item() < 0 < powers_140["Fc4 (cutting)"].item()  # "blade 4 gives some back"
assert powers_140["inertia of link 2"].item() == 0
assert powers_140["inertia of link 3"].item() > 0 > powers_140["inertia of link 4"].item()
assert np.isclose(gk.effort_by_virtual_work(at_140).item(), cutter.solve(at=np.radians(140)).effort.item())
inertia_work = cycle.mean(sum(P for k, P in gk.load_powers(cycle.analysis.kinematics).items() if "inertia" in k))
assert abs(inertia_work) < 1e-6 * np.abs(cycle.power).max()  # "give back all they take"

# %% [markdown]
# ## 4. What virtual work cannot tell you
#
# It gives one number per position, the driving effort — nothing about the bearings. To size a pin
# or a guide you still need the joint forces, and so the matrix method or the force polygons.
#
# And it needs a frictionless machine. Friction at a slider takes power $\mu\,|N|\,|v|$, and the normal
# force $N$ is a joint force: the unknown the method set out to avoid. graphkin says so rather than
# give a wrong torque:

# %%
try:
    gk.effort_by_virtual_work(gk.load("slider_crank_friction").kinematics())
except gk.GraphkinError as why:
    print(why)

# %% [markdown]
# ## 5. Your turn
#
# The engine of section 2, static, at **your own** crank angle and gas load (the inertia force,
# 6480 N, and the friction, 600 N, stay). Type your id in place of `"your-id"` and run the cell.
#
# Work it **by hand first**: the piston effort, its speed per unit $\omega$, then the torque from
# $T_{12}\,\omega_2 + \vec F_P\cdot\vec v_P = 0$. Think about the sign before you type: does the gas
# drive the crank in the sense $\theta$ grows (CCW), and which way must the frame then hold it? Type
# $T_{12}$ with its sense (`"1234 N*m CW"`) and press **Check**.

# %%
student = "your-id"  # ← type your own id here
gk.exercise("virtual_work", student)

# %% [markdown]
# Only when you have checked your answer, run the next cell: graphkin's solution of your engine, the
# torque both ways.

# %%
mine = gk.exercises.variant("virtual_work", student).problem
print(f"T12 by virtual work: {gk.effort_by_virtual_work(mine.kinematics()).item():.1f} N·m")
print(f"T12 by the matrix:   {mine.solve().effort.item():.1f} N·m   (negative: clockwise)")

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
key = gk.exercises.key("virtual_work", student)["questions"][0]["answer"]["si"]
assert np.isclose(key, gk.effort_by_virtual_work(mine.kinematics()).item(), rtol=1e-9)
