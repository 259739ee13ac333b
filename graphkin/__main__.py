"""``python -m graphkin``: the ``graphkin`` command."""

import sys

from graphkin.cli import main

sys.exit(main())
