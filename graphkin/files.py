"""Reading and writing the files graphkin's commands take and make.

Every file is written to a temporary file in the same folder, then moved into
place with :func:`os.replace`: a reader never sees half a file, and an
interrupted or failed write leaves the old file (or none). Destinations are
checked before any work is done, so a bad path costs nothing.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from .errors import GraphkinError

_UMASK = os.umask(0)
os.umask(_UMASK)

MAX_INPUT_BYTES = 10_000_000
"""Largest answers or roster file read (10 MB: a course of thousands is far below it)."""


def check_destination(path: str | Path, what: str = "output") -> Path:
    """The path, if a file can be written there; a clear error naming it if not."""
    p = Path(path)
    if p.is_dir():
        raise GraphkinError(f"{what} {p}: is a folder, not a file")
    parent = p.parent if str(p.parent) else Path(".")
    if parent.exists() and not parent.is_dir():
        raise GraphkinError(f"{what} {p}: {parent} is a file, not a folder")
    if parent.exists() and not os.access(parent, os.W_OK):
        raise GraphkinError(f"{what} {p}: the folder {parent} cannot be written")
    return p


def write_text(path: str | Path, text: str, what: str = "output") -> Path:
    """Write ``text`` (UTF-8) to ``path`` atomically: a temporary file, then :func:`os.replace`."""
    return write_bytes(path, text.encode("utf-8"), what)


def write_bytes(path: str | Path, data: bytes, what: str = "output", *, executable: bool = False) -> Path:
    """Write ``data`` to ``path`` atomically: a temporary file in the same folder, then :func:`os.replace`.

    The file gets the permissions a plain ``open`` would give it (the
    temporary file's are owner-only), plus execute bits for a script.
    """
    p = check_destination(path, what)
    try:
        p.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=p.parent, prefix=f".{p.name}.", suffix=".tmp")
    except OSError as exc:
        raise GraphkinError(f"{what} {p}: cannot be written ({exc.strerror})") from None
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.chmod(tmp, (0o777 if executable else 0o666) & ~_UMASK)
        os.replace(tmp, p)
    except BaseException as exc:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        if isinstance(exc, OSError):
            raise GraphkinError(f"{what} {p}: cannot be written ({exc.strerror})") from None
        raise
    return p


def read_text(path: str | Path, what: str) -> str:
    """A UTF-8 text file (a byte-order mark is fine), at most :data:`MAX_INPUT_BYTES`; ``-`` reads stdin."""
    import sys

    try:
        if str(path) == "-":
            data = sys.stdin.buffer.read(MAX_INPUT_BYTES + 1)
            name = "standard input"
        else:
            with open(path, "rb") as f:
                data = f.read(MAX_INPUT_BYTES + 1)
            name = str(path)
    except OSError as exc:
        raise GraphkinError(f"{what} {path}: cannot be read ({exc.strerror})") from None
    if len(data) > MAX_INPUT_BYTES:
        raise GraphkinError(f"{what} {name}: larger than {MAX_INPUT_BYTES // 1_000_000} MB")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise GraphkinError(f"{what} {name}: is not UTF-8 text (byte {exc.start}); save it as UTF-8") from None
