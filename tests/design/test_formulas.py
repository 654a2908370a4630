"""Closed forms and limits of the design formulas and of the Hertz stiffness of the nut."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import design
from ballscrew.errors import InputError
from ballscrew.kinematics.limits import critical_speed
from ballscrew.loads import nut_forces


def test_life_scales_with_the_inverse_cube_of_the_load() -> None:
    lives = design.rating_life(10_000.0, [100.0, 200.0, 400.0])
    assert lives[0] / lives[1] == pytest.approx(8.0) and lives[1] / lives[2] == pytest.approx(8.0)
    assert float(design.rating_life(10_000.0, 10_000.0)) == pytest.approx(1e6)
    assert math.isinf(float(design.rating_life(10_000.0, 0.0)))


def test_reliability_factors() -> None:
    assert design.reliability_factor(90) == 1.0
    assert float(design.rating_life(1e4, 1e3, reliability=99)) == pytest.approx(0.21e9)
    with pytest.raises(InputError, match="reliability"):
        design.reliability_factor(93)


def test_cube_mean_of_one_level_is_the_level() -> None:
    assert design.cube_mean_loads([700.0], [3.0]) == pytest.approx((700.0, 0.0))
    with pytest.raises(InputError, match="shares"):
        design.cube_mean_loads([1.0, 2.0], [0.0, 0.0])


def test_preloaded_halves() -> None:
    """No load: both halves carry the preload; lift-off at 2^(3/2) F_pr: the other half is free."""
    f1, f2 = design.preloaded_half_loads([0.0, design.LIFT_OFF_FACTOR * 1000.0, 5000.0], 1000.0)
    assert f1[0] == pytest.approx(1000.0) and f2[0] == pytest.approx(1000.0)
    assert f1[1] == pytest.approx(2.0**1.5 * 1000.0) and f2[1] == pytest.approx(0.0, abs=1e-9)
    assert (f1[2], f2[2]) == (5000.0, 0.0)


def test_combined_life_of_equal_halves() -> None:
    assert design.combined_life([1e9, 1e9]) == pytest.approx(1e9 * 2.0 ** (-0.9))
    assert design.combined_life([1e9, math.inf]) == pytest.approx(1e9)


def test_fixed_fixed_critical_speed_is_the_eigenvalue_ratio_squared_of_fixed_free() -> None:
    args = (0.03, 1.2, 2.06e11, 7850.0)
    ratio = critical_speed(*args, "fixed-fixed") / critical_speed(*args, "fixed-free")
    assert ratio == pytest.approx((4.7300 / 1.8751) ** 2, rel=1e-12)  # Blevins' eigenvalues
    assert ratio == pytest.approx((4.730 / 1.875) ** 2, rel=2e-4)  # THK's, to 4 digits


def test_buckling_end_fixity_ratios() -> None:
    loads = [design.buckling_load(0.03, 1.0, 2e11, m) for m in design.MOUNTINGS]
    assert np.allclose(np.array(loads) / loads[1], [0.25, 1.0, 2.0, 4.0])


def test_shaft_stiffness_fixed_fixed_is_four_times() -> None:
    one = design.shaft_axial_stiffness(0.03, 1.0, 2e11, "fixed-supported")
    assert one == pytest.approx(math.pi * 0.03**2 / 4 * 2e11)
    assert design.shaft_axial_stiffness(0.03, 1.0, 2e11, "fixed-fixed") == pytest.approx(4 * one)


def test_shaft_stiffness_fixed_fixed_off_centre() -> None:
    """Fixed–fixed: the two shaft parts in parallel, A E l/(a (l − a)); the old code gave
    4 A E/a (3× too stiff at a = l/4)."""
    bar = math.pi * 0.03**2 / 4 * 2e11
    k = design.shaft_axial_stiffness(0.03, 1.0, 2e11, "fixed-fixed", 0.25)
    assert k == pytest.approx(bar / 0.25 + bar / 0.75)
    assert design.shaft_axial_stiffness(0.03, 1.0, 2e11, "fixed-free", 0.25) == pytest.approx(
        bar / 0.25
    )
    with pytest.raises(InputError, match="nut_distance"):
        design.shaft_axial_stiffness(0.03, 1.0, 2e11, "fixed-fixed", 1.0)


def test_series_and_pretension() -> None:
    assert design.series_stiffness(2e8, 2e8) == pytest.approx(1e8)
    force = design.thermal_pretension(0.03, 2e11, 12e-6, 3.0)
    strain = design.thermal_elongation(1.0, 12e-6, 3.0) / 1.0
    assert force == pytest.approx(2e11 * math.pi * 0.03**2 / 4 * strain)


def test_catalogue_rigidity_at_the_reference_preload_is_80_percent() -> None:
    assert design.catalogue_nut_rigidity(1e9, 5000.0, 5000.0) == pytest.approx(0.8e9)
    assert design.catalogue_nut_rigidity(1e9, 625.0, 5000.0) == pytest.approx(0.4e9)


COMPLIANCE = 3.749e-8  # m N^(-2/3), the example screw


@pytest.mark.parametrize("nuts", [1, 2])
@pytest.mark.parametrize("load", [0.0, 1000.0, 3000.0, 4000.0, 8000.0])
def test_hertz_stiffness_is_the_derivative_of_the_load_deflection_curve(nuts, load) -> None:
    fp, h = 1500.0, 1e-3
    x = design.nut_load_deflection(np.array([load, load + h]), fp, COMPLIANCE, nuts)
    forward = h / (x[1] - x[0])
    k = design.nut_stiffness(load, fp, COMPLIANCE, nuts)
    assert k == pytest.approx(forward, rel=1e-5)


def test_the_load_curve_gives_the_closed_form_stiffness_below_and_above_lift_off() -> None:
    """Two halves 1.5 F_i^(1/3)/C summed (F₁^(2/3) + F₂^(2/3) = 2 F_p^(2/3) below lift-off: 2×
    a half's at F_a = 0), one half 1.5 F_a^(1/3)/C above; one flank 1.5 (F_p + F_a)^(1/3)/C."""
    fp = 1500.0
    loads = np.array([0.0, 1000.0, 3000.0, 4000.0, 8000.0])
    x, k = design.nut_load_curve(loads, fp, COMPLIANCE)
    f1, f2 = np.array([tuple(nut_forces(fp, f)) for f in loads]).T
    closed = 1.5 * (np.cbrt(f1) + np.cbrt(f2)) / COMPLIANCE
    np.testing.assert_allclose(k, closed, rtol=1e-12)
    above = loads > design.LIFT_OFF_FACTOR * fp
    np.testing.assert_allclose(k[above], 1.5 * np.cbrt(loads[above]) / COMPLIANCE, rtol=1e-9)
    np.testing.assert_allclose(x, COMPLIANCE * (f1 ** (2 / 3) - fp ** (2 / 3)), rtol=1e-12)
    _, single = design.nut_load_curve(loads, fp, COMPLIANCE, nuts=1)
    np.testing.assert_allclose(single, 1.5 * np.cbrt(fp + loads) / COMPLIANCE, rtol=1e-12)
    with pytest.raises(InputError, match=r"^preload = 0"):
        design.nut_load_curve(loads, 0.0, COMPLIANCE, nuts=1)


@pytest.mark.parametrize("nuts", [0, 3])
def test_a_nut_count_other_than_one_or_two_names_nuts(nuts) -> None:
    for call in (design.nut_stiffness, design.nut_load_deflection, design.nut_load_curve):
        with pytest.raises(InputError, match=rf"^nuts = {nuts} .*1 or 2"):
            call(1000.0, 1500.0, COMPLIANCE, nuts)


def test_lift_off_at_two_to_the_three_halves_preload() -> None:
    fp = 1500.0
    lift_off = design.LIFT_OFF_FACTOR * fp
    assert nut_forces(fp, lift_off).f2 == pytest.approx(0.0, abs=1e-6)
    assert nut_forces(fp, 0.999 * lift_off).f2 > 0.0
    # below lift-off both halves work: twice the single-half stiffness at zero load
    single = 1.5 * fp / (COMPLIANCE * fp ** (2 / 3))
    assert design.nut_stiffness(0.0, fp, COMPLIANCE) == pytest.approx(2 * single)
    # at lift-off the displacement is δ₀ (THK A-687: half that of the nut without preload)
    delta0 = COMPLIANCE * fp ** (2 / 3)
    x = float(design.nut_load_deflection(lift_off, fp, COMPLIANCE))
    assert x == pytest.approx(delta0, rel=1e-9)
    assert x == pytest.approx(0.5 * COMPLIANCE * lift_off ** (2 / 3), rel=1e-9)


def test_bad_inputs_name_the_argument() -> None:
    with pytest.raises(InputError, match="mounting"):
        design.buckling_load(0.03, 1.0, 2e11, "clamped")
    with pytest.raises(InputError, match="maker"):
        design.maker_critical_speed(0.03, 1.0, "fixed-fixed", "ACME")
    with pytest.raises(InputError, match="load_factor"):
        design.rating_life(1e4, 1e3, load_factor=0.5)
