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
# In this lesson you find the forces in a linkage whose **motion is already known**.
# That is *kinetostatics*: a dynamics problem turned into a statics problem.
#
# You will
#
# 1. see why adding inertia loads turns every moving link into a body in equilibrium;
# 2. solve a single rotating link by hand, as a 3 × 3 linear system, and with `graphkin`;
# 3. solve a four-link double slider (9 unknowns) and compare every number with the textbook;
# 4. solve the same mechanism at other positions, to see that nothing was typed in by hand;
# 5. solve both problems again with **your own data**, and have your answers checked.
#
# All numbers inside `graphkin` are SI (m, kg, s, N, rad). We convert to mm, degrees and N·mm
# only when printing, to match the books.
#
# The checks that keep the lesson honest (the numbers quoted in the text are compared there with
# what `graphkin` computes) are collected at the very end, out of your way.

# %%
import math

import numpy as np

import graphkin as gk

np.set_printoptions(precision=4, suppress=True)


def show(v, unit="N", digits=4):
    """A plane vector as the books write it: magnitude ∠ angle."""
    size, angle = gk.polar(v)
    return f"{size:.{digits}g} {unit} ∠ {angle:.2f}°"


# %% [markdown]
# ## 1. The idea: d'Alembert's principle
#
# Newton's second law for a rigid link moving in the plane reads
#
# $$\sum \vec F = m\,\vec a_G, \qquad \sum M_G = I_G\,\alpha ,$$
#
# where $G$ is the centre of mass, $I_G$ the moment of inertia about $G$ and $\alpha$ the
# angular acceleration. In a mechanism driven at a **known** input motion, the kinematic
# analysis gives $\vec a_G$ and $\alpha$ of every link *before* we know any force. So the
# right-hand sides are known numbers, and we may move them to the left:
#
# $$\sum \vec F + \underbrace{(-m\,\vec a_G)}_{\vec F_i} = 0, \qquad
#   \sum M_G + \underbrace{(-I_G\,\alpha)}_{T_i} = 0 .$$
#
# This is **d'Alembert's principle**: add an *inertia force* $\vec F_i = -m\vec a_G$ acting at $G$
# and an *inertia torque* $T_i = -I_G\alpha$ as if they were ordinary loads, and then each moving
# link is in **static equilibrium**. Each moving link gives **3 scalar equations**
# ($\Sigma F_x = 0$, $\Sigma F_y = 0$, $\Sigma M_G = 0$), so a mechanism with $n$ moving links
# gives $3n$ equations for the unknown joint forces and the driving effort.
#
# **Sign convention** (used everywhere in `graphkin` and in these lessons):
#
# * link 1 is the frame (ground);
# * $\vec F_{ij}$ is the force that link $i$ exerts **on** link $j$; by Newton's third law
#   $\vec F_{ji} = -\vec F_{ij}$;
# * angles, angular velocities, accelerations and torques are positive **counter-clockwise (CCW)**;
# * $T_{12}$ is the torque the frame (the motor) applies to link 2.

# %% [markdown]
# ## 2. A single link in pure rotation
#
# The simplest case: one bar pivoted to the frame at $O_2$, driven by a motor torque $T_{12}$,
# with a known external force $\vec F_P$ at its tip. The catalog problem `single_link` follows
# the example in Norton, *Design of Machinery*, §11.2 (the numbers are our own).

# %%
p = gk.load("single_link")
print(p.title)
print(p.source)
print(p.notes)

# %% [markdown]
# ### The link's data
#
# A problem file describes the link in its own coordinates (the $x$-axis along the bar).
# `graphkin` computed the mass properties from the `rod` shape: for a thin rod
# $I_G = mL^2/12$.

# %%
mech = p.mechanism
bar = mech.link(2)
print("link 2:", bar.name)
print("  points (local, m):", dict(bar.points))
print("  mass m  =", bar.mass, "kg")
print("  G       =", bar.G, "m (local)")
print(f"  I_G     = {bar.I_G:.6f} kg·m²   (m L²/12 = {2.0 * 0.25**2 / 12:.6f})")
print("external loads:", [(ld.name, ld.point, show(ld.force)) for ld in mech.loads])
print("driver input: θ =", np.degrees(p.q), "deg, ω =", p.q_dot, "rad/s, α =", p.q_ddot, "rad/s²")

