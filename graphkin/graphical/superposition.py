"""Superposition as books write it: one sub-problem per loaded link, each solved to its own driving effort, then the sum."""

from __future__ import annotations

from graphkin.graphical.builder import Builder, _Load, _other, xy
from graphkin.graphical.captions import Later, and_list, mark, number, polar, roman, sense
from graphkin.graphical.construction import Arrow, SubProblem
from graphkin.kinematics import DriverGroup, Kinematics
from graphkin.model import Prismatic
from graphkin.notation import largest, unless_rounding


def superposition(kin: Kinematics, index: int, whole: Builder):
    """The steps of a superposition, as books write it, and its sub-problems.

    Every link's own loads first; then one sub-problem per loaded link, each
    announced, solved with every other link unloaded, and its readings and
    driving effort given; then the sum of every joint force, and the input
    link with the summed reactions, whose effort is the sum of the
    sub-problems' efforts.
    """
    mech = kin.mechanism
    p = Builder(kin, index, like=whole)
    own = {link: p.own_loads(link) for link in mech.moving}
    loaded = [link for link in mech.moving if own[link].F != 0 or own[link].M0 != 0]
    crank = mech.driver.crank
    effort = "driving torque" if crank else "driving force"
    labels = [roman(k) for k in range(1, len(loaded) + 1)]
    marks = [mark(k) for k in range(1, len(loaded) + 1)]
    if any(isinstance(J, Prismatic) and J.mu > 0 for J in mech.joints):
        p.add("note", "Friction: each guide reaction is tilted by atan μ against the sliding, to the side the normal "
              "force pushes. That side is taken from the whole problem (solved first) and kept in every sub-problem, "
              "so the equations stay linear in the loads and the sub-problems add up.", mech.driver.link)
    p.add("note", Later(_why, tuple(dict.fromkeys(whole.superposed)), tuple(zip(labels, loaded)), effort))
    subs = []
    fixed = whole.sides
    for x, m, L in zip(labels, marks, loaded):
        b = Builder(kin, index, sub=x, mark=m, scope=f"sub-problem {x}", fixed=fixed, steps=p.steps,
                     warnings=p.warnings, like=whole)
        b.rname = dict(p.rname)
        others = tuple(n for n in mech.moving if n != L)
        b.add("sub-problem", Later(_announce, x, L, p.rname[L], own[L].F, own[L].M0, own[L].point() is not None, others,
                                   m, b.name(*_first_pair(mech))), L)
        b.run(lambda link, L=L: _Load(own[link].F, own[link].M0) if link == L else _Load())
        readings = {}
        for J, on in b.order.values():
            other = _other(J, on)
            readings[b.name(other, on)] = xy(b.on(J, on))
        drive = mech.driver.symbol + m
        readings[drive] = b.effort if crank else b.driver_vector
        b.add("readings", Later(_readings, x, tuple((n, v) for n, v in readings.items() if n != drive), effort, drive,
                                b.effort, crank), L, values=readings)
        subs.append((x, m, L, b))
    # The sums: every joint force of the groups, then the input link with the summed reactions.
    first = subs[0][3]
    zero = []
    driver_group = next(g for g in kin.groups if isinstance(g, DriverGroup))
    for J, on in first.order.values():
        if J is driver_group.joint:
            continue
        other = _other(J, on)
        n = p.base_name(other, on)
        parts = [(n + m, b.on(J, on)) for _, m, _, b in subs]
        total = sum((F for _, F in parts), 0j)
        shown = [(name, F) for name, F in parts if F != 0]
        if not shown:
            zero.append(n)
            continue
        rest = " (it is zero in the other sub-problems)" if len(shown) < len(parts) and len(shown) == 1 else ""
        p.add("superpose", Later(lambda n, shown, total, rest: f"Sum of the sub-problems: {n} = "
                                 + " + ".join(name for name, _ in shown) + f" = {polar(total)}{rest}.",
                                 n, tuple(shown), total, rest), on,
              polygon=tuple(Arrow(name, xy(F), True) for name, F in shown) + (Arrow(f"−{n}", xy(-total), False),),
              values={n: xy(total)})
    if zero:
        p.add("note", f"{and_list(zero)} {'is' if len(zero) == 1 else 'are'} zero in every sub-problem, so zero in the "
              "whole problem.")
    link = driver_group.link
    extra = {}
    for _, _, _, b in subs:
        for base, _, F, X, C in b.passed[link]:
            if base in extra:
                extra[base][1] += F
                extra[base][3] += C
            else:
                extra[base] = [base, F, X, C]
    p.scope = "the whole problem"
    R = p.combine(link, _Load(own[link].F, own[link].M0), [tuple(v) for v in extra.values()])
    drive = mech.driver.symbol
    total = Later(_sum_of_efforts, effort, drive, tuple((m, b.effort, tuple(b.forces.values())) for _, m, _, b in subs),
                  crank)
    p.driver(driver_group, R, total)
    out = tuple(SubProblem(x, L, m, dict(b.forces), dict(b.normal), dict(b.couple), b.effort, b.driver_vector)
                for x, m, L, b in subs)
    return p.steps, out, p.warnings


