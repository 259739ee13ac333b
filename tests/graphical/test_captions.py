"""Captions written when first read, and the hand-written __init__ of the steps and their lines and arrows."""

import copy
import dataclasses
import inspect
import pickle

import pytest

from graphkin import catalog
from graphkin.graphical import construct_forces
from graphkin.graphical.captions import Later
from graphkin.graphical.construction import Arrow, Line, Step

# Superposition (with and without friction, parts of a dyad), gears, a slider driver, a plain four-bar.
CASES = [("strip_cutter", 0), ("strip_cutter", 60), ("slider_crank_friction", 18), ("epicyclic_khurmi", 0),
         ("gearset", 0), ("shaper_six_bar", 0), ("double_slider", 0), ("fourbar_two_loads_makdin", 0),
         ("engine_gas_force", 0)]

_VALUES = (str, int, float, complex, bool, type(None), Arrow, Line)


def _walk(value):
    """A pending caption, the pending captions it holds and every value they hold, nested in tuples."""
    yield value
    for v in value.values if isinstance(value, Later) else value if isinstance(value, tuple) else ():
        yield from _walk(v)


@pytest.mark.parametrize(("name", "i"), CASES)
def test_pending_captions_hold_values_not_state(name, i):
    steps = construct_forces(catalog.load(name).kinematics(), i).steps
    pending = [s.__dict__["caption"] for s in steps if not isinstance(s.__dict__["caption"], str)]
    assert pending, "every caption was written at once: nothing here tests the pending ones"
    for text in pending:
        assert isinstance(text, Later)
        for v in _walk(text):
            if isinstance(v, Later):
                # No free variables: a write function sees only what it was given when the step was made.
                assert v.write.__code__.co_freevars == (), v.write
            else:
                # ... and what it was given cannot change after (a builder's dict, a _Load, a list can).
                assert isinstance(v, (tuple, *_VALUES)), f"a pending caption holds a value that can change: {v!r}"


@pytest.mark.parametrize(("name", "i"), CASES)
def test_caption_is_text_for_every_reader(name, i):
    c = construct_forces(catalog.load(name).kinematics(), i)
    for step in c.steps:
        text = step.caption
        assert type(text) is str and text.endswith(".") and "<" not in text
        assert step.caption is text  # written once, then kept
        assert dataclasses.asdict(step)["caption"] == text
    again = construct_forces(catalog.load(name).kinematics(), i)
    # Copies, pickles and replacements made before the caption is read still read the same text.
    for fresh, read in zip(again.steps, c.steps):
        assert pickle.loads(pickle.dumps(fresh)).caption == read.caption
    again = construct_forces(catalog.load(name).kinematics(), i)
    for fresh, read in zip(again.steps, c.steps):
        assert copy.deepcopy(fresh).caption == read.caption
        assert dataclasses.replace(fresh, link=fresh.link).caption == read.caption
        assert fresh == read and repr(fresh) == repr(read)


def test_step_caption_stays_required_and_frozen():
    with pytest.raises(TypeError, match="caption"):
        Step("note")
    step = Step("note", Later(lambda x: f"x = {x}.", 3))
    with pytest.raises(dataclasses.FrozenInstanceError):
        step.caption = "other"
    assert step.caption == "x = 3."


@pytest.mark.parametrize("cls", [Line, Arrow, Step])
def test_hand_written_init_takes_the_dataclass_fields(cls):
    # Line, Arrow and Step write their own __init__ (for speed): it must take the fields, in order, with their defaults.
    params = list(inspect.signature(cls).parameters.values())
    fields = dataclasses.fields(cls)
    assert [p.name for p in params] == [f.name for f in fields]
    for p, f in zip(params, fields):
        if f.default_factory is not dataclasses.MISSING:
            assert p.default is None  # None gives a new f.default_factory()
        else:
            assert p.default is (inspect.Parameter.empty if f.default is dataclasses.MISSING else f.default)
    required = [f"x{k}" for k, p in enumerate(params) if p.default is inspect.Parameter.empty]
    made = cls(*required)
    assert [getattr(made, f.name) for f in fields] == [
        required[k] if k < len(required) else f.default_factory() if f.default is dataclasses.MISSING else f.default
        for k, f in enumerate(fields)]
    assert made == cls(*required) and dataclasses.replace(made) == made
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(made, fields[0].name, "other")


def test_a_step_has_dicts_of_its_own():
    a, b = Step("note", "a."), Step("note", "b.")
    assert a.points == {} and a.points is not b.points and a.values is not b.values