# %% [markdown]
# ### Step 1: kinematics
#
# For a link turning about a fixed pivot the centre of mass has the acceleration
# $\vec a_G = \alpha\,\hat k\times\vec r_G - \omega^2\,\vec r_G$ (tangential plus centripetal part).
# We let `graphkin` do it and check the formula.

# %%
k = p.kinematics()
theta2, omega2, alpha2 = k.theta[2][0], k.omega[2][0], k.alpha[2][0]
rG = k.G(2)[0]
aG = k.a_G(2)[0]
print(f"θ2 = {math.degrees(theta2):.1f}°, ω2 = {omega2} rad/s, α2 = {alpha2} rad/s²")
print("r_G =", rG, "m")
print("a_G =", aG, "m/s² =", show(aG, "m/s²"))

by_hand = alpha2 * np.array([-rG[1], rG[0]]) - omega2**2 * rG
print("a_G by the formula =", by_hand, "m/s²")

# %% [markdown]
# ### Step 2: inertia loads
#
# `bar_result.inertia(2)` gives $\vec F_i = -m\vec a_G$, $T_i = -I_G\alpha$ and the distance
# $h = |T_i|/|\vec F_i|$ by which the single equivalent inertia force is shifted from $G$.

# %%
bar_result = p.solve()
inert = bar_result.inertia(2)
print("F_i =", inert.F[0], "N =", show(inert.F[0]))
print(f"T_i = {inert.T[0]:.4f} N·m  (negative: clockwise)")
print(f"h   = {inert.h[0] * 1e3:.3f} mm")

# %% [markdown]
# ### Step 3: the equilibrium equations as a matrix
#
# Unknowns: the pin force $\vec F_{12} = (F_{12x}, F_{12y})$ of the frame on the bar at $O_2$, and the
# driving torque $T_{12}$. Three unknowns, three equations:
#
# $$\begin{aligned}
# F_{12x} + F_{Px} + F_{ix} &= 0\\
# F_{12y} + F_{Py} + F_{iy} &= 0\\
# (\vec r_{O_2} - \vec r_G)\times\vec F_{12} + T_{12} + (\vec r_P - \vec r_G)\times\vec F_P + T_i &= 0
# \end{aligned}$$
#
# Keep the unknowns on the left and move everything known to the right-hand side: this is
# $[A]\{x\} = \{b\}$. `gk.assemble(bar_result)` builds it; `format(0)` prints it for position 0.
# (A 2-D cross product is the scalar $a_x b_y - a_y b_x$.)

# %%
system = gk.assemble(bar_result)
print(system.format(0))

# %% [markdown]
# We solve it with plain numpy and compare with what `p.solve()` found.
# `bar_result["F12"]` is an (n, 2) array — one row per position; here there is one position.

# %%
x = np.linalg.solve(system.A[0], system.b[0])
for name, value in zip(system.unknowns, x):
    print(f"{name:>5} = {value:10.4f}")

print()
print("graphkin: F12 =", bar_result["F12"][0], "N =", show(bar_result["F12"][0]))
print(f"graphkin: T12 = {bar_result['T12'][0]:.4f} N·m")

# %% [markdown]
# ### Step 4: check $T_{12}$ by hand
#
# Take moments about the **fixed pivot** $O_2$ instead of about $G$: the unknown pin force passes
# through $O_2$ and drops out, leaving one equation in one unknown.
#
# For a point of a link turning about $O_2$, $\vec r_G\times(-m\vec a_G) = -m\,r_G^2\,\alpha$ (the
# centripetal part is parallel to $\vec r_G$ and has no moment). Adding the inertia torque
# $-I_G\alpha$ gives $-(I_G + m\,r_G^2)\,\alpha = -I_O\,\alpha$, where
#
# $$I_O = I_G + m\,r_G^2 \qquad \text{(parallel-axis theorem).}$$
#
# So $\;T_{12} + \vec r_P\times\vec F_P - I_O\,\alpha = 0$, that is
#
# $$T_{12} = I_O\,\alpha - \vec r_P\times\vec F_P .$$

