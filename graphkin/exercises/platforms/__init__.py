"""Exercises on the platforms courses already grade with.

``export(exercise, to, dest)`` writes everything a teacher uploads to or
commits into otter-grader, nbgrader, PrairieLearn or Gradescope, with a
README naming the platform's next command. graphkin does not run a grading
service: each platform runs the students' submissions on its own machines,
and the code it runs calls :mod:`graphkin.exercises.platforms.runtime`, so
every platform gives the same per-student data, the same score and the same
feedback as ``graphkin exercise grade``.

What travels with an export (a :class:`Bundle`):

- the exercise file (and its base problem when that is not in the catalog),
  so the platform draws the same variants as the teacher's machine;
- a copy of the graphkin package itself (``vendor/graphkin``) and a
  ``requirements.txt`` of what it needs, for platforms whose machines do not
  have graphkin;
- the course secret, only in the parts students never see (hidden tests,
  server code, autograder);
- with a roster, each student's sheet (their data and questions, never the
  answers) for the notebook platforms, so the student notebook needs no secret.

Each platform module has ``build(bundle) -> {relative path: text or bytes}``;
:func:`export` checks the destination, builds the tree and writes every file
atomically.
"""

from __future__ import annotations

import importlib
import importlib.metadata
import re
from dataclasses import dataclass, field
from pathlib import Path

from graphkin import catalog
from graphkin.errors import GraphkinError
from graphkin.exercises import load
from graphkin.exercises.batch import run_roster
from graphkin.exercises.keys import make_keys
from graphkin.exercises.platforms import runtime
from graphkin.exercises.variants import check_student
from graphkin.files import check_destination, write_bytes

PLATFORMS = ("otter", "nbgrader", "prairielearn", "gradescope")
"""The platforms :func:`export` writes for."""

SAMPLE_STUDENT = "sample"
"""The id whose variant the exported solutions and self-tests use when no roster is given."""

_SKIP = re.compile(r"(__pycache__|\.pyc$|\.egg-info)")


@dataclass(frozen=True)
class Bundle:
    """What an export carries, whatever the platform.

    Attributes
    ----------
    exercise : graphkin.exercises.Exercise
    name : str
        The exercise id: file names and notebook names are made from it.
    files : dict of str to str
        The exercise file as ``<name>.toml`` and, when its base problem is
        not a catalog problem, that file under the name the exercise gives it.
    secret : str
        The course secret ("" if none): only for the parts students never see.
    students : tuple of str, or None
        The roster, if one was given.
    sheets : dict of str to dict
        With a roster: each student's sheet (data and questions, no answers).
    sample : str
        The student whose variant the export's own solution and checks use.
    """

    exercise: object
    name: str
    files: dict
    secret: str
    students: tuple | None
    sheets: dict = field(default_factory=dict)
    sample: str = SAMPLE_STUDENT
    _memo: dict = field(default_factory=dict, repr=False, compare=False)

    def keys(self) -> dict:
        """The roster's precomputed keys (:func:`graphkin.exercises.keys.make_keys`), what grading carries in
        place of the secret; without a roster (and so without a secret), keys that draw from the id."""
        if "keys" not in self._memo:
            entries = None
            if self.students is not None:
                entries = [r["entry"] for r in run_roster(self.exercise, "entry", list(self.students), self.secret)]
            self._memo["keys"] = make_keys(self.exercise, self.students, self.secret, entries=entries)
        return self._memo["keys"]

    @property
    def exercise_file(self) -> str:
        """File name of the exercise inside the export."""
        return f"{self.name}.toml"

    def question_ids(self) -> list[str]:
        return [q.id for q in self.exercise.questions]

    def sample_key(self) -> dict:
        """The sample student's key (the answers an export's own solution types)."""
        return runtime.variant(self.exercise, self.sample, self.secret).key()


def requirements() -> list[str]:
    """What graphkin needs at run time, as pip requirement lines (from the installed package's metadata)."""
    try:
        reqs = importlib.metadata.requires("graphkin") or []
    except importlib.metadata.PackageNotFoundError:  # running from a source tree that was never installed
        reqs = ["numpy>=1.26", "shapely>=2.0", "pint>=0.24", "matplotlib>=3.8"]
    lines = []
    for r in reqs:
        if "extra ==" in r:
            continue
        name = re.split(r"[<>=!~ ;\[]", r, maxsplit=1)[0].lower()
        # The platforms grade without a browser: the notebook front end is theirs, not graphkin's to install;
        # nor do they typeset handouts.
        if name in ("jupyterlab", "ipywidgets", "typst"):
            continue
        lines.append(r.split(";")[0].strip())
    return lines


