"""One-sided power spectral density of a profile and its W–M closed form, equation (F2).

    (F2) S(ω) = G^(2(D−1)) / (2 ln γ) · ω^(−(5−2D))      (one-sided, ω in cycles/m)

normalised so that ∫ S dω over a band is the mean-square height of that band (F3). A W–M
profile (F1) has a *line* spectrum: power G^(2(D−1)) γ^(−2(2−D)n)/2 at ω = γⁿ. (F2) is its
density per unit frequency when each line is spread over the band [γ^(n−½), γ^(n+½)), i.e.
ω S(ω) ln γ equals the line power at ω = γⁿ. :func:`log_smoothed_spectrum` turns either a line
spectrum or a continuous one into a smooth density that can be fitted in log–log axes.

Sources: Majumdar, A. & Bhushan, B. (1990), J. Tribol. 112:205 (F2); Berry, M. V. & Lewis,
Z. V. (1980), Proc. R. Soc. Lond. A 370:459. Theory manual: ``docs/theory/surface.md``.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.signal import get_window, periodogram

from ballscrew.errors import InputError
from ballscrew.fractal.domain_extension import validate_dimension
from ballscrew.surface.profile import as_rows, check_spacing
from ballscrew.surface.weierstrass_mandelbrot import check_gamma
from ballscrew.validation import nonnegative_array, positive, positive_array

__all__ = [
    "log_binned_power",
    "log_smoothed_spectrum",
    "power_spectrum",
    "smoothing_kernel",
    "wm_power_spectrum",
]

FloatArray = NDArray[np.float64]

#: Sub-bins per smoothing width used to pre-sum the periodogram before the Gaussian smoothing.
_SUBBINS = 16


def wm_power_spectrum(frequency: ArrayLike, D: float, G: float, gamma: float = 1.5) -> FloatArray:
    """One-sided PSD (F2) of the W–M profile, m²/(cycles/m) = m³.

    ``frequency`` ω in cycles/m (> 0). ∫ S dω from 1/L to ω_h gives the variance (F3).
    """
    d = validate_dimension(D)
    g = check_gamma(gamma)
    G = positive("G", G, "m")
    f = positive_array("frequency", frequency, "cycles/m")
    return G ** (2.0 * (d - 1.0)) / (2.0 * math.log(g)) * f ** (-(5.0 - 2.0 * d))


def power_spectrum(
    heights: ArrayLike,
    spacing: float,
    *,
    window: str | None = "hann",
    detrend: str | None = "linear",
) -> tuple[FloatArray, FloatArray]:
    """One-sided PSD of a profile (or the mean over the rows of an areal measurement), m³.

    The periodogram of each row after removing a ``detrend`` (``"linear"``, ``"constant"`` or
    ``None``) and tapering with ``window`` (any :func:`scipy.signal.get_window` name; ``None``
    for none), scaled as a density: S_k = 2 Δx |Σ w_j z_j e^(−2πijk/N)|² / Σ w_j², so that
    Σ S_k Δω is the mean-square height (Parseval, the F2/F3 convention). The zero frequency is
    left out; frequencies are k/(N Δx), k = 1 … N/2, in cycles/m.

    Returns:
        ``(frequency, psd)``: frequency in cycles/m, PSD in m²/(cycles/m).
    """
    rows = as_rows(heights)
    dx = check_spacing(spacing)
    if detrend not in ("linear", "constant", None, False):
        raise InputError("detrend", detrend, "'linear', 'constant' or None")
    window = "boxcar" if window is None else window
    try:
        get_window(window, rows.shape[1])
    except (TypeError, ValueError):
        raise InputError("window", window, "a scipy.signal window name, e.g. 'hann'") from None
    f, p = periodogram(
        rows,
        fs=1.0 / dx,
        window=window,
        detrend=detrend if detrend else False,
        scaling="density",
        axis=-1,
    )
    return f[1:], p[:, 1:].mean(axis=0)


def log_smoothed_spectrum(
    frequency: ArrayLike, psd: ArrayLike, at: ArrayLike, width: float
) -> FloatArray:
    """PSD smoothed with a Gaussian of standard deviation ``width`` in ln ω, evaluated ``at``.

    The power S_k Δω of each bin is spread over ln ω with a normalised Gaussian kernel K, which
    gives the power per unit ln ω, p̃(x) = Σ_k S_k Δω K(x − ln ω_k); the result is p̃/ω. For a
    W–M line spectrum with ``width`` ≳ 0.7 ln γ the log-periodic ripple of the lines falls below
    e^(−2π² (width/ln γ)²) (≈ 3·10⁻⁹ at width = ln γ), so the smoothed spectrum is a clean power
    law. Smoothing a power law S ∝ ω^(−(α+1)) multiplies it by exp(α² width²/2) and keeps its
    slope; :func:`ballscrew.surface.fit.fit_power_spectrum` divides this factor out. Evaluate only
    ≳ 2.5 ``width`` away from the ends of the spectrum (the kernel is cut there).

    Args:
        frequency: bin frequencies in cycles/m, uniformly spaced, > 0.
        psd: one-sided PSD at those frequencies, m³.
        at: frequencies (cycles/m) at which to evaluate the smoothed PSD.
        width: Gaussian standard deviation in ln ω (natural log units), > 0.

    Returns:
        The smoothed PSD at ``at``, m³.
    """
    x_eval = np.log(positive_array("at", at, "cycles/m"))
    x_bin, p_bin, _ = log_binned_power(frequency, psd, width)
    return (smoothing_kernel(x_eval, x_bin, width) @ p_bin) / np.exp(x_eval)


def log_binned_power(
    frequency: ArrayLike, psd: ArrayLike, width: float
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Power S_k Δω summed into narrow ln ω sub-bins (``width``/16 wide).

    Returns ``(x, power, power_squared)``: each sub-bin's power centroid in ln ω, its power
    Σ S_k Δω (m²) and Σ (S_k Δω)² (for the periodogram variance).
    """
    positive("width", width, "(a smoothing width in ln ω)")
    f = positive_array("frequency", frequency, "cycles/m")
    s = nonnegative_array("psd", psd, "m³")
    if f.shape != s.shape or f.ndim != 1:
        raise InputError("frequency, psd", (f.shape, s.shape), "1-D arrays of one length")
    df = f[1] - f[0] if f.size > 1 else f[0]
    power = s * df
    lnf = np.log(f)
    h = width / _SUBBINS
    index = np.floor((lnf - lnf[0]) / h).astype(np.int64)
    p_bin = np.bincount(index, weights=power)
    x_sum = np.bincount(index, weights=power * lnf)
    centre = lnf[0] + (np.arange(p_bin.size) + 0.5) * h
    x_bin = np.divide(x_sum, p_bin, out=centre, where=p_bin > 0.0)
    return x_bin, p_bin, np.bincount(index, weights=power * power)


def smoothing_kernel(x: FloatArray, centres: FloatArray, width: float) -> FloatArray:
    """Normalised Gaussian K(x − c) of standard deviation ``width`` (rows x, columns c)."""
    u = (x[:, None] - centres[None, :]) / width
    return np.exp(-0.5 * u * u) / (width * math.sqrt(2.0 * math.pi))
