"""How the velocity and acceleration polygons' captions write things: a sense, a rate, a vector, a link's image.

Captions are plain text (a hyphen-minus), written with :mod:`graphkin.notation`. A link's image is the step
most polygons have most of; its caption, and the driver's and a gear's, are written when first read
(:class:`graphkin.graphical.captions.Later`): their writers take every value they print as an argument.
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


def driver_turning(link: int, pivot: str, w: float) -> str:
    """The caption of a turning driver's velocity step: ``w`` its ω [rad/s] about the pin ``pivot``."""
    return (f"Driver {link} turns about {pivot} at ω{link} = {rate(w, 'rad/s')}: each of its points moves "
            f"perpendicular to its line from {pivot}, at ω{link} times that distance.")


def driver_sliding(link: int, s: str, v_s: float, v: complex, scale: float) -> str:
    """The caption of a sliding driver's velocity step: its point ``s`` moves at ``v_s`` [m/s] along the guide, the
    vector ``v`` [m/s] (a rounding residue beside ``scale`` [m/s] written as 0)."""
    return f"Driver {link} slides along its guide at v = {number(v_s)} m/s: v_{s} = {vector(v, V, scale)}, " \
        f"drawn from the pole o to {s.lower()}."


def driver_turning_acceleration(link: int, pivot: str, al: float) -> str:
    """The caption of a turning driver's acceleration step: ``al`` its α [rad/s²] about the pin ``pivot``."""
    return (f"Driver {link}: α{link} = {rate(al, 'rad/s²')}; each of its points has a normal component "
            f"ω{link}² r towards {pivot} and a tangential one α{link} r perpendicular to its line from {pivot}.")


def driver_sliding_acceleration(link: int, s: str, a_s: float, a: complex, scale: float) -> str:
    """The caption of a sliding driver's acceleration step, as :func:`driver_sliding`'s [m/s²]."""
    return f"Driver {link} accelerates along its guide at a = {number(a_s)} m/s²: a_{s} = {vector(a, A, scale)}, " \
        f"drawn from the pole o′ to {s.lower()}′."


def gear_rolling(j: int, k: int, p: str, c: str, v_P: complex, w: float, scale: float) -> str:
    """The caption of gear ``k``'s velocity step: it meshes with gear ``j`` at the pitch point ``p`` and turns about
    its centre ``c``; ``v_P`` [m/s] the pitch point's velocity, ``w`` gear k's ω [rad/s]."""
    return (f"Gear {k} meshes with gear {j} at the pitch point {p}, where the gears roll: v_{p} on gear {k} "
            f"equals v_{p} on gear {j} = {vector(v_P, V, scale)}. Gear {k} turns about {c}: "
            f"ω{k} = v_{p}{c} / {c}{p} = {rate(w, 'rad/s')}.")


def gear_rolling_acceleration(j: int, k: int, p: str, c: str, t_name: str, a_n: float, al: float) -> str:
    """The caption of gear ``k``'s acceleration step: ``a_n`` the size of its pitch point's normal component
    about ``c`` [m/s²], ``al`` its α [rad/s²], ``t_name`` the tangential component's symbol."""
    return (f"Gear {k}: a_{p} = a_{c} + a^n_{p}{c} + {t_name}, a^n_{p}{c} = ω{k}² {c}{p} = "
            f"{number(a_n)} m/s² towards {c}, {t_name} ⊥ {c}{p}; rolling makes the tangential "
            f"components of the two gears' pitch points equal, so a_{p} lies on the line through gear {j}'s "
            f"a_{p} along the line of centres. They meet: α{k} = {t_name} / {c}{p} = {rate(al, 'rad/s²')}.")
