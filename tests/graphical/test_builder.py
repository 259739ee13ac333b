"""The builder's per-position memory: what it keeps is what it would compute again."""

import pytest

from graphkin import catalog
from graphkin.graphical import builder as B


@pytest.fixture
def builder():
    return B.Builder(catalog.load("strip_cutter").kinematics(), 30)


def test_lines_meet_once_per_position(builder, monkeypatch):
    calls = []
    meet = B._meet
    monkeypatch.setattr(B, "_meet", lambda *args: calls.append(args) or meet(*args))
    lines = (0.1 + 0.2j, 0.6 + 0.8j, -0.3 + 0.05j, 1 + 0j)
    first = builder.meet(*lines)
    # A sub-problem's builder shares the memory of the whole problem's.
    again = B.Builder(builder.kin, builder.i, sub="I", like=builder).meet(*lines)
    assert first == again == meet(*lines, builder.reach) and len(calls) == 1
    # Keyed by the numbers' bits: a line through −0.0 is drawn again, not taken for one through 0.0.
    builder.meet(complex(-0.0, 0.2), *lines[1:])
    builder.meet(complex(0.0, 0.2), *lines[1:])
    assert len(calls) == 3


def test_parallel_lines_meet_nowhere(builder):
    assert builder.meet(0j, 1 + 0j, 1j, -1 + 0j) is None
