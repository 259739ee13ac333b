"""The units a report is printed in: SI (as graphkin always printed), US (the inch-pound books), or a file's.

``graphkin solve``, ``cycle``, ``flywheel`` and ``handout`` take ``--units SI|US|FILE``. A
:class:`UnitSystem` says, for each kind of quantity, which unit a report shows it in and the factor from SI:

=====================  ===============  ===============  ==============================================
kind                   SI               US               why the US unit
=====================  ===============  ===============  ==============================================
length                 mm               in               drawings and bores in inches
angle                  deg              deg              books print degrees in both systems
force                  N                lbf              pound-force ("lb" in the books)
torque                 N·m              lbf·ft           "lb ft", as Bevan prints a crankshaft torque
angular_velocity       rad/s            rpm              shaft speeds are given in rpm
angular_acceleration   rad/s²           rad/s²           no other unit is in use
velocity               m/s              ft/s
acceleration           m/s²             ft/s²
mass                   kg               lb               pound-mass
moment_of_inertia      kg·m²            lb·ft²
energy                 J                ft·lbf
power                  W                hp
pressure               MPa              psi              N/mm² and lb/in², as indicator diagrams
stiffness              N/mm             lbf/in
=====================  ===============  ===============  ==============================================

A units file (TOML) names a unit per kind, starting from SI or from ``base = "US"``::

    base = "US"
    torque = "lbf*in"      # Wentzell prints torques in lb·in

Converting takes pint (through :func:`graphkin.units.to_si`, whose disk cache usually answers without it), and
only when a report is asked for in another system's units: ``import graphkin`` still loads no pint.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Mapping

from graphkin.errors import GraphkinError, ProblemFileError
from graphkin.files import read_text
from graphkin.units.convert import to_si
from graphkin.units.registries import registry

KINDS: dict[str, str] = {
    "length": "length", "angle": "angle", "force": "force", "torque": "torque",
    "angular_velocity": "angular_velocity", "angular_acceleration": "angular_acceleration",
    "velocity": "velocity", "acceleration": "acceleration", "mass": "mass",
    "moment_of_inertia": "moment_of_inertia", "energy": "energy", "power": "power", "pressure": "pressure",
    "stiffness": "stiffness",
}
"""The kinds of quantity a report prints, each with its dimension (a key of :data:`graphkin.units.DIMENSIONS`)."""


# Unit (pint spelling), symbol as printed, and the number of display units in one SI unit. SI's factors are
# written exactly, so that a report in SI prints the digits it always printed.
_SI: dict[str, tuple[str, str, float]] = {
    "length": ("mm", "mm", 1e3), "angle": ("deg", "°", 180 / math.pi), "force": ("N", "N", 1.0),
    "torque": ("N*m", "N·m", 1.0), "angular_velocity": ("rad/s", "rad/s", 1.0),
    "angular_acceleration": ("rad/s^2", "rad/s²", 1.0), "velocity": ("m/s", "m/s", 1.0),
    "acceleration": ("m/s^2", "m/s²", 1.0), "mass": ("kg", "kg", 1.0), "moment_of_inertia": ("kg*m^2", "kg·m²", 1.0),
    "energy": ("J", "J", 1.0), "power": ("W", "W", 1.0), "pressure": ("MPa", "MPa", 1e-6),
    "stiffness": ("N/mm", "N/mm", 1e-3),
}

_US: dict[str, tuple[str, str]] = {
    "length": ("in", "in"), "angle": ("deg", "°"), "force": ("lbf", "lbf"), "torque": ("lbf*ft", "lbf·ft"),
    "angular_velocity": ("rpm", "rpm"), "angular_acceleration": ("rad/s^2", "rad/s²"), "velocity": ("ft/s", "ft/s"),
    "acceleration": ("ft/s^2", "ft/s²"), "mass": ("lb", "lb"), "moment_of_inertia": ("lb*ft^2", "lb·ft²"),
    "energy": ("ft*lbf", "ft·lbf"), "power": ("hp", "hp"), "pressure": ("psi", "psi"), "stiffness": ("lbf/in", "lbf/in"),
}


@dataclass(frozen=True)
class UnitSystem:
    """The unit each kind of quantity is shown in, with its symbol and its factor from SI.

    Parameters
    ----------
    name : str
        ``"SI"``, ``"US"`` or the units file's path.
    units : mapping of str to str
        Kind (a key of :data:`KINDS`) -> unit in pint spelling (``"lbf*ft"``), as the JSON states it.
    symbols : mapping of str to str
        Kind -> unit as a report prints it (``"lbf·ft"``).
    scales : mapping of str to float
        Kind -> display units per SI unit: ``shown = scales[kind] * si``.
    """

    name: str
    units: Mapping[str, str] = field(repr=False)
    symbols: Mapping[str, str] = field(repr=False)
    scales: Mapping[str, float] = field(repr=False)

    def show(self, x: float, kind: str) -> float:
        """An SI value (a float or an array) in this system's unit of ``kind``."""
        return self.scales[kind] * x

    def si(self, x: float, kind: str) -> float:
        """A value in this system's unit of ``kind`` back in SI."""
        return x / self.scales[kind]

    def symbol(self, kind: str) -> str:
        """How a report prints the unit of ``kind`` (``"lbf·ft"``)."""
        return self.symbols[kind]

    @property
    def is_si(self) -> bool:
        """True for the SI system graphkin's reports always used."""
        return self.name == "SI"


