"""The lessons and the explorer in a real browser: Debian's Chromium driven by Playwright's Python package.

Run with ``make e2e`` (or ``.venv/bin/python -m pytest tests/e2e``). These
tests are collected only when they are asked for by path: ``make test`` runs
``pytest ... tests`` and leaves them out (they need a Chromium and a few
minutes), and ``pytest tests/e2e`` runs them.

The servers are started once per run on 127.0.0.1 (JupyterLab, with
``--allow-root`` when the run is root; Voilà), on a copy of ``lessons/`` in
``build/e2e/lessons`` so that nothing the browser saves touches the
repository. Their logs, the screenshots and ``timings.json`` go to
``build/e2e/``.
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
OUT = ROOT / "build" / "e2e"
CHROMIUM = os.environ.get("GRAPHKIN_CHROMIUM", "/usr/bin/chromium")


def pytest_ignore_collect(collection_path, config):
    """Leave the browser tests out unless a path given to pytest lies in this folder."""
    if collection_path == HERE / "conftest.py" or not collection_path.name.startswith("test_"):
        return None
    root = Path(config.invocation_params.dir)
    for arg in config.invocation_params.args:
        if arg.startswith("-"):
            continue
        asked = (root / arg.split("::")[0]).resolve()
        if asked == HERE or HERE in asked.parents:
            return None
    return True


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_http(url: str, proc, log: Path, timeout: float = 90.0):
    """Until ``url`` answers; fails with the server's last log lines if it dies or never answers."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if proc.poll() is not None:
            pytest.fail(f"the server stopped (exit {proc.returncode}):\n{log.read_text()[-2000:]}")
        try:
            with urllib.request.urlopen(url, timeout=2):
                return
        except OSError:
            time.sleep(0.2)
    pytest.fail(f"{url} did not answer within {timeout:.0f} s:\n{log.read_text()[-2000:]}")


def stop(proc):
    if proc.poll() is None:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()


@pytest.fixture(scope="session")
def out() -> Path:
    OUT.mkdir(parents=True, exist_ok=True)
    for old in OUT.glob("FAILED-*.png"):  # a screenshot of an earlier run's failure
        old.unlink()
    return OUT


@pytest.fixture(scope="session")
def workdir(out) -> Path:
    """A copy of the lessons for the browser to run (and save)."""
    lessons = out / "lessons"
    shutil.rmtree(lessons, ignore_errors=True)
    lessons.mkdir()
    for nb in sorted((ROOT / "lessons").glob("*.ipynb")):
        data = json.loads(nb.read_text(encoding="utf-8"))
        for cell in data["cells"]:
            # A folded cell shows no prompt, and the prompt's number is how the test knows a cell has run.
            cell["metadata"].get("jupyter", {}).pop("source_hidden", None)
        (lessons / nb.name).write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    return lessons


def _server(cmd, log: Path, url: str, env=None):
    with open(log, "w", encoding="utf-8") as f:
        proc = subprocess.Popen(cmd, stdout=f, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                start_new_session=True, env=env)
    wait_http(url, proc, log)
    return proc


@pytest.fixture(scope="session")
def jupyterlab(out, workdir):
    """JupyterLab on 127.0.0.1 serving the lessons' copy: no token, no autosave, every cell in the page."""
    settings, workspaces = out / "lab-settings", out / "lab-workspaces"
    for folder in (settings, workspaces):  # no layout of an earlier run restored
        shutil.rmtree(folder, ignore_errors=True)
    for plugin, values in {
        "@jupyterlab/docmanager-extension/plugin": {"autosave": False},
        # Every cell stays in the page (no windowing), so the test can find each one.
        "@jupyterlab/notebook-extension/tracker": {"windowingMode": "none"},
        "@jupyterlab/apputils-extension/notification": {"fetchNews": "false", "checkForUpdates": False},
    }.items():
        path = settings / f"{plugin}.jupyterlab-settings"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(values))
    env = dict(os.environ, JUPYTERLAB_SETTINGS_DIR=str(settings), JUPYTERLAB_WORKSPACES_DIR=str(workspaces),
               PYDEVD_DISABLE_FILE_VALIDATION="1")
    port = free_port()
    cmd = [sys.executable, "-m", "jupyterlab", "--no-browser", f"--port={port}", "--ServerApp.ip=127.0.0.1",
           "--IdentityProvider.token=", "--ServerApp.password=", f"--ServerApp.root_dir={workdir}"]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        cmd.append("--allow-root")
    url = f"http://127.0.0.1:{port}"
    proc = _server(cmd, out / "jupyterlab.log", f"{url}/api/status", env=env)
    yield url
    stop(proc)


@pytest.fixture(scope="session")
def voila(out, workdir):
    """Voilà on 127.0.0.1 serving the lessons' copy, tracebacks shown."""
    port = free_port()
    cmd = [sys.executable, "-m", "voila", str(workdir), "--no-browser", f"--port={port}", "--Voila.ip=127.0.0.1",
           "--show_tracebacks=True", "--theme=light",
           # A closed page's kernel goes (Voilà's own shutdown request on closing is refused for want of XSRF).
           "--MappingKernelManager.cull_idle_timeout=20", "--MappingKernelManager.cull_interval=10"]
    url = f"http://127.0.0.1:{port}"
    proc = _server(cmd, out / "voila.log", f"{url}/", env=dict(os.environ, PYDEVD_DISABLE_FILE_VALIDATION="1"))
    yield url
    stop(proc)


@pytest.fixture(scope="session")
def browser():
    """Debian's Chromium, headless, driven by Playwright (never ``playwright install``: nothing is downloaded)."""
    if not os.path.exists(CHROMIUM):
        pytest.fail(f"no Chromium at {CHROMIUM}: apt-get install chromium (make e2e does it as root), "
                    "or set GRAPHKIN_CHROMIUM")
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=["--no-sandbox"])
        yield b
        b.close()


@pytest.fixture(scope="session")
def timings(out):
    """Measurements gathered by the tests, written to build/e2e/timings.json at the end."""
    found: dict = {}
    yield found
    (out / "timings.json").write_text(json.dumps(found, indent=1, ensure_ascii=False), encoding="utf-8")
