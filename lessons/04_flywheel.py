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
# # Lesson 04 — Sizing a flywheel, and the joint-force index
#
# Lessons 01 and 02 found the forces at **one** position of a linkage; lesson 03 followed them
# over a whole turn. This lesson uses the torque the motor must supply at every crank angle. That torque usually swings
# far above and below its average, because the links store kinetic energy and give it back
# twice a turn. A **flywheel** on the crank shaft soaks up those swings, so that a motor sized
# for the *average* torque can drive the machine at a nearly steady speed.
#
# You will
#
# 1. see where the formula $I_s = E/(C_s\,\omega_{avg}^2)$ comes from, and redo the accumulation
#    arithmetic of Norton's Table 11-1 (*Design of Machinery*, §11.11);
# 2. check `graphkin`'s energy table on a torque curve you can integrate by hand;
# 3. size a flywheel for the strip-cutter four-bar at 900 rpm (Söylemez §6.4.1): the average
#    torque, the crossings, the pulse areas, the energy table, the largest swing $E$, the system
#    inertia $I_s$, and a steel disk or a cast-iron rim that provides it;
# 4. look at the machine **before and after**: the speed and the torque the motor sees;
# 5. compute Holte and Chase's **joint-force index** (Norton §11.12) over the cut;
# 6. drive the **interactive explorer** from code, and check what it shows;
# 7. size a flywheel and find the index for **your own data**, and get feedback on your answers.
#
# Every number `graphkin` gives is compared with a route that does not use it: the work of the
# cutting force, the kinetic energy of the links, a hand integration, a simulation of the shaft.
# The checks that keep this notebook honest (every number quoted in the text is verified) are
# collected at the end, in a section students may skip.
# All numbers inside `graphkin` are SI (m, kg, s, N, J, rad); we print degrees and rpm.

# %%
# %matplotlib inline

import math

import numpy as np
from IPython.display import Image
from matplotlib.figure import Figure

import graphkin as gk

np.set_printoptions(precision=4, suppress=True)
TURN = 2 * math.pi
RPM = math.pi / 30  # 1 rpm in rad/s


def rel(a, b):
    """Relative difference |a − b| / |b|."""
    return abs(a - b) / abs(b)


def label(q):
    """A crank angle for a table: '124°', or '124°+ε' for a sample the sweep put 1e-9 rad beside it."""
    b = round(math.degrees(q))
    d = q - math.radians(b)
    return f"{b}°" if abs(d) < 1e-12 else f"{b}°{'+' if d > 0 else '−'}ε"


# %% [markdown]
# ## 1. The idea: energy in and out of the shaft
#
# Let $T(\theta)$ be the driving torque the linkage needs at crank angle $\theta$ (lessons 01–02,
# computed at a constant crank speed) and $T_{avg}$ its average over a turn,
#
# $$T_{avg} = \frac{1}{2\pi}\oint T\,d\theta .$$
#
# A motor that supplies only $T_{avg}$ gives the shaft the energy $T_{avg}\,d\theta$ while the
# linkage takes $T\,d\theta$. The difference comes out of the kinetic energy of everything on the
# shaft, of moment of inertia $I_s$ (the flywheel, the motor's rotor, the crank):
#
# $$d\left(\tfrac12 I_s\,\omega^2\right) = -\,(T - T_{avg})\,d\theta .$$
#
# So where $T > T_{avg}$ (a *positive pulse*) the shaft slows down, where $T < T_{avg}$ it speeds
# up. Between the slowest and the fastest instant the shaft gives up the energy
#
# $$E = \tfrac12 I_s\left(\omega_{max}^2 - \omega_{min}^2\right)
#     = I_s\,\underbrace{\frac{\omega_{max}+\omega_{min}}{2}}_{\omega_{avg}}\,
#       \underbrace{\frac{\omega_{max}-\omega_{min}}{\omega_{avg}}}_{C_s}\,\omega_{avg}
#     = I_s\,C_s\,\omega_{avg}^2 ,$$
#
# where $C_s$ is the **coefficient of speed fluctuation** (Norton suggests 0.01 to 0.05 for most
# machinery). Choose $C_s$, find $E$ from the torque curve, and the system inertia follows:
#
# $$\boxed{I_s = \frac{E}{C_s\,\omega_{avg}^2}}$$
#
# $E$ is the largest swing of the energy $U(\theta) = \int (T - T_{avg})\,d\theta$. Its extremes
# are where $T$ crosses $T_{avg}$, so Norton integrates $T - T_{avg}$ **pulse by pulse, from one
# crossing to the next**, and adds the pulse areas up in a table (his Table 11-1). The largest
# and the smallest running sum — the start, 0, counts too — are the fastest and the slowest
# instants, and $E$ is their difference.
#
# ### Norton's example
#
# Norton's linkage (his Fig. 11-8) runs at 50 rad/s; its torque swings from +341.7 lb·in to
# −166.4 lb·in about an average of 70.2 lb·in. The linkage itself is only in the book's figure,
# so we cannot solve it here. But the text quotes the two extremes of the accumulated column of
# Table 11-1, and we can redo the last step by hand: the largest accumulated energy delivered to
# the linkage is +200.73 in·lb (after it the shaft is slowest), the largest returned is
# −60.32 in·lb (after it the shaft is fastest), and the total variation is their algebraic
# difference, which the book prints as −261.05 in·lb.

# %%
most_delivered, most_returned = 200.73, -60.32  # in·lb, Norton §11.11 (Table 11-1)
E_book = most_delivered - most_returned
print(f"E = {most_delivered} − ({most_returned}) = {E_book:.2f} in·lb   (book: −261.05 in·lb, energy out of the linkage)")

# With the book's speed and the C_s of its Fig. 11-12 (our arithmetic; the text does not print I_s):
omega_book, Cs_book = 50.0, 0.05  # rad/s, Norton §11.11
Is_book = E_book / (Cs_book * omega_book**2)
IN_LB = 4.4482216152605 * 0.0254  # 1 in·lbf in J (and 1 lbf·in·s² in kg·m²)
print(f"I_s = E / (C_s ω²) = {E_book:.2f} / ({Cs_book} × {omega_book:g}²) = {Is_book:.4f} lb·in·s²"
      f" = {Is_book * IN_LB:.4f} kg·m²")

# %% [markdown]
# The book's total is negative because it is *energy coming out of* the linkage into the
# flywheel; the size of the swing, 261.05 in·lb, is what enters $I_s$. The sign of the first
# pulse does not matter either: starting the table at another crossing shifts every running sum
# by the same amount, and the difference between the largest and the smallest stays the same.
#
# ## 2. The energy table on a curve you can integrate by hand
#
# `gk.size_flywheel(theta, T, omega_avg=..., Cs=...)` does Norton's procedure on any sampled torque
# curve: trapezoidal average, crossings by linear interpolation, pulse areas by the trapezoidal
# rule, the table, $E$ and $I_s$. Before we trust it on a linkage, we give it a curve whose answer
# we know exactly (our own numbers, not a book's):
#
# $$T(\theta) = T_0 + a\cos\theta + b\sin 2\theta = T_0 + \cos\theta\,(a + 2b\sin\theta) ,$$
#
# with $T_0 = 10$ N·m, $a = 20$ N·m, $b = 30$ N·m. Its average is $T_0$; it crosses it at
# $\theta = 90°, 270°$ and where $\sin\theta = -a/2b$; and
# $U(\theta) = \int_0^\theta (T - T_0)\,d\theta = a\sin\theta + b\sin^2\theta$, so each pulse area
# is a difference of $U$ between two crossings.

# %%
T0, a, b = 10.0, 20.0, 30.0
n = 720
theta = (np.arange(n) + 0.5) * TURN / n  # no sample falls exactly on a crossing
f_hand = gk.size_flywheel(theta, T0 + a * np.cos(theta) + b * np.sin(2 * theta), omega_avg=100.0, Cs=0.05)

