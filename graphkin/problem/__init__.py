"""Problems as books state them: a mechanism, its input motion and loads, read from TOML files with units.

==========================  ===========================================================
:mod:`.problem`             :class:`Problem`: a mechanism with its input motion, to solve
:mod:`.file`                :func:`load_problem`, :func:`parse_problem`, :func:`build_problem`
:mod:`.reader`              :class:`FieldReader`: fields to SI, errors naming file and field
:mod:`.fields`              a field by its path (``links[1].mass``): read, found, set
:mod:`.tables`              tables against the input (a torque curve), inline or in a CSV
:mod:`.books`               pressures, powers, dead centres, a slider placed by an angle, ``[forward]``
:mod:`.placement`           where a link stands at an angle as the slider moves (``driver.place``)
:mod:`.shared`              parts read once per equal table, and the mechanism made of them
==========================  ===========================================================

The format is documented field by field in ``docs/problem-files.md``.
"""

from graphkin.problem.file import build_problem, load_problem, parse_problem
from graphkin.problem.problem import Forward, Problem
from graphkin.problem.reader import FieldReader

__all__ = ["FieldReader", "Forward", "Problem", "build_problem", "load_problem", "parse_problem"]
