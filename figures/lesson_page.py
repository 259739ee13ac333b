"""The README's picture of the lessons: a page of lesson 01 as a student sees it, in a real browser.

Voilà renders ``lessons/01_newtonian_method.ipynb`` (run, code hidden) on 127.0.0.1; Debian's
Chromium driven by Playwright's Python package (the ``e2e`` extra; never ``playwright install``) takes
the part of the page from the heading "The free body and its equations" through the equations it is
drawn beside, and the PNG is reduced to a 256-colour palette so that it stays small (< 300 kB).

Run from the repository root: ``.venv/bin/python figures/lesson_page.py`` (``GRAPHKIN_CHROMIUM`` names
another Chromium). Writes ``docs/images/lesson01_free_body.png``.
"""

from __future__ import annotations

import io
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

from PIL import Image

from graphkin.files import replacing

ROOT = Path(__file__).resolve().parents[1]
LESSON = "01_newtonian_method.ipynb"
HEADING = "The free body and its equations"
OUT = ROOT / "docs" / "images" / "lesson01_free_body.png"
CHROMIUM = os.environ.get("GRAPHKIN_CHROMIUM", "/usr/bin/chromium")
WIDTH, HEIGHT = 1150, 772  # CSS pixels of the part of the page kept: the heading through the matrix


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_http(url: str, proc, timeout: float = 90.0):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if proc.poll() is not None:
            sys.exit(f"lesson_page: Voilà stopped (exit {proc.returncode})")
        try:
            with urllib.request.urlopen(url, timeout=2):
                return
        except OSError:
            time.sleep(0.2)
    sys.exit(f"lesson_page: {url} did not answer within {timeout:.0f} s")


def screenshot(url: str) -> bytes:
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=["--no-sandbox"])
        page = browser.new_context(viewport={"width": WIDTH + 40, "height": HEIGHT}, device_scale_factor=1).new_page()
        page.goto(url, wait_until="load", timeout=180_000)
        heading = page.get_by_role("heading", name=HEADING)
        heading.wait_for(timeout=180_000)
        page.wait_for_function("document.querySelectorAll('.jp-OutputArea-output img').length >= 2", timeout=180_000)
        page.wait_for_timeout(1500)  # MathJax typesets the equations after the page has loaded
        heading.scroll_into_view_if_needed()
        box = heading.bounding_box()
        top = page.evaluate("window.scrollY") + box["y"] - 12
        page.set_viewport_size({"width": WIDTH + 40, "height": int(top + HEIGHT + 50)})
        png = page.screenshot(full_page=True, clip={"x": max(box["x"] - 16, 0), "y": top, "width": WIDTH,
                                                    "height": HEIGHT})
        browser.close()
    return png


def main():
    if not os.path.exists(CHROMIUM):
        sys.exit(f"lesson_page: no Chromium at {CHROMIUM} (apt-get install chromium, or set GRAPHKIN_CHROMIUM)")
    with tempfile.TemporaryDirectory(prefix="graphkin-lesson-page-") as tmp:
        shutil.copy(ROOT / "lessons" / LESSON, tmp)
        port = free_port()
        log = open(Path(tmp) / "voila.log", "w", encoding="utf-8")  # noqa: SIM115 (open for the server's life)
        proc = subprocess.Popen([sys.executable, "-m", "voila", tmp, "--no-browser", f"--port={port}",
                                 "--Voila.ip=127.0.0.1", "--theme=light"], stdout=log, stderr=subprocess.STDOUT,
                                stdin=subprocess.DEVNULL, start_new_session=True)
        try:
            wait_http(f"http://127.0.0.1:{port}/", proc)
            png = screenshot(f"http://127.0.0.1:{port}/voila/render/{LESSON}")
        finally:
            proc.send_signal(signal.SIGTERM)
            proc.wait(timeout=30)
            log.close()
    image = Image.open(io.BytesIO(png)).convert("RGB").quantize(colors=256, method=Image.Quantize.MEDIANCUT)
    with replacing(OUT, "the lesson's picture") as tmp_path:
        image.save(tmp_path, format="PNG", optimize=True)
    print(f"{OUT.relative_to(ROOT)}: {image.width} × {image.height} px, {OUT.stat().st_size / 1024:.0f} kB")


if __name__ == "__main__":
    main()
