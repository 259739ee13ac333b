"""How the velocity and acceleration polygons' captions write things: a sense, a rate, a vector, a link's image.

Captions are plain text (a hyphen-minus), written with :mod:`graphkin.notation`. A link's image is the step
most polygons have most of, and its caption is written when first read (:class:`graphkin.graphical.captions.Later`):
its writers take every value they print as an argument.
"""

from __future__ import annotations

import math

from graphkin.graphical.captions import number
from graphkin.notation import polar_text

V, A = "m/s", "m/s²"


def sense(w: float) -> str:
    """The sense of ω or α: ``"CCW"`` or ``"CW"``."""
    return "CCW" if w > 0 else "CW"


def rate(x: float, unit: str) -> str:
    """ω or α as a caption prints it: ``2.5 rad/s (CCW)``."""
    return f"{number(x)} {unit}" + (f" ({sense(x)})" if x else "")


def vector(z: complex, unit: str, scale: float) -> str:
    """A vector of a polygon [m/s or m/s²], its rounding residue beside ``scale`` (the same unit) written as 0."""
    return polar_text((z.real, z.imag), unit, scale=scale, minus="-")


def velocity_image(link: int, w: float, v: complex, listed: list, scale: float) -> str:
    """The caption of a link's velocity image.

    Parameters
    ----------
    link : int
    w : float
        The link's ω [rad/s].
    v : complex
        The velocity of the point of the link the image starts from [m/s].
    listed : list of (str, complex)
        The symbol and velocity [m/s] of each point the image finds first.
    scale : float
        What a rounding residue is beside [m/s].
    """
    if w == 0 and v == 0:
        how = f"Link {link} is at rest (ω{link} = 0, no velocity): its image is the pole"
    elif w == 0:
        how = f"Link {link} translates (ω{link} = 0): every point has the same velocity, its image is one point"
    else:
        how = (f"Velocity image of link {link}: its shape turned 90° {sense(w)} and scaled by "
               f"|ω{link}| = {number(abs(w))} rad/s")
    found = ", ".join([f"v_{s} = {vector(z, V, scale)}" for s, z in listed])
    return f"{how}: {found}." if found else f"{how}."


def acceleration_image(link: int, w: float, al: float, a: complex, listed: list, scale: float) -> str:
    """The caption of a link's acceleration image, as :func:`velocity_image`'s: ``al`` its α [rad/s²], ``a`` the
    acceleration of its known point, ``listed`` and ``scale`` in m/s²."""
    if w == 0 and al == 0 and a == 0:
        how = f"Link {link} has no acceleration (ω{link} = α{link} = 0): its image is the pole"
    elif w == 0 and al == 0:
        how = f"Link {link} translates (ω{link} = α{link} = 0): its acceleration image is one point"
    else:
        turn = math.degrees(math.atan2(al, -w * w))
        how = (f"Acceleration image of link {link}: its shape turned {number(turn)}° (atan2(α{link}, -ω{link}²)) "
               f"and scaled by √(ω{link}⁴ + α{link}²) = {number(math.hypot(w * w, al))} 1/s²")
    found = ", ".join([f"a_{s} = {vector(z, A, scale)}" for s, z in listed])
    return f"{how}: {found}." if found else f"{how}."
