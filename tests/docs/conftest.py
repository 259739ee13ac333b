"""The documentation site's own modules (docs/offline.py, docs/lesson_cache.py) are imported as Sphinx imports
them: from the docs folder, which is not a package."""

from __future__ import annotations

import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parents[2] / "docs"
if str(DOCS) not in sys.path:
    sys.path.insert(0, str(DOCS))
