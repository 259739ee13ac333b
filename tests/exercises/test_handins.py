"""A hand-in reduced to its notebook's answers, read as data: notebooks, zips and folders, and what is beside them."""

from __future__ import annotations

import json
import os
import stat
import zipfile

import pytest

from graphkin.errors import GraphkinError
from graphkin.exercises.handins import (
    REFUSALS,
    clear_folder,
    literal,
    notebook_text,
    own_files,
    read_handin,
    stripped_notebook,
)
from graphkin.exercises.notebooks import MAX_NOTEBOOK_BYTES, NotData

NAMES = {"F23": "F23", "T12": "T12"}


def _nb(*sources, **metadata) -> bytes:
    cells = [{"cell_type": "code", "source": s} for s in sources]
    cells.insert(1, {"cell_type": "markdown", "source": 'F23 = "not code: markdown"'})
    return json.dumps({"cells": cells, "metadata": metadata}).encode()


def test_a_notebook_is_read_as_data(tmp_path):
    f = tmp_path / "hw.ipynb"
    f.write_bytes(b"\xef\xbb\xbf" + _nb('STUDENT = "s001"', 'F23 = "12 N"\nT12 = f"{x} N*m"'))  # a BOM, as some save
    h = read_handin(f, NAMES)
    assert (h.claimed, h.answers, h.refused, h.notebook, h.ignored) == (
        "s001", {"F23": "12 N", "T12": NotData("an f-string")}, None, "hw.ipynb", ())


@pytest.mark.parametrize(("data", "code"), [
    (b'{"cells": [], "x": ' + b"[" * 100_000 + b"]" * 100_000 + b"}", "too_deep"),
    ('{"cells": [], "t": "\u00e9"}'.encode("latin-1"), "not_utf8"),
    (b"{not json", "not_json"),
    (b'{"cells": "x"}', "not_notebook"),
    (b"[1, 2]", "not_notebook"),
])
def test_a_notebook_that_cannot_be_read_is_refused_with_a_sentence(tmp_path, data, code):
    f = tmp_path / "hw.ipynb"
    f.write_bytes(data)
    h = read_handin(f, NAMES)
    assert (h.refused, h.answers, h.claimed) == (code, {}, None)
    assert h.reason == REFUSALS[code]


def test_a_notebook_too_big_is_refused_unread(tmp_path):
    f = tmp_path / "hw.ipynb"
    with open(f, "wb") as out:
        out.truncate(MAX_NOTEBOOK_BYTES + 1)  # sparse: never read
    assert read_handin(f, NAMES).refused == "too_big"


def test_a_link_is_never_followed(tmp_path):
    secret = tmp_path / "keys.json"
    secret.write_bytes(_nb('F23 = "the key"'))
    os.symlink(secret, tmp_path / "hw.ipynb")
    assert read_handin(tmp_path / "hw.ipynb", NAMES).refused == "link"
    folder = tmp_path / "sub"
    folder.mkdir()
    os.symlink(secret, folder / "hw.ipynb")
    h = read_handin(folder, NAMES)
    assert (h.refused, h.answers) == ("link", {})


def test_a_folder_names_what_is_beside_the_notebook_and_leaves_its_own(tmp_path):
    own_dir = tmp_path / "source"
    (own_dir / "vendor").mkdir(parents=True)
    (own_dir / "hw.toml").write_text("ex")
    (own_dir / "vendor" / "a.py").write_text("a")
    folder = tmp_path / "sub"
    (folder / "vendor").mkdir(parents=True)
    (folder / "hw.toml").write_text("ex")
    (folder / "vendor" / "a.py").write_text("a")
    (folder / "hw.ipynb").write_bytes(_nb('F23 = "1 N"'))
    (folder / "other.ipynb").write_bytes(_nb('F23 = "the right one"'))
    (folder / ".OTTER_LOG").write_bytes(b"\x80\x04.")
    (folder / "otter").mkdir()
    (folder / "otter" / "__init__.py").write_text("")
    os.symlink("/etc/passwd", folder / "passwd")
    h = read_handin(folder, NAMES, notebook="hw.ipynb", own=own_files(own_dir))
    assert h.answers["F23"] == "1 N"
    assert h.ignored == (".OTTER_LOG (otter's log, a pickle)", "other.ipynb (another notebook)",
                         "otter/ (a Python package, 1 file)", "passwd (a link)")
    (folder / "vendor" / "b.py").write_text("shadow")
    assert "vendor/ (a folder, not the assignment's own, 2 files)" in read_handin(
        folder, NAMES, notebook="hw.ipynb", own=own_files(own_dir)).ignored


def test_which_notebook_of_several(tmp_path):
    (tmp_path / "a.ipynb").write_bytes(_nb('F23 = "a"'))
    assert read_handin(tmp_path, NAMES).answers["F23"] == "a"  # the only one
    (tmp_path / "b.ipynb").write_bytes(_nb('F23 = "b"'))
    assert read_handin(tmp_path, NAMES, notebook="b.ipynb").answers["F23"] == "b"  # the assignment's
    assert read_handin(tmp_path, NAMES, notebook="hw.ipynb").refused == "notebooks"
    empty = tmp_path / "empty"
    empty.mkdir()
    assert read_handin(empty, NAMES).refused == "no_notebook"


