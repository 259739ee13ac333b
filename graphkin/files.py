"""Reading and writing the files graphkin's commands take and make: the one atomic writer, the one JSON writer.

Every file is written to a temporary file in the same folder, then moved into
place with :func:`os.replace`: a reader never sees half a file, and an
interrupted or failed write leaves the old file (or none). Destinations are
checked before any work is done, so a bad path costs nothing.
"""

from __future__ import annotations

import contextlib
import errno
import os
import signal
import threading
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

    The temporary file of :func:`replacing` is made owner-only; a file moved
    into place from it gets these instead, so a figure or a sheet can be read by whoever
    could read one written the ordinary way.
    """
    return (0o777 if executable else 0o666) & ~_UMASK


def write_text(path: str | Path, text: str, what: str = "output") -> Path:
    """Write ``text`` (UTF-8) to ``path`` atomically (:func:`replacing`)."""
    return write_bytes(path, text.encode("utf-8"), what)


def write_bytes(path: str | Path, data: bytes, what: str = "output", *, executable: bool = False) -> Path:
    """Write ``data`` to ``path`` atomically (:func:`replacing`), with execute bits for a script."""
    with replacing(path, what, executable=executable) as tmp:
        with open(tmp, "wb") as f:
            f.write(data)
    return Path(path)


@contextlib.contextmanager
def replacing(path: str | Path, what: str = "output", *, executable: bool = False):
    """Write ``path`` whole or not at all: yields a temporary file beside it, moved into place at the end.

    graphkin's one way of writing a file a person gets. The caller writes the
    temporary file (any writer that takes a path: ``open``, ``savefig``); when
    the ``with`` block ends normally the file gets the permissions a plain
    ``open`` would give it (plus execute bits for a script) and replaces
    ``path`` with :func:`os.replace`. A reader never sees half a file, and an
    error or a Ctrl-C leaves the old file (or none) and no temporary file: its
    name is chosen inside the cleanup's reach.

    Parameters
    ----------
    path : str or Path
        The file to write; its folder is made if missing.
    what : str
        What the file is, or the option that named it (``"-o"``,
        ``"--figure"``), to start the message of an error.
    executable : bool
        Give the file execute bits (a script).

    Yields
    ------
    Path
        The temporary file, in ``path``'s folder.

    Raises
    ------
    GraphkinError
        If the file cannot be written: the message names ``path`` (never the
        temporary file) and the reason.
    """
    p = check_destination(path, what)
    tmp = None
    try:
        p.parent.mkdir(parents=True, exist_ok=True)
        for _ in range(100):
            tmp = p.parent / f".{p.name}.{os.urandom(6).hex()}.tmp"
            try:
                os.close(os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600))
                break
            except FileExistsError:
                tmp = None
        else:  # pragma: no cover - 100 random names all taken
            raise FileExistsError(errno.EEXIST, f"no free temporary name beside {p}")
        yield tmp
        # The temporary file was made owner-only: the file gets the permissions a plain open() would give it.
        os.chmod(tmp, file_mode(executable))
        os.replace(tmp, p)
        tmp = None
    except OSError as exc:
        raise GraphkinError(f"{what} {p}: cannot be written ({exc.strerror or exc})") from None
    finally:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass


@contextlib.contextmanager
def interrupts_deferred():
    """Hold Ctrl-C (SIGINT) until the block ends, then raise :class:`KeyboardInterrupt` there.

    A KeyboardInterrupt raised inside a C extension's call can come out as
    another error: matplotlib's transforms (pybind11) report one that lands
    while converting their arguments as a ``TypeError``, and the command would
    print a traceback instead of "interrupted". Inside :func:`replacing` the
    deferred interrupt still discards the temporary file: the old file (or
    none) stays. Only the main thread with Python's own handler installed is
    changed; anywhere else the block runs as it is.
    """
    if threading.current_thread() is not threading.main_thread() or \
            signal.getsignal(signal.SIGINT) is not signal.default_int_handler:
        yield
        return
    caught = []
    previous = signal.signal(signal.SIGINT, lambda signum, frame: caught.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
    if caught:
        raise KeyboardInterrupt


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
        line = data.count(b"\n", 0, data.index(b"\x00")) + 1
        raise GraphkinError(f"{what} {name}: line {line}: a NUL byte; this is not a text file (save it as UTF-8 text)")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        # Editors on some systems still save Latin-1 or Windows-1252: say which character it would be there.
        line = data[:exc.start].count(b"\n") + 1
        guess = data[exc.start:exc.start + 1].decode("cp1252", errors="replace")
        raise GraphkinError(f"{what} {name}: is not UTF-8 text (line {line}, byte 0x{data[exc.start]:02x}, "
                            f"{guess!r} in Latin-1); save it as UTF-8") from None


def json_text(data) -> str:
    """The JSON text of plain data, indented by two spaces, as ``json.dumps(data, indent=2, ensure_ascii=False)``.

    Written by orjson: a whole cycle's half a million numbers take ~12 ms, where json's indented
    encoder (pure Python, a call per number) takes ~0.3 s. The text is laid out as json lays it out, line for
    line; numbers are the same shortest round-trip ones, spelt ``2.5e-8`` where json writes ``2.5e-08``, and
    one that is not finite (NaN, ±inf) is ``null`` (json writes ``NaN``, which JSON does not have). numpy
    arrays and scalars are written as lists and numbers.

    Parameters
    ----------
    data : dict, list or scalar
        Plain data (what ``json.dumps`` takes).

    Returns
    -------
    str

    Examples
    --------
    >>> print(json_text({"x": [0.1, None, 2], "ok": [True]}))
    {
      "x": [
        0.1,
        null,
        2
      ],
      "ok": [
        true
      ]
    }
    """
    import orjson

    options = orjson.OPT_INDENT_2 | orjson.OPT_SERIALIZE_NUMPY | orjson.OPT_NON_STR_KEYS
    return orjson.dumps(data, option=options).decode("utf-8")