phi = math.asin(-a / (2 * b))  # −19.47°, where sin θ = −a/2b
crossings = np.array([math.pi / 2, math.pi - phi, 3 * math.pi / 2, TURN + phi])  # 90°, 199.47°, 270°, 340.53°
U = lambda x: a * np.sin(x) + b * np.sin(x) ** 2  # noqa: E731
areas = np.diff(U(np.append(crossings, crossings[0] + TURN)))
accumulated = np.cumsum(areas)
E_exact = max(accumulated.max(), 0) - min(accumulated.min(), 0)

print(f"T_avg = {f_hand.T_avg:.10f} N·m (exact {T0})")
print(f"{'from':>8}{'to':>9}{'area by hand':>15}{'graphkin':>12}{'accumulated':>14}")
for row, area, acc in zip(f_hand.table(), areas, accumulated):
    print(f"{math.degrees(row.start):7.2f}°{math.degrees(row.end):8.2f}°{area:13.4f} J{row.area:10.4f} J"
          f"{row.accumulated:12.4f} J")
print(f"E = {f_hand.E:.4f} J (by hand {E_exact:.4f} J = 160/3 J),  I_s = {f_hand.I_s:.6f} kg·m²")

# %% [markdown]
# ## 3. The strip cutter over one turn
#
# The worked machine of this lesson is the four-bar strip cutter of lesson 02 (Söylemez §6.4.1):
# crank $A_0A$ at a constant 900 rpm, and a cutting force of 2000 N on the two blades at $C$ while
# $124° < \theta_{12} < 156°$. The catalog file samples the turn every 2°, as the book's MathCad
# solution does. `gk.sweep(problem)` solves all of them at once — and four more, either side of 124°
# and of 156°, where the cut switches on and off (see below) — and returns a `Cycle`.

# %%
p = gk.load("strip_cutter")
print(p.title)
print(p.notes)
c = gk.sweep(p)
omega = float(c.q_dot[0])
peaks = c.peaks()
print(f"{c.n} positions ({len(p.q)} from the file, 4 at the jumps), closed turn: {c.closed},"
      f"  ω = {omega:.4f} rad/s = {omega / RPM:g} rpm")
print(f"largest torque  {peaks.effort_max.value:8.2f} N·m at θ12 = {math.degrees(peaks.effort_max.at):5.1f}°")
print(f"smallest torque {peaks.effort_min.value:8.2f} N·m at θ12 = {math.degrees(peaks.effort_min.at):5.1f}°")
print(f"average torque  {c.average:8.4f} N·m   (average power {c.average * omega:.1f} W)")

# %% [markdown]
# The motor must push with up to 256 N·m and hold back with up to 325 N·m, although on average it
# supplies only about 8 N·m. Almost all of the swing is the links' inertia: they are accelerated
# and slowed twice a turn at 900 rpm.
#
# ### The average torque from the work of the cut
#
# Here is a route to $T_{avg}$ that uses no torque at all. Over one turn at constant speed the
# links come back to the same kinetic energy, so the inertia loads do no net work; with no
# friction and no gravity the motor's work per turn, $2\pi\,T_{avg}$, must equal the work done
# *against* the cutting forces. Each cutting force is constant while it acts, so its work is the
# force times the displacement of its point:
#
# $$W_{cut} = \vec F_{c3}\cdot\left[\vec r_{C3}(156°) - \vec r_{C3}(124°)\right]
#           + \vec F_{c4}\cdot\left[\vec r_{C4}(156°) - \vec r_{C4}(124°)\right],
# \qquad T_{avg} = -\frac{W_{cut}}{2\pi}.$$
#
# Only two positions of the kinematics are needed.

# %%
cut = list(p.mechanism.loads)  # the two cutting forces
start, stop = cut[0].active.start, cut[0].active.stop
ends = p.kinematics(at=[start, stop])
W_cut = sum(np.array(ld.force) @ (ends.position(ld.link, ld.point)[1] - ends.position(ld.link, ld.point)[0])
            for ld in cut)
T_exact = -W_cut / TURN
print(f"cut from {math.degrees(start):g}° to {math.degrees(stop):g}°: W_cut = {W_cut:.4f} J per turn")
print(f"T_avg = −W_cut/2π = {T_exact:.4f} N·m;   the sweep's trapezoidal average: {c.average:.4f} N·m"
      f"  ({(c.average - T_exact) / T_exact:+.3%})")

# %% [markdown]
# The two agree to about 0.01 % — because `gk.sweep` took care at the jumps. The cutting force
# switches on at 124° and off at 156°, and the torque jumps there (lesson 03); the trapezoidal
# rule assumes the curve is straight between samples. On the **plain** 2° grid of the file, the
# samples at 124° and 156° have no cut (the interval is open), each jump is spread over a 2° step,
# and the rule is only **first order**: half the step, half the error. `gk.sweep` adds a sample
# $\varepsilon = 10^{-9}$ rad either side of each switching angle — 184 positions instead of 180 —
# so each jump falls in a step at most $2\varepsilon$ wide (here $\varepsilon$, beside the file's own
# sample at 124° or 156°), where the rule can miss no more than $\varepsilon$ times the jump. Every
# other step lies on one smooth piece of the curve, and the rule is **second order** again: half
# the step, a quarter of the error. We compare the two on grids of $n$ equally spaced
# angles (`gk.sweep(p, n)` adds its four samples to those), for the average and for the largest
# energy swing $E$ that sizes the flywheel ($C_s = 0.05$; section 4 explains $E$).

# %%
grid2 = np.radians(np.arange(0, 360, 2.0))
plain = p.solve(at=grid2).effort.mean()  # over a turn, the mean of equally spaced samples is the trapezoidal rule
print(f"plain 2° grid, 180 samples: T_avg = {plain:.4f} N·m ({(plain - T_exact) / T_exact:+.2%});"
      f"  sweep, {c.n} samples: {c.average:.4f} N·m ({(c.average - T_exact) / T_exact:+.3%})\n")
print(f"{'':14}{'—— plain grid ——':>26}{'—— sweep ——':>26}")
print(f"{'n':>6}{'step':>8}{'T_avg error':>14}{'E [J]':>12}{'T_avg error':>14}{'E [J]':>12}")
ns = (180, 360, 720, 1440, 2880, 5760)
err_plain, err_sweep, E_plain, E_sweep = [], [], [], []
for m in ns:
    grid = np.linspace(0.0, TURN, m, endpoint=False)
    fp = gk.size_flywheel(grid, p.solve(at=grid).effort, omega_avg=omega, Cs=0.05)  # the plain grid
    fs = gk.sweep(p, m).flywheel(0.05)  # the same grid and the four samples at the jumps
    err_plain.append(fp.T_avg - T_exact)
    err_sweep.append(fs.T_avg - T_exact)
    E_plain.append(fp.E)
    E_sweep.append(fs.E)
    print(f"{m:6}{360 / m:7.4f}°{err_plain[-1]:14.5f}{fp.E:12.3f}{err_sweep[-1]:14.2e}{fs.E:12.3f}")
r_plain, r_sweep = np.divide(err_plain[:-1], err_plain[1:]), np.divide(err_sweep[:-1], err_sweep[1:])
print("T_avg error ratio between successive steps:  plain", r_plain.round(3), "  sweep", r_sweep.round(3))

# %% [markdown]
# $E$ converges the same two ways. On the plain grid it is 0.3 % low at 2°, and almost all of that
# comes through the average line. As the table of section 4 will show, $E$ is the energy between two
# crossings that both come *before* the cut (A and B, near 10° and 76°), so the jumps are not inside
# that pulse. But the pulse from A to B lies below the average line, and the plain average is
# 0.48 N·m too low: the pulse loses a strip 0.48 N·m high and $B - A \approx 1.16$ rad wide.