# %%
m, L = 2.0, 0.250  # kg, m
I_G = m * L**2 / 12
I_O = I_G + m * (L / 2) ** 2
rP = k.position(2, "P")[0]
FP = np.array(mech.loads[0].force)
T12_hand = I_O * alpha2 - gk.cross(rP, FP)
print(f"I_G = {I_G:.6f} kg·m², I_O = {I_O:.6f} kg·m² (= m L²/3 = {m * L**2 / 3:.6f})")
print(f"I_O α = {I_O * alpha2:.4f} N·m,  r_P × F_P = {gk.cross(rP, FP):.4f} N·m")
print(f"T12 by hand = {T12_hand:.4f} N·m,  graphkin = {bar_result['T12'][0]:.4f} N·m")

# %% [markdown]
# The motor must hold the bar back (clockwise torque): the tip force pushes harder than the
# bar's inertia resists. The pin force follows from the two force equations,
# $\vec F_{12} = m\vec a_G - \vec F_P$. Everything together, with textbook units:

# %%
print(gk.format_solution(p, bar_result))

# %% [markdown]
# ## 3. The double slider (Söylemez, §6.4)
#
# Now a mechanism with three moving links: slider 2 moves along the $x$-axis at a constant
# 2 m/s, slider 4 along the $y$-axis, and the heavy rod 3 (500 mm, 5 kg) joins them with pins at
# $A$ and $B$. The sliders are massless, there is no friction and no gravity.

# %%
p = gk.load("double_slider")
mech = p.mechanism
print(p.title)
print(p.source)
print(p.notes)
for joint in mech.joints:
    print("joint:", joint.label)
print("moving links:", mech.moving, "  driver:", mech.driver)

# %% [markdown]
# ### Naming the forces
#
# * At a **pin** (revolute joint) the force has two unknown components: $\vec F_{23}$, $\vec F_{34}$.
# * At a **prismatic pair** (slider in a guide) the reaction is written $\vec G_{ij}$, a *guide
#   force*. Without friction it is **normal to the guide**, so its direction is known; what is
#   unknown is its size $N$ and *where along the guide* it acts. `graphkin` uses a normal force $N$
#   and a couple $C$ as the two unknowns (the offset of the line of action is $e = C/N$).
# * The slider driver pushes link 2 **along** its guide; that force is the input effort and is
#   called $\vec F_{12}$. So between the frame and link 2 there are two forces: the guide
#   reaction $\vec G_{12}$ (normal to the guide) and the driving force $\vec F_{12}$ (along it).
#
# Count: 2 + 2 (pins) + 2 + 2 (guides) + 1 (driver) = 9 unknowns, and 3 moving links × 3 = 9
# equations. The problem is statically determinate.

# %%
result = p.solve()
print("forces in the result:", result.names())
print("valid position:", result.valid)

# %% [markdown]
# ### Free-body bookkeeping
#
# For each moving link, list every force that acts **on** it: for each neighbour $i$ the force
# `result.force(i, j)` of $i$ on $j$. Notice $\vec F_{32} = -\vec F_{23}$ appearing on two
# different free bodies. Link 2 also carries the driving force, and link 3 its inertia loads.
# Every list must add up to zero.

# %%
sums = {}  # link → the sum of the forces on it
for j in mech.moving:
    print(f"link {j} ({mech.link(j).name}):")
    total = np.zeros(2)
    for joint in mech.joints_of(j):
        (i,) = [n for n in joint.links if n != j]
        F = result.force(i, j)[0]
        total += F
        print(f"   {result.name_of(i, j):>4} = {show(F):<22}  ({joint.label})")
    if j == mech.driver.link:
        F = result.driver_force()[0]
        total += F
        print(f"   {'F12':>4} = {show(F):<22}  (driver, along the guide)")
    if mech.link(j).mass > 0:
        F = result.inertia(j).F[0]
        total += F
        print(f"   {'F_i':>4} = {show(F):<22}  (inertia force at G)")
    else:
        print("         massless: no inertia loads")
    print(f"   sum of forces = {total}")
    sums[j] = total

# %% [markdown]
# ### The inertia loads of the rod
#
# Slider $A$ moves at a constant speed and $G_3$ is the middle of $AB$, so $x_G = x_A/2$ has no
# acceleration: $\vec a_{G3}$ — and the inertia force — are vertical. The rod also has an angular
# acceleration, hence an inertia torque; $h = |T_i|/|F_i|$ is the distance by which the
# single resultant inertia force is shifted from $G_3$.

