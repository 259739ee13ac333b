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
# Lessons 01 and 02 solved linkages whose joints pass forces with no further rule: a pin
# force may point anywhere, a frictionless guide pushes normal to itself. Two common joints add
# **one extra relation between the components of a joint force**:
#
# * a slider with **Coulomb friction**: the force along the guide is $\mu$ times the normal force,
#   against the sliding — $F_{14x} = -\operatorname{sign}(V_4)\,\mu\,F_{14y}$ in the ME 370 notes;
# * a pair of **spur gears**: the tooth force lies on the pressure line, at the pressure angle
#   $\phi$ to the common tangent — $F_{32x} = c\,F_{32y}$ with $c = \tan\phi\,\operatorname{sign}(F_{32y})$.
#
# Both come from ME 370 lecture 22 (*Dynamic force analysis 3*); the numbers in graphkin's two
# catalog problems are our own, because the notes give none. In both relations the coefficient
# carries a **sign that depends on the answer** (the side the normal force pushes on, the flank
# the tooth pushes with). The way round it is the same both times: **assume the sign, solve the
# linear system, check the sign.**
#
# You will
#
# 1. write the friction relation into Norton's matrix $[A]\{x\} = \{b\}$ and see the assume-and-check
#    step choose the one consistent answer;
# 2. draw the same solution with force polygons, the guide reaction tilted by the friction angle
#    $\rho = \arctan\mu$;
# 3. follow the friction force round a whole turn: it flips with the slider's velocity (and not with
#    the normal force), vanishes where the slider stands still, and the work it takes is exactly the
#    extra work the motor puts in;
# 4. solve the gearset both ways: the tooth force along the pressure line, the torque ratio, and the
#    power balance;
# 5. drive the interactive explorer of each problem from code and check what it shows;
# 6. solve a slider-crank with friction and a gear pair with **your own data**, and get feedback on
#    your answers.
#
# All numbers inside graphkin are SI (m, kg, s, N, rad); we print mm, degrees and rpm to read them.
# The checks that keep this notebook honest (every number quoted in the text is verified) are
# collected at the end, in a section students may skip.

# %%
# %matplotlib inline

import math

import numpy as np
from matplotlib.figure import Figure

import graphkin as gk

np.set_printoptions(precision=4, suppress=True)


def show(v, unit="N", digits=4):
    """A plane vector as the books write it: magnitude ∠ angle."""
    size, angle = gk.polar(v)
    return f"{size:.{digits}g} {unit} ∠ {angle:.2f}°"


