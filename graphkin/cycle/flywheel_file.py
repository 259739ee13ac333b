"""Flywheel problems: a turning-moment diagram without a mechanism, written in TOML with units.

The format is documented in ``docs/problem-files.md`` ("Flywheel files"); in short::

    title = "Four-cylinder four-stroke engine"
    source = "book, example"

    [flywheel]
    omega_avg = "1800 rpm"
    Cs = 0.01                  # or I = "0.25 kg*m^2": then C_s is found
    period = "720 deg"         # one cycle; default one turn

    [driving]                  # engine torque against crank angle
    csv = "cylinder.csv"       # beside this file; or table = \"\"\"angle [deg], torque [N*m] ...\"\"\"
    cylinders = 4              # the table is one cylinder's torque: the sum of 4 copies,
    phase = "180 deg"          # each fired 180° after the one before (default: period / cylinders)

    [resisting]
    torque = "mean"            # or a constant "95 N*m", or a table or csv of its own

This is the boundary where textbook units become SI: every error names the
file and the field (``flywheel.omega_avg``, ``driving.table``), and the CLI
exits with code 2.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Mapping

import numpy as np

from graphkin.cycle.flywheel import size_flywheel
from graphkin.errors import GraphkinError, ProblemFileError
from graphkin.files import read_text
from graphkin.problem import FieldReader
from graphkin.problem.tables import parse_table, read_csv_beside

_TOP = {"title", "source", "notes", "flywheel", "driving", "resisting"}
_FLYWHEEL = {"omega_avg", "Cs", "I", "period"}
_TORQUE = {"table", "csv", "decimal", "torque", "cylinders", "phase"}
_COLUMNS = {"angle": "angle", "torque": "torque"}


@dataclass(frozen=True)
class FlywheelProblem:
    """A turning-moment diagram with its speed and what to find, as read from a flywheel file.

    Attributes
    ----------
    name : str
        The file's path (or the name given).
    theta : ndarray, shape (n,)
        Shaft angles [rad] of one cycle, increasing: every angle of either table
        (and of each cylinder's shifted copy), so that the piecewise-linear
        curves are exact between samples.
    driving, resisting : ndarray, shape (n,), float or "mean"
        The torques [N·m] at ``theta``: a curve, a constant, or ``"mean"``.
    omega_avg : float
        Average shaft speed [rad/s].
    Cs, I : float or None
        The coefficient of speed fluctuation or the system inertia [kg·m²]:
        one is given, the other is found.
    period : float
        One cycle [rad].
    driving_text, resisting_text : str
        Each torque in words, for reports.
    title, source, notes : str
    """

    name: str
    theta: np.ndarray
    driving: Any
    resisting: Any
    omega_avg: float
    Cs: float | None
    I: float | None
    period: float
    driving_text: str = ""
    resisting_text: str = ""
    title: str = ""
    source: str = ""
    notes: str = ""

    def size(self):
        """The flywheel (:func:`graphkin.cycle.size_flywheel`): I_s from C_s, or C_s from I."""
        return size_flywheel(self.theta, driving=self.driving, resisting=self.resisting, omega_avg=self.omega_avg,
                             Cs=self.Cs, I=self.I, period=self.period)


def load_flywheel(source: str | Path, *, name: str | None = None) -> FlywheelProblem:
    """Read a flywheel file (TOML); a ``csv`` it names is read from the same folder.

    Parameters
    ----------
    source : str or Path
        The file.
    name : str, optional
        The name messages and reports show (default: the path).

    Returns
    -------
    FlywheelProblem
        The turning-moment diagram, its speed and what to find, in SI units.

    Raises
    ------
    ProblemFileError
        With the file, the field and what is wrong.
    """
    if not isinstance(source, (str, Path)) or not str(source):
        raise GraphkinError(f"load_flywheel takes the path of a flywheel file (a str or Path), got "
                            f"{type(source).__name__} {source!r}")
    path = Path(source)
    file = name or str(path)
    text = read_text(path, "flywheel", shown=file)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ProblemFileError(file, "", f"is not valid TOML ({exc})") from None
    return build_flywheel(data, file=file, base=path)


def parse_flywheel(text: str, *, file: str = "<flywheel>", base: str | Path = ".") -> FlywheelProblem:
    """Build a :class:`FlywheelProblem` from TOML text (``base``: a path in the folder a ``csv`` is read from)."""
    if not isinstance(text, str):
        raise GraphkinError(f"parse_flywheel takes the file's text as a str, got {type(text).__name__}")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ProblemFileError(file, "", f"is not valid TOML ({exc})") from None
    return build_flywheel(data, file=file, base=Path(base) / "_" if Path(base).is_dir() else base)


def build_flywheel(data: Mapping[str, Any], *, file: str = "<flywheel>", base: str | Path = ".") -> FlywheelProblem:
    """Build a :class:`FlywheelProblem` from a flywheel file's tables already read into a dict."""
    rd = FieldReader(file)
    if not isinstance(data, Mapping):
        raise GraphkinError(f"build_flywheel takes a flywheel file's tables as a dict, got {type(data).__name__}")
    rd.table(dict(data), "", _TOP)
    fw = rd.table(rd.need(data, "flywheel", ""), "flywheel", _FLYWHEEL)
    omega = rd.si(rd.need(fw, "omega_avg", "flywheel"), "angular_velocity", "flywheel.omega_avg")
    if omega <= 0:
        raise rd.fail("flywheel.omega_avg", f"must be > 0 (the shaft turning CCW at its average speed), got "
                      f"{fw['omega_avg']!r}")
    if ("Cs" in fw) == ("I" in fw):
        raise rd.fail("flywheel.Cs" if "Cs" not in fw else "flywheel.I",
                      "give exactly one of Cs (to find the inertia) and I (to find the speed fluctuation)"
                      if "Cs" not in fw else "give either Cs or I, not both: the other one is found")
    Cs = I = None
    if "Cs" in fw:
        Cs = rd.si(fw["Cs"], "dimensionless", "flywheel.Cs", None)
        if not 0 < Cs < 2:
            raise rd.fail("flywheel.Cs", f"the coefficient of speed fluctuation (ω_max − ω_min)/ω_avg must lie between 0 "
                          f"and 2 (machines use 0.002 to 0.2), got {fw['Cs']!r}")
    else:
        I = rd.si(fw["I"], "moment_of_inertia", "flywheel.I")
        if I <= 0:
            raise rd.fail("flywheel.I", f"must be > 0, got {fw['I']!r}")
    period = rd.si(fw.get("period", "360 deg"), "angle", "flywheel.period")
    if not math.isclose(period, 2 * math.pi, rel_tol=1e-9) and not math.isclose(period, 4 * math.pi, rel_tol=1e-9):
        raise rd.fail("flywheel.period", f"one cycle is one turn (\"360 deg\") or, for a four-stroke engine, two "
                      f"(\"720 deg\"), got {fw['period']!r}")
    curves, constants, texts = {}, {}, {}
    for role in ("driving", "resisting"):
        t = rd.table(data.get(role, {"torque": "mean"}), role, _TORQUE)
        curves[role], constants[role], texts[role] = _torque(rd, t, role, period, base)
    if curves["driving"] is None and curves["resisting"] is None:
        named = "driving" if "driving" in data else "resisting"
        raise rd.fail(named, "one of the torques must vary with the angle: give [driving] (or [resisting]) a table "
                      "or a csv")
    theta = _grid([c for c in curves.values() if c is not None], period)
    values = {}
    for role in ("driving", "resisting"):
        if curves[role] is not None:
            x, y = curves[role]
            values[role] = np.interp(theta, x, y, period=period)
        else:
            values[role] = constants[role]
    title = str(data.get("title", ""))
    problem = FlywheelProblem(file, theta, values["driving"], values["resisting"], omega, Cs, I, period,
                              texts["driving"], texts["resisting"], title, str(data.get("source", "")),
                              str(data.get("notes", "")))
    try:
        problem.size()
    except GraphkinError as exc:
        # What the torques together make impossible (unequal means, an inertia too small): named by its field.
        head, _, rest = str(exc).partition(": ")
        field = {"resisting": "resisting", "I": "flywheel.I"}.get(head)
        raise rd.fail(field or "flywheel", rest if field else str(exc)) from None
    return problem


def _torque(rd: FieldReader, t: dict, role: str, period: float, base):
    """(curve (angles, torques) or None, constant or "mean" or None, words) of one ``[driving]``/``[resisting]`` table."""
    sources = [k for k in ("table", "csv", "torque") if k in t]
    decimal = rd.decimal(t, role)
    if len(sources) != 1:
        raise rd.fail(f"{role}.{sources[1]}" if sources else role,
                      "give exactly one of table (inline), csv (a file beside this one) and torque (a constant or "
                      "\"mean\")" if not sources else f"give only one of {', '.join(sources)}")
    if "torque" in t:
        for key in ("cylinders", "phase"):
            if key in t:
                raise rd.fail(f"{role}.{key}", "is for a torque curve (table or csv), not a constant torque")
        value = t["torque"]
        if value == "mean":
            return None, "mean", "constant, the mean of the other torque"
        x = rd.si(value, "torque", f"{role}.torque")
        return None, x, f"constant, {x:.6g} N·m"

    if "table" in t:
        text, shown, where = rd.text(t["table"], f"{role}.table"), None, f"{role}.table"
    else:
        text, shown = read_csv_beside(t["csv"], base, file=rd.file, field=f"{role}.csv")
        where = f"{role}.csv"
    cols = parse_table(text, _COLUMNS, file=rd.file, field=where, shown=shown, decimal=decimal)
    angle, torque = cols["angle"], cols["torque"]
    for k in range(len(torque)):
        rd.ranged(torque[k], f"{torque[k]:g} N·m", "torque", f"{where} (row {k + 1})")
        rd.ranged(angle[k], f"{angle[k]:g} rad", "angle", f"{where} (row {k + 1})")
    if not np.all(np.diff(angle) > 0):
        k = int(np.flatnonzero(np.diff(angle) <= 0)[0])
        raise rd.fail(where, f"the angles must increase from row to row: row {k + 2} ({math.degrees(angle[k + 1]):g}°) "
                      f"does not come after row {k + 1} ({math.degrees(angle[k]):g}°)")
    span = angle[-1] - angle[0]
    if span > period * (1 + 1e-9):
        raise rd.fail(where, f"the angles span {math.degrees(span):g}°, more than one cycle "
                      f"({math.degrees(period):g}°; set flywheel.period for a four-stroke engine)")
    if math.isclose(span, period, rel_tol=1e-9):
        # The last row repeats the first one cycle on: it must carry the same torque.
        if not math.isclose(torque[-1], torque[0], rel_tol=1e-9, abs_tol=1e-12 * max(np.abs(torque).max(), 1.0)):
            raise rd.fail(where, f"the last row ({math.degrees(angle[-1]):g}°) is the first one cycle on, but its torque "
                          f"{torque[-1]:g} N·m differs from the first's {torque[0]:g} N·m")
        angle, torque = angle[:-1], torque[:-1]
    elif span < period * (1 - 1e-9) and len(angle) > 1:
        gap = period - span
        if gap > np.max(np.diff(angle)) * (1 + 1e-9) + 1e-12:
            raise rd.fail(where, f"the angles cover {math.degrees(span):g}° of a {math.degrees(period):g}° cycle, "
                          f"leaving a gap of {math.degrees(gap):g}° wider than any step: give the whole cycle")
    words = f"a curve of {len(angle)} points" + (f" ({shown})" if shown else "")
    n = 1
    if "cylinders" in t:
        n = rd.whole(t["cylinders"], f"{role}.cylinders")
        if not 1 <= n <= 24:
            raise rd.fail(f"{role}.cylinders", f"must be a whole number from 1 to 24, got {n!r}")
    if "phase" in t and "cylinders" not in t:
        raise rd.fail(f"{role}.phase", "is the angle between successive cylinders' firings: give cylinders too")
    phase = rd.si(t.get("phase", f"{math.degrees(period) / n!r} deg"), "angle", f"{role}.phase")
    if n > 1:
        # An engine's torque is the sum of its cylinders', each the same curve fired a phase after the one before.
        x = np.unique(np.concatenate([(angle + k * phase - angle[0]) % period + angle[0] for k in range(n)]))
        y = sum(np.interp(x - k * phase, angle, torque, period=period) for k in range(n))
        angle, torque = x, y
        words += f", {n} cylinders fired {math.degrees(phase):g}° apart (their sum)"
    return (angle, torque), None, words


def _grid(curves, period: float) -> np.ndarray:
    """Every sample angle of the curves within one cycle from the first curve's first angle, ascending.

    Angles that differ by rounding only (1e-12 of the cycle: 180° written in degrees and π in radians) are one.
    """
    start = curves[0][0][0]
    x = np.sort(np.concatenate([(c[0] - start) % period + start for c in curves]))
    keep = np.append(True, np.diff(x) > 1e-12 * period)
    x = x[keep]
    return x[x < start + period * (1 - 1e-12)]
