"""Textbook problems as data: TOML problem files shipped with graphkin, each citing its source."""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.problem import load_problem

DEFAULT = "double_slider"
"""The example ``make demo`` solves."""


FAMILIES = {
    "double_slider": "double slider (PRRP), driven by a slider",
    "engine_gas_force": "slider-crank engine with a gas force",
    "engine_balancing": "single-cylinder engine, no gas load, a counterweight on the crank (balancing)",
    "engine_double_acting_khurmi": "double-acting steam engine: pressures on both faces and a piston rod, clockwise, "
                                   "with a flywheel's forward step",
    "engine_static_khurmi": "slider-crank, static: a gas force (with friction and a given inertia) on the piston",
    "gearset": "spur gear pair",
    "diesel_vertical_khurmi": "vertical diesel engine: gas and back pressure, weight of the reciprocating parts",
    "engine_inch_bevan": "steam engine in inch-pound units, static: pressures on both faces round a piston rod",
    "engine_vertical_khurmi": "vertical double-acting steam engine with a piston rod and the weight of its parts",
    "epicyclic_khurmi": "epicyclic train: sun driven, annulus held, arm the output (holding torque)",
    "fourbar_dynamic_makdin": "four-bar, dynamic, matrix method with the book's accelerations",
    "fourbar_two_loads_makdin": "four-bar, static, two external loads: graphical superposition",
    "gas_engine_khurmi": "gas engine: gudgeon-pin load and side thrust at speed",
    "petrol_vertical_khurmi": "vertical petrol engine: net force on the piston with its weight",
    "slider_crank_dynamic_makdin": "slider-crank, dynamic, matrix method with the book's accelerations and a gas load",
    "slider_crank_static_makdin": "slider-crank, static: the crank torque holding a piston load; driven by the piston too",
    "spring_link_hibbeler": "double slider, static, held by a spring and its weight: the equilibrium angle",
    "spur_pair_wentzell": "spur gear pair in inch-pound units: a power at a speed",
    "shaper_six_bar": "six-bar quick-return: crank, block on a slotted lever, ram (R-RTR-RRT), with gravity",
    "single_link": "single link (a crank alone)",
    "slider_crank_friction": "offset slider-crank with slider friction",
    "strip_cutter": "four-bar with a cutting load",
    "strip_cutter_study": "four-bar with a cutting load: a design study of its crank and coupler ([study])",
    "vertical_engine_sarkar": "vertical engine at speed, short rod (l = 4 r): the effective turning moment, weight "
                              "included",
    "vertical_engine_gudgeon_expertsmind": "vertical engine at speed: gudgeon-pin load and cylinder-wall thrust, weight "
                                           "included",
}
"""Each catalog problem's family of mechanism, as ``graphkin list`` shows it."""


def family(name: str) -> str:
    """The family of a catalog problem (:data:`FAMILIES`), e.g. ``"spur gear pair"``."""
    if name not in names():
        raise GraphkinError(f"no catalog problem {name!r} (the catalog has: {', '.join(names())})")
    if name not in FAMILIES:
        raise GraphkinError(f"catalog problem {name!r} has no family: add it to graphkin.catalog.FAMILIES")
    return FAMILIES[name]


def names() -> list[str]:
    """Names of the catalog problems, sorted."""
    return sorted(p.name[:-5] for p in resources.files(__name__).iterdir() if p.name.endswith(".toml"))


def path(name: str) -> Path:
    """Path of a catalog problem file."""
    if name not in names():
        raise GraphkinError(f"no catalog problem {name!r} (the catalog has: {', '.join(names())})")
    return Path(str(resources.files(__name__).joinpath(name + ".toml")))


def flywheel_names() -> list[str]:
    """Names of the catalog's flywheel files (``graphkin flywheel NAME``), sorted."""
    return sorted(p.name[:-5] for p in resources.files(__name__).joinpath("flywheels").iterdir()
                  if p.name.endswith(".toml"))


def flywheel_path(name: str) -> Path:
    """Path of a catalog flywheel file."""
    if name not in flywheel_names():
        raise GraphkinError(f"no catalog flywheel {name!r} (the catalog has: {', '.join(flywheel_names())})")
    return Path(str(resources.files(__name__).joinpath("flywheels", name + ".toml")))


def load(name_or_path: str):
    """A :class:`graphkin.problem.Problem` from a catalog name or a file path.

    Parameters
    ----------
    name_or_path : str or Path
        A catalog name (:func:`names`, ``graphkin list``) or a problem file.

    Returns
    -------
    Problem
        The problem, read from its TOML file.

    Examples
    --------
    >>> load("double_slider").title
    'Double slider with a heavy connecting rod'
    """
    if not isinstance(name_or_path, (str, Path)):
        raise GraphkinError(f"catalog.load takes a catalog name ({', '.join(names())}) or a file path, "
                            f"got {type(name_or_path).__name__} {name_or_path!r}")
    name_or_path = str(name_or_path)
    if name_or_path in names():
        return load_problem(path(name_or_path), name=name_or_path)
    p = Path(name_or_path)
    if p.suffix == ".toml" or p.exists():
        return load_problem(p)
    raise GraphkinError(f"{name_or_path!r} is neither a catalog problem ({', '.join(names())}) nor a file")
