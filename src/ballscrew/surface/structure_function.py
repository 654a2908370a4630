"""Structure function of a profile and its W–M closed form, equation (F4).

    (F4) ⟨[z(x+τ) − z(x)]²⟩ = C_D G^(2(D−1)) (2πτ)^(4−2D),
         C_D = Γ(2D−3) sin((2D−3)π/2) / ((4−2D) ln γ)

(F4) follows from the PSD (F2) through ⟨[z(x+τ) − z(x)]²⟩ = 2 ∫ S(ω) (1 − cos 2πωτ) dω over
0 < ω < ∞. The form often quoted from Majumdar & Bhushan (1990), C G^(2(D−1)) τ^(4−2D), leaves
out the factor (2π)^(4−2D); with it left out, G read from a structure-function fit would not be
the G of (F1)/(F2). A sampled record only holds the band 1/L ≲ ω ≲ 1/(2Δx);
:func:`band_limited_ratio` is the factor by which that band's structure function falls below
(F4), used by the fit to correct both ends.

Sources: Majumdar, A. & Bhushan, B. (1990), J. Tribol. 112:205; Berry, M. V. & Lewis, Z. V.
(1980), Proc. R. Soc. Lond. A 370:459. Theory manual: ``docs/theory/surface.md``.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import gamma as gamma_function
from scipy.special import gammaln

from ballscrew.errors import InputError
from ballscrew.fractal.domain_extension import validate_dimension
from ballscrew.surface.profile import as_rows, check_spacing
from ballscrew.surface.weierstrass_mandelbrot import check_gamma
from ballscrew.validation import integer_at_least, nonnegative_array, positive

__all__ = [
    "band_limited_ratio",
    "structure_function",
    "structure_function_constant",
    "wm_structure_function",
]

FloatArray = NDArray[np.float64]

#: Below this u the power series of ∫₀^u t^(−α−1)(1 − cos t) dt is used, above it the asymptotic
#: expansion of the tail (both accurate to ~1e-9 relative there).
_SERIES_LIMIT = 20.0
_SERIES_TERMS = 60
_ASYMPTOTIC_TERMS = 14


def _mellin_integral(alpha: float) -> float:
    """J(α) = ∫₀^∞ u^(−α−1) (1 − cos u) du = Γ(1−α) cos(απ/2)/α for 0 < α < 2.

    Written with ε = 1 − α as Γ(1+ε) (π/2) sinc(ε/2) / α, which is regular at α = 1 (D = 1.5).
    """
    eps = 1.0 - alpha
    return float(gamma_function(1.0 + eps)) * 0.5 * math.pi * float(np.sinc(0.5 * eps)) / alpha


def structure_function_constant(D: float, gamma: float = 1.5) -> float:
    """C_D = Γ(2D−3) sin((2D−3)π/2) / ((4−2D) ln γ) of (F4), dimensionless.

    Regular at D = 1.5 (C_D = π/(2 ln γ)).
    """
    d = validate_dimension(D)
    return _mellin_integral(4.0 - 2.0 * d) / math.log(check_gamma(gamma))


def wm_structure_function(lag: ArrayLike, D: float, G: float, gamma: float = 1.5) -> FloatArray:
    """(F4): ⟨[z(x+τ) − z(x)]²⟩ = C_D G^(2(D−1)) (2πτ)^(4−2D) of the W–M profile, m².

    ``lag`` τ in m (≥ 0). It is the continuous-n (all-band) form; the W–M line sum itself has a
    log-periodic ripple around it of period ln γ in ln τ (largest deviation about 1 % at D = 1.3,
    4 % at 1.5, 6.5 % at 1.59 and 11.5 % at 1.7 for γ = 1.5), whose geometric mean over a period
    matches (F4) to < 0.4 %.
    """
    d = validate_dimension(D)
    G = positive("G", G, "m")
    tau = nonnegative_array("lag", lag, "m")
    c = structure_function_constant(d, gamma)
    return c * G ** (2.0 * (d - 1.0)) * (2.0 * math.pi * tau) ** (4.0 - 2.0 * d)


def _lower_part(a: FloatArray, alpha: float) -> FloatArray:
    """∫₀^a u^(−α−1)(1 − cos u) du by its power series (use for a ≤ 20)."""
    k = np.arange(1, _SERIES_TERMS + 1, dtype=np.float64)
    a = np.asarray(a, dtype=np.float64)
    safe = np.where(a > 0.0, a, 1.0)[..., None]
    log_mag = (2.0 * k - alpha) * np.log(safe) - gammaln(2.0 * k + 1.0)
    terms = (-1.0) ** (k + 1.0) * np.exp(log_mag) / (2.0 * k - alpha)
    return np.where(a > 0.0, terms.sum(axis=-1), 0.0)


def _upper_part(b: FloatArray, alpha: float) -> FloatArray:
    """∫_b^∞ u^(−α−1)(1 − cos u) du (0 for b = ∞).

    Series for b ≤ 20 (as J − lower part); for larger b, b^(−α)/α − Re ∫_b^∞ u^(−β) e^(iu) du
    with β = α + 1 and the asymptotic expansion e^(ib) b^(−β) Σ_k i (−i)^k (β)_k b^(−k).
    """
    b = np.asarray(b, dtype=np.float64)
    out = np.zeros_like(b)
    small = b <= _SERIES_LIMIT
    if np.any(small):
        out[small] = _mellin_integral(alpha) - _lower_part(b[small], alpha)
    large = ~small & np.isfinite(b)
    if np.any(large):
        bl = b[large]
        beta = alpha + 1.0
        k = np.arange(_ASYMPTOTIC_TERMS, dtype=np.float64)
        rising = np.concatenate(([1.0], np.cumprod(beta + k[:-1])))
        series = (1j * (-1j) ** k * rising)[None, :] * bl[:, None] ** (-k[None, :])
        tail = np.exp(1j * bl) * bl ** (-beta) * series.sum(axis=1)
        out[large] = bl ** (-alpha) / alpha - tail.real
    return out


def band_limited_ratio(
    lag: ArrayLike,
    D: float,
    frequency_min: float,
    frequency_max: float,
) -> FloatArray:
    """Structure function of the band [ω_min, ω_max] of (F2), divided by the all-band (F4).

        r(τ) = ∫_{u_lo}^{u_hi} u^(−α−1)(1 − cos u) du / ∫₀^∞ u^(−α−1)(1 − cos u) du,
        α = 4 − 2D, u_lo = 2πτ ω_min, u_hi = 2πτ ω_max

    It depends on D but not on G. A W–M line comb n₁ … n_max has, in the continuous-n sense,
    the band [γ^(n₁−½), γ^(n_max+½)]. ``frequency_min`` may be 0 and ``frequency_max`` ∞.
    """
    d = validate_dimension(D)
    alpha = 4.0 - 2.0 * d
    tau = np.asarray(lag, dtype=np.float64)
    lo, hi = float(frequency_min), float(frequency_max)
    if not (0.0 <= lo < hi):
        raise InputError("frequency band", (lo, hi), "0 <= frequency_min < frequency_max")
    u_lo = 2.0 * math.pi * tau * lo
    u_hi = 2.0 * math.pi * tau * hi
    if np.any(u_lo > _SERIES_LIMIT):
        raise InputError("lag", tau, f"lags below {_SERIES_LIMIT / (2 * math.pi * lo):.3g} m")
    missing = _lower_part(u_lo, alpha) + _upper_part(u_hi, alpha)
    return 1.0 - missing / _mellin_integral(alpha)


def _detrended(rows: FloatArray, detrend: str | None) -> FloatArray:
    if detrend in (None, False):
        return rows
    if detrend == "constant":
        return rows - rows.mean(axis=1, keepdims=True)
    if detrend == "linear":
        n = rows.shape[1]
        t = np.arange(n, dtype=np.float64) - 0.5 * (n - 1)
        slope = (rows @ t) / (t @ t)
        return rows - rows.mean(axis=1, keepdims=True) - slope[:, None] * t[None, :]
    raise InputError("detrend", detrend, "'linear', 'constant' or None")


def structure_function(
    heights: ArrayLike,
    spacing: float,
    *,
    detrend: str | None = "linear",
    max_lag: int | None = None,
) -> tuple[FloatArray, FloatArray]:
    """Structure function ⟨[z(x+τ) − z(x)]²⟩ of a profile at τ = kΔx, k = 1 … ``max_lag``, m².

    The mean over all N − k pairs of each row (after removing a ``"linear"`` or ``"constant"``
    trend, or ``None``), then the mean over the rows. Computed in O(N log N): Σ (z_{j+k} − z_j)²
    = Σ z_{j+k}² + Σ z_j² − 2 Σ z_j z_{j+k}, the last from a zero-padded FFT.

    Returns:
        ``(lag, sf)``: lags in m and the structure function in m².
    """
    rows = _detrended(as_rows(heights), detrend)
    dx = check_spacing(spacing)
    n = rows.shape[1]
    k_max = n - 1 if max_lag is None else integer_at_least("max_lag", max_lag, 1)
    if not 1 <= k_max <= n - 1:
        raise InputError("max_lag", max_lag, f"an integer between 1 and {n - 1}")
    size = 1 << math.ceil(math.log2(2 * n))
    spec = np.fft.rfft(rows, size, axis=1)
    cross = np.fft.irfft(spec * np.conj(spec), size, axis=1)[:, 1 : k_max + 1]
    csum = np.cumsum(rows * rows, axis=1)
    k = np.arange(1, k_max + 1)
    head = csum[:, n - k - 1]  # Σ_{j < N−k} z_j²
    tail = csum[:, -1][:, None] - csum[:, k - 1]  # Σ_{j ≥ k} z_j²
    sf = (head + tail - 2.0 * cross) / (n - k)
    return k * dx, np.maximum(sf, 0.0).mean(axis=0)