def _why(dyads, subs, effort) -> str:
    """Why the steps are a superposition: the ``dyads`` with both links loaded; the sub-problems ``subs`` ((label,
    link) pairs)."""
    return (f"Superposition: in {and_list([f'the {label}' for label in dyads])} both links carry loads, so neither is "
            "a two-force member. At a fixed position the equilibrium equations are linear in the loads, so the problem "
            "is solved once per loaded link, with every other link unloaded — "
            + "; ".join(f"sub-problem {x}: only the loads on link {L}" for x, L in subs)
            + f" — and the joint forces and {effort}s of the sub-problems are added.")


def _sum_of_efforts(effort, drive, subs, crank) -> str:
    """The driver's effort as the sum of the sub-problems' (``subs``: (mark, effort, its joint forces) triples)."""
    return (f"it is the sum of the sub-problems' {effort}s, {drive} = " + " + ".join(drive + m for m, _, _ in subs)
            + " = " + " + ".join(f"({number(e)})" if e < 0 else f"{number(e)}"
                                 for e in (unless_rounding(e, largest(forces)) for _, e, forces in subs))
            + (" N·m" if crank else " N"))


def _announce(x, L, R, F, M0, line, others, m, example) -> str:
    """Sub-problem x's first words: only the loads on link L (their resultant R = F, or a couple M0 where it has no
    ``line``), the ``others`` unloaded, and the mark ``m`` of its forces (an ``example`` of a marked name)."""
    size = f"{R} = {number(abs(F))} N" if line else f"a couple of {number(M0)} N·m"
    return (f"Sub-problem {x}: only the loads on link {L} ({size}); "
            + (f"link{'s' * (len(others) > 1)} {and_list([str(n) for n in others])} "
               f"{'are' if len(others) > 1 else 'is'} unloaded. " if others else "")
            + f"Its forces are marked {m} ({example}).")


def _readings(x, forces, effort, drive, value, crank) -> str:
    """What sub-problem x found: its joint ``forces`` ((name, (x, y)) pairs [N]) and its ``effort`` ``drive``."""
    biggest = largest(v for _, v in forces)
    shown = unless_rounding(value, biggest)  # a sub-problem whose loads pass through the pivot: 0
    effort_text = f"{number(shown)} N·m{sense(shown)}" if crank else f"{number(shown)} N along the guide"
    return (f"Sub-problem {x} gives " + ", ".join(f"{n} = {polar(complex(*v), biggest)}" for n, v in forces)
            + f"; its {effort} {drive} = {effort_text}.")


def _first_pair(mech):
    """A joint's two links, for an example of a marked name (F23′): a joint between moving links if there is one."""
    joints = [j for j in mech.joints if mech.frame not in j.links] or list(mech.joints)
    return tuple(sorted(joints[0].links))
