"""What a student hands in, reduced to the answers its notebook holds, read as data.

A hand-in is a notebook on its own, a zip (otter's ``grader.export()`` writes one, with otter's log
``.OTTER_LOG`` beside the notebook) or a folder (nbgrader's ``submitted/<student>/<assignment>/``), and
whatever else the student put in it. The notebook platforms load some of that before any test runs:
otter unpickles ``.OTTER_LOG`` in the process that grades; the kernel otter and nbgrader start in the
hand-in's folder imports modules from it before its own (a ``graphkin/``, ``otter/`` or ``IPython/``
package, a ``json.py``); nbgrader copies the files it holds, and what its links point to, into the folder
it hands back as feedback. So graphkin reduces a hand-in before a platform loads anything of it
(:func:`read_handin`) to

- the id and the answers its notebook holds, read as data
  (:func:`graphkin.exercises.notebooks.notebook_answers`): the notebook's bytes are read once, within
  :data:`~graphkin.exercises.notebooks.MAX_NOTEBOOK_BYTES`, decoded and parsed as JSON; nothing in them
  is run;
- the names of everything else it holds, for the teacher's log. Nothing of it is opened, imported or
  unpickled, and a link is never followed.

A platform then clears the folder its kernel starts in of all of it (:func:`clear_folder`), so the kernel
finds nothing of the student's to import, and what the platform hands back holds nothing of it either.

A hand-in that cannot be read (too big, nested too deeply, not UTF-8, not JSON, not a notebook, no
notebook or several, a link) is refused with a sentence (:data:`REFUSALS`): that student's row, never a
stop for the class.

Examples
--------
>>> import json, pathlib, tempfile
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> _ = (folder / "hw.ipynb").write_text(json.dumps({"cells": [
...     {"cell_type": "code", "source": 'STUDENT = "s001"\\nF23 = "12 N"'}]}))
>>> _ = (folder / ".OTTER_LOG").write_bytes(b"\\x80\\x04...")
>>> (folder / "graphkin").mkdir(); _ = (folder / "graphkin" / "__init__.py").write_text("...")
>>> h = read_handin(folder, {"F23": "F23"})
>>> h.claimed, h.answers, h.refused
('s001', {'F23': '12 N'}, None)
>>> h.ignored
(".OTTER_LOG (otter's log, a pickle)", 'graphkin/ (a Python package, 1 file)')
"""

from __future__ import annotations

import json
import os
import shutil
import stat
import zipfile
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath

from graphkin.errors import GraphkinError
from graphkin.exercises.grading import echo
from graphkin.exercises.notebooks import MAX_NOTEBOOK_BYTES, code_sources, notebook_answers
from graphkin.files import write_bytes

REFUSALS = {
    "too_big": (f"This notebook is larger than {MAX_NOTEBOOK_BYTES // 1_000_000} MB, more than a notebook of "
                "answers can be: clear its outputs (Kernel, then Restart Kernel and Clear Outputs), save it and "
                "hand it in again."),
    "too_deep": "This file is nested too deeply to be a notebook: hand in the notebook as Jupyter saved it.",
    "not_utf8": "This file is not UTF-8 text, as Jupyter saves a notebook: hand in the notebook as Jupyter saved it.",
    "not_json": "This file is not JSON, so it is not a notebook: hand in the notebook (.ipynb) as Jupyter saved it.",
    "not_notebook": ("This file is JSON but not a notebook (it has no list of cells): hand in the notebook as "
                     "Jupyter saved it."),
    "no_notebook": "No notebook (.ipynb) was handed in.",
    "notebooks": ("More than one notebook was handed in, and none has the assignment's name: hand in your one "
                  "notebook."),
    "link": "The notebook handed in is a link to another file, not a notebook: hand in the notebook itself.",
    "bad_zip": "This zip cannot be opened (it is damaged, or not a zip): hand in your notebook again.",
}
"""Why a hand-in is not graded, by code: the sentence its every question gets (a student reads it)."""

class FolderError(GraphkinError):
    """A hand-in's folder that cannot be cleared or given back the assignment's files: one sentence naming the file
    (the teacher's machine at fault, never the student's hand-in)."""


METADATA = "graphkin"
"""The notebook metadata key of a notebook graphkin made from a hand-in (:func:`stripped_notebook`)."""

_NAMED = 20  # names of what else a hand-in holds, at most, in the log

