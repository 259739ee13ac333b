"""Settings for the whole test session.

graphkin keeps caches in the user's cache folder (pint's parsed registry,
the unit factors pint has given: :func:`graphkin.units.cache_folder`). A test
run keeps its own in a temporary folder, removed at the end, so the suite
neither reads what an earlier run left nor writes into the user's home.
"""

from __future__ import annotations

import os
import shutil
import tempfile

_MADE: list[str] = []


def pytest_configure(config):
    if "GRAPHKIN_CACHE_DIR" not in os.environ:
        _MADE.append(tempfile.mkdtemp(prefix="graphkin-test-cache-"))
        os.environ["GRAPHKIN_CACHE_DIR"] = _MADE[-1]


def pytest_unconfigure(config):
    for folder in _MADE:
        shutil.rmtree(folder, ignore_errors=True)
        if os.environ.get("GRAPHKIN_CACHE_DIR") == folder:
            del os.environ["GRAPHKIN_CACHE_DIR"]
