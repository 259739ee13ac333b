"""Units converted without pint, by pint's own factor kept on disk, and pint's parsed registry kept on disk.

The same floats as pint gives, every error still pint's; a damaged, missing or unwritable cache costs time,
never a wrong number or an error. Timings are in ``benchmarks/bench_cli.py``.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphkin import units
from graphkin.errors import ProblemFileError
from graphkin.units import checks, convert, registries

REPO = Path(__file__).resolve().parents[2]


# Units teachers write; each is learned from pint on its first use.
TABLE = sorted({
    ("mm", "length"), ("cm", "length"), ("m", "length"), ("in", "length"), ("ft", "length"),
    ("deg", "angle"), ("degree", "angle"), ("rad", "angle"), ("rev", "angle"), ("turn", "angle"),
    ("g", "mass"), ("kg", "mass"), ("lb", "mass"), ("ms", "time"), ("s", "time"), ("min", "time"),
    ("m/s", "velocity"), ("mm/s", "velocity"), ("km/h", "velocity"), ("m/s^2", "acceleration"),
    ("mm/s**2", "acceleration"), ("rpm", "angular_velocity"), ("rad/s", "angular_velocity"),
    ("deg/s", "angular_velocity"), ("rev/min", "angular_velocity"), ("rad/s^2", "angular_acceleration"),
    ("deg/s**2", "angular_acceleration"), ("rpm/s", "angular_acceleration"), ("N", "force"), ("kN", "force"),
    ("lbf", "force"), ("N*m", "torque"), ("N*mm", "torque"), ("kN*m", "torque"), ("N·m", "torque"),
    ("kg*m^2", "moment_of_inertia"), ("kg*mm^2", "moment_of_inertia"), ("g*cm^2", "moment_of_inertia"),
    ("J", "energy"), ("kJ", "energy"), ("N*mm", "energy"), ("kg/m^3", "density"), ("g/cm^3", "density"),
    ("%", "dimensionless"), ("percent", "dimensionless"),
})


@pytest.fixture(autouse=True)
def _own_cache(tmp_path_factory, monkeypatch):
    """Each test learns units into a cache folder of its own, never the user's."""
    monkeypatch.setenv("GRAPHKIN_CACHE_DIR", str(tmp_path_factory.mktemp("cache")))
    monkeypatch.setattr(registries, "_FACTORS", None)


def _python(code: str, **env) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO,
                          env={**os.environ, **env}, timeout=120)


def _learned(unit, dimension):
    """The factor graphkin learns for ``unit`` from pint (by converting "1 unit" once), or None."""
    convert._CONVERTED.clear()
    try:
        units.to_si(f"1 {unit}", dimension, field="x", file="f.toml")
    except ProblemFileError:
        return None
    return registries.known_factors().get((unit, dimension))


def _convert(text, dimension, *, table=True):
    """``to_si`` with or without the learned factors: the value, or the error's message."""
    saved = registries.known_factors()
    registries._FACTORS = dict(saved) if table else {}
    convert._CONVERTED.clear()
    try:
        return units.to_si(text, dimension, field="x", file="f.toml")
    except ProblemFileError as exc:
        return f"error: {exc}"
    finally:
        registries._FACTORS = saved
        convert._CONVERTED.clear()


@pytest.mark.parametrize("unit, dimension", TABLE)
def test_each_factor_is_pints_own_and_pint_accepts_the_unit(unit, dimension):
    ureg = units.registry()
    parsed = checks.parse_unit(unit, f"1 {unit}", "f.toml", "x")
    checks.check_unit(parsed, f"1 {unit}", dimension, "f.toml", "x")  # raises if pint would refuse it
    pint_factor = ureg.Quantity(1.0, parsed).m_as(units.SI_UNITS[dimension] or "dimensionless")
    assert _learned(unit, dimension) == pint_factor  # exactly: pint converts x as x * factor
    # Kept on disk: a fresh process reads it back without pint.
    registries._FACTORS = None
    assert registries.known_factors()[unit, dimension] == pint_factor