# %%
f_sweep = c.flywheel(0.05)
A, B = f_sweep.crossings[:2]
shift = -err_plain[0] * (B - A)  # [J]
print(f"−(T_avg error of the plain 2° grid) × (B − A) = {-err_plain[0]:.4f} N·m × {B - A:.4f} rad = {shift:.4f} J")
print(f"E(sweep) − E(plain) at 2° = {E_sweep[0] - E_plain[0]:.4f} J")
print(f"E at 2°, relative to the finest sweep: plain {E_plain[0] / E_sweep[-1] - 1:+.3%},"
      f" sweep {E_sweep[0] / E_sweep[-1] - 1:+.3%}")

# %% [markdown]
# With the samples at the jumps, the 2° sweep's $E$ is within 0.1 % of the finest. We size the
# flywheel from the book's 2° positions (the sweep of the file, `c`) and check $E$ against an exact
# route in section 5.
#
# ## 4. Crossings, pulses and the energy table
#
# `c.flywheel(Cs)` sizes a flywheel for the cycle's torque at its own ω (it calls
# `gk.size_flywheel`). We take $C_s = 0.05$, Norton's upper value. The table has Norton's columns:
# the pulse from one crossing to the next, its area $\Delta E = \int (T - T_{avg})\,d\theta$, and
# the running sum. Positive areas are energy the linkage takes from the shaft (the shaft slows);
# negative areas are energy it gives back.

# %%
Cs = 0.05
f = c.flywheel(Cs)
labels = "ABCDEFGH"
print(f"T_avg = {f.T_avg:.4f} N·m,  {len(f.crossings)} crossings:",
      ", ".join(f"{lab} = {math.degrees(x):.2f}°" for lab, x in zip(labels, f.crossings)))
print()
print(f"{'pulse':>8}{'from':>10}{'to':>10}{'ΔE = area':>13}{'accumulated E':>16}")
for k, row in enumerate(f.table()):
    pulse = f"{labels[k]} to {labels[(k + 1) % len(f.crossings)]}"
    print(f"{pulse:>8}{math.degrees(row.start):9.2f}°{math.degrees(row.end):9.2f}°"
          f"{row.area:11.2f} J{row.accumulated:14.2f} J")
hi, lo = max(f.accumulated.max(), 0.0), min(f.accumulated.min(), 0.0)
print(f"\nlargest running sum {hi:.2f} J, smallest {lo:.2f} J:  E = {hi:.2f} − ({lo:.2f}) = {f.E:.2f} J")

# %% [markdown]
# Read the table as Norton reads his. Starting at crossing A (9.6°), the linkage first *returns*
# 237.2 J to the shaft, which speeds up; the running sum is lowest, −237.2 J, at B (75.8°): the
# shaft is **fastest** there. The running sum is highest, 0, at A itself — after the last pulse
# (D to A) has taken 211.8 J — so the shaft is **slowest** at A. The swing is $E = 237.2$ J.
#
# Checks on the table:
#
# * at every crossing the (linearly interpolated) torque equals $T_{avg}$;
# * the areas add up to zero, because $T_{avg}$ is the same trapezoidal mean (rounding only);
# * $E$ is max − min of the running sum with the start included, and it does not depend on which
#   crossing the table starts from (we restart it at each crossing in turn).

# %%
T_at_crossings = np.interp(f.crossings, f.theta, f.T, period=TURN)
print("T at the crossings − T_avg:", T_at_crossings - f.T_avg)
print(f"sum of the pulse areas: {f.areas.sum():.1e} J")
for first in range(len(f.areas)):
    running = np.cumsum(np.roll(f.areas, -first))
    E_here = max(running.max(), 0) - min(running.min(), 0)
    print(f"table started at {labels[first]}: running sums {running.round(2)} J, E = {E_here:.4f} J")

# %% [markdown]
# The torque curve with its pulses shaded, and the energy $U(\theta)$ with the swing $E$ marked.
# (The green curve on the torque plot is the motor's torque with the flywheel in place: section 7.)

# %%
fig = Figure(figsize=(13, 4.6))
gk.draw.draw_torque_curve(c, flywheel=f, ax=fig.add_subplot(1, 2, 1))
gk.draw.draw_energy(f, ax=fig.add_subplot(1, 2, 2))
fig.subplots_adjust(wspace=0.25)
fig

# %% [markdown]
# ## 5. $E$ from the kinetic energy of the links
#
# An exact route to the energy curve, with no torque and no integration: the work the motor has
# done from $\theta_0$ to $\theta$ equals the gain of kinetic energy of the links minus the work of
# the cutting forces,
#
# $$\int_{\theta_0}^{\theta} T\,d\theta = K(\theta) - K(\theta_0) - W_{cut}(\theta_0\to\theta),
# \qquad K = \sum_j \tfrac12 m_j\,v_{Gj}^2 + \tfrac12 I_{Gj}\,\omega_j^2 ,$$
#
# so $U(\theta) = K(\theta) - K(\theta_0) - W_{cut}(\theta_0\to\theta) - T_{avg}\,(\theta - \theta_0)$
# with the exact $T_{avg}$ of section 3. $K$ needs only velocities, so we can evaluate it on a
# fine grid (0.05°) for almost nothing; the work of the cut up to $\theta$ is the force times the
# displacement of $C$ from 124° to $\theta$ clipped to the cut.

# %%
fine = np.linspace(0.0, TURN, 7200, endpoint=False)
kin = p.kinematics(at=fine)
mech = p.mechanism
K = sum(0.5 * mech.link(j).mass * np.sum(kin.v_G(j) ** 2, axis=1) + 0.5 * mech.link(j).I_G * kin.omega[j] ** 2
        for j in mech.moving)
in_cut = p.kinematics(at=np.clip(fine, start, stop))
W_upto = sum((in_cut.position(ld.link, ld.point) - ends.position(ld.link, ld.point)[0]) @ np.array(ld.force)
             for ld in cut)
U_energy = K - K[0] - W_upto - T_exact * fine
E_energy = U_energy.max() - U_energy.min()
print(f"kinetic energy of the links: {K.min():.2f} J to {K.max():.2f} J")
print(f"E from the kinetic energy:    {E_energy:.3f} J   (fastest at {math.degrees(fine[np.argmin(U_energy)]):.2f}°,"
      f" slowest at {math.degrees(fine[np.argmax(U_energy)]):.2f}°)")
print(f"E from the 2° torque samples: {f.E:.3f} J   ({(f.E - E_energy) / E_energy:+.3%};"
      f" the plain 2° grid: {(E_plain[0] - E_energy) / E_energy:+.3%})")

dense = gk.sweep(p, 11520).flywheel(Cs)  # and graphkin's own procedure on a 1/32° grid
print(f"E from the 1/32° torque samples: {dense.E:.3f} J   ({(dense.E - E_energy) / E_energy:+.3%})")

# %% [markdown]
# Two lessons from this. First, the 2° sizing is less than 0.1 % low (0.3 % on the plain grid),
# far inside the freedom we have in choosing $C_s$. Second, the kinetic energy of the links swings by about 230 J (from 215 to
# 443 J) while the cut takes only 50 J per turn: in this machine the flywheel is there mainly to absorb the links'
# own energy, not the cut.
#
# ## 6. The system inertia, and what it scales with
#
# $I_s = E/(C_s\,\omega_{avg}^2)$ is required of *everything* on the crank shaft. If the motor's
# rotor and the gears already provide some of it, the flywheel itself ($I_f$) can be that much
# smaller (Norton §11.11); here we make the flywheel provide all of it.

# %%
print(f"E = {f.E:.3f} J,  C_s = {f.Cs},  ω_avg = {f.omega_avg:.4f} rad/s")
print(f"I_s = E / (C_s ω_avg²) = {f.I_s:.4f} kg·m²")

# %% [markdown]
# For the **same torque curve**, halving $C_s$ doubles $I_s$, and running the shaft at half the
# speed needs four times the inertia (the flywheel stores $\tfrac12 I\omega^2$). We check this with
# `gk.size_flywheel` on the same samples:

