"""D and G recovered from synthetic W–M profiles (within 2 % and 10 %), both methods."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ballscrew.errors import InputError
from ballscrew.surface import (
    FractalFit,
    fit_power_spectrum,
    fit_structure_function,
    fractal_parameters,
    weierstrass_mandelbrot_profile,
)

DX = 1e-7  # 0.1 µm sampling
N_LONG = 2**18  # 26.2 mm: the structure function needs a long record when D is low
N_PSD = 2**16
D_TOL, G_TOL = 0.02, 0.10


def check(fit: FractalFit, D: float, G: float) -> None:
    assert abs(fit.D / D - 1) < D_TOL, fit
    assert abs(fit.G / G - 1) < G_TOL, fit


@pytest.mark.parametrize("D", [1.3, 1.5, 1.59, 1.7])
@pytest.mark.parametrize("G", [1e-10, 9e-10])
def test_both_methods_recover_d_and_g(D: float, G: float) -> None:
    p = weierstrass_mandelbrot_profile(D, G, N_LONG * DX, DX, seed=20240601)
    result = fractal_parameters(p)
    check(result.psd, D, G)
    check(result.structure_function, D, G)
    # The PSD estimate, recommended, is much closer than the tolerance.
    assert result.recommended is result.psd
    assert abs(result.D / D - 1) < 1e-3
    assert abs(result.G / G - 1) < 0.02
    assert result.psd.r_squared > 0.999
    assert result.structure_function.r_squared > 0.999


@given(
    D=st.floats(1.2, 1.85),
    log_g=st.floats(math.log(1e-11), math.log(1e-8)),
    seed=st.integers(0, 2**32 - 1),
)
@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_psd_recovers_d_and_g_for_any_seed(D: float, log_g: float, seed: int) -> None:
    G = math.exp(log_g)
    p = weierstrass_mandelbrot_profile(D, G, N_PSD * DX, DX, seed=seed)
    check(fit_power_spectrum(p.heights, DX), D, G)


@given(D=st.floats(1.4, 1.85), seed=st.integers(0, 2**32 - 1))
@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_structure_function_recovers_d_and_g_for_any_seed(D: float, seed: int) -> None:
    """Above D ≈ 1.4; below, the record's longest wavelengths make G scatter by ≈ 4 % (1 σ)."""
    G = 3e-10
    p = weierstrass_mandelbrot_profile(D, G, N_LONG * DX, DX, seed=seed)
    check(fit_structure_function(p.heights, DX), D, G)


def test_rows_of_an_areal_measurement_are_averaged() -> None:
    D, G = 1.59, 9e-10
    p = weierstrass_mandelbrot_profile(D, G, 2**14 * DX, DX, seed=3, profiles=16)
    result = fractal_parameters(p)
    assert result.psd.profiles == 16
    check(result.psd, D, G)
    check(result.structure_function, D, G)


def test_fit_ranges_avoid_both_ends_and_report_units() -> None:
    p = weierstrass_mandelbrot_profile(1.5, 1e-10, N_PSD * DX, DX, seed=1)
    result = fractal_parameters(p)
    L, nyquist = p.length, 0.5 / DX
    psd, sf = result.psd, result.structure_function
    assert psd.method == "psd" and psd.range_unit == "1/m"
    assert psd.fit_range == pytest.approx((20 / L, nyquist / 3))
    assert psd.points == pytest.approx((nyquist / 3 - 20 / L) * L, abs=2)
    assert sf.method == "structure_function" and sf.range_unit == "m"
    assert sf.fit_range[0] == pytest.approx(10 * DX)
    # τ_max = (L/2π) ε^(1/(2D−2)) with ε = 0.02 (the long-wave share of the SF)
    assert sf.fit_range[1] == pytest.approx(L / (2 * math.pi) * 0.02 ** (1 / (2 * sf.D - 2)))
    assert sf.points == math.floor(sf.fit_range[1] / DX + 1e-9) - 10 + 1
    assert result.length == pytest.approx(L)
    assert psd.surface_dimension == pytest.approx(psd.D + 1)


