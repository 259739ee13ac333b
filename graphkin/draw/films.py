"""An animation's frames written as a GIF (Pillow), an MP4 (ffmpeg) or one web page that needs no network.

Every file is written to a temporary file beside it and moved into place
(:func:`graphkin.files.replacing`), so a failed or interrupted write leaves
the old file or none. The web page holds the frames inline as PNG data URLs
and a player of a few lines of script (play and pause, a step either way, a
slider): it opens from a USB stick in a lecture hall with no network, and
loads nothing from anywhere.

A GIF counts time in hundredths of a second: each frame lasts
``round(100 / fps)`` of them, so 24 fps plays at 25. Browsers slow down GIFs
faster than 50 frames a second, hence :data:`MAX_FPS`.
"""

from __future__ import annotations

import base64
import hashlib
import html
import io
import json
import shutil
import subprocess
import tempfile
from pathlib import Path

from graphkin.errors import GraphkinError
from graphkin.files import check_destination, replacing

FORMATS = ("gif", "mp4", "html")
"""The suffixes an animation can be written as."""

MAX_FPS = 50.0
"""The most frames per second: a GIF's shortest frame browsers play as written is 2/100 s."""


def check_fps(fps) -> float:
    """``fps`` as a float if it is above 0 and at most :data:`MAX_FPS`; an error naming ``--fps`` if not."""
    try:
        value = float(fps)
    except (TypeError, ValueError):
        value = float("nan")
    if isinstance(fps, bool) or not 0 < value <= MAX_FPS:
        raise GraphkinError(f"--fps {fps}: give the frames per second, above 0 and at most {MAX_FPS:g}")
    return value


def check_path(path, what: str = "-o") -> Path:
    """The path, if an animation can be written there; a one-line error naming ``what`` and the path if not."""
    p = Path(path)
    fmt = p.suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise GraphkinError(f"{what} {p}: the file must end in .gif, .mp4 or .html")
    if fmt == "mp4" and ffmpeg() is None:
        raise GraphkinError(f"{what} {p}: an MP4 needs ffmpeg, which is not installed here (not on the PATH); "
                            "write a .gif or an .html instead")
    return check_destination(p, what)


def ffmpeg() -> str | None:
    """The ffmpeg program on the PATH, or None."""
    return shutil.which("ffmpeg")


def write(anim, path, what: str = "animation") -> Path:
    """Write ``anim`` (a :class:`graphkin.draw.animation.Animation`) to ``path``, the format chosen by its suffix."""
    p = check_path(path, what)
    fmt = p.suffix.lower().lstrip(".")
    with replacing(p, what) as tmp:
        if fmt == "gif":
            _gif(anim, tmp)
        elif fmt == "mp4":
            _mp4(anim, tmp, what, p)
        else:
            tmp.write_text(html_page(anim), encoding="utf-8")
    return p


def gif_duration(fps: float) -> int:
    """How long a GIF shows each frame [ms]: a whole number of hundredths of a second, at least two."""
    return 10 * max(2, round(100.0 / fps))


def _gif(anim, tmp):
    from PIL import Image

    images = [Image.open(io.BytesIO(png)) for png in anim.frames]
    images[0].save(tmp, format="GIF", save_all=True, append_images=images[1:], duration=gif_duration(anim.fps),
                   loop=0)


def _mp4(anim, tmp, what, shown):
    """H.264 through ffmpeg, the frames piped in as raw RGB (padded to even sizes, which yuv420p needs)."""
    from PIL import Image

    exe = ffmpeg()
    if exe is None:  # removed since the check before the work
        raise GraphkinError(f"{what} {shown}: an MP4 needs ffmpeg, which is not installed here (not on the PATH)")
    w, h = anim.size
    cmd = [exe, "-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", f"{w}x{h}",
           "-framerate", f"{anim.fps:g}", "-i", "-", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white",
           "-c:v", "libx264", "-pix_fmt", "yuv420p", "-movflags", "+faststart", "-f", "mp4", str(tmp)]
    # ffmpeg's messages go to a file, not a pipe: a pipe nobody reads while the frames go in could fill and stall it.
    with tempfile.TemporaryFile() as err:
        proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=err)
        try:
            for png in anim.frames:
                proc.stdin.write(Image.open(io.BytesIO(png)).convert("RGB").tobytes())
            proc.stdin.close()
        except BrokenPipeError:
            pass
        finally:
            code = proc.wait()
        if code:
            err.seek(0)
            lines = err.read().decode("utf-8", "replace").strip().splitlines()
            raise GraphkinError(f"{what} {shown}: ffmpeg failed ({lines[-1] if lines else f'exit code {code}'})")


