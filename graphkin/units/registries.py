"""graphkin's one pint registry, and the disk caches that keep ``graphkin``'s start free of pint.

pint's parsed definitions are kept in graphkin's cache folder (:func:`cache_folder`),
so a registry builds in ~20 ms instead of ~130 ms; and the factor pint converts each
unit by is kept there too (:func:`known_factors`), so a file in units met before is
read without importing pint at all.
"""

from __future__ import annotations

import functools
import json
import math
import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

from graphkin.files import write_text
from graphkin.units.dimensions import DIMENSIONS, SI_UNITS

if TYPE_CHECKING:  # pragma: no cover
    import pint

# SI factor of each unit pint has converted, (unit text, dimension) -> factor, exactly the one pint
# multiplies by (pint converts a float x as x * factor: PlainRegistry._convert). Learned from pint on a
# unit's first use and kept on disk (:func:`_factors_path`), so that the next command reads a file written
# in units it has met before without importing pint (~0.2 s of its start), with the same numbers. A unit
# not met before, and every error message, goes through pint.
_FACTORS: dict[tuple[str, str], float] | None = None


@functools.cache
def registry() -> pint.UnitRegistry:
    """Return graphkin's one shared pint unit registry.

    The registry is created on first call (this is where pint is imported)
    and cached. Products of units print in the order written
    (``N·m``, not ``m·N``), and ``rev`` is defined as an alias of ``turn``.

    pint's parsed definitions are kept on disk (:func:`cache_folder`), which
    builds the registry in ~20 ms instead of ~130 ms from the second process
    on; without a usable cache folder it is built from pint's text files,
    with the same units and the same numbers.

    Returns
    -------
    pint.UnitRegistry
        The shared registry; use it for every quantity that must interact
        with graphkin's.
    """
    import pint

    ureg = _cached_registry(pint, cache_folder())
    ureg.formatter.default_sort_func = None
    ureg.define("@alias turn = rev")
    return ureg


def _pint_stamp() -> str | None:
    """pint's version and definition files as a short tag, found without importing pint (None: no pint)."""
    import importlib.util
    import zlib

    spec = importlib.util.find_spec("pint")
    if spec is None or not spec.origin:
        return None
    here = Path(spec.origin).parent
    times = [str(p.stat().st_mtime_ns) for p in sorted(here.glob("*.txt"))] + [str(Path(spec.origin).stat().st_mtime_ns)]
    return f"{zlib.crc32(' '.join(times).encode()):08x}"


def _factors_path() -> Path | None:
    """The file the learned unit factors are kept in (None: no cache folder)."""
    root = cache_folder()
    return None if root is None else root / "unit-factors.json"


def known_factors() -> dict[tuple[str, str], float]:
    """The unit factors pint has given before, read once per process from :func:`_factors_path`.

    A missing, unreadable or damaged file, or one written by another pint,
    is an empty table: every unit then goes through pint once more.
    """
    global _FACTORS
    if _FACTORS is None:
        _FACTORS = {}
        try:
            path = _factors_path()
            data = json.loads(path.read_text(encoding="utf-8")) if path is not None else {}
            if data.get("pint") == _pint_stamp():
                for unit, dimension, factor in data["factors"]:
                    if isinstance(unit, str) and dimension in DIMENSIONS and type(factor) is float \
                            and math.isfinite(factor) and factor > 0:
                        _FACTORS[(unit, dimension)] = factor
        except Exception:  # no cache yet, or a damaged one: pint answers, and the file is written again
            _FACTORS = {}
    return _FACTORS


def learn(ureg, unit, unit_text: str, dimension: str, x: float, si: float) -> None:
    """Keep pint's factor for ``unit_text`` (in memory, and on disk where it can be written).

    Only a factor that reproduces pint's own result for this value is kept
    (a multiplicative unit: pint converts x as x * factor); the file is
    written whole or not at all, and a folder that cannot be written is
    skipped without a word.
    """
    factor = float(ureg.Quantity(1.0, unit).m_as(SI_UNITS[dimension] or "dimensionless"))
    if not (math.isfinite(factor) and factor > 0 and x * factor == si):
        return
    factors = known_factors()
    if factors.get((unit_text, dimension)) == factor:
        return
    factors[(unit_text, dimension)] = factor
    try:
        path = _factors_path()
        if path is not None:
            path.parent.mkdir(parents=True, exist_ok=True)
            write_text(path, json.dumps({"pint": _pint_stamp(),
                                         "factors": sorted([u, d, f] for (u, d), f in factors.items())}))
    except Exception:  # a read-only home costs the time the cache would save, no more
        pass


