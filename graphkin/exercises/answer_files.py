"""Files of answers read as data: JSON and TOML, whatever numbers a student put in them.

``json`` and ``tomllib`` turn a whole number into a Python int, and Python refuses to convert one of
more than 4300 digits (a guard against slow conversions): the whole file would fail to load over one
answer. Here such a number is kept as its text instead, so that it is that one answer's problem (the
reader refuses it with a sentence) and the others are graded.

Examples
--------
>>> answers = json_answers('{"F23": 1' + "0" * 5000 + ', "T12": "12 N*m"}')
>>> len(answers["F23"]), answers["T12"]
(5001, '12 N*m')
>>> toml_answers("F23 = 1" + "0" * 5000 + '\\nT12 = "12 N*m"')["T12"]
'12 N*m'
"""

from __future__ import annotations

import json
import re
import tomllib

LONG_DIGITS = 300
"""A whole number of more digits than this is kept as text (no float holds it anyway)."""

# `key = 123...` with a long run of digits, at the end of a line (a comment may follow): quoted before parsing.
_LONG_TOML_INT = re.compile(rf"^([^\n#\[\"'=]*=[ \t]*)([+-]?[0-9][0-9_]{{{LONG_DIGITS},}})([ \t]*(?:#[^\n]*)?)$",
                            re.MULTILINE)


def _int(text: str):
    return int(text) if len(text.lstrip("+-")) <= LONG_DIGITS else text


def json_answers(text: str):
    """JSON text as data; a whole number too long for a float is kept as its digits.

    Raises
    ------
    ValueError
        Text that is not JSON (``json.JSONDecodeError``), or nested too deeply to read.
    """
    try:
        return json.loads(text, parse_int=_int)
    except RecursionError:
        raise ValueError("nested too deeply to read") from None


def toml_answers(text: str) -> dict:
    """TOML text as data; a whole number too long for a float (a key's whole value) is kept as its digits.

    Raises
    ------
    tomllib.TOMLDecodeError
        Text that is not TOML.
    ValueError
        A number that still cannot be read (a long one inside an array), or nesting too deep.
    """
    try:
        return tomllib.loads(_LONG_TOML_INT.sub(r'\1"\2"\3', text))
    except RecursionError:
        raise ValueError("nested too deeply to read") from None


__all__ = ["LONG_DIGITS", "json_answers", "toml_answers"]
