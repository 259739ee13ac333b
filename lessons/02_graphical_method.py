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
# computers, engineers found the same forces **with a ruler and a pencil**: every force is
# drawn as an arrow, and equilibrium means that the arrows, placed tip to tail, close into a
# polygon. The method is still worth learning — it shows *why* each force points where it does.
#
# You will
#
# 1. learn the four tools of the method: the inertia resultant offset by $h$, two-force members,
#    three-force members with their point of concurrency, and superposition;
# 2. follow the construction for Söylemez's double slider step by step and check each step;
# 3. solve a four-bar in which two links carry loads, by superposition, and compare every number
#    with the analytical route of lesson 01;
# 4. move the mechanism and change its data to see the construction respond;
# 5. work two exercises with **your own data** — one of them with a pencil and a ruler — and have
#    your answers checked.
#
# `graphkin` does each construction exactly (it computes where a draftsman would measure), so
# the graphical and the analytical answers agree to rounding error. All numbers are SI inside;
# we print mm and degrees to match the books. The checks that keep the lesson honest (the numbers
# quoted in the text are compared there with what `graphkin` computes) are collected at the very
# end, out of your way.

# %%
# %matplotlib inline

import math

import numpy as np

import graphkin as gk

np.set_printoptions(precision=4, suppress=True)


def show(v, unit="N", digits=4):
    """A plane vector as the books write it: magnitude ∠ angle."""
    size, angle = gk.polar(v)
    return f"{size:.{digits}g} {unit} ∠ {angle:.2f}°"


def vec(size, angle_deg):
    """The vector of a force given in polar form (as the book prints it)."""
    a = math.radians(angle_deg)
    return np.array([size * math.cos(a), size * math.sin(a)])


