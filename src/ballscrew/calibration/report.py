"""What the calibration shows: its summary, fit table, figure and report section."""

from __future__ import annotations

from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from ballscrew.analyses.result import Figure, Section, Table
from ballscrew.analyses.result import quantity as value
from ballscrew.plotting import plain, pyplot, revolutions_axis, save_figure

if TYPE_CHECKING:
    from ballscrew.calibration.result import CalibrationResult

__all__ = [
    "DISPLAY",
    "STANDARD_ERRORS",
    "data_notes",
    "figures",
    "fit_dataset",
    "fit_plot",
    "fit_table",
    "sections",
    "summary",
]

STANDARD_ERRORS = (
    "Standard errors come from the residual scatter only, cov = RSS/(n − p)·(JᵀJ)⁻¹, as if the "
    "model were right and the residuals independent: they leave out the model-form error (a "
    "model whose shape misses the data's) and understate the uncertainty when the residuals "
    "are correlated. The errors 'allowing for correlated residuals' use n_eff = n(1 − r₁)/(1 + "
    "r₁) points (lag-1 autocorrelation r₁ > 0; Bayley & Hammersley 1946) in place of n; they "
    "still leave out the model-form error."
)
"""What the calibration's standard errors cover and what they leave out."""

#: Label and display unit (name, factor from SI) of each measured quantity.
DISPLAY: dict[str, tuple[str, str, float]] = {
    "friction_torque": ("friction torque", "N·m", 1.0),
    "preload": ("preload", "N", 1.0),
    "wear_depth": ("maximum wear depth", "µm", 1.0e6),
}


def summary(result: CalibrationResult, inflated_errors: bool = True) -> dict[str, Any]:
    """The fit as a JSON-ready dict (the fitted values first, then diagnostics); without the
    errors allowing for correlated residuals where ``inflated_errors`` is False (a history of a
    joint fit, whose errors have the joint degrees of freedom)."""
    from ballscrew.calibration.multi import FIT_PARAMETERS

    inflated = (result.inflated_errors if inflated_errors else None) or {}
    return {
        "case": result.case_name,
        "wear_coefficient": value(result.wear_coefficient, ""),
        "wear_coefficient_standard_error": value(result.standard_error, ""),
        "torque_scale": value(result.torque_scale, ""),
        "rms_residual": value(result.rms_residual, result.unit),
        "wear_coefficient_relative_error": value(result.relative_error, ""),
        "torque_scale_standard_error": (
            value(result.torque_scale_error, "") if result.torque_scale_error is not None else None
        ),
        "torque_scale_fitted": result.torque_scale_error is not None,
        "correlation_ln_wear_coefficient_torque_scale": result.correlation,
        "torque_offset": value(result.torque_offset, "N*m"),
        "torque_offset_standard_error": (
            value(result.errors["torque_offset"], "N*m")
            if "torque_offset" in result.errors
            else None
        ),
        "correlations": dict(result.correlations),
        "fitted": {
            name: {
                "value": v,
                "standard_error": result.errors.get(name),
                "standard_error_correlated_residuals": inflated.get(name),
                "unit": FIT_PARAMETERS[name].unit,
            }
            for name, v in result.values.items()
        },
        "fit_until": result.fit_until,
        "prediction_rmse": (
            value(result.prediction_rmse, result.unit)
            if result.prediction_rmse is not None
            else None
        ),
        "residual_diagnostics": dict(result.diagnostics),
        "effective_points": result.effective_points,
        "standard_errors_cover": STANDARD_ERRORS,
        "calibrated_range": _range(result),
        "prediction_band": "95 % prediction band ŷ ± 1.96 √(gᵀ cov g + s²), delta method "
        "from the Jacobian covariance",
        "measured": {
            "file": result.source,
            "notes": list(result.data_notes),
            "quantity": result.quantity,
            "unit": result.unit,
            "points": result.n_points,
            "first_revolutions": float(result.revolutions[0]),
            "last_revolutions": float(result.revolutions[-1]),
        },
        "fit": {
            "method": "scipy.optimize.least_squares (trf) on ln K after a coarse decade scan",
            "parameters": result.parameters,
            "degrees_of_freedom": result.n_points - result.parameters,
            "model_evaluations": result.evaluations,
            "initial_wear_coefficient": value(result.initial_coefficient, ""),
            "scan": [
                {"wear_coefficient": k, "rms_residual": value(rms, result.unit)}
                for k, rms in result.scan
            ],
            "message": result.message,
        },
        "options": dict(result.options),
        "note": "K is confounded with the stroke and the revolution count of the case "
        "(theory manual, Wear); quote it with them. Standard errors assume the model is "
        "right and the noise independent with equal variance (see standard_errors_cover).",
    }


