"""Bad input gets one clear line naming the file and field (or position), exit code 2, no traceback."""

import pytest

from graphkin import catalog
from graphkin.cli import main

BASE = catalog.path("double_slider").read_text()
FRICTION = catalog.path("slider_crank_friction").read_text()


def run(capsys, *args):
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def write(tmp_path, text, name="problem.toml"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return str(path)


@pytest.mark.parametrize(
    "old, new, expected",
    [
        ('mass = "5 kg"', 'mass = "-5 kg"', ["links[1].mass", "≥ 0"]),
        ('B = ["500 mm", "0 mm"]', 'B = ["0 mm", "0 mm"]', ["links[1].shape", "length must be positive"]),
        ("links = [3, 4]", "links = [3, 7]", ["unknown link 7"]),
        ('point = "B"\n\n[[joints]]\ntype = "prismatic"', 'point = "Q"\n\n[[joints]]\ntype = "prismatic"', ["no point 'Q'"]),
        ('s = "200 mm"', 's = "200"', ["driver.s", "units"]),
        ('s = "200 mm"', 's = "5 N"', ["driver.s", "length"]),
        ('v = "2 m/s"', 'v = "2 N"', ["driver.v"]),
        ('mass = "5 kg"', 'mas = "5 kg"', ["links[1].mas", "did you mean 'mass'"]),
        ("[driver]", "[driver", ["not valid TOML"]),
        ('direction = "90 deg"', 'direction = "90 deg"\nmu = -0.1', ["joints[3].mu", "≥ 0"]),
        ('direction = "90 deg"', 'direction = "90"', ["joints[3].direction", "degrees or radians"]),
        ('type = "slider"', 'type = "rocket"', ["driver.type"]),
    ],
)
def test_malformed_problem_files(tmp_path, capsys, old, new, expected):
    assert old in BASE
    path = write(tmp_path, BASE.replace(old, new, 1))
    code, out, err = run(capsys, "solve", path)
    assert code == 2
    assert out == ""
    assert err.count("\n") == 1 and err.startswith("graphkin: error: ")
    assert "Traceback" not in err
    assert path in err
    for text in expected:
        assert text in err, err


def test_zero_length_link(tmp_path, capsys):
    text = catalog.path("strip_cutter").read_text().replace('B = ["235 mm", "0 mm"]', 'B = ["0 mm", "0 mm"]')
    code, _, err = run(capsys, "solve", write(tmp_path, text))
    assert code == 2 and "link 3" in err and "coincide (zero length)" in err


def test_position_that_cannot_close(capsys):
    code, out, err = run(capsys, "solve", "double_slider", "--at", "600 mm")
    assert code == 2
    assert "s = 600 mm" in err and "cannot be assembled" in err
    assert "no solution" in out


def test_dead_point(capsys):
    # At x = AB the rod lies along the x-axis: B's guide is perpendicular to AB
    # and the velocity equations are singular.
    code, out, err = run(capsys, "solve", "double_slider", "--at", "500 mm")
    assert code == 2
    assert "s = 500 mm" in err and "dead point" in err


def test_negative_friction_in_python_api():
    from graphkin.errors import ModelError
    from graphkin.model import Prismatic

    with pytest.raises(ModelError, match="mu must be ≥ 0"):
        Prismatic(1, 4, "B", "E", 0.0, mu=-0.2)


def test_unknown_catalog_name(capsys):
    code, _, err = run(capsys, "solve", "no_such_problem")
    assert code == 2 and "no_such_problem" in err and "double_slider" in err


def test_wrong_units_on_the_command_line(capsys):
    code, _, err = run(capsys, "solve", "double_slider", "--at", "200 deg")
    assert code == 2 and "--at" in err


def test_unreadable_file(capsys, tmp_path):
    code, _, err = run(capsys, "solve", str(tmp_path / "missing.toml"))
    assert code == 2 and "missing.toml" in err and "cannot be read" in err


def test_given_for_unknown_link(tmp_path, capsys):
    path = write(tmp_path, BASE + '\n[given.9]\nomega = "1 rad/s"\n')
    code, _, err = run(capsys, "solve", path)
    assert code == 2 and "given.9" in err


def test_friction_problem_is_fine(tmp_path, capsys):
    code, out, _ = run(capsys, "solve", write(tmp_path, FRICTION), "--at", "30 deg")
    assert code == 0 and "friction" in out