@settings(max_examples=300, deadline=None)
@given(entry=st.sampled_from(TABLE),
       x=st.floats(allow_nan=False, allow_infinity=False) | st.integers(-10**6, 10**6),
       spaced=st.booleans())
def test_the_table_gives_the_same_float_as_pint(entry, x, spaced):
    unit, dimension = entry
    assert _learned(unit, dimension) is not None
    text = f"{x!r}{' ' if spaced else ''}{unit}"
    assert _convert(text, dimension) == _convert(text, dimension, table=False)


@settings(max_examples=100, deadline=None)
@given(unit=st.sampled_from(sorted({u for u, _ in TABLE})), dimension=st.sampled_from(sorted(units.DIMENSIONS)),
       x=st.sampled_from(["1", "-2.5", "1e308", "0", "nan", "inf", "1,5"]))
def test_every_unit_in_every_dimension_says_what_pint_says(unit, dimension, x):
    """Right or wrong dimension, overflow, nan: the same value or the same message, table or not."""
    for d in sorted(units.DIMENSIONS):
        _learned(unit, d)
    text = f"{x} {unit}"
    assert _convert(text, dimension) == _convert(text, dimension, table=False)


def test_a_damaged_or_foreign_factor_file_is_only_time_lost(tmp_path, monkeypatch):
    monkeypatch.setenv("GRAPHKIN_CACHE_DIR", str(tmp_path))
    path = tmp_path / "unit-factors.json"
    for text in ("garbage", "", json.dumps({"pint": "another", "factors": [["mm", "length", 1.0]]}),
                 json.dumps({"pint": registries._pint_stamp(), "factors": [["mm", "length", "0.001"], ["x", "nope", 1.0]]})):
        path.write_text(text, encoding="utf-8")
        registries._FACTORS = None
        assert registries.known_factors() == {}
        convert._CONVERTED.clear()
        assert units.to_si("250 mm", "length", field="x", file="f.toml") == 0.25
        registries._FACTORS = None
        assert registries.known_factors()[("mm", "length")] == 0.001  # written again, whole


def test_an_unwritable_cache_folder_is_skipped(tmp_path, monkeypatch):
    (tmp_path / "file").write_text("not a folder", encoding="utf-8")
    monkeypatch.setenv("GRAPHKIN_CACHE_DIR", str(tmp_path / "file" / "cache"))
    convert._CONVERTED.clear()
    assert units.to_si("3 kN", "force", field="x", file="f.toml") == 3000.0


def test_reading_every_catalog_problem_and_solving_does_not_import_pint(tmp_path):
    # The first command meets the catalog's units through pint and keeps their factors; the next needs no pint.
    warm = _python("from graphkin import catalog\nfor name in catalog.names(): catalog.load(name)\n"
                   "from graphkin.cli import main\nmain(['solve', 'double_slider', '--at', '200 mm,250 mm'])",
                   GRAPHKIN_CACHE_DIR=str(tmp_path))
    assert warm.returncode == 0, warm.stderr
    r = _python("import sys\n"
                "from graphkin import catalog\n"
                "from graphkin.cli import main\n"
                "for name in catalog.names(): catalog.load(name)\n"
                "assert main(['solve', 'double_slider', '--at', '200 mm,250 mm']) == 0\n"
                "print('loaded:', sorted(m for m in ('pint', 'matplotlib', 'ipywidgets', 'graphkin.exercises')"
                " if m in sys.modules))", GRAPHKIN_CACHE_DIR=str(tmp_path))
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip().splitlines()[-1] == "loaded: []"


def _factors(ureg, names=("mm", "deg", "rpm", "N*mm", "kg*mm^2", "lbf", "g/cm^3", "revolution/min", "inch", "kWh")):
    return [ureg.Quantity(1.0, n).to_base_units().magnitude for n in names]


@pytest.fixture(scope="module")
def pint():
    import pint

    return pint