def cache_folder() -> Path | None:
    """The folder for graphkin's caches, or None if caching is switched off.

    ``$GRAPHKIN_CACHE_DIR`` if set (an empty value switches the cache off),
    else the user cache folder of the platform (``~/.cache/graphkin`` on
    Linux, through platformdirs, which pint depends on). The folder need not
    exist or be writable: a cache that cannot be read or written is skipped.

    Returns
    -------
    pathlib.Path or None
    """
    env = os.environ.get("GRAPHKIN_CACHE_DIR")
    if env is not None:
        return Path(env).expanduser() if env.strip() else None
    try:
        import platformdirs

        return Path(platformdirs.user_cache_path("graphkin", appauthor=False))
    except Exception:  # no platformdirs, or no home folder to put a cache in: no cache
        return None


# The file naming a complete set of pint cache files: pint reads its cache
# only when this lists files that are all there, so it never finds a missing
# file and writes one itself (pint writes in place, where a second process
# could read half a file).
_PINT_MARKER = "complete.json"


def _cached_registry(pint: Any, root: Path | None) -> pint.UnitRegistry:
    """A pint registry, read from the disk cache under ``root`` when it can be.

    Parameters
    ----------
    pint : module
        The pint module (imported by the caller).
    root : pathlib.Path or None
        graphkin's cache folder (:func:`cache_folder`); None for no cache.

    Returns
    -------
    pint.UnitRegistry
        Built without its own disk cache (pint's ``_diskcache`` is None or
        points at the complete cache folder).

    Notes
    -----
    The cache of one pint version lives in ``root/pint-VERSION``. A missing,
    incomplete or unreadable cache is built again in a temporary folder
    beside it and each file moved into place with :func:`os.replace`, the
    list of files last; a reader sees the old files or the new ones, never
    half a file. If nothing can be written there (a read-only home), the
    registry is built from pint's text files, as without a cache.
    """
    if root is None:
        return pint.UnitRegistry()
    folder = root / f"pint-{pint.__version__}-{_definitions_stamp(pint)}"
    try:
        names = json.loads((folder / _PINT_MARKER).read_text(encoding="utf-8"))
        if names and all(isinstance(n, str) and (folder / n).is_file() for n in names):
            return pint.UnitRegistry(cache_folder=folder)
    except Exception:  # no cache yet, or a damaged one (pickle, json, a partial file): build it again
        pass
    try:
        return _publish_registry(pint, folder)
    except Exception:  # a cache folder that cannot be written costs the time the cache would save, no more
        return pint.UnitRegistry()


def _definitions_stamp(pint: Any) -> str:
    """A short tag of pint's definition files' modification times.

    pint takes a cache file older than its source for stale and rewrites it
    in place; a reinstalled pint gets a new folder instead.
    """
    import zlib

    here = Path(pint.__file__).parent
    times = [str(p.stat().st_mtime_ns) for p in sorted(here.glob("*.txt"))]
    return f"{zlib.crc32(' '.join(times).encode()):08x}"


def _publish_registry(pint: Any, folder: Path) -> pint.UnitRegistry:
    """Build pint's disk cache in a temporary folder, move it into ``folder``, and read it back."""
    import shutil
    import tempfile

    folder.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(dir=folder.parent, prefix=f".{folder.name}."))
    try:
        pint.UnitRegistry(cache_folder=tmp)
        names = sorted(p.name for p in tmp.iterdir())
        for name in names:
            os.replace(tmp / name, folder / name)
        write_text(folder / _PINT_MARKER, json.dumps(names))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return pint.UnitRegistry(cache_folder=folder)
