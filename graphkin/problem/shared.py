"""What the problems an exercise builds share: parts read once per equal table, and the mechanism made of them.

An exercise builds a problem for every draw from the same tables with a few values changed (the crank's angle,
its speed, a load), so most links, joints and loads are read again and again from equal tables, and most
draws are made of the same parts. Parts and mechanisms are frozen, so problems may share them.
"""

from __future__ import annotations

from collections import OrderedDict

from graphkin.model import Mechanism

_READ: OrderedDict = OrderedDict()
_READ_SIZE = 256


def read_once(read, rd, t, where, *args):
    """``read(rd, t, where, *args)``: a part read from its table, or the part read before from an equal table.

    An exercise builds a problem for every draw from the same tables with a
    few values changed (the crank angle, a load), so most links and loads are
    read again and again from equal tables; reading the links (units, ranges,
    mass properties) was a third of a build. Links and loads are frozen, so
    problems may share them. Only a table that reads without error is kept (an
    error names the file, which differs from one caller to the next); the key
    is the table's ``repr``, which tells apart every value TOML can hold (``1``,
    ``1.0``, ``true``, ``"1"``).
    """
    key = (read, where, repr(t), args)
    part = _READ.get(key)
    if part is not None:
        _READ.move_to_end(key)
        return part
    part = _READ[key] = read(rd, t, where, *args)
    if len(_READ) > _READ_SIZE:
        _READ.popitem(last=False)
    return part


_MECHANISMS: OrderedDict = OrderedDict()
_MECHANISMS_SIZE = 256


def mechanism_once(links, joints, driver, loads, gravity, assembly, title, source, frame) -> Mechanism:
    """The mechanism of these parts, or the one made before of the very same parts.

    Links, joints and forces are read once per equal table (:func:`read_once`), so the draws of an exercise
    that change only the input's position or speed, or a load's size among a few, are made of the same part
    objects again and again: they share one mechanism, and with it the plan the solvers keep for it (the
    decomposition into groups, the compiled steps; :func:`graphkin.kinematics.plan.plan_of`), which each new
    mechanism would work out afresh (a seventh of a draw's build and solve). A mechanism is frozen, as its parts
    are. The key holds the parts' ids: the mechanism it leads to keeps them alive, so no other object has them
    while the entry is kept.
    """
    key = (tuple(map(id, links)), tuple(map(id, joints)), driver, tuple(map(id, loads)), gravity,
           tuple(assembly.items()), title, source, frame)
    mech = _MECHANISMS.get(key)
    if mech is not None:
        _MECHANISMS.move_to_end(key)
        return mech
    mech = _MECHANISMS[key] = Mechanism(links, joints, driver, loads, gravity, assembly, title=title, source=source,
                                        frame=frame)
    if len(_MECHANISMS) > _MECHANISMS_SIZE:
        _MECHANISMS.popitem(last=False)
    return mech
