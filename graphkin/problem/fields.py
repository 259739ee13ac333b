"""A problem file's fields by path: ``"driver.theta"``, ``"links[1].mass"``, ``"loads[0].force.magnitude"``.

What an exercise varies from student to student (and a study from design to design) is a field of the problem
file, named by the path a teacher reads in the file: tables and keys joined by dots, list items by ``[index]``.
These functions read such a path, find whether the problem has it, and put a value there.

Examples
--------
>>> field_path("loads[0].force.magnitude")
['loads', 0, 'force', 'magnitude']
>>> data = {"driver": {"theta": "30 deg"}, "links": [{"id": 1}, {"id": 2, "mass": "1 kg"}]}
>>> set_field(data, "links[1].mass", "2 kg"); data["links"][1]
{'id': 2, 'mass': '2 kg'}
>>> missing(data, "links[2].mass")
'links[2]'
"""

from __future__ import annotations

import re
from typing import Any

_TOKEN = re.compile(r"([A-Za-z_]\w*)|\[(\d+)\]")


def field_path(field: str) -> list[str | int]:
    """The keys of a dotted field path: ``"links[1].mass"`` → ``["links", 1, "mass"]``.

    Raises
    ------
    KeyError
        ``field`` is not a path (an empty part, a stray character).
    """
    keys: list[str | int] = []
    for part in field.split("."):
        pos = 0
        for m in _TOKEN.finditer(part):
            if m.start() != pos:
                raise KeyError(field)
            keys.append(m[1] if m[1] is not None else int(m[2]))
            pos = m.end()
        if pos != len(part) or not part:
            raise KeyError(field)
    return keys


def missing(data: dict, field: str) -> str | None:
    """The first part of ``field`` that problem data ``data`` does not have, as a path (None if it has them all).

    The last key of a table may be missing (it is a field the file may leave out and a value may fill in); a
    list's index must exist.

    Raises
    ------
    KeyError
        ``field`` is not a path.
    """
    keys = field_path(field)
    node: Any = data
    for i, key in enumerate(keys):
        last = i == len(keys) - 1
        ok = (isinstance(key, int) and isinstance(node, list) and key < len(node)) or \
             (isinstance(key, str) and isinstance(node, dict) and (key in node or last))
        if not ok:
            return "".join(f"[{k}]" if isinstance(k, int) else ("." if n else "") + k for n, k in enumerate(keys[:i + 1]))
        if not last:
            node = node[key]
    return None


def set_field(data: dict, field: str, value: Any, *, copy: bool = False) -> None:
    """Put ``value`` at the dotted ``field`` of problem data, in place.

    With ``copy``, every table and list on the way is copied first, so the
    data ``data`` shares with another dict (a shallow copy of an exercise's
    base problem) are left untouched; copying only that path is ~10× cheaper
    than a deep copy of the whole file.
    """
    keys = field_path(field)
    node: Any = data
    for key in keys[:-1]:
        if copy:
            node[key] = type(node[key])(node[key])
        node = node[key]
    node[keys[-1]] = value
