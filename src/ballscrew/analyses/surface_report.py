"""What the surface analysis shows: its summary, spectra, log–log fit plots and report section."""

from __future__ import annotations

from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from ballscrew.analyses.result import Figure, Section, Table
from ballscrew.analyses.result import quantity as value
from ballscrew.fractal.conventions import surface_roughness_from_profile
from ballscrew.plotting import plain, pyplot, save_figure
from ballscrew.surface.fit import FractalFit, SurfaceFit
from ballscrew.surface.profile import Profile
from ballscrew.surface.structure_function import band_limited_ratio

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from ballscrew.analyses.surface import SurfaceCharacterisation

__all__ = [
    "fields",
    "figures",
    "profile_plot",
    "psd_plot",
    "sections",
    "structure_function_plot",
    "summary",
]

_NAMES = {"psd": "power spectrum (F2)", "structure_function": "structure function (F4)"}


def _stderr(error: float | None) -> str:
    """A standard error for the report's table: "–" when not given (None or NaN)."""
    return "–" if error is None or not np.isfinite(error) else f"{error:.2g}"


def _fit_summary(fit: FractalFit) -> dict[str, Any]:
    unit = "1/m" if fit.method == "psd" else "m"
    return {
        "D": fit.D,
        "surface_dimension": fit.surface_dimension,
        "G": value(fit.G, "m"),
        "fit_range": {
            "quantity": "frequency (cycles/m)" if fit.method == "psd" else "lag",
            "min": value(fit.fit_range[0], unit),
            "max": value(fit.fit_range[1], unit),
        },
        "D_standard_error": fit.D_stderr,
        "lnG_standard_error": fit.lnG_stderr,
        **({"standard_error_reason": fit.stderr_reason} if fit.stderr_reason else {}),
        "r_squared": fit.r_squared,
        "points": fit.points,
        "profiles": fit.profiles,
        "slope": fit.slope,
        "intercept": fit.intercept,
        "notes": list(fit.notes),
    }


def summary(result: SurfaceCharacterisation) -> dict[str, Any]:
    """Scalars of both fits and the recommended D and G, each with its unit."""
    fit, profile = result.fit, result.profile
    rows = profile.rows
    finite = rows[np.all(np.isfinite(rows), axis=1)]
    detrended = finite - finite.mean(axis=1, keepdims=True)
    methods = {
        name: _fit_summary(f)
        for name, f in (("psd", fit.psd), ("structure_function", fit.structure_function))
        if f is not None
    }
    return {
        "source": profile.source,
        "format": profile.metadata.get("format", ""),
        "profiles": profile.n_profiles,
        "profiles_used": int(finite.shape[0]),
        "points_per_profile": profile.n_points,
        "spacing": value(profile.spacing, "m"),
        "sampling_length": value(profile.length, "m"),
        "rms_height": value(float(np.sqrt(np.mean(detrended**2))), "m"),
        "gamma": fit.recommended.gamma,
        "recommended": {
            "method": fit.recommended.method,
            "D": fit.D,
            "surface_dimension": fit.D + 1.0,
            "G": value(fit.G, "m"),
            "G_surface": value(
                surface_roughness_from_profile(fit.D, fit.G, fit.recommended.gamma), "m"
            ),
        },
        "methods": methods,
        "notes": list(fit.notes),
        "conventions": {
            "D": "profile fractal dimension, 1 < D < 2 (3-D surface Ds = D + 1)",
            "G": "Majumdar–Bhushan profile G: a case takes it with surface.G_convention = "
            "'profile' (the default); G_surface is the 3-D Yan–Komvopoulos G of the same RMS "
            "height (theory manual, Fractal contact)",
            "psd": "one-sided, frequency in cycles/m: S = G^(2(D-1))/(2 ln γ) ω^-(5-2D)",
            "structure_function": "C_D G^(2(D-1)) (2π τ)^(4-2D) (theory manual, Surface, F4)",
        },
    }


