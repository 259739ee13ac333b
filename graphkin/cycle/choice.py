"""Choosing among a study's designs: its figures of merit by name, its fields as numbers, the best design.

A designer picks the design that costs least by one figure of merit among those that meet stated limits on
others: the least peak torque with a transmission angle of at least 40° (Norton, *Design of Machinery*, §4.10 and
ch. 11). :func:`best` does that over a :class:`~graphkin.cycle.studies.Study`; the limits are read as data
(``"transmission_angle_min >= 40 deg"``: a figure's name, a comparison and a value with its unit), never run as
code. A design that cannot be assembled over its cycle is never chosen, nor one whose figure is not defined.
"""

from __future__ import annotations

import math
import re
from typing import NamedTuple

import numpy as np

from graphkin.errors import GraphkinError, ProblemFileError
from graphkin.units.convert import to_si

__all__ = ["Choice", "Requirement", "best", "field_axis", "figure_values", "figures", "requirement"]

_FIXED = {"torque_peak": None, "torque_rms": None, "I_s": "moment_of_inertia", "shaking_force_peak": "force",
          "shaking_moment_peak": "torque", "transmission_angle_min": "angle"}
"""Each figure of merit a design has by itself, and its dimension (None: the driving effort's, a torque or a
force)."""

_COMPARE = {"<=": np.less_equal, ">=": np.greater_equal, "<": np.less, ">": np.greater}

_REQUIREMENT = re.compile(r"\s*(?P<name>[A-Za-z_]\w*)\s*(?P<op><=|>=|<|>)\s*(?P<value>\S(?:.*\S)?)\s*")

_NUMBER = re.compile(r"\s*(?P<x>[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(?P<unit>.*?)\s*")


def figures(study) -> dict[str, str]:
    """The figures of merit of a study's designs, by name, and the dimension of each (a key of
    :data:`graphkin.units.dimensions.DIMENSIONS`): the six of :class:`~graphkin.cycle.studies.Design` and the peak
    force at each joint, ``"F12_peak"``, ...; a slider driver's effort is a force.
    """
    effort = "torque" if study.crank else "force"
    out = {name: dim or effort for name, dim in _FIXED.items()}
    joints = next((d.joint_peaks for d in study.designs if d.joint_peaks), {})
    out.update({f"{j}_peak": "force" for j in joints})
    return out


def _known(study, name: str, label: str) -> str:
    if name not in figures(study):
        raise GraphkinError(f"{label} {name!r}: no such figure of merit; the study has {', '.join(figures(study))}")
    return name


def figure_values(study, name: str, label: str = "figure") -> np.ndarray:
    """One figure of merit of every design, in SI units, in the order of the designs (nan where a design cannot
    be assembled or the figure is not defined).

    Raises
    ------
    GraphkinError
        If the study has no such figure, naming it and those it has.
    """
    _known(study, name, label)
    if name in _FIXED:
        return np.array([getattr(d, name) for d in study.designs], float)
    joint = name.removesuffix("_peak")
    return np.array([d.joint_peaks.get(joint, math.nan) for d in study.designs], float)


class Requirement(NamedTuple):
    """A limit a chosen design must meet: ``figure op bound``, the bound in SI units, as the user wrote it."""

    figure: str
    op: str
    bound: float
    text: str

    def met(self, study) -> np.ndarray:
        """True for each design whose figure meets the limit (False where it is nan)."""
        with np.errstate(invalid="ignore"):
            return _COMPARE[self.op](figure_values(study, self.figure), self.bound)


def requirement(study, text: str, label: str = "require") -> Requirement:
    """A limit read from ``"FIGURE OP VALUE UNIT"``, e.g. ``"transmission_angle_min >= 40 deg"``.

    Parameters
    ----------
    study : Study
        The study whose figures the limit names.
    text : str
        The limit; OP is one of ``<=``, ``>=``, ``<``, ``>``; VALUE must be in units of the figure's dimension.
    label : str
        What messages call the limit (``"--require"`` on the command line).

    Raises
    ------
    GraphkinError
        One line naming the limit and what is wrong with it: its form, its figure or its value's unit.
    """
    m = _REQUIREMENT.fullmatch(text) if isinstance(text, str) else None
    if m is None:
        raise GraphkinError(f"{label} {text!r}: write it FIGURE OP VALUE UNIT, e.g. "
                            "\"transmission_angle_min >= 40 deg\" (OP one of <=, >=, <, >)")
    name = _known(study, m["name"], f"{label} {text!r}:")
    try:
        bound = to_si(m["value"], figures(study)[name], field=name, file=label)
    except ProblemFileError as exc:  # the unit's fault, said once, under the limit's name
        raise GraphkinError(f"{label} {text!r}: {str(exc).split(': ', 2)[-1]}") from None
    return Requirement(name, m["op"], bound, text.strip())


class Choice(NamedTuple):
    """The best design of a study: the one with the least ``minimise`` among those that meet ``require``.

    ``index`` is its place in :attr:`Study.designs` (None if no design qualifies, and ``why`` says so).
    """

    minimise: str
    require: tuple
    index: int | None
    why: str | None


def best(study, minimise: str, require=(), *, label: str = "best") -> Choice:
    """The design with the least value of one figure of merit among those that meet every limit.

    Parameters
    ----------
    study : Study
        The designs.
    minimise : str
        A figure's name (:func:`figures`), e.g. ``"torque_peak"``.
    require : iterable of str or Requirement
        Limits every candidate must meet, e.g. ``["transmission_angle_min >= 40 deg"]`` (:func:`requirement`).
    label : str
        What messages call ``minimise`` (``"--best"`` on the command line).

    Returns
    -------
    Choice
        The first of equal least designs (in the grid's order); none if no design that assembles meets the limits.

    Examples
    --------
    >>> from graphkin.cycle import study
    >>> s = study("strip_cutter", {"links[1].mass": ["2 kg", "3 kg", "4 kg"]}, n=36)
    >>> best(s, "torque_peak", ["transmission_angle_min >= 20 deg"]).index
    0
    """
    _known(study, minimise, label)
    limits = tuple(r if isinstance(r, Requirement) else requirement(study, r) for r in require)
    ok = np.array([d.ok for d in study.designs], bool)
    for r in limits:
        ok &= r.met(study)
    x = np.where(ok, figure_values(study, minimise), np.nan)
    if np.isnan(x).all():
        meets = f" meets {' and '.join(r.text for r in limits)} and" if limits else ""
        why = f"no design that assembles over its cycle{meets} has a {minimise}"
        return Choice(minimise, limits, None, why)
    return Choice(minimise, limits, int(np.nanargmin(x)), None)


def field_axis(values) -> tuple[str, np.ndarray] | None:
    """A varied field's values as numbers in the unit they are written in: ``(unit, numbers)``; None if they are
    not all numbers with one unit (points, tables: drawn and written as the file writes them).

    >>> field_axis(["60.0 mm", "80.0 mm"])
    ('mm', array([60., 80.]))
    """
    units, numbers = set(), []
    for v in values:
        m = _NUMBER.fullmatch(v) if isinstance(v, str) else None
        if m is not None:
            units.add(m["unit"])
            numbers.append(float(m["x"]))
        elif isinstance(v, (int, float)) and not isinstance(v, bool):
            units.add("")
            numbers.append(float(v))
        else:
            return None
    return (units.pop(), np.array(numbers)) if len(units) == 1 else None
