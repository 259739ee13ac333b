"""A problem file's fields by path (graphkin.problem.fields): what exercises vary, and the message for a path the
problem does not have."""

from __future__ import annotations

import pytest

from graphkin import exercises
from graphkin.errors import GraphkinError
from graphkin.problem.fields import field_path, missing, set_field


def test_a_path_is_read_found_and_set():
    data = {"driver": {"theta": "30 deg"}, "links": [{"id": 1}, {"id": 2, "mass": "1 kg"}]}
    assert field_path("links[1].mass") == ["links", 1, "mass"]
    assert missing(data, "links[1].I_G") is None  # a field the file left out may be given
    assert missing(data, "links[2].mass") == "links[2]"
    assert missing(data, "loads[0].force") == "loads"
    shared = dict(data)
    set_field(shared, "links[1].mass", "2 kg", copy=True)
    assert shared["links"][1]["mass"] == "2 kg" and data["links"][1]["mass"] == "1 kg"
    for bad in ("links[x].mass", "links..mass", ""):
        with pytest.raises(KeyError):
            field_path(bad)


@pytest.mark.parametrize("field, says", [("links[9].mass", "the problem has no 'links[9]'"),
                                         ("links[1].ma-ss", "could not read the path")])
def test_an_exercise_varying_a_field_the_problem_lacks_names_it(field, says):
    text = exercises.path("double_slider_graphical").read_text(encoding="utf-8").replace(
        'field = "driver.s"', f'field = "{field}"')
    with pytest.raises(GraphkinError, match=r"vary\.x\.field") as info:
        exercises.parse_exercise(text, id="lacks")
    assert says in str(info.value)
