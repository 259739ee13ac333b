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
# # Lesson 12 — Balancing: counterweights, primary and secondary forces
#
# Lesson 03 measured the **shaking force**, what the moving links do to the frame, and left it
# there. This lesson cures it, as far as it can be cured, for the commonest machine of all, the
# single-cylinder engine:
#
# 1. what shakes the frame of an engine;
# 2. a rotating mass and its counterweight;
# 3. the reciprocating mass: primary and secondary forces, and why a counterweight can only trade
#    one for another;
# 4. graphkin's shaking force against the theory, for several counterweights;
# 5. your turn.

# %%
# %matplotlib inline
import tomllib

import numpy as np

import graphkin as gk

# %% [markdown]
# ## 1. What shakes the frame
#
# The frame feels the forces of the moving links on it: at the main bearing, $\vec F_{21}$, and at
# the cylinder wall, $\vec G_{41}$. Add up the equilibrium of all the moving links (d'Alembert): the
# frame's forces on them, the external loads and the inertia forces sum to zero. The **gas** pushes
# on the piston, but it pushes just as hard on the cylinder head, which is part of the frame; it
# shakes nothing. So the shaking force of an engine is the sum of the inertia forces of its moving
# parts:
#
# $$\vec S = \vec F_{21} + \vec G_{41} = \sum_j \left(-m_j\,\vec a_{Gj}\right).$$
#
# To balance an engine is to make that sum small. It involves masses and accelerations only.
#
# ## 2. A rotating mass and its counterweight
#
# A mass $m$ at radius $r$ on a shaft turning at $\omega$ has the inertia force $m\,\omega^2 r$,
# outwards along the radius: a force of constant size turning with the shaft. A **counterweight** $B$
# at radius $b$ diametrically opposite, with
#
# $$B\,b = m\,r ,$$
#
# has an equal and opposite inertia force at every angle. A rotating mass can be balanced completely
# in one plane (with several planes, the moments need balancing too; that is for a book's chapter on
# rotating masses).
#
# ## 3. The reciprocating mass
#
# The piston and the parts that move with it, $m_R$, move along the stroke with the acceleration of
# lesson 09. Their inertia force, along the line of stroke, is
#
# $$F_I = \underbrace{m_R\,\omega^2 r\cos\theta}_{\text{primary}}
#       \;+\; \underbrace{m_R\,\omega^2 r\,\frac{\cos 2\theta}{n}}_{\text{secondary}} .$$
#
# The **primary** force varies at the crank's speed and looks like the along-stroke part of a mass
# $m_R$ at the crank pin. So try a counterweight for a fraction $c$ of it, $B\,b = c\,m_R\,r$. Its
# inertia force is $c\,m_R\,\omega^2 r$ turning with the crank, pointing away from the pin. Along the
# stroke it takes away $c$ of the primary force; across the stroke it adds what was not there before:
#
# $$S_x = (1-c)\,m_R\,\omega^2 r\cos\theta + m_R\,\omega^2 r\,\frac{\cos 2\theta}{n}, \qquad
#   S_y = -\,c\,m_R\,\omega^2 r\sin\theta .$$
#
# Nothing rotating can do better: a counterweight **trades** the primary force along the stroke for
# one across it. Most single-cylinder engines choose $c$ between $\tfrac12$ and $\tfrac23$; at
# $c = \tfrac12$ the largest unbalanced primary force is halved, and is the same in every direction.
# The **secondary** force, turning at twice the crank speed, is untouched by any counterweight on the
# crank.

# %% [markdown]
# ## 4. graphkin: an engine half balanced
#
# The engine of Khurmi & Gupta's Example 15.9 (lesson 09's exercise): $r = 50$ mm, $n = 4$,
# $m_R = 1$ kg at 1800 rpm, the rod light, written for balancing — no gas load, and a counterweight
# of 0.5 kg at 50 mm opposite the crank pin: $c = \tfrac12$. Over a turn, the shaking force along
# the stroke (x) and across it (y):

# %%
engine = gk.load("engine_balancing")
half = gk.sweep(engine, 360)
gk.draw.draw_shaking_components(half)

# %% [markdown]
# The formulas of section 3 give the same curves, except that they use the two-term series for the
# piston's acceleration, and graphkin the exact one: they differ by at most 15 N, about 1 % of the
# largest force, near $\theta = 90^\circ$ — the terms the series leaves out are largest for a rod as
# short as this one ($n = 4$).

# %% [markdown]
# Now the counterweight itself. The problem file read as a dictionary (as `tomllib` reads any TOML)
# is easy to change: here the crank's mass, the counterweight, for $c = 0$, $\tfrac12$, $\tfrac23$ and
# $1$, each swept over a turn. The largest shaking force along and across the stroke:

# %%
data = tomllib.loads(gk.catalog.path("engine_balancing").read_text(encoding="utf-8"))
print(f"{'c':>6}{'largest |S_x|':>15}{'largest |S_y|':>15}")
for c in (0, 1 / 2, 2 / 3, 1):
    data["links"][0]["mass"] = f"{c * 1.0} kg"  # B b = c m_R r with b = r
    S_c = gk.sweep(gk.build_problem(data), 360).shaking_force()
    print(f"{c:>6.2f}{np.abs(S_c[:, 0]).max():>13.0f} N{np.abs(S_c[:, 1]).max():>13.0f} N")

# %% [markdown]
# Read the table against the theory: $S_y$ grows in step with $c$, to the full primary
# $m_R\,\omega^2 r = 1777$ N at $c = 1$; $S_x$ falls, but never below the secondary force,
# $m_R\,\omega^2 r/n = 444$ N: at $c = 1$ what is left along the stroke is the secondary and the small
# terms the series leaves out (459 N). "Full" balance of the primary only turns it through 90°. The best choice depends on the mounting: an engine on springs that are soft sideways
# would take a small $c$.

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
m_R, r, n, omega = 1.0, 0.050, 4.0, 1800 * 2 * np.pi / 60
theta = half.q
S = half.shaking_force()
primary, secondary = m_R * omega**2 * r * np.cos(theta), m_R * omega**2 * r * np.cos(2 * theta) / n
series_error = np.abs(S[:, 0] - (0.5 * primary + secondary))
assert 14 < series_error.max() < 15.5 and 0.008 < series_error.max() / np.abs(S).max() < 0.012  # "15 N, about 1 %"
assert 80 < np.degrees(theta[series_error.argmax()]) < 100 or 260 < np.degrees(theta[series_error.argmax()]) < 280
assert np.allclose(S[:, 1], -0.5 * m_R * omega**2 * r * np.sin(theta), rtol=0, atol=1e-9 * np.abs(S).max())
peak = m_R * omega**2 * r
for c in (0, 1 / 2, 2 / 3, 1):
    data["links"][0]["mass"] = f"{c * 1.0} kg"
    S_c = gk.sweep(gk.build_problem(data), 360).shaking_force()
    assert np.isclose(np.abs(S_c[:, 1]).max(), c * peak, rtol=1e-6, atol=1e-9 * peak)  # "S_y grows with c"
    assert np.abs(S_c[:, 0]).max() >= peak / n * (1 - 1e-9)  # "never below the secondary"
at_c1 = np.abs(S_c[:, 0])
assert round(at_c1.max()) == 459  # c = 1: the secondary and the series' remainder are what is left
assert round(peak) == 1777 and round(peak / n) == 444

# %% [markdown]
# ### The secondary force
#
# No counterweight on the crank can touch the secondary force: it turns at $2\omega$. A book's
# chapter on multi-cylinder engines balances it by arranging cylinders whose secondary forces cancel
# (the four-cylinder in-line engine balances its primaries but not its secondaries; the six balances
# both), or with **balancer shafts** turning at twice the crank speed (Lanchester's arrangement).
#
# ## 5. Your turn
#
# The engine of section 4 idling at **your own** speed and crank angle, with your own counterweight.
# Type your id in place of `"your-id"` and run the cell.
#
# Work it **by hand first**: the inertia forces of the piston and of the counterweight, then the
# equilibrium (with lesson 09's exact $a_P$: the grader allows 1 %). Two hints: with no loads, $\vec F_{12} + \vec G_{14}$ is the sum of the inertia forces
# turned round; and the cylinder wall pushes only across the stroke ($G_{14}$ from lesson 09's
# $F_N = F_P\tan\varphi$, with $F_P = -F_I$ here). Type the two components (`"-123 N"`) and press
# **Check**.

# %%
student = "your-id"  # ← type your own id here
gk.exercise("engine_balance", student)

# %% [markdown]
# Only when you have checked your answers, run the next cell: graphkin's solution of your engine.

# %%
mine = gk.exercises.variant("engine_balance", student).problem
print(gk.format_solution(mine, mine.solve()))

# %% tags=["remove-input"] jupyter={"source_hidden": true}
# The lesson's own check (folded): it keeps what the text above says right; nothing to do here.
key = {q["id"]: q["answer"]["si"] for q in gk.exercises.key("engine_balance", student)["questions"]}
worked = mine.solve()
F12 = worked.force(1, 2)[0]
assert np.allclose([key["F12x"], key["F12y"]], F12, rtol=1e-9)
