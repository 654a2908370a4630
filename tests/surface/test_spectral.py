"""The one-sided PSD: Parseval normalisation and (F2) for synthetic W–M profiles."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.surface import (
    log_smoothed_spectrum,
    power_spectrum,
    weierstrass_mandelbrot_profile,
    wm_power_spectrum,
)

GAMMA = 1.5
LN_G = math.log(GAMMA)


def test_white_noise_level_is_two_dx_sigma_squared() -> None:
    rng = np.random.default_rng(0)
    sigma, dx = 3e-9, 2e-6
    f, s = power_spectrum(rng.normal(0.0, sigma, size=(16, 4096)), dx, detrend="constant")
    assert f[0] == pytest.approx(1.0 / (4096 * dx))
    assert f[-1] == pytest.approx(0.5 / dx)
    assert np.mean(s) == pytest.approx(2.0 * dx * sigma**2, rel=0.02)


def test_sine_power_is_half_its_amplitude_squared() -> None:
    dx, n, a = 1e-6, 8192, 5e-8
    x = np.arange(n) * dx
    z = a * np.sin(2 * math.pi * 300.5 / (n * dx) * x + 0.3)  # between two DFT lines
    f, s = power_spectrum(z, dx)
    df = f[1] - f[0]
    assert np.sum(s) * df == pytest.approx(a**2 / 2, rel=0.01)


@pytest.mark.parametrize("D", [1.3, 1.5, 1.59, 1.7])
def test_f2_density_times_band_equals_line_power(D: float) -> None:
    """(F2) is the W–M line power spread over [γ^(n−½), γ^(n+½)): S(γⁿ) γⁿ ln γ = A_n²/2."""
    G = 3e-10
    n = np.arange(-5, 40)
    omega = GAMMA**n
    line_power = (G ** (D - 1) / GAMMA ** ((2 - D) * n)) ** 2 / 2
    np.testing.assert_allclose(
        wm_power_spectrum(omega, D, G) * omega * LN_G, line_power, rtol=1e-12
    )


@pytest.mark.parametrize("D", [1.3, 1.5, 1.59, 1.7])
def test_periodogram_of_a_wm_profile_holds_each_line_power(D: float) -> None:
    G, dx = 1e-9, 1e-7
    p = weierstrass_mandelbrot_profile(D, G, 2**16 * dx, dx, seed=11)
    f, s = power_spectrum(p.heights, dx)
    df = f[1] - f[0]
    n = np.arange(p.metadata["n1"], p.metadata["n_max"] + 1)
    for k in n[8:-3]:  # lines inside the fit band (ω > 20/L)
        band = (f >= GAMMA ** (k - 0.5)) & (f < GAMMA ** (k + 0.5))
        expected = wm_power_spectrum(GAMMA**k, D, G) * GAMMA**k * LN_G
        assert np.sum(s[band]) * df == pytest.approx(expected, rel=0.02)


@pytest.mark.parametrize("D", [1.3, 1.5, 1.59, 1.7])
def test_smoothed_spectrum_follows_f2_slope_and_level(D: float) -> None:
    G, dx = 2e-10, 1e-7
    p = weierstrass_mandelbrot_profile(D, G, 2**16 * dx, dx, seed=2)
    f, s = power_spectrum(p.heights, dx)
    at = np.geomspace(30 / p.length, 0.5 / dx / 4, 40)
    smooth = log_smoothed_spectrum(f, s, at, LN_G)
    alpha = 4 - 2 * D
    expected = wm_power_spectrum(at, D, G) * math.exp((alpha * LN_G) ** 2 / 2)
    np.testing.assert_allclose(smooth, expected, rtol=0.02)
    slope = np.polyfit(np.log(at), np.log(smooth), 1)[0]
    assert slope == pytest.approx(-(5 - 2 * D), abs=2e-3)


def test_smoothing_factor_of_a_continuous_power_law() -> None:
    """A Gaussian of width σ in ln ω raises ω^−(α+1) by exp(α²σ²/2) (lognormal moment)."""
    f = np.arange(1, 2_000_001) * 1.0
    alpha, width = 1.2, 0.3
    s = f ** (-(alpha + 1))
    at = np.array([1e3, 1e4, 1e5])
    ratio = log_smoothed_spectrum(f, s, at, width) / at ** (-(alpha + 1))
    np.testing.assert_allclose(ratio, math.exp((alpha * width) ** 2 / 2), rtol=1e-3)
