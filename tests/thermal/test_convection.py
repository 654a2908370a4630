"""Convection correlations against worked examples (Q5)–(Q6) and hand values."""

from __future__ import annotations

import math

import pytest

from ballscrew.errors import InputError
from ballscrew.thermal.convection import (
    Air,
    flat_plate_laminar,
    horizontal_cylinder_natural,
    rotating_cylinder,
)

RPM = 2 * math.pi / 60
AIR = Air(1.589e-5, 0.0263, 0.707, 300.0)  # air of the worked examples; β = 1/300 K reproduces Ra


@pytest.mark.parametrize(("rpm", "h"), [(1000, 37.46), (800, 32.28)])
def test_kreith_rotating_screw(rpm, h):
    """(Q5) d = 40 mm: Re = 10545 / 8436, Nu = 56.97 / 49.10, h = 37.46 / 32.28 W/(m² K)."""
    assert rotating_cylinder(0.040, rpm * RPM, AIR) == pytest.approx(h, abs=0.01)


def test_kreith_scales_as_speed_to_two_thirds():
    """Nu ∝ Re^{2/3} ∝ ω^{2/3}, and a screw at rest has no forced convection."""
    ratio = rotating_cylinder(0.04, 200.0, AIR) / rotating_cylinder(0.04, 25.0, AIR)
    assert ratio == pytest.approx(8.0 ** (2 / 3), rel=1e-12)
    assert rotating_cylinder(0.04, 0.0, AIR) == 0.0


def test_churchill_chu_nut():
    """(Q6) OD 70 mm, ΔT = 10 K: Ra = 3.14e5, Nu = 10.55, h = 3.96 W/(m² K)."""
    assert horizontal_cylinder_natural(0.070, 10.0, AIR) == pytest.approx(3.96, abs=0.01)


def test_laminar_flat_plate_by_hand():
    """Moving nut, L = 130 mm at v = 1000 r/min × 10 mm = 0.1667 m/s: Re = 1363.6,
    Nu = 0.664·√Re·Pr^{1/3} = 21.84, h = 4.42 W/(m² K)."""
    v = 1000 / 60 * 0.010
    assert flat_plate_laminar(0.130, v, AIR) == pytest.approx(4.418, abs=0.005)


def test_bad_geometry_raises():
    with pytest.raises(InputError, match="diameter"):
        rotating_cylinder(0.0, 100.0)
    with pytest.raises(InputError, match="temperature_difference"):
        horizontal_cylinder_natural(0.07, 0.0)