def html_player(anim) -> str:
    """The frames and a player as an HTML fragment (a notebook shows it inline); nothing is loaded from elsewhere."""
    frames = ["data:image/png;base64," + base64.b64encode(png).decode("ascii") for png in anim.frames]
    # The same animation gives the same page; two players on one page have their own ids.
    key = hashlib.sha1(b"".join(anim.frames[:2]) + str(len(frames)).encode()).hexdigest()[:10]
    w, h = anim.size
    n = len(frames)
    title = html.escape(anim.title or "graphkin animation")
    return _PLAYER.format(id=f"graphkin-anim-{key}", first=frames[0] if frames else "", w=w, h=h, title=title,
                          last=max(n - 1, 0), n=n, frames=json.dumps(frames), fps=json.dumps(anim.fps))


def html_page(anim) -> str:
    """The animation as a whole web page (:func:`html_player` in a page of its own)."""
    return _PAGE.format(title=html.escape(anim.title or "graphkin animation"), player=html_player(anim))


_PAGE = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title}</title>
</head>
<body style="margin:1em;font:15px sans-serif">
{player}
</body>
</html>
"""

_PLAYER = """<div id="{id}" class="graphkin-animation" style="display:inline-block;font:14px sans-serif">
<img src="{first}" width="{w}" height="{h}" alt="{title}" style="display:block;max-width:100%;height:auto">
<div style="display:flex;gap:6px;align-items:center;margin-top:4px">
<button type="button" data-do="play" title="play or pause (space)">Pause</button>
<button type="button" data-do="back" title="a frame back (left arrow)">&#9664;</button>
<button type="button" data-do="next" title="a frame on (right arrow)">&#9654;</button>
<input type="range" min="0" max="{last}" value="0" step="1" style="flex:1" aria-label="frame">
<span data-do="count">1 / {n}</span>
</div>
</div>
<script>
(function () {{
  var root = document.getElementById("{id}");
  var frames = {frames}, fps = {fps};
  var img = root.querySelector("img"), slider = root.querySelector("input");
  var count = root.querySelector("[data-do=count]"), play = root.querySelector("[data-do=play]");
  var i = 0, timer = null;
  function show(k) {{
    i = (k + frames.length) % frames.length;
    img.src = frames[i];
    slider.value = i;
    count.textContent = (i + 1) + " / " + frames.length;
  }}
  function stop() {{ clearInterval(timer); timer = null; play.textContent = "Play"; }}
  function start() {{
    if (timer === null && frames.length > 1) {{
      timer = setInterval(function () {{ show(i + 1); }}, 1000 / fps);
      play.textContent = "Pause";
    }}
  }}
  play.onclick = function () {{ if (timer === null) {{ start(); }} else {{ stop(); }} }};
  root.querySelector("[data-do=back]").onclick = function () {{ stop(); show(i - 1); }};
  root.querySelector("[data-do=next]").onclick = function () {{ stop(); show(i + 1); }};
  slider.oninput = function () {{ stop(); show(+slider.value); }};
  root.tabIndex = 0;
  root.onkeydown = function (e) {{
    if (e.key === " ") {{ play.onclick(); }} else if (e.key === "ArrowLeft") {{ stop(); show(i - 1); }}
    else if (e.key === "ArrowRight") {{ stop(); show(i + 1); }} else {{ return; }}
    e.preventDefault();
  }};
  show(0);
  start();
  if (timer === null) {{ play.textContent = "Play"; }}
}})();
</script>
"""