# %%
f_half_Cs = gk.size_flywheel(f.theta, f.T, omega_avg=f.omega_avg, Cs=Cs / 2)
f_half_w = gk.size_flywheel(f.theta, f.T, Cs=Cs, omega_avg=f.omega_avg / 2)
print(f"C_s = {Cs / 2}: I_s = {f_half_Cs.I_s:.4f} kg·m²  (× {f_half_Cs.I_s / f.I_s:.4f})")
print(f"ω/2:         I_s = {f_half_w.I_s:.4f} kg·m²  (× {f_half_w.I_s / f.I_s:.4f})")

# %% [markdown]
# (A real machine slowed to half speed also has a different torque curve: its inertia torques
# fall with $\omega^2$. Section 9 looks at that with the explorer.)
#
# ### A solid disk or a rim
#
# Now the flywheel itself. A **solid disk** of radius $r$, thickness $t$ and density $\rho$ has
# $m = \rho\pi r^2 t$ and $I = \tfrac12 m r^2 = \tfrac12\rho\pi t\,r^4$, so
# $r = \left(2 I_s/(\pi\rho t)\right)^{1/4}$. A **rim** (an annulus of mean radius $R$ and radial
# width $w$, the hub and spokes left out) puts the mass far out, where it counts most. We take
# typical densities (our values): steel 7850 kg/m³, cast iron 7200 kg/m³.

# %%
STEEL, CAST_IRON = 7850.0, 7200.0  # kg/m³
disk = f.disk(density=STEEL, thickness=0.050)
rim = f.rim(density=CAST_IRON, mean_radius=0.250, thickness=0.050)
print(f"steel disk, t = {disk.thickness * 1e3:.0f} mm:  r = {disk.radius * 1e3:.1f} mm"
      f" (Ø {2 * disk.radius * 1e3:.0f} mm),  m = {disk.mass:.2f} kg,  I = {disk.I:.4f} kg·m²")
print(f"cast-iron rim, R = {rim.mean_radius * 1e3:.0f} mm, t = {rim.thickness * 1e3:.0f} mm:  w = {rim.width * 1e3:.2f} mm"
      f" (r_i = {rim.inner_radius * 1e3:.1f}, r_o = {rim.outer_radius * 1e3:.1f} mm),  m = {rim.mass:.2f} kg,"
      f"  I = {rim.I:.4f} kg·m²")

# %% [markdown]
# Check both with the hand formulas and with `graphkin.model.mass`, the module that builds link
# mass properties from shapes (lesson 01): a `disk` and a `hollow_cylinder` of those dimensions
# must have $I = I_s$.

# %%
m_hand = STEEL * math.pi * disk.radius**2 * disk.thickness
ring = gk.mass.hollow_cylinder(rim.inner_radius, rim.outer_radius, rim.thickness, CAST_IRON)
print(f"m r²/2 = {0.5 * m_hand * disk.radius**2:.6f},  mass.disk: {gk.mass.disk(disk.radius, disk.thickness, STEEL).I_G:.6f},"
      f"  mass.hollow_cylinder: {ring.I_G:.6f},  I_s = {f.I_s:.6f} kg·m²")

# %% [markdown]
# Norton's advice, in numbers: since $I \propto m r^2$, a thin disk of large diameter needs less
# material than a thick one of small diameter — for a disk $m \propto \sqrt t$ at a given $I$ — and
# a rim less still.

# %%
print(f"{'flywheel':>32}{'radius [mm]':>13}{'mass [kg]':>11}")
disks = {t: f.disk(STEEL, t) for t in (0.0125, 0.025, 0.05, 0.1)}
for t, d in disks.items():
    print(f"{f'steel disk, t = {t * 1e3:g} mm':>32}{d.radius * 1e3:13.1f}{d.mass:11.2f}")
for R in (0.2, 0.25, 0.3):
    r_ = f.rim(CAST_IRON, R, 0.05)
    print(f"{f'cast-iron rim, R = {R * 1e3:g} mm, t = 50':>32}{r_.outer_radius * 1e3:13.1f}{r_.mass:11.2f}")

# %% [markdown]
# ## 7. Before and after
#
# ### The speed
#
# With the flywheel on the shaft and a motor delivering $T_{avg}$, the energy balance of
# section 1 gives the speed at every angle: $\tfrac12 I_s\omega^2 = \tfrac12 I_s\omega_{max}^2 -
# (U - U_{min})$. `f.speed()` evaluates it. The fluctuation it shows should be $C_s$, the value
# we designed for (the samples miss the exact extremes by a little).

# %%
w = f.speed()
print(f"ω from {w.min():.3f} to {w.max():.3f} rad/s ({w.min() / RPM:.1f} to {w.max() / RPM:.1f} rpm)")
print(f"(ω_max − ω_min)/ω_avg = {np.ptp(w) / f.omega_avg:.5f}   (C_s = {Cs})")

# %% [markdown]
# ### The torque the motor sees
#
# A flywheel can only help if the motor lets its speed droop a little under load. `graphkin`
# models the motor by a straight speed–torque line through its operating point,
# $T_m = T_{avg} - k_m(\omega - \omega_{avg})$, as for an induction motor running with slip $s$
# ($k_m = T_{avg}(1-s)/(s\,\omega_{avg})$, $s = 0.05$ by default). The shaft obeys
#
# $$I_s\,\omega\,\frac{d\omega}{d\theta} = T_m(\omega) - T(\theta),$$
#
# and `f.smoothed_torque()` gives its periodic solution, linearised about $\omega_{avg}$.
# For an independent check we **simulate the shaft**: start at $\omega_{avg}$, integrate the
# nonlinear equation turn after turn with a Runge–Kutta step from each sample to the next (2°,
# and the tiny steps across the jumps), until the start-up transient has died out and every turn
# is the same.

# %%
slip = 0.05
k_m = f.T_avg * (1 - slip) / (slip * f.omega_avg)
steps = np.diff(np.append(f.theta, f.theta[0] + TURN))  # to the next sample, the last one closing the turn
print(f"{len(steps)} steps: {np.degrees(steps.max()):g}° and {np.count_nonzero(steps < 1e-6)} of {steps.min():.0e} rad")


def shaft(x, w):
    """dω/dθ of the shaft with the flywheel and the motor line."""
    T = np.interp(x, f.theta, f.T, period=TURN)
    return (f.T_avg - k_m * (w - f.omega_avg) - T) / (f.I_s * w)


w_sim = f.omega_avg
for turn in range(60):
    one_turn = np.empty(len(f.theta))
    for i, (x, h) in enumerate(zip(f.theta, steps)):
        one_turn[i] = w_sim
        k1 = shaft(x, w_sim)
        k2 = shaft(x + h / 2, w_sim + h / 2 * k1)
        k3 = shaft(x + h / 2, w_sim + h / 2 * k2)
        k4 = shaft(x + h, w_sim + h * k3)
        w_sim = w_sim + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
print(f"after 60 turns the speed changes by {abs(w_sim - one_turn[0]):.1e} rad/s per turn")

Tm_sim = f.T_avg - k_m * (one_turn - f.omega_avg)
w_mean = np.sum(0.5 * (one_turn + np.roll(one_turn, -1)) * steps) / TURN  # (1/2π)∮ω dθ, trapezoidal
Tm = f.smoothed_torque(slip)
print(f"motor torque, graphkin:   {Tm.min():.3f} to {Tm.max():.3f} N·m")
print(f"motor torque, simulation: {Tm_sim.min():.3f} to {Tm_sim.max():.3f} N·m"
      f"   (largest difference {np.abs(Tm - Tm_sim).max():.3f} N·m)")
print(f"speed fluctuation in the simulation: {np.ptp(one_turn) / f.omega_avg:.4f},"
      f" mean speed over the turn {w_mean / RPM:.3f} rpm")
print(f"without the flywheel the motor would see {f.T.min():.1f} to {f.T.max():.1f} N·m")

