"""A crank placed by its piston's travel from a dead centre (``driver.travel``, issue 35): a length or a fraction of
the stroke, on the stroke away from the dead centre or back towards it.

The crank angles are checked against the piston's displacement worked out by hand (the crank pin on the circles
about the pivot and about the piston's pin), for an in-line and an offset engine, either sense of rotation and
either dead centre; bad travels are one line naming the field.
"""

from __future__ import annotations

import math
from importlib.resources import files

import numpy as np
import pytest

from graphkin.problem import parse_problem
from tests.bad_input.test_catalogue import solve_refuses

ENGINE = (files("graphkin.catalog") / "engine_double_acting_khurmi.toml").read_text(encoding="utf-8")
"""Crank 200 mm, rod 600 mm, the piston on +x of the pivot; 45° from the inner dead centre, clockwise."""

R, L = 0.2, 0.6


def edit(text, *pairs):
    for old, new in pairs:
        assert old in text, old
        text = text.replace(old, new, 1)
    return text


def engine(travel: str, *, offset_mm: float = 0.0, extra: str = "", sense: str = "clockwise") -> str:
    frame = f'points = {{ O = ["0 mm", "0 mm"], E = ["0 mm", "{offset_mm} mm"] }}'
    return edit(ENGINE, ('through = "O"', 'through = "E"'), ('points = { O = ["0 mm", "0 mm"] }', frame),
                ('theta = "45 deg"', f"travel = {travel}{extra}"), ('sense = "clockwise"', f'sense = "{sense}"'))


def piston_x(theta, e=0.0):
    """The piston pin's x for the crank at θ (from +x), the guide the line y = e: by hand."""
    return R * np.cos(theta) + np.sqrt(L**2 - (e - R * np.sin(theta)) ** 2)


def dead_centres(e=0.0):
    """x of the piston's pin at the inner (crank and rod in line, r + l from the pivot) and outer (l − r) centres."""
    return math.sqrt((R + L) ** 2 - e**2), math.sqrt((L - R) ** 2 - e**2)


@pytest.mark.parametrize("offset", [0.0, 50.0, -80.0])
@pytest.mark.parametrize("sense", ["clockwise", "counter-clockwise"])
@pytest.mark.parametrize("which", ["inner dead centre", "outer dead centre"])
@pytest.mark.parametrize("moving", ["away", "towards"])
def test_the_piston_stands_at_its_travel_on_the_stroke_named(offset, sense, which, moving):
    e = offset / 1e3
    text = engine('["80 mm", 0.25, "1/3", 0.999]', offset_mm=offset, sense=sense,
                  extra=f'\nmoving = "{moving}"')
    text = edit(text, ('from = "inner dead centre"', f'from = "{which}"'))
    problem = parse_problem(text)
    x_in, x_out = dead_centres(e)
    stroke = x_in - x_out
    start, away = (x_in, -1.0) if which.startswith("inner") else (x_out, 1.0)
    travel = np.array([0.080, 0.25 * stroke, stroke / 3, 0.999 * stroke])
    np.testing.assert_allclose(piston_x(problem.q, e), start + away * travel, rtol=0, atol=1e-13)
    # The stroke: the piston's velocity as the crank turns in its sense, away from the dead centre or back to it.
    turn = 1.0 if sense == "counter-clockwise" else -1.0
    h = 1e-7
    v = (piston_x(problem.q + turn * h, e) - piston_x(problem.q - turn * h, e)) / (2 * h)
    assert np.all(np.sign(v) == away * (1.0 if moving == "away" else -1.0)), v


def test_the_dead_centres_themselves_are_travel_0_and_the_whole_stroke():
    """0 and the whole stroke (a fraction 1, or its length as written) are the dead centres exactly, on either
    stroke: no angle off by the rounding of the stroke's length."""
    ends = parse_problem(engine('[0, 1, "400 mm", "0 mm"]')).q
    ccw = parse_problem(engine('[0, 1, "400 mm", "0 mm"]', extra='\nmoving = "towards"')).q
    for q in (ends, ccw):
        np.testing.assert_allclose(np.mod(q, 2 * math.pi), [0.0, math.pi, math.pi, 0.0], rtol=0, atol=1e-15)