def _range(result: CalibrationResult) -> dict[str, Any] | None:
    bounds = result.calibrated_range
    if bounds is None:
        return None
    return {
        "speed_min": value(bounds["speed_min"], "rad/s"),
        "speed_max": value(bounds["speed_max"], "rad/s"),
        "load_min": value(bounds["load_min"], "N"),
        "load_max": value(bounds["load_max"], "N"),
    }


def fit_table(result: CalibrationResult) -> str:
    """CSV text: revolutions, measured, model and residual (SI units)."""
    unit = result.unit or "1"
    lines = [f"revolutions,{result.quantity} [{unit}],model [{unit}],residual [{unit}]"]
    for n, y, f in zip(result.revolutions, result.measured, result.fitted, strict=True):
        lines.append(f"{n:.10g},{y:.10g},{f:.10g},{f - y:.10g}")
    return "\n".join(lines) + "\n"


def fit_plot(result: CalibrationResult, title: str, path: str | Path) -> Path:
    """Measured points and the fitted model curve against revolutions, residuals below."""
    plt = pyplot()
    label, unit, factor = DISPLAY[result.quantity]
    fig, (ax, axr) = plt.subplots(
        2,
        1,
        figsize=(6.8, 5.0),
        sharex=True,
        height_ratios=(3, 1),
        layout="constrained",
    )
    rev_scale, rev_label = revolutions_axis(
        np.concatenate([result.model_revolutions, result.revolutions])
    )
    ax.plot(
        result.model_revolutions / rev_scale,
        result.model_values * factor,
        "-",
        color="tab:blue",
        label=f"model, K = {result.wear_coefficient:.4e} ± {result.standard_error:.2e}"
        + (
            f", torque scale {result.torque_scale:.4g} ± {result.torque_scale_error:.2g}"
            if result.torque_scale_error is not None
            else ""
        ),
    )
    if result.prediction_sigma is not None:
        half = 1.96 * result.prediction_sigma * factor
        ax.fill_between(
            result.model_revolutions / rev_scale,
            result.model_values * factor - half,
            result.model_values * factor + half,
            color="tab:blue",
            alpha=0.2,
            linewidth=0,
            label="95 % prediction band (delta method)",
        )
    if result.fit_until is not None:
        for axis in (ax, axr):
            axis.axvline(result.fit_until / rev_scale, color="0.3", linestyle="--", linewidth=0.8)
        ax.text(result.fit_until / rev_scale, ax.get_ylim()[1], " held out →", va="top", fontsize=8)
    ax.plot(
        result.revolutions / rev_scale,
        result.measured * factor,
        "o",
        color="tab:red",
        markersize=4,
        label=plain(f"measured ({result.source})"),
    )
    ax.set_ylabel(f"{label} [{unit}]")
    ax.set_title(plain(title), fontsize=10)
    ax.legend(fontsize=8)
    axr.axhline(0.0, color="0.5", linewidth=0.8)
    axr.plot(result.revolutions / rev_scale, result.residuals * factor, "o", color="tab:red", ms=3)
    axr.set_xlabel(rev_label)
    axr.set_ylabel(f"model − measured [{unit}]", fontsize=8)
    return save_figure(fig, path)


def fit_dataset(result: CalibrationResult) -> xr.Dataset:
    """Measured, model and residual at the measured revolutions (SI units)."""
    unit = result.unit or "1"
    return xr.Dataset(
        {
            "measured": ("point", result.measured, {"units": unit}),
            "model": ("point", result.fitted, {"units": unit}),
            "residual": ("point", result.residuals, {"units": unit}),
        },
        coords={"revolutions": ("point", result.revolutions, {"units": "1"})},
        attrs={"quantity": result.quantity, "source": result.source},
    )


