"""The textbook names of joint forces: ``F23`` (a pin or a gear mesh), ``G14`` (a sliding pair's guide force).

``F_ij`` is the force of link i on link j; names with a link above 9 separate the numbers
with a comma (``F10,11``). The driver's unknown is named by :attr:`graphkin.model.Driver.symbol`.
"""

from __future__ import annotations

import re

from graphkin.errors import GraphkinError

_NAME = re.compile(r"^([FGT])(\d)(\d)$|^([FGT])_?(\d+),(\d+)$")


def force_name(mechanism, i: int, j: int) -> str:
    """The name of the force of link ``i`` on link ``j``: ``F23``, ``G14``, ``F10,11``.

    Examples
    --------
    >>> from graphkin import catalog
    >>> mech = catalog.load("double_slider").mechanism
    >>> force_name(mech, 2, 3), force_name(mech, 4, 1)
    ('F23', 'G41')
    """
    letter = mechanism.joint_between(i, j).force_letter
    return f"{letter}{i}{j}" if i < 10 and j < 10 else f"{letter}{i},{j}"


def parse_force_name(mechanism, name: str) -> tuple[int, int]:
    """Links (i, j) of a joint-force name: ``"F23"`` → (2, 3); checks the letter (F or G) fits the joint.

    Raises
    ------
    GraphkinError
        If ``name`` is not a force name, names links with no joint between
        them, or has the wrong letter for the joint.
    """
    m = _NAME.match(name) if isinstance(name, str) else None
    if not m:
        raise GraphkinError(f"{name!r} is not a force name like 'F23', 'G14' or {mechanism.driver.symbol!r}")
    letter, i, j = (m.group(1), m.group(2), m.group(3)) if m.group(1) else (m.group(4), m.group(5), m.group(6))
    i, j = int(i), int(j)
    try:
        joint = mechanism.joint_between(i, j)
    except GraphkinError:
        raise GraphkinError(f"{name!r}: links {i} and {j} share no joint") from None
    if letter != joint.force_letter:
        raise GraphkinError(f"{name!r}: the joint between links {i} and {j} is named {joint.force_letter}{i}{j}")
    return i, j