_HINTS = {".pkl": "a pickle", ".pickle": "a pickle", ".dill": "a pickle", ".py": "Python code",
          ".pth": "a Python path file", ".ipynb": "another notebook", ".zip": "a zip", ".so": "compiled code"}


@dataclass(frozen=True)
class HandIn:
    """A hand-in reduced to what grading reads.

    Attributes
    ----------
    claimed : object
        What the notebook assigns to ``STUDENT`` (text, :class:`~graphkin.exercises.notebooks.NotData`, or
        None when it assigns nothing or the hand-in is refused).
    answers : dict
        Question id → the answer read as data (:func:`~graphkin.exercises.notebooks.notebook_answers`);
        empty when the hand-in is refused.
    refused : str or None
        Why it is not graded, a key of :data:`REFUSALS`; None when its notebook was read.
    notebook : str or None
        The notebook read (its name inside the hand-in).
    ignored : tuple of str
        Everything else it holds, named for the teacher's log (never opened).
    sources : tuple of str
        The text of the notebook's code cells, in order: all the answers are read from (never run).
    grade_ids : tuple of str
        The nbgrader grade ids its cells' metadata carry, in order (read as data, for the log of what a
        platform was not given: a cell the student added, a grade cell twice).
    """

    claimed: object = None
    answers: dict = field(default_factory=dict)
    refused: str | None = None
    notebook: str | None = None
    ignored: tuple = ()
    sources: tuple = ()
    grade_ids: tuple = ()

    @property
    def reason(self) -> str | None:
        """The sentence of :attr:`refused` (None when the hand-in was read)."""
        return REFUSALS[self.refused] if self.refused else None


def read_handin(path, variables: Mapping[str, str], *, notebook: str | None = None,
                own: Mapping[str, bytes | Path] | None = None) -> HandIn:
    """A hand-in (a notebook, a zip or a folder) reduced to its notebook's answers, read as data.

    Parameters
    ----------
    path : str or Path
        The notebook file, a ``.zip``, or a folder.
    variables : mapping of str to str
        Question id → the notebook variable its answer is typed into.
    notebook : str, optional
        The assignment's notebook name (``hw1.ipynb``): in a zip or folder that holds several notebooks,
        this one is read.
    own : mapping of str to bytes or Path, optional
        The platform's and the assignment's own files, by relative path (``vendor/graphkin/__init__.py``),
        each with its content or the file holding it: a file of the hand-in that is one of them, unchanged,
        is not named in :attr:`HandIn.ignored`.

    Returns
    -------
    HandIn

    Raises
    ------
    GraphkinError
        ``path`` is not there or cannot be listed (the teacher's mistake, not the student's).
    """
    p = Path(path)
    if not os.path.lexists(p):
        raise GraphkinError(f"{p}: no such file or folder")
    if p.is_symlink():
        return HandIn(refused="link", notebook=p.name)
    if p.is_dir():
        return _from_folder(p, variables, notebook, own or {})
    if p.suffix.lower() == ".zip":
        return _from_zip(p, variables, notebook)
    try:
        data = _read_capped(p)
    except OSError as exc:
        raise GraphkinError(f"{p}: cannot be read ({exc.strerror or exc})") from None
    return _reading(data, variables, p.name, ())


def stripped_notebook(handin: HandIn, metadata: Mapping | None = None) -> dict:
    """A hand-in as a notebook a platform can read: its code cells' text and nothing else.

    No output, attachment, markdown or cell metadata of the student's is carried, nor anything that was
    beside the notebook; the notebook's metadata is ``metadata`` and, for a refused hand-in, the reason
    (``{"graphkin": {"refused": code}}``), so that reading it again gives the same verdict. Reading it
    (:func:`read_handin`) gives the hand-in's id and answers, as the code cells are the same text in the
    same order. Nothing in it is run by graphkin; a platform that grades it must not run it either.
    """
    meta = dict(metadata or {})
    if handin.refused:
        meta[METADATA] = {"refused": handin.refused}
    cells = [{"cell_type": "code", "id": f"c{i}", "metadata": {}, "execution_count": None, "outputs": [],
              "source": source} for i, source in enumerate(handin.sources)]
    return {"cells": cells, "metadata": meta, "nbformat": 4, "nbformat_minor": 5}


