"""``graphkin explore``: a problem's interactive explorer as a web page, for a teacher at a projector.

::

    graphkin explore PROBLEM [--port N] [--base-url PATH] [--no-browser]
    graphkin explore PROBLEM -o page.html [--n N] [--no-polygons]

With ``-o``, the cycle is solved once (:func:`graphkin.scene.scene`) and written as one self-contained HTML file
that draws every position in the browser (:func:`graphkin.scene.write_page`): the scene's JSON and the drawing's
JavaScript are in the file, which works from disk with the network off and needs no Python to look at. Nothing is
served; the command prints the file's name and size.

`Voilà <https://voila.readthedocs.io>`_ serves one notebook on 127.0.0.1 that
holds the problem's explorer (:func:`graphkin.widgets.explore`) and nothing
else: no code, no cells to run. The command prints the page's address, opens
it in the desktop's browser where there is one, and serves until Ctrl-C, which
stops Voilà and its kernels and prints one line (exit code 130). Behind a JupyterHub, ``--base-url`` serves the
page under the path the hub's proxy forwards whole (jupyter-server-proxy's ``/user/NAME/proxy/absolute/PORT/``;
``{port}`` in it stands for the port), as ``docs/hub.md`` shows.

A problem that is neither in the catalog nor a readable problem file is a
:class:`graphkin.errors.GraphkinError` (one line, exit code 2), reported
before anything is started; so is a missing Voilà.
"""

from __future__ import annotations

# Only what building the parser needs is imported here: `graphkin` builds every subcommand's parser, and
# `graphkin solve` should not pay for sockets and subprocesses (each function imports what it runs).
import json
import os
import re
import sys
from pathlib import Path

from graphkin.errors import GraphkinError

READY = 60.0
"""Seconds Voilà is given to start listening."""

CULL = ("--MappingKernelManager.cull_idle_timeout=120", "--MappingKernelManager.cull_interval=30")
"""Each page has its own kernel, and Voilà's request to shut it down when the page closes is refused
(no XSRF token): a kernel that no page is connected to is shut down after two idle minutes instead
(a page left open keeps its kernel)."""


def add_parser(sub) -> None:
    """Add ``explore`` to the ``graphkin`` subcommands."""
    e = sub.add_parser("explore", help="a problem's interactive explorer as a web page (Voilà on 127.0.0.1), "
                       "for a projector; Ctrl-C stops it")
    e.add_argument("problem", metavar="PROBLEM", help="a catalog problem (graphkin list) or a problem file")
    e.add_argument("--port", type=int, default=0, help="the port on 127.0.0.1 (default: a free one)")
    e.add_argument("--base-url", default="/", metavar="PATH", help="serve under this path, behind a JupyterHub's "
                   "proxy: /user/NAME/proxy/absolute/{port}/ ({port} stands for the port; default /)")
    e.add_argument("--no-browser", action="store_true", help="print the address only; do not open a browser")
    e.add_argument("-o", "--output", metavar="PAGE.html", help="write one self-contained HTML page that draws the "
                   "presolved cycle in the browser (no server, no network) instead of serving the explorer")
    e.add_argument("--n", type=int, default=None, help="with -o: crank angles over the turn (default 360)")
    e.add_argument("--no-polygons", action="store_true", help="with -o: leave the graphical route's force "
                   "polygons out (a smaller page, built faster)")
    e.add_argument("--motion", action="store_true", help="with -o: the velocity and acceleration polygons too, "
                   "with a toggle on the page")
    e.add_argument("--units", metavar="SI|US|FILE", help="with -o: the units a reader may switch to beside SI, "
                   "when hovering a force: US (in, lbf, lbf·ft) or a units file (TOML)")


def notebook(source: str, title: str) -> dict:
    """The notebook Voilà shows: the problem's title and its explorer.

    Parameters
    ----------
    source : str
        A catalog name, or a problem file's absolute path.
    title : str
        The problem's title, as the page's heading.

    Returns
    -------
    dict
        The notebook (nbformat 4) as plain data.
    """
    code = ("from graphkin import catalog\n"
            "from graphkin.widgets import explore\n\n"
            f"explore(catalog.load({source!r}))")
    return {
        "cells": [
            {"cell_type": "markdown", "id": "title", "metadata": {}, "source": f"## {title}"},
            {"cell_type": "code", "id": "explorer", "metadata": {}, "execution_count": None, "outputs": [],
             "source": code},
        ],
        "metadata": {"kernelspec": {"display_name": "Python 3 (ipykernel)", "language": "python", "name": "python3"},
                     "language_info": {"name": "python"}},
        "nbformat": 4,
        "nbformat_minor": 5,
    }


def base_url(text: str, port: int) -> str:
    """The path the page is served under: ``text`` with ``{port}`` replaced, one slash at each end.

    Examples
    --------
    >>> base_url("/", 8866), base_url("user/ada/proxy/absolute/{port}", 8866)
    ('/', '/user/ada/proxy/absolute/8866/')
    """
    path = text.replace("{port}", str(port)).strip("/")
    if not re.fullmatch(r"[A-Za-z0-9._~%@!$&'()*+,;=:/-]*", path) or "//" in path or \
            any(part in (".", "..") for part in path.split("/")):
        raise GraphkinError(f"--base-url must be a path such as /user/NAME/proxy/absolute/{{port}}/, got {text!r}")
    return f"/{path}/" if path else "/"


