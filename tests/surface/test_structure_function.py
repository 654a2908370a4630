"""Structure function: the estimator, (F4) and C_D against the discrete W–M sum, the band ratio."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import gamma as gamma_fn

from ballscrew.errors import InputError
from ballscrew.surface import (
    band_limited_ratio,
    structure_function,
    structure_function_constant,
    weierstrass_mandelbrot_profile,
    wm_power_spectrum,
    wm_structure_function,
)

GAMMA = 1.5
LN_G = math.log(GAMMA)


def comb_structure_function(tau: np.ndarray, D: float, G: float, n: np.ndarray) -> np.ndarray:
    """Σ_n A_n² (1 − cos 2πγⁿτ): the x-average of [z(x+τ) − z(x)]² for the lines n of (F1)."""
    a2 = G ** (2 * (D - 1)) * GAMMA ** (-2 * (2 - D) * n)
    return np.sum(a2 * (1 - np.cos(2 * math.pi * np.outer(tau, GAMMA**n))), axis=1)


def test_estimator_against_the_definition() -> None:
    rng = np.random.default_rng(4)
    z = np.cumsum(rng.normal(size=(3, 500)), axis=1)
    lag, sf = structure_function(z, 0.25, detrend=None)
    ref = np.mean([[np.mean((r[k:] - r[:-k]) ** 2) for k in range(1, 500)] for r in z], axis=0)
    np.testing.assert_allclose(lag, 0.25 * np.arange(1, 500))
    np.testing.assert_allclose(sf, ref, rtol=1e-9)


@pytest.mark.parametrize("D", [1.1, 1.3, 1.5, 1.59, 1.7, 1.9])
def test_c_d_is_the_integral_of_f2(D: float) -> None:
    """C_D G^(2(D−1)) (2πτ)^(4−2D) = 2 ∫₀^∞ S(ω)(1 − cos 2πωτ) dω with S from (F2)."""
    G, tau = 5e-10, 3e-6
    alpha = 4 - 2 * D

    def integrand(u: float) -> float:  # u = 2πωτ
        return u ** (-alpha - 1) * (1 - math.cos(u)) if u > 0 else 0.0

    integral = (
        quad(integrand, 0, 50, limit=400)[0]
        + quad(lambda u: u ** (-alpha - 1), 50, np.inf)[0]
        - quad(lambda u: u ** (-alpha - 1), 50, np.inf, weight="cos", wvar=1.0)[0]
    )
    # 2 ∫ S dω (1 − cos) = 2 G^(2(D−1))/(2 ln γ) (2πτ)^α ∫ u^(−α−1)(1 − cos u) du
    expected = G ** (2 * (D - 1)) / LN_G * (2 * math.pi * tau) ** alpha * integral
    assert wm_structure_function(tau, D, G) == pytest.approx(expected, rel=1e-7)
    z = 2 * D - 3
    if abs(z) > 1e-9:
        doc = gamma_fn(z) * math.sin(z * math.pi / 2) / ((4 - 2 * D) * LN_G)
        assert structure_function_constant(D) == pytest.approx(doc, rel=1e-12)


def test_c_d_is_regular_at_d_one_and_a_half() -> None:
    assert structure_function_constant(1.5) == pytest.approx(math.pi / (2 * LN_G), rel=1e-12)
    assert structure_function_constant(1.5 + 1e-7) == pytest.approx(
        structure_function_constant(1.5), rel=1e-6
    )


@pytest.mark.parametrize(("D", "ripple"), [(1.3, 0.012), (1.5, 0.045), (1.59, 0.07), (1.7, 0.12)])
def test_f4_is_the_log_period_mean_of_the_discrete_sum(D: float, ripple: float) -> None:
    """(F4) agrees with the discrete sum to 0.4 %.

    The infinite W–M sum oscillates about (F4) with period ln γ in ln τ; its geometric mean over
    a period equals (F4) to < 0.4 %; the oscillation itself reaches 1 % (D = 1.3), 4 % (1.5),
    7 % (1.59) and 12 % (1.7).
    """
    G = 1e-9
    n = np.arange(-150, 150)
    tau = 1e-6 * np.exp(np.linspace(0.0, LN_G, 64, endpoint=False))
    ratio = comb_structure_function(tau, D, G, n) / wm_structure_function(tau, D, G)
    assert math.exp(np.mean(np.log(ratio))) == pytest.approx(1.0, abs=4e-3)
    assert np.max(np.abs(ratio - 1)) < ripple


@pytest.mark.parametrize("D", [1.3, 1.5, 1.7])
def test_band_ratio_against_quadrature(D: float) -> None:
    alpha = 4 - 2 * D
    f_lo, f_hi = 150.0, 5e6
    tau = np.array([2e-7, 1e-6, 3e-5, 1e-3])

    def band(t: float) -> float:
        lo, hi = 2 * math.pi * t * f_lo, 2 * math.pi * t * f_hi
        pieces = np.geomspace(lo, hi, 200)
        return sum(
            quad(lambda u: u ** (-alpha - 1) * (1 - math.cos(u)), a, b, limit=200)[0]
            for a, b in itertools.pairwise(pieces)
        )

    j = structure_function_constant(D) * LN_G
    expected = np.array([band(t) for t in tau]) / j
    np.testing.assert_allclose(band_limited_ratio(tau, D, f_lo, f_hi), expected, rtol=1e-6)


@pytest.mark.parametrize("D", [1.3, 1.5, 1.7])
def test_band_ratio_describes_a_truncated_wm_comb(D: float) -> None:
    """Lines n₁ … n_max stand for the band [γ^(n₁−½), γ^(n_max+½)] in the continuum sense."""
    G, n = 1e-9, np.arange(10, 36)
    tau = np.geomspace(3e-7, 1e-3, 25)
    full = comb_structure_function(tau, D, G, np.arange(-150, 150))
    truncated = comb_structure_function(tau, D, G, n)
    ratio = band_limited_ratio(tau, D, GAMMA ** (n[0] - 0.5), GAMMA ** (n[-1] + 0.5))
    # pointwise to within the discreteness of the comb's edges, on average much closer
    np.testing.assert_allclose(truncated / full, ratio, rtol=0.06)
    assert np.exp(np.mean(np.log(truncated / full / ratio))) == pytest.approx(1.0, abs=0.005)


@pytest.mark.parametrize("D", [1.3, 1.59, 1.7])
def test_sampled_wm_profile_follows_its_line_sum_and_f4(D: float) -> None:
    G, dx = 1e-9, 1e-7
    p = weierstrass_mandelbrot_profile(D, G, 2**16 * dx, dx, seed=5)
    n = np.arange(p.metadata["n1"], p.metadata["n_max"] + 1)
    lag, sf = structure_function(p.heights, dx, detrend=None, max_lag=400)
    pick = np.array([1, 3, 10, 30, 100, 300]) - 1
    exact = comb_structure_function(lag[pick], D, G, n)
    # exact but for the finite-record cross terms of the longest wavelengths
    np.testing.assert_allclose(sf[pick][:4], exact[:4], rtol=0.01)
    np.testing.assert_allclose(sf[pick], exact, rtol=0.025)
    # and (F4) times the band ratio of the record, to within the ripple of the comb
    model = wm_structure_function(lag[pick], D, G) * band_limited_ratio(
        lag[pick], D, 1.0 / p.length, 0.5 / dx
    )
    np.testing.assert_allclose(sf[pick], model, rtol=0.15)


def test_f4_and_f2_use_the_same_g() -> None:
    """Through 2∫S(1 − cos): the G of (F4) with the (2π)^(4−2D) factor is the G of (F2)."""
    D, G, tau = 1.59, 9e-10, 2e-6
    omega = np.geomspace(1e-2, 1e11, 400001)
    integrand = 2 * wm_power_spectrum(omega, D, G) * (1 - np.cos(2 * math.pi * omega * tau))
    integral = np.trapezoid(integrand * omega, np.log(omega))
    assert integral == pytest.approx(wm_structure_function(tau, D, G), rel=2e-3)
    quoted = structure_function_constant(D) * G ** (2 * (D - 1)) * tau ** (4 - 2 * D)
    assert integral / quoted == pytest.approx((2 * math.pi) ** (4 - 2 * D), rel=2e-3)


def test_bad_lag_and_band() -> None:
    with pytest.raises(InputError):
        wm_structure_function(-1.0, 1.5, 1e-9)
    with pytest.raises(InputError):
        band_limited_ratio(1e-6, 1.5, 10.0, 5.0)
    with pytest.raises(InputError):
        structure_function(np.ones(100), 1e-6, max_lag=200)