def test_explicit_fit_ranges_are_used() -> None:
    D, G = 1.59, 9e-10
    p = weierstrass_mandelbrot_profile(D, G, N_LONG * DX, DX, seed=8)
    ranges = {"psd": (1e4, 1e6), "structure_function": (2e-6, 2e-5)}
    result = fractal_parameters(p, fit_range=ranges)
    assert result.psd.fit_range == (1e4, 1e6)
    assert result.structure_function.fit_range == (2e-6, 2e-5)
    check(result.psd, D, G)
    check(result.structure_function, D, G)
    only = fractal_parameters(p.heights, DX, method="psd", fit_range=(1e4, 1e6))
    assert only.structure_function is None and only.psd.fit_range == (1e4, 1e6)


def test_without_the_band_correction_the_structure_function_is_biased() -> None:
    """The reason for r(τ): at D = 1.7 the missing lines above Nyquist matter at small τ."""
    D, G = 1.7, 1e-10
    p = weierstrass_mandelbrot_profile(D, G, N_LONG * DX, DX, seed=4)
    corrected = fit_structure_function(p.heights, DX)
    raw = fit_structure_function(
        p.heights, DX, fit_range=corrected.fit_range, band_correction=False
    )
    assert abs(corrected.G / G - 1) < G_TOL
    assert abs(raw.G / G - 1) > 2 * abs(corrected.G / G - 1)


def test_brownian_profile_has_d_one_and_a_half() -> None:
    """Independent of W–M: a random walk has D = 1.5 and SF = s² τ/Δx, i.e. G = s² ln γ/(π² Δx).

    A random profile scatters (χ²), so the check is against the reported standard errors.
    """
    rng = np.random.default_rng(12)
    s, dx = 2e-9, 1e-6
    z = np.cumsum(rng.normal(0.0, s, size=(8, 2**14)), axis=1)
    G = s**2 * math.log(1.5) / (math.pi**2 * dx)
    result = fractal_parameters(z, dx)
    psd = result.psd
    assert abs(psd.D - 1.5) < 4 * psd.D_stderr + 0.01  # + the sin² roll-off near Nyquist
    assert abs(math.log(psd.G / G)) < 4 * psd.lnG_stderr + 0.3
    assert 0.005 < psd.D_stderr < 0.05
    sf = fit_structure_function(z, dx, band_correction=False)
    assert sf.D == pytest.approx(1.5, abs=0.03)


def test_white_noise_is_not_fractal() -> None:
    z = np.random.default_rng(0).normal(size=2**12)
    fit = fit_power_spectrum(z, 1e-6)
    assert math.isnan(fit.D) and math.isnan(fit.G)
    assert any("outside 1 < D < 2" in n for n in fit.notes)


def test_rows_with_missing_points_are_left_out() -> None:
    p = weierstrass_mandelbrot_profile(1.5, 1e-10, 2**14 * DX, DX, seed=2, profiles=4)
    heights = p.heights.copy()
    heights[1, 100] = np.nan
    result = fractal_parameters(heights, DX)
    assert result.psd.profiles == 3
    assert any("1 of 4 profiles left out" in n for n in result.notes)


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"method": "fft"}, "method"),
        ({"fit_range": (1e4, 1e6)}, "fit_range"),
        ({"fit_range": {"psd": (1e6, 1e4)}}, "fit_range (psd)"),
        ({"fit_range": {"sf": (1e-6, 1e-5)}}, "fit_range"),
        ({"method": "psd", "fit_range": (1e-3, 1e12)}, "fit_range (psd)"),
    ],
)
def test_bad_arguments(kwargs: dict, field: str) -> None:
    p = weierstrass_mandelbrot_profile(1.5, 1e-10, 2**12 * DX, DX, seed=2)
    with pytest.raises(InputError) as err:
        fractal_parameters(p, **kwargs)
    assert err.value.field == field


def test_bare_array_needs_a_spacing() -> None:
    with pytest.raises(InputError) as err:
        fractal_parameters(np.zeros(100))
    assert err.value.field == "spacing"
    with pytest.raises(InputError):
        fractal_parameters(np.zeros(100), 1e-6)  # flat
    with pytest.raises(InputError):
        fractal_parameters(np.zeros(8), 1e-6)  # too short
