"""``graphkin lessons DIR``: every lesson notebook copied whole, a teacher's copy never replaced by accident, and a
bad folder refused in one line before anything is written."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from graphkin.catalog.lessons import copy_lessons, lesson_files, lessons_folder
from graphkin.cli import main
from graphkin.errors import GraphkinError

REPOSITORY_LESSONS = sorted((Path(__file__).resolve().parents[2] / "lessons").glob("[0-9][0-9]_*.ipynb"))


def run(capsys, *argv):
    code = main(["lessons", *map(str, argv)])
    out, err = capsys.readouterr()
    return code, out, err


def test_a_clone_reads_the_repositorys_lessons():
    assert [f.name for f in lesson_files()] == [p.name for p in REPOSITORY_LESSONS]
    assert Path(str(lessons_folder())) == REPOSITORY_LESSONS[0].parent


def test_every_lesson_is_copied_whole(capsys, tmp_path):
    course = tmp_path / "course" / "lessons"  # made, parents too
    code, out, err = run(capsys, course)
    assert code == 0 and out == ""
    assert sorted(p.name for p in course.iterdir()) == [p.name for p in REPOSITORY_LESSONS]  # no temporary file left
    assert all((course / p.name).read_bytes() == p.read_bytes() for p in REPOSITORY_LESSONS)
    assert err.count("\n") == 1 and err.startswith(f"{len(REPOSITORY_LESSONS)} lessons written to {course} (01_")


def test_lessons_already_there_are_kept_unless_forced(capsys, tmp_path):
    first = REPOSITORY_LESSONS[0].name
    copy_lessons(tmp_path)
    (tmp_path / first).write_text("the teacher's edit", encoding="utf-8")
    (tmp_path / "notes.md").write_text("mine", encoding="utf-8")
    code, out, err = run(capsys, tmp_path)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert err.startswith(f"graphkin: error: lessons folder {tmp_path}: {len(REPOSITORY_LESSONS)} of the lessons are "
                          f"already there ({first}, ") and "--force" in err
    assert (tmp_path / first).read_text(encoding="utf-8") == "the teacher's edit"
    code, _, _ = run(capsys, tmp_path, "--force")
    assert code == 0 and (tmp_path / first).read_bytes() == REPOSITORY_LESSONS[0].read_bytes()
    assert (tmp_path / "notes.md").read_text(encoding="utf-8") == "mine"


def test_one_lesson_there_stops_the_whole_copy(tmp_path):
    """All or nothing: a course folder is never left half old, half new."""
    last = REPOSITORY_LESSONS[-1].name
    (tmp_path / last).write_text("kept", encoding="utf-8")
    with pytest.raises(GraphkinError, match=rf"1 of the lessons are already there \({last}\)"):
        copy_lessons(tmp_path)
    assert [p.name for p in tmp_path.iterdir()] == [last]


@pytest.mark.parametrize("folder, message", [
    ("a_file", "lessons folder {tmp}/a_file: {tmp}/a_file is a file, not a folder"),
    ("a_file/sub", "lessons folder {tmp}/a_file/sub: {tmp}/a_file is a file, not a folder"),
    ("", "lessons folder: give the folder to copy the lessons into, e.g. 'course/lessons'"),
    ("  ", "lessons folder: give the folder to copy the lessons into, e.g. 'course/lessons'"),
])
def test_a_bad_folder_is_one_line_and_nothing_is_written(capsys, tmp_path, monkeypatch, folder, message):
    monkeypatch.chdir(tmp_path)  # an empty name must not mean "here"
    (tmp_path / "a_file").write_text("x", encoding="utf-8")
    code, out, err = run(capsys, str(tmp_path / folder) if folder.strip() else folder)
    assert code == 2 and out == ""
    assert err == f"graphkin: error: {message.format(tmp=tmp_path)}\n"
    assert [p.name for p in tmp_path.iterdir()] == ["a_file"]


def test_no_folder_given_is_one_line(capsys):
    code, out, err = run(capsys)
    assert code == 2 and out == "" and err.count("\n") == 1 and "DIR" in err


@pytest.mark.skipif(hasattr(os, "geteuid") and os.geteuid() == 0, reason="root writes in any folder")
def test_a_folder_that_cannot_be_written_is_named(capsys, tmp_path):
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o555)
    try:
        code, _, err = run(capsys, locked / "lessons")
    finally:
        locked.chmod(0o755)
    assert code == 2 and err == f"graphkin: error: lessons folder {locked}/lessons: the folder {locked} cannot be written\n"


def test_an_installed_wheels_lessons_come_first(tmp_path, monkeypatch):
    from graphkin.catalog import lessons

    (tmp_path / "lessons").mkdir()
    (tmp_path / "lessons" / "01_only.ipynb").write_text("{}", encoding="utf-8")
    (tmp_path / "lessons" / "notes.txt").write_text("not a lesson", encoding="utf-8")
    monkeypatch.setattr(lessons.resources, "files", lambda package: tmp_path)
    assert [f.name for f in lesson_files()] == ["01_only.ipynb"]


def test_an_install_without_lessons_says_so(tmp_path, monkeypatch):
    from graphkin.catalog import lessons

    monkeypatch.setattr(lessons.resources, "files", lambda package: tmp_path)
    monkeypatch.setattr(lessons, "__file__", str(tmp_path / "site-packages" / "graphkin" / "catalog" / "lessons.py"))
    with pytest.raises(GraphkinError, match="this install of graphkin has no lesson notebooks: reinstall it"):
        copy_lessons(tmp_path / "course")
    assert not (tmp_path / "course").exists()
