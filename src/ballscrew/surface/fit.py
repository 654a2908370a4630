"""Fractal parameters D and G of a measured profile from its power spectrum and structure function.

Two estimators, each a straight-line fit in log–log axes, both reported:

* **PSD** (F2): ln S(ω) = ln[G^(2(D−1))/(2 ln γ)] − (5 − 2D) ln ω. The periodogram (Hann window,
  linear detrend, rows averaged) is smoothed with a Gaussian of width ln γ in ln ω
  (:func:`~ballscrew.surface.spectral.log_smoothed_spectrum`), which turns the line spectrum of a
  W–M profile into a clean power law and averages the χ² scatter of a measured one. Smoothing a
  power law of slope −(α+1) (α = 4 − 2D) raises it by exp(α² σ²/2); the fit divides this out,
  so the estimate is unbiased for any power law. The slope gives D, the intercept G.
* **Structure function** (F4): ln SF(τ) = ln[C_D G^(2(D−1))] + (4 − 2D) ln(2πτ). The record only
  holds the band ω_min = 1/L … ω_max = 1/(2Δx); its structure function falls below (F4) by the
  factor r(τ; D) of :func:`~ballscrew.surface.structure_function.band_limited_ratio` (for D = 1.7
  about 10 % at τ = 10Δx). The fit divides the data by r (iterating on D), smooths ln SF over
  ln γ in ln τ (which removes the log-periodic ripple of a W–M comb and leaves a power law
  unchanged) and fits the line.

Automatic fit ranges (``fit_range=None``). With ω_top = 1/(2 max(Δx, resolution)) the highest
resolved frequency (Nyquist, or the instrument's lateral resolution when it is coarser):

* PSD: 20/L ≤ ω ≤ ω_top/3. The low end leaves out the first 20 DFT lines, where the window's
  leakage, the detrend and the few cycles per record bias the periodogram; the high end stays
  e ≈ 2.7 smoothing widths below ω_top (aliasing, instrument transfer, the cut kernel). If that
  is less than a decade, the low end moves down to max(5/L, ω_hi/10).
* Structure function: 5/ω_top ≤ τ ≤ τ_hi with τ_hi = (L/2π) ε^(1/(2D−2)), ε = 0.02, clipped
  to [10 τ_lo, L/10]. At lag τ the wavelengths near L, of which a record holds only one or
  two, carry a share ≈ (2πτ/L)^(2D−2) of the structure function; their finite-record
  cross terms make it noisy there. τ_hi keeps that share at ε: for D = 1.3, 1.5 and 1.7,
  τ_hi ≈ L/4200, L/310 and L/100. The low end, 10Δx at the Nyquist limit, stays clear of
  the instrument's resolution; r(τ) corrects what is left of the band edges.

``FractalFit.fit_range`` reports the range used (cycles/m for the PSD, m for the structure
function). The recommended value is the PSD estimate: it separates the scales, so it is not
biased by the few longest wavelengths of the record that dominate the structure function when
D < 1.5; the structure-function estimate is the cross-check. On synthetic W–M profiles of 2¹⁸
points the PSD recovers D to 0.03 % and G to 1 %; the structure function D to 0.3 % and G to
≈ 4 % (1 σ at D = 1.3, less at higher D).

G is ill-conditioned: it is the level of the power law extrapolated from the fit range (centre
ω_c ≈ 10⁴–10⁵ cycles/m) to the scale G (≈ 10⁻¹⁰ m), so d ln G/dD = −ln(ω_c G)/(D − 1), about
12/(D − 1). A measured (random) profile scatters from one record to the next: for a Brownian
profile (D = 1.5) of 2¹⁶ points by ≈ 2 % in D and a factor ≈ 1.7 in G. ``FractalFit.D_stderr``
and ``lnG_stderr`` (PSD) estimate this; the structure function gives none
(``FractalFit.stderr_reason``). Average several profiles (rows of an areal file) and
compare G values only at equal D.

Sources: Majumdar, A. & Bhushan, B. (1990), J. Tribol. 112:205 and Wear 136:313; Berry, M. V. &
Lewis, Z. V. (1980), Proc. R. Soc. Lond. A 370:459.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import asdict, dataclass, field
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.signal import get_window

from ballscrew.errors import InputError
from ballscrew.surface.profile import Profile, as_rows, check_spacing
from ballscrew.surface.spectral import log_binned_power, power_spectrum, smoothing_kernel
from ballscrew.surface.structure_function import (
    band_limited_ratio,
    structure_function,
    structure_function_constant,
)
from ballscrew.surface.weierstrass_mandelbrot import check_gamma

__all__ = [
    "FractalFit",
    "SurfaceFit",
    "fit_power_spectrum",
    "fit_structure_function",
    "fractal_parameters",
]

FloatArray = NDArray[np.float64]
Method = Literal["psd", "structure_function", "both"]
Range = tuple[float, float]

#: Share of the structure function allowed from wavelengths ≈ L at the top of the SF range.
SF_LONG_WAVE_SHARE = 0.02
#: Lowest SF lag of the automatic range, in units of 1/ω_top (1/ω_top = 2Δx at Nyquist).
SF_MIN_LAG = 5.0
#: Least ratio τ_max/τ_min of the automatic SF range.
SF_MIN_DECADES = 10.0
#: Least RMS height (after removing a line) relative to the largest |height|: below it the
#: profile is flat to rounding and any slope fitted to it is noise.
MIN_RELATIVE_RMS = 1.0e-9
#: Physically plausible fractal roughness G, m; a fit outside it is refused.
PLAUSIBLE_G: Range = (1.0e-30, 1.0e-2)
#: Why the structure-function fit gives no standard errors.
SF_STDERR_REASON = (
    "not computed for the structure function: its lags are differences of one record, "
    "correlated over the whole fit range, so the least-squares covariance of the log–log line "
    "would understate the error (σ_D ≈ 0.001 against a miss of 0.02 on a W–M profile); the "
    "PSD fit's standard errors estimate it"
)
#: Points per smoothing width on the evaluation grid of the fits.
_GRID_PER_WIDTH = 4
_SUBBINS = 16


@dataclass(frozen=True)
class FractalFit:
    """Result of one log–log fit.

    Attributes:
        D: profile fractal dimension (NaN if the slope is outside 1 < D < 2).
        G: fractal roughness, m (NaN likewise).
        method: ``"psd"`` or ``"structure_function"``.
        fit_range: (min, max) of ω (PSD, cycles/m) or τ (structure function, m) fitted.
        range_unit: ``"1/m"`` (cycles per metre) or ``"m"``.
        r_squared: R² of the smoothed log–log points about the fitted line.
        points: periodogram bins (PSD) or lags (SF) inside the fit range, per profile.
        profiles: number of profiles (rows) averaged.
        slope, intercept: the fitted line ln y = intercept + slope ln x (natural logs), y the
            PSD in m³ or the structure function in m², after the corrections described in
            :mod:`ballscrew.surface.fit`; x in cycles/m or m.
        gamma: W–M frequency ratio γ used for G.
        D_stderr, lnG_stderr: standard errors of D and of ln G (≈ the relative error of G) for
            a Gaussian random profile, PSD fit only (NaN when D is not determined): the
            periodogram bins are taken as independent with variance mean²/rows (delta method
            through the smoothing and the line fit). Rows of an areal measurement are not
            independent at long wavelengths, so for them it is a lower bound; a W–M profile,
            whose line amplitudes are fixed, scatters much less. G is ill-conditioned:
            d ln G/dD = −ln(ω_c G)/(D − 1) at the centre ω_c of the fit range, e.g. ≈ 20.
            None for the structure function, for the reason :attr:`stderr_reason` gives.
        notes: anything the caller should know (narrowed range, slope out of range…).
        x, y: the smoothed, corrected points that were fitted (for plots).
    """

    D: float
    G: float
    method: str
    fit_range: Range
    range_unit: str
    r_squared: float
    points: int
    profiles: int
    slope: float
    intercept: float
    gamma: float = 1.5
    D_stderr: float | None = float("nan")
    lnG_stderr: float | None = float("nan")
    notes: tuple[str, ...] = ()
    x: FloatArray = field(default_factory=lambda: np.empty(0), repr=False, compare=False)
    y: FloatArray = field(default_factory=lambda: np.empty(0), repr=False, compare=False)

    @property
    def stderr_reason(self) -> str | None:
        """Why :attr:`D_stderr` and :attr:`lnG_stderr` are None (None when they are given)."""
        return SF_STDERR_REASON if self.D_stderr is None else None

    @property
    def surface_dimension(self) -> float:
        """Ds = D + 1, the dimension of the 3-D surface (theory manual, *Fractal contact*)."""
        return self.D + 1.0

    def line(self, x: ArrayLike) -> FloatArray:
        """The fitted power law exp(intercept) x^slope at ``x``."""
        return np.exp(self.intercept) * np.asarray(x, dtype=np.float64) ** self.slope

    def as_dict(self) -> dict[str, Any]:
        """Scalars of the fit as a plain dict (arrays left out)."""
        out = asdict(self)
        out.pop("x")
        out.pop("y")
        out["fit_range"] = list(self.fit_range)
        out["notes"] = list(self.notes)
        out["stderr_reason"] = self.stderr_reason
        return out


@dataclass(frozen=True, eq=False)
class SurfaceFit:
    """Both estimates and the recommended one, with the spectra they came from.

    Attributes:
        psd, structure_function: the two fits (``None`` if not asked for).
        recommended: the PSD fit when it gave a valid D, else the structure-function fit.
        spectrum: ``(frequency, psd)`` periodogram, cycles/m and m³ (``None`` if not computed).
        structure: ``(lag, sf)``, m and m² (``None`` if not computed).
        spacing, length: sampling interval and sampling length, m.
        notes: comparison of the two methods.
    """

    psd: FractalFit | None
    structure_function: FractalFit | None
    recommended: FractalFit
    spectrum: tuple[FloatArray, FloatArray] | None
    structure: tuple[FloatArray, FloatArray] | None
    spacing: float
    length: float
    notes: tuple[str, ...] = ()

    @property
    def D(self) -> float:
        """Recommended profile fractal dimension."""
        return self.recommended.D

    @property
    def G(self) -> float:
        """Recommended fractal roughness, m."""
        return self.recommended.G


# ----------------------------------------------------------------------------------- helpers


def _check_range(name: str, rng: object, lo_ok: float, hi_ok: float, unit: str) -> Range:
    try:
        lo, hi = (float(v) for v in rng)  # type: ignore[union-attr]
    except (TypeError, ValueError):
        raise InputError(name, rng, f"a pair (min, max) in {unit}") from None
    if not (math.isfinite(lo) and math.isfinite(hi) and lo_ok <= lo < hi <= hi_ok):
        raise InputError(name, rng, f"min < max within the data, [{lo_ok:.4g}, {hi_ok:.4g}] {unit}")
    return lo, hi


def _top_frequency(spacing: float, resolution: float | None) -> float:
    if resolution is None:
        return 0.5 / spacing
    res = check_spacing(resolution, "resolution")
    return 0.5 / max(spacing, res)


def _log_grid(lo: float, hi: float, width: float) -> FloatArray:
    count = max(8, math.ceil(math.log(hi / lo) * _GRID_PER_WIDTH / width) + 1)
    return np.linspace(math.log(lo), math.log(hi), count)


def _line_fit(x: FloatArray, y: FloatArray) -> tuple[float, float, float]:
    slope, intercept = np.polyfit(x, y, 1)
    resid = y - (intercept + slope * x)
    ss_tot = float(np.sum((y - y.mean()) ** 2))
    r2 = 1.0 - float(np.sum(resid**2)) / ss_tot if ss_tot > 0.0 else float("nan")
    return float(slope), float(intercept), r2


def _local_linear(
    x: FloatArray, xd: FloatArray, yd: FloatArray, wd: FloatArray, width: float
) -> FloatArray:
    """Gaussian local-linear smoother of (xd, yd) with weights wd, evaluated at x.

    Exact for a straight line, also where the kernel is cut by the end of the data.
    """
    u = xd[None, :] - x[:, None]
    k = np.exp(-0.5 * (u / width) ** 2) * wd[None, :]
    s0, s1, s2 = k.sum(axis=1), (k * u).sum(axis=1), (k * u * u).sum(axis=1)
    t0, t1 = k @ yd, (k * u) @ yd
    return (s2 * t0 - s1 * t1) / (s0 * s2 - s1 * s1)


def _window_factor(window: str | None, n: int) -> float:
    """1 + 2 Σ_k |ρ_k|² for the correlation ρ_k of DFT bins k apart under ``window``."""
    if window is None:
        return 1.0
    w2 = get_window(window, n) ** 2
    rho = np.fft.fft(w2)[1:6] / w2.sum()
    return float(1.0 + 2.0 * np.sum(np.abs(rho) ** 2))


def _check_variation(rows: FloatArray) -> None:
    """InputError for profiles that are flat (to rounding) once a line is removed."""
    t = np.linspace(-1.0, 1.0, rows.shape[1])
    residual = rows - rows.mean(axis=1, keepdims=True)
    residual -= np.outer(residual @ t / (t @ t), t)
    rms = float(np.sqrt(np.mean(residual**2)))
    if not rms > MIN_RELATIVE_RMS * float(np.max(np.abs(rows))):
        raise InputError(
            "heights",
            f"a profile with no height variation (RMS {rms:.2g} m after removing a line)",
            "a rough profile",
        )


def _determined(D: float, G: float, notes: list[str], what: str, D_se: float = 0.0) -> bool:
    """Whether a fit's G is plausible and its D determined (σ_D < D − 1, the fractal part)."""
    lo, hi = PLAUSIBLE_G
    if not lo <= G <= hi:
        notes.append(f"{what} fit gives G = {G:.3g} m, outside the plausible {lo:g}–{hi:g} m")
        return False
    if not D_se < D - 1.0:
        notes.append(
            f"{what} fit undetermined: D = {D:.4g} ± {D_se:.2g}, an uncertainty larger than D − 1"
        )
        return False
    return True