def vendor_files() -> dict[str, bytes]:
    """The graphkin package as installed, file by file (``graphkin/...`` → bytes), for a platform without it."""
    root = Path(importlib.import_module("graphkin").__file__).parent
    out = {}
    for p in sorted(root.rglob("*")):
        rel = p.relative_to(root.parent).as_posix()
        if p.is_file() and not _SKIP.search(rel):
            out[rel] = p.read_bytes()
    return out


def _exercise_files(ex) -> dict[str, str]:
    """The exercise file (and a non-catalog base problem) as the export carries them."""
    files = {f"{ex.id}.toml": ex.text}
    if ex.problem not in catalog.names():
        if Path(ex.problem).name != ex.problem or ex.problem == f"{ex.id}.toml":
            raise GraphkinError(f"{ex.file}: problem = {ex.problem!r}: for an export, put the problem file beside "
                                "the exercise file, under its own name, and name it without a folder")
        files[ex.problem] = ex.base_text
    return files


def bundle(exercise, *, secret: str = "", students=None, progress=None) -> Bundle:
    """Everything an export carries, checked (every roster student gets a usable variant).

    Parameters
    ----------
    exercise : str or Exercise
        A catalog name or an exercise file.
    secret : str
        The course secret ("" if none).
    students : sequence of str, optional
        The roster; its students' sheets travel with the notebook platforms.
    progress : callable, optional
        Called with the number of students done, as a batch goes.
    """
    ex = load(exercise)
    sheets = {}
    roster = None
    if students is not None:
        roster = tuple(check_student(s) for s in students)
        if not roster:
            raise GraphkinError("the roster has no students")
        dup = sorted({s for s in roster if roster.count(s) > 1}) if len(set(roster)) != len(roster) else []
        if dup:
            raise GraphkinError(f"the roster names a student more than once: {', '.join(dup[:5])}")
        for s in run_roster(ex, "make", list(roster), secret, progress=progress):
            if "error" in s:
                raise GraphkinError(f"student {s['student']}: {s['error']}")
            sheets[s["student"]] = s
    sample = roster[0] if roster else SAMPLE_STUDENT
    return Bundle(ex, ex.id, _exercise_files(ex), secret, roster, sheets, sample)


def platform(to: str):
    """The module that builds an export for platform ``to``."""
    if to not in PLATFORMS:
        raise GraphkinError(f"--to {to!r}: graphkin exports to {', '.join(PLATFORMS)}")
    return importlib.import_module(f"{__name__}.{to}")


def export(exercise, to: str, dest, *, secret: str = "", students=None, progress=None) -> list[Path]:
    """Write the export of an exercise for a platform into the folder ``dest``.

    Returns the files written. Every file goes to a temporary file first,
    then into place; files already in ``dest`` that the export does not
    write are left alone.
    """
    module = platform(to)
    dest = Path(dest)
    if dest.exists() and not dest.is_dir():
        raise GraphkinError(f"-o {dest}: is a file; give a folder to export into")
    check_destination(dest / "README.md", "-o")
    tree = module.build(bundle(exercise, secret=secret, students=students, progress=progress))
    written = []
    try:
        for rel, content in sorted(tree.items()):
            data = content.encode("utf-8") if isinstance(content, str) else content
            written.append(write_bytes(dest / rel, data, "-o", executable=rel.endswith((".sh", "run_autograder"))))
    except KeyboardInterrupt:
        # Each file is whole or absent; say how far the export got, so the teacher knows to run it again.
        raise KeyboardInterrupt(f"{len(written)} of {len(tree)} files of the export were written to {dest}; "
                                "run the export again") from None
    except GraphkinError as exc:
        raise GraphkinError(f"{exc}; {len(written)} of {len(tree)} files of the export were written to {dest}") \
            from None
    return written


__all__ = ["PLATFORMS", "SAMPLE_STUDENT", "Bundle", "bundle", "export", "platform", "requirements", "vendor_files"]
