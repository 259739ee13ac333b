"""The units boundary: problem-file strings in, SI floats out.

Problem files (TOML) write every dimensional value as a string with units,
e.g. ``"500 mm"``, ``"900 rpm"``, ``"7.6 deg"``, ``"-2000 N"``,
``"0.10417 kg*m^2"``, ``"865 N*mm"``. The rest of graphkin works in SI with
plain floats:

=====================  ==========  =====================================
dimension              SI unit     accepted, for example
=====================  ==========  =====================================
length                 m           mm, cm, m, in
angle                  rad         deg, rad, rev, turn
mass                   kg          g, kg, lb
time                   s           ms, s, min
velocity               m/s         m/s, mm/s, km/h
acceleration           m/s^2       m/s^2, mm/s^2
angular_velocity       rad/s       rpm, rad/s, deg/s, rev/min
angular_acceleration   rad/s^2     rad/s^2, deg/s^2, rpm/s
force                  N           N, kN
torque                 N*m         N*m, N*mm, kN*m
moment_of_inertia      kg*m^2      kg*m^2, kg*mm^2
energy                 J           J, kJ, N*m (exercise answers)
density                kg/m^3      kg/m^3, g/cm^3
dimensionless          (none)      0.3, "0.3", "30 percent"
=====================  ==========  =====================================

This package is the only place graphkin uses pint, and it imports pint lazily
inside functions: ``import graphkin.units`` does not load pint. The factor
pint converts each unit by is kept on disk once pint has found it
(:mod:`graphkin.units.registries`, in graphkin's cache folder), so reading a
problem file in units met before does not import pint at all; a new unit, and
every check that fails, goes through pint.

=========================  ============================================================
:mod:`.dimensions`         the dimensions, their SI units, examples for messages
:mod:`.registries`         the one pint registry and the disk caches
:mod:`.checks`             which units a dimension accepts, and the slips refused
:mod:`.convert`            :func:`to_si`, :func:`to_si_vector`, :func:`to_si_array`, :func:`written`
:mod:`.format`             :func:`format_si`
:mod:`.systems`            the units a report prints in (``--units SI|US|FILE``)
=========================  ============================================================

Rules (every violation raises :class:`graphkin.errors.ProblemFileError`
naming the file and the field):

* A string is a number followed by units (``"500 mm"``, ``"500mm"``); only
  ``"dimensionless"`` accepts a bare number (``0.3`` or ``"0.3"``).
  ``"angle"`` accepts no bare number either: ``7.6`` could be degrees or
  radians.
* Angular quantities must name an angle unit: ``"5 Hz"`` or ``"5 1/s"`` is
  rejected for an angular velocity (revolutions or radians per second?), and
  an angle unit is rejected where no angle is expected (``"5 deg"`` for a
  friction coefficient).
* ``"Nm"``, ``"kNm"``, ``"Nmm"`` are rejected (pint would read ``Nm`` as a
  nanometre-like unit): write ``"N*m"``, ``"kN*m"``, ``"N*mm"``.
* Energy and power units (J, kJ, cal, Wh, W*s, ...) are rejected for a
  torque, although pint finds them dimensionally equal: torque is written in
  N*m.
* ``nan`` and ``inf`` are rejected, and so are values that overflow when
  converted to SI.
* Booleans, ``None``, tables and lists are rejected where a scalar is
  expected; the message names the Python type.

Offset units (degC, degF) are not supported.
"""

from graphkin.units.convert import Written, to_si, to_si_array, to_si_vector, written
from graphkin.units.dimensions import DIMENSIONS, SI_UNITS
from graphkin.units.format import format_si
from graphkin.units.registries import cache_folder, registry

__all__ = ["DIMENSIONS", "SI_UNITS", "Written", "cache_folder", "format_si", "registry", "to_si", "to_si_array",
           "to_si_vector", "written"]
