"""graphkin: kinetostatics of planar machinery, analytically and graphically.

Importing graphkin loads numpy only; matplotlib, ipywidgets and pint are loaded
by the layers that need them (drawing, widgets, problem files and the CLI).
"""

__version__ = "0.1.0"
