"""The animation: one view and one force scale for every frame, and the GIF, MP4 and web page it is written as."""

from __future__ import annotations

import html.parser
import io
import os
import stat
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from graphkin import catalog, draw
from graphkin.draw import films
from graphkin.draw.animation import Film, joint_forces, loads
from graphkin.draw.axes import MM
from graphkin.errors import GraphkinError
from graphkin.graphical import construct_forces

FRAMES = 5


@pytest.fixture(scope="module")
def cutter():
    return catalog.load("strip_cutter")


@pytest.fixture(scope="module")
def film(cutter):
    return draw.animate(cutter, frames=FRAMES, fps=10, dpi=30)


@pytest.fixture(scope="module")
def constructions(cutter):
    kin = cutter.kinematics(at=np.linspace(0.0, 2 * np.pi, 8, endpoint=False))  # every 45°
    return [construct_forces(kin, i) for i in range(kin.n)]


def test_one_view_for_every_frame_holds_every_joint_and_arrow(constructions):
    f = Film(constructions, dpi=30)
    views, reach = set(), []
    for c in constructions:
        ax = f.draw(c).axes[0]
        views.add((ax.get_xlim(), ax.get_ylim()))
        ends = [(X, X + F / f.scale) for _, F, X in joint_forces(c) + loads(c)]
        reach += [p for pair in ends for p in pair]
        reach += [np.asarray(p) * MM for pts in c.points.values() for p in pts.values()]
    assert len(views) == 1
    (x0, x1), (y0, y1) = views.pop()
    reach = np.array(reach)
    assert np.all((reach[:, 0] > x0) & (reach[:, 0] < x1) & (reach[:, 1] > y0) & (reach[:, 1] < y1))


def test_one_force_scale_draws_every_arrow(constructions):
    f = Film(constructions, dpi=30)
    largest = max(float(np.hypot(*F)) for c in constructions for _, F, _ in joint_forces(c) + loads(c))
    size = max(float(np.ptp(np.asarray([p for pts in c.points.values() for p in pts.values()]) * MM, axis=0).max())
               for c in constructions)
    # Round (1, 2 or 5 times a power of ten), and the largest force of the turn not longer than LONGEST of the size.
    mantissa = f.scale / 10 ** np.floor(np.log10(f.scale))
    assert min(abs(mantissa - m) for m in (1, 2, 5)) < 1e-9
    assert largest / f.scale <= 0.35 * size * 1.000001
    cut = 0
    for c in constructions:
        f.draw(c)
        cut += any(name == "Fc3" for name, _, _ in loads(c))
        for name, F, X in joint_forces(c) + loads(c):
            tail, tip = np.asarray(f.drawn.ends[name])
            assert f.drawn.arrows[name] in f.ax.patches
            assert np.allclose(tail, X) and np.allclose(tip - tail, F / f.scale)
    assert cut == 1  # the cutting force, drawn at 135°, the one frame inside the cut (124° to 156°)
    texts = [t.get_text() for t in f.figure.axes[0].texts]
    assert any(f"(1 mm = {f.scale:g} N)" in t for t in texts), texts


def test_the_polygons_close_and_keep_their_panels(constructions):
    f = Film(constructions, polygons=True, dpi=30)
    assert sorted(f.ax_polygons) == [2, 3, 4]
    views = []
    for c in constructions:
        f.draw(c)
        for link, ax in f.ax_polygons.items():
            names = [k for k in f.drawn.ends if k.startswith(f"polygon{link}:")]
            assert names and all(f.drawn.arrows[k] in ax.patches for k in names)
            ends = np.array([f.drawn.ends[k] for k in names])
            assert np.allclose(ends[1:, 0], ends[:-1, 1])  # tip to tail
            assert np.allclose(ends[0, 0], ends[-1, 1], atol=1e-6 * np.ptp(ends))  # closed: the link balances
        views.append([(ax.get_xlim(), ax.get_ylim()) for ax in f.ax_polygons.values()])
    assert all(v == views[0] for v in views)


def test_gif_holds_every_frame_at_the_frame_rate(film, tmp_path):
    path = film.save(tmp_path / "cutter.gif")
    with Image.open(path) as gif:
        assert gif.n_frames == FRAMES
        assert gif.size == film.size
        durations = []
        for k in range(gif.n_frames):
            gif.seek(k)
            durations.append(gif.info["duration"])
    assert durations == [100] * FRAMES  # 10 fps: a tenth of a second each


@pytest.mark.parametrize("fps, ms", [(24, 40), (10, 100), (50, 20), (0.5, 2000)])
def test_gif_frame_time_is_whole_hundredths(fps, ms):
    assert films.gif_duration(fps) == ms


