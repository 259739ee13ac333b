"""A mechanism's plan: its decomposition and constants, worked out once and reused by every solve.

The structure of a mechanism -- which links form which dyad, in what order,
each point's local coordinates as a complex number, each bar's length -- does
not change from one call to the next; only the input positions do. Working it
out again on every call was most of the cost of a solve at a few hundred
positions. :func:`plan_of` builds it on the first call and keeps it for as long
as the mechanism lives.

A cached plan must never answer for a mechanism that has changed. A
:class:`~graphkin.model.Mechanism` is frozen (``dataclasses.replace`` makes a
new one, which gets its own plan), but ``object.__setattr__`` can still change
a field in place; so the plan keeps a snapshot of the attributes of the
mechanism and of every part it is built from (links, joints, loads, the
driver), and is rebuilt whenever one of them no longer equals its snapshot.
The check compares a dozen small dicts, a few microseconds (the parts with no cached property in one list
comparison).

The plan holds no reference to the mechanism itself (only a weak one): the
cache entry goes when the mechanism goes.
"""

from __future__ import annotations

import weakref
from functools import cache, cached_property, partial

from graphkin.kinematics.structure import decompose
from graphkin.model import Mechanism


@cache
def _derived(cls) -> frozenset:
    """The names of ``cls``'s cached properties (found once per class)."""
    return frozenset(k for k in dir(cls) if isinstance(getattr(cls, k, None), cached_property))


def _state(obj) -> dict:
    """An object's attributes, less what its cached properties keep: those are worked out from the others (a
    mechanism's ``moving`` links), so that asking for one first, after the plan was made, changes nothing."""
    derived = _derived(type(obj))
    return {k: v for k, v in vars(obj).items() if k not in derived} if derived else dict(vars(obj))


def _changed(obj, state: dict) -> bool:
    """Whether ``obj``'s attributes differ from ``state`` (compared as they are, for a class with no cached
    properties: the check runs on every solve)."""
    return (vars(obj) if not _derived(type(obj)) else _state(obj)) != state


def _parts(mech: Mechanism) -> list:
    """The objects besides the mechanism whose attributes decide the plan: every part of it."""
    parts = [mech.driver, *mech.links, *mech.joints, *mech.loads]
    parts += [load.active for load in mech.loads if getattr(load, "active", None) is not None]
    return parts


class Plan:
    """What :func:`graphkin.kinematics.solve_kinematics` and :func:`graphkin.analytical.solve_forces` reuse.

    Attributes
    ----------
    groups : tuple
        :func:`graphkin.kinematics.decompose` of the mechanism.
    points : dict of (int, str) to complex
        Every named point of every link, in the link's frame [m].
    compiled : dict
        Per-solver compiled steps (filled in by the solvers on first use).
    """

    __slots__ = ("ref", "own", "snapshot", "plain", "derived", "groups", "points", "frame", "moving", "compiled")

    def __init__(self, mech: Mechanism):
        # The weak reference's callback drops the cache entry when the mechanism is collected.
        self.ref = weakref.ref(mech, partial(_forget, id(mech)))
        # Copies of the attribute dicts: a field set in place later makes them differ. The parts are held
        # (they are small and frozen); the mechanism is not, so that its plan goes when it goes.
        self.own = _state(mech)
        self.snapshot = [(part, _state(part)) for part in _parts(mech)]
        # Most parts have no cached property: their attribute dicts are compared as they are, all in one go.
        self.plain = ([part for part, _ in self.snapshot if not _derived(type(part))],
                      [state for part, state in self.snapshot if not _derived(type(part))])
        self.derived = [(part, state) for part, state in self.snapshot if _derived(type(part))]
        self.groups = decompose(mech)
        self.points = {(link.number, name): complex(x, y)
                       for link in mech.links for name, (x, y) in link.points.items()}
        self.frame = mech.frame
        self.moving = mech.moving
        self.compiled: dict = {}

    def current(self, mech: Mechanism) -> bool:
        """Whether this plan still describes ``mech`` (the same object, no attribute changed since)."""
        if self.ref() is not mech or _changed(mech, self.own):
            return False
        parts, states = self.plain
        return [vars(part) for part in parts] == states and not any(_changed(p, s) for p, s in self.derived)


_PLANS: dict[int, Plan] = {}
"""Plans by the id of their mechanism. No lock: a dict's get, set and pop are atomic, and the worst a race
can do is drop a plan that is then built again."""


def _forget(key: int, ref: weakref.ref, plans=_PLANS) -> None:
    # ``plans`` is bound here: at interpreter exit the module's globals may be gone before the last callbacks.
    plan = plans.get(key)
    if plan is not None and plan.ref is ref:
        plans.pop(key, None)


def plan_of(mech: Mechanism) -> Plan:
    """The plan of ``mech``: cached while the mechanism lives and is unchanged, else built now.

    Raises
    ------
    ModelError
        If the mechanism cannot be decomposed into a driver, dyads and gear pairs.
    """
    key = id(mech)
    plan = _PLANS.get(key)
    if plan is not None and plan.current(mech):
        return plan
    plan = _PLANS[key] = Plan(mech)
    return plan


def plan_solved(mech: Mechanism, groups: tuple) -> Plan:
    """The plan kinematics of ``mech`` were solved with: the kept plan whose decomposition is ``groups`` (the
    kinematics' own), found without checking every part of ``mech`` for a change since, else :func:`plan_of`.

    For a reader of those kinematics (the graphical route): the plan describes the mechanism as they were solved
    for, which is what they describe, where a mechanism changed in place since would not match them.
    """
    plan = _PLANS.get(id(mech))
    if plan is not None and plan.groups is groups and groups and plan.ref() is mech:
        return plan
    return plan_of(mech)


def kept_plan(mech: Mechanism) -> Plan | None:
    """The plan of ``mech`` if one is kept and still describes it, else None (none is made: for a cache of a
    caller's own, keyed by the plan, that must not cost a decomposition)."""
    plan = _PLANS.get(id(mech))
    return plan if plan is not None and plan.current(mech) else None


def cached_plans() -> int:
    """How many plans are cached (for tests)."""
    return len(_PLANS)