def run(args) -> int:
    """Carry out ``graphkin explore``; returns the exit code (130 after Ctrl-C)."""
    import subprocess
    import tempfile

    from graphkin import catalog

    problem = catalog.load(args.problem)  # a bad name or file: GraphkinError, before anything starts
    if args.output is not None:
        return _write(problem, args)
    if args.n is not None or args.no_polygons or args.motion or args.units:
        raise GraphkinError("--n, --no-polygons, --motion and --units go with -o PAGE.html (the page of the "
                            "presolved cycle)")
    source = args.problem if args.problem in catalog.names() else str(Path(args.problem).resolve())
    from graphkin.optional import available, missing

    if not available("voila"):
        raise missing("voila", "graphkin explore")
    if not 0 <= args.port < 65536:
        raise GraphkinError(f"--port must be 0–65535, got {args.port}")
    port = args.port or _free_port()
    base = base_url(args.base_url, port)
    url = f"http://127.0.0.1:{port}{base}"
    with tempfile.TemporaryDirectory(prefix="graphkin-explore-") as folder:
        # The page Voilà serves and its log live in this private folder, deleted on the way out: no user file,
        # so no temporary-then-rename dance.
        page = Path(folder) / f"{Path(source).stem}.ipynb"
        page.write_text(json.dumps(notebook(source, problem.title), ensure_ascii=False, indent=1), encoding="utf-8")
        log_path = Path(folder) / "voila.log"
        with open(log_path, "w", encoding="utf-8") as log:
            # A session of its own: Ctrl-C reaches graphkin only, which stops Voilà in order (no second
            # shutdown report from Voilà), and Voilà's log stays in the file, out of the teacher's way.
            voila = subprocess.Popen([sys.executable, "-m", "voila", str(page), "--no-browser", f"--port={port}",
                                      "--Voila.ip=127.0.0.1", f"--Voila.base_url={base}", "--theme=light",
                                      "--show_tracebacks=True", *CULL],
                                     cwd=folder, stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
                                     start_new_session=True)
            stop_on = _stop_on_sigterm()
            try:
                _wait_listening(voila, port, log_path)
                print(f"graphkin: the explorer of {problem.title} is at {url} (Ctrl-C stops it)", flush=True)
                if not args.no_browser and _has_desktop():
                    import webbrowser

                    webbrowser.open(url)
                voila.wait()
                raise GraphkinError(f"Voilà stopped: {_last_line(log_path)}")
            except KeyboardInterrupt:
                print("graphkin: explorer stopped", file=sys.stderr)
                return 130
            finally:
                _stop(voila)
                stop_on()


def _write(problem, args) -> int:
    """``explore -o``: the self-contained page of the presolved cycle."""
    from graphkin.files import check_destination
    from graphkin.scene import scene, write_page

    path = check_destination(args.output, "-o")  # a folder or an unwritable place is refused before the solve
    from graphkin.units.systems import unit_system

    data = scene(problem, 360 if args.n is None else args.n, polygons=not args.no_polygons, motion=args.motion,
                 units=unit_system(args.units))
    write_page(data, path, "-o")
    n = data["n"]
    print(f"graphkin: wrote {path} ({path.stat().st_size / 1e6:.2f} MB, {n} position{'s' * (n != 1)} of "
          f"{problem.title}); open it in a browser, no server needed", file=sys.stderr, flush=True)
    return 0


def _stop_on_sigterm():
    """Let SIGTERM and SIGHUP (a closed terminal, a process manager) stop the page as Ctrl-C does; returns the undo."""
    import signal

    if not _main_thread():
        return lambda: None

    def interrupt(signum, frame):
        raise KeyboardInterrupt

    names = [n for n in ("SIGTERM", "SIGHUP") if hasattr(signal, n)]
    before = {n: signal.signal(getattr(signal, n), interrupt) for n in names}
    return lambda: [signal.signal(getattr(signal, n), h) for n, h in before.items()]


def _free_port() -> int:
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _wait_listening(voila, port: int, log_path: Path):
    """Until Voilà accepts connections (a request for the page itself would run the notebook once for nothing)."""
    import contextlib
    import socket
    import time

    end = time.monotonic() + READY
    while time.monotonic() < end:
        if voila.poll() is not None:
            raise GraphkinError(f"Voilà did not start: {_last_line(log_path)}")
        with contextlib.suppress(OSError), socket.create_connection(("127.0.0.1", port), timeout=0.5):
            return
        time.sleep(0.1)
    raise GraphkinError(f"Voilà did not listen on 127.0.0.1:{port} within {READY:.0f} s: {_last_line(log_path)}")


def _last_line(log_path: Path) -> str:
    lines = [x.strip() for x in log_path.read_text(encoding="utf-8", errors="replace").splitlines() if x.strip()]
    return lines[-1] if lines else "no message"


def _has_desktop() -> bool:
    """Whether a graphical browser can open: a console browser (lynx, w3m) would take over the terminal."""
    if sys.platform in ("darwin", "win32"):
        return True
    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")) and sys.stdout.isatty()


def _stop(voila):
    """Stop Voilà and its kernels; a second Ctrl-C meanwhile is not a traceback."""
    import signal
    import subprocess

    previous = signal.signal(signal.SIGINT, signal.SIG_IGN) if _main_thread() else None
    try:
        if voila.poll() is None:
            voila.terminate()  # Voilà shuts its kernels down on SIGTERM
            try:
                voila.wait(timeout=15)
            except subprocess.TimeoutExpired:
                os.killpg(voila.pid, signal.SIGKILL)
                voila.wait()
    finally:
        if previous is not None:
            signal.signal(signal.SIGINT, previous)


def _main_thread() -> bool:
    import threading

    return threading.current_thread() is threading.main_thread()