@pytest.fixture(scope="module")
def plain(pint):
    return _factors(pint.UnitRegistry())


def _cache(root: Path) -> Path:
    (folder,) = [p for p in root.iterdir() if p.name.startswith("pint-")]
    return folder


def test_the_cache_is_made_once_and_read_after(tmp_path, pint, plain):
    first = registries._cached_registry(pint, tmp_path)
    folder = _cache(tmp_path)
    names = json.loads((folder / registries._PINT_MARKER).read_text())
    assert names and all((folder / n).is_file() for n in names)
    assert [p.name for p in tmp_path.iterdir()] == [folder.name]  # no temporary folder left behind
    stamp = {n: (folder / n).stat().st_mtime_ns for n in names}
    second = registries._cached_registry(pint, tmp_path)
    assert {n: (folder / n).stat().st_mtime_ns for n in names} == stamp  # read, not written again
    assert _factors(first) == _factors(second) == plain


@pytest.mark.parametrize("damage", ["garbage", "truncated", "empty", "missing", "marker"])
def test_a_damaged_cache_still_gives_the_same_numbers_and_is_mended(tmp_path, pint, plain, damage):
    registries._cached_registry(pint, tmp_path)
    folder = _cache(tmp_path)
    pickles = sorted(folder.glob("*.pickle"))
    for p in pickles:
        if damage == "garbage":
            p.write_bytes(b"not a pickle at all")
        elif damage == "truncated":
            p.write_bytes(p.read_bytes()[: p.stat().st_size // 2])
        elif damage == "empty":
            p.write_bytes(b"")
    if damage == "missing":
        pickles[0].unlink()
    if damage == "marker":
        (folder / registries._PINT_MARKER).write_text("{not json")
    assert _factors(registries._cached_registry(pint, tmp_path)) == plain
    # Mended: the next process reads whole files again.
    for p in folder.glob("*.pickle"):
        import pickle

        pickle.loads(p.read_bytes())
    assert _factors(registries._cached_registry(pint, tmp_path)) == plain


def test_a_cache_folder_that_cannot_be_written_is_skipped(tmp_path, pint, plain):
    blocker = tmp_path / "a-file"
    blocker.write_text("in the way")
    assert _factors(registries._cached_registry(pint, blocker / "cache")) == plain  # mkdir fails: no cache
    if os.geteuid() != 0:  # root writes anywhere
        ro = tmp_path / "read-only"
        ro.mkdir()
        ro.chmod(0o500)
        try:
            assert _factors(registries._cached_registry(pint, ro)) == plain
        finally:
            ro.chmod(0o700)


def test_the_cache_folder_follows_the_environment(monkeypatch, tmp_path):
    monkeypatch.setenv("GRAPHKIN_CACHE_DIR", str(tmp_path))
    assert units.cache_folder() == tmp_path
    monkeypatch.setenv("GRAPHKIN_CACHE_DIR", "")
    assert units.cache_folder() is None
    monkeypatch.delenv("GRAPHKIN_CACHE_DIR")
    assert units.cache_folder() is not None


@pytest.mark.slow
def test_processes_that_build_the_cache_at_once_all_get_a_registry(tmp_path):
    code = ("from graphkin import units\n"
            "ureg = units.registry()\n"
            "print(ureg.Quantity(900, 'rpm').m_as('rad/s'), units.format_si(0.865, 'torque', 'N*mm'))")
    procs = [subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                              cwd=REPO, env={**os.environ, "GRAPHKIN_CACHE_DIR": str(tmp_path)}) for _ in range(3)]
    outs = [p.communicate(timeout=120) for p in procs]
    assert all(p.returncode == 0 for p in procs), [e for _, e in outs]
    assert {o.strip() for o, _ in outs} == {"94.24777960769379 865 N·mm"}
    folder = _cache(tmp_path)
    assert all((folder / n).is_file() for n in json.loads((folder / registries._PINT_MARKER).read_text()))