def _system(name: str, table: Mapping[str, tuple[str, str, float]]) -> UnitSystem:
    return UnitSystem(name, MappingProxyType({k: v[0] for k, v in table.items()}),
                      MappingProxyType({k: v[1] for k, v in table.items()}),
                      MappingProxyType({k: v[2] for k, v in table.items()}))


SI = _system("SI", _SI)
"""Reports as graphkin always printed them: mm, degrees, N, N·m, rad/s."""


def _scale(unit: str, kind: str, file: str, where: str) -> float:
    """Display units per SI unit of ``unit``, checked as a unit of ``kind`` (the message names ``where``)."""
    if not isinstance(unit, str) or not unit.strip():
        raise ProblemFileError(file, where, f"expected a unit such as \"{_US[kind][0]}\", got {unit!r}")
    if unit.strip()[:1].isdigit() or unit.strip()[:1] in "+-.":
        raise ProblemFileError(file, where, f"give the unit only, without a number: e.g. \"{_US[kind][0]}\"")
    unit = unit.strip()
    try:
        return 1.0 / to_si(f"1 {unit}", KINDS[kind], field=where, file=file)
    except ProblemFileError as exc:  # the message quotes the value "1 lbf" it converted: say "lbf", as written
        message = exc.message.replace(f' in "1 {unit}"', "").replace(f'"1 {unit}"', f'"{unit}"')
        raise ProblemFileError(file, where, message) from None


def _us() -> UnitSystem:
    return _system("US", {k: (u, s, _scale(u, k, "US", k)) for k, (u, s) in _US.items()})


def _symbol(unit: str) -> str:
    return format(registry().parse_units(unit), "~P")


def read_units(path: str | Path) -> UnitSystem:
    """A units file (TOML): a unit per kind of quantity, over ``base = "SI"`` (default) or ``"US"``.

    Parameters
    ----------
    path : str or Path
        The file, e.g. ``torque = "lbf*in"`` and ``base = "US"``.

    Returns
    -------
    UnitSystem

    Raises
    ------
    graphkin.errors.GraphkinError
        A file that cannot be read or is not TOML, an unknown kind or base, a unit that is unknown or of another
        dimension than its kind: one line naming the file and the field.
    """
    file = str(path)
    try:
        data = tomllib.loads(read_text(path, "--units"))
    except tomllib.TOMLDecodeError as exc:
        raise ProblemFileError(file, "", f"is not valid TOML ({exc})") from None
    base = data.pop("base", "SI")
    if base not in ("SI", "US"):
        raise ProblemFileError(file, "base", f'the base is "SI" or "US", got {base!r}')
    unknown = sorted(k for k in data if k not in KINDS)
    if unknown:
        raise ProblemFileError(file, unknown[0], f"not a kind of quantity; the kinds are {', '.join(KINDS)}")
    start = SI if base == "SI" else _us()
    units, symbols, scales = dict(start.units), dict(start.symbols), dict(start.scales)
    for kind, unit in data.items():
        scales[kind] = _scale(unit, kind, file, kind)
        units[kind], symbols[kind] = unit.strip(), _symbol(unit.strip())
    return UnitSystem(file, MappingProxyType(units), MappingProxyType(symbols), MappingProxyType(scales))


def unit_system(text: str | None) -> UnitSystem | None:
    """``--units`` as a :class:`UnitSystem`: ``"SI"``, ``"US"`` (any case) or a units file's path; None for None.

    Raises
    ------
    graphkin.errors.GraphkinError
        Neither SI, US nor a file that exists; or a bad units file (:func:`read_units`).
    """
    if text is None:
        return None
    if text.upper() == "SI":
        return SI
    if text.upper() == "US":
        return _us()
    if not Path(text).is_file():
        raise GraphkinError(f"--units {text!r}: give SI, US or a units file (TOML, e.g. torque = \"lbf*in\"); "
                            "no such file")
    return read_units(text)
