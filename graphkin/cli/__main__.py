"""``python -m graphkin.cli``: the ``graphkin`` command (as ``python -m graphkin``)."""

import sys

from graphkin.cli import main

sys.exit(main())
