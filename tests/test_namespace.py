"""The public namespace: ``import graphkin as gk`` loads nothing until a name is used, and every name is documented.

The numpydoc checks run on every public function and class of the namespace
(numpydoc's own validator): a docstring, every parameter documented and none
that is not one, in the signature's order, and a Returns section for a
function that returns something.
"""

from __future__ import annotations

import inspect
import subprocess
import sys
from pathlib import Path

import pytest

import graphkin as gk

ROOT = Path(__file__).resolve().parents[1]

CHECKS = {
    "GL08": "no docstring",
    "PR01": "a parameter is not documented",
    "PR02": "a documented parameter is not in the signature",
    "PR03": "the parameters are documented in another order than the signature's",
    "PR07": "a parameter has no description",
    "RT01": "no Returns section",
    "RT03": "the return value has no description",
}
"""numpydoc's error codes the public API is held to (``numpydoc.validate``)."""


def test_importing_graphkin_loads_no_module_of_it_nor_any_other_package():
    code = ("import sys\n"
            "before = set(sys.modules)\n"
            "import graphkin\n"
            "new = {m.split('.')[0] for m in set(sys.modules) - before}\n"
            "print(' '.join(sorted(new - set(sys.stdlib_module_names))),\n"
            "      sorted(m for m in sys.modules if m.startswith('graphkin.')))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=60)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["graphkin", "[]"]


def test_a_public_name_loads_its_module_and_not_the_heavy_ones():
    code = ("import sys, graphkin as gk\n"
            "p = gk.load('double_slider')\n"
            "r = p.solve()\n"
            "c = gk.construct_forces(r.kinematics, 0)\n"
            "print(round(float(r['F12'][0][0]), 4), c.valid,\n"
            "      [m for m in ('matplotlib', 'ipywidgets', 'IPython') if m in sys.modules])")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=60)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["7.5586", "True", "[]"]


@pytest.mark.parametrize("name", [n for n in gk.__all__ if n != "__version__"])
def test_every_public_name_resolves(name):
    value = getattr(gk, name)
    assert value is not None and name in dir(gk)


def test_an_unknown_name_says_so():
    with pytest.raises(AttributeError, match="has no attribute 'solv'"):
        gk.solv  # noqa: B018


def _public_callables():
    out = []
    for name in gk.__all__:
        if name == "__version__":
            continue
        value = getattr(gk, name)
        if inspect.isfunction(value) or inspect.isclass(value):
            out.append(name)
    return out


@pytest.mark.parametrize("name", _public_callables())
def test_the_public_api_follows_the_numpydoc_convention(name):
    validate = pytest.importorskip("numpydoc.validate").validate
    value = getattr(gk, name)
    errors = validate(f"{value.__module__}.{value.__qualname__}")["errors"]
    wanted = set(CHECKS)
    if inspect.isclass(value):
        # A dataclass documents its fields under Attributes (or Parameters): numpydoc reads __init__'s parameters.
        wanted -= {"PR01", "PR02", "PR03", "RT01", "RT03"}
    found = [f"{code} ({CHECKS[code]}): {message}" for code, message in errors if code in wanted]
    assert found == []
