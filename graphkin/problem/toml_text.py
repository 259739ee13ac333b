"""A problem file's data written back as TOML: what ``graphkin study ... -o design.toml`` writes.

The data is what ``tomllib`` read (tables, arrays of tables, strings with units, numbers, booleans), so the text
reads back to the same data: ``tomllib.loads(toml_text(data)) == data``. Values come first, then each table
(``[frame]``, ``[driver]``) and each array of tables (``[[links]]``) in the data's order; a table inside one of
those is written inline (``points = { A = ["85 mm", "0 mm"] }``), as the catalog's files write them.
"""

from __future__ import annotations

import json
import math
import re
from typing import Any, Mapping

from graphkin.errors import GraphkinError

__all__ = ["toml_text"]

_BARE = re.compile(r"[A-Za-z0-9_-]+")


def _key(key: str) -> str:
    return key if _BARE.fullmatch(key) else json.dumps(key, ensure_ascii=False)


def _value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return repr(v) if math.isfinite(v) else ("nan" if math.isnan(v) else ("inf" if v > 0 else "-inf"))
    if isinstance(v, str):
        if "\n" in v and v.replace("\n", "").isprintable():  # notes: a multi-line string, as the file wrote it
            return '"""\n' + v.replace("\\", "\\\\").replace('"""', '""\\"') + '"""'
        return json.dumps(v, ensure_ascii=False)  # a TOML basic string: JSON's escapes are TOML's
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, Mapping):
        return "{ " + ", ".join(f"{_key(str(k))} = {_value(x)}" for k, x in v.items()) + " }" if v else "{}"
    raise GraphkinError(f"a problem file holds text, numbers, booleans, lists and tables, not {type(v).__name__}")


def _is_tables(v: Any) -> bool:
    return isinstance(v, list) and bool(v) and all(isinstance(x, Mapping) for x in v)


def toml_text(data: Mapping[str, Any], comment: str = "") -> str:
    """TOML text that reads back to ``data`` (a problem file's tables and values, as ``tomllib`` reads them).

    Parameters
    ----------
    data : mapping
        The file's data.
    comment : str, optional
        Lines written first, each as a ``#`` comment.

    Returns
    -------
    str

    Examples
    --------
    >>> print(toml_text({"title": "A", "links": [{"number": 2, "mass": "1 kg"}], "driver": {"link": 2}}))
    title = "A"
    <BLANKLINE>
    [[links]]
    number = 2
    mass = "1 kg"
    <BLANKLINE>
    [driver]
    link = 2
    <BLANKLINE>
    """
    out = [f"# {line}".rstrip() for line in comment.splitlines()]
    out += [f"{_key(k)} = {_value(v)}" for k, v in data.items() if not isinstance(v, Mapping) and not _is_tables(v)]
    for k, v in data.items():
        if isinstance(v, Mapping):
            out += ["", f"[{_key(k)}]"] + [f"{_key(str(kk))} = {_value(x)}" for kk, x in v.items()]
        elif _is_tables(v):
            for t in v:
                out += ["", f"[[{_key(k)}]]"] + [f"{_key(str(kk))} = {_value(x)}" for kk, x in t.items()]
    return "\n".join(out) + "\n"