# %%
k = result.kinematics
i3 = result.inertia(3)
print(f"θ3 = {math.degrees(k.theta[3][0]):.3f}°,  ω3 = {k.omega[3][0]:.4f} rad/s,  α3 = {k.alpha[3][0]:.4f} rad/s²")
print("a_G3 =", show(k.a_G(3)[0], "m/s²"))
print("F3i  =", show(i3.F[0]))
print(f"T3i  = {i3.T[0] * 1e3:.1f} N·mm  ({'CW' if i3.T[0] < 0 else 'CCW'})")
print(f"h    = {i3.h[0] * 1e3:.2f} mm")

# %% [markdown]
# ### The 9 × 9 system
#
# Columns are the unknowns (forces of the lower-numbered link on the higher one); rows are the
# three equilibrium equations of links 2, 3 and 4. $N_{12}$ and $N_{14}$ are measured along
# $\hat k\times\hat u$, the guide direction turned by +90°. Entries such as `1e-15` or `6e-17`
# are rounding noise of a zero.

# %%
system = gk.assemble(result)
print(system.format(0))

# %%
sol = dict(zip(system.unknowns, np.linalg.solve(system.A[0], system.b[0])))
for name, value in sol.items():
    print(f"{name:>5} = {value:10.4f}")

# %% [markdown]
# The couples $C_{12}$ and $C_{14}$ come out zero: every force on a massless slider passes through
# its pin, so the guide reaction also passes through the pin ($e = 0$).
#
# ### Comparison with the book
#
# The book prints four or five significant digits and rounds intermediate results
# (for example it divides the rounded 865 N·mm by the rounded 25.97 N to get $h$). So we do not
# expect exact agreement, only agreement to a few tenths of a percent. For a vector we compare
# the whole vector: $|\vec F_\text{graphkin} - \vec F_\text{book}| / |\vec F_\text{book}|$, which
# catches an error in direction as well as in size (0.3 % corresponds to about 0.17°).
# The book writes angles in $[0°, 360°)$, `graphkin` in $(-180°, 180°]$: $270° = -90°$.

# %%
def vec(size, angle_deg):
    a = math.radians(angle_deg)
    return np.array([size * math.cos(a), size * math.sin(a)])


# name, book value, graphkin value, unit. Vectors are given as (size, angle°) for the book.
rows = [
    ("θ3", 113.578, math.degrees(k.theta[3][0]), "°"),
    ("y_B", 458.258, k.position(4, "B")[0, 1] * 1e3, "mm"),
    ("ω13", 4.364, k.omega[3][0], "rad/s"),
    ("α13", 8.312, k.alpha[3][0], "rad/s²"),
    ("a_G3", (5.194, 270), k.a_G(3)[0], "m/s²"),
    ("F3i", (25.97, 90), i3.F[0], "N"),
    ("T3i", -865, i3.T[0] * 1e3, "N·mm"),  # 865 N·mm clockwise
    ("h", 33.31, i3.h[0] * 1e3, "mm"),
    ("F43", (7.555, 180), result["F43"][0], "N"),
    ("F23", (27.04, -73.78), result["F23"][0], "N"),
    ("F12", (7.555, 0), result["F12"][0], "N"),
    ("G12", (25.97, 270), result["G12"][0], "N"),
]

print(f"{'':6}{'book':>22}{'graphkin':>24}   {'unit':<7}{'rel. diff':>10}")
worst = 0.0
diffs = {}  # name → relative difference from the book
for name, book, ours, unit in rows:
    if isinstance(book, tuple):
        ref = vec(*book)
        diff = np.linalg.norm(ours - ref) / np.linalg.norm(ref)
        size, angle = gk.polar(ours)
        book_text, ours_text = f"{book[0]:g} ∠ {book[1]:g}°", f"{size:.4f} ∠ {angle:.2f}°"
    else:
        diff = abs(ours - book) / abs(book)
        book_text, ours_text = f"{book:g}", f"{ours:.4f}"
    worst = max(worst, diff)
    diffs[name] = diff
    print(f"{name:6}{book_text:>22}{ours_text:>24}   {unit:<7}{diff:>9.3%}")
print(f"\nlargest difference: {worst:.3%}")

