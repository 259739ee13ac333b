"""The one JSON writer (:func:`graphkin.files.json_text`): what it writes reads back as the data, laid out as
``json.dumps(..., indent=2)`` lays it out, with a number that is not finite written as null."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphkin.files import json_text
from graphkin.report import cycle_data
from graphkin.report.plain import floats as _floats

_leaves = (st.none() | st.booleans() | st.integers(-(2**63), 2**63 - 1) | st.floats()
           | st.text(alphabet=st.characters(codec="utf-8"), max_size=8))


_keys = st.text(max_size=6)


_data = st.recursive(
    _leaves | st.lists(st.floats(), max_size=6) | st.lists(st.booleans(), max_size=4) | st.lists(st.text(max_size=4)),
    lambda inner: (st.lists(inner, max_size=5) | st.dictionaries(_keys, inner, max_size=5)
                   | st.dictionaries(st.integers(-5, 5), inner, max_size=3) | st.tuples(inner, inner)),
    max_leaves=30)


def _as_json_reads(x):
    """What JSON makes of plain data: a number that is not finite is null, a key a string, a tuple a list."""
    if isinstance(x, float):
        return x if math.isfinite(x) else None
    if isinstance(x, dict):
        return {str(k): _as_json_reads(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_as_json_reads(v) for v in x]
    return x


@settings(max_examples=400, deadline=None)
@given(_data)
def test_json_text_reads_back_as_the_data(data):
    text = json_text(data)
    assert json.loads(text) == _as_json_reads(data)
    # Laid out as json lays it out (two spaces, one item per line): the same lines, but for how a number is
    # spelt (orjson writes 2.5e-8 where json writes 2.5e-08, null where json writes NaN).
    assert text.count("\n") == json.dumps(data, indent=2, ensure_ascii=False).count("\n")


@pytest.fixture(scope="module")
def strip_cutter_cycle():
    from graphkin import catalog
    from graphkin.cycle import sweep

    return sweep(catalog.load("strip_cutter"), 90)


def test_the_cycle_json_is_jsons_own_text(strip_cutter_cycle):
    data = cycle_data(strip_cutter_cycle, 0.05)
    assert json_text(data) == json.dumps(data, indent=2, ensure_ascii=False)


def test_floats_are_those_of_float_one_by_one():
    a = np.array([0.1, -0.0, np.nan, np.inf, -np.inf, 1e-310, 2.0**60, np.pi])
    expected = [float(x) if math.isfinite(x) else None for x in a]
    got = _floats(a)
    assert got == expected and all(type(x) in (float, type(None)) for x in got)
    assert math.copysign(1.0, got[1]) == -1.0
    assert _floats(a.reshape(2, 4)) == expected
