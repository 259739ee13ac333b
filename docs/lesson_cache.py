"""The lessons run once per change, all cores at once, before Sphinx reads a page; their outputs kept in build/.

myst-nb takes a lesson's outputs from a jupyter-cache (``nb_execution_mode = "cache"``) when the cache holds a run
of the same code cells, and otherwise runs the notebook while it reads that page. Two things are added here:

* **What the outputs depend on.** jupyter-cache compares a notebook's code only; a lesson's output also depends
  on graphkin, on the files beside the lessons and on the installed packages. :func:`source_digest` hashes
  those, and a cache made under another digest is emptied: a changed graphkin runs every lesson again, a
  changed lesson runs that lesson, a changed page of the guide runs none.
* **Every core.** Sphinx's parallel reading hands pages out in alphabetical chunks, so that most lessons fall to
  one process and run one after another. On ``builder-inited`` the lessons the cache does not hold are run here
  instead, ``-j`` at a time, the slowest first, and put in the cache; the
  explorers' scene pages (docs/offline.py) are built in the same pool.

The cache lives in ``build/.docs-cache``, which ``make docs`` in a fresh clone creates (``make clean`` removes
it). A lesson that fails here is not cached: myst-nb then runs it again as it reads the page, and the build stops
on its error as before.
"""

from __future__ import annotations

import hashlib
import json
import shutil
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CACHE = ROOT / "build" / ".docs-cache"
"""The folder of everything kept between builds: ``jupyter`` (the executed lessons), ``scenes`` (the explorers'
pages), ``digest`` (what they were made from) and ``runtimes.json`` (each lesson's last run, in seconds)."""

LESSONS = ROOT / "lessons"

RAN: set[str] = set()
"""The docnames of the lessons :func:`prepare` ran in this build."""


def source_digest(root: Path = ROOT) -> str:
    """A hash of what a lesson's outputs depend on besides its own code: graphkin's files (source, catalog,
    scripts), the files beside the lessons, pyproject.toml, Python's version and every installed package's.

    Parameters
    ----------
    root : Path
        The repository.

    Returns
    -------
    str
        Hex digest.
    """
    from importlib import metadata

    h = hashlib.sha256(sys.version.encode())
    files = [p for p in sorted((root / "graphkin").rglob("*")) if p.is_file() and "__pycache__" not in p.parts]
    # the lessons themselves are jupyter-cache's to compare (notebook and jupytext twin); any other file is data
    files += [p for p in sorted((root / "lessons").iterdir()) if p.is_file() and p.suffix != ".ipynb"
              and not (p.suffix == ".py" and p.with_suffix(".ipynb").exists())]
    files.append(root / "pyproject.toml")
    for path in files:
        h.update(str(path.relative_to(root)).encode() + b"\0" + path.read_bytes() + b"\0")
    for dist in sorted(f"{d.metadata['Name']}=={d.version}" for d in metadata.distributions()):
        h.update(dist.encode() + b"\n")
    return h.hexdigest()


def _code_length(path: Path) -> int:
    """The characters of a notebook's code cells."""
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    return sum(len("".join(c["source"])) for c in cells if c["cell_type"] == "code")


def _run(path: str, timeout: int) -> tuple[str, dict | None, float, str | None]:
    """Run one notebook in its own folder (a worker process): (path, the executed notebook, seconds, error)."""
    import nbformat
    from jupyter_cache.executors.utils import single_nb_execution

    nb = nbformat.read(path, as_version=4)
    result = single_nb_execution(nb, cwd=str(Path(path).parent), timeout=timeout, allow_errors=False)
    return path, (nb if result.err is None else None), result.time, result.exc_string


def _scene(name: str, path: str) -> tuple[str, float]:
    """Write problem ``name``'s scene page to ``path``: (name, seconds).

    As ``graphkin explore NAME --motion -o page.html`` writes it: the motion polygons too, for lesson 08.
    """
    from graphkin import catalog
    from graphkin.scene import scene, write_page

    start = time.perf_counter()
    write_page(scene(catalog.load(name), motion=True), path)
    return name, time.perf_counter() - start