def _log_sample(x: np.ndarray, count: int = 600) -> np.ndarray:
    index = np.unique(np.geomspace(1, x.size, count).astype(int) - 1)
    return index


def _fit_lines(ax: Axes, r: FractalFit, x: np.ndarray, label: str) -> None:
    """The shaded fit range, the fitted line over the whole of ``x`` (dashed) and over the
    range (solid)."""
    ax.axvspan(*r.fit_range, color="C2", alpha=0.12, label="fit range")
    ax.loglog(x, r.line(x), "--", color="C3", linewidth=1.0, label=f"{label}, extended")
    fr = np.geomspace(*r.fit_range, 50)
    ax.loglog(fr, r.line(fr), "-", color="C3", linewidth=1.8, label=label)


def psd_plot(fit: SurfaceFit, path: Path) -> Path:
    """Periodogram, log-smoothed spectrum, fitted (F2) line and the shaded fit range."""
    plt = pyplot()
    assert fit.psd is not None and fit.spectrum is not None
    f, s = fit.spectrum
    r = fit.psd
    fig, ax = plt.subplots(figsize=(6.4, 4.4), layout="constrained")
    idx = _log_sample(f, 2000)
    ax.loglog(f[idx], s[idx], color="0.75", linewidth=0.6, label="periodogram")
    ax.loglog(r.x, r.y, "o", markersize=3, color="C0", label="log-smoothed (bias removed)")
    _fit_lines(ax, r, f, "fit")
    ax.set_xlabel("frequency ω [cycles/m]")
    ax.set_ylabel("one-sided PSD S(ω) [m³]")
    ax.set_title(f"PSD: D = {r.D:.4f}, G = {r.G:.3g} m, R² = {r.r_squared:.4f}", fontsize=10)
    ax.set_ylim(max(s[s > 0].min(), r.y.min() * 1e-4), s.max() * 10)
    ax.legend(fontsize=8)
    return save_figure(fig, path)


def structure_function_plot(fit: SurfaceFit, path: Path) -> Path:
    """Structure function, band-corrected points, fitted (F4) line and the shaded fit range."""
    plt = pyplot()
    assert fit.structure_function is not None and fit.structure is not None
    lag, sf = fit.structure
    r = fit.structure_function
    fig, ax = plt.subplots(figsize=(6.4, 4.4), layout="constrained")
    idx = _log_sample(lag)
    ax.loglog(lag[idx], sf[idx], color="0.55", linewidth=1.0, label="structure function")
    ax.loglog(r.x, r.y, "o", markersize=3, color="C0", label="band-corrected, smoothed")
    _fit_lines(ax, r, lag, "fit (F4)")
    if np.isfinite(r.D):
        top = 0.5 / fit.spacing
        keep = lag <= fit.length / 3.5
        model = r.line(lag[keep]) * band_limited_ratio(lag[keep], r.D, 1.0 / fit.length, top)
        ax.loglog(lag[keep], model, ":", color="k", linewidth=1.0, label="fit × band ratio")
    ax.set_xlabel("lag τ [m]")
    ax.set_ylabel("⟨[z(x+τ) − z(x)]²⟩ [m²]")
    ax.set_title(
        f"Structure function: D = {r.D:.4f}, G = {r.G:.3g} m, R² = {r.r_squared:.4f}",
        fontsize=10,
    )
    ax.legend(fontsize=8)
    return save_figure(fig, path)


