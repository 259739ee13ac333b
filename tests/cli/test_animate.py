"""``graphkin animate``: the file it writes, its one line on stderr, and the progress bar at a terminal only."""

from __future__ import annotations

import io

import pytest
from PIL import Image

from graphkin.cli import _common, main


def run(capsys, *argv):
    code = main(["animate", *map(str, argv)])
    out, err = capsys.readouterr()
    return code, out, err


def test_gif_has_the_frames_and_the_rate_asked_for(capsys, tmp_path):
    path = tmp_path / "cutter.gif"
    code, out, err = run(capsys, "strip_cutter", "-o", path, "--frames", 4, "--fps", 5, "--dpi", 30)
    assert code == 0 and out == ""  # no data to print: the message is on stderr
    assert err.count("\n") == 1 and err.startswith("4 frames (") and err.rstrip().endswith(f"written to {path}")
    assert "5 fps" in err and "1 mm = 50 N" in err
    with Image.open(path) as gif:
        assert gif.n_frames == 4 and gif.info["duration"] == 200


def test_html_with_polygons(capsys, tmp_path):
    path = tmp_path / "cutter.html"
    code, out, err = run(capsys, "strip_cutter", "-o", path, "--frames", 3, "--dpi", 25, "--polygons")
    assert code == 0 and out == "" and err.startswith("3 frames")
    text = path.read_text(encoding="utf-8")
    assert text.count("data:image/png;base64,") == 4 and "https:" not in text and "http:" not in text


def test_frames_without_a_solution_are_drawn_and_named_once(capsys, tmp_path):
    from graphkin import catalog

    problem = tmp_path / "no_turn.toml"
    text = catalog.path("strip_cutter").read_text(encoding="utf-8")
    assert 'A = ["85 mm", "0 mm"]' in text
    problem.write_text(text.replace('A = ["85 mm", "0 mm"]', 'A = ["300 mm", "0 mm"]'), encoding="utf-8")
    code, out, err = run(capsys, problem, "-o", tmp_path / "a.gif", "--frames", 12, "--dpi", 20)
    lines = err.splitlines()
    assert code == 0 and len(lines) == 2
    assert lines[0].startswith("graphkin: warning: ") and "of 12 frames have no solution, the first at θ" in lines[0]
    with Image.open(tmp_path / "a.gif") as gif:
        assert gif.n_frames == 12


class _Terminal(io.StringIO):
    def isatty(self):
        return True


def test_progress_bar_at_a_terminal_only(capsys, tmp_path, monkeypatch):
    monkeypatch.setattr(_common, "PROGRESS_DELAY", 0.0)
    code, _, err = run(capsys, "strip_cutter", "-o", tmp_path / "a.gif", "--frames", 3, "--dpi", 20)
    assert code == 0 and "graphkin: drawing" not in err and err.count("\n") == 1  # stderr here is no terminal
    terminal = _Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    assert main(["animate", "strip_cutter", "-o", str(tmp_path / "b.gif"), "--frames", "3", "--dpi", "20"]) == 0
    shown = terminal.getvalue()
    # The bar shows at once with its total; later counts show only as often as tqdm refreshes (every 0.1 s,
    # so three small frames may finish between two refreshes); it is cleared before the closing message.
    assert "graphkin: drawing:   0%" in shown and "0/3" in shown, shown
    assert shown.rstrip("\n").rsplit("\r", 1)[-1].lstrip().startswith("3 frames ("), shown


@pytest.mark.parametrize("args, named", [
    (["no_such_problem", "-o", "a.gif"], ["no_such_problem"]),
    (["strip_cutter", "-o", "a.avi"], ["-o", "a.avi", ".gif, .mp4 or .html"]),
    (["strip_cutter", "-o", "a.gif", "--frames", "0"], ["--frames", "0"]),
    (["strip_cutter", "-o", "a.gif", "--frames", "-5"], ["--frames", "-5"]),
    (["strip_cutter", "-o", "a.gif", "--frames", "many"], ["--frames", "many"]),
    (["strip_cutter", "-o", "a.gif", "--fps", "0"], ["--fps", "0"]),
    (["strip_cutter", "-o", "a.gif", "--fps", "-2"], ["--fps", "-2"]),
    (["strip_cutter", "-o", "a.gif", "--fps", "fast"], ["--fps", "fast"]),
    (["strip_cutter", "-o", "a.gif", "--dpi", "0"], ["--dpi"]),
    (["strip_cutter", "-o", "{file}/a.gif"], ["-o", "a.gif", "is a file"]),
    (["strip_cutter", "-o", "{dir}"], ["-o", "b.gif", "is a folder"]),
    (["strip_cutter"], ["-o", "required"]),
    (["double_slider", "-o", "a.gif"], ["double_slider", "slider"]),
    (["engine_gas_force", "-o", "a.mp4"], ["-o", "a.mp4", "ffmpeg"]),
    (["{given}", "-o", "a.gif"], ["given.toml", "[given]", "no cycle"]),
])
def test_bad_input_is_one_line_naming_it(capsys, tmp_path, monkeypatch, args, named):
    from graphkin import catalog

    (tmp_path / "a_file.txt").write_text("x")
    (tmp_path / "b.gif").mkdir()
    # Kinematics measured at one position hold there only (ω3 read off a drawing: graphkin's is −3.352 rad/s).
    given = catalog.path("engine_gas_force").read_text(encoding="utf-8") + '\n[given.3]\nomega = "-3.35 rad/s"\n'
    (tmp_path / "given.toml").write_text(given, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("PATH", str(tmp_path / "b.gif"))  # no ffmpeg
    before = sorted(p.name for p in tmp_path.rglob("*"))
    code, out, err = run(capsys, *[a.format(file="a_file.txt", dir="b.gif", given="given.toml") for a in args])
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith("graphkin: error: ") and "Traceback" not in err, err
    for text in named:
        assert text in err, (text, err)
    assert sorted(p.name for p in tmp_path.rglob("*")) == before  # nothing written, no temporary file left
