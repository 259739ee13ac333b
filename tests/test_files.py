"""Every file graphkin writes is whole or absent (issue 12): concurrent writers, Ctrl-C mid-write, a batch cut short.

Files are written to a temporary file in the same folder and moved into place
with ``os.replace`` (:func:`graphkin.draw.save`, :mod:`graphkin.files`), so a
reader sees the old file or the new one, never a mixture, and an interrupted
write leaves no temporary file behind.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

GRAPHKIN = Path(sys.executable).with_name("graphkin")
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
WRITERS = 8


def valid_png(data: bytes) -> bool:
    """A PNG that Pillow reads to the last pixel."""
    import io

    from PIL import Image

    if not data.startswith(PNG_SIGNATURE):
        return False
    try:
        with Image.open(io.BytesIO(data)) as im:
            im.load()
    except Exception:  # any reader error means a broken file; the assertion says which
        return False
    return True


def valid_svg(data: bytes) -> bool:
    """An SVG that parses as XML and whose root is <svg>."""
    try:
        root = ET.fromstring(data)
    except ET.ParseError:
        return False
    return root.tag.endswith("svg")


def temporaries(folder: Path) -> list[str]:
    return sorted(n for n in os.listdir(folder) if n.endswith(".tmp"))


# One process draws the double slider's side-by-side figure, then forks the writers: each a process of its own
# with its own copy of the figure (drawing it eight times over would only repeat the same work), which waits for
# the others, then saves it as PNG and SVG to the same two paths, twice, as fast as it can. The first process
# waits for them all and prints their exit statuses; a writer's error goes to stderr.
WRITER = textwrap.dedent("""
    import os, sys, time, traceback
    from pathlib import Path
    from graphkin import catalog, draw
    from graphkin.graphical import construct_forces

    folder, writers = Path(sys.argv[1]), int(sys.argv[2])
    p = catalog.load("double_slider")
    fig = draw.draw_solution(construct_forces(p.kinematics(), 0), p.solve())
    sys.stdout.flush()
    sys.stderr.flush()
    children = []
    for me in range(writers):
        pid = os.fork()
        if pid:
            children.append(pid)
            continue
        status = 0
        try:
            (folder / f"ready_{me}").touch()
            while not (folder / "go").exists():
                time.sleep(0.005)
            for _ in range(2):
                draw.save(fig, folder / "out" / "same.png")
                draw.save(fig, folder / "out" / "same.svg")
        except BaseException:
            traceback.print_exc()
            status = 1
        sys.stderr.flush()
        os._exit(status)
    print([os.waitstatus_to_exitcode(os.waitpid(pid, 0)[1]) for pid in children])