# %% [markdown]
# Two relations the book reads straight off its force polygons are exact here:
#
# * the sliders are massless and there is no friction, so the rod is held only by the two pin
#   forces and its own inertia force. Slider 4 can only push horizontally (its guide is vertical),
#   so $\vec F_{43}$ is horizontal; slider 2 pushes with $\vec F_{23} = -\vec F_{43} - \vec F_{3i}$;
# * on slider 2 the guide takes the vertical part ($\vec G_{12} = -\vec F_{3i}$) and the driver the
#   horizontal part ($\vec F_{12} = -\vec F_{43}$).

# %%
print("G12 =", show(result["G12"][0]), "    −F3i =", show(-i3.F[0]))
print("F12 =", show(result["F12"][0]), "     −F43 =", show(-result["F43"][0]))
print("G14 =", show(result["G14"][0]), "      F43 =", show(result["F43"][0]))

# %% [markdown]
# ## 4. Other positions: nothing is hard-coded
#
# The book works at $x_A = 200$ mm. `p.solve(at=[...])` takes other values of the input
# coordinate, in **SI units** (metres for a slider); the speed of slider 2 stays 2 m/s.
# Here is $x_A = 300$ mm:

# %%
r300 = p.solve(at=[0.3])
print(gk.format_solution(p, r300))

# %% [markdown]
# An independent check, without any free-body diagram: with no friction the joint forces do no
# net work, so the power of the driver must balance the power of the inertia loads,
#
# $$\vec F_{12}\cdot\vec v_A + \vec F_{3i}\cdot\vec v_{G3} + T_{3i}\,\omega_3 = 0 .$$

# %%
k300 = r300.kinematics
i300 = r300.inertia(3)
P_driver = r300["F12"][0] @ k300.velocity(2, "A")[0]
P_inertia = i300.F[0] @ k300.v_G(3)[0] + i300.T[0] * k300.omega[3][0]
print(f"driver power  {P_driver:9.4f} W")
print(f"inertia power {P_inertia:9.4f} W")
print(f"sum           {P_driver + P_inertia:9.1e} W")

# %% [markdown]
# `at` may hold many positions at once: every result array then has one row per position.
# A sweep of slider 2 from 50 mm to 450 mm:

# %%
xs = np.linspace(0.05, 0.45, 9)
sweep = p.solve(at=xs)
ks = sweep.kinematics
print(f"{'x_A [mm]':>9}{'θ3 [°]':>9}{'ω3 [rad/s]':>12}{'α3 [rad/s²]':>13}{'F12 [N]':>10}{'G12 [N]':>10}")
for n, xa in enumerate(xs):
    print(f"{xa * 1e3:9.0f}{math.degrees(ks.theta[3][n]):9.2f}{ks.omega[3][n]:12.3f}{ks.alpha[3][n]:13.3f}"
          f"{sweep.effort[n]:10.3f}{gk.polar(sweep['G12'][n])[0]:10.3f}")

# %% [markdown]
# The driving force grows very fast as $x_A$ approaches the rod length (500 mm): the rod then
# lies almost along the $x$-axis, slider 4 must move very fast for a small motion of slider 2,
# and $\omega_3$, $\alpha_3$ and the inertia loads blow up. At $x_A = 500$ mm the mechanism is
# at a dead point. The row for 200 mm repeats the book's problem.

# %% [markdown]
# ## 5. Try it yourself
#
# A problem file is plain text, so you can change it and solve again. The cell below doubles the
# speed of slider 2. **Before you run it**, predict: by what factor should $F_{12}$ change?
# (Hint: with $a_A = 0$, every velocity is proportional to $v_A$ and every acceleration to
# $v_A^2$.)
#
# Then try on your own:
#
# * give slider 2 an acceleration, e.g. `a = "3 m/s^2"`, and explain the sign of the change in $F_{12}$;
# * in `single_link`, find the angular acceleration for which $T_{12} = 0$ (use the hand formula);
# * make the rod's sliders heavy (e.g. `gk.mass = "1 kg"` for link 4) and see which of the relations
#   $\vec G_{12} = -\vec F_{3i}$, $\vec F_{12} = -\vec F_{43}$ still hold.

# %%

