"""How the construction's captions write things: sub-problem marks and labels, lists, forces and numbers.

Captions are plain text (a hyphen-minus), written with :mod:`graphkin.notation`.
"""

from __future__ import annotations

from dataclasses import FrozenInstanceError

from graphkin.notation import num, polar_text

_MARKS = ("′", "″", "‴", "⁗")


class Later:
    """A caption written when first read: ``write(*values)``, the values taken when the step is made.

    Most constructions are made to be checked (an exercise's draw), not read, and formatting their numbers
    is a good part of their cost; :class:`graphkin.graphical.construction.Step` writes the text the first
    time its ``caption`` is read, and every reader sees the same str as if it had been written at once.
    ``write`` must take everything it reads as arguments (a function without free variables: a builder's
    state changes after the step is made).

    Examples
    --------
    >>> str(Later(lambda F, link: f"Link {link}: F = {polar(F)}", 3 - 4j, 3))
    'Link 3: F = 5 N ∠ -53.13°'
    """

    __slots__ = ("write", "values")

    def __init__(self, write, *values):
        self.write, self.values = write, values

    def __str__(self) -> str:
        return self.write(*self.values)


class Caption:
    """A step's caption, as every reader sees it: a str (a descriptor of the ``caption`` field of a step).

    The builder may hand a step text that is written only when first read (any object whose ``str()`` is the
    caption, e.g. :class:`Later`): most constructions are made to be checked, not read, and their captions are a
    good part of their cost. Once read, the text replaces it. The step's ``__init__`` writes its ``__dict__``, and
    its ``__getstate__`` writes the text before it is copied or pickled.
    """

    def __get__(self, step, owner=None):
        if step is None:
            # No class-level default: the dataclass keeps ``caption`` a required field.
            raise AttributeError("caption")
        text = step.__dict__["caption"]
        if type(text) is not str:
            text = step.__dict__["caption"] = str(text)
        return text

    def __set__(self, step, text):
        # A frozen instance refuses every assignment; the step's __init__ writes the instance's dict.
        raise FrozenInstanceError("cannot assign to field 'caption'")


class Captions:
    """A tuple of captions, as every reader sees it: str each (a descriptor of a frozen dataclass's field).

    As :class:`Caption`, for results whose captions are a tuple (the instant centres' ``steps``): each may be
    handed over unwritten (a :class:`Later`), and all are written the first time the field is read. The class's
    ``__getstate__`` must read the field (write them) before the instance is copied or pickled.
    """

    def __set_name__(self, owner, name):
        self.name = name

    def __get__(self, obj, owner=None):
        if obj is None:
            return ()  # the dataclass's default
        texts = obj.__dict__[self.name]
        if not all(type(text) is str for text in texts):
            texts = obj.__dict__[self.name] = tuple([str(text) for text in texts])
        return texts

    def __set__(self, obj, texts):
        # Only the dataclass's __init__ gets here (object.__setattr__): its frozen __setattr__ refuses the rest.
        obj.__dict__[self.name] = tuple(texts)


_SUPERSCRIPT = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


def mark(k: int) -> str:
    """How sub-problem k (from 1) marks its forces: ′, ″, ‴, ⁗, then ⁽⁵⁾, ⁽⁶⁾, …"""
    return _MARKS[k - 1] if k <= len(_MARKS) else f"⁽{str(k).translate(_SUPERSCRIPT)}⁾"


def roman(k: int) -> str:
    """Sub-problem k's label: I, II, III, IV, …

    Examples
    --------
    >>> [roman(k) for k in (1, 4, 9, 14)]
    ['I', 'IV', 'IX', 'XIV']
    """
    out = ""
    for value, letters in ((1000, "M"), (900, "CM"), (500, "D"), (400, "CD"), (100, "C"), (90, "XC"), (50, "L"),
                           (40, "XL"), (10, "X"), (9, "IX"), (5, "V"), (4, "IV"), (1, "I")):
        while k >= value:
            out, k = out + letters, k - value
    return out


def and_list(items) -> str:
    """``"a"``, ``"a and b"``, ``"a, b and c"``."""
    items = list(items)
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def polar(z, scale: float = 0.0) -> str:
    """A force as the captions print it: ``1290 N ∠ -123.45°`` (``0 N`` for none, or for rounding beside ``scale``)."""
    z = complex(z)
    return polar_text((z.real, z.imag), "N", scale=scale, minus="-")


def number(x: float) -> str:
    """A value in a caption: four significant figures, no exponent where none is needed (``50640``)."""
    return num(x, minus="-")


def sense(T: float) -> str:
    return " (CCW)" if T > 0 else " (CW)" if T < 0 else ""
