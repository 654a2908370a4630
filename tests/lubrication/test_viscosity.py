"""ASTM D341 viscosity line, ASTM D2270 viscosity index, density, conductivity, α_p."""

from __future__ import annotations

import itertools
import math

import pytest

from ballscrew.errors import InputError
from ballscrew.lubrication.viscosity import (
    Walther,
    density,
    nu40_from_viscosity_index,
    pressure_viscosity_coefficient,
    reference_viscosities,
    thermal_conductivity,
    viscosity_index,
)

MM2 = 1e-6
T40, T100 = 313.15, 373.15


@pytest.mark.parametrize(("nu40", "nu100"), [(68.0, 8.6), (10.0, 2.65), (460.0, 30.5)])
def test_walther_line_reproduces_its_two_anchor_points(nu40, nu100):
    line = Walther.through(T40, nu40 * MM2, T100, nu100 * MM2)
    assert line.kinematic(T40) == pytest.approx(nu40 * MM2, rel=1e-12)
    assert line.kinematic(T100) == pytest.approx(nu100 * MM2, rel=1e-12)
    assert line.temperature(nu40 * MM2) == pytest.approx(T40, rel=1e-12)
    assert line.temperature(line.kinematic(350.0)) == pytest.approx(350.0, rel=1e-12)


def test_walther_line_matches_a_published_d341_worksheet():
    """A D341 worksheet (T = °C + 273): 32 mm²/s at 313 K, 5.4 at 373 K → A = 9.5259,
    B = 3.7449, ν(353 K) = 8.5 mm²/s."""
    line = Walther.through(313.0, 32 * MM2, 373.0, 5.4 * MM2)
    assert (line.a, line.b) == pytest.approx((9.5259, 3.7449), abs=5e-5)
    assert line.kinematic(353.0) / MM2 == pytest.approx(8.5, abs=0.05)


def test_walther_line_is_the_double_log_law():
    line = Walther.through(T40, 68 * MM2, T100, 8.6 * MM2)
    for t in (280.0, 330.0, 400.0):
        z = line.kinematic(t) / MM2 + 0.7
        assert math.log10(math.log10(z)) == pytest.approx(line.a - line.b * math.log10(t))


def test_viscosity_falls_with_temperature_and_beta_is_its_log_slope():
    line = Walther.through(T40, 68 * MM2, T100, 8.6 * MM2)
    temps = [273.15 + 10.0 * i for i in range(13)]
    nus = [line.kinematic(t) for t in temps]
    assert all(a > b for a, b in itertools.pairwise(nus))
    t, dt = 330.0, 1e-3
    slope = -(math.log(line.kinematic(t + dt)) - math.log(line.kinematic(t - dt))) / (2 * dt)
    assert line.temperature_coefficient(t) == pytest.approx(slope, rel=1e-6)


@pytest.mark.parametrize(
    ("t1", "nu1", "t2", "nu2"),
    [
        (T40, 8.6 * MM2, T100, 68 * MM2),
        (T40, 68 * MM2, T100, 68 * MM2),
        (T100, 8.6 * MM2, T40, 5.0 * MM2),
    ],
)
def test_viscosity_rising_with_temperature_is_refused_naming_the_field(t1, nu1, t2, nu2):
    with pytest.raises(InputError, match=r"^nu100 = .*falls with temperature"):
        Walther.through(t1, nu1, t2, nu2, ("nu40", "nu100"))


def test_d2270_procedure_a_worked_example():
    """ASTM D2270 §5.1.4: U = 73.30, Y = 8.86 mm²/s, L = 119.94, H = 69.48 → VI = 92.43 ≈ 92."""
    vi = viscosity_index(73.30 * MM2, 8.86 * MM2, (119.94 * MM2, 69.48 * MM2))
    assert vi == pytest.approx(92.43, abs=0.005)


def test_d2270_procedure_b_worked_example():
    """ASTM D2270 §6.1.4: U = 22.83, Y = 5.05 mm²/s, H = 28.97 → N = 0.14708, VI = 156.37."""
    vi = viscosity_index(22.83 * MM2, 5.05 * MM2, (60.0 * MM2, 28.97 * MM2))
    assert vi == pytest.approx(156.37, abs=0.01)


def test_d2270_closed_forms_above_70_and_their_inverse():
    y = 80.0
    low, high = reference_viscosities(y * MM2)
    assert low / MM2 == pytest.approx(0.8353 * y * y + 14.67 * y - 216)
    assert high / MM2 == pytest.approx(0.1684 * y * y + 11.85 * y - 97)
    assert viscosity_index(low, y * MM2) == pytest.approx(0.0, abs=1e-9)
    assert viscosity_index(high, y * MM2) == pytest.approx(100.0)
    for vi in (-20.0, 0.0, 55.0, 100.0, 140.0, 200.0):
        nu40 = nu40_from_viscosity_index(y * MM2, vi)
        assert viscosity_index(nu40, y * MM2) == pytest.approx(vi, abs=1e-9)


def test_d2270_table_range_needs_l_and_h():
    with pytest.raises(InputError, match=r"^nu100 = .*ASTM D2270 Table 1"):
        viscosity_index(68 * MM2, 8.6 * MM2)
    with pytest.raises(InputError, match=r"^nu100 = .*undefined below 2"):
        viscosity_index(5 * MM2, 1.5 * MM2, (1.0, 1.0))


def test_density_and_conductivity():
    assert density(288.15, 880.0) == 880.0
    assert density(388.15, 880.0) == pytest.approx(880.0 * (1 - 0.064))
    # Cragoe (1929): k = 0.813/d Btu in/(h ft² °F) at 32 °F, d = 1 → 0.1172 W/(m K).
    btu_in = 1055.056 / 3600.0 * 0.0254 / 0.3048**2 / (5.0 / 9.0)
    assert thermal_conductivity(273.15, 999.0) == pytest.approx(0.813 * btu_in, rel=1e-3)
    assert thermal_conductivity(373.15, 999.0) == pytest.approx(0.1172 * (1 - 0.054))


def test_gold_pressure_viscosity_of_mineral_oil():
    """Gold et al. (2001), mineral oil: α = 9.904 ν^0.1390 GPa⁻¹ (ν in mm²/s)."""
    assert pressure_viscosity_coefficient(1.0 * MM2) == pytest.approx(9.904e-9)
    assert pressure_viscosity_coefficient(68 * MM2) == pytest.approx(9.904e-9 * 68**0.139)
    assert 1.5e-8 < pressure_viscosity_coefficient(68 * MM2) < 2.5e-8
    with pytest.raises(InputError, match=r"^oil_class = 'ester'.*mineral"):
        pressure_viscosity_coefficient(68 * MM2, "ester")
