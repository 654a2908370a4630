"""ASTM D341 viscosity line, ASTM D2270 viscosity index, density, conductivity, α_p."""

from __future__ import annotations

import itertools
import math

import pytest

from ballscrew.errors import InputError
from ballscrew.lubrication.viscosity import (
    ISO_VISCOSITY_GRADES,
    Walther,
    density,
    nu40_from_viscosity_index,
    nu100_from_viscosity_index,
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
    """ASTM D2270-10 §5.1.4: U = 73.30, Y = 8.86 mm²/s; Table 1 by interpolation L = 119.94,
    H = 69.48; VI = 92.43, reported 92."""
    low, high = reference_viscosities(8.86 * MM2)
    assert (low / MM2, high / MM2) == (
        pytest.approx(119.94, abs=5e-3),
        pytest.approx(69.48, abs=5e-3),
    )
    vi = viscosity_index(73.30 * MM2, 8.86 * MM2)
    assert vi == pytest.approx(92.43, abs=5e-3)
    assert round(vi) == 92


def test_d2270_procedure_b_worked_example():
    """ASTM D2270-10 §6.1.4 (1): U = 22.83, Y = 5.05 mm²/s; Table 1 by interpolation H = 28.97;
    N = 0.14708, VI = 156.37, reported 156 (the table row mean is 28.975, printed 28.97)."""
    high = reference_viscosities(5.05 * MM2)[1] / MM2
    assert high == pytest.approx(28.97, abs=5e-3)
    vi = viscosity_index(22.83 * MM2, 5.05 * MM2)
    assert math.log10(1 + 0.00715 * (vi - 100)) == pytest.approx(0.14708, abs=2e-4)
    assert round(vi) == 156


def test_d2270_reference_oils_have_vi_0_and_100_over_the_table_and_above():
    # L and H are by definition the ν40 of the VI = 0 and VI = 100 oils of the same ν100
    for y in (2.0, 2.65, 8.6, 19.95, 30.0, 55.25, 70.0, 80.0, 300.0):
        low, high = reference_viscosities(y * MM2)
        assert viscosity_index(low, y * MM2) == pytest.approx(0.0, abs=1e-9)
        assert viscosity_index(high, y * MM2) == pytest.approx(100.0, abs=1e-9)


def test_d2270_table_rows_and_closed_forms():
    # printed rows are returned as printed; interpolation between rows is linear (§5.1.1)
    assert tuple(v / MM2 for v in reference_viscosities(2.0 * MM2)) == pytest.approx((7.994, 6.394))
    assert tuple(v / MM2 for v in reference_viscosities(70.0 * MM2)) == pytest.approx((4905, 1558))
    mid = tuple(v / MM2 for v in reference_viscosities(30.25 * MM2))
    assert mid == pytest.approx(((1023 + 1055) / 2, (421.7 + 432.4) / 2))
    y = 80.0
    low, high = reference_viscosities(y * MM2)
    assert low / MM2 == pytest.approx(0.8353 * y * y + 14.67 * y - 216)
    assert high / MM2 == pytest.approx(0.1684 * y * y + 11.85 * y - 97)
    # the table's last row and the closed forms meet at 70 mm²/s to 0.03 %
    y = 70.0 + 1e-9
    assert reference_viscosities(y * MM2)[0] / MM2 == pytest.approx(4905, rel=3e-4)
    assert reference_viscosities(y * MM2)[1] / MM2 == pytest.approx(1558, rel=3e-4)


@pytest.mark.parametrize("nu100", [2.3, 8.86, 25.0, 80.0])
@pytest.mark.parametrize("vi", [-20.0, 0.0, 55.0, 100.0, 140.0, 200.0])
def test_nu40_from_viscosity_index_inverts_it(nu100, vi):
    nu40 = nu40_from_viscosity_index(nu100 * MM2, vi)
    assert viscosity_index(nu40, nu100 * MM2) == pytest.approx(vi, abs=1e-9)


@pytest.mark.parametrize("grade", ISO_VISCOSITY_GRADES[4:])
@pytest.mark.parametrize("vi", [0.0, 50.0, 95.0, 100.0, 140.0, 250.0])
def test_nu100_from_viscosity_index_round_trips_to_1e_9(grade, vi):
    nu100 = nu100_from_viscosity_index(grade * MM2, vi)
    assert 2 * MM2 <= nu100 < grade * MM2
    assert viscosity_index(grade * MM2, nu100) == pytest.approx(vi, abs=1e-9)


def test_nu100_from_viscosity_index_of_the_worked_examples():
    assert nu100_from_viscosity_index(73.30 * MM2, 92.43) / MM2 == pytest.approx(8.86, abs=5e-3)
    assert nu100_from_viscosity_index(22.83 * MM2, 156.37) / MM2 == pytest.approx(5.05, abs=5e-3)
    # a higher VI is a flatter line: ν100 rises with VI at the same ν40
    nus = [nu100_from_viscosity_index(68 * MM2, vi) for vi in (0.0, 50.0, 100.0, 150.0)]
    assert nus == sorted(nus)


def test_viscosity_index_outside_the_definition_is_refused_naming_the_field():
    with pytest.raises(InputError, match=r"^nu100 = .*undefined below 2"):
        viscosity_index(5 * MM2, 1.5 * MM2)
    with pytest.raises(InputError, match=r"^nu100 = .*undefined below 2"):
        reference_viscosities(1.9 * MM2)
    # ν40 = 10 mm²/s reaches ν100 = 2 mm²/s at VI = −125.4: lower VIs have no ν100 ≥ 2
    with pytest.raises(InputError, match=r"^viscosity_index = -300.0 is not allowed: -?\d.* to "):
        nu100_from_viscosity_index(10 * MM2, -300.0)
    with pytest.raises(InputError, match=r"^viscosity_index = nan is not allowed: a finite"):
        nu100_from_viscosity_index(68 * MM2, math.nan)
    with pytest.raises(InputError, match=r"^nu40 = "):
        nu100_from_viscosity_index(1.5 * MM2, 100.0)


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