def notebook_text(notebook: Mapping) -> str:
    """A notebook as JSON text (text as typed; ``\\u`` escapes only where UTF-8 cannot carry a character)."""
    text = json.dumps(notebook, ensure_ascii=False, indent=1)
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:  # a lone surrogate the student's JSON held as an escape
        text = json.dumps(notebook, indent=1)
    return text + "\n"


def literal(value) -> str:
    """A value read as data, as the Python literal a platform's kernel may run in its place.

    Text and finite numbers as they are; anything else (a marker of what is not data, a huge number)
    ``None``: the grade never comes from the kernel, so this only keeps it from running anything else.

    >>> literal("12 N"), literal(3.5), literal(10**400), literal(True)
    ("'12 N'", '3.5', 'None', 'None')
    """
    if isinstance(value, str):
        return repr(value)
    if isinstance(value, (int, float)) and not isinstance(value, bool) and abs(value) < 1e300:
        return repr(value)
    return "None"


def clear_folder(folder, own: Mapping[str, bytes | Path], *, leave=()) -> list[str]:
    """Empty a hand-in's folder of all but the platform's and the assignment's own files, put back as they were.

    Every entry of ``folder`` that is not one of ``own`` unchanged, nor named in ``leave``, is removed (a
    link itself, never what it points to); every file of ``own`` that is then missing is written again
    from its source. A kernel started in ``folder`` finds nothing of the student's to import.

    Parameters
    ----------
    folder : Path
    own : mapping of str to bytes or Path
        Relative path → content, or the file holding it.
    leave : iterable of str
        Top-level names left as they are (the notebook the platform writes itself).

    Returns
    -------
    list of str
        The top-level names removed, for the log.

    Raises
    ------
    FolderError
        An entry that cannot be removed, or an own file that cannot be read or written back: one sentence naming
        it. Each file is written whole or not at all (:func:`graphkin.files.write_bytes`), so a kernel started
        after a failure never imports half a module.
    """
    folder = Path(folder)
    leave = set(leave)
    tops = _tops(own)
    removed = []
    for entry in sorted(os.scandir(folder), key=lambda e: e.name):
        if entry.name in leave or (entry.name in tops and _unchanged(folder, entry.name, own)):
            continue
        _remove(entry)
        removed.append(entry.name)
    for rel, source in own.items():
        target = folder / rel
        if not os.path.lexists(target):
            _put_back(target, source)
    return removed


def _remove(entry: os.DirEntry) -> None:
    """Remove one entry of a hand-in's folder (a link itself, never what it points to)."""
    try:
        if entry.is_dir(follow_symlinks=False):
            shutil.rmtree(entry.path)
        else:
            os.unlink(entry.path)
    except OSError as exc:
        raise FolderError(f"hand-in folder: {entry.path} cannot be removed ({exc.strerror or exc})") from None


def _put_back(target: Path, source) -> None:
    """Write one of the assignment's own files back into a hand-in's folder, atomically (temp file, os.replace)."""
    try:
        data = _content(source)
    except OSError as exc:
        raise FolderError(f"assignment file {source}: cannot be read to put back as {target} "
                          f"({exc.strerror or exc})") from None
    try:
        write_bytes(target, data, "assignment file")
    except GraphkinError as exc:  # the writer's sentence names the file; said again as this module's error
        raise FolderError(str(exc)) from None


def own_files(folder, *, skip=(), prefix: str = "") -> dict[str, Path]:
    """Every file under ``folder`` (relative path → the file), links not followed, names in ``skip`` left out."""
    folder = Path(folder)
    out = {}
    for dirpath, dirnames, filenames in os.walk(folder):
        dirnames[:] = sorted(d for d in dirnames if d not in skip)
        for name in sorted(filenames):
            path = Path(dirpath, name)
            if name not in skip and not path.is_symlink():
                out[prefix + path.relative_to(folder).as_posix()] = path
    return out


def class_notes(graded, roster=None) -> list[str]:
    """What a teacher must look at in a class's hand-ins, each graded as the id it names: one student graded from
    several files (the id typed in a notebook is the student's to type, so a second notebook may claim a classmate's
    id, and a gradebook keeps one of the rows), and the roster's students no hand-in was graded as.

    Parameters
    ----------
    graded : iterable of mapping
        One per hand-in, with ``"student"`` (whom it is graded as; ``""`` when none) and ``"file"``.
    roster : list of str, optional

    Returns
    -------
    list of str
        Sentences for the log, in roster order, then file order.
    """
    files: dict[str, list[str]] = {}
    for g in graded:
        if g["student"]:
            files.setdefault(g["student"], []).append(str(g["file"]))
    notes = [f"student {echo(s, 100)!r} was graded in {len(f)} files ({', '.join(f)}): check who handed each one in"
             for s, f in files.items() if len(f) > 1]
    absent = [s for s in roster or () if s not in files]
    if absent:
        shown = ", ".join(absent[:10]) + (f" and {len(absent) - 10} more" if len(absent) > 10 else "")
        notes.append(f"no hand-in is graded as {len(absent)} roster student{'s' if len(absent) > 1 else ''}: {shown}")
    return notes


