"""The exceptions graphkin raises for malformed input.

Only malformed input raises. A position that cannot be assembled, or a dead
point, is not an error: results carry ``nan`` there and a ``valid`` mask, and
reports name the position (see :mod:`graphkin.kinematics`).
"""

from __future__ import annotations


class GraphkinError(ValueError):
    """Base class: a one-line message a student can act on."""


class GraphkinWarning(UserWarning):
    """Input that is accepted but unusual enough to say so (a friction coefficient above 1, ...).

    The command line prints each as one line, ``graphkin: warning: ...``.
    """


class ModelError(GraphkinError):
    """The mechanism as described cannot be built (unknown link, zero length, ...).

    Parameters
    ----------
    message : str
        What is wrong, in words.
    at : tuple, optional
        Where in the :class:`graphkin.model.Mechanism` the fault lies, e.g.
        ``("joints", 2, "point")`` for the point of its third joint or
        ``("links", 1, "number")``; the problem-file reader turns it into the
        field path of the file (``joints[2].point``). Empty when unknown.
    """

    def __init__(self, message: str, at: tuple = ()):
        self.at = tuple(at)
        super().__init__(message)


class ProblemFileError(GraphkinError):
    """A problem file is malformed; the message names the file and the field.

    Parameters
    ----------
    file : str
        Path or catalog name of the problem file.
    field : str
        Dotted path of the field at fault, e.g. ``"links[2].mass"``; empty
        when the whole file is at fault (bad TOML).
    message : str
        What is wrong, in words.
    """

    def __init__(self, file: str, field: str, message: str):
        self.file = file
        self.field = field
        self.message = message
        where = f"{file}: {field}: " if field else f"{file}: "
        super().__init__(where + message)
