"""The numerical semi-axes: contact edges interpolated between cells, so that a grid sized to the
Hertz ellipse no longer returns the Hertz semi-axes by construction."""

from pathlib import Path

import numpy as np
import pytest

from ballscrew.case import load_case
from ballscrew.contact import contact_semi_axes, hertz, solve_contact

E_STAR = 113.19e9
ROOT = Path(__file__).resolve().parents[2]
CONTACTS = {"sphere": (10e-3, 10e-3, 100.0), "screw contact A": (1 / 354.5, 1 / 12.11, 85.9)}


def paraboloid(rx, ry):
    return lambda x, y: x**2 / (2 * rx) + y**2 / (2 * ry)


@pytest.mark.parametrize("name", CONTACTS)
def test_semi_axes_of_a_hertz_gap_are_hertz_to_half_a_percent(name):
    """64 cells across the Hertz ellipse: a and b within 0.5 % (measured −0.37 % and −0.31 %);
    the loaded cells alone cannot tell a from a ± Δ/2 (±0.8 %)."""
    rx, ry, load = CONTACTS[name]
    reference = hertz(rx, ry, E_STAR, load)
    a, b = solve_contact(paraboloid(rx, ry), rx, ry, E_STAR, load).solution.semi_axes
    assert a == pytest.approx(reference.a, rel=5e-3)
    assert b == pytest.approx(reference.b, rel=5e-3)


@pytest.mark.parametrize("name", CONTACTS)
def test_semi_axes_of_a_gap_that_is_not_the_grids_hertz_are_found(name):
    """The gap has radii 1.3 × those the grid is sized from: its Hertz semi-axes are 1.3^(1/3) =
    1.0914 × the grid's; the interpolated edges find them to 0.5 % (a difference to the grid's
    Hertz of +8.7 %, where the loaded cells' half-extent is stuck on the cells)."""
    rx, ry, load = CONTACTS[name]
    grid_hertz, true = hertz(rx, ry, E_STAR, load), hertz(1.3 * rx, 1.3 * ry, E_STAR, load)
    solution = solve_contact(paraboloid(1.3 * rx, 1.3 * ry), rx, ry, E_STAR, load).solution
    a, b = solution.semi_axes
    assert a == pytest.approx(true.a, rel=5e-3)
    assert b == pytest.approx(true.b, rel=5e-3)
    assert a / grid_hertz.a - 1 == pytest.approx(1.3 ** (1 / 3) - 1, abs=5e-3)


def test_edges_of_a_sampled_hertz_profile_are_second_order():
    """p = p0·√(1 − x²/a²) at cell centres, the edge at various places in a cell: the half-width
    is a to within Δ²/a (the secant of P² = p0²(1 − x²/a²) over the last two cells misses the
    edge by ε(ε + Δ)/(2a), ε ≤ Δ the edge's distance past the last centre), against ±Δ/2 for the
    loaded cells' extent (measured 0.0017, 0.0030, 0.00015, 7e-6 at Δ = 0.115 ... 0.0144)."""
    for n in (20, 40, 80, 160):
        step = 2.3 / n
        x = (np.arange(-n, n) + 0.5) * step
        p = np.sqrt(np.maximum(1 - x**2, 0.0))[:, None] * np.ones((1, 3))
        assert abs(contact_semi_axes(p, step, 1.0)[0] - 1.0) < step**2


def test_a_lone_cell_and_no_contact():
    p = np.zeros((5, 4))
    assert contact_semi_axes(p, 1.0, 2.0) == (0.0, 0.0)
    p[2, 1] = 3.0
    assert contact_semi_axes(p, 1.0, 2.0) == (0.5, 1.0)


def test_the_contact_summary_reports_a_semi_axis_difference_that_is_not_zero():
    """The example screw (exact helical gap, 64 cells across): the semi-axes differ from Hertz
    by a fraction of a percent, no longer exactly 0.0, and the summary gives the solution's."""
    from ballscrew.analyses.ball_contact import solve_ball_contacts

    result = solve_ball_contacts(load_case(ROOT / "examples" / "gao2019_tcr.toml"))
    for side in ("screw", "nut"):
        contact = result.contact(side)
        summary = result.summary()["contacts"][side]
        difference = summary["relative_difference_to_hertz"]
        for key, numerical, closed in (
            ("semi_axis_x", contact.solution.semi_axes[0], contact.hertz.a),
            ("semi_axis_y", contact.solution.semi_axes[1], contact.hertz.b),
        ):
            assert difference[key] != 0.0
            assert abs(difference[key]) < 0.02
            assert difference[key] == pytest.approx(numerical / closed - 1, rel=1e-12)
