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

from graphkin.errors import GraphkinError

_UMASK = os.umask(0)
os.umask(_UMASK)

MAX_INPUT_BYTES = 10_000_000
"""Largest answers or roster file read (10 MB: a course of thousands is far below it)."""


def check_destination(path: str | Path, what: str = "output") -> Path:
    """The path, if a file can be written there; a clear error naming it if not."""
    p = Path(path)
    if p.is_dir():
        raise GraphkinError(f"{what} {p}: is a folder, not a file")
    check_folder(p.parent if str(p.parent) else Path("."), what, shown=p)
    return p


def check_folder(path: str | Path, what: str = "output", *, shown=None) -> Path:
    """The folder, if files can be written in it (made if missing); a clear error naming it if not.

    Walks up to the first folder that exists: a file on the way (``out.txt/x.png``)
    or a folder that cannot be written is refused before any work is done.
    """
    p = Path(path)
    shown = shown or p
    q = p
    while not q.exists():
        if q.parent == q:
            break
        q = q.parent
    if q.exists() and not q.is_dir():
        raise GraphkinError(f"{what} {shown}: {q} is a file, not a folder")
    if q.exists() and not os.access(q, os.W_OK | os.X_OK):
        raise GraphkinError(f"{what} {shown}: the folder {q} cannot be written")
    return p


def file_mode(executable: bool = False) -> int:
    """The permissions a plain ``open(path, "w")`` gives a new file (under the current umask), plus execute bits.

    :func:`tempfile.mkstemp` makes its file owner-only; a file moved into place
    from it gets these instead, so a figure or a sheet can be read by whoever
    could read one written the ordinary way.
    """
    return (0o777 if executable else 0o666) & ~_UMASK


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
        os.chmod(tmp, file_mode(executable))
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


def read_text(path: str | Path, what: str, *, shown: str | None = None) -> str:
    """A UTF-8 text file (a byte-order mark is fine), at most :data:`MAX_INPUT_BYTES`; ``-`` reads stdin.

    Parameters
    ----------
    path : str or Path
    what : str
        What the file is ("problem", "roster"), to start the message of an error.
    shown : str, optional
        The name to show in messages (default: the path).

    Raises
    ------
    GraphkinError
        One sentence naming the file and what is wrong: cannot be read, too
        large, UTF-16, binary, or not UTF-8 (with the byte and a hint).
    """
    import sys

    name = shown or ("standard input" if str(path) == "-" else str(path))
    try:
        if str(path) == "-":
            data = sys.stdin.buffer.read(MAX_INPUT_BYTES + 1)
        else:
            with open(path, "rb") as f:
                data = f.read(MAX_INPUT_BYTES + 1)
    except OSError as exc:
        raise GraphkinError(f"{what} {name}: cannot be read ({exc.strerror})") from None
    if len(data) > MAX_INPUT_BYTES:
        raise GraphkinError(f"{what} {name}: larger than {MAX_INPUT_BYTES // 1_000_000} MB; is it the right file?")
    if data[:2] in (b"\xff\xfe", b"\xfe\xff"):
        raise GraphkinError(f"{what} {name}: is UTF-16 text; save it as UTF-8")
    if b"\x00" in data:
        raise GraphkinError(f"{what} {name}: is not a text file (it holds NUL bytes)")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        # Editors on some systems still save Latin-1 or Windows-1252: say which character it would be there.
        line = data[:exc.start].count(b"\n") + 1
        guess = data[exc.start:exc.start + 1].decode("cp1252", errors="replace")
        raise GraphkinError(f"{what} {name}: is not UTF-8 text (line {line}, byte 0x{data[exc.start]:02x}, "
                            f"{guess!r} in Latin-1); save it as UTF-8") from None
