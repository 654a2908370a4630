"""Values set side by side (a margin's demand and capacity) read in one engineering unit."""

from __future__ import annotations

import math

import pytest

from ballscrew.units import in_display_units


@pytest.mark.parametrize(
    ("values", "unit", "shown", "symbol"),
    [
        ((800.0, 1.2e4), "N", (0.8, 12.0), "kN"),
        ((500.0, 900.0), "N", (500.0, 900.0), "N"),
        ((2.0e6, 3.0e7), "N", (2.0, 30.0), "MN"),
        ((1000.0 * math.pi / 30.0, 317.4 * math.pi / 30.0), "rad/s", (1000.0, 317.4), "rpm"),
        ((9.633e8, 4.2e9), "Pa", (0.9633, 4.2), "GPa"),
        ((5.0e8,), "N/m", (500.0,), "N/µm"),
        ((2.5e-5, 0.0), "m", (25.0, 0.0), "µm"),
        ((1.5, 70.55), "", (1.5, 70.55), ""),
        ((1.0e6, 72890.0), "h", (1.0e6, 72890.0), "h"),
        ((40000.0, 70000.0), "mm·rpm", (40000.0, 70000.0), "mm·rpm"),
        ((math.inf, 2.0e3), "N", (math.inf, 2.0), "kN"),
        ((0.0, 0.0), "m", (0.0, 0.0), "mm"),
    ],
)
def test_one_unit_picked_by_the_largest_value(values, unit, shown, symbol) -> None:
    """The largest finite value picks the unit (a non-finite one is shown as it is)."""
    got, got_symbol = in_display_units(values, unit)
    assert got_symbol == symbol
    assert got == pytest.approx(shown, rel=1e-12)


@pytest.mark.parametrize(
    ("values", "unit", "shown", "symbol"),
    [
        ((881.0, 2.0e7), "N", (0.881, 2.0e4), "kN"),
        ((4840.0, 8.485), "N", (4840.0, 8.485), "N"),
        ((50.0, 4999.0), "N", (0.05, 4.999), "kN"),
    ],
)
def test_values_far_apart_share_the_unit_of_their_geometric_mean(
    values, unit, shown, symbol
) -> None:
    """100 x apart or more, neither reads as a tiny fraction (8.81×10⁻⁴ MN against 20 MN)."""
    got, got_symbol = in_display_units(values, unit)
    assert got_symbol == symbol
    assert got == pytest.approx(shown, rel=1e-12)