# %% [markdown]
# In the speed plot the two curves have the same shape but not the same level: `f.speed()` puts
# $\omega_{avg}$ midway between the extremes (Norton's definition), while the simulated motor line
# makes the *mean* speed over the turn 900 rpm (the mean motor torque must equal $T_{avg}$). Either way the
# fluctuation is about $C_s$.
#
# The motor's torque now stays between about 5 and 12.7 N·m instead of −325 and +256 N·m. Its
# swing is about $k_m(\omega_{max}-\omega_{min}) = T_{avg}\,C_s\,(1-s)/s$: with a 5 % slip motor
# that is about $T_{avg}$ itself for $C_s = 0.05$. A smaller $C_s$ (a bigger flywheel) smooths the
# motor's torque in proportion — five times more for $C_s = 0.01$.
# (Norton's Fig. 11-12 shows the smoothed torque of his linkage; how much smoothing one gets
# depends on the motor's speed–torque line, so we do not compare with its numbers.)

# %%
swing = f.T_avg * Cs * (1 - slip) / slip
f_01 = c.flywheel(0.01)
print(f"motor swing: C_s = 0.05: {np.ptp(Tm):.3f} N·m (estimate {swing:.3f});"
      f"  C_s = 0.01: {np.ptp(f_01.smoothed_torque(slip)):.3f} N·m")

fig = Figure(figsize=(13, 4.3))
ax1, ax2 = fig.subplots(1, 2)
deg = np.degrees(f.theta)
ax1.plot(deg, f.T, color="tab:blue", label="without flywheel (constant speed)")
ax1.plot(deg, Tm, color="tab:green", lw=2, label=f"motor with flywheel, C_s = {Cs}")
ax1.plot(deg, f_01.smoothed_torque(slip), color="tab:olive", lw=1.5, ls="--", label="motor with flywheel, C_s = 0.01")
ax1.axhline(f.T_avg, color="k", lw=0.8, ls=":", label=f"average {f.T_avg:.2f} N·m")
ax1.set(xlabel="crank angle θ₁₂ [°]", ylabel="torque [N·m]", title="Torque before and after", xlim=(0, 360))
ax1.legend(fontsize=8)
ax2.plot(deg, w / RPM, color="tab:purple", label="constant motor torque (f.speed())")
ax2.plot(deg, one_turn / RPM, color="tab:green", ls="--", label="motor line, simulated")
ax2.axhline(f.omega_avg / RPM, color="k", lw=0.8, ls=":")
ax2.set(xlabel="crank angle θ₁₂ [°]", ylabel="crank speed [rpm]", title=f"Crank speed with the flywheel (C_s = {Cs})",
        xlim=(0, 360))
ax2.legend(fontsize=8)
fig

# %% [markdown]
# One assumption runs through all of this, in Norton as here: $T(\theta)$ was computed at a
# *constant* 900 rpm. With the flywheel the speed varies by ±2.5 %, the inertia torques by about
# ±5 %; for $C_s$ of a few percent that is a small correction.
#
# ## 8. The joint-force index (Norton §11.12)
#
# The transmission angle judges a four-bar only when the load is on the rocker. Holte and Chase's
# **joint-force index** works for any linkage and any load: at each position, the largest joint
# force divided by the external load,
#
# $$\text{JFI} = \frac{\max_{ij}|\vec F_{ij}|}{|\vec F_{ext}|},$$
#
# from a **static** force analysis (no inertia: if a linkage is bad without the dynamic forces, it
# will be worse at speed). They suggest keeping it below about 2. Where the input can no longer
# move the linkage (an *immovable* position) the index grows without bound.
#
# `gk.joint_force_index(problem)` sets every mass and moment of inertia to zero (`gk.static_problem`),
# keeps the cutting forces, and divides the largest joint force by the largest external force
# acting there (2000 N during the cut). Outside the cut there is no load and the index is undefined.

# %%
jfi = gk.joint_force_index(p)
defined = np.isfinite(jfi.index)
print(f"index defined at {defined.sum()} positions (the cut), undefined at {len(jfi.unloaded)} (no load)")
print(f"{'θ12':>7}{'JFI':>8}{'largest':>9}")
for q, value, name in zip(jfi.q[defined], jfi.index[defined], jfi.joint[defined]):
    print(f"{label(q):>7}{value:8.3f}{name:>9}")
print(f"\npeak {jfi.peak.value:.4f} at θ12 = {label(jfi.peak.at)} (in {jfi.joint[jfi.peak.index]})")
print(f"positions above {jfi.limit:g}: {np.degrees(jfi.over_limit).tolist() or 'none'}")
print(f"immovable positions: {list(jfi.immovable) or 'none'}")

# %% [markdown]
# ### Check at the peak, with the matrix of lesson 01
#
# Solve the static problem at the peak position as Norton's $[A]\{x\} = \{b\}$ with plain numpy,
# and divide the largest pin force by 2000 N. Statics also says what to expect: the crank and
# coupler carry no load of their own at $A$, so $\vec F_{12} = \vec F_{23}$ and the coupler takes the
# cut upwards, $\vec F_{34} = \vec F_{23} + \vec F_{c3}$.

# %%
static = gk.static_problem(p)
system = gk.assemble(static.solve(at=[jfi.peak.at]))
x = dict(zip(system.unknowns, np.linalg.solve(system.A[0], system.b[0])))
pins = {name: math.hypot(x[name + "x"], x[name + "y"]) for name in ("F12", "F23", "F34", "F14")}
print({name: round(v, 2) for name, v in pins.items()}, "N")
by_hand = max(pins.values()) / 2000.0
print(f"max |F| / 2000 N = {by_hand:.4f}   (graphkin: {jfi.peak.value:.4f})")

# %% [markdown]
# The static index stays near 1.4 over the whole cut: the strip cutter transmits its cutting force
# well. At 900 rpm, though, the *dynamic* joint forces are much larger than the cut — just as
# Norton warns, the index says nothing about speed:

# %%
for name, pk in peaks.forces.items():
    print(f"{name}: peak {pk.value:7.1f} N = {pk.value / 2000:.2f} × the cutting force, at θ12 = {math.degrees(pk.at):.0f}°")

fig = Figure(figsize=(6.4, 4.2))
gk.draw.draw_joint_force_index(jfi, ax=fig.add_subplot())
fig

# %% [markdown]
# ### What a bad linkage looks like
#
# Lengthen the crank from 85 mm to 245 mm (we keep everything else). The crank can then no
# longer turn all the way round: the coupler $AB$ and the rocker $BB_0$ line up — a toggle — when
# $|AB_0| = a_3 + a_4$, that is (law of cosines in the triangle $A_0AB_0$) at
#
# $$\cos\theta_t = \frac{a_2^2 + a_1^2 - (a_3 + a_4)^2}{2\,a_2 a_1},$$
#
# and between $\theta_t$ and $360° - \theta_t$ the linkage cannot be assembled. Watch the index climb
# through 2 and blow up as the transmission angle goes to zero, and see the positions reported as
# immovable.

# %%
text = gk.catalog.path("strip_cutter").read_text()
crank = 'A = ["85 mm", "0 mm"]'
long_crank = gk.parse_problem(text.replace(crank, 'A = ["245 mm", "0 mm"]'), file="strip cutter, 245 mm crank")
jfi_long = gk.joint_force_index(long_crank)
long_cycle = gk.sweep(long_crank)
mu = np.degrees(long_cycle.transmission_angle())
ok = np.isfinite(jfi_long.index)
print(f"{'θ12':>7}{'JFI':>8}{'transmission angle':>20}")
for i in np.flatnonzero(ok):
    print(f"{label(jfi_long.q[i]):>7}{jfi_long.index[i]:8.2f}{mu[i]:19.2f}°")
print(f"\nabove 2 at: {', '.join(label(q) for q in jfi_long.over_limit)}")
stuck = np.array([q for q, _ in jfi_long.immovable])
print(f"{len(stuck)} immovable positions, {label(stuck[0])} to {label(stuck[-1])};"
      f" the reason at {label(stuck[0])}: {jfi_long.immovable[0][1]}")