def figures(result: CalibrationResult) -> list[Figure]:
    """The measured history with the fitted model."""
    label = DISPLAY[result.quantity][0]
    title = f"{result.case_name}: {label} against revolutions"
    return [
        Figure(
            "fit",
            f"Measured {label} and the fitted model; residuals below.",
            partial(fit_plot, result, title),
        )
    ]


def data_notes(result: CalibrationResult) -> list[str]:
    """A paragraph with what the measured file says about its data (none if it says nothing)."""
    if not result.data_notes:
        return []
    return [f"What {result.source} says about its data: " + " ".join(result.data_notes)]


def sections(result: CalibrationResult, inflated_errors: bool = True) -> list[Section]:
    """The fitted values, their uncertainty and the method (``inflated_errors``: as in
    :func:`summary`)."""
    from ballscrew.calibration.multi import FIT_PARAMETERS

    label, unit, factor = DISPLAY[result.quantity]
    rows: list[tuple[object, ...]] = [
        ("wear coefficient K", result.wear_coefficient),
        ("standard error of K", result.standard_error),
        ("relative standard error of K", result.relative_error),
        (
            "torque scale" + (" (fitted)" if result.torque_scale_error is not None else ""),
            result.torque_scale,
        ),
    ]
    if result.torque_scale_error is not None:
        rows.append(("standard error of the torque scale", result.torque_scale_error))
        rows.append(("correlation (ln K, torque scale)", result.correlation))
    if result.quantity == "friction_torque":
        fitted = " (fitted)" if "torque_offset" in result.values else ""
        rows.append((f"torque offset T_0 [N·m]{fitted}", result.torque_offset))
    rows += [
        (f"{name} (fitted)", v)
        for name, v in result.values.items()
        if name not in ("wear_coefficient", "torque_scale", "torque_offset")
    ]
    rows += [
        (
            f"standard error of {name}"
            + (f" [{FIT_PARAMETERS[name].unit}]" * bool(FIT_PARAMETERS[name].unit)),
            e,
        )
        for name, e in result.errors.items()
        if name not in ("wear_coefficient", "torque_scale")
    ]
    shown = {"wear_coefficient,torque_scale"} if result.torque_scale_error is not None else set()
    rows += [
        (f"correlation ({pair.replace(',', ', ')})", r)
        for pair, r in result.correlations.items()
        if pair not in shown  # (ln K, torque scale) has its row above
    ]
    if result.prediction_rmse is not None:
        rows.append((f"held-out RMS error [{unit}]", result.prediction_rmse * factor))
    if result.diagnostics:
        rows.append(("runs-test p (residual signs)", result.diagnostics["runs_test_p_value"]))
        rows.append(("lag-1 autocorrelation", result.diagnostics["lag1_autocorrelation"]))
        rows.append(("effective points n_eff", result.effective_points))
    if result.diagnostics and inflated_errors:
        inflated = result.inflated_errors
        rows += [
            (f"standard error of {name}, allowing for correlated residuals", e)
            for name, e in (inflated or {}).items()
        ]
        if inflated is None:
            rows.append(("standard errors allowing for correlated residuals", "not determined"))
    rows += [
        (f"RMS residual [{unit}]", result.rms_residual * factor),
        ("measured points", result.n_points),
        ("model evaluations", result.evaluations),
    ]
    return [
        Section(
            "Calibration of the wear coefficient",
            paragraphs=(
                f"The wear model of case {result.case_name!r} was fitted to the measured {label} "
                f"of {result.source} ({result.n_points} points) by nonlinear least squares on "
                "ln K (scipy least_squares, trust-region reflective, after a coarse scan "
                "one decade apart), the model history interpolated linearly onto the "
                "measured revolutions. Standard errors from the Jacobian at the solution: "
                "cov = RSS/(n − p)·(JᵀJ)⁻¹, K's by the delta method from ln K. The shaded band "
                "is the 95 % prediction band ŷ ± 1.96 √(gᵀ cov g + s²) (delta method, g the "
                "model's sensitivity); a runs test and the lag-1 autocorrelation check that the "
                "residuals are noise.",
                "K is confounded with the stroke and the revolution count of the case: quote "
                "it together with them. " + STANDARD_ERRORS,
                *data_notes(result),
            ),
            tables=(Table(("quantity", "value"), tuple(rows)),),
            figures=("fit",),
        )
    ]