text = gk.catalog.path("double_slider").read_text()
text = text.replace('v = "2 m/s"', 'v = "4 m/s"')  # edit here
mine = gk.parse_problem(text, file="my double slider")
mine_result = mine.solve()
print(f"F12 = {mine_result.effort[0]:.4f} N   (v = 2 m/s gave {result.effort[0]:.4f} N)")
print(f"ratio: {mine_result.effort[0] / result.effort[0]:.3f}")

# %% [markdown]
# ### The worked solutions, to keep
#
# Everything above, written out as a textbook solution — the given data, the sign convention, each
# link's kinematics with the numbers substituted, the inertia loads, the matrix [A]{x} = {b} and its
# solution, the graphical route step by step, and both routes side by side — is in the handouts
# [`single_link.pdf`](../figures/handouts/single_link.pdf) and
# [`double_slider.pdf`](../figures/handouts/double_slider.pdf) (rebuilt by `make figures`). Make your
# own, as PDF, HTML or Markdown, from a terminal:
#
# ```sh
# graphkin handout double_slider -o double_slider.pdf
# graphkin handout double_slider_forces --student YOUR_ID -o my_sheet.pdf   # your own data, no answers
# ```

# %% [markdown]
# ## 6. Your turn
#
# Now the two problems of this lesson with **your own data**. Every student gets different
# numbers, drawn from their id, and the answers are checked against a key solved from exactly the
# numbers you see. A wrong answer gets a sentence of feedback; when the grader recognises the slip
# (the force of the wrong link, a torque with the wrong sense, mm read as m) it says so, and the
# answer earns part of the points.
#
# **Type your own id** (for example your student number) between the quotes below, in place of
# `"your-id"`, and run the cells of this section. (The lesson comes with the placeholder so that it
# can be run and tested as it is.)

# %%

student = "your-id"  # ← type your own id here

# %% [markdown]
# ### 6.1 The single link, with your mass and angle
#
# Work it out as in section 2: step 4 gives $T_{12}$ in one line, and the two force equations give
# $\vec F_{12} = m\vec a_G - \vec F_P$. (To check your hand work with `graphkin`, change
# `gk.mass = "2 kg"` and `theta = "30 deg"` in the problem text, as in section 5.) Type each answer in
# its box and press **Check**, as often as you like. Write a force as magnitude and direction,
# `12.3 N at -45 deg` (or `12.3 N ∠ -45°`), or as components, `(8.7, -8.7) N`; a torque with its
# sense, `4.5 N*m CW`.

# %%
gk.exercise("single_link", student)

# %% [markdown]
# If you prefer code to boxes, put your answers in a dictionary (question → answer as you would
# type it) and print `gk.exercises.check`: it gives the same feedback. Empty answers are reported as
# missing.

# %%
answers = {"F12": "", "T12": ""}  # e.g. "12.3 N at -45 deg" and "4.5 N*m CW"
print(gk.exercises.check("single_link", student, answers))

# %% [markdown]
# ### 6.2 The double slider, at your position and speed
#
# Five answers from the method of section 3. You can find them with the free bodies by hand, or
# with `graphkin`: `p.at_speed(v).solve(at=[x])` solves the double slider of section 3 at your
# speed `v` [m/s] and position `x` [m].

# %%
gk.exercise("double_slider_forces", student)

# %% [markdown]
# ### 6.3 What the feedback looks like
#
# A made-up student, `"demo"`, answers the double slider with three classic slips: they give
# $\vec F_{32}$ where $\vec F_{23}$ is asked, take the driving force with the wrong sign, and type
# $h$ in metres into a question that reads a bare number in millimetres. The other two answers are
# right. (The folded cell below makes these answers from the demo student's key; you need not
# read it.)

# %% jupyter={"source_hidden": true}
def slipped_answers(name, student):
    """Answers to the double slider exercise with three typical slips, made from the key (for the demo only)."""
    key = {q["id"]: q["answer"] for q in gk.exercises.key(name, student)["questions"]}
    return {
        "F23": show(-np.array(key["F23"]["si"])),  # F32 = −F23 given for F23
        "F34": key["F34"]["text"],  # right
        "G12": key["G12"]["text"],  # right
        "F12": f"{-key['F12']['si']:.4g} N",  # the sign of the driving force reversed
        "h3": f"{key['h3']['si']:.4g}",  # h in metres, where a bare number is read in mm
    }


# %%
demo = slipped_answers("double_slider_forces", "demo")
print(demo)
print(gk.exercises.check("double_slider_forces", "demo", demo))