def rel(a, b):
    """Relative difference |a − b| / |b| of two vectors (or numbers)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    return float(np.linalg.norm(a - b) / np.linalg.norm(b))


def off_line(point, line):
    """Distance [m] of a point from a line of action (a graphkin Line: a point and a unit direction)."""
    return abs(float(gk.cross(np.subtract(point, line.point), line.direction)))


def steps_of(c, kind, link=None):
    """The steps of a construction of one kind (and on one link)."""
    return [s for s in c.steps if s.kind == kind and (link is None or s.link == link)]


# %% [markdown]
# ## 1. The idea
#
# ### One force instead of a force and a torque
#
# d'Alembert gives each moving link an inertia force $\vec F_i = -m\vec a_G$ acting at $G$ and an
# inertia torque $T_i = -I_G\alpha$. A force and a couple in the plane can always be replaced by
# **one force**: the same vector $\vec F_i$, moved sideways from $G$ by
#
# $$h = \frac{|T_i|}{|\vec F_i|}$$
#
# so that its moment about $G$ is exactly $T_i$. It goes to the side that turns the link the
# same way as $T_i$: if $T_i$ is clockwise, the shifted force must pass $G$ so that it turns the
# link clockwise. We call this single force the *inertia resultant* $\vec R_{i}$. Any other known
# loads on the link (a cutting force, a weight) are added to it the same way — two forces
# combine into one through the point where their lines cross.
#
# ### Two-force members
#
# A link with **no load of its own** (massless, no external force) that is touched at only two
# points is held by two forces. Two forces balance only if they are equal, opposite and **on the
# same line** — the line through the two joints. So we know the direction of the force it passes
# on before we know its size. (A massless slider in a frictionless guide is the same idea: the
# force passes through its pin, normal to the guide.)
#
# ### Three-force members
#
# A link held by **three forces** is in equilibrium only if
#
# * the three lines of action meet in **one point** (otherwise one force would have a moment about
#   the crossing point of the other two), and
# * the three force vectors, drawn **tip to tail**, close a triangle (the *force polygon*).
#
# So: take the known resultant and the line fixed by a two-force neighbour, find where they
# cross — the *point of concurrency* $I$ — and the third force must pass through $I$ and through
# its own joint. Now all three directions are known and one size; the polygon gives the rest.
#
# ### Superposition
#
# If **both** links of a pair carry loads, neither is a two-force member. Then we load one link
# at a time (the other becomes a two-force member), solve each case as above, and **add** the
# joint forces of the cases.
#
# ### Sign convention
#
# As in lesson 01: $x$ right, $y$ up, angles and torques positive counter-clockwise, and
# $\vec F_{ij}$ is the force of link $i$ **on** link $j$, with $\vec F_{ji} = -\vec F_{ij}$.
# In a free body of link $j$ we draw the forces $\vec F_{ij}$ of its neighbours.

# %%
gk.draw.draw_sign_convention().figure

# %% [markdown]
# ## 2. The double slider, step by step (Söylemez §6.4)
#
# The same mechanism as in lesson 01: slider 2 moves along $x$ at 2 m/s, slider 4 along $y$, and
# the rod 3 (500 mm, 5 kg) joins them. Only the rod has mass. `gk.construct_forces` builds the
# graphical solution at one position of the kinematics and returns it as data: a list of
# **steps**, each with a kind, a caption in words, the lines and points it draws, and its force
# polygon.

# %%
p = gk.load("double_slider")
c = gk.construct_forces(p.kinematics(), 0)
r = p.solve()  # the analytical route, for comparison later

for number, step in enumerate(c.steps, start=1):
    print(f"Step {number} [{step.kind}] link {step.link}")
    print(f"    {step.caption}")

# %% [markdown]
# We draw one frame per step and look at them in turn.

# %%
frames = gk.draw.draw_steps(c)
print(len(frames), "frames for", len(c.steps), "steps")

# %% [markdown]
# ### Step 1 — the inertia resultant of the rod
#
# The rod's inertia force points straight up (25.98 N) and its inertia torque is clockwise.
# An upward force turns the rod clockwise about $G_3$ if it passes **to the left** of $G_3$: so the
# resultant $\vec R_{3i}$ is drawn vertical, $h$ to the left of $G_3$.

# %%
frames[0]

# %%
s1 = c.steps[0]
h = s1.values["h"]
F3i, T3i = np.array(s1.values["F3i"]), s1.values["T3i"]
G3 = np.array(c.G[3])
(R3i_line,) = [ln for ln in s1.lines if ln.name == "R3i"]

print(f"F3i = {show(F3i)},  T3i = {T3i * 1e3:.1f} N·mm ({'CW' if T3i < 0 else 'CCW'})")
print(f"h = |T3i|/|F3i| = {h * 1e3:.3f} mm   (book: 33.31 mm)")
print(f"distance of G3 from the line of R3i: {off_line(G3, R3i_line) * 1e3:.3f} mm")
print(f"moment of R3i about G3: {float(gk.cross(np.subtract(R3i_line.point, G3), F3i)) * 1e3:.1f} N·mm"
      f"  (the inertia torque; the line passes {'left' if R3i_line.point[0] < G3[0] else 'right'} of G3)")

# %% [markdown]
# ### Step 2 — slider 4 is a two-force member
#
# Slider 4 is massless and its guide has no friction. It is touched by the rod's pin at $B$ and by
# the guide, which can only push normal to itself (horizontally). So the force the slider passes
# to the rod, $\vec F_{43}$, is **horizontal, through $B$**.

# %%
frames[1]

# %% [markdown]
# ### Step 3 — the rod is a three-force member
#
# The rod carries $\vec R_{3i}$ (line known), $\vec F_{43}$ (line known from step 2) and
# $\vec F_{23}$ at $A$ (line unknown). The first two lines cross at $I_3$; the third force must pass
# through $I_3$ too, so its line is $AI_3$.

# %%
frames[2]

# %%
s3 = c.steps[2]
I3 = np.array(s3.points["I3"])
lines3 = {ln.name: ln for ln in s3.lines}
A, B = np.array(c.points[3]["A"]), np.array(c.points[3]["B"])
print("I3 =", I3 * 1e3, "mm")
for name in ("R3i", "F43", "F23"):
    print(f"   distance of I3 from the line of {name}: {off_line(I3, lines3[name]):.1e} m")
print(f"   distance of A from the line of F23: {off_line(A, lines3['F23']):.1e} m")
# Here I3 is simply (x of the vertical R3i line, y of B).
print("(x of the line of R3i, y of B) =", np.array([R3i_line.point[0], B[1]]) * 1e3, "mm")

# %% [markdown]
# ### Step 4 — the force polygon of the rod
#
# Draw $\vec R_{3i}$ to scale (it is known), then from its tip a line parallel to $\vec F_{43}$
# (horizontal), and from its tail a line parallel to $\vec F_{23}$ (parallel to $AI_3$). Where they
# cross closes the triangle: $\vec R_{3i} + \vec F_{43} + \vec F_{23} = 0$. Here we follow the arrows
# tip to tail and check that we come back to the start.

# %%
frames[3]

# %%
s4 = c.steps[3]
tip = np.zeros(2)
for arrow in s4.polygon:
    tip = tip + arrow.vector
    print(f"{arrow.name:>4} = {show(arrow.vector):<22} {'known' if arrow.known else 'found'}   tip at {tip} N")
print(f"closure = |sum| / largest side = {s4.closure():.1e}")

# %% [markdown]
# ### Steps 5 and 6 — slider 2 and the driving force
#
# Slider 2 carries $\vec F_{32} = -\vec F_{23}$, found above. The frame holds it with the guide force
# $\vec G_{12}$ (normal to the guide: vertical) and the driving force $\vec F_{12}$ (along the guide:
# horizontal). One known force and two known directions: the polygon gives both sizes.

# %%
frames[4]

# %%
frames[5]

# %% [markdown]
# The book reads two results straight off the polygons: **$\vec G_{12} = -\vec R_{3i}$ and
# $\vec F_{12} = -\vec F_{43}$**. $\vec F_{32}$ is the sum $\vec R_{3i} + \vec F_{43}$ (from the rod's
# polygon); the vertical part is taken by the guide and the horizontal part by the driver. We
# check this on the numbers of the construction.

# %%
(drive,) = steps_of(c, "driver")
G12 = c.force(1, 2)
F12 = np.array(drive.values["F12"])
F43 = c.force(4, 3)
R3i = np.array(c.inertia[3]["F"])
print("G12 =", show(G12), "   −R3i =", show(-R3i))
print("F12 =", show(F12), "    −F43 =", show(-F43))
print(f"the driving effort (F12 along the guide, +x): {c.effort:.4f} N")

# %% [markdown]
# ### Graphical, analytical and the book
#
# The last column of differences is against the book, which rounds intermediate values, so we
# only expect a few tenths of a percent. Between the two routes of `graphkin` we expect rounding
# noise only.

# %%
book = {"F43": (7.555, 180), "F23": (27.04, -73.78), "G12": (25.97, 270), "F12": (7.555, 0)}
graphical = {"F43": c.force(4, 3), "F23": c.force(2, 3), "G12": c.force(1, 2), "F12": F12}
analytical = {name: r[name][0] for name in book}  # r["F12"] is the driving force as a vector

print(f"{'':5}{'graphical':>22}{'analytical':>22}{'book':>18}{'graph/anal':>12}{'graph/book':>12}")
for name, (size, angle) in book.items():
    g, a, b = graphical[name], analytical[name], vec(size, angle)
    d_an, d_book = rel(g, a), rel(g, b)
    print(f"{name:5}{show(g):>22}{show(a):>22}{f'{size:g} N ∠ {angle:g}°':>18}{d_an:>12.1e}{d_book:>11.3%}")
d_h = abs(h * 1e3 - 33.31) / 33.31
print(f"{'h':5}{f'{h * 1e3:.3f} mm':>22}{f'{r.inertia(3).h[0] * 1e3:.3f} mm':>22}{'33.31 mm':>18}"
      f"{rel(h, r.inertia(3).h[0]):>12.1e}{d_h:>11.3%}")

# %% [markdown]
# Everything on one sheet: the mechanism, a table of both routes, the free body of each link
# (with the inertia resultant on its offset line and $h$ dimensioned) and the force polygons.

# %%
gk.draw.draw_solution(c, r)

# %% [markdown]
# ## 3. A four-bar by superposition: the strip cutter (Söylemez §6.4.1)
#
# Crank 2 ($A_0A$) turns at 900 rpm; the coupler 3 and the rocker 4 both carry a blade at $C$.
# While $124° < \theta_{12} < 156°$ the strip pushes the blades apart with 2000 N (up on link 3,
# down on link 4). We take $\theta_{12} = 140°$, in the middle of the cut.
#
# Now **both** links of the dyad 3–4 carry loads (inertia and the cutting force), so neither is a
# two-force member and the simple recipe of section 2 does not apply directly.

# %%
p2 = gk.load("strip_cutter")
print(p2.title)
print(p2.notes)
r2 = p2.solve(at=[np.radians(140)])
c2 = gk.construct_forces(r2.kinematics, 0)

for number, step in enumerate(c2.steps, start=1):
    print(f"Step {number:2} [{step.kind}] link {step.link}: {step.caption}")

# %% [markdown]
# ### Why superposition is allowed
#
# Once the position is fixed, every equilibrium equation is **linear in the loads**: the lever
# arms and directions come from the geometry, which does not change, and the unknown joint forces
# appear to the first power. So if loads $L_a$ produce joint forces $x_a$ and loads $L_b$ produce
# $x_b$, then $L_a + L_b$ produce $x_a + x_b$. We may therefore solve
#
# * **case 3**: only link 3 loaded — link 4 is a two-force member (force along $B_0B$);
# * **case 4**: only link 4 loaded — link 3 is a two-force member (force along $AB$);
#
# and add the joint forces of the two cases.
#
# First each link's known loads become one resultant: the inertia resultant (offset by $h$) plus
# the cutting force at $C$ gives $\vec R_3$, and likewise $\vec R_4$. The two forces combine through
# the point where their lines cross.

# %%
combined = {}  # link → (inertia resultant, cutting force, R, where their lines cross, the line of R)
for link in (3, 4):
    (s,) = steps_of(c2, "resultant", link)
    lines = {ln.name: ln for ln in s.lines}
    (cut,) = c2.external[link]
    Ri, R = np.array(s.values[f"F{link}i"]), np.array(s.values[f"R{link}"])
    print(f"link {link}: F{link}i = {show(Ri)}, h = {s.values['h'] * 1e3:.1f} mm;  "
          f"{cut.name} = {show(cut.vector)};  R{link} = {show(R)}")
    # Where the inertia resultant's line crosses the cutting force's line, R passes too.
    Li, u = np.array(lines[f"R{link}i"].point), np.array(lines[f"R{link}i"].direction)
    X, w = np.array(cut.at), np.array(cut.vector) / np.linalg.norm(cut.vector)
    t = float(gk.cross(X - Li, w) / gk.cross(u, w))
    crossing = Li + t * u
    print(f"        the two lines cross at {crossing * 1e3} mm; R{link} passes "
          f"{off_line(crossing, lines[f'R{link}']):.1e} m from there")
    combined[link] = (Ri, np.array(cut.vector), R, crossing, lines[f"R{link}"])

# %% [markdown]
# ### The two cases
#
# Each case is the recipe of section 2: a two-force member fixes one line, the loaded link is a
# three-force member with its point of concurrency ($I_3$, then $I_4$), and its polygon closes.
# The parts are the forces of each case's polygon.

# %%
part = {}
for loaded, other in ((3, 4), (4, 3)):
    (three,) = steps_of(c2, "three-force", loaded)
    (poly,) = steps_of(c2, "polygon", loaded)
    I = np.array(three.points[f"I{loaded}"])
    print(f"case {loaded} (link {other} a two-force member): I{loaded} = {I * 1e3} mm,  closure {poly.closure():.1e}")
    for arrow in poly.polygon:
        print(f"    {arrow.name:>3} = {show(arrow.vector)}")
    part[loaded] = {arrow.name.rstrip("′″"): np.array(arrow.vector) for arrow in poly.polygon}

# %% [markdown]
# ### Adding the cases
#
# The `superpose` steps add the parts of each joint force of the dyad: $\vec F_{23}$ (at $A$),
# $\vec F_{34}$ (at $B$) and $\vec F_{14}$ (at $B_0$). At the two **outer** joints a case's part
# comes from the other link's polygon: in case 4, link 3 is a two-force member, so the force 2 puts
# on 3 equals the force 3 puts on 4: $\vec F_{23}^{(4)} = \vec F_{34}^{(4)}$; likewise in case 3,
# $\vec F_{14}^{(3)} = \vec F_{43}^{(3)}$.
#
# In graphkin's superposition polygon the last side is the sum reversed ($-\vec F_{23}$): the parts
# run tip to tail from the start, and the closing side brings you back, so that the polygon adds
# up to zero like every other.

# %%
for s in steps_of(c2, "superpose"):
    parts = [a for a in s.polygon if a.known]
    (total_name,) = s.values
    total = sum(np.array(a.vector) for a in parts)
    print(s.caption)
    for a in parts:
        print(f"    {a.name:>14} = {show(a.vector)}")
    print(f"    {total_name:>14} = {show(total)}")

# %% [markdown]
# By hand from the two cases: the outer joint forces as above, and the middle pin $B$ the same way
# — in case 3 the force of 3 on 4 is $-\vec F_{43}^{(3)}$; in case 4 it is $\vec F_{34}^{(4)}$.

# %%
F23 = part[3]["F23"] + part[4]["F34"]
F34 = -part[3]["F43"] + part[4]["F34"]
F14 = part[3]["F43"] + part[4]["F14"]
print("F23 =", show(F23), "   F34 =", show(F34), "   F14 =", show(F14))

# %% [markdown]
# All the steps on one sheet, in the order they are built:

# %%
gk.draw.draw_step_grid(c2)

# %% [markdown]
# ### The crank: a couple
#
# The crank (its centre of mass is on the pivot and it turns at constant speed, so it has no inertia
# loads) carries only
# $\vec F_{32}$ at $A$, so $\vec R_2 = \vec F_{32}$. The pivot force $\vec F_{12} = -\vec R_2$ at $A_0$ and
# $\vec R_2$ are equal, opposite and parallel: a **couple** of arm $d$ (the distance from $A_0$ to the
# line of $\vec R_2$). The motor's torque must cancel it: $|T_{12}| = |\vec R_2|\, d$.

# %%
drive2 = steps_of(c2, "driver")[-1]  # the whole problem's crank, after sub-problems I and II
d, T12 = drive2.values["d"], drive2.values["T12"]
R2_step = [s for s in steps_of(c2, "resultant", 2) if "R2" in s.values][-1]
R2 = np.array(R2_step.values["R2"])
(R2_line,) = [ln for ln in R2_step.lines if ln.name == "R2"]
A0 = np.array(c2.points[1]["A0"])
print(f"R2 = {show(R2)},  d = {d * 1e3:.2f} mm,  |R2|·d = {np.linalg.norm(R2) * d:.3f} N·m")
print(f"T12 = {T12:.3f} N·m ({'CCW' if T12 > 0 else 'CW'})")

# %% [markdown]
# ### Comparison with the analytical route
#
# Every joint force and the driving torque, by both routes:

# %%
print(f"{'':5}{'graphical':>22}{'analytical':>22}{'rel. diff':>11}")
for name in r2.names():
    g, a = c2[name], r2[name][0]
    if np.ndim(a) == 0:  # the driving torque
        g_text, a_text = f"{g:.4f} N·m", f"{a:.4f} N·m"
    else:
        g_text, a_text = show(g), show(a)
    diff = rel(g, a)
    print(f"{name:5}{g_text:>22}{a_text:>22}{diff:>11.1e}")

# %%
gk.draw.draw_solution(c2, r2)

# %% [markdown]
# ### When superposition is *not* allowed: friction
#
# Coulomb friction at a guide is $\mu |N|$ **against** the sliding: its direction depends on the
# sign of the *total* normal force $N$. That is not linear in the loads — if case 3 alone pushed the
# slider down and case 4 alone pushed it up, each case would tilt the guide reaction a different
# way, and their sum would be wrong.
#
# The way out: **assume** which side the total normal force pushes. With the side fixed, friction
# is again a fixed multiple of $N$, the equations are linear, and superposition works. At the end,
# check that the total $N$ really pushes on the assumed side; if not, assume the other side and
# redo. graphkin does exactly that, and says so in a `note` step. An example with friction at the
# slider of a slider-crank ($\mu = 0.2$), at $\theta_{12} = 60°$:

# %%
p3 = gk.load("slider_crank_friction")
r3 = p3.solve(at=[np.radians(60)])
c3 = gk.construct_forces(r3.kinematics, 0)
note = next(s for s in steps_of(c3, "note") if s.caption.startswith("Friction"))
print(note.caption)
print()
(guide,) = [j for j in p3.mechanism.joints if getattr(j, "mu", 0)]
G14 = c3.force(1, 4)
v4 = r3.kinematics.velocity(4, "B")[0]
print(f"slider velocity {v4} m/s;  G14 = {G14} N;  μ = {guide.mu}")
print(f"friction |G14x| = {abs(G14[0]):.3f} N,  μ |N| = μ |G14y| = {guide.mu * abs(G14[1]):.3f} N")

# %% [markdown]
# ## 4. Try it yourself
#
# **Move the crank.** The cell below builds the construction at three crank angles and marks the
# point of concurrency $I_3$ of link 3 with the line $AI_3$ of $\vec F_{23}$. (Outside the cut —
# 100° and 200° — link 3 carries its inertia resultant only.) Predict first: does $I_3$ stay near
# the mechanism? Try other angles, e.g. 130° or 300°. Also print `I4`: where the two lines that meet
# there are nearly parallel, $I_4$ runs far away — that is where a drawn construction becomes
# inaccurate.

# %%
from matplotlib.figure import Figure

angles = [100, 140, 200]  # degrees: edit here
fig = Figure(figsize=(4.2 * len(angles), 4.2))
for ax, deg in zip(fig.subplots(1, len(angles)), angles):
    ck = gk.construct_forces(p2.kinematics(at=[np.radians(deg)]), 0)
    I = {name: np.array(xy) for s in ck.steps for name, xy in s.points.items()}
    A_mm = np.array(ck.points[3]["A"]) * 1e3
    gk.draw.draw_mechanism(ck, ax=ax)
    ax.plot(*np.array([A_mm, I["I3"] * 1e3]).T, "--", color="tab:green")
    ax.plot(*(I["I3"] * 1e3), "o", color="tab:green")
    ax.annotate("I₃", I["I3"] * 1e3, textcoords="offset points", xytext=(5, 5), color="tab:green")
    ax.relim()
    ax.autoscale(True)  # draw_mechanism fixes the limits; let them grow to show I3
    ax.margins(0.08)
    ax.set_title(f"θ₁₂ = {deg}°:  T₁₂ = {ck.effort:.1f} N·m", fontsize=10)
    print(f"θ12 = {deg:3}°: I3 = {I['I3'] * 1e3} mm, I4 = {I['I4'] * 1e3} mm, T12 = {ck.effort:8.2f} N·m")
fig

# %% [markdown]
# **Change the data.** A problem is plain TOML text, so we can edit it and parse it again. Predict
# before you run: if the rod of the double slider is twice as heavy, what happens to $h$? (Hint:
# for a uniform rod $I_G = mL^2/12$, so both $T_i$ and $\vec F_i$ are proportional to $m$.)

# %%
text = gk.catalog.path("double_slider").read_text()
heavy = gk.parse_problem(text.replace('mass = "5 kg"', 'mass = "10 kg"'), file="heavy rod")  # edit here
ch = gk.construct_forces(heavy.kinematics(), 0)
print(f"h: {c.inertia[3]['h'] * 1e3:.3f} mm -> {ch.inertia[3]['h'] * 1e3:.3f} mm")
print(f"F12: {c.effort:.4f} N -> {ch.effort:.4f} N")

# %% [markdown]
# The mass cancels in $h = I_G|\alpha| / (m|\vec a_G|) = k^2|\alpha|/|\vec a_G|$, where $k$ is the
# radius of gyration. So to move the resultant, change how the mass is *spread*. The strip cutter
# gives $k$ directly; shrink link 3's from 268 mm to 150 mm and watch $h$, $I_3$ and $T_{12}$ change.

# %%
text = gk.catalog.path("strip_cutter").read_text()
compact = gk.parse_problem(text.replace('k = "268 mm"', 'k = "150 mm"'), file="compact coupler")  # edit here
cc = gk.construct_forces(compact.kinematics(at=[np.radians(140)]), 0)
for label, ck in (("k3 = 268 mm", c2), ("k3 = 150 mm", cc)):
    (three,) = steps_of(ck, "three-force", 3)
    print(f"{label}: h3 = {ck.inertia[3]['h'] * 1e3:7.1f} mm,  I3 = {np.array(three.points['I3']) * 1e3} mm,"
          f"  T12 = {ck.effort:.2f} N·m")

# %% [markdown]
# ### The worked solutions, to keep
#
# Both constructions of this lesson, each step's figure with its caption and its force polygon to
# scale, are in the handouts [`double_slider.pdf`](../figures/handouts/double_slider.pdf) and
# [`strip_cutter.pdf`](../figures/handouts/strip_cutter.pdf) (the strip cutter's at the crank angle
# where its driving torque peaks; `--at '140 deg'` gives the position of section 3). To draw the
# polygons yourself, `--blank` gives the free bodies to scale with room for each polygon:
#
# ```sh
# graphkin handout strip_cutter --at '140 deg' -o strip_cutter.pdf
# graphkin handout double_slider --blank -o double_slider_worksheet.pdf
# ```

# %% [markdown]
# ## 5. Your turn
#
# Two exercises with **your own data**. Every student gets different numbers, drawn from their id,
# and the answers are checked against a key solved from exactly the numbers you see. A wrong answer
# gets a sentence of feedback; when the grader recognises the slip (a torque with the wrong sense,
# the resultant on the wrong side of $G$, mm read as m) it says so, and the answer earns part of the
# points.
#
# **Type your own id** (for example your student number) between the quotes below, in place of
# `"your-id"`, and run the cells of this section. (The lesson comes with the placeholder so that it
# can be run and tested as it is.)

# %%

student = "your-id"  # ← type your own id here

# %% [markdown]
# ### 5.1 The inertia resultant of the strip cutter's coupler
#
# Section 1 and step 1 of section 2, on the coupler of the strip cutter at your own crank angle
# and speed (outside the cut). Find $\vec F_{3i}$, $T_{3i}$, the offset $h$ and the foot of the
# perpendicular from $G_3$ to the resultant's line — on the side that turns the link the same way
# as $T_{3i}$. Work by hand from the kinematics, or with `graphkin`:
# `gk.construct_forces(p2.at_speed(ω).kinematics(at=[θ]), 0).inertia[3]` holds them for the strip
# cutter of section 3 at your speed ω [rad/s] and angle θ [rad] (`line_point` is the foot).
#
# Write a force as `12.3 N at -45 deg` (or `12.3 N ∠ -45°`), a torque with its sense, `4.5 N*m CW`,
# and a point as `(x, y) mm`. Press **Check** as often as you like.

# %%
gk.exercise("inertia_resultant", student)

# %% [markdown]
# If you prefer code to boxes, put your answers in a dictionary (question → answer as you would
# type it) and print `gk.exercises.check`: it gives the same feedback. Empty answers are reported as
# missing.

# %%
answers = {"F3i": "", "T3i": "", "h3": "", "line3": ""}  # e.g. "12.3 N at -45 deg", "4.5 N*m CW", ...
print(gk.exercises.check("inertia_resultant", student, answers))

# %% [markdown]
# ### 5.2 The double slider with a pencil and a ruler
#
# Section 2 at your own position and speed — but this time *you* do the construction. The cell
# below draws your mechanism and the free body of the rod to scale, with the rod's inertia
# resultant $\vec R_{3i}$ on its offset line and a force scale bar. The joint forces are left out:
# they are what you find. Print the figure (or copy it onto paper), then
#
# 1. draw the line of $\vec F_{43}$: slider 4 is a two-force member (step 2);
# 2. find $I_3$ where it crosses the line of $\vec R_{3i}$, and draw the line $AI_3$ (step 3);
# 3. draw the polygon $\vec R_{3i} + \vec F_{43} + \vec F_{23} = 0$ at the printed force scale
#    (step 4), then the polygon of slider 2 (steps 5 and 6), and measure the sides.
#
# An answer within 3 % earns full marks, or within what a ruler reads at the printed scale (±0.5 mm)
# where that is larger: the sheet states both beside each question. The drawing is made for the id
# in the `student` cell above (if you typed your id only in a box, type it there too).

# %%
from matplotlib.figure import Figure

mine = gk.exercises.variant("double_slider_graphical", student)
print(f"student {mine.student}:", ", ".join(value.shown for value in mine.data))
left, right = Figure(figsize=(11, 5)).subplots(1, 2)
gk.draw.draw_mechanism(mine.construction, ax=left)
gk.draw.draw_free_body(mine.construction, 3, ax=right, unknowns=False).figure

# %%
gk.exercise("double_slider_graphical", student)

# %% [markdown]
# ### 5.3 What the feedback looks like
#
# A made-up student, `"demo"`, answers the inertia-resultant exercise with two classic slips: they
# give $T_{3i}$ with the wrong sense, and put the resultant's line on the wrong side of $G_3$ (the
# mirror image of the right foot of the perpendicular). $\vec F_{3i}$ and $h$ are right. (The folded
# cell below makes these answers from the demo student's key; you need not read it.)

# %% jupyter={"source_hidden": true}
def slipped_answers(name, student):
    """Answers to the inertia-resultant exercise with two typical slips, made from the key (for the demo only)."""
    key = {q["id"]: q["answer"] for q in gk.exercises.key(name, student)["questions"]}
    T = key["T3i"]["si"]
    G3_demo = gk.exercises.variant(name, student).problem.kinematics().G(3)[0]
    wrong_foot = (2 * G3_demo - np.array(key["line3"]["si"])) * 1e3  # the foot mirrored through G3 [mm]
    return {
        "F3i": key["F3i"]["text"],  # right
        "T3i": f"{abs(T):.4g} N*m {'CW' if T > 0 else 'CCW'}",  # the sense reversed
        "h3": key["h3"]["text"],  # right
        "line3": f"({wrong_foot[0]:.1f}, {wrong_foot[1]:.1f}) mm",  # on the wrong side of G3
    }


# %%
demo = slipped_answers("inertia_resultant", "demo")
print(demo)
print(gk.exercises.check("inertia_resultant", "demo", demo))

# %% [markdown]
# Each slip is named and earns half a point; the feedback says what to look at again but does not
# give the value. Now check your own.

# %% [markdown]
# ## Checks (for the course maintainers; students may skip)
#
# Every number this lesson quotes, and every claim it makes, is checked here against the variables
# of the cells above, so that a change in `graphkin` that breaks the lesson fails the notebook test.
# (If you edited an "edit here" cell, the checks of section 4 may fail: that is expected.)

# %% [markdown]
# ### Section 2: the double slider, step by step

# %%
assert np.isclose(p.q_dot[0], 2.0) and math.isclose(p.mechanism.link(3).mass, 5.0)  # 2 m/s, a 5 kg rod ...
assert math.isclose(math.dist(*p.mechanism.link(3).points.values()), 0.5)  # ... 500 mm long
assert len(frames) == len(c.steps)
# Step 1: the inertia resultant.
assert s1.kind == "resultant" and s1.link == 3
assert round(float(np.linalg.norm(F3i)), 2) == 25.98 and F3i[1] > 0  # "straight up (25.98 N)"
assert abs(F3i[0]) < 1e-9 * np.linalg.norm(F3i)
assert T3i < 0  # "its inertia torque is clockwise"
assert math.isclose(h, abs(T3i) / np.linalg.norm(F3i))
assert abs(h * 1e3 - 33.31) / 33.31 < 2e-3  # the book rounds before dividing
assert math.isclose(off_line(G3, R3i_line), h)
# The right side: the moment of R3i (on its line) about G3 is the inertia torque.
assert math.isclose(float(gk.cross(np.subtract(R3i_line.point, G3), F3i)), T3i)
assert R3i_line.point[0] < G3[0]  # to the left of G3, as argued in step 1
# Step 3: the point of concurrency.
assert s3.kind == "three-force"
for name in ("R3i", "F43", "F23"):
    assert off_line(I3, lines3[name]) < 1e-12
assert off_line(A, lines3["F23"]) < 1e-12  # F23's line passes through A ...
assert np.allclose(lines3["F23"].point, A)
# ... and, here, I3 is simply (x of the vertical R3i line, y of B).
assert np.allclose(I3, [R3i_line.point[0], B[1]])
# Step 4: the polygon of the rod.
assert s4.kind == "polygon"
assert s4.closure() < 1e-12
assert np.allclose(s4.values["F23"], c.force(2, 3)) and np.allclose(s4.values["F43"], c.force(4, 3))
# Steps 5 and 6: slider 2.
assert drive.closure() < 1e-12
assert np.allclose(G12, -R3i, atol=1e-12)
assert np.allclose(F12, -F43, atol=1e-12)
assert math.isclose(c.effort, F12[0])  # the effort: F12 along the guide (+x)
# Graphical, analytical and the book.
for name, (size, angle) in book.items():
    assert rel(graphical[name], analytical[name]) < 1e-12
    assert rel(graphical[name], vec(size, angle)) < 3e-3
assert rel(h, r.inertia(3).h[0]) < 1e-12

# %% [markdown]
# ### Section 3: the strip cutter by superposition

# %%
assert np.allclose(p2.q_dot, 900 * 2 * math.pi / 60)  # 900 rpm
for ld, link, up in zip(p2.mechanism.loads, (3, 4), (1, -1)):  # 2000 N, up on 3 and down on 4, ...
    assert ld.link == link and np.allclose(ld.force, (0.0, up * 2000.0))
    assert np.allclose(np.degrees([ld.active.start, ld.active.stop]), [124, 156])  # ... for 124° < θ12 < 156°
assert c2.valid and not c2.warnings
for link, (Ri, F_cut, R, crossing, R_line) in combined.items():
    assert np.allclose(R, Ri + F_cut)
    assert off_line(crossing, R_line) < 1e-9
for loaded in (3, 4):
    (three_k,) = steps_of(c2, "three-force", loaded)
    (poly_k,) = steps_of(c2, "polygon", loaded)
    I_k = np.array(three_k.points[f"I{loaded}"])
    assert poly_k.closure() < 1e-12
    for ln in three_k.lines:
        assert off_line(I_k, ln) < 1e-9
assert [sp.values.keys() for sp in steps_of(c2, "superpose")] == [{"F23"}, {"F34"}, {"F14"}]  # A, B, B0
for sp in steps_of(c2, "superpose"):
    (sp_name,) = sp.values
    sp_total = sum(np.array(a.vector) for a in sp.polygon if a.known)
    assert np.allclose(sp_total, sp.values[sp_name])
    assert np.allclose(sp.polygon[-1].vector, -sp_total) and sp.closure() < 1e-12
assert np.allclose(F23, c2.force(2, 3)) and np.allclose(F14, c2.force(1, 4))
assert np.allclose(F34, c2.force(3, 4))
# The crank: a couple.
assert not any(c2.inertia[2]["F"]) and not c2.inertia[2]["T"]  # "it has no inertia loads"
assert math.isclose(d, off_line(A0, R2_line))
assert math.isclose(abs(T12), np.linalg.norm(R2) * d)
assert np.allclose(R2, -c2.force(2, 3))  # R2 is F32
assert math.isclose(T12, c2.effort)
for name in r2.names():
    assert rel(c2[name], r2[name][0]) < 1e-9, name
# Friction: μ = 0.2 at θ12 = 60°.
assert guide.mu == 0.2 and math.isclose(c3.q, math.radians(60))
assert math.isclose(abs(G14[0]), guide.mu * abs(G14[1]))  # friction = μ |N|
assert np.sign(G14[0]) == -np.sign(v4[0])  # ... against the sliding
for name in r3.names():
    assert rel(c3[name], r3[name][0]) < 1e-9, name

# %% [markdown]
# ### Section 4: try it yourself (as shipped)

# %%
for deg in (100, 200):  # "outside the cut, link 3 carries its inertia resultant only"
    assert not gk.construct_forces(p2.kinematics(at=[np.radians(deg)]), 0).external[3]
assert math.isclose(ch.inertia[3]["h"], c.inertia[3]["h"])
assert math.isclose(ch.effort, 2 * c.effort)
assert math.isclose(cc.inertia[3]["h"] / c2.inertia[3]["h"], (150 / 268) ** 2)

# %% [markdown]
# ### Section 5: your turn

# %%
given_gids = {a.get_gid() for a in right.patches}
assert "fbd3:R3i" in given_gids  # the student sees R3i on its line ...
assert not {"fbd3:F23", "fbd3:F43"} & given_gids  # ... but not the joint forces they measure
demo_report = {q["id"]: q for q in gk.exercises.grade("inertia_resultant", "demo", demo)["questions"]}
assert demo_report["F3i"]["verdict"] == "correct" and demo_report["h3"]["verdict"] == "correct"
assert demo_report["T3i"]["verdict"] == "slip" and demo_report["T3i"]["slip"] == "sign"
assert demo_report["line3"]["verdict"] == "slip" and demo_report["line3"]["slip"] == "wrong_side"
assert all(q["score"] == 0.5 for q in demo_report.values() if q["verdict"] == "slip")  # "half a point"
