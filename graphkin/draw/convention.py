"""The sign convention as a small drawn legend (README, "Sign convention")."""

from __future__ import annotations

import math

import numpy as np

from graphkin.draw import style as _style
from graphkin.draw.arrows import arrow, moment_arrow
from graphkin.draw.axes import Drawn, line, markers, new_axes, setup_axes


def draw_sign_convention(*, ax=None, title=True, **style) -> Drawn:
    """Draw the sign convention: x right, y up, counter-clockwise positive, and F_ij with its reaction.

    Two links 2 and 3 are drawn pulled apart at their common pin: F23 (the
    force of link 2 on link 3) acts on link 3, and F32 = −F23 on link 2.

    Returns
    -------
    Drawn
        ``.arrows`` (``"x"``, ``"y"``, ``"CCW"``, ``"F23"``, ``"F32"``) and ``.labels``.
    """
    s = _style.resolve(**style)
    ax = new_axes(ax, (4.0, 3.6), s)
    setup_axes(ax)
    drawn = Drawn(ax)
    if title:
        ax.set_title("Sign convention", fontsize=s.title_size, color=s.ink)
    fs = s.small_size

    def text(x, y, t, key=None, **kw):
        kw.setdefault("fontsize", fs)
        kw.setdefault("color", s.ink)
        art = ax.text(x, y, t, **kw)
        drawn.add(art)
        if key:
            drawn.labels[key] = art
        return art

    # Axes and the positive sense.
    O = np.array([0.4, 0.5])
    for key, tip in (("x", O + [1.7, 0.0]), ("y", O + [0.0, 1.7])):
        a = arrow(ax, O, tip, color=s.ink, lw=1.3, s=s)
        drawn.arrows[key] = a
        drawn.add(a)
    text(*(O + [1.8, 0.0]), "x", "x", ha="left", va="center", fontsize=s.label_size, style="italic")
    text(*(O + [0.0, 1.8]), "y", "y", ha="center", va="bottom", fontsize=s.label_size, style="italic")
    C = np.array([3.35, 1.25])
    a, arc, mid = moment_arrow(ax, C, 0.55, True, color=s.known, lw=1.6, s=s, start=-0.6 * math.pi, span=1.55 * math.pi)
    drawn.arrows["CCW"] = a
    drawn.add(a)
    dot = markers(ax, *C, ms=3, color=s.ink)
    drawn.add(dot)
    text(C[0] + 0.75, C[1] + 0.15, "+ CCW:\nθ, ω, α, T", "CCW", ha="left", va="center", color=s.known)
    # Two links pulled apart at their pin: action and reaction.
    A2 = np.array([2.15, 3.55])
    A3 = np.array([3.35, 3.95])
    for P, Q, n in ((np.array([0.35, 2.75]), A2, "2"), (A3, np.array([5.25, 3.2]), "3")):
        outer = line(ax, *np.array([P, Q]).T, color=s.ink, lw=s.link_lw, solid_capstyle="round")
        inner = line(ax, *np.array([P, Q]).T, color=s.link_fill, lw=s.link_lw - 2 * s.outline_lw,
                     solid_capstyle="round")
        for X in (P, Q):
            pin = markers(ax, *X, ms=s.pin_size, mfc="white", mec=s.ink, mew=1.2, zorder=5)
            drawn.add(pin)
        M = 0.5 * (P + Q)
        d = (Q - P) / np.hypot(*(Q - P))
        text(*(M + 0.32 * np.array([-d[1], d[0]])), n, f"link {n}", ha="center", va="center", fontsize=s.label_size,
             bbox=dict(boxstyle="circle,pad=0.18", fc="white", ec=s.ink, lw=0.8))
        drawn += [outer, inner]
    F = np.array([0.55, 0.95])
    a = arrow(ax, A3, A3 + F, color=s.unknown, lw=s.unknown_lw, s=s, hollow=True)
    drawn.arrows["F23"] = a
    drawn.add(a)
    text(*(A3 + F + [0.08, 0.0]), "F₂₃", "F23", ha="left", va="center", fontsize=s.label_size, color=s.unknown)
    a = arrow(ax, A2, A2 - F, color=s.unknown, lw=s.unknown_lw, s=s, hollow=True)
    drawn.arrows["F32"] = a
    drawn.add(a)
    text(*(A2 - F + [0.08, -0.05]), "F₃₂ = −F₂₃", "F32", ha="left", va="top", fontsize=s.label_size,
         color=s.unknown)
    text(0.2, 5.55, "Fᵢⱼ = force of link i on link j", "Fij", ha="left", va="center", fontsize=s.label_size)
    text(0.2, 5.1, "Fⱼᵢ = −Fᵢⱼ;  Gᵢⱼ at a sliding pair", "Fji", ha="left", va="center")
    ax.set_xlim(0.0, 6.0)
    ax.set_ylim(0.1, 5.85)
    return drawn