class _Resources(html.parser.HTMLParser):
    """Every URL a page would load: src, href, srcset, poster, data and action attributes."""

    def __init__(self):
        super().__init__()
        self.urls, self.tags = [], []

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        for name, value in attrs:
            if name in ("src", "href", "srcset", "poster", "data", "action", "xlink:href"):
                self.urls.append(value or "")


def test_html_is_one_file_that_loads_nothing(film, tmp_path):
    path = film.save(tmp_path / "cutter.html")
    text = path.read_text(encoding="utf-8")
    page = _Resources()
    page.feed(text)
    assert page.urls and all(u.startswith("data:image/png;base64,") for u in page.urls)
    assert "http:" not in text and "https:" not in text and "//cdn" not in text
    assert "@import" not in text and "url(" not in text and "fetch(" not in text and "XMLHttpRequest" not in text
    assert not ({"link", "iframe", "object", "embed"} & set(page.tags))
    # Every frame is in the page (the first also as the picture shown before the script runs), at the frame rate.
    assert text.count("data:image/png;base64,") == FRAMES + 1
    assert "fps = 10.0" in text and f'max="{FRAMES - 1}"' in text


def test_notebook_shows_the_player(film):
    fragment = film._repr_html_()
    assert fragment.startswith("<div") and fragment.count("data:image/png;base64,") == FRAMES + 1
    assert fragment in film.to_html()


def test_a_failed_write_names_the_path_and_leaves_nothing(film, tmp_path, monkeypatch):
    def full_disk(anim, tmp):
        Path(tmp).write_bytes(b"half a GIF")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(films, "_gif", full_disk)
    target = tmp_path / "out" / "cutter.gif"
    with pytest.raises(GraphkinError) as err:
        film.save(target)
    assert str(target) in str(err.value) and "No space left on device" in str(err.value)
    assert ".tmp" not in str(err.value)
    assert list(target.parent.iterdir()) == []


def test_mp4_frames_go_to_ffmpeg(film, tmp_path, monkeypatch):
    """A stand-in ffmpeg on the PATH: it counts the raw frames piped to it and writes what it was asked for."""
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    fake = bin_dir / "ffmpeg"
    fake.write_text(f"#!{sys.executable}\n"
                    "import sys\n"
                    "args = sys.argv[1:]\n"
                    "data = sys.stdin.buffer.read()\n"
                    "open(args[-1], 'w').write(' '.join(args[:-1]) + f' | {len(data)}')\n")
    fake.chmod(fake.stat().st_mode | stat.S_IXUSR)
    monkeypatch.setenv("PATH", str(bin_dir) + os.pathsep + os.environ.get("PATH", ""))
    path = film.save(tmp_path / "cutter.mp4")
    args, count = path.read_text().split(" | ")
    w, h = film.size
    assert int(count) == FRAMES * w * h * 3  # every frame, as raw RGB
    assert f"-s {w}x{h}" in args and "-framerate 10" in args and "-f mp4" in args and "yuv420p" in args


def test_mp4_without_ffmpeg_is_one_clear_error(film, tmp_path, monkeypatch):
    monkeypatch.setenv("PATH", str(tmp_path))
    with pytest.raises(GraphkinError, match="needs ffmpeg"):
        film.save(tmp_path / "cutter.mp4")
    assert not (tmp_path / "cutter.mp4").exists()


def test_frames_are_png_of_one_size(film):
    sizes = {Image.open(io.BytesIO(png)).size for png in film.frames}
    assert sizes == {film.size} and len(film.frames) == FRAMES and film.fps == 10.0


def test_progress_is_called_once_a_frame(cutter):
    ticks = []
    draw.animate(cutter, frames=3, dpi=20, progress=ticks.append)
    assert ticks == [1, 1, 1]


@pytest.mark.parametrize("kwargs, named", [
    ({"frames": 0}, "--frames"), ({"frames": -2}, "--frames"), ({"frames": 2.5}, "--frames"),
    ({"fps": 0}, "--fps"), ({"fps": -1}, "--fps"), ({"fps": float("nan")}, "--fps"), ({"fps": 1000}, "--fps"),
    ({"dpi": 0}, "--dpi"), ({"path": "cutter.avi"}, "cutter.avi"),
])
def test_bad_arguments_are_one_error_each(cutter, kwargs, named):
    with pytest.raises(GraphkinError, match=named.replace(".", r"\.")):
        draw.animate(cutter, **kwargs)


@pytest.mark.parametrize("name, why", [("double_slider", "slider")])
def test_a_problem_without_a_turn_is_refused(name, why):
    with pytest.raises(GraphkinError, match=why):
        draw.animate(catalog.load(name), frames=2)