def _valid_dimension(D: float, notes: list[str], what: str) -> bool:
    if math.isfinite(D) and 1.0 < D < 2.0:
        return True
    notes.append(f"{what} slope gives D = {D:.4g}, outside 1 < D < 2: not a fractal profile")
    return False


# ------------------------------------------------------------------------------- PSD method


def fit_power_spectrum(
    heights: ArrayLike,
    spacing: float,
    *,
    fit_range: Range | None = None,
    gamma: float = 1.5,
    resolution: float | None = None,
    window: str | None = "hann",
    detrend: str | None = "linear",
    spectrum: tuple[FloatArray, FloatArray] | None = None,
) -> FractalFit:
    """D and G from the log–log slope and level of the one-sided PSD (F2).

    Args:
        heights: one profile (1-D) or rows (2-D; the periodograms are averaged), m.
        spacing: sampling interval Δx, m.
        fit_range: (ω_min, ω_max) in cycles/m; default the automatic range of the module
            docstring.
        gamma: W–M γ of (F2) (sets the smoothing width ln γ and the level constant).
        resolution: instrument lateral resolution, m (caps ω_top at 1/(2·resolution)).
        window, detrend: see :func:`~ballscrew.surface.spectral.power_spectrum`.
        spectrum: a precomputed ``(frequency, psd)`` of these heights (skips the periodogram).

    Returns:
        A :class:`FractalFit` with ``method="psd"``; ``fit_range`` in cycles/m.
    """
    g = check_gamma(gamma)
    dx = check_spacing(spacing)
    rows = as_rows(heights)
    _check_variation(rows)
    n_rows, n = rows.shape
    length = n * dx
    f, s = (
        spectrum
        if spectrum is not None
        else power_spectrum(rows, dx, window=window, detrend=detrend)
    )
    width = math.log(g)
    notes: list[str] = []
    f_top = _top_frequency(dx, resolution)
    if fit_range is None:
        hi = f_top / 3.0
        lo = 20.0 / length
        if hi < 10.0 * lo:
            lo = max(5.0 / length, hi / 10.0)
            notes.append("short profile: PSD fit range narrowed below the 20/L low end")
        if hi < 2.0 * lo and resolution is not None and resolution > dx:
            # ω_top/3 = 1/(6·resolution) must reach 2·(5/L): resolution ≤ L/60
            raise InputError(
                "resolution",
                resolution,
                f"at most {length / 60.0:.3g} m on this {length:.3g} m profile (a coarser one "
                "leaves no PSD fit range)",
            )
        if hi < 2.0 * lo:
            raise InputError(
                "heights", f"{n} points per profile", "enough points for a PSD fit (≥ 64)"
            )
    else:
        lo, hi = _check_range("fit_range (psd)", fit_range, f[0], f[-1], "cycles/m")
    x = _log_grid(lo, hi, width)
    x_bin, p_bin, p2_bin = log_binned_power(f, s, width)
    kernel = smoothing_kernel(x, x_bin, width)
    power = kernel @ p_bin  # power per unit ln ω
    if np.any(power <= 0.0):
        raise InputError("heights", "a profile with no height variation", "a rough profile")
    smoothed = power / np.exp(x)
    slope, intercept, r2 = _line_fit(x, np.log(smoothed))
    alpha = -slope - 1.0  # S ∝ ω^−(α+1), α = 4 − 2D
    D = 0.5 * (5.0 + slope)
    level = intercept - 0.5 * (alpha * width) ** 2  # remove the smoothing factor exp(α²σ²/2)
    G = D_se = lnG_se = float("nan")
    if _valid_dimension(D, notes, "PSD"):
        lnG_num = level + math.log(2.0 * math.log(g))
        G = math.exp(lnG_num / (2.0 * (D - 1.0)))
        # Delta method: a and b are linear in ln p̃(x_j); ln p̃ is linear in the bin powers.
        design = np.column_stack((np.ones_like(x), x))
        coef_a, coef_b = np.linalg.solve(design.T @ design, design.T)
        dlnG_da = 1.0 / (2.0 * (D - 1.0))
        dlnG_db = alpha * width**2 / (2.0 * (D - 1.0)) - lnG_num / (2.0 * (D - 1.0)) ** 2
        # Var of a row-mean periodogram bin ≈ E[P]²/m (χ²₂); E[P̄²] = E[P]²(1 + 1/m) and the
        # window correlates neighbouring bins (factor 1 + 2 Σ ρ_k², ≈ 1.94 for Hann).
        var_bin = p2_bin * _window_factor(window, n) / (n_rows + 1.0)
        w_D = (0.5 * coef_b / power) @ kernel
        w_G = ((dlnG_da * coef_a + dlnG_db * coef_b) / power) @ kernel
        D_se = math.sqrt(float(np.sum(w_D**2 * var_bin)))
        lnG_se = math.sqrt(float(np.sum(w_G**2 * var_bin)))
        if not _determined(D, G, notes, "PSD", D_se):
            D = G = float("nan")
    else:
        D = float("nan")
    points = int(np.count_nonzero((f >= lo) & (f <= hi)))
    y = np.log(smoothed) - 0.5 * (alpha * width) ** 2
    return FractalFit(
        D=D,
        G=G,
        method="psd",
        fit_range=(lo, hi),
        range_unit="1/m",
        r_squared=r2,
        points=points,
        profiles=n_rows,
        slope=slope,
        intercept=level,
        gamma=g,
        D_stderr=D_se,
        lnG_stderr=lnG_se,
        notes=tuple(notes),
        x=np.exp(x),
        y=np.exp(y),
    )


