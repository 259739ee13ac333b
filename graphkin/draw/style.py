"""Colours, line weights and font sizes of every graphkin figure.

The palette is Okabe and Ito's (2008), safe for the common colour-vision
deficiencies. Colour is never the only cue: known loads are drawn solid and
heavy, unknown forces lighter with an open look, lines of action by dash
pattern (known load: solid; known direction only: dashed; found: dash-dot).

Every drawing function takes ``**style`` keyword overrides of the fields of
:class:`Style` (``draw_mechanism(c, link_lw=5)``); :data:`STYLE` is the
default, and :func:`use` changes it for the session.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace

# Okabe–Ito palette.
BLACK = "#000000"
ORANGE = "#E69F00"
SKY_BLUE = "#56B4E9"
GREEN = "#009E73"
YELLOW = "#F0E442"
BLUE = "#0072B2"
VERMILLION = "#D55E00"
PURPLE = "#CC79A7"
GREY = "#6E6E6E"
LIGHT = "#E8E8E8"

OKABE_ITO = (BLACK, ORANGE, SKY_BLUE, GREEN, YELLOW, BLUE, VERMILLION, PURPLE)


@dataclass(frozen=True)
class Style:
    """Visual parameters (colours, weights in points, font sizes in points)."""

    # Forces.
    known: str = BLUE
    """Known loads: inertia resultants, weights, external forces and torques."""
    unknown: str = VERMILLION
    """Unknown forces: joint reactions found by the analysis."""
    driver: str = PURPLE
    """The driving torque or force."""
    found: str = GREEN
    """Lines and points found by a construction step (concurrency points, found lines)."""
    known_lw: float = 2.2
    unknown_lw: float = 1.6
    head: float = 11.0
    """Arrowhead size (matplotlib mutation scale) [pt]."""
    # Mechanism.
    ink: str = "#222222"
    link_fill: str = "#D9D9D9"
    plate_fill: str = "#E6E6E6"
    link_lw: float = 7.0
    """Width of a bar drawn as an outlined band [pt]."""
    outline_lw: float = 1.1
    thin_lw: float = 0.7
    pin_size: float = 6.5
    """Diameter of a pin circle [pt]."""
    ground_hatch: str = "////"
    faint_alpha: float = 0.28
    # Lines of action.
    line_lw: float = 1.1
    # Text.
    font: str = "DejaVu Sans"
    label_size: float = 9.5
    small_size: float = 8.0
    caption_size: float = 9.0
    title_size: float = 10.5
    suptitle_size: float = 12.5
    label_pad: float = 3.5
    """Gap between an arrow and its label [pt]."""
    dpi: int = 200
    """Resolution of saved PNGs."""

    def but(self, **overrides) -> Style:
        """A copy with some fields changed; unknown names raise ``TypeError``."""
        if not overrides:
            return self
        names = {f.name for f in fields(self)}
        bad = sorted(set(overrides) - names)
        if bad:
            raise TypeError(f"unknown style option(s) {', '.join(bad)}; known: {', '.join(sorted(names))}")
        return replace(self, **overrides)


STYLE = Style()
"""The default style."""


def use(**overrides) -> Style:
    """Change the default style for every later figure; returns the new default."""
    global STYLE
    STYLE = STYLE.but(**overrides)
    return STYLE


def resolve(style: Style | None = None, **overrides) -> Style:
    """``style`` (or the current default) with ``overrides`` applied."""
    return (style or STYLE).but(**overrides)


LINE_DASH = {
    "resultant": "-",
    "known direction": (0, (6, 3)),
    "found": (0, (8, 2.5, 1.5, 2.5)),
}
"""Dash pattern of a line of action by its role (see :class:`graphkin.graphical.Line`)."""


def line_color(role: str, s: Style | None = None) -> str:
    s = s or STYLE
    return {"resultant": s.known, "known direction": s.unknown, "found": s.found}.get(role, s.ink)