def rel(a, b):
    """Relative difference |a − b| / |b| of two vectors (or numbers)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    return float(np.linalg.norm(a - b) / np.linalg.norm(b))


def off_line(point, line):
    """Distance [m] of a point from a line of action (a graphkin Line: a point and a unit direction)."""
    return abs(float(gk.cross(np.subtract(point, line.point), line.direction)))


def tilt(F, normal):
    """Angle [deg] between a force and a unit normal, 0…90° (the sense along the normal ignored)."""
    F = np.asarray(F, float)
    return math.degrees(math.atan2(abs(gk.cross(normal, F)), abs(float(np.dot(F, normal)))))


def steps_of(c, kind, link=None):
    """The steps of a construction of one kind (and on one link)."""
    return [s for s in c.steps if s.kind == kind and (link is None or s.link == link)]


def edited(name, old, new):
    """A catalog problem with one piece of its TOML text replaced, parsed again."""
    text = gk.catalog.path(name).read_text()
    assert text.count(old) == 1, f"{old!r} is not in {name}.toml exactly once"
    return gk.parse_problem(text.replace(old, new), file=f"{name} with {new}")


# %% [markdown]
# ## 1. The slider-crank with friction at the slider
#
# Crank 2 ($O_2A$ = 60 mm) turns at a constant 300 rpm; the connecting rod 3 ($AB$ = 200 mm, a
# uniform 1.2 kg rod) drives slider 4 (0.8 kg) along a horizontal guide 20 mm above $O_2$. A gas
# force $F_P$ = 500 N pushes the slider to the left (−x), and the guide has friction $\mu = 0.2$.

# %%
p = gk.load("slider_crank_friction")
print(p.title)
print(p.source)
print(p.notes)
(guide,) = [j for j in p.mechanism.joints if getattr(j, "mu", 0) > 0]
mu = guide.mu
print("friction pair:", guide.label, " μ =", mu)

# %% [markdown]
# ### The friction law, and the sign it needs
#
# Coulomb's law: while the slider slides, the guide pushes on it with a **normal force** $N$ and a
# **friction force** of size $\mu|N|$ that opposes the sliding velocity $V_4$. With a horizontal
# guide the normal force is $F_{14y}$ and
#
# $$F_{14x} = -\operatorname{sign}(V_4)\;\mu\,|F_{14y}| .$$
#
# The notes write $-\operatorname{sign}(V_4)\,\mu F_{14y}$, which is the same thing **as long as
# $F_{14y} > 0$** (the guide pushes the slider up). We will see that here the normal force changes
# side twice a turn; where $F_{14y} < 0$ the unsigned form would turn friction round so that it
# *helps* the motion.
#
# The absolute value makes the equations non-linear. Write $|N| = \sigma N$ with $\sigma = \operatorname{sign}(N)$:
# once $\sigma$ is **assumed**, $F_{14x} = -\mu\,\sigma\,\operatorname{sign}(V_4)\,N$ is a fixed multiple of
# $N$ and the system is linear again. Solve it, then **check** that $N$ came out with the assumed
# sign $\sigma$. If not, take the other sign. graphkin does exactly that at every position.
#
# ### One position: θ₁₂ = 60°

# %%
theta = math.radians(60)
r = p.solve(at=[theta])
k = r.kinematics
vB = k.velocity(4, "B")[0]
N14 = r.normal[(1, 4)][0]
print(f"slider velocity V4 = {vB[0]:.4f} m/s  ({'to the left' if vB[0] < 0 else 'to the right'})")
print(f"normal force N14 = F14y = {N14:.3f} N")
print("G14 (guide on slider) =", r["G14"][0], "N =", show(r["G14"][0]))
print(f"T12 = {r['T12'][0]:.4f} N·m")
G14 = r["G14"][0]
print(f"friction G14x = {G14[0]:+.3f} N: size μ|N14| = {mu * abs(N14):.3f} N, against the sliding")

# %% [markdown]
# ### The matrix
#
# `gk.assemble` writes the three equilibrium equations of every moving link (lesson 01). Compare it
# with the lecture's list of equations:
#
# * the pin forces $\vec F_{12}$, $\vec F_{23}$, $\vec F_{34}$ each bring two columns (graphkin names
#   the force of the lower-numbered link on the higher: $\vec F_{34} = -\vec F_{43}$);
# * the guide brings the columns $N_{14}$ and $C_{14}$. Per unit of $N_{14}$ the guide pushes with
#   $\vec w = (-\mu\sigma\operatorname{sign}V_4,\ 1)$: so in the row *link 4: ΣFx* the column $N_{14}$
#   holds $-\mu\sigma\operatorname{sign}V_4$ — the lecture's $\pm\mu F_{14y}$, with the $\pm$ written out.
#   $F_{14x}$ is not a separate unknown, just as in the notes;
# * $C_{14}$ is the couple the guide can also pass (it places the line of the guide force). The notes
#   leave out the slider's moment equation ("all forces pass through $CG_4$"): here that row reads
#   $C_{14} = 0$. Dropping that row and column gives the lecture's 8 × 8 system.

# %%
system = gk.assemble(r)
print(system.format(0))

# %%
row = system.equations.index("link 4: ΣFx")
col = system.unknowns.index("N14")
sigma = np.sign(N14)
print(f"A[link 4: ΣFx, N14] = {system.A[0, row, col]:+.3f}   (−μ σ sign V4 = {-mu * sigma * np.sign(vB[0]):+.3f})")

x = np.linalg.solve(system.A[0], system.b[0])
sol = dict(zip(system.unknowns, x))
print(f"numpy's solution: N14 = {sol['N14']:.3f} N, C14 = {sol['C14']:.1e} N·m, T12 = {sol['T12']:.4f} N·m"
      f"   (graphkin: N14 = {N14:.3f} N, T12 = {r['T12'][0]:.4f} N·m)")

# %% [markdown]
# `gk.assemble` took $\sigma$ from the answer (that is what the entry above shows). A student does not
# know it in advance, so let us do the **assume-and-check** ourselves: put each sign into the
# friction entry, solve, and see which assumption the answer confirms.

# %%
consistent = []
for s in (+1.0, -1.0):
    A = system.A[0].copy()
    A[row, col] = -mu * s * np.sign(vB[0])
    xs = dict(zip(system.unknowns, np.linalg.solve(A, system.b[0])))
    ok = xs["N14"] * s >= 0
    print(f"assume σ = {s:+.0f}: N14 = {xs['N14']:9.3f} N, T12 = {xs['T12']:8.4f} N·m  ->  "
          f"{'consistent' if ok else 'contradicts the assumption'}")
    if ok:
        consistent.append(xs)

# %% [markdown]
# ### The graphical route: a guide reaction tilted by the friction angle
#
# Without friction a guide pushes normal to itself. With friction the guide force $\vec G_{14}$ is the
# normal force plus the friction force $\mu|N|$, so it leans away from the normal by the **friction
# angle**
#
# $$\rho = \arctan\mu ,$$
#
# and it leans *against* the sliding. Once the side of $N$ is assumed, the direction of $\vec G_{14}$ is
# known before its size — exactly what a force polygon needs. The rod and the slider both carry loads,
# so the construction uses superposition (lesson 02) with the same assumed side in both cases; the
# `note` step says the assumption was confirmed.

# %%
c = gk.construct_forces(k, 0)
for number, step in enumerate(c.steps, start=1):
    print(f"Step {number:2} [{step.kind}] link {step.link}: {step.caption}")

# %%
rho = math.degrees(math.atan(mu))
normal = np.array([0.0, 1.0])  # the guide runs along x
G14g = c.force(1, 4)
print(f"friction angle ρ = atan μ = {rho:.3f}°")
print(f"G14 = {show(G14g)}: tilted {tilt(G14g, normal):.3f}° from the guide's normal, "
      f"its x part {'+' if G14g[0] > 0 else '−'}, the slider moves {'−' if vB[0] < 0 else '+'}x")

# While only the rod is loaded, the slider passes the rod's force on along the tilted guide line:
(two_force,) = [s for s in steps_of(c, "two-force", 4)]
(F43_line,) = two_force.lines
print(f"{two_force.caption}\n  its line through B is tilted {tilt(F43_line.direction, normal):.3f}° from the normal")

# %% [markdown]
# Both routes, force by force:

# %%
print(f"{'':5}{'graphical':>24}{'analytical':>24}{'rel. diff':>11}")
for name in r.names():
    g, a = c[name], r[name][0]
    if np.ndim(a) == 0:
        g_text, a_text = f"{g:.4f} N·m", f"{a:.4f} N·m"
    else:
        g_text, a_text = show(g), show(a)
    print(f"{name:5}{g_text:>24}{a_text:>24}{rel(g, a):>11.1e}")

# %% [markdown]
# The whole solution on one sheet. On the slider's free body (link 4) the dashed line through $B$ is the
# guide's **normal**, and the arc between it and $\vec G_{14}$ is the friction angle $\rho$: the guide's force
# leans away from the normal by exactly $\rho = \arctan\mu$ = 11.31°, against the sliding. Each polygon's scale
# bar also gives the drawing scale (1 mm = … N), to redraw it by hand.

# %%
sheet = gk.draw.draw_solution(c, r)
sheet

# %% [markdown]
# The graphical route agrees at other positions too, including those where the normal force pushes
# the other way (the construction then redoes its polygons with the other side assumed):

# %%
at = np.radians(np.arange(0, 360, 30))
rs = p.solve(at=at)
worst = 0.0
for i, th in enumerate(at):
    ci = gk.construct_forces(rs.kinematics, i)
    worst = max(worst, max(rel(ci[name], rs[name][i]) for name in rs.names()))
    print(f"θ12 = {math.degrees(th):5.0f}°: N14 = {rs.normal[(1, 4)][i]:8.2f} N, "
          f"T12 = {rs['T12'][i]:8.3f} N·m (analytical), {ci.effort:8.3f} N·m (graphical)")
print(f"largest relative difference over these positions: {worst:.1e}")

# %% [markdown]
# ## 2. Friction over a whole turn
#
# Now the whole cycle, once with the file's $\mu$ = 0.2 and once without friction.
# `p.with_friction(0.0)` is the same problem with $\mu = 0$ at every sliding pair (any other $\mu$ works
# the same way). A problem file is text, so the frictionless problem is also the same file with
# `mu = 0.0`: the helper `edited` replaces that line and parses the text again. The two ways must agree.

# %%
p0 = p.with_friction(0.0)
p0_file = edited("slider_crank_friction", "mu = 0.2", "mu = 0.0")

n = 360
cyc, cyc0 = gk.sweep(p, n), gk.sweep(p0, n)

deg = np.degrees(cyc.q)
res, res0 = cyc.analysis, cyc0.analysis
kin = res.kinematics
V4 = kin.velocity(4, "B")[:, 0]
N = res.normal[(1, 4)]
G = res["G14"]
omega = float(cyc.q_dot[0])
print(f"ω = {omega:.4f} rad/s (300 rpm), {n} positions")
print(f"average T12: {cyc.average:.4f} N·m with friction, {cyc0.average:.2e} N·m without")
print(f"T12 range: {cyc.torque.min():.2f} … {cyc.torque.max():.2f} N·m with friction, "
      f"{cyc0.torque.min():.2f} … {cyc0.torque.max():.2f} N·m without")

# %%
fig = Figure(figsize=(11, 7.5))
ax1, ax2 = fig.subplots(2, 1, sharex=True)
ax1.plot(deg, cyc0.torque, color="#0072B2", label="μ = 0")
ax1.plot(deg, cyc.torque, color="#D55E00", label=f"μ = {mu:g}")
ax1.fill_between(deg, cyc0.torque, cyc.torque, color="#D55E00", alpha=0.2, label="extra torque for friction")
ax1.axhline(0, color="0.6", lw=0.6)
ax1.set_ylabel("T₁₂ (N·m)")
ax1.legend(loc="upper left")
ax1.set_title("Driving torque over one turn")
ax2.plot(deg, G[:, 0], color="#D55E00", label="friction G₁₄ₓ (N)")
ax2.plot(deg, N, color="#009E73", label="normal force N₁₄ = G₁₄ᵧ (N)")
ax2.plot(deg, V4 * 100, color="#CC79A7", ls="--", label="slider velocity V₄ (cm/s)")
ax2.axhline(0, color="0.6", lw=0.6)
ax2.set_xlabel("θ₁₂ (deg)")
ax2.set_xlim(0, 360)
ax2.set_xticks(range(0, 361, 30))
ax2.legend(loc="upper left", fontsize=9)
ax2.set_title("At the guide")
fig

# %% [markdown]
# ### The friction force flips with the velocity — not with the normal force
#
# The slider stops and turns back at the two **dead centres**, where crank and rod are in line. With
# offset $e$, crank $r$ and rod $l$, the extended position has $\sin\theta = e/(r+l)$ and the folded one
# $\theta = 180° + \arcsin\big(e/(l-r)\big)$. We compute these angles from the geometry alone and check
# that the slider's velocity — and with it the friction force — changes sign there and nowhere else.

# %%
e, crank, rod = 0.020, 0.060, 0.200
dead = np.array([math.asin(e / (crank + rod)), math.pi + math.asin(e / (rod - crank))])
print("dead centres from the geometry: θ12 =", np.round(np.degrees(dead), 3), "deg")

V_dead = p.kinematics(at=dead).velocity(4, "B")[:, 0]
print("slider velocity there:", V_dead, "m/s")

flips_V = np.flatnonzero(np.sign(V4) != np.sign(np.roll(V4, -1)))
flips_F = np.flatnonzero(np.sign(G[:, 0]) != np.sign(np.roll(G[:, 0], -1)))
flips_N = np.flatnonzero(np.sign(N) != np.sign(np.roll(N, -1)))
print("V4 changes sign between θ =", [f"{deg[i]:.0f}°…{deg[i] + 1:.0f}°" for i in flips_V])
print("friction changes sign between θ =", [f"{deg[i]:.0f}°…{deg[i] + 1:.0f}°" for i in flips_F])
print("N changes sign between θ =", [f"{deg[i]:.0f}°…{deg[i] + 1:.0f}°" for i in flips_N])

# %% [markdown]
# Everywhere on the turn the friction force has size $\mu|N|$ and opposes the sliding. So at a dead centre it
# **jumps**: a hair before and a hair after (±0.01°) it has the opposite sense. Its size $\mu|N|$ changes a little
# too, because the tilt of the guide reaction changes how the loads share out, so $N$ itself changes. The driving
# torque hardly notices: crank and rod are in line, so the rod's force has almost no moment about $O_2$.
#
# At the exact dead centre the slider is at rest, and Coulomb's law only bounds the friction, $|F| \le \mu|N|$ —
# static friction, which the kinetostatic model cannot size. graphkin takes it as **zero** there: where the slide
# rate is below $10^{-9}$ of the mechanism's velocity scale (the fastest joint point), `Kinematics.slide_sense` is 0
# instead of ±1, and the guide pushes normal to itself. Without that rule, the rounding error left in the computed
# velocity, about $10^{-17}$ m/s of either sign, would switch on full friction in a random sense. So at the dead
# centre the solution *with* friction is exactly the frictionless one, and lies between its two neighbours:

# %%
print(f"over the turn: |friction| − μ|N| at most {np.max(np.abs(np.abs(G[:, 0]) - mu * np.abs(N))):.0e} N;"
      f" friction against V4 at {np.sum(np.sign(G[:, 0]) == -np.sign(V4))} of {n} positions")
hair = math.radians(0.01)
for th in dead:
    around = p.solve(at=[th - hair, th, th + hair])
    Ga, Na, Va = around["G14"], around.normal[(1, 4)], around.kinematics.velocity(4, "B")[:, 0]
    print(f"θ12 = {math.degrees(th):7.3f}° − 0.01°, exactly, + 0.01°:\n"
          f"   V4 {Va[0]:+.5f} → {Va[1]:+.0e} → {Va[2]:+.5f} m/s,  friction {Ga[0, 0]:+7.3f} → {Ga[1, 0]:+.3f} → {Ga[2, 0]:+7.3f} N,\n"
          f"   N14 {Na[0]:+8.3f} → {Na[1]:+8.3f} → {Na[2]:+8.3f} N,  T12 {around['T12'][0]:+.4f} → {around['T12'][1]:+.4f}"
          f" → {around['T12'][2]:+.4f} N·m")

guide_kin = p.kinematics(at=dead)
print("slide_sense at the dead centres:", guide_kin.slide_sense(guide, guide.slider))
at_dead, at_dead0 = p.solve(at=dead), p0.solve(at=dead)
print("at the dead centres the solution with μ =", mu, "is the frictionless one: T12 =", at_dead.effort, "N·m")

# %% [markdown]
# And the unsigned form $F_{14x} = -\operatorname{sign}(V_4)\,\mu F_{14y}$ from the notes: it gives the
# right friction force wherever $F_{14y} > 0$, and the **wrong sense** wherever $F_{14y} < 0$ — which
# here is most of the turn.

# %%
lecture = -np.sign(V4) * mu * G[:, 1]
agree = np.isclose(lecture, G[:, 0])
print(f"N14 < 0 at {np.sum(N < 0)} of {n} positions; the unsigned form is wrong at {np.sum(~agree)} of them")
for th in (60, 120, 240, 300):
    i = int(np.argmin(abs(deg - th)))
    print(f"θ12 = {th:3}°: V4 = {V4[i]:+.3f} m/s, N14 = {N[i]:+8.2f} N, friction {G[i, 0]:+7.2f} N, "
          f"−sign(V4) μ F14y = {lecture[i]:+7.2f} N")

# %% [markdown]
# ### The work lost to friction
#
# Compare the two solutions at the same crank angle. The kinematics are the same, so the inertia
# loads and the gas force take the same power in both. The pin forces do no net work (each pair of
# $\vec F_{ij}$, $\vec F_{ji}$ acts at one point moving with one velocity), and in the frictionless case the
# guide force is normal to the sliding, so it does no work either (nor does the guide's couple: the slider does not
# turn). The **only** difference is the
# friction force, whose power is $-\mu|N||V_4|$. Hence, at every instant,
#
# $$\big(T_{12} - T_{12}^{\mu=0}\big)\,\omega_2 = \mu\,|N|\,|V_4| ,$$
#
# with $N$ the normal force *with* friction. Over one turn (period $2\pi/\omega_2$):
#
# $$W_f = \oint \big(T_{12} - T_{12}^{\mu=0}\big)\,d\theta = \int_0^{2\pi/\omega_2} \mu\,|N|\,|V_4|\,dt > 0 .$$

# %%
P_f = mu * np.abs(N) * np.abs(V4)  # friction power [W]
extra = (cyc.torque - cyc0.torque) * omega
print(f"largest |(T12 − T12⁰)ω − μ|N||V4|| over the turn: {np.max(np.abs(extra - P_f)):.1e} W "
      f"(friction power up to {P_f.max():.1f} W)")

period = 2 * math.pi / omega
W_in, W_in0 = 2 * math.pi * cyc.average, 2 * math.pi * cyc0.average  # ∮ T dθ
W_f = np.mean(P_f) * period  # ∫ μ|N||V4| dt, trapezoidal rule on the periodic grid
print(f"input work per turn: {W_in:.4f} J with friction, {W_in0:.1e} J without")
print(f"work lost to friction per turn: {W_f:.4f} J  (average friction power {W_f / period:.2f} W)")

# %% [markdown]
# Without friction the motor does **no net work** over a turn: the kinetic energy comes back to the
# same value, and the constant gas force gives back on one stroke exactly the work it takes on the
# other. That is a check of its own:

# %%
print(f"motor's work per turn without friction: {W_in0:.1e} J"
      f"  (its torque swings over ±{np.max(np.abs(cyc0.torque)):.0f} N·m)")

# %% [markdown]
# A last check of the friction solution, with no frictionless solution involved: the **power balance**
# of the whole linkage. Motor, inertia loads (d'Alembert), gas force and guide force must take zero power
# together at every crank angle:
#
# $$T_{12}\,\omega_2 + \sum_j \big(\vec F_{ji}\cdot\vec v_{Gj} + T_{ji}\,\omega_j\big) + \vec F_P\cdot\vec v_B + \vec G_{14}\cdot\vec v_B = 0 .$$
#
# And a rough size: the slider slides twice its stroke per turn, against at most $\mu\max|N|$.

# %%
P_inertia = sum(np.sum(res.inertia(j).F * kin.v_G(j), axis=1) + res.inertia(j).T * kin.omega[j] for j in (2, 3, 4))
vB_all = kin.velocity(4, "B")
FP = np.array(p.mechanism.loads[0].force)
balance = cyc.torque * omega + P_inertia + vB_all @ FP + np.sum(G * vB_all, axis=1)
print(f"largest residual of the power balance: {np.max(np.abs(balance)):.1e} W")

stroke = math.sqrt((rod + crank) ** 2 - e**2) - math.sqrt((rod - crank) ** 2 - e**2)
print(f"stroke {stroke * 1e3:.2f} mm; μ max|N| · 2·stroke = {mu * np.abs(N).max() * 2 * stroke:.3f} J ≥ W_f = {W_f:.3f} J")

# %% [markdown]
# ### The interactive explorer
#
# `gk.explore(problem)` shows the mechanism, each link's free body, every force polygon and the torque
# curve with a marker. Move the slider (crank angle) or change the speed. In a live notebook, watch
# $\vec G_{14}$ lean the other way as the crank passes the dead centres near 4° and 188°.

# %%
ex = gk.explore(p)
ex

# %% [markdown]
# The explorer is also an object we can drive from code. We set the crank angle and check what it
# shows against a solve of our own: the one-position analytical answer (`ex.analytical`), the graphical
# construction it draws (`ex.construction`), the marker on the torque curve, the status line, and the
# sweep behind the curve (`ex.cycle`).

# %%
ex.speed.value = 300  # the file's speed, whatever was typed above: this cell depends on nothing done before it
for angle in (60.0, 150.0, 240.0, 330.0):
    ex.slider.value = angle
    mine = p.solve(at=[math.radians(angle)])
    shown_T = ex.analytical["T12"][0]
    x_marker, y_marker = (float(v[0]) for v in ex.marker.get_data())
    print(f"θ12 = {angle:5.1f}°: explorer T12 = {shown_T:8.4f} (analytical), {ex.construction.effort:8.4f} (graphical); "
          f"own solve {mine['T12'][0]:8.4f} N·m;  G14 drawn = {show(ex.construction['G14'])}")

# %% [markdown]
# Doubling the speed to 600 rpm recomputes the torque curve: the explorer solves `p.at_speed(ω)`, the same
# problem at another constant crank speed. We check it against a route that does not use `at_speed`: the same
# file with `omega = "600 rpm"`.

# %%
ex.speed.value = 600
fast = edited("slider_crank_friction", 'omega = "300 rpm"', 'omega = "600 rpm"')
fast_cycle = gk.sweep(fast, n)
print(f"at 600 rpm: average T12 = {ex.cycle.average:.4f} N·m (explorer), {fast_cycle.average:.4f} N·m (own sweep)")
ex.speed.value = 300  # back to the file's speed

# %% [markdown]
# ## 3. The gearset
#
# Gear 2 (pitch radius $r_2$ = 100 mm, 3 kg, $I_{G2}$ = 0.015 kg·m²) drives pinion 3 ($r_3$ = 40 mm,
# 0.6 kg, $I_{G3}$ = 0.0005 kg·m²), both pivoted on the frame at their centres, $O_3$ 140 mm to the right
# of $O_2$. The pressure angle is $\phi$ = 20°. At the instant solved the gear turns at 120 rpm CCW and
# speeds up at 50 rad/s²; a resisting torque $T_{13}$ = 8 N·m acts on the pinion (CCW, against the pinion's
# CW rotation). Find the tooth force, the pivot forces and the driving torque $T_{12}$.

# %%
g = gk.load("gearset")
print(g.title)
print(g.source)
print(g.notes)
(mesh,) = [j for j in g.mechanism.joints if hasattr(j, "pressure_angle")]
r2, r3 = mesh.radii
phi = mesh.pressure_angle
(T13,) = [ld.torque for ld in g.mechanism.loads]
m2, m3 = g.mechanism.link(2).mass, g.mechanism.link(3).mass
I2, I3 = g.mechanism.link(2).I_G, g.mechanism.link(3).I_G
print(f"r2 = {r2 * 1e3:g} mm, r3 = {r3 * 1e3:g} mm, φ = {math.degrees(phi):g}°, T13 = {T13:g} N·m")

# %% [markdown]
# ### Kinematics
#
# The pitch circles roll on each other, so $\omega_3 = -(r_2/r_3)\,\omega_2$ and $\alpha_3 = -(r_2/r_3)\,\alpha_2$
# (external gears turn opposite ways). The centres of mass are on the fixed pivots: no inertia forces,
# only inertia torques $-I_G\alpha$.

# %%
rg = g.solve()
kg = rg.kinematics
w2, w3, a2, a3 = kg.omega[2][0], kg.omega[3][0], kg.alpha[2][0], kg.alpha[3][0]
print(f"ω2 = {w2:.4f} rad/s, ω3 = {w3:.4f} rad/s;  α2 = {a2:g} rad/s², α3 = {a3:g} rad/s²")
for j in (2, 3):
    print(f"link {j}: F_i = {rg.inertia(j).F[0]} N, T_i = {rg.inertia(j).T[0]:+.4f} N·m")

# %% [markdown]
# ### The equations, and the pressure-angle constraint
#
# The lecture's equations, with $\vec R_{32}$ from $O_2$ to the pitch point $P$ and $\vec R_{23}$ from $O_3$ to $P$:
#
# $$\begin{aligned}
# &(1)\ F_{12x} + F_{32x} = m_2A_{G2x} &&(4)\ F_{13x} - F_{32x} = m_3A_{G3x}\\
# &(2)\ F_{12y} + F_{32y} = m_2A_{G2y} &&(5)\ F_{13y} - F_{32y} = m_3A_{G3y}\\
# &(3)\ T_{12} + R_{32x}F_{32y} - R_{32y}F_{32x} = I_{G2}\alpha_2 &&(6)\ T_{13} - (R_{23x}F_{32y} - R_{23y}F_{32x}) = I_{G3}\alpha_3
# \end{aligned}$$
#
# Seven unknowns ($F_{12x}, F_{12y}, F_{13x}, F_{13y}, F_{32x}, F_{32y}, T_{12}$), six equations. The seventh relation
# is the tooth geometry: the tooth force lies on the **pressure line**, inclined $\phi$ to the common tangent at
# $P$. Here the centres lie on the x-axis, so the tangent is the y-direction, the tangential part of the tooth
# force is $F_{32y}$ and the radial part $F_{32x}$ has size $\tan\phi\,|F_{32y}|$:
#
# $$(7)\quad F_{32x} = c\,F_{32y}, \qquad |c| = \tan\phi .$$
#
# The sign of $c$: the radial part always **pushes the gears apart**. The notes' $c = \tan\phi\,\operatorname{sign}(F_{32y})$
# makes $F_{32x} > 0$, which pushes gear 2 away from a pinion lying on its −x side. In our file the pinion is on
# the **+x side**, so $F_{32x}$ must be negative: $c = -\tan\phi\,\operatorname{sign}(F_{32y})$. Either way $c$ depends on
# the sign of the answer $F_{32y}$ — assume, solve, check, as for friction.
#
# ### graphkin's matrix: one unknown along the pressure line
#
# graphkin uses the pressure-angle relation the other way round: its single mesh unknown $F_{23}$ is the size of
# the tooth force *along the pressure line*, so the column of $F_{23}$ holds the pressure line's direction
# $(\sin\phi, \cos\phi)$ in the rows of link 3 and its negative in the rows of link 2, and the moment rows hold its
# moment arms. Six unknowns, six equations.

# %%
sys_g = gk.assemble(rg)
print(sys_g.format(0))

# %%
cF = sys_g.unknowns.index("F23")
rows3 = [sys_g.equations.index(f"link 3: ΣF{a}") for a in "xy"]
d = sys_g.A[0, rows3, cF]
print(f"column F23 in link 3's force rows: {d}  = (sin φ, cos φ) = ({math.sin(phi):.4f}, {math.cos(phi):.4f})")
xg = dict(zip(sys_g.unknowns, np.linalg.solve(sys_g.A[0], sys_g.b[0])))
for name, value in xg.items():
    print(f"{name:>5} = {value:10.4f}")

# %% [markdown]
# ### The lecture's 6 × 6, built by hand
#
# Now the lecture's own form: eliminate $F_{32x} = cF_{32y}$ and keep $F_{32y}$ as the unknown,
#
# $$\begin{bmatrix} 1&0&c&0&0&0\\ 0&1&1&0&0&0\\ 0&0&X&0&0&1\\ 0&0&-c&1&0&0\\ 0&0&-1&0&1&0\\ 0&0&Y&0&0&0 \end{bmatrix}
# \begin{Bmatrix}F_{12x}\\F_{12y}\\F_{32y}\\F_{13x}\\F_{13y}\\T_{12}\end{Bmatrix} =
# \begin{Bmatrix}m_2A_{G2x}\\m_2A_{G2y}\\I_{G2}\alpha_2\\m_3A_{G3x}\\m_3A_{G3y}\\I_{G3}\alpha_3 - T_{13}\end{Bmatrix},
# \qquad X = R_{32x} - cR_{32y},\quad Y = cR_{23y} - R_{23x}.$$
#
# We build it with numpy from the data and the kinematics only (nothing from graphkin's force solution),
# for each assumed sign of $F_{32y}$, and keep the assumption the answer confirms.

# %%
O2, O3 = kg.position(2, "O2")[0], kg.position(3, "O3")[0]
P = O2 + r2 * (O3 - O2) / np.linalg.norm(O3 - O2)  # the pitch point
R32, R23 = P - O2, P - O3
A2, A3 = kg.a_G(2)[0], kg.a_G(3)[0]
rhs = np.array([m2 * A2[0], m2 * A2[1], I2 * a2, m3 * A3[0], m3 * A3[1], I3 * a3 - T13])
lecture_answer = None
for s in (+1.0, -1.0):
    cc = -math.tan(phi) * s  # pinion on the +x side (see above)
    X, Y = R32[0] - cc * R32[1], cc * R23[1] - R23[0]
    A = np.array([[1, 0, cc, 0, 0, 0], [0, 1, 1, 0, 0, 0], [0, 0, X, 0, 0, 1],
                  [0, 0, -cc, 1, 0, 0], [0, 0, -1, 0, 1, 0], [0, 0, Y, 0, 0, 0]], float)
    F12x, F12y, F32y, F13x, F13y, T12 = np.linalg.solve(A, rhs)
    ok = np.sign(F32y) == s
    print(f"assume sign(F32y) = {s:+.0f}: c = {cc:+.4f}, F32y = {F32y:9.3f} N, T12 = {T12:.4f} N·m -> "
          f"{'consistent' if ok else 'contradicts the assumption'}")
    if ok:
        lecture_answer = dict(F12=np.array([F12x, F12y]), F32=np.array([cc * F32y, F32y]), F13=np.array([F13x, F13y]), T12=T12)
print("the lecture's matrix and graphkin agree:", show(-lecture_answer["F32"]), "=", show(rg["F23"][0]))

# %% [markdown]
# Row (6) has only the one unknown $F_{32y}$ ($Y = -R_{23x}$ here, since $R_{23y} = 0$): the pinion's moment
# balance alone fixes the tangential tooth force, whatever $c$ is. That is why exactly one sign is consistent.
#
# ### Mesh force and torque ratio
#
# Take moments about each fixed centre, where the unknown pivot force has no moment.
#
# * **Pinion**, about $O_3$: the tangential tooth force $W_t$ at radius $r_3$ balances the load torque and the
#   inertia torque, $W_t = (T_{13} - I_{G3}\alpha_3)/r_3$.
# * The tooth force along the pressure line is $W = W_t/\cos\phi$; its radial part $W_r = W_t\tan\phi$ pushes the
#   gears apart and loads the bearings, but has no moment about either centre.
# * **Gear**, about $O_2$: $T_{12} - I_{G2}\alpha_2 = r_2 W_t$, so
#
# $$T_{12} - I_{G2}\alpha_2 = \frac{r_2}{r_3}\,\big(T_{13} - I_{G3}\alpha_3\big) ,$$
#
# the torque ratio $r_2/r_3$ = 2.5 (with both torques CCW-positive; without inertia simply $T_{12} = 2.5\,T_{13}$).

# %%
F23 = rg["F23"][0]
W_t = (T13 - I3 * a3) / r3
W = W_t / math.cos(phi)
W_r = W_t * math.tan(phi)
e23 = (O3 - O2) / np.linalg.norm(O3 - O2)  # from gear centre to pinion centre
print(f"W_t = {W_t:.3f} N, W = W_t / cos φ = {W:.3f} N, W_r = W_t tan φ = {W_r:.3f} N")
print(f"graphkin: F23 = {show(F23)} (tangential {F23[1]:.3f} N, radial {F23 @ e23:.3f} N, pushing the pinion away)")

T12g = rg["T12"][0]
print(f"T12 = {T12g:.4f} N·m;  I2 α2 + (r2/r3)(T13 − I3 α3) = {I2 * a2 + r2 / r3 * (T13 - I3 * a3):.4f} N·m")
print(f"torque ratio without the inertia torques: (T12 − I2α2)/(T13 − I3α3) = {(T12g - I2 * a2) / (T13 - I3 * a3):.4f}")

# %% [markdown]
# The pressure angle changes the **bearing loads**, not the torques: the radial part has no moment about the
# centres. A check on re-parsed files with $\phi$ = 14.5° and 25°:

# %%
for new in ("14.5 deg", "25 deg"):
    gp = edited("gearset", 'pressure_angle = "20 deg"', f'pressure_angle = "{new}"')
    rp = gp.solve()
    phi_p = math.radians(float(new.split()[0]))
    print(f"φ = {new:>8}: T12 = {rp['T12'][0]:.4f} N·m, |F23| = {np.linalg.norm(rp['F23'][0]):7.3f} N "
          f"(W_t / cos φ = {W_t / math.cos(phi_p):7.3f} N)")

# %% [markdown]
# ### The graphical route
#
# The pinion carries no inertia force, only torques: its loads reduce to a **pure couple**
# $T_{13} + T_{3i}$. It is held by the tooth force, whose line is known (the pressure line through $P$), and
# the pivot force at $O_3$. A couple can only be balanced by a couple: the pivot force is equal, opposite and
# parallel to the tooth force, $\vec F_{13} = -\vec F_{23}$, and its arm is the distance from $O_3$ to the pressure
# line. That distance is the **base-circle radius** $r_3\cos\phi$: the pressure line is tangent to both base
# circles, which is why the moment arm of the tooth force is $r\cos\phi$ and not $r$.
#
# So the pinion is **not** a three-force member: there is no resultant force for the two others to meet. The
# construction says so. It reduces the pinion's loads to the couple, puts the tooth force on the pressure line, and
# then states that gear 3 carries only a couple, which $\vec F_{23}$ and the pivot force $\vec F_{13}$ balance by
# forming the opposite couple; the force polygon of gear 3 has just those **two** arrows, $\vec F_{23} + \vec F_{13} = 0$.
# Gear 2 carries $\vec F_{32}$ and the inertia torque of a gear that speeds up; they reduce to one force, and the
# driver step balances it.
# %%
cg = gk.construct_forces(kg, 0)
for number, step in enumerate(cg.steps, start=1):
    print(f"Step {number} [{step.kind}] link {step.link}: {step.caption}")

# %%
(pressure,) = steps_of(cg, "line", 3)  # the tooth force's line: the pressure line
(couple,) = steps_of(cg, "couple", 3)  # the pivot force's line: F13 = −F23, a couple
(line,) = pressure.lines
print("pitch point P =", np.array(pressure.points["P"]) * 1e3, "mm")
print(f"pressure line: {tilt(line.direction, e23):.3f}° from the line of centres "
      f"(= 90° − φ), distance {off_line(O2, line) * 1e3:.3f} mm from O2 and {off_line(O3, line) * 1e3:.3f} mm from O3")
print(f"base circles: r2 cos φ = {r2 * math.cos(phi) * 1e3:.3f} mm, r3 cos φ = {r3 * math.cos(phi) * 1e3:.3f} mm")

(poly3,) = steps_of(cg, "polygon", 3)
print(poly3.caption, "—", len(poly3.polygon), "arrows:", ", ".join(arrow.name for arrow in poly3.polygon))
F23g = np.array(poly3.values["F23"])
(pivot_line,) = couple.lines
print(f"gear 3: |F23| · r3 cos φ = {np.linalg.norm(F23g) * r3 * math.cos(phi):.4f} N·m = T13 + T3i = "
      f"{T13 + rg.inertia(3).T[0]:.4f} N·m")

(drive,) = steps_of(cg, "driver")
print(drive.caption)

# %% [markdown]
# On gear 2 the tooth force $\vec F_{32}$ and the inertia torque $T_{2i}$ add up to one resultant $\vec R_2$: the same
# vector as $\vec F_{32}$ on a line shifted from the pressure line. The pivot force and $\vec R_2$ form the couple
# $|\vec R_2|\,d$ that the motor balances; $d$ is a little more than the base radius because $T_{2i}$ moved the
# line. Both routes side by side:

# %%
print(f"{'':5}{'graphical':>24}{'analytical':>24}{'rel. diff':>11}")
for name in rg.names():
    gv, av = cg[name], rg[name][0]
    g_text, a_text = (f"{gv:.4f} N·m", f"{av:.4f} N·m") if np.ndim(av) == 0 else (show(gv), show(av))
    print(f"{name:5}{g_text:>24}{a_text:>24}{rel(gv, av):>11.1e}")

# %%
gk.draw.draw_solution(cg, rg)

# %% [markdown]
# ### Power balance over a cycle
#
# Sweep one turn of the gear. Both gears turn about their centres of mass, so nothing in the force analysis
# depends on the angle: the driving torque is the same at every position. At every instant the motor, the load
# and the inertia torques take zero power together (the pivots do not move, and the tooth forces of 2 on 3
# and of 3 on 2 act at the pitch point, where both pitch circles have the same velocity):
#
# $$T_{12}\,\omega_2 + T_{13}\,\omega_3 + T_{2i}\,\omega_2 + T_{3i}\,\omega_3 = 0 ,$$
#
# that is, power in = power to the load + rate of change of kinetic energy $I_{G2}\alpha_2\omega_2 + I_{G3}\alpha_3\omega_3$.

# %%
gcyc = gk.sweep(g, 72)
ga = gcyc.analysis
kin_g = ga.kinematics
P_in = gcyc.power
P_load = T13 * kin_g.omega[3]
dEdt = I2 * kin_g.alpha[2] * kin_g.omega[2] + I3 * kin_g.alpha[3] * kin_g.omega[3]
print(f"power in {P_in[0]:.3f} W = to the load {-P_load[0]:.3f} W + into kinetic energy {dEdt[0]:.3f} W")
# The tooth force's power: the velocity of P is the same on both pitch circles.
vP2 = kin_g.omega[2][:, None] * np.array([-R32[1], R32[0]])
vP3 = kin_g.omega[3][:, None] * np.array([-R23[1], R23[0]])
P_teeth = np.sum(ga["F23"] * vP3, axis=1) + np.sum(ga["F32"] * vP2, axis=1)
print(f"the velocity of P on the two pitch circles differs by at most {np.abs(vP2 - vP3).max():.0e} m/s;"
      f" the two tooth forces take {np.abs(P_teeth).max():.0e} W together")

# %% [markdown]
# At a **steady** speed ($\alpha_2 = 0$) no energy goes into the gears: power in equals power out, and over one
# turn of the gear the motor's work $\oint T_{12}\,d\theta_2 = 2\pi T_{12}$ equals the work done against the load,
# $-T_{13}\,\Delta\theta_3$ with $\Delta\theta_3 = -2\pi\, r_2/r_3$ (the pinion turns 2.5 times, clockwise).
# Without inertia the torque ratio is exactly $r_2/r_3$, and this ideal mesh has no losses.

# %%
steady = edited("gearset", 'alpha = "50 rad/s^2"', 'alpha = "0 rad/s^2"')
scyc = gk.sweep(steady, 72)
sk = scyc.analysis.kinematics
W_motor = 2 * math.pi * scyc.average
dtheta3 = -2 * math.pi * r2 / r3
W_load = -T13 * dtheta3
print(f"steady speed: T12 = {scyc.average:.4f} N·m = (r2/r3) T13 = {r2 / r3 * T13:.4f} N·m")
print(f"per turn of the gear: motor work {W_motor:.4f} J, work against the load {W_load:.4f} J")

# %% [markdown]
# ### The explorer for the gearset
#
# Turn the gear with the slider: the teeth move (a spoke on each gear marks its x-axis, and the pinion turns 2.5
# times as far the other way), the forces do not (the torque curve is flat). Then we drive it from code and compare
# with our own solve.

# %%
ex_g = gk.explore(g)
ex_g

# %%
for angle in (0.0, 90.0, 200.0):
    ex_g.slider.value = angle
    mine = g.solve(at=[math.radians(angle)])
    print(f"θ12 = {angle:5.1f}°: explorer T12 = {ex_g.analytical['T12'][0]:.4f} (analytical), "
          f"{ex_g.construction.effort:.4f} (graphical); own solve {mine['T12'][0]:.4f} N·m; "
          f"F23 drawn = {show(ex_g.construction['F23'])}")

# %% [markdown]
# ### The worked solutions, to keep
#
# Both examples of this lesson are written out as textbook solutions — the data, each link's
# kinematics with the numbers, the inertia loads, the matrix with the friction and pressure-angle
# rows, the graphical route step by step (the guide reaction tilted by ρ, the tooth force on the
# pressure line) and both routes side by side — in the handouts
# [`slider_crank_friction.pdf`](../figures/handouts/slider_crank_friction.pdf) and
# [`gearset.pdf`](../figures/handouts/gearset.pdf). Make your own with
#
# ```sh
# graphkin handout slider_crank_friction --at '60 deg' -o slider_crank_friction.pdf
# graphkin handout gearset -o gearset.html
# ```

# %% [markdown]
# ## 4. Your turn
#
# Two exercises with **your own numbers**: every student id gets its own crank angle, speed and
# coefficient of friction for the slider-crank, and its own speed, acceleration and load for the
# gears, the same each time you run the notebook. Type the id your teacher gave you between the
# quotes below, in place of `"your-id"`, and run the cells from here. Answer in the boxes and press
# **Check**, or in code with `gk.exercises.check`: the grader reads numbers with their units as you would
# write them (`"85.2 N ∠ 61.5°"`, `"20.4 N*m CW"`, `"410 N"`) and, when an answer is off, tells you
# what kind of slip it looks like.

# %%

student = "your-id"  # ← type your own id here

# %% [markdown]
# ### Exercise 1: your slider-crank with friction
#
# The slider-crank of section 1 (its gas force, dimensions and masses) at your own crank angle, speed
# and coefficient of friction:

# %%
gk.exercise("slider_crank_friction", student)

# %% [markdown]
# `gk.exercises.variant(name, student).problem` is your machine as a `Problem`, just like `p`; `.solve()`
# solves it at your angle (section 1), or draw the polygons with the guide reaction tilted by your
# friction angle. Then type your answers in the boxes above, or fill them in here and run the cell:

# %%
my_slider = gk.exercises.variant("slider_crank_friction", student).problem
# your work here: my_slider.solve(), then G14, |F34| and T12
answers = {"G14": "", "F34": "", "T12": ""}  # e.g. "12.3 N ∠ 45.6°", "123 N", "1.23 N*m CCW"
print(gk.exercises.check("slider_crank_friction", student, answers))

# %% [markdown]
# ### What the feedback looks like
#
# A made-up student, `"example"`, got the guide force the wrong way round — they gave the force of
# the slider on the guide, $\vec G_{41} = -\vec G_{14}$ — and the torque right. Their correct answers
# come from `gk.exercises.key`, the teacher's answer sheet (values in SI) — for another id than yours,
# so that nothing is given away:

# %%
demo = "example"
key = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("slider_crank_friction", demo)["questions"]}
slipped = {"G14": show(-np.array(key["G14"])), "T12": f"{key['T12']:.4g} N*m"}  # G14: turned round
print(gk.exercises.check("slider_crank_friction", demo, slipped))

# %% [markdown]
# A slip earns part of the points (a force turned round, half) and says what to look at; a wrong
# answer earns nothing. `gk.exercises.grade(...)` gives the same report as plain data (score, and per
# question the verdict, the slip and the feedback), for your own records.
#
# ### Exercise 2: your gear pair
#
# The gearset of section 3 at your own speed and acceleration of gear 2, with your own load on the
# pinion: the tooth force, the bearing force on the gear and the driving torque.

# %%
gk.exercise("gear_pair", student)

# %%
my_gears = gk.exercises.variant("gear_pair", student).problem
# your work here: my_gears.solve(), then |F23|, F12 and T12
answers = {"F23": "", "F12": "", "T12": ""}  # e.g. "123 N", "123 N ∠ 45.6°", "12.3 N*m CCW"
print(gk.exercises.check("gear_pair", student, answers))

# %% [markdown]
# ### More to try
#
# * **More friction.** Predict first: is the work lost to friction proportional to $\mu$? (It would be if $N$ did not
#   depend on $\mu$.) The cell below sweeps a few values; then try μ = 3. graphkin reports positions where friction
#   **locks** the slider-crank: no side of the normal force is consistent, so no driving torque can move it. Compare
#   the locked angles with where the rod leans more than $90° - \rho$ from the guide.
# * **Turn the load round.** Make `torque = "-8 N*m"` in the gearset: which way does the tooth force tilt now, and on
#   which flank does it push? Does $T_{12}$ just change sign? (Hint: the inertia torques do not change.)
# * **Which side is the pinion?** Move the frame's `O3` to `["-140 mm", "0 mm"]` and check that the notes'
#   $c = \tan\phi\,\operatorname{sign}(F_{32y})$ is then right as written.

# %%
for m in (0.0, 0.1, 0.2, 0.4):  # edit here
    cm = gk.sweep(p.with_friction(m), n)
    if cm.valid.all():
        print(f"μ = {m:4}: work lost to friction per turn {2 * math.pi * (cm.average - cyc0.average):7.3f} J")
    else:
        print(f"μ = {m:4}: no solution at {np.sum(~cm.valid)} positions: {'; '.join(cm.analysis.failures)}")

# %% [markdown]
# **Self-locking.** With μ = 3 the friction angle is $\rho = \arctan 3 = 71.6°$. If the slider were pushed only along
# the rod, it would lock wherever the rod leans more than $90° - \rho = 18.4°$ from the guide: the rod's push then lies
# inside the friction cone, and the harder it pushes, the harder the guide holds. (The rod and the slider have mass, so
# this is a rule of thumb, not an exact law.) Compare with where graphkin finds no consistent side of $N$:

# %%
mu_big = 3.0  # edit here
locked = gk.sweep(p.with_friction(mu_big), n)
A_, B_ = locked.analysis.kinematics.position(3, "A"), locked.analysis.kinematics.position(3, "B")
lean = np.degrees(np.arctan2(np.abs(B_[:, 1] - A_[:, 1]), np.abs(B_[:, 0] - A_[:, 0])))
limit = 90 - math.degrees(math.atan(mu_big))
stuck = ~locked.valid
print(f"μ = {mu_big:g}: locked at {stuck.sum()} of {n} positions", end="")
if stuck.any():
    print(f", from θ12 = {np.degrees(locked.q[stuck]).min():.0f}° to {np.degrees(locked.q[stuck]).max():.0f}°")
    print("   why:", "; ".join(locked.analysis.failures))
else:
    print()
print(f"the rod leans more than 90° − ρ = {limit:.2f}° at {np.sum(lean > limit)} positions; "
      f"the two lists agree at {np.mean((lean > limit) == stuck):.1%} of the turn")

# %% [markdown]
# ## Checks (for the course maintainers; students may skip)
#
# Every claim of the lesson, checked against a route that does not use it, and every number quoted
# in the text checked at the precision it is quoted. Grouped by section; they read the variables the
# sections above computed. The explorers are driven here from a known state, whatever was done with
# them above.

# %% [markdown]
# ### 1. The slider-crank with friction at the slider

# %%
links = {j: p.mechanism.link(j) for j in (1, 2, 3, 4)}
assert np.allclose([e, crank, rod], [links[1].points["E"][1], math.dist(links[2].points["O2"], links[2].points["A"]),
                                     math.dist(links[3].points["A"], links[3].points["B"])])  # the data as quoted
assert [links[3].mass, links[4].mass] == [1.2, 0.8] and p.mechanism.loads[0].force == (-500.0, 0.0) and mu == 0.2
assert math.isclose(abs(G14[0]), mu * abs(N14), rel_tol=1e-12)  # friction = μ|N|
assert np.sign(G14[0]) == -np.sign(vB[0])  # ... against the sliding
assert math.isclose(system.A[0, row, col], -mu * sigma * np.sign(vB[0]))
assert np.allclose([sol["F23x"], sol["F23y"]], r["F23"][0])
assert np.allclose([sol["F34x"], sol["F34y"]], r["F34"][0])
assert math.isclose(sol["N14"], N14) and abs(sol["C14"]) < 1e-9
assert math.isclose(sol["T12"], r["T12"][0])
assert len(consistent) == 1  # assume and check: exactly one side of N is consistent
assert math.isclose(consistent[0]["T12"], r["T12"][0])
assert c.valid and not c.warnings
assert math.isclose(tilt(G14g, normal), rho)
assert np.sign(G14g[0]) == -np.sign(vB[0])
assert math.isclose(tilt(F43_line.direction, normal), rho)
assert np.allclose(F43_line.point, k.position(4, "B")[0])
slider_fbd = next(ax for ax in sheet.axes if ax.get_title().startswith("Free body: link 4"))
assert f"ρ = {rho:.2f}°" in [t.get_text() for t in slider_fbd.texts] and f"{rho:.2f}" == "11.31"  # the sheet shows ρ
for name in r.names():  # both routes, force by force
    gv, av = c[name], r[name][0]
    assert rel(gv, av) < 1e-9, name
for i, th in enumerate(at):  # the graphical route at other positions
    ci = gk.construct_forces(rs.kinematics, i)
    assert ci.valid and not ci.warnings
assert worst < 1e-9

# %% [markdown]
# ### 2. Friction over a whole turn

# %%
assert math.isclose(omega, 300 * math.pi / 30)
assert cyc.closed and cyc.valid.all() and cyc0.valid.all()
assert cyc.n == cyc0.n == n  # the gas force acts all the time: no switching samples to add
assert np.array_equal(gk.sweep(p0_file, n).torque, cyc0.torque)
assert all(getattr(j, "mu", 0.0) == 0.0 for j in p0.mechanism.joints) and guide.mu == mu > 0  # p is unchanged
assert np.allclose(V_dead, 0, atol=1e-12)
assert np.array_equal(np.round(np.degrees(dead)), [4, 188])  # "the dead centres near 4° and 188°"
assert list(flips_F) == list(flips_V) and len(flips_V) == 2
for i, th in zip(flips_V, dead):
    assert cyc.q[i] < th < cyc.q[i] + 2 * np.pi / n
assert not set(flips_N) & set(flips_V)  # here N changes side at other angles
assert len(flips_N) == 2  # "the normal force changes side twice a turn"
assert np.allclose(np.abs(G[:, 0]), mu * np.abs(N))
assert np.all(np.sign(G[:, 0]) == -np.sign(V4))
for th in dead:
    around = p.solve(at=[th - hair, th, th + hair])
    Ga, Na, Va = around["G14"], around.normal[(1, 4)], around.kinematics.velocity(4, "B")[:, 0]
    assert np.sign(Va[0]) == -np.sign(Va[2]) and np.sign(Ga[0, 0]) == -np.sign(Ga[2, 0])
    assert np.allclose(np.abs(Ga[::2, 0]), mu * np.abs(Na[::2]))  # μ|N| either side
    assert Ga[1, 0] == 0.0  # and no friction at the dead centre itself
assert np.array_equal(guide_kin.slide_sense(guide, guide.slider), [0.0, 0.0])
assert np.allclose(at_dead.effort, at_dead0.effort, rtol=1e-12, atol=1e-12)
for name in at_dead0.names():
    assert np.allclose(at_dead[name], at_dead0[name], rtol=1e-12, atol=1e-9), name
assert np.all(agree[N > 0]) and not np.any(agree[(N < 0) & (V4 != 0)])
assert np.sum(N < 0) > n / 2  # the unsigned form is wrong on "most of the turn"
assert np.allclose(extra, P_f, rtol=1e-9, atol=1e-9)
assert W_f > 0
assert math.isclose(W_in - W_in0, W_f, rel_tol=1e-9)
assert abs(W_in0) < 1e-9 * np.max(np.abs(cyc0.torque)) * 2 * math.pi
assert np.allclose(balance, 0, atol=1e-9 * np.max(np.abs(cyc.torque * omega)))
assert np.isclose(np.ptp(kin.position(4, "B")[:, 0]), stroke, rtol=1e-3)
assert W_f <= mu * np.abs(N).max() * 2 * stroke

# %%
# The explorer, driven from a known state: the file's speed, then the four angles, then 600 rpm.
ex.speed.value = 300
assert np.allclose(ex.cycle.torque, cyc.torque)  # the same turn at 300 rpm
for angle in (60.0, 150.0, 240.0, 330.0):
    ex.slider.value = angle
    mine = p.solve(at=[math.radians(angle)])
    shown_T = ex.analytical["T12"][0]
    x_marker, y_marker = (float(v[0]) for v in ex.marker.get_data())
    assert not ex.message
    assert math.isclose(shown_T, mine["T12"][0], rel_tol=1e-12)
    assert math.isclose(ex.construction.effort, mine["T12"][0], rel_tol=1e-9)
    assert rel(ex.construction["G14"], mine["G14"][0]) < 1e-9
    assert math.isclose(tilt(ex.construction["G14"], normal), rho)
    assert math.isclose(x_marker, angle) and math.isclose(y_marker, mine["T12"][0])
    assert f"{mine['T12'][0]:.5g}" in ex.status.value
ex.speed.value = 600
assert np.allclose(ex.cycle.torque, fast_cycle.torque)
assert np.allclose(gk.sweep(p.at_speed(2 * omega), n).torque, fast_cycle.torque)
assert math.isclose(ex.analytical["T12"][0], fast.solve(at=[math.radians(330)])["T12"][0])
ex.speed.value = 300  # back to the file's speed

# %% [markdown]
# ### 3. The gearset

# %%
assert np.allclose([r2, r3, math.degrees(phi), T13, m2, m3, I2, I3], [0.1, 0.04, 20, 8, 3, 0.6, 0.015, 0.0005])
assert np.allclose(O3 - O2, [0.14, 0]) and math.isclose(w2, 120 * math.pi / 30) and a2 == 50  # the data as quoted
assert math.isclose(w3, -r2 / r3 * w2) and math.isclose(a3, -r2 / r3 * a2)
assert np.allclose(kg.a_G(2), 0) and np.allclose(kg.a_G(3), 0)
assert np.allclose(d, [math.sin(phi), math.cos(phi)])
assert np.allclose(xg["F23"] * d, rg["F23"][0])
assert math.isclose(xg["T12"], rg["T12"][0])
assert lecture_answer is not None
assert np.allclose(lecture_answer["F32"], -rg["F23"][0])
assert np.allclose(lecture_answer["F12"], rg["F12"][0]) and np.allclose(lecture_answer["F13"], rg["F13"][0])
assert math.isclose(lecture_answer["T12"], rg["T12"][0])
assert R23[1] == 0.0  # "Y = −R23x here, since R23y = 0"
assert math.isclose(np.linalg.norm(F23), W) and math.isclose(F23 @ e23, W_r)  # radial part pushes 3 away from 2
assert math.isclose(tilt(F23, e23), 90 - math.degrees(phi))  # φ from the tangent = 90° − φ from the line of centres
assert math.isclose(T12g, I2 * a2 + r2 / r3 * (T13 - I3 * a3))
assert np.allclose(rg["F12"][0], F23) and np.allclose(rg["F13"][0], -F23)  # pivots take the tooth force
assert math.isclose(r2 / r3, 2.5)  # the torque ratio; the pinion turns 2.5 times per turn of the gear
for new in ("14.5 deg", "25 deg"):  # the pressure angle changes the bearing loads, not the torques
    rp = edited("gearset", 'pressure_angle = "20 deg"', f'pressure_angle = "{new}"').solve()
    phi_p = math.radians(float(new.split()[0]))
    assert math.isclose(rp["T12"][0], T12g)
    assert math.isclose(np.linalg.norm(rp["F23"][0]), W_t / math.cos(phi_p))

# %%
# The graphical route
assert cg.valid and not cg.warnings
assert not steps_of(cg, "three-force") and "only a couple" in couple.caption
assert np.allclose(pressure.points["P"], P) and np.allclose(cg.pitch_points[(2, 3)], P)
assert math.isclose(tilt(line.direction, e23), 90 - math.degrees(phi))
assert math.isclose(off_line(O2, line), r2 * math.cos(phi)) and math.isclose(off_line(O3, line), r3 * math.cos(phi))
assert [arrow.name for arrow in poly3.polygon] == ["F23", "F13"]
assert np.allclose(pivot_line.point, O3) and math.isclose(tilt(pivot_line.direction, e23), 90 - math.degrees(phi))
assert np.allclose(cg.force(1, 3), -F23g)
assert math.isclose(np.linalg.norm(F23g) * r3 * math.cos(phi), T13 + rg.inertia(3).T[0])
assert math.isclose(drive.values["d"] * np.linalg.norm(drive.values["F12"]), abs(cg.effort))
assert r2 * math.cos(phi) < drive.values["d"] < 1.05 * r2 * math.cos(phi)  # "a little more than the base radius"
for name in rg.names():
    gv, av = cg[name], rg[name][0]
    assert rel(gv, av) < 1e-9, name

# %%
# Power balance, and the explorer driven from a known state
assert gcyc.valid.all() and np.ptp(gcyc.torque) < 1e-12 * abs(T12g)
assert np.allclose(P_in + P_load, dEdt)
assert np.allclose(vP2, vP3)
assert np.allclose(np.sum(ga["F23"] * vP3, axis=1) + np.sum(ga["F32"] * vP2, axis=1), 0)
assert math.isclose(scyc.average, r2 / r3 * T13)
assert np.allclose(scyc.power, -T13 * sk.omega[3])
assert math.isclose(W_motor, W_load)
ex_g.speed.value = 120  # the file's speed
assert np.allclose(ex_g.cycle.torque, T12g)
for angle in (0.0, 90.0, 200.0):
    ex_g.slider.value = angle
    mine = g.solve(at=[math.radians(angle)])
    assert not ex_g.message
    assert math.isclose(ex_g.analytical["T12"][0], mine["T12"][0])
    assert math.isclose(ex_g.construction.effort, mine["T12"][0], rel_tol=1e-9)
    assert rel(ex_g.construction["F23"], mine["F23"][0]) < 1e-9
    assert np.allclose(ex_g.construction.pitch_points[(2, 3)], P)
    # "The teeth move": the spokes drawn on gear 2 and the pinion point along their links' x-axes, θ12 and
    # −2.5 θ12 (the mechanism starts at θ12 = 0 with both axes along x).
    spokes = [ln.get_data() for ln in ex_g.ax_mechanism.lines if ln.get_linewidth() == 2.4]
    turned = [math.degrees(math.atan2(y[1] - y[0], x[1] - x[0])) for x, y in spokes]
    assert len(turned) == 2
    for got, want in zip(turned, (angle, -r2 / r3 * angle)):
        assert abs((got - want + 180) % 360 - 180) < 1e-6, (angle, got, want)

# %% [markdown]
# ### 4. Your turn

# %%
# More to try: the self-locking rule of thumb, with the numbers of its text (whatever μ was typed above).
assert round(math.degrees(math.atan(3.0)), 1) == 71.6 and round(90 - math.degrees(math.atan(3.0)), 1) == 18.4

# The feedback example: a force turned round earns half the points, a right torque all, an empty box none.
report = gk.exercises.grade("slider_crank_friction", demo, slipped)
verdict = {q["id"]: (q["verdict"], q["slip"], q["score"] / q["max"]) for q in report["questions"]}
assert verdict["G14"] == ("slip", "sign", 0.5) and verdict["T12"] == ("correct", None, 1.0)
assert verdict["F34"][0] == "missing"
assert gk.exercises.check("slider_crank_friction", demo, slipped).splitlines()[0].endswith(
    f"{report['score']:g} / 3 points")

# The lesson's own tools give the answer key (for the id the notebook runs with).
key1 = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("slider_crank_friction", student)["questions"]}
r_mine = my_slider.solve()
assert np.allclose(r_mine["G14"][0], key1["G14"], rtol=1e-9, atol=0)
assert math.isclose(np.linalg.norm(r_mine["F34"][0]), key1["F34"], rel_tol=1e-9)
assert math.isclose(r_mine["T12"][0], key1["T12"], rel_tol=1e-9)
key2 = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("gear_pair", student)["questions"]}
r_gears = my_gears.solve()
assert math.isclose(np.linalg.norm(r_gears["F23"][0]), key2["F23"], rel_tol=1e-9)
assert np.allclose(r_gears["F12"][0], key2["F12"], rtol=1e-9, atol=0)
assert math.isclose(r_gears["T12"][0], key2["T12"], rel_tol=1e-9)

# The answer boxes: type an id, fill in the key's answers as it prints them, press Check; then a slip.
box = gk.exercise("slider_crank_friction", "")
box.student.value = demo
assert all(g["shown"] in box.data.value for g in gk.exercises.make("slider_crank_friction", demo)["data"])
for q in gk.exercises.key("slider_crank_friction", demo)["questions"]:
    box.answers[q["id"]].value = q["answer"]["text"]
assert box.check()["score"] == 3
box.answers["G14"].value = slipped["G14"]
assert box.check()["score"] == 2.5 and box.report["questions"][0]["slip"] == "sign"