""")


@pytest.mark.slow
def test_eight_writers_at_once_leave_a_valid_file(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    proc = subprocess.Popen([sys.executable, "-c", WRITER, str(tmp_path), str(WRITERS)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 120
        while len(list(tmp_path.glob("ready_*"))) < WRITERS:
            assert proc.poll() is None, "the writers died before the start"
            assert time.monotonic() < deadline
            time.sleep(0.01)
        (tmp_path / "go").touch()
        # While they write, a reader keeps opening the two files: it must never see half of one.
        reads = 0
        while proc.poll() is None:
            for name, valid in (("same.png", valid_png), ("same.svg", valid_svg)):
                try:
                    data = (out / name).read_bytes()
                except FileNotFoundError:
                    continue
                reads += 1
                assert valid(data), f"a reader saw a broken {name} ({len(data)} bytes)"
            time.sleep(0.005)  # leave the two cores to the writers
    finally:
        stdout, stderr = proc.communicate(timeout=120)
    assert proc.returncode == 0 and stdout.strip() == str([0] * WRITERS), stdout + stderr[-2000:]
    assert reads > 0
    assert valid_png((out / "same.png").read_bytes())
    assert valid_svg((out / "same.svg").read_bytes())
    assert sorted(os.listdir(out)) == ["same.png", "same.svg"]


def _interrupt_when(args, folder: Path, prefix: str):
    """Run ``graphkin ARGS`` in ``folder``; send SIGINT the moment a temporary file starting ``prefix`` appears.

    The command is a child in a session of its own, and the signal goes to it alone: nothing reaches the test's
    own process or its process group (issue 40, item 6).
    """
    # Ctrl-C as at a terminal: a shell without job control starts a background job (`make test &`) with SIGINT
    # ignored, and a child inherits that, so the signal would be dropped and the command run to its end.
    proc = subprocess.Popen([str(GRAPHKIN), *args], cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            text=True, start_new_session=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    sent = False
    while proc.poll() is None:
        if any(n.startswith(prefix) for n in os.listdir(folder)):
            proc.send_signal(signal.SIGINT)
            sent = True
            break
        time.sleep(0.001)
    err = proc.communicate(timeout=120)[1]
    assert sent, f"the write never started: exit {proc.returncode}, {err!r}"
    return proc.returncode, err


@pytest.mark.slow
@pytest.mark.parametrize("previous", [False, True], ids=["no-previous-file", "previous-file"])
def test_ctrl_c_during_a_long_figure_write(tmp_path, previous):
    # 200,000 positions: the sweep takes about a second, the SVG a few tenths more; SIGINT lands in the write.
    figure = tmp_path / "big.svg"
    old = b'<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"/>\n'
    if previous:
        figure.write_bytes(old)
    code, err = _interrupt_when(["cycle", "strip_cutter", "--n", "200000", "--figure", "big.svg"], tmp_path,
                                ".big.svg.")
    assert code == 130, err
    assert err == "graphkin: interrupted\n"
    assert temporaries(tmp_path) == []
    if previous:
        assert figure.read_bytes() == old
    else:
        assert not figure.exists()


def test_a_batch_cut_short_says_what_it_wrote(tmp_path):
    # Eight positions, one figure each: SIGINT while the second is written leaves the first whole and says so.
    at = ",".join(f"{a} deg" for a in range(10, 90, 10))
    code, err = _interrupt_when(["solve", "strip_cutter", "--at", at, "--figure", "f.png"], tmp_path, ".f_2.png.")
    assert code == 130
    lines = err.splitlines()  # what was written, as it was written (stderr: messages), then the interruption
    assert lines[-1].startswith("graphkin: interrupted: ") and lines[:-1] == ["figure written to f_1.png"]
    assert "1 file was written before it stopped, the last f_1.png" in lines[-1]
    assert sorted(os.listdir(tmp_path)) == ["f_1.png"]
    assert valid_png((tmp_path / "f_1.png").read_bytes())


@pytest.mark.parametrize("argv, name", [
    (["exercise", "key", "gear_pair", "--student", "s1", "--secret", "k", "--json", "-o"], "key.json"),
    (["solve", "double_slider", "-o"], "out.png"),
    (["cycle", "double_slider", "-o"], "out.svg"),
    (["handout", "double_slider", "-o"], "out.md"),
])
def test_a_failed_write_names_the_users_path_not_the_temporary_file(tmp_path, monkeypatch, capsys, argv, name):
    # A disk that fills as the file is moved into place: the error must name the file the user asked for.
    import errno

    from graphkin import cli

    def disk_full(src, dst):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(src))

    monkeypatch.setattr(os, "replace", disk_full)
    target = tmp_path / name
    code = cli.main([*argv, str(target)])
    err = capsys.readouterr().err
    assert code == 2, err
    # The file asked for, or (a handout) the first of its figures beside it: a path the user chose.
    named = err.removeprefix("graphkin: error: ").split(": cannot be written")[0].split(" ", 1)[1]
    assert named == str(target) or Path(named).parent == tmp_path / f"{target.stem}_figures", err
    assert f": cannot be written ({os.strerror(errno.ENOSPC)})" in err, err
    assert ".tmp" not in err, err
    assert [f for f in tmp_path.rglob("*") if f.is_file()] == [], "a file or temporary file was left behind"


# Python's own handler, as at a terminal (a background job may start with SIGINT ignored); the child sends the
# signal to itself, inside the block.
DEFERRED = textwrap.dedent("""
    import os, signal, sys, time
    from pathlib import Path
    from graphkin.files import interrupts_deferred, replacing

    signal.signal(signal.SIGINT, signal.default_int_handler)
    target, finished = Path(sys.argv[1]), []
    try:
        with replacing(target, "figure") as tmp, interrupts_deferred():
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(0.05)  # the handler has run by now: it only noted the signal
            Path(tmp).write_text("whole")
            finished.append(True)
    except KeyboardInterrupt:
        print("raised at the end", finished, signal.getsignal(signal.SIGINT) is signal.default_int_handler)
""")


def test_ctrl_c_inside_a_deferred_block_is_raised_when_it_ends_and_the_file_is_not_written(tmp_path):
    """Why draw.save defers it: a KeyboardInterrupt inside matplotlib's C++ transforms comes out as a TypeError.

    In a child of its own: a test never signals a process it did not start, the test worker least of all.
    """
    target = tmp_path / "out.txt"
    done = subprocess.run([sys.executable, "-c", DEFERRED, str(target)], capture_output=True, text=True, timeout=120,
                          start_new_session=True, cwd=Path(__file__).resolve().parents[1])
    assert done.returncode == 0, done.stderr
    assert done.stdout == "raised at the end [True] True\n"
    assert not target.exists() and temporaries(tmp_path) == []
