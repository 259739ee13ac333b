"""The parts of graphkin that need an extra, and the one line that says which to install.

graphkin's core (the command line, figures, handouts and grading) needs only
its dependencies; the notebook widgets, the explorer's web page and the
notebook platforms' exports need packages a grader or a command-line user
never installs. Each is imported through :func:`require`, which turns a
missing package into one line naming the extra.

======================  ==============  ===========================================
package                 extra           for
======================  ==============  ===========================================
ipywidgets, anywidget,  ``notebook``    the explorer and the exercise box
IPython
voila                   ``explore``     ``graphkin explore``
nbformat                ``platforms``   ``graphkin exercise export --to otter|nbgrader``
scipy                   ``study``       a design study's optimum (``graphkin study --optimize``)
======================  ==============  ===========================================
"""

from __future__ import annotations

import importlib
import importlib.util

from graphkin.errors import GraphkinError

EXTRAS = {"ipywidgets": "notebook", "anywidget": "notebook", "traitlets": "notebook", "IPython": "notebook",
          "voila": "explore", "nbformat": "platforms",
          "scipy": "study"}
"""The extra (``pip install 'graphkin[EXTRA]'``) that installs each optional package."""


def missing(package: str, what: str) -> GraphkinError:
    """The error for an optional package that is not installed: one line naming the extra to install.

    Parameters
    ----------
    package : str
        The package's import name (a key of :data:`EXTRAS`).
    what : str
        What needs it, for people ("the explorer", "graphkin explore").

    Returns
    -------
    GraphkinError
    """
    return GraphkinError(f"{what} needs {package}, which is not installed: pip install 'graphkin[{EXTRAS[package]}]'")


def require(module: str, what: str):
    """Import an optional module, or raise :func:`missing`'s one-line error.

    Parameters
    ----------
    module : str
        The module to import (``"ipywidgets"``, ``"IPython.display"``).
    what : str
        What needs it, for people.

    Returns
    -------
    module

    Raises
    ------
    GraphkinError
        If the package is not installed.
    """
    package = module.split(".")[0]
    try:
        return importlib.import_module(module)
    except ModuleNotFoundError as exc:
        if exc.name is not None and exc.name.split(".")[0] != package:
            raise  # the package is there but one of its own imports is broken: the original error says which
        raise missing(package, what) from None


def available(package: str) -> bool:
    """Whether an optional package is installed (without importing it)."""
    return importlib.util.find_spec(package) is not None