# ---------------------------------------------------------------------------------------------------------
# Reading


def _read_capped(path: Path) -> bytes | None:
    """A file's bytes, never following a link; None when it is larger than a notebook may be (it is not read)."""
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0))
    with os.fdopen(fd, "rb") as f:
        if os.fstat(f.fileno()).st_size > MAX_NOTEBOOK_BYTES:
            return None
        return f.read(MAX_NOTEBOOK_BYTES + 1)


def _parse(data: bytes | None):
    """A notebook's JSON, or the code of why it is not one."""
    if data is None or len(data) > MAX_NOTEBOOK_BYTES:
        return "too_big"
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return "not_utf8"
    try:
        nb = json.loads(text)
    except RecursionError:
        return "too_deep"
    except ValueError:
        return "not_json"
    if not isinstance(nb, dict) or not isinstance(nb.get("cells"), list):
        return "not_notebook"
    return nb


def _reading(data: bytes | None, variables, name: str, ignored: tuple) -> HandIn:
    nb = _parse(data)
    if isinstance(nb, str):
        return HandIn(refused=nb, notebook=name, ignored=ignored)
    meta = nb.get("metadata")
    mark = meta.get(METADATA) if isinstance(meta, dict) else None
    # A notebook graphkin made from a hand-in it refused says so: read again, it gets the same verdict. (A
    # student who writes this into their own notebook refuses it, nothing more.)
    if isinstance(mark, dict) and mark.get("refused") in REFUSALS:
        return HandIn(refused=mark["refused"], notebook=name, ignored=ignored)
    claimed, answers = notebook_answers(nb, variables)
    return HandIn(claimed, answers, None, name, ignored, tuple(code_sources(nb)), _grade_ids(nb))


def _grade_ids(nb: dict) -> tuple:
    ids = []
    for cell in nb["cells"]:
        meta = cell.get("metadata") if isinstance(cell, dict) else None
        marks = meta.get("nbgrader") if isinstance(meta, dict) else None
        if isinstance(marks, dict) and isinstance(marks.get("grade_id"), str):
            ids.append(marks["grade_id"])
    return tuple(ids)


def _choose(names: list[str], wanted: str | None):
    """The notebook of a hand-in among its ``.ipynb`` names, or the refusal code."""
    if wanted in names:
        return wanted
    if len(names) == 1:
        return names[0]
    return "no_notebook" if not names else "notebooks"


def _from_folder(folder: Path, variables, wanted, own) -> HandIn:
    try:
        entries = {e.name: e for e in os.scandir(folder)}
    except OSError as exc:
        raise GraphkinError(f"{folder}: cannot be listed ({exc.strerror or exc})") from None
    candidates = sorted(n for n, e in entries.items() if n.lower().endswith(".ipynb")
                        and not e.is_dir(follow_symlinks=False))
    chosen = _choose(candidates, wanted)
    found = chosen if chosen in entries else None
    ignored = _capped([_describe(folder, n, own) for n in sorted(entries) if n != found
                       and not (n in _tops(own) and _unchanged(folder, n, own))])
    if found is None:
        return HandIn(refused=chosen, ignored=ignored)
    if entries[found].is_symlink():
        return HandIn(refused="link", notebook=found, ignored=ignored)
    try:
        data = _read_capped(folder / found)
    except OSError:
        return HandIn(refused="link", notebook=found, ignored=ignored)
    return _reading(data, variables, found, ignored)


