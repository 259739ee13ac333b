"""The fast paths behind the command line's latency (issue 15) give what the slow ones gave.

* A unit pint has converted once is converted again without pint, by pint's
  own factor kept on disk (:data:`graphkin.registries._FACTORS`): the same floats,
  and every error still pint's.
* pint's parsed registry is kept on disk (:func:`graphkin.units.registry`): a
  damaged, missing or unwritable cache costs time, never a wrong number or an
  error.
* ``graphkin``'s JSON (:func:`graphkin.files.json_text`) is ``json.dumps(...,
  indent=2)`` character for character.
* :func:`graphkin.draw.save` draws a PNG once, with the pixels matplotlib's
  ``bbox_inches="tight"`` gives.
* A command imports only what it runs.

Behaviour only: the timings are in ``benchmarks/bench_cli.py``.
"""

from __future__ import annotations

import io
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphkin import units
from graphkin.errors import ProblemFileError
from graphkin.files import json_text
from graphkin.report import cycle_data
from graphkin.report.plain import floats as _floats
from graphkin.units import checks, convert, registries

REPO = Path(__file__).resolve().parents[1]
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


# -- units without pint --------------------------------------------------------------------------


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


# -- pint's registry on disk ---------------------------------------------------------------------


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


# -- JSON ----------------------------------------------------------------------------------------

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


# -- what a command imports ----------------------------------------------------------------------


def test_building_the_parser_imports_nothing_heavy():
    r = _python("import sys\n"
                "from graphkin.cli import parser as _parser\n"
                "_parser()\n"
                "print(sorted(m for m in ('numpy', 'pint', 'matplotlib', 'ipywidgets', 'graphkin.exercises', 'socket',"
                " 'subprocess') if m in sys.modules))")
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]"


def test_numpy_is_loaded_with_one_blas_thread_and_the_environment_is_put_back():
    code = ("import os, sys\n"
            "from graphkin.cli._common import single_threaded_blas as _single_threaded_blas\n"
            "_single_threaded_blas()\n"
            "print('numpy' in sys.modules, os.environ.get('OPENBLAS_NUM_THREADS'))")
    env = {k: v for k, v in os.environ.items() if k not in ("OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS",
                                                           "OMP_NUM_THREADS")}
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, env=env, timeout=60)
    assert r.stdout.split() == ["True", "None"], r.stderr
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, timeout=60,
                       env={**env, "OPENBLAS_NUM_THREADS": "2"})
    assert r.stdout.split()[1] == "2", r.stderr  # the user's choice stands


# -- figures -------------------------------------------------------------------------------------


def _solved(name):
    from graphkin import catalog, report

    r = catalog.load(name).solve()
    return r, report.constructions(r)[0]


def _pixels(source):
    from PIL import Image

    with Image.open(source) as im:
        return np.asarray(im.convert("RGBA")), im.info


# The double slider's solution, small; and a figure whose box is 3487.99... pixels wide at 200 dpi, which Agg
# makes 3488: the canvas's size is read from the canvas, never recomputed.
@pytest.mark.parametrize("name, what, dpi", [("double_slider", "solution", 40), ("slider_crank_friction", "given", 200)])
def test_a_png_is_drawn_once_with_the_pixels_of_matplotlibs_tight_box(tmp_path, name, what, dpi):
    from graphkin import draw

    r, c = _solved(name)

    def make():
        return draw.draw_solution(c, r) if what == "solution" else draw.draw_given(c)

    fig = make()
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi, bbox_inches="tight", pad_inches=0.08, facecolor="white")
    buf.seek(0)
    expected, _ = _pixels(buf)
    fig = make()
    dpi_before, canvas_before = fig.dpi, fig.canvas
    draws = []
    original = type(fig).draw

    def counting(self, renderer):
        draws.append(renderer)
        return original(self, renderer)

    type(fig).draw = counting
    try:
        path = draw.save(fig, tmp_path / "s.png", dpi=dpi)
    finally:
        type(fig).draw = original
    got, info = _pixels(path)
    assert len(draws) == 1
    assert got.shape == expected.shape and np.array_equal(got, expected)
    assert round(info["dpi"][0]) == dpi and info["Software"].startswith("Matplotlib")
    assert fig.dpi == dpi_before and fig.canvas is canvas_before


def test_a_transparent_figure_keeps_its_alpha_and_other_options_go_to_matplotlib(tmp_path):
    from matplotlib.figure import Figure

    from graphkin import draw

    fig = Figure(figsize=(2, 1))
    fig.add_subplot().plot([0, 1], [0, 1])
    got, _ = _pixels(draw.save(fig, tmp_path / "t.png", dpi=30, facecolor="none"))
    assert got[..., 3].min() == 0  # see-through where nothing is drawn
    path = draw.save(fig, tmp_path / "m.png", dpi=30, metadata={"Title": "a line"})
    assert _pixels(path)[1]["Title"] == "a line"
    fig = Figure(figsize=(2, 1), layout="constrained")
    fig.add_subplot().set_title("constrained")
    assert _pixels(draw.save(fig, tmp_path / "c.png", dpi=30))[0].shape[2] == 4
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c.png", "m.png", "t.png"]  # no temporary file left