def test_a_zip_is_read_without_extracting_it(tmp_path):
    z = tmp_path / "hw.zip"
    link = zipfile.ZipInfo("keys.json")
    link.external_attr = (stat.S_IFLNK | 0o777) << 16
    with zipfile.ZipFile(z, "w") as out:
        out.writestr("hw.ipynb", _nb('STUDENT = "s001"', 'T12 = "5 N*m CW"'))
        out.writestr(".OTTER_LOG", b"\x80\x04.")
        out.writestr("graphkin/__init__.py", "")
        out.writestr(link, "../source/files/keys.json")
    h = read_handin(z, NAMES, notebook="hw.ipynb")
    assert (h.claimed, h.answers["T12"]) == ("s001", "5 N*m CW")
    assert h.ignored == (".OTTER_LOG (otter's log, a pickle)", "graphkin/ (a Python package, 1 file)",
                         "keys.json (a link)")
    assert os.listdir(tmp_path) == ["hw.zip"]
    with zipfile.ZipFile(z, "w") as out:
        info = zipfile.ZipInfo("hw.ipynb")
        info.external_attr = (stat.S_IFLNK | 0o777) << 16
        out.writestr(info, "/etc/passwd")
    assert read_handin(z, NAMES).refused == "link"
    z.write_bytes(b"PK\x03\x04 not a zip")
    assert read_handin(z, NAMES).refused == "bad_zip"


def test_a_missing_hand_in_is_the_teachers_error(tmp_path):
    with pytest.raises(GraphkinError, match="no such file or folder"):
        read_handin(tmp_path / "nope.ipynb", NAMES)


@pytest.mark.parametrize("sources", [
    ('STUDENT = "s001"', 'F23 = "12 N ∠ 45°"\nT12 = open("k").read()'),
    ('F23 = 1 + 2', 'T12: str = "3 N*m"', 'F23 = )', 'T12 = "\ud800"'),
    (),
])
def test_a_stripped_notebook_reads_as_its_hand_in(tmp_path, sources):
    """Only the code cells' text is carried, so the stripped notebook reads the same: id, answers, markers."""
    f = tmp_path / "hw.ipynb"
    f.write_text(json.dumps({"cells": [{"cell_type": "code", "source": s, "outputs": [{"x": 1}],
                                        "metadata": {"nbgrader": {"grade": True}}} for s in sources],
                             "metadata": {"otter": {"tests": "forged"}}}), encoding="utf-8")
    h = read_handin(f, NAMES)
    out = tmp_path / "out.ipynb"
    out.write_text(notebook_text(stripped_notebook(h, {"kernelspec": {"name": "python3"}})), encoding="utf-8")
    again = read_handin(out, NAMES)
    assert (again.claimed, again.answers, again.refused) == (h.claimed, h.answers, None)
    data = json.loads(out.read_text(encoding="utf-8"))
    assert data["metadata"] == {"kernelspec": {"name": "python3"}}
    assert all(c["outputs"] == [] and c["metadata"] == {} for c in data["cells"])


def test_a_stripped_notebook_of_a_refused_hand_in_is_refused_again(tmp_path):
    f = tmp_path / "hw.ipynb"
    f.write_bytes(b"not json")
    out = tmp_path / "out.ipynb"
    out.write_text(notebook_text(stripped_notebook(read_handin(f, NAMES))), encoding="utf-8")
    assert read_handin(out, NAMES).refused == "not_json"


def test_literals_for_a_kernel():
    assert [literal(v) for v in ("12 N", 3, -2.5, 10**400, float("inf"), True, None, NotData("a call"), [1])] == [
        "'12 N'", "3", "-2.5", "None", "None", "None", "None", "None", "None"]


def test_clear_folder_leaves_only_the_platforms_own_files(tmp_path):
    source = tmp_path / "source"
    (source / "vendor" / "graphkin").mkdir(parents=True)
    (source / "vendor" / "graphkin" / "__init__.py").write_text("real")
    (source / "hw.toml").write_text("ex")
    target = tmp_path / "keys.json"
    target.write_text("keys")
    folder = tmp_path / "sub"
    (folder / "vendor" / "graphkin").mkdir(parents=True)
    (folder / "vendor" / "graphkin" / "__init__.py").write_text("shadow")
    (folder / "otter").mkdir()
    (folder / "otter" / "__init__.py").write_text("x")
    (folder / "hw.toml").write_text("ex")
    (folder / "hw.ipynb").write_text("{}")
    os.symlink(target, folder / "link.json")
    os.symlink(tmp_path, folder / "up")
    removed = clear_folder(folder, {**own_files(source), "__init__.py": b""}, leave={"hw.ipynb"})
    assert removed == ["link.json", "otter", "up", "vendor"]
    assert target.read_text() == "keys" and (tmp_path / "source").is_dir()  # a link's target is left alone
    assert sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*") if p.is_file()) == [
        "__init__.py", "hw.ipynb", "hw.toml", "vendor/graphkin/__init__.py"]
    assert (folder / "vendor" / "graphkin" / "__init__.py").read_text() == "real"


def test_the_grade_ids_its_cells_carry_are_read_for_the_log(tmp_path):
    cells = [{"cell_type": "code", "source": "x = 1", "metadata": {"nbgrader": {"grade_id": gid, "grade": True}}}
             for gid in ("test_F23", "extra", "test_F23")]
    cells += [{"cell_type": "code", "source": "", "metadata": {"nbgrader": {"grade_id": 5}}}, "not a cell"]
    f = tmp_path / "hw.ipynb"
    f.write_text(json.dumps({"cells": cells}), encoding="utf-8")
    assert read_handin(f, NAMES).grade_ids == ("test_F23", "extra", "test_F23")