def _from_zip(path: Path, variables, wanted) -> HandIn:
    try:
        with zipfile.ZipFile(path) as z:
            infos = [i for i in z.infolist() if not i.is_dir()]
            tops: dict[str, list] = {}
            for info in infos:
                parts = PurePosixPath(info.filename).parts
                if parts and not parts[0].startswith("__MACOSX"):
                    tops.setdefault(parts[0], []).append(info)
            candidates = sorted(t for t, members in tops.items() if t.lower().endswith(".ipynb")
                                and len(members) == 1 and members[0].filename == t)
            chosen = _choose(candidates, wanted)
            found = chosen if chosen in tops else None
            ignored = _capped([_describe_zip(t, tops[t]) for t in sorted(tops) if t != found])
            if found is None:
                return HandIn(refused=chosen, ignored=ignored)
            info = tops[found][0]
            if stat.S_ISLNK(info.external_attr >> 16):
                return HandIn(refused="link", notebook=found, ignored=ignored)
            if info.file_size > MAX_NOTEBOOK_BYTES:
                return HandIn(refused="too_big", notebook=found, ignored=ignored)
            with z.open(info) as f:
                data = f.read(MAX_NOTEBOOK_BYTES + 1)
    except (zipfile.BadZipFile, zipfile.LargeZipFile, NotImplementedError, EOFError, ValueError):
        return HandIn(refused="bad_zip", notebook=path.name)
    except OSError as exc:
        raise GraphkinError(f"{path}: cannot be read ({exc.strerror or exc})") from None
    return _reading(data, variables, found, ignored)


# ---------------------------------------------------------------------------------------------------------
# Naming what else a hand-in holds


def _capped(names: list[str]) -> tuple:
    """At most :data:`_NAMED` names for the log, and how many more there were."""
    if len(names) <= _NAMED:
        return tuple(names)
    return (*names[:_NAMED], f"and {len(names) - _NAMED} more")


def _tops(own) -> set[str]:
    return {PurePosixPath(rel).parts[0] for rel in own}


def _content(source) -> bytes:
    return source if isinstance(source, bytes) else Path(source).read_bytes()


def _same(path: Path, source) -> bool:
    """Whether the file ``path`` holds ``source`` (bytes, or a file's), sizes compared before any byte is read."""
    size = len(source) if isinstance(source, bytes) else Path(source).stat().st_size
    return path.stat().st_size == size and path.read_bytes() == _content(source)


def _unchanged(folder: Path, top: str, own) -> bool:
    """Whether ``folder/top`` is exactly the platform's own file or folder of that name (no link, nothing added)."""
    path = folder / top
    if path.is_symlink():
        return False
    if path.is_file():
        return top in own and _same(path, own[top])
    if not path.is_dir():
        return False
    wanted = {rel: src for rel, src in own.items() if rel.startswith(top + "/")}
    seen = 0
    for dirpath, dirnames, filenames in os.walk(path):
        for name in dirnames + filenames:
            if Path(dirpath, name).is_symlink():
                return False
        for name in filenames:
            rel = Path(dirpath, name).relative_to(folder).as_posix()
            if rel not in wanted or not _same(Path(dirpath, name), wanted[rel]):
                return False
            seen += 1
    return seen == len(wanted)


def _hint(name: str) -> str:
    if name == ".OTTER_LOG":
        return "otter's log, a pickle"
    return _HINTS.get(Path(name).suffix.lower(), "a file")


def _files(count: int) -> str:
    return f"{count} file" + ("" if count == 1 else "s")


def _describe(folder: Path, name: str, own) -> str:
    """One entry of a folder, as the teacher's log names it."""
    path = folder / name
    shown = echo(name, 60)
    if path.is_symlink():
        return f"{shown} (a link)"
    if not path.is_dir():
        return f"{shown} ({_hint(name)})"
    count = sum(len(files) for _, _, files in os.walk(path))
    what = "a Python package" if (path / "__init__.py").exists() else "a folder"
    differs = ", not the assignment's own" if name in _tops(own) else ""
    return f"{shown}/ ({what}{differs}, {_files(count)})"


def _describe_zip(top: str, members: list) -> str:
    shown = echo(top, 60)
    if len(members) == 1 and members[0].filename == top:
        if stat.S_ISLNK(members[0].external_attr >> 16):
            return f"{shown} (a link)"
        return f"{shown} ({_hint(top)})"
    package = any(m.filename == f"{top}/__init__.py" for m in members)
    return f"{shown}/ ({'a Python package' if package else 'a folder'}, {_files(len(members))})"


__all__ = ["METADATA", "REFUSALS", "FolderError", "HandIn", "class_notes", "clear_folder", "literal", "notebook_text",
           "own_files", "read_handin", "stripped_notebook"]
