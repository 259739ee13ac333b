"""``python -m graphkin``: the ``graphkin`` command."""

from graphkin.cli import command

command()