def test_a_fraction_is_of_the_stroke_between_the_two_dead_centres():
    """An offset engine's stroke is longer than twice the crank: a fraction is of that stroke."""
    x_in, x_out = dead_centres(0.05)
    assert x_in - x_out > 2 * R
    a, b = (parse_problem(engine(t, offset_mm=50.0)).q[0] for t in ("0.5", f'"{(x_in - x_out) / 2 * 1e3!r} mm"'))
    assert a == pytest.approx(b, abs=1e-12)


def test_the_crank_angle_then_serves_as_theta_does():
    """The travel only places the crank: the same problem with that θ written out (from +x) solves the same."""
    by_travel = parse_problem(engine('"80 mm"'))
    theta = math.degrees(by_travel.q[0])
    by_angle = parse_problem(edit(ENGINE, ('theta = "45 deg"', f'theta = "{theta!r} deg"'),
                                  ('from = "inner dead centre"\n', "")))
    assert by_angle.q[0] == pytest.approx(by_travel.q[0], abs=1e-12)
    np.testing.assert_allclose(by_travel.solve().effort, by_angle.solve().effort, rtol=1e-9)


# -- bad travels ------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("travel, named", [
    ('"420 mm"', ['"420 mm" is beyond the stroke', "400 mm from the inner dead centre"]),
    ('["80 mm", "401 mm"]', ["driver.travel[1]", "beyond the stroke", "400 mm"]),
    ("1.5", ["1.5 is not a fraction of the stroke", "from 0 to 1"]),
    ('"-10 mm"', ["give it ≥ 0"]),
    ('"3/0"', ["divides by zero"]),
    ('"80 N"', ["driver.travel", "length"]),
    ("true", ["must be a length"]),
])
def test_a_travel_the_engine_cannot_make_is_refused(capsys, tmp_path, travel, named):
    solve_refuses(capsys, tmp_path, engine(travel), "driver.travel", *named)


def test_travel_and_theta_together_are_refused(capsys, tmp_path):
    solve_refuses(capsys, tmp_path, edit(ENGINE, ('theta = "45 deg"', 'theta = "45 deg"\ntravel = "80 mm"')),
                  "driver.travel", "not both")


def test_moving_without_a_travel_is_refused(capsys, tmp_path):
    solve_refuses(capsys, tmp_path, edit(ENGINE, ('theta = "45 deg"', 'theta = "45 deg"\nmoving = "away"')),
                  "driver.moving", "with travel")


def test_a_stroke_named_wrongly_is_refused(capsys, tmp_path):
    solve_refuses(capsys, tmp_path, engine('"80 mm"', extra='\nmoving = "out"'), "driver.moving", '"away"',
                  '"towards"')


def test_a_clockwise_omega_without_its_sense_is_refused(capsys, tmp_path):
    """Without driver.sense the crank is taken to turn counter-clockwise; a negative ω says otherwise, and the
    stroke the piston is on depends on it."""
    text = edit(engine('"80 mm"'), ('sense = "clockwise"\n', ""), ('omega = "120 rpm"', 'omega = "-120 rpm"'))
    solve_refuses(capsys, tmp_path, text, "driver.omega", "clockwise", 'sense = "clockwise"')


def test_a_slider_driver_has_no_travel(capsys, tmp_path):
    from tests.bad_input.test_issue25_fields import SLIDER_PLACED

    text = edit(SLIDER_PLACED, ("place = { link = 2, theta = \"60 deg\" }", 'travel = "10 mm"'))
    solve_refuses(capsys, tmp_path, text, "driver.travel", "slider driver's position is s")


def test_a_linkage_without_a_piston_has_no_travel(capsys, tmp_path):
    from tests.bad_input.test_issue25_fields import EPICYCLIC

    text = edit(EPICYCLIC, ('theta = "30 deg"', 'travel = "10 mm"'))
    solve_refuses(capsys, tmp_path, text, "driver.travel", "slider-crank")


def test_a_handout_states_the_travel_and_the_crank_angle_it_gives(tmp_path):
    """The table of given data says what the book says, and where that puts the crank."""
    from graphkin import handout

    path = tmp_path / "engine.toml"
    path.write_text(engine('"80 mm"'), encoding="utf-8")
    theta = math.degrees(parse_problem(engine('"80 mm"')).q[0])
    text = handout.render(handout.build(str(path)), "md")[0].decode()
    row = next(line for line in text.splitlines() if line.startswith("| driver, link 2"))
    assert "piston travel = 80 mm, so" in row and f"= {theta:.6g}°".replace("-", "−") in row, row