# %% [markdown]
# Each slip is named and earns half a point; the feedback says what to look at again but does not
# give the value. Now check your own.

# %% [markdown]
# ## Checks (for the course maintainers; students may skip)
#
# Every number this lesson quotes, and every claim it makes, is checked here against the variables
# of the cells above, so that a change in `graphkin` that breaks the lesson fails the notebook test.
# (If you edited an "edit here" cell, the checks of section 5 may fail: that is expected.)

# %% [markdown]
# ### Section 2: a single link

# %%
assert np.allclose(aG, by_hand)
assert math.isclose(bar.mass, m) and math.isclose(bar.I_G, I_G)  # the data typed in step 4
assert len(x) == 3  # three unknowns, three equations
assert np.allclose(x[:2], bar_result["F12"][0])
assert np.isclose(x[2], bar_result["T12"][0])
assert math.isclose(T12_hand, bar_result["T12"][0], rel_tol=1e-12)
assert bar_result["T12"][0] < 0  # "the motor must hold the bar back (clockwise torque)"

# %% [markdown]
# ### Section 3: the double slider

# %%
assert np.isclose(p.q[0], 0.2) and np.isclose(p.q_dot[0], 2.0)  # x_A = 200 mm, 2 m/s
assert math.isclose(mech.link(3).mass, 5.0)  # the rod: 5 kg ...
assert math.isclose(math.dist(*mech.link(3).points.values()), 0.5)  # ... and 500 mm
assert system.A[0].shape == (9, 9) and len(system.unknowns) == 9  # 9 unknowns, 3 × 3 equations
for j, total in sums.items():
    assert np.allclose(total, 0, atol=1e-9)
assert abs(i3.F[0][0]) < 1e-9 * np.linalg.norm(i3.F[0])  # the inertia force is vertical
assert math.isclose(i3.h[0], abs(i3.T[0]) / np.linalg.norm(i3.F[0]))
assert np.allclose([sol["F23x"], sol["F23y"]], result["F23"][0])
assert np.allclose([sol["F34x"], sol["F34y"]], result["F34"][0])
assert np.isclose(sol["F12"], result.effort[0])
assert np.allclose([0.0, sol["N12"]], result["G12"][0])  # guide 1–2 is the x-axis: normal is +y
assert abs(sol["C12"]) < 1e-9 and abs(sol["C14"]) < 1e-9  # "the couples come out zero"
assert round(math.degrees(2 * math.asin(3e-3 / 2)), 2) == 0.17  # a turn of 0.17° moves a vector by 0.3 %
for name, diff in diffs.items():
    assert diff < 3e-3, f"{name} differs from the book by {diff:.2%}"
assert np.allclose(result["G12"][0], -i3.F[0])
assert np.allclose(result["F12"][0], -result["F43"][0])
assert np.allclose(result["G14"][0], result["F43"][0])

# %% [markdown]
# ### Section 4: other positions

# %%
assert math.isclose(P_driver + P_inertia, 0.0, abs_tol=1e-9 * abs(P_driver))
assert sweep.valid.all()
row = int(np.argmin(abs(xs - 0.2)))
assert np.isclose(sweep.effort[row], result.effort[0])  # the row for 200 mm is the book's problem

# %% [markdown]
# ### Section 5: try it yourself (as shipped: v = 4 m/s)

# %%
assert math.isclose(mine_result.effort[0] / result.effort[0], 4.0)  # accelerations scale with v_A²

# %% [markdown]
# ### Section 6: the demo student's slips are named

# %%
demo_report = {q["id"]: q for q in gk.exercises.grade("double_slider_forces", "demo", demo)["questions"]}
assert demo_report["F23"]["verdict"] == "slip" and demo_report["F23"]["slip"] == "sign"
assert demo_report["F34"]["verdict"] == "correct" and demo_report["G12"]["verdict"] == "correct"
assert demo_report["F12"]["verdict"] == "slip" and demo_report["F12"]["slip"] == "sign"
assert demo_report["h3"]["verdict"] == "slip" and demo_report["h3"]["slip"] == "power_of_ten"
assert all(q["score"] == 0.5 for q in demo_report.values() if q["verdict"] == "slip")  # "half a point"
assert "F32" in demo_report["F23"]["feedback"]