# -------------------------------------------------------------------- structure-function method


def _sf_upper_lag(D: float, length: float, lo: float) -> float:
    d = min(max(D, 1.05), 1.95)
    tau = length / (2.0 * math.pi) * SF_LONG_WAVE_SHARE ** (1.0 / (2.0 * d - 2.0))
    return min(max(tau, SF_MIN_DECADES * lo), length / 10.0)


def fit_structure_function(
    heights: ArrayLike,
    spacing: float,
    *,
    fit_range: Range | None = None,
    gamma: float = 1.5,
    resolution: float | None = None,
    detrend: str | None = "linear",
    band_correction: bool = True,
    structure: tuple[FloatArray, FloatArray] | None = None,
    max_iterations: int = 20,
) -> FractalFit:
    """D and G from the log–log slope and level of the structure function (F4).

    Args:
        heights: one profile (1-D) or rows (2-D; the structure functions are averaged), m.
        spacing: sampling interval Δx, m.
        fit_range: (τ_min, τ_max) in m; default the automatic, D-dependent range of the module
            docstring.
        gamma: W–M γ of (F4) (sets C_D and the smoothing width ln γ).
        resolution: instrument lateral resolution, m (raises τ_min, lowers ω_max of the band).
        detrend: trend removed from each row before the differences.
        band_correction: divide by the band-limited ratio r(τ; D) for the band
            [1/L, ω_top] (default), right for data band-limited at ω_top (synthetic profiles,
            instruments whose optics cut near the Nyquist frequency). For sampled data that
            keep power above ω_top (aliased), it over-corrects the smallest lags by
            ≈ (2πτω_top)^(2D−4); ``False`` fits the raw structure function.
        structure: a precomputed ``(lag, sf)`` of these heights.
        max_iterations: iterations on D (the correction and τ_max depend on D).

    Returns:
        A :class:`FractalFit` with ``method="structure_function"``; ``fit_range`` in m.
    """
    g = check_gamma(gamma)
    dx = check_spacing(spacing)
    rows = as_rows(heights)
    _check_variation(rows)
    n_rows, n = rows.shape
    length = n * dx
    lag, sf = structure if structure is not None else structure_function(rows, dx, detrend=detrend)
    if np.any(sf <= 0.0):
        raise InputError("heights", "a profile with no height variation", "a rough profile")
    width = math.log(g)
    f_top = _top_frequency(dx, resolution)
    notes: list[str] = []
    # Fine ln τ bins of the lags, each lag weighted by the ln τ interval it stands for.
    k = np.rint(lag / dx)
    weight = np.log((k + 0.5) / np.maximum(k - 0.5, 0.25))
    x_lag, y_lag = np.log(lag), np.log(sf)
    h = width / _SUBBINS
    index = np.floor((x_lag - x_lag[0]) / h).astype(np.int64)
    w_bin = np.bincount(index, weights=weight)
    keep = w_bin > 0.0
    x_bin = (np.bincount(index, weights=weight * x_lag)[keep]) / w_bin[keep]
    y_bin = (np.bincount(index, weights=weight * y_lag)[keep]) / w_bin[keep]
    w_bin = w_bin[keep]

    if fit_range is not None:
        lo, hi = _check_range("fit_range (structure_function)", fit_range, lag[0], lag[-1], "m")
    else:
        lo = SF_MIN_LAG / f_top
        if lo * SF_MIN_DECADES > length / 10.0:
            lo = max(3.0 * dx, length / 100.0)
            notes.append("short profile: structure-function range starts below 5/ω_top")
        hi = _sf_upper_lag(1.5, length, lo)

    D = 1.5
    for _ in range(max(1, int(max_iterations))):
        if fit_range is None:
            hi = _sf_upper_lag(D, length, lo)
        if not hi > lo:
            raise InputError(
                "heights", f"{n} points per profile", "enough points for a structure-function fit"
            )
        x = _log_grid(lo, hi, width)
        near = (x_bin > x[0] - 4.0 * width) & (x_bin < x[-1] + 4.0 * width)
        yb = y_bin[near]
        if band_correction:
            ratio = band_limited_ratio(np.exp(x_bin[near]), D, 1.0 / length, f_top)
            yb = yb - np.log(ratio)
        y = _local_linear(x, x_bin[near], yb, w_bin[near], width)
        slope, intercept, r2 = _line_fit(x, y)
        D_new = 0.5 * (4.0 - slope)
        converged = abs(D_new - D) < 1e-7
        D = D_new
        if converged or not 1.0 < D < 2.0 or (fit_range is not None and not band_correction):
            break
    else:
        notes.append(f"D iteration stopped after {max_iterations} steps (last change > 1e-7)")
    G = float("nan")
    if _valid_dimension(D, notes, "structure-function"):
        alpha = 4.0 - 2.0 * D
        c_d = structure_function_constant(D, g)
        G = math.exp(
            (intercept - alpha * math.log(2.0 * math.pi) - math.log(c_d)) / (2.0 * (D - 1.0))
        )
        if not _determined(D, G, notes, "structure-function"):
            D = G = float("nan")
    else:
        D = float("nan")
    points = int(np.count_nonzero((lag >= lo) & (lag <= hi)))
    return FractalFit(
        D=D,
        G=G,
        method="structure_function",
        fit_range=(lo, hi),
        range_unit="m",
        r_squared=r2,
        points=points,
        profiles=n_rows,
        slope=slope,
        intercept=intercept,
        gamma=g,
        D_stderr=None,
        lnG_stderr=None,
        notes=tuple(notes),
        x=np.exp(x),
        y=np.exp(y),
    )