def length(j, P, Q):
    """Distance between two points of link j of the long-crank linkage [m]."""
    points = long_crank.mechanism.link(j).points
    return math.dist(points[P], points[Q])


a1, a2, a3, a4 = length(1, "A0", "B0"), length(2, "A0", "A"), length(3, "A", "B"), length(4, "B0", "B")
print(f"a1 = {a1 * 1e3:g} mm, a2 = {a2 * 1e3:g} mm, a3 = {a3 * 1e3:g} mm, a4 = {a4 * 1e3:g} mm")
theta_t = math.acos((a2**2 + a1**2 - (a3 + a4) ** 2) / (2 * a2 * a1))
print(f"toggle by hand: θ_t = {math.degrees(theta_t):.2f}° and {360 - math.degrees(theta_t):.2f}°")
q_long = jfi_long.q

# %% [markdown]
# ## 9. The interactive explorer
#
# `gk.explore(problem)` puts the whole analysis behind two controls: a **slider** for the crank angle
# and a **speed** box. It draws the mechanism, each link's free body, the force polygons of the
# graphical construction (lesson 02) and the driving torque over the cycle with a marker at the
# current angle. Move the slider, or type another speed (the torque curve is re-swept).
# (On a page that does not run Python, the widget shows nothing; the picture at the end of this
# section is what it showed when the notebook ran.)

# %%

ex = gk.explore(p)
ex

# %% [markdown]
# A widget is code like any other, so we can drive it from a cell and check what it shows. First
# the speed: 600 rpm. The explorer takes the problem at the new speed (`p.at_speed(ω)`, the same
# problem at another constant crank speed) and re-sweeps the torque curve: `ex.cycle` is
# `gk.sweep(problem, ex.n)`, 360 angles and the four samples at the jumps. We build the same problem at
# 600 rpm independently — by editing the speed line of the problem file — and sweep it.

# %%
ex.speed.value = 600
speed_line = 'omega = "900 rpm"'
p600 = gk.parse_problem(text.replace(speed_line, 'omega = "600 rpm"'), file="strip cutter at 600 rpm")
c600 = gk.sweep(p600, ex.n)
print(f"explorer: {ex.cycle.n} positions at {ex.cycle.q_dot[0] / RPM:.1f} rpm;"
      f" largest difference from the independent sweep {np.abs(ex.cycle.torque - c600.torque).max():.1e} N·m")

# %% [markdown]
# A second, physical check of the new curve. The crank turns at a constant speed, so every
# velocity is proportional to $\omega$ and every acceleration to $\omega^2$; the inertia part of
# the torque scales with $\omega^2$ and the cutting part not at all:
#
# $$T(\theta;\,600) = T_{static}(\theta) + \left(\tfrac{600}{900}\right)^2\left[T(\theta;\,900) - T_{static}(\theta)\right].$$
#
# The average does not change with speed (the inertia loads do no work over a turn), but $E$ and
# $I_s$ do.

# %%
c900 = gk.sweep(p, ex.n)
T_static = static.solve(at=c900.q).effort
predicted = T_static + (600 / 900) ** 2 * (c900.torque - T_static)

f600, f900 = c600.flywheel(Cs), c900.flywheel(Cs)  # c600: the same curve as the explorer's, shown above
print(f"{f'n = {ex.n}':>8}{'T_avg [N·m]':>13}{'peak T [N·m]':>14}{'E [J]':>9}{'I_s [kg·m²]':>13}")
for speed_name, cy, fl in (("900 rpm", c900, f900), ("600 rpm", c600, f600)):
    print(f"{speed_name:>8}{cy.average:13.4f}{np.abs(cy.torque).max():14.2f}{fl.E:9.2f}{fl.I_s:13.4f}")

# %% [markdown]
# At 600 rpm the swing $E$ is less than half, but the flywheel must store it at a lower speed, so
# the required inertia is a little *larger*.
#
# Now the slider, which moves in whole degrees. At 600 rpm the torque is largest at the first
# sample of the cut, 124° + ε: the jump now reaches higher than the inertia peaks. The slider's first
# whole degree after it, 125°, is inside the cut: send the slider there and compare the one position
# the explorer solved, analytically (`ex.analytical`) and graphically (`ex.construction`), and the
# marker it drew, with the independent sweep. (The cell sets the speed too: what it shows depends on
# nothing done with the explorer before it.)

# %%
i_max = int(np.argmax(c600.torque))
print(f"largest torque at 600 rpm: {c600.torque[i_max]:.4f} N·m at {label(c600.q[i_max])}")
theta = math.ceil(math.degrees(c600.q[i_max]))  # the slider's first whole degree after it
i_at = int(np.argmin(abs(np.degrees(c600.q) - theta)))
ex.speed.value = 600
ex.slider.value = theta
print(ex.status.value)
marker_x, marker_y = (float(v[0]) for v in ex.marker.get_data())
print(f"independent sweep: T12 = {c600.torque[i_at]:.4f} N·m at {label(c600.q[i_at])};"
      f" marker at ({marker_x:g}°, {marker_y:.4f} N·m)")
worst = max(float(np.abs(np.subtract(route, c600.analysis[name][i_at])).max())
            for name in ex.analytical.names() for route in (ex.analytical[name][0], ex.construction[name]))
print(f"the forces and T12, analytical and graphical, against the sweep: largest difference {worst:.1e} (N, N·m)")

# %% [markdown]
# And in the middle of the cut, where the polygons carry the 2000 N cutting forces:

# %%
ex.speed.value = 600
ex.slider.value = 140
i140 = int(np.argmin(abs(np.degrees(c600.q) - 140)))
print(ex.status.value)
Image(data=ex.image.value)  # exactly what the widget shows now

# %% [markdown]
# ### The worked solution, to keep
#
# The last pages of the handout [`strip_cutter.pdf`](../figures/handouts/strip_cutter.pdf) are this
# lesson on paper: the torque curve with the pulses of T − T_avg, the energy table after Norton's
# Table 11-1, E and I_s with the disk that gives it, and the joint-force index. `--cs` sets the
# coefficient of speed fluctuation:
#
# ```sh
# graphkin handout strip_cutter --cs 0.02 -o strip_cutter.pdf
# ```

# %% [markdown]
# ## 10. Your turn
#
# Two exercises on the strip cutter, with **your own numbers**: every student id gets its own
# speed, coefficient of speed fluctuation and crank length, the same each time you run the notebook.
# Type the id your teacher gave you between the quotes below, in place of `"your-id"`, and run the
# cells from here. Answer in the boxes and press **Check**, or in code with `gk.exercises.check`: the
# grader reads numbers with their units as you would write them (`"250 J"`, `"0.75 kg*m^2"`,
# `"150 deg"`) and, when an answer is off, tells you what kind of slip it looks like.

# %%

student = "your-id"  # ← type your own id here

# %% [markdown]
# ### Exercise 1: size the flywheel of your cutter
#
# Your cutter turns at its own average speed, and must keep its own $C_s$:

# %%
gk.exercise("flywheel", student)

# %% [markdown]
# `gk.exercises.variant(name, student).problem` is your machine as a `Problem`, just like `p`. Sweep it
# at 1° steps, `gk.sweep(my_cutter, 360)`, and size the flywheel as in sections 4–6 with **your** $C_s$
# (it is in your data, not in the problem). Then type your answers in the boxes above, or fill them
# in here and run the cell:

# %%
my_cutter = gk.exercises.variant("flywheel", student).problem
# your work here: sweep my_cutter at 1° steps, then .flywheel(your C_s)
answers = {"E": "", "I_s": ""}  # e.g. "123.4 J", "0.123 kg*m^2"
print(gk.exercises.check("flywheel", student, answers))

# %% [markdown]
# ### What the feedback looks like
#
# A made-up student, `"example"`, worked out $E$ in kJ but wrote J after it (a factor of 1000), and
# got $I_s$ right. Their correct answers come from `gk.exercises.key`, the teacher's answer sheet
# (values in SI) — for another id than yours, so that nothing is given away:

# %%
demo = "example"
key = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("flywheel", demo)["questions"]}
slipped = {"E": f"{key['E'] / 1000:.4g} J", "I_s": f"{key['I_s']:.4g} kg*m^2"}  # E: kJ written as J
print(gk.exercises.check("flywheel", demo, slipped))

# %% [markdown]
# A slip earns part of the points (a power of ten, half) and says what to look at; a wrong answer
# earns nothing. `gk.exercises.grade(...)` gives the same report as plain data (score, and per question
# the verdict, the slip and the feedback), for your own records.
#
# ### Exercise 2: the joint-force index of your cutter
#
# Your cutter has a crank of its own length. Find its joint-force index over the cut as in
# section 8, at 1° steps: `gk.joint_force_index(my_crank, 360)`.

# %%
gk.exercise("joint_force_index", student)

# %%
my_crank = gk.exercises.variant("joint_force_index", student).problem
# your work here: the joint-force index of my_crank at 1° steps, its peak and where it is
answers = {"JFI": "", "JFI_at": ""}  # e.g. "1.234", "145 deg"
print(gk.exercises.check("joint_force_index", student, answers))

# %% [markdown]
# ### More to try
#
# * The cell below sizes the flywheel for $C_s = 0.01$ instead of 0.05: predict $I_s$, the disk's
#   radius and its mass before you run it (hint: $r \propto I_s^{1/4}$ at a given thickness).
# * Which costs less material for the same $I_s$: a steel disk 25 mm thick or a cast-iron rim of
#   mean radius 300 mm? What limits how large you can make a rim? (Think of the stress in a
#   spinning ring, $\sigma = \rho v^2$ — and see what `f.rim` says if you ask for a small mean radius.)
# * In the explorer, type speeds of 300, 600, 1200 rpm. Where is the largest torque each time, and
#   why does the average not move?
# * Copy the cell of section 8 that lengthens the crank, and try crank lengths between 85 and
#   245 mm. For which does the index first pass 2? Compare with where the transmission angle drops
#   below about 40°.

# %%
Cs_try = 0.01  # edit here
f_try = c.flywheel(Cs_try)
d_try = f_try.disk(STEEL, 0.050)
print(f"C_s = {Cs_try}: I_s = {f_try.I_s:.4f} kg·m², steel disk 50 mm thick: r = {d_try.radius * 1e3:.1f} mm,"
      f" m = {d_try.mass:.2f} kg")

# %% [markdown]
# ## Checks (for the course maintainers; students may skip)
#
# Every claim of the lesson, checked against a route that does not use it, and every number quoted
# in the text checked at the precision it is quoted. Grouped by section; they read the variables the
# sections above computed. The explorer is driven here from a known state, whatever was done with it
# above.

# %% [markdown]
# ### 1–2. Norton's table, and a curve integrated by hand

# %%
assert math.isclose(E_book, 261.05, abs_tol=0.005)  # the book's own total, to its 2 decimals
assert math.isclose(f_hand.T_avg, T0, rel_tol=1e-12)
assert np.allclose(f_hand.crossings, crossings, atol=1e-4)  # rad: linear interpolation near a crossing
assert np.allclose(np.degrees(crossings), [90, 199.47, 270, 340.53], atol=0.005)  # as in the comment
assert np.allclose(f_hand.areas, areas, atol=2e-3)  # J: trapezoidal rule with 0.5° steps
assert math.isclose(E_exact, 160 / 3) and math.isclose(f_hand.E, E_exact, rel_tol=1e-4)
assert math.isclose(f_hand.I_s, f_hand.E / (0.05 * 100.0**2))

# %% [markdown]
# ### 3. The strip cutter over one turn

# %%
assert c.closed and c.valid.all() and c.n == len(p.q) + 4
assert len(p.q) == 180 and c.n == 184  # "184 positions instead of 180"
assert math.isclose(omega / RPM, 900)
assert math.isclose(peaks.effort_max.value, c.torque.max()) and math.isclose(peaks.effort_min.value, c.torque.min())
assert round(peaks.effort_max.value) == 256 and round(-peaks.effort_min.value) == 325  # "up to 256 ... up to 325 N·m"
assert round(c.average) == 8  # "on average it supplies only about 8 N·m"
assert round(abs(c.average / T_exact - 1), 4) == 0.0001  # "the two agree to about 0.01 %"
assert math.isclose(err_plain[0], plain - T_exact) and math.isclose(err_sweep[0], c.average - T_exact)
# First order: the ratio is 2 up to the next (h²) term. Second order: 4 up to the h⁴ term and the
# steps ε wide between the file's samples at 124° and 156° (force off) and their neighbours at ±ε
# (force on): together a constant ε·(116 + 58 N·m)/4π ≈ 1.4e-8 N·m, 1.3 % of the smallest error in
# the table — hence its last ratio, 3.96.
assert np.all(abs(r_plain - 2) < 0.05) and np.all(abs(r_sweep - 4) < 0.05)
assert round(r_sweep[-1], 2) == 3.96
assert round(E_plain[0] / E_sweep[-1] - 1, 3) == -0.003  # "on the plain grid it is 0.3 % low at 2°"
assert np.allclose(np.degrees([A, B]), [10, 76], atol=0.5)  # "A and B, near 10° and 76°"
assert round(-err_plain[0], 2) == 0.48 and round(B - A, 2) == 1.16  # "0.48 N·m too low", "B − A ≈ 1.16 rad"
assert math.isclose(shift, E_sweep[0] - E_plain[0], rel_tol=0.01)  # the rest: the crossings move a little
assert abs(E_sweep[0] / E_sweep[-1] - 1) < 0.001  # "within 0.1 % of the finest"

# %% [markdown]
# ### 4. Crossings, pulses and the energy table

# %%
assert np.allclose(T_at_crossings, f.T_avg, atol=1e-9 * np.abs(f.T).max())
assert abs(f.areas.sum()) < 1e-12 * f.E
assert math.isclose(f.E, hi - lo)
for first in range(len(f.areas)):
    running = np.cumsum(np.roll(f.areas, -first))
    E_here = max(running.max(), 0) - min(running.min(), 0)
    assert math.isclose(E_here, f.E, rel_tol=1e-12)
# The reading of the table: A (9.6°) and B (75.8°); 237.2 J returned from A to B, the running sum
# lowest there; 211.8 J taken by the last pulse, D to A, and the running sum highest, 0, at A; E = 237.2 J.
assert len(f.crossings) == 4 and np.allclose(np.degrees(f.crossings[:2]), [9.6, 75.8], atol=0.05)
assert round(f.areas[0], 1) == -237.2 and round(f.areas[-1], 1) == 211.8
assert np.argmin(f.accumulated) == 0 and round(lo, 1) == -237.2 and abs(hi) < 1e-12 * f.E and abs(f.accumulated[-1]) < 1e-9
assert round(f.E, 1) == 237.2

# %% [markdown]
# ### 5. $E$ from the kinetic energy of the links

# %%
# Second order in the step (section 3): 0.07 % at 2°, a quarter of that at each halving.
assert abs(f.E - E_energy) < 0.001 * E_energy
assert abs(dense.E - E_energy) < 0.0002 * E_energy
assert np.allclose(np.degrees(f.crossings[:2]), np.degrees([fine[np.argmax(U_energy)], fine[np.argmin(U_energy)]]),
                   atol=0.1)
assert f.E < E_energy and round((E_plain[0] - E_energy) / E_energy, 3) == -0.003  # "less than 0.1 % low (0.3 %...)"
assert round(np.ptp(K), -1) == 230 and round(K.min()) == 215 and round(K.max()) == 443  # "about 230 J (215 to 443)"
assert round(-W_cut) == 50  # "the cut takes only 50 J per turn"

# %% [markdown]
# ### 6. The system inertia, a disk or a rim