def profile_plot(profile: Profile, path: Path) -> Path:
    """The first complete profile, heights in µm against x in mm."""
    plt = pyplot()
    rows = profile.rows
    good = np.flatnonzero(np.all(np.isfinite(rows), axis=1))
    z = rows[good[0]] if good.size else rows[0]
    fig, ax = plt.subplots(figsize=(8.0, 2.6), layout="constrained")
    step = max(1, z.size // 20000)
    ax.plot(profile.x[::step] * 1e3, z[::step] * 1e6, linewidth=0.6)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("z [µm]")
    ax.set_title(
        plain(f"{Path(profile.source).name or 'profile'} (first complete row)"), fontsize=10
    )
    return save_figure(fig, path)


def _row(fit: FractalFit) -> list[object]:
    unit = "1/m" if fit.method == "psd" else "m"
    return [
        _NAMES[fit.method],
        fit.D,
        fit.surface_dimension,
        fit.G,
        _stderr(fit.D_stderr),
        _stderr(fit.lnG_stderr),
        f"{fit.fit_range[0]:.4g} – {fit.fit_range[1]:.4g} {unit}",
        fit.r_squared,
        fit.points,
    ]


def fields(result: SurfaceCharacterisation) -> xr.Dataset:
    """The periodogram (dimension ``frequency``) and the structure function (dimension
    ``lag``) that were fitted, with units, in one dataset."""
    fit, data, coords = result.fit, {}, {}
    if fit.spectrum is not None:
        f, s = fit.spectrum
        data["psd"] = ("frequency", s, {"units": "m^3", "long_name": "one-sided PSD"})
        coords["frequency"] = ("frequency", f, {"units": "1/m"})
    if fit.structure is not None:
        lag, sf = fit.structure
        data["structure_function"] = ("lag", sf, {"units": "m^2"})
        coords["lag"] = ("lag", lag, {"units": "m"})
    return xr.Dataset(data, coords=coords)


def figures(result: SurfaceCharacterisation) -> list[Figure]:
    """The profile, and the log–log plot of each fit."""
    fit = result.fit
    out = [Figure("profile", "The measured profile.", partial(profile_plot, result.profile))]
    if fit.psd is not None:
        out.append(
            Figure(
                "psd",
                "PSD: periodogram (grey), the Gaussian log-smoothed spectrum that was fitted, "
                "the fitted line and the fit range (shaded).",
                partial(psd_plot, fit),
            )
        )
    if fit.structure_function is not None:
        out.append(
            Figure(
                "structure_function",
                "Structure function (grey), the band-corrected points that were fitted, the "
                "fitted (F4) line, the line times the band ratio, and the fit range.",
                partial(structure_function_plot, fit),
            )
        )
    return out


def sections(result: SurfaceCharacterisation) -> list[Section]:
    """The recommended D and G, the conventions and the table of both fits."""
    fit, profile = result.fit, result.profile
    fits = [f for f in (fit.psd, fit.structure_function) if f is not None]
    notes = [n for f in fits for n in f.notes] + list(fit.notes)
    header = ("method", "D", "Ds = D + 1", "G [m]", "s.e. D", "s.e. ln G", "fit range", "R²")
    g_surface = surface_roughness_from_profile(fit.D, fit.G, fit.recommended.gamma)
    return [
        Section(
            "Fractal parameters",
            paragraphs=(
                f"{profile.n_profiles} profile(s) of {profile.n_points} points at "
                f"Δx = {profile.spacing:.4g} m (L = {profile.length:.4g} m). Recommended: "
                f"D = {fit.D:.4f} (surface Ds = {fit.D + 1:.4f}), G = {fit.G:.4g} m from "
                f"the {_NAMES[fit.recommended.method]}: a profile G (surface.G_convention = "
                "'profile', the default); the 3-D Yan–Komvopoulos surface of the same RMS height "
                f"has G = {g_surface:.4g} m.",
                "Conventions: profile dimension 1 < D < 2, G in m, "
                "one-sided PSD in cycles/m (F2), structure function with the (2π)^(4−2D) "
                "factor (F4), γ = "
                f"{fit.recommended.gamma:g}. Fit ranges are chosen away from the sampling "
                "length and the Nyquist/resolution ends (see ballscrew.surface.fit). "
                "Standard errors (PSD) treat the profile as a Gaussian random process; "
                "G is ill-conditioned, d ln G/dD ≈ −ln(ω_c G)/(D − 1).",
                *notes,
            ),
            tables=(Table((*header, "points"), tuple(tuple(_row(f)) for f in fits)),),
            figures=tuple(f.name for f in figures(result)),
        )
    ]