def prepare(app) -> None:
    """``builder-inited``: empty a cache made from other sources, then run the lessons it lacks and build the
    scene pages it lacks, ``app.parallel`` at a time."""
    import nbformat
    from jupyter_cache import get_cache
    from jupyter_cache.base import CacheBundleIn
    from offline import explored_problems
    from sphinx.util import logging

    from graphkin import catalog

    logger = logging.getLogger(__name__)
    if app.config.nb_execution_mode != "cache":  # e.g. -D nb_execution_mode=off: the lessons are not run at all
        return
    digest = source_digest()
    stamp, times_file, scenes = CACHE / "digest", CACHE / "runtimes.json", CACHE / "scenes"
    times = json.loads(times_file.read_text()) if times_file.exists() else {}
    if not stamp.exists() or stamp.read_text() != digest:
        shutil.rmtree(CACHE / "jupyter", ignore_errors=True)
        shutil.rmtree(scenes, ignore_errors=True)
        CACHE.mkdir(parents=True, exist_ok=True)
        stamp.write_text(digest)
    scenes.mkdir(exist_ok=True)
    cache = get_cache(str(CACHE / "jupyter"))

    lessons = sorted(LESSONS.glob("*.ipynb"))
    todo = []
    for path in lessons:
        try:
            cache.match_cache_notebook(nbformat.read(path, as_version=4))
        except KeyError:
            todo.append(path)
    # The slowest first, so that the last to start is a short one: as long as each took last time, or (a fresh
    # clone, a new lesson) as long as its code, which ranks the lessons' times well enough to start the
    # grading platforms' first.
    known = all(p.name in times for p in todo)
    todo.sort(key=lambda p: -times[p.name] if known else -_code_length(p))
    # The lessons' explorers and the catalog page's: every catalog problem's scene page.
    wanted = set().union(*(explored_problems(p) for p in lessons)) | set(catalog.names())
    missing = sorted(n for n in wanted if not (scenes / f"{n}.html").exists())
    if not todo and not missing:
        return
    logger.info(f"running {len(todo)} lessons and building {len(missing)} scene pages, {app.parallel} at a time")
    with ProcessPoolExecutor(max_workers=max(1, app.parallel)) as pool:
        jobs = [pool.submit(_run, str(p), app.config.nb_execution_timeout) for p in todo]
        jobs += [pool.submit(_scene, n, str(scenes / f"{n}.html")) for n in missing]
        for job in as_completed(jobs):
            out = job.result()
            if len(out) == 2:
                logger.info(f"scene page of {out[0]} built in {out[1]:.1f} s")
                continue
            path, nb, seconds, error = out
            times[Path(path).name] = round(seconds, 1)
            if nb is None:  # myst-nb runs it again while reading its page, and reports the error there
                logger.info(f"{Path(path).name} failed: {error.splitlines()[-1] if error else ''}")
                continue
            cache.cache_notebook_bundle(CacheBundleIn(nb, path, data={"execution_seconds": seconds}),
                                        check_validity=False, overwrite=True)
            RAN.add(Path(path).relative_to(ROOT).with_suffix("").as_posix())
            logger.info(f"{Path(path).name} ran in {seconds:.1f} s")
    times_file.write_text(json.dumps(times, indent=1, sort_keys=True))


def outdated(app, env, added, changed, removed) -> list[str]:
    """``env-get-outdated``: the lessons run in this build are read again, though their notebooks did not change
    (graphkin did): their pages show the new outputs."""
    return sorted(RAN & env.found_docs)


def copy_scenes(app, exception) -> None:
    """``build-finished``: the scene pages into the site's ``_scenes`` folder."""
    from offline import SCENES

    if exception is not None or app.builder.format != "html":
        return
    target = Path(app.outdir, SCENES)
    target.mkdir(exist_ok=True)
    for page in (CACHE / "scenes").glob("*.html"):
        shutil.copyfile(page, target / page.name)
    # The drawn exercises' practice pages (docs/exercises.md frames them): a second or two each, made anew.
    from catalog_page import write_practice_pages

    write_practice_pages(target)


def setup(app):
    app.connect("builder-inited", prepare)
    app.connect("env-get-outdated", outdated)
    app.connect("build-finished", copy_scenes)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
