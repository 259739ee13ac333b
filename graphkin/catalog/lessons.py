"""The lesson notebooks shipped with graphkin, and a copy of them for a course (``graphkin lessons DIR``).

The wheel carries them as ``graphkin/lessons/NN_name.ipynb`` (``setup.py`` copies them there from the
repository's ``lessons/`` as it builds); a clone, or an editable install of one, reads ``lessons/`` itself.
They are the notebooks as committed: no outputs, so a student's first Run All draws every figure afresh.
"""

from __future__ import annotations

import re
from importlib import resources
from importlib.resources.abc import Traversable
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.files import check_folder, write_bytes

LESSON = re.compile(r"^\d\d_\w+\.ipynb$")
"""A lesson's file name: two digits, its name, ``.ipynb`` (``08_velocity_and_acceleration_polygons.ipynb``)."""


def lessons_folder() -> Traversable:
    """Where this install of graphkin keeps its lessons: in the package (a wheel) or beside it (a clone)."""
    packaged = resources.files("graphkin").joinpath("lessons")
    if packaged.is_dir():
        return packaged
    clone = Path(__file__).resolve().parents[2] / "lessons"
    if clone.is_dir():
        return clone
    raise GraphkinError("this install of graphkin has no lesson notebooks: reinstall it from the package index "
                        "(pip install graphkin) or from a clone of its repository")


def lesson_files() -> list[Traversable]:
    """The lesson notebooks, in the order of their numbers."""
    return sorted((f for f in lessons_folder().iterdir() if LESSON.match(f.name)), key=lambda f: f.name)


def copy_lessons(folder: str | Path, *, force: bool = False) -> list[Path]:
    """Copy every lesson notebook into ``folder`` (made if missing), for a course to hand out.

    Nothing is written if a lesson is already there, unless ``force``: a teacher's edited copy is never
    replaced by accident. Each file is written whole or not at all (:func:`graphkin.files.write_bytes`).

    Parameters
    ----------
    folder : str or Path
        The course's folder (a git repository that nbgitpuller pulls from, a shared folder, ...).
    force : bool
        Replace lessons of the same names already in ``folder``; other files there are left alone.

    Returns
    -------
    list of Path
        The notebooks written, in the order of their numbers.

    Raises
    ------
    GraphkinError
        If ``folder`` is a file, lies under a file or cannot be written, or holds lessons and not ``force``.
    """
    what = "lessons folder"
    if not str(folder).strip():
        raise GraphkinError(f"{what}: give the folder to copy the lessons into, e.g. 'course/lessons'")
    target = check_folder(folder, what)
    sources = lesson_files()
    there = [f.name for f in sources if (target / f.name).exists()]
    if there and not force:
        raise GraphkinError(f"{what} {target}: {len(there)} of the lessons are already there ({', '.join(there[:3])}"
                            f"{', ...' if len(there) > 3 else ''}); --force (force=True) replaces them")
    return [write_bytes(target / f.name, f.read_bytes(), what) for f in sources]