# %%
assert math.isclose(f.I_s, f.E / (Cs * omega**2), rel_tol=1e-12)
assert math.isclose(f_half_Cs.I_s, 2 * f.I_s, rel_tol=1e-12) and math.isclose(f_half_Cs.E, f.E, rel_tol=1e-12)
assert math.isclose(f_half_w.I_s, 4 * f.I_s, rel_tol=1e-12)
assert math.isclose(disk.mass, m_hand, rel_tol=1e-12)
assert math.isclose(0.5 * m_hand * disk.radius**2, f.I_s, rel_tol=1e-12)  # I = m r²/2
assert math.isclose(gk.mass.disk(disk.radius, disk.thickness, STEEL).I_G, f.I_s, rel_tol=1e-12)
assert math.isclose(ring.I_G, f.I_s, rel_tol=1e-12) and math.isclose(ring.m, rim.mass, rel_tol=1e-12)
assert math.isclose(rim.outer_radius - rim.inner_radius, rim.width)
assert math.isclose(disks[0.1].mass / disks[0.025].mass, 2.0, rel_tol=1e-12)  # 4 × t  →  2 × m

# %% [markdown]
# ### 7. Before and after

# %%
assert abs(np.ptp(w) / f.omega_avg - Cs) < 0.01 * Cs
# The energy balance between the two extremes, on the samples: ½ I_s (ω_max² − ω_min²) ≈ E.
assert rel(0.5 * f.I_s * (w.max() ** 2 - w.min() ** 2), f.E) < 0.01
assert abs(w_sim - one_turn[0]) < 1e-4  # the simulation has settled on a periodic turn
assert np.abs(Tm - Tm_sim).max() < 0.02 * np.ptp(Tm)
assert abs(np.ptp(one_turn) / f.omega_avg - Cs) < 0.05 * Cs
assert abs(w_mean - f.omega_avg) < 1e-3 * Cs * f.omega_avg
assert round(Tm.min()) == 5 and round(Tm.max(), 1) == 12.7  # "between about 5 and 12.7 N·m"
assert round(f.T.min()) == -325 and round(f.T.max()) == 256  # "instead of −325 and +256 N·m"
assert rel(np.ptp(Tm), swing) < 0.02
assert math.isclose(swing / f.T_avg, 1 - slip) and slip == Cs == 0.05  # "about T_avg itself" (0.95 T_avg)
assert rel(np.ptp(Tm) / np.ptp(f_01.smoothed_torque(slip)), 5.0) < 0.02

# %% [markdown]
# ### 8. The joint-force index

# %%
assert np.array_equal(jfi.q, c.q)  # the positions of the sweep, the samples at ±ε included
assert defined.sum() + len(jfi.unloaded) == c.n and not jfi.immovable and len(jfi.over_limit) == 0
assert np.array_equal(defined, cut[0].active.mask(jfi.q))
assert np.all(abs(jfi.index[defined] - 1.4) < 0.05)  # "the static index stays near 1.4 over the whole cut"
assert all(link.mass == 0 and link.I_G == 0 for link in static.mechanism.links)
assert math.isclose(by_hand, jfi.peak.value, rel_tol=1e-9)
assert np.allclose([x["F34x"], x["F34y"]], np.array([x["F23x"], x["F23y"]]) + cut[0].force)
assert text.count(crank) == 1
assert np.array_equal(long_cycle.q, jfi_long.q)  # the file's 180 angles and the 4 at ±ε, as before
assert np.array_equal(stuck, q_long[(q_long > theta_t) & (q_long < TURN - theta_t)])
assert np.array_equal(np.isin(q_long, stuck), ~long_crank.kinematics(at=q_long).valid)
assert np.all(np.diff(jfi_long.index[ok]) > 0) and np.all(np.diff(mu[ok]) < 0)  # index up, transmission angle down
assert jfi_long.peak.index == np.flatnonzero(ok)[-1] and jfi_long.peak.value > 5
assert np.array_equal(jfi_long.over_limit, jfi_long.q[ok])  # all of the cut is above 2

# %% [markdown]
# ### 9. The interactive explorer

# %%
ex.speed.value = 600  # the state the section's text describes, whatever was typed above
assert text.count(speed_line) == 1
assert ex.n == 360 and ex.cycle.n == 364
assert math.isclose(ex.cycle.q_dot[0], 600 * RPM) and np.allclose(ex.cycle.q, c600.q)
assert np.allclose(ex.cycle.torque, c600.torque, rtol=1e-12, atol=1e-9)
assert np.allclose(ex.cycle.torque, predicted, rtol=1e-9, atol=1e-9)
assert math.isclose(ex.cycle.average, c900.average, rel_tol=1e-9)
assert f600.E < 0.5 * f900.E and f600.I_s > f900.I_s

assert i_max == np.flatnonzero(mech.loads[0].active.mask(c600.q))[0]  # the first sample of the cut
cut = mech.loads[0].active.mask(np.radians([theta - 1, theta]))
assert theta == 125 and math.isclose(math.degrees(c600.q[i_at]), 125) and list(cut) == [False, True]  # "125°, in the cut"
ex.slider.value = theta
marker_x, marker_y = (float(v[0]) for v in ex.marker.get_data())
assert math.isclose(ex.analytical.effort[0], c600.torque[i_at], rel_tol=1e-9)
assert math.isclose(ex.construction.effort, c600.torque[i_at], rel_tol=1e-9)
assert math.isclose(marker_x, theta) and math.isclose(marker_y, c600.torque[i_at], rel_tol=1e-9)
for name in ex.analytical.names():  # every joint force, both routes, against the sweep
    assert np.allclose(ex.analytical[name][0], c600.analysis[name][i_at], rtol=1e-9, atol=1e-6)
    assert np.allclose(ex.construction[name], c600.analysis[name][i_at], rtol=1e-9, atol=1e-6)

ex.slider.value = 140
assert math.isclose(ex.analytical.effort[0], c600.torque[i140], rel_tol=1e-9)
assert math.isclose(ex.construction.effort, c600.torque[i140], rel_tol=1e-9)

# %% [markdown]
# ### 10. Your turn

# %%
# The feedback example: E a factor 1000 off earns half the points, the right I_s all of them.
report = gk.exercises.grade("flywheel", demo, slipped)
verdict = {q["id"]: (q["verdict"], q["slip"], q["score"] / q["max"]) for q in report["questions"]}
assert verdict["E"] == ("slip", "power_of_ten", 0.5) and verdict["I_s"] == ("correct", None, 1.0)
assert gk.exercises.check("flywheel", demo, slipped).splitlines()[0].endswith(f"{report['score']:g} / 2 points")

# The lesson's own tools give the answer key (for the id the notebook runs with); C_s comes with the data.
mine = gk.exercises.variant("flywheel", student)
assert f"Cs = {mine.Cs:g}" in [g["shown"] for g in gk.exercises.make("flywheel", student)["data"]]
key1 = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("flywheel", student)["questions"]}
f_mine = gk.sweep(my_cutter, 360).flywheel(mine.Cs)
assert math.isclose(f_mine.E, key1["E"], rel_tol=1e-9) and math.isclose(f_mine.I_s, key1["I_s"], rel_tol=1e-9)
key2 = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("joint_force_index", student)["questions"]}
jfi_mine = gk.joint_force_index(my_crank, 360)
assert math.isclose(jfi_mine.peak.value, key2["JFI"], rel_tol=1e-9)
assert math.isclose(jfi_mine.peak.at, key2["JFI_at"], rel_tol=1e-9)

# The answer boxes: type an id, fill in the key's answers as it prints them, press Check; then a slip.
box = gk.exercise("flywheel", "")
box.student.value = demo
assert all(g["shown"] in box.data.value for g in gk.exercises.make("flywheel", demo)["data"])
for q in gk.exercises.key("flywheel", demo)["questions"]:
    box.answers[q["id"]].value = q["answer"]["text"]
assert box.check()["score"] == 2
box.answers["E"].value = slipped["E"]
assert box.check()["score"] == 1.5 and box.report["questions"][0]["slip"] == "power_of_ten"
