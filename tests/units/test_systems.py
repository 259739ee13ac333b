"""``--units``: the unit systems a report is printed in (graphkin/units/systems.py)."""

from __future__ import annotations

import math
import subprocess
import sys

import pytest

from graphkin.units import to_si
from graphkin.units.systems import KINDS, SI, read_units, unit_system

LBF, INCH, FT = 4.4482216152605, 0.0254, 0.3048  # exact by definition


def test_si_is_what_reports_always_printed():
    assert SI.show(0.2, "length") == 0.2 * 1e3  # mm, the same arithmetic as before
    assert SI.show(1.0, "angle") == math.degrees(1.0)
    assert all(SI.show(3.0, k) == 3.0 for k in ("force", "torque", "angular_velocity", "energy", "power"))
    assert SI.symbol("torque") == "N·m" and SI.is_si


def test_us_units_are_the_inch_pound_books():
    us = unit_system("us")
    assert us.name == "US" and not us.is_si
    assert us.show(LBF, "force") == pytest.approx(1.0, rel=1e-15)
    assert us.show(INCH, "length") == pytest.approx(1.0, rel=1e-15)
    assert us.show(LBF * FT, "torque") == pytest.approx(1.0, rel=1e-15)
    assert us.show(2 * math.pi / 60, "angular_velocity") == pytest.approx(1.0, rel=1e-15)  # rpm
    assert us.show(6894.757293168361, "pressure") == pytest.approx(1.0, rel=1e-12)  # psi
    assert (us.symbol("force"), us.symbol("torque"), us.symbol("length")) == ("lbf", "lbf·ft", "in")


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_si_to_us_to_si_round_trip(kind):
    """A value printed in US units and read back as a problem file reads it gives the SI value again."""
    us = unit_system("US")
    for si in (1234.5678, -0.0123, 7.0):
        shown = us.show(si, kind)
        back = to_si(f"{shown!r} {us.units[kind]}", KINDS[kind], field=kind)
        assert back == pytest.approx(si, rel=1e-14), (kind, si, shown)
        assert us.si(shown, kind) == pytest.approx(si, rel=1e-15)


def test_a_units_file_picks_its_own_over_a_base(tmp_path):
    f = tmp_path / "wentzell.toml"
    f.write_text('base = "US"\ntorque = "lbf*in"\nforce = "kN"\n', encoding="utf-8")
    u = read_units(f)
    assert u.show(LBF * INCH, "torque") == pytest.approx(1.0, rel=1e-15)
    assert u.symbol("torque") == "lbf·in" and u.units["torque"] == "lbf*in"
    assert u.show(1000.0, "force") == pytest.approx(1.0) and u.symbol("force") == "kN"
    assert u.symbol("length") == "in"  # from the base
    g = tmp_path / "si.toml"
    g.write_text('length = "m"\n', encoding="utf-8")
    assert read_units(g).symbol("length") == "m" and read_units(g).symbol("force") == "N"


def test_asking_for_units_does_not_load_pint_on_import():
    code = "import sys, graphkin, graphkin.report, graphkin.units.systems; print('pint' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"