# ------------------------------------------------------------------------------ both methods


def _ranges(method: str, fit_range: object) -> dict[str, Range | None]:
    names = ("psd", "structure_function") if method == "both" else (method,)
    if fit_range is None:
        return dict.fromkeys(names)
    if isinstance(fit_range, Mapping):
        unknown = set(fit_range) - {"psd", "structure_function"}
        if unknown:
            raise InputError("fit_range", sorted(unknown), "keys 'psd' and 'structure_function'")
        return {name: fit_range.get(name) for name in names}
    if method == "both":
        raise InputError(
            "fit_range",
            fit_range,
            "a dict {'psd': (ω_min, ω_max) [1/m], 'structure_function': (τ_min, τ_max) [m]} "
            "when method='both'",
        )
    return {method: fit_range}  # type: ignore[dict-item]


def fractal_parameters(
    profile: Profile | ArrayLike,
    spacing: float | None = None,
    method: Method = "both",
    fit_range: Range | Mapping[str, Range | None] | None = None,
    *,
    gamma: float = 1.5,
    resolution: float | None = None,
) -> SurfaceFit:
    """Estimate D and G of a profile (or the rows of an areal measurement) by PSD and/or SF.

    Args:
        profile: a :class:`Profile` or heights in m (1-D, or 2-D rows averaged).
        spacing: sampling interval, m (taken from the :class:`Profile` when ``None``).
        method: ``"psd"``, ``"structure_function"`` or ``"both"``.
        fit_range: ``None`` (automatic), a (min, max) pair for a single method (cycles/m for
            the PSD, m for the structure function), or a dict keyed by method name.
        gamma: W–M γ (1.5).
        resolution: instrument lateral resolution, m, when coarser than the sampling interval.

    Returns:
        A :class:`SurfaceFit`; ``.D`` and ``.G`` are the recommended values (the PSD fit unless
        it failed). Raises :class:`InputError` if no method gave 1 < D < 2.
    """
    if method not in ("psd", "structure_function", "both"):
        raise InputError("method", method, "'psd', 'structure_function' or 'both'")
    if isinstance(profile, Profile):
        heights = profile.heights
        dx = profile.spacing if spacing is None else check_spacing(spacing)
    else:
        if spacing is None:
            raise InputError("spacing", None, "the sampling interval in m for a bare array")
        heights, dx = profile, check_spacing(spacing)
    rows = as_rows(heights)
    ranges = _ranges(method, fit_range)
    notes: list[str] = []
    total = 1 if np.ndim(heights) == 1 else int(np.shape(heights)[0])
    if rows.shape[0] < total:
        notes.append(f"{total - rows.shape[0]} of {total} profiles left out (non-measured points)")
    psd_fit = sf_fit = None
    spectrum = structure = None
    if "psd" in ranges:
        spectrum = power_spectrum(rows, dx)
        psd_fit = fit_power_spectrum(
            rows,
            dx,
            fit_range=ranges["psd"],
            gamma=gamma,
            resolution=resolution,
            spectrum=spectrum,
        )
    if "structure_function" in ranges:
        structure = structure_function(rows, dx)
        sf_fit = fit_structure_function(
            rows,
            dx,
            fit_range=ranges["structure_function"],
            gamma=gamma,
            resolution=resolution,
            structure=structure,
        )
    candidates = [f for f in (psd_fit, sf_fit) if f is not None and math.isfinite(f.D)]
    if not candidates:
        reasons = "; ".join(n for f in (psd_fit, sf_fit) if f is not None for n in f.notes)
        raise InputError("profile", "no fractal fit", f"a slope with 1 < D < 2 ({reasons})")
    if psd_fit is not None and sf_fit is not None and len(candidates) == 2:
        dD = sf_fit.D - psd_fit.D
        ratio = sf_fit.G / psd_fit.G
        notes.append(f"structure function − PSD: ΔD = {dD:+.4f}, G ratio = {ratio:.3f}")
        if abs(dD) > 0.02 * psd_fit.D or not 0.8 < ratio < 1.25:
            notes.append(
                "the two methods disagree by more than 2 % in D or 25 % in G: check the fit "
                "ranges and the form removal"
            )
    return SurfaceFit(
        psd=psd_fit,
        structure_function=sf_fit,
        recommended=candidates[0],
        spectrum=spectrum,
        structure=structure,
        spacing=dx,
        length=rows.shape[1] * dx,
        notes=tuple(notes),
    )
